"""The rigid rod driven by forces in its own chart (`--frame rod`): T its left end's proper time (t of S before the
forces), X the distance from the left end along the rod's own line of simultaneity. Checked against hand
derivations (hyperbolic motion under a constant push), the history's exact world-lines and the chart's defining
property (each level line is one of the rod's own lines of simultaneity), to 1e-12."""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np
import pytest

from rodparadox.io.scenario import load
from rodparadox.physics.models import run_rod

#: the push: F = 0.25 M c^2/L on the left end from t = 0.5 to 4.5 of S; alpha_L = F/M, alpha_R = alpha_L/(1 + alpha_L L)
F, START, DURATION = 0.25, 0.5, 4.0


@lru_cache(maxsize=None)
def chart(name: str):
    h = run_rod(load(name))
    return h, h.own_chart()


def test_a_constant_push_is_hyperbolic_motion_in_the_chart():
    """The left end's proper time over the push is asinh(F t/M)/(F/M) = 4 asinh(1); the right end's clock runs
    1 + alpha_L L = 1.25 times faster, 5 asinh(1): its own hyperbola's phi/alpha_R with phi = asinh(1), alpha_R = 0.2."""
    h, c = chart("push")
    start, end = (e for e in h.driving.force_events() if e.moment in ("start", "end"))
    assert c.to_chart(start.event) == pytest.approx((START, 0.0), abs=1e-12)
    T_end, X_end = c.to_chart(end.event)
    assert T_end == pytest.approx(START + 4 * math.asinh(1.0), abs=1e-12) and abs(X_end) <= 1e-12
    assert c.proper_time(0.0, START, T_end) == pytest.approx(4 * math.asinh(1.0), abs=1e-12)
    assert c.proper_time(1.0, START, T_end) == pytest.approx(math.asinh(1.0) / 0.2, abs=1e-12)
    assert c.proper_time(0.5, 0.0, START) == pytest.approx(START, abs=1e-15)  # at rest before: T is t of S


@pytest.mark.parametrize("name", ["push", "sears_moving"])
def test_each_level_line_is_a_line_of_the_rods_own_simultaneity(name):
    """At every T the events X = 0, L/2, L are on one line whose slope dt/dx is the rod's velocity there (Minkowski
    orthogonal to its world-lines): the rod's "now"; and they lie on the material world-lines 0, L/2, L."""
    h, c = chart(name)
    for T in np.linspace(-0.5, 6.0, 14):
        events = [c.to_event(T, X) for X in (0.0, 0.5, 1.0)]
        slope = (events[2].t - events[0].t) / (events[2].x - events[0].x)
        assert slope == pytest.approx(h.material_velocity(0.0, 0.0, events[0].t), abs=1e-12)
        assert (events[1].t - events[0].t) / (events[1].x - events[0].x) == pytest.approx(slope, abs=1e-12)
        for X, e in zip((0.0, 0.5, 1.0), events):
            assert h.material_worldline(X).event_at_time(e.t).x == pytest.approx(e.x, abs=1e-12)


@pytest.mark.parametrize("name", ["push", "sears_moving"])
def test_the_chart_maps_there_and_back_and_keeps_each_material_point_at_its_label(name):
    h, c = chart(name)
    for T in np.linspace(-0.5, 6.0, 11):
        for X in (0.0, 0.3, 1.0):
            back = c.to_chart(c.to_event(T, X))
            assert back == pytest.approx((T, X), abs=1e-12)
    for sigma in (0.0, 0.4, 1.0):
        line = h.material_worldline(sigma)
        for t in (0.2, 1.0, 2.5, 5.0):
            assert c.to_chart(line.event_at_time(t))[1] == pytest.approx(sigma, abs=1e-12)
    assert c.to_event(0.0, -0.5) is None and c.placed(c.to_event(1.0, 0.5))
