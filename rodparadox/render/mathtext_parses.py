"""Each mathtext string parsed once per process, not once per renderer (imported by `text`, so by every drawing).

matplotlib keeps its parses in an lru_cache on the method `MathTextParser._parse_cached`, which keys on the parser
itself, and each renderer makes its own parser: every savefig, every page of a PDF and every canvas parsed the same
impact labels and titles again (pyparsing: about 10 ms a string; a handout parsed each label dozens of times).
A parse depends only on its arguments, the parser's output type ("vector" or "raster") and the mathtext rcParams, so
one cache keyed on all of them returns what a fresh parse returns: drawings keep their bytes. `install` is idempotent.
"""

from __future__ import annotations

import inspect
from functools import lru_cache

import matplotlib
from matplotlib import mathtext

#: the rcParams a parse reads besides its arguments (mathtext.fontset is also in the font properties, which key it)
_RC_KEYS = tuple(sorted(k for k in matplotlib.rcParams if k.startswith("mathtext.")))
#: what matplotlib's cached method computes (matplotlib 3.10 and 3.11); None if a later matplotlib changed that
#: private method: then nothing is installed and matplotlib parses as it always did
_ONE_PARSE = getattr(getattr(mathtext.MathTextParser, "_parse_cached", None), "__wrapped__", None)
if _ONE_PARSE is not None and list(inspect.signature(_ONE_PARSE).parameters) != [
        "self", "s", "dpi", "prop", "antialiased", "load_glyph_flags"]:
    _ONE_PARSE = None
_PARSERS = {output_type: mathtext.MathTextParser(output)
            for output_type, output in (("vector", "path"), ("raster", "agg"))}


@lru_cache(maxsize=1024)  # bounded: a long-lived process (a notebook) parses many strings
def _parsed(output_type: str, s: str, dpi: float, prop, antialiased: bool, load_glyph_flags, rc: tuple):
    """A parse, for this output type and these mathtext rcParams (`rc`: part of the key only)."""
    return _ONE_PARSE(_PARSERS[output_type], s, dpi, prop, antialiased, load_glyph_flags)


def _parse_cached(self, s, dpi, prop, antialiased, load_glyph_flags):
    value = dict.__getitem__  # the stored values, without RcParams' per-read checks
    rc = tuple(str(value(matplotlib.rcParams, k)) for k in _RC_KEYS)
    return _parsed(self._output_type, s, dpi, prop, antialiased, load_glyph_flags, rc)


def install() -> None:
    """Route every MathTextParser's parses through the one process-wide cache (where matplotlib's is as expected)."""
    if _ONE_PARSE is not None:
        mathtext.MathTextParser._parse_cached = _parse_cached


def cache_info():
    """How full the cache of parses is (functools' CacheInfo): it is bounded."""
    return _parsed.cache_info()


install()
