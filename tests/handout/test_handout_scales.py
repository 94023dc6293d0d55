"""`handout --equal-scales` (issue 14, item 4): the option names its file as `plot` names it (`_samescale`) and
reaches the diagrams the PDF and the LaTeX draw: every panel draws one length of L as one length on the page.

Cheap: the CLI runs with the PDF writer replaced by one that keeps the document (nothing is set on pages); the
diagram alone is then drawn as the PDF draws it (one page holding only that block) and as the LaTeX draws it."""

from __future__ import annotations

import numpy as np
import pytest
from click.testing import CliRunner

from rodparadox import render
from rodparadox.handout import pdf, tex
from rodparadox.handout.document import DiagramBlock, Handout, Section
from sears_paradox_cli.main import main

#: one worker runs this file: its module fixture is built once, not once per worker
pytestmark = pytest.mark.xdist_group("handout_scales")

#: at this speed S′ spans about four times the length S does: panels that each fill their box differ in scale
V = 0.97


def _run(tmp_path, monkeypatch, *extra):
    kept = []

    def keep(document, paper="a4", style="print"):
        kept.append(document)
        return b"%PDF-1.4 stand-in\n"
    monkeypatch.setattr(pdf, "to_pdf", keep)
    result = CliRunner().invoke(main, ["handout", "while_turning", "--v", str(V), "-o", str(tmp_path), *extra])
    assert result.exit_code == 0, result.output
    [document] = kept
    [diagram] = [b for b in document.blocks() if isinstance(b, DiagramBlock)]
    return result.output.strip(), diagram


def _scales(axes_list) -> list[float]:
    """Points per L of each panel, across and up (the panels' own axes, found by their ids)."""
    scales = []
    for axes in axes_list:
        box = axes.get_window_extent()
        scales += [box.width / np.ptp(axes.get_xlim()), box.height / np.ptp(axes.get_ylim())]
    return scales


def _panels(figure):
    return [ax for ax in figure.axes if str(ax.get_gid()).endswith("-axes") and len(str(ax.get_gid())) == 6]


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    """The handout's command with and without the option: its output line and the diagram block it built."""
    out = {}
    with pytest.MonkeyPatch.context() as monkeypatch:
        for extra in ((), ("--equal-scales",)):
            out[extra] = _run(tmp_path_factory.mktemp("h"), monkeypatch, *extra)
    return out


def test_the_option_names_the_file_as_plot_does_and_reaches_the_diagram_block(runs):
    line, block = runs[("--equal-scales",)]
    assert line.endswith("while_turning_handout_v0.97_samescale.pdf")
    assert block.equal_scales and "drawn to one scale" in block.caption
    line, block = runs[()]
    assert line.endswith("while_turning_handout_v0.97.pdf") and not block.equal_scales
    assert "one scale" not in block.caption


def test_the_pdf_and_the_latex_draw_every_panel_to_one_scale_with_the_option_only(runs, monkeypatch):
    drawn = {}
    for extra, (_, block) in runs.items():
        page = Handout("t", (Section("s", "t", (block,)),))
        [figure] = pdf.page_figures(page, "a4", "print")
        drawn[("pdf",) + extra] = _scales(_panels(figure))
        figures = []
        monkeypatch.setattr(render, "figure_bytes", lambda figure, fmt, style="default": figures.append(figure))
        tex.figure_pdf(block, "a4", "print")
        drawn[("tex",) + extra] = _scales(_panels(figures[0]))
    for writer in ("pdf", "tex"):
        same = drawn[(writer, "--equal-scales")]
        assert len(same) == 4 and max(same) == pytest.approx(min(same), rel=1e-6), (writer, same)
        # without it panel (a), S, is drawn larger than (b), S′, which spans four times as much: the option acts
        a_across, _, b_across, _ = drawn[(writer,)]
        assert a_across > 1.5 * b_across, (writer, drawn[(writer,)])
