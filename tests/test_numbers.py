"""How numbers are written (`rodparadox.numbers`): exactly in names, readably in figures."""

from __future__ import annotations

import re

import pytest
from hypothesis import given
from hypothesis import strategies as st

from rodparadox.numbers import exact, shown

_SUPERSCRIPTS = "⁰¹²³⁴⁵⁶⁷⁸⁹⁻"


def read_back(text: str) -> float:
    """A drawn number as a float: the real minus sign, and a×10ⁿ with superscript digits."""
    text = text.replace("\N{MINUS SIGN}", "-")
    m = re.fullmatch(r"(-?[\d.]+)×10([" + _SUPERSCRIPTS + "]+)", text)
    if m:
        exponent = m.group(2).translate(str.maketrans(_SUPERSCRIPTS, "0123456789-"))
        return float(m.group(1)) * 10.0 ** int(exponent)
    return float(text)


@pytest.mark.parametrize("value, text", [
    (1e-6, "1×10⁻⁶"), (-1e-6, "\N{MINUS SIGN}1×10⁻⁶"), (1.5e-5, "1.5×10⁻⁵"), (0.6, "0.6"), (-0.0, "0"),
    (2.0, "2"), (0.001, "0.001"), (1e8, "1×10⁸"), (-0.9999999, "\N{MINUS SIGN}0.9999999"),
])
def test_a_drawn_number_reads_as_a_reader_writes_it(value, text):
    """Issue 6.15: v = 1e-6 was drawn "1e − 06" (a minus sign set as an operator inside the exponent)."""
    assert shown(value) == text


@pytest.mark.parametrize("value, text", [(1e-6, "1{\\times}10^{-6}"), (-2.5e-7, "-2.5{\\times}10^{-7}"), (0.6, "0.6")])
def test_inside_mathtext_the_same_number_is_spelled_for_mathtext(value, text):
    assert shown(value, math_text=True) == text


@given(st.floats(min_value=-1e12, max_value=1e12, allow_nan=False), st.integers(min_value=4, max_value=10))
def test_a_drawn_number_has_no_e_no_ascii_minus_no_minus_zero_and_reads_back(value, significant):
    text = shown(value, significant)
    assert "e" not in text and "-" not in text
    assert not re.fullmatch("\N{MINUS SIGN}0(\\.0*)?", text)
    assert read_back(text) == pytest.approx(value, rel=10.0 ** (1 - significant), abs=1e-300)


@given(st.floats(min_value=-0.9999999999999999, max_value=0.9999999999999999))
def test_a_speed_below_1_is_never_drawn_as_1(u):
    assert abs(read_back(shown(u, 4))) < 1.0


@given(st.floats(allow_nan=False, allow_infinity=False))
def test_an_exact_number_gives_back_the_float(value):
    text = exact(value)
    assert float(text) == value and not text.endswith(".0") and text != "-0" and not text.startswith("-0.0e")
