"""A worksheet's questions on what the rod does, asked where the scenario shows it, with their worked answers:
the momentum hidden in the rod's stress on a slice, a turn stopped by an impact, the whole rod at rest in a moving
frame, the far end following a single impact, momentum conserved in a collision, impacts taken together, and a
zig-zag. Pure; each returns an `Asked` (`worksheet_frames`), or None where the scenario has nothing to ask.
"""

from __future__ import annotations

import math

from rodparadox.handout.reading import Reading, zigzags
from rodparadox.handout.words import (ANSWER_DIGITS, answer_numeral, bracketed, impact_names, in_c, in_l,
                                      in_l_approx, listed, numeral_approx, pushed, summand, time_name, told_claim,
                                      told_number)
from rodparadox.handout.worksheet_frames import Asked, gamma, momentum
from rodparadox.physics.types import Impact
from rodparadox.physics.frames import Frame, frame_name, rest_frame
from rodparadox.physics.rod import rod_slice
from rodparadox.tables import build as tables
from rodparadox.numbers import impact_name
from rodparadox.tolerances import PRINTED_ZERO, SAME_RAPIDITY

#: the rod's material points sampled to tell whether it moves as a whole on a slice (not turning there)
WHOLE_ROD_POINTS = 9


def _whole_rod(r: Reading, frame: Frame, t: float) -> bool:
    """Whether every material point of the rod has one velocity on the slice t of the frame (no turn crosses it)."""
    sigmas = [k * r.L / (WHOLE_ROD_POINTS - 1) for k in range(WHOLE_ROD_POINTS)]
    rapidities = rod_slice(r.history, frame.rapidity, t, sigmas).rapidity
    return float(max(rapidities) - min(rapidities)) <= SAME_RAPIDITY


def _between(r: Reading, frame: Frame, t: float) -> str:
    """after A₁ and before B₁; before B₁; after B₂, the last impact."""
    impacts = [i for _, g in r.instants(frame) for i in g]
    before = [i for i in impacts if r.t(i, frame) < t]
    after = [i for i in impacts if r.t(i, frame) > t]
    if before and after:
        return f"after {impact_name(before[-1].label)} and before {impact_name(after[0].label)}"
    if after:
        return f"before {impact_name(after[0].label)}, the first impact in {frame_name(frame)}"
    return f"after {impact_name(before[-1].label)}, the last impact in {frame_name(frame)}"


def question_hidden(r: Reading, a: Frame, b: Frame) -> Asked | None:
    """The hidden momentum on a slice between two changes: total before the first impact less every body's kinetic
    momentum on the slice. A slice where the rod moves as a whole is preferred (the student can compute the rod's
    momentum), then the largest hidden momentum; frame b first."""
    h = r.history
    chosen = None
    for f in [b, a] + [f for f in r.frames if f not in (a, b)]:
        total = h.initial_total(f.rapidity)
        zero = PRINTED_ZERO * max(total.E, abs(total.p))  # a difference of totals below this is rounding
        for t in tables.hidden_instants(h, f):
            hidden = h.energy_momentum(f.rapidity, t).hidden
            if abs(hidden.p) > zero:
                key = (not _whole_rod(r, f, t), -abs(hidden.p))
                if chosen is None or key < chosen[0]:
                    chosen = (key, f, t)
        if chosen is not None:
            break
    if chosen is None:
        return None
    _, f, t = chosen
    s = h.energy_momentum(f.rapidity, t)
    total = h.initial_total(f.rapidity)
    zero = PRINTED_ZERO * max(total.E, abs(total.p))
    symbol, time = frame_name(f), time_name(f)
    whole = _whole_rod(r, f, t)
    bodies = dict(s.bodies)
    steps = ["A body of mass m moving at u has momentum m u/√(1 − u²) (c = 1)."]
    known, terms = [], []
    for name in ("A", "B"):
        if name not in bodies:
            continue
        m = h.scenario.particle(name).mass
        u = r.velocity(h.worldline(name).seen_from(f.rapidity).rapidity_at_time(t) + f.rapidity, f)
        known.append(f"{name} moves at {in_c(u, ANSWER_DIGITS)}")
        p = 0.0 if abs(bodies[name].p) <= zero else bodies[name].p
        steps.append(f"{name}: {answer_numeral(m)} × {bracketed(u)}/√(1 − {bracketed(u)}²) = "
                     f"{answer_numeral(p)} M c.")
        terms.append(p)
    rod_p = 0.0 if abs(bodies["rod"].p) <= zero else bodies["rod"].p
    if whole:
        u = math.tanh(rod_slice(h, f.rapidity, t, [0.5 * r.L]).rapidity[0])
        known.append(f"the rod moves as a whole at {in_c(u, ANSWER_DIGITS)}")
        steps.append(f"The rod: 1 × {bracketed(u)}/√(1 − {bracketed(u)}²) = {answer_numeral(rod_p)} M c.")
    else:
        known.append(f"the rod is turning, its material points moving at different velocities: their momenta "
                     f"(each point's share of M at its own velocity) add up to {answer_numeral(rod_p)} M c")
        steps.append(f"The rod: {answer_numeral(rod_p)} M c, as given.")
    terms.append(rod_p)
    kinetic = sum(terms)
    hidden = total.p - kinetic
    steps.append(f"All the bodies' momentum on the slice: {' + '.join(summand(q) for q in terms)} = "
                 f"{answer_numeral(kinetic)} M c. Hidden: {answer_numeral(total.p)} − {summand(kinetic)} = "
                 f"{numeral_approx(hidden)} M c.")
    where = ("this slice of " + symbol + " cuts across a turn, the rod's rigid response to an impact, so part of the "
             "impulse already given sits in the stress and has not yet reached the motion of the rod's material "
             "points" if not whole else
             "this slice of " + symbol + " falls between two impacts the rod takes together on its own line of "
             "simultaneity: the impulse of the first sits in the stress until the second arrives")
    steps.append(f"It is carried by the stress in the rod: {where}. (The hidden energy on the slice is "
                 f"{numeral_approx(s.hidden.E)} M c².)")
    # where the slice lies among the impacts is the answer's (it tells the order of the impacts in the frame), and
    # the total is the student's to find (given, it may be a number another question asks: γ v for one particle)
    steps[:0] = [f"The slice lies {_between(r, f, t)}. Before the first impact the bodies' total momentum in "
                 f"{symbol}, m u/√(1 − u²) summed over the rod and the particles at their first velocities, is "
                 f"{answer_numeral(total.p)} M c, and it is conserved."]
    if f in r.frames:  # a frame shown has its events table to fill in: the velocities are taken from it
        turning = [k for k in known if k.startswith("the rod is turning")]
        given = (f"take {'each body' if whole else 'each particle'}\u2019s velocity on it from your table of {symbol}"
                 + "".join(f"; {k}" for k in turning))
        steps.insert(1, f"On the slice: {listed(known)}.")
    else:
        given = listed(known)
    text = (f"On the slice {time} = {in_l(r.length(t), ANSWER_DIGITS)} of {symbol}, {given}. Find the bodies' "
            f"total momentum in {symbol} before the first impact, from the set-up. How much momentum does no body's "
            f"motion carry on this slice (the momentum Sears called hidden), and where is it?")
    asks = (told_number(f"the hidden momentum on the slice {time} = {in_l(r.length(t))} of {symbol}", hidden),
            told_number(f"the bodies' total momentum in {symbol}", total.p))
    return Asked(text, tuple(steps), asks)


def question_stopped_turn(r: Reading) -> Asked | None:
    """A turn stopped by an impact: the far end's velocity there, from the two events, against the rod's."""
    h = r.history
    turn = next((t for t in h.turning.turns if not t.completed), None)
    if turn is None:
        return None
    stopper = next(i for i in h.impacts if i.label == turn.stopped_by)
    cause = r.turn_cause(turn)
    far = "left" if turn.pivot_end == "right" else "right"
    P, E = turn.pivot, stopper.event
    at_pivot = [i for i in cause if i in r.impacts_at(P)] or r.impacts_at(P)
    dx, dt = r.length(E.x - P.x), r.length(E.t - P.t)
    u_far = dt / dx  # on the hyperbola (x − x₀)² − (t − t₀)² = L² the velocity is (t − t₀)/(x − x₀)
    u_rod = r.velocity(turn.rapidity_to, rest_frame())
    S, name, stop = "S", impact_names(cause), impact_name(stopper.label)
    text = (f"{stop} strikes the {far} end while the rod is still turning from {name}. How fast is the {far} end "
            f"moving in S at that instant, and how does that compare with the rod's velocity after {name}? (During a "
            f"turn about the event P = (x₀, t₀) the far end moves on the hyperbola (x − x₀)² − (t − t₀)² = L², "
            f"whose velocity at (x, t) is (t − t₀)/(x − x₀).)")
    answer = (f"P is {impact_names(at_pivot)}, at x = {in_l(r.length(P.x), ANSWER_DIGITS)}, "
              f"t = {in_l(r.length(P.t), ANSWER_DIGITS)}; "
              f"{stop} is at x = {in_l(r.length(E.x), ANSWER_DIGITS)}, t = {in_l(r.length(E.t), ANSWER_DIGITS)}.",
              f"{stop} is on the hyperbola: {bracketed(dx)}² − {bracketed(dt)}² = "
              f"{answer_numeral(dx * dx - dt * dt)} (in L²).",
              f"The {far} end's velocity there: {answer_numeral(dt)}/{bracketed(dx)} = "
              f"{in_c(u_far, ANSWER_DIGITS)} in {S}, "
              f"while the rod's momentum moves at {in_c(u_rod, ANSWER_DIGITS)} after {name}: the {far} end had "
              f"not caught up when {stop} struck, so the rod never moved as a whole at "
              f"{in_c(u_rod, ANSWER_DIGITS)}.")
    asks = (told_number(f"the {far} end's velocity in S at {stop}", u_far),
            told_number(f"the rod's velocity in S after {name}", u_rod),
            told_claim(f"the {far} end had not caught up at {stop}", "not caught up", "never moved as a whole"))
    return Asked(text, answer, asks)


def question_at_rest(r: Reading) -> Asked | None:
    """A moving frame in which the whole rod stands still for an instant or a while: when, and how long it is."""
    for f in (f for f in r.frames if f.name != "rest"):
        rests = r.rests(f)
        if not rests:
            continue
        turn, end, next_start, _ = rests[0]
        symbol, time = frame_name(f), time_name(f)
        u0 = r.rod_velocities(f)[0]
        if next_start is None:
            when = f"from {time} = {in_l_approx(r.length(end))} on"
        elif r.same_time(next_start, end):
            when = f"at the one instant {time} = {in_l_approx(r.length(end))}"
        else:
            when = f"from {time} = {in_l_approx(r.length(end))} to {in_l_approx(r.length(next_start))}"
        # asked, not told: that the rod stops in S′ is a blank cell of its table (the rod's velocity after B₁)
        text = (f"Is the whole rod ever at rest in {symbol}, every point of it at once? If so, when, and how long is "
                f"it then, measured in {symbol}? How long is it in {symbol} before it is first struck?")
        answer = (f"It is at rest {when}: the turn that {impact_names(r.turn_cause(turn))} started ends on a line of "
                  f"constant {time}, so every point of the rod reaches velocity 0 in {symbol} at once.",
                  f"At rest in {symbol}, it has its full proper length L there. Before it is struck it moves at "
                  f"{in_c(u0, ANSWER_DIGITS)} in {symbol}, contracted to L √(1 − u²) = L √(1 − {bracketed(u0)}²) "
                  f"= {in_l_approx(1.0 / gamma(u0))}.")
        asks = (told_claim(f"the whole rod at rest in {symbol}", f"comes to rest in {symbol}",
                           f"at rest in {symbol}", f"stops in {symbol}"),
                told_number(f"when the rod comes to rest in {symbol}", r.length(end)),
                told_claim(f"the rod at rest in {symbol} has its full length", "full length", "proper length L there"),
                told_number(f"the rod's length in {symbol} before it is struck", 1.0 / gamma(u0)))
        return Asked(text, answer, asks)
    return None


def question_single(r: Reading) -> Asked | None:
    """One particle: how long the far end takes to follow, and how far the struck end moves meanwhile, in S."""
    h = r.history
    if len(h.scenario.particles) != 1 or not h.turning.turns or not h.turning.turns[0].completed:
        return None
    turn = h.turning.turns[0]
    struck = impact_name(r.turn_cause(turn)[-1].label)
    far = "left" if turn.pivot_end == "right" else "right"
    u = r.velocity(turn.rapidity_to, rest_frame())
    g = gamma(u)
    delay = abs(u) * g  # the far end's hyperbola about the impact reaches velocity u at t − t_P = L sinh φ = γ|u| L
    # S shown has its events table to fill in, the rod's velocity after the impact among its cells: taken from it
    velocity = (f"its velocity after {struck} (your table of S)" if any(f.name == "rest" for f in r.frames) else
                f"the velocity {in_c(u, ANSWER_DIGITS)} in S")
    text = (f"{struck} gives the rod's momentum {velocity} at once, but the {far} end follows only gradually, on the "
            f"hyperbola of radius L about {struck}. How long after {struck}, in S, does the {far} end reach that "
            f"velocity? How far has the struck end moved by then?")
    answer = (f"On that hyperbola the velocity is tanh φ a time L sinh φ after {struck}; it reaches |u| = "
              f"{answer_numeral(abs(u))} where sinh φ = γ|u| = {answer_numeral(g)} × {answer_numeral(abs(u))} = "
              f"{answer_numeral(delay)}.",
              f"So the {far} end takes {in_l_approx(delay)} of S's time. Meanwhile the struck end, moving at "
              f"{in_c(u, ANSWER_DIGITS)} from the impact on, moves {in_l_approx(abs(u) * delay)} to the "
              f"{'right' if u > 0 else 'left'}; the rod then has "
              f"its moving length L/γ = {in_l_approx(1.0 / g)} in S.")
    asks = (told_number(f"how long the {far} end takes in S", delay),
            told_number("how far the struck end moves meanwhile", abs(u) * delay))
    return Asked(text, answer, asks)


def _s_table(r: Reading) -> str:
    """Where the student finds velocities in S: the events table of S, if S is shown."""
    return " (the events table of S)" if any(f.name == "rest" for f in r.frames) else ""


def question_momentum(r: Reading, collision: tuple[Impact, ...] | None = None) -> Asked:
    """Momentum in S before and after a collision (the first, or the one given), from the velocities."""
    h = r.history
    s = h.scenario
    rest = rest_frame()
    c = collision or r.collisions[0]
    rows, before, after = [], 0.0, 0.0
    for i in c:
        m = s.particle(i.particle).mass
        ub, ua = r.velocity(i.particle_rapidity_before, rest), r.velocity(i.particle_rapidity_after, rest)
        pb, pa = momentum(m, ub), momentum(m, ua)
        before, after = before + pb, after + pa
        rows.append(f"{i.particle} ({answer_numeral(m)} M): {in_c(ub, ANSWER_DIGITS)} → {in_c(ua, ANSWER_DIGITS)}, "
                    f"p = {answer_numeral(pb)} → {answer_numeral(pa)} M c")
    ub, ua = r.velocity(c[0].rod_rapidity_before, rest), r.velocity(c[-1].rod_rapidity_after, rest)
    pb, pa = momentum(1.0, ub), momentum(1.0, ua)
    rows.append(f"the rod (M): {in_c(ub, ANSWER_DIGITS)} → {in_c(ua, ANSWER_DIGITS)}, p = {answer_numeral(pb)} → "
                f"{answer_numeral(pa)} M c")
    why = ua != ub and len(c) > 1
    text = (f"Using the velocities in S just before and just after {impact_names(c)}{_s_table(r)}, check that "
            f"momentum is conserved in S." + (" Why does the rod move off?" if why else ""))
    answer = ["p = m u/√(1 − u²). " + "; ".join(rows) + ".",
              f"Before: {answer_numeral(before + pb)} M c; after: {answer_numeral(after + pa)} M c: the same."]
    if why:
        answer.append("The particles' momenta do not cancel before the impacts (the heavier one carries more), so the "
                      "rod carries the difference after them.")
    asks = [told_number(f"momentum in S before {impact_names(c)}", before + pb),
            told_number(f"momentum in S after {impact_names(c)}", after + pa)]
    asks += [told_number(f"{i.particle}'s momentum in S before {impact_names(c)}",
                         momentum(s.particle(i.particle).mass, r.velocity(i.particle_rapidity_before, rest)))
             for i in c]
    return Asked(text, tuple(answer), tuple(asks))


def question_together(r: Reading, b: Frame) -> Asked | None:
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
    symbol = frame_name(b)
    u_rod = r.velocity(c[0].rod_rapidity_before, b)
    momenta = [momentum(h.scenario.particle(i.particle).mass, r.velocity(i.particle_rapidity_before, rest_frame()))
               for i in c]
    cancel = (f" (in S, where that line is one of constant t, the particles arrive with momenta "
              f"{listed([answer_numeral(p) + ' M c' for p in momenta])}, which cancel)"
              if abs(sum(momenta)) <= PRINTED_ZERO * sum(abs(p) for p in momenta) else "")
    # asked without telling the order in b, which the question on simultaneity asks
    text = (f"What is the rod's velocity in {symbol} from before {impact_names(c)} until after both, and why do "
            f"their impulses not change it?")
    answer = (f"{in_c(u_rod, ANSWER_DIGITS)}, as before and after: the rod takes {impact_names(c)} together, on one line "
              f"of its own simultaneity, and there the impulses cancel{cancel}.",
              f"Between the two impacts in {symbol} the momentum {first.particle} has given up is held by the stress "
              f"in the rod: the hidden part of the ledger, which the question on hidden momentum computes.")
    asks = (told_number(f"the rod's velocity in {symbol} between {impact_names(c)}", u_rod),
            told_claim(f"the rod takes {impact_names(c)} together", f"takes {impact_names(c)} together",
                       f"{impact_names(c)} together", "impulses cancel"))
    return Asked(text, answer, asks)


def question_zigzag(r: Reading) -> Asked | None:
    """Where the rod zig-zags: its motion in S from the events table, and why a particle strikes twice."""
    h = r.history
    if not zigzags([0.0] + [c[-1].rod_rapidity_after for c in r.collisions]):
        return None
    rest = rest_frame()
    u = r.rod_velocities(rest)
    steps = [f"after {impact_names(c)} (t = {in_l(r.length(r.t(c[0], rest)), ANSWER_DIGITS)}) "
             f"{in_c(u[k + 1], ANSWER_DIGITS)}: it {pushed(u[k], u[k + 1])}" for k, c in enumerate(r.collisions)]
    text = (f"From the rod's velocities in S{_s_table(r)}: in which direction is the rod driven after each impact? "
            f"Why is it struck more than once by the same particle?")
    answer = [f"Its velocity in S is 0 before {impact_names(r.collisions[0])}; " + "; ".join(steps) + "."]
    repeat = next((i for i in h.impacts if any(p.particle == i.particle for p in h.impacts[:h.impacts.index(i)])), None)
    if repeat is not None:
        previous = next(p for p in reversed(h.impacts[:h.impacts.index(repeat)]) if p.particle == repeat.particle)
        answer.append(f"After {impact_name(previous.label)}, {repeat.particle} moves at "
                      f"{in_c(r.velocity(repeat.particle_rapidity_before, rest), ANSWER_DIGITS)} while the rod, "
                      f"driven the other way since, moves at "
                      f"{in_c(r.velocity(repeat.rod_rapidity_before, rest), ANSWER_DIGITS)}: its {repeat.end} end "
                      f"closes on {repeat.particle} again, at {impact_name(repeat.label)}. The impulses do not cancel "
                      f"because the rod takes them one at a time.")
    asks = [told_number(f"the rod's velocity in S after {impact_names(c)}", u[k + 1])
            for k, c in enumerate(r.collisions)]
    asks.append(told_claim("the rod zig-zags in S", "zig-zag", *(f"it {pushed(u[k], u[k + 1])}"
                                                                for k in range(len(r.collisions)))))
    return Asked(text, tuple(answer), tuple(asks))
