"""The handout's LaTeX tables fit the text width even for extreme masses (issue 15 item 14: with masses 1e-6 and
1e6 the ledger tables overran the margin by up to 118 pt). Compiled with pdflatex where it is installed; everywhere,
the width each fragment falls back to (footnote size, half the column gap) is estimated from its cells' contents."""

from __future__ import annotations

import re
import shutil
import subprocess

import pytest

from rodparadox.io.scenario import parse
from rodparadox.physics.rigid import run
from rodparadox.physics.frames import paper_frames
from rodparadox.tables.build import events_table, hidden_table, ledger_table
from rodparadox.tables.formats import to_latex

MASSES = "name: masses\nv: 0.6\nparticles:\n  A:\n    mass: 1.0e-6\n    gap: 0.5\n  B:\n    mass: 1.0e+6\n    gap: 0.5\n"
#: the handout's page (handout.tex: article 11pt, A4, 20 mm margins): 210 mm less two margins, in TeX points
TEXT_WIDTH = (210 - 40) / 25.4 * 72.27
#: \footnotesize in an 11pt article is 9 pt; a digit of Computer Modern is half an em; letters average about that
FOOTNOTE_EM = 9.0


def _fragments() -> dict[str, str]:
    h = run(parse(MASSES, "masses.yaml", "masses"))
    out = {}
    for frame in paper_frames(h.scenario.v):
        for table in (events_table(h, frame), ledger_table(h, frame), hidden_table(h, frame)):
            if table is not None:
                out[table.name] = to_latex(table)
    return out


def _fallback_width(fragment: str) -> float:
    """The tabular's width at footnote size with 3 pt column gaps: each column as wide as its longest cell
    (TeX markup stripped, a character half an em), plus the gaps."""
    body = fragment.split(r"\midrule", 1)[1].split(r"\bottomrule", 1)[0]
    rows = [row for row in body.split(r"\\") if row.strip() and not row.strip().startswith("[")]
    cells = [[re.sub(r"\\[a-zA-Z]+|[{}$_]|\[[^\]]*\]", "", cell).strip() for cell in row.split("&")] for row in rows]
    columns = max(len(row) for row in cells)
    widest = [max(len(row[k]) if k < len(row) else 0 for row in cells) for k in range(columns)]
    return sum(0.5 * FOOTNOTE_EM * n for n in widest) + 2 * 3.0 * columns


def test_every_table_falls_back_to_a_width_that_fits_the_page():
    fragments = _fragments()
    assert {"ledger_rest", "ledger_moving", "events_rest", "events_moving"} <= set(fragments)
    for name, fragment in fragments.items():
        assert r"\setbox0=\hbox{\rodparadoxtable}" in fragment and fragment.count(r"\leavevmode\box0") == 1
        assert _fallback_width(fragment) <= TEXT_WIDTH, name


@pytest.mark.skipif(shutil.which("pdflatex") is None, reason="pdflatex is not installed")
def test_the_tables_of_masses_1e_6_and_1e6_compile_without_an_overfull_line(tmp_path):
    fragments = _fragments()
    for name, fragment in fragments.items():
        (tmp_path / f"{name}.tex").write_text(fragment, encoding="utf-8")
    inputs = "\n\n".join(rf"\input{{{name}.tex}}" for name in fragments)
    (tmp_path / "doc.tex").write_text(
        "\\documentclass[11pt]{article}\n\\usepackage[a4paper,margin=20mm]{geometry}\n\\usepackage{amsmath}\n"
        "\\usepackage{booktabs}\n\\usepackage{siunitx}\n\\begin{document}\n" + inputs + "\n\\end{document}\n",
        encoding="utf-8")
    done = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error", "doc.tex"], cwd=tmp_path,
                          capture_output=True, text=True, timeout=120)
    log = (tmp_path / "doc.log").read_text(encoding="latin-1")
    assert done.returncode == 0, log[-2000:]
    assert "Overfull \\hbox" not in log
