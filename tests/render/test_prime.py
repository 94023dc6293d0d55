"""A separation's label, A′₁ in a figure (mathtext): the prime sits as in print, on the letter's baseline at the
letter's size, against its top, in every style (issue 24: mathtext's own $A'_{1}$ sets it as a superscript,
raised above the letter in STIX). Read from the glyphs mathtext lays out."""

from __future__ import annotations

import pytest
from matplotlib import mathtext
from matplotlib.font_manager import FontProperties

from rodparadox.numbers import impact_name
from rodparadox.render.diagram import style_context
from rodparadox.render.styles import STYLE_NAMES

PRIME = 0x2032


@pytest.mark.parametrize("style", STYLE_NAMES)
def test_the_separations_prime_sits_on_the_letters_baseline_at_its_size(style):
    size = 10.0
    with style_context(style):
        parse = mathtext.MathTextParser("path").parse(impact_name("A1s", math_text=True), 72, FontProperties(size=size))
    glyphs = {chr(code): (font_size, ox, oy) for _, font_size, code, _, ox, oy in parse.glyphs}
    assert set(glyphs) == {"A", chr(PRIME), "1"}
    (a_size, a_x, a_y), (p_size, p_x, p_y), (s_size, s_x, s_y) = glyphs["A"], glyphs[chr(PRIME)], glyphs["1"]
    assert p_size == a_size == size and abs(p_y - a_y) < 1e-9  # no superscript: the prime glyph is drawn high
    assert a_x < p_x < s_x and s_size < size and s_y < a_y - 0.1 * size  # then the subscript, smaller and lower
    # a contact's label is unchanged: the letter, then its subscript
    assert impact_name("A1", math_text=True) == "$A_{1}$" and impact_name("B12s") == "B\N{PRIME}\u2081\u2082"
