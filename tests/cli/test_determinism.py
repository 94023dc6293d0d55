"""The same command gives the same bytes, across processes: one pair of runs checks every kind of output.

A fresh interpreter with a hash seed other than this process's (dict and set orders, font caches and import order
differ between them) writes every kind of file the tool writes -- plot's SVG, PDF and PNG, the ledger's figure and
tables, an animation as GIF and as PNG stills in both modes, a handout and a worksheet as PDF, a handout's LaTeX
folder (its figures as PDF, tables as .tex, world-lines as .dat) -- while this test's own process (a worker that
has run other tests: its caches of histories, measured texts and PDF font subsets are warm) runs the same
commands; the two trees of files must be equal byte for byte. So one check covers both a Makefile's fresh
processes and a notebook's long-lived one, whose kept results must not change a byte. It was two fresh processes
(13 CPU-s, the suite's slowest test); the worker's run saves one interpreter's start and its cold caches
(about 9 CPU-s in the suite). It also caught what two fresh processes could not: a paused animation's generator
left its style's figure.dpi (72) on the process, and the LaTeX strips made after it differed in the last digit.
This one pair of runs is the suite's check across processes: plot's SVG and PDF, the animation's GIF and
boost stills and the worksheet's PDF each had a pair of their own in their test files before.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

#: what each process runs, in one interpreter: every output kind, each by the cheapest command that writes it
#: (issue 13, item 8). One plot writes SVG and PDF (PNG is the ledger figure's: the same writer, 0.4 s less each):
#: while_turning with rod lines, clocks and a third frame draws all that fig2's default plot draws and more, so
#: fig2's plot (a command of its own before) is not needed.
#: The ledger's figure as SVG (its elements' order) and PNG. Animations have 2 images, the fewest an animation may
#: have, the GIF in one panel (the stills draw both frames). The worksheet (its PDF is written by the handout's
#: writer, its pages and key included: a handout of its own was the same kind twice) and the LaTeX folder of fig1
#: (two particles, both frames, every question), where an order that a hash seed changes would show.
COMMANDS = (
    ["plot", "while_turning", "--v", "0.95", "--style", "print", "--rod-lines", "5", "--rod-now",
     "--proper-time", "--frame", "both,0.3", "--format", "svg,pdf", "-o", "."],
    # the causal rod's figures: its compression shading is rasterised inside the vector files
    ["plot", "fig1", "--rod", "causal", "--frame", "rest", "--format", "svg,pdf", "-o", "."],
    ["ledger", "fig2", "--format", "svg,png", "-o", "."],
    ["ledger", "fig2", "--format", "json", "-o", "ledger.json"],
    ["ledger", "fig2", "--format", "latex", "-o", "ledger.tex"],
    ["export", "fig2", "--format", "csv", "-o", "fig2.csv"],
    ["animate", "fig2", "--frame", "rest", "--fps", "4", "--seconds", "0.5", "-o", "a.gif"],
    ["animate", "while_turning", "--v", "0.95", "--mode", "boost", "--style", "print", "--fps", "4",
     "--seconds", "0.5", "--format", "png", "-o", "stills"],
    # two particles, both frames, every question: where an order that hash seeds change could show
    ["handout", "fig1", "--worksheet", "-o", "."],
    ["handout", "fig1", "--format", "tex", "-o", "tex"],
)

_SCRIPT = """
import json, sys
from sears_paradox_cli.main import main
for args in json.loads(sys.argv[1]):
    try:
        main(args)
    except SystemExit as e:
        if e.code:
            raise
"""


def _files(folder: Path) -> dict[str, bytes]:
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


def _other_seed() -> str:
    """A hash seed this process does not have (it has PYTHONHASHSEED's, or a random one when that is unset)."""
    own = os.environ.get("PYTHONHASHSEED", "random")
    return "2" if own == "1" else "1"


def two_runs(tmp_path_factory) -> tuple[dict[str, bytes], dict[str, bytes]]:
    """Every command's files from a fresh interpreter with another hash seed, and from this process, run side by
    side (the fresh one in the background)."""
    import json

    from sears_paradox_cli.main import main

    fresh, here = tmp_path_factory.mktemp("fresh"), tmp_path_factory.mktemp("here")
    env = {**os.environ, "PYTHONHASHSEED": _other_seed()}
    process = subprocess.Popen([sys.executable, "-c", _SCRIPT, json.dumps(COMMANDS)], cwd=fresh, env=env,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    before = os.getcwd()
    try:
        os.chdir(here)
        for args in COMMANDS:
            try:
                main(args)
            except SystemExit as e:
                assert not e.code, f"{args}: exit {e.code}"
    finally:
        os.chdir(before)
        out, err = process.communicate(timeout=600)
    assert process.returncode == 0, err.decode()
    return _files(fresh), _files(here)


@pytest.mark.slow
def test_a_fresh_process_with_another_hash_seed_and_this_one_write_every_output_kind_with_the_same_bytes(
        tmp_path_factory):
    """One test, so that the pair of runs is made once whichever worker process takes it."""
    first, second = two_runs(tmp_path_factory)
    # every output kind is written
    names = set(first)
    suffixes = {Path(n).suffix for n in names}
    assert suffixes >= {".svg", ".pdf", ".png", ".json", ".tex", ".csv", ".gif", ".dat"}
    assert {"while_turning_v0.95_both_u0.3_print_now_clocks_lines5.pdf", "fig2_ledger.png", "a.gif",
            "fig1_worksheet.pdf", "tex/handout.tex", "fig2_ledger.svg",
            "fig1_rest_causal.svg", "fig1_rest_causal.pdf"} <= names
    assert sum(n.startswith("stills/") for n in names) == 2  # round(0.5 s * 4 fps) stills
    # the same bytes
    assert set(first) == set(second)
    assert [name for name in first if first[name] != second[name]] == []
