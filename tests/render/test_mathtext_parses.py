"""The process-wide cache of mathtext parses (rodparadox/render/mathtext_parses.py) returns what a fresh parse returns."""

from __future__ import annotations

import matplotlib
from matplotlib import mathtext
from matplotlib.font_manager import FontProperties

from rodparadox.render import mathtext_parses


def _fresh(output: str, s: str, prop: FontProperties):
    """A parse by matplotlib's own code on a new parser, the shared cache bypassed."""
    from matplotlib.backends import backend_agg
    from matplotlib.ft2font import LoadFlags

    flags = LoadFlags.NO_HINTING if output == "path" else backend_agg.get_hinting_flag()  # as parse() passes them
    return mathtext_parses._ONE_PARSE(mathtext.MathTextParser(output), s, 72, prop.copy(), True, flags)


def test_two_renderers_parsers_share_one_parse_and_it_is_matplotlibs_own():
    s, prop = r"$B'_{1}$ at $\times2.5$", FontProperties(size=13)
    first = mathtext.MathTextParser("path").parse(s, 72, prop)
    second = mathtext.MathTextParser("path").parse(s, 72, prop)  # another renderer's parser
    assert second is first  # parsed once
    fresh = _fresh("path", s, prop)
    assert (first.width, first.height, first.depth) == (fresh.width, fresh.height, fresh.depth)
    assert [g[1:] for g in first.glyphs] == [g[1:] for g in fresh.glyphs] and first.rects == fresh.rects
    raster = mathtext.MathTextParser("agg").parse(s, 72, prop, antialiased=True)
    assert type(raster).__name__ == "RasterParse" and type(first).__name__ == "VectorParse"  # output types apart


def test_a_changed_mathtext_rcparam_or_size_is_parsed_again():
    s = r"$v = 0.6$"
    parser = mathtext.MathTextParser("path")
    upright = parser.parse(s, 72, FontProperties(size=11))
    with matplotlib.rc_context({"mathtext.default": "rm"}):
        roman = parser.parse(s, 72, FontProperties(size=11))
    def fonts(parse):
        return [(glyph[0].fname, glyph[2]) for glyph in parse.glyphs]
    assert roman is not upright and fonts(roman) != fonts(upright)  # upright v against italic v
    assert parser.parse(s, 72, FontProperties(size=22)).width > 1.9 * upright.width
    assert parser.parse(s, 72, FontProperties(size=11)) is upright


def test_the_cache_is_bounded_and_installed_once():
    assert 0 < mathtext_parses.cache_info().maxsize <= 10_000
    mathtext_parses.install()
    assert mathtext.MathTextParser._parse_cached is mathtext_parses._parse_cached
