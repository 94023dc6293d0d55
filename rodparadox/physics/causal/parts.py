"""The causal rod's (E, p) on a slice split into its matter part and its stress part (docs/model.md, "The causal rod").

T = (rho + p) u u - p eta splits into matter, rho u u (rho = (M/2L)(1 + lam^2), the rest-frame energy density,
elastic energy included), and stress, p (u u - eta) (p = (M/2L)(lam^2 - 1)): densities on a slice of a frame
where the element moves at rapidity th,
  matter (rho cosh^2 th, rho cosh th sinh th),  stress (p sinh^2 th, p cosh th sinh th).
Together they are the rod's whole stress-energy tensor: nothing is hidden.

This is the ledger's exact integral, slice by slice (a second a slice near c): only the stress part is integrated; the matter part is the rod's exact total (`causal.CausalHistory.
rod_energy_momentum`, one-variable integrals) less it, so the two add up to the total to rounding. With
A = exp(r+ - f), B = exp(r- + f) (lam^2 = 1/AB, e^(2 th) = A/B) and dx = A du along the slice t = const, the
stress densities per du are (M/8L)(lam^2 - 1)(A/B - 2 + B/A) A and (M/8L)(lam^2 - 1)(A/B - B/A) A: exactly zero
where the rod is unstressed. They mix r+ and r- (the point w of the slice on the light line u), so they are
integrated along the slice: parametrised by u, cut at every front crossing it (lam and th jump there), Gauss-
Legendre on each smooth piece, all its nodes at once, halved until the halves agree with the whole. The w of
each node is found by Newton's method on t' = (e^-f a(u) + e^f b(w))/2 (b' = exp(r-)), kept in its piece. Many
slices at once (the ledger figure's curves, the html page) read tables of the invariants instead
(`slices.rod_parts_on_slices`), checked against this one (tests/physics/test_causal_slices.py).
"""

from __future__ import annotations

import math

import numpy as np

from rodparadox.errors import ScenarioError
from rodparadox.physics.types import EnergyMomentum

#: Gauss-Legendre nodes on each smooth piece of the slice
NODES = 16
#: each smooth piece is halved until its halves agree with it to this, relative to the rod's (E, p) (1e-10: a
#: ledger prints 4 to 6 digits)
TOLERANCE = 1e-10
#: or until they agree to this many times the rounding of the sum of the densities' magnitudes (at extreme speeds
#: the densities in a frame far from the rod's are e^(2|th|) times its rest energy, and their rounding exceeds
#: TOLERANCE: halving further would only chase that noise)
NOISE = 256.0 * np.finfo(float).eps
#: the most Gauss-Legendre pieces one slice's stress may take; more, and the slice is refused in one sentence
MAX_PIECES = 600

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

    pieces = [0, 0.0]  # Gauss-Legendre pieces taken, and the sum of the magnitudes of the densities' terms

    def gauss(lo: float, hi: float, w_hi: float, w_lo: float) -> np.ndarray:
        """Both densities integrated over u in [lo, hi], where w runs from w_hi down to w_lo."""
        if not hi > lo:
            return np.zeros(2)
        pieces[0] += 1
        if pieces[0] > MAX_PIECES:
            raise ScenarioError(f"the causal rod's stress on the slice t = {t:.6g} of a frame of velocity "
                                f"{math.tanh(f):.7g} cannot be integrated to {TOLERANCE:g} of its energy in double "
                                f"precision: its compression and this frame's speed are too extreme together; choose "
                                f"a lower v or particles nearer the rod's mass.", "v")
        u = 0.5 * (lo + hi) + 0.5 * (hi - lo) * _Z
        w = np.array([w_of(float(x), w_lo, w_hi, w_hi + (w_lo - w_hi) * s) for x, s in zip(u, _SPAN)])
        r_plus = np.array([sol.r_plus(float(x)) for x in u])
        r_minus = np.array([sol.r_minus(float(x)) for x in w])
        A, B = np.exp(r_plus - f), np.exp(r_minus + f)
        lam2 = np.exp(-(r_plus + r_minus))  # of the frame-free sum: exactly 1 where unstressed, in every frame
        weight = 0.125 * rho0 * (lam2 - 1.0) * A * 0.5 * (hi - lo) * _W
        pieces[1] += float(np.sum(np.abs(weight) * (A / B + 2.0 + B / A)))
        return np.array([np.sum(weight * (A / B - 2.0 + B / A)), np.sum(weight * (A / B - B / A))])

    def adaptive(lo, hi, w_hi, w_lo, whole, depth, scale) -> np.ndarray:
        # a contact's decay can be steep inside a smooth piece: halve until the halves agree with the whole
        mid = 0.5 * (lo + hi)
        w_mid = w_of(mid, w_lo, w_hi, 0.5 * (w_lo + w_hi))
        left, right = gauss(lo, mid, w_hi, w_mid), gauss(mid, hi, w_mid, w_lo)
        if depth >= 30 or np.max(np.abs(left + right - whole)) <= max(TOLERANCE * scale, NOISE * pieces[1]):
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
