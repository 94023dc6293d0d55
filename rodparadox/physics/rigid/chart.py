"""The rigid rod's own chart (the rod's own view, `--frame rod`): its rest frame between turns (T its time, X the
distance from its left end), and during a turn the pivot's Rindler chart: T = T_start + L |phi - phi_from| (phi the
fan line through the event), X the proper distance d from the pivot, shifted so the rod is 0 <= X <= L. The
material point at d keeps one X (its hyperbola is a vertical line) and its clock runs d tau = (d / L) dT during
the turn. Beyond a pivot's horizon (the far side of the pivot during its turn) the rod's own time orders nothing:
those events are in no piece of the chart, or in two (the rest frames before and after the turn both reach
them), and are reported as beyond the horizon (`to_chart` gives None), never placed. Pure.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from rodparadox.physics.kinematics import Event
from rodparadox.physics.rod_view import Clock


@dataclass(frozen=True)
class _Rest:
    """A stretch between turns: the rest frame of rapidity `rapidity`; `left` is the left end's event at chart
    time `T_ref`; the stretch holds chart times T_lo to T_hi."""

    rapidity: float
    left: Event
    T_ref: float
    T_lo: float
    T_hi: float

    def to_chart(self, e: Event, L: float):
        p, o = e.seen_from(self.rapidity), self.left.seen_from(self.rapidity)
        T = self.T_ref + p.t - o.t
        return (T, p.x - o.x) if self.T_lo - 1e-12 * L <= T <= self.T_hi + 1e-12 * L else None

    def to_event(self, T: float, X: float, L: float) -> Event:
        o = self.left.seen_from(self.rapidity)
        return Event(o.x + X, o.t + T - self.T_ref).seen_from(-self.rapidity)

    def tick_rate(self, X: float, L: float) -> float:
        return 1.0


@dataclass(frozen=True)
class _Turning:
    """A turn (`engine.Turn`) as the pivot's Rindler chart: chart times T_lo to T_hi = T_lo + L |Dphi|."""

    turn: object
    T_lo: float
    T_hi: float

    def _sign(self) -> float:
        return 1.0 if self.turn.rapidity_stop >= self.turn.rapidity_from else -1.0

    def to_chart(self, e: Event, L: float):
        turn = self.turn
        dx, dt = e.x - turn.pivot.x, e.t - turn.pivot.t
        if turn.side * dx <= abs(dt):  # not in the rod's wedge of the pivot: its far side, or its light cone
            return None
        d, fan = math.sqrt((dx - dt) * (dx + dt)), math.atanh(dt / dx)
        lo, hi = sorted((turn.rapidity_from, turn.rapidity_stop))
        slack = 1e-12 * (1 + abs(lo) + abs(hi))
        if not lo - slack <= fan <= hi + slack:
            return None
        return self.T_lo + L * abs(fan - turn.rapidity_from), (d if turn.pivot_end == "left" else L - d)

    def to_event(self, T: float, X: float, L: float):
        turn = self.turn
        d = X if turn.pivot_end == "left" else L - X
        if d < 0:
            return None  # beyond the pivot: its horizon
        fan = turn.rapidity_from + self._sign() * (T - self.T_lo) / L
        return turn.pivot.displaced(turn.side * d, fan)

    def tick_rate(self, X: float, L: float) -> float:
        """d tau / dT of material point X: its distance from the pivot over L (the pivot's clock stops)."""
        return abs(X if self.turn.pivot_end == "left" else L - X) / L


class RigidChart:
    """The rigid rod's own chart: rest frames between turns, each turn's Rindler chart (module docstring)."""


    def __init__(self, history):
        self.history, self.L = history, history.scenario.L
        L, pieces = self.L, []
        rapidity, left, T_ref, T_lo = 0.0, Event(-0.5 * L, 0.0), 0.0, -math.inf
        for turn in history.turns:
            T_start = max(T_lo, T_ref + turn.pivot.time_in(rapidity) - left.time_in(rapidity))
            pieces.append(_Rest(rapidity, left, T_ref, T_lo, T_start))
            T_end = T_start + L * abs(turn.rapidity_stop - turn.rapidity_from)
            pieces.append(_Turning(turn, T_start, T_end))
            rapidity = turn.rapidity_stop
            left = turn.pivot if turn.pivot_end == "left" else turn.pivot.displaced(-L, rapidity)
            T_ref = T_lo = T_end
        pieces.append(_Rest(rapidity, left, T_ref, T_lo, math.inf))
        self.pieces = tuple(pieces)

    @property
    def turns(self) -> list[tuple[float, float, str]]:
        """Each turn's chart times (start, end) and its pivot's end."""
        return [(p.T_lo, p.T_hi, p.turn.pivot_end) for p in self.pieces if isinstance(p, _Turning)]

    def _candidates(self, e: Event) -> list[tuple[float, float, int]]:
        """(T, X, piece) of every piece that charts e, the same point once (a piece's edge is its neighbour's)."""
        found: list[tuple[float, float, int]] = []
        for k, piece in enumerate(self.pieces):
            point = piece.to_chart(e, self.L)
            if point is not None and not any(abs(point[0] - f[0]) + abs(point[1] - f[1]) <= 1e-9 * self.L
                                             for f in found):
                found.append((*point, k))
        return found

    def _is_pivot(self, e: Event) -> bool:
        return any(abs(e.x - t.pivot.x) + abs(e.t - t.pivot.t) <= 1e-9 * self.L for t in self.history.turns)

    def placed(self, e: Event) -> list[tuple[float, float, int]]:
        """Where the chart puts e, as (T, X, piece): one place; a turn's pivot (one event for the whole turn, its
        clock stopped) at the turn's start and at its end; none beyond a pivot's horizon."""
        found = self._candidates(e)
        if len(found) == 1 or (found and self._is_pivot(e)):
            return sorted(found)
        return []

    def to_chart(self, e: Event) -> tuple[float, float] | None:
        """(T, X) of an event in S (a turn's pivot: where the turn starts), or None beyond a pivot's horizon (in no
        piece of the chart, or in two at different places)."""
        found = self.placed(e)
        return (found[0][0], found[0][1]) if found else None

    def beyond_horizon(self, e: Event) -> bool:
        return self.to_chart(e) is None

    def _piece_at(self, T: float):
        for piece in self.pieces:
            if piece.T_lo <= T <= piece.T_hi and (isinstance(piece, _Turning) or piece.T_hi > piece.T_lo):
                return piece
        return self.pieces[-1]

    def to_event(self, T: float, X: float) -> Event | None:
        """The event at (T, X), or None where the chart holds none (beyond a pivot during its turn) or where that
        event is beyond a horizon (the rod's time gives it two places)."""
        e = self._piece_at(T).to_event(T, X, self.L)
        return e if e is not None and self.placed(e) else None

    def proper_time(self, X: float, T0: float, T1: float) -> float:
        """The proper time of material point X from chart time T0 to T1: dT between turns, (d / L) dT in a turn."""
        total = 0.0
        for piece in self.pieces:
            lo, hi = max(T0, piece.T_lo), min(T1, piece.T_hi)
            if hi > lo:
                total += (hi - lo) * piece.tick_rate(X, self.L)
        return total

    def clock_ticks(self, X: float, step: float, T_lo: float, T_hi: float) -> list[tuple[float, float]]:
        """(proper time, chart time) of material point X's clock ticks every `step`, counted from chart time 0."""
        lo = min(0.0, T_lo)
        breaks = [T for p in self.pieces for T in (p.T_lo, p.T_hi) if lo < T < T_hi]
        return Clock(lambda T: self._piece_at(T).tick_rate(X, self.L), breaks, lo, T_hi, self.L).ticks(step, T_lo)
