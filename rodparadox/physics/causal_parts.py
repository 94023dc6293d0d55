"""The causal rod's (E, p) on a slice split into its matter part and its stress part (README, "The causal rod").

T = (rho + p) u u - p eta splits into matter, rho u u (rho = (M/2L)(1 + lam^2), the rest-frame energy density,
elastic energy included), and stress, p (u u - eta) (p = (M/2L)(lam^2 - 1)): densities on a slice of a frame
where the element moves at rapidity th,
  matter (rho cosh^2 th, rho cosh th sinh th),  stress (p sinh^2 th, p cosh th sinh th).
The stress part is the real, local version of the rigid model's hidden momentum (von Laue). Unlike the total
(`causal.CausalHistory.rod_energy_momentum`, one-variable integrals), these mix r+ and r-, so they are integrated
along the slice: parametrised by u (dx = exp(r+ - f) du), split at every front crossing it (lam and th jump
there), adaptive Gauss-Legendre on each smooth piece.
"""

from __future__ import annotations

import math

import numpy as np

from rodparadox.physics.ledger import EnergyMomentum

#: Gauss-Legendre nodes on each smooth piece of the slice
NODES = 16
#: each smooth piece is halved until its halves agree with it to this, relative to the rod's (E, p) (1e-10: a
#: ledger prints 4 to 6 digits, and 1e-12 costs a second a slice)
TOLERANCE = 1e-10


def _invert(F, target: float, lo: float, hi: float) -> float:
    """The s in [lo, hi] with F(s) = target, F increasing: bisection to the last bit."""
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mid in (lo, hi):
            break
        if F(mid) < target:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def rod_parts(history, frame_rapidity: float, t: float) -> tuple[EnergyMomentum, EnergyMomentum]:
    """(matter, stress) of the causal rod on the slice t of the frame of rapidity `frame_rapidity`."""
    sol, L, f = history.solution, history.scenario.L, frame_rapidity
    T_L, T_R = history.end_chart_time("left", f, t), history.end_chart_time("right", f, t)
    u_L, u_R, w_L, w_R = T_L, T_R + L, T_L, T_R - L
    ef = math.exp(f)

    def w_of(u: float) -> float:  # where the slice t' = t crosses the light line u: t' = (e^-f a + e^f b)/2
        return _invert(sol.b, (2.0 * t - sol.a(u) / ef) / ef, w_R, w_L)

    cuts = {u_L, u_R, *sol.plus.breaks(u_L, u_R)}
    for w in sol.minus.breaks(w_R, w_L):
        cuts.add(_invert(sol.a, ef * (2.0 * t - ef * sol.b(w)), u_L, u_R))
    cuts = sorted(cuts)
    nodes, weights = np.polynomial.legendre.leggauss(NODES)
    rho0 = 1.0 / L

    def gauss(lo: float, hi: float) -> np.ndarray:
        out = np.zeros(4)
        for z, wt in zip(nodes, weights):
            u = 0.5 * (lo + hi) + 0.5 * (hi - lo) * z
            rp, rm = sol.r_plus(u) - f, sol.r_minus(w_of(u)) + f
            th, lam2 = 0.5 * (rp - rm), math.exp(-(rp + rm))
            rho, p = 0.5 * rho0 * (1.0 + lam2), 0.5 * rho0 * (lam2 - 1.0)
            c, s = math.cosh(th), math.sinh(th)
            out += math.exp(rp) * 0.5 * (hi - lo) * wt * np.array([rho * c * c, rho * c * s, p * s * s, p * c * s])
        return out

    def adaptive(lo: float, hi: float, whole: np.ndarray, depth: int) -> np.ndarray:
        # a contact's decay can be steep inside a smooth piece: halve until the halves agree with the whole
        mid = 0.5 * (lo + hi)
        left, right = gauss(lo, mid), gauss(mid, hi)
        if depth >= 30 or np.max(np.abs(left + right - whole)) <= TOLERANCE * max(1.0, np.max(np.abs(whole))):
            return left + right
        return adaptive(lo, mid, left, depth + 1) + adaptive(mid, hi, right, depth + 1)

    sums = np.zeros(4)
    for lo, hi in zip(cuts, cuts[1:]):
        if hi > lo:
            sums += adaptive(lo, hi, gauss(lo, hi), 0)
    return EnergyMomentum(1.0, sums[0] - 1.0, sums[1]), EnergyMomentum(0.0, sums[2], sums[3])
