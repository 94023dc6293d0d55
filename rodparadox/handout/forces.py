"""A handout's section on a rod driven by forces at its ends (docs/model.md, "Forces at the ends"): Sears's own
paradox. Pure text and tables, no drawing.

`forces_reading.read` reads a driven history once; `section_blocks` (a handout's) and `worksheet_blocks` (a
worksheet's and its key's, the questions from `worksheet_forces`) turn it into the section's blocks: the set-up,
the diagram, what it shows, "Sears's own paradox" (where the momentum is while the forces act at different
instants: in the stress, von Laue's point; for one constant push, the rigid rod's hyperbola against the causal
rod's steps), the forces' tables and the momentum slice by slice, both rods side by side where the causal rod is
given, and each frame's strips of each rod (`forces_strips`). Every number is read from the histories; the sentences
say nothing a history does not show. What has no meaning for forces (impacts, particles' starts) is left out.
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Sequence

from rodparadox.handout.document import Block, Cell, DiagramBlock, Heading, Paragraph, Table
from rodparadox.handout.forces_strips import strips_blocks
from rodparadox.handout.forces_reading import (ZERO, ForcesReading, FrameForces, Moment, far_start, read, signed,
                                               staircase, zero)
from rodparadox.handout.narrative import frame_described
from rodparadox.handout.words import in_c, in_l, listed, numeral, time_name
from rodparadox.handout.worksheet_forces import force_questions, timed_frame
from rodparadox.numbers import MINUS, coordinate_format, exact, velocity_format, without_zero_sign
from rodparadox.physics.frames import Frame, frame_name, frame_symbol, frame_word
from rodparadox.tables.build import coordinates, with_fraction
from rodparadox.tables.comparison import force_text

#: how a force's moments are named in a table and in the sentences
MOMENTS = {"start": "on", "peak": "peak", "end": "off"}
#: the title of the section that explains where the momentum is (the typographic apostrophe, as the headings set it)
PARADOX_TITLE = "Sears\u2019s own paradox"
#: the title of the same section for a rod pushed at one end only
PUSH_TITLE = "One end pushed: where the momentum goes"


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
    from rodparadox.physics.frames import PANEL_LETTERS

    s = history.scenario
    panels = "; ".join(f"({PANEL_LETTERS[k]}) in {frame_described(f, s.v, 'the forces act')}"
                       for k, f in enumerate(frames))
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
        said.append(f"{in_c(zero(after.rod.p / after.rod.E)) if after.rod.p else '0'} in {frame_name(f.frame)}")
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
                 "F": force(zero(m.force)), "end velocity": velocity(zero(m.velocity))}
        rows.append((Cell(MOMENTS[m.moment]), Cell(m.end),
                     *(Cell(text.replace("-", MINUS), blank is not None and column in blank(m, x, t))
                       for column, text in cells.items())))
    model = "" if not r.fronts else "causal rod, "
    return Table(f"{stem}forces_{'causal_' if r.fronts else ''}{frame_word(frame)}",
                 f"The forces in frame {frame_symbol(frame)} ({model}"
                 + ("end by end)" if by_end else f"in the order of {time_name(frame)})"),
                 ("force", "end", x, t, "F", "end velocity"), tuple(rows), "llnnnn")


def _p(x: float) -> str:
    """A momentum cell: 0 where it is nought, else four decimals, a rounding zero without a sign's minus (+0.0000,
    as the other tables set one), never −0.0000."""
    x = zero(x)
    return "0" if x == 0.0 else without_zero_sign(f"{x:+.4f}").replace("-", MINUS)


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
                 (t, "left delivered", "right delivered", f"rod {moving}", "rod stress", "rod total", "p/E",
                  "centre velocity"),
                 tuple(rows), "lnnnnnnn",
                 (f"Momenta in M c; the centre velocity is that of the rod's centre of energy, p/E the rod's total "
                  f"momentum over its total energy; the rod's total is its momentum before the forces, "
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
    stress = "gone" if abs(after.stress.p) < 1e-9 else f"{signed(after.stress.p)} M c"
    text += f" When both forces are off, the stress is {stress} and the rod holds {signed(after.rod.p)} M c."
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
                    f"t = {in_l(t1)}, it moves at {in_c(u)} and has gone "
                    f"{in_l(abs(stop.event.x - start.event.x) / L)}. "
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
                  f"{moving} and its stress part, which add up to its total; beside p/E, the velocity of the "
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
    if "strips" in parts:  # each frame's strips, each rod's
        blocks += strips_blocks(stem, [r.history for r in readings], frames)
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
    if "strips" in parts:  # in the key: the rows' forces and shading tell which force acts first
        told += strips_blocks(stem, [r.history for r in readings], frames)
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
