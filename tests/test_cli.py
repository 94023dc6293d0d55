"""The command line: every command, its help, the JSON/CSV contract parsed back, and bad input (message + exit 2)."""

import csv
import io
import json
import math
import re
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from sears_paradox_cli.main import main

README = (Path(__file__).resolve().parent.parent / "README.md").read_text()


def run(*args, expect=0):
    result = CliRunner().invoke(main, list(args))
    assert result.exit_code == expect, (result.output, result.exception)
    return result


def error_of(*args) -> str:
    """The one-sentence error a bad call prints; it must exit 2 and print no traceback."""
    result = run(*args, expect=2)
    assert isinstance(result.exception, SystemExit), result.exception  # a ClickException, not a crash
    lines = [line for line in result.output.splitlines() if line.startswith("Error: ")]
    assert len(lines) == 1, result.output
    return lines[0][len("Error: "):]


def test_version():
    from rodparadox import __version__

    assert run("--version").output.strip() == f"sears-paradox, version {__version__}"


@pytest.mark.parametrize("command", sorted(main.commands))
def test_every_command_has_help_with_an_example_and_is_in_the_readme(command):
    for flag in ("--help", "-h"):
        text = run(command, flag).output
        assert re.search(rf"Example: sears-paradox {command}\b", text), text
    assert f"sears-paradox {command}" in README


@pytest.mark.parametrize("command", sorted(main.commands))
def test_every_help_example_runs_in_an_empty_folder(command, tmp_path, monkeypatch):
    """The example is what a new user types first, outside a checkout: it must work as printed."""
    monkeypatch.chdir(tmp_path)
    example = re.search(r"Example: sears-paradox (.+)", run(command, "--help").output).group(1)
    run(*example.split())


def test_the_commands_share_one_module_and_plot_does_not_import_main():
    """cli.common holds what main and plot share; plot never imports main (main imports plot to register it)."""
    cli = Path(__file__).resolve().parent.parent / "cli"
    assert not re.search(r"from \.main import|import sears_paradox_cli\.main", (cli / "plot.py").read_text())
    plot_help = {p.name: p.help for p in main.commands["plot"].params}
    for command in ("events", "export"):
        helps = {p.name: p.help for p in main.commands[command].params}
        assert helps["v"] == plot_help["v"] and helps["L"] == plot_help["L"]


@pytest.mark.parametrize("command", ["events", "export", "plot"])
def test_any_library_error_is_one_sentence_and_exit_2(command, tmp_path, monkeypatch):
    """Every RodParadoxError is caught once, at the CLI edge: here one the frames module might raise."""
    import rodparadox.frames
    from rodparadox.errors import RodParadoxError

    class Refused(ValueError, RodParadoxError):
        pass

    def refuse(*args):
        raise Refused("frame velocity must be a number u with -1 < u < 1 (units of c), got 1.")

    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(rodparadox.frames, "paper_frames", refuse)  # events, export
    monkeypatch.setattr(rodparadox.frames, "Frame", refuse)  # plot
    assert error_of(command, "fig2") == "frame velocity must be a number u with -1 < u < 1 (units of c), got 1."
    assert list(tmp_path.iterdir()) == []


def test_list_names_every_builtin_with_a_line():
    lines = run("list").output.splitlines()
    names = [line.split()[0] for line in lines]
    assert names[:2] == ["fig1", "fig2"] and len(names) >= 5
    assert all(len(line.split(maxsplit=1)) == 2 for line in lines)


def test_events_table_fig2_rest_and_moving():
    out = run("events", "fig2", "--v", "0.6").output
    # Fig. 2 in S: B1 at (L/2, L/2v); A1 at (L/2 - gL, L/2v + gvL); B2 at (L/2, L/2v + 2gvL); g = 1.25
    assert "  B1     right    +0.500000   +0.833333   -0.600000 -> +0.000000   +0.000000 -> -0.600000" in out
    assert "  A1     left     -0.750000   +1.583333   +0.600000 -> -0.600000   -0.600000 -> +0.600000" in out
    assert "  B2     right    +0.500000   +2.333333   +0.000000 -> +0.600000   +0.600000 -> +0.000000" in out
    # in S' B1 and A1 share t' = (gL/2v)(1 + v^2) = 17/12; A arrives at 2v/(1+v^2) = 15/17
    assert "  B1     right    +1.250000   +1.416667" in out
    assert "  A1     left     +0.250000   +1.416667   +0.882353 -> +0.000000" in out
    assert out.count("frame ") == 2


def test_events_with_an_extra_frame():
    out = run("events", "fig1", "--frame-velocity", "0.6").output
    assert "frame u=0.6: velocity +0.6 relative to S; the rod first moves at -0.6" in out
    # in the frame of velocity +v, B (velocity -v in S) moves at -2v/(1+v^2)
    assert "-0.882353 -> +0.000000" in out


def test_export_json_contract_fig1():
    v, L = 0.5, 2.0
    doc = json.loads(run("export", "fig1", "--v", str(v), "--L", str(L)).output)
    assert doc["format"] == "sears-paradox/1"
    assert set(doc["frames"]) == {"rest", "moving"}
    rest, moving = doc["frames"]["rest"], doc["frames"]["moving"]
    assert rest["velocity"] == 0.0 and moving["velocity"] == -v
    # Fig. 1a: both impacts at t = L/2v, at the ends
    events = {e["label"]: e for e in rest["events"]}
    assert set(events) == {"A1", "B1"}
    assert (events["A1"]["particle"], events["A1"]["end"]) == ("A", "left")
    assert events["A1"]["x"] == pytest.approx(-L / 2, rel=1e-12) and events["A1"]["t"] == pytest.approx(L / (2 * v), rel=1e-12)
    assert events["B1"]["x"] == pytest.approx(L / 2, rel=1e-12) and events["B1"]["t"] == pytest.approx(L / (2 * v), rel=1e-12)
    g = 1 / math.sqrt(1 - v * v)
    moved = {e["label"]: e for e in moving["events"]}
    assert moved["A1"]["t"] == pytest.approx(g * (L / (2 * v) - v * L / 2), rel=1e-12)  # t' = g(t + v x)
    assert moved["A1"]["t"] < moved["B1"]["t"]  # in S' A strikes first
    for frame in (rest, moving):
        assert set(frame["worldlines"]) == {"A", "B", "rod_left", "rod_right"}
        first = min(e["t"] for e in frame["events"])
        last = max(e["t"] for e in frame["events"])
        for name, points in frame["worldlines"].items():
            ts = [t for _, t in points]
            assert ts == sorted(ts) and ts[0] < first and ts[-1] > last, name
        for e in frame["events"]:  # every impact is a kink point of the particle's and the end's world-line
            for name in (e["particle"], f"rod_{e['end']}"):
                assert any(math.hypot(x - e["x"], t - e["t"]) < 1e-12 * L for x, t in frame["worldlines"][name])


def test_export_json_round_trips_the_library_floats_exactly():
    from rodparadox.engine import run as simulate
    from rodparadox.frames import Frame, view
    from rodparadox.scenario import load

    doc = json.loads(run("export", "fig2", "--v", "0.7").output)
    fv = view(simulate(load("fig2").with_overrides(v=0.7)), Frame("moving", -0.7))
    assert [(e["x"], e["t"]) for e in doc["frames"]["moving"]["events"]] == [(e.x, e.t) for e in fv.events]


def test_export_segments_are_exact_arcs_in_each_frame():
    doc = json.loads(run("export", "fig2", "--v", "0.6").output)
    arcs = [s for s in doc["frames"]["rest"]["segments"]["rod_left"] if s["kind"] == "arc"]
    # the left end's first arc: centred on B1 = (L/2, L/2v), radius L, on the left branch
    assert arcs[0]["centre"] == pytest.approx([0.5, 0.5 / 0.6], rel=1e-12)
    assert (arcs[0]["radius"], arcs[0]["side"]) == (1.0, -1)
    for s in arcs:
        for key in ("start", "end"):
            x, t = s[key]
            cx, ct = s["centre"]
            assert (x - cx) ** 2 - (t - ct) ** 2 == pytest.approx(s["radius"] ** 2, rel=1e-12)


def test_export_csv_parses_and_matches_json():
    doc = json.loads(run("export", "fig2").output)
    rows = list(csv.DictReader(io.StringIO(run("export", "fig2", "--format", "csv").output)))
    assert list(rows[0]) == ["frame", "kind", "name", "particle", "end", "index", "x", "t"]
    events = [(r["frame"], r["name"], float(r["x"]), float(r["t"])) for r in rows if r["kind"] == "event"]
    expected = [(f, e["label"], e["x"], e["t"]) for f, fr in doc["frames"].items() for e in fr["events"]]
    assert events == expected
    points = [[float(r["x"]), float(r["t"])] for r in rows if r["kind"] == "worldline" and r["frame"] == "moving"
              and r["name"] == "rod_right"]
    assert points == doc["frames"]["moving"]["worldlines"]["rod_right"]


def test_export_to_a_file_is_quiet_and_leaves_an_unchanged_file_alone(tmp_path):
    target = tmp_path / "fig2.json"
    assert run("export", "fig2", "-o", str(target)).output == f"{target}\n"
    before = target.stat().st_mtime_ns
    first = target.read_bytes()
    run("export", "fig2", "-o", str(target))
    assert target.read_bytes() == first and target.stat().st_mtime_ns == before
    assert json.loads(first) == json.loads(run("export", "fig2").output)


def test_export_is_byte_identical_twice():
    assert run("export", "fig2", "--v", "0.3").output == run("export", "fig2", "--v", "0.3").output


@pytest.mark.parametrize("args, message", [
    (("events", "fig2", "--v", "1"), "option --v: v must be a number with 0 < v < 1 (units of c), got 1."),
    (("events", "fig2", "--v", "0"), "option --v: v must be a number with 0 < v < 1 (units of c), got 0."),
    (("export", "fig1", "--L", "-2"), "option --L: L must be a positive length (the rod's proper length), got -2."),
    (("export", "fig1", "--v", "nan"), "option --v: v must be a number with 0 < v < 1 (units of c), got nan."),
    (("events", "fig1", "--frame-velocity", "1.5"),
     "option --frame-velocity must be a velocity u with -1 < u < 1 (units of c), got 1.5."),
    (("events", "fig9"), "there is no built-in scenario 'fig9' and no file of that name; built-in: "),
    (("export", "nowhere/my.yaml"), "scenario file 'nowhere/my.yaml' does not exist; check the path"),
    (("events", "fig2", "--v", "fast"), "Invalid value for '--v': 'fast' is not a valid float."),
    (("export", "fig2", "--format", "xml"), "Invalid value for '--format': 'xml' is not one of 'json', 'csv'."),
])
def test_bad_input_is_one_sentence_and_exit_2(args, message):
    assert error_of(*args).startswith(message)


def test_bad_scenario_file_names_file_key_and_line(tmp_path):
    bad = tmp_path / "my.yaml"
    bad.write_text("v: 0.6\nparticles:\n  A: {gap: 0.5, spead: 0.3}\n")
    assert error_of("events", str(bad)) == (f"{bad}, line 3: unknown key 'spead' in particles.A "
                                            "(allowed: mass, speed, gap, timed_with); did you mean speed?")


def test_contradictory_timing_is_refused(tmp_path):
    bad = tmp_path / "early.yaml"
    bad.write_text("v: 0.5\nparticles:\n  A: {timed_with: {particle: B, frame: rest, delay: -0.3}}\n  B: {gap: 0.1}\n")
    assert error_of("events", str(bad)) == (
        f"{bad}: particles.A.timed_with: A cannot strike the rod with delay -0.3 after B's first impact, because "
        "its impact would come first in the rod's own time and move B's; time B against A instead, or give A a gap.")


def test_export_to_a_missing_folder_writes_nothing(tmp_path):
    target = tmp_path / "no" / "such" / "out.json"
    message = error_of("export", "fig2", "-o", str(target))
    assert message == f"cannot write {target}: the folder {target.parent} does not exist; create it first."
    assert not (tmp_path / "no").exists()


def test_export_to_an_unwritable_folder_writes_nothing(unwritable_folder):
    folder = unwritable_folder
    before = sorted(folder.iterdir())
    message = error_of("export", "fig2", "-o", str(folder / "x.json"))
    assert message == f"cannot write {folder / 'x.json'}: permission denied in the folder {folder}."
    assert sorted(folder.iterdir()) == before


def test_failed_write_leaves_the_old_file_and_no_temporary(tmp_path, monkeypatch):
    import os

    from rodparadox import output
    from rodparadox.errors import OutputError

    target = tmp_path / "keep.json"
    target.write_text("old")

    def broken_replace(src, dst):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "replace", broken_replace)
    with pytest.raises(OutputError, match="no space left on device"):
        output.write_atomic(target, b"new")
    assert target.read_text() == "old" and [p.name for p in tmp_path.iterdir()] == ["keep.json"]


@pytest.mark.parametrize("argv", [["--help"], ["list"], ["events", "fig2"], ["export", "fig2"], ["plot", "--help"]])
def test_non_drawing_paths_never_import_matplotlib(argv):
    code = ("import sys\nfrom sears_paradox_cli.main import main\n"
            f"try:\n    main({argv!r})\nexcept SystemExit:\n    pass\n"
            "sys.stderr.write('MPL' if any(m.startswith('matplotlib') for m in sys.modules) else 'CLEAN')\n")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert result.stderr.endswith("CLEAN"), result.stderr[-500:]
