"""A worksheet's questions on frames, with their worked answers: an impact read off two panels, a Lorentz
transformation, the relativistic addition of velocities, and the same scenario at another speed. Pure.

Each question is an `Asked`: its text, its worked answer's paragraphs and the facts it asks for
(`document.Fact`: what the worksheet must not print before its key); the
numbers are computed by the tool, S′ moving at −v relative to S, so
t′ = γ(t + v x) (derived from `Event.seen_from`, never copied from the paper's
appendix, which misprints the sign).
"""

from __future__ import annotations

import math
from typing import NamedTuple, Sequence

from rodparadox.errors import RodParadoxError
from rodparadox.handout.reading import Reading
from rodparadox.handout.document import Fact
from rodparadox.handout.words import (ANSWER_DIGITS, answer_numeral, bracketed, capitalised, impact_names,
                                      in_c, in_c_approx, in_l, in_l_approx, listed, numeral_approx, order_facts,
                                      signed_numeral, simultaneity_facts, told_claim, told_number)
from rodparadox.numbers import MINUS, exact, impact_name
from rodparadox.physics.history import RodHistory
from rodparadox.physics.types import Impact
from rodparadox.physics.models import run_rod as run
from rodparadox.physics.frames import Frame, frame_name, moving_frame, PANEL_LETTERS, relative_velocity, rest_frame
from rodparadox.tables.build import coordinates

#: the speeds a "what if" question tries, in this order, for one that differs meaningfully from the scenario's
#: (by at least OTHER_SPEED_GAP: never 0.8 for v = 0.81) and runs
OTHER_SPEEDS = (0.8, 0.5, 0.9, 0.3)
OTHER_SPEED_GAP = 0.15


class Asked(NamedTuple):
    """A question: its text, its worked answer's paragraphs, and the facts it asks for."""

    text: str
    answer: tuple[str, ...]
    asks: tuple[Fact, ...] = ()


def gamma(w: float) -> float:
    return 1.0 / math.sqrt((1.0 - w) * (1.0 + w))


def momentum(mass: float, u: float) -> float:
    """m u/√(1 − u²), c = 1."""
    return mass * u * gamma(u)


def frame_pair(r: Reading) -> tuple[Frame, Frame]:
    """The two frames the questions compare: the first two shown, or S and the one shown."""
    if len(r.frames) > 1:
        return r.frames[0], r.frames[1]
    only = r.frames[0]
    return (rest_frame(), only) if only.name != "rest" else (only, moving_frame(r.v))


def _relative(a: Frame, b: Frame) -> float:
    """The velocity of frame b relative to frame a (`frames.relative_velocity`)."""
    return relative_velocity(b.velocity, a.velocity)


def lorentz_pair(r: Reading, a: Frame, b: Frame) -> tuple[Impact, ...]:
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


def question_read(r: Reading, a: Frame, b: Frame, avoid: Sequence[Impact]) -> Asked:
    """Read an impact's coordinates off two panels, checked by the interval t² − x², the same in every frame."""
    h = r.history
    i = next((i for i in reversed(h.impacts) if i not in avoid), h.impacts[-1])
    # an impact the Lorentz question gives in frame a is read in frame b alone
    panels = [f for f in ((b,) if i in avoid else (a, b)) if f in r.frames] or list(r.frames[:1])
    lines, checks, asks = [], [], []
    for f in panels:
        x, t = r.length(r.x(i, f)), r.length(r.t(i, f))
        asks += [told_number(f"{impact_name(i.label)}'s {c} in {frame_name(f)}", value)
                 for c, value in zip(coordinates(f), (x, t))]
        xs, ts = coordinates(f)
        letter = PANEL_LETTERS[r.frames.index(f)]
        lines.append(f"In {frame_name(f)} (panel ({letter})): {xs} = {in_l_approx(x)}, {ts} = {in_l_approx(t)}.")
        checks.append(f"in {frame_name(f)} {bracketed(t)}² − {bracketed(x)}² = {numeral_approx(t * t - x * x)}")
    letters = [f"({PANEL_LETTERS[r.frames.index(f)]})" for f in panels]
    where = f"panel {letters[0]}" if len(letters) == 1 else f"panels {listed(letters)}"
    text = (f"Read off the diagram, in {where}, where and when {impact_name(i.label)} happens ({i.particle} striking "
            f"the {i.end} end).")
    if len(panels) == 1:
        return Asked(text, tuple(lines) + ("A careful reading gets these to about a twentieth of L.",), tuple(asks))
    answer = tuple(lines) + (f"A careful reading gets these to about a twentieth of L. The check, in units of L²: "
                             f"{'; '.join(checks)}: the same, as a Lorentz transformation keeps t² − x².",)
    return Asked(text + " Check your readings: t² − x² must be the same in every frame.", answer, tuple(asks))


def question_lorentz(r: Reading, a: Frame, b: Frame, pair: tuple[Impact, ...]) -> Asked:
    """Transform one or two impacts from frame a to frame b: t_b = γ(t_a − w x_a), w the velocity of b relative to a
    (`kinematics.Event.seen_from`: x′ = γ(x − u t), t′ = γ(t − u x) for a frame of velocity u)."""
    w = _relative(a, b)
    g = gamma(w)
    xa, ta = coordinates(a)
    xb, tb = coordinates(b)
    A, B = frame_name(a), frame_name(b)
    sign, W = ("+" if w < 0 else MINUS), answer_numeral(abs(w))
    stated = "; ".join(f"{impact_name(i.label)} strikes at {xa} = {in_l(r.length(r.x(i, a)), ANSWER_DIGITS)}, "
                       f"{ta} = {in_l(r.length(r.t(i, a)), ANSWER_DIGITS)}" for i in pair)
    # a frame shown has its events table to fill in: the question takes the coordinates from it, never gives them
    given = (f"take the {xa} and {ta} of " + " and of ".join(impact_name(i.label) for i in pair)
             + f" from your table of {A}" if a in r.frames else stated)
    steps = ([f"In {A}, {stated}."] if a in r.frames else []) + [
             f"{capitalised(B)} moves at w = {in_c(w, ANSWER_DIGITS)} relative to {A}, so {tb} = γ({ta} − w {xa}) = "
             f"γ({ta} {sign} {W} {xa}) and {xb} = γ({xa} {sign} {W} {ta}), with γ = 1/√(1 − w²) = 1/√(1 − {W}²) = "
             f"{numeral_approx(g)}."]
    times = []
    for i in pair:
        x, t = r.length(r.x(i, a)), r.length(r.t(i, a))
        inner = t - w * x
        times.append(g * inner)
        steps.append(f"{impact_name(i.label)}: {tb} = {answer_numeral(g)} × ({answer_numeral(t)} {sign} {W} × "
                     f"{bracketed(x)}) L = {answer_numeral(g)} × "
                     f"{bracketed(inner) if inner < 0 else answer_numeral(inner)} L = {in_l_approx(g * inner)}.")
    if len(pair) == 1:
        i = pair[0]
        x, t = r.length(r.x(i, a)), r.length(r.t(i, a))
        steps.append(f"And {xb} = {answer_numeral(g)} × ({answer_numeral(x)} {sign} {W} × {bracketed(t)}) L = "
                     f"{in_l_approx(g * (x - w * t))}.")
        asks = (told_number(f"{impact_name(i.label)}'s {tb}", times[0]),
                told_number(f"{impact_name(i.label)}'s {xb}", g * (x - w * t)))
        return Asked(f"In {A}, {given}. {capitalised(B)} moves at {in_c(w, ANSWER_DIGITS)} relative to {A}. Use the "
                     f"Lorentz transformation to find where and when it strikes in {B}.", tuple(steps), asks)
    p, q = pair
    apart_a = abs(r.length(r.t(q, a) - r.t(p, a)))
    same_a = r.same_time(r.t(p, a), r.t(q, a))
    same_b = r.same_time(r.t(p, b), r.t(q, b))
    in_a = f"in {A} they are simultaneous" if same_a else f"in {A} they are {in_l(apart_a, ANSWER_DIGITS)} apart"
    asks = [told_number(f"{impact_name(i.label)}'s {tb}", time) for i, time in zip(pair, times)]
    names = [impact_name(i.label) for i in sorted(pair, key=lambda i: r.t(i, b))]
    asks += simultaneity_facts(*names, B, same_b, abs(times[1] - times[0]))
    if same_b:
        steps.append(f"The two times are equal: {impact_name(p.label)} and {impact_name(q.label)} are simultaneous in "
                     f"{B}, while {in_a}.")
    else:
        earlier, later = (p, q) if times[0] < times[1] else (q, p)
        steps.append(f"The times differ: in {B} {impact_name(later.label)} comes {in_l_approx(abs(times[1] - times[0]))}"
                     f" after {impact_name(earlier.label)}, while {in_a}.")
    text = (f"In {A}, {given}. {capitalised(B)} moves at {in_c(w, ANSWER_DIGITS)} relative to {A}. Use the Lorentz "
            f"transformation to find {tb} of each. Are they simultaneous in {B}?")
    if not same_a and not same_b and (r.t(p, a) - r.t(q, a)) * (r.t(p, b) - r.t(q, b)) < 0:
        text += f" Which comes first in {B}?"
        asks += order_facts(*names, B)
    return Asked(text, tuple(steps), tuple(asks))


def question_velocity(r: Reading, a: Frame, b: Frame) -> Asked:
    """The rod's velocity after a collision (or a particle's, if the rod never changes) in b, by velocity addition."""
    w = _relative(a, b)
    A, B = frame_name(a), frame_name(b)
    candidates = [(f"After {impact_names(c)} the rod moves at "
                    f"{in_c(r.velocity(c[-1].rod_rapidity_after, a), ANSWER_DIGITS)}"
                   f" in {A}.", f"the rod's velocity after {impact_names(c)}", r.velocity(c[-1].rod_rapidity_after, a))
                  for c in r.collisions]
    candidates = [c for c in candidates if c[2] != 0.0]
    if not candidates:  # the rod never changes velocity: ask about a particle
        candidates = [(f"{when.capitalize()} {impact_name(i.label)}, {i.particle} moves at "
                       f"{in_c(r.velocity(rapidity, a), ANSWER_DIGITS)} in {A}.",
                       f"{i.particle}'s velocity {when} {impact_name(i.label)}", r.velocity(rapidity, a))
                      for i in r.history.impacts
                      for when, rapidity in (("before", i.particle_rapidity_before), ("after", i.particle_rapidity_after))]
        candidates = [c for c in candidates if c[2] != 0.0]
    stated, what, u = max(candidates, key=lambda c: abs(relative_velocity(c[2], w)))
    # a frame shown has its events table to fill in: the question takes the velocity from it, never gives it
    given = f"Take {what} in {A} from your table of {A}." if a in r.frames else stated
    result = relative_velocity(u, w)
    answer = ([stated] if a in r.frames else []) + [f"{capitalised(B)} moves at w = {in_c(w, ANSWER_DIGITS)} relative to {A}, so a velocity u in {A} is "
              f"(u − w)/(1 − u w) in {B}.",
              f"({signed_numeral(u, ANSWER_DIGITS)} − ({signed_numeral(w, ANSWER_DIGITS)}))/"
              f"(1 − ({signed_numeral(u, ANSWER_DIGITS)}) × ({signed_numeral(w, ANSWER_DIGITS)})) = "
              f"{bracketed(u - w)}/{bracketed(1 - u * w)} = "
              f"{in_c_approx(result)}{' (at rest)' if result == 0.0 else ''}."]
    if abs(u - w) >= 1.0:
        answer.append(f"Adding velocities as Galileo did would give {in_c(u - w, ANSWER_DIGITS)}, faster than "
                      f"light.")
    asks = (told_number(f"{what} in {B}", result),) + ((told_claim(f"{what} in {B}: at rest", f"at rest in {B}"),)
                                                        if result == 0.0 else ())
    return Asked(f"{given} Use the relativistic addition of velocities to find {what} in {B}.", tuple(answer), asks)


def question_other_speed(r: Reading, a: Frame, b: Frame, compare_v: float | None = None) -> Asked | None:
    """The same scenario at another v, run again: the interval between the rod's first two impacts in both frames
    (or, for one impact, how long the far end takes to follow), and whether the rod ends at rest in S."""
    h = r.history
    s = h.scenario
    other = None
    candidates = (compare_v,) if compare_v is not None else tuple(
        u for u in OTHER_SPEEDS if abs(u - s.v) >= OTHER_SPEED_GAP)
    for v2 in candidates:
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

    asks: list[Fact] = []  # what the run at v2 finds (at v the other questions ask it, or the set-up gives it)

    def facts(history: RodHistory) -> str:
        at = f"at v = {exact(history.scenario.v)}"
        told = len(asks)
        reading = Reading(history, tuple(moving_frame(history.scenario.v) if f.name == "moving" else f
                                          for f in (a, b)))
        found = {i.label: i for i in history.impacts}
        out = []
        if len(labels) == 2 and all(label in found for label in labels):
            p, q = found[labels[0]], found[labels[1]]
            for f in reading.frames:
                gap = reading.length(reading.t(q, f) - reading.t(p, f))
                # the intervals at v2 (the phrases "A₁ and B₁" name this worksheet's impacts at v, not v2's)
                asks.extend(f for f in simultaneity_facts(names[0], names[1], frame_name(f), gap == 0.0, abs(gap))
                            if f.number)
                out.append(f"{names[0]} and {names[1]} are simultaneous in {frame_name(f)}" if gap == 0.0 else
                           f"{names[1]} comes {in_l(abs(gap), ANSWER_DIGITS)} {'after' if gap > 0 else 'before'} "
                           f"{names[0]} in {frame_name(f)}")
        elif len(labels) == 2:
            out.append(f"the rod is struck {len(history.impacts)} times: {impact_names(history.impacts)}")
        elif history.turning.turns:
            start, end = history.turning.turns[0].interval(0.0)
            asks.append(told_number(f"the far end's delay in S {at}", reading.length(end - start)))
            out.append(f"the far end takes {in_l(reading.length(end - start), ANSWER_DIGITS)} of S's time to reach "
                       f"the rod's new velocity")
        final = reading.velocity(history.final_rapidity, rest_frame())
        asks.append(told_claim(f"the rod at rest at the end in S {at}", "ends at rest", "at rest again",
                               "rest before and after", "finally at rest") if final == 0.0 else
                    told_number(f"the rod's final velocity in S {at}", final))
        out.append("the rod ends at rest in S" if final == 0.0 else
                   f"the rod ends moving at {in_c(final, ANSWER_DIGITS)} in S")
        if history is h:
            del asks[told:]
        return "; ".join(out)

    v, v2 = exact(s.v), exact(other.scenario.v)
    following = [p.name for p in s.particles if p.speed is None]
    changes = ("S′ and the speed of " + listed(following) + ", which the scenario takes from v, change with it"
               if following else "S′ changes with it; the particles keep the speeds the scenario gives them")
    if len(labels) == 2:
        asked = (f"How long after {names[0]} does {names[1]} come, in {frame_name(a)} and in {frame_name(b)}? "
                 f"Does the rod end at rest in S?")
    else:
        asked = "How long does the far end of the rod take, in S, to reach the rod's new velocity? How does the rod end?"
    text = f"Now take v = {v2} instead of {v} ({changes}). {asked} Compare with v = {v}."
    answer = (f"At v = {v}: {facts(h)}.", f"At v = {v2}: {facts(other)}.")
    return Asked(text, answer, tuple(asks))
