"""The value types every rod model shares: an impact (a contact or a separation), a body's energy-momentum, the
ledger on a slice, and the names of the world-lines (docs, "The model"). A leaf beside `kinematics` (its events).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from rodparadox.physics.kinematics import Event

WORLDLINE_NAMES = ("A", "B", "rod_left", "rod_right")


@dataclass(frozen=True)
class Impact:
    """One particle striking one end of the rod, at `event` (coordinates in S).

    Rapidities are in S. The rod's `rod_rapidity_before`/`after` are its
    dynamical rapidity (that of its energy-momentum M(cosh, sinh)) just before
    and just after the collision; `line_rapidity` is that of the rod's line of
    simultaneity through the impact, the rest frame of its shape there (the
    same as `rod_rapidity_before` unless the rod is still turning, rule 6).
    `collision` numbers the collisions from 0: impacts sharing it are one
    collision (rule 5). `simultaneous_with` names the impact at the other end
    on the same line of the rod's simultaneity; `while_turning` says the rod
    had not finished its previous turn.
    """

    label: str
    particle: str
    end: str
    event: Event
    particle_rapidity_before: float
    particle_rapidity_after: float
    rod_rapidity_before: float
    rod_rapidity_after: float
    simultaneous_with: str | None = None
    while_turning: bool = False
    line_rapidity: float = 0.0
    collision: int = 0
    #: "contact" (a particle meets an end; every rigid impact) or "separation" (it leaves a causal rod's end)
    kind: str = "contact"

    @property
    def is_separation(self) -> bool:
        """A particle leaving an end (a rod whose contacts last), not striking it."""
        return self.kind == "separation"


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
    #: the causal rod's (E, p) split into its matter part and its stress part (docs/model.md, "The causal rod")
    rod_parts: tuple[tuple[str, EnergyMomentum], ...] = ()


#: what a force event is (a rod driven by forces, `history.Driving.force_events`): its profile's first instant with
#: force, its largest, its last
FORCE_MOMENTS = ("start", "peak", "end")


@dataclass(frozen=True)
class ForceEvent:
    """A force's start, peak or end at one end: the event in S, the end's rapidity in S there, the force there
    (units of M c^2/L; at the end, the force just before it stops) and the instant in the profile's frame (units of
    L)."""

    end: str
    moment: str
    event: Event
    rapidity: float
    force: float
    profile_time: float
