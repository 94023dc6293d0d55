"""What a new user broke in the newer commands (issue 15): the command line and its files at the edges.

Signals and pipes are tried on real processes; everything else in-process (click's runner).
"""

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from click.testing import CliRunner

from sears_paradox_cli.main import main


def run(*args, expect=0):
    result = CliRunner().invoke(main, [str(a) for a in args])
    assert result.exit_code == expect, (result.output, result.exception)
    return result


def error_of(*args) -> str:
    """The one-sentence error a bad call prints; it must exit 2 and print no traceback."""
    result = run(*args, expect=2)
    assert isinstance(result.exception, SystemExit), result.exception
    lines = [line for line in result.output.splitlines() if line.startswith("Error: ")]
    assert len(lines) == 1, result.output
    return lines[0][len("Error: "):]


def _cli() -> list[str]:
    script = Path(sys.executable).parent / "sears-paradox"
    return [str(script)] if script.exists() else [sys.executable, "-c", "from sears_paradox_cli.main import main; main()"]


# --- item 8: output lost in a pipe is exit 141, whatever the buffering ------------------------------------

@pytest.mark.parametrize("unbuffered", ["1", ""])
@pytest.mark.parametrize("args", [["ledger", "fig2", "--format", "json"],
                                  ["ledger", "fig2", "--format", "json", "-o", "/dev/stdout"]])
def test_a_reader_that_leaves_after_a_pause_is_exit_141(args, unbuffered):
    """The table (215 kB) is more than a pipe holds (64 kB): a reader that takes 10 bytes a moment later and leaves
    loses the rest, which the README says is status 141. With PYTHONUNBUFFERED the text stream handed the
    system one write and dropped what the pipe did not take, exiting 0."""
    env = dict(os.environ, PYTHONUNBUFFERED=unbuffered)
    process = subprocess.Popen(_cli() + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env)
    time.sleep(1.0)  # the pipe fills and the writer waits
    assert len(process.stdout.read(10)) == 10
    process.stdout.close()
    stderr = process.stderr.read().decode()
    assert (process.wait(timeout=60), stderr) == (141, "")


# --- item 15: -o /dev/stdout into a pipe ----------------------------------------------------------------

@pytest.mark.parametrize("args, start", [
    (["ledger", "fig2", "--format", "json"], b'{\n "format": "sears-paradox-ledger/1"'),
    (["export", "fig2", "--format", "csv"], b"frame,kind,name"),
    (["plot", "fig2", "--format", "svg"], b"<?xml"),
])
def test_output_to_dev_stdout_in_a_pipe_is_the_data_alone(args, start):
    """/dev/stdout in a pipe leads to `pipe:[...]`, no path: it was "no such file or directory"; now it is written
    in place, and the path written is not printed into the data."""
    result = subprocess.run(_cli() + args + ["-o", "/dev/stdout"], capture_output=True, timeout=60)
    assert (result.returncode, result.stderr) == (0, b"")
    assert result.stdout.startswith(start)
    assert b"/dev/stdout" not in result.stdout


def test_a_figure_to_dev_stdout_needs_its_format():
    assert error_of("plot", "fig2", "-o", "/dev/null") == ("option -o: cannot tell the format of '/dev/null' from "
                                                          "its extension; name it .svg, .pdf, .png or give --format.")
    run("plot", "fig2", "--format", "pdf", "-o", "/dev/null")


# --- item 7: ledger's -o and --format contradicting ------------------------------------------------------

@pytest.mark.parametrize("name, fmt", [("x.svg", "json"), ("x.png", "text"), ("x.pdf", "csv"), ("x.tex", "svg"),
                                       ("x.md", "pdf"), ("x.JSON", "png"), ("x.md", "latex"), ("x.csv", "json")])
def test_ledger_refuses_an_extension_that_contradicts_the_format(tmp_path, monkeypatch, name, fmt):
    monkeypatch.chdir(tmp_path)
    assert error_of("ledger", "fig2", "-o", name, "--format", fmt) == (f"option -o names {name!r} but --format is "
                                                                      f"{fmt}; make them agree.")
    assert list(tmp_path.iterdir()) == []


def test_ledger_still_writes_an_agreeing_or_unknown_extension(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    run("ledger", "fig2", "-o", "x.TXT", "--format", "text")
    run("ledger", "fig2", "-o", "table.dat", "--format", "json")
    run("ledger", "fig2", "-o", "x.svg", "--format", "svg")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["table.dat", "x.TXT", "x.svg"]
    assert (tmp_path / "table.dat").read_text().startswith('{\n "format": "sears-paradox-ledger/1"')


# --- item 9: handout --format tex -o DIR is DIR every time ------------------------------------------------

def test_handout_tex_writes_into_the_folder_named_every_time(tmp_path):
    folder = tmp_path / "pieces"
    first = run("handout", "fig2", "--format", "tex", "-o", folder, "-q")
    second = run("handout", "fig2", "--format", "tex", "-o", folder)
    assert first.output == ""
    assert (folder / "handout.tex").is_file() and not (folder / "fig2_handout").exists()
    printed = second.output.splitlines()
    assert printed and all(line.startswith(f"{folder}/") and line.endswith(" (unchanged)") for line in printed)
    assert {Path(line.split(" ")[0]).name for line in printed} == {p.name for p in folder.iterdir()}
