"""Each font subset a PDF embeds, and each text's glyph layout, made once per process (`kept_subsets`), for the
PDFs this package writes.

matplotlib's PDF backend embeds every font a file uses as a subset of its glyphs, made by fontTools from the font
file on disk: about 30 ms a font, and a file embeds three to six. A handout's LaTeX folder writes a PDF per figure,
each embedding the same fonts with nearly the same glyphs, and a Makefile's `plot` call writes many figures; each
made its subsets afresh. A subset depends only on the font file and the set of glyphs, so one made earlier gives
the bytes a fresh one gives: the files keep their bytes. The subsets are kept only inside `kept_subsets` (the
package's own PDF writers), never for matplotlib's other users in the process; if a later matplotlib changes the
private functions this relies on, nothing is kept and matplotlib makes each subset as it always did.

Layouts likewise: the PDF renderer lays out every text it draws glyph by glyph (FreeType and libraqm, about 30 us
a character), and a handout's running text is thousands of runs, most of them drawn again in the next document of
a run (the same questions, headings and table headers). A layout depends only on the font object (its files,
hinting and kerning factors), its size, the text and its features and language, so a kept one is what a fresh one
gives; the renderer reads only each glyph's index, position and kern from it (never the glyph loaded as a side
effect of matplotlib's own `layout`), so the files keep their bytes.
"""

from __future__ import annotations

import inspect
from contextlib import contextmanager
from io import BytesIO
from typing import NamedTuple

from matplotlib import _text_helpers
from matplotlib.backends import _backend_pdf_ps, backend_pdf
from matplotlib.ft2font import LoadFlags

_SUBSET = getattr(_backend_pdf_ps, "get_glyphs_subset", None)
_AS_FILE = getattr(_backend_pdf_ps, "font_as_file", None)
#: matplotlib 3.11's private API, as this module expects it (None: keep nothing)
_USABLE = (_SUBSET is not None and _AS_FILE is not None and hasattr(_backend_pdf_ps, "SubsetResults")
           and list(inspect.signature(_SUBSET).parameters) == ["fontfile", "glyphs"])
#: at most this many subsets kept (a few kilobytes to a few hundred each)
KEEP = 256
_kept: dict[tuple, tuple[bytes, dict]] = {}
_FONT_TTF = getattr(backend_pdf.RendererPdf, "_get_font_ttf", None)
#: and the PDF renderer's use of them as this module expects it (None: lay out every text as matplotlib does)
_LAYOUT_USABLE = (_FONT_TTF is not None and getattr(backend_pdf, "_text_helpers", None) is _text_helpers
                  and "_get_font_ttf" not in vars(backend_pdf.RendererPdf)
                  and list(inspect.signature(_text_helpers.layout).parameters) == ["string", "font", "features",
                                                                                   "language"])
#: at most this many layouts kept (a text's glyphs: a few hundred bytes each)
KEEP_LAYOUTS = 8192
_layouts: dict[tuple, list] = {}
_sized: list = [None, 0.0]  # the font the PDF renderer set up last, and the size it set


class _Saved(NamedTuple):
    """A kept subset where the backend expects a fontTools font: `font_as_file` gives its bytes back."""

    data: bytes


@contextmanager
def _subset(fontfile, glyphs):
    """`get_glyphs_subset`, kept by font file and set of glyphs."""
    glyphs = frozenset(glyphs)
    key = (str(fontfile), getattr(fontfile, "face_index", 0), glyphs)
    found = _kept.get(key)
    if found is None:
        with _SUBSET(fontfile, glyphs) as made:
            found = (_AS_FILE(made.font).getvalue(), dict(made.glyph_index_map))
        if len(_kept) >= KEEP:
            _kept.pop(next(iter(_kept)))  # the oldest
        _kept[key] = found
    data, index_map = found
    yield _backend_pdf_ps.SubsetResults(_Saved(data), dict(index_map))


def _as_file(font):
    return BytesIO(font.data) if isinstance(font, _Saved) else _AS_FILE(font)


def _font_ttf(renderer, prop):
    """The renderer's own `_get_font_ttf` (the font, cleared and set to the size), noting the font and its size."""
    font = _FONT_TTF(renderer, prop)
    _sized[0], _sized[1] = font, prop.get_size_in_points()
    return font


def _layout(string, font, *, features=None, language=None):
    """matplotlib's `_text_helpers.layout` for the PDF renderer: the glyphs of a text in the font just set up, kept
    by font object, size, text, features and language (the glyphs are not loaded: the renderer never reads them)."""
    if font is not _sized[0]:  # not set up by `_font_ttf`: its size is not known here
        yield from _text_helpers.layout(string, font, features=features, language=language)
        return
    try:
        key = (font, _sized[1], string, features, language)
        items = _layouts.get(key)
    except TypeError:  # features or language given as a list
        yield from _text_helpers.layout(string, font, features=features, language=language)
        return
    if items is None:
        items = font._layout(string, LoadFlags.NO_HINTING, features=features, language=language)
        if len(_layouts) >= KEEP_LAYOUTS:
            _layouts.pop(next(iter(_layouts)))  # the oldest
        _layouts[key] = items
    yield from items


class _KeptLayouts:
    """Stands for `matplotlib._text_helpers` in the PDF backend while inside `kept_subsets`."""

    layout = staticmethod(_layout)

    def __getattr__(self, name):
        return getattr(_text_helpers, name)


@contextmanager
def kept_subsets():
    """Inside: every PDF written takes its font subsets and text layouts from those kept (and keeps those it
    makes)."""
    if not _USABLE or _backend_pdf_ps.get_glyphs_subset is _subset:  # unusable, or inside already
        yield
        return
    _backend_pdf_ps.get_glyphs_subset, _backend_pdf_ps.font_as_file = _subset, _as_file
    if _LAYOUT_USABLE:
        backend_pdf._text_helpers, backend_pdf.RendererPdf._get_font_ttf = _KeptLayouts(), _font_ttf
    try:
        yield
    finally:
        _backend_pdf_ps.get_glyphs_subset, _backend_pdf_ps.font_as_file = _SUBSET, _AS_FILE
        if _LAYOUT_USABLE:
            backend_pdf._text_helpers = _text_helpers
            del backend_pdf.RendererPdf._get_font_ttf
            _sized[0] = None


def kept_count() -> int:
    """How many subsets are kept (bounded by KEEP)."""
    return len(_kept)


def kept_layouts() -> int:
    """How many text layouts are kept (bounded by KEEP_LAYOUTS)."""
    return len(_layouts)
