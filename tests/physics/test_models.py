"""The one door to the rod models (`physics.models`): one call runs a scenario in the rods asked for, and with both
rods the two are struck by the same particles (docs, "The causal rod": like for like).

The paper's Fig. 2 times A so that its first impact is simultaneous in S' with B's. That rule is resolved once, in
the scenario's own rod: for the rigid rod A1 is at (-3/4, 19/12) L in S (the paper's section 3), so A starts at
x = -3/4 - (3/5)(19/12) = -1.7 L, and the causal rod is struck by the very same A.
"""

from __future__ import annotations

import math

import pytest

from rodparadox.io.scenario import load
from rodparadox.physics import models
from rodparadox.physics.model import Particle, Scenario, Timing

PRESETS = ("fig1", "fig2", "single", "off_timing", "unequal_masses", "while_turning")


def initial_worldlines(history) -> dict[str, tuple[float, float, float]]:
    """Each particle's event at t = 0 and its rapidity before any contact, read from its world-line."""
    out = {}
    for name, _ in history.starts:
        w = history.worldline(name)
        start = w.first  # the world-line's first event is its first impact; step back to t = 0 along it
        r = w.rapidity_before
        out[name] = (start.x - math.tanh(r) * start.t, r, dict(history.starts)[name].x)
    return out


def same_particles(a, b, tolerance: float = 1e-12) -> bool:
    wa, wb = initial_worldlines(a), initial_worldlines(b)
    return wa.keys() == wb.keys() and all(
        abs(wa[n][k] - wb[n][k]) <= tolerance * (1 + abs(wa[n][k])) for n in wa for k in range(3))


@pytest.mark.parametrize("name", PRESETS)
def test_both_rods_are_struck_by_the_same_particles(name):
    rigid, causal = models.run_rods(load(name), "both")
    assert (rigid.model, causal.model) == ("rigid", "causal")
    assert rigid.turning is not None and causal.fronts is not None
    assert same_particles(rigid, causal)
    # each particle's world-line before its first contact is its start at t = 0 and its speed
    for h in (rigid, causal):
        for name_, (x0, r, start_x) in initial_worldlines(h).items():
            assert x0 == pytest.approx(start_x, abs=1e-12)


def test_fig2s_timing_is_resolved_once_in_the_scenarios_own_rod():
    rigid, causal = models.run_rods(load("fig2"), "both")
    assert dict(rigid.starts)["A"].x == pytest.approx(-1.7, abs=1e-12)  # -3/4 - (3/5)(19/12), by hand
    assert dict(causal.starts)["A"].x == pytest.approx(-1.7, abs=1e-12)
    # the rigid rod: A1 simultaneous in S' with B1 (the rule it was placed by); the causal rod, struck by the same
    # A, meets it later in S' (its far end starts only when B1's front arrives): not simultaneous there
    eta = math.atanh(-0.6)
    t_rigid = [i.event.time_in(eta) for i in rigid.impacts[:2]]
    assert t_rigid[0] == pytest.approx(t_rigid[1], abs=1e-12)
    first = {p: next(i for i in causal.impacts if i.particle == p) for p in ("A", "B")}
    assert first["A"].event.time_in(eta) - first["B"].event.time_in(eta) > 0.01


def test_the_causal_rod_alone_keeps_its_own_timing():
    alone = models.run_rods(load("fig2"), "causal")
    assert len(alone) == 1 and alone[0].model == "causal"
    placed = models.particle_starts(load("fig2").with_overrides(rod="causal"))
    assert dict(alone[0].starts)["A"] == placed["A"]
    assert placed["A"].x != pytest.approx(-1.7, abs=1e-3)  # the causal rod's own rule puts A elsewhere
    eta = math.atanh(-0.6)
    first = {p: next(i for i in alone[0].impacts if i.particle == p) for p in ("A", "B")}
    assert first["A"].event.time_in(eta) == pytest.approx(first["B"].event.time_in(eta), abs=1e-9)


def test_a_file_that_says_rod_causal_places_the_particles_for_both_rods():
    s = load("fig2").with_overrides(rod="causal")
    rigid, causal = models.run_rods(s, "both")
    assert rigid.model == "rigid" and same_particles(rigid, causal)
    assert dict(rigid.starts)["A"] == models.particle_starts(s)["A"]


@pytest.mark.parametrize("v, gap, delay, mass", [(0.3, 0.2, 0.1, 1.0), (0.8, 1.0, 0.0, 2.5), (0.45, 0.0, 0.3, 0.4)])
def test_generated_timed_scenarios_share_their_particles(v, gap, delay, mass):
    s = Scenario("own", v, (Particle("B", mass=1.0, gap=gap),
                            Particle("A", mass=mass, timed_with=Timing("B", "moving", delay))), 1.3)
    rigid, causal = models.run_rods(s, "both")
    assert same_particles(rigid, causal)


def test_one_model_is_run_alone():
    (h,) = models.run_rods(load("fig1"))
    assert h.model == "rigid"
    assert models.models_of("both", load("fig1")) == ("rigid", "causal")
