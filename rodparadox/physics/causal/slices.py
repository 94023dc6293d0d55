"""The causal rod's matter and stress on many slices at once, and the tables of its invariants they are read from
(docs/model.md, "The causal rod"). Pure: numpy, no matplotlib. The integral across many slices at once: the ledger
figure's curves (`CausalHistory.rod_parts_on_slices`) and the html page's ledger call `rod_parts_on_slices`; the
ledger's own numbers, slice by slice, are `parts.rod_parts`' exact integral, which the tests compare this with.

The engine's solution (`solve`) gives the invariants r+(u), r-(w) and the chart map a(u), b(w) exactly, one
scalar call at a time (tens of microseconds each). `ChartTables` reads the solution once: on every smooth piece
between two breaks of an invariant (a front, a contact's start or end) r and a (or b) are interpolated by a
Chebyshev polynomial through the engine's values, each piece halved until the polynomial agrees with the engine at
test points to a tolerance (in units of L), or until halving gains nothing (the engine's own rounding noise, near
c): numpy then evaluates them for whole arrays at once.

On the slice t of the frame of rapidity f an element of the rod moves at rapidity th = (r+ - r-)/2 - f, with
lam = exp(-(r+ + r-)/2); T = (rho + p) u u - p eta splits into matter, rho u u (rho = (M/2L)(1 + lam^2), the
rest-frame energy density, elastic energy included), and stress, p (u u - eta) (p = (M/2L)(lam^2 - 1)):
densities on the slice
  matter (rho cosh^2 th, rho cosh th sinh th),  stress (p sinh^2 th, p cosh th sinh th),
with dx = e^(r+ - f) du along the slice. Each slice is parametrised by u, cut at every front crossing it (lam and th
jump there) and into stretches at most STRETCH L long, Gauss-Legendre on each, every stretch of every slice at once,
each halved until its halves agree with it; the w of each node is found by Newton's method on
t = (e^-f a(u) + e^f b(w))/2 kept in its bracket.
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
#: Gauss-Legendre nodes per stretch of a slice, and the longest stretch (units of L)
GAUSS = 8
STRETCH = 0.25
#: the integral's tolerance by default: each stretch halved until its halves agree with it to this, relative to
#: the rod's energy M c^2 (or to a few thousand roundings of the stretch's own sum, where that is larger: v near c);
#: with tables to PRECISE_TABLES, within 1e-10 of the exact integral at ordinary speeds
#: (tests/physics/test_causal_slices.py; a known gap near c there)
PARTS_TOLERANCE = 1e-9
PRECISE_TABLES = 1e-12
#: bounds on the work (every preset needs a tenth of each): pieces of one table, points of one sampled line, stretches
#: of the slices' sums; past one, `BeyondBounds`
MAX_PIECES = 1000
MAX_POINTS = 20000
MAX_STRETCHES = 15000


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
        """The fits at x, every point on its own piece at once (Clenshaw's recurrence)."""
        # the same operations in the same order as b1, b2 = 2 x b1 - b2 + c_j, b1, with the points' coefficients
        # gathered once and 2 x computed once: the per-operation cost of numpy dominates these short arrays
        rows = coef[:, index]
        twice_x = 2 * x
        b1, b2 = np.zeros_like(x), np.zeros_like(x)
        for j in range(NODES - 1, 0, -1):
            b1, b2 = twice_x * b1 - b2 + rows[j], b1
        return x * b1 - b2 + rows[0]

    def r(self, s):
        index, x, _ = self._place(s)
        return self._clenshaw(self.r_coef, index, x)

    def m(self, s):
        index, x, n = self._place(s)
        return self._clenshaw(self.m_coef, index, x) + n * self.gain

    def both(self, s):
        """(r, m) at s."""
        index, x, n = self._place(s)
        return self._clenshaw(self.r_coef, index, x), self._clenshaw(self.m_coef, index, x) + n * self.gain


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
        U, V = math.exp(-f) * self.plus.m(u), math.exp(f) * self.minus.m(w)
        return 0.5 * (U - V), 0.5 * (U + V), 0.5 * (self.plus.r(u) - self.minus.r(w)) - f

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
            x, t, _ = self.point(X, Ts)
            mid = 0.5 * (Ts[1:] + Ts[:-1])
            xm, tm, _ = self.point(X, mid)
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
            value = time(T) - t
            lo, hi = np.where(value < 0, T, lo), np.where(value >= 0, T, hi)
            slope = 0.5 * (np.exp(self.plus.r(T + X)) / ef + ef * np.exp(self.minus.r(T - X)))
            step = T - value / slope
            done = (np.abs(value) <= 1e-13 * (1 + np.abs(t))) | (hi - lo <= 1e-15 * (1 + np.abs(T)))
            if done.all():
                break
            T = np.where(done, T, np.where((step > lo) & (step < hi), step, 0.5 * (lo + hi)))
        return T


# --- the rod's parts on slices ----------------------------------------------------------------------------------

def rod_parts_on_slices(history, f, t, tables: ChartTables | None = None, tolerance: float = PARTS_TOLERANCE,
                        ends: tuple[np.ndarray, np.ndarray] | None = None) -> tuple[np.ndarray, np.ndarray]:
    """(matter, stress): arrays (n, 2) of (E, p) of the causal rod on each slice (f[k], t[k]) (frame rapidity and
    time; either may be one number for every slice); matter's E includes the rod's rest energy M (M = 1).

    `tables`: the invariants' tables to read (by default built to PRECISE_TABLES over the slices' chart times);
    `tolerance`: each stretch's (the module's docstring), in M c^2; `ends`: the chart times of the left and right
    ends on the slices, where the caller has them. Within 1e-10 of the exact integral with the defaults."""
    t = np.atleast_1d(np.asarray(t, dtype=float))
    f = np.broadcast_to(np.asarray(f, dtype=float), t.shape).copy()
    L = history.scenario.L
    if tables is None:
        T = [history.end_chart_time(end, float(fk), float(tk)) for fk, tk in zip(f, t) for end in ("left", "right")]
        tables = ChartTables(history, min(T) - L, max(T) + L, PRECISE_TABLES)
    ef = np.exp(f)
    T_L, T_R = ends if ends is not None else (tables.end_chart_times(0.0, f, t), tables.end_chart_times(L, f, t))
    u_L, u_R, w_L, w_R = T_L, T_R + L, T_L, T_R - L
    # the stretches of each slice: between u-breaks, the u where the slice meets a w-break, at most STRETCH L long
    plus_breaks, minus_breaks = np.array(tables.plus.breaks), np.array(tables.minus.breaks)
    crossings_slice, crossings_target = [], []
    for k in range(len(t)):
        inside = minus_breaks[(minus_breaks > w_R[k]) & (minus_breaks < w_L[k])]
        crossings_slice += [k] * len(inside)
        crossings_target += list(ef[k] * (2 * t[k] - ef[k] * tables.minus.m(inside)) if len(inside) else [])
    crossing_u = _invert(tables.plus, np.array(crossings_target), np.array(crossings_slice, dtype=int),
                         u_L, u_R)
    slice_of, lo_of, hi_of = [], [], []
    for k in range(len(t)):
        cuts = sorted({u_L[k], u_R[k], *plus_breaks[(plus_breaks > u_L[k]) & (plus_breaks < u_R[k])],
                       *crossing_u[np.array(crossings_slice, dtype=int) == k]})
        for a, b in zip(cuts, cuts[1:]):
            n = max(1, math.ceil((b - a) / (STRETCH * L)))
            if len(slice_of) + n > MAX_STRETCHES:
                raise BeyondBounds(f"{MAX_STRETCHES} stretches of slices to add up the ledger")
            edges = np.linspace(a, b, n + 1)
            slice_of += [k] * n
            lo_of, hi_of = lo_of + list(edges[:-1]), hi_of + list(edges[1:])
    total = _adaptive(tables, f, t, np.array(slice_of, dtype=int), np.array(lo_of), np.array(hi_of), w_R, w_L,
                      tolerance)
    return total[:, :2], total[:, 2:]


def _gauss(tables: ChartTables, f, t, k, lo, hi, w_R, w_L) -> np.ndarray:
    """(stretches, 4): Gauss-Legendre sums of the densities on each stretch [lo, hi] of u of slice k."""
    L = tables.L
    nodes, weights = np.polynomial.legendre.leggauss(GAUSS)
    u = (0.5 * (lo + hi))[:, None] + (0.5 * (hi - lo))[:, None] * nodes[None, :]
    weight = (0.5 * (hi - lo))[:, None] * weights[None, :]
    kk = np.repeat(k, GAUSS)
    u, weight, fk = u.ravel(), weight.ravel(), f[kk]
    target = np.exp(-fk) * (2 * t[kk] - np.exp(-fk) * tables.plus.m(u))
    w = _invert(tables.minus, target, kk, w_R, w_L)
    rp, rm = tables.plus.r(u) - fk, tables.minus.r(w) + fk
    th, lam2 = 0.5 * (rp - rm), np.exp(-(rp + rm))
    rho, p = 0.5 / L * (1.0 + lam2), 0.5 / L * (lam2 - 1.0)
    c, s = np.cosh(th), np.sinh(th)
    scale = np.exp(rp) * weight  # dx = e^(r+ - f) du along the slice
    densities = np.stack([rho * c * c, rho * c * s, p * s * s, p * c * s], axis=1) * scale[:, None]
    return densities.reshape(len(k), GAUSS, 4).sum(axis=1)


def _adaptive(tables: ChartTables, f, t, k, lo, hi, w_R, w_L, tolerance: float) -> np.ndarray:
    """The densities integrated over every slice's stretches, each halved until its halves agree with it."""
    total = np.zeros((len(t), 4))
    whole = _gauss(tables, f, t, k, lo, hi, w_R, w_L)
    spent = 3 * len(k)  # stretches summed, a whole and its halves each
    before = np.full(len(k), np.inf)  # each stretch's parent's miss
    for depth in range(40):
        mid = 0.5 * (lo + hi)
        # both halves in one call: each stretch's sums depend on that stretch alone (and the slices' brackets, the
        # same for both halves), so they are the values two calls would give, at half the calls' cost
        n = len(k)
        both = _gauss(tables, f, t, np.concatenate([k, k]), np.concatenate([lo, mid]), np.concatenate([mid, hi]),
                      w_R, w_L)
        left, right = both[:n], both[n:]
        halves = left + right
        # to the tolerance, or a few thousand roundings where a body's energy is thousands of M c^2 (v near c), or,
        # where halving gains nothing (the tables' own noise near c), below NOISE_TOLERANCE tolerances
        miss = np.max(np.abs(halves - whole), axis=1)
        good = (miss <= np.maximum(tolerance, 1e-12 * np.max(np.abs(halves), axis=1))) | (
            (miss <= NOISE_TOLERANCE * tolerance) & (miss >= 0.25 * before))
        if depth == 39:
            good[:] = True
        np.add.at(total, k[good], halves[good])
        bad = ~good
        if not bad.any():
            break
        spent += 2 * int(bad.sum())
        if spent > MAX_STRETCHES:
            raise BeyondBounds(f"{MAX_STRETCHES} stretches of slices to add up the ledger")
        k, lo, hi = np.concatenate([k[bad], k[bad]]), np.concatenate([lo[bad], mid[bad]]), \
            np.concatenate([mid[bad], hi[bad]])
        before = np.concatenate([miss[bad], miss[bad]])
        whole = np.concatenate([left[bad], right[bad]])
    return total


def _invert(table: _Table, target: np.ndarray, k: np.ndarray, lo_k: np.ndarray, hi_k: np.ndarray) -> np.ndarray:
    """s with table.m(s) = target (m increasing, m' = e^r), within [lo_k[k], hi_k[k]]: from a guess read off m on
    a grid, Newton's method kept inside the bracket."""
    if len(target) == 0:
        return np.zeros(0)
    lo, hi = lo_k[k].copy(), hi_k[k].copy()
    grid = np.linspace(lo.min(), hi.max(), 257)
    s = np.clip(np.interp(target, table.m(grid), grid), lo, hi)
    for _ in range(100):
        r, m = table.both(s)
        value = m - target
        lo, hi = np.where(value < 0, s, lo), np.where(value >= 0, s, hi)
        step = s - value / np.exp(r)
        done = (np.abs(value) <= 1e-13 * (1 + np.abs(target))) | (hi - lo <= 1e-15 * (1 + np.abs(s)))
        if done.all():
            break
        s = np.where(done, s, np.where((step > lo) & (step < hi), step, 0.5 * (lo + hi)))
    return s
