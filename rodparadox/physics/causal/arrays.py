"""The causal rod's invariants and chart map for whole arrays of chart times at once, exactly (docs/model.md, "The
causal rod"). Pure: numpy.

The engine (`solve`) gives r+(u), r-(w) and the chart map a(u), b(w) one scalar call at a time, from its pieces:
constants, contacts in closed form, views of other pieces (an input read at the other end, a free end's output)
and contacts solved by collocation (`ode.Solved`, polynomials on steps). `Arrays` evaluates the same pieces, with
the same formulas, for numpy arrays: each chart time is sent to its piece (and, after the last separation, moved
into the first period, as `solve.Invariant` does), then every piece evaluates its chart times at once. The values
are the engine's to rounding: no table, no fit, nothing to tune. A piece names its kind (`form`).
"""

from __future__ import annotations

import numpy as np

_EPS = float(np.finfo(float).eps)
#: at most this many points, a polynomial is summed point by point (`_clenshaw`)
FEW = 24


def _clenshaw(coef: np.ndarray, k: np.ndarray, x: np.ndarray) -> np.ndarray:
    """sum_j coef[j, k] T_j(x): each point x with its own column k of coefficients (`ode._clenshaw` for arrays; a
    few points one by one, in plain floats: numpy's cost per call would dominate). `coef` (degrees, steps), or
    (degrees, m, steps) for m sums at each point at once, (m, points)."""
    if len(x) <= FEW:
        if coef.ndim == 3:
            return np.array([_clenshaw(coef[:, i, :], k, x) for i in range(coef.shape[1])])
        out = []
        for column, xi in zip(coef.T[k].tolist(), x.tolist()):
            b1 = b2 = 0.0
            twice = 2.0 * xi
            for c in reversed(column[1:]):
                b1, b2 = c + twice * b1 - b2, b1
            out.append(column[0] + xi * b1 - b2)
        return np.array(out)
    # the same operations in the same order as b1, b2 = c_j + 2 x b1 - b2, b1, with the points' columns gathered
    # once and no array made per operation: numpy's cost per call dominates these short arrays (measured: a third
    # of the time of the whole-array path)
    rows = coef[..., k]
    twice = 2.0 * x
    b1, b2, spare = np.zeros(rows.shape[1:]), np.zeros(rows.shape[1:]), np.empty(rows.shape[1:])
    for j in range(coef.shape[0] - 1, 0, -1):
        np.multiply(twice, b1, out=spare)
        np.add(rows[j], spare, out=spare)
        np.subtract(spare, b2, out=spare)
        b1, b2, spare = spare, b1, b2
    return rows[0] + x * b1 - b2


class _Steps:
    """A solved contact's steps as arrays: their starts and ends, and the coefficients of psi, of the primitives of
    exp(+-out) and of out (where the piece keeps its own), one column a step."""

    def __init__(self, piece):
        steps = piece.steps
        self.a = np.array([st.a for st in steps])
        self.b = np.array([st.b for st in steps])
        self.plus0, self.minus0 = np.array([st.plus0 for st in steps]), np.array([st.minus0 for st in steps])
        # one column a step: each row (a degree) is read for many points at once
        self.psi = np.array([st.psi for st in steps]).T.copy()
        self.plus = np.array([st.plus for st in steps]).T.copy()
        self.minus = np.array([st.minus for st in steps]).T.copy()
        self.out = np.array([st.out for st in steps]).T.copy() if steps[0].out is not None else None
        # psi with each primitive, summed together (`Arrays.piece_both`): psi has one degree fewer, its top
        # coefficient 0 leaves Clenshaw's sums at their start (0 + 2x 0 - 0 = +0), so its values are the same floats
        padded = np.vstack([self.psi, np.zeros((self.plus.shape[0] - self.psi.shape[0], len(steps)))])
        self.psi_plus = np.ascontiguousarray(np.stack([padded, self.plus], axis=1))
        self.psi_minus = np.ascontiguousarray(np.stack([padded, self.minus], axis=1))

    def place(self, s: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Each s's step and its place in the step's window [-1, 1] (clipped, as `ode.Step.x`)."""
        k = np.maximum(np.searchsorted(self.a, s, side="right") - 1, 0)
        a, b = self.a[k], self.b[k]
        return k, np.clip((2.0 * s - a - b) / (b - a), -1.0, 1.0)


class Arrays:
    """r+, r-, a and b of a run's solution (`solve.Solution`) for arrays of chart times."""

    def __init__(self, solution):
        self.solution, self.L = solution, solution.L
        self._steps: dict[int, _Steps] = {}
        self._starts: dict[int, np.ndarray] = {}

    # --- one piece ------------------------------------------------------------------------------------------------

    def _solved(self, piece) -> _Steps:
        steps = self._steps.get(id(piece))
        if steps is None:
            steps = self._steps[id(piece)] = _Steps(piece)
        return steps

    def piece_r(self, piece, s: np.ndarray) -> np.ndarray:
        """The piece's r at s (as its own `r`)."""
        form = piece.form
        if form == "const":
            return np.full_like(s, piece.c)
        if form == "contact":
            return -piece.r_in - 2.0 * (2.0 * np.arctanh(self._q(piece, s)))
        if form == "view":
            return piece.sign * self.piece_r(piece.base, s - piece.shift)
        steps = self._solved(piece)
        k, x = steps.place(s)
        if steps.out is not None:  # a long chain of contacts: its own polynomial (`ode.MAX_DEPTH`)
            return _clenshaw(steps.out, k, x)
        return self.piece_r(piece.r_in.__self__, s) - 2.0 * _clenshaw(steps.psi, k, x)

    def piece_primitive(self, piece, s: np.ndarray, plus: bool) -> np.ndarray:
        """The piece's integral of exp(r) (`plus`) or exp(-r) from its start to s (as its own `ep`, `em`)."""
        form = piece.form
        if form == "const":
            return np.exp(piece.c if plus else -piece.c) * (s - piece.lo)
        if form == "contact":
            q, q0 = self._q(piece, s), piece.k
            if plus:
                return np.exp(-piece.r_in) * ((s - piece.lo) - 4.0 / piece.c * (q0 - q) / ((1.0 + q) * (1.0 + q0)))
            return np.exp(piece.r_in) * ((s - piece.lo) + 4.0 / piece.c * (q0 - q) / ((1.0 - q) * (1.0 - q0)))
        if form == "view":
            inner = plus if piece.sign > 0 else not plus
            base_at = self.piece_primitive(piece.base, np.concatenate([[piece.lo], s]) - piece.shift, inner)
            return base_at[1:] - base_at[0]
        steps = self._solved(piece)
        k, x = steps.place(s)
        coef, start = (steps.plus, steps.plus0) if plus else (steps.minus, steps.minus0)
        return start[k] + 0.5 * (steps.b[k] - steps.a[k]) * _clenshaw(coef, k, x)

    def piece_both(self, piece, s: np.ndarray, plus: bool = True) -> tuple[np.ndarray, np.ndarray]:
        """`piece_r` and `piece_primitive` at once, the same floats: a step is placed, a contact's q and a view's
        base read once for both (the chart map reads both at every step of every search)."""
        form = piece.form
        if form == "const":
            return np.full_like(s, piece.c), np.exp(piece.c if plus else -piece.c) * (s - piece.lo)
        if form == "contact":
            q, q0 = self._q(piece, s), piece.k
            r = -piece.r_in - 2.0 * (2.0 * np.arctanh(q))
            if plus:
                return r, np.exp(-piece.r_in) * ((s - piece.lo) - 4.0 / piece.c * (q0 - q) / ((1.0 + q) * (1.0 + q0)))
            return r, np.exp(piece.r_in) * ((s - piece.lo) + 4.0 / piece.c * (q0 - q) / ((1.0 - q) * (1.0 - q0)))
        if form == "view":
            inner = plus if piece.sign > 0 else not plus
            r, base_at = self.piece_both(piece.base, np.concatenate([[piece.lo], s]) - piece.shift, inner)
            return piece.sign * r[1:], base_at[1:] - base_at[0]
        steps = self._solved(piece)
        k, x = steps.place(s)
        coef, start = (steps.plus, steps.plus0) if plus else (steps.minus, steps.minus0)
        if steps.out is not None:  # a long chain of contacts: its own polynomial (`ode.MAX_DEPTH`)
            r, primitive = _clenshaw(steps.out, k, x), _clenshaw(coef, k, x)
        else:
            psi, primitive = _clenshaw(steps.psi_plus if plus else steps.psi_minus, k, x)
            r = self.piece_r(piece.r_in.__self__, s) - 2.0 * psi
        return r, start[k] + 0.5 * (steps.b[k] - steps.a[k]) * primitive

    @staticmethod
    def _q(piece, s: np.ndarray) -> np.ndarray:
        if piece.log_k is not None:
            return np.exp(piece.log_k - piece.c * (s - piece.lo))
        return piece.k * np.exp(-piece.c * (s - piece.lo))

    # --- one invariant ----------------------------------------------------------------------------------------------

    @staticmethod
    def _reduce(invariant, s: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """s moved into the first period after the last separation, and the periods it was moved by."""
        if invariant.period is None:
            return s, np.zeros_like(s)
        n = np.where(s < invariant.tail_start + invariant.period,
                     0.0, np.floor((s - invariant.tail_start) / invariant.period))
        return s - n * invariant.period, n

    def _groups(self, invariant, s: np.ndarray):
        """s (reduced into the first period) grouped by the piece it falls in: (piece index, positions) for each
        piece read, the positions into s; before the first piece, none."""
        starts = self._starts.get(id(invariant))
        if starts is None:
            starts = self._starts[id(invariant)] = np.asarray(invariant.starts)
        k = np.searchsorted(starts, s, side="right") - 1
        if not len(k):
            return []
        first = k[0]
        if (k == first).all():  # all in one piece (as often, once a search closes in): no sort
            return [(int(first), np.arange(len(k)))] if first >= 0 else []
        order = np.argsort(k, kind="stable")
        ordered = k[order]
        firsts = np.flatnonzero(np.concatenate([[True], ordered[1:] != ordered[:-1]]))
        ends = np.append(firsts[1:], len(k))
        return [(int(ordered[a]), order[a:b]) for a, b in zip(firsts, ends) if ordered[a] >= 0]

    def invariant(self, invariant, s, primitive: bool = True) -> tuple[np.ndarray, np.ndarray]:
        """r(s) and the integral of exp(r) from 0 to s (0 for it with `primitive` False) of an invariant."""
        s = np.asarray(s, dtype=float)
        shape, s = s.shape, s.ravel()
        s, n = self._reduce(invariant, s)
        r, m = np.zeros_like(s), s.copy()  # before the first piece: r = 0, the integral s itself
        for j, here in self._groups(invariant, s):
            piece = invariant.pieces[j]
            at = np.minimum(s[here], piece.hi)
            if primitive:
                r[here], at_m = self.piece_both(piece, at)
                m[here] = invariant.offsets[j][0] + at_m
            else:
                r[here] = self.piece_r(piece, at)
        return r.reshape(shape), (m + n * invariant.tail_gain[0]).reshape(shape)

    def minus_integral(self, invariant, s) -> np.ndarray:
        """The integral of exp(-r) from 0 to s of an invariant (its `integrals(s)[1]`)."""
        s = np.asarray(s, dtype=float)
        shape, s = s.shape, s.ravel()
        s, n = self._reduce(invariant, s)
        m = s.copy()
        for j, here in self._groups(invariant, s):
            piece = invariant.pieces[j]
            m[here] = invariant.offsets[j][1] + self.piece_primitive(piece, np.minimum(s[here], piece.hi), False)
        return (m + n * invariant.tail_gain[1]).reshape(shape)

    # --- the chart map --------------------------------------------------------------------------------------------

    def plus(self, u) -> tuple[np.ndarray, np.ndarray]:
        """r+(u) and a(u) (t + x = a(u))."""
        r, m = self.invariant(self.solution.plus, u)
        return r, m - 0.5 * self.L

    def minus(self, w) -> tuple[np.ndarray, np.ndarray]:
        """r-(w) and b(w) (t - x = b(w))."""
        r, m = self.invariant(self.solution.minus, w)
        return r, m + 0.5 * self.L

    def inverse(self, which: str, y: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
        """The s in [lo, hi] with a(s) = y (`which` "plus") or b(s) = y ("minus"), a and b increasing with slopes
        exp(r+), exp(r-) > 0: Newton's method from the chord's root, kept inside the bracket."""
        chart = self.plus if which == "plus" else self.minus

        def value_and_slope(s, index):
            r, m = chart(s)
            return m - y[index], np.exp(r), np.abs(m) + np.abs(y[index])
        m_lo, m_hi = chart(lo)[1], chart(hi)[1]  # the first guess: the chord's
        guess = lo + (hi - lo) * np.clip((y - m_lo) / np.where(m_hi > m_lo, m_hi - m_lo, 1.0), 0.0, 1.0)
        return solve_increasing(value_and_slope, lo, hi, guess, self.L)


def solve_increasing(value_and_slope, lo, hi, guess, L: float) -> np.ndarray:
    """The root in [lo, hi] of each of many increasing functions: `value_and_slope(s, index)` gives the values, the
    slopes and the values' sizes (their rounding's scale) of functions `index` (an index array) at s (each value < 0
    at lo, >= 0 at hi). Newton's method from `guess`, kept inside a shrinking bracket, until the value is within a
    few roundings of nought, or the step or the bracket a few ulps; each root is the last point its function was
    evaluated at. Where Newton's method crawls (a root at a kink, or where the slope vanishes, as at a contact's steep start)
    the step is doubled while the value keeps its sign and only halves, and where a step crossed the root without
    halving the value the next is the chord's through the two points."""
    lo, hi = np.array(lo, dtype=float), np.array(hi, dtype=float)
    s = np.clip(np.asarray(guess, dtype=float), lo, hi)
    previous = np.full(s.shape, np.inf)  # each function's value at its last point, and that point
    before = s.copy()
    index = np.arange(s.size)
    for _ in range(200):
        sa, la, ha = s[index], lo[index], hi[index]
        value, slope, size = value_and_slope(sa, index)
        la, ha = np.where(value < 0.0, sa, la), np.where(value >= 0.0, sa, ha)
        last, at = previous[index], before[index]
        ratio = np.abs(value) / np.abs(last)
        same_side = np.sign(value) == np.sign(last)
        newton, doubled = sa - value / slope, sa - 2.0 * value / slope
        halving = same_side & (ratio > 0.35) & (ratio < 0.65)  # where the slope vanishes at the root
        step = np.where(halving & (doubled > la) & (doubled < ha), doubled, newton)
        # across a kink (a front) without halving the value: the chord through the two points instead
        with np.errstate(divide="ignore", invalid="ignore"):
            chord = sa - value * (sa - at) / (value - last)
        step = np.where(~same_side & (ratio > 0.5) & np.isfinite(last), chord, step)
        inside = (step > la) & (step < ha)
        ulp = np.spacing(np.abs(sa) + L)
        done = (np.abs(value) <= 4.0 * _EPS * size) | (np.abs(value) <= 2.0 * ulp * slope) | (ha - la <= 4.0 * ulp)
        s[index] = np.where(done, sa, np.where(inside, step, 0.5 * (la + ha)))
        previous[index], before[index] = value, sa
        lo[index], hi[index] = la, ha
        index = index[~done]
        if index.size == 0:
            break
    return s
