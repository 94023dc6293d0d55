"""What the html page embeds for the causal rod (README, "One page to explore" and "The causal rod"). Pure.

The engine's solution (`physics.causal_solve`) gives the invariants r+(u), r-(w) and the chart map a(u), b(w)
exactly, one scalar call at a time (a call into an integrator's dense output costs tens of microseconds). The page
needs thousands of points per speed, so `ChartTables` reads the solution once per speed: on every smooth piece
between two breaks of an invariant (a front, a contact's start or end) r and a (or b) are interpolated by a
Chebyshev polynomial through the engine's values, each piece halved until the polynomial agrees with the engine
at test points to `TABLE_TOLERANCE` (in units of L): numpy then evaluates them for whole arrays at once.

From the tables, in S (units of L): the world-lines of the ends, the particles and the material points, sampled
adaptively to a tolerance as the rigid rod's are, each point with its rapidity; the light fronts as their two end
points (a front is a light line: boosting its ends is exact); the world-sheet's cells of compression, bounded by
light lines u, w = const, given by their edges' chart coordinates and a(u), b(w) there (a boost of rapidity f
scales t + x by e^-f and t - x by e^f: the page scales the edges, exact) with r+ and r- at each cell's centre
(lam = exp(-(r+ + r-)/2)); and the ledger on a grid of frames and instants: each particle's (E, p), the rod's
matter and stress parts (`physics.causal_parts`' densities), integrated across each slice by Gauss-Legendre
between its fronts, every slice of a speed at once.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

#: the tables agree with the engine's a, b and r to this (units of L; r is a number): far below a pixel and the
#: ledger's 5 decimals
TABLE_TOLERANCE = 1e-9
#: Chebyshev nodes per piece of a table; pieces are halved until within TABLE_TOLERANCE
NODES = 12
#: Gauss-Legendre nodes per stretch of a slice, and the longest stretch (units of L)
GAUSS = 8
STRETCH = 0.25
#: a varying piece of an invariant is cut into cells this long (units of L), as the figures' shading
CELL = 1.0 / 24
#: shades a cell may differ from its neighbour by about one of (as the figures')
SHADES = 64
#: a jump of an invariant smaller than this is no front
FRONT_JUMP = 1e-9


class _Table:
    """One invariant r(s) and its chart map m(s) (a or b) on [lo, hi], piecewise Chebyshev. After the last
    separation r repeats with the invariant's period and m gains the same each period (`Invariant.close`): one
    period is fitted, the rest read from it."""

    def __init__(self, invariant, r, m, lo: float, hi: float):
        self.starts, self.ends, self.r_fits, self.m_fits = [], [], [], []
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

    def _fit(self, r, m, a: float, b: float, depth: int) -> None:
        if depth >= 40 or b - a <= 1e-12 * (1.0 + abs(a)):  # a jump the breaks do not name: a sliver, flat
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
        error = max(max(abs(r_fit(s) - r(s)), abs(m_fit(s) - m(s))) for s in test)
        if not error <= TABLE_TOLERANCE:  # (NaN included)
            mid = 0.5 * (a + b)
            self._fit(r, m, a, mid, depth + 1)
            self._fit(r, m, mid, b, depth + 1)
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

    def __init__(self, history, lo: float, hi: float):
        sol, L = history.solution, history.scenario.L
        self.history, self.L = history, L
        self.plus = _Table(sol.plus, sol.r_plus, sol.a, lo - 2 * L, hi + 2 * L)
        self.minus = _Table(sol.minus, sol.r_minus, sol.b, lo - 2 * L, hi + 2 * L)

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
        """Chart times on [T0, T1] whose points' polyline lies within `tolerance` of line X, in S, every kink
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
            bad = error > tolerance
            if not bad.any():
                break
            Ts = np.sort(np.concatenate([Ts, mid[bad]]))
        return (Ts, *self.point(X, Ts))

    def end_chart_times(self, X: float, f: np.ndarray, t: np.ndarray) -> np.ndarray:
        """The chart time where material line X crosses the slice t of the frame f (arrays): t(T) rises with T
        (dt/dT = (e^(r+ - f) + e^(r- + f))/2 > 0); Newton's method kept inside a bracket, then bisection."""
        ef = np.exp(f)

        def time(T):
            return 0.5 * (self.plus.m(T + X) / ef + ef * self.minus.m(T - X))

        lo, hi = np.full_like(t, -1.0), np.full_like(t, 1.0)
        for _ in range(80):  # a bracket: t(T) - T is bounded by the rod's motion, below c
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


# --- the page's data ----------------------------------------------------------------------------------------------

def drawn(value: float, digits: int) -> float:
    """As `data.drawn`: `digits` significant digits, never -0."""
    return float(f"{value:.{digits}g}") + 0.0


def line(tables: ChartTables, X: float, T0: float, T_hi: float, tolerance: float, digits: int) -> dict[str, Any]:
    """Points of material line X in S (units of L) from chart time T0 on, to T_hi: after the last separation the
    line repeats, each period 2L of chart time advancing every point by the same (dx, dt) (`period`), so only one
    period is given, from the point `repeat_from`, and `repeats` copies of it reach T_hi (the page translates
    them: exact for points). No rapidities: the page colours the causal rod from its cells."""
    sol, L = tables.history.solution, tables.L
    T_star = max(sol.plus.tail_start - X, sol.minus.tail_start + X, T0)
    period = sol.plus.period
    head = tables.sample(X, T0, T_star, tolerance) if T_star > T0 else None
    tail = tables.sample(X, T_star, T_star + period, tolerance)
    x = np.concatenate([head[1][:-1], tail[1]]) if head is not None else tail[1]
    t = np.concatenate([head[2][:-1], tail[2]]) if head is not None else tail[2]
    advance = period_advance(tables)
    return {"x": [drawn(v / L, digits) for v in x], "t": [drawn(v / L, digits) for v in t],
            "repeat_from": len(x) - len(tail[1]), "repeats": max(0, math.ceil((T_hi - T_star) / period) - 1),
            "period": [drawn(advance[0] / L, 15), drawn(advance[1] / L, 15)], "before": 0.0, "after": 0.0}


def period_advance(tables: ChartTables) -> tuple[float, float]:
    """(dx, dt) of every material point over one period of chart time after the last separation."""
    g_plus, g_minus = tables.plus.gain, tables.minus.gain
    return 0.5 * (g_plus - g_minus), 0.5 * (g_plus + g_minus)


def worldlines(history, tables: ChartTables, T_hi: float, tolerance: float, digits: int) -> dict[str, Any]:
    """The ends and the particles in S: at rest, then each on its chart curves (a particle free between them)."""
    L, out = history.scenario.L, {}
    for name in ("rod_left", "rod_right"):
        X = 0.0 if name == "rod_left" else L
        out[name] = line(tables, X, history.worldline(name).segments[0].T_start, T_hi, tolerance, digits)
    for name in ("A", "B"):
        w = history.worldline(name)
        if w is None:
            continue
        xs, ts = [w.first.x / L], [w.first.t / L]
        for segment in w.segments:
            if hasattr(segment, "chart"):
                _, x, t, _ = tables.sample(segment.X, segment.T_start, segment.T_end, tolerance)
                xs, ts = xs + list(x[1:] / L), ts + list(t[1:] / L)
            else:
                xs.append(segment.end.x / L), ts.append(segment.end.t / L)
        out[name] = {"x": [drawn(v, digits) for v in xs], "t": [drawn(v, digits) for v in ts],
                     "before": w.rapidity_before + 0.0, "after": w.rapidity_after + 0.0}
    return out


def fronts(history, tables: ChartTables, lo: float, hi: float) -> list[list[float]]:
    """Each light front in chart times [lo, hi] as [x, t] of its ends on the left and right end, in S (units of L)."""
    sol, L = history.solution, history.scenario.L
    out = []
    for family, invariant in (("+", sol.plus), ("-", sol.minus)):
        for s in invariant.breaks(lo, hi + L):
            if abs(invariant.r(s) - invariant.r(np.nextafter(s, -math.inf))) <= FRONT_JUMP:
                continue
            T_right = s - L if family == "+" else s + L  # r+ jumps along u = T + X, r- along w = T - X
            xl, tl, _ = tables.point(0.0, np.array([s]))
            xr, tr, _ = tables.point(L, np.array([T_right]))
            out.append([drawn(v / L, 7) for v in (xl[0], tl[0], xr[0], tr[0])])
    return out


def _edges(table: _Table, lo: float, hi: float, L: float, step: float) -> np.ndarray:
    """The cells' edges on [lo, hi]: every break, and inside a piece where r varies cells no longer than CELL L
    and short enough that r changes by about `step` from one to the next (as the figures' shading)."""
    cuts = [lo, *[s for s in table.breaks if lo < s < hi], hi]
    edges = [lo]
    for a, b in zip(cuts, cuts[1:]):
        r = table.r(np.array([a + 1e-9 * (b - a), 0.5 * (a + b), b - 1e-9 * (b - a)]))
        varies = float(r.max() - r.min())
        n = min(math.ceil((b - a) / (CELL * L)), math.ceil(2 * varies / step)) if varies > FRONT_JUMP else 1
        edges += list(np.linspace(a, b, max(n, 1) + 1)[1:])
    return np.array(edges)


def cells(history, tables: ChartTables, lo: float, hi: float, compression: tuple[float, float]) -> dict[str, Any]:
    """The world-sheet's cells of compression between chart times lo and hi: edges u_i (w_j) with a(u_i) (b(w_j)),
    and r+ (r-) at each cell's middle; cell (i, j) is in the rod where 0 < u - w < 2L."""
    L = history.scenario.L
    step = 2 * (compression[1] - compression[0]) / SHADES
    us, ws = _edges(tables.plus, lo, hi + 2 * L, L, step), _edges(tables.minus, lo - 2 * L, hi, L, step)
    return {"u": [drawn(v / L, 6) for v in us], "a": [drawn(v / L, 6) for v in tables.plus.m(us)],
            "r_plus": [drawn(v, 3) for v in tables.plus.r(0.5 * (us[1:] + us[:-1]))],
            "w": [drawn(v / L, 6) for v in ws], "b": [drawn(v / L, 6) for v in tables.minus.m(ws)],
            "r_minus": [drawn(v, 3) for v in tables.minus.r(0.5 * (ws[1:] + ws[:-1]))],
            "ln_lam": [compression[0], compression[1]]}


def ledger_sums(history, tables: ChartTables, f: np.ndarray, t: np.ndarray) -> dict[str, np.ndarray]:
    """On each slice (f[k], t[k]): each particle's (E, p), the rod's matter and stress (E, p) (arrays, M = 1)."""
    L, ef = history.scenario.L, np.exp(f)
    T_L, T_R = tables.end_chart_times(0.0, f, t), tables.end_chart_times(L, f, t)
    u_L, u_R, w_L, w_R = T_L, T_R + L, T_L, T_R - L
    nodes, weights = np.polynomial.legendre.leggauss(GAUSS)
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
            edges = np.linspace(a, b, n + 1)
            slice_of += [k] * n
            lo_of, hi_of = lo_of + list(edges[:-1]), hi_of + list(edges[1:])
    sums = _adaptive(tables, f, t, np.array(slice_of), np.array(lo_of), np.array(hi_of), w_R, w_L)
    sums.update(particles(history, tables, f, t, T_L, T_R))
    return sums


#: the rod's matter and stress (E, p) densities, per unit of u along a slice
PARTS = ("matter_E", "matter_p", "stress_E", "stress_p")
#: a stretch is halved until its halves agree with it to this (M c^2; the page prints 4 decimals)
SLICE_TOLERANCE = 1e-6


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


def _adaptive(tables: ChartTables, f, t, k, lo, hi, w_R, w_L) -> dict[str, np.ndarray]:
    """The densities integrated over every slice's stretches, each halved until its halves agree with it."""
    total = np.zeros((len(t), 4))
    whole = _gauss(tables, f, t, k, lo, hi, w_R, w_L)
    for depth in range(40):
        mid = 0.5 * (lo + hi)
        # both halves in one call: each stretch's sums depend on that stretch alone (and the slices' brackets, the
        # same for both halves), so they are the values two calls would give, at half the calls' cost
        n = len(k)
        both = _gauss(tables, f, t, np.concatenate([k, k]), np.concatenate([lo, mid]), np.concatenate([mid, hi]), w_R, w_L)
        left, right = both[:n], both[n:]
        halves = left + right
        good = np.max(np.abs(halves - whole), axis=1) <= SLICE_TOLERANCE
        if depth == 39:
            good[:] = True
        np.add.at(total, k[good], halves[good])
        bad = ~good
        if not bad.any():
            break
        k, lo, hi = np.concatenate([k[bad], k[bad]]), np.concatenate([lo[bad], mid[bad]]), \
            np.concatenate([mid[bad], hi[bad]])
        whole = np.concatenate([left[bad], right[bad]])
    return {name: total[:, j] for j, name in enumerate(PARTS)}


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


def particles(history, tables: ChartTables, f: np.ndarray, t: np.ndarray, T_L, T_R) -> dict[str, np.ndarray]:
    """Each particle's (E, p) on the slices: free at its rapidity between contacts; in contact, the end's."""
    L, out = history.scenario.L, {}
    for name in ("A", "B"):
        w = history.worldline(name)
        if w is None:
            continue
        mass = history.scenario.particle(name).mass
        mine = [i for i in history.impacts if i.particle == name]
        theta = np.full_like(t, w.rapidity_before) - f
        for contact, separation in zip(mine[::2], mine[1::2]):
            t0 = np.cosh(f) * contact.event.t - np.sinh(f) * contact.event.x
            t1 = np.cosh(f) * separation.event.t - np.sinh(f) * separation.event.x
            X, T = (0.0, T_L) if contact.end == "left" else (L, T_R)
            riding = (t >= t0) & (t < t1)
            theta = np.where(riding, tables.point(X, T, 0.0)[2] - f, theta)
            theta = np.where(t >= t1, separation.particle_rapidity_after - f, theta)
        out[f"{name}_E"], out[f"{name}_p"] = mass * np.cosh(theta), mass * np.sinh(theta)
    return out


# --- one speed --------------------------------------------------------------------------------------------------

#: the causal rod's material lines drawn in the diagram (the ends besides): at X = L/4, L/2, 3L/4
MATERIAL_LINES = 4


def windows(changes: np.ndarray, starts: np.ndarray, rapidities: np.ndarray) -> np.ndarray:
    """Each frame's time window as the page computes it (`frames.time_window`): from the first change to the
    last, widened by the lead from the scenario's start, clamped to [L/2, 2L] (units of L)."""
    c, s = np.cosh(rapidities)[:, None], np.sinh(rapidities)[:, None]
    times = c * changes[None, :, 1] - s * changes[None, :, 0]
    at_start = c * starts[None, :, 1] - s * starts[None, :, 0]
    first, last = times.min(axis=1), times.max(axis=1)
    lead = np.clip(first - at_start.min(axis=1), 0.5, 2.0)
    return np.column_stack([first - lead, last + lead])


def model_data(history, v: float, frames, reach: float, tolerance: float, material_tolerance: float,
               digits: int, material_digits: int, instants: int, table_rows, fixed) -> dict[str, Any]:
    """The causal rod at one speed: what the page draws and prints (the module's docstring). `frames`: the
    ledger's frames in the rigid rod's order (S', S, the others)."""
    from rodparadox.numbers import impact_name
    from rodparadox.tables.causal_ledger import event_name

    s, L = history.scenario, history.scenario.L
    sol = history.solution
    impacts = [{"label": i.label, "name": event_name(i.label), "row": impact_name(i.label), "kind": i.kind,
                "particle": i.particle, "end": i.end, "x": i.event.x / L, "t": i.event.t / L,
                "particle_before": i.particle_rapidity_before, "particle_after": i.particle_rapidity_after,
                "rod_before": i.rod_rapidity_before, "rod_after": i.rod_rapidity_after, "simultaneous_with": None}
               for i in history.impacts]
    changes = [(i.event.x, i.event.t) for i in history.impacts]
    for name in ("A", "B", "rod_left", "rod_right"):
        w = history.worldline(name)
        if w is not None:
            changes += [(e.x, e.t) for seg in w.segments for e in (seg.start, seg.end) if math.isfinite(e.t)]
    starts = [(e.x, e.t) for _, e in history.starts] + [(-L / 2, 0.0), (L / 2, 0.0)]
    changes_L, starts_L = np.array(changes) / L, np.array(starts) / L
    # the chart times every frame of the page reaches: tables over all of them (the ringing tail costs nothing)
    T_first = min(sol.plus.starts[0], sol.minus.starts[0])
    top = max(sol.plus.tail_start, sol.minus.tail_start)
    tables = ChartTables(history, T_first - 2 * L, top + 60 * L)
    speeds_ = np.concatenate([np.linspace(-reach, reach, 21), [-v]])
    f = np.arctanh(speeds_)
    spans = windows(changes_L, starts_L, f) * L
    ends = [tables.end_chart_times(X, np.concatenate([f, f]), np.concatenate([spans[:, 0], spans[:, 1]]))
            for X in (0.0, L)]
    T_lo, T_hi = min(e.min() for e in ends) - 0.5 * L, max(e.max() for e in ends) + 0.5 * L
    lines = worldlines(history, tables, T_hi, tolerance, digits)
    material = []
    for k in range(1, MATERIAL_LINES):
        X = L * k / MATERIAL_LINES
        T0 = history.material_worldline(X).segments[0].T_start
        material.append(line(tables, X, T0, T_hi, material_tolerance, material_digits))
    compression = history.fronts.compression_range()
    bound = max(abs(r) for r in history.rapidity_range())
    # the ledger: every frame's instants at once
    rapidities = np.array([fr.rapidity for fr in frames])
    spans = windows(changes_L, starts_L, rapidities) * L
    fraction = np.linspace(0.0, 1.0, instants)
    ff = np.repeat(rapidities, instants)
    tt = (spans[:, 0][:, None] + (spans[:, 1] - spans[:, 0])[:, None] * fraction[None, :]).ravel()
    sums = ledger_sums(history, tables, ff, tt)
    bodies = [n for n in ("A", "B") if f"{n}_E" in sums] + ["matter", "stress"]
    ledger = []
    for j, frame in enumerate(frames):
        rows = []
        for k in range(j * instants, (j + 1) * instants):
            rows.append([fixed(sums[f"{name}_{part}"][k]) for name in bodies for part in ("E", "p")])
        # the slices evenly spread over the window: the page reads slice k's time from the window, as it is built
        ledger.append({"u": frame.velocity + 0.0, "bodies": bodies, "slices": rows,
                       "window": [spans[j, 0] / L, spans[j, 1] / L]})
    return {
        "model": "causal", "impacts": impacts, "worldlines": lines, "material": material,
        "colour_bound": bound, "changes": [[drawn(x, digits), drawn(t, digits)] for x, t in changes_L],
        "starts": [[x, t] for x, t in starts_L],
        "tables": {"rest": table_rows(history, frames[1]), "moving": table_rows(history, frames[0])},
        "ledger": ledger, "fronts": fronts(history, tables, T_lo, T_hi),
        "cells": cells(history, tables, T_lo, T_hi, compression),
        "final": history.final_rapidity,
    }
