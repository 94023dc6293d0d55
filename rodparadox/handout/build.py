"""What a handout and a worksheet say, as `document` blocks (issue 9). Pure: no matplotlib, no LaTeX.

`build` turns scenarios' histories into a `document.Handout`: per scenario a
heading, a set-up paragraph, the diagram with its caption, an explanation, the
rod at successive instants in each frame, the events, ledger and hidden tables,
and for a worksheet 5 to 8 questions whose worked answers the answer key
prints. Every sentence is generated from the computed history: which impacts
share a line of simultaneity is tested, pair by pair, in each frame shown and
on the rod's own lines (`Impact.collision`); the rod's velocity is read from
the impacts' rapidities; turns come from `History.turns`; a question about
another speed runs the engine again. `handout_pdf` and `handout_tex` set the
same blocks on paper and in LaTeX.

Conventions (README, "The model"): c = 1; x and t are quoted as multiples of L
(17/12 L), so they hold for any L; speeds as fractions of c; masses in M,
energies in M c², momenta in M c. S′ moves at −v relative to S, so
t′ = γ(t + v x) (derived in the answers from `Event.seen_from`, never copied from
the paper's appendix, which misprints the sign). A number is written as a
fraction where a small-denominator one matches and its decimal never ends
(`numbers.fraction_text`: 17/12, 15/17), else with PROSE_DIGITS significant
digits in the running text and ANSWER_DIGITS in the worked answers.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from functools import cached_property
from typing import Sequence

from rodparadox.tables import build as tables
from rodparadox.handout.document import Block, DiagramBlock, Handout, Heading, Paragraph, Question, Section, Strips
from rodparadox.physics.engine import History, Impact, Turn, run
from rodparadox.errors import RodParadoxError
from rodparadox.physics.frames import (PANEL_LETTERS, Frame, frame_symbol, frame_word, moving_frame, paper_frames, relative_velocity,
                     rest_frame, time_window)
from rodparadox.physics.ledger import initial_total, ledger_slice
from rodparadox.numbers import MINUS, SCIENTIFIC_BELOW, exact, fraction_text, impact_name, shown
from rodparadox.physics.rod import rod_slice, turn_corners, turn_interval
from rodparadox.physics.frames import time_order
from rodparadox.tables.build import coordinates
from rodparadox.tolerances import ONE_INSTANT, PRINTED_ZERO

#: significant digits of a number in running text (explanations, captions), and in a worked answer
PROSE_DIGITS = 4
ANSWER_DIGITS = 7
#: the fewest and the most instants of the rod shown per frame
STRIPS_FEWEST, STRIPS_MOST = 6, 8
#: the speeds a "what if" question tries, in this order, for one that differs from the scenario's and runs
OTHER_SPEEDS = (0.8, 0.5, 0.9, 0.3)
#: two rapidities closer than this are one velocity: the engine ends a turn within 1e-12 of its line
#: (engine.TURN_LINE_ROUNDING) and a boost shifts a rapidity by a rounding of about 1e-15 of it
SAME_RAPIDITY = 1e-9
#: the rod's material points sampled to tell whether it moves as a whole on a slice (not turning there)
WHOLE_ROD_POINTS = 9
#: two stills closer than this fraction of the frame's time window look alike on the page: one is kept
STRIP_SEPARATION = 0.02


# --- numbers as text -----------------------------------------------------------------------------------------

def _number(x: float, digits: int = PROSE_DIGITS, speed: bool = False) -> str:
    """17/12 where a small fraction matches and its decimal never ends, else `digits` significant digits; a `speed`
    below c keeps the digits that keep it below 1 (`numbers.shown`), any other number rounds (1 − 2e-16 is 1)."""
    x += 0.0
    exact_text = fraction_text(x)
    if exact_text:
        return exact_text
    if not speed and SCIENTIFIC_BELOW <= abs(x) < 1.0:
        return f"{x:.{digits}g}".replace("-", MINUS)
    return shown(x, digits)


def _approx(x: float, digits: int = ANSWER_DIGITS) -> str:
    """17/12 ≈ 1.416667: the fraction and the decimal a calculator shows; the decimal alone if no fraction."""
    exact_text = fraction_text(x + 0.0)
    return f"{exact_text} ≈ {shown(x, digits)}" if exact_text else shown(x, digits)


def _signed(x: float, digits: int = PROSE_DIGITS) -> str:
    """+0.6, −15/17, 0: a velocity's sign always shown."""
    text = _number(x, digits, speed=True)
    return text if text == "0" or text.startswith(MINUS) else "+" + text


def _velocity(u: float, digits: int = PROSE_DIGITS) -> str:
    """+0.6 c, −15/17 c, 0 (at rest: no sign, no unit)."""
    text = _signed(u, digits)
    return text if text == "0" else f"{text} c"


def _in_l(value: float, digits: int = PROSE_DIGITS) -> str:
    """A multiple of L: 17/12 L, −3/4 L, 0."""
    text = _number(value, digits)
    return text if text == "0" else f"{text} L"


def _in_l_approx(value: float) -> str:
    """17/12 L ≈ 1.416667 L, or 1.981152 L."""
    exact_text = fraction_text(value + 0.0)
    if exact_text:
        return f"{exact_text} L ≈ {shown(value, ANSWER_DIGITS)} L"
    return _in_l(value, ANSWER_DIGITS)


def _listed(words: Sequence[str]) -> str:
    """a; a and b; a, b and c."""
    words = list(words)
    return words[0] if len(words) == 1 else ", ".join(words[:-1]) + " and " + words[-1]


def _names(impacts: Sequence[Impact]) -> str:
    return _listed([impact_name(i.label) for i in impacts])


def _primes(text: str) -> str:
    """A scenario's own text in the handout's Unicode: S' -> S′, t' -> t′ (an apostrophe after one of these
    letters standing alone is a prime; "rod's" keeps its apostrophe)."""
    return re.sub(r"\b([Sxt])'(?![A-Za-z])", "\\1\N{PRIME}", " ".join(text.split()))


def _frame_name(frame: Frame) -> str:
    """S, S′, or "the frame u = 0.3" in running text."""
    symbol = frame_symbol(frame)
    return symbol if frame.name in ("rest", "moving") else f"the frame {symbol}"


def _cap(text: str) -> str:
    """A sentence's first letter upper case: the frame u = 0.3 -> The frame u = 0.3."""
    return text[:1].upper() + text[1:]


def _table_unit(L: float) -> str:
    """How the tables give x and t: in units of L, or, for L other than 1, in the unit L is given in."""
    return "in units of L" if L == 1.0 else f"in the unit L is given in (L = {exact(L)})"


def _time_of(frame: Frame) -> str:
    """The frame's time coordinate: t, t′, tᵤ."""
    return coordinates(frame)[1]


# --- the history read for text: times, instants, collisions, velocities ---------------------------------------

@dataclass(frozen=True)
class _Reading:
    """A history and the frames shown, with what the text needs computed once: each impact's coordinates in each
    frame, the instants at which impacts coincide, the rod's collisions in its own order, velocities."""

    history: History
    frames: tuple[Frame, ...]

    @property
    def L(self) -> float:
        return self.history.scenario.L

    @property
    def v(self) -> float:
        return self.history.scenario.v

    @cached_property
    def scale(self) -> float:
        """L plus the largest |x| or |t| of an impact in any frame shown (or in S): what rounding is measured against."""
        values = [abs(c) for f in (*self.frames, rest_frame()) for i in self.history.impacts
                  for c in (self.t(i, f), self.x(i, f))]
        return self.L + max(values, default=0.0)

    @staticmethod
    def t(impact: Impact, frame: Frame) -> float:
        return impact.event.time_in(frame.rapidity)

    @staticmethod
    def x(impact: Impact, frame: Frame) -> float:
        return impact.event.seen_from(frame.rapidity).x

    def length(self, value: float) -> float:
        """A coordinate or time as a multiple of L, rounding-sized values 0 (x′ = 0 of A₁ in Fig. 1 is 6e-17)."""
        return 0.0 if abs(value) <= ONE_INSTANT * self.scale else value / self.L

    def same_time(self, a: float, b: float) -> bool:
        return abs(a - b) <= ONE_INSTANT * self.scale

    def instants(self, frame: Frame) -> tuple[tuple[float, tuple[Impact, ...]], ...]:
        """The impacts grouped by instant of the frame's time, in its order (each group in the rod's order)."""
        impacts = self.history.impacts
        times = [self.t(i, frame) for i in impacts]
        out: list[tuple[float, list[Impact]]] = []
        for k in time_order(times, self.scale):
            if out and self.same_time(out[-1][0], times[k]):
                out[-1][1].append(impacts[k])
            else:
                out.append((times[k], [impacts[k]]))
        return tuple((t, tuple(group)) for t, group in out)

    @cached_property
    def collisions(self) -> tuple[tuple[Impact, ...], ...]:
        """The rod's collisions in its own order, each the impacts on one of its lines of simultaneity (rule 5)."""
        out: list[list[Impact]] = []
        for i in self.history.impacts:
            if out and out[-1][0].collision == i.collision:
                out[-1].append(i)
            else:
                out.append([i])
        return tuple(tuple(c) for c in out)

    @cached_property
    def lines(self) -> tuple[tuple[Impact, ...], ...]:
        """The rod's lines of simultaneity it is struck on, in its own order, each with its impacts: one collision,
        or several when a particle strikes again at once (rule 7). Consecutive impacts on one line share its
        rapidity and their time along it."""
        out: list[list[Impact]] = []
        for i in self.history.impacts:
            last = out[-1][-1] if out else None
            if (last is not None and last.line_rapidity == i.line_rapidity
                    and abs(last.event.time_in(i.line_rapidity) - i.event.time_in(i.line_rapidity))
                    <= ONE_INSTANT * self.scale):
                out[-1].append(i)
            else:
                out.append([i])
        return tuple(tuple(line) for line in out)

    @cached_property
    def turn_causes(self) -> tuple[tuple[Impact, ...], ...]:
        """For each of `History.turns`, the impacts that started it: those on the line after which the rod's
        momentum no longer matches the line (engine: a turn starts where the rod's rapidity differs from the
        line's). Should the count ever differ, the impacts at each turn's pivot."""
        starting = [line for line in self.lines if line[-1].rod_rapidity_after != line[-1].line_rapidity]
        if len(starting) == len(self.history.turns):
            return tuple(starting)
        return tuple(self.impacts_at(turn.pivot) for turn in self.history.turns)

    def velocity(self, rapidity: float, frame: Frame) -> float:
        """The velocity in the frame of a body of this rapidity in S; a rounding-sized one is 0."""
        return 0.0 if abs(rapidity - frame.rapidity) <= SAME_RAPIDITY else math.tanh(rapidity - frame.rapidity)

    def rod_velocities(self, frame: Frame) -> tuple[float, ...]:
        """The rod's (dynamical) velocity in the frame before the first collision and after each, in its own order."""
        rapidities = [0.0] + [c[-1].rod_rapidity_after for c in self.collisions]
        return tuple(self.velocity(r, frame) for r in rapidities)

    def when(self, impacts: Sequence[Impact], frame: Frame, digits: int = PROSE_DIGITS) -> str:
        """t′ = 17/12 L for impacts at one instant of the frame; t′ = 2/3 L and 17/12 L (in the frame's order) for
        impacts the rod takes together but the frame at different instants."""
        times = sorted(self.t(i, frame) for i in impacts)
        distinct = [t for k, t in enumerate(times) if k == 0 or not self.same_time(times[k - 1], t)]
        return f"{_time_of(frame)} = " + _listed([_in_l(self.length(t), digits) for t in distinct])

    def at_instant(self, impact: Impact) -> str:
        """The label of the impact(s) at this impact's event: B₂, or A₁ and B₁ when the rod takes them together."""
        return _names(next(c for c in self.collisions if impact in c))

    def impacts_at(self, event) -> tuple[Impact, ...]:
        """The impacts at an event (a turn's pivot), in the rod's order."""
        return tuple(i for i in self.history.impacts
                     if math.hypot(i.event.x - event.x, i.event.t - event.t) <= ONE_INSTANT * self.scale)


def _zigzags(rapidities: Sequence[float]) -> bool:
    """Whether the rod zig-zags: its velocity changes direction (up, then down, or down, then up) more than once,
    or returns to a value it had before. Rapidities, so the answer is the same in every frame."""
    changes = [b - a for a, b in zip(rapidities, rapidities[1:]) if abs(b - a) > SAME_RAPIDITY]
    reversals = sum(1 for a, b in zip(changes, changes[1:]) if (a > 0) != (b > 0))
    returns = any(abs(rapidities[j] - rapidities[i]) <= SAME_RAPIDITY and any(
        abs(r - rapidities[i]) > SAME_RAPIDITY for r in rapidities[i:j]) for i in range(len(rapidities))
        for j in range(i + 2, len(rapidities)))
    return reversals > 1 or returns


# --- the set-up -----------------------------------------------------------------------------------------------

def _speed(history: History) -> str:
    """v = 0.6, or v = 0.6, L = 2."""
    s = history.scenario
    return f"v = {exact(s.v)}" + (f", L = {exact(s.L)}" if s.L != 1.0 else "")


def title(items: Sequence[tuple[str, History]]) -> str:
    """The Sears paradox: fig2 at v = 0.6; fig1 and fig2 at v = 0.6; fig1 at v = 0.6 and fig2 at v = 0.8."""
    stems = [item[0] for item in items]
    speeds = [_speed(item[1]) for item in items]
    if len(set(speeds)) == 1:
        return f"The Sears paradox: {_listed(stems)} at {speeds[0]}"
    return "The Sears paradox: " + _listed([f"{stem} at {sp}" for stem, sp in zip(stems, speeds)])


def heading(history: History) -> str:
    """The scenario's name and description."""
    s = history.scenario
    description = _primes(s.description)
    return f"{s.name} — {description}" if description else s.name


def _timing_frame(frame: str | float) -> str:
    """The frame a `model.Timing` counts its delay in: S, S′, or the frame of velocity u relative to S."""
    if frame == "rest":
        return "S"
    if frame == "moving":
        return "S′"
    return f"the frame of velocity {_velocity(float(frame))} relative to S"


def setup_text(history: History) -> str:
    """One paragraph: the rod, v and the frames, then each particle's mass, speed, end and start."""
    s = history.scenario
    v = exact(s.v)
    sentences = [
        f"A rod of proper length L = {exact(s.L)} and mass M lies at rest in S, its centre at x = 0 and its ends at "
        f"x = {MINUS}L/2 and x = +L/2, until it is first struck.",
        f"S′ is the frame that moves at {MINUS}{v} c relative to S (v = {v}), so in S′ the rod first moves at "
        f"+{v} c.",
    ]
    starts = dict(history.starts)
    particles = sorted(s.particles, key=lambda p: (p.timed_with is not None, p.name))
    for p in particles:
        mass = "M" if p.mass == 1.0 else f"{_number(p.mass)} M"
        direction = "right" if p.name == "A" else "left"
        speed = exact(s.speed(p)) + " c"
        text = f"Particle {p.name}, of mass {mass}, moves {direction} at {speed} in S towards the rod's {p.end} end"
        gap = (-s.L / 2 - starts[p.name].x) if p.name == "A" else (starts[p.name].x - s.L / 2)
        if p.timed_with is None:
            text += (", starting at that end at t = 0." if p.gap == 0 else
                     f", starting {_in_l(p.gap)} from it at t = 0.")
        else:
            timing = p.timed_with
            frame = _timing_frame(timing.frame)
            if timing.delay == 0:
                when = f"at the same instant of {frame} as {timing.particle}'s first impact"
            else:
                delay = _in_l(abs(timing.delay))
                when = f"{delay} {'after' if timing.delay > 0 else 'before'} {timing.particle}'s first impact, in " \
                       f"the time of {frame}"
            text += f"; it is placed so that its first impact comes {when}"
            text += (f", so at t = 0 it is {_in_l(gap / s.L)} from that end." if gap >= 0 else
                     f", so at t = 0 it is at x = {_in_l(starts[p.name].x / s.L)}.")
        sentences.append(text)
    tables_unit = "" if s.L == 1.0 else f" (the tables give them in the unit L is given in, L = {exact(s.L)})"
    sentences.append(f"Below, lengths and times are given as multiples of L{tables_unit}, speeds as fractions of c "
                     f"(c = 1), masses in units of M; t = 0 is the instant of S at which the particles are where this "
                     f"paragraph puts them.")
    return " ".join(sentences)


# --- the diagram ------------------------------------------------------------------------------------------------

def _frame_described(frame: Frame, v: float) -> str:
    if frame.name == "rest":
        return "S, the rod's rest frame before it is struck"
    if frame.name == "moving":
        return f"S′, where the rod first moves at +{exact(v)} c"
    return f"the frame {frame_symbol(frame)}, moving at {_velocity(frame.velocity)} relative to S"


def diagram_caption(history: History, frames: Sequence[Frame]) -> str:
    """Which panel is which frame, how to read the lines of simultaneity, and which impacts share one."""
    r = _Reading(history, tuple(frames))
    s = history.scenario
    panels = "; ".join(f"({PANEL_LETTERS[k]}) in {_frame_described(f, s.v)}" for k, f in enumerate(frames))
    labels = _names(history.impacts)
    particles = sorted(p.name for p in s.particles)
    dashed = f"the particle {particles[0]} is dashed" if len(particles) == 1 else \
        f"the particles {_listed(particles)} are dashed"
    impacts = (f"The impact is labelled {labels}. Through it run" if len(history.impacts) == 1 else
               f"The impacts are labelled {labels} in the order of the rod's own time. Through each impact run")
    sentences = [f"{s.name} at v = {exact(s.v)}: {panels}.",
                 f"Time runs up the page, x to the right, both in units of L, light at 45°; the rod's two ends bound "
                 f"its shaded world-sheet, and {dashed}.",
                 f"{impacts} the line of simultaneity of S (dotted) and of S′ (dash-dotted)."]
    styles = {"rest": "dotted", "moving": "dash-dotted"}
    shared = []
    for frame in (rest_frame(), moving_frame(s.v)):
        for t, group in r.instants(frame):
            if len(group) > 1:
                shared.append(f"{_names(group)} share one {styles[frame.name]} line, of {frame_symbol(frame)} "
                              f"({r.when(group, frame)})")
    if shared:
        sentences.append(_listed(shared) + ".")
    elif len(history.impacts) > 1:
        sentences.append("No two impacts share a line of S or of S′.")
    return " ".join(sentences)


# --- the explanation -------------------------------------------------------------------------------------------

def _simultaneity(r: _Reading) -> str:
    """Which impacts share a line of simultaneity of which frame, and in what order the rod and each frame take them."""
    h = r.history
    if len(h.impacts) == 1:
        i = h.impacts[0]
        where = "; ".join(f"{r.when([i], f)} in {_frame_name(f)}" for f in r.frames)
        return f"The rod is struck once, by {i.particle} at its {i.end} end: {impact_name(i.label)}, at {where}."
    sentences = []
    collisions, lines = r.collisions, r.lines
    if len(lines) == len(h.impacts):
        sentences.append(f"The rod takes its impacts one at a time, in the order {_names(h.impacts)}: no two lie on "
                         f"one line of its own simultaneity, so each is a collision of its own.")
    elif len(collisions) == 1:
        sentences.append(f"The rod takes {_names(h.impacts)} together: they lie on one line of its own "
                         f"simultaneity and make one collision.")
    else:
        parts = []
        for line in lines:
            on_line = [c for c in collisions if c[0] in line]
            parts.append(", then at once ".join(_names(c) + (" together" if len(c) > 1 else "") for c in on_line))
        sentences.append(f"In its own time the rod takes {', then '.join(parts)}: impacts it takes at once lie on "
                         f"one line of its own simultaneity, and impacts it takes together make one collision.")
    # every set of impacts at one instant of a shown frame, or on one line of the rod's own simultaneity
    groups: list[tuple[Impact, ...]] = [line for line in lines if len(line) > 1]
    for frame in r.frames:
        groups += [g for _, g in r.instants(frame) if len(g) > 1]
    seen = set()
    for group in groups:
        key = tuple(i.label for i in group)
        if key in seen:
            continue
        seen.add(key)
        same_event = all(math.hypot(i.event.x - group[0].event.x, i.event.t - group[0].event.t)
                         <= ONE_INSTANT * r.scale for i in group)
        if same_event:
            sentences.append(f"{_names(group)} happen at one event, so at one instant of every frame.")
            continue
        together = [f for f in r.frames if all(r.same_time(r.t(i, f), r.t(group[0], f)) for i in group)]
        apart = [f for f in r.frames if f not in together]
        on_rod_line = any(set(group) <= set(line) for line in lines)
        if together:
            text = (f"{_names(group)} lie on one line of simultaneity of "
                    + _listed([f"{_frame_name(f)} ({r.when(group, f)})" for f in together]))
            if not on_rod_line:
                text += ", but not on one of the rod's own lines"
        else:
            text = f"{_names(group)} lie on one line of the rod's own simultaneity"
        if apart:
            details = []
            for f in apart:
                ordered = sorted(group, key=lambda i: r.t(i, f))
                first, last = ordered[0], ordered[-1]
                gap = r.length(r.t(last, f) - r.t(first, f))
                details.append(f"in {_frame_name(f)}, where {impact_name(first.label)} comes at {r.when([first], f)} "
                               f"and {impact_name(last.label)} at {_in_l(r.length(r.t(last, f)))}, {_in_l(gap)} later")
            text += ". They are not simultaneous " + "; nor ".join(details)
        sentences.append(text + ".")
    if not groups:
        sentences.append("No two impacts lie on one line of simultaneity of "
                         + " or of ".join(_frame_name(f) for f in r.frames) + ".")
    # the order in each frame's time, and where it is not the rod's own
    orders = []
    for f in r.frames:
        steps = []
        for k, (t, group) in enumerate(r.instants(f)):
            time = r.when(group, f) if k == 0 else _in_l(r.length(t))
            steps.append(f"{_names(group)}{' together' if len(group) > 1 else ''} ({time})")
        orders.append(f"in {_frame_name(f)} {', then '.join(steps)}")
    sentences.append("In each frame's own time the order is: " + "; ".join(orders) + ".")
    for f in r.frames:
        pair = _out_of_order(r, f)
        if pair is not None:
            a, b = (impact_name(i.label) for i in pair)
            sentences.append(f"In {_frame_name(f)} {b} comes before {a}, although the rod takes {a} first: the two "
                             f"events are too far apart for light to join them, so frames may disagree about their "
                             f"order, and it is the rod's own order that decides what happens to it.")
    return " ".join(sentences)


def _out_of_order(r: _Reading, frame: Frame) -> tuple[Impact, Impact] | None:
    """The first two impacts (a, b) that the rod takes in the order a, b but the frame's clocks in the order b, a.
    Only events too far apart for light to join them (|Δx| > |Δt|) can be so: then every frame need not agree."""
    rod_index = {i: k for k, c in enumerate(r.collisions) for i in c}
    for a in r.history.impacts:
        for b in r.history.impacts:
            if (rod_index[a] < rod_index[b] and r.t(b, frame) < r.t(a, frame)
                    and not r.same_time(r.t(a, frame), r.t(b, frame))
                    and abs(a.event.x - b.event.x) > abs(a.event.t - b.event.t)):
                return a, b
    return None


def _velocities(r: _Reading) -> str:
    """The rod's velocity before and after each collision, in each frame, and overall."""
    collisions = r.collisions
    sentences = ["The rod's velocity here is that of its momentum: it changes at once at an impact, while the rod's "
                 "shape follows only as its lines of simultaneity turn (below)."]
    unchanged = all(abs(c[-1].rod_rapidity_after) <= SAME_RAPIDITY for c in collisions)
    if unchanged:
        speeds = _listed([f"{_velocity(r.rod_velocities(f)[0])} in {_frame_name(f)}" for f in r.frames])
        sentences.append(f"It never changes: it is {speeds} before, between and after the impacts.")
        return " ".join(sentences)
    for f in r.frames:
        u = r.rod_velocities(f)
        steps = [f"{_velocity(u[0])} before {_names(collisions[0])}"]
        steps += [f"{_velocity(u[k + 1])} after {_names(c)} ({r.when(c, f)})" for k, c in enumerate(collisions)]
        order = "" if [c[0] for c in collisions] == _first_of_each(r, f) else \
            f" (the clocks of {_frame_name(f)} put these impacts in another order)"
        sentences.append(f"In {_frame_name(f)}, in the rod's own order{order}: " + "; ".join(steps) + ".")
    finals = [(r.rod_velocities(f)[-1], _frame_name(f)) for f in r.frames]
    at_rest = [symbol for u, symbol in finals if u == 0.0]
    moving = [f"{_velocity(u)} in {symbol}" for u, symbol in finals if u != 0.0]
    states = _listed(([f"is at rest in {_listed(at_rest)}"] if at_rest else [])
                     + ([f"moves at {_listed(moving)}"] if moving else []))
    final = r.velocity(r.collisions[-1][-1].rod_rapidity_after, rest_frame())
    sentences.append(f"After the last impact it {states}" + (": as before the first." if final == 0.0 else "."))
    return " ".join(sentences)


def _direction(before: float, after: float) -> str:
    """What a change of velocity does, in words: starts moving left, reverses, slows to, speeds up to, stops."""
    side = "right" if after > 0 else "left"
    if after == 0.0:
        return "stops"
    if before == 0.0:
        return f"starts moving {side} at {_velocity(abs(after)).lstrip('+')}"
    if (before > 0) != (after > 0):
        return f"reverses to move {side} at {_velocity(abs(after)).lstrip('+')}"
    return f"{'speeds up' if abs(after) > abs(before) else 'slows'} to {_velocity(after)}"


def _pushed(before: float, after: float) -> str:
    """What a collision does to the rod's velocity, in words without numbers: sets off left, turns right, stops."""
    side = "right" if after > 0 else "left"
    if after == 0.0:
        return "stops"
    if before == 0.0:
        return f"sets off {side}"
    if (before > 0) != (after > 0):
        return f"turns {side}"
    return "speeds up" if abs(after) > abs(before) else "slows"


def _turn_cause(r: _Reading, turn: Turn) -> tuple[Impact, ...]:
    """The impacts that started the turn."""
    return r.turn_causes[next(k for k, t in enumerate(r.history.turns) if t is turn)]


def _rest_at_full_length(r: _Reading, frame: Frame) -> list[str]:
    """Where the whole rod stands still in the frame after a turn that completes (`_rests`): when, and why."""
    out = []
    time, symbol = _time_of(frame), _frame_name(frame)
    for turn, end, next_start, next_turn in _rests(r, frame):
        cause = _names(_turn_cause(r, turn))
        if next_start is None and frame.name == "rest":
            out.append(f"In S the rod is at rest again, at its full length L, from t = {_in_l(r.length(end))} on, "
                       f"when the turn that {cause} started ends.")
            continue
        if next_start is None:
            span = f"from {time} = {_in_l(r.length(end))} on"
            why = f"the turn that {cause} started ends on a line of constant {time}"
        elif r.same_time(next_start, end):
            span = f"at the instant {time} = {_in_l(r.length(end))}"
            why = (f"the turn that {cause} started ends there, on a line of constant {time}, and "
                   f"{_names(_turn_cause(r, next_turn))} starts the next one at that same instant")
        else:
            span = f"from {time} = {_in_l(r.length(end))} to {_in_l(r.length(next_start))}"
            why = f"the turn that {cause} started ends on a line of constant {time}, and the next begins later"
        out.append(f"In {symbol} the whole rod is at rest {span}, at its full length L: {why}.")
    return out


def _why(r: _Reading) -> str:
    """Zig-zags, stops at full length and turns stopped by an impact: when, in each frame's time, and why."""
    h = r.history
    collisions = r.collisions
    sentences = []
    rest = rest_frame()
    if len(collisions) == 1 and len(collisions[0]) > 1:
        c = collisions[0]
        still = abs(c[-1].rod_rapidity_after) <= SAME_RAPIDITY
        for f in r.frames:
            times = sorted(c, key=lambda i: r.t(i, f))
            if r.same_time(r.t(times[0], f), r.t(times[-1], f)):
                continue
            first, last = times[0], times[-1]
            if still:
                middle = 0.5 * (r.t(first, f) + r.t(last, f))
                hidden = ledger_slice(h, f.rapidity, middle).hidden
                sentences.append(
                    f"In {_frame_name(f)} {impact_name(first.label)} comes at {r.when([first], f)} and "
                    f"{impact_name(last.label)} only at {_in_l(r.length(r.t(last, f)))}, yet the rod moves on at "
                    f"{_velocity(r.rod_velocities(f)[0])} between them: it takes both impulses together, on its own "
                    f"line of simultaneity, where they cancel. Between them in {_frame_name(f)}, {first.particle} "
                    f"has already been struck and {last.particle} not yet, so the momentum {first.particle} gave up, "
                    f"{_number(hidden.p)} M c, is carried by the stress in the rod: the hidden part of the ledger.")
        if not still:
            masses = _listed([f"{i.particle} (mass {_number(h.scenario.particle(i.particle).mass)} M)" for i in c])
            sentences.append(f"The impulses of {masses}, taken together, do not cancel: the rod moves off at "
                             f"{_velocity(r.velocity(c[-1].rod_rapidity_after, rest))} in S.")
    rapidities = [0.0] + [c[-1].rod_rapidity_after for c in collisions]
    if _zigzags(rapidities):
        ups = ["up" if b > a else "down" for a, b in zip(rapidities, rapidities[1:]) if abs(b - a) > SAME_RAPIDITY]
        sentences.append(f"The rod zig-zags: in its own order its velocity goes {', then '.join(ups)}, because it "
                         f"takes the impacts one at a time and each impulse acts alone.")
        motions = []
        for f in r.frames:
            u = r.rod_velocities(f)
            steps = [f"{_pushed(u[k], u[k + 1])} ({_names(c)})" for k, c in enumerate(collisions) if u[k + 1] != u[k]]
            backwards = "" if any(a * b < 0 for a in u for b in u) else ", never moving backwards"
            motions.append(f"in {_frame_name(f)} it {_listed(steps)}{backwards}")
        text = "; ".join(motions)
        sentences.append(text[0].upper() + text[1:] + ".")
    for k, c in enumerate(collisions):
        for i in c:
            previous = next((p for p in reversed(h.impacts[:h.impacts.index(i)]) if p.particle == i.particle), None)
            if previous is None:
                continue
            u_rod = r.velocity(i.rod_rapidity_before, rest)
            u_particle = r.velocity(i.particle_rapidity_before, rest)
            particle = "stood still" if u_particle == 0.0 else f"moved at {_velocity(u_particle)}"
            sentences.append(f"{i.particle} strikes again ({impact_name(i.label)}) because after "
                             f"{_names(collisions[k - 1])} the rod was driven at {_velocity(u_rod)} in S while "
                             f"{i.particle}, since {impact_name(previous.label)}, {particle}: the rod's {i.end} end "
                             f"closed on {i.particle} again.")
    for k, turn in enumerate(t for t in h.turns if not t.completed):
        stopper = impact_name(turn.stopped_by)
        cause = _names(_turn_cause(r, turn))
        far = "left" if turn.pivot_end == "right" else "right"
        reached = _in_frames(r, [r.velocity(turn.rapidity_stop, f) for f in r.frames])
        target = _in_frames(r, [r.velocity(turn.rapidity_to, f) for f in r.frames])
        if k == 0:
            sentences.append(
                f"{stopper} strikes the {far} end while the rod is still turning from {cause}: that turn stops on the "
                f"rod's line of simultaneity through {stopper}, where the {far} end had got only to {reached}, on its "
                f"way to the rod's velocity after {cause}, {target}, and the next turn starts from there; so the rod "
                f"never moves as a whole at that velocity.")
        else:
            sentences.append(f"Likewise {stopper} strikes the {far} end while the rod is still turning from {cause}, "
                             f"when that end had got only to {reached}, on its way to {target}.")
    if any(not t.completed for t in h.turns):
        ranges = []
        for f in r.frames:
            speeds = [r.velocity(x, f) for x in [0.0, h.final_rapidity]
                      + [y for t in h.turns for y in (t.rapidity_from, t.rapidity_stop)]]
            ranges.append(f"from {_velocity(min(speeds))} to {_velocity(max(speeds))} in {_frame_name(f)}")
        sentences.append("Because its turns are cut short, the rod's material only ever moves at velocities "
                         + _listed(ranges) + ".")
    for f in r.frames:
        sentences += _rest_at_full_length(r, f)
    return " ".join(sentences)


def _in_frames(r: _Reading, velocities: Sequence[float]) -> str:
    """−0.2425 c in S (+0.4183 c in S′): one velocity per frame shown, the first frame's outside the brackets."""
    text = f"{_velocity(velocities[0])} in {_frame_name(r.frames[0])}"
    rest = [f"{_velocity(u)} in {_frame_name(f)}" for u, f in zip(velocities[1:], r.frames[1:])]
    return text + (f" ({'; '.join(rest)})" if rest else "")


def _first_of_each(r: _Reading, frame: Frame) -> list[Impact]:
    """The first impact of each collision, ordered by the frame's time of that impact (the rod's order at a tie)."""
    firsts = [c[0] for c in r.collisions]
    return [firsts[k] for k in time_order([r.t(i, frame) for i in firsts], r.scale)]


def explanation(history: History, frames: Sequence[Frame]) -> tuple[Paragraph, ...]:
    """One to three paragraphs generated from the history: simultaneity and order; the rod's velocity; zig-zags,
    stops at full length and stopped turns, when and why."""
    r = _Reading(history, tuple(frames))
    paragraphs = [_simultaneity(r), _velocities(r), _why(r)]
    return tuple(Paragraph(p) for p in paragraphs if p)


# --- the rod at successive instants ---------------------------------------------------------------------------

def _end_changes(r: _Reading, frame: Frame) -> dict[str, list[tuple[float, float, Turn, bool]]]:
    """For each end, when its velocity changes in the frame: (start, end, turn, struck) per turn it takes part in;
    struck: it is the turn's pivot and jumps at the impact, else it follows the turn's hyperbola."""
    eta = frame.rapidity
    out: dict[str, list] = {"left": [], "right": []}
    for turn in r.history.turns:
        pivot, far_start, far_end = turn_corners(turn)
        out[turn.pivot_end].append((pivot.time_in(eta), pivot.time_in(eta), turn, True))
        if abs(turn.rapidity_stop - turn.rapidity_from) > SAME_RAPIDITY:
            far = "left" if turn.pivot_end == "right" else "right"
            out[far].append((far_start.time_in(eta), far_end.time_in(eta), turn, False))
    return out


def strip_times(history: History, frame: Frame) -> tuple[float, ...]:
    """Six to eight instants of the frame's time that teach, earliest first, all within `frames.time_window`:
    before the first change, every instant at which an impact strikes, the start of any turn before its impact
    (the far end moving first), the middle of each turn, and after the last change."""
    r = _Reading(history, (frame,))
    eta = frame.rapidity
    t_lo, t_hi = time_window(history, frame)
    impacts = [t for t, _ in r.instants(frame)]
    turns = [turn_interval(turn, eta) for turn in history.turns]
    changes = sorted(impacts + [t for interval in turns for t in interval])
    first, last = changes[0], changes[-1]
    # (priority, time): the lower the priority, the surer an instant is kept
    candidates = [(0, 0.5 * (t_lo + first)), (0, 0.5 * (last + t_hi))]
    candidates += [(1, t) for t in impacts]
    candidates += [(1, start) for start, _ in turns if not any(r.same_time(start, t) for t in impacts)]
    candidates += [(2, 0.5 * (a + b)) for a, b in turns if b - a > 0]
    candidates += [(3, end) for _, end in turns]
    close = STRIP_SEPARATION * (t_hi - t_lo)
    chosen: list[tuple[int, float]] = []
    for priority, t in sorted(candidates):
        if all(abs(t - c) > close for _, c in chosen):
            chosen.append((priority, t))
    times = sorted(t for _, t in chosen[:STRIPS_MOST])
    while len(times) < STRIPS_FEWEST:  # halve the widest gap, the ends of the window included as bounds
        bounds = [t_lo] + times + [t_hi]
        a, b = max(zip(bounds, bounds[1:]), key=lambda ab: ab[1] - ab[0])
        times = sorted(times + [0.5 * (a + b)])
    return tuple(min(max(t, t_lo), t_hi) for t in times)


def _kink(worldline, t: float) -> tuple[float, float]:
    """The rapidities just before and just after the world-line's kink nearest the time t (the kink's own time may
    differ from t by rounding, so the pieces either side are found by their ends, not by t)."""
    segments = worldline.segments
    if not segments:
        return worldline.rapidity_before, worldline.rapidity_after
    boundaries = [segments[0].start.t] + [seg.end.t for seg in segments]
    k = min(range(len(boundaries)), key=lambda j: abs(boundaries[j] - t))
    before = worldline.rapidity_before if k == 0 else segments[k - 1].rapidity_at_end
    after = segments[k].rapidity_at_start if k < len(segments) else worldline.rapidity_after
    return before, after


def _gradually(before: float, after: float) -> str:
    """How an end following a turn's hyperbola changes velocity, in words."""
    side = "right" if after > 0 else "left"
    if before == 0.0:
        return f"starts moving {side}, gradually reaching {_velocity(after)}"
    if after == 0.0:
        return f"slows gradually from {_velocity(before)} to rest"
    if (before > 0) != (after > 0):
        return f"turns back gradually from {_velocity(before)} to {_velocity(after)}"
    return f"{'speeds up' if abs(after) > abs(before) else 'slows'} gradually from {_velocity(before)} to {_velocity(after)}"


def _which_end_first(r: _Reading, frame: Frame) -> str:
    """Which end of the rod changes velocity first in the frame, when, and how the other follows."""
    h = r.history
    symbol, time = _frame_name(frame), _time_of(frame)
    eta = frame.rapidity
    if not h.turns:
        u = r.rod_velocities(frame)[0]
        changes = _listed([f"{i.particle}'s at {impact_name(i.label)} ({r.when([i], frame)})"
                           for _, g in r.instants(frame) for i in g])
        motion = "stays at rest" if u == 0.0 else f"moves on at {_velocity(u)}"
        return (f"Neither end of the rod ever changes velocity in {symbol}: the rod {motion}, while the particles' "
                f"velocities change, {changes}.")

    def change(end: str, turn: Turn, struck: bool, start: float, stop: float) -> str:
        """What one end does in one turn: jumps at its impact, or follows the hyperbola."""
        if struck:
            before, after = (r.velocity(x + eta, frame) for x in _kink(h.worldline(f"rod_{end}").seen_from(eta), start))
            return f"is struck by {_names(r.impacts_at(turn.pivot))} and {_direction(before, after)} at once"
        return _gradually(r.velocity(turn.rapidity_from, frame), r.velocity(turn.rapidity_stop, frame)) + \
            f" by {time} = {_in_l(r.length(stop))}"

    def earliest(items: list) -> tuple:
        """The earliest change; among changes at one instant (to rounding), an impact's jump."""
        t0 = min(c[0] for c in items)
        return min((c for c in items if r.same_time(c[0], t0)), key=lambda c: not c[3])

    changes = _end_changes(r, frame)
    firsts = {end: earliest(changes[end]) for end in ("left", "right") if changes[end]}
    order = sorted(firsts, key=lambda end: firsts[end][0])
    if len(order) > 1 and r.same_time(firsts[order[0]][0], firsts[order[1]][0]) and firsts[order[1]][3]:
        order.reverse()  # at one instant, the struck end first
    first = order[0]
    start, stop, turn, struck = firsts[first]
    if len(order) > 1 and r.same_time(firsts[order[1]][0], start):
        other = order[1]
        o_start, o_stop, o_turn, o_struck = firsts[other]
        return (f"Both ends start to change velocity at {time} = {_in_l(r.length(start))}: the {first} end "
                f"{change(first, turn, struck, start, stop)}; the {other} end {change(other, o_turn, o_struck, o_start, o_stop)}"
                f". The shading shows the velocity spreading along the rod.")
    text = f"The {first} end moves first, at {time} = {_in_l(r.length(start))}: "
    if struck:
        text += "it " + change(first, turn, struck, start, stop)
    else:
        cause = _turn_cause(r, turn)
        strike = "strike" if len(cause) > 1 else "strikes"
        text += (f"before {_names(cause)} {strike} the {turn.pivot_end} end (at {_in_l(r.length(turn.pivot.time_in(eta)))}"
                 f"), it {change(first, turn, struck, start, stop)}, because the rod responds along its own line of "
                 f"simultaneity through {_names(cause)}, which reaches the {first} end earlier in {symbol}")
    if len(order) > 1:
        other = order[1]
        o_start, o_stop, o_turn, o_struck = firsts[other]
        text += (f". The {other} end follows from {time} = {_in_l(r.length(o_start))}: it "
                 f"{change(other, o_turn, o_struck, o_start, o_stop)}")
    return text + "."


def strips_caption(history: History, frame: Frame, times: Sequence[float]) -> str:
    """What the stills show, at which instants, and what to look at."""
    r = _Reading(history, (frame,))
    symbol = _frame_name(frame)
    instants = _listed([_number(r.length(t)) for t in times])
    return (f"The rod and the particles in {symbol} at {_time_of(frame)} = {instants} (in units of L), earliest "
            f"first. The bar runs from the rod's left end to its right end, shaded by the velocity in {symbol} of "
            f"each of its material points (the scale is centred on {_velocity(frame.rod_velocity())}, the rod's "
            f"velocity in {symbol} before it is struck); the dots are the particles. "
            + _which_end_first(r, frame))


# --- tables --------------------------------------------------------------------------------------------------

def _tables(history: History, frame: Frame, blank: bool) -> list[Block]:
    symbol, time = _frame_name(frame), _time_of(frame)
    x = coordinates(frame)[0]
    blocks: list[Block] = [
        Paragraph(f"The impacts in {symbol}, in the order of its time: where and when each strikes ({x} and {time} "
                  f"{_table_unit(history.scenario.L)}), and the velocities (in units of c) of the particle and of the "
                  f"rod just before and just after it."),
        tables.events_table(history, frame, blank),
        Paragraph(f"The ledger in {symbol}: at each impact, the energy E and momentum p of the particle, of the rod "
                  f"(its momentum's, which takes the whole impulse) and the hidden part (what the rod's stress "
                  f"carries: the total before the first impact less every body's kinetic E and p on the slice "
                  f"{time} = constant), just before and just after."),
        tables.ledger_table(history, frame, blank),
    ]
    hidden = tables.hidden_table(history, frame, blank)
    if hidden is None:
        blocks.append(Paragraph(f"In {symbol} the hidden part is zero on every slice between impacts: at every "
                                f"instant of {symbol} the bodies' own motion carries all the energy and momentum."))
    else:
        blocks += [Paragraph(f"The hidden part in {symbol} on a slice halfway between each two consecutive changes "
                             f"(impacts, the start or end of a turn), where it is not zero: energy and momentum that "
                             f"no body's motion shows, held by the stress in the rod."), hidden]
    return blocks


# --- questions ------------------------------------------------------------------------------------------------

def _n7(x: float) -> str:
    """A number in a worked answer: a fraction where one matches, else ANSWER_DIGITS significant digits."""
    return _number(x, ANSWER_DIGITS)


def _bracketed(x: float) -> str:
    """A number squared, divided or multiplied: (−0.75), (5/6), 0.5."""
    text = _n7(x)
    return f"({text})" if text.startswith(MINUS) or "/" in text else text


def _term(x: float) -> str:
    """A number in a sum: (−0.75), 5/6."""
    text = _n7(x)
    return f"({text})" if text.startswith(MINUS) else text


def _velocity_approx(u: float) -> str:
    """+15/17 c ≈ +0.8823529 c, or +0.5076923 c."""
    exact_text = fraction_text(u + 0.0)
    if exact_text:
        return f"{_signed(u)} c ≈ {_signed(u, ANSWER_DIGITS).replace(exact_text, shown(abs(u), ANSWER_DIGITS))} c"
    return _velocity(u, ANSWER_DIGITS)


def _momentum(mass: float, u: float) -> float:
    """m u/√(1 − u²), c = 1."""
    return mass * u * _gamma(u)


def _frame_pair(r: _Reading) -> tuple[Frame, Frame]:
    """The two frames the questions compare: the first two shown, or S and the one shown."""
    if len(r.frames) > 1:
        return r.frames[0], r.frames[1]
    only = r.frames[0]
    return (rest_frame(), only) if only.name != "rest" else (only, moving_frame(r.v))


def _relative(a: Frame, b: Frame) -> float:
    """The velocity of frame b relative to frame a (`frames.relative_velocity`)."""
    return relative_velocity(b.velocity, a.velocity)


def _gamma(w: float) -> float:
    return 1.0 / math.sqrt((1.0 - w) * (1.0 + w))


def _lorentz_pair(r: _Reading, a: Frame, b: Frame) -> tuple[Impact, ...]:
    """The impacts a Lorentz question transforms: two simultaneous in one frame and not in the other, else two whose
    order differs between the frames, else the first two, else the only one."""
    h = r.history
    pairs = [(p, q) for k, p in enumerate(h.impacts) for q in h.impacts[k + 1:]]
    for p, q in pairs:
        if r.same_time(r.t(p, a), r.t(q, a)) != r.same_time(r.t(p, b), r.t(q, b)):
            return p, q
    for p, q in pairs:
        if (r.t(p, a) - r.t(q, a)) * (r.t(p, b) - r.t(q, b)) < 0:
            return p, q
    return tuple(h.impacts[:2])


_Asked = tuple[str, tuple[str, ...]]


def _question_lorentz(r: _Reading, a: Frame, b: Frame, pair: tuple[Impact, ...]) -> _Asked:
    """Transform one or two impacts from frame a to frame b: t_b = γ(t_a − w x_a), w the velocity of b relative to a
    (`kinematics.Event.seen_from`: x′ = γ(x − u t), t′ = γ(t − u x) for a frame of velocity u)."""
    w = _relative(a, b)
    g = _gamma(w)
    xa, ta = coordinates(a)
    xb, tb = coordinates(b)
    A, B = _frame_name(a), _frame_name(b)
    sign, W = ("+" if w < 0 else MINUS), _n7(abs(w))
    given = "; ".join(f"{impact_name(i.label)} strikes at {xa} = {_in_l(r.length(r.x(i, a)), ANSWER_DIGITS)}, "
                      f"{ta} = {_in_l(r.length(r.t(i, a)), ANSWER_DIGITS)}" for i in pair)
    steps = [f"{_cap(B)} moves at w = {_velocity(w, ANSWER_DIGITS)} relative to {A}, so {tb} = γ({ta} − w {xa}) = "
             f"γ({ta} {sign} {W} {xa}) and {xb} = γ({xa} {sign} {W} {ta}), with γ = 1/√(1 − w²) = 1/√(1 − {W}²) = "
             f"{_approx(g)}."]
    times = []
    for i in pair:
        x, t = r.length(r.x(i, a)), r.length(r.t(i, a))
        inner = t - w * x
        times.append(g * inner)
        steps.append(f"{impact_name(i.label)}: {tb} = {_n7(g)} × ({_n7(t)} {sign} {W} × {_bracketed(x)}) L = "
                     f"{_n7(g)} × {_bracketed(inner) if inner < 0 else _n7(inner)} L = {_in_l_approx(g * inner)}.")
    if len(pair) == 1:
        i = pair[0]
        x, t = r.length(r.x(i, a)), r.length(r.t(i, a))
        steps.append(f"And {xb} = {_n7(g)} × ({_n7(x)} {sign} {W} × {_bracketed(t)}) L = "
                     f"{_in_l_approx(g * (x - w * t))}.")
        return (f"In {A}, {given}. {_cap(B)} moves at {_velocity(w, ANSWER_DIGITS)} relative to {A}. Use the Lorentz "
                f"transformation to find where and when it strikes in {B}.", tuple(steps))
    p, q = pair
    apart_a = abs(r.length(r.t(q, a) - r.t(p, a)))
    same_a = r.same_time(r.t(p, a), r.t(q, a))
    same_b = r.same_time(r.t(p, b), r.t(q, b))
    in_a = f"in {A} they are simultaneous" if same_a else f"in {A} they are {_in_l(apart_a, ANSWER_DIGITS)} apart"
    if same_b:
        steps.append(f"The two times are equal: {impact_name(p.label)} and {impact_name(q.label)} are simultaneous in "
                     f"{B}, while {in_a}.")
    else:
        earlier, later = (p, q) if times[0] < times[1] else (q, p)
        steps.append(f"The times differ: in {B} {impact_name(later.label)} comes {_in_l_approx(abs(times[1] - times[0]))}"
                     f" after {impact_name(earlier.label)}, while {in_a}.")
    text = (f"In {A}, {given}. {_cap(B)} moves at {_velocity(w, ANSWER_DIGITS)} relative to {A}. Use the Lorentz "
            f"transformation to find {tb} of each. Are they simultaneous in {B}?")
    if not same_a and not same_b and (r.t(p, a) - r.t(q, a)) * (r.t(p, b) - r.t(q, b)) < 0:
        text += f" Which comes first in {B}?"
    return text, tuple(steps)


def _question_read(r: _Reading, a: Frame, b: Frame, avoid: Sequence[Impact]) -> _Asked:
    """Read an impact's coordinates off two panels, checked by the interval t² − x², the same in every frame."""
    h = r.history
    i = next((i for i in reversed(h.impacts) if i not in avoid), h.impacts[-1])
    panels = [f for f in (a, b) if f in r.frames] or list(r.frames[:1])
    lines, checks = [], []
    for f in panels:
        x, t = r.length(r.x(i, f)), r.length(r.t(i, f))
        xs, ts = coordinates(f)
        letter = PANEL_LETTERS[r.frames.index(f)]
        lines.append(f"In {_frame_name(f)} (panel ({letter})): {xs} = {_in_l_approx(x)}, {ts} = {_in_l_approx(t)}.")
        checks.append(f"in {_frame_name(f)} {_bracketed(t)}² − {_bracketed(x)}² = {_approx(t * t - x * x)}")
    letters = [f"({PANEL_LETTERS[r.frames.index(f)]})" for f in panels]
    where = f"panel {letters[0]}" if len(letters) == 1 else f"panels {_listed(letters)}"
    text = (f"Read off the diagram, in {where}, where and when {impact_name(i.label)} happens ({i.particle} striking "
            f"the {i.end} end).")
    if len(panels) == 1:
        return text, tuple(lines) + ("A careful reading gets these to about a twentieth of L.",)
    answer = tuple(lines) + (f"A careful reading gets these to about a twentieth of L. The check, in units of L²: "
                             f"{'; '.join(checks)}: the same, as a Lorentz transformation keeps t² − x².",)
    return text + " Check your readings: t² − x² must be the same in every frame.", answer


def _question_velocity(r: _Reading, a: Frame, b: Frame) -> _Asked:
    """The rod's velocity after a collision (or a particle's, if the rod never changes) in b, by velocity addition."""
    w = _relative(a, b)
    A, B = _frame_name(a), _frame_name(b)
    candidates = [(f"After {_names(c)} the rod moves at {_velocity(r.velocity(c[-1].rod_rapidity_after, a), ANSWER_DIGITS)}"
                   f" in {A}.", f"the rod's velocity after {_names(c)}", r.velocity(c[-1].rod_rapidity_after, a))
                  for c in r.collisions]
    candidates = [c for c in candidates if c[2] != 0.0]
    if not candidates:  # the rod never changes velocity: ask about a particle
        candidates = [(f"{when.capitalize()} {impact_name(i.label)}, {i.particle} moves at "
                       f"{_velocity(r.velocity(rapidity, a), ANSWER_DIGITS)} in {A}.",
                       f"{i.particle}'s velocity {when} {impact_name(i.label)}", r.velocity(rapidity, a))
                      for i in r.history.impacts
                      for when, rapidity in (("before", i.particle_rapidity_before), ("after", i.particle_rapidity_after))]
        candidates = [c for c in candidates if c[2] != 0.0]
    given, what, u = max(candidates, key=lambda c: abs(relative_velocity(c[2], w)))
    result = relative_velocity(u, w)
    answer = [f"{_cap(B)} moves at w = {_velocity(w, ANSWER_DIGITS)} relative to {A}, so a velocity u in {A} is "
              f"(u − w)/(1 − u w) in {B}.",
              f"({_signed(u, ANSWER_DIGITS)} − ({_signed(w, ANSWER_DIGITS)}))/(1 − ({_signed(u, ANSWER_DIGITS)}) × "
              f"({_signed(w, ANSWER_DIGITS)})) = {_bracketed(u - w)}/{_bracketed(1 - u * w)} = "
              f"{_velocity_approx(result)}{' (at rest)' if result == 0.0 else ''}."]
    if abs(u - w) >= 1.0:
        answer.append(f"Adding velocities as Galileo did would give {_velocity(u - w, ANSWER_DIGITS)}, faster than "
                      f"light.")
    return f"{given} Use the relativistic addition of velocities to find {what} in {B}.", tuple(answer)


def _whole_rod(r: _Reading, frame: Frame, t: float) -> bool:
    """Whether every material point of the rod has one velocity on the slice t of the frame (no turn crosses it)."""
    sigmas = [k * r.L / (WHOLE_ROD_POINTS - 1) for k in range(WHOLE_ROD_POINTS)]
    rapidities = rod_slice(r.history, frame.rapidity, t, sigmas).rapidity
    return float(max(rapidities) - min(rapidities)) <= SAME_RAPIDITY


def _between(r: _Reading, frame: Frame, t: float) -> str:
    """after A₁ and before B₁; before B₁; after B₂, the last impact."""
    impacts = [i for _, g in r.instants(frame) for i in g]
    before = [i for i in impacts if r.t(i, frame) < t]
    after = [i for i in impacts if r.t(i, frame) > t]
    if before and after:
        return f"after {impact_name(before[-1].label)} and before {impact_name(after[0].label)}"
    if after:
        return f"before {impact_name(after[0].label)}, the first impact in {_frame_name(frame)}"
    return f"after {impact_name(before[-1].label)}, the last impact in {_frame_name(frame)}"


def _question_hidden(r: _Reading, a: Frame, b: Frame) -> _Asked | None:
    """The hidden momentum on a slice between two changes: total before the first impact less every body's kinetic
    momentum on the slice. A slice where the rod moves as a whole is preferred (the student can compute the rod's
    momentum), then the largest hidden momentum; frame b first."""
    h = r.history
    chosen = None
    for f in [b, a] + [f for f in r.frames if f not in (a, b)]:
        total = initial_total(h, f.rapidity)
        zero = PRINTED_ZERO * max(total.E, abs(total.p))  # a difference of totals below this is rounding
        for t in tables.hidden_instants(h, f):
            hidden = ledger_slice(h, f.rapidity, t).hidden
            if abs(hidden.p) > zero:
                key = (not _whole_rod(r, f, t), -abs(hidden.p))
                if chosen is None or key < chosen[0]:
                    chosen = (key, f, t)
        if chosen is not None:
            break
    if chosen is None:
        return None
    _, f, t = chosen
    s = ledger_slice(h, f.rapidity, t)
    total = initial_total(h, f.rapidity)
    zero = PRINTED_ZERO * max(total.E, abs(total.p))
    symbol, time = _frame_name(f), _time_of(f)
    whole = _whole_rod(r, f, t)
    bodies = dict(s.bodies)
    steps = ["A body of mass m moving at u has momentum m u/√(1 − u²) (c = 1)."]
    known, terms = [], []
    for name in ("A", "B"):
        if name not in bodies:
            continue
        m = h.scenario.particle(name).mass
        u = r.velocity(h.worldline(name).seen_from(f.rapidity).rapidity_at_time(t) + f.rapidity, f)
        known.append(f"{name} moves at {_velocity(u, ANSWER_DIGITS)}")
        p = 0.0 if abs(bodies[name].p) <= zero else bodies[name].p
        steps.append(f"{name}: {_n7(m)} × {_bracketed(u)}/√(1 − {_bracketed(u)}²) = {_n7(p)} M c.")
        terms.append(p)
    rod_p = 0.0 if abs(bodies["rod"].p) <= zero else bodies["rod"].p
    if whole:
        u = math.tanh(rod_slice(h, f.rapidity, t, [0.5 * r.L]).rapidity[0])
        known.append(f"the rod moves as a whole at {_velocity(u, ANSWER_DIGITS)}")
        steps.append(f"The rod: 1 × {_bracketed(u)}/√(1 − {_bracketed(u)}²) = {_n7(rod_p)} M c.")
    else:
        known.append(f"the rod is turning: the momentum of its material points, added up along it as the ledger "
                     f"does, is {_n7(rod_p)} M c")
        steps.append(f"The rod: {_n7(rod_p)} M c, as given.")
    terms.append(rod_p)
    kinetic = sum(terms)
    hidden = total.p - kinetic
    steps.append(f"All the bodies' momentum on the slice: {' + '.join(_term(q) for q in terms)} = {_n7(kinetic)} "
                 f"M c. Hidden: {_n7(total.p)} − {_term(kinetic)} = {_approx(hidden)} M c.")
    where = ("this slice of " + symbol + " cuts across a turn, the rod's rigid response to an impact, so part of the "
             "impulse already given sits in the stress and has not yet reached the motion of the rod's material "
             "points" if not whole else
             "this slice of " + symbol + " falls between two impacts the rod takes together on its own line of "
             "simultaneity: the impulse of the first sits in the stress until the second arrives")
    steps.append(f"It is carried by the stress in the rod: {where}. (The hidden energy on the slice is "
                 f"{_approx(s.hidden.E)} M c².)")
    text = (f"On the slice {time} = {_in_l(r.length(t), ANSWER_DIGITS)} of {symbol} ({_between(r, f, t)}), "
            f"{_listed(known)}. Before the first impact the bodies' total momentum in {symbol} was "
            f"{_n7(total.p)} M c. How much momentum is hidden on this slice, and where is it?")
    return text, tuple(steps)


def _question_other_speed(r: _Reading, a: Frame, b: Frame) -> _Asked | None:
    """The same scenario at another v, run again: the interval between the rod's first two impacts in both frames
    (or, for one impact, how long the far end takes to follow), and whether the rod ends at rest in S."""
    h = r.history
    s = h.scenario
    other = None
    for v2 in OTHER_SPEEDS:
        if v2 != s.v:
            try:
                other = run(s.with_overrides(v=v2))
            except RodParadoxError:
                continue
            break
    if other is None:
        return None
    labels = [i.label for i in h.impacts[:2]]
    names = [impact_name(label) for label in labels]

    def facts(history: History) -> str:
        reading = _Reading(history, tuple(moving_frame(history.scenario.v) if f.name == "moving" else f
                                          for f in (a, b)))
        found = {i.label: i for i in history.impacts}
        out = []
        if len(labels) == 2 and all(label in found for label in labels):
            p, q = found[labels[0]], found[labels[1]]
            for f in reading.frames:
                gap = reading.length(reading.t(q, f) - reading.t(p, f))
                out.append(f"{names[0]} and {names[1]} are simultaneous in {_frame_name(f)}" if gap == 0.0 else
                           f"{names[1]} comes {_in_l(abs(gap), ANSWER_DIGITS)} {'after' if gap > 0 else 'before'} "
                           f"{names[0]} in {_frame_name(f)}")
        elif len(labels) == 2:
            out.append(f"the rod is struck {len(history.impacts)} times: {_names(history.impacts)}")
        elif history.turns:
            start, end = turn_interval(history.turns[0], 0.0)
            out.append(f"the far end takes {_in_l(reading.length(end - start), ANSWER_DIGITS)} of S's time to reach "
                       f"the rod's new velocity")
        final = reading.velocity(history.final_rapidity, rest_frame())
        out.append("the rod ends at rest in S" if final == 0.0 else
                   f"the rod ends moving at {_velocity(final, ANSWER_DIGITS)} in S")
        return "; ".join(out)

    v, v2 = exact(s.v), exact(other.scenario.v)
    following = [p.name for p in s.particles if p.speed is None]
    changes = ("S′ and the speed of " + _listed(following) + ", which the scenario takes from v, change with it"
               if following else "S′ changes with it; the particles keep the speeds the scenario gives them")
    if len(labels) == 2:
        asked = (f"How long after {names[0]} does {names[1]} come, in {_frame_name(a)} and in {_frame_name(b)}? "
                 f"Does the rod end at rest in S?")
    else:
        asked = "How long does the far end of the rod take, in S, to reach the rod's new velocity? How does the rod end?"
    text = f"Now take v = {v2} instead of {v} ({changes}). {asked} Compare with v = {v}."
    return text, (f"At v = {v}: {facts(h)}.", f"At v = {v2} (the tool runs the scenario again): {facts(other)}.")


def _question_stopped_turn(r: _Reading) -> _Asked | None:
    """A turn stopped by an impact: the far end's velocity there, from the two events, against the rod's."""
    h = r.history
    turn = next((t for t in h.turns if not t.completed), None)
    if turn is None:
        return None
    stopper = next(i for i in h.impacts if i.label == turn.stopped_by)
    cause = _turn_cause(r, turn)
    far = "left" if turn.pivot_end == "right" else "right"
    P, E = turn.pivot, stopper.event
    at_pivot = [i for i in cause if i in r.impacts_at(P)] or r.impacts_at(P)
    dx, dt = r.length(E.x - P.x), r.length(E.t - P.t)
    u_far = dt / dx  # on the hyperbola (x − x_P)² − (t − t_P)² = L² the velocity is (t − t_P)/(x − x_P)
    u_rod = r.velocity(turn.rapidity_to, rest_frame())
    S, name, stop = "S", _names(cause), impact_name(stopper.label)
    text = (f"{stop} strikes the {far} end while the rod is still turning from {name}. How fast is the {far} end "
            f"moving in S at that instant, and how does that compare with the rod's velocity after {name}? (During a "
            f"turn about the event P the far end moves on the hyperbola (x − x_P)² − (t − t_P)² = L², whose velocity "
            f"at (x, t) is (t − t_P)/(x − x_P).)")
    answer = (f"P is {_names(at_pivot)}, at x = {_in_l(r.length(P.x), ANSWER_DIGITS)}, t = {_in_l(r.length(P.t), ANSWER_DIGITS)}; "
              f"{stop} is at x = {_in_l(r.length(E.x), ANSWER_DIGITS)}, t = {_in_l(r.length(E.t), ANSWER_DIGITS)}.",
              f"{stop} is on the hyperbola: {_bracketed(dx)}² − {_bracketed(dt)}² = {_n7(dx * dx - dt * dt)} (in L²).",
              f"The {far} end's velocity there: {_n7(dt)}/{_bracketed(dx)} = {_velocity(u_far, ANSWER_DIGITS)} in {S}, "
              f"while the rod's momentum moves at {_velocity(u_rod, ANSWER_DIGITS)} after {name}: the {far} end had "
              f"not caught up when {stop} struck, so the rod never moved as a whole at "
              f"{_velocity(u_rod, ANSWER_DIGITS)}.")
    return text, answer


def _rests(r: _Reading, frame: Frame) -> list[tuple[Turn, float, float | None, Turn | None]]:
    """Each stretch of the frame's time in which the whole rod stands still in it after a turn that completes:
    (the turn, when it ends, when the next turn starts or None, that next turn or None). The turn's last line is a
    line of simultaneity of the frame, so every point reaches rest at one instant of it, at the rod's full length."""
    out = []
    turns = r.history.turns
    for k, turn in enumerate(turns):
        if not turn.completed or abs(turn.rapidity_stop - frame.rapidity) > SAME_RAPIDITY:
            continue
        end = turn_interval(turn, frame.rapidity)[1]
        later = sorted(((turn_interval(t, frame.rapidity)[0], t) for t in turns[k + 1:]), key=lambda st: st[0])
        if later and later[0][0] < end - ONE_INSTANT * r.scale:
            continue  # another turn already moves part of the rod
        out.append((turn, end, later[0][0] if later else None, later[0][1] if later else None))
    return out


def _question_at_rest(r: _Reading) -> _Asked | None:
    """A moving frame in which the whole rod stands still for an instant or a while: when, and how long it is."""
    for f in (f for f in r.frames if f.name != "rest"):
        rests = _rests(r, f)
        if not rests:
            continue
        turn, end, next_start, _ = rests[0]
        symbol, time = _frame_name(f), _time_of(f)
        u0 = r.rod_velocities(f)[0]
        if next_start is None:
            when = f"from {time} = {_in_l_approx(r.length(end))} on"
        elif r.same_time(next_start, end):
            when = f"at the one instant {time} = {_in_l_approx(r.length(end))}"
        else:
            when = f"from {time} = {_in_l_approx(r.length(end))} to {_in_l_approx(r.length(next_start))}"
        text = (f"The whole rod comes to rest in {symbol}. When, and how long is it then, measured in {symbol}? How "
                f"long is it in {symbol} before it is first struck?")
        answer = (f"It is at rest {when}: the turn that {_names(_turn_cause(r, turn))} started ends on a line of "
                  f"constant {time}, so every point of the rod reaches velocity 0 in {symbol} at once.",
                  f"At rest in {symbol}, it has its full proper length L there. Before it is struck it moves at "
                  f"{_velocity(u0, ANSWER_DIGITS)} in {symbol}, contracted to L √(1 − u²) = L √(1 − {_bracketed(u0)}²) "
                  f"= {_in_l_approx(1.0 / _gamma(u0))}.")
        return text, answer
    return None


def _question_single(r: _Reading) -> _Asked | None:
    """One particle: how long the far end takes to follow, and how far the struck end moves meanwhile, in S."""
    h = r.history
    if len(h.scenario.particles) != 1 or not h.turns or not h.turns[0].completed:
        return None
    turn = h.turns[0]
    struck = impact_name(_turn_cause(r, turn)[-1].label)
    far = "left" if turn.pivot_end == "right" else "right"
    u = r.velocity(turn.rapidity_to, rest_frame())
    g = _gamma(u)
    delay = abs(u) * g  # the far end's hyperbola about the impact reaches velocity u at t − t_P = L sinh φ = γ|u| L
    text = (f"{struck} gives the rod's momentum the velocity {_velocity(u, ANSWER_DIGITS)} in S at once, but the "
            f"{far} end follows only gradually, on the hyperbola of radius L about {struck}. How long after {struck}, "
            f"in S, does the {far} end reach {_velocity(u, ANSWER_DIGITS)}? How far has the struck end moved by then?")
    answer = (f"On that hyperbola t − t_P = L sinh φ and the velocity is tanh φ; it reaches |u| = "
              f"{_n7(abs(u))} where sinh φ = γ|u| = {_n7(g)} × {_n7(abs(u))} = {_n7(delay)}.",
              f"So the {far} end takes {_in_l_approx(delay)} of S's time. Meanwhile the struck end, moving at "
              f"{_velocity(u, ANSWER_DIGITS)} from the impact on, moves {_in_l_approx(abs(u) * delay)} to the "
              f"{'right' if u > 0 else 'left'}; the rod then has "
              f"its moving length L/γ = {_in_l_approx(1.0 / g)} in S.")
    return text, answer


def _s_table(r: _Reading) -> str:
    """Where the student finds velocities in S: the events table of S, if S is shown."""
    return " (the events table of S)" if any(f.name == "rest" for f in r.frames) else ""


def _question_momentum(r: _Reading, collision: tuple[Impact, ...] | None = None) -> _Asked:
    """Momentum in S before and after a collision (the first, or the one given), from the velocities."""
    h = r.history
    s = h.scenario
    rest = rest_frame()
    c = collision or r.collisions[0]
    rows, before, after = [], 0.0, 0.0
    for i in c:
        m = s.particle(i.particle).mass
        ub, ua = r.velocity(i.particle_rapidity_before, rest), r.velocity(i.particle_rapidity_after, rest)
        pb, pa = _momentum(m, ub), _momentum(m, ua)
        before, after = before + pb, after + pa
        rows.append(f"{i.particle} ({_n7(m)} M): {_velocity(ub, ANSWER_DIGITS)} → {_velocity(ua, ANSWER_DIGITS)}, "
                    f"p = {_n7(pb)} → {_n7(pa)} M c")
    ub, ua = r.velocity(c[0].rod_rapidity_before, rest), r.velocity(c[-1].rod_rapidity_after, rest)
    pb, pa = _momentum(1.0, ub), _momentum(1.0, ua)
    rows.append(f"the rod (M): {_velocity(ub, ANSWER_DIGITS)} → {_velocity(ua, ANSWER_DIGITS)}, p = {_n7(pb)} → "
                f"{_n7(pa)} M c")
    why = ua != ub and len(c) > 1
    text = (f"Using the velocities in S just before and just after {_names(c)}{_s_table(r)}, check that "
            f"momentum is conserved in S." + (" Why does the rod move off?" if why else ""))
    answer = ["p = m u/√(1 − u²). " + "; ".join(rows) + ".",
              f"Before: {_n7(before + pb)} M c; after: {_n7(after + pa)} M c: the same."]
    if why:
        answer.append("The particles' momenta do not cancel before the impacts (the heavier one carries more), so the "
                      "rod carries the difference after them.")
    return text, tuple(answer)


def _question_together(r: _Reading, b: Frame) -> _Asked | None:
    """Impacts the rod takes together, without changing velocity, at different times of frame b: why it moves on."""
    h = r.history
    c = next((c for c in r.collisions if len(c) > 1 and
              abs(c[-1].rod_rapidity_after - c[0].rod_rapidity_before) <= SAME_RAPIDITY), None)
    if c is None:
        return None
    ordered = sorted(c, key=lambda i: r.t(i, b))
    first, last = ordered[0], ordered[-1]
    if r.same_time(r.t(first, b), r.t(last, b)):
        return None
    symbol = _frame_name(b)
    u_rod = r.velocity(c[0].rod_rapidity_before, b)
    momenta = [_momentum(h.scenario.particle(i.particle).mass, r.velocity(i.particle_rapidity_before, rest_frame()))
               for i in c]
    cancel = (f" (in S, where that line is one of constant t, the particles arrive with momenta "
              f"{_listed([_n7(p) + ' M c' for p in momenta])}, which cancel)" if abs(sum(momenta)) <= PRINTED_ZERO * sum(
                  abs(p) for p in momenta) else "")
    text = (f"In {symbol}, {impact_name(first.label)} comes before {impact_name(last.label)}. What is the rod's "
            f"velocity in {symbol} between them, and why does {first.particle}'s impulse not change it?")
    answer = (f"{_velocity(u_rod, ANSWER_DIGITS)}, as before and after: the rod takes {_names(c)} together, on one line "
              f"of its own simultaneity, and there the impulses cancel{cancel}.",
              f"Between the two impacts in {symbol} the momentum {first.particle} has given up is held by the stress "
              f"in the rod: the hidden part of the ledger, which the question on hidden momentum computes.")
    return text, answer


def _question_zigzag(r: _Reading) -> _Asked | None:
    """Where the rod zig-zags: its motion in S from the events table, and why a particle strikes twice."""
    h = r.history
    if not _zigzags([0.0] + [c[-1].rod_rapidity_after for c in r.collisions]):
        return None
    rest = rest_frame()
    u = r.rod_velocities(rest)
    steps = [f"after {_names(c)} (t = {_in_l(r.length(r.t(c[0], rest)), ANSWER_DIGITS)}) "
             f"{_velocity(u[k + 1], ANSWER_DIGITS)}: it {_pushed(u[k], u[k + 1])}" for k, c in enumerate(r.collisions)]
    text = (f"From the rod's velocities in S{_s_table(r)}: in which direction is the rod driven after each impact? "
            f"Why is it struck more than once by the same particle?")
    answer = [f"Its velocity in S is 0 before {_names(r.collisions[0])}; " + "; ".join(steps) + "."]
    repeat = next((i for i in h.impacts if any(p.particle == i.particle for p in h.impacts[:h.impacts.index(i)])), None)
    if repeat is not None:
        previous = next(p for p in reversed(h.impacts[:h.impacts.index(repeat)]) if p.particle == repeat.particle)
        answer.append(f"After {impact_name(previous.label)}, {repeat.particle} moves at "
                      f"{_velocity(r.velocity(repeat.particle_rapidity_before, rest), ANSWER_DIGITS)} while the rod, "
                      f"driven the other way since, moves at "
                      f"{_velocity(r.velocity(repeat.rod_rapidity_before, rest), ANSWER_DIGITS)}: its {repeat.end} end "
                      f"closes on {repeat.particle} again, at {impact_name(repeat.label)}. The impulses do not cancel "
                      f"because the rod takes them one at a time.")
    return text, tuple(answer)


def questions(history: History, frames: Sequence[Frame]) -> tuple[Question, ...]:
    """Five to eight questions on the scenario, numbered from 1, each with a worked answer computed by the tool:
    read an event off the panels; a Lorentz transformation; velocity addition; the hidden momentum on a slice;
    the questions that fit the scenario (a stopped turn, a rod at rest in a moving frame, a single particle, unequal
    masses, impacts taken together, a zig-zag); and the same scenario at another speed."""
    r = _Reading(history, tuple(frames))
    a, b = _frame_pair(r)
    pair = _lorentz_pair(r, a, b)
    asked: list[_Asked] = [_question_read(r, a, b, pair), _question_lorentz(r, a, b, pair), _question_velocity(r, a, b)]
    fitting = [_question_hidden(r, a, b), _question_stopped_turn(r), _question_at_rest(r), _question_single(r),
               _question_momentum(r, next((c for c in r.collisions if len(c) > 1), None))
               if len({p.mass for p in history.scenario.particles}) > 1 else None,
               _question_together(r, b), _question_zigzag(r)]
    asked += [q for q in fitting if q is not None]
    other = _question_other_speed(r, a, b)
    if other is not None:
        asked = asked[:7] + [other]
    if len(asked) < 5:  # a scenario with little to ask about: momentum is conserved at each collision
        asked += [_question_momentum(r, c) for c in r.collisions][:5 - len(asked)]
    return tuple(Question(k + 1, text, answer) for k, (text, answer) in enumerate(asked[:8]))


# --- the document ---------------------------------------------------------------------------------------------

def _section(stem: str, history: History, frames: tuple[Frame, ...], worksheet: bool) -> tuple[Section, list[Block]]:
    """One scenario's section, and for a worksheet its part of the answer key (a heading, the filled tables and
    the questions again)."""
    blocks: list[Block] = [Heading(heading(history)), Paragraph(setup_text(history)),
                           DiagramBlock(f"{stem}_diagram", history, frames, diagram_caption(history, frames)),
                           Heading("What the diagram shows", 2)]
    blocks += explanation(history, frames)
    blocks.append(Heading("The rod at successive instants", 2))
    for f in frames:
        times = strip_times(history, f)
        blocks.append(Strips(f"{stem}_strips_{frame_word(f)}", history, f, times, strips_caption(history, f, times)))
    blocks.append(Heading("The numbers", 2))
    for f in frames:
        blocks += _tables(history, f, worksheet)
    section_title = f"{stem} at {_speed(history)}"
    key: list[Block] = []
    if worksheet:
        asked = questions(history, frames)
        blocks.append(Heading("Questions", 2))
        blocks += asked
        key.append(Heading(section_title, 2))
        key += [b.filled() for b in blocks if hasattr(b, "filled")]
        key += asked
    return Section(stem, section_title, tuple(blocks)), key


def build(items: Sequence[tuple], frames: Sequence[Frame] | None = None, worksheet: bool = False) -> Handout:
    """The handout (or, with `worksheet`, the worksheet and its answer key) of each (stem, history) item, one
    section each, in order. `frames` defaults to S and S′ of each scenario; a frame named `moving` is S′ of each
    scenario's own v. An item may also be (stem, history, frames), its own frames overriding `frames`."""
    entries = []
    for item in items:
        stem, history, *own = item
        if own:
            shown_frames = tuple(own[0])
        elif frames is None:
            shown_frames = paper_frames(history.scenario.v)
        else:
            shown_frames = tuple(moving_frame(history.scenario.v) if f.name == "moving" else f for f in frames)
        entries.append((stem, history, shown_frames))
    sections, key = [], []
    for stem, history, shown_frames in entries:
        section, answers = _section(stem, history, shown_frames, worksheet)
        sections.append(section)
        key += answers
    answer_key = (Heading("Answer key"), *key) if worksheet else ()
    return Handout(title([(stem, history) for stem, history, _ in entries]), tuple(sections), worksheet,
                   tuple(answer_key))
