"""A worksheet's questions on a rod driven by forces, with their worked answers (Sears's own paradox; one end pushed).
Pure.

Two forces: when each starts in the other frame (a Lorentz transformation; which acts first); where the momentum is
on a slice of that frame while they act at different instants (delivered, the rod's kinetic part, its stress); the
centre of energy against p/E. One push: the pushed end's velocity and distance (hyperbolic motion, proper
acceleration F/M), its proper time, and when the push ends in the other frame. Every number is the rigid rod's, read
from its history (`forces_reading.read`), the working written from the closed forms it satisfies.
"""

from __future__ import annotations

import math
from typing import Sequence

from rodparadox.handout.document import Question
from rodparadox.handout.forces_reading import ForcesReading, FrameForces, signed
from rodparadox.handout.words import (ANSWER_DIGITS, answer_numeral, bracketed, capitalised, in_c, in_c_approx, in_l,
                                      in_l_approx, told_claim, told_number)
from rodparadox.handout.worksheet_frames import Asked, gamma
from rodparadox.numbers import MINUS
from rodparadox.physics.frames import frame_name
from rodparadox.tables.build import coordinates


def timed_frame(r: ForcesReading) -> tuple[FrameForces, FrameForces]:
    """(a, b): the frame shown in whose time the forces are given (else the first), and another frame shown."""
    profiles = dict(r.history.driving.profiles())
    timed = next(iter(profiles.values())).frame
    a = next((f for f in r.frames if f.frame.name == timed), r.frames[0])
    b = next(f for f in r.frames if f is not a)
    return a, b


def _w(a: FrameForces, b: FrameForces) -> float:
    """The velocity of frame b relative to frame a."""
    return math.tanh(b.frame.rapidity - a.frame.rapidity)


def question_starts(r: ForcesReading, a: FrameForces, b: FrameForces) -> Asked:
    """Where each force starts in a (given), when in b (Lorentz); at one instant of b? Which first? (One force: when
    it starts in b.)"""
    w = _w(a, b)
    g = gamma(w)
    xa, ta = coordinates(a.frame)
    _, tb = coordinates(b.frame)
    A, B = frame_name(a.frame), frame_name(b.frame)
    sign, W = ("+" if w < 0 else MINUS), answer_numeral(abs(w))
    starts = [a.when(end, "start") for end in a.ends]
    stated = "; ".join(f"the {m.end} force starts at {xa} = {in_l(m.x, ANSWER_DIGITS)}, {ta} = "
                       f"{in_l(m.t, ANSWER_DIGITS)}" for m in starts)
    steps = [f"{capitalised(B)} moves at w = {in_c(w, ANSWER_DIGITS)} relative to {A}, so {tb} = γ({ta} − w {xa}) "
             f"= γ({ta} {sign} {W} {xa}), with γ = 1/√(1 − {W}²) = {answer_numeral(g)}."]
    times = []
    for m in starts:
        inner = m.t - w * m.x
        times.append(g * inner)
        steps.append(f"The {m.end} force: {tb} = {answer_numeral(g)} × ({answer_numeral(m.t)} {sign} {W} × "
                     f"{bracketed(m.x)}) L = {in_l_approx(g * inner)}.")
    asks = [told_number(f"the {m.end} force's start in {B}", t) for m, t in zip(starts, times)]
    if len(starts) == 1:
        return Asked(f"In {A}, {stated}. {capitalised(B)} moves at {in_c(w, ANSWER_DIGITS)} relative to {A}. Use the "
                     f"Lorentz transformation to find when it starts in {B}.", tuple(steps), tuple(asks))
    gap = abs(times[1] - times[0])
    if gap <= 1e-9 * (1.0 + abs(times[0])):
        steps.append(f"So in {B} the two forces start at the same instant.")
        asks.append(told_claim(f"the forces start together in {B}", "start at the same instant"))
    else:
        first = "left" if times[0] < times[1] else "right"
        other = "right" if first == "left" else "left"
        together = a.together("start")
        steps.append(f"So in {B} the {first} force starts first, {in_l_approx(gap)} before the {other} one"
                     + (f", though in {A} they start together: the forces that balance at every instant of {A} act "
                        f"at different instants of {B}." if together else "."))
        asks += [told_number(f"the gap between the starts in {B}", gap),
                 told_claim(f"the {first} force first in {B}", f"the {first} force starts first",
                            f"{first} force acts from", f"the {first} force acts first")]
    return Asked(f"In {A}, {stated}. {capitalised(B)} moves at {in_c(w, ANSWER_DIGITS)} relative to {A}. Use the "
                 f"Lorentz transformation to find {tb} of each start. Do the forces start at the same instant of "
                 f"{B}? If not, which starts first, and how much earlier?", tuple(steps), tuple(asks))


def question_momentum(r: ForcesReading, a: FrameForces, b: FrameForces) -> Asked:
    """At b's key slice: the momentum the agents delivered in b, the rod's kinetic part, the stress part."""
    k = b.key
    tb = coordinates(b.frame)[1]
    A, B = frame_name(a.frame), frame_name(b.frame)
    w = _w(a, b)
    u = a.initial.p / a.initial.E
    g = gamma(w)
    steps = [
        f"In {A} the forces are equal and opposite at every instant, so nothing changes there: the rod keeps its "
        f"velocity {in_c(u) if abs(u) > 1e-12 else '0'} in {A}, and each agent pushes an end moving at that velocity. "
        f"An agent delivers momentum F d{coordinates(a.frame)[1]} in {A} (the area under its force) and energy "
        f"{'none' if abs(u) < 1e-12 else 'u times that'}; in {B} its momentum is γ(p − w E) = γ(1 − w u) p with "
        f"γ = {answer_numeral(g)}.",
        f"The slice {tb} = {in_l(k.t, ANSWER_DIGITS)} meets each end at its own instant of {A}; by then the left agent "
        f"has delivered {signed(k.left.p, ANSWER_DIGITS)} M c in {B}, the right {signed(k.right.p, ANSWER_DIGITS)} "
        f"M c: together {signed(k.delivered, ANSWER_DIGITS)} M c.",
        f"The rod's points all still move at its velocity before the forces, so its kinetic part is still "
        f"{signed(k.moving.p, ANSWER_DIGITS)} M c, its momentum before them. The momentum delivered is in the stress "
        f"of the rod: {signed(k.stress.p, ANSWER_DIGITS)} M c (von Laue: a stressed body that moves carries momentum "
        f"that no motion of its matter shows). When both forces have ended, the agents' momenta cancel and the "
        f"stress, and its momentum, are gone."]
    asks = (told_number(f"the momentum delivered by {tb} = {k.t}", k.delivered),
            told_number(f"the stress momentum at {tb} = {k.t}", k.stress.p),
            told_number(f"the left agent's momentum at {tb} = {k.t}", k.left.p),
            told_number(f"the right agent's momentum at {tb} = {k.t}", k.right.p),
            told_claim("the momentum is in the stress", "is in the stress", "in the stress of the rod"))
    return Asked(f"Yet the rigid rod's velocity is the same after both forces as before them, in every frame. At "
                 f"{tb} = {in_l(k.t, ANSWER_DIGITS)} in {B}: how much momentum have the two agents delivered, "
                 f"together, in {B}? How much of it is in the rod's motion (its kinetic part)? Where is the rest?",
                 tuple(steps), asks)


def question_balanced_moves(r: ForcesReading, a: FrameForces) -> Asked:
    """Forces balanced at every instant of a frame that is not the rod's rest frame: the rigid rod still moves."""
    A, ta = frame_name(a.frame), coordinates(a.frame)[1]
    k = max(a.slices, key=lambda x: abs(x.moving.p - a.initial.p))
    steps = [f"Yes. A rigid rod obeys the forces on its own lines of simultaneity, those of the frame it rests in "
             f"(S before the forces), not those of {A}: the forces that are equal at every instant of {A} are not "
             f"equal at every instant of the rod's own time, so the rod turns and moves while they act.",
             f"At {ta} = {in_l(k.t, ANSWER_DIGITS)} its kinetic part is {signed(k.moving.p, ANSWER_DIGITS)} M c, "
             f"against {signed(a.initial.p, ANSWER_DIGITS)} M c before the forces, and its stress holds the rest, "
             f"{signed(k.stress.p, ANSWER_DIGITS)} M c: together what it held before, since in {A} the two agents "
             f"have delivered equal and opposite momenta by every instant. After both forces it moves as before."]
    return Asked(f"In {A} the two forces are equal and opposite at every instant. Does the rigid rod's velocity "
                 f"change while they act? Explain with the rod's own lines of simultaneity.", tuple(steps),
                 (told_number(f"the kinetic part at {ta} = {k.t}", k.moving.p),
                  told_number(f"the stress part at {ta} = {k.t}", k.stress.p),
                  told_claim("the rod moves though balanced", "Yet the rod moves", "the rod turns and moves")))


def question_centre(r: ForcesReading, b: FrameForces) -> Asked:
    k = b.key
    tb = coordinates(b.frame)[1]
    B = frame_name(b.frame)
    steps = [f"At {tb} = {in_l(k.t, ANSWER_DIGITS)} in {B} the rod's centre of energy moves at "
             f"{in_c(k.v_E, ANSWER_DIGITS)} while p/E = {in_c(k.p_over_E, ANSWER_DIGITS)}.",
             "For a closed system the centre of energy moves at p/E: the energy flows where the momentum points. "
             "Here the agents feed energy in and out at the two ends, at different rates at each instant of "
             f"{B}, and the stress carries momentum that no flow of energy along the rod shows: for a closed "
             "system they would be equal; with forces at its ends they are not."]
    return Asked(f"While the forces act, does the rod's centre of energy in {B} move at p/E (its total momentum over "
                 f"its total energy)? When must the two agree?", tuple(steps),
                 (told_number(f"v_E at {tb} = {k.t}", k.v_E), told_number(f"p/E at {tb} = {k.t}", k.p_over_E),
                  told_claim("closed system", "for a closed system they would be equal")))


def push_questions(r: ForcesReading, a: FrameForces, b: FrameForces) -> list[Asked]:
    """One push on the rigid rod: hyperbolic motion (velocity, distance), proper time, the end of the push in b."""
    driving = r.history.driving
    (end, profile), = driving.profiles()
    events = {e.moment: e for e in driving.force_events() if e.end == end}
    start, stop = events["start"], events["end"]
    F = start.force  # units of M c²/L
    L = r.history.scenario.L
    dt = (stop.event.t - start.event.t) / L
    a_ = abs(F)  # the proper acceleration's size |F|/M, units of c²/L (M = 1, F in M c²/L)
    u = math.tanh(stop.rapidity)
    dx = abs(stop.event.x - start.event.x) / L
    tau = stop.rapidity / a_
    kind, does = ("push", "pushes") if F > 0 else ("pull", "pulls")
    first = Asked(
        f"The agent {does} the {end} end with a constant force F = {answer_numeral(F)} M c²/L, from t = "
        f"{in_l(start.event.t / L)} to t = {in_l(stop.event.t / L)} in S. A rigid rod's end driven so, with nothing "
        f"at the other end, has a proper acceleration of size |F|/M. How fast does that end move in S when the "
        f"{kind} ends, and how far has it gone?",
        (f"Constant proper acceleration a = |F|/M = {answer_numeral(a_)} c²/L from rest is hyperbolic motion: the "
         f"velocity after a time Δt of S is u = aΔt/√(1 + (aΔt)²), the distance (√(1 + (aΔt)²) − 1)/a.",
         f"With Δt = {in_l(dt)}: aΔt = {answer_numeral(a_ * dt)}, so u = {in_c_approx(u)} and the end has gone "
         f"{in_l_approx(dx)}."),
        (told_number("the pushed end's velocity when the push ends, in S", u),
         told_number("the pushed end's distance", dx)))
    second = Asked(
        f"How long does the {kind} last in the driven end's own time (its proper time)?",
        (f"On the hyperbola the rapidity grows as aτ, and sinh(aτ) = aΔt: τ = asinh(aΔt)/a = "
         f"asinh({answer_numeral(a_ * dt)})/{answer_numeral(a_)} L = {in_l_approx(tau)}, less than the "
         f"{in_l(dt)} of S.",),
        (told_number("the push's proper duration", tau),))
    b = next(f for f in r.frames if f.frame.name != "rest")  # the events above are S's
    w = math.tanh(b.frame.rapidity)
    g = gamma(w)
    tb = coordinates(b.frame)[1]
    B = frame_name(b.frame)
    t_end = g * (stop.event.t - w * stop.event.x) / L
    third = Asked(
        f"When does the {kind} end in {B}, which moves at {in_c(w, ANSWER_DIGITS)} relative to S?",
        (f"The {kind} ends at the event x = {in_l(stop.event.x / L, ANSWER_DIGITS)}, t = "
         f"{in_l(stop.event.t / L, ANSWER_DIGITS)} of S (found above). {tb} = γ(t − w x) with γ = "
         f"{answer_numeral(g)}: {tb} = {in_l_approx(t_end)}.",),
        (told_number(f"the push's end in {B}", t_end),))
    return [first, second, third]


def force_questions(r: ForcesReading, chosen: Sequence[int] | None = None) -> tuple[Question, ...]:
    """The questions on the rigid rod's reading `r`, numbered from 1 (`chosen`: the teacher's choice)."""
    a, b = timed_frame(r)
    profiles = dict(r.history.driving.profiles())
    if len(r.areas) == 2:
        asked = [question_starts(r, a, b)]
        balanced = a.together("start") and a.together("end") and abs(r.areas[0][1] - r.areas[1][1]) < 1e-12
        if balanced and abs(b.key.stress.p) > 1e-9 and abs(b.key.moving.p - b.initial.p) < 1e-9:
            asked.append(question_momentum(r, a, b))  # Sears's question: the rod's motion unchanged, yet ...
        elif balanced and any(abs(x.moving.p - a.initial.p) > 1e-6 for x in a.slices):
            asked.append(question_balanced_moves(r, a))  # balanced in S′, not in the rod's own time
        if abs(b.key.v_E - b.key.p_over_E) > 1e-6:
            asked.append(question_centre(r, b))
    elif next(iter(profiles.values())).shape == "step":  # one constant force: hyperbolic motion
        asked = push_questions(r, a, b)
    else:
        asked = [question_starts(r, a, b)] + ([question_centre(r, b)] if abs(b.key.v_E - b.key.p_over_E) > 1e-6
                                              else [])
    if chosen is not None:
        asked = [asked[k - 1] for k in chosen if 1 <= k <= len(asked)]
    return tuple(Question(k + 1, q.text, q.answer, q.asks) for k, q in enumerate(asked))
