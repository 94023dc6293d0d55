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

from helpers import SHARED_PROCESS_GROUP, commands_in_one_process, register_shared_process, shared_process
from test_docs import documented_console_commands
from sears_paradox_cli.main import main

#: the commands page of the documentation (docs/commands.md), which names every command
COMMANDS_PAGE = (Path(__file__).resolve().parents[2] / "docs" / "commands.md").read_text()


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


def test_the_program_runs_main_with_the_collectors_thresholds_raised(monkeypatch):
    """The console script is `run`: `main` in a collector tuned for a short process, which the tests' own process
    (calling `main`) keeps out of."""
    import gc
    import tomllib

    from sears_paradox_cli import main as program

    scripts = tomllib.loads((Path(__file__).resolve().parents[2] / "pyproject.toml").read_text())["project"]["scripts"]
    assert scripts == {"sears-paradox": "sears_paradox_cli.main:run"}
    seen = []
    monkeypatch.setattr(program, "main", lambda: seen.append(gc.get_threshold()))
    monkeypatch.setattr(gc, "freeze", lambda: seen.append("frozen"))  # the test process's own objects stay as they are
    before = gc.get_threshold()
    try:
        program.run()
    finally:
        gc.set_threshold(*before)
    assert seen == [(100_000, 10, 10), "frozen"] and before[0] < 100_000


def test_version():
    from rodparadox import __version__

    assert run("--version").output.strip() == f"sears-paradox, version {__version__}"


@pytest.mark.parametrize("command", sorted(main.commands))
def test_every_command_has_help_with_an_example_and_is_in_the_documentation(command):
    for flag in ("--help", "-h"):
        text = run(command, flag).output
        assert re.search(rf"Example: sears-paradox {command}\b", text), text
    assert f"`sears-paradox {command}`" in COMMANDS_PAGE


@pytest.mark.parametrize("command", sorted(main.commands))
def test_every_help_example_runs_in_an_empty_folder(command, tmp_path, monkeypatch):
    """The example is what a new user types first, outside a checkout: it must work as printed."""
    monkeypatch.chdir(tmp_path)
    if command == "html":  # the same command on a coarser speed grid (tests/web/test_html.py checks the full page): 0.3 s, not 3
        import rodparadox.web.data as web_data

        monkeypatch.setattr(web_data, "SPEED_STEPS", 2)
        monkeypatch.setattr(web_data, "LEDGER_INSTANTS", 3)
    example = re.search(r"Example: sears-paradox (.+)", run(command, "--help").output).group(1)
    if f"sears-paradox {example}" in documented_console_commands():
        return  # tests/test_docs.py runs it as printed in the README or the documentation, its output compared
    run(*example.split())


def test_the_commands_share_one_module_and_plot_does_not_import_main():
    """cli.options and cli.edge hold what main and plot share; plot never imports main (main imports plot to register it)."""
    cli = Path(__file__).resolve().parents[2] / "cli"
    assert not re.search(r"from \.main import|import sears_paradox_cli\.main", (cli / "plot.py").read_text())
    plot_help = {p.name: p.help for p in main.commands["plot"].params}
    for command in ("events", "export"):
        helps = {p.name: p.help for p in main.commands[command].params}
        assert helps["v"] == plot_help["v"] and helps["L"] == plot_help["L"]


@pytest.mark.parametrize("command", ["events", "export", "plot"])
def test_any_library_error_is_one_sentence_and_exit_2(command, tmp_path, monkeypatch):
    """Every RodParadoxError is caught once, at the CLI edge: here one the frames module might raise."""
    import rodparadox.physics.frames
    import sears_paradox_cli.planning  # noqa: F401  imported before the patch below, which it would keep for good
    from rodparadox.errors import RodParadoxError

    class Refused(ValueError, RodParadoxError):
        pass

    def refuse(*args):
        raise Refused("frame velocity must be a number u with -1 < u < 1 (units of c), got 1.")

    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(rodparadox.physics.frames, "paper_frames", refuse)  # events, export
    monkeypatch.setattr(rodparadox.physics.frames, "Frame", refuse)  # plot
    assert error_of(command, "fig2") == "frame velocity must be a number u with -1 < u < 1 (units of c), got 1."
    assert list(tmp_path.iterdir()) == []


def test_list_names_every_builtin_with_a_line():
    lines = run("list").output.splitlines()
    names = [line.split()[0] for line in lines]
    assert names[:2] == ["fig1", "fig2"] and len(names) >= 5
    assert all(len(line.split(maxsplit=1)) == 2 for line in lines)


def test_events_table_fig2_rest_and_moving():
    out = run("events", "fig2", "--v", "0.6").output
    assert out.splitlines()[0] == "fig2: v = 0.6, L = 1   (c = 1; x and t in the unit L is given in)"
    # Fig. 2 in S: B1 at (L/2, L/2v); A1 at (L/2 - gL, L/2v + gvL); B2 at (L/2, L/2v + 2gvL); g = 1.25
    # each column of a frame shares its decimals: 7 digits in its largest (x: 0.75, t: 7/3), as many in the others
    assert "  B1     right  +0.5000000 +0.833333   -0.600000 -> +0.000000   +0.000000 -> -0.600000" in out
    assert "  A1     left   -0.7500000 +1.583333   +0.600000 -> -0.600000   -0.600000 -> +0.600000" in out
    assert "  B2     right  +0.5000000 +2.333333   +0.000000 -> +0.600000   +0.600000 -> +0.000000" in out
    # in S' B1 and A1 share t' = (gL/2v)(1 + v^2) = 17/12; A arrives at 2v/(1+v^2) = 15/17
    assert "  B1     right   +1.250000 +1.416667" in out
    assert "  A1     left    +0.250000 +1.416667   +0.882353 -> +0.000000" in out
    assert out.count("frame ") == 2


def _table_rows(out: str) -> list[str]:
    return [line for line in out.splitlines() if re.match(r"  [AB]\d", line)]


@pytest.mark.parametrize("args, rows", [
    # L = 1e-5: the numbers are in the unit L is given in, with their significant digits
    (("--L", "1e-5"), ["  B1     right  +5.000000e-06 +8.333333e-06   -0.600000 -> +0.000000   +0.000000 -> -0.600000",
                       "  A1     left   -7.500000e-06 +1.583333e-05   +0.600000 -> -0.600000   -0.600000 -> +0.600000"]),
    # L = 2: the right end is at x = 1 (not 0.5 "in the unit of L")
    (("--L", "2"), ["  B1     right  +1.000000 +1.666667   -0.600000 -> +0.000000   +0.000000 -> -0.600000"]),
    # v = 1e-6: the velocities keep their digits and no zero has a sign
    (("--v", "1e-6"), ["  B1     right  +0.5000000 +500000.0   -0.00000100000 -> +0.00000000000   "
                       "+0.00000000000 -> -0.00000100000"]),
])
def test_events_table_digits_fit_the_magnitudes(args, rows):
    out = run("events", "fig2", *args).output
    for row in rows:
        assert row in _table_rows(out)


def test_events_table_stays_aligned_for_huge_lengths_and_has_no_negative_zero(tmp_path):
    big = tmp_path / "big.yaml"
    big.write_text("v: 0.3\nL: 1.0e100\nparticles: {A: {gap: 0.25}, B: {gap: 0.5}}\n")
    for out in (run("events", str(big)).output, run("events", "fig2", "--v", "1e-6").output,
                run("events", "fig2", "--v", "0.9999999", "--frame-velocity", "-0.9999999").output):
        blocks = out.split("\n\n")[1:]
        for block in blocks:
            lines = block.splitlines()[1:]  # the header, then the rows
            ends = {len(line.split("->")[0]) for line in lines[1:]}  # the particle velocity's arrow, one column
            assert len(ends) == 1, block
            x_end = lines[0].index(" x") + 2
            assert all(line[x_end - 1] != " " for line in lines[1:]), block  # x right-aligned under its head
        assert not re.search(r"-0(\.0*)?(e[+-]\d+)?(?![\d.e])", out), out


def test_events_table_velocities_never_round_to_c():
    out = run("events", "fig2", "--v", "0.9999999", "--frame-velocity", "-0.9999999").output
    speeds = [float(u) for line in _table_rows(out) for u in re.findall(r"[-+]0\.\d+", line.split("  ", 4)[-1])]
    assert speeds and max(abs(u) for u in speeds) < 1
    assert "+0.9999999999999950 -> +0.000000" in out  # A's speed in S', 5e-15 below c, keeps its digits
    assert not re.search(r"[-+]1\.0+\b", out)


def test_a_velocity_that_rounds_to_c_is_refused(tmp_path):
    heavy = tmp_path / "heavy.yaml"
    heavy.write_text("v: 0.9999999\nparticles: {B: {gap: 0.5, mass: 1e9}}\n")
    message = ("in frame u=0.9999999 the rod's velocity after B1 is within 2.5e-22 of c, closer than double "
               "precision can write; choose a slower frame, a slower v or a lighter particle.")
    for command in ("events", "export"):
        assert error_of(command, str(heavy), "--frame-velocity", "0.9999999") == message


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
    from rodparadox.physics.rigid import run as simulate
    from rodparadox.physics.frames import Frame, view
    from rodparadox.io.scenario import load

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
     "option --frame-velocity: a frame velocity must be a number U with -0.9999999 <= U <= 0.9999999 (units of c) "
     "for double precision to place the events, got 1.5."),
    (("events", "fig9"), "there is no built-in scenario 'fig9' and no file of that name; built-in: "),
    (("export", "nowhere/my.yaml"), "scenario file 'nowhere/my.yaml' does not exist; check the path"),
    (("events", "fig2", "--v", "fast"), "Invalid value for '--v': 'fast' is not a valid float."),
    (("export", "fig2", "--format", "xml"), "Invalid value for '--format': 'xml' is not one of 'json', 'csv'."),
])
def test_bad_input_is_one_sentence_and_exit_2(args, message):
    assert error_of(*args).startswith(message)


@pytest.mark.parametrize("option, value, message", [
    ("--v", "1.0", "option --v: v must be a number with 0 < v < 1 (units of c), got 1."),
    ("--v", "0.0", "option --v: v must be a number with 0 < v < 1 (units of c), got 0."),
    ("--v", "-0.5", "option --v: v must be a number with 0 < v < 1 (units of c), got -0.5."),
    ("--v", "nan", "option --v: v must be a number with 0 < v < 1 (units of c), got nan."),
    ("--v", "1e-9", "option --v: v must be between 1e-06 and 0.9999999 for double precision to place the impacts, "
                    "got 1e-09."),
    ("--v", "0.99999999", "option --v: v must be between 1e-06 and 0.9999999 for double precision to place the "
                          "impacts, got 0.99999999."),
    ("--L", "0.0", "option --L: L must be a positive length (the rod's proper length), got 0."),
    ("--L", "inf", "option --L: L must be a positive length (the rod's proper length), got inf."),
])
@pytest.mark.parametrize("command", ["events", "export"])
def test_bad_overrides_name_the_option(command, option, value, message):
    """The library's error keeps the key (test_scenario); the command line names it as its option."""
    assert error_of(command, "fig1", option, value) == message


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

    from rodparadox.io import output
    from rodparadox.errors import OutputError

    target = tmp_path / "keep.json"
    target.write_text("old")

    def broken_replace(src, dst):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "replace", broken_replace)
    with pytest.raises(OutputError, match="no space left on device"):
        output.write_atomic(target, b"new")
    assert target.read_text() == "old" and [p.name for p in tmp_path.iterdir()] == ["keep.json"]


#: the commands that draw nothing: each was a process of its own, now they run one after another in one
NON_DRAWING = [["--help"], ["list"], ["events", "fig2"], ["export", "fig2"], ["plot", "--help"], ["ledger", "fig2"],
               ["ledger", "fig2", "--format", "json", "--at", "1"], ["ledger", "--help"],
               ["events", "fig2", "--format", "markdown"], ["events", "fig2", "--format", "latex"],
               ["ledger", "fig2", "--format", "markdown", "--at", "1"], ["ledger", "fig2", "--format", "latex"]]


register_shared_process("non_drawing", NON_DRAWING, draws=False)


@pytest.mark.xdist_group(SHARED_PROCESS_GROUP)
def test_non_drawing_paths_never_import_matplotlib():
    """Nor scipy: only a causal rod needs an integrator (issue 16, item 8). The commands run in one fresh
    interpreter, one after another (a process each cost 12 interpreters): what is imported accumulates, so the
    first command after which matplotlib or scipy is there is the one that imported it, and is named. The
    interpreter is helpers.shared_process's: before these only other tests' commands that draw nothing (refused
    inputs, help, an export); those that draw come after."""
    results, _ = shared_process("non_drawing")
    assert [r["argv"] for r in results] == NON_DRAWING
    assert not {"matplotlib", "scipy"} & set(results[0]["modules_before"]), "imported by another test's command"
    for result in results:
        assert not {"matplotlib", "scipy"} & set(result["modules"]), (result["argv"], result["modules"])
        assert (result["code"], result["left_unflushed"]) == (0, None), result


# --- export: no negative zero, the format from the extension, output paths, empty values (items 10, 12, 15) ---

def test_export_writes_no_negative_zero():
    text = run("export", "fig2").output
    assert "-0.0," not in text and "-0.0\n" not in text and "-0.0]" not in text
    assert json.loads(text)["frames"]["rest"]["rod_velocity_before"] == 0.0
    csv_text = run("export", "fig2", "--format", "csv", "--v", "0.3").output
    assert not re.search(r",-0\.0(,|$)", csv_text, re.M)


@pytest.mark.parametrize("name, kind", [("fig2.csv", "csv"), ("fig2.json", "json"), ("FIG2.CSV", "csv")])
def test_export_takes_the_format_from_the_extension(tmp_path, name, kind):
    target = tmp_path / name
    assert run("export", "fig2", "-o", str(target)).output == f"{target}\n"
    text = target.read_text()
    assert text.startswith("frame,kind,name") if kind == "csv" else json.loads(text)["format"] == "sears-paradox/1"


def test_export_prints_an_unchanged_file_as_unchanged_and_quiet_prints_nothing(tmp_path):
    target = tmp_path / "fig2.json"
    assert run("export", "fig2", "-o", str(target), "-q").output == ""
    assert run("export", "fig2", "-o", str(target)).output == f"{target} (unchanged)\n"
    assert run("export", "fig2", "-o", str(target), "--quiet").output == ""


@pytest.mark.parametrize("args, message", [
    (("--format", "csv", "-o", "x.json"), "option -o names 'x.json' but --format is csv; make them agree."),
    (("-o", "x.JSON", "--format", "csv"), "option -o names 'x.JSON' but --format is csv; make them agree."),
    (("-o", "x.txt"), "option -o: cannot tell the format of 'x.txt' from its extension; name it .json, .csv or "
                      "give --format."),
    (("-o", ""), "option -o must name a file or folder, got ''."),
    (("-o", " "), "option -o must name a file or folder, got ' '."),
    (("--format", ""), "Invalid value for '--format': '' is not one of 'json', 'csv'."),
])
def test_export_refuses_a_contradictory_unknown_or_empty_output(tmp_path, monkeypatch, args, message):
    monkeypatch.chdir(tmp_path)
    assert error_of("export", "fig2", *args) == message
    assert list(tmp_path.iterdir()) == []


def test_export_with_a_format_writes_any_name(tmp_path):
    target = tmp_path / "data.txt"
    run("export", "fig2", "--format", "csv", "-o", str(target))
    assert target.read_text().startswith("frame,kind,name")


def test_export_to_a_dangling_link_says_where_it_leads(tmp_path):
    link = tmp_path / "d.json"
    link.symlink_to(tmp_path / "gone" / "x.json")
    assert error_of("export", "fig2", "-o", str(link)) == (
        f"cannot write {link}: it is a symbolic link to {tmp_path}/gone/x.json, whose folder {tmp_path}/gone "
        f"does not exist.")
    other = tmp_path / "e.json"  # a dangling link into an existing folder: the target is created, the link kept
    other.symlink_to("target.json")
    run("export", "fig2", "-o", str(other))
    assert other.is_symlink() and json.loads((tmp_path / "target.json").read_text())["format"] == "sears-paradox/1"


def test_empty_scenario_is_refused():
    assert error_of("events", "") == "SCENARIO is empty; give a built-in name (see 'sears-paradox list') or a YAML file."


# --- frame velocity: one bound, one name (item 9) -------------------------------------------------------------

@pytest.mark.parametrize("u", ["0.9999999999999999", "0.99999999", "-0.99999995", "1", "inf", "nan"])
def test_frame_velocity_beyond_the_bound_is_refused(u):
    assert error_of("export", "fig2", "--frame-velocity", u) == (
        "option --frame-velocity: a frame velocity must be a number U with -0.9999999 <= U <= 0.9999999 (units of c) "
        f"for double precision to place the events, got {float(u)!r}.")


@pytest.mark.parametrize("u, name", [("0.9999999", "u=0.9999999"), ("-0.9999999", "u=-0.9999999"), ("0", "u=0"),
                                     ("-0", "u=0"), ("0.30000000000000004", "u=0.30000000000000004"),
                                     ("1e-7", "u=1e-07"), ("0.123456789012", "u=0.123456789012")])
def test_frame_velocity_names_keep_every_digit(u, name):
    doc = json.loads(run("export", "fig2", "--frame-velocity", u).output)
    assert list(doc["frames"]) == ["rest", "moving", name]
    frame = doc["frames"][name]
    assert frame["velocity"] == float(u) + 0.0
    assert all(abs(e[k]) < 1 for e in frame["events"] for k in e if k.endswith("velocity_before") or
               k.endswith("velocity_after"))


def test_frames_library_names_and_bounds_frames():
    from rodparadox.errors import FrameError
    from rodparadox.physics.frames import check_velocity, FASTEST_FRAME, frame_of_velocity
    from rodparadox.physics.model import FASTEST

    assert FASTEST_FRAME == FASTEST
    assert frame_of_velocity(-0.0).name == "u=0" and frame_of_velocity(0.5).name == "u=0.5"
    assert frame_of_velocity(0.1 + 0.2).name != frame_of_velocity(0.3).name
    assert check_velocity(FASTEST) == FASTEST and check_velocity(-FASTEST) == -FASTEST
    for bad in (math.nextafter(FASTEST, 1), math.nan, True, "0.3"):
        with pytest.raises(FrameError):
            check_velocity(bad)


# --- write errors: one sentence, exit 1; a closed pipe: quiet (item 8) --------------------------------------

@pytest.mark.skipif(not Path("/dev/full").exists(), reason="needs /dev/full")
def test_a_full_standard_output_is_one_sentence_and_exit_1(tmp_path):
    """Each command once had a process of its own; now they run one after another in one interpreter whose
    standard output is /dev/full again before each (a failed write points it at /dev/null), each with its own
    status and standard error."""
    argvs = [("events", "fig2"), ("export", "fig2"), ("export", "fig2", "--format", "csv"), ("list",), ("--help",),
             ("plot", "--help"), ("--version",)]
    for result in commands_in_one_process(argvs, tmp_path, stdout_path="/dev/full"):
        assert (result["code"], result["stderr"], result["left_unflushed"]) == (
            1, b"Error: cannot write to standard output: no space left on device.\n", None), result


TO_FULL_DEVICE = ["export", "fig2", "--format", "json", "-o", "/dev/full"]
if Path("/dev/full").exists():
    register_shared_process("full_device", [TO_FULL_DEVICE], draws=False)


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="needs /dev/full")
@pytest.mark.xdist_group(SHARED_PROCESS_GROUP)
def test_a_full_device_as_output_file_is_one_sentence_and_exit_1():
    """In helpers.shared_process's interpreter (a process of its own before), with its own status and error."""
    [result], _ = shared_process("full_device")
    assert result["argv"] == TO_FULL_DEVICE
    assert (result["code"], result["stderr"], result["left_unflushed"]) == (
        1, b"Error: cannot write /dev/full: no space left on device.\n", None), result


def test_a_closed_pipe_ends_quietly():
    for args in (["export", "fig2", "--format", "csv", "--v", "0.99"], ["events", "fig2"]):
        process = subprocess.Popen(_cli_prefix() + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        process.stdout.readline()
        process.stdout.close()  # as `| head -1` does
        stderr = process.stderr.read().decode()
        process.wait(timeout=60)
        assert stderr == "" and process.returncode in (0, 141), (stderr, process.returncode)


def _cli_prefix() -> list[str]:
    script = Path(sys.executable).parent / "sears-paradox"
    return [str(script)] if script.exists() else [sys.executable, "-c", "from sears_paradox_cli.main import main; main()"]


CLICKS_OWN_CHECKS = [
    (["plot", "fig2", "--style", "fancy"], "Invalid value for '--style': 'fancy' is not one of 'default', 'print', "
                                           "'slides'."),
    (["plot", "fig2", "--rod-lines", "-1"], "Invalid value for '--rod-lines': -1 is not in the range 0<=x<=50."),
    (["events", "fig2", "--v", ""], "Invalid value for '--v': '' is not a valid float."),
    (["nope"], "No such command 'nope'."),
]
register_shared_process("clicks_own_checks", [argv for argv, _ in CLICKS_OWN_CHECKS], draws=False)


@pytest.mark.xdist_group(SHARED_PROCESS_GROUP)
def test_clicks_own_checks_are_one_sentence_too():
    """Found in review: click's usage errors printed three lines (Usage, Try, Error); now one sentence, exit 2.
    The four calls (a process each before) run one after another in one interpreter (helpers.shared_process's),
    each with its own status and output."""
    calls = CLICKS_OWN_CHECKS
    results, _ = shared_process("clicks_own_checks")
    assert [r["argv"] for r in results] == [argv for argv, _ in calls]
    for result, (argv, message) in zip(results, calls):
        assert (result["code"], result["stdout"], result["stderr"]) == (2, b"", f"Error: {message}\n".encode()), result


def test_every_package_of_the_source_is_installed():
    """A non-editable install takes only the packages pyproject.toml names: rodparadox.render once went missing
    (`pip install .` then failed with ImportError on every drawing command; the editable test install hid it)."""
    root = Path(__file__).resolve().parents[2]
    line = re.search(r"^packages = \[(.*?)\]$", (root / "pyproject.toml").read_text(), re.M | re.S).group(1)
    listed = set(re.findall(r'"([\w.]+)"', line))
    found = {".".join(p.relative_to(root).parent.parts) for p in (root / "rodparadox").rglob("__init__.py")}
    assert found <= listed, found - listed
