"""How numbers are written: exactly in names (files, frames), readably in figures. Pure, no imports to speak of.

One home for both, so a frame's name, a file name and a figure's title never
disagree about a number, and no figure shows a `-0` or a `1e-06`.
"""

from __future__ import annotations

import math

MINUS = "\N{MINUS SIGN}"
TIMES = "\N{MULTIPLICATION SIGN}"
_SUPERSCRIPT = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")
#: below this magnitude (and at or above SCIENTIFIC_ABOVE) a drawn number is written a×10ⁿ: 0.000001 is hard to count
SCIENTIFIC_BELOW = 1e-3
SCIENTIFIC_ABOVE = 1e6


def exact(value: float) -> str:
    """Every digit the float holds (its repr), no trailing .0, no -0: 0.8, 2, 0.9999999999999999, 1e-06.

    For names: a file name (`fig2_v0.8`) or a frame's (`u=0.3`), where two different numbers must never read alike.
    """
    text = repr(value + 0.0)  # -0.0 -> 0.0
    return text[:-2] if text.endswith(".0") else text


def shown(value: float, significant: int = 10, math_text: bool = False) -> str:
    """A number as a figure draws it: up to `significant` digits, a real minus sign, no -0, 1×10⁻⁶ for tiny ones.

    More digits than `significant` where fewer would round a speed |u| < 1 up to 1
    (0.99999999999 stays below 1). Plain text by default (Unicode minus, ×,
    superscripts), which reads the same in a title, a tick label or a legend;
    `math_text` spells the same number for inside $...$ (1\\times10^{-6}), as
    mathtext's fonts lack the superscript digits and set a `-` as a minus itself.
    """
    value += 0.0  # -0.0 -> 0.0
    if value != 0.0 and math.isfinite(value) and not SCIENTIFIC_BELOW <= abs(value) < SCIENTIFIC_ABOVE:
        for digits in range(significant, 18):
            mantissa, exponent = f"{value:.{digits - 1}e}".split("e")
            if abs(value) >= 1.0 or abs(float(f"{mantissa}e{exponent}")) < 1.0:
                break
        mantissa = mantissa.rstrip("0").rstrip(".") if "." in mantissa else mantissa
        if math_text:
            return f"{mantissa}{{\\times}}10^{{{int(exponent)}}}"
        return f"{mantissa.replace('-', MINUS)}{TIMES}10{str(int(exponent)).translate(_SUPERSCRIPT)}"
    for digits in range(significant, 18):  # 17 digits give back the float itself
        text = f"{value:.{digits}g}"
        if abs(float(text)) < 1.0 or abs(value) >= 1.0:
            break
    return text if math_text else text.replace("-", MINUS)


#: the largest denominator a number is written as a fraction with: the paper's are 12ths, 8ths, 25ths at v = 0.6
FRACTION_DENOMINATOR = 100
#: a fraction stands for a float within this relative distance (the engine's rounding is about 1e-15 relative)
FRACTION_MATCH = 1e-12


def fraction(value: float, largest_denominator: int = FRACTION_DENOMINATOR) -> tuple[int, int] | None:
    """(p, q) with q > 1 if `value` is p/q to FRACTION_MATCH relative, q <= `largest_denominator` and the decimal
    of p/q never ends (q has a prime factor other than 2 and 5: 17/12, 1/3), else None.

    A decimal that ends (5/4 = 1.25, 73/100 = 0.73) says everything already; 1.416667 does not say 17/12.
    """
    from fractions import Fraction

    if not math.isfinite(value):
        return None
    f = Fraction(value).limit_denominator(largest_denominator)
    if f.denominator == 1 or abs(value - f.numerator / f.denominator) > FRACTION_MATCH * max(abs(value), 1e-300):
        return None
    q = f.denominator
    for prime in (2, 5):
        while q % prime == 0:
            q //= prime
    return (f.numerator, f.denominator) if q > 1 else None


def fraction_text(value: float) -> str | None:
    """`value` as `17/12` (a real minus sign if negative), or None (see `fraction`)."""
    pq = fraction(value)
    if pq is None:
        return None
    p, q = pq
    return f"{MINUS if p < 0 else ''}{abs(p)}/{q}"
