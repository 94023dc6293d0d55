"""The rod's own view (`--frame rod`, README "The rod's own view"): charts in which the rod is a fixed strip. Pure.

Not a Lorentz frame: a chart (T, X) of spacetime built from the rod's own motion, X the material label (the rod is
the strip 0 <= X <= L at every T), T the rod's own time. Every map is exact (the history's segments, the causal
chart functions a(u), b(w)); points are sampled only to draw.

* `CausalChart`, the causal rod's material chart: t + x = a(T + X), t - x = b(T - X) (README, "The causal rod").
  a and b are increasing, so the chart covers all spacetime once: outside the rod, (T, X) is where the light ray
  that leaves an end at one chart time meets the ray that reaches it at another (the end's radar chart, exact).
  Every light ray is a 45-degree line; a material point's proper time runs d tau = dT / lam.
* `RigidChart`, the rigid rod's: its rest frame between turns (T its time, X the distance from its left end),
  and during a turn the pivot's Rindler chart: T = T_start + L |phi - phi_from| (phi the fan line through the
  event), X the proper distance d from the pivot, shifted so the rod is 0 <= X <= L. The material point at d
  keeps one X (its hyperbola is a vertical line) and its clock runs d tau = (d / L) dT during the turn. Beyond a
  pivot's horizon (the far side of the pivot during its turn) the rod's own time orders nothing: those events
  are in no piece of the chart, or in two (the rest frames before and after the turn both reach them), and are
  reported as beyond the horizon (`to_chart` gives None), never placed.
"""

from __future__ import annotations

import bisect
import functools
import math
from dataclasses import dataclass

import numpy as np

from rodparadox.errors import OptionError
from rodparadox.physics.kinematics import Event

#: the rod's own view, as a frame word (`--frame rod`); not a Lorentz frame, so not a `frames.Frame`
ROD_WORD = "rod"


@dataclass(frozen=True)
class RodView:
    """The rod's own view, where a list of frames names it (`--frame rod,rest`): a panel in the rod's chart."""

    name: str = ROD_WORD


ROD_VIEW = RodView()

#: the teacher's extras (`render.Options`) that draw on the frames' panels only: the rod's own view shows none
FRAME_EXTRAS = ("other_axes", "light_cones", "hyperbolae", "grid", "rod_lines", "rod_now", "proper_time",
                "equal_scales")


def refuse_frame_extras(frames, **extras) -> None:
    """Extras asked for (`FRAME_EXTRAS`, true or non-zero) with no frame's panel to draw them on, every panel of
    `frames` the rod's own view: an OptionError naming the first, since the figure would be the one without it."""
    asked = [name for name in FRAME_EXTRAS if extras.get(name)]
    if asked and frames and all(frame == ROD_VIEW for frame in frames):
        raise OptionError(asked[0], extras[asked[0]], template="{what} draws on the frames' panels, and {frame} "
                          "{view} has only the rod's own view: leave it out, or give a frame beside it ({frame} "
                          "rest,{view}).", view=ROD_WORD)

@functools.cache
def _gauss_legendre() -> tuple[np.ndarray, np.ndarray]:
    """Gauss-Legendre nodes and weights for a material clock between fronts (the integrand is analytic there);
    made on first use: numpy.polynomial is not loaded by what never reads a clock (`--frame rod` does)."""
    return np.polynomial.legendre.leggauss(24)


def chart_of(history) -> "CausalChart | RigidChart":
    """The rod's own chart for a history of either model."""
    return RigidChart(history) if history.rigid is not None else CausalChart(history)


def _inverse(f, slope, y: float, scale: float) -> float:
    """The s with f(s) = y, f increasing without bound both ways with derivative `slope` (> 0; it may jump, f stays
    continuous): bracketed, then Newton kept inside the bracket (bisection when a step would leave it), to the
    last bit."""
    lo, hi, step = y - scale, y + scale, scale
    while f(lo) > y:
        lo, step = lo - step, 2 * step
    step = scale
    while f(hi) < y:
        hi, step = hi + step, 2 * step
    s = 0.5 * (lo + hi)
    for _ in range(200):
        g = f(s) - y
        if g == 0:
            return s
        lo, hi = (s, hi) if g < 0 else (lo, s)
        newton = s - g / slope(s)
        following = newton if lo < newton < hi else 0.5 * (lo + hi)
        if following in (lo, hi) or following == s:
            break
        s = following
    return lo if abs(f(lo) - y) <= abs(f(hi) - y) else hi


class CausalChart:
    """The causal rod's material chart (T, X), with its exact maps to and from events in S."""

    kind = "causal"

    def __init__(self, history):
        self.history, self.solution, self.L = history, history.solution, history.scenario.L

    def to_event(self, T: float, X: float) -> Event:
        U, V = self.solution.a(T + X), self.solution.b(T - X)
        return Event(0.5 * (U - V), 0.5 * (U + V))

    def to_chart(self, event: Event) -> tuple[float, float]:
        """(T, X) of an event in S: the whole plane is charted (outside the rod, by light rays from its ends)."""
        sol = self.solution
        u = _inverse(sol.a, lambda s: math.exp(sol.r_plus(s)), event.t + event.x, self.L)
        w = _inverse(sol.b, lambda s: math.exp(sol.r_minus(s)), event.t - event.x, self.L)
        return 0.5 * (u + w), 0.5 * (u - w)

    def compression(self, T: float, X: float) -> float:
        """lam at (T, X): exp(-(r+ + r-)/2)."""
        return math.exp(-0.5 * (self.solution.r_plus(T + X) + self.solution.r_minus(T - X)))

    def fronts(self, T_lo: float, T_hi: float) -> tuple[list[float], list[float]]:
        """The light fronts crossing the rod between chart times T_lo and T_hi: the u = T + X of each left-going one
        and the w = T - X of each right-going one (where lam or the velocity jumps or kinks)."""
        L = self.L
        return (self.solution.plus.breaks(T_lo, T_hi + L), self.solution.minus.breaks(T_lo - L, T_hi))

    def proper_time(self, X: float, T0: float, T1: float) -> float:
        """The proper time of material point X from chart time T0 to T1: the integral of dT / lam, split at fronts."""
        return _Clock(lambda T: 1.0 / self.compression(T, X), self.solution.breaks(X, T0, T1), T0, T1, self.L).total

    def clock_ticks(self, X: float, step: float, T_lo: float, T_hi: float) -> list[tuple[float, float]]:
        """(proper time, chart time) of material point X's clock ticks, every `step` of its proper time counted
        from chart time 0 (before any contact, where the chart time is S's time), between T_lo and T_hi."""
        lo = min(0.0, T_lo)
        clock = _Clock(lambda T: 1.0 / self.compression(T, X), self.solution.breaks(X, lo, T_hi), lo, T_hi, self.L)
        return clock.ticks(step, T_lo)


class _Clock:
    """A material clock from chart time T0 to T1: d tau / dT = rate(T), smooth between the knots (the fronts, or a
    turn's ends), integrated by Gauss-Legendre on spans of at most L / 4; tau(0) = 0 when 0 lies in the span."""

    def __init__(self, rate, breaks, T0: float, T1: float, L: float):
        self.rate = rate
        knots = [T0]
        for b in [*sorted(breaks), T1]:
            a = knots[-1]
            if b <= a:
                continue
            n = max(1, math.ceil((b - a) / (0.25 * L)))
            knots += [a + (b - a) * (k + 1) / n for k in range(n)]
        self.knots = knots
        self.taus = [0.0]
        for a, b in zip(knots, knots[1:]):
            self.taus.append(self.taus[-1] + self._integral(a, b))
        self.total = self.taus[-1]
        self.zero = self.tau(0.0) if T0 <= 0.0 <= T1 else 0.0

    def _integral(self, a: float, b: float) -> float:
        mid, half = 0.5 * (a + b), 0.5 * (b - a)
        return half * sum(w * self.rate(mid + half * s) for s, w in zip(*_gauss_legendre()))

    def tau(self, T: float) -> float:
        k = max(0, min(len(self.knots) - 2, bisect.bisect_right(self.knots, T) - 1))
        return self.taus[k] + self._integral(self.knots[k], T)

    def ticks(self, step: float, T_lo: float) -> list[tuple[float, float]]:
        """(tau, T) where tau crosses each multiple of step, T >= T_lo: Newton in each span, kept in its bracket."""
        out: list[tuple[float, float]] = []
        for k, (a, b) in enumerate(zip(self.knots, self.knots[1:])):
            tau_a, tau_b = self.taus[k] - self.zero, self.taus[k + 1] - self.zero
            n = math.ceil(tau_a / step - 1e-12)
            while tau_b > tau_a and n * step <= tau_b + 1e-12 * step:
                target, lo, hi = n * step, a, b
                T = a + (b - a) * (target - tau_a) / (tau_b - tau_a)
                for _ in range(60):
                    f = tau_a + self._integral(a, T) - target
                    if abs(f) <= 1e-14 * (1 + abs(target)):
                        break
                    lo, hi = (T, hi) if f < 0 else (lo, T)
                    rate = self.rate(T)
                    T = T - f / rate if rate > 0 and lo < T - f / rate < hi else 0.5 * (lo + hi)
                if T >= T_lo and (not out or target > out[-1][0] + 1e-12 * step):
                    out.append((target, T))
                n += 1
        return out

# --- the rigid rod ----------------------------------------------------------------------------------------------

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

    kind = "rigid"

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
        return _Clock(lambda T: self._piece_at(T).tick_rate(X, self.L), breaks, lo, T_hi, self.L).ticks(step, T_lo)


def chart_polyline(chart, points: np.ndarray) -> np.ndarray:
    """An (n, 2) array of [x, t] points in S as [X, T] chart points, a row of NaN (a break in a drawn line) where an
    event is beyond a horizon and between two points on either side of a turn (a line through a turn's pivot
    leaves it at the turn's end, where it arrived at the start)."""
    out, last = [], None
    for x, t in points:
        e = Event(float(x), float(t))
        if chart.kind == "causal":
            out.append(chart.to_chart(e)[::-1])
            continue
        found = chart.placed(e)
        if not found:
            out.append((math.nan, math.nan))
            last = None
            continue
        T, X, piece = min(found, key=lambda f: abs(f[2] - last)) if last is not None else found[0]
        if last is not None and abs(piece - last) > 1:
            out.append((math.nan, math.nan))
        if len(found) > 1 and last is not None:  # a pivot reached: the line goes on from the turn's end
            out.append((X, T))
            T, X, piece = max(found, key=lambda f: f[2])
            out.append((math.nan, math.nan))
        out.append((X, T))
        last = piece
    return np.array(out, dtype=float).reshape(-1, 2)


def densified(points: np.ndarray, spacing: float) -> np.ndarray:
    """The polyline with points added along each chord, at most `spacing` apart (a chart map bends straight lines)."""
    out = [points[:1]]
    for p, q in zip(points[:-1], points[1:]):
        n = max(1, math.ceil(float(np.hypot(*(q - p))) / spacing))
        out.append(p + np.outer(np.arange(1, n + 1) / n, q - p))
    return np.concatenate(out)
