"""The causal rod read beside the rigid one, for a handout's comparison (docs/model.md, "The causal rod"): `compare`. Pure.

A `Comparison` holds the numbers the comparison's sentences and questions quote, each read once from the two
histories of one scenario (the rigid `engine.History` and the causal `causal.CausalHistory`): when each rod's far
end first moves and when light from the first contact reaches it, how fast each particle leaves each rod, what
the ringing causal rod carries after the last separation, and the hidden momentum against the stress momentum on
one slice. Lengths and times are multiples of L, energies of M c², momenta of M c, velocities of c.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

from rodparadox.physics.types import Impact
from rodparadox.physics.frames import Frame, rest_frame
from rodparadox.physics.types import EnergyMomentum
from rodparadox.tables import build as tables
from rodparadox.tolerances import SAME_RAPIDITY

#: a stress momentum below this, relative to the total energy, is none: the rod is unstressed on the slice
UNSTRESSED = 1e-9


@dataclass(frozen=True)
class FarEnd:
    """The first contact on the causal rod (on the rod at rest in S) and the other end: when each model moves it."""

    contact: Impact
    far: str
    #: the contact's time in S, and when light from it reaches the far end (the rod at rest: light crosses L in L)
    t_contact: float
    t_light: float
    #: when the causal rod's far end first moves in S, and whether the front from the contact moved it (else the
    #: far end's own first contact, `own`, came first)
    t_causal: float
    by_light: bool
    own: Impact | None
    #: the causal far end's velocity in S just after it starts (the front from the contact: 2 θ of the struck end)
    u_causal: float
    #: the struck end's rapidity just after the contact, in S
    rapidity_struck: float
    #: when the rigid rod's far end starts to move in S (a turn from rest about the contact), or None
    t_rigid: float | None
    #: when the rigid rod's far end first moves in S by any impact (None: neither end ever moves, the rigid rod at rest
    #: in S throughout, as in fig1, whose equal and opposite impacts at one instant of S cancel)
    t_rigid_moves: float | None = None


@dataclass(frozen=True)
class Leaving:
    """A particle's velocity as it leaves for good, in each model and each frame (by frame name)."""

    particle: str
    rigid: dict
    causal: dict
    #: its contacts with the causal rod
    contacts: int


@dataclass(frozen=True)
class Ringing:
    """The causal rod after the last separation: it rings for ever, its motion repeating every 2L of chart time."""

    #: the last separation's time in S
    t_last: float
    #: what every material point advances by in S over one period, in units of L
    dt: float
    dx: float
    #: the rod's (E, p) in S, (M/2L)(Δt, Δx), its rest mass sqrt(E² − p²) and the velocity of its centre Δx/Δt
    E: float
    p: float
    rest_mass: float
    velocity: float
    #: the rigid rod's velocity in S after its last impact
    rigid_velocity: float
    #: the particles' kinetic energy in S before the first impact, and after the last contact in each model
    kinetic_before: float
    kinetic_rigid: float
    kinetic_causal: float


@dataclass(frozen=True)
class StressSlice:
    """One slice of one frame: the rigid ledger's hidden part and, made the same way, the causal rod's part that its
    material points' motion does not show (its total less its rest-mass motion); its matter and stress parts."""

    frame: Frame
    t: float
    hidden: EnergyMomentum
    matter: EnergyMomentum
    stress: EnergyMomentum
    #: the particles' (E, p) on the slice in the causal run, by name, and the causal total before the first contact
    particles: tuple[tuple[str, EnergyMomentum], ...]
    total: EnergyMomentum
    #: the causal rod's (E, p) on the slice, and its rest-mass motion (M/L)∫(cosh ψ, sinh ψ)dσ there, as (E, p)
    rod: tuple[float, float] = (0.0, 0.0)
    motion: tuple[float, float] = (0.0, 0.0)

    @property
    def unshown(self) -> tuple[float, float]:
        """What the causal rod carries beyond its material points' motion: its total less (M/L)∫(cosh ψ, sinh ψ)dσ,
        the counterpart of the rigid rod's hidden part (elastic energy and the momentum its stress carries)."""
        return self.rod[0] - self.motion[0], self.rod[1] - self.motion[1]


@dataclass(frozen=True)
class Energy:
    """Where the particles' energy went, in one frame: what they lose from before the first impact to after the
    last (their energy then less now), and, for the causal rod, its split into the rise of the rod's rest mass
    (internal energy, the same in every frame) and the change of its bulk kinetic energy (rest mass times γ − 1 of
    its centre); the rigid rod keeps its rest mass M, so what the particles lose to it is all bulk kinetic energy.
    Energies in M c²."""

    frame: Frame
    lost_causal: float
    internal: float
    bulk_before: float
    bulk_after: float
    lost_rigid: float

    @property
    def bulk_change(self) -> float:
        return self.bulk_after - self.bulk_before


def energies(rigid, causal, frames, ring: "Ringing") -> tuple[Energy, ...]:
    """`Energy` in each frame, from the rod's (E, p) in S after the last separation (its period's advance) and the
    particles' rapidities before their first and after their last impact: E′ = E cosh η − p sinh η in the frame of
    rapidity η, the rod at rest in S before (E′ = M cosh η)."""
    def particles(history, eta: float, after: bool) -> float:
        total = 0.0
        for q in history.scenario.particles:
            mine = [i for i in history.impacts if i.particle == q.name]
            th = mine[-1].particle_rapidity_after if after else mine[0].particle_rapidity_before
            total += q.mass * math.cosh(th - eta)
        return total

    out = []
    for frame in frames:
        eta = frame.rapidity
        rod_after = ring.E * math.cosh(eta) - ring.p * math.sinh(eta)
        out.append(Energy(frame, particles(causal, eta, False) - particles(causal, eta, True), ring.rest_mass - 1.0,
                          math.cosh(eta) - 1.0, rod_after - ring.rest_mass,
                          particles(rigid, eta, False) - particles(rigid, eta, True)))
    return tuple(out)


@dataclass(frozen=True)
class Comparison:
    #: the rod's proper length, and each particle's (mass in M, velocity in S) before its first contact
    L: float
    particles: dict
    far_end: FarEnd
    leaving: tuple[Leaving, ...]
    ringing: Ringing
    stress: StressSlice
    #: where the particles' energy went, in each frame shown
    energy: tuple[Energy, ...] = ()


def far_end(rigid, causal) -> FarEnd:
    """When each model first moves the end the first contact did not strike (the rod at rest in S before it)."""
    L = causal.scenario.L
    contact = causal.impacts[0]
    far = "left" if contact.end == "right" else "right"
    line = causal.material_worldline(0.0 if far == "left" else L)
    t_causal = line.first.t / L
    own = next((i for i in causal.impacts if i.kind == "contact" and i.end == far), None)
    by_light = own is None or own.event.t / L > t_causal + 1e-9 * (1.0 + abs(t_causal))
    u_causal = math.tanh(line.rapidity_at_time(line.first.t, after=True))
    turn = next(iter(rigid.turning.turns), None)
    t_rigid = turn.pivot.t / L if turn is not None and turn.rapidity_from == 0.0 else None
    ends = {side: rigid.material_worldline(sigma) for side, sigma in (("left", 0.0), ("right", L))}
    still = all(not e.segments and e.rapidity_before == 0.0 == e.rapidity_after for e in ends.values())
    end = ends[far]
    t_moves = None if still else (end.segments[0].start.t if end.segments else end.origin.t) / L
    return FarEnd(contact, far, contact.event.t / L, contact.event.t / L + 1.0, t_causal, by_light,
                  None if by_light else own, u_causal, contact.rod_rapidity_after, t_rigid, t_moves)


def _velocity(rapidity: float, frame: Frame) -> float:
    """The velocity in the frame of a body of this rapidity in S; a rounding-sized one is 0 (`Reading.velocity`)."""
    return 0.0 if abs(rapidity - frame.rapidity) <= SAME_RAPIDITY else math.tanh(rapidity - frame.rapidity)


def leaving(rigid, causal, frames) -> tuple[Leaving, ...]:
    """Each particle's velocity after its last impact (rigid) and its last separation (causal), in each frame."""
    out = []
    for p in causal.scenario.particles:
        last_rigid = [i for i in rigid.impacts if i.particle == p.name][-1]
        mine = [i for i in causal.impacts if i.particle == p.name]
        last_causal = [i for i in mine if i.kind == "separation"][-1]
        out.append(Leaving(p.name, {f.name: _velocity(last_rigid.particle_rapidity_after, f) for f in frames},
                           {f.name: _velocity(last_causal.particle_rapidity_after, f) for f in frames},
                           sum(i.kind == "contact" for i in mine)))
    return tuple(out)


def ringing(rigid, causal) -> Ringing:
    """The ringing rod after the last separation, from its period's advance (docs/model.md, "The causal rod")."""
    L = causal.scenario.L
    dt, dx = causal.period_advance()
    E, p = dt / (2.0 * L), dx / (2.0 * L)  # (M/2L)(Δt, Δx), M = 1

    def kinetic(history, after: bool) -> float:
        total = 0.0
        for q in history.scenario.particles:
            mine = [i for i in history.impacts if i.particle == q.name]
            th = mine[-1].particle_rapidity_after if after else mine[0].particle_rapidity_before
            total += EnergyMomentum.of(q.mass, th).T
        return total

    last = max(i.event.t for i in causal.impacts if i.kind == "separation") / L
    return Ringing(last, dt / L, dx / L, E, p, math.sqrt((E - p) * (E + p)), dx / dt,
                   _velocity(rigid.final_rapidity, rest_frame()), kinetic(rigid, False), kinetic(rigid, True),
                   kinetic(causal, True))


def stress_slice(rigid, causal, frames) -> StressSlice:
    """The slice where the rigid ledger's hidden momentum is largest, in the first frame shown where it has one and
    the causal rod is stressed there too (moving frames before S: the paper's S′ first); where no frame has such a
    slice (the causal rod not yet reached), halfway through the causal rod's first contact in the first moving
    frame (else the first frame). So the comparison sets the two against each other wherever the rigid model has a
    hidden part (`single`'s is in S only: in S′ its rod turns about the struck end at rest)."""
    ordered = [f for f in frames if f.name != "rest"] + [f for f in frames if f.name == "rest"]
    first = causal.impacts[0]
    ended = next(i for i in causal.impacts if i.kind == "separation" and i.particle == first.particle)
    candidates = []
    for frame in ordered:
        f = frame.rapidity
        hidden = {t: abs(rigid.energy_momentum(f, t).hidden.p) for t in tables.hidden_instants(rigid, frame)}
        if hidden and max(hidden.values()) > UNSTRESSED * rigid.initial_total(f).E:
            candidates.append((frame, max(hidden, key=hidden.get)))
    fallback = ordered[0] if ordered else frames[0]
    candidates.append((fallback, 0.5 * (first.event.time_in(fallback.rapidity) + ended.event.time_in(fallback.rapidity))))
    for frame, t in candidates:  # a slice the rigid rod's stress crosses, unless the causal rod's has not reached it
        f = frame.rapidity
        s = causal.energy_momentum(f, t, split=True)
        parts = dict(s.rod_parts)
        if abs(parts["stress"].p) > UNSTRESSED * s.kinetic.E:
            break
    rod = dict(s.bodies)["rod"]
    return StressSlice(frame, t, rigid.energy_momentum(f, t).hidden, parts["matter"], parts["stress"],
                       tuple((n, em) for n, em in s.bodies if n != "rod"), causal.initial_total(f),
                       (rod.E, rod.p), tuple(float(x) for x in causal.fronts.rest_mass_motion(f, [t])[0]))


def compare(rigid, causal, frames) -> Comparison:
    """The numbers of the comparison of one scenario's two rods, `frames` the handout's (S, S′ ...): worked out once
    per pair of histories and frames (a handout and its worksheet, a worksheet and its key, compare the same rods;
    the Comparison is frozen and only read)."""
    return _compare(rigid, causal, tuple(frames))


@functools.lru_cache(maxsize=16)
def _compare(rigid, causal, frames: tuple[Frame, ...]) -> Comparison:
    first = {p.name: (p.mass, math.tanh(next(i for i in causal.impacts if i.particle == p.name)
                                        .particle_rapidity_before)) for p in causal.scenario.particles}
    ring = ringing(rigid, causal)
    return Comparison(causal.scenario.L, first, far_end(rigid, causal), leaving(rigid, causal, frames), ring,
                      stress_slice(rigid, causal, frames), energies(rigid, causal, frames, ring))
