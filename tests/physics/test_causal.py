"""The causal rod (README, "The causal rod"): closed forms derived by hand, the classical limit, conservation on
slices of several frames, covariance, light speed, the ringing rod. Every history is built once (module fixtures).

Derivations used below (units L = 1, M = 1, mu = M/m, th0 the particle's rapidity):
* A particle striking the left end of the resting rod: the end takes th0 at once, lam = exp(th0) (r+ = 0 comes
  in). While r+ = 0 comes in, psi = th obeys d th/dT = -mu sinh(th) (m d th/d tau = -p, p = (lam^2 - 1)/2,
  d tau = dT/lam, lam = exp(th)), so tanh(th/2) = k exp(-mu T), k = tanh(th0/2). The compression reaches the
  far end at T = L (t = L after the contact in S, the far end still at rest until then); the free end sends back
  r+ = -r- = 2 th0 - ..., its rapidity (r+ - r-)/2 = 2 th0 just after. That tension reaches the struck end at
  T = 2L: r+ jumps to 2 th0 > th(2L), so lam would fall below 1: the particle leaves with
  tanh(th_f/2) = k exp(-2 mu).
* v -> 0: th ~ v, tanh(th/2) ~ th/2, so v_f = v exp(-2 M/m): the classical bar.
* After the last separation both ends are free, r- = -r+ and r+(u) = r+(u - 2L): every material point's
  (t + x, t - x) gains (Da, Db) per period 2L of chart time, the same for every X; the rod's (E, p) from the
  stress-energy over one period is (M/2L)(Dt, Dx) (README).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from rodparadox.io.scenario import load

from helpers import particle_presets
from rodparadox.physics.causal import run
from rodparadox.physics.rigid import run as run_rigid
from rodparadox.physics.model import Particle, Scenario, Timing

#: one worker runs this file, so its shared fixtures are built once (`--dist loadgroup`, pyproject.toml)
pytestmark = pytest.mark.xdist_group("causal")


def _single(v: float, mass: float = 1.0, name: str = "A", gap: float = 0.5) -> Scenario:
    return Scenario("single", v, (Particle(name, mass, gap=gap),), 1.0)


@pytest.fixture(scope="module")
def presets():
    return {name: run(load(name)) for name in particle_presets()}


GENERATED = {
    "unequal": Scenario("unequal", 0.7, (Particle("A", 0.3, gap=0.2), Particle("B", 2.5, speed=0.4, gap=1.1)), 1.0),
    "off_timing": Scenario("off", 0.55, (Particle("A", 1.0, gap=0.3),
                                         Particle("B", 0.8, timed_with=Timing("A", 0.2, 0.35))), 2.0),
    "heavy": Scenario("heavy", 0.35, (Particle("A", 6.0, gap=0.1), Particle("B", 0.5, gap=0.9)), 1.0),
}


@pytest.fixture(scope="module")
def generated():
    return {name: run(s) for name, s in GENERATED.items()}


# --- closed forms ------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("v, mass", [(0.6, 1.0), (0.9, 2.0), (0.3, 0.25)])
def test_one_particle_closed_form(v, mass):
    """Contact lasts chart time 2L; tanh(th_f/2) = k exp(-2M/m); the far end starts at t = L after the contact,
    at rapidity 2 th0; mid-contact tanh(th/2) = k exp(-mu T/L)."""
    h = run(_single(v, mass))
    th0, mu = math.atanh(v), 1.0 / mass
    k = math.tanh(th0 / 2)
    contact, separation = h.solution.events
    assert (contact.kind, separation.kind) == ("contact", "separation")
    assert separation.T - contact.T == pytest.approx(2.0, abs=1e-10)
    assert separation.th_particle == pytest.approx(2 * math.atanh(k * math.exp(-2 * mu)), abs=1e-10)
    assert h.impacts[1].particle_rapidity_after == separation.th_particle
    t_c = 1.0 / (2.0 * v)  # gap L/2 at speed v; the left end rests at x = -L/2 until then
    assert h.impacts[0].event.t == pytest.approx(t_c, abs=1e-12)
    far = h.worldline("rod_right")
    assert far.first.t == pytest.approx(t_c + 1.0, abs=1e-10) and far.first.x == pytest.approx(0.5, abs=1e-12)
    assert far.rapidity_at_time(t_c + 1.0 - 1e-9) == 0.0
    assert far.segments[0].rapidity(contact.T + 1.0) == pytest.approx(2 * th0, abs=1e-10)
    mid = contact.T + 0.7
    end_curve = h.worldline("A").segments[0]
    assert end_curve.rapidity(mid) == pytest.approx(2 * math.atanh(k * math.exp(-mu * 0.7)), abs=1e-10)


def test_right_end_mirrors_left_end():
    """B on the right end is A on the left seen in a mirror: the same separation, rapidity negated."""
    a, b = run(_single(0.8, 1.7, "A")), run(_single(0.8, 1.7, "B"))
    assert b.solution.events[1].th_particle == pytest.approx(-a.solution.events[1].th_particle, abs=1e-12)
    assert b.final_rapidity == pytest.approx(-a.final_rapidity, abs=1e-12)


@pytest.mark.parametrize("mass", [1.0, 0.5])
def test_classical_limit(mass):
    """v -> 0: v_f = v exp(-2M/m), to relative order v^2."""
    v = 1e-4
    h = run(_single(v, mass))
    v_f = math.tanh(h.impacts[-1].particle_rapidity_after)
    assert v_f / v == pytest.approx(math.exp(-2.0 / mass), rel=1e-7)


# --- conservation, covariance, light speed -----------------------------------------------------------------------

def _slices(h):
    first = min(i.event.t for i in h.impacts)
    last = max(i.event.t for i in h.impacts)
    return np.linspace(first - 0.5, last + 3.0, 11)


@pytest.mark.parametrize("which", ["presets", "generated"])
def test_total_conserved_on_slices_of_several_frames(which, presets, generated):
    """Particles plus the rod (stress-energy integrated across the slice, fronts inside exactly) keep the initial
    total to 1e-9, on slices before, during and after the contacts, in S, S' and a fast frame."""
    histories = presets if which == "presets" else generated
    for name, h in histories.items():
        for f in (0.0, -math.atanh(h.scenario.v), 0.9):
            scale = max(1.0, h.initial_total(f).E)
            for t in _slices(h) * math.cosh(f):
                sl = h.energy_momentum(f, t)
                assert abs(sl.hidden.E) <= 1e-9 * scale and abs(sl.hidden.p) <= 1e-9 * scale, (name, f, t, sl.hidden)


def test_generated_scenarios_re_contact(presets):
    """fig2's A strikes the left end again after leaving it (the end, pulled back by tension, catches it)."""
    numbers = [e.number for e in presets["fig2"].solution.events if e.particle == "A"]
    assert max(numbers) >= 2


def test_rod_four_momentum_after_is_a_vector(presets):
    """After the last separation the rod's (E, p) is the same on every slice, and in S' it is the S value boosted:
    a check of the stress-energy integral in a moving frame against the one in S."""
    for name, h in presets.items():
        late = max(i.event.t for i in h.impacts) + 5.0
        E, p = (lambda em: (em.E, em.p))(h.rod_energy_momentum(0.0, late))
        E2, p2 = (lambda em: (em.E, em.p))(h.rod_energy_momentum(0.0, late + 3.3))
        assert (E2, p2) == pytest.approx((E, p), abs=1e-10)
        for f in (-math.atanh(h.scenario.v), 0.6):
            em = h.rod_energy_momentum(f, 10 * late)
            c, s = math.cosh(f), math.sinh(f)
            assert (em.E, em.p) == pytest.approx((c * E - s * p, c * p - s * E), abs=1e-10), name


def test_no_material_point_outruns_light(presets, generated):
    """Every sampled material line is time-like: |dx| < dt between consecutive points, in S and S'."""
    for h in [*presets.values(), *generated.values()]:
        lo, hi = _slices(h)[0], _slices(h)[-1]
        for sigma in (0.0, 0.4 * h.scenario.L, h.scenario.L):  # the ends, where contacts are, and one inside
            for f in (0.0, -math.atanh(h.scenario.v)):
                w = h.material_worldline(sigma).seen_from(f)
                pts = w.sample(lo * math.cosh(f) - 1, hi * math.cosh(f), 1e-3)  # every front is a knot anyway
                d = np.diff(pts, axis=0)
                assert np.all(np.abs(d[:, 0]) < d[:, 1]), sigma


# --- the ringing rod ---------------------------------------------------------------------------------------------

def test_ringing_period_and_momentum(presets, generated):
    """Every material point advances by the same (Dt, Dx) per period 2L after the last separation, and the rod's
    (E, p) is (M/2L)(Dt, Dx)."""
    for name, h in [*presets.items(), *generated.items()]:
        L = h.scenario.L
        T0 = h.last_separation + 0.37 * L
        steps = []
        for X in (0.0, 0.3 * L, L):
            curve = h.material_worldline(X).segments[0]
            a, b = curve.point(T0), curve.point(T0 + 2 * L)
            steps.append((b.t - a.t, b.x - a.x))
        for step in steps[1:]:
            assert step == pytest.approx(steps[0], abs=1e-10), name
        D_t, D_x = steps[0]
        em = h.rod_energy_momentum(0.0, h.material_worldline(0.0).segments[0].point(T0 + 5 * L).t)
        assert (em.E, em.p) == pytest.approx((D_t / (2 * L), D_x / (2 * L)), abs=1e-10), name


def test_rod_rings_and_particles_rebound_slower(presets):
    """Energy goes into the ringing: the rod's rest mass after > M, and in fig1 both particles leave slower than
    the rigid rod sends them back (it returns them at v)."""
    for name, h in presets.items():
        late = max(i.event.t for i in h.impacts) + 5.0
        em = h.rod_energy_momentum(0.0, late)
        assert math.sqrt(em.E ** 2 - em.p ** 2) > 1.0 + 1e-6, name
    causal, rigid = presets["fig1"], run_rigid(load("fig1"))
    for name in ("A", "B"):
        after_causal = [i for i in causal.impacts if i.particle == name][-1].particle_rapidity_after
        after_rigid = [i for i in rigid.impacts if i.particle == name][-1].particle_rapidity_after
        assert abs(after_causal) < abs(after_rigid) - 1e-3


def test_matter_plus_stress_is_the_rod(presets):
    """The matter and stress parts add up to the rod's exact total; unstressed before any contact, the stress part
    is zero; while compressed and moving, its momentum is not."""
    h = presets["fig2"]
    first = h.impacts[0].event.t
    before = h.energy_momentum(0.0, first - 0.1, split=True)
    assert dict(before.rod_parts)["stress"].p == 0.0
    during = h.energy_momentum(0.0, first + 0.4, split=True)
    parts = dict(during.rod_parts)
    rod = dict(during.bodies)["rod"]
    assert (parts["matter"].E + parts["stress"].E, parts["matter"].p + parts["stress"].p) == \
        pytest.approx((rod.E, rod.p), abs=1e-9)
    assert abs(parts["stress"].p) > 1e-2


def test_a_slice_through_a_contact_or_a_separation_itself_conserves_the_total():
    """A slice at a separation's own instant read the end's rapidity after the arriving front as the particle's:
    single at v = 0.6 in S, t = 2.4197, gave B (2.125, -1.875) and a total of 3.37 against 2.25. At a contact's or a
    separation's instant the particle has the velocity it brings or leaves with, and the total holds to 1e-9."""
    import math

    from rodparadox.io.scenario import load
    from rodparadox.physics.models import run_rod

    for name in ("single", "fig2"):
        history = run_rod(load(name).with_overrides(rod="causal"))
        for f in (0.0, -math.atanh(history.scenario.v)):
            initial = history.initial_total(f)
            for impact in history.impacts:
                t = impact.event.seen_from(f).t
                missing = history.energy_momentum(f, t).hidden
                assert abs(missing.E) <= 1e-9 * initial.E and abs(missing.p) <= 1e-9 * initial.E, (name, impact.label)
