"""The prose of a handout's section: the set-up paragraph, the diagram's caption and the explanation of what
the diagram shows (simultaneity and order, the rod's velocity, zig-zags, rests and stopped turns). Pure text.

Every sentence is generated from the computed history (`reading.Reading`):
which impacts share a line of simultaneity is tested, pair by pair, in each
frame shown and on the rod's own lines (`Impact.collision`); the rod's velocity
is read from the impacts' rapidities; turns come from `RodHistory.turns`.
"""

from __future__ import annotations

import math
from typing import Sequence

from rodparadox.handout.document import Paragraph
from rodparadox.handout.reading import Reading, zigzags
from rodparadox.handout.words import (impact_names, in_c, in_l, listed, numeral, pushed, time_name)
from rodparadox.numbers import MINUS, exact, impact_name
from rodparadox.physics.history import RodHistory
from rodparadox.physics.types import Impact
from rodparadox.physics.frames import Frame, frame_name, frame_symbol, moving_frame, PANEL_LETTERS, rest_frame, time_order
from rodparadox.tolerances import ONE_INSTANT, SAME_RAPIDITY


# --- the set-up ------------------------------------------------------------------------------------------------

def _timing_frame(frame: str | float) -> str:
    """The frame a `model.Timing` counts its delay in: S, S′, or the frame of velocity u relative to S."""
    if frame == "rest":
        return "S"
    if frame == "moving":
        return "S′"
    return f"the frame of velocity {in_c(float(frame))} relative to S"


def setup_text(history: RodHistory, tell: bool = True) -> str:
    """One paragraph: the rod, v and the frames, then each particle's mass, speed, end and start; with `tell`, how a
    particle's start was chosen (at the same instant of S′ as B's first impact: a worksheet asks it, and gives the
    start alone)."""
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
        mass = "M" if p.mass == 1.0 else f"{numeral(p.mass)} M"
        direction = "right" if p.name == "A" else "left"
        speed = exact(s.speed(p)) + " c"
        text = f"Particle {p.name}, of mass {mass}, moves {direction} at {speed} in S towards the rod's {p.end} end"
        gap = (-s.L / 2 - starts[p.name].x) if p.name == "A" else (starts[p.name].x - s.L / 2)
        if p.timed_with is None:
            text += (", starting at that end at t = 0." if p.gap == 0 else
                     f", starting {in_l(p.gap)} from it at t = 0.")
        elif not tell:
            text += (f", starting {in_l(gap / s.L)} from it at t = 0." if gap >= 0 else
                     f", starting at x = {in_l(starts[p.name].x / s.L)} at t = 0.")
        else:
            timing = p.timed_with
            frame = _timing_frame(timing.frame)
            if timing.delay == 0:
                when = f"at the same instant of {frame} as {timing.particle}'s first impact"
            else:
                delay = in_l(abs(timing.delay))
                when = f"{delay} {'after' if timing.delay > 0 else 'before'} {timing.particle}'s first impact, in " \
                       f"the time of {frame}"
            text += f"; it is placed so that its first impact comes {when}"
            text += (f", so at t = 0 it is {in_l(gap / s.L)} from that end." if gap >= 0 else
                     f", so at t = 0 it is at x = {in_l(starts[p.name].x / s.L)}.")
        sentences.append(text)
    tables_unit = "" if s.L == 1.0 else f" (the tables give them in the unit of length in which L = {exact(s.L)})"
    where = "the particles are where this paragraph puts them" if len(particles) > 1 else \
        "the particle is where this paragraph puts it"  # `single`: one particle
    sentences.append(f"Below, lengths and times are given as multiples of L{tables_unit}, speeds as fractions of c "
                     f"(c = 1), masses in units of M; t = 0 is the instant of S at which {where}.")
    return " ".join(sentences)


# --- the diagram -----------------------------------------------------------------------------------------------

def frame_described(frame: Frame, v: float, before: str = "it is struck") -> str:
    """A panel's frame in words; `before`: what S is the rod's rest frame before ("the forces act")."""
    if frame.name == "rest":
        return f"S, the rod's rest frame before {before}"
    if frame.name == "moving":
        return f"S′, where the rod first moves at +{exact(v)} c"
    return f"the frame {frame_symbol(frame)}, moving at {in_c(frame.velocity)} relative to S"


def diagram_caption(history: RodHistory, frames: Sequence[Frame], tell: bool = True) -> str:
    """Which panel is which frame, how to read the lines of simultaneity, and (`tell`; a worksheet asks it) which
    impacts share one."""
    r = Reading(history, tuple(frames))
    s = history.scenario
    panels = "; ".join(f"({PANEL_LETTERS[k]}) in {frame_described(f, s.v)}" for k, f in enumerate(frames))
    labels = impact_names(history.impacts)
    particles = sorted(p.name for p in s.particles)
    # as the styles draw them (render.styles: PARTICLE_DASH, B_DASH): A dashed, B long-and-short dashed
    looks = {"A": "dashed", "B": "long-and-short dashed"}
    dashed = " and ".join(f"the particle {name} is {looks[name]}" for name in particles)
    # a worksheet lists the labels without "and" (a ledger's row "B₁ and A₁" is a claim of simultaneity it asks)
    labels = labels if tell else ", ".join(impact_name(i.label) for i in history.impacts)
    sentences = [f"At v = {exact(s.v)}: {panels}.",
                 f"Time runs up the page, x to the right, both in units of L, light at 45°; the rod's two ends bound "
                 f"its shaded world-sheet, and {dashed}."]
    if not tell:  # no lines of simultaneity through the impacts: which impacts share one is asked
        sentences.append(f"The impact is labelled {labels}." if len(history.impacts) == 1 else
                         f"The impacts are labelled in the order of the rod's own time: {labels}.")
        return " ".join(sentences)
    impacts = (f"The impact is labelled {labels}. Through it run" if len(history.impacts) == 1 else
               f"The impacts are labelled {labels} in the order of the rod's own time. Through each impact run")
    sentences.append(f"{impacts} the line of simultaneity of S (dotted) and of S′ (dash-dotted).")
    styles = {"rest": "dotted", "moving": "dash-dotted"}
    shared = []
    for frame in (rest_frame(), moving_frame(s.v)):
        for t, group in r.instants(frame):
            if len(group) > 1:
                shared.append(f"{impact_names(group)} share one {styles[frame.name]} line, of {frame_symbol(frame)}")
    if shared:
        sentences.append(listed(shared) + ".")
    elif len(history.impacts) > 1:
        sentences.append("No two impacts share a line of S or of S′.")
    return " ".join(sentences)


# --- the explanation -------------------------------------------------------------------------------------------

def _simultaneity(r: Reading) -> str:
    """Which impacts share a line of simultaneity of which frame, and in what order the rod and each frame take them."""
    h = r.history
    if len(h.impacts) == 1:
        i = h.impacts[0]
        where = "; ".join(f"{r.when([i], f)} in {frame_name(f)}" for f in r.frames)
        return f"The rod is struck once, by {i.particle} at its {i.end} end: {impact_name(i.label)}, at {where}."
    sentences = []
    collisions, lines = r.collisions, r.lines
    if len(lines) == len(h.impacts):
        sentences.append(f"The rod takes its impacts one at a time, in the order {impact_names(h.impacts)}: no two lie on "
                         f"one line of its own simultaneity, so each is a collision of its own.")
    elif len(collisions) == 1:
        sentences.append(f"The rod takes {impact_names(h.impacts)} together: they lie on one line of its own "
                         f"simultaneity and make one collision.")
    else:
        parts = []
        for line in lines:
            on_line = [c for c in collisions if c[0] in line]
            parts.append(", then at once ".join(impact_names(c) + (" together" if len(c) > 1 else "") for c in on_line))
        sentences.append(f"In its own time the rod takes {', then '.join(parts)}: impacts it takes at once lie on "
                         f"one line of its own simultaneity, and impacts it takes together make one collision.")
    # every set of impacts at one instant of a shown frame, or on one line of the rod's own simultaneity
    groups: list[tuple[Impact, ...]] = [line for line in lines if len(line) > 1]
    for frame in r.frames:
        groups += [g for _, g in r.instants(frame) if len(g) > 1]
    seen = set()
    said: set[tuple[str, str]] = set()  # (impact, frame) whose time a sentence has given: the order leaves it out
    for group in groups:
        key = tuple(i.label for i in group)
        if key in seen:
            continue
        seen.add(key)
        same_event = all(math.hypot(i.event.x - group[0].event.x, i.event.t - group[0].event.t)
                         <= ONE_INSTANT * r.scale for i in group)
        if same_event:
            sentences.append(f"{impact_names(group)} happen at one event, so at one instant of every frame.")
            continue
        together = [f for f in r.frames if all(r.same_time(r.t(i, f), r.t(group[0], f)) for i in group)]
        apart = [f for f in r.frames if f not in together]
        on_rod_line = any(set(group) <= set(line) for line in lines)
        if together:
            text = (f"{impact_names(group)} lie on one line of simultaneity of "
                    + listed([f"{frame_name(f)} ({r.when(group, f)})" for f in together]))
            said |= {(i.label, f.name) for i in group for f in together}
            if not on_rod_line:
                text += ", but the rod takes them one at a time, as collisions of their own"
        else:
            text = f"{impact_names(group)} lie on one line of the rod's own simultaneity"
        if apart:
            details = []
            for f in apart:
                ordered = sorted(group, key=lambda i: r.t(i, f))
                first, last = ordered[0], ordered[-1]
                gap = r.length(r.t(last, f) - r.t(first, f), [first, last], f)
                details.append(f"in {frame_name(f)}, where {impact_name(first.label)} comes at {r.when([first], f)} "
                               f"and {impact_name(last.label)} at {in_l(r.length(r.t(last, f), [last], f))}, {in_l(gap)} later")
                said |= {(first.label, f.name), (last.label, f.name)}
            text += ". They are not simultaneous " + "; nor ".join(details)
        sentences.append(text + ".")
    if not groups:
        sentences.append("No two impacts lie on one line of simultaneity of "
                         + " or of ".join(frame_name(f) for f in r.frames) + ".")
    # the order in each frame's time, and where it is not the rod's own
    orders = []
    for f in r.frames:
        steps, named = [], False  # named: the frame's time (t′ = ...) said once in this list
        for t, group in r.instants(f):
            told = all((i.label, f.name) in said for i in group)  # its time given above: not again
            time = in_l(r.length(t, group, f)) if named else r.when(group, f)
            named = named or not told
            steps.append(f"{impact_names(group)}{' together' if len(group) > 1 else ''}" + ("" if told else f" ({time})"))
        orders.append(f"in {frame_name(f)} {', then '.join(steps)}")
    sentences.append("In each frame's own time the order is: " + "; ".join(orders) + ".")
    for f in r.frames:
        pair = _out_of_order(r, f)
        if pair is not None:
            a, b = (impact_name(i.label) for i in pair)
            sentences.append(f"In {frame_name(f)} {b} comes before {a}, although the rod takes {a} first: the two "
                             f"events are too far apart for light to join them, so frames may disagree about their "
                             f"order, and it is the rod's own order that decides what happens to it.")
    return " ".join(sentences)


def _out_of_order(r: Reading, frame: Frame) -> tuple[Impact, Impact] | None:
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


def _velocities(r: Reading) -> str:
    """The rod's velocity before and after each collision, in each frame, and overall."""
    collisions = r.collisions
    sentences = ["The rod's velocity here is that of its momentum: it changes at once at an impact, while the rod's "
                 "shape follows only as its lines of simultaneity turn (below)."]
    unchanged = all(abs(c[-1].rod_rapidity_after) <= SAME_RAPIDITY for c in collisions)
    if unchanged:
        speeds = listed([f"{in_c(r.rod_velocities(f)[0])} in {frame_name(f)}" for f in r.frames])
        sentences.append(f"It never changes: it is {speeds} before, between and after the impacts.")
        return " ".join(sentences)
    for f in r.frames:
        u = r.rod_velocities(f)
        steps = [f"{in_c(u[0])} before {impact_names(collisions[0])}"]
        # the impacts' times are the first paragraph's: not again
        steps += [f"{in_c(u[k + 1])} after {impact_names(c)}" for k, c in enumerate(collisions)]
        order = "" if [c[0] for c in collisions] == _first_of_each(r, f) else \
            f" (the clocks of {frame_name(f)} put these impacts in another order)"
        sentences.append(f"In {frame_name(f)}, in the rod's own order{order}: " + "; ".join(steps) + ".")
    finals = [(r.rod_velocities(f)[-1], frame_name(f)) for f in r.frames]
    at_rest = [symbol for u, symbol in finals if u == 0.0]
    moving = [f"{in_c(u)} in {symbol}" for u, symbol in finals if u != 0.0]
    states = listed(([f"is at rest in {listed(at_rest)}"] if at_rest else [])
                     + ([f"moves at {listed(moving)}"] if moving else []))
    final = r.velocity(r.collisions[-1][-1].rod_rapidity_after, rest_frame())
    sentences.append(f"After the last impact it {states}" + (": as before the first." if final == 0.0 else "."))
    return " ".join(sentences)


def _first_of_each(r: Reading, frame: Frame) -> list[Impact]:
    """The first impact of each collision, ordered by the frame's time of that impact (the rod's order at a tie)."""
    firsts = [c[0] for c in r.collisions]
    return [firsts[k] for k in time_order([r.t(i, frame) for i in firsts], r.scale)]


def _why(r: Reading) -> str:
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
                hidden = h.energy_momentum(f.rapidity, middle).hidden
                sentences.append(
                    f"In {frame_name(f)} {impact_name(first.label)} comes before {impact_name(last.label)}, yet the "
                    f"rod moves on at {in_c(r.rod_velocities(f)[0])} between them: it takes both impulses together, on "
                    f"its own "
                    f"line of simultaneity, where they cancel. Between them in {frame_name(f)}, {first.particle} "
                    f"has already struck and {last.particle} not yet, so the momentum {first.particle} gave up, "
                    f"{numeral(hidden.p)} M c, is carried by the stress in the rod: the hidden part of the ledger.")
        if not still:
            masses = listed([f"{i.particle} (mass {numeral(h.scenario.particle(i.particle).mass)} M)" for i in c])
            sentences.append(f"The impulses of {masses}, taken together, do not cancel: the rod moves off at "
                             f"{in_c(r.velocity(c[-1].rod_rapidity_after, rest))} in S.")
    rapidities = [0.0] + [c[-1].rod_rapidity_after for c in collisions]
    if zigzags(rapidities):
        ups = ["up" if b > a else "down" for a, b in zip(rapidities, rapidities[1:]) if abs(b - a) > SAME_RAPIDITY]
        sentences.append(f"The rod zig-zags: in its own order its velocity goes {', then '.join(ups)}, because it "
                         f"takes the impacts one at a time and each impulse acts alone.")
        motions = []
        for f in r.frames:  # what the material does, turn by turn: a turn cut short never reaches the momentum's velocity
            turns = r.turn_steps(f)
            u = [turns[0][0]] + [after for _, after, _ in turns] if turns else list(r.rod_velocities(f))
            steps = [f"{pushed(before, after)} ({impact_names(cause)})" for before, after, cause in turns
                     if after != before]
            backwards = "" if any(a * b < 0 for a in u for b in u) else ", never moving backwards"
            motions.append(f"in {frame_name(f)} it {listed(steps)}{backwards}")
        text = "; ".join(motions)
        sentences.append(text[0].upper() + text[1:] + ".")
    for k, c in enumerate(collisions):
        for i in c:
            previous = next((p for p in reversed(h.impacts[:h.impacts.index(i)]) if p.particle == i.particle), None)
            if previous is None:
                continue
            # the struck end's own velocity just before the impact (a turn cut short leaves it short of the
            # momentum's velocity)
            sigma = 0.0 if i.end == "left" else h.scenario.L
            u_end = h.material_velocity(sigma, 0.0, i.event.t - ONE_INSTANT * r.scale * 1e3)
            u_end = 0.0 if abs(u_end) <= SAME_RAPIDITY else u_end
            u_particle = r.velocity(i.particle_rapidity_before, rest)
            particle = "stood still" if u_particle == 0.0 else f"moved at {in_c(u_particle)}"
            sentences.append(f"{i.particle} strikes again ({impact_name(i.label)}) because after "
                             f"{impact_names(collisions[k - 1])} the rod's {i.end} end moved at {in_c(u_end)} in S while "
                             f"{i.particle}, since {impact_name(previous.label)}, {particle}: the rod's {i.end} end "
                             f"closed on {i.particle} again.")
    for k, turn in enumerate(t for t in h.turning.turns if not t.completed):
        stopper = impact_name(turn.stopped_by)
        cause = impact_names(r.turn_cause(turn))
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
    if any(not t.completed for t in h.turning.turns):
        ranges = []
        for f in r.frames:
            speeds = [r.velocity(x, f) for x in [0.0, h.final_rapidity]
                      + [y for t in h.turning.turns for y in (t.rapidity_from, t.rapidity_stop)]]
            ranges.append(f"from {in_c(min(speeds))} to {in_c(max(speeds))} in {frame_name(f)}")
        sentences.append("Because its turns are cut short, the rod's material only ever moves at velocities "
                         + listed(ranges) + ".")
    for f in r.frames:
        sentences += _rest_at_full_length(r, f)
    return " ".join(sentences)


def _in_frames(r: Reading, velocities: Sequence[float]) -> str:
    """−0.2425 c in S (+0.4183 c in S′): one velocity per frame shown, the first frame's outside the brackets."""
    text = f"{in_c(velocities[0])} in {frame_name(r.frames[0])}"
    rest = [f"{in_c(u)} in {frame_name(f)}" for u, f in zip(velocities[1:], r.frames[1:])]
    return text + (f" ({'; '.join(rest)})" if rest else "")


def _rest_at_full_length(r: Reading, frame: Frame) -> list[str]:
    """Where the whole rod stands still in the frame after a turn that completes (`Reading.rests`): when, and why."""
    out = []
    time, symbol = time_name(frame), frame_name(frame)
    for turn, end, next_start, next_turn in r.rests(frame):
        cause = impact_names(r.turn_cause(turn))
        if next_start is None and frame.name == "rest":
            out.append(f"In S the rod is at rest again, at its full length L, from t = {in_l(r.length(end))} on, "
                       f"when the turn that {cause} started ends.")
            continue
        if next_start is None:
            span = f"from {time} = {in_l(r.length(end))} on"
            why = f"the turn that {cause} started ends on a line of constant {time}"
        elif r.same_time(next_start, end):
            span = f"at the instant {time} = {in_l(r.length(end))}"
            why = (f"the turn that {cause} started ends there, on a line of constant {time}, and "
                   f"{impact_names(r.turn_cause(next_turn))} starts the next one at that same instant")
        else:
            span = f"from {time} = {in_l(r.length(end))} to {in_l(r.length(next_start))}"
            why = f"the turn that {cause} started ends on a line of constant {time}, and the next begins later"
        out.append(f"In {symbol} the whole rod is at rest {span}, at its full length L: {why}.")
    return out


def explanation(history: RodHistory, frames: Sequence[Frame]) -> tuple[Paragraph, ...]:
    """One to three paragraphs generated from the history: simultaneity and order; the rod's velocity; zig-zags,
    stops at full length and stopped turns, when and why."""
    r = Reading(history, tuple(frames))
    paragraphs = [_simultaneity(r), _velocities(r), _why(r)]
    return tuple(Paragraph(p) for p in paragraphs if p)
