"""Each font subset a PDF embeds, made once per process (`kept_subsets`), for the PDFs this package writes.

matplotlib's PDF backend embeds every font a file uses as a subset of its glyphs, made by fontTools from the font
file on disk: about 30 ms a font, and a file embeds three to six. A handout's LaTeX folder writes a PDF per figure,
each embedding the same fonts with nearly the same glyphs, and a Makefile's `plot` call writes many figures; each
made its subsets afresh. A subset depends only on the font file and the set of glyphs, so one made earlier gives
the bytes a fresh one gives: the files keep their bytes. The subsets are kept only inside `kept_subsets` (the
package's own PDF writers), never for matplotlib's other users in the process; if a later matplotlib changes the
private functions this relies on, nothing is kept and matplotlib makes each subset as it always did.
"""

from __future__ import annotations

import inspect
from contextlib import contextmanager
from io import BytesIO
from typing import NamedTuple

from matplotlib.backends import _backend_pdf_ps

_SUBSET = getattr(_backend_pdf_ps, "get_glyphs_subset", None)
_AS_FILE = getattr(_backend_pdf_ps, "font_as_file", None)
#: matplotlib 3.11's private API, as this module expects it (None: keep nothing)
_USABLE = (_SUBSET is not None and _AS_FILE is not None and hasattr(_backend_pdf_ps, "SubsetResults")
           and list(inspect.signature(_SUBSET).parameters) == ["fontfile", "glyphs"])
#: at most this many subsets kept (a few kilobytes to a few hundred each)
KEEP = 256
_kept: dict[tuple, tuple[bytes, dict]] = {}


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


@contextmanager
def kept_subsets():
    """Inside: every PDF written takes its font subsets from those kept (and keeps those it makes)."""
    if not _USABLE or _backend_pdf_ps.get_glyphs_subset is _subset:  # unusable, or inside already
        yield
        return
    _backend_pdf_ps.get_glyphs_subset, _backend_pdf_ps.font_as_file = _subset, _as_file
    try:
        yield
    finally:
        _backend_pdf_ps.get_glyphs_subset, _backend_pdf_ps.font_as_file = _SUBSET, _AS_FILE


def kept_count() -> int:
    """How many subsets are kept (bounded by KEEP)."""
    return len(_kept)
