"""A handout's section on a rod driven by forces at its ends (docs/model.md, "Forces at the ends"): Sears's own
paradox. Pure text and tables, no drawing.

`read` reads a driven history once (`ForcesReading`): each force's start, peak and end in each frame shown, where
and when, with the end's velocity; on chosen slices of each frame the momentum each agent has delivered, the rod's
kinetic (rigid) or matter (causal) part, its stress part, its total, p/E and the velocity of its centre of energy.
`section_blocks` turns it into the section's blocks: the set-up, the diagram, what it shows, the forces' tables and
"Sears's own paradox" (where the momentum is while the forces act at different instants: in the stress, von
Laue's point), both rods side by side where the causal rod is given; for one push, the rigid rod's hyperbolic
motion against the causal rod's staircase. Every number is read from the histories; the sentences say nothing a
history does not show. Sections that have no meaning for forces (impacts, particles' starts, the rod's own view of
a turn) are left out.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, replace
from typing import Sequence

from rodparadox.handout.document import Block, Cell, DiagramBlock, Heading, Paragraph, Table
from rodparadox.handout.words import in_c, in_l, listed, numeral, time_name
from rodparadox.io.export_forces import force_rows
from rodparadox.numbers import MINUS, coordinate_format, exact, shown, velocity_format
from rodparadox.physics.frames import Frame, frame_name, frame_symbol, frame_word, time_window
from rodparadox.physics.types import EnergyMomentum
from rodparadox.tables.build import coordinates, with_fraction
from rodparadox.tables.comparison import force_text
from rodparadox.tables.forces_ledger import slice_row

#: how a force's moments are named in a table and in the sentences
MOMENTS = {"start": "on", "peak": "peak", "end": "off"}
#: momenta below this (units of M c) are rounding: printed as 0, never as "the rod moves"
ZERO = 1e-9
#: the title of the section that explains where the momentum is (the typographic apostrophe, as the headings set it)
PARADOX_TITLE = "Sears\u2019s own paradox"
#: the title of the same section for a rod pushed at one end only
PUSH_TITLE = "One end pushed: where the momentum goes"


def _zero(x: float) -> float:
    return 0.0 if abs(x) < ZERO else x + 0.0


def signed(x: float, digits: int = 4) -> str:
    """+0.1250, −0.03831, 0: a momentum with its sign, `digits` significant digits (a fraction where one fits)."""
    x = _zero(x)
    if x == 0.0:
        return "0"
    text = numeral(x, digits)
    return text if text.startswith(MINUS) else "+" + text


# --- the reading -----------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Moment:
    """A force's start, peak or end seen from a frame: its end, where and when (units of L), the force (M c²/L) and
    the end's velocity there."""

    end: str
    moment: str
    x: float
    t: float
    force: float
    velocity: float


@dataclass(frozen=True)
class Momenta:
    """One slice t of a frame: the momentum (and energy) each agent delivered up to it, the rod's kinetic (matter)
    part and its stress part, their sum, p/E and the centre of energy's velocity."""

    t: float
    left: EnergyMomentum
    right: EnergyMomentum
    moving: EnergyMomentum
    stress: EnergyMomentum
    rod: EnergyMomentum
    p_over_E: float
    v_E: float

    @property
    def delivered(self) -> float:
        return self.left.p + self.right.p


@dataclass(frozen=True)
class FrameForces:
    """A frame's view of the forces: their moments in its time order, the slices its table prints, and the key
    slice (where the stress holds most momentum)."""

    frame: Frame
    moments: tuple[Moment, ...]
    slices: tuple[Momenta, ...]
    key: Momenta
    initial: EnergyMomentum

    def when(self, end: str, moment: str) -> Moment:
        return next(m for m in self.moments if m.end == end and m.moment == moment)

    @property
    def ends(self) -> tuple[str, ...]:
        return tuple(dict.fromkeys(m.end for m in self.moments))

    def together(self, moment: str) -> bool:
        """Both forces' `moment` at one instant of the frame (False with one force)."""
        if len(self.ends) < 2:
            return False
        a, b = (self.when(end, moment).t for end in ("left", "right"))
        return abs(a - b) <= 1e-9 * (1.0 + abs(a) + abs(b))

    @property
    def first(self) -> str | None:
        """The end whose force starts first in this frame (None: both at once, or one force)."""
        if len(self.ends) < 2 or self.together("start"):
            return None
        return min(("left", "right"), key=lambda end: self.when(end, "start").t)


@dataclass(frozen=True)
class ForcesReading:
    """A driven history read once for the text: the model's name as the text says it, the velocity after the
    forces in S, each profile's area (the momentum it delivers in its own frame), and each frame's forces."""

    history: object
    frames: tuple[FrameForces, ...]
    final_velocity: float
    areas: tuple[tuple[str, float], ...]

    @property
    def fronts(self) -> bool:
        """The rod carries its stress as fronts at c (the causal rod): its moving part is 'matter'."""
        return self.history.fronts is not None

    def frame(self, name: str) -> FrameForces:
        return next(f for f in self.frames if f.frame.name == name)


def _momenta(history, frame: Frame, t: float) -> Momenta:
    """The slice t of the frame (t in the scenario's unit of length; the `Momenta` holds it in units of L)."""
    row = slice_row(history, frame, t)
    left, right, moving, stress, rod, _ = row["parts"].values()
    return Momenta(t / history.scenario.L, left, right, moving, stress, rod, row["p_over_E"], row["v_E"])


def slice_times(history, frame: Frame, moments: Sequence[Moment]) -> tuple[float, ...]:
    """The slices a frame's table prints: each force's start, peak and end (one row per instant; at the first start
    nothing is delivered yet), and after the last, halfway to the window's end."""
    hi = time_window(history, frame)[1] / history.scenario.L
    times = sorted({m.t for m in moments})
    out: list[float] = []
    for t in times:
        if not out or t - out[-1] > 1e-9 * (1.0 + abs(t)):
            out.append(t)
    return (*out, out[-1] + 0.5 * (hi - out[-1]))


def read(history, frames: Sequence[Frame]) -> ForcesReading:
    """The reading of `history` (driven: `history.driving` not None) in each frame (read once per history and
    frames: a worksheet and its key, a handout of the same run, read the same slices)."""
    return _read(history, tuple(frames))


@functools.lru_cache(maxsize=16)
def _read(history, frames: tuple[Frame, ...]) -> ForcesReading:
    driving = history.driving
    seen = []
    for frame in frames:
        rows = force_rows(history, frame)
        L = history.scenario.L
        moments = tuple(Moment(r["end"], r["moment"], r["x"] / L, r["t"] / L, r["force"], r["end_velocity"])
                        for r in rows)
        times = tuple(t * L for t in slice_times(history, frame, moments))
        # the key slice: halfway between two of the forces' moments (never at one: a worksheet asks those instants),
        # where the stress holds the most momentum
        halves = [0.5 * (a + b) for a, b in zip(times[:-2], times[1:-1])]
        key = _momenta(history, frame, max(halves, key=lambda t: abs(history.rod_parts(frame.rapidity, t)[1].p))) \
            if halves else None
        slices = tuple(sorted([_momenta(history, frame, t) for t in times] + ([key] if key else []),
                              key=lambda s: s.t))
        seen.append(FrameForces(frame, moments, slices, key or slices[-1], slices[0].rod))
    areas = tuple((end, p.area()) for end, p in driving.profiles())
    return ForcesReading(history, tuple(seen), math.tanh(history.final_rapidity), areas)


# --- the set-up and the diagram's caption ------------------------------------------------------------------------

def _force_words(profile) -> str:
    return force_text(profile).replace("\N{NO-BREAK SPACE}", " ")


def setup_text(history) -> str:
    """The rod, v and the frames, then each end's force (shape, size, when and in which frame's time)."""
    s = history.scenario
    v = exact(s.v)
    profiles = dict(history.driving.profiles())
    said = [f"on its {end} end {_force_words(p)}" for end, p in profiles.items()]
    pushes = "Agents act" if len(profiles) > 1 else "An agent acts"
    units = "" if s.L == 1.0 else f" (the tables give them in the unit of length in which L = {exact(s.L)})"
    return " ".join([
        f"A rod of proper length L = {exact(s.L)} and mass M lies at rest in S, its centre at x = 0 and its ends at "
        f"x = {MINUS}L/2 and x = +L/2, until a force acts on it.",
        f"S′ is the frame that moves at {MINUS}{v} c relative to S (v = {v}), so in S′ the rod first moves at "
        f"+{v} c.",
        f"{pushes} on the rod: {'; '.join(said)}. A force is the push its agent exerts in the end's own rest "
        f"frame (positive presses into the rod), given as a function of the time, in the frame named, of the event "
        f"where the end is.",
        f"Below, lengths and times are given as multiples of L{units}, speeds as fractions of c (c = 1), forces in "
        f"units of M c²/L, energies in M c² and momenta in M c."])


def diagram_caption(history, frames: Sequence[Frame], tell: bool = True) -> str:
    """Which panel is which frame and how the forces are drawn; with `tell`, the lines of simultaneity through each
    force's start and end (a worksheet leaves them out: which force starts first is asked)."""
    from rodparadox.handout.narrative import _frame_described
    from rodparadox.physics.frames import PANEL_LETTERS

    s = history.scenario
    panels = "; ".join(f"({PANEL_LETTERS[k]}) in {_frame_described(f, s.v)}" for k, f in enumerate(frames))
    sentences = [f"At v = {exact(s.v)}: {panels}.",
                 "Time runs up the page, x to the right, both in units of L, light at 45°; the rod's two ends bound "
                 "its shaded world-sheet.",
                 "Each force is drawn as a band beside its end, as wide as the force, with arrows that press into the "
                 "rod; a marker labelled on or off shows where it starts and ends."]
    if tell:
        sentences.append("Through each start and end run the line of simultaneity of S (dotted) and of S′ "
                         "(dash-dotted).")
    return " ".join(sentences)


# --- what the diagram shows --------------------------------------------------------------------------------------

def _span(f: FrameForces, end: str) -> str:
    t = time_name(f.frame)
    return f"from {t} = {in_l(f.when(end, 'start').t)} to {in_l(f.when(end, 'end').t)}"


def timing_text(f: FrameForces) -> str:
    """When the forces act in the frame, and whether at the same instants."""
    name = frame_name(f.frame)
    if len(f.ends) == 1:
        end = f.ends[0]
        return f"In {name} the force on the {end} end acts {_span(f, end)}."
    if f.together("start") and f.together("end"):
        return (f"In {name} the two forces act at the same instants, {_span(f, 'left')}: at every instant of "
                f"{name} they are equal and opposite.")
    first = f.first
    other = "right" if first == "left" else "left"
    gap = f.when(other, "start").t - f.when(first, "start").t
    return (f"In {name} the forces do not act at the same instants: the {first} force acts {_span(f, first)}, the "
            f"{other} force {_span(f, other)}, {in_l(gap)} later.")


def velocity_text(r: ForcesReading) -> str:
    """The rod's velocity after the forces, in each frame."""
    said = []
    for f in r.frames:
        after = f.slices[-1]
        said.append(f"{in_c(_zero(after.rod.p / after.rod.E)) if after.rod.p else '0'} in {frame_name(f.frame)}")
    before = [f"{in_c(f.initial.p / f.initial.E) if abs(f.initial.p) > ZERO else '0'} in {frame_name(f.frame)}"
              for f in r.frames]
    return (f"Before the forces the rod moves at {listed(before)}; after them, at {listed(said)}"
            + (": the forces leave its velocity unchanged." if abs(r.final_velocity) < 1e-9 else "."))


def explanation(r: ForcesReading) -> tuple[Paragraph, ...]:
    return (Paragraph(" ".join(timing_text(f) for f in r.frames)), Paragraph(velocity_text(r)))


# --- the tables ----------------------------------------------------------------------------------------------------

def events_table(r: ForcesReading, f: FrameForces, blank=None, stem: str = "", by_end: bool = False) -> Table:
    """Each force's start, peak and end in the frame, in its time order: end, x, t, F and the end's velocity there;
    `blank(moment)`: the columns of that row a worksheet's student fills in (x, t, end velocity); `by_end`: the rows
    end by end, each force's moments in order (a worksheet's: the frame's time order tells which force acts first)."""
    frame = f.frame
    coordinate = coordinate_format([c for m in f.moments for c in (m.x, m.t)])
    force = coordinate_format([m.force for m in f.moments])
    velocity = velocity_format([m.velocity for m in f.moments])
    x, t = coordinates(frame)
    rows = []
    order = {"start": 0, "peak": 1, "end": 2}
    moments = sorted(f.moments, key=lambda m: (m.end, order[m.moment])) if by_end else f.moments
    for m in moments:
        cells = {x: with_fraction(coordinate(m.x), m.x), t: with_fraction(coordinate(m.t), m.t),
                 "F": force(_zero(m.force)), "end velocity": velocity(_zero(m.velocity))}
        rows.append((Cell(MOMENTS[m.moment]), Cell(m.end),
                     *(Cell(text.replace("-", MINUS), blank is not None and column in blank(m, x, t))
                       for column, text in cells.items())))
    model = "" if not r.fronts else "causal rod, "
    return Table(f"{stem}forces_{'causal_' if r.fronts else ''}{frame_word(frame)}",
                 f"The forces in frame {frame_symbol(frame)} ({model}"
                 + ("end by end)" if by_end else f"in the order of {time_name(frame)})"),
                 ("force", "end", x, t, "F", "end velocity"), tuple(rows), "llnnnn")


def _p(x: float) -> str:
    x = _zero(x)
    return "0" if x == 0.0 else f"{x:+.4f}".replace("-", MINUS)


def momentum_table(r: ForcesReading, f: FrameForces, compared: bool = False, blank: bool = False) -> Table:
    """Von Laue's row per slice: the momentum each agent delivered, the rod's kinetic (matter) part and its stress
    part, the total, and beside p/E the velocity of the rod's centre of energy."""
    t = time_name(f.frame)
    moving = "matter" if r.fronts else "kinetic"
    rows = []
    for s in f.slices:
        values = (s.left.p, s.right.p, s.moving.p, s.stress.p, s.rod.p)
        rows.append((Cell(in_l(s.t, 4).replace(" L", "")), *(Cell(_p(x), blank) for x in values),
                     Cell(_p(s.p_over_E), blank), Cell(_p(s.v_E), blank)))
    return Table(f"momentum_{'causal_' if r.fronts else ''}{frame_word(f.frame)}",
                 f"Where the momentum is in frame {frame_symbol(f.frame)}"
                 + (" (causal rod)" if r.fronts else (" (rigid rod)" if compared else "")),
                 (t, "left delivered", "right delivered", f"rod {moving}", "rod stress", "rod total", "p/E", "v_E"),
                 tuple(rows), "lnnnnnnn",
                 (f"Momenta in M c; v_E is the velocity of the rod's centre of energy, p/E the rod's total momentum "
                  f"over its total energy; the rod's total is its momentum before the forces, "
                  f"{_p(f.initial.p)}, plus what the two agents delivered.",))


# --- Sears's own paradox ---------------------------------------------------------------------------------------

def _model(r: ForcesReading) -> str:
    return "causal rod" if r.fronts else "rigid rod"


def _timed_in(frame) -> str:
    """The frame a profile is timed in, in running text: S, S′, the frame u = 0.3."""
    return {"rest": "S", "moving": "S′"}.get(frame, None) if isinstance(frame, str) else \
        f"the frame moving at {in_c(float(frame))} relative to S"


def delivered_text(r: ForcesReading) -> str:
    """The momentum each force delivers in the frame its profile is timed in: the profile's area."""
    profiles = dict(r.history.driving.profiles())
    said = [f"the {end} agent delivers {signed(area if end == 'left' else -area)} M c" for end, area in r.areas]
    timed = {p.frame for p in profiles.values()}
    if len(timed) == 1:
        where = _timed_in(next(iter(timed)))
        return (f"In {where}, in whose time the forces are given, the momentum an agent delivers is the area under "
                f"its force against time: {listed(said)}.")
    said = [f"{text} in {_timed_in(profiles[end].frame)}" for text, (end, _) in zip(said, r.areas)]
    return (f"In the frame in whose time a force is given, the momentum its agent delivers is the area under the force "
            f"against time: {listed(said)}.")


def sears_case(r: ForcesReading) -> bool:
    """Sears's case: two equal forces, timed in the rod's rest frame S, acting at the same instants of it."""
    profiles = [p for _, p in r.history.driving.profiles()]
    return (len(profiles) == 2 and profiles[0] == profiles[1] and profiles[0].frame == "rest"  # the rod's own frame
            and all(f.together("start") and f.together("end") for f in r.frames
                    if f.frame.name == profiles[0].frame or (not isinstance(profiles[0].frame, str)
                                                             and abs(f.frame.velocity - profiles[0].frame) < 1e-12)))


def balance_text(r: ForcesReading, f: FrameForces) -> str:
    """The frame where the forces are simultaneous: what was delivered when they peak, and what the rod does."""
    name, t = frame_name(f.frame), time_name(f.frame)
    peak = next((s for s in f.slices if abs(s.t - f.when("left", "peak").t) <= 1e-9 * (1 + abs(s.t))), f.key)
    moving = "matter" if r.fronts else "kinetic"
    text = (f"The {_model(r)} in {name}: at {t} = {in_l(peak.t)}, when both forces peak, the left agent has delivered "
            f"{signed(peak.left.p)} M c and the right {signed(peak.right.p)} M c, together {signed(peak.delivered)} "
            f"M c.")
    still = all(abs(x.moving.p - f.initial.p) < 1e-9 for x in f.slices)
    if not r.fronts and still:
        return text + (f" Nothing moves: the balanced forces only stress the rod, the same all along it; its "
                       f"{moving} part stays {signed(peak.moving.p)} M c and its stress part {signed(peak.stress.p)} "
                       f"M c.")
    if r.fronts and abs(f.initial.p) < 1e-12:  # squeezed from both ends at once in its own rest frame
        return text + (f" The rod is squeezed from both ends at once: its ends move in, its two halves oppositely, "
                       f"and its momentum stays {signed(peak.rod.p)} M c; the work done on it, "
                       f"{signed(peak.left.E + peak.right.E)} M c² by then, is stored as its energy.")
    # balanced in this frame, not in the rod's own time: the rod moves (sears_moving seen from S′)
    k = max(f.slices, key=lambda x: abs(x.moving.p - f.initial.p))
    return text + (f" Yet the rod moves: the forces balance at every instant of {name}, not at every instant of the "
                   f"rod's own time, so at {t} = {in_l(k.t)} its {moving} part is {signed(k.moving.p)} M c and its "
                   f"stress part {signed(k.stress.p)} M c: together {signed(k.rod.p)} M c, its momentum before the "
                   f"forces plus what the agents have delivered.")


def shift_text(r: ForcesReading, f: FrameForces) -> str:
    """The frame where the forces are not simultaneous: the key slice's row, and the answer (the stress)."""
    name, t = frame_name(f.frame), time_name(f.frame)
    k = f.key
    moving = "matter" if r.fronts else "kinetic"
    kinetic_change = k.moving.p - f.initial.p
    text = (f"The {_model(r)} in {name}: at {t} = {in_l(k.t)} the left agent has delivered {signed(k.left.p)} M c and "
            f"the right {signed(k.right.p)} M c, together {signed(k.delivered)} M c more than the rod held before, "
            f"{signed(f.initial.p)} M c.")
    if abs(kinetic_change) < 1e-9:
        text += (f" Yet the rod's {moving} part is still {signed(k.moving.p)} M c: its velocity has not changed. The "
                 f"momentum delivered is in the stress, {signed(k.stress.p)} M c (a stressed body moving at v carries "
                 f"momentum that no motion of its matter shows; von Laue).")
    else:
        text += (f" The rod's {moving} part has changed by {signed(kinetic_change)} M c and its stress part holds "
                 f"{signed(k.stress.p)} M c: the rod moves while the forces act, and what was delivered is shared "
                 f"between its motion and its stress.")
    text += (f" Its centre of energy moves at {in_c(k.v_E)} there, while p/E = {in_c(k.p_over_E)}: for a closed "
             f"system they would be equal; with forces acting at its ends they are not.")
    after = f.slices[-1]
    text += (f" When both forces are off, the stress is {'gone' if abs(after.stress.p) < 1e-9 else signed(after.stress.p) + ' M c'} "
             f"and the rod holds {signed(after.rod.p)} M c.")
    return text


def push_text(r: ForcesReading) -> str:
    """One end pushed: how that end moves (rigid: a hyperbola, its proper acceleration; causal: in steps)."""
    driving = r.history.driving
    (end, profile), = driving.profiles()
    events = {e.moment: e for e in driving.force_events() if e.end == end}
    start, stop = events["start"], events["end"]
    L = r.history.scenario.L
    t0, t1 = start.event.t / L, stop.event.t / L
    u = math.tanh(stop.rapidity)
    kind = "push" if profile.greatest() > 0 else "pull"
    far = "right" if end == "left" else "left"
    constant = profile.shape == "step"  # constant in the end's own rest frame: |proper acceleration| F/M
    if not r.fronts:
        if constant:  # a constant force on a rod at rest in S: hyperbolic motion, proper acceleration F/M
            a = abs(math.sinh(stop.rapidity)) / (t1 - t0)
            return (f"The rigid rod: the {kind} gives its {end} end a constant proper acceleration, "
                    f"{numeral(a)} c²/L = |F|/M; in S that end moves on a hyperbola and, when the {kind} ends at "
                    f"t = {in_l(t1)}, it moves at {in_c(u)} and has gone {in_l(abs(stop.event.x - start.event.x) / L)}. "
                    f"The whole rod moves at once, along its own lines of simultaneity.")
        return (f"The rigid rod: when the force ends, at t = {in_l(t1)} in S, its {end} end moves at {in_c(u)}. The "
                f"whole rod moves at once, along its own lines of simultaneity.")
    arrive = far_start(r.history, far, start.event.t, stop.event.t) / L
    signal = (f" Its {far} end starts to move only at t = {in_l(arrive)}, when the force's first signal, at c, "
              f"reaches it." if arrive < t1 else "")
    if constant:
        steps = staircase(r.history, end, start.event.t, stop.event.t)
        return (f"The causal rod: its {end} end moves at once at {in_c(steps[0])}, and keeps that velocity until the "
                f"{kind}'s first signal has crossed the rod and come back; its velocity changes in steps, "
                f"{listed([in_c(w) for w in steps])}, while the {kind} lasts." + signal)
    return f"The causal rod: when the force ends its {end} end moves at {in_c(u)}." + signal


def staircase(history, end: str, t0: float, t1: float, samples: int = 400) -> tuple[float, ...]:
    """The distinct velocities (in S) of the driven end while its force acts (the causal rod's steps), in order."""
    sigma = 0.0 if end == "left" else history.scenario.L
    out: list[float] = []
    for k in range(1, samples):
        w = history.material_velocity(sigma, 0.0, t0 + (t1 - t0) * k / samples)
        if not out or abs(w - out[-1]) > 1e-9:
            out.append(w)
    return tuple(out)


def far_start(history, end: str, t0: float, t1: float) -> float:
    """The first instant of S at which the far end moves (bisection on its velocity)."""
    sigma = 0.0 if end == "left" else history.scenario.L
    lo, hi = t0, t1
    if abs(history.material_velocity(sigma, 0.0, hi)) < 1e-12:
        return hi
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if abs(history.material_velocity(sigma, 0.0, mid)) < 1e-12 else (lo, mid)
    return hi


def paradox_blocks(readings: Sequence[ForcesReading]) -> list[Block]:
    """The section "Sears's own paradox" (two forces) or "One end pushed" (one), for each rod given (the rigid rod
    first): what each agent delivers, and where the momentum is, in sentences (`momentum_blocks`: the tables)."""
    first = readings[0]
    two = len(first.areas) == 2
    kind = "pushed" if any(p.greatest() > 0 for _, p in first.history.driving.profiles()) else "pulled"
    blocks: list[Block] = [Heading(PARADOX_TITLE if two else PUSH_TITLE.replace("pushed", kind), 2),
                           Paragraph(delivered_text(first))]
    if two:
        blocks.append(Paragraph(
            "Sears asked: where the forces act at different instants, the momentum delivered changes while the "
            "rod's velocity does not; where is the momentum in between? The answer is in the rod's stress, which "
            "carries momentum when the rod moves. The tables at the end of the section follow it slice by slice."
            if sears_case(first) else
            "While the forces act, the momentum they deliver is shared between the rod's motion and its stress, "
            "which carries momentum when the rod moves. The tables at the end of the section follow it slice by "
            "slice."))
        for r in readings:
            said = []
            for f in r.frames:
                said.append(balance_text(r, f) if f.together("start") and f.together("end") else shift_text(r, f))
            blocks.append(Paragraph(" ".join(said)))
    else:
        blocks += [Paragraph(push_text(r)) for r in readings]
        g = first.frames[0]
        k = g.key
        blocks.append(Paragraph(
            f"In {frame_name(g.frame)}, while the {kind[:-2]} acts, the agent's momentum is partly in the rod's motion "
            f"and partly in its stress: at {time_name(g.frame)} = {in_l(k.t)} the agent has delivered "
            f"{signed(k.left.p + k.right.p)} M c, the {_model(first)}'s kinetic part has gained "
            f"{signed(k.moving.p - g.initial.p)} M c and its stress holds {signed(k.stress.p)} M c."))
    return blocks


def momentum_blocks(readings: Sequence[ForcesReading], blank: bool = False) -> list[Block]:
    """Per frame, each rod's momentum table (von Laue's row, slice by slice), after the sentence that reads them."""
    first = readings[0]
    moving = "kinetic part (its mass moving with its points' velocities)" if len(readings) == 1 else \
        "kinetic part (rigid rod) or matter part (causal rod)"
    blocks: list[Block] = [
        Heading("Where the momentum is, slice by slice", 2),
        Paragraph(f"On slices of each frame (each force's start, peak and end, a slice halfway between two of them "
                  f"where the stress holds most, and one after the forces): what each agent has delivered, the rod's "
                  f"{moving} and its stress part, which add up to its total; beside p/E, the velocity v_E of the "
                  f"rod's centre of energy.")]
    for f_index in range(len(first.frames)):
        for r in readings:
            blocks.append(momentum_table(r, r.frames[f_index], len(readings) > 1, blank))
    return blocks


def causal_diagram(stem: str, causal, frames, worksheet: bool, equal_scales: bool) -> DiagramBlock:
    """The causal rod's diagram, in the same frames as the rigid rod's."""
    from rodparadox.physics.frames import PANEL_LETTERS

    panels = "; ".join(f"({PANEL_LETTERS[k]}) in {frame_name(f)}" for k, f in enumerate(frames))
    caption = (f"The causal rod, driven by the same forces: {panels}. Its world-sheet is shaded by its compression "
               f"λ, its length per unit of proper length (the legend gives the scale); the forces are drawn as for "
               f"the rigid rod.")
    if worksheet is False:
        caption += " Through each start and end run the lines of simultaneity of S and S′."
    return DiagramBlock(f"{stem}_causal_diagram", causal, tuple(frames), caption, tell=not worksheet,
                        equal_scales=equal_scales)


def frames_tables(readings: Sequence[ForcesReading], blank_columns=None) -> list[Block]:
    """The forces' events tables of each frame, each rod's (the rigid rod first)."""
    blocks: list[Block] = []
    for k, f in enumerate(readings[0].frames):
        symbol = frame_name(f.frame)
        x, t = coordinates(f.frame)
        order = "end by end" if blank_columns else "in the order of its time"
        blocks.append(Paragraph(
            f"The forces in {symbol}, {order}: where and when each starts (on), peaks and ends "
            f"(off) ({x} and {t} in units of L), the force there and the velocity of its end (in units of c)."
            if k == 0 else f"The forces in {symbol}, in the same columns ({x} and {t} in units of L)."))
        for r in readings:
            blocks.append(events_table(r, r.frames[k], blank_columns(r.frames[k]) if blank_columns else None,
                                       by_end=blank_columns is not None))
    return blocks


def diagram(stem: str, history, frames, worksheet: bool, equal_scales: bool, causal=None,
            together: bool = False) -> DiagramBlock:
    """The rigid rod's diagram; `together`: with the causal rod's row under it (a handout's), else the causal rod's,
    where compared, is its own block (a worksheet's: `causal_diagram`, set apart so that each fits a page with the
    text around it)."""
    caption = diagram_caption(history, frames, tell=not worksheet)
    if together:
        caption += (" The upper row is the rigid rod, the lower row the causal rod, driven by the same forces, its "
                    "world-sheet shaded by its compression λ, its length per unit of proper length (the legend gives "
                    "the scale); each frame's two panels are drawn to one scale.")
        return DiagramBlock(f"{stem}_diagram", history, tuple(frames), caption, tell=not worksheet,
                            equal_scales=equal_scales, compared=causal)
    if causal is not None:
        caption = caption.replace(": (a)", ", the rigid rod: (a)", 1)
    if equal_scales and len(frames) > 1:
        caption += " The panels are drawn to one scale: a length of L is as long on the page in each."
    return DiagramBlock(f"{stem}_diagram", history, tuple(frames), caption, tell=not worksheet,
                        equal_scales=equal_scales)


def section_blocks(stem: str, history, frames: tuple[Frame, ...], causal=None, parts=frozenset(),
                   heading: str = "", worksheet: bool = False, equal_scales: bool = False) -> list[Block]:
    """A handout's section on a driven rod (`build._section` for a history with `driving`)."""
    readings = [read(history, frames)] + ([read(causal, frames)] if causal is not None else [])
    blocks: list[Block] = [Heading(heading), Paragraph(setup_text(history))]
    ledger = "ledger" in parts or "comparison" in parts
    if causal is None:  # the diagram, then what it shows and the paradox's sentences (they fill the page it leaves)
        if "diagrams" in parts:
            blocks += [diagram(stem, history, frames, worksheet, equal_scales),
                       Heading("What the diagram shows", 2), *explanation(readings[0])]
        blocks += paradox_blocks(readings) if ledger else []
    else:  # both rods' diagram, a page tall, the sentences after it (they fill the page before it)
        if "diagrams" in parts:
            blocks += [diagram(stem, history, frames, worksheet, equal_scales, causal, together=True),
                       Heading("What the diagrams show", 2), *explanation(readings[0])]
        blocks += paradox_blocks(readings) if ledger else []
    if "tables" in parts:
        blocks += [Heading("The numbers", 2), *frames_tables(readings)]
    if ledger:
        blocks += momentum_blocks(readings)
    return blocks


def worksheet_blocks(stem: str, history, frames: tuple[Frame, ...], causal=None, parts=frozenset(),
                     heading: str = "", key_heading: str = "", chosen=None,
                     equal_scales: bool = False) -> tuple[list[Block], list[Block]]:
    """A worksheet's section on a driven rod and its part of the answer key. Before the key: the set-up, the diagram
    without the lines of simultaneity through the forces' starts and ends (which force acts first is asked), the
    forces' tables with the cells to fill in left blank, and the questions (`worksheet_forces`); the key: the
    filled tables, the worked answers, what the diagram shows and Sears's own paradox with its momentum tables."""
    from rodparadox.handout.document import Question  # noqa: F401 (the questions' type)
    from rodparadox.handout.worksheet_forces import force_questions, timed_frame

    readings = [read(history, frames)] + ([read(causal, frames)] if causal is not None else [])
    timed = timed_frame(readings[0])[0].frame

    def blank(f: FrameForces):
        def cells(m: Moment, x: str, t: str) -> frozenset[str]:
            if f.frame == timed:  # the set-up gives the forces' times in this frame, a question where each starts
                return frozenset({"end velocity"}) if m.moment == "start" else frozenset({x, "end velocity"})
            return frozenset({x, t, "end velocity"})
        return cells

    asked = force_questions(readings[0], chosen)
    blocks: list[Block] = [Heading(heading), Paragraph(setup_text(history))]
    told: list[Block] = []
    if "diagrams" in parts:
        blocks.append(diagram(stem, history, frames, True, equal_scales, causal))
        if causal is not None:
            blocks.append(causal_diagram(stem, causal, frames, True, equal_scales))
        told += [Heading("What the diagram shows", 2), *explanation(readings[0])]
    filled: list[Block] = []
    if "tables" in parts:  # the rigid rod's to fill in (the questions ask about it); the key fills both rods'
        blocks += [Heading("The numbers", 2)]
        for k, b in enumerate(frames_tables(readings[:1], blank)):
            blocks.append(b if isinstance(b, Table) or k else
                          Paragraph(b.text.replace("The forces in", "Fill in the forces in", 1)
                                    + " The cells left empty are yours to fill in."))
        filled = [replace(b.filled(), name=f"{stem}_{b.name}_key") if isinstance(b, Table) else b
                  for b in frames_tables(readings, blank)]
    blocks += [Heading("Questions", 2), *asked]
    if "ledger" in parts or "comparison" in parts:
        told += [replace(b, name=f"{stem}_{b.name}_key") if isinstance(b, Table) else b
                 for b in paradox_blocks(readings) + momentum_blocks(readings)]
    key: list[Block] = [Heading(key_heading, 2), Paragraph(setup_text(history)),
                        *([Heading("The numbers", 2), *filled] if filled else []),
                        Heading("Questions and answers", 2), *asked, *told]
    return blocks, key
