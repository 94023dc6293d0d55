"""The causal rod's matter and stress on many slices at once (`physics.causal.slices.rod_parts_on_slices`: the
ledger figure's curves and the html page's ledger, from tables of the invariants) against the ledger's exact
slice-by-slice integral (`physics.causal.parts.rod_parts`: the engine's own a, b, no table, Gauss-Legendre of 16
nodes halved to 1e-10 of the rod's (E, p)), and the sum of the two parts against the engine's exact total of the rod
(one-variable integrals). Within 1e-10 at v = 0.6 in S, S' and another frame; at 0.97 (where the cubic splines of
the figure's former integral crashed) within 2e-6; at 0.99 a known gap (3.7e-4 in S', marked xfail).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from rodparadox.io.scenario import load
from rodparadox.physics.causal.parts import rod_parts
from rodparadox.physics.causal.slices import PRECISE_TABLES, BeyondBounds, ChartTables, rod_parts_on_slices
from rodparadox.physics.models import run_rod

pytestmark = pytest.mark.xdist_group("causal_slices")


def exact_parts(history, f: float, t: float) -> np.ndarray:
    """[matter E, matter p, stress E, stress p] by the ledger's exact slice-by-slice integral (`causal.parts`)."""
    matter, stress = rod_parts(history, f, t)
    return np.array([matter.E, matter.p, stress.E, stress.p])


@pytest.fixture(scope="module")
def runs():
    return {v: run_rod(load("fig2").with_overrides(v=v, rod="causal")) for v in (0.6, 0.97, 0.99)}


def slices(history, f: float, n: int) -> np.ndarray:
    """n slices of the frame spread over the contacts' times (and one before the first)."""
    times = [i.event.seen_from(f).t for i in history.impacts]
    lo, hi = min(times), max(times)
    return np.concatenate([[lo - 0.3 * history.scenario.L], np.linspace(lo, hi, n - 1)])


def test_matter_and_stress_on_many_slices_are_the_exact_integral_within_1e_10(runs):
    h = runs[0.6]
    for f in (0.0, -math.atanh(0.6), math.atanh(0.3)):
        times = slices(h, f, 4)
        matter, stress = rod_parts_on_slices(h, f, times)
        for k, t in enumerate(times):
            exact = exact_parts(h, f, float(t))
            assert np.concatenate([matter[k], stress[k]]) == pytest.approx(exact, abs=1e-10), (f, t)


@pytest.mark.parametrize("v", [0.97, pytest.param(0.99, marks=pytest.mark.xfail(strict=True, reason=(
    "known gap: in S' at v = 0.99 the tables' matter + stress misses the exact total by 3.7e-4 M c^2 (3.7e-6 of it) "
    "on a slice through an event; 4e-7 at 0.97; within 1e-10 at 0.6")))])
def test_near_c_the_parts_add_up_to_the_exact_total_and_end(runs, v):
    """Where the spline version crashed: finite, bounded, matter and stress adding up to the engine's exact total
    (within 2e-6: the known gap) in S and S'; slice by slice against the exact integral in S."""
    h = runs[v]
    for f in (0.0, -math.atanh(v)):
        times = slices(h, f, 5)
        matter, stress = rod_parts_on_slices(h, f, times)
        for k, t in enumerate(times):
            total = h.rod_energy_momentum(f, float(t))
            assert matter[k] + stress[k] == pytest.approx([total.E, total.p], abs=2e-6), (v, f, t)
    t = float(slices(h, 0.0, 3)[1])
    matter, stress = rod_parts_on_slices(h, 0.0, [t])
    assert np.concatenate([matter[0], stress[0]]) == pytest.approx(exact_parts(h, 0.0, t), abs=2e-6)


def test_one_slice_and_many_slices_agree_and_add_up_to_the_engines_total(runs):
    """Slice by slice and all at once, the same parts; matter and stress add up to the exact total."""
    h = runs[0.6]
    times = slices(h, 0.0, 3)
    matter, stress = rod_parts_on_slices(h, 0.0, times)
    for k, t in enumerate(times):
        m, s = rod_parts(h, 0.0, float(t))  # the ledger's: matter is the exact total less the stress
        total = h.rod_energy_momentum(0.0, float(t))
        assert (m.E + s.E, m.p + s.p) == pytest.approx((total.E, total.p), abs=1e-14)
        assert [m.E, m.p, s.E, s.p] == pytest.approx([*matter[k], *stress[k]], abs=1e-10)
    # before the first contact the rod rests unstressed: matter is M at rest, stress exactly nothing
    assert matter[0] == pytest.approx([1.0, 0.0], abs=1e-13) and list(stress[0]) == [0.0, 0.0]


def test_a_planted_error_in_the_density_is_found():
    """The test can fail: the stress part's density off by one part in 1e8 misses the exact integral."""
    h = run_rod(load("single").with_overrides(v=0.6, rod="causal"))
    t = [i.event.t for i in h.impacts][0] + 0.2
    tables = ChartTables(h, -3.0, 6.0, PRECISE_TABLES)
    _, stress = rod_parts_on_slices(h, 0.0, [t], tables)
    exact = exact_parts(h, 0.0, t)
    assert stress[0] == pytest.approx(exact[2:], abs=1e-10)
    assert not stress[0] * (1 + 1e-8) == pytest.approx(exact[2:], abs=1e-10)


def test_near_c_the_integral_ends_within_its_bounds():
    """At v = 0.9999999 a contact's invariant falls over 1e-11 L: the tables stop at their bounds (one sentence)
    or finish; never the hang of the spline version (killed at 300 s)."""
    import time

    h = run_rod(load("fig2").with_overrides(v=0.9999999, rod="causal"))
    start = time.process_time()
    try:
        matter, stress = rod_parts_on_slices(h, 0.0, [h.impacts[0].event.t + 0.5])
        assert np.all(np.isfinite(matter)) and np.all(np.isfinite(stress))
    except BeyondBounds as e:
        assert str(e).startswith("the causal rod would need more than ")
    assert time.process_time() - start < 20
