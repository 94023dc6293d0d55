"""The engine on scenarios the paper never drew, against values derived by hand (velocities, not rapidities)."""

import math

import pytest

from rodparadox.collision import elastic
from rodparadox.engine import run
from rodparadox.kinematics import Event
from rodparadox.scenario import Particle, Scenario, Timing, load


def add(u, w):
    """Relativistic velocity addition."""
    return (u + w) / (1 + u * w)


def g(u):
    return 1 / math.sqrt(1 - u * u)


def x_at(history, name, t):
    return history.worldline(name).event_at_time(t).x


def momentum_energy(masses, velocities):
    return (sum(m * g(u) * u for m, u in zip(masses, velocities)), sum(m * g(u) for m, u in zip(masses, velocities)))


@pytest.mark.parametrize("m, u", [(1.0, 0.6), (2.0, 0.3), (0.5, -0.9), (3.0, -0.2), (0.1, 0.99)])
def test_two_body_collision_conserves_energy_momentum_and_separates(m, u):
    rod, (particle,) = elastic((m,), (math.atanh(u),))
    w, up = math.tanh(rod), math.tanh(particle)
    before = momentum_energy((m, 1.0), (u, 0.0))
    assert momentum_energy((m, 1.0), (up, w)) == pytest.approx(before, rel=1e-13)
    assert w != 0 and (up - w) * u < 0  # something happened, and the particle now recedes from the rod
    # textbook form: a target at rest recoils at twice the centre-of-momentum velocity, added relativistically
    beta = before[0] / before[1]
    assert w == pytest.approx(add(beta, beta), rel=1e-13)


def test_equal_masses_exchange_velocities():
    for u in (0.1, -0.6, 0.95):
        rod, (particle,) = elastic((1.0,), (math.atanh(u),))
        assert math.tanh(rod) == pytest.approx(u, rel=1e-14) and abs(particle) < 1e-15


@pytest.mark.parametrize("v, L", [(0.3, 1.0), (0.6, 2.0), (0.9, 0.5)])
def test_single_impact_far_end_follows_the_hyperbola_then_moves_at_v(v, L):
    h = run(load("single").with_overrides(v=v, L=L))
    (b1,) = h.impacts
    tb = L / (2 * v)
    assert (b1.label, b1.end, b1.event.x, b1.event.t) == ("B1", "right", pytest.approx(L / 2), pytest.approx(tb))
    # right end: kinks at B1 to -v; left end: x = L/2 - sqrt(L^2 + (t - tb)^2) until tb + g v L, then straight at -v
    for f in (0.1, 0.5, 0.99):
        t = tb + f * g(v) * v * L
        assert x_at(h, "rod_left", t) == pytest.approx(L / 2 - math.sqrt(L * L + (t - tb) ** 2), rel=1e-12)
        assert x_at(h, "rod_right", t) == pytest.approx(L / 2 - v * (t - tb), rel=1e-12)
    t = tb + 3 * L
    assert x_at(h, "rod_left", t) == pytest.approx(L / 2 - g(v) * L - v * (t - tb - g(v) * v * L), rel=1e-12)
    assert x_at(h, "rod_left", tb - 0.1) == -L / 2 and x_at(h, "B", tb + 5) == pytest.approx(L / 2)


def test_unequal_simultaneous_impacts_follow_the_centre_of_momentum_rule():
    v = 0.6
    h = run(load("unequal_masses"))
    a1, b1 = h.impacts
    assert (a1.simultaneous_with, b1.simultaneous_with) == ("B1", "A1")
    assert a1.event == Event(-0.5, 0.5 / v) and b1.event.t == pytest.approx(0.5 / v, rel=1e-14)
    # by hand, in velocities: total E and p, the centre-of-momentum velocity, reverse, come back
    masses, velocities = (2.0, 0.5, 1.0), (v, -v, 0.0)
    E = sum(m * g(u) for m, u in zip(masses, velocities))
    p = sum(m * g(u) * u for m, u in zip(masses, velocities))
    beta = p / E
    after = [add(-add(u, -beta), beta) for u in velocities]
    assert math.tanh(a1.particle_rapidity_after) == pytest.approx(after[0], rel=1e-12)
    assert math.tanh(b1.particle_rapidity_after) == pytest.approx(after[1], rel=1e-12)
    assert math.tanh(a1.rod_rapidity_after) == pytest.approx(after[2], rel=1e-12)
    # pushed to the right: the left end kinks, the right end turns on the hyperbola centred on A1
    u, t0 = after[2], 0.5 / v
    for f in (0.2, 0.7):
        t = t0 + f * g(u) * u
        assert x_at(h, "rod_left", t) == pytest.approx(-0.5 + u * (t - t0), rel=1e-12)
        assert x_at(h, "rod_right", t) == pytest.approx(-0.5 + math.sqrt(1 + (t - t0) ** 2), rel=1e-12)


def test_impact_while_turning_stops_the_turn_on_the_fan_line():
    """PHYSICS.md rule 6, derived by hand for scenario while_turning (v = 0.6, L = 1, A 0.3 L after B in S)."""
    v, L = 0.6, 1.0
    h = run(load("while_turning"))
    b1, a1, b2 = h.impacts
    tb = L / (2 * v)
    assert (b1.event.x, b1.event.t) == (pytest.approx(L / 2), pytest.approx(tb))

    def left_end(t):  # on the hyperbola about B1 until tb + g v L = tb + 0.75
        return L / 2 - math.sqrt(L * L + (t - tb) ** 2)

    ta = tb + 0.3 * L
    assert (a1.event.x, a1.event.t) == (pytest.approx(left_end(ta), rel=1e-12), pytest.approx(ta, rel=1e-12))
    assert a1.while_turning
    # the rod's rest frame at A1: the fan line from B1 through A1; its slope dt/dx is that frame's velocity
    u = (ta - tb) / (left_end(ta) - L / 2)
    assert math.tanh(a1.rod_rapidity_before) == pytest.approx(u, rel=1e-12)
    # equal masses exchange velocities (in any frame): the rod takes A's v, A takes the rod's u
    assert math.tanh(a1.rod_rapidity_after) == pytest.approx(v, rel=1e-12)
    assert math.tanh(a1.particle_rapidity_after) == pytest.approx(u, rel=1e-12)
    # new turn about A1; the right end starts at B1 (on the fan line, L from A1) and returns to B at x = L/2
    xa = left_end(ta)
    tb2 = ta + math.sqrt((L / 2 - xa) ** 2 - L * L)
    assert (b2.event.x, b2.event.t) == (pytest.approx(L / 2, rel=1e-12), pytest.approx(tb2, rel=1e-12))
    assert x_at(h, "rod_right", 0.5 * (tb + tb2)) == pytest.approx(xa + math.sqrt(L * L + (0.5 * (tb + tb2) - ta) ** 2))
    # at B2 the rod's frame is the line from A1 to B2; B (at rest) and the rod exchange: the rod stops
    u2 = (tb2 - ta) / (L / 2 - xa)
    assert math.tanh(b2.rod_rapidity_before) == pytest.approx(u2, rel=1e-12)
    assert abs(math.tanh(b2.rod_rapidity_after)) < 1e-12
    # and ends where it began: left end at rest at -L/2 after the last turn
    late = tb2 + 2 * L
    assert x_at(h, "rod_left", late) == pytest.approx(-L / 2, abs=1e-12)
    assert x_at(h, "rod_right", late) == pytest.approx(L / 2, abs=1e-12)


def test_fig1_timing_off_by_a_little_makes_the_rod_recoil():
    """The paper, Section 1: struck at other times than Fig. 1's, the rod recoils."""
    h = run(load("off_timing"))
    assert [i.label for i in h.impacts] == ["B1", "A1", "B2"]
    assert abs(math.tanh(h.impacts[0].rod_rapidity_after)) > 0.5  # the rod moves after B1
    exact = run(load("fig1"))
    assert all(i.rod_rapidity_after == 0 for i in exact.impacts)


def test_a_single_particle_a_and_fig2s_b_struck_twice():
    s = Scenario("a_only", 0.5, (Particle("A", gap=0.25),), L=2.0)
    h = run(s)
    (a1,) = h.impacts
    assert (a1.label, a1.end, a1.event.x, a1.event.t) == ("A1", "left", -1.0, pytest.approx(0.5 / 0.5))
    assert h.worldline("B") is None and math.tanh(a1.rod_rapidity_after) == pytest.approx(0.5)
    assert [i.label for i in run(load("fig2")).impacts] == ["B1", "A1", "B2"]


def test_timing_in_an_arbitrary_frame_lands_on_time():
    s = Scenario("t", 0.5, (Particle("B", gap=0.4), Particle("A", timed_with=Timing("B", 0.3, 0.7))), L=1.5)
    h = run(s)
    first = {i.particle: i for i in h.impacts if i.label.endswith("1")}
    eta = math.atanh(0.3)
    dt = first["A"].event.boosted(eta).t - first["B"].event.boosted(eta).t
    assert dt == pytest.approx(0.7 * 1.5, rel=1e-12)


def totals(history):
    """The system's energy and momentum (rod mass 1) before the first impact and after the last, in S."""
    s = history.scenario
    masses = {p.name: p.mass for p in s.particles}
    before = {p.name: math.atanh(s.speed(p)) * (1 if p.name == "A" else -1) for p in s.particles}
    after = dict(before)
    for i in history.impacts:
        after[i.particle] = i.particle_rapidity_after
    rod = history.impacts[-1].rod_rapidity_after

    def energy_momentum(rod_rapidity, particles):
        u = [(1.0, math.tanh(rod_rapidity))] + [(masses[n], math.tanh(r)) for n, r in particles.items()]
        return sum(m * g(w) for m, w in u), sum(m * g(w) * w for m, w in u)

    return energy_momentum(0.0, before), energy_momentum(rod, after)


@pytest.mark.parametrize("name", ["fig1", "fig2", "single", "unequal_masses"])
def test_the_system_conserves_energy_and_momentum_when_no_turn_is_stopped(name):
    before, after = totals(run(load(name)))
    assert after == pytest.approx(before, rel=1e-12, abs=1e-12)


@pytest.mark.parametrize("delay", [0.25, 0.1])
def test_a_stopped_turn_does_not_conserve_the_systems_energy(delay):
    """Rule 6 puts the rod in the fan's frame at the impact with no impulse: documented in the README's model.

    off_timing with equal masses, A `delay` L after B in S: A1 is on the left end's hyperbola about B1,
    delay after it, where the fan's velocity is -delay/sqrt(L^2 + delay^2); A leaves with it, and by
    symmetry B leaves B2 with +delay/sqrt(L^2 + delay^2); the rod ends at rest. Energy after:
    1 + 2 sqrt(1 + delay^2), against 1 + 2 g(v) before; momentum stays 0.
    """
    s = Scenario("off_timing", 0.6, (Particle("B", gap=0.5), Particle("A", timed_with=Timing("B", "rest", delay))))
    (e0, p0), (e1, p1) = totals(run(s))
    assert e0 == pytest.approx(1 + 2 * g(0.6), rel=1e-14)
    assert e1 == pytest.approx(1 + 2 * math.sqrt(1 + delay * delay), rel=1e-12)
    assert p0 == pytest.approx(0.0, abs=1e-12) and p1 == pytest.approx(0.0, abs=1e-12)
