"""The causal rod's (E, p) on slices split into its matter part and its stress part, and its material points' rest
mass in motion (docs/model.md, "The causal rod"). Pure: numpy. The one integral across the rod of every consumer:
the ledger (one slice at a time), the ledger figure's curves and the html page (hundreds of slices at once).

T = (rho + p) u u - p eta splits into matter, rho u u (rho = (M/2L)(1 + lam^2), the rest-frame energy density,
elastic energy included), and stress, p (u u - eta) (p = (M/2L)(lam^2 - 1)): densities on a slice of a frame where
the element moves at rapidity th,
  matter (rho cosh^2 th, rho cosh th sinh th),  stress (p sinh^2 th, p cosh th sinh th).
Together they are the rod's whole stress-energy tensor: nothing is hidden.

Each slice is integrated over the rod's material labels X, 0 to L: with A = exp(r+ - f), B = exp(r- + f) (so
lam^2 = 1/AB, e^(2 th) = A/B) the slice's length element is dx = 2AB/(A + B) dX = dX/(lam cosh th), and per dX
  stress (p (A - B)^2 / 2(A + B), p (A - B)/2),  matter (rho (A + B)/2, rho (A - B)/2),
  rest mass in motion (M/L)(cosh th, sinh th),
bounded wherever lam and th are, however fast the element moves in the frame. (Along x or along one light line a
contact's steep start is squeezed into a sliver that a quadrature may step over; over X neither family is squeezed:
|du/dX| and |dw/dX| are below 2.) Where X meets the slice, its chart time T solves
  t = (e^-f a(T + X) + e^f b(T - X))/2,  dt/dT = (A + B)/2 > 0,
with |dT/dX| < 1 (the slice is space-like), which brackets T from the ends of each smooth piece: Newton's method
inside that bracket (`arrays.solve_increasing`). The slice is cut where a front crosses it (lam and th jump there)
and into stretches at most STRETCH L long; Gauss-Kronrod's 15 nodes on each stretch of every slice at once, each
stretch halved until Gauss-Legendre's 7 among them agree with the 15 to TOLERANCE (or to a few hundred roundings of
its densities' size, or, where halving gains nothing, to the engine's own rounding: ROUNDING).
The invariants and the chart map are the engine's own, for whole arrays (`arrays.Arrays`): nothing tabulated.

Only the stress is integrated so: the matter part is the rod's exact total less it (one-variable integrals,
`CausalHistory.rod_energy_momentum`, here for arrays), so the two add up to the total to rounding.
"""

from __future__ import annotations

import math

import numpy as np

from rodparadox.errors import BeyondBounds
from rodparadox.physics.causal.arrays import solve_increasing
from rodparadox.physics.types import EnergyMomentum

#: the longest stretch of a slice (units of L); each is summed by Gauss-Kronrod's 15 nodes, the 7 of Gauss-Legendre
#: among them telling its error
STRETCH = 0.25
#: each stretch is halved until its Gauss-Legendre and Gauss-Kronrod sums agree to this (M c^2; the ledger prints 4
#: to 6 digits, the tests ask 1e-10 of every slice), or to NOISE times the sum of its densities' magnitudes (their
#: rounding: in a frame far from the rod's, densities are e^(2|th|) times its rest energy)
TOLERANCE = 1e-12
NOISE = 256.0 * np.finfo(float).eps
#: where halving a stretch no longer shrinks its miss fourfold (a smooth stretch's shrinks 2^14-fold), what is
#: left is the engine's own rounding (a contact's closed form near extreme compression, v near c, keeps r to fewer
#: digits): the stretch is kept once its miss is below this times its densities' size
ROUNDING = 1e-9
#: halvings of one stretch at most, and the most stretches the slices of one call may take: past it, `BeyondBounds`
MAX_DEPTH = 40
MAX_STRETCHES = 20000

#: Gauss-Kronrod's 15 nodes on [-1, 1] and their weights, with Gauss-Legendre's 7 weights (on every other node)
_K = (0.991455371120812639206854697526329, 0.949107912342758524526189684047851, 0.864864423359769072789712788640926,
      0.741531185599394439863864773280788, 0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
      0.207784955007898467600689403773245)
_KW = (0.022935322010529224963732008058970, 0.063092092629978553290700663189204, 0.104790010322250183839876322541518,
       0.140653259715525918745189590510238, 0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
       0.204432940075298892414161999234649)
_GW = (0.129484966168869693270611432679082, 0.279705391489276667901467771423780, 0.381830050505118944950369775488975)
_Z = np.array([-z for z in _K] + [0.0] + list(reversed(_K)))
_W = np.array(list(_KW) + [0.209482141084727828012999174891714] + list(reversed(_KW)))
_G = np.array([0.0, _GW[0], 0.0, _GW[1], 0.0, _GW[2], 0.0, 0.417959183673469387755102040816327,
               0.0, _GW[2], 0.0, _GW[1], 0.0, _GW[0], 0.0])
NODES = len(_Z)
#: the polynomial through values at a stretch's nodes, read at its halves' nodes (each row a node of the half)
_TO_LEFT, _TO_RIGHT = (np.polynomial.legendre.legvander(0.5 * (_Z + side), NODES - 1)
                       @ np.linalg.inv(np.polynomial.legendre.legvander(_Z, NODES - 1)) for side in (-1.0, 1.0))


class _Slices:
    """Slices (f[k], t[k]) across one run's causal rod: where its ends are on each, and its smooth pieces."""

    def __init__(self, history, f, t):
        self.t = np.atleast_1d(np.asarray(t, dtype=float))
        self.f = np.broadcast_to(np.asarray(f, dtype=float), self.t.shape).copy()
        self.arrays, self.L = history.arrays, history.scenario.L
        self.sol = history.solution
        n = len(self.t)
        ends = self.chart_time(np.concatenate([np.zeros(n), np.full(n, self.L)]), np.concatenate([self.t, self.t]),
                               np.concatenate([self.f, self.f]))
        self.T_L, self.T_R = ends[:n], ends[n:]

    def chart_time(self, X: np.ndarray, t: np.ndarray, f: np.ndarray) -> np.ndarray:
        """The chart time where material line X[j] crosses the slice t[j] of the frame f[j]: from where it would be in
        the rod at rest (T cosh f - (X - L/2) sinh f = t), bracketed by doubling, then Newton."""
        k = np.arange(len(t))
        equation = _slice_equation(self.arrays, t, f, X)
        guess = (t + (X - 0.5 * self.L) * np.sinh(f)) / np.cosh(f)
        lo, hi = guess - self.L, guess + self.L
        for _ in range(200):
            below, above = equation(lo, k)[0] > 0.0, equation(hi, k)[0] < 0.0
            if not (below.any() or above.any()):
                break
            lo, hi = np.where(below, 2 * lo - hi, lo), np.where(above, 2 * hi - lo, hi)
        return solve_increasing(equation, lo, hi, np.clip(guess, lo, hi), self.L)

    def pieces(self) -> tuple[np.ndarray, ...]:
        """The smooth pieces of every slice between the fronts crossing it: (slice, X, T at its start, X, T at its
        end), arrays in slice order then X."""
        ef = np.exp(self.f)
        u_L, u_R, w_L, w_R = self.T_L, self.T_R + self.L, self.T_L, self.T_R - self.L
        cut_k, cut_u, cut_w, which = [], [], [], []
        for k in range(len(self.t)):
            for u in _breaks(self.sol.plus, u_L[k], u_R[k]):
                cut_k.append(k), cut_u.append(u), cut_w.append(math.nan), which.append(0)
            for w in _breaks(self.sol.minus, w_R[k], w_L[k]):
                cut_k.append(k), cut_u.append(math.nan), cut_w.append(w), which.append(1)
        cut_k, cut_u, cut_w, which = np.array(cut_k, dtype=int), np.array(cut_u), np.array(cut_w), np.array(which)
        if len(cut_k):
            on_u, on_w = which == 0, which == 1
            k, e = cut_k[on_u], ef[cut_k[on_u]]  # a front of r+: the slice's w there, b(w) = e^-f (2t - e^-f a(u))
            cut_w[on_u] = self.arrays.inverse("minus", (2 * self.t[k] - self.arrays.plus(cut_u[on_u])[1] / e) / e,
                                              w_R[k], w_L[k])
            k, e = cut_k[on_w], ef[cut_k[on_w]]  # a front of r-: a(u) = e^f (2t - e^f b(w))
            cut_u[on_w] = self.arrays.inverse("plus", e * (2 * self.t[k] - e * self.arrays.minus(cut_w[on_w])[1]),
                                              u_L[k], u_R[k])
        n = len(self.t)
        ks = np.concatenate([np.arange(n), cut_k, np.arange(n)])
        Xs = np.concatenate([np.zeros(n), np.clip(0.5 * (cut_u - cut_w), 0.0, self.L), np.full(n, self.L)])
        Ts = np.concatenate([self.T_L, 0.5 * (cut_u + cut_w), self.T_R])
        order = np.lexsort((Xs, ks))
        ks, Xs, Ts = ks[order], Xs[order], Ts[order]
        keep = (ks[1:] == ks[:-1]) & (Xs[1:] > Xs[:-1])
        return ks[:-1][keep], Xs[:-1][keep], Ts[:-1][keep], Xs[1:][keep], Ts[1:][keep]

    def integrate(self, densities, columns: int) -> np.ndarray:
        """(slices, columns): each slice's integral over X of `densities(A, B, th, lam2, L)` (an (nodes, columns)
        array per dX), stretch by stretch, each halved until its halves agree with it."""
        k, Xa, Ta, Xb, Tb = self.pieces()
        n = np.maximum(1, np.ceil((Xb - Xa) / (STRETCH * self.L))).astype(int)
        if n.sum() > MAX_STRETCHES:
            raise BeyondBounds(f"{MAX_STRETCHES} stretches of slices to add up the rod's stress")
        piece = np.repeat(np.arange(len(k)), n)
        j = np.arange(len(piece)) - np.repeat(np.cumsum(n) - n, n)
        lo = Xa[piece] + (Xb - Xa)[piece] * j / n[piece]
        hi = np.where(j + 1 == n[piece], Xb[piece], Xa[piece] + (Xb - Xa)[piece] * (j + 1) / n[piece])
        anchors = (k, Xa, Ta, Xb, Tb)
        total = np.zeros((len(self.t), columns))
        spent = len(piece)
        guess, before = None, np.full(len(piece), np.inf)  # each stretch's parent's miss
        for depth in range(MAX_DEPTH + 1):
            kronrod, gauss, size, T = self._gauss(anchors, piece, lo, hi, densities, guess)
            miss = np.max(np.abs(kronrod - gauss), axis=1)
            # to the tolerance, or to the densities' rounding; or, where halving gains nothing, the engine's
            stalled = (miss >= 0.25 * before) & (miss <= ROUNDING * size)
            good = (miss <= np.maximum(TOLERANCE, NOISE * size)) | stalled | (depth == MAX_DEPTH)
            np.add.at(total, k[piece[good]], kronrod[good])
            bad = np.flatnonzero(~good)
            if not bad.size:
                break
            spent += 2 * bad.size
            if spent > MAX_STRETCHES:
                raise BeyondBounds(f"{MAX_STRETCHES} stretches of slices to add up the rod's stress")
            mid = 0.5 * (lo[bad] + hi[bad])
            piece = np.concatenate([piece[bad]] * 2)
            lo, hi = np.concatenate([lo[bad], mid]), np.concatenate([mid, hi[bad]])
            # the halves' nodes' chart times first guessed from the whole's: T(X) is smooth on a stretch
            guess = np.concatenate([T[bad] @ _TO_LEFT.T, T[bad] @ _TO_RIGHT.T])
            before = np.concatenate([miss[bad], miss[bad]])
        return total

    def _gauss(self, anchors, piece, lo, hi, densities, guess=None) -> tuple[np.ndarray, ...]:
        """Gauss-Kronrod's and Gauss-Legendre's sums of the densities on each stretch [lo, hi] of X of its piece, the
        sums of their magnitudes, and the nodes' chart times (stretches, NODES) (`guess`: a first guess of them)."""
        k, Xa, Ta, Xb, Tb = (a[piece] for a in anchors)
        X = (0.5 * (lo + hi))[:, None] + (0.5 * (hi - lo))[:, None] * _Z[None, :]
        half = 0.5 * (hi - lo)
        kk = np.repeat(k, NODES)
        X = X.ravel()
        Xa, Ta, Xb, Tb = (np.repeat(a, NODES) for a in (Xa, Ta, Xb, Tb))
        # |dT/dX| < 1 along the slice: T lies within X's distance of each end's T
        T_lo = np.maximum(Ta - (X - Xa), Tb - (Xb - X))
        T_hi = np.minimum(Ta + (X - Xa), Tb + (Xb - X))
        if guess is None:
            guess = Ta + (Tb - Ta) * (X - Xa) / np.where(Xb > Xa, Xb - Xa, 1.0)
        keep = (np.empty_like(X), np.empty_like(X))  # r+ and r- where each root was found
        equation = _slice_equation(self.arrays, self.t[kk], self.f[kk], X, keep)
        T = solve_increasing(equation, np.minimum(T_lo, T_hi), np.maximum(T_lo, T_hi), np.ravel(guess), self.L)
        fk = self.f[kk]
        r_plus, r_minus = keep[0] - fk, keep[1] + fk
        A, B = np.exp(r_plus), np.exp(r_minus)
        values = densities(A, B, 0.5 * (r_plus - r_minus), np.exp(-(r_plus + r_minus)), self.L)
        values = values.reshape(len(piece), NODES, values.shape[1]) * half[:, None, None]
        kronrod = np.einsum("snc,n->sc", values, _W)
        gauss = np.einsum("snc,n->sc", values, _G)
        size = np.einsum("snc,n->s", np.abs(values), _W)
        return kronrod, gauss, size, T.reshape(len(piece), NODES)

    def totals(self) -> tuple[np.ndarray, np.ndarray]:
        """The rod's exact (E - M, p) on each slice (as `CausalHistory.rod_energy_momentum`, for arrays)."""
        L, f, arrays, sol = self.L, self.f, self.arrays, self.sol
        I_plus = arrays.minus_integral(sol.plus, self.T_R + L) - arrays.minus_integral(sol.plus, self.T_L)
        I_minus = arrays.minus_integral(sol.minus, self.T_L) - arrays.minus_integral(sol.minus, self.T_R - L)
        ef = np.exp(f)
        x_L = 0.5 * (arrays.plus(self.T_L)[1] / ef - ef * arrays.minus(self.T_L)[1])
        x_R = 0.5 * (arrays.plus(self.T_R + L)[1] / ef - ef * arrays.minus(self.T_R - L)[1])
        rho0 = 1.0 / L
        E = 0.5 * rho0 * (x_R - x_L) + 0.25 * rho0 * (ef * I_plus + I_minus / ef)
        return E - 1.0, 0.25 * rho0 * (I_minus / ef - ef * I_plus)


def _slice_equation(arrays, t: np.ndarray, f: np.ndarray, X: np.ndarray, keep=None):
    """The slices' equation t = (e^-f a(T + X) + e^f b(T - X))/2 for material lines X on slices (t, f) (arrays, one
    entry a root): values, slopes (A + B)/2 and sizes at chart times T of the entries `index`, as
    `arrays.solve_increasing` asks; r+ and r- there are written into `keep` (two arrays), where given."""
    ef = np.exp(f)

    def value_and_slope(T, index):
        XX, e = X[index], ef[index]
        r_plus, a = arrays.plus(T + XX)
        r_minus, b = arrays.minus(T - XX)
        if keep is not None:
            keep[0][index], keep[1][index] = r_plus, r_minus
        U, V, ti = 0.5 * a / e, 0.5 * e * b, t[index]
        return U + V - ti, 0.5 * (np.exp(r_plus) / e + e * np.exp(r_minus)), np.abs(U) + np.abs(V) + np.abs(ti)
    return value_and_slope


def _breaks(invariant, lo: float, hi: float) -> list[float]:
    """Where the invariant may jump or kink in (lo, hi): its breaks, and the seams of its periodic tail (each period
    read from the first, which need not join smoothly onto what precedes it)."""
    out = invariant.breaks(lo, hi)
    if invariant.period is not None:
        n = max(1, math.ceil((lo - invariant.tail_start) / invariant.period))
        while (seam := invariant.tail_start + n * invariant.period) < hi:
            if seam > lo:
                out.append(seam)
            n += 1
    return out


def _stress_densities(A, B, th, lam2, L) -> np.ndarray:
    p = 0.5 / L * (lam2 - 1.0)
    return np.stack([p * (A - B) ** 2 / (2.0 * (A + B)), 0.5 * p * (A - B)], axis=1)


def _motion_densities(A, B, th, lam2, L) -> np.ndarray:
    return np.stack([np.cosh(th) / L, np.sinh(th) / L], axis=1)


def rod_parts_on_slices(history, frame_rapidity, times) -> tuple[np.ndarray, np.ndarray]:
    """(matter, stress): arrays (n, 2) of (E, p) of the causal rod on each slice (frame_rapidity[k], times[k]) (either
    may be one number for every slice); matter's E includes the rod's rest energy M (M = 1)."""
    slices = _Slices(history, frame_rapidity, times)
    stress = slices.integrate(_stress_densities, 2)
    kinetic, p = slices.totals()
    matter = np.column_stack([1.0 + (kinetic - stress[:, 0]), p - stress[:, 1]])
    return matter, stress


def rod_parts(history, frame_rapidity: float, t: float) -> tuple[EnergyMomentum, EnergyMomentum]:
    """(matter, stress) of the causal rod on the slice t of the frame of rapidity `frame_rapidity`."""
    slices = _Slices(history, frame_rapidity, t)
    stress_E, stress_p = slices.integrate(_stress_densities, 2)[0]
    kinetic, p = (float(v[0]) for v in slices.totals())
    return (EnergyMomentum(1.0, kinetic - float(stress_E), p - float(stress_p)),
            EnergyMomentum(0.0, float(stress_E), float(stress_p)))


def rest_mass_motion(history, frame_rapidity, times) -> np.ndarray:
    """(n, 2): (E, p) of the rod's material points' rest mass moving at their own velocities on each slice,
    (M/L) int_0^L (cosh th, sinh th) dX (M = 1), th the rapidity of material point X where it crosses the slice."""
    return _Slices(history, frame_rapidity, times).integrate(_motion_densities, 2)
