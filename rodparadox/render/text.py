"""What the panels say, and how large it is: frame names, axis and impact labels, titles, tick labels, and text
measured in points as the SVG and PDF backends lay it out (current rcParams), without a renderer."""

from __future__ import annotations

import math
import re
from functools import lru_cache

import matplotlib
import numpy as np
from matplotlib.cbook import is_math_text
from matplotlib.font_manager import FontProperties
from matplotlib.textpath import text_to_path

from rodparadox.physics.frames import Frame, frame_symbol, FrameView
from rodparadox.render import mathtext_parses  # noqa: F401 -- installs the process-wide cache of mathtext parses
from rodparadox.physics.model import Scenario
from rodparadox.numbers import MINUS, SCIENTIFIC_ABOVE, impact_parts, shown, shown_signed
from rodparadox.tolerances import AT_REST, STEP_ROUNDING


def coordinate_names(frame: Frame) -> tuple[str, str]:
    """The frame's (x, t) as plain italic text, or mathtext for a frame of velocity u (x_u, t_u)."""
    return {"rest": ("x", "t"), "moving": ("x\N{PRIME}", "t\N{PRIME}")}.get(frame.name, ("$x_u$", "$t_u$"))


def axis_label(name: str) -> str:
    """x -> x/L (set in italics), $x_u$ -> $x_u/L$ (mathtext)."""
    return f"{name[:-1]}/L$" if name.endswith("$") else f"{name}/L"


def impact_text_size(label: str, size: float) -> tuple[float, float, float]:
    """A box at least as large as `impact_name(label, math_text=True)` draws, from plain glyph metrics (no
    mathtext parse).

    The letter in italics, then the digits at 0.7 of the size, then a tenth of
    the size to spare; height: the letter's plus the subscript's drop. It is a
    few per cent larger than mathtext's own box in every style (tested), which
    is safe for placing the label: the drawn text lies inside it.
    """
    letter, digits = impact_parts(label)
    w_letter, h_letter, _ = text_size(letter, size, italic=True)
    w_digits = text_size(digits, 0.7 * size)[0] if digits else 0.0
    return w_letter + w_digits + 0.1 * size, h_letter + 0.22 * size, 0.22 * size


def _velocity_phrase(before: float, after: float) -> str:
    """The rod's velocity in a panel's frame, before the first impact and after the last."""
    def at(u: float) -> str:
        return "at rest" if abs(u) < AT_REST else f"at {shown_signed(u, 4)}"
    if abs(before - after) < AT_REST:
        return f"rod {at(before)} before and after"
    return f"rod first {at(before)}, finally {at(after)}"


def panel_title(letter: str, fv: FrameView, ringing_at: float | None = None, after: float | None = None) -> str:
    """Plain text, no mathtext (each mathtext string costs milliseconds to lay out): the frame and the rod's velocity
    (`ringing_at`: a causal rod's velocity after its last separation, that of its centre of momentum: it rings;
    `after`: its velocity at the end, where no impact says it, as for a rod driven by forces)."""
    frame = fv.frame
    if after is None:
        after = fv.events[-1].rod_velocity_after if fv.events else frame.rod_velocity()
    if ringing_at is not None:
        return f"({letter}) frame {frame_symbol(frame)}: {_velocity_phrase(frame.rod_velocity(), ringing_at)}, ringing"
    return f"({letter}) frame {frame_symbol(frame)}: {_velocity_phrase(frame.rod_velocity(), after)}"


def mathtext_safe(text: str) -> str:
    return text.replace("$", r"\$")


def heading(scenario: Scenario) -> str:
    """What a figure's title calls the scenario: its title, in words ("Impacts simultaneous in the moving frame"),
    or its name where it has none (a file name says nothing to a reader of the figure when a title is given)."""
    text = scenario.title or scenario.name
    if not scenario.title:
        return text
    text = re.sub(r"\b([SxXtT])'", "\\1\N{PRIME}", text)  # S' as in the panels: S′
    return re.sub(r"(?<=\w)'(?=\w)", "\N{RIGHT SINGLE QUOTATION MARK}", text)  # the paper’s, as set in print


def suptitle(scenario: Scenario, width: float, size: float, after: str = "") -> str:
    """The scenario's heading (`heading`), `after` (what the figure shows: ": energy and momentum") and v; without
    a title, the name followed by its description's first clause if that fits; a title's closing parenthesis is
    dropped if that fits, else a long heading is cut with an ellipsis."""
    s = scenario
    room = width - 10
    label = heading(s)

    def fits(text: str) -> bool:
        return approximate_size(text, size)[0] <= room

    tail = f"{mathtext_safe(after)}, $v = {shown(s.v, math_text=True)}$"
    head = f"{mathtext_safe(label)}{tail}"
    short = re.sub(r"\s*\([^()]*\)$", "", label)  # a title's closing parenthesis ("(the paper's Fig. 2)") may go
    if not fits(head) and short != label and fits(f"{mathtext_safe(short)}{tail}"):
        return f"{mathtext_safe(short)}{tail}"
    if not fits(head):  # the longest start of the heading that fits, then an ellipsis: visibly cut, never off the page
        lo, hi = 0, len(label)
        while lo < hi:
            mid = (lo + hi + 1) // 2
            lo, hi = (mid, hi) if fits(f"{mathtext_safe(label[:mid].rstrip())}\N{HORIZONTAL ELLIPSIS}{tail}") else (lo, mid - 1)
        return f"{mathtext_safe(label[:lo].rstrip())}\N{HORIZONTAL ELLIPSIS}{tail}"
    if s.title:
        return head
    # the description's first clause: up to a semicolon or the end of its first sentence
    clause = re.split(r";|\.(?=\s+[A-Z]|\s*$)", " ".join(s.description.split()))[0].strip()
    if clause:
        clause = re.sub(r"\b([SxXtT])'", "\\1\N{PRIME}", clause)  # S' as in the panels: S′
        full = f"{head}: {mathtext_safe(clause)}"
        if fits(full):
            return full
    return head


#: a unit (and what closes after it) that stays on the line of the number before it: "3.207 L)", "0.5 M c²"
_UNIT = re.compile(r"(?:L|c|c²|M)[),.;:]*")


def note_lines(note: str, width: float, size: float) -> list[str]:
    """A paragraph of plain text (a figure's note) broken into lines no wider than `width` points at `size`, never
    between a number and its unit."""
    room, lines, words = width / 1.08, [], []  # long runs of text draw up to 6 % wider than measured
    for word in note.split(" ") if note else ():
        if words and _UNIT.fullmatch(word):
            words[-1] += f" {word}"
        else:
            words.append(word)
    # Each line: its first word, then as many of the next words as fit. A line's measured width never shrinks as
    # words are added (the box of its glyphs only grows to the right), so the most that fit is found by bisection:
    # the same lines as adding word after word, from a few measurements a line instead of one a word (a handout's
    # notes measured thousands of lines growing by a word).
    start = 0
    while start < len(words):
        lo, hi = start + 1, len(words)  # words[start:lo] is the line so far (it fits, or is one word)
        while lo < hi:
            mid = (lo + hi + 1) // 2
            if approximate_size(" ".join(words[start:mid]), size)[0] <= room:
                lo = mid
            else:
                hi = mid - 1
        lines.append(" ".join(words[start:lo]))
        start = lo
    return lines


# --- ticks ------------------------------------------------------------------------------------------

def ticks_at(lo: float, hi: float, step: float) -> np.ndarray:
    k = np.arange(math.ceil(lo / step - STEP_ROUNDING), math.floor(hi / step + STEP_ROUNDING) + 1)
    return k * step


def tick_text(value: float, step: float) -> str:
    """A tick label with as many decimals as the step has (0.25 -> 2), a real minus sign, no -0; 2×10⁶ for steps of 10⁵ on."""
    if step >= SCIENTIFIC_ABOVE / 10:
        return shown(value, 3)
    decimals = next(d for d in range(12) if abs(round(step, d) - step) <= STEP_ROUNDING * step)
    text = f"{value:.{decimals}f}"
    if float(text) == 0:
        text = "0" if decimals == 0 else f"{0:.{decimals}f}"
    return text.replace("-", MINUS)


# --- sizes in points -------------------------------------------------------------------------------

def text_size(text: str, size: float, italic: bool = False, ismath: bool | None = None,
              bold: bool = False) -> tuple[float, float, float]:
    """(width, height, descent) in points of a text as the SVG and PDF backends lay it out (current rcParams).

    `ismath` None reads the text as a Text artist does: mathtext if it holds an
    even number of unescaped $ (matplotlib.cbook.is_math_text), else plain.
    Drawing calls it for plain text only: parsing mathtext costs milliseconds
    and the renderer parses each string again, so mathtext is sized from its
    glyphs instead (`approximate_size`, `impact_text_size`).
    """
    return _measured(text, float(size), italic, is_math_text(text) if ismath is None else bool(ismath), bool(bold),
                     *measuring_fonts())


def measuring_fonts() -> tuple:
    """The current rcParams' font settings that decide what `text_size` measures: the key of what is kept for
    them (its own cache, and `handout.pdf_text.wrap`'s)."""
    value = dict.__getitem__  # the stored values, without RcParams' per-read checks: called ~10^5 times a handout
    rc = matplotlib.rcParams
    return (value(rc, "mathtext.fontset"), tuple(value(rc, "font.family")), tuple(value(rc, "font.sans-serif")),
            tuple(value(rc, "font.serif")))


@lru_cache(maxsize=8192)  # a figure measures a few hundred texts, a handout thousands; bounded for a long-lived process
def _measured(text: str, size: float, italic: bool, ismath: bool, bold: bool, *fonts) -> tuple[float, float, float]:
    """`text_size` for the current rcParams, whose font settings are `fonts` (part of the cache key only)."""
    prop = FontProperties(size=size, style="italic" if italic else "normal", weight="bold" if bold else "normal")
    w, h, d = text_to_path.get_text_width_height_descent(text, prop, ismath=ismath)
    return float(w), float(h), float(d)


# mathtext -> the plain characters it draws, roughly: the braces of groups vanish, \$ is a dollar sign
_MATH_AS_PLAIN = {"\\$": "$", "\\pm": "\N{PLUS-MINUS SIGN}", "\\times": "\N{MULTIPLICATION SIGN}",
                  "^2": "\N{SUPERSCRIPT TWO}", "{": "", "}": "", "'": "\N{PRIME}"}



def text_size_cache_info():
    """How full `text_size`'s cache of measured texts is (functools' CacheInfo): it is bounded."""
    return _measured.cache_info()

def approximate_size(text: str, size: float) -> tuple[float, float, float]:
    """A slight over-estimate of what a Text artist draws for `text`, without parsing mathtext.

    Plain text (no pair of unescaped $) is measured as it is. Mathtext is
    measured as plain characters, each $...$ part by the characters it draws,
    each \\$ outside them as a dollar sign, plus 4 %.
    """
    if not is_math_text(text):
        return text_size(text, size, ismath=False)
    parts = re.split(r"(?<!\\)\$", text)  # even: plain text between the math parts; odd: math
    plain = "".join(part.replace("\\$", "$") if i % 2 == 0 else
                    re.sub(r"\\\$|\\pm|\\times|\^2|[{}']", lambda m: _MATH_AS_PLAIN[m.group(0)], part)
                    for i, part in enumerate(parts))
    w, h, d = text_size(plain, size, ismath=False)
    return w * 1.04 + 2.0, max(h, size * 1.1), max(d, size * 0.25)
