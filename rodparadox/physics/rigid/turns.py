"""The rigid rod's turns (docs/model.md, "Inside the rod"; the paper's rule 3): its lines of simultaneity turning about a
pivot, the material points' world-lines through them, and the rod's own "now" (the fans and the lines between
turns). Pure.

The material point sigma (its proper distance from the left end, 0 <= sigma <= L) rests at x = sigma - L/2 until
the first turn; during each turn it moves on the hyperbola of radius d (its distance from the pivot) centred on
the pivot, between the turn's first and last fan lines; between turns the whole rod moves at one velocity. So its
world-line is a chain of exact lines and arcs, boosted exactly like the ends'.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from rodparadox.physics.history import RodHistory
from rodparadox.physics.kinematics import Event, HyperbolicArc, Line, Segment, WorldLine
from rodparadox.tolerances import SAME_EVENT


@dataclass(frozen=True)
class Turn:
    """The rod's lines of simultaneity turning about `pivot` (rule 3), from `rapidity_from` towards `rapidity_to`.

    `rapidity_to` is the rod's dynamical rapidity during the turn; the turn
    ends on the line `rapidity_stop`, which is `rapidity_to` unless the impact
    `stopped_by` struck the far end first (rule 6). The material point at
    proper distance d from the pivot moves on the hyperbola of radius d
    centred on it (`arc(d)`).
    """

    pivot: Event
    pivot_end: str
    rapidity_from: float
    rapidity_to: float
    rapidity_stop: float
    stopped_by: str | None
    L: float

    @property
    def side(self) -> int:
        """+1 when the pivot is the left end (the rod lies at +x from it on its own lines), else -1."""
        return 1 if self.pivot_end == "left" else -1

    @property
    def completed(self) -> bool:
        return self.stopped_by is None

    def arc(self, d: float) -> HyperbolicArc:
        """The path of the material point at proper distance d from the pivot during this turn."""
        return HyperbolicArc(self.pivot, d, self.side, self.rapidity_from, self.rapidity_stop)

    def corners(self) -> tuple[Event, Event, Event]:
        """The pivot, and the far end where the turn starts and where it stops (`turn_corners`)."""
        return turn_corners(self)

    def interval(self, frame_rapidity: float) -> tuple[float, float]:
        """When the turn starts and ends in the frame's time (`turn_interval`)."""
        return turn_interval(self, frame_rapidity)

    def distance(self, sigma: float) -> float:
        """Proper distance from the pivot of the material point sigma (its distance from the left end)."""
        return sigma if self.pivot_end == "left" else self.L - sigma


def material_worldline(history: RodHistory, sigma: float) -> WorldLine:
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


def now_lines(history: RodHistory, per_turn: int = 4, between: int = 2) -> list[tuple[Event, Event]]:
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


@dataclass(frozen=True)
class RigidTurns:
    """The rigid rod's own part of the rod interface (`physics.history.Turning`): its turns, its own lines of
    simultaneity, and when each turn starts and ends in a frame. `History.turning` gives it."""

    history: RodHistory

    @property
    def turns(self) -> tuple[Turn, ...]:
        return self.history.turns

    def now_lines(self, per_turn: int = 4, between: int = 2) -> list[tuple[Event, Event]]:
        return now_lines(self.history, per_turn, between)

    def turn_interval(self, turn: Turn, frame_rapidity: float) -> tuple[float, float]:
        return turn_interval(turn, frame_rapidity)

    def turn_times(self, frame_rapidity: float) -> list[float]:
        return sorted({t for turn in self.history.turns for t in turn_interval(turn, frame_rapidity)})

    def rapidities(self) -> tuple[float, ...]:
        """Every rapidity, in S, a material point of the rod takes at the start or end of a piece of its world-line.

        A point's rapidity is 0 before the first turn, runs monotonically from `rapidity_from` to `rapidity_stop`
        during each turn, stays there between turns, and is `final_rapidity` after the last: so the extremes of
        every point's rapidity over the whole history are among these. (A turn's `rapidity_to`, the rod's
        dynamical rapidity, is not: a stopped turn never reaches it.)
        """
        values = [0.0, self.history.final_rapidity]
        for turn in self.history.turns:
            values += [turn.rapidity_from, turn.rapidity_stop]
        return tuple(values)
