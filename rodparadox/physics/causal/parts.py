"""The causal rod's (E, p) on a slice split into its matter part and its stress part (README, "The causal rod").

T = (rho + p) u u - p eta splits into matter, rho u u (rho = (M/2L)(1 + lam^2), the rest-frame energy density,
elastic energy included), and stress, p (u u - eta) (p = (M/2L)(lam^2 - 1)): densities on a slice of a frame
where the element moves at rapidity th,
  matter (rho cosh^2 th, rho cosh th sinh th),  stress (p sinh^2 th, p cosh th sinh th).
The stress part is the real, local version of the rigid model's hidden momentum (von Laue).

Only the stress part is integrated; the matter part is the rod's exact total (`causal.CausalHistory.
rod_energy_momentum`, one-variable integrals) less it, so the two add up to the total to rounding. With
A = exp(r+ - f), B = exp(r- + f) (lam^2 = 1/AB, e^(2 th) = A/B) and dx = A du along the slice t = const, the
stress densities per du are (M/8L)(lam^2 - 1)(A/B - 2 + B/A) A and (M/8L)(lam^2 - 1)(A/B - B/A) A: exactly zero
where the rod is unstressed. They mix r+ and r- (the point w of the slice on the light line u), so they are
integrated along the slice: parametrised by u, cut at every front crossing it (lam and th jump there), Gauss-
Legendre on each smooth piece, all its nodes at once, halved until the halves agree with the whole. The w of
each node is found by Newton's method on t' = (e^-f a(u) + e^f b(w))/2 (b' = exp(r-)), kept in its piece.
"""

from __future__ import annotations

import math

import numpy as np

from rodparadox.physics.types import EnergyMomentum

#: Gauss-Legendre nodes on each smooth piece of the slice
NODES = 16
#: each smooth piece is halved until its halves agree with it to this, relative to the rod's (E, p) (1e-10: a
#: ledger prints 4 to 6 digits)
TOLERANCE = 1e-10

_Z, _W = np.polynomial.legendre.leggauss(NODES)
_SPAN = 0.5 * (1.0 + _Z)  # each node's place in its piece, 0 to 1: the first guess of its w


def _invert(F, dF, target: float, lo: float, hi: float, guess: float) -> float:
    """The s in [lo, hi] with F(s) = target, F increasing and smooth there (F' = dF): Newton's method kept inside
    a shrinking bracket (a bisection where a step would leave it), to the last bits."""
    s = min(max(guess, lo), hi)
    for _ in range(100):
        value = F(s) - target
        if value == 0.0:
            return s
        if value < 0.0:
            lo = s
        else:
            hi = s
        step = value / dF(s)
        new = s - step
        if not lo <= new <= hi:
            new = 0.5 * (lo + hi)
        if abs(new - s) <= 2.0 * math.ulp(s) or hi - lo <= 2.0 * math.ulp(s):
            return new
        s = new
    return s


def _stress(history, f: float, t: float) -> tuple[float, float]:
    """(E, p) of the stress part on the slice t of the frame of rapidity f, by quadrature."""
    sol, L = history.solution, history.scenario.L
    T_L, T_R = history.end_chart_time("left", f, t), history.end_chart_time("right", f, t)
    u_L, u_R, w_L, w_R = T_L, T_R + L, T_L, T_R - L
    ef = math.exp(f)

    def a_prime(u: float) -> float:
        return math.exp(sol.r_plus(u))

    def b_prime(w: float) -> float:
        return math.exp(sol.r_minus(w))

    def w_of(u: float, lo: float, hi: float, guess: float) -> float:  # the slice meets the light line u
        return _invert(sol.b, b_prime, (2.0 * t - sol.a(u) / ef) / ef, lo, hi, guess)

    # the cuts: every front of either family crossing the slice, as (u, w) pairs from the left end to the right
    cuts = {u_L: w_L, u_R: w_R}
    for u in sol.plus.breaks(u_L, u_R):
        cuts[u] = None
    for w in sol.minus.breaks(w_R, w_L):
        target = ef * (2.0 * t - ef * sol.b(w))
        u = _invert(sol.a, a_prime, target, u_L, u_R, u_L + (u_R - u_L) * (w_L - w) / (w_L - w_R))
        cuts[u] = w
    us = sorted(cuts)
    ws = [cuts[u] for u in us]
    for k in range(1, len(us) - 1):  # a front of r+ only: where the slice is on its other light line there
        if ws[k] is None:
            ws[k] = w_of(us[k], w_R, w_L, w_L + (w_R - w_L) * (us[k] - u_L) / (u_R - u_L))
    rho0 = 1.0 / L

    def gauss(lo: float, hi: float, w_hi: float, w_lo: float) -> np.ndarray:
        """Both densities integrated over u in [lo, hi], where w runs from w_hi down to w_lo."""
        if not hi > lo:
            return np.zeros(2)
        u = 0.5 * (lo + hi) + 0.5 * (hi - lo) * _Z
        w = np.array([w_of(float(x), w_lo, w_hi, w_hi + (w_lo - w_hi) * s) for x, s in zip(u, _SPAN)])
        r_plus = np.array([sol.r_plus(float(x)) for x in u])
        r_minus = np.array([sol.r_minus(float(x)) for x in w])
        A, B = np.exp(r_plus - f), np.exp(r_minus + f)
        lam2 = np.exp(-(r_plus + r_minus))  # of the frame-free sum: exactly 1 where unstressed, in every frame
        weight = 0.125 * rho0 * (lam2 - 1.0) * A * 0.5 * (hi - lo) * _W
        return np.array([np.sum(weight * (A / B - 2.0 + B / A)), np.sum(weight * (A / B - B / A))])

    def adaptive(lo, hi, w_hi, w_lo, whole, depth, scale) -> np.ndarray:
        # a contact's decay can be steep inside a smooth piece: halve until the halves agree with the whole
        mid = 0.5 * (lo + hi)
        w_mid = w_of(mid, w_lo, w_hi, 0.5 * (w_lo + w_hi))
        left, right = gauss(lo, mid, w_hi, w_mid), gauss(mid, hi, w_mid, w_lo)
        if depth >= 30 or np.max(np.abs(left + right - whole)) <= TOLERANCE * scale:
            return left + right
        return (adaptive(lo, mid, w_hi, w_mid, left, depth + 1, scale)
                + adaptive(mid, hi, w_mid, w_lo, right, depth + 1, scale))

    total = history.rod_energy_momentum(f, t)
    scale = max(1.0, abs(total.E), abs(total.p))
    sums = np.zeros(2)
    for k in range(len(us) - 1):
        if us[k + 1] > us[k]:
            sums += adaptive(us[k], us[k + 1], ws[k], ws[k + 1], gauss(us[k], us[k + 1], ws[k], ws[k + 1]), 0,
                             scale)
    return float(sums[0]), float(sums[1])


def rod_parts(history, frame_rapidity: float, t: float) -> tuple[EnergyMomentum, EnergyMomentum]:
    """(matter, stress) of the causal rod on the slice t of the frame of rapidity `frame_rapidity`."""
    stress_E, stress_p = _stress(history, frame_rapidity, t)
    total = history.rod_energy_momentum(frame_rapidity, t)
    return (EnergyMomentum(total.rest, total.T - stress_E, total.p - stress_p),
            EnergyMomentum(0.0, stress_E, stress_p))


# --- many slices at once: the ledger figure's curves -------------------------------------------------------------

#: the tabulated invariants: a piece's r against a(u) (or b(w)) is a cubic spline through nodes at most this far
#: apart (in units of L), halved until it meets r at the midpoints to SPLINE_TOLERANCE
SPLINE_STEP = 1.0 / 32
SPLINE_TOLERANCE = 1e-10
#: Gauss-Legendre nodes between neighbouring knots of the tables, on each slice
GAUSS = 4


def _tabulated(invariant, chart, lo: float, hi: float, L: float):
    """r of the invariant as a function of F = chart(s) (a(u) or b(w)) on [lo, hi]: a PPoly, one cubic spline per
    piece (r jumps between pieces: a front), and F at every piece boundary inside."""
    from scipy.interpolate import CubicSpline, PPoly

    cuts = set(invariant.breaks(lo, hi))
    if invariant.period is not None:  # where the periodic tail repeats, r may turn a corner the breaks do not list
        n = math.ceil((lo - invariant.tail_start) / invariant.period)
        cuts.update(s for s in invariant.tail_start + invariant.period * np.arange(max(n, 1), max(n, 1) +
                    math.ceil((hi - lo) / invariant.period) + 1) if lo < s < hi)
    cuts = [lo, *sorted(cuts), hi]
    xs, cs = [], []
    for a, b in zip(cuts, cuts[1:]):
        inside = b - 1e-12 * (b - a + L)  # r at a piece's right end is its own, not the next piece's
        grid = np.linspace(a, inside, max(4, math.ceil((b - a) / (SPLINE_STEP * L))) + 1)
        F, r = np.array([chart(x) for x in grid]), np.array([invariant.r(x) for x in grid])
        fresh = np.ones(len(grid) - 1, dtype=bool)  # intervals not yet checked
        for _ in range(40):  # halve the intervals where the spline misses r at their midpoint
            spline = CubicSpline(F, r)
            which = np.flatnonzero(fresh)
            mids = 0.5 * (grid[which + 1] + grid[which])
            F_mid = np.array([chart(m) for m in mids])
            r_mid = np.array([invariant.r(m) for m in mids])
            missed = np.abs(spline(F_mid) - r_mid) > SPLINE_TOLERANCE
            if not missed.any():
                break
            at = which[missed] + 1
            grid, F, r = (np.insert(q, at, q_mid[missed]) for q, q_mid in ((grid, mids), (F, F_mid), (r, r_mid)))
            fresh = np.zeros(len(grid) - 1, dtype=bool)
            fresh[np.concatenate([at + np.arange(len(at)) - 1, at + np.arange(len(at))])] = True  # both halves
        xs.append(spline.x[:-1])
        cs.append(spline.c)
    return PPoly(np.concatenate(cs, axis=1), np.concatenate([*xs, [chart(hi)]]))


def _end_chart_times(history, f: float, X: float, times: np.ndarray) -> np.ndarray:
    """The chart time T at which the end X (0 or L) crosses each slice t of the frame of rapidity f: on the end,
    t(T) = (e^-f a(T + X) + e^f b(T - X))/2 rises with T (dt/dT = (e^(r+ - f) + e^(r- + f))/2); read off a table of
    it between breaks, then Newton's method to the last bits."""
    sol, L = history.solution, history.scenario.L
    end = "left" if X == 0.0 else "right"
    lo, hi = (history.end_chart_time(end, f, t) for t in (times.min(), times.max()))
    ef = math.exp(f)

    def t_of(T: float) -> float:
        return 0.5 * (sol.a(T + X) / ef + ef * sol.b(T - X))

    grid = np.unique(np.concatenate([np.linspace(lo, hi, max(2, math.ceil(16 * (hi - lo) / L)) + 1),
                                     sol.breaks(X, lo, hi)]))
    t_grid = np.array([t_of(T) for T in grid])
    out = np.interp(times, t_grid, grid)
    for k, t in enumerate(times):
        j = int(np.clip(np.searchsorted(t_grid, t) - 1, 0, len(grid) - 2))
        a, b, T = grid[j], grid[j + 1], out[k]
        for _ in range(8):  # Newton inside the table's bracket (t(T) is smooth between breaks)
            slope = 0.5 * (math.exp(sol.r_plus(T + X)) / ef + ef * math.exp(sol.r_minus(T - X)))
            step = (t_of(T) - t) / slope
            T = min(max(T - step, a), b)
            if abs(step) <= 1e-15 * (abs(T) + L):
                break
        out[k] = T
    return out


def rod_parts_on_slices(history, frame_rapidity: float, times) -> tuple[np.ndarray, np.ndarray]:
    """(matter, stress): arrays (n, 2) of (E, p) of the causal rod on each slice t of `times` in the frame of
    rapidity `frame_rapidity`; matter's E includes the rod's rest energy M.

    The densities of `rod_parts`, integrated across each slice in x: a point x of the slice t lies on the light
    lines a(u) = e^f (t + x) and b(w) = e^-f (t - x), where r+ and r- are read from the invariants tabulated against
    a and b (`_tabulated`: cubic splines to 1e-10); each slice is cut at every front crossing it and into parts
    of at most PART L, GAUSS nodes each. Agrees with `rod_parts` to about 1e-9 at a few milliseconds a slice: the
    ledger figure's curves (hundreds of slices), where `rod_parts` would take a second each."""
    sol, L, f = history.solution, history.scenario.L, frame_rapidity
    times = np.asarray(times, dtype=float)
    T_L, T_R = (_end_chart_times(history, f, X, times) for X in (0.0, L))
    plus = _tabulated(sol.plus, sol.a, float(T_L.min()), float(T_R.max()) + L, L)
    minus = _tabulated(sol.minus, sol.b, float(T_R.min()) - L, float(T_L.max()), L)
    ef = math.exp(f)
    x_L = 0.5 * (np.array([sol.a(T) for T in T_L]) / ef - ef * np.array([sol.b(T) for T in T_L]))
    x_R = 0.5 * (np.array([sol.a(T + L) for T in T_R]) / ef - ef * np.array([sol.b(T - L) for T in T_R]))
    z, wz = np.polynomial.legendre.leggauss(GAUSS)
    which, lo, hi = [], [], []
    for k, t in enumerate(times):
        # the knots of both tables on this slice (the fronts among them): a(u) = F sits at x = F/e^f - t, b(w) = F
        # at x = t - e^f F; between neighbours r+ and r- are cubics
        cuts = np.concatenate([[x_L[k], x_R[k]], plus.x / ef - t, t - ef * minus.x])
        cuts = np.unique(cuts[(cuts >= x_L[k]) & (cuts <= x_R[k])])
        which.append(np.full(len(cuts) - 1, k))
        lo.append(cuts[:-1])
        hi.append(cuts[1:])
    which, lo, hi = np.concatenate(which), np.concatenate(lo), np.concatenate(hi)
    x = 0.5 * (lo + hi)[:, None] + 0.5 * (hi - lo)[:, None] * z[None]
    weight = 0.5 * (hi - lo)[:, None] * wz[None]
    t = times[which][:, None]
    rp = plus(ef * (t + x)) - f
    rm = minus((t - x) / ef) + f
    th, lam2 = 0.5 * (rp - rm), np.exp(-(rp + rm))
    rho0 = 1.0 / L
    rho, p = 0.5 * rho0 * (1.0 + lam2), 0.5 * rho0 * (lam2 - 1.0)
    c, s = np.cosh(th), np.sinh(th)
    densities = [rho * c * c, rho * c * s, p * s * s, p * c * s]
    sums = [np.bincount(which, weights=(d * weight).sum(1), minlength=len(times)) for d in densities]
    return np.column_stack(sums[:2]), np.column_stack(sums[2:])
