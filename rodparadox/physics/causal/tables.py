"""Tables of the causal rod's invariants and chart map, read for whole arrays at once: the html page's world-lines,
fronts and cells of compression (docs/model.md, "The causal rod"). Pure: numpy, no matplotlib.

The engine's solution (`solve`) gives the invariants r+(u), r-(w) and the chart map a(u), b(w) exactly, one
scalar call at a time (tens of microseconds each). `ChartTables` reads the solution once: on every smooth piece
between two breaks of an invariant (a front, a contact's start or end) r and a (or b) are interpolated by a
Chebyshev polynomial through the engine's values, each piece halved until the polynomial agrees with the engine at
test points to a tolerance (in units of L), or until halving gains nothing (the engine's own rounding noise, near
c): numpy then evaluates them for whole arrays at once. (The rod's energy and momentum on slices are read from the
engine's own pieces instead, `parts`.)
"""

from __future__ import annotations

import math

import numpy as np

from rodparadox.errors import BeyondBounds

#: the tables agree with the engine's a, b and r to this by default (units of L; r is a number)
TABLE_TOLERANCE = 1e-9
#: a piece whose error halving does not reduce (the engine's own noise) is kept below this many times the tolerance
NOISE_TOLERANCE = 1000.0
#: Chebyshev nodes per piece of a table; pieces are halved until within the tolerance
NODES = 12
#: bounds on the work (every preset needs a tenth of each): pieces of one table, points of one sampled line; past
#: one, `BeyondBounds`
MAX_PIECES = 1000
MAX_POINTS = 20000


class _Table:
    """One invariant r(s) and its chart map m(s) (a or b) on [lo, hi], piecewise Chebyshev. After the last
    separation r repeats with the invariant's period and m gains the same each period (`Invariant.close`): one
    period is fitted, the rest read from it."""

    def __init__(self, invariant, r, m, lo: float, hi: float, L: float, tolerance: float = TABLE_TOLERANCE):
        self.starts, self.ends, self.r_fits, self.m_fits = [], [], [], []
        self.L, self.fits, self.tolerance = L, 0, tolerance
        self.breaks = invariant.breaks(lo, hi)
        self.period, self.tail, self.gain = invariant.period, invariant.tail_start, invariant.tail_gain[0]
        top = hi if self.period is None else min(hi, self.tail + self.period)
        knots = [lo, *[s for s in self.breaks if s < top], top]
        for a, b in zip(knots, knots[1:]):
            if b > a:
                self._fit(r, m, a, b, 0)
        self.starts, self.ends = np.array(self.starts), np.array(self.ends)
        self.r_coef = np.ascontiguousarray(np.array([fit.coef for fit in self.r_fits]).T)  # (NODES, pieces)
        self.m_coef = np.ascontiguousarray(np.array([fit.coef for fit in self.m_fits]).T)
        self.rm_coef = np.ascontiguousarray(np.stack([self.r_coef, self.m_coef], axis=1))  # both in one pass

    def _fit(self, r, m, a: float, b: float, depth: int, parent: float = math.inf) -> None:
        self.fits += 1
        if self.fits > 2 * MAX_PIECES:
            raise BeyondBounds(f"{MAX_PIECES} pieces to tabulate the rod's invariants")
        if depth >= 40 or b - a <= 1e-12 * (self.L + abs(a)):  # a jump the breaks do not name: a sliver, flat
            self.starts.append(a), self.ends.append(b)
            for fits, f in ((self.r_fits, r), (self.m_fits, m)):
                fits.append(np.polynomial.Chebyshev([f(0.5 * (a + b))] + [0.0] * (NODES - 1), domain=[a, b]))
            return
        k = np.arange(NODES)
        x = 0.5 * (a + b) + 0.5 * (b - a) * np.cos(math.pi * (k + 0.5) / NODES)
        rs, ms = np.array([r(s) for s in x]), np.array([m(s) for s in x])
        r_fit = np.polynomial.Chebyshev.fit(x, rs, NODES - 1, domain=[a, b])
        m_fit = np.polynomial.Chebyshev.fit(x, ms, NODES - 1, domain=[a, b])
        test = a + (b - a) * np.array([0.013, 0.5, 0.987])  # between nodes, and nearer the ends than any
        # r to the tolerance, m to the tolerance times L, or to a few hundred roundings of m where m is large (a
        # rapidity near 10 makes m thousands of L: its own rounding is then above 1e-9 L)
        m_tolerance = max(self.tolerance * self.L, 1e-14 * float(np.max(np.abs(ms))))
        error = max(max(abs(r_fit(s) - r(s)) / self.tolerance, abs(m_fit(s) - m(s)) / m_tolerance) for s in test)
        # where the engine's own values are noisier than that (a contact's closed form near lam's extremes, v near
        # c, loses digits of r), halving gains nothing: a smooth piece's error falls by 2^NODES a halving, noise's
        # does not; kept once below NOISE_TOLERANCE times the tolerance
        noise = error <= NOISE_TOLERANCE and error >= 0.25 * parent
        if not (error <= 1.0 or noise):  # (NaN included)
            mid = 0.5 * (a + b)
            self._fit(r, m, a, mid, depth + 1, error)
            self._fit(r, m, mid, b, depth + 1, error)
            return
        self.starts.append(a), self.ends.append(b), self.r_fits.append(r_fit), self.m_fits.append(m_fit)

    def _reduce(self, s) -> tuple[np.ndarray, np.ndarray]:
        """s moved into the fitted period, and the periods it was moved by."""
        s = np.asarray(s, dtype=float)
        if self.period is None:
            return s, np.zeros_like(s)
        n = np.maximum(np.floor((s - self.tail) / self.period), 0.0)
        return s - n * self.period, n

    def _place(self, s) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Each s's piece, its place in the piece's window [-1, 1], and the periods it was moved by."""
        s, n = self._reduce(s)
        index = np.clip(np.searchsorted(self.starts, s, side="right") - 1, 0, len(self.starts) - 1)
        a, b = self.starts[index], self.ends[index]
        return index, (2 * s - (a + b)) / (b - a), n

    @staticmethod
    def _clenshaw(coef: np.ndarray, index: np.ndarray, x: np.ndarray) -> np.ndarray:
        """The fits at x, every point on its own piece at once (Clenshaw's recurrence); `coef` (NODES, pieces), or
        (NODES, m, pieces) for m fits at each point at once, (m, points)."""
        # the same operations in the same order as b1, b2 = 2 x b1 - b2 + c_j, b1, with the points' coefficients
        # gathered once and 2 x computed once: the per-operation cost of numpy dominates these short arrays
        # (and into arrays kept from one degree to the next, no array made per operation: a third less time)
        rows = coef[..., index]
        twice_x = 2 * x
        b1, b2, spare = np.zeros(rows.shape[1:]), np.zeros(rows.shape[1:]), np.empty(rows.shape[1:])
        for j in range(NODES - 1, 0, -1):
            np.multiply(twice_x, b1, out=spare)
            np.subtract(spare, b2, out=spare)
            np.add(spare, rows[j], out=spare)
            b1, b2, spare = spare, b1, b2
        return x * b1 - b2 + rows[0]

    def r(self, s):
        index, x, _ = self._place(s)
        return self._clenshaw(self.r_coef, index, x)

    def m(self, s):
        index, x, n = self._place(s)
        return self._clenshaw(self.m_coef, index, x) + n * self.gain

    def both(self, s):
        """(r, m) at s: `r(s)` and `m(s)`, the same floats, placed once and summed in one pass."""
        index, x, n = self._place(s)
        r, m = self._clenshaw(self.rm_coef, index, x)
        return r, m + n * self.gain


class ChartTables:
    """r+, a on u and r-, b on w over [lo, hi] of chart time (extended by 2L for the right end's u and w)."""

    def __init__(self, history, lo: float, hi: float, tolerance: float = TABLE_TOLERANCE):
        sol, L = history.solution, history.scenario.L
        self.history, self.L, self.tolerance = history, L, tolerance
        self.plus = _Table(sol.plus, sol.r_plus, sol.a, lo - 2 * L, hi + 2 * L, L, tolerance)
        self.minus = _Table(sol.minus, sol.r_minus, sol.b, lo - 2 * L, hi + 2 * L, L, tolerance)

    def point(self, X, T, f: float = 0.0):
        """x, t and the rapidity of material line X at chart times T in the frame of rapidity f (arrays)."""
        u, w = np.asarray(T) + X, np.asarray(T) - X
        (r_plus, a), (r_minus, b) = self.plus.both(u), self.minus.both(w)
        U, V = math.exp(-f) * a, math.exp(f) * b
        return 0.5 * (U - V), 0.5 * (U + V), 0.5 * (r_plus - r_minus) - f

    def knots(self, X: float, T0: float, T1: float) -> list[float]:
        """Where a front crosses material line X between chart times T0 and T1 (where it kinks)."""
        inside = [u - X for u in self.plus.breaks] + [w + X for w in self.minus.breaks]
        return [T0, *sorted(T for T in set(inside) if T0 < T < T1), T1]

    def sample(self, X: float, T0: float, T1: float, tolerance: float) -> tuple[np.ndarray, ...]:
        """Chart times on [T0, T1] whose points' polyline lies within `tolerance` L of line X, in S, every kink
        included: each smooth stretch cut evenly, every chord whose middle strays halved, all at once."""
        cuts = self.knots(X, T0, T1)
        Ts = np.unique(np.concatenate([np.linspace(a, b, 5) for a, b in zip(cuts, cuts[1:]) if b > a]))
        for _ in range(40):
            mid = 0.5 * (Ts[1:] + Ts[:-1])
            x, t, _ = self.point(X, np.concatenate([Ts, mid]))  # both at once: each point alone, one call
            x, t, xm, tm = x[:len(Ts)], t[:len(Ts)], x[len(Ts):], t[len(Ts):]
            dx, dt = np.diff(x), np.diff(t)
            chord = np.hypot(dx, dt)
            error = np.abs(dx * (tm - t[:-1]) - dt * (xm - x[:-1])) / np.where(chord > 0, chord, 1.0)
            bad = error > tolerance * self.L
            if not bad.any():
                break
            Ts = np.sort(np.concatenate([Ts, mid[bad]]))
            if len(Ts) > MAX_POINTS:
                raise BeyondBounds(f"{MAX_POINTS} points to draw a line")
        return (Ts, *self.point(X, Ts))

    def end_chart_times(self, X: float, f: np.ndarray, t: np.ndarray) -> np.ndarray:
        """The chart time where material line X crosses the slice t of the frame f (arrays): t(T) rises with T
        (dt/dT = (e^(r+ - f) + e^(r- + f))/2 > 0); Newton's method kept inside a bracket, then bisection."""
        ef = np.exp(f)

        def time(T):
            return 0.5 * (self.plus.m(T + X) / ef + ef * self.minus.m(T - X))

        # a bracket: t(T) - T is bounded by the rod's motion, below c (in units of L, which may be 1e-100 or 1e100)
        lo, hi = np.full_like(t, -self.L), np.full_like(t, self.L)
        for _ in range(80):
            below, above = time(lo) > t, time(hi) < t
            if not (below.any() or above.any()):
                break
            lo, hi = np.where(below, 2 * lo - hi, lo), np.where(above, 2 * hi - lo, hi)
        T = 0.5 * (lo + hi)
        for _ in range(100):
            (r_plus, a), (r_minus, b) = self.plus.both(T + X), self.minus.both(T - X)  # time(T), r once
            value = 0.5 * (a / ef + ef * b) - t
            lo, hi = np.where(value < 0, T, lo), np.where(value >= 0, T, hi)
            slope = 0.5 * (np.exp(r_plus) / ef + ef * np.exp(r_minus))
            step = T - value / slope
            done = (np.abs(value) <= 1e-13 * (1 + np.abs(t))) | (hi - lo <= 1e-15 * (1 + np.abs(T)))
            if done.all():
                break
            T = np.where(done, T, np.where((step > lo) & (step < hi), step, 0.5 * (lo + hi)))
        return T
