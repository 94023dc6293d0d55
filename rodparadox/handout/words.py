"""Numbers and names as a handout writes them in its sentences. Pure text.

A number is written as a fraction where a small-denominator one matches and its
decimal never ends (`numbers.fraction_text`: 17/12, 15/17), else with PROSE_DIGITS
significant digits in the running text and ANSWER_DIGITS in the worked answers;
x and t as multiples of L (`in_l`: 17/12 L), velocities as fractions of c with
their sign (`in_c`: +0.6 c, −15/17 c). Names: impacts (A₁ and B₁), a frame's time
coordinate (t, t′, tᵤ), and lists (a, b and c); a frame (S, S′, the frame u = 0.3)
is named by `physics.frames.frame_name`, as a strip's readout names it.
"""

from __future__ import annotations

import re
from typing import Sequence

from rodparadox.numbers import MINUS, SCIENTIFIC_BELOW, fraction_text, impact_name, shown
from rodparadox.physics.engine import Impact
from rodparadox.physics.frames import Frame
from rodparadox.tables.build import coordinates

#: significant digits of a number in running text (explanations, captions), and in a worked answer
PROSE_DIGITS = 4
ANSWER_DIGITS = 7


# --- numbers ---------------------------------------------------------------------------------------------------

def numeral(x: float, digits: int = PROSE_DIGITS, speed: bool = False) -> str:
    """17/12 where a small fraction matches and its decimal never ends, else `digits` significant digits; a `speed`
    below c keeps the digits that keep it below 1 (`numbers.shown`), any other number rounds (1 − 2e-16 is 1)."""
    x += 0.0
    exact_text = fraction_text(x)
    if exact_text:
        return exact_text
    if not speed and SCIENTIFIC_BELOW <= abs(x) < 1.0:
        return f"{x:.{digits}g}".replace("-", MINUS)
    return shown(x, digits)


def numeral_approx(x: float, digits: int = ANSWER_DIGITS) -> str:
    """17/12 ≈ 1.416667: the fraction and the decimal a calculator shows; the decimal alone if no fraction."""
    exact_text = fraction_text(x + 0.0)
    return f"{exact_text} ≈ {shown(x, digits)}" if exact_text else shown(x, digits)


def signed_numeral(x: float, digits: int = PROSE_DIGITS) -> str:
    """+0.6, −15/17, 0: a velocity's sign always shown."""
    text = numeral(x, digits, speed=True)
    return text if text == "0" or text.startswith(MINUS) else "+" + text


def in_c(u: float, digits: int = PROSE_DIGITS) -> str:
    """+0.6 c, −15/17 c, 0 (at rest: no sign, no unit)."""
    text = signed_numeral(u, digits)
    return text if text == "0" else f"{text} c"


def in_l(value: float, digits: int = PROSE_DIGITS) -> str:
    """A multiple of L: 17/12 L, −3/4 L, 0."""
    text = numeral(value, digits)
    return text if text == "0" else f"{text} L"


def in_l_approx(value: float) -> str:
    """17/12 L ≈ 1.416667 L, or 1.981152 L."""
    exact_text = fraction_text(value + 0.0)
    if exact_text:
        return f"{exact_text} L ≈ {shown(value, ANSWER_DIGITS)} L"
    return in_l(value, ANSWER_DIGITS)


# --- numbers in worked answers ---------------------------------------------------------------------------------

def answer_numeral(x: float) -> str:
    """A number in a worked answer: a fraction where one matches, else ANSWER_DIGITS significant digits."""
    return numeral(x, ANSWER_DIGITS)


def bracketed(x: float) -> str:
    """A number squared, divided or multiplied: (−0.75), (5/6), 0.5."""
    text = answer_numeral(x)
    return f"({text})" if text.startswith(MINUS) or "/" in text else text


def summand(x: float) -> str:
    """A number in a sum: (−0.75), 5/6."""
    text = answer_numeral(x)
    return f"({text})" if text.startswith(MINUS) else text


def in_c_approx(u: float) -> str:
    """+15/17 c ≈ +0.8823529 c, or +0.5076923 c."""
    exact_text = fraction_text(u + 0.0)
    if exact_text:
        decimal = signed_numeral(u, ANSWER_DIGITS).replace(exact_text, shown(abs(u), ANSWER_DIGITS))
        return f"{signed_numeral(u)} c ≈ {decimal} c"
    return in_c(u, ANSWER_DIGITS)


# --- names -----------------------------------------------------------------------------------------------------

def listed(words: Sequence[str]) -> str:
    """a; a and b; a, b and c."""
    words = list(words)
    return words[0] if len(words) == 1 else ", ".join(words[:-1]) + " and " + words[-1]


def impact_names(impacts: Sequence[Impact]) -> str:
    return listed([impact_name(i.label) for i in impacts])


def with_primes(text: str) -> str:
    """A scenario's own text in the handout's Unicode: S' -> S′, t' -> t′ (an apostrophe after one of these
    letters standing alone is a prime; "rod's" keeps its apostrophe)."""
    return re.sub(r"\b([Sxt])'(?![A-Za-z])", "\\1\N{PRIME}", " ".join(text.split()))


def capitalised(text: str) -> str:
    """A sentence's first letter upper case: the frame u = 0.3 -> The frame u = 0.3."""
    return text[:1].upper() + text[1:]


def time_name(frame: Frame) -> str:
    """The frame's time coordinate: t, t′, tᵤ."""
    return coordinates(frame)[1]


# --- changes of velocity ---------------------------------------------------------------------------------------

def pushed(before: float, after: float) -> str:
    """What a collision does to the rod's velocity, in words without numbers: sets off left, turns right, stops."""
    side = "right" if after > 0 else "left"
    if after == 0.0:
        return "stops"
    if before == 0.0:
        return f"sets off {side}"
    if (before > 0) != (after > 0):
        return f"turns {side}"
    return "speeds up" if abs(after) > abs(before) else "slows"
