"""Inside the rod: its material points, the rod on a slice of any frame, and its own lines of simultaneity.

README, "Inside the rod". Pure. The material point sigma (its proper distance
from the left end, 0 <= sigma <= L) rests at x = sigma - L/2 until the first
turn; during each turn (`engine.Turn`) it moves on the hyperbola of radius d
(its distance from the pivot) centred on the pivot, between the turn's first
and last fan lines; between turns the whole rod moves at one velocity. So its
world-line is a chain of exact lines and arcs, boosted exactly like the ends'.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rodparadox.physics.engine import History, Turn
from rodparadox.physics.kinematics import Event, Line, Segment, WorldLine
from rodparadox.numbers import nice_number
from rodparadox.tolerances import SAME_EVENT


def material_worldline(history: History, sigma: float) -> WorldLine:
    """The exact world-line, in S, of the material point at proper distance sigma from the left end."""
    L = history.scenario.L
    if not 0.0 <= sigma <= L:
        raise ValueError(f"sigma must lie between 0 and L = {L!r}, got {sigma!r}")
    segments: list[Segment] = []
    first: Event | None = None
    last: Event | None = None
    for turn in history.turns:
        d = turn.distance(sigma)
        arc = turn.arc(d) if d > 0 else None
        start, end = (arc.start, arc.end) if arc is not None else (turn.pivot, turn.pivot)
        if last is None:
            first = start
        elif math.hypot(start.x - last.x, start.t - last.t) > SAME_EVENT * L:
            segments.append(Line(last, start))  # between turns: straight, at the rapidity the last turn stopped on
        if arc is not None and arc.phi_start != arc.phi_end:
            segments.append(arc)
        last = end
    if first is None:
        return WorldLine(Event(sigma - L / 2, 0.0), 0.0)
    return WorldLine(first, 0.0, tuple(segments), history.final_rapidity)


@dataclass(frozen=True)
class RodSlice:
    """The rod on the slice t = `t` of the frame of rapidity `frame_rapidity`: where each material point is, and its
    rapidity there (`velocity` = tanh of it), all in that frame."""

    frame_rapidity: float
    t: float
    sigma: np.ndarray
    x: np.ndarray
    rapidity: np.ndarray

    @property
    def velocity(self) -> np.ndarray:
        return np.tanh(self.rapidity)


def rod_slice(history: History, frame_rapidity: float, t: float, sigmas) -> RodSlice:
    """Where the material points `sigmas` cross the slice t of the frame, and their rapidities there."""
    sigmas = np.asarray(sigmas, dtype=float)
    xs, rapidities = np.empty(len(sigmas)), np.empty(len(sigmas))
    for k, sigma in enumerate(sigmas):
        event, rapidities[k] = material_worldline(history, float(sigma)).seen_from(frame_rapidity).event_and_rapidity_at_time(t)
        xs[k] = event.x
    return RodSlice(frame_rapidity, t, sigmas, xs, rapidities)


def turn_corners(turn: Turn) -> tuple[Event, Event, Event]:
    """The corners of the part of spacetime a turn sweeps: its pivot and the far end's first and last events."""
    arc = turn.arc(turn.L)
    return turn.pivot, arc.start, arc.end


def turn_interval(turn: Turn, frame_rapidity: float) -> tuple[float, float]:
    """When a turn starts and ends in a frame's time: its region's earliest and latest corner.

    Along a fan line the time is linear in d, and along the far end's arc it
    increases: the extremes lie at the corners.
    """
    times = [e.time_in(frame_rapidity) for e in turn_corners(turn)]
    return min(times), max(times)


def now_lines(history: History, per_turn: int = 4, between: int = 2) -> list[tuple[Event, Event]]:
    """The rod's own lines of simultaneity (its "now"), as (left end, right end) event pairs in S.

    During each turn, `per_turn` lines of its fan through the pivot (first and
    last included); between turns, `between` lines of the rest frame there,
    evenly spaced in its own time. Before the first turn and after the last,
    `between` lines a proper time L apart.
    """
    L = history.scenario.L
    lines: list[tuple[Event, Event]] = []

    def across(pivot: Event, pivot_end: str, rapidity: float) -> tuple[Event, Event]:
        other = pivot.displaced(L if pivot_end == "left" else -L, rapidity)
        return (pivot, other) if pivot_end == "left" else (other, pivot)

    turns = history.turns
    if not turns:
        return lines
    first = turns[0]
    start = across(first.pivot, first.pivot_end, 0.0)[0]
    for k in range(between, 0, -1):
        left = Event(start.x, start.t - k * L)
        lines.append((left, left.displaced(L, 0.0)))
    for k, turn in enumerate(turns):
        for j in range(per_turn):
            f = j / max(per_turn - 1, 1)
            lines.append(across(turn.pivot, turn.pivot_end, turn.rapidity_from + f * (turn.rapidity_stop - turn.rapidity_from)))
        end_line = across(turn.pivot, turn.pivot_end, turn.rapidity_stop)
        if k + 1 < len(turns):
            nxt = turns[k + 1]
            next_line = across(nxt.pivot, nxt.pivot_end, nxt.rapidity_from)
            gap = next_line[0].time_in(turn.rapidity_stop) - end_line[0].time_in(turn.rapidity_stop)
            if gap <= SAME_EVENT * L:
                continue  # the next turn starts on the line this one stopped on (a stopped turn, or Fig. 2's A1)
            for j in range(1, between + 1):
                tau = j * gap / (between + 1)
                lines.append((_later(end_line[0], turn.rapidity_stop, tau), _later(end_line[1], turn.rapidity_stop, tau)))
        else:
            for j in range(1, between + 1):
                lines.append((_later(end_line[0], turn.rapidity_stop, j * L), _later(end_line[1], turn.rapidity_stop, j * L)))
    return lines


def _later(event: Event, rapidity: float, proper_time: float) -> Event:
    """The event a proper time later on the straight world-line of the given rapidity through `event`."""
    return Event(event.x + proper_time * math.sinh(rapidity), event.t + proper_time * math.cosh(rapidity))


def material_lines(history: History, frame_rapidity: float, count: int, t_lo: float, t_hi: float,
                   tolerance: float) -> list[tuple[float, np.ndarray]]:
    """`count` interior material points, evenly spaced (sigma = k L/(count + 1)), as (sigma, (n, 2) points of
    [x, t]) in the frame's coordinates from t_lo to t_hi, every kink included, arcs within `tolerance`."""
    L = history.scenario.L
    out = []
    for k in range(1, count + 1):
        sigma = k * L / (count + 1)
        out.append((sigma, history.material_worldline(sigma).seen_from(frame_rapidity).sample(t_lo, t_hi, tolerance)))
    return out


def clock_step(span: float, ticks: int = 10) -> float:
    """A nice proper-time step (`numbers.nice_number`: 1, 2, 2.5 or 5 times a power of ten) giving about `ticks`
    clock ticks over a time `span`: a figure passes its longest panel's span, so that a body at rest in that frame
    gets no more than about `ticks` ticks, and uses the one step in every panel, as proper time is the same in every
    frame."""
    return nice_number(span / ticks, "at_least")


@dataclass(frozen=True)
class RigidTurns:
    """The rigid rod's own part of the rod interface (`physics.history.RigidResponse`): its turns, its own lines
    of simultaneity, and when each turn starts and ends in a frame. `History.rigid` gives it."""

    history: History

    @property
    def turns(self) -> tuple[Turn, ...]:
        return self.history.turns

    def now_lines(self, per_turn: int = 4, between: int = 2) -> list[tuple[Event, Event]]:
        return now_lines(self.history, per_turn, between)

    def turn_interval(self, turn: Turn, frame_rapidity: float) -> tuple[float, float]:
        return turn_interval(turn, frame_rapidity)

    def turn_times(self, frame_rapidity: float) -> list[float]:
        return sorted({t for turn in self.history.turns for t in turn_interval(turn, frame_rapidity)})
