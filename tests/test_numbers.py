"""How numbers are written (`rodparadox.numbers`): exactly in names, readably in figures, aligned in tables; nice
steps; impact labels."""

from __future__ import annotations

import re

import pytest
from hypothesis import example, given
from hypothesis import strategies as st

import math

from rodparadox.numbers import (coordinate_format, exact, exact_signed, impact_name, impact_parts, nice_number,
                                number_text, shown, shown_signed, velocity_format)

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


@pytest.mark.parametrize("value, significant, text", [
    (10000.0, 4, "10000"), (9999.5, 4, "10000"), (-12345.4, 4, "\N{MINUS SIGN}12345"), (999999.0, 5, "999999"),
    (1234.5, 4, "1234"), (1234.5, 5, "1234.5")])
def test_a_number_with_as_many_digits_before_the_point_as_asked_is_written_out_whole(value, significant, text):
    """Hypothesis found 10000 with 4 digits drawn as '1e+04' ('g' format turns to an exponent there)."""
    assert shown(value, significant) == text


@given(st.floats(min_value=-1e12, max_value=1e12, allow_nan=False), st.integers(min_value=4, max_value=10))
@example(10000.0, 4)
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


# --- nice numbers: the one 1, 2, 2.5, 5 step of ticks, clocks and scale bars ------------------------------------

@pytest.mark.parametrize("value, at_least, at_most, above", [
    (0.37, 0.5, 0.25, 0.5), (1.0, 1.0, 1.0, 2.0), (2.4, 2.5, 2.0, 2.5), (2.5, 2.5, 2.5, 5.0), (7.0, 10.0, 5.0, 10.0),
    (0.0031, 0.005, 0.0025, 0.005), (3e6, 5e6, 2.5e6, 5e6),
])
def test_a_nice_number_is_1_2_2_5_or_5_times_a_power_of_ten_on_the_side_asked(value, at_least, at_most, above):
    assert nice_number(value) == pytest.approx(at_least) and nice_number(value, "at_least") == nice_number(value)
    assert nice_number(value, "at_most") == pytest.approx(at_most)
    assert nice_number(value, "above") == pytest.approx(above)


@given(st.floats(min_value=1e-12, max_value=1e12))
def test_nice_numbers_bracket_the_value_and_are_nice(value):
    up, down, above = nice_number(value), nice_number(value, "at_most"), nice_number(value, "above")
    assert down <= value * (1 + 1e-9) and up >= value * (1 - 1e-9) and above > value
    for nice in (up, down, above):
        mantissa = nice / 10.0 ** math.floor(math.log10(nice) + 1e-9)
        assert any(mantissa == pytest.approx(m) for m in (1, 2, 2.5, 5, 10))


def test_a_nice_number_needs_a_side():
    with pytest.raises(ValueError, match="at_least, at_most or above"):
        nice_number(1.0, "nearest")


# --- impact labels ---------------------------------------------------------------------------------------------

def test_an_impact_label_is_written_one_way_in_plain_text_and_in_mathtext():
    assert impact_parts("B12") == ("B", "12") and impact_parts("rod") == ("rod", "")
    assert impact_name("B1") == "B₁" and impact_name("A12") == "A₁₂" and impact_name("rod") == "rod"
    assert impact_name("B1", math_text=True) == "$B_{1}$" and impact_name("rod", math_text=True) == "rod"


# --- signed numbers and numbers in tables ----------------------------------------------------------------------

def test_signed_numbers_show_their_sign_exactly_or_as_drawn():
    assert [exact_signed(u) for u in (0.6, -0.9999999, 0.0, -0.0)] == ["+0.6", "-0.9999999", "+0", "+0"]
    assert [shown_signed(u, 4) for u in (0.6, -0.6, 0.0, 0.123456)] == ["+0.6", "\N{MINUS SIGN}0.6", "0", "+0.1235"]


def test_table_numbers_keep_their_digits_and_write_rounding_as_zero():
    # a column shares its decimals: seven digits in its largest, every other value and a zero with as many decimals
    coordinate = coordinate_format([0.5, -1.25, 1e-14])
    assert [coordinate(x) for x in (0.5, -1.25, 1e-14, -1e-14)] == ["+0.500000", "-1.250000", "+0.000000", "+0.000000"]
    assert [coordinate_format([0.5, 0.0])(x) for x in (0.5, 0.0)] == ["+0.5000000", "+0.0000000"]
    assert [coordinate_format([2236.068, 3.2])(x) for x in (2236.068, 3.2)] == ["+2236.068", "+3.200"]
    assert [coordinate_format([1.583333e-05, -2e-6])(x) for x in (1.583333e-05, -2e-6)] == ["+1.583333e-05",
                                                                                          "-2.000000e-06"]
    assert coordinate_format([0.0])(0.0) == "+0" and coordinate_format([1.5], signed=False)(1.5) == "1.500000"
    velocity = velocity_format([0.6, -0.9999999])
    assert [velocity(u) for u in (0.6, -0.9999999, -0.0)] == ["+0.600000000", "-0.999999900", "+0.000000000"]
    assert [number_text(x) for x in (17 / 12, -0.0, 1e-20)] == ["1.416667", "0", "1e-20"]
    assert number_text(1e-13, zero_below=1e-12) == "0" and number_text(-1e-13) == "-1e-13"

