"""The causal rod's invariants on its light-line characteristics, and its contacts (docs/model.md, "The causal rod"). Pure.

The rod's material (sound speed c) obeys the wave equation in its material chart (T, X), X in [0, L] the label.
Two invariants carry every disturbance: r+ = th - ln lam, a function of u = T + X (constant along left-going
light lines), and r- = -th - ln lam, of w = T - X; th = (r+ - r-)/2, ln lam = -(r+ + r-)/2. The chart map is
t + x = a(u), t - x = b(w), a' = exp(r+), b' = exp(r-); before any contact r+ = r- = 0, a(u) = u - L/2,
b(w) = w + L/2 (the rod at rest, centre at x = 0).

Each end takes one invariant in and sends the other out. Left end (X = 0, u = w = T): in r+(T), out r-(T).
Right end (X = L): in r-(T - L), out r+(T + L). With psi the end's rapidity pointing into the rod (th at the
left, -th at the right) and delta = ln lam at the end, both ends read alike (derivation in docs/model.md):

* free (p = 0, lam = 1): out = -in;
* a particle of mass m riding with the end, pushed by the end's pressure p = (M/2L)(lam^2 - 1) in its rest
  frame (m d th / d tau = -p at the left end, +p at the right, d tau = dT / lam):
  d psi / dT = -(mu/L) sinh(psi - in),  mu = M/m,  delta = psi - in,  out = in - 2 psi = -in - 2 delta.
  With `in` constant: tanh(delta/2) = k exp(-mu (T - T0)/L), k = tanh(delta0/2) (closed form, `_Contact`);
  otherwise Chebyshev collocation to 1e-12 relative with the integrals of exp(+-out) (`causal_ode`).
* contact starts where the particle's world-line meets the free end's (a root of an exact expression), with
  delta0 = psi_particle - in > 0 (lam jumps to the Doppler factor); it ends where delta reaches 0 (an ODE event)
  or where a front arriving in `in` leaves delta <= 0 (lam never falls below 1: no adhesion).

Each end's input is the other end's output one crossing time L earlier, so the run advances in windows of chart
time L, the two ends independent within one. After the last separation both ends are free: r+ and r- repeat
with period 2L in chart time (the rod rings for ever), and are extended periodically.

A piece of an invariant gives r(s) and the exact integrals of exp(r) and exp(-r) from its start (`ep`, `em`):
a(u) and b(w), and the rod's energy and momentum (`causal`), are sums of these.
"""

from __future__ import annotations

import bisect
import math
from dataclasses import dataclass, field

from rodparadox.errors import ScenarioError
from rodparadox.physics.causal.budget import MAX_STEPS, Budget
from rodparadox.physics.causal.ode import falling_root, solve_contact
#: windows of chart time L processed before a scenario is refused as never settling
MAX_WINDOWS = 5000
#: windows with a particle in contact before a scenario is refused: a contact costs far more than a free window,
#: and particles far heavier than the rod squeeze it slowly, like a spring, for thousands of crossings
MAX_CONTACT_WINDOWS = 300


# --- pieces of an invariant ------------------------------------------------------------------------------------

class _Const:
    """r = c on [lo, hi]."""

    form = "const"  # each kind of piece names itself (`causal.arrays` evaluates them for whole arrays)

    def __init__(self, lo: float, hi: float, c: float):
        self.lo, self.hi, self.c = lo, hi, c

    def r(self, s: float) -> float:
        return self.c

    def ep(self, s: float) -> float:
        return math.exp(self.c) * (s - self.lo)

    def em(self, s: float) -> float:
        return math.exp(-self.c) * (s - self.lo)


class _Contact:
    """An end in contact while its input is the constant `r_in`: tanh(delta/2) = k exp(-c (s - lo)), c = mu/L,
    out = -r_in - 2 delta. Integrals in closed form: with q = k exp(-c (s - lo)), q0 = k,
    int exp(out) = exp(-r_in) [(s - lo) - (4/c)(q0 - q)/((1 + q)(1 + q0))],
    int exp(-out) = exp(r_in) [(s - lo) + (4/c)(q0 - q)/((1 - q)(1 - q0))]."""

    form = "contact"

    def __init__(self, lo: float, hi: float, r_in: float, delta0: float, c: float, log_k: float | None = None):
        self.lo, self.hi, self.r_in, self.c = lo, hi, r_in, c
        self.log_k = log_k
        if log_k is None:  # k from delta0 (k > 0: delta0 > 0)
            self.k = math.tanh(0.5 * delta0)
            self._log_k = math.log(self.k) if self.k > 0.0 else math.log(delta0) - math.log(2.0)
        else:  # a contact continued past where delta0 = psi - r_in still shows in double precision: k from ln k
            self.k = math.exp(log_k)
            self._log_k = log_k

    def q(self, s: float) -> float:
        if self.log_k is not None:
            return math.exp(self.log_k - self.c * (s - self.lo))
        return self.k * math.exp(-self.c * (s - self.lo))

    def log_q(self, s: float) -> float:
        """ln tanh(delta/2), finite however far delta has decayed below what a double holds: the contact lasts
        while delta > 0, and with a constant input delta only decays, never reaching 0 (a mass ratio M/m above
        about 745 makes q = k exp(-(M/m) T/L) underflow to 0 within one crossing time)."""
        return self._log_k - self.c * (s - self.lo)

    def delta(self, s: float) -> float:
        return 2.0 * math.atanh(self.q(s))

    def psi(self, s: float) -> float:
        return self.r_in + self.delta(s)

    def r(self, s: float) -> float:
        return -self.r_in - 2.0 * self.delta(s)

    def ep(self, s: float) -> float:
        q, q0 = self.q(s), self.k
        return math.exp(-self.r_in) * ((s - self.lo) - 4.0 / self.c * (q0 - q) / ((1.0 + q) * (1.0 + q0)))

    def em(self, s: float) -> float:
        q, q0 = self.q(s), self.k
        return math.exp(self.r_in) * ((s - self.lo) + 4.0 / self.c * (q0 - q) / ((1.0 - q) * (1.0 - q0)))


class _View:
    """sign * base.r(s - shift) on [lo, hi] (a free end's output, or an input read at another end)."""

    form = "view"

    def __init__(self, base, shift: float, sign: int, lo: float, hi: float):
        while isinstance(base, _View):  # flattened: a view of a view is a view of the base
            base, shift, sign = base.base, shift + base.shift, sign * base.sign
        self.base, self.shift, self.sign, self.lo, self.hi = base, shift, sign, lo, hi
        self._base_ep, self._base_em = (base.ep, base.em) if sign > 0 else (base.em, base.ep)  # chosen once
        self._p0 = self._base_ep(lo - shift)
        self._m0 = self._base_em(lo - shift)

    def r(self, s: float) -> float:
        return self.sign * self.base.r(s - self.shift)

    def ep(self, s: float) -> float:
        return self._base_ep(s - self.shift) - self._p0

    def em(self, s: float) -> float:
        return self._base_em(s - self.shift) - self._m0

    @property
    def constant(self) -> float | None:
        return self.sign * self.base.c if isinstance(self.base, _Const) else None


def _constant(piece) -> float | None:
    if isinstance(piece, _Const):
        return piece.c
    return piece.constant if isinstance(piece, _View) else None


Const, View, constant_of = _Const, _View, _constant  # public for the driven ends' run (`causal.driven`)


# --- an invariant: pieces, then a periodic tail ------------------------------------------------------------------

@dataclass
class Invariant:
    """r(s) for all s: 0 before the first piece, then contiguous pieces, then (once `close`d) periodic with
    period `period` from `tail_start`. `ep(s)`, `em(s)`: the integrals of exp(r), exp(-r) from s = 0."""

    pieces: list = field(default_factory=list)
    starts: list = field(default_factory=list)
    offsets: list = field(default_factory=list)  # (ep, em) at each piece's start
    period: float | None = None
    tail_start: float | None = None
    tail_gain: tuple[float, float] = (0.0, 0.0)

    @property
    def end(self) -> float:
        return self.pieces[-1].hi

    def append(self, piece) -> None:
        if piece.hi <= piece.lo:
            return
        if not self.pieces:
            offset = (piece.lo, piece.lo)  # r = 0 before: the integrals from 0 are s itself
        else:
            last = self.pieces[-1]
            p0, m0 = self.offsets[-1]
            offset = (p0 + last.ep(last.hi), m0 + last.em(last.hi))
        self.pieces.append(piece)
        self.starts.append(piece.lo)
        self.offsets.append(offset)

    def pop(self) -> None:
        self.pieces.pop(), self.starts.pop(), self.offsets.pop()

    def close(self, tail_start: float, period: float) -> None:
        """From tail_start on r repeats with `period` (the pieces must reach tail_start + period)."""
        cut = tail_start + period
        while self.pieces and self.pieces[-1].lo >= cut:
            self.pieces.pop(), self.starts.pop(), self.offsets.pop()
        self.period, self.tail_start = period, tail_start
        a0, b0 = self._integral(tail_start, True), self._integral(tail_start, False)
        a1, b1 = self._integral(cut, True), self._integral(cut, False)
        self.tail_gain = (a1 - a0, b1 - b0)

    def _reduce(self, s: float) -> tuple[float, int]:
        if self.period is None or s < self.tail_start + self.period:
            return s, 0
        n = math.floor((s - self.tail_start) / self.period)
        return s - n * self.period, n

    def _index(self, s: float) -> int:
        return bisect.bisect_right(self.starts, s) - 1

    def piece_at(self, s: float):
        s, _ = self._reduce(s)
        k = self._index(s)
        return None if k < 0 or (k == len(self.pieces) - 1 and s > self.pieces[k].hi) else self.pieces[k]

    def r(self, s: float) -> float:
        s, _ = self._reduce(s)
        k = bisect.bisect_right(self.starts, s) - 1  # `_index`, written out: r is read at every step of a search
        if k < 0:
            return 0.0
        return self.pieces[k].r(min(s, self.pieces[k].hi))

    def _integral(self, s: float, plus: bool) -> float:
        """int_0^s exp(r) (`plus`) or exp(-r), s before any tail."""
        k = self._index(s)
        if k < 0:
            return s
        piece, at = self.pieces[k], min(s, self.pieces[k].hi)
        return self.offsets[k][0] + piece.ep(at) if plus else self.offsets[k][1] + piece.em(at)

    def integrals(self, s: float) -> tuple[float, float]:
        """(int_0^s exp(r), int_0^s exp(-r))."""
        return self.integral(s), self.integral(s, False)

    def integral(self, s: float, plus: bool = True) -> float:
        """One of `integrals(s)`, the other not computed (a and b read only the first, at every step of a search)."""
        s, n = self._reduce(s)
        return self._integral(s, plus) + n * self.tail_gain[0 if plus else 1]

    def breaks(self, lo: float, hi: float) -> list[float]:
        """Every piece boundary (a front, or where a contact starts or ends) in (lo, hi)."""
        if self.period is None:
            return [s for s in self.starts if lo < s < hi]
        base = [s for s in self.starts if self.tail_start <= s < self.tail_start + self.period]
        out = [s for s in self.starts if lo < s < min(hi, self.tail_start + self.period)]
        n = n0 = max(1, math.floor((lo - self.tail_start) / self.period))
        while True:
            shifted = [s + n * self.period for s in base]
            if shifted and shifted[0] >= hi:
                break
            out += [s for s in shifted if lo < s < hi]
            n += 1
            if n - n0 > 100000:
                break
        return sorted(set(out))

    def pieces_in(self, lo: float, hi: float):
        """The pieces covering [lo, hi] (before any tail), clipped: (lo_k, hi_k, piece)."""
        out = []
        k = max(self._index(lo), 0)
        while k < len(self.pieces) and self.pieces[k].lo < hi:
            p = self.pieces[k]
            a, b = max(lo, p.lo), min(hi, p.hi)
            if b > a:
                out.append((a, b, p))
            k += 1
        return out


# --- the run ----------------------------------------------------------------------------------------------------

@dataclass
class Rider:
    """A particle: free on its straight line through (t0, x0) at rapidity th, or riding with an end."""

    name: str
    end: str
    mass: float
    th: float
    t0: float
    x0: float
    riding: bool = False
    contacts: int = 0


@dataclass(frozen=True)
class ContactEvent:
    """A contact's start or end in chart time T at an end; th_before/th_after the particle's rapidity in S."""

    kind: str  # "contact" or "separation"
    particle: str
    end: str
    T: float
    number: int
    th_particle: float
    th_end_before: float
    th_end_after: float


class Solution:
    """The invariants r+ (of u) and r- (of w) of a run, its contact events, and the chart map."""

    def __init__(self, L: float, plus: Invariant, minus: Invariant, events: list, riders: dict):
        self.L, self.plus, self.minus, self.events, self.riders = L, plus, minus, events, riders
        self._a: dict[float, float] = {}  # the chart map at each u and w read: every frame, every layer and
        self._b: dict[float, float] = {}  # the contacts (the ends' own curves) read the same chart times again

    def a(self, u: float) -> float:
        value = self._a.get(u)
        if value is None:
            value = self._a[u] = -0.5 * self.L + self.plus.integral(float(u))
        return value

    def b(self, w: float) -> float:
        value = self._b.get(w)
        if value is None:
            value = self._b[w] = 0.5 * self.L + self.minus.integral(float(w))
        return value

    def r_plus(self, u: float) -> float:  # a, b, r+, r- at Python floats: numpy's cost twice theirs, the same floats
        return self.plus.r(float(u))

    def r_minus(self, w: float) -> float:
        return self.minus.r(float(w))

    def breaks(self, X: float, T_lo: float, T_hi: float) -> list[float]:
        """The chart times in (T_lo, T_hi) where a front crosses the material line X."""
        out = [u - X for u in self.plus.breaks(T_lo + X, T_hi + X)]
        out += [w + X for w in self.minus.breaks(T_lo - X, T_hi - X)]
        return sorted(set(out))


def _end_coordinates(sol_a, sol_b, end: str, T: float, L: float) -> tuple[float, float]:
    """(t + x, t - x) of an end at chart time T."""
    return (sol_a(T), sol_b(T)) if end == "left" else (sol_a(T + L), sol_b(T - L))


class Characteristics:
    """The rod's two invariants as a run builds them (undisturbed up to T_first, a crossing time early), and what
    each end reads of them and writes into them."""

    def __init__(self, L: float, T_first: float):
        self.L, self.plus, self.minus = L, Invariant(), Invariant()
        self.plus.append(Const(T_first - 2 * L, T_first, 0.0))
        self.minus.append(Const(T_first - 2 * L, T_first - L, 0.0))

    def a(self, u: float) -> float:
        return -0.5 * self.L + self.plus.integral(u)

    def b(self, w: float) -> float:
        return 0.5 * self.L + self.minus.integral(w)

    def end_inputs(self, end: str, lo: float, hi: float) -> list:  # an end's input pieces, as views in end time
        L = self.L
        if end == "left":
            return [(x, y, View(p, 0.0, 1, x, y)) for x, y, p in self.plus.pieces_in(lo, hi)]
        return [(x + L, y + L, View(p, L, 1, x + L, y + L)) for x, y, p in self.minus.pieces_in(lo - L, hi - L)]

    def out_append(self, end: str, piece) -> None:  # the end's output piece, in end time
        if end == "left":
            self.minus.append(piece)
        else:
            self.plus.append(View(piece, self.L, 1, piece.lo + self.L, piece.hi + self.L))


def solve(L: float, M_over_m: dict[str, float], riders: dict[str, Rider], T_first: float,
          budget: Budget | None = None) -> Solution:
    """Run the rod from chart time T_first (the first contact; before it the rod rests unstressed); `budget`: a bound
    on its work besides MAX_WINDOWS, or None for MAX_STEPS."""
    if budget is None:
        budget = Budget(MAX_STEPS, asked=False)
    chars = Characteristics(L, T_first)  # undisturbed before the first contact
    plus, minus, a_of, b_of, end_inputs, out_append = (chars.plus, chars.minus, chars.a, chars.b, chars.end_inputs,
                                                       chars.out_append)
    events: list[ContactEvent] = []
    state = {"left": None, "right": None}  # psi of the rider in contact, else None
    # a contact whose input was the constant r_in up to the window's end: (r_in, ln tanh(delta/2) there). delta =
    # psi - r_in may no longer show in psi (it decays as exp(-(M/m) T/L)); if the input goes on unchanged the
    # particle is still pressed, not released
    pressed = {"left": None, "right": None}
    T0 = T_first - L  # a window early: the first contact is a root found inside it, like every other
    last_separation = T_first
    quiet = 0

    def gap(rider, T):
        """(t + x) e^-th - (t - x) e^th of the end minus the particle's: 2 (x_end - x_p) cosh - 2 (t_end - t_p) sinh,
        the end's distance from the particle in the particle's rest frame, times 2 (the sign into the rod)."""
        U, V = _end_coordinates(a_of, b_of, rider.end, T, L)
        e = math.exp(rider.th)
        d = (U / e - V * e) - ((rider.t0 + rider.x0) / e - (rider.t0 - rider.x0) * e)
        return d if rider.end == "left" else -d

    def first_contact(rider, lo, hi, inputs):
        """The first chart time in [lo, hi] where the free particle meets its free end, closing, or None."""
        grid = [lo]
        for x, y, _ in inputs:
            grid += [x + (y - x) * j / 8 for j in range(1, 9)]
        grid = sorted(set(g for g in grid if lo <= g <= hi))
        prev_T, prev_g = grid[0], gap(rider, grid[0])
        touching = abs(prev_g) <= 1e-12 * (L + abs(rider.t0) + abs(rider.x0) + abs(prev_T))
        if prev_g <= 0.0 and touching:
            prev_g = 0.0
        for T in grid[1:]:
            g = gap(rider, T)
            if touching and T == grid[1] and g < 0.0 and not rider.contacts:
                return lo  # it reaches the end just where the window starts (gap 0 to rounding), and closes on it
            if prev_g > 0.0 and g <= 0.0:
                return falling_root(lambda s: gap(rider, s), prev_T, T, 1e-15 * (L + abs(T)), 8.9e-16)
            prev_T, prev_g = T, g
        return None

    windows = contact_windows = 0
    while True:
        windows += 1
        if budget is not None:
            budget.spend()
        waiting = [r.name for r in riders.values() if not r.contacts]
        if windows > MAX_WINDOWS and waiting:
            raise ScenarioError(f"particle {waiting[0]} reaches the causal rod more than {MAX_WINDOWS} crossing times "
                                f"of the rod after the first contact; give it a smaller gap or a higher speed.",
                                f"particles.{waiting[0]}.gap")
        if contact_windows > MAX_CONTACT_WINDOWS:
            raise ScenarioError(f"the particles stay in contact with the causal rod for more than "
                                f"{MAX_CONTACT_WINDOWS} crossing times of the rod (far heavier than the rod, they "
                                f"squeeze it slowly, like a spring); choose masses nearer the rod's.", "particles")
        if windows > MAX_WINDOWS:
            raise ScenarioError(f"the causal rod and the particles have not parted for good after {MAX_WINDOWS} "
                                f"crossing times of the rod (a particle keeps pace with the ringing rod); choose "
                                f"masses nearer the rod's.", "particles")
        T1 = T0 + L
        any_contact = False
        for end in ("left", "right"):
            rider = next((r for r in riders.values() if r.end == end), None)
            T = T0
            for lo, hi, inp in end_inputs(end, T0, T1):
                T = lo
                while T < hi:
                    if budget is not None:  # each contact, separation and free stretch
                        budget.spend()
                    if rider is not None and rider.riding:
                        any_contact = True
                        c = M_over_m[rider.name] / L
                        psi = state[end]
                        r_in0 = inp.r(T)
                        delta = psi - r_in0
                        held, pressed[end] = pressed[end], None
                        log_k = held[1] if delta <= 0.0 and held is not None and held[0] == r_in0 else None
                        if delta <= 0.0 and log_k is None:  # a front arrived that the end may follow: separation
                            T = _separate(rider, end, T, psi, r_in0, events, state, a_of, b_of, L)
                            last_separation = max(last_separation, T)
                            continue
                        const = _constant(inp)
                        if const is not None:
                            piece = _Contact(T, hi, const, delta, c, log_k)
                            out_append(end, piece)
                            state[end] = piece.psi(hi)
                            pressed[end] = (const, piece.log_q(hi))
                            T = hi
                            continue
                        piece, T_sep = solve_contact(T, hi, inp, psi if log_k is None else r_in0, c, L, budget)
                        out_append(end, piece)
                        if T_sep is None:
                            state[end] = piece.psi(hi)
                            T = hi
                        else:
                            psi_sep = piece.psi(T_sep)
                            T = _separate(rider, end, T_sep, psi_sep, inp.r(T_sep), events, state, a_of, b_of, L)
                            last_separation = max(last_separation, T)
                        continue
                    # free end: out = -in; a particle on its way may meet it
                    # the end's output is written first: where the end is depends on it
                    out_append(end, _View(inp, 0.0, -1, T, hi))
                    T_hit = None if rider is None else first_contact(rider, T, hi, [(T, hi, inp)])
                    if T_hit is not None and T_hit < hi:
                        (minus if end == "left" else plus).pop()
                        out_append(end, _View(inp, 0.0, -1, T, T_hit))
                    T_was, T = T, hi if T_hit is None else T_hit
                    if T_hit is not None:
                        any_contact = True
                        side = 1.0 if end == "left" else -1.0
                        psi = side * rider.th
                        r_in = inp.r(T_hit)
                        if psi - r_in <= 0.0:
                            T = hi if T_hit <= T_was else T  # grazing at equal speed: no push
                            continue
                        rider.riding, rider.contacts = True, rider.contacts + 1
                        state[end] = psi
                        events.append(ContactEvent("contact", rider.name, end, T_hit, rider.contacts, rider.th,
                                                   side * r_in, rider.th))
                        if T_hit >= hi:
                            break
        T0 = T1
        if any_contact or any(r.riding for r in riders.values()):
            contact_windows += 1
            quiet = 0
            continue
        quiet += 1
        # free since last_separation: periodic for both ends once T0 >= last_separation + 3L; a quiet period after
        # that, with every particle drifting away (its gap gains over a period), means no contact ever again
        if T0 >= last_separation + 5 * L and quiet >= 2 and all(_drifts_away(r, plus, minus, last_separation, L)
                                                                 for r in riders.values()):
            break
    plus.close(last_separation, 2 * L)
    minus.close(last_separation, 2 * L)
    return Solution(L, plus, minus, events, riders)


def _drifts_away(rider: Rider, plus: Invariant, minus: Invariant, T_s: float, L: float) -> bool:
    """Over one period 2L of the ringing rod its end advances by (D(t + x), D(t - x)); the particle's gap grows
    (in its rest frame) when D(t + x) e^-th - D(t - x) e^th has the sign into the rod's side."""
    p0, _ = plus.integrals(T_s)
    p1, _ = plus.integrals(T_s + 2 * L)
    m0, _ = minus.integrals(T_s)
    m1, _ = minus.integrals(T_s + 2 * L)
    e = math.exp(rider.th)
    d = (p1 - p0) / e - (m1 - m0) * e
    return (d if rider.end == "left" else -d) > 0.0


def _separate(rider, end, T, psi, r_in, events, state, a_of, b_of, L) -> float:
    side = 1.0 if end == "left" else -1.0
    rider.riding = False
    rider.th = side * psi
    U, V = _end_coordinates(a_of, b_of, end, T, L)
    state[end] = None
    events.append(ContactEvent("separation", rider.name, end, T, rider.contacts, rider.th, rider.th, side * r_in))
    rider.t0, rider.x0 = 0.5 * (U + V), 0.5 * (U - V)  # it leaves on a straight line from here
    return T
