"""A worksheet's questions on the causal rod beside the rigid one, with their worked answers (the docs, "The causal
rod"): when the far end moves, where the energy went (the ringing rod's rest mass), and the stress momentum on a
slice. Pure; each returns an `Asked` (`worksheet_frames`) from a `causal_reading.Comparison`.
"""

from __future__ import annotations

import math
from typing import Sequence

from rodparadox.handout.causal_reading import Comparison
from rodparadox.handout.document import Question
from rodparadox.handout.words import (ANSWER_DIGITS, answer_numeral, bracketed, in_c, in_l, listed, signed_numeral,
                                      summand, time_name, told_claim, told_number)
from rodparadox.handout.worksheet_frames import Asked, gamma
from rodparadox.numbers import impact_name
from rodparadox.physics.frames import frame_name


def _zero(x: float, scale: float = 1.0) -> float:
    return 0.0 if abs(x) <= 1e-12 * max(1.0, abs(scale)) else x


def question_far_end(c: Comparison, tabled: bool = True) -> Asked:
    """When light from the first contact reaches the far end, and when each model moves that end; `tabled`: the
    worksheet's events table of S asks the contact's time (the rigid rod's first impact, the same event), so the
    question points to it rather than give it."""
    f = c.far_end
    C = impact_name(f.contact.label)
    when = (f"at the time t your table of S gives for {C}" if tabled else f"at t = {in_l(f.t_contact, ANSWER_DIGITS)}")
    start = f"{C} strikes the {f.contact.end} end of the rod, at rest in S, {when}."
    light = (f"Light from {C} crosses the rod\u2019s length L, at rest in S, in a time L: it reaches the {f.far} end at "
             f"t = {in_l(f.t_contact, ANSWER_DIGITS)} + L = {in_l(f.t_light, ANSWER_DIGITS)}.")
    rigid = (f" The rigid rod\u2019s {f.far} end starts to move at t = {in_l(f.t_rigid, ANSWER_DIGITS)}, at {C}\u2019s "
             f"instant of S, on the rod\u2019s turned line of simultaneity: before light could reach it."
             if f.t_rigid is not None else "")
    asks = [told_number(f"when light from {C} reaches the {f.far} end", f.t_light)]
    if f.by_light:
        th = f.rapidity_struck  # signed: negative where the struck end is pushed left
        text = (f"{start} When does light from {C} reach the {f.far} end? When does the {f.far} end of the rigid rod "
                f"start to move, and when that of the causal rod, whose sound travels at c? The compression front "
                f"comes back from the free {f.far} end as tension, so that end\u2019s rapidity jumps to twice the struck "
                f"end\u2019s: how fast does it start?")
        answer = (f"{C} strikes at t = {in_l(f.t_contact, ANSWER_DIGITS)}. " + light + rigid,
                  f"The causal rod\u2019s {f.far} end feels nothing until the front, at speed c, arrives: it starts at "
                  f"t = {in_l(f.t_causal, ANSWER_DIGITS)}, exactly when light does.",
                  f"The struck end takes {f.contact.particle}\u2019s velocity at once, u = "
                  f"{in_c(math.tanh(th), ANSWER_DIGITS)} in S, rapidity θ₀ = artanh u = "
                  f"{signed_numeral(th, ANSWER_DIGITS)}; the far end starts at rapidity 2θ₀ = "
                  f"{signed_numeral(2 * th, ANSWER_DIGITS)}, velocity tanh 2θ₀ = {in_c(f.u_causal, ANSWER_DIGITS)} "
                  f"(= 2u/(1 + u²)).")
        asks += [told_number(f"the causal far end's starting velocity", f.u_causal)]
        return Asked(text, answer, tuple(asks))
    D = impact_name(f.own.label)
    same = abs(f.own.event.t / c.L - f.t_contact) <= 1e-12 * (1.0 + abs(f.t_contact))
    # at C's instant the far end has not moved in either model: D is the rigid rod's impact too, whose time the
    # table of S asks (that it is C's instant fills that blank cell), so the question points to the table
    at = (f"at the time your table of S gives for {D}" if same and tabled else "at the same instant of S" if same
          else f"at t = {in_l(f.own.event.t / c.L, ANSWER_DIGITS)}")
    text = (f"{start} {D} strikes the {f.far} end {at}. When "
            f"does light from {C} reach the {f.far} end? What sets the causal rod\u2019s {f.far} end moving, and when "
            f"does the rigid rod\u2019s {f.far} end start to move?")
    if not rigid:  # no turn from rest about C: the rigid rod's far end moves with D, or never
        rigid = (f" The rigid rod\u2019s {f.far} end never moves in S: {C} and {D}"
                 f"{', at one instant of S,' if same else ''} together leave the rigid rod at rest."
                 if f.t_rigid_moves is None else
                 f" The rigid rod\u2019s {f.far} end starts to move at t = {in_l(f.t_rigid_moves, ANSWER_DIGITS)}.")
    answer = (f"{C} strikes at t = {in_l(f.t_contact, ANSWER_DIGITS)}. " + light + rigid,
              f"{D} strikes the {f.far} end before light from {C} reaches it, so in the causal rod, where no push "
              f"travels faster than light, the {f.far} end is set moving by {D} itself, and the fronts from {C} and "
              f"{D} cross inside the rod.")
    asks.append(told_claim(f"{D} sets the causal far end moving", f"set moving by {D} itself"))
    return Asked(text, answer, tuple(asks))


def question_ringing(c: Comparison) -> Asked:
    """The causal rod's energy, momentum, rest mass and velocity after the last separation, from conservation."""
    r = c.ringing
    leaving = [(p.particle, c.particles[p.particle][0], p.causal["rest"]) for p in c.leaving]
    steps = ["A body of mass m moving at u has E = m/√(1 − u²) and p = m u/√(1 − u²) (c = 1)."]
    E0 = 1.0 + sum(m * gamma(u) for m, u in c.particles.values())
    p0 = sum(m * u * gamma(u) for m, u in c.particles.values())
    E_out = sum(m * gamma(u) for _, m, u in leaving)
    p_out = sum(m * u * gamma(u) for _, m, u in leaving)
    E, p = E0 - E_out, _zero(p0 - p_out, E0)
    mass = math.sqrt((E - p) * (E + p))
    u = _zero(p / E)
    steps += [f"Before the first impact, in S: E = {answer_numeral(E0)} M c², p = {answer_numeral(_zero(p0, E0))} M c "
              f"(the rod at rest, M, and the particles at their first velocities).",
              f"After the last separation the particles carry E = {answer_numeral(E_out)} M c², p = "
              f"{answer_numeral(_zero(p_out, E0))} M c, so the rod carries E = {answer_numeral(E0)} − "
              f"{summand(E_out)} = {answer_numeral(E)} M c² and p = {answer_numeral(p)} M c.",
              f"Its rest mass: √(E² − p²) = √({bracketed(E)}² − {bracketed(p)}²) = {answer_numeral(mass)} M; its centre "
              f"moves at p/E = {in_c(u, ANSWER_DIGITS)}.",
              f"It is more than M by {answer_numeral(mass - 1.0)} M: the rod rings for ever after the particles leave, "
              f"and the energy of its vibration counts in its rest mass. The same follows from the ringing "
              f"itself: every material point advances by (Δt, Δx) = ({in_l(r.dt, ANSWER_DIGITS)}, "
              f"{in_l(_zero(r.dx, r.dt), ANSWER_DIGITS)}) per period, and (M/2L)(Δt, Δx) = ({answer_numeral(r.E)} M c², "
              f"{answer_numeral(_zero(r.p, r.E))} M c)."]
    given = listed([f"{n} at {in_c(u, ANSWER_DIGITS)}" for n, _, u in leaving])
    text = (f"After the last separation from the causal rod the particles move in S: {given}. From the conservation "
            f"of energy and momentum in S, find the causal rod\u2019s energy and momentum, its rest mass and the "
            f"velocity of its centre. Why is its rest mass not M?")
    asks = [told_number("the causal rod's rest mass after the last separation", mass),
            told_number("the causal rod's internal energy", mass - 1.0),
            told_number("the causal rod's energy after the last separation", E)]
    if u != 0.0:
        asks.append(told_number("the causal rod's velocity after the last separation", u))
    return Asked(text, tuple(steps), tuple(asks))


def question_stress(c: Comparison) -> Asked:
    """Like with like: the causal rod's momentum beyond its material points' motion on a slice (the total less the
    particles' and (M/L)∫ sinh ψ dσ), against the rigid rod's hidden momentum on the same slice."""
    s = c.stress
    symbol, time = frame_name(s.frame), time_name(s.frame)
    scale = s.total.E
    particles = [(n, _zero(em.p, scale)) for n, em in s.particles]
    motion, hidden = _zero(s.motion[1], scale), _zero(s.hidden.p, scale)
    unshown = _zero(s.total.p - sum(q for _, q in particles) - motion, scale)
    slice_name = f"{time} = {in_l(s.t, ANSWER_DIGITS)} of {symbol}"
    text = (f"On the slice {slice_name} the particles carry momentum "
            f"{listed([f'{answer_numeral(q)} M c ({n})' for n, q in particles])}, and the causal rod\u2019s material "
            f"points, each its share of M moving at its own velocity, (M/L)∫ sinh ψ dσ = {answer_numeral(motion)} M c. "
            f"From the bodies\u2019 total momentum in {symbol} before the first impact (the set-up), how much momentum "
            f"does the causal rod carry on this slice beyond its material points\u2019 motion, and what carries it? "
            f"Is it the same as the rigid rod\u2019s hidden momentum on this slice?")
    terms = [q for _, q in particles] + [motion]
    answer = (f"Before the first impact the bodies\u2019 momentum in {symbol} is {answer_numeral(s.total.p)} M c, and "
              f"it is conserved.",
              f"Beyond its material points\u2019 motion the causal rod carries {answer_numeral(s.total.p)} − "
              f"({' + '.join(summand(q) for q in terms)}) = {answer_numeral(unshown)} M c: the momentum of its "
              f"stress, where the fronts have compressed it (p(uu − η) in its stress-energy), real and local.",
              f"The rigid rod\u2019s hidden momentum on this slice, made the same way (the total less every body\u2019s "
              f"motion), is {answer_numeral(hidden)} M c: not the same. The rigid rod\u2019s stress takes an impulse "
              f"across the whole rod at once, the causal rod\u2019s only as far as the fronts have come.")
    asks = [told_number(f"the causal rod's momentum beyond its material points' motion on {slice_name}", unshown),
            told_number(f"the bodies' total momentum in {symbol}", s.total.p)]
    if hidden != 0.0:
        asks.append(told_number(f"the rigid rod's hidden momentum on {slice_name}", hidden))
    return Asked(text, answer, tuple(asks))


def causal_questions(c: Comparison, first: int, tabled: bool = True) -> tuple[Question, ...]:
    """The comparison's questions, numbered from `first` (after the rigid rod's); `tabled`: the worksheet has an
    events table of S to fill in."""
    asked: Sequence[Asked] = (question_far_end(c, tabled), question_ringing(c), question_stress(c))
    return tuple(Question(first + k, q.text, q.answer, q.asks) for k, q in enumerate(asked))
