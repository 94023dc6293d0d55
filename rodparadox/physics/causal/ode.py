"""The causal rod's contact equation d psi/dT = -c sinh(psi - in(T)) where `in` varies, solved by Chebyshev
collocation (docs/model.md, "The causal rod"). Pure; numpy only.

Why not a general integrator (scipy's `solve_ivp`, which this replaced): importing `scipy.integrate` costs
0.35-0.45 s a process (it pulls scipy.special and scipy.optimize), more than the whole rest of the causal rod's
plot, for one scalar equation whose input is smooth on each of its pieces. No closed form covers it: with
y = e^psi it is the Riccati equation y' = (c/2)(e^in - e^-in y^2), solved in closed form for a constant `in`
(`causal_solve._Contact`), but `in` is the other end's output a crossing earlier, itself a contact's decay or an
earlier solution of this equation, and the linear form v'' + in' v' - (c/2)^2 v = 0 has no elementary solution
for those. Spectral collocation is short, implicit (a stiff contact, c large, needs no tiny steps) and gives its
dense output and the integrals of exp(+-out) to rounding for free.

A step [a, b]: psi is the polynomial of degree N through its values at the N + 1 Chebyshev-Lobatto points, fixed
by the collocation equations Psi = psi_a + S f(Psi) (S integrates the interpolant exactly from a), solved by
Newton's method. The step is kept when the last Chebyshev coefficients of psi, exp(out) and exp(-out) are below
ODE_RTOL relative (their interpolants then are the functions to rounding everywhere on the step), else halved;
the integrals of exp(+-out) are the exact integrals of their interpolants. The contact's end (delta = psi - in
falling to 0: the particle leaves) is a root of the dense solution found by bisection to the last bit, checked
at every node of every step: an event, never a step.
"""

from __future__ import annotations

import bisect

import numpy as np
from numpy.polynomial import chebyshev as cheb

from rodparadox.errors import ScenarioError

#: the relative tolerance of the contact equation (issue 16: 1e-12 relative)
ODE_RTOL = 1e-12
#: the degree of the polynomial on each step
DEGREE = 20
#: the machine epsilon
EPS = float(np.finfo(float).eps)
#: halvings of a step before the equation is refused as not integrable
MAX_HALVINGS = 60
#: a contact's output reads its input (the other end's output a crossing earlier, itself perhaps a contact's) at
#: every point: a long contact between heavy particles (hundreds of crossings) would make each reading walk back
#: through all of them. Past this many contacts in a chain, the output is read from its own polynomial instead
MAX_DEPTH = 32

_X = -np.cos(np.pi * np.arange(DEGREE + 1) / DEGREE)  # the Lobatto points on [-1, 1], ascending
_X[0], _X[-1] = -1.0, 1.0
_TO_COEF = np.linalg.inv(cheb.chebvander(_X, DEGREE))  # values at the points -> Chebyshev coefficients
_INTEGRATE = np.column_stack([cheb.chebint(unit, lbnd=-1) for unit in np.eye(DEGREE + 1)])  # coef -> primitive
_S = cheb.chebvander(_X, DEGREE + 1) @ _INTEGRATE @ _TO_COEF  # values -> integral from -1 at each point
_EYE = np.eye(DEGREE + 1)


def _clenshaw(coef: list[float], x: float) -> float:
    """sum c_k T_k(x), for one x (plain floats: faster than numpy for a scalar)."""
    b1 = b2 = 0.0
    x2 = 2.0 * x
    for c in coef[:0:-1]:
        b1, b2 = c + x2 * b1 - b2, b1
    return coef[0] + x * b1 - b2


class Step:
    """One kept step: [a, b], psi's coefficients and the primitives (from a) of exp(out) and exp(-out)."""

    __slots__ = ("a", "b", "psi", "plus", "minus", "plus0", "minus0", "out")

    def __init__(self, a, b, psi, plus, minus, plus0, minus0, out=None):
        self.a, self.b, self.psi, self.plus, self.minus, self.out = a, b, psi, plus, minus, out
        self.plus0, self.minus0 = plus0, minus0  # the integrals from the piece's start to a

    def x(self, s: float) -> float:
        return min(1.0, max(-1.0, (2.0 * s - self.a - self.b) / (self.b - self.a)))


def _place(st: Step, s: float) -> float:
    """`st.x(s)`, the same float, without the calls (min(1, max(-1, x)), NaN to -1 as there): the scalar chart
    map reads a step at every step of every search."""
    x = (2.0 * s - st.a - st.b) / (st.b - st.a)
    return x if -1.0 < x < 1.0 else (1.0 if x >= 1.0 else -1.0)


class Solved:
    """An end in contact while its input varies: psi, out = in - 2 psi and the integrals of exp(+-out) from lo,
    on [lo, hi], as polynomials on steps (the dense solution)."""

    form = "solved"

    def __init__(self, lo: float, hi: float, r_in, steps: list[Step], depth: int = 1):
        self.lo, self.hi, self.r_in, self.steps, self.depth = lo, hi, r_in, steps, depth
        self._starts = [st.a for st in steps]

    def _step(self, s: float) -> Step:
        k = bisect.bisect_right(self._starts, s) - 1
        return self.steps[k if k > 0 else 0]

    def psi(self, s: float) -> float:
        st = self._step(s)
        return _clenshaw(st.psi, _place(st, s))

    def r(self, s: float) -> float:
        if self.depth > MAX_DEPTH:  # its own polynomial: reading the input would read every earlier contact's
            st = self._step(s)
            return _clenshaw(st.out, _place(st, s))
        st = self._step(s)
        return self.r_in(s) - 2.0 * _clenshaw(st.psi, _place(st, s))  # r_in - 2 psi

    def ep(self, s: float) -> float:
        st = self._step(s)
        return st.plus0 + 0.5 * (st.b - st.a) * _clenshaw(st.plus, _place(st, s))

    def em(self, s: float) -> float:
        st = self._step(s)
        return st.minus0 + 0.5 * (st.b - st.a) * _clenshaw(st.minus, _place(st, s))


def _tail(coef: np.ndarray, scale: float, noise: float = 0.0) -> bool:
    """The interpolant is the function to the tolerance (relative to `scale`, or the input's own `noise` where
    that is larger): its last three coefficients are negligible."""
    return float(np.max(np.abs(coef[-3:]))) <= max(ODE_RTOL, noise) * scale


def _roughness(inp, lo: float, hi: float) -> float:
    """Ten times the rounding noise of the input (in units of r): its last Chebyshev coefficients on spans far too
    short for the smooth part to reach them, at the start, the middle and the end. No step makes the solution
    smoother than its input: where the input is known to less than the tolerance (a contact's closed form near
    lam's extremes loses digits), this sets the tolerance instead."""
    span = 1e-9 * (hi - lo)
    worst = 0.0
    for a in (lo, 0.5 * (lo + hi) - 0.5 * span, hi - span):
        r_in = np.array([inp.r(float(x)) for x in a + 0.5 * span * (_X + 1.0)])
        worst = max(worst, float(np.max(np.abs((_TO_COEF @ r_in)[-3:]))))
    return 10.0 * worst


def _collocate(r_in: np.ndarray, psi_a: float, half: float, c: float) -> np.ndarray | None:
    """psi at the points of a step of half-width `half`, by Newton's method on the collocation equations."""
    psi = np.full(DEGREE + 1, psi_a)
    with np.errstate(over="ignore", invalid="ignore"):  # a step too long diverges: it is halved
        return _newton(psi, r_in, psi_a, half, c)


def _newton(psi: np.ndarray, r_in: np.ndarray, psi_a: float, half: float, c: float) -> np.ndarray | None:
    for _ in range(40):
        d = psi - r_in
        residual = psi - psi_a + half * c * (_S @ np.sinh(d))
        jacobian = _EYE + half * c * _S * np.cosh(d)[None, :]
        try:
            change = np.linalg.solve(jacobian, residual)
        except np.linalg.LinAlgError:
            return None
        if not np.all(np.isfinite(change)):
            return None
        psi -= change
        if float(np.max(np.abs(change))) <= 4e-16 * (1.0 + float(np.max(np.abs(psi)))):
            return psi
    return None


def solve_contact(lo: float, hi: float, inp, psi0: float, c: float, L: float = 1.0,
                  budget=None) -> tuple[Solved, float | None]:
    """Integrate d psi/dT = -c sinh(psi - in(T)) from lo (psi = psi0, psi0 > in(lo)) to hi, stopping where
    delta = psi - in falls to 0 (the end unstressed: the particle leaves). `inp.r` is in(T), smooth on [lo, hi].
    Returns the dense solution and the chart time of the separation (None when the contact lasts to hi), found to
    rounding relative to the rod's length L (chart times scale with it, from 1e-100 to 1e100). `budget`: a
    `budget.Budget` each step tried is spent from, or None."""
    steps: list[Step] = []
    a, psi_a, plus0, minus0 = lo, psi0, 0.0, 0.0
    h = hi - lo
    halvings = 0
    noise = _roughness(inp, lo, hi)
    base = getattr(inp, "base", inp)
    depth = 1 + getattr(base, "depth", 0)
    while a < hi:
        if budget is not None:
            budget.spend()
        b = hi if a + h >= hi else a + h
        s = a + 0.5 * (b - a) * (_X + 1.0)
        s[0], s[-1] = a, b
        r_in = np.array([inp.r(float(x)) for x in s])
        psi = _collocate(r_in, psi_a, 0.5 * (b - a), c)
        if psi is not None:
            out = r_in - 2.0 * psi
            ep, em = np.exp(out), np.exp(-out)
            cp, cep, cem = _TO_COEF @ psi, _TO_COEF @ ep, _TO_COEF @ em
            good = (_tail(cp, max(1.0, float(np.max(np.abs(psi)))), noise) and _tail(cep, float(np.max(ep)), noise)
                    and _tail(cem, float(np.max(em)), noise))
        if psi is None or not good:
            halvings += 1
            if halvings > MAX_HALVINGS:
                raise ScenarioError("the contact of a particle with the rod could not be integrated to "
                                    f"{ODE_RTOL:g} relative; this scenario is beyond the tool's precision.")
            h = 0.5 * (b - a)
            continue
        step = Step(a, b, cp.tolist(), cheb.chebint(cep, lbnd=-1).tolist(), cheb.chebint(cem, lbnd=-1).tolist(),
                    plus0, minus0, (_TO_COEF @ out).tolist() if depth > MAX_DEPTH else None)
        steps.append(step)
        below = np.nonzero(psi[1:] - r_in[1:] <= 0.0)[0]
        if below.size:  # the end falls unstressed inside this step: the separation, to the last bit
            j = int(below[0]) + 1
            solved = Solved(lo, b, inp.r, steps, depth)
            T_sep = falling_root(lambda T: solved.psi(T) - inp.r(T), float(s[j - 1]), float(s[j]), 4 * EPS * L)
            solved.hi = T_sep
            return solved, T_sep
        plus0 += 0.5 * (b - a) * _clenshaw(step.plus, 1.0)
        minus0 += 0.5 * (b - a) * _clenshaw(step.minus, 1.0)
        a, psi_a = b, float(psi[-1])
        h = 2.0 * (b - step.a) if halvings == 0 else b - step.a  # grow while the first try is kept
        halvings = 0
    return Solved(lo, hi, inp.r, steps, depth), None


def falling_root(g, lo: float, hi: float, xtol: float = 4 * EPS, rtol: float = 4 * EPS) -> float:
    """A root of g in [lo, hi], g(lo) > 0 >= g(hi) (a contact's start or end), by Brent's method (R. P. Brent,
    "Algorithms for minimization without derivatives", 1973, ch. 4: inverse interpolation kept inside a shrinking
    bracket, bisection where it would not shrink fast): to xtol + rtol |root|. Bisection alone stops where the
    rounding noise of g changes sign, a few ulps off the root; interpolation across a wider bracket does not."""
    x_pre, x_cur = lo, hi
    f_pre, f_cur = g(x_pre), g(x_cur)
    if f_pre == 0.0:
        return x_pre
    if f_cur == 0.0:
        return x_cur
    x_blk = f_blk = s_pre = s_cur = 0.0
    for _ in range(100):
        if f_pre != 0.0 and f_cur != 0.0 and (f_pre < 0.0) != (f_cur < 0.0):
            x_blk, f_blk = x_pre, f_pre
            s_pre = s_cur = x_cur - x_pre
        if abs(f_blk) < abs(f_cur):
            x_pre, x_cur, x_blk = x_cur, x_blk, x_cur
            f_pre, f_cur, f_blk = f_cur, f_blk, f_cur
        delta = 0.5 * (xtol + rtol * abs(x_cur))
        s_bis = 0.5 * (x_blk - x_cur)
        if f_cur == 0.0 or abs(s_bis) < delta:
            return x_cur
        if abs(s_pre) > delta and abs(f_cur) < abs(f_pre):
            if x_pre == x_blk:  # secant
                s_try = -f_cur * (x_cur - x_pre) / (f_cur - f_pre)
            else:  # inverse quadratic
                d_pre = (f_pre - f_cur) / (x_pre - x_cur)
                d_blk = (f_blk - f_cur) / (x_blk - x_cur)
                s_try = -f_cur * (f_blk * d_blk - f_pre * d_pre) / (d_blk * d_pre * (f_blk - f_pre))
            if 2.0 * abs(s_try) < min(abs(s_pre), 3.0 * abs(s_bis) - delta):
                s_pre, s_cur = s_cur, s_try
            else:
                s_pre = s_cur = s_bis
        else:
            s_pre = s_cur = s_bis
        x_pre, f_pre = x_cur, f_cur
        x_cur += s_cur if abs(s_cur) > delta else (delta if s_bis > 0.0 else -delta)
        f_cur = g(x_cur)
    return x_cur


# the collocation's pieces, public for the other boundary equation solved the same way (`causal.driven`, an end
# driven by a force)
LOBATTO, TO_COEFFICIENTS, INTEGRATE_FROM_START, PRIMITIVE = _X, _TO_COEF, _S, _INTEGRATE
clenshaw, roughness, negligible_tail = _clenshaw, _roughness, _tail
