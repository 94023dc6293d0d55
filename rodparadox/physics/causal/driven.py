"""The causal rod driven by forces at its ends (docs/model.md, "Forces at the ends"). Pure; numpy only.

A force F at an end is the push of its agent in the end's momentary rest frame (F > 0 presses into the rod). It
sets the end's pressure, p = (rho0/2)(lam^2 - 1) = F (rho0 = M/L), so the end's compression is
lam_end^2 = 1 + 2F/rho0: a tension of rho0/2 or more would stretch the end without bound, and is refused. With
psi the end's rapidity pointing into the rod (th at the left end, -th at the right) and `in` its incoming
invariant (r+ at the left end, r- at the right), psi = in + ln lam_end and the outgoing one is
out = in - 2 psi = -in - 2 ln lam_end, as for a particle's contact (`causal.solve`); F = 0 is the free end.

F is read at t_F = (e^-f U + e^f V)/2, the time in its profile's frame (rapidity f relative to S) of the end's
event (U, V) = (t + x, t - x). The end's own coordinate y (b(T) at the left end, a(T + L) at the right) obeys
    dy/dT = exp(out) = exp(-in(T)) / lam_end^2(t_F(z(T), y)),
z the other coordinate (a(T) at the left end, b(T - L) at the right), dz/dT = exp(in(T)) known from the input:
one scalar equation along the end, solved by Chebyshev collocation (the collocation equations Y = y_a + S g(Y)
by fixed-point iteration, steps halved until the last coefficients of psi, exp(+-out) and the delivered
integrands fall below 1e-12 relative; `ode`'s machinery). The profile's non-smooth instants (switch-on, jumps,
corners) are events: the step ending on t_F = t_k is solved again until its end meets t_k to rounding, and the
equation restarts there (a jump of F is a jump of lam, a front running into the rod).

What the agent delivers: the 4-momentum F (sinh th, cosh th) per unit proper time at the left end,
-F (sinh th, cosh th) at the right, i.e. +-F (dx, dt). With I_U = int F dU, I_V = int F dV along the end (the same
in every frame), in the frame of rapidity f it is (E, p) = +-((e^-f I_U - e^f I_V)/2, (e^-f I_U + e^f I_V)/2).
"""

from __future__ import annotations

import bisect
import math

import numpy as np

from rodparadox.errors import ScenarioError
from rodparadox.physics.causal.ode import (DEGREE, EPS, INTEGRATE_FROM_START as _S, LOBATTO as _X, MAX_HALVINGS,
                                           ODE_RTOL, PRIMITIVE as _PRIMITIVE, TO_COEFFICIENTS as _TO_COEF, Solved, Step, clenshaw as _clenshaw,
                                           falling_root, negligible_tail as _tail, roughness as _roughness)
from rodparadox.physics.causal.budget import Budget
from rodparadox.physics.causal.solve import Characteristics, Const as _Const, Solution, View as _View, constant_of

#: windows of chart time L a forced run may take before it is refused (a push lasting that many crossing times)
MAX_FORCED_WINDOWS = 2000
#: steps of the driven ends' equation (each tried step) a run may take before it is refused: each costs a few
#: milliseconds, so a run is refused within seconds (every preset takes under a hundred)
MAX_STEPS = 2000
#: the largest |r+-| a driven run may reach: e^36 L of t per L of chart time leaves no digit of L in t (a pull
#: near rho0/2 makes each crossing multiply the rapidity's e-fold, far beyond any force's own size)
MAX_INVARIANT = 36.0
#: Newton iterations of one step's collocation equations before the step is halved
MAX_ITERATIONS = 40
_EYE = np.eye(DEGREE + 1)


class Work(Budget):
    """The bound MAX_STEPS on the driven ends' steps, refused in one sentence past it."""

    def spend(self) -> None:
        self.spent += 1
        if self.spent > self.limit:
            raise ScenarioError(f"the forces on the causal rod need more than {self.limit} steps of its driven ends "
                                f"to be followed to 1e-12; give gentler or shorter forces.", "forces")


def check_invariant(value: float) -> None:
    """Refuse a run whose invariants leave double precision behind (MAX_INVARIANT)."""
    if not abs(value) <= MAX_INVARIANT:
        raise ScenarioError(f"the forces drive the causal rod's ends to rapidities beyond {MAX_INVARIANT / 2:g} (a "
                            f"pull near M c^2/(2L) stretches it without bound), where double precision keeps no "
                            f"digit of its length; give gentler or shorter forces.", "forces")


class Drive:
    """One end's force: its profile in the engine's units (`forces.ScaledProfile`: t and L alike, F in units of
    M c^2 with M = 1, so 2F/rho0 = 2 F L) and the rapidity of the frame it is timed in; the profile's smooth
    segments between its instants (segment 0 before the force, the last after it: free)."""

    def __init__(self, profile, frame_rapidity: float, L: float):
        self.profile, self.f, self.L = profile, frame_rapidity, L
        lo, hi = profile.support()
        self.instants = sorted({lo, hi, *(t for t in profile.pieces() if lo <= t <= hi)})
        self.ef = math.exp(frame_rapidity)

    def time(self, U: float, V: float) -> float:
        """t_F of the event (U, V) = (t + x, t - x) in S."""
        return 0.5 * (U / self.ef + self.ef * V)

    def free(self, k: int) -> bool:
        """Segment k has no force: before the first instant or after the last."""
        return k == 0 or k >= len(self.instants)

    def bounds(self, k: int) -> tuple[float, float]:
        lo = self.instants[k - 1] if k > 0 else -math.inf
        hi = self.instants[k] if k < len(self.instants) else math.inf
        return lo, hi

    def constant(self, k: int) -> float | None:
        """F on segment k where it is constant there (a step, a flat stretch of points), else None."""
        lo, hi = self.bounds(k)
        return self.profile.piece_constant(self.profile.piece_index(0.5 * (lo + hi)))

    def force(self, k: int):
        """F(t) on segment k by its piece's own smooth formula, continued past the segment's ends (the step that
        overshoots an event is solved again up to it)."""
        lo, hi = self.bounds(k)
        index = self.profile.piece_index(0.5 * (lo + hi))
        constant = self.profile.piece_constant(index)
        if constant is not None:
            return lambda t: np.full(np.shape(t), constant)
        piece_value = self.profile.piece_value
        return lambda t: np.asarray(piece_value(index, t), dtype=float)


class ConstantPush(_Const):
    """A constant force on an end whose input is the constant `in`: lam_end, out = -in - 2 ln lam_end, and the
    agent's integrals in closed form, int F dz = F e^in (s - lo), int F dy = F e^-in / lam^2 (s - lo)."""

    def __init__(self, lo: float, hi: float, r_in: float, force: float, lam2: float):
        super().__init__(lo, hi, -r_in - math.log(lam2))
        self.rates = (force * math.exp(r_in), force * math.exp(-r_in) / lam2)

    def delivered(self, s: float) -> tuple[float, float]:
        return self.rates[0] * (s - self.lo), self.rates[1] * (s - self.lo)


def _constant_push(lo: float, hi: float, r_in: float, force: float, y: float, z: float, drive: "Drive",
                   t_end: float, left: bool, L: float) -> tuple[ConstantPush, float, bool]:
    """A constant force on a constant input over [lo, hi], stopped where t_F reaches t_end: y and z grow linearly
    (dy/dT = e^-in/lam^2, dz/dT = e^in), and so does t_F: its event in closed form."""
    lam2 = 1.0 + 2.0 * L * force
    check_invariant(r_in + math.log(lam2))
    dy, dz = math.exp(-r_in) / lam2, math.exp(r_in)
    t_lo = drive.time(z, y) if left else drive.time(y, z)
    rate = drive.time(dz, dy) if left else drive.time(dy, dz)
    ended = False
    if math.isfinite(t_end) and t_lo + rate * (hi - lo) >= t_end - 4.0 * EPS * (abs(t_end) + L):
        hi = min(hi, max(lo, lo + (t_end - t_lo) / rate))
        ended = True
    return ConstantPush(lo, hi, r_in, force, lam2), hi, ended


class DrivenPiece(Solved):
    """An end driven by a force while its input is smooth: psi = in + ln lam_end, out = in - 2 psi and the
    integrals of exp(+-out) as `Solved`, and besides them the integrals from lo of F exp(in) and F exp(out) (the
    agent's int F dz and int F dy along the end: `delivered`)."""

    def __init__(self, lo, hi, r_in, steps, depth, fin, fout):
        super().__init__(lo, hi, r_in, steps, depth)
        self.fin, self.fout = fin, fout  # per step: (primitive coefficients, value at the step's start)

    def delivered(self, s: float) -> tuple[float, float]:
        """(int F dz, int F dy) from lo to s."""
        k = max(0, bisect.bisect_right(self._starts, s) - 1)
        st = self.steps[k]
        x, half = st.x(s), 0.5 * (st.b - st.a)
        (ci, i0), (co, o0) = self.fin[k], self.fout[k]
        return i0 + half * _clenshaw(ci, x), o0 + half * _clenshaw(co, x)


def _collocate(y_a: float, z: np.ndarray, r_in: np.ndarray, half: float, drive: Drive, F, left: bool,
               scale: float):
    """y at the step's points (and the force and lam^2 there), by Newton's method on the collocation equations
    Y = y_a + half S g(Y) (the Jacobian's dF/dt by a central difference: it steers, the residual decides), or None
    where it does not converge (the step is then halved)."""
    e_in = np.exp(-r_in)
    ef = drive.ef
    # t_F = (U/ef + ef V)/2: the end's own coordinate is V at the left end, U at the right
    zt, dt_dy = (0.5 * z / ef, 0.5 * ef) if left else (0.5 * ef * z, 0.5 / ef)
    two_L = 2.0 * drive.L  # 2F/rho0 = 2 F L (rho0 = M/L, M = 1)
    Y = np.full(DEGREE + 1, y_a)
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        for _ in range(MAX_ITERATIONS):
            t = zt + dt_dy * Y
            force = F(t)
            lam2 = 1.0 + two_L * force
            if not np.all(lam2 > 0.0):
                return None
            g = e_in / lam2
            residual = Y - y_a - half * (_S @ g)
            if not np.all(np.isfinite(residual)):
                return None
            delta = 1e-7 * (np.abs(t) + drive.L)
            slope = (F(t + delta) - F(t - delta)) / (2.0 * delta)
            g_y = -g / lam2 * two_L * slope * dt_dy
            try:
                change = np.linalg.solve(_EYE - half * _S * g_y[None, :], residual)
            except np.linalg.LinAlgError:
                return None
            Y = Y - change
            if not np.all(np.isfinite(Y)):
                return None
            if float(np.max(np.abs(change))) <= 4.0 * EPS * scale:
                t = zt + dt_dy * Y
                force = F(t)
                lam2 = 1.0 + two_L * force
                if not np.all(lam2 > 0.0):
                    return None
                # the rounding of t_F (|t| eps) read through F's slope: no step makes psi smoother than that
                blur = 8.0 * EPS * float(np.max(np.abs(t) * np.abs(slope) / lam2)) * two_L
                return Y, force, lam2, e_in / lam2, blur
    return None


def solve_driven(lo: float, hi: float, inp, y_lo: float, z_lo: float, drive: Drive, k: int, left: bool,
                 L: float, budget: Budget | None, work: Work) -> tuple[DrivenPiece, float, bool]:
    """Integrate the driven end over end time [lo, hi] on the profile's segment k, from y = y_lo, z = z_lo;
    stop early where t_F reaches the segment's end (an event). Returns the piece, the chart time it ends at, and
    whether the segment ended there."""
    F = drive.force(k)
    _, t_end = drive.bounds(k)
    steps: list[Step] = []
    fin, fout = [], []
    a, y_a, z_a = lo, y_lo, z_lo
    plus0 = minus0 = in0 = out0 = 0.0
    h = hi - lo
    halvings = 0
    noise = _roughness(inp, lo, hi)
    base = getattr(inp, "base", inp)
    depth = 1 + getattr(base, "depth", 0)
    ep_lo = inp.ep(lo)
    ended = False
    target_b = None  # an event inside a step: the step is solved again up to it
    while a < hi and not ended:
        if budget is not None:
            budget.spend()
        work.spend()
        b = target_b if target_b is not None else (hi if a + h >= hi else a + h)
        s = a + 0.5 * (b - a) * (_X + 1.0)
        s[0], s[-1] = a, b
        r_in = np.array([inp.r(float(x)) for x in s])
        z = z_lo + np.array([inp.ep(float(x)) for x in s]) - ep_lo
        scale = L + abs(y_a) + abs(z_a)
        solved = _collocate(y_a, z, r_in, 0.5 * (b - a), drive, F, left, scale)
        good = False
        if solved is not None:
            Y, force, lam2, g, blur = solved
            blurred = max(noise, blur)
            psi = r_in + 0.5 * np.log(lam2)
            em = np.exp(r_in) * lam2
            f_in, f_out = force * np.exp(r_in), force * g
            cp, cep, cem = _TO_COEF @ psi, _TO_COEF @ g, _TO_COEF @ em
            cfi, cfo = _TO_COEF @ f_in, _TO_COEF @ f_out
            # the agent's integrands to 1e-12 of the rod's own scale (F in units of rho0: near a switch-on or -off
            # F is tiny and known only to the rounding of t_F, not to 1e-12 of itself)
            fscale = max(float(np.max(np.exp(r_in))) / L, float(np.max(np.exp(-r_in))) / L,
                         float(np.max(np.abs(f_in))), float(np.max(np.abs(f_out))))  # F in units of rho0 = 1/L
            good = (_tail(cp, max(1.0, float(np.max(np.abs(psi)))), blurred)
                    and _tail(cep, float(np.max(g)), blurred) and _tail(cem, float(np.max(em)), blurred)
                    and _tail(cfi, fscale, blurred) and _tail(cfo, fscale, blurred))
        if solved is not None:
            t_b = drive.time(z[-1], Y[-1]) if left else drive.time(Y[-1], z[-1])
            tol = 4.0 * EPS * (abs(t_end) + L) if math.isfinite(t_end) else 0.0
            if math.isfinite(t_end) and t_b > t_end + tol:
                # the event t_F = t_end lies inside the step: find it on the dense solution, solve up to it again
                step = Step(a, b, cp.tolist(), (_PRIMITIVE @ cep).tolist(), [], 0.0, 0.0)

                def time_gap(T: float, step=step, a=a, b=b, s=s) -> float:
                    y = y_a + 0.5 * (b - a) * _clenshaw(step.plus, step.x(T))
                    zz = z_lo + inp.ep(T) - ep_lo
                    return t_end - (drive.time(zz, y) if left else drive.time(y, zz))
                new_b = falling_root(time_gap, a, b, 4 * EPS * L)
                if target_b is not None and new_b >= b:  # no progress: the root is this step's end to rounding
                    pass
                elif target_b is None or abs(new_b - b) > 4 * EPS * (abs(b) + L):
                    target_b = max(new_b, math.nextafter(a, math.inf))
                    continue
        if not good:
            target_b = None
            halvings += 1
            if halvings > MAX_HALVINGS:
                raise ScenarioError("the force on an end of the causal rod could not be integrated to "
                                    f"{ODE_RTOL:g} relative; this scenario is beyond the tool's precision.", "forces")
            h = 0.5 * (b - a)
            continue
        # a step solved up to the event ends on it (t_F within rounding of t_end: 1e-12 of it, not a sliver more)
        near = 1e-12 * (abs(t_end) + L) if target_b is not None else tol
        if math.isfinite(t_end) and t_b >= t_end - near:
            ended = True
        out = r_in - 2.0 * psi
        check_invariant(float(np.max(np.abs(out))))
        step = Step(a, b, cp.tolist(), (_PRIMITIVE @ cep).tolist(), (_PRIMITIVE @ cem).tolist(),
                    plus0, minus0, (_TO_COEF @ out).tolist())
        steps.append(step)
        ci, co = (_PRIMITIVE @ cfi).tolist(), (_PRIMITIVE @ cfo).tolist()
        fin.append((ci, in0))
        fout.append((co, out0))
        half = 0.5 * (b - a)
        plus0 += half * _clenshaw(step.plus, 1.0)
        minus0 += half * _clenshaw(step.minus, 1.0)
        in0 += half * _clenshaw(ci, 1.0)
        out0 += half * _clenshaw(co, 1.0)
        was_target = target_b is not None
        target_b = None
        a, y_a, z_a = b, float(Y[-1]), float(z[-1])
        if not was_target:
            h = 2.0 * (b - step.a) if halvings == 0 else b - step.a
        halvings = 0
    return DrivenPiece(lo, a, inp.r, steps, depth, fin, fout), a, ended


class Delivered:
    """What one end's agent delivered: its forced pieces in end time, (int F dz, int F dy) accumulated."""

    def __init__(self):
        self.starts: list[float] = []
        self.pieces: list[DrivenPiece] = []
        self.offsets: list[tuple[float, float]] = []

    def add(self, piece: DrivenPiece) -> None:
        if not self.pieces:
            offset = (0.0, 0.0)
        else:
            last = self.pieces[-1]
            o_in, o_out = self.offsets[-1]
            d_in, d_out = last.delivered(last.hi)
            offset = (o_in + d_in, o_out + d_out)
        self.starts.append(piece.lo), self.pieces.append(piece), self.offsets.append(offset)

    def at(self, T: float) -> tuple[float, float]:
        """(int F dz, int F dy) from the first force up to end time T."""
        k = bisect.bisect_right(self.starts, T) - 1
        if k < 0:
            return 0.0, 0.0
        piece = self.pieces[k]
        d_in, d_out = piece.delivered(min(T, piece.hi))
        return self.offsets[k][0] + d_in, self.offsets[k][1] + d_out


class DrivenSolution(Solution):
    """A `Solution` of a rod driven by forces: no contacts; each end's first and last forced chart time and what
    its agent delivered."""

    def __init__(self, L, plus, minus, first: dict, last: dict, delivered: dict, drives: dict):
        super().__init__(L, plus, minus, [], {})
        self.first, self.last, self.delivered, self.drives = first, last, delivered, drives


def solve_forces(L: float, drives: dict, budget: Budget | None = None) -> DrivenSolution:
    """Run the rod, at rest in S until the first force, driven at each end by `drives[end]` (a `Drive` or None).
    """
    ends = [e for e in ("left", "right") if drives.get(e) is not None]
    if not ends:
        raise ScenarioError("a scenario with forces needs a force at the left or the right end.", "forces")
    x_end = {"left": -0.5 * L, "right": 0.5 * L}
    # chart time at rest: T = t; the force starts at t_F = t cosh f - x sinh f
    start = {e: (drives[e].instants[0] + x_end[e] * math.sinh(drives[e].f)) / math.cosh(drives[e].f) for e in ends}
    T_first = min(start.values())
    chars = Characteristics(L, T_first)  # undisturbed before the first force
    plus, minus, a_of, b_of = chars.plus, chars.minus, chars.a, chars.b
    end_inputs, out_append = chars.end_inputs, chars.out_append
    segment = {e: 0 for e in ends}
    first = {e: math.inf for e in ("left", "right")}
    last = {e: -math.inf for e in ("left", "right")}
    delivered = {e: Delivered() for e in ("left", "right")}

    def coordinates(end, T):
        """(y, z): the end's own coordinate and the other one at end time T."""
        return (b_of(T), a_of(T)) if end == "left" else (a_of(T + L), b_of(T - L))

    T0 = T_first - L
    windows = 0
    work = Work(MAX_STEPS)
    done_at = None
    while True:
        windows += 1
        if budget is not None:
            budget.spend()
        if windows > MAX_FORCED_WINDOWS:
            raise ScenarioError(f"the forces act on the causal rod for more than {MAX_FORCED_WINDOWS} crossing times "
                                f"of the rod; give them shorter durations.", "forces")
        T1 = T0 + L
        for end in ("left", "right"):
            drive = drives.get(end)
            for lo, hi, inp in end_inputs(end, T0, T1):
                T = lo
                while T < hi:
                    if budget is not None:
                        budget.spend()
                    k = segment.get(end)
                    if drive is None or k >= len(drive.instants):  # free for good
                        out_append(end, _View(inp, 0.0, -1, T, hi))
                        T = hi
                        continue
                    y, z = coordinates(end, T)
                    left = end == "left"
                    if drive.free(k):  # free until t_F reaches the force's first instant
                        t_on = drive.instants[0]
                        em0, ep0 = inp.em(T), inp.ep(T)

                        def time_at(s, y=y, z=z, em0=em0, ep0=ep0, inp=inp):
                            yy, zz = y + inp.em(s) - em0, z + inp.ep(s) - ep0
                            return drive.time(zz, yy) if left else drive.time(yy, zz)
                        if time_at(hi) < t_on:
                            out_append(end, _View(inp, 0.0, -1, T, hi))
                            T = hi
                            continue
                        T_on = T if time_at(T) >= t_on else falling_root(lambda s: t_on - time_at(s), T, hi,
                                                                          4 * EPS * L)
                        out_append(end, _View(inp, 0.0, -1, T, T_on))
                        segment[end] = 1
                        first[end] = min(first[end], T_on)
                        T = T_on
                        continue
                    r_in, force = constant_of(inp), drive.constant(k)
                    if r_in is not None and force is not None:
                        piece, T_next, ended = _constant_push(T, hi, r_in, force, y, z, drive, drive.bounds(k)[1],
                                                              left, L)
                    else:
                        piece, T_next, ended = solve_driven(T, hi, inp, y, z, drive, k, left, L, budget, work)
                    if piece.hi > piece.lo:
                        out_append(end, piece)
                        delivered[end].add(piece)
                    if ended:
                        segment[end] = k + 1
                        if k + 1 >= len(drive.instants):
                            last[end] = T_next
                    T = T_next
        T0 = T1
        finished = all(segment[e] >= len(drives[e].instants) for e in ends)
        if finished and done_at is None:
            done_at = max(last[e] for e in ends)
        if done_at is not None and T0 >= done_at + 3 * L:
            break
    plus.close(done_at, 2 * L)
    minus.close(done_at, 2 * L)
    return DrivenSolution(L, plus, minus, first, last, delivered, drives)


__all__ = ["Drive", "DrivenSolution", "solve_forces"]
