"""The causal rod driven by generated force profiles (step, sine^2, points; timed in S, S' or u; one end or both):
on slices of S, S' and a third frame the rod holds its (E, p) before the forces plus what the agents delivered
(1e-9), and each agent delivers, in its profile's frame, the profile's area."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from generated import force_profiles
from rodparadox.physics.forces import ForceProfile, Forces
from rodparadox.physics.model import Scenario
from rodparadox.physics.models import run_rod


def profiles(end):
    """Pulls stay below the causal limit M c^2/(2L) (0.5) with room: near it a long pull is refused by the run's
    bounds."""
    return force_profiles(end, -0.45)


@pytest.mark.slow
@given(left=st.one_of(st.none(), profiles("left")), right=st.one_of(st.none(), profiles("right")),
       v=st.floats(0.05, 0.95), t=st.floats(-2.0, 6.0), u=st.floats(-0.9, 0.9))
def test_generated_profiles_conserve_on_slices_of_S_S_prime_and_u(left, right, v, t, u):
    if left is None and right is None:
        left = ForceProfile("sine2", peak=0.3, start=0.0, duration=1.0)
    h = run_rod(Scenario("generated", v, (), forces=Forces(left, right), rod="causal"))
    for f in (0.0, -math.atanh(v), math.atanh(u)):
        rod, held = dict(h.energy_momentum(f, t).bodies)["rod"], h.driving.total(f, t)
        scale = max(1.0, abs(held.E))
        assert abs(rod.E - held.E) <= 1e-9 * scale and abs(rod.p - held.p) <= 1e-9 * scale
    for end, profile in h.driving.profiles():
        g = h.driving.frame_rapidity(end)
        delivered = h.driving.delivered_at(end, g, math.inf).p
        assert abs(delivered - (1 if end == "left" else -1) * profile.area()) <= 1e-10 * max(1.0, abs(profile.area()))


def test_a_tiny_constant_force_keeps_its_digits():
    """The rigid rod's hypothesis case (a flat stretch of 2e-247 M c^2/L after a ramp) on the causal rod."""
    right = ForceProfile("points", points=((0.0, 0.3), (0.5, 1.978908151166676e-247), (1.0, 1.978908151166676e-247)),
                         key="forces.right")
    h = run_rod(Scenario("tiny", 0.5, (), forces=Forces(None, right), rod="causal"))
    assert math.isclose(h.driving.delivered("right", 0.0, 9.0).p, -right.area(), rel_tol=1e-12)
