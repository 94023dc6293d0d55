"""Runs a scenario: impacts, the rod's rigid response, the order of impacts (docs/model.md, "The model"). Pure.

Everything is computed in S, the rod's rest frame before any impact, as exact
segments; `History` is the result, and `kinematics` boosts it to any frame.

The rod's motion is a chain of *turns*. A collision fixes the rod's
energy-momentum at once: its *dynamical* rapidity theta' (rule 2). Its shape
follows only as the turn proceeds: the rod's lines of simultaneity turn
about the pivot P, from the line they had (rapidity phi) to theta' (rule 3).
The pivot is the end on the side the rod is pushed from (a gain to the right
turns about the left end, else the far end would move before the impact),
which is the struck end of a single impact. The far end, a proper distance L
from P, moves on the hyperbola P + side*L*(cosh psi, sinh psi), psi from phi
to theta', then on at theta'. The rod's own time orders the impacts (rule 4):
while the lines still fan out from P, only the far end can be struck; such an
impact on the fan line at psi is a collision with the rod of dynamical
rapidity theta' (revised rule 6), the turn stops on that line, and the next
turn starts there, from psi. Every collision conserves energy and momentum,
so the whole history does.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

from rodparadox.physics.collision import elastic
from rodparadox.errors import ScenarioError
from rodparadox.physics.kinematics import Event, HyperbolicArc, Line, Segment, WorldLine
from rodparadox.physics.ledger import initial_total
from rodparadox.physics.model import Particle, Scenario
from rodparadox.physics.rigid.chart import RigidChart
from rodparadox.physics.rigid.ledger import ledger_slice
from rodparadox.physics.rigid.turns import RigidTurns, Turn, material_worldline
from rodparadox.physics.types import EnergyMomentum, Impact, Slice, WORLDLINE_NAMES
from rodparadox.tolerances import DIFFERENCE_ROUNDING, SAME_EVENT, SIMULTANEITY_TOLERANCE, TIMING_MATCH, TURN_LINE_ROUNDING

#: at most this many material points' world-lines kept per history (`History.material_worldline`): a strip's points,
#: a figure's rod lines and a ledger's grid are a few hundred; a slice integrated by quadrature (thousands of points,
#: each read once) would only fill memory and the garbage collector's rounds
KEEP_MATERIAL = 512

#: a scenario with more impacts than this is refused rather than run forever
MAX_IMPACTS = 1000


@dataclass(frozen=True)
class History:
    """The exact world-lines of a scenario in S, its impacts and turns in the rod's own order, each particle's event
    at t = 0, and the rod's rapidity after the last impact."""

    scenario: Scenario
    impacts: tuple[Impact, ...]
    worldlines: tuple[tuple[str, WorldLine], ...]
    starts: tuple[tuple[str, Event], ...]
    turns: tuple[Turn, ...] = ()
    final_rapidity: float = 0.0

    # The rod interface (physics.history.RodHistory), of which this rigid rod is the first implementation.

    model = "rigid"
    fronts = None  # its signals are instantaneous: no fronts (physics.history.Fronts)
    driving = None  # struck by particles, not driven by forces (physics.history.Driving)

    def worldline(self, name: str) -> WorldLine | None:
        """The world-line of A, B, rod_left or rod_right (None for a particle the scenario lacks)."""
        return dict(self.worldlines).get(name)

    @property
    def turning(self) -> RigidTurns:
        """The rigid rod's own part of the interface: its turns and its own lines of simultaneity."""
        return RigidTurns(self)

    def own_chart(self) -> RigidChart:
        """The rod's own chart: its rest frames between turns, each turn's Rindler chart (`rigid.chart`)."""
        return RigidChart(self)

    def material_worldline(self, sigma: float) -> WorldLine:
        """The exact world-line in S of the material point at proper distance sigma from the left end."""
        # each point's world-line is built once per history and kept (in the instance's __dict__, outside the frozen
        # fields: equality and hash are the fields'): a slice of the rod (`rod.rod_slice`), a material velocity on a
        # grid of instants, reads the same few points again and again. Kept by value and type: a numpy scalar's
        # world-line holds numpy scalars, a float's floats; 0.0 and -0.0 give the same world-line.
        known = self.__dict__.get("_material")
        if known is None:
            known = self.__dict__["_material"] = {}
        key = (sigma, type(sigma))
        try:
            line = known.get(key)
        except TypeError:  # an unhashable number (a numpy array of one value): built afresh
            return material_worldline(self, sigma)
        if line is None:
            line = material_worldline(self, sigma)
            if len(known) < KEEP_MATERIAL:  # the first points asked for; a quadrature's thousands are built and let go
                known[key] = line
        return line

    def rapidity_range(self) -> tuple[float, float]:
        """The least and largest rapidity in S of any material point over the whole history, 0 included (the
        turns' ends: `RigidTurns.rapidities`)."""
        rapidities = self.turning.rapidities()
        return min(rapidities), max(rapidities)

    def material_velocity(self, sigma: float, frame_rapidity: float, t: float) -> float:
        """The velocity of material point sigma at the instant t of the frame of rapidity `frame_rapidity`."""
        return math.tanh(self.material_worldline(sigma).seen_from(frame_rapidity).rapidity_at_time(t))

    def energy_momentum(self, frame_rapidity: float, t: float) -> Slice:
        """Each body's (E, p) on the slice t of the frame, their total and the hidden part (`types.Slice`)."""
        return ledger_slice(self, frame_rapidity, t)

    def initial_total(self, frame_rapidity: float) -> EnergyMomentum:
        """The system's total (E, p) in the frame."""
        return initial_total(self, frame_rapidity)


def particle_starts(scenario: Scenario) -> dict[str, Event]:
    """Each particle's event at t = 0: from its gap, or timed against the other particle's first impact."""
    starts = {p.name: _start_from_gap(scenario, p) for p in scenario.particles if p.gap is not None}
    for p in scenario.particles:
        if p.timed_with is not None:
            starts[p.name] = _start_from_timing(scenario, p, starts)
    return starts


def run(scenario: Scenario, starts: dict[str, Event] | None = None) -> History:
    """The history of a scenario: particles placed (`starts`, default `particle_starts`), then simulated in S."""
    history = _simulate(scenario, particle_starts(scenario) if starts is None else starts)
    for p in scenario.particles:
        if not any(i.particle == p.name for i in history.impacts):
            raise ScenarioError(f"particles.{p.name} never reaches the rod; give it a speed towards the rod.",
                                f"particles.{p.name}")
    return history


def _start_from_gap(scenario: Scenario, p: Particle) -> Event:
    side = -1.0 if p.name == "A" else 1.0
    return Event(side * scenario.L * (0.5 + p.gap), 0.0)


def _particle_rapidity(scenario: Scenario, p: Particle) -> float:
    return math.atanh(scenario.speed(p)) * (1.0 if p.name == "A" else -1.0)


def _start_from_timing(scenario: Scenario, p: Particle, starts: dict[str, Event]) -> Event:
    """Place p so that its first impact comes `delay` after the other particle's first, in the timing frame.

    The rod's history up to p's first impact does not depend on p (rule 4), so
    the target event is read off p's end of the rod in the scenario without p;
    the full run then must find p's impact there and the other particle's first
    impact unchanged, else the timing asked for contradicts itself.
    """
    timing = p.timed_with
    key = f"particles.{p.name}.timed_with"
    other = scenario.particle(timing.particle)
    without = Scenario(scenario.name, scenario.v, (other,), scenario.L)
    alone = _simulate(without, {other.name: starts[other.name]})
    reference = next(i for i in alone.impacts if i.particle == other.name)
    eta = math.atanh(scenario.frame_velocity(timing.frame))
    end_line = alone.worldline(f"rod_{p.end}").seen_from(eta)
    target_time = reference.event.seen_from(eta).t + timing.delay * scenario.L
    target = end_line.event_at_time(target_time).seen_from(-eta)
    start = Event(target.x - math.tanh(_particle_rapidity(scenario, p)) * target.t, 0.0)

    history = _simulate(scenario, {**starts, p.name: start})
    first = {name: next((i for i in history.impacts if i.particle == name), None) for name in (p.name, other.name)}
    scale = scenario.L + abs(target.t) + abs(target.x)
    lands = first[p.name] is not None and _distance(first[p.name].event, target) <= TIMING_MATCH * scale
    reference_kept = first[other.name] is not None and _distance(first[other.name].event, reference.event) <= TIMING_MATCH * scale
    order = list(history.impacts)
    not_first = lands and reference_kept and (order.index(first[p.name]) > order.index(first[other.name])
                                              or first[p.name].simultaneous_with == first[other.name].label)
    if not not_first:
        raise ScenarioError(
            f"{key}: {p.name} cannot strike the rod with delay {timing.delay:g} after {other.name}'s first impact, "
            f"because its impact would come first in the rod's own time and move {other.name}'s; "
            f"time {other.name} against {p.name} instead, or give {p.name} a gap.", key)
    return start


def _distance(a: Event, b: Event) -> float:
    return math.hypot(a.x - b.x, a.t - b.t)


# --- the simulation -------------------------------------------------------------------------------

@dataclass
class _ParticleState:
    name: str
    mass: float
    rapidity: float
    start: Event
    initial_rapidity: float
    since: Event | None = None  # last impact
    kinks: list = field(default_factory=list)  # [(event, rapidity after)]
    impacts: int = 0


@dataclass(frozen=True)
class _Phase:
    """From the rod simultaneity line (left0, right0) at rapidity theta0: a turn about `pivot` to theta1, then free motion."""

    theta0: float
    left0: Event
    right0: Event
    pivot: str | None
    theta1: float
    L: float
    bounded: bool = True  # False for the rod's motion before any impact, which has no start

    @property
    def turn(self) -> HyperbolicArc | None:
        """The far end's hyperbola: proper distance L from the pivot, rapidity theta0 -> theta1."""
        if self.pivot is None:
            return None
        centre, side = (self.left0, 1) if self.pivot == "left" else (self.right0, -1)
        return HyperbolicArc(centre, self.L, side, self.theta0, self.theta1)


def _simulate(scenario: Scenario, starts: dict[str, Event]) -> History:
    L = scenario.L
    tolerance = SIMULTANEITY_TOLERANCE * L
    particles = {
        p.name: _ParticleState(p.name, p.mass, _particle_rapidity(scenario, p), starts[p.name],
                                _particle_rapidity(scenario, p))
        for p in scenario.particles if p.name in starts
    }
    ends: dict[str, list[Segment]] = {"left": [], "right": []}
    impacts: list[Impact] = []
    turns: list[Turn] = []
    phase = _Phase(0.0, Event(-L / 2, 0.0), Event(L / 2, 0.0), None, 0.0, L, bounded=False)
    first_line = None
    collisions = 0

    while True:
        if len(impacts) > MAX_IMPACTS:
            raise ScenarioError(f"the rod is struck more than {MAX_IMPACTS} times; this scenario does not settle.")
        arc = phase.turn
        far_start = None if arc is None else (phase.right0 if arc.side == 1 else phase.left0)
        hit = _hit_while_turning(arc, far_start, L, particles) if arc is not None else None
        if hit is not None:
            name, phi, completed = hit
            far = "right" if arc.side == 1 else "left"
            stopped = HyperbolicArc(arc.centre, arc.radius, arc.side, arc.phi_start, phi)
            ends[far].append(stopped)
            event = stopped.end
            struck = [(name, far, event)]
            line_rapidity, while_turning = phi, not completed
            new_left, new_right = (arc.centre, event) if far == "right" else (event, arc.centre)
            stopped_by = None if completed else f"{name}{particles[name].impacts + 1}"
            turns.append(_turn_of(phase, phi, stopped_by))
        else:
            if arc is not None:
                far = "right" if arc.side == 1 else "left"
                ends[far].append(arc)
                left1, right1 = (arc.centre, arc.end) if far == "right" else (arc.end, arc.centre)
                turns.append(_turn_of(phase, phase.theta1, None))
            else:
                left1, right1 = phase.left0, phase.right0
            theta = phase.theta1
            found = _hits_after_turn(theta, left1, right1, particles, phase.bounded, tolerance)
            if not found:
                break
            line_rapidity, while_turning = theta, False
            _, first_end, first_event = found[0]
            if first_end == "left":
                new_left, new_right = first_event, first_event.displaced(L, theta)
            else:
                new_left, new_right = first_event.displaced(-L, theta), first_event
            struck = [(n, e, new_left if e == "left" else new_right) for n, e, _ in found]
            if phase.bounded:
                for end, a, b in (("left", left1, new_left), ("right", right1, new_right)):
                    if _distance(a, b) > SAME_EVENT * L:
                        ends[end].append(Line(a, b))

        # every collision on this rod line, with the rod's dynamical rapidity (rule 6): first the impact(s)
        # found, then any particle at an end of the line that the new motion of that end would run into
        rod_rapidity = phase.theta1
        on_line = len(impacts)
        while struck:
            relative = tuple(particles[n].rapidity - rod_rapidity for n, _, _ in struck)
            rod_change, particle_after = elastic(tuple(particles[n].mass for n, _, _ in struck), relative)
            new_theta = rod_rapidity + rod_change
            for (name, end, event), after in zip(struck, particle_after):
                state = particles[name]
                state.impacts += 1
                impacts.append(Impact(f"{name}{state.impacts}", name, end, event, state.rapidity, rod_rapidity + after,
                                      rod_rapidity, new_theta, while_turning=while_turning,
                                      line_rapidity=line_rapidity, collision=collisions))
                state.rapidity = rod_rapidity + after
                state.since = event
                state.kinks.append((event, state.rapidity))
            collisions += 1
            rod_rapidity = new_theta
            struck = _running_into_the_rod(particles, new_left, new_right, line_rapidity, rod_rapidity)
            if len(impacts) > MAX_IMPACTS:
                break
        _link_simultaneous(impacts, on_line)
        pivot = None if rod_rapidity == line_rapidity else ("left" if rod_rapidity > line_rapidity else "right")
        first_line = first_line or (new_left, new_right)
        phase = _Phase(line_rapidity, new_left, new_right, pivot, rod_rapidity, L)

    worldlines = [(name, _particle_worldline(state)) for name, state in particles.items()]
    # each end's world-line starts at the rod's simultaneity line through the first impact, so that
    # impact is a point of it even where the end does not kink (Fig. 1)
    origins = first_line or (Event(-L / 2, 0.0), Event(L / 2, 0.0))
    for end, origin in zip(("left", "right"), origins):
        worldlines.append((f"rod_{end}", WorldLine(origin, 0.0, tuple(ends[end]), phase.theta1)))
    order = {n: i for i, n in enumerate(WORLDLINE_NAMES)}
    worldlines.sort(key=lambda item: order[item[0]])
    return History(scenario, tuple(impacts), tuple(worldlines),
                   tuple((name, state.start) for name, state in sorted(particles.items())),
                   tuple(turns), phase.theta1)


def _turn_of(phase: _Phase, stop: float, stopped_by: str | None) -> Turn:
    pivot = phase.left0 if phase.pivot == "left" else phase.right0
    return Turn(pivot, phase.pivot, phase.theta0, phase.theta1, stop, stopped_by, phase.L)


def _running_into_the_rod(particles: dict, left: Event, right: Event, line_rapidity: float,
                          rod_rapidity: float) -> list[tuple[str, str, Event]]:
    """Particles at an end of the rod line (left, right) that the end's motion just after it would run into.

    After a collision the rod turns from the line's rapidity towards its new
    dynamical one about the end it is pushed from; that end leaves the line at
    the new rapidity, the other at the line's. A particle sitting at an end (it
    struck there, or struck the pivot of a turn stopped on this line) and
    moving into the rod at that end's speed strikes it again at once: the
    re-strike of a particle heavier than the rod at the old pivot (rule 6).
    Such a particle also closes on the rod's dynamical rapidity, so the
    collision is an ordinary one; the repeated collisions end, as three bodies
    on a line collide only finitely often.
    """
    left_rapidity = rod_rapidity if rod_rapidity > line_rapidity else line_rapidity
    right_rapidity = rod_rapidity if rod_rapidity < line_rapidity else line_rapidity
    out = []
    a, b = particles.get("A"), particles.get("B")
    if a is not None and a.since == left and a.rapidity > left_rapidity:
        out.append(("A", "left", left))
    if b is not None and b.since == right and b.rapidity < right_rapidity:
        out.append(("B", "right", right))
    return out


def _link_simultaneous(impacts: list[Impact], first: int) -> None:
    """Impacts at the two ends on one rod line (from index `first` on) name each other: the first at the other end."""
    on_line = impacts[first:]
    for k, i in enumerate(on_line):
        other = next((o for o in on_line if o.end != i.end), None)
        if other is not None:
            impacts[first + k] = replace(i, simultaneous_with=other.label)


def _particle_worldline(state: _ParticleState) -> WorldLine:
    # a particle struck twice at one event (rule 6 with a heavy particle) kinks once, to its last rapidity
    kinks = [k for k, after in zip(state.kinks, state.kinks[1:] + [None]) if after is None or after[0] != k[0]]
    before = state.initial_rapidity
    if not kinks:
        return WorldLine(state.start, before)
    segments = tuple(Line(a, b) for (a, _), (b, _) in zip(kinks, kinks[1:]))
    return WorldLine(kinks[0][0], before, segments, kinks[-1][1])


def _hit_while_turning(arc: HyperbolicArc, far_start: Event, L: float,
                       particles: dict) -> tuple[str, float, bool] | None:
    """The far end struck during the turn: (particle, rapidity phi of the fan line through it, on the last line?), or None.

    In the particle's rest frame (rapidity psi) the arc is x = side*L*cosh(phi - psi)
    about the pivot and the particle stands at its proper distance D from the pivot,
    so they meet where cosh(phi - psi) = side*D/L; the closing root is
    phi = psi + side*acosh(side*D/L). A particle that sits at the arc's start
    (struck there just before, rule 6) meets it again at the mirror angle
    phi = 2*psi - phi_start exactly: acosh near 1 would lose that to rounding.
    """
    name = "B" if arc.side == 1 else "A"
    state = particles.get(name)
    if state is None:
        return None
    s, psi = arc.side, state.rapidity
    if state.since == far_start:
        phi = 2.0 * psi - arc.phi_start
        if not s * (phi - arc.phi_start) > 0:
            return None
        rounding = TURN_LINE_ROUNDING
    else:
        here = state.since or state.start
        dx, dt = here.x - arc.centre.x, here.t - arc.centre.t
        terms = (math.cosh(psi) * dx, math.sinh(psi) * dt)
        c = s * (terms[0] - terms[1]) / L
        if not c > 1.0:
            return None
        a = math.acosh(c)
        phi = psi + s * a
        # c comes from a difference of terms that may be far larger than L (high speeds, late impacts):
        # its rounding, divided by dc/dphi = sinh(a), bounds phi's
        rounding = max(TURN_LINE_ROUNDING, DIFFERENCE_ROUNDING * (abs(terms[0]) + abs(terms[1])) / L / max(math.sinh(a), 1e-300))
        if not s * (phi - arc.phi_start) > min(0.1 * TURN_LINE_ROUNDING, rounding):
            return None
        if state.since is not None and arc.point(phi).t < state.since.t - SAME_EVENT * L:
            return None
    if s * (phi - arc.phi_end) > rounding:
        return None
    completed = s * (phi - arc.phi_end) >= -rounding
    phi = arc.phi_end if completed else phi  # a hit on the turn's last line (Fig. 2's A1, B2) ends a complete turn
    return name, phi, completed


def _hits_after_turn(theta: float, left: Event, right: Event, particles: dict, bounded: bool,
                     tolerance: float) -> list[tuple[str, str, Event]]:
    """The next impact(s) on the rod moving freely at rapidity theta from the simultaneity line (left, right).

    Computed in the rod's rest frame, where the ends stand still: the earliest
    on the rod's own time axis, both ends if within `tolerance` (rule 5).
    """
    start_time = left.time_in(theta)
    candidates = []
    for name, end_event, sign in (("A", left, 1.0), ("B", right, -1.0)):
        state = particles.get(name)
        if state is None:
            continue
        w = math.tanh(state.rapidity - theta)
        if not sign * w > 0:
            continue  # moving away from its end, or with it
        here = (state.since or state.start).seen_from(theta)
        end_x = end_event.seen_from(theta).x
        t = here.t + (end_x - here.x) / w
        if bounded and t < start_time - tolerance:
            continue
        if state.since is not None and t < here.t - tolerance:
            continue
        candidates.append((t, name, Event(end_x, t).seen_from(-theta)))
    if not candidates:
        return []
    candidates.sort(key=lambda c: c[0])
    first_time = candidates[0][0]
    # a simultaneous pair is listed left end first, whatever rounding says about their order
    return sorted((name, "left" if name == "A" else "right", event)
                  for t, name, event in candidates if t - first_time <= tolerance)
