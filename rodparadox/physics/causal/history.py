"""A run of the causal rod: the stiffest rod relativity allows, sound at c (docs/model.md, "The causal rod"). Pure.

`run(scenario)` places the particles as the rigid engine does (a gap, or an impact timed against the other
particle's first contact, here in the causal rod), solves the invariants (`causal_solve`) and returns a
`CausalHistory`, the rod interface (`history.RodHistory`) with the capability `fronts`. Its events are each contact's
start ("contact") and end ("separation"); every world-line is exact (`kinematics.ChartCurve`, boosted by
scaling the chart map), the rod's ends and material points ringing for ever after the last separation.

Energy and momentum, exactly. In null coordinates U = t + x, V = t - x the rod's stress-energy has T_UV = rho0/4,
T_UU = (rho0/4) exp(-2 r+) along u, T_VV = (rho0/4) exp(-2 r-) along w (rho0 = M/L), so on the slice t = const
(dU = dx = -dV) the rod's energy and momentum are
  E = (rho0/2)(x_R - x_L) + (rho0/4)(I+ + I-),  p = (rho0/4)(I- - I+),
with I+ = int from u_L to u_R of exp(-r+) du and I- = int from w_R to w_L of exp(-r-) dw, the ends' chart
coordinates on the slice (u_L = w_L = T_L; u_R = T_R + L, w_R = T_R - L). A frame of rapidity f shifts
r+ by -f and r- by +f: I+ -> e^f I+, I- -> e^-f I-. Fronts (jumps of lam) sit inside these integrals exactly.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

from rodparadox.errors import ScenarioError
from rodparadox.physics.causal.arrays import Arrays
from rodparadox.physics.causal.chart import CausalChart, points_on_slice
from rodparadox.physics.causal.extremes import causal_rapidity_range, compression_range
from rodparadox.physics.causal.parts import rest_mass_motion, rod_parts, rod_parts_on_slices
from rodparadox.physics.causal.solve import Budget, Rider, Solution, solve
from rodparadox.physics.kinematics import ChartCurve, Event, Line, WorldLine
from rodparadox.physics.ledger import initial_total
from rodparadox.physics.model import Scenario
from rodparadox.physics.types import EnergyMomentum, Impact, Slice, ZERO


def run(scenario: Scenario, starts: dict[str, Event] | None = None, budget: int | None = None) -> "CausalHistory":
    """The causal rod's history of a scenario (the same scenarios the rigid engine runs), the particles starting
    at `starts` (default: `particle_starts`); `budget`: a bound on its work, in windows of chart time L, stretches
    of an end's window and steps of its contacts (`budget.Budget`), or None for the solver's own bounds."""
    spend = None if budget is None else Budget(budget)
    history = _run(scenario, particle_starts(scenario, spend) if starts is None else starts, spend)
    _check_conserved(history)
    return history


def particle_starts(scenario: Scenario, budget: Budget | None = None) -> dict[str, Event]:
    """Each particle's event at t = 0: from its gap, or timed against the other particle's first contact in the
    causal rod (that run within `budget`, where given)."""
    starts = {p.name: _start_from_gap(scenario, p) for p in scenario.particles if p.gap is not None}
    for p in scenario.particles:
        if p.timed_with is not None:
            starts[p.name] = _start_from_timing(scenario, p, starts, budget)
    return starts


#: the run is refused where the total after the last separation misses the initial total by more than this,
#: relative to the initial energy, in S or S' (docs/model.md, "The causal rod": "to 1e-9"). Ordinary runs keep it to
#: 1e-12 or better; the rounding grows with the compressions (lam up to e^(2 th) at v = 0.9999999)
CONSERVED = 1e-9


def _check_conserved(history: "CausalHistory") -> None:
    """Refuse, in one sentence naming what to change, a run whose totals double precision cannot keep."""
    scenario = history.scenario
    for f in (0.0, -math.atanh(scenario.v)):
        t = max(i.event.seen_from(f).t for i in history.impacts) + scenario.L
        missing = history.energy_momentum(f, t).hidden
        initial = history.initial_total(f)
        worst = max(abs(missing.T), abs(missing.p)) / (initial.rest + initial.T)
        if not worst <= CONSERVED:
            raise ScenarioError(f"the causal rod's run keeps energy and momentum only to {worst:.0e} of the total "
                                f"in double precision (its compressions are too extreme at v = {scenario.v!r} with "
                                f"these masses); choose a lower v or masses nearer the rod's.", "v")


def _rapidity(scenario: Scenario, p) -> float:
    return (1.0 if p.name == "A" else -1.0) * math.atanh(scenario.speed(p))


def _start_from_gap(scenario: Scenario, p) -> Event:
    side = -1.0 if p.name == "A" else 1.0
    return Event(side * scenario.L * (0.5 + p.gap), 0.0)


def _start_from_timing(scenario: Scenario, p, starts: dict[str, Event], budget: Budget | None = None) -> Event:
    """As the rigid engine (`engine._start_from_timing`), in the causal rod: the target is p's end, at the timing
    frame's time of the other particle's first contact plus the delay, in the run without p."""
    timing = p.timed_with
    other = scenario.particle(timing.particle)
    alone = _run(Scenario(scenario.name, scenario.v, (other,), scenario.L), {other.name: starts[other.name]},
                 budget)
    reference = next(i for i in alone.impacts if i.particle == other.name)
    eta = math.atanh(scenario.frame_velocity(timing.frame))
    end_line = alone.worldline(f"rod_{p.end}").seen_from(eta)
    target = end_line.event_at_time(reference.event.seen_from(eta).t + timing.delay * scenario.L).seen_from(-eta)
    return Event(target.x - math.tanh(_rapidity(scenario, p)) * target.t, 0.0)


def _run(scenario: Scenario, starts: dict[str, Event], budget: Budget | None = None) -> "CausalHistory":
    L = scenario.L
    riders = {}
    T_first = math.inf
    for p in scenario.particles:
        if p.name not in starts:
            continue
        th, start = _rapidity(scenario, p), starts[p.name]
        riders[p.name] = Rider(p.name, p.end, p.mass, th, start.t, start.x)
        end_x = -0.5 * L if p.end == "left" else 0.5 * L
        T_first = min(T_first, start.t + (end_x - start.x) / math.tanh(th))  # the resting rod's end: T = t
    solution = solve(L, {n: 1.0 / r.mass for n, r in riders.items()}, riders, T_first, budget)
    history = CausalHistory(scenario, solution, starts)
    for p in scenario.particles:
        if p.name in starts and not any(i.particle == p.name for i in history.impacts):
            raise ScenarioError(f"particles.{p.name} never reaches the rod; give it a speed towards the rod.",
                                f"particles.{p.name}")
    return history



@dataclass(frozen=True)
class RodParts:
    """The causal rod's (E, p) on a slice: matter (rho u u, rho the rest-frame energy density, elastic energy
    included) and stress (p (u u - eta), von Laue's momentum of a stressed body); their sum is the rod's total."""

    matter: EnergyMomentum
    stress: EnergyMomentum


class CausalHistory:
    """The rod interface (`history.RodHistory`) for the causal rod. Coordinates in S, units of L, M = 1."""

    model = "causal"
    turning = None  # no turns: its lines of simultaneity are not the rigid rod's (physics.history.Turning)
    driving = None  # struck by particles, not driven by forces (physics.history.Driving)

    @property
    def fronts(self) -> "CausalHistory":
        """The causal rod's own part of the interface (`physics.history.Fronts`): itself."""
        return self

    def own_chart(self) -> CausalChart:
        """The rod's own chart: its material chart (T, X)."""
        return CausalChart(self)

    def rapidity_range(self) -> tuple[float, float]:
        """The least and largest rapidity in S of any material point over the whole history, 0 included."""
        return causal_rapidity_range(self)

    @functools.cached_property
    def arrays(self) -> Arrays:
        """The solution for whole arrays of chart times (`causal.arrays`), made once."""
        return Arrays(self.solution)

    def rod_parts_on_slices(self, frame_rapidity, times) -> tuple:
        """The matter and stress parts on many slices at once, as arrays (`causal.parts`)."""
        return rod_parts_on_slices(self, frame_rapidity, times)

    def rest_mass_motion(self, frame_rapidity, times):
        """(n, 2): (E, p) of the material points' rest mass moving at their own velocities on each slice
        (`causal.parts`)."""
        return rest_mass_motion(self, frame_rapidity, times)

    def chart_tables(self, lo: float, hi: float, tolerance: float | None = None):
        """Tables of r+, a and r-, b over chart times [lo, hi] (`causal.tables.ChartTables`)."""
        from rodparadox.physics.causal.tables import TABLE_TOLERANCE, ChartTables

        return ChartTables(self, lo, hi, TABLE_TOLERANCE if tolerance is None else tolerance)

    def points_on_slice(self, frame_rapidity: float, t: float, sigmas) -> tuple:
        """Where each material point sigma is on the slice t of the frame, and its rapidity there (`chart`)."""
        return points_on_slice(self, frame_rapidity, t, sigmas)

    def compression_range(self) -> tuple[float, float]:
        """The least and largest ln lam anywhere in the rod over its whole history, 0 (unstressed) inside."""
        return compression_range(self)

    def rod_parts(self, frame_rapidity: float, t: float) -> tuple[EnergyMomentum, EnergyMomentum]:
        """The rod's (E, p) on the slice split into its matter part and its stress part (`causal.parts`)."""
        return rod_parts(self, frame_rapidity, t)

    def __init__(self, scenario: Scenario, solution: Solution, starts: dict[str, Event]):
        self.scenario, self.solution = scenario, solution
        self._end_times: dict[tuple[str, float, float], float] = {}
        self.starts = tuple(sorted(starts.items()))
        L = scenario.L
        first = {"left": math.inf, "right": math.inf}
        for e in solution.events:
            first[e.end] = min(first[e.end], e.T)
        self._first_left, self._first_right = first["left"], first["right"]
        self.impacts = tuple(self._impact(e) for e in sorted(solution.events, key=lambda e: (e.T, e.end)))
        self._ends = {"left": self.material_worldline(0.0), "right": self.material_worldline(L)}
        self.final_rapidity = self._final_rapidity()
        self._particles = {name: self._particle_worldline(name, start) for name, start in starts.items()}

    # --- events and world-lines --------------------------------------------------------------------------------

    def _end_event(self, end: str, T: float) -> Event:
        X = 0.0 if end == "left" else self.scenario.L
        return ChartCurve(self.solution, X, T, T).point(T)

    def _impact(self, e) -> Impact:
        label = f"{e.particle}{e.number}" + ("" if e.kind == "contact" else "s")
        return Impact(label, e.particle, e.end, self._end_event(e.end, e.T), e.th_particle, e.th_particle,
                      e.th_end_before, e.th_end_after, kind=e.kind, line_rapidity=e.th_end_before)

    def _start_T(self, X: float) -> float:
        """The chart time the first front reaches material line X: from a contact at either end, at speed c."""
        return min(self._first_left + X, self._first_right + self.scenario.L - X)

    def material_worldline(self, sigma: float) -> WorldLine:
        """The exact world-line in S of the material point sigma (its label X, the unstressed distance from the
        left end): at rest until the first front reaches it, then the chart curve, for ever."""
        L = self.scenario.L
        if not 0.0 <= sigma <= L:
            raise ValueError(f"sigma must lie between 0 and L = {L!r}, got {sigma!r}")
        curve = ChartCurve(self.solution, sigma, self._start_T(sigma), math.inf)
        return WorldLine(curve.start, 0.0, (curve,), getattr(self, "final_rapidity", 0.0))

    def _particle_worldline(self, name: str, start: Event) -> WorldLine:
        end = self.scenario.particle(name).end
        X = 0.0 if end == "left" else self.scenario.L
        mine = [i for i in self.impacts if i.particle == name]
        segments = []
        for contact, separation in zip(mine[::2], mine[1::2]):
            if segments:
                segments.append(Line(segments[-1].end, contact.event))
            T0 = next(e.T for e in self.solution.events if e.kind == "contact" and e.particle == name
                      and e.number == int(contact.label[1:]))
            T1 = next(e.T for e in self.solution.events if e.kind == "separation" and e.particle == name
                      and e.number == int(contact.label[1:]))
            segments.append(ChartCurve(self.solution, X, T0, T1))
        return WorldLine(mine[0].event, mine[0].particle_rapidity_before, tuple(segments),
                         mine[-1].particle_rapidity_after)

    def worldline(self, name: str) -> WorldLine | None:
        if name in ("rod_left", "rod_right"):
            return self._ends[name[4:]]
        return self._particles.get(name)

    def material_velocity(self, sigma: float, frame_rapidity: float, t: float) -> float:
        return math.tanh(self.material_worldline(sigma).seen_from(frame_rapidity).rapidity_at_time(t))

    # --- energy and momentum -----------------------------------------------------------------------------------

    def end_chart_time(self, end: str, frame_rapidity: float, t: float) -> float:
        key = (end, frame_rapidity, t)  # each slice's ends are asked for by every layer: found once
        if key not in self._end_times:
            X = 0.0 if end == "left" else self.scenario.L
            # at Python floats: a numpy scalar's arithmetic (a time taken from an array) costs more, the floats the same
            line = ChartCurve(self.solution, X, -math.inf, math.inf, float(frame_rapidity))
            self._end_times[key] = line.chart_time(float(t))
        return self._end_times[key]

    def rod_energy_momentum(self, frame_rapidity: float, t: float) -> EnergyMomentum:
        """The rod's (E, p) on the slice t of the frame, from its stress-energy (module docstring), exactly."""
        L, f, sol = self.scenario.L, frame_rapidity, self.solution
        T_L, T_R = self.end_chart_time("left", f, t), self.end_chart_time("right", f, t)
        I_plus = sol.plus.integral(T_R + L, False) - sol.plus.integral(T_L, False)
        I_minus = sol.minus.integral(T_L, False) - sol.minus.integral(T_R - L, False)
        x_L = ChartCurve(sol, 0.0, T_L, T_L, f).point(T_L).x
        x_R = ChartCurve(sol, L, T_R, T_R, f).point(T_R).x
        rho0 = 1.0 / L
        E = 0.5 * rho0 * (x_R - x_L) + 0.25 * rho0 * (math.exp(f) * I_plus + math.exp(-f) * I_minus)
        p = 0.25 * rho0 * (math.exp(-f) * I_minus - math.exp(f) * I_plus)
        return EnergyMomentum(1.0, E - 1.0, p)

    def particle_energy_momentum(self, name: str, frame_rapidity: float, t: float) -> EnergyMomentum:
        line = self._particles[name].seen_from(frame_rapidity)
        return EnergyMomentum.of(self.scenario.particle(name).mass, line.rapidity_at_time(t))

    def energy_momentum(self, frame_rapidity: float, t: float, split: bool = False) -> Slice:
        """Each body's (E, p) on the slice t of the frame (A, B, the rod), their total, the part missing from the
        initial total (zero to rounding: nothing is hidden) and, with `split`, the rod's matter and stress parts."""
        bodies = [(n, self.particle_energy_momentum(n, frame_rapidity, t)) for n in sorted(self._particles)]
        bodies.append(("rod", self.rod_energy_momentum(frame_rapidity, t)))
        total = ZERO
        for _, em in bodies:
            total += em
        parts = ()
        if split:
            matter, stress = rod_parts(self, frame_rapidity, t)
            parts = (("matter", matter), ("stress", stress))
        return Slice(t, tuple(bodies), total, self.initial_total(frame_rapidity) - total, parts)

    def initial_total(self, frame_rapidity: float) -> EnergyMomentum:
        return initial_total(self, frame_rapidity)

    def _final_rapidity(self) -> float:
        """The rod's centre-of-momentum rapidity after the last separation: of its (E, p) over one period,
        (M/2L)(Dt, Dx) of any material point (docs/model.md, "The causal rod")."""
        D_t, D_x = self.period_advance()
        return math.atanh(D_x / D_t)

    def period_advance(self) -> tuple[float, float]:
        """(Dt, Dx) of every material point over one period 2L of chart time after the last separation."""
        sol = self.solution
        a_gain, b_gain = sol.plus.tail_gain[0], sol.minus.tail_gain[0]
        return 0.5 * (a_gain + b_gain), 0.5 * (a_gain - b_gain)

    @property
    def last_separation(self) -> float:
        """Chart time of the last separation: the rod rings freely from then on."""
        return self.solution.plus.tail_start
