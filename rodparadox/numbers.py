"""How numbers are written: exactly in names (files, frames), readably in figures, aligned in tables; nice steps;
impact labels. Pure, no imports to speak of.

One home for all of these, so a frame's name, a file name, a figure's title, a
table and a handout never disagree about a number or an impact's name, and no
figure shows a `-0` or a `1e-06`.
"""

from __future__ import annotations

import math
import re

from rodparadox.tolerances import FRACTION_CHANCE, FRACTION_MATCH, PRINTED_ZERO, STEP_ROUNDING

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
    """A number as a figure draws it: up to `significant` digits (every digit before the point, where there are more:
    12345.6 with 4 is 12346), a real minus sign, no -0, 1×10⁻⁶ for tiny ones.

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
    if "e" in text:  # at least `significant` digits before the point: 'g' would write 12345 as 1.234e+04
        text = f"{value:.0f}"
    return text if math_text else text.replace("-", MINUS)


#: a number as a user writes it, on the command line and in a scenario file: decimal digits, an optional point and
#: exponent (0.6, -.5, 1e-6, 2E9), or inf/nan (which the values' own checks refuse as not finite)
DECIMAL = re.compile(r"[-+]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][-+]?[0-9]+)?|[-+]?(?:inf|infinity|nan)",
                     re.IGNORECASE)


def decimal(text: str) -> float:
    """A number written in decimal, as `float`, but refusing what only Python reads (`1_000`, ` 1`) or reads
    otherwise (`0x10` is no float at all): one rule for every number a user writes. -0 is 0.
    Raises ValueError."""
    if not isinstance(text, str) or not DECIMAL.fullmatch(text.strip()):
        raise ValueError(f"not a decimal number: {text!r}")
    return float(text) + 0.0


def whole(text: str) -> int:
    """A whole number written in decimal digits (an optional sign): `int` without Python's `1_000`. Raises
    ValueError."""
    if isinstance(text, int) and not isinstance(text, bool):
        return text
    if not isinstance(text, str) or not re.fullmatch(r"[-+]?[0-9]+", text.strip()):
        raise ValueError(f"not a whole number: {text!r}")
    return int(text)


def exact_signed(value: float) -> str:
    """`exact`, with its sign always written: +0.6, -0.9999999, +0 (a velocity the user gave, or its negative)."""
    text = exact(value)
    return text if text.startswith("-") else "+" + text


def shown_signed(value: float, significant: int = 10) -> str:
    """`shown`, with a + before a positive number: +0.6, −0.6, 0 (zero has no sign)."""
    return ("+" if value > 0 else "") + shown(value, significant)


# --- numbers in tables ----------------------------------------------------------------------------------------

#: significant digits of a coordinate, and of the largest velocity, in a table (`events`, `ledger`, a handout's)
TABLE_DIGITS = 7


def without_zero_sign(text: str) -> str:
    """A number's text without the sign of a zero: -0.000 is +0.000 (a value that rounds to zero has no sign)."""
    mantissa = text.split("e")[0]
    return "+" + text[1:] if text.startswith("-") and not any(c in "123456789" for c in mantissa) else text


def coordinate_format(values: list[float], signed: bool = True):
    """Every value of one column with the same decimals, so that the decimal points line up and every digit says
    the same precision: TABLE_DIGITS significant digits in the largest, trailing zeros kept (+0.5000000 where the
    largest is below 1; beside +1.048285 a zero is +0.000000, never +0, and +3.206777 keeps its place); rounding-sized
    values (PRINTED_ZERO of the largest) are zero. A column whose largest is below SCIENTIFIC_BELOW or at least
    10**TABLE_DIGITS writes each value with TABLE_DIGITS significant digits and an exponent (1.583333e-05).
    `signed`: a plus sign on the positive (the events' x and t), else none (the slices' times, an energy)."""
    largest = max((abs(x) for x in values), default=0.0)
    scientific = largest > 0.0 and not SCIENTIFIC_BELOW <= largest < 10.0 ** TABLE_DIGITS
    decimals = 0 if largest == 0.0 or scientific else max(0, TABLE_DIGITS - 1 - math.floor(math.log10(largest)))

    def text(x: float) -> str:
        if abs(x) <= PRINTED_ZERO * largest:
            x = 0.0
        if scientific and x != 0.0:
            written = without_zero_sign(f"{x + 0.0:+#.{TABLE_DIGITS}g}")
        else:
            written = without_zero_sign(f"{x + 0.0:+.{decimals}f}")
        return written if signed else written.lstrip("+")
    return text


def velocity_format(velocities: list[float]):
    """Every velocity fixed-point with one number of decimals, so that the decimal points line up: TABLE_DIGITS - 1
    significant digits in the largest (6 decimals, more when every speed is small: 1e-6 keeps its digits), and,
    where a speed is near c, as many more decimals as keep it from rounding to 1 (`frames.check_below_c`: none is
    1), for every velocity given: pass one column's."""
    largest = max((abs(u) for u in velocities), default=0.0)
    decimals = TABLE_DIGITS - 1
    if 0 < largest < 0.1:
        decimals = TABLE_DIGITS - 2 - math.floor(math.log10(largest))

    def near_c(u: float) -> int:
        return math.ceil(-math.log10(1.0 - abs(u))) + 1 if abs(u) > 0.5 else 0
    # one number of decimals for every velocity given, so that a column shares them (issue 24)
    decimals = max([decimals] + [near_c(u) for u in velocities])

    def text(u: float) -> str:
        return without_zero_sign(f"{u + 0.0:+.{max(decimals, near_c(u))}f}")
    return text


def number_text(x: float, zero_below: float = 0.0) -> str:
    """TABLE_DIGITS significant digits, no -0; a value below `zero_below` in size is rounding of a difference: 0."""
    x = x + 0.0
    if abs(x) < zero_below:
        return "0"
    text = f"{x:.{TABLE_DIGITS}g}"
    return "0" if float(text) == 0 else text


# --- nice numbers -------------------------------------------------------------------------------------------------

#: a nice number is one of these times a power of ten: tick steps, clock steps, scale bars
NICE_MULTIPLES = (1, 2, 2.5, 5)


def nice_number(value: float, bound: str = "at_least") -> float:
    """The nice number (NICE_MULTIPLES times a power of ten) nearest `value` (> 0) on one side:

    `at_least`: the least not below it (a tick step for at most so many ticks); `at_most`: the largest not
    above it (a scale bar that fits); `above`: the least strictly above it (the next tick step up). Equality is
    within STEP_ROUNDING, as `value` is often computed.
    """
    if bound == "above":
        magnitude = 10.0 ** math.floor(math.log10(value) + STEP_ROUNDING)
        return next(m * magnitude for m in (*NICE_MULTIPLES[1:], 10, 20) if m * magnitude > value * (1 + STEP_ROUNDING))
    magnitude = 10.0 ** math.floor(math.log10(value))
    if bound == "at_most":
        return max(m * magnitude for m in NICE_MULTIPLES if m * magnitude <= value * (1 + STEP_ROUNDING))
    if bound == "at_least":
        return next(m * magnitude for m in (*NICE_MULTIPLES, 10) if m * magnitude >= value * (1 - STEP_ROUNDING))
    raise ValueError(f"bound must be at_least, at_most or above, got {bound!r}")


# --- impact labels ------------------------------------------------------------------------------------------------

_SUBSCRIPT = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def impact_parts(label: str) -> tuple[str, str]:
    """An impact's label split into its particle and its number: B12 -> (B, 12); anything else -> (label, "")."""
    m = re.fullmatch(r"([A-Za-z]+)(\d+)", label)
    return (m.group(1), m.group(2)) if m else (label, "")


def impact_name(label: str, math_text: bool = False) -> str:
    """An impact's label as every figure, table and handout writes it: B1 -> B₁ (plain text, subscript digits),
    or with `math_text` $B_{1}$ for mathtext; the causal rod's separation B1s as B′₁ (`$B$′$_{1}$`: the prime a
    character of the text between the letter and the subscript, at the letter's height as in print; mathtext's own
    $B'_{1}$ raises it as a superscript, above the letter's top in STIX); anything else as it is."""
    separation = label.endswith("s") and impact_parts(label[:-1])[1] != ""
    letter, digits = impact_parts(label[:-1] if separation else label)
    if not digits:
        return label
    if math_text:
        return f"${letter}$\N{PRIME}$_{{{digits}}}$" if separation else f"${letter}_{{{digits}}}$"
    return letter + ("\N{PRIME}" if separation else "") + digits.translate(_SUBSCRIPT)


# --- fractions ----------------------------------------------------------------------------------------------------

#: the largest denominator a number is written as a fraction with: the paper's are 12ths, 8ths, 25ths at v = 0.6
FRACTION_DENOMINATOR = 100


def fraction(value: float, largest_denominator: int = FRACTION_DENOMINATOR) -> tuple[int, int] | None:
    """(p, q) with q > 1 if `value` is p/q to FRACTION_MATCH relative, q <= `largest_denominator`, the match is
    meaningful in double precision (a number that is no fraction would come that close to one with a chance
    below FRACTION_CHANCE: a large number, matched to FRACTION_MATCH of its size, never is) and the decimal
    of p/q never ends (q has a prime factor other than 2 and 5: 17/12, 1/3), else None.

    A decimal that ends (5/4 = 1.25, 73/100 = 0.73) says everything already; 1.416667 does not say 17/12.
    """
    from fractions import Fraction

    if not math.isfinite(value):
        return None
    f = Fraction(value).limit_denominator(largest_denominator)
    match = FRACTION_MATCH * max(abs(value), 1e-300)  # how far rounding may have moved a number of this size
    if f.denominator == 1 or abs(value - f.numerator / f.denominator) > match:
        return None
    q = f.denominator
    # meaningful only if a number that is no fraction would seldom come this close to one: fractions with
    # denominators up to q lie about 3 q^2 / pi^2 to a unit, so a chance match has probability about
    # 2 match 3 q^2 / pi^2 (909999955/91 matched to 1e-12 of 1e7 would be one in sixteen)
    if 2.0 * match * 3.0 * q * q / math.pi ** 2 > FRACTION_CHANCE:
        return None
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
