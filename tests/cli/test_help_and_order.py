"""Options say what they take, and the events table lists each frame's impacts in that frame's time order."""

from __future__ import annotations

import re

import pytest
from click.testing import CliRunner

from sears_paradox_cli.main import main


def run(*args: str) -> str:
    result = CliRunner().invoke(main, list(args))
    assert result.exit_code == 0, result.output
    return result.output


@pytest.mark.parametrize("command", sorted(main.commands))
def test_help_says_what_each_option_takes(command):
    text = run(command, "--help")
    assert "None" not in text  # click's unbounded range once read "[default: 25; x<=None]"
    if "--rod" in text:  # the metavar lists exactly the rods the command takes
        both = command in ("plot", "ledger", "events", "export", "handout", "html")
        assert ("rigid|causal|both" in text) == both, command


@pytest.mark.parametrize("rod", ["rigid", "causal"])
@pytest.mark.parametrize("args", [("fig2",), ("fig2", "--frame-velocity", "0.9"), ("off_timing", "--v", "0.9")])
def test_events_rows_run_in_each_frames_time_order(rod, args):
    text = run("events", *args, "--rod", rod)
    for block in text.split("\n\nframe ")[1:]:
        times = [float(line.split()[3]) for line in block.splitlines()[2:] if re.match(r"\s+[AB]\d", line)]
        assert len(times) >= 2 and times == sorted(times), block
