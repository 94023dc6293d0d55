"""A PDF's font subsets and text layouts are made once per process inside the package's PDF writers, and the files
keep their bytes."""

from __future__ import annotations

import io

import pytest
from matplotlib import _text_helpers
from matplotlib.backends import _backend_pdf_ps, backend_pdf
from matplotlib.figure import Figure

from rodparadox.render import pdf_fonts
from rodparadox.render.diagram import FIGURE_METADATA, figure_bytes, style_context

pytestmark = pytest.mark.skipif(not pdf_fonts._USABLE, reason="this matplotlib's subsetting is not the one expected")


def _figure(text: str) -> Figure:
    figure = Figure(figsize=(2, 1))
    figure.text(0.1, 0.5, text)
    figure.text(0.1, 0.2, f"$x_{{u}} = {len(text)}$")  # a second font, mathtext's
    return figure


def _matplotlibs_own(figure: Figure) -> bytes:
    """The figure saved as figure_bytes saves it, but with matplotlib making every subset itself."""
    with style_context("default"):
        buffer = io.BytesIO()
        figure.savefig(buffer, format="pdf", metadata=FIGURE_METADATA["pdf"])
    return buffer.getvalue()


def test_a_kept_subset_gives_the_bytes_a_fresh_one_gives_and_is_made_once():
    figure = _figure("Kept glyphs: qwz")  # letters no other test is likely to have asked for in this order
    first = figure_bytes(figure, "pdf")
    kept = pdf_fonts.kept_count()
    again = figure_bytes(_figure("Kept glyphs: qwz"), "pdf")
    assert again == first and pdf_fonts.kept_count() == kept  # the same fonts and glyphs: nothing new made
    assert _matplotlibs_own(_figure("Kept glyphs: qwz")) == first
    other = figure_bytes(_figure("Other glyphs: jk"), "pdf")  # other glyphs: another subset, other bytes
    assert other != first and other == _matplotlibs_own(_figure("Other glyphs: jk"))


@pytest.mark.skipif(not pdf_fonts._LAYOUT_USABLE, reason="this matplotlib's PDF text drawing is not the one expected")
def test_a_kept_layout_gives_the_bytes_a_fresh_one_gives_at_every_size():
    """The same words at three sizes and kerned pairs (AV, To), drawn twice: the second drawing takes the kept
    layouts, and both are what matplotlib writes laying out every text itself."""
    def figure() -> Figure:
        f = Figure(figsize=(3, 2))
        for k, size in enumerate((7, 10, 10.5)):
            f.text(0.05, 0.1 + 0.3 * k, "AVAST To Wave: kept layout", size=size)
        return f

    first = figure_bytes(figure(), "pdf")
    kept = pdf_fonts.kept_layouts()
    assert kept >= 3 or kept == pdf_fonts.KEEP_LAYOUTS
    assert figure_bytes(figure(), "pdf") == first == _matplotlibs_own(figure())
    assert backend_pdf._text_helpers is _text_helpers and "_get_font_ttf" not in vars(backend_pdf.RendererPdf)


def test_matplotlibs_other_users_get_its_own_functions():
    assert _backend_pdf_ps.get_glyphs_subset is pdf_fonts._SUBSET
    with pdf_fonts.kept_subsets():
        with pdf_fonts.kept_subsets():  # nested: still kept, and put back only by the outer one
            assert _backend_pdf_ps.get_glyphs_subset is pdf_fonts._subset
        assert _backend_pdf_ps.font_as_file is pdf_fonts._as_file
    assert (_backend_pdf_ps.get_glyphs_subset, _backend_pdf_ps.font_as_file) == (pdf_fonts._SUBSET, pdf_fonts._AS_FILE)
