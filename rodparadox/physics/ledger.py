"""The energy-momentum ledger of any rod model (the docs, "Energy and momentum: the ledger"): the system's total
before the first impact, each particle's (E, p) on a slice of any frame, and every body just before and after each
impact, the rod's own part read from the model (`RodHistory.energy_momentum`). Pure.

Units: energy in M c^2, momentum in M c (c = 1); a particle of mass m and rapidity a has m (cosh a, sinh a). How
the rod's part is found is the model's own: in closed form for the rigid rod (`rigid.ledger`, with the hidden
part), from its stress-energy for the causal rod (`causal.history`, matter and stress).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from rodparadox.physics.frames import time_order
from rodparadox.physics.history import RodHistory
from rodparadox.physics.types import EnergyMomentum, Impact, ZERO
from rodparadox.tolerances import ONE_INSTANT, PRINTED_ZERO, SAME_INSTANT


def initial_total(history: RodHistory, frame_rapidity: float) -> EnergyMomentum:
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


def particle_on_slice(history: RodHistory, name: str, frame_rapidity: float, t: float, after: bool = True) -> EnergyMomentum:
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


def impact_entries(history: RodHistory, frame_rapidity: float) -> tuple[ImpactEntry, ...]:
    """Every impact in the order of the frame's time (the rod's own order for impacts at one instant), with the
    (E, p) of every body just before and after it."""
    out = []
    total = initial_total(history, frame_rapidity)
    names = sorted(p.name for p in history.scenario.particles)
    for i in history.impacts:
        t = i.event.time_in(frame_rapidity)
        rod = dict(history.energy_momentum(frame_rapidity, t).bodies)["rod"]
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


def instant_entries(history: RodHistory, frame_rapidity: float) -> tuple[InstantEntry, ...]:
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
