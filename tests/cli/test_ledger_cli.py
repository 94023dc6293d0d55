"""`sears-paradox ledger`: its text, JSON and CSV against hand-derived values, its figure, its bad input, the README."""

from __future__ import annotations

import csv
import io
import json
import math
import os
import re
import xml.etree.ElementTree as ET
from pathlib import Path

import matplotlib
import pytest
from click.testing import CliRunner

from rodparadox.physics.rigid import run as simulate
from rodparadox.physics.rigid.turns import turn_interval
from rodparadox.io.scenario import load
from sears_paradox_cli.ledger import ledger
from sears_paradox_cli.main import main

from helpers import blank_figure

ROOT = Path(__file__).resolve().parents[2]
#: the ledger's page of the documentation
LEDGER_PAGE = (ROOT / "docs" / "ledger.md").read_text()


def run(*args: str):
    return CliRunner().invoke(main, ["ledger", *args])


def error_of(*args: str) -> str:
    result = run(*args)
    assert result.exit_code == 2, result.output
    lines = [line for line in result.output.splitlines() if line.startswith("Error: ")]
    assert len(lines) == 1, result.output
    return lines[0][len("Error: "):]


@pytest.fixture
def in_tmp(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    return tmp_path


def g_of(v: float) -> float:
    return 1 / math.sqrt(1 - v * v)


# --- tables -----------------------------------------------------------------------------------------

@pytest.mark.parametrize("v, L", [(0.6, 1.0), (0.37, 2.5)])
def test_json_hidden_part_of_fig1_in_S_prime_between_the_impacts(v, L):
    """By hand (README, the model's ledger section): (2 g^2 v^2, 2 g^2 v) between A1 and B1 in S', 0 outside; in S 0."""
    a1, b1 = L / (2 * v) * (1 - v * v) * g_of(v), L / (2 * v) * (1 + v * v) * g_of(v)  # t' = g(t + v x), x = -+L/2
    middle = 0.5 * (a1 + b1)
    doc = json.loads(run("fig1", "--v", str(v), "--L", str(L), "--format", "json",
                         "--at", f"{a1 - 0.1 * L},{middle},{b1 + 0.1 * L}").output)
    assert doc["format"] == "sears-paradox-ledger/1" and list(doc["frames"]) == ["rest", "moving"]
    moving = doc["frames"]["moving"]
    assert [i["label"] for i in moving["impacts"]] == ["A1", "B1"]
    assert [i["t"] for i in moving["impacts"]] == [pytest.approx(a1, rel=1e-12), pytest.approx(b1, rel=1e-12)]
    g = g_of(v)
    hidden = [(s["hidden"]["E"], s["hidden"]["p"]) for s in moving["slices"]]
    assert hidden[0] == (pytest.approx(0, abs=1e-12), pytest.approx(0, abs=1e-12))
    assert hidden[1] == (pytest.approx(2 * g * g * v * v, rel=1e-12), pytest.approx(2 * g * g * v, rel=1e-12))
    assert hidden[2] == (pytest.approx(0, abs=1e-12), pytest.approx(0, abs=1e-12))
    # the total in S': the rod at v (g, g v), A at 2v/(1 + v^2) (g^2 (1 + v^2), 2 g^2 v), B at rest (1, 0)
    assert moving["total"] == {"E": pytest.approx(g + g * g * (1 + v * v) + 1, rel=1e-12),
                               "p": pytest.approx(g * v + 2 * g * g * v, rel=1e-12)}
    rest = doc["frames"]["rest"]
    assert rest["total"] == {"E": pytest.approx(1 + 2 * g, rel=1e-14), "p": pytest.approx(0, abs=1e-14)}
    for s in rest["slices"]:
        assert (s["hidden"]["E"], s["hidden"]["p"]) == (pytest.approx(0, abs=1e-12), pytest.approx(0, abs=1e-12))


def test_text_table_of_fig1_in_S_prime():
    out = run("fig1", "--frame", "moving", "--at", "0.5,1,1.5").output
    assert out.startswith("fig1: v = 0.6, L = 1; E in M c^2, p in M c")
    assert "frame moving (S', where the rod first moves at +v): velocity -0.6 relative to S" in out
    assert "all bodies before the first impact: E = 4.375, p = 2.625" in out  # 1.25 + 2.125 + 1, 0.75 + 1.875
    block = out.split("impact A1")[1].split("impact B1")[0]
    assert re.search(r"hidden\s+0\.0000\s+0\.0000\s+1\.1250\s+1\.8750", block)  # 2 g^2 v^2, 2 g^2 v at v = 0.6
    assert "impulse of A1 to the rod: E 1.1250, p 1.8750" in block
    rows = out.split("slices")[1].splitlines()[2:]
    assert rows[1].split() == ["1", "1", "0", "1", "0", "1.25", "0.75", "3.25", "0.75", "1.125", "1.875"]


def test_json_slices_without_at_hold_every_turn_start_and_end_and_add_up():
    history = simulate(load("fig2"))
    doc = json.loads(run("fig2", "--format", "json").output)
    for name, eta in (("rest", 0.0), ("moving", -math.atanh(0.6))):
        frame = doc["frames"][name]
        times = [s["t"] for s in frame["slices"]]
        assert times == sorted(times) and len(times) >= 240
        for turn in history.turns:
            for t in turn_interval(turn, eta):
                assert any(abs(t - u) <= 1e-12 for u in times)
        assert [(t["start"], t["end"]) for t in frame["turns"]] == [
            pytest.approx(turn_interval(turn, eta), rel=1e-12) for turn in history.turns]
        total = frame["total"]
        for s in frame["slices"]:
            bodies = s["bodies"]
            for q in ("E", "p"):
                assert sum(b[q] for b in bodies.values()) == pytest.approx(s["kinetic"][q], abs=1e-12)
                assert s["kinetic"][q] + s["hidden"][q] == pytest.approx(total[q], abs=1e-12)
        for i in frame["impacts"]:
            for q in ("E", "p"):
                assert i["impulse"][q] == pytest.approx(i["particle_before"][q] - i["particle_after"][q], abs=1e-15)
                # the dynamical rod takes the whole impulse
                assert i["rod_dynamical_after"][q] - i["rod_dynamical_before"][q] == pytest.approx(i["impulse"][q],
                                                                                                   abs=1e-12)
    assert not re.search(r"-0\.0[,}\]]", json.dumps(doc))  # no negative zero


def test_csv_holds_the_json_numbers():
    doc = json.loads(run("fig2", "--format", "json", "--at", "1,2").output)
    rows = list(csv.DictReader(io.StringIO(run("fig2", "--format", "csv", "--at", "1,2").output)))
    assert list(rows[0]) == ["frame", "kind", "label", "t", "body", "E", "p"]
    for frame, content in doc["frames"].items():
        for s in content["slices"]:
            for body, em in [*s["bodies"].items(), ("kinetic", s["kinetic"]), ("hidden", s["hidden"])]:
                row = next(r for r in rows if (r["frame"], r["kind"], r["body"]) == (frame, "slice", body)
                           and float(r["t"]) == s["t"])
                assert (float(row["E"]), float(row["p"])) == (em["E"], em["p"])
        for i in content["impacts"]:
            row = next(r for r in rows if (r["frame"], r["kind"], r["label"]) == (frame, "impulse", i["label"]))
            assert (float(row["E"]), float(row["p"])) == (i["impulse"]["E"], i["impulse"]["p"])


def test_tables_go_to_a_file_atomically_and_say_unchanged(in_tmp):
    assert run("fig2", "-o", "l.json").output == "l.json\n"
    assert json.loads(Path("l.json").read_text())["format"] == "sears-paradox-ledger/1"
    assert run("fig2", "-o", "l.json").output == "l.json (unchanged)\n"
    assert run("fig2", "-o", "l.csv", "-q").output == "" and Path("l.csv").read_text().startswith("frame,kind")
    assert run("fig2", "-o", "l.txt").output == "l.txt\n" and Path("l.txt").read_text().startswith("fig2: v = 0.6")


# --- the figure ---------------------------------------------------------------------------------------

def test_the_figure_is_named_as_plot_names_its_figures_and_is_deterministic(in_tmp, monkeypatch):
    assert run("fig2").output.startswith("fig2: v = 0.6")  # no format, no -o: the text table
    assert run("fig2", "--format", "svg").output == "outputs/fig2_ledger.svg\n"
    stamp = os.stat("outputs/fig2_ledger.svg").st_mtime_ns
    # the same command again, the same bytes: "(unchanged)" is said only when the file already holds exactly the
    # bytes drawn (io.output.write_atomic compares them), and the file is left alone (a third run after removing
    # the file, comparing the bytes read back, showed this again; across processes: test_determinism's ledger)
    assert run("fig2", "--format", "svg").output == "outputs/fig2_ledger.svg (unchanged)\n"
    assert os.stat("outputs/fig2_ledger.svg").st_mtime_ns == stamp
    # the other names and formats: each figure blank (an empty figure), written by its real writer
    from rodparadox.render import ledger_figure

    monkeypatch.setattr(ledger_figure, "draw", blank_figure)
    assert run("fig2", "--v", "0.8", "--style", "print", "--format", "svg,pdf").output == (
        "outputs/fig2_ledger_v0.8_print.svg\noutputs/fig2_ledger_v0.8_print.pdf\n")
    assert run("fig2", "--frame", "moving", "-o", "m.png").output == "m.png\n"
    assert Path("m.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    pdf = Path("outputs/fig2_ledger_v0.8_print.pdf").read_bytes()
    assert b"CreationDate" not in pdf and b"Producer" not in pdf


def test_the_figure_draws_every_curve_in_every_frame_with_its_impacts(in_tmp):
    run("fig2", "--frame", "both,0.3", "--format", "svg")
    root = ET.parse("outputs/fig2_ledger_both_u0.3.svg").getroot()
    ids = {g.get("id") for g in root.iter("{http://www.w3.org/2000/svg}g")}
    for letter in "abc":
        for q in ("p", "E"):
            for what in ("A", "B", "rod", "kinetic", "total", "hidden", "impact-B1", "impact-A1", "impact-B2"):
                assert f"{letter}-{q}-{what}" in ids, (letter, q, what)
        for label in ("B1", "A1", "B2"):
            assert f"{letter}-label-{label}" in ids
    assert "legend" in ids and "title" in ids


def test_the_figure_values_are_the_ledgers():
    """The drawn kinetic total is the ledger's, and at an impact the curve jumps from before to after."""
    from rodparadox.render import ledger_figure
    from rodparadox.physics.frames import Frame
    from rodparadox.physics.ledger import impact_entries

    history = simulate(load("fig1"))
    frame = Frame("moving", -0.6)
    figure = ledger_figure.draw(history, (frame,), "default")
    kinetic = next(a for ax in figure.axes for a in ax.lines if a.get_gid() == "a-p-kinetic")
    t, p = kinetic.get_data()
    for e in impact_entries(history, frame.rapidity):
        k = [j for j, x in enumerate(t) if abs(x - e.t) < 1e-12]
        assert len(k) == 2  # the instant twice: just before, then just after
        assert (p[k[0]], p[k[1]]) == (pytest.approx(e.kinetic_before.p), pytest.approx(e.kinetic_after.p))


# --- bad input -----------------------------------------------------------------------------------------

@pytest.mark.parametrize("args, message", [
    (["fig2", "--at", "1,x"], "option --at must be one or more times (numbers, in the unit L is given in), "
                              "comma-separated, got 'x'."),
    (["fig2", "--at", "1,"], "option --at must be one or more times (numbers, in the unit L is given in), "
                             "comma-separated, got ''."),
    (["fig2", "--at", "nan"], "option --at must be one or more times (numbers, in the unit L is given in), "
                              "comma-separated, got 'nan'."),
    (["fig2", "--format", "svg", "--at", "1"], "option --at selects the slices of a table (text, json, csv, "
                                               "markdown, latex); a figure shows every instant."),
    (["fig2", "--format", "xls"], "option --format must be one of text, json, csv, markdown, latex, or one "
                                  "or more of svg, pdf, png comma-separated, got 'xls'."),
    (["fig2", "--format", "json,svg"], "option --format must be one of text, json, csv, markdown, latex, or "
                                       "one or more of svg, pdf, png comma-separated, got 'json,svg'."),
    (["fig2", "-o", "x.doc"], "option -o: cannot tell the format of 'x.doc' from its extension; name it .txt, .json, "
                              ".csv, .md, .tex, .svg, .pdf or .png, or give --format."),
    (["fig2", "-o", "x.csv", "--format", "json"], "option -o names 'x.csv' but --format is json; make them agree."),
    (["fig2", "-o", ""], "option -o must name a file or folder, got ''."),
    (["fig2", "--frame", "sideways"], "option --frame: a frame must be rest, moving, both or a velocity U with "
                                      "-0.9999999 <= U <= 0.9999999 (or a comma-separated list of these), got "
                                      "'sideways'."),
    (["fig2", "--v", "1"], "option --v: v must be a number with 0 < v < 1 (units of c), got 1."),
    (["nope"], None),
])
def test_bad_input_is_one_sentence_and_exit_2_and_writes_nothing(in_tmp, args, message):
    text = error_of(*args)
    if message is not None:
        assert text == message
    else:
        assert text.startswith("there is no built-in scenario 'nope'")
    assert list(in_tmp.iterdir()) == []


def test_a_missing_folder_is_said_before_any_work(in_tmp):
    assert error_of("fig2", "-o", "no/such/l.json") == (
        "cannot write no/such/l.json: the folder no/such does not exist; create it first.")
    assert error_of("fig2", "-o", "no/such/l.svg") == (
        "cannot write no/such/l.svg: the folder no/such does not exist; create it first.")


# --- the documentation ----------------------------------------------------------------------------------------------

def _section() -> str:
    return LEDGER_PAGE


def test_readme_example_is_what_the_tool_prints_now():
    section = _section()
    command = "sears-paradox ledger fig1 --frame moving --at 0.5,1,1.5"
    printed = section.split(f"$ {command}\n")[1].split("```")[0]
    assert printed == run(*command.split()[2:]).output


def test_readme_documents_every_ledger_option():
    section = _section()
    for param in ledger.params:
        for flag in getattr(param, "opts", []):
            if flag.startswith("--"):
                assert f"`{flag}" in section, flag


def test_readme_ledger_figure_is_what_the_tool_draws_now():
    from rodparadox.render import ledger_figure
    from rodparadox import render
    from rodparadox.physics.frames import paper_frames

    path = ROOT / "outputs" / "readme" / "fig2_ledger.svg"
    assert "outputs/readme/fig2_ledger.svg" in _section()
    made_with = (ROOT / "outputs" / "readme" / "made-with.txt").read_text().split()
    scenario = load("fig2")
    drawn = render.figure_bytes(ledger_figure.draw(simulate(scenario), paper_frames(scenario.v)), "svg")
    if made_with == ["matplotlib", matplotlib.__version__]:
        assert drawn == path.read_bytes(), f"{path} is out of date: run `make readme-figures`"
    else:  # another matplotlib writes other bytes: the same curves, to 0.01 pt
        def curves(svg: bytes):
            ns = "{http://www.w3.org/2000/svg}"
            return {g.get("id"): [round(float(n), 2) for p in g.iter(f"{ns}path")
                                  for n in re.findall(r"-?\d+\.?\d*", p.get("d", ""))]
                    for g in ET.fromstring(svg).iter(f"{ns}g") if re.match(r"[ab]-[pE]-", g.get("id", ""))}
        assert curves(drawn) == curves(path.read_bytes())
