"""The rigid rod driven by forces at its ends (docs/model.md, "Forces at the ends"). Pure; numpy only.

Born-rigid motion is fixed by one world-line: the left end z(tau), rapidity phi(tau), tau its proper time. The
rod's "now" is the normal line through z; the material point at proper distance sigma from the left end is at
z + sigma (sinh phi, cosh phi) (as (t, x)), moves at rapidity phi and has proper acceleration alpha / (1 + alpha
sigma), alpha = d phi / d tau the left end's. A rigid material stores no strain energy (rest energy density rho0 =
M/L), so momentum balance in the momentary rest frame, (rho0 + p) alpha(sigma) = -dp/dsigma, with p(0) = F_L and
p(L) = F_R gives at every instant

    alpha (M + F_R L) = F_L - F_R,        p(sigma) = (rho0 + F_L) / (1 + alpha sigma) - rho0,

each force read at its end's event on the current normal line, at that event's time in its profile's frame. Units:
M = 1, lengths and times as the scenario's L, forces in M c^2 (a profile's value / L).

The profiles are smooth between their pieces (`ForceProfile.pieces`): the history is a chain of *stages*, each
with one piece of each end's profile, that end where an end's time reaches its profile's next piece (an event
found to rounding, never a step). A stage where both forces are constant has constant alpha: its motion is
hyperbolic (or uniform) in closed form (`ConstantStage`; material world-lines are `HyperbolicArc`s and `Line`s). Any
other stage is solved by Chebyshev collocation (`CollocatedStage`: on each step the state is the polynomial of degree
DEGREE through its values at the Chebyshev-Lobatto points, fixed by Picard iteration; a step is kept when its last
coefficients are below ODE_RTOL relative, so its dense output is the solution to that everywhere on the step),
with the momentum each agent delivered as exact integrals of the interpolants. A material world-line there is a
`DrivenArc` (`driven_worldlines`), exact to the same tolerance anywhere, in any frame.
"""

from __future__ import annotations

import bisect
import math
from dataclasses import dataclass

import numpy as np
from numpy.polynomial import chebyshev as cheb

from rodparadox.errors import ScenarioError

#: the relative tolerance of the collocated stages (issue 26: 1e-12 relative)
ODE_RTOL = 1e-13
#: the degree of the polynomial on each step
DEGREE = 20
#: halvings of a step before a stage is refused as not integrable
MAX_HALVINGS = 60
#: the most steps and stages of one history
MAX_STEPS = 20_000
#: below this |alpha| L a constant stage's material world-lines are `DrivenArc`s, not hyperbolae of radius
#: 1/|alpha|: an arc's centre that far away would cost its points their digits
CLOSED_FORM_ALPHA = 1e-3
#: Gauss-Legendre nodes per piece of a slice
GAUSS_NODES = 24
#: at most this many single instants' states kept per collocated stage: a handout asks for the same instants again
#: and again (its strips measured, then drawn; its ledger's slices; handout sears_moving --rod both: 55,688 asked,
#: 7,704 different); a state is a pure function of the instant, so a kept one is the one computed afresh
KEEP_INSTANTS = 50_000

_X = -np.cos(np.pi * np.arange(DEGREE + 1) / DEGREE)  # the Lobatto points on [-1, 1], ascending
_X[0], _X[-1] = -1.0, 1.0
_TO_COEF = np.linalg.inv(cheb.chebvander(_X, DEGREE))
_INTEGRATE = np.column_stack([cheb.chebint(unit, lbnd=-1) for unit in np.eye(DEGREE + 1)])
_S = cheb.chebvander(_X, DEGREE + 1) @ _INTEGRATE @ _TO_COEF  # values -> integral from -1 at each point
GAUSS_X, GAUSS_W = np.polynomial.legendre.leggauss(GAUSS_NODES)

#: the components of a stage's state: the left end's (t, x, phi) in S, and the (E, p) in S each agent delivered
T_, X_, PHI, EL, PL, ER, PR = range(7)


def _sinhc(y):
    """sinh(y) / y, 1 at 0 (arrays)."""
    y = np.asarray(y, dtype=float)
    small = np.abs(y) < 1e-4
    safe = np.where(small, 1.0, y)
    return np.where(small, 1.0 + y * y / 6.0, np.sinh(safe) / safe)


@dataclass(frozen=True)
class Drive:
    """One end's force: the profile in the engine's units, its frame's rapidity, and its pieces' instants."""

    end: str
    profile: object  # forces.ForceProfile (units of L and M c^2/L: the solution is for L = 1)
    frame_rapidity: float

    @property
    def bounds(self) -> tuple[float, ...]:
        return self.profile.pieces()

    def time(self, t, x):
        """The time, in the profile's frame, of the event (t, x) of S."""
        return math.cosh(self.frame_rapidity) * np.asarray(t) - math.sinh(self.frame_rapidity) * np.asarray(x)


class _Rates:
    """The right-hand side of one stage: each end on a fixed piece of its profile."""

    def __init__(self, L: float, drives: dict, pieces: dict):
        self.L, self.drives, self.pieces = L, drives, pieces

    def forces(self, t, x, phi):
        """(F_L, F_R) at the left end's state (t, x, phi) of S (arrays), each read on its stage's piece."""
        out = []
        for end in ("left", "right"):
            d = self.drives.get(end)
            if d is None:
                out.append(np.zeros_like(np.asarray(t, dtype=float)))
                continue
            if end == "left":
                tf = d.time(t, x)
            else:
                tf = d.time(np.asarray(t) + self.L * np.sinh(phi), np.asarray(x) + self.L * np.cosh(phi))
            out.append(np.asarray(d.profile.piece_value(self.pieces[end], tf), dtype=float))
        return out[0], out[1]

    def alpha(self, FL, FR):
        return (FL - FR) / (1.0 + FR * self.L)

    def __call__(self, Y: np.ndarray) -> np.ndarray:
        t, x, phi = Y[:, T_], Y[:, X_], Y[:, PHI]
        FL, FR = self.forces(t, x, phi)
        a = self.alpha(FL, FR)
        ch, sh = np.cosh(phi), np.sinh(phi)
        right = -FR * (1.0 + a * self.L)
        return np.column_stack([ch, sh, a, FL * sh, FL * ch, right * sh, right * ch])


class Stage:
    """A stretch of the history with each end's force on one piece of its profile: tau in [tau0, tau1]."""

    tau0: float
    tau1: float
    rates: _Rates

    def state(self, tau) -> np.ndarray:
        """The state (`T_` ... `PR`) at tau (an array: shape (n, 7))."""
        raise NotImplementedError

    def alpha(self, tau):
        Y = self.state(tau)
        FL, FR = self.rates.forces(Y[:, T_], Y[:, X_], Y[:, PHI])
        return self.rates.alpha(FL, FR)

    def forces(self, tau):
        Y = self.state(tau)
        return self.rates.forces(Y[:, T_], Y[:, X_], Y[:, PHI])


class ConstantStage(Stage):
    """Both forces constant: alpha constant, the left end on a hyperbola (a line for alpha = 0), in closed form."""

    def __init__(self, tau0: float, tau1: float, y0: np.ndarray, rates: _Rates, FL: float, FR: float):
        self.tau0, self.tau1, self.y0, self.rates, self.FL, self.FR = tau0, tau1, y0, rates, FL, FR
        self.a = rates.alpha(FL, FR)

    def state(self, tau) -> np.ndarray:
        s = np.atleast_1d(np.asarray(tau, dtype=float)) - self.tau0
        y0, a = self.y0, self.a
        mid = y0[PHI] + 0.5 * a * s
        k = s * _sinhc(0.5 * a * s)
        dt, dx = k * np.cosh(mid), k * np.sinh(mid)  # (sinh phi - sinh phi0)/a, (cosh phi - cosh phi0)/a
        right = -self.FR * (1.0 + a * self.rates.L)
        return np.column_stack([y0[T_] + dt, y0[X_] + dx, y0[PHI] + a * s, y0[EL] + self.FL * dx,
                                y0[PL] + self.FL * dt, y0[ER] + right * dx, y0[PR] + right * dt])

    def alpha(self, tau):
        return np.full(np.shape(np.atleast_1d(tau)), self.a)

    def forces(self, tau):
        n = np.shape(np.atleast_1d(tau))
        return np.full(n, self.FL), np.full(n, self.FR)

    def crossing(self, sigma, frame_rapidity: float, target: float):
        """The tau at which the point sigma (a number or an array) reaches the time `target` of the frame, in
        closed form (it may lie outside the stage)."""
        f, y0, a = frame_rapidity, self.y0, self.a
        sigma = np.asarray(sigma, dtype=float)
        y = y0[PHI] - f
        s0 = math.sinh(y)
        rest = target - (math.cosh(f) * y0[T_] - math.sinh(f) * y0[X_] + sigma * s0)
        if a == 0.0:
            return self.tau0 + rest / math.cosh(y)
        k = 1.0 + a * sigma
        # the point's time runs k (sinh(y + a s) - sinh y)/a = k s cosh(y + a s/2) sinhc(a s/2) after the stage's
        # start: solved in closed form where a is not small, from the uniform motion's answer where it is (the closed
        # form's asinh(...)/a would lose every digit), then polished by Newton's method (derivative k cosh(y + a s))
        with np.errstate(invalid="ignore", over="ignore"):
            s = np.where(abs(a) >= 1e-6, (np.arcsinh(s0 + a * rest / k) - y) / a, rest / (k * math.cosh(y)))
            for _ in range(3):
                g = k * s * np.cosh(y + 0.5 * a * s) * _sinhc(0.5 * a * s) - rest
                s = s - g / (k * np.cosh(y + a * s))
        return self.tau0 + s


class _Step:
    __slots__ = ("a", "b", "coef")

    def __init__(self, a: float, b: float, coef: np.ndarray):
        self.a, self.b, self.coef = a, b, coef  # coef: (DEGREE + 1, 7)


class CollocatedStage(Stage):
    """A stage solved by Chebyshev collocation: the state on each step is a polynomial in tau."""

    def __init__(self, tau0: float, steps: list[_Step], rates: _Rates, tau1: float):
        self.tau0, self.tau1, self.steps, self.rates = tau0, tau1, steps, rates
        self._starts = np.array([st.a for st in steps])
        self._coef = np.stack([st.coef for st in steps])  # (steps, DEGREE + 1, 7)
        self._ab = np.array([(st.a, st.b) for st in steps])
        self._starts_list = [st.a for st in steps]
        self._ab_list = [(st.a, st.b) for st in steps]
        self._kept: dict[float, np.ndarray] = {}  # the states of single instants asked for (`state`)
        self._coef_motion = np.ascontiguousarray(self._coef[:, :, :PHI + 1])  # (t, x, phi) alone
        self._later_starts = self._starts[1:]  # an instant's step: how many of these it has reached

    def state(self, tau, motion_only: bool = False) -> np.ndarray:
        """The state at tau; for an array and `motion_only`, the left end's (t, x, phi) alone (shape (n, 3)), the
        same numbers as the first three columns of the whole state (each column's sums are its own)."""
        if np.ndim(tau) == 0:  # one instant: the Chebyshev polynomials by their recurrence, then one product
            tau = float(tau)
            kept = self._kept.get(tau)
            if kept is None:
                kept = self._kept[tau] = self._state_at(tau)
                if len(self._kept) > KEEP_INSTANTS:
                    self._kept.clear()
            return kept.copy()
        tau = np.atleast_1d(np.asarray(tau, dtype=float))
        # the step (the last one starting at or before tau, the first before them all) and u clipped to [-1, 1], by
        # ufuncs: np.clip's Python wrapper cost a tenth of a slice's crossing
        i = np.searchsorted(self._later_starts, tau, side="right")
        a, b = self._ab[i, 0], self._ab[i, 1]
        u = np.minimum(np.maximum((2.0 * tau - a - b) / (b - a), -1.0), 1.0)[:, None]
        return _clenshaw((self._coef_motion if motion_only else self._coef)[i], u)

    def _state_at(self, tau: float) -> np.ndarray:
        i = min(max(bisect.bisect_right(self._starts_list, tau) - 1, 0), len(self.steps) - 1)
        a, b = self._ab_list[i]
        u = min(1.0, max(-1.0, (2.0 * tau - a - b) / (b - a)))
        T = [1.0, u]
        for _ in range(DEGREE - 1):
            T.append(2.0 * u * T[-1] - T[-2])
        return (np.array(T) @ self._coef[i])[None, :]

    def step_bounds(self) -> list[float]:
        return [st.a for st in self.steps[1:]]


def _clenshaw(c: np.ndarray, u: np.ndarray) -> np.ndarray:
    """sum_k c[:, k] T_k(u) by Clenshaw's recurrence, c of shape (n, DEGREE + 1, m), u of shape (n, 1).

    b1 <- c[k] + 2 u b1 - b2 in place, in three buffers: each number is the one the plain expression gives
    ((c + (2 u) b1) - b2, the sum's operands swapped, which leaves it exact), without a new array per operation (it
    halved the time of a driven rod's slice, `DrivenHistory.slice_nodes`, which runs it in every Newton step)."""
    u2 = 2.0 * u
    shape = (c.shape[0], c.shape[2])
    b1 = np.zeros(shape)
    b2 = np.zeros(shape)
    spare = np.empty(shape)
    for k in range(DEGREE, 0, -1):
        np.multiply(u2, b1, out=spare)
        np.add(spare, c[:, k, :], out=spare)
        np.subtract(spare, b2, out=spare)
        b1, b2, spare = spare, b1, b2
    return c[:, 0, :] + u * b1 - b2


def _collocate(rates: _Rates, y_a: np.ndarray, a: float, b: float) -> np.ndarray | None:
    """The state at the Lobatto points of [a, b] by Picard iteration, or None where it does not converge."""
    half = 0.5 * (b - a)
    Y = np.tile(y_a, (DEGREE + 1, 1))
    scale = np.maximum(np.abs(y_a), 1.0)
    last = math.inf
    with np.errstate(over="ignore", invalid="ignore"):
        for _ in range(60):
            new = y_a + half * (_S @ rates(Y))
            if not np.all(np.isfinite(new)):
                return None
            change = np.max(np.abs(new - Y) / np.maximum(scale, np.max(np.abs(new), axis=0)))
            Y = new
            if change <= 1e-15 or (change <= 1e-13 and change >= last):  # converged, or down to rounding
                return Y
            last = change
    return None


@dataclass
class Solution:
    stages: list
    L: float
    drives: dict
    start_time: float  # the S time of the first stage's start (the rod at rest until then)


def _end_time(drive: Drive, y: np.ndarray, L: float) -> float:
    """The end's time in its profile's frame at the state y."""
    if drive.end == "left":
        return float(drive.time(y[T_], y[X_]))
    return float(drive.time(y[T_] + L * math.sinh(y[PHI]), y[X_] + L * math.cosh(y[PHI])))


def solve(L: float, drives: dict) -> Solution:
    """The history of a rod of proper length L at rest in S (left end at x = -L/2), driven by `drives` (end ->
    Drive): a chain of stages from the first force's start until both forces have ended."""
    starts = []
    for end, d in drives.items():
        x = -0.5 * L if end == "left" else 0.5 * L
        f = d.frame_rapidity
        starts.append((d.bounds[0] + math.sinh(f) * x) / math.cosh(f))
    t0 = min(starts)
    y = np.array([t0, -0.5 * L, 0.0, 0.0, 0.0, 0.0, 0.0])
    pieces = {end: 0 for end in drives}
    tau = 0.0
    stages: list = []
    budget = MAX_STEPS
    while True:
        _advance(pieces, drives, y, L)
        pending = {end: d.bounds[pieces[end]] for end, d in drives.items() if pieces[end] < len(d.bounds)}
        rates = _Rates(L, drives, dict(pieces))
        constants = {end: d.profile.piece_constant(pieces[end]) for end, d in drives.items()}
        if all(c is not None for c in constants.values()):
            FL, FR = constants.get("left", 0.0) or 0.0, constants.get("right", 0.0) or 0.0
            stage = ConstantStage(tau, math.inf, y, rates, FL, FR)
            if not pending:
                stages.append(stage)
                break
            tau1 = min(_constant_event(stage, drives[end], target, L) for end, target in pending.items())
            stage.tau1 = max(tau1, tau)
        else:
            stage = _collocate_stage(tau, y, rates, drives, pending, L)
            budget -= len(stage.steps)
        stages.append(stage)
        budget -= 1
        if budget < 0:
            raise ScenarioError(f"the forces would need more than {MAX_STEPS:,} steps of the rigid rod's motion; "
                                f"give smoother or fewer pieces.")
        y = stage.state(stage.tau1)[0]
        tau = stage.tau1
    return Solution(stages, L, drives, t0)


def _advance(pieces: dict, drives: dict, y: np.ndarray, L: float) -> None:
    """Move each end on to its profile's next piece wherever its time has reached that piece (to rounding)."""
    for end, d in drives.items():
        now = _end_time(d, y, L)
        tolerance = 1e-13 * (L + abs(now))
        while pieces[end] < len(d.bounds) and now >= d.bounds[pieces[end]] - tolerance:
            pieces[end] += 1


def _constant_event(stage: ConstantStage, drive: Drive, target: float, L: float) -> float:
    """The tau at which the end reaches the time `target` of its profile's frame, in a constant stage."""
    return stage.crossing(0.0 if drive.end == "left" else L, drive.frame_rapidity, target)


def _collocate_stage(tau0: float, y0: np.ndarray, rates: _Rates, drives: dict, pending: dict,
                     L: float) -> CollocatedStage:
    steps: list[_Step] = []
    a, y_a = tau0, y0
    h = 0.25 * L
    halvings = 0
    while True:
        b = a + h
        Y = _collocate(rates, y_a, a, b)
        good = False
        if Y is not None:
            coef = _TO_COEF @ Y
            scale = np.maximum(np.max(np.abs(Y), axis=0), 1.0)
            scale[T_] = scale[X_] = max(L, float(np.max(np.abs(Y[:, T_]))), float(np.max(np.abs(Y[:, X_]))))
            good = bool(np.all(np.max(np.abs(coef[-3:]), axis=0) <= ODE_RTOL * scale))
        if not good:
            halvings += 1
            if halvings > MAX_HALVINGS:
                raise ScenarioError(f"the rigid rod's motion under these forces could not be integrated to "
                                    f"{ODE_RTOL:g} relative; give smoother forces.")
            h *= 0.5
            continue
        step = _Step(a, b, coef)
        steps.append(step)
        if len(steps) > MAX_STEPS:
            raise ScenarioError(f"the forces would need more than {MAX_STEPS:,} steps of the rigid rod's motion; "
                                f"give smoother or fewer pieces.")
        probe = CollocatedStage(tau0, steps, rates, b)
        hits = []
        for end, target in pending.items():
            d = drives[end]
            past = _end_time(d, Y[-1], L) >= target
            k = _first_reaching(d, Y, target, L)
            if k is not None and (not past or any(_end_time(d, y, L) < target for y in Y[k + 1:])):
                hi = a + 0.5 * (b - a) * (1.0 + _X[k])  # reached inside, then left behind: the first crossing
            elif past:
                hi = b
            else:
                continue
            hits.append(rising_root(lambda s: _end_time(d, probe.state(s)[0], L) - target, a, hi))
        if hits:
            probe.tau1 = min(hits)
            return probe
        a, y_a = b, Y[-1]
        h = 2.0 * h if halvings == 0 else h
        halvings = 0


def _first_reaching(drive: Drive, Y: np.ndarray, target: float, L: float) -> int | None:
    """The first Lobatto point of a step at which the end's time has reached `target`, or None.

    A step is solved with the stage's pieces of the profiles beyond the stage's end (the step is then cut at the
    first event), and there an extrapolated force can be strong enough for the right end to lie beyond the rod's
    horizon (1 + alpha L < 0), where its time runs backwards: an event passed inside the step may no longer show at
    its end (a step of a force profile in S' was missed so, and its end delivered 0.89 of its impulse), or the end
    may show a later crossing than the first."""
    for k in range(1, len(Y) - 1):
        if _end_time(drive, Y[k], L) >= target:
            return k
    return None


def rising_root(g, lo: float, hi: float) -> float:
    """The root of the increasing g on [lo, hi] (g(lo) <= 0 <= g(hi)), by bisection with secant steps, to
    rounding."""
    glo, ghi = g(lo), g(hi)
    if glo >= 0.0:
        return lo
    for _ in range(200):
        if hi - lo <= 4e-16 * (abs(lo) + abs(hi)) or ghi == glo:
            break
        mid = lo - glo * (hi - lo) / (ghi - glo)
        if not lo < mid < hi or _ % 3 == 2:
            mid = 0.5 * (lo + hi)
        gm = g(mid)
        if gm == 0.0:
            return mid
        if gm < 0.0:
            lo, glo = mid, gm
        else:
            hi, ghi = mid, gm
    return hi if abs(ghi) <= abs(glo) else lo
