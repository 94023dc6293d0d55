"""The causal rod's own integrator and its matter/stress split (issue 16, items 2 and 8): checked against closed
forms and an independent computation, never against themselves.

* Constant input: tanh(delta/2) = k exp(-c (T - T0)) (README, "The causal rod"), and `_Contact`'s integrals.
* A manufactured solution with a separation at a known time: take psi(T) = cos T and ask which input makes it the
  solution of d psi/dT = -c sinh(psi - in): in = cos T - asinh(sin T / c). Then delta = psi - in = asinh(sin T / c)
  falls to 0 at T = pi exactly: the contact must end there.
* The stress part on a slice from the material world-lines alone (a midpoint rule, to a percent): each label X's event and rapidity th at time t,
  lam = (dX/dx)/cosh th (a moving element's rest length is cosh th times its length on the slice), stress
  densities p sinh^2 th and p cosh th sinh th with p = (M/2L)(lam^2 - 1), summed by the midpoint rule.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from helpers import causal_history
from rodparadox.physics.causal.ode import falling_root, solve_contact
from rodparadox.physics.causal.parts import rod_parts
from rodparadox.physics.causal.solve import _Contact


class _Input:
    def __init__(self, r):
        self.r = r


def test_constant_input_follows_the_closed_form_and_its_integrals():
    r_in, delta0, c, lo, hi = 0.3, 1.7, 2.5, 0.4, 2.9
    solved, T_sep = solve_contact(lo, hi, _Input(lambda T: r_in), r_in + delta0, c)
    exact = _Contact(lo, hi, r_in, delta0, c)
    assert T_sep is None and solved.hi == hi
    for T in np.linspace(lo, hi, 23):
        k_T = math.tanh(delta0 / 2) * math.exp(-c * (T - lo))
        assert solved.psi(T) == pytest.approx(r_in + 2 * math.atanh(k_T), abs=1e-12)
        assert solved.ep(T) == pytest.approx(exact.ep(T), rel=1e-12, abs=1e-13)
        assert solved.em(T) == pytest.approx(exact.em(T), rel=1e-12, abs=1e-13)


@pytest.mark.parametrize("c", [0.7, 40.0])  # a slow contact, and a stiff one (many decay times in the window)
def test_a_contact_ends_where_the_manufactured_solution_says(c):
    def r_in(T):
        return math.cos(T) - math.asinh(math.sin(T) / c)

    lo = 0.3
    solved, T_sep = solve_contact(lo, 5.0, _Input(r_in), math.cos(lo), c)
    assert T_sep == pytest.approx(math.pi, abs=1e-12)
    nodes, weights = np.polynomial.legendre.leggauss(60)
    for T in np.linspace(lo, T_sep, 17):
        assert solved.psi(T) == pytest.approx(math.cos(T), abs=1e-12)
        # int exp(+-out), out = in - 2 psi = -cos T - asinh(sin T / c): Gauss-Legendre on the smooth integrand
        s = 0.5 * (T + lo) + 0.5 * (T - lo) * nodes
        out = -np.cos(s) - np.arcsinh(np.sin(s) / c)
        assert solved.ep(T) == pytest.approx(0.5 * (T - lo) * weights @ np.exp(out), rel=1e-12, abs=1e-14)
        assert solved.em(T) == pytest.approx(0.5 * (T - lo) * weights @ np.exp(-out), rel=1e-12, abs=1e-14)


def test_the_root_finder_lands_on_the_nearest_float():
    assert falling_root(lambda x: 5.0 / 6.0 - x, 0.0, 1.0, 1e-15, 8.9e-16) == pytest.approx(5 / 6, abs=2e-16)
    assert falling_root(lambda x: math.cos(x), 1.0, 2.0) == pytest.approx(math.pi / 2, abs=4e-16)


def _stress_from_material_lines(h, f: float, t: float, n: int = 150) -> tuple[float, float]:
    L = h.scenario.L
    X = (np.arange(n + 1) / n) * L
    x = np.array([h.material_worldline(s).seen_from(f).event_at_time(t).x for s in X])
    mid = 0.5 * (X[1:] + X[:-1])
    th = np.array([h.material_worldline(s).seen_from(f).rapidity_at_time(t) for s in mid])
    dx = np.diff(x)
    lam = (L / n) / dx / np.cosh(th)
    p = 0.5 / L * (lam ** 2 - 1)
    return float(np.sum(p * np.sinh(th) ** 2 * dx)), float(np.sum(p * np.cosh(th) * np.sinh(th) * dx))


@pytest.mark.parametrize("f, t", [(0.0, 1.3), (0.3, 1.6)])
def test_the_stress_part_is_the_stress_of_the_material_lines(f, t):
    h = causal_history("fig2", 0.6)
    matter, stress = rod_parts(h, f, t)
    E, p = _stress_from_material_lines(h, f, t)
    scale = abs(stress.E) + abs(stress.p)
    assert scale > 1e-2  # the slice crosses a stressed, moving rod
    # the midpoint rule errs by O(1/n) in the few cells a front crosses (lam jumps there): 1.5 percent at n = 150,
    # where a wrong density (lam^2 for lam^2 - 1, a lost cosh) is wrong by tens of percent
    assert stress.E == pytest.approx(E, abs=1.5e-2 * scale) and stress.p == pytest.approx(p, abs=1.5e-2 * scale)
    rod = h.rod_energy_momentum(f, t)
    assert (matter.E + stress.E, matter.p + stress.p) == pytest.approx((rod.E, rod.p), abs=1e-14)


def test_the_shortcuts_give_the_general_paths_floats_bit_for_bit():
    """The chart map's shortcuts (a run's pieces read once for two results, a numpy scalar read as a float) give
    the very floats of the general paths: `Arrays.piece_both` those of `piece_r` and `piece_primitive`, a table's
    `both` its `r` and `m`, a(u) at np.float64 that of `integrals` at a float."""
    h = causal_history("unequal_masses", 0.97)  # long contacts: solved pieces read through chains of views
    sol, arrays = h.solution, h.arrays
    s = np.linspace(sol.plus.starts[0] - 1.0, sol.plus.tail_start + 5.0, 301)
    for invariant in (sol.plus, sol.minus):
        for piece in invariant.pieces:
            at = np.clip(s, piece.lo, piece.hi)
            for plus in (True, False):
                r, primitive = arrays.piece_both(piece, at, plus)
                assert np.array_equal(r, arrays.piece_r(piece, at))
                assert np.array_equal(primitive, arrays.piece_primitive(piece, at, plus))
    tables = h.chart_tables(s[0], s[-1])
    r, m = tables.plus.both(s)
    assert np.array_equal(r, tables.plus.r(s)) and np.array_equal(m, tables.plus.m(s))
    fresh = type(sol)(sol.L, sol.plus, sol.minus, sol.events, sol.riders)  # an empty memo of a and b
    assert [fresh.a(u) for u in s] == [-0.5 * sol.L + sol.plus.integrals(u)[0] for u in s.tolist()]


def test_the_fields_on_their_grid_are_read_once_per_history():
    """`extremes._chart_extremes` is kept per history (both ranges read it): a hit is what a fresh reading gives."""
    from rodparadox.physics.causal.extremes import _chart_extremes

    h = causal_history("fig1")
    kept = _chart_extremes(h)
    assert _chart_extremes(h) is kept
    assert all(np.array_equal(a, b) for a, b in zip(kept, _chart_extremes.__wrapped__(h)))
