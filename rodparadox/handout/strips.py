"""The rod at successive instants of a frame (the handout's strips): which instants teach (`strip_times`), and
the caption saying what they show, which end of the rod changes velocity first and how the other follows. Pure.
"""

from __future__ import annotations

from typing import Sequence

from rodparadox.handout.reading import Reading
from rodparadox.handout.words import coordinates, impact_names, in_c, in_l, listed, numeral, time_name
from rodparadox.physics.history import RodHistory, Turn
from rodparadox.physics.frames import Frame, frame_name, time_window
from rodparadox.numbers import impact_name
from rodparadox.render.colour_scale import colour_scale
from rodparadox.render.strip_windows import strips_follow_rod
from rodparadox.tolerances import SAME_RAPIDITY

#: the fewest and the most instants of the rod shown per frame
STRIPS_FEWEST, STRIPS_MOST = 6, 8
#: two stills closer than this fraction of the frame's time window look alike on the page: one is kept
STRIP_SEPARATION = 0.02


def _end_changes(r: Reading, frame: Frame) -> dict[str, list[tuple[float, float, Turn, bool]]]:
    """For each end, when its velocity changes in the frame: (start, end, turn, struck) per turn it takes part in;
    struck: it is the turn's pivot and jumps at the impact, else it follows the turn's hyperbola."""
    eta = frame.rapidity
    out: dict[str, list] = {"left": [], "right": []}
    for turn in r.history.turning.turns:
        pivot, far_start, far_end = turn.corners()
        out[turn.pivot_end].append((pivot.time_in(eta), pivot.time_in(eta), turn, True))
        if abs(turn.rapidity_stop - turn.rapidity_from) > SAME_RAPIDITY:
            far = "left" if turn.pivot_end == "right" else "right"
            out[far].append((far_start.time_in(eta), far_end.time_in(eta), turn, False))
    return out


def strip_times(history: RodHistory, frame: Frame) -> tuple[float, ...]:
    """Six to eight instants of the frame's time that teach, earliest first, all within `frames.time_window`:
    before the first change, every instant at which an impact strikes, the start of any turn before its impact
    (the far end moving first), the middle of each turn, and after the last change."""
    r = Reading(history, (frame,))
    eta = frame.rapidity
    t_lo, t_hi = time_window(history, frame)
    impacts = [t for t, _ in r.instants(frame)]
    turns = [turn.interval(eta) for turn in history.turning.turns]
    changes = sorted(impacts + [t for interval in turns for t in interval])
    first, last = changes[0], changes[-1]
    # (priority, time): the lower the priority, the surer an instant is kept
    candidates = [(0, 0.5 * (t_lo + first)), (0, 0.5 * (last + t_hi))]
    candidates += [(1, t) for t in impacts]
    candidates += [(1, start) for start, _ in turns if not any(r.same_time(start, t) for t in impacts)]
    candidates += [(2, 0.5 * (a + b)) for a, b in turns if b - a > 0]
    candidates += [(3, end) for _, end in turns]
    return tuple(min(max(t, t_lo), t_hi) for t in chosen_instants(candidates, t_lo, t_hi))


def chosen_instants(candidates: Sequence[tuple[int, float]], t_lo: float, t_hi: float) -> list[float]:
    """Of (priority, time) candidates, the lower the priority the surer kept: at most STRIPS_MOST, none closer than
    STRIP_SEPARATION of the window [t_lo, t_hi] to one kept before it; fewer than STRIPS_FEWEST, the widest gap
    (the window's ends as bounds) halved until there are. In time order."""
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
    return times


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


def _direction(before: float, after: float) -> str:
    """What a change of velocity does, in words: starts moving left, reverses, slows to, speeds up to, stops."""
    side = "right" if after > 0 else "left"
    if after == 0.0:
        return "stops"
    if before == 0.0:
        return f"starts moving {side} at {in_c(abs(after)).lstrip('+')}"
    if (before > 0) != (after > 0):
        return f"reverses to move {side} at {in_c(abs(after)).lstrip('+')}"
    return f"{'speeds up' if abs(after) > abs(before) else 'slows'} to {in_c(after)}"


def _gradually(before: float, after: float) -> str:
    """How an end following a turn's hyperbola changes velocity, in words."""
    side = "right" if after > 0 else "left"
    if before == 0.0:
        return f"starts moving {side}, gradually reaching {in_c(after)}"
    if after == 0.0:
        return f"slows gradually from {in_c(before)} to rest"
    if (before > 0) != (after > 0):
        return f"turns back gradually from {in_c(before)} to {in_c(after)}"
    return f"{'speeds up' if abs(after) > abs(before) else 'slows'} gradually from {in_c(before)} to {in_c(after)}"


def _which_end_first(r: Reading, frame: Frame) -> str:
    """Which end of the rod changes velocity first in the frame, when, and how the other follows."""
    h = r.history
    symbol, time = frame_name(frame), time_name(frame)
    eta = frame.rapidity
    if not h.turning.turns:
        u = r.rod_velocities(frame)[0]
        changes = listed([f"{i.particle}'s at {impact_name(i.label)} ({r.when([i], frame)})"
                           for _, g in r.instants(frame) for i in g])
        motion = "stays at rest" if u == 0.0 else f"moves on at {in_c(u)}"
        return (f"Neither end of the rod ever changes velocity in {symbol}: the rod {motion}, while the particles' "
                f"velocities change, {changes}.")

    def change(end: str, turn: Turn, struck: bool, start: float, stop: float) -> str:
        """What one end does in one turn: jumps at its impact, or follows the hyperbola."""
        if struck:
            before, after = (r.velocity(x + eta, frame) for x in _kink(h.worldline(f"rod_{end}").seen_from(eta), start))
            return f"is struck by {impact_names(r.impacts_at(turn.pivot))} and {_direction(before, after)} at once"
        return _gradually(r.velocity(turn.rapidity_from, frame), r.velocity(turn.rapidity_stop, frame)) + \
            f" by {time} = {in_l(r.length(stop, r.impacts_at(turn.pivot), frame))}"

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
    near = r.impacts_at(turn.pivot)  # what the times of this turn are computed from: their rounding's scale
    if len(order) > 1 and r.same_time(firsts[order[1]][0], start):
        other = order[1]
        o_start, o_stop, o_turn, o_struck = firsts[other]
        return (f"Both ends start to change velocity at {time} = {in_l(r.length(start, near, frame))}: the {first} end "
                f"{change(first, turn, struck, start, stop)}; the {other} end {change(other, o_turn, o_struck, o_start, o_stop)}"
                f". The shading shows the velocity spreading along the rod.")
    text = f"The {first} end moves first, at {time} = {in_l(r.length(start, near, frame))}: "
    if struck:
        text += "it " + change(first, turn, struck, start, stop)
    else:
        cause = r.turn_cause(turn)
        strike = "strike" if len(cause) > 1 else "strikes"
        text += (f"before {impact_names(cause)} {strike} the {turn.pivot_end} end (at {in_l(r.length(turn.pivot.time_in(eta), near, frame))}"
                 f"), it {change(first, turn, struck, start, stop)}, because the rod responds along its own line of "
                 f"simultaneity through {impact_names(cause)}, which reaches the {first} end earlier in {symbol}")
    if len(order) > 1:
        other = order[1]
        o_start, o_stop, o_turn, o_struck = firsts[other]
        text += (f". The {other} end follows from {time} = {in_l(r.length(o_start))}: it "
                 f"{change(other, o_turn, o_struck, o_start, o_stop)}")
    return text + "."


def strips_caption(history: RodHistory, frame: Frame, times: Sequence[float]) -> str:
    """What the stills show, at which instants, and what to look at."""
    r = Reading(history, (frame,))
    symbol = frame_name(frame)
    instants = listed([numeral(r.length(t)) for t in times])
    if colour_scale(history, frame).shown is None:  # the rod never changes velocity: one shade, no colour bar
        bar = (f"The bar runs from the rod's left end to its right end; its material points keep the rod's first "
               f"velocity in {symbol}, {in_c(frame.rod_velocity())}, throughout, so it has one shade")
    else:
        # the scale is centred on the rod's first velocity only on screen: in print the bar runs from the slowest
        # velocity (light) to the fastest (dark), and a rod that only slows has its first velocity at an end
        bar = (f"The bar runs from the rod's left end to its right end, shaded by the velocity in {symbol} of each of "
               f"its material points, which the scale under the rows gives")
    follows = " " + following_rows(frame) if strips_follow_rod(history, frame, times) else ""
    return (f"The rod and the particles in {symbol} at {time_name(frame)} = {instants} (in units of L), earliest "
            f"first. {bar}; the dots are the particles.{follows} " + _which_end_first(r, frame))


def following_rows(frame: Frame, particles: bool = True) -> str:
    """What a block of stills whose rows each follow the rod (`render.strip_windows`) says of them (of the arrowheads
    marking a particle beyond a row's edge only where there are `particles`)."""
    return (f"The rod moves far in {frame_name(frame)} compared with its length, so each row follows it: every row "
            f"is drawn to the same scale, centred on the rod at its instant, and has its own {coordinates(frame)[0]} "
            f"axis" + ("; an arrowhead at a row\u2019s edge points to a particle beyond it." if particles else "."))
