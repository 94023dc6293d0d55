"""The causal rod's material chart (the rod's own view, `--frame rod`): t + x = a(T + X), t - x = b(T - X) (docs,
"The causal rod"). a and b are increasing, so the chart covers all spacetime once: outside the rod, (T, X) is where
the light ray that leaves an end at one chart time meets the ray that reaches it at another (the end's radar
chart, exact). Every light ray is a 45-degree line; a material point's proper time runs d tau = dT / lam. Pure.
"""

from __future__ import annotations

import math

import numpy as np

from rodparadox.physics.kinematics import Event
from rodparadox.physics.rod_view import Clock, quiet_start


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


    def __init__(self, history):
        self.history, self.solution, self.L = history, history.solution, history.scenario.L

    def to_event(self, T: float, X: float) -> Event:
        U, V = self.solution.a(T + X), self.solution.b(T - X)
        return Event(0.5 * (U - V), 0.5 * (U + V))

    def to_chart(self, event: Event) -> tuple[float, float]:
        """(T, X) of an event in S: the whole plane is charted (outside the rod, by light rays from its ends)."""
        sol = self.solution
        # at Python floats (an event's coordinates may be numpy scalars: the same floats, at a higher cost)
        u = _inverse(sol.a, lambda s: math.exp(sol.r_plus(s)), float(event.t + event.x), self.L)
        w = _inverse(sol.b, lambda s: math.exp(sol.r_minus(s)), float(event.t - event.x), self.L)
        return 0.5 * (u + w), 0.5 * (u - w)

    def placed(self, event: Event) -> list[tuple[float, float, int]]:
        """(T, X, piece) of the event: the whole plane is charted once, in one piece."""
        return [(*self.to_chart(event), 0)]

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
        return Clock(lambda T: 1.0 / self.compression(T, X), self.solution.breaks(X, T0, T1), T0, T1, self.L).total

    def clock_ticks(self, X: float, step: float, T_lo: float, T_hi: float) -> list[tuple[float, float]]:
        """(proper time, chart time) of material point X's clock ticks, every `step` of its proper time counted
        from chart time 0 (before any contact, where the chart time is S's time), between T_lo and T_hi."""
        plus = self.solution.plus  # its first piece: the undisturbed rod, up to the first contact
        lo, offset = quiet_start(T_lo, plus.pieces[0].hi if plus.pieces else math.inf, self.L)
        clock = Clock(lambda T: 1.0 / self.compression(T, X), self.solution.breaks(X, lo, T_hi), lo, T_hi, self.L,
                      offset)
        return clock.ticks(step, T_lo)


def points_on_slice(history, f: float, t: float, sigmas: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Where each material point X = sigma of the causal rod is at time t of the frame of rapidity f, and its
    rapidity there: the chart time T on the slice, t(T) = (e^-f a(T + X) + e^f b(T - X))/2 = t, by Newton's method
    (dt/dT = (e^(r+ - f) + e^(r- + f))/2 > 0) kept inside a bracket, from the neighbour's T; to 1e-13 of t."""
    sol, L = history.solution, history.scenario.L
    f, t = float(f), float(t)  # Python floats: numpy scalars cost twice as much, the same floats
    ef = math.exp(f)
    xs, rapidities = [], []
    T = None
    for X in np.asarray(sigmas, dtype=float).tolist():  # Python floats: numpy scalars cost twice as much, same floats
        def time(T_: float) -> float:
            return 0.5 * (sol.a(T_ + X) / ef + ef * sol.b(T_ - X))
        if T is None:
            T = t
        lo, hi, step = T, T, L  # in units of the rod's length: L may be 1e-100 or 1e100
        while time(lo) > t:
            lo, step = lo - step, 2 * step
        step = L
        while time(hi) < t:
            hi, step = hi + step, 2 * step
        for _ in range(100):
            error = time(T) - t
            if abs(error) <= 1e-13 * (L + abs(t)):
                break
            if error > 0:
                hi = T
            else:
                lo = T
            slope = 0.5 * (math.exp(sol.r_plus(T + X)) / ef + ef * math.exp(sol.r_minus(T - X)))
            T = T - error / slope
            if not lo < T < hi:  # out of the bracket (a front's kink): bisect instead
                T = 0.5 * (lo + hi)
        U, V = sol.a(T + X) / ef, ef * sol.b(T - X)
        xs.append(0.5 * (U - V))
        rapidities.append(0.5 * (sol.r_plus(T + X) - sol.r_minus(T - X)) - f)
    return np.array(xs), np.array(rapidities)
