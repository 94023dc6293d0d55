"""The energy-momentum ledger: each body's (E, p) on any slice of any frame, and the hidden part (README,
"Energy and momentum: the ledger").

Pure. Units: energy in M c^2, momentum in M c (c = 1). A particle of mass m
and rapidity a has m (cosh a, sinh a). The rod's *kinetic* (E, p) on the slice
t = tau of a frame is (M/L) times the integral over its material points sigma
of (cosh psi, sinh psi), psi the point's rapidity where it crosses the slice
(rest mass flows along material lines). The *hidden* part is the system's
total before the first impact minus the kinetic total on the slice: what the
rod's stress carries (Sears's "hidden momentum").

The integral is exact, in closed form: the slice crosses the boundaries of
the turns' fans at points found in closed form, which split [0, L] into
pieces where every point is either straight (one rapidity) or on the
hyperbolae of one turn, where sinh psi = a/d (d the distance from the pivot)
and the integrals of cosh psi and sinh psi over d are elementary.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from rodparadox.physics.engine import History, Impact
from rodparadox.physics.frames import time_order
from rodparadox.physics.kinematics import HyperbolicArc, Line
from rodparadox.physics.rod import material_worldline
from rodparadox.tolerances import ONE_INSTANT, PRINTED_ZERO, SAME_INSTANT


@dataclass(frozen=True)
class EnergyMomentum:
    """(E, p) in one frame: E in M c^2, p in M c.

    Carried as rest energy plus kinetic energy, E = rest + T, with T computed
    without cancellation (2 m sinh^2(a/2), not m cosh a - m): a difference of
    two totals (the hidden part, an impulse) then keeps its digits even where
    every body moves slowly and E is 1 to within 1e-12.
    """

    rest: float
    T: float
    p: float

    @property
    def E(self) -> float:
        return self.rest + self.T

    def __add__(self, other: "EnergyMomentum") -> "EnergyMomentum":
        return EnergyMomentum(self.rest + other.rest, self.T + other.T, self.p + other.p)

    def __sub__(self, other: "EnergyMomentum") -> "EnergyMomentum":
        return EnergyMomentum(self.rest - other.rest, self.T - other.T, self.p - other.p)

    @staticmethod
    def of(mass: float, rapidity: float) -> "EnergyMomentum":
        return EnergyMomentum(mass, 2.0 * mass * math.sinh(0.5 * rapidity) ** 2, mass * math.sinh(rapidity))


ZERO = EnergyMomentum(0.0, 0.0, 0.0)


@dataclass(frozen=True)
class Slice:
    """The ledger on the slice t of a frame: each body's kinetic (E, p), their total, and the hidden part."""

    t: float
    bodies: tuple[tuple[str, EnergyMomentum], ...]  # A, B (those present), rod
    kinetic: EnergyMomentum
    hidden: EnergyMomentum
    #: the causal rod's (E, p) split into its matter part and its stress part (README, "The causal rod")
    rod_parts: tuple[tuple[str, EnergyMomentum], ...] = ()


@dataclass(frozen=True)
class ImpactEntry:
    """One impact in a frame: the particle's (E, p) just before and after, the impulse it delivers to the rod, the
    rod's kinetic (E, p) on the slice through the impact (continuous there: the impact is one point of the rod),
    the rod's dynamical (E, p) before and after, and the system's kinetic and hidden totals just before and after."""

    impact: Impact
    t: float
    particle_before: EnergyMomentum
    particle_after: EnergyMomentum
    impulse: EnergyMomentum
    rod_kinetic: EnergyMomentum
    rod_dynamical_before: EnergyMomentum
    rod_dynamical_after: EnergyMomentum
    kinetic_before: EnergyMomentum
    kinetic_after: EnergyMomentum
    hidden_before: EnergyMomentum
    hidden_after: EnergyMomentum


def initial_total(history: History, frame_rapidity: float) -> EnergyMomentum:
    """All bodies before the first impact: the rod at rest in S, each particle at its speed towards the rod."""
    s = history.scenario
    total = ZERO
    for p in sorted(s.particles, key=lambda p: p.name):  # the order ledger_slice sums in: rest energies cancel exactly
        r = (1.0 if p.name == "A" else -1.0) * math.atanh(s.speed(p))
        total += EnergyMomentum.of(p.mass, r - frame_rapidity)
    return total + EnergyMomentum.of(1.0, -frame_rapidity)


def rounding_zero(total: EnergyMomentum) -> float:
    """A difference of totals (the hidden part, an impulse) smaller than this, in a frame whose total before the
    first impact is `total`, is rounding: PRINTED_ZERO of the frame's kinetic scale, since rest energies cancel
    exactly in a difference and its rounding is of the order of the kinetic energies and momenta."""
    return PRINTED_ZERO * max(total.T, abs(total.p), 1e-300)


def particle_on_slice(history: History, name: str, frame_rapidity: float, t: float, after: bool = True) -> EnergyMomentum:
    """A particle's (E, p) at time t of the frame; at one of its impacts, just after it (or just before, after=False).

    An impact within rounding of t (SAME_INSTANT) counts as at t: boosting the
    impact and the world-line separately may put them an ulp apart.
    """
    mass = history.scenario.particle(name).mass
    tolerance = SAME_INSTANT * (history.scenario.L + abs(t))
    here = [i for i in history.impacts if i.particle == name and abs(i.event.time_in(frame_rapidity) - t) <= tolerance]
    if here:
        rapidity = here[-1].particle_rapidity_after if after else here[0].particle_rapidity_before
        return EnergyMomentum.of(mass, rapidity - frame_rapidity)
    w = history.worldline(name).seen_from(frame_rapidity)
    return EnergyMomentum.of(mass, w.rapidity_at_time(t))


def rod_kinetic(history: History, frame_rapidity: float, t: float) -> EnergyMomentum:
    """The rod's kinetic (E, p) on the slice t of the frame, exactly (closed form on each piece of [0, L])."""
    L = history.scenario.L
    cuts = {0.0, L}
    for turn in history.turns:
        pivot = turn.pivot.seen_from(frame_rapidity)
        for rapidity in (turn.rapidity_from, turn.rapidity_stop):
            sinh = math.sinh(rapidity - frame_rapidity)
            if sinh == 0.0:
                continue  # this fan line is a slice of the frame: it bounds nothing on another slice
            d = (t - pivot.t) / (turn.side * sinh)
            if 0.0 < d < L:
                cuts.add(turn.distance(d))  # distance(.) maps d to sigma and back: it is its own inverse
    cuts = sorted(cuts)
    T = p = 0.0
    for lo, hi in zip(cuts, cuts[1:]):
        if hi - lo <= 0.0:
            continue
        w = material_worldline(history, 0.5 * (lo + hi)).seen_from(frame_rapidity)
        piece = w.piece_at_time(t)
        if isinstance(piece, HyperbolicArc) and piece.radius > 0:
            dT, dp = _across_arc(piece, t, lo, hi, L)
        else:
            psi = piece if isinstance(piece, float) else piece.rapidity_at_start if isinstance(piece, Line) else piece.phi_at_time(t)
            dT, dp = (hi - lo) * 2.0 * math.sinh(0.5 * psi) ** 2, (hi - lo) * math.sinh(psi)
        T, p = T + dT, p + dp
    return EnergyMomentum(1.0, T / L, p / L)


def _across_arc(arc: HyperbolicArc, t: float, sigma_lo: float, sigma_hi: float, L: float) -> tuple[float, float]:
    """Integral over sigma in [sigma_lo, sigma_hi] of (cosh psi - 1, sinh psi), every point on a hyperbola about one pivot.

    The point at distance d from the pivot P crosses the slice where
    t - t_P = side d sinh psi: sinh psi = a/d with a = side (t - t_P). Then
    integral of sinh psi dd = a ln(d2/d1) and integral of cosh psi dd =
    integral of sqrt(d^2 + a^2)/d dd = [sqrt(d^2 + a^2) - |a| asinh(|a|/d)];
    less the rest energy d: [a^2/(sqrt(d^2 + a^2) + d) - |a| asinh(|a|/d)], which keeps its digits for small a.
    """
    # the pivot's distance from sigma: the arc's radius at the midpoint says which end the pivot is
    mid = 0.5 * (sigma_lo + sigma_hi)
    pivot_at_left = abs(arc.radius - mid) < abs(arc.radius - (L - mid))
    d1, d2 = sorted((sigma_lo, sigma_hi) if pivot_at_left else (L - sigma_hi, L - sigma_lo))
    a = arc.side * (t - arc.centre.t)
    if a == 0.0:
        return 0.0, 0.0
    if d1 <= 0.0:
        # only a slice through the pivot itself (a rounding-sized a) puts the pivot on the arcs: the piece is
        # then rounding-sized too, and its midpoint's rapidity is as good as the exact integral
        psi = math.asinh(a / (0.5 * d2))
        return d2 * 2.0 * math.sinh(0.5 * psi) ** 2, d2 * math.sinh(psi)
    b = abs(a)

    def primitive(d: float) -> float:
        return a * a / (math.hypot(d, a) + d) - b * math.asinh(b / d)

    return primitive(d2) - primitive(d1), a * math.log(d2 / d1)


def ledger_slice(history: History, frame_rapidity: float, t: float) -> Slice:
    """Each body's kinetic (E, p) on the slice t of the frame (particles just after any impact at t), and the hidden part."""
    bodies = [(p.name, particle_on_slice(history, p.name, frame_rapidity, t)) for p in sorted(history.scenario.particles,
                                                                                               key=lambda p: p.name)]
    bodies.append(("rod", rod_kinetic(history, frame_rapidity, t)))
    kinetic = ZERO
    for _, em in bodies:
        kinetic += em
    return Slice(t, tuple(bodies), kinetic, initial_total(history, frame_rapidity) - kinetic)


def impact_entries(history: History, frame_rapidity: float) -> tuple[ImpactEntry, ...]:
    """Every impact in the order of the frame's time (the rod's own order for impacts at one instant), with the
    (E, p) of every body just before and after it."""
    out = []
    total = initial_total(history, frame_rapidity)
    names = sorted(p.name for p in history.scenario.particles)
    for i in history.impacts:
        t = i.event.time_in(frame_rapidity)
        rod = rod_kinetic(history, frame_rapidity, t)
        before = {n: particle_on_slice(history, n, frame_rapidity, t, after=False) for n in names}
        after = {n: particle_on_slice(history, n, frame_rapidity, t, after=True) for n in names}
        mass = history.scenario.particle(i.particle).mass
        p_before = EnergyMomentum.of(mass, i.particle_rapidity_before - frame_rapidity)
        p_after = EnergyMomentum.of(mass, i.particle_rapidity_after - frame_rapidity)
        kinetic_before, kinetic_after = ZERO, ZERO
        for n in names:  # particles by name, then the rod: as initial_total sums, so rest energies cancel exactly
            kinetic_before += before[n]
            kinetic_after += after[n]
        kinetic_before, kinetic_after = kinetic_before + rod, kinetic_after + rod
        out.append(ImpactEntry(i, t, p_before, p_after, p_before - p_after, rod,
                               EnergyMomentum.of(1.0, i.rod_rapidity_before - frame_rapidity),
                               EnergyMomentum.of(1.0, i.rod_rapidity_after - frame_rapidity),
                               kinetic_before, kinetic_after, total - kinetic_before, total - kinetic_after))
    scale = history.scenario.L + max((abs(e.t) for e in out), default=0.0)
    return tuple(out[k] for k in time_order([e.t for e in out], scale))  # the rod's own order at one instant


def turn_times(history: History, frame_rapidity: float) -> list[float]:
    """Every instant of the frame's time where a turn starts or ends."""
    return history.rigid.turn_times(frame_rapidity)


@dataclass(frozen=True)
class InstantEntry:
    """The impacts at one instant of a frame (several where they share its time: B₁ and A₁ at t′ = 17/12 in Fig. 2),
    taken as one: every body's kinetic (E, p) just before all of them and just after all of them, the hidden part
    and the total (the same before and after, and the same as before the first impact), and apart from these the
    rod's dynamical (E, p) before the first and after the last (not a summand: the rod's kinetic part is)."""

    impacts: tuple[Impact, ...]
    t: float
    before: tuple[tuple[str, EnergyMomentum], ...]  # A, B (those present), "rod" (kinetic), "hidden"
    after: tuple[tuple[str, EnergyMomentum], ...]
    total: EnergyMomentum
    rod_dynamical_before: EnergyMomentum
    rod_dynamical_after: EnergyMomentum


def instant_entries(history: History, frame_rapidity: float) -> tuple[InstantEntry, ...]:
    """The impacts grouped by instant of the frame's time (`impact_entries`' order), one entry per instant."""
    entries = impact_entries(history, frame_rapidity)
    scale = history.scenario.L + max((abs(e.t) for e in entries), default=0.0)
    groups: list[list[ImpactEntry]] = []
    for e in entries:
        if groups and abs(groups[-1][0].t - e.t) <= ONE_INSTANT * scale:
            groups[-1].append(e)
        else:
            groups.append([e])
    total = initial_total(history, frame_rapidity)
    names = sorted(p.name for p in history.scenario.particles)
    out = []
    for group in groups:
        t = group[0].t
        rod = group[0].rod_kinetic

        def state(after: bool) -> tuple[tuple[str, EnergyMomentum], ...]:
            bodies = [(n, particle_on_slice(history, n, frame_rapidity, t, after=after)) for n in names]
            kinetic = ZERO
            for _, em in bodies:  # as initial_total sums, so rest energies cancel exactly
                kinetic += em
            kinetic += rod
            return (*bodies, ("rod", rod), ("hidden", total - kinetic))

        rod_order = sorted(group, key=lambda e: history.impacts.index(e.impact))
        out.append(InstantEntry(tuple(e.impact for e in rod_order), t, state(False), state(True), total,
                                rod_order[0].rod_dynamical_before, rod_order[-1].rod_dynamical_after))
    return tuple(out)
