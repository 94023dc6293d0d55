"""The rod interface: what every command reads from a run of a rod model (README, "From Python").

A drawing, a table, the ledger, an animation and a handout read a run only through `RodHistory`:

* the scenario it ran, and its events (`impacts`: each contact of a particle with an end, in the rod's own
  order), with the rod's velocity after the last one;
* exact world-lines in S of the particles and the rod's ends (`worldline`) and of any material point
  (`material_worldline(sigma)`, sigma its proper distance from the left end); `WorldLine.seen_from` gives
  them in any frame;
* a material point's velocity at an instant of any frame (`material_velocity`);
* energy and momentum of every body on any slice of any frame (`energy_momentum`), and the system's total
  (`initial_total`).

What only a rigid rod has is the optional, named part `rigid` (`RigidResponse`): the turns of its lines of
simultaneity about each impact (the paper's rule 3), its own "now" (the fans and the lines between turns),
and when each turn starts and ends in a frame. A model without it (the causal rod, whose signals run at c)
gives `rigid = None`, and every command leaves out what needs it. `engine.History`, the paper's rigid rod, is
the first implementation.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol, runtime_checkable

if TYPE_CHECKING:  # the types only: the interface imports no implementation
    from rodparadox.physics.engine import Impact, Turn
    from rodparadox.physics.kinematics import Event, WorldLine
    from rodparadox.physics.ledger import EnergyMomentum, Slice
    from rodparadox.physics.model import Scenario


@runtime_checkable
class RigidResponse(Protocol):
    """The part of a run only a rigid rod has: its turns and its own lines of simultaneity (README, "Inside the
    rod")."""

    turns: tuple["Turn", ...]

    def now_lines(self, per_turn: int = 4, between: int = 2) -> list[tuple["Event", "Event"]]:
        """The rod's own lines of simultaneity as (left end, right end) event pairs in S: each turn's fan through
        its pivot, and lines of its rest frame between turns."""

    def turn_interval(self, turn: "Turn", frame_rapidity: float) -> tuple[float, float]:
        """When the turn starts and ends in the frame's time (its earliest and latest corner)."""

    def turn_times(self, frame_rapidity: float) -> list[float]:
        """Every instant of the frame's time where a turn starts or ends, in order."""


@runtime_checkable
class RodHistory(Protocol):
    """A run of a rod model, as every command reads it. Coordinates in S, units of L, c = 1; a frame is given
    by its rapidity relative to S (`Frame.rapidity`)."""

    scenario: "Scenario"
    impacts: tuple["Impact", ...]
    final_rapidity: float

    @property
    def rigid(self) -> RigidResponse | None:
        """The rigid rod's own part (turns, its lines of simultaneity), or None for a model without one."""

    def worldline(self, name: str) -> "WorldLine | None":
        """The world-line in S of A, B, rod_left or rod_right (None for a particle the scenario lacks)."""

    def material_worldline(self, sigma: float) -> "WorldLine":
        """The exact world-line in S of the material point at proper distance sigma (0 to L) from the left end."""

    def material_velocity(self, sigma: float, frame_rapidity: float, t: float) -> float:
        """The velocity of material point sigma at the instant t of the frame."""

    def energy_momentum(self, frame_rapidity: float, t: float) -> "Slice":
        """Each body's (E, p) on the slice t of the frame, their total and the hidden part."""

    def initial_total(self, frame_rapidity: float) -> "EnergyMomentum":
        """The system's total (E, p) in the frame: the same on every slice (energy and momentum are conserved)."""
