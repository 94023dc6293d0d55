"""The rod interface: what every command reads from a run of a rod model (docs, "From Python").

A drawing, a table, the ledger, an animation, a handout and the page read a run only through `RodHistory`:

* the scenario it ran, each particle's event at t = 0 (`starts`), and its events (`impacts`: each contact of a
  particle with an end, and for a rod whose contacts last, each separation, in the rod's own order), with the
  rod's velocity after the last one;
* exact world-lines in S of the particles and the rod's ends (`worldline`) and of any material point
  (`material_worldline(sigma)`, sigma its proper distance from the left end); `WorldLine.seen_from` gives
  them in any frame;
* a material point's velocity at an instant of any frame (`material_velocity`);
* energy and momentum of every body on any slice of any frame (`energy_momentum`), and the system's total
  (`initial_total`);
* the rod's own chart, in which it is a fixed strip (`own_chart`, the rod's own view).

What only one model has is a named, optional capability, None where the model lacks it; a consumer asks for the
capability, never for the model's name:

* `turning` (`Turning`): the rigid rod's turns of its lines of simultaneity about each impact (the paper's
  rule 3), its own "now" (the fans and the lines between turns), and when each turn starts and ends in a frame;
* `fronts` (`Fronts`): the causal rod's signals at c: its solution in characteristic coordinates (the chart
  map, the fronts, the compression), the matter and stress parts of its energy-momentum, its ringing after the
  last separation;
* `driving` (`Driving`): a rod driven by forces at its ends (`scenario.forces`, docs "Forces at the ends")
  rather than struck by particles: the profiles, the (E, p) each agent delivered up to a slice's end events (the
  rod holds initial + delivered on every slice), the force at an end on a slice, the stress along a slice, each
  force's start, peak and end events, and the rod's own lines of simultaneity. A driven run has no impacts and
  no particle starts; its `energy_momentum` gives the rod's kinetic part and, as `hidden`, its stress part
  (their sum is `Driving.total`), and `initial_total` is the rod's before any force (not conserved: see
  `Driving.total`).

`model` names the model for people (headings, file names: "rigid", "causal"), not for branching.
The implementations are `physics.rigid.History`, `physics.rigid.DrivenHistory` (forces) and
`physics.causal.CausalHistory`; `physics.models` runs them.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol, runtime_checkable

if TYPE_CHECKING:  # the types only: the interface imports no implementation
    from rodparadox.physics.kinematics import Event, WorldLine
    from rodparadox.physics.model import Scenario
    from rodparadox.physics.types import EnergyMomentum, Impact, Slice


class Turn(Protocol):
    """One turn of the rigid rod's lines of simultaneity about its pivot (rule 3), as `Turning.turns` gives it."""

    pivot: "Event"
    pivot_end: str
    rapidity_from: float
    rapidity_to: float
    rapidity_stop: float
    stopped_by: str | None

    @property
    def completed(self) -> bool:
        """The turn reached the rod's dynamical rapidity (no impact on the far end stopped it)."""

    def corners(self) -> tuple["Event", "Event", "Event"]:
        """The pivot, and the far end where the turn starts and where it stops."""

    def interval(self, frame_rapidity: float) -> tuple[float, float]:
        """When the turn starts and ends in the frame's time."""


@runtime_checkable
class Turning(Protocol):
    """The part of a run only a rigid rod has: its turns and its own lines of simultaneity (docs, "Inside the
    rod")."""

    turns: tuple[Turn, ...]

    def now_lines(self, per_turn: int = 4, between: int = 2) -> list[tuple["Event", "Event"]]:
        """The rod's own lines of simultaneity as (left end, right end) event pairs in S: each turn's fan through
        its pivot, and lines of its rest frame between turns."""

    def turn_interval(self, turn, frame_rapidity: float) -> tuple[float, float]:
        """When the turn starts and ends in the frame's time (its earliest and latest corner)."""

    def turn_times(self, frame_rapidity: float) -> list[float]:
        """Every instant of the frame's time where a turn starts or ends, in order."""

    def rapidities(self) -> tuple[float, ...]:
        """Every rapidity, in S, a material point takes at the start or end of a piece of its world-line (the
        extremes of every point's rapidity are among these)."""


@runtime_checkable
class Fronts(Protocol):
    """The part of a run only a rod whose signals run at c has (the causal rod, docs "The causal rod"): its
    invariants and chart map (`solution`), where each end is on a slice (`end_chart_time`), the matter and stress
    parts of its (E, p), and how it rings after the last separation."""

    solution: object

    def end_chart_time(self, end: str, frame_rapidity: float, t: float) -> float:
        """The chart time T at which the end ("left" or "right") crosses the slice t of the frame."""

    def rod_parts(self, frame_rapidity: float, t: float) -> tuple["EnergyMomentum", "EnergyMomentum"]:
        """The rod's (E, p) on the slice split into its matter part and its stress part."""

    def rod_parts_on_slices(self, frame_rapidity, times) -> tuple:
        """The matter and stress parts on many slices at once (one frame, or a frame per slice): two (n, 2) arrays
        of (E, p), the same integral as `rod_parts`."""

    def rest_mass_motion(self, frame_rapidity, times):
        """(n, 2): (E, p) of the rod's material points' rest mass moving at their own velocities on each slice,
        (M/L) int_0^L (cosh psi, sinh psi) d sigma, psi the rapidity of material point sigma where it crosses it."""

    def chart_tables(self, lo: float, hi: float, tolerance: float | None = None):
        """Tables of the invariants and the chart map over chart times [lo, hi], evaluated for whole arrays at once
        (r, a and b within `tolerance` L of the solution's)."""

    def period_advance(self) -> tuple[float, float]:
        """(Dt, Dx) of every material point over one period 2L of chart time after the last separation."""

    def compression_range(self) -> tuple[float, float]:
        """The least and largest ln lam (lam the compression) anywhere in the rod over its whole history."""

    def points_on_slice(self, frame_rapidity: float, t: float, sigmas) -> tuple:
        """Where each material point sigma is on the slice t of the frame, and its rapidity there (two arrays)."""


@runtime_checkable
class Driving(Protocol):
    """The part of a run only a rod driven by forces has (docs, "Forces at the ends"). Frames by rapidity relative
    to S, times in the frame's coordinates (units of L, as every coordinate), (E, p) in M c^2 and M c, forces in
    M c^2/L."""

    def profiles(self) -> tuple:
        """(end, `forces.ForceProfile`) for each end with a force, left first."""

    def frame_rapidity(self, end: str) -> float:
        """The rapidity relative to S of the frame the end's profile is timed in."""

    def delivered(self, end: str, frame_rapidity: float, t: float) -> "EnergyMomentum":
        """The (E, p), in the frame, the agent at `end` ("left", "right") delivered up to that end's event on the
        slice t of the frame (zero for an end without force)."""

    def total(self, frame_rapidity: float, t: float) -> "EnergyMomentum":
        """The rod's (E, p) before any force plus what both agents delivered up to the slice: what it holds."""

    def force_at(self, end: str, frame_rapidity: float, t: float) -> float:
        """The force at the end's event on the slice t of the frame."""

    def stress(self, frame_rapidity: float, t: float, sigmas) -> object:
        """The stress p (> 0 compression) where each material point sigma crosses the slice (an array)."""

    def force_events(self) -> tuple:
        """Each force's start, peak and end (`ForceEvent`: end, moment, event in S, the end's rapidity in S, the
        force, the instant in the profile's frame), ends in order, moments in order."""

    def now_lines(self, count: int = 12) -> list[tuple["Event", "Event"]]:
        """The rod's own lines of simultaneity as (left end, right end) event pairs in S."""

    def centre_of_energy(self, frame_rapidity: float, t: float) -> tuple[float, float]:
        """The rod's centre of energy x_E on the slice t of the frame, and its energy there."""

    def centre_velocity(self, frame_rapidity: float, t: float) -> float:
        """d x_E / dt: beside p / E, von Laue's point (equal for a closed system, not with forces)."""


@runtime_checkable
class RodHistory(Protocol):
    """A run of a rod model, as every command reads it. Coordinates in S, units of L, c = 1; a frame is given
    by its rapidity relative to S (`Frame.rapidity`)."""

    scenario: "Scenario"
    impacts: tuple["Impact", ...]
    starts: tuple[tuple[str, "Event"], ...]
    final_rapidity: float
    model: str

    @property
    def turning(self) -> Turning | None:
        """The rigid rod's turns and its own lines of simultaneity, or None for a model without them."""

    @property
    def fronts(self) -> Fronts | None:
        """The causal rod's fronts, chart and stress, or None for a model without them."""

    @property
    def driving(self) -> Driving | None:
        """The forces at the ends and what they delivered, or None for a rod struck by particles."""

    def own_chart(self):
        """The rod's own chart (T, X), in which the rod is the fixed strip 0 <= X <= L (`physics.rod_view`)."""

    def worldline(self, name: str) -> "WorldLine | None":
        """The world-line in S of A, B, rod_left or rod_right (None for a particle the scenario lacks)."""

    def material_worldline(self, sigma: float) -> "WorldLine":
        """The exact world-line in S of the material point at proper distance sigma (0 to L) from the left end."""

    def material_velocity(self, sigma: float, frame_rapidity: float, t: float) -> float:
        """The velocity of material point sigma at the instant t of the frame."""

    def rapidity_range(self) -> tuple[float, float]:
        """The least and largest rapidity in S of any material point over the whole history, 0 included."""

    def energy_momentum(self, frame_rapidity: float, t: float) -> "Slice":
        """Each body's (E, p) on the slice t of the frame, their total and the hidden part."""

    def initial_total(self, frame_rapidity: float) -> "EnergyMomentum":
        """The system's total (E, p) in the frame: the same on every slice (energy and momentum are conserved)."""
