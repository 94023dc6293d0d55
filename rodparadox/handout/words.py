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

from rodparadox.handout.document import Fact
from rodparadox.numbers import MINUS, SCIENTIFIC_BELOW, fraction_text, impact_name, shown
from rodparadox.physics.types import Impact
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


# --- what a question asks, as it would be printed ----------------------------------------------------------------

#: the digits a number is printed with anywhere (prose 4, a table 7, a figure's readout or colour bar 3 or 4)
PRINTED_DIGITS = range(3, 8)


def number_forms(x: float) -> tuple[str, ...]:
    """Every way a handout, a table or a figure could print |x|: its fraction (15/17) and its decimals with 3 to 7
    significant digits or decimals (0.882, 0.8824, 0.882353, 0.8823529; 1.3 for 1.299651 is too short to search). The sign is left out, so +0.8824 and
    −0.8824 are both found. A round number (x to two significant digits: 0, 0.6, 1.2, 0.25) has none: it is also
    what the set-up gives (v = 0.6, 0.5 L), so finding it would tell nothing."""
    x = abs(x + 0.0)
    if abs(float(f"{x:.2g}") - x) <= 1e-12 * max(1.0, x) or not 1e-3 <= x < 1e6:
        return ()
    forms = {fraction_text(x)} | {shown(x, d) for d in PRINTED_DIGITS} | {f"{x:.{d}f}" for d in PRINTED_DIGITS}
    return tuple(sorted(f for f in forms if f and ("/" in f or len(f.replace(".", "").lstrip("0")) >= 3)))


def told_number(what: str, x: float) -> Fact:
    """A number a question asks for (`number_forms`)."""
    return Fact(what, number_forms(x), number=True)


def told_claim(what: str, *phrases: str) -> Fact:
    """A claim a question asks about, as the phrases that would state it."""
    return Fact(what, tuple(dict.fromkeys(phrases)))


def simultaneity_facts(first: str, second: str, frame: str, same: bool, gap: float = 0.0) -> tuple[Fact, ...]:
    """Whether two impacts (named B₁, A₁, the earlier first) are simultaneous in a frame (named S′), and if not how
    far apart: the phrases that state it (a ledger's row label "B₁ and A₁" for one instant, "same instant of S′",
    the preset's title "simultaneous in the moving frame"; if not, that one comes before the other: "In S′, A₁
    comes before B₁" answers whether they are simultaneous) and the interval."""
    described = {"S": "the rod's rest frame", "S′": "the moving frame"}.get(frame, frame)
    if same:
        return (told_claim(f"{first} and {second} simultaneous in {frame}", f"{first} and {second}",
                           f"{second} and {first}", f"simultaneous in {frame}", f"simultaneous in {described}",
                           f"same instant of {frame}", f"one instant of {frame}", "share one"),)
    return (told_claim(f"{first} and {second} not simultaneous in {frame}", "not simultaneous",
                       f"different instants of {frame}", f"different instants of {described}"),
            *order_facts(first, second, frame),
            told_number(f"the time between {first} and {second} in {frame}", gap))


def order_facts(earlier: str, later: str, frame: str) -> tuple[Fact, ...]:
    """That one impact comes before another in a frame's time, as the phrases that would say so."""
    return (told_claim(f"{earlier} before {later} in {frame}", f"{earlier} comes before {later}",
                       f"{later} comes after {earlier}", f"after {earlier} and before {later}",
                       f"{earlier}, then {later}", f"{later} comes"),)


# --- variables in math italics ---------------------------------------------------------------------------------

#: the letters that are variables wherever they stand alone (v, L, t, x, E, p, u, w, m): set in math italics, while
#: units (c, M), frames (S, S′) and labels (A, B₁) stay upright
VARIABLES = "vLtxEpuwm"
#: a variable: one of VARIABLES standing alone (no letter or apostrophe before it, no letter after it), with its
#: primes, subscripts (tᵤ, x_P) and powers (u²)
VARIABLE = re.compile(rf"(?<![A-Za-z'’_])[{VARIABLES}]['′]*(?:_[A-Z]|[ᵤ₀-₉]+)?²?(?![A-Za-z0-9])")


def math_pieces(text: str) -> list[tuple[str, bool]]:
    """The text cut into (piece, is a variable), in order: "t′ = 17/12 L" -> [("t′", True), (" = 17/12 ", False),
    ("L", True)]. The PDF sets the variables in italics, the LaTeX in $...$."""
    pieces, k = [], 0
    for m in VARIABLE.finditer(text):
        if m.start() > k:
            pieces.append((text[k:m.start()], False))
        pieces.append((m.group(), True))
        k = m.end()
    if k < len(text):
        pieces.append((text[k:], False))
    return pieces


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
