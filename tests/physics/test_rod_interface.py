"""The rod interface (`physics.history.RodHistory`): what every command reads from a run, checked on the rigid
engine against hand-derived values and invariants, and a model without the rigid part drawn and tabulated."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pytest

from rodparadox.io.scenario import load
from rodparadox.physics.rigid.engine import History
from rodparadox.physics.rigid import run
from rodparadox.physics.history import RodHistory, Turning


@pytest.fixture(scope="module")
def fig2() -> History:
    return run(load("fig2"))


def test_the_rigid_engine_implements_the_interface_and_its_rigid_part(fig2):
    assert isinstance(fig2, RodHistory) and isinstance(fig2.turning, Turning)
    assert fig2.model == "rigid" and fig2.fronts is None and fig2.turning.turns == fig2.turns


def test_material_velocity_matches_the_paper_in_both_frames(fig2):
    """Fig. 2 at v = 0.6: in S the rod rests before B1 (t = 5/6) and after the last turn; in S' it moves at +v
    before any impact, every point rests at t' = 17/12 (B1 and A1), and after the last turn moves on at v."""
    v, L = 0.6, 1.0
    moving = math.atanh(-v)  # S' moves at -v relative to S
    for sigma in np.linspace(0, L, 7):
        assert fig2.material_velocity(sigma, 0.0, 0.5) == pytest.approx(0.0, abs=1e-15)
        assert fig2.material_velocity(sigma, 0.0, 10.0) == pytest.approx(0.0, abs=1e-12)
        assert fig2.material_velocity(sigma, moving, -1.0) == pytest.approx(v, abs=1e-15)
        # at t' = 17/12 every point rests but the left end, which A1 has just kicked to 15/17 (the pivot kinks)
        assert fig2.material_velocity(sigma, moving, 17 / 12) == pytest.approx(0.0 if sigma else 15 / 17, abs=1e-12)
    # A1's turn ends on the rod's line through B2 (the far end reaches 15/17 a time g u L = 15/8 after A1, at
    # t' = 17/12 + 15/8 = 3.2917, B2's instant): B2's turn starts there, and after it the rod moves on at v
    u = 15 / 17
    assert 17 / 12 + u / math.sqrt(1 - u * u) * L == pytest.approx(fig2.impacts[2].event.time_in(moving), abs=1e-12)
    for sigma in np.linspace(0, L, 7):
        assert fig2.material_velocity(sigma, moving, 6.0) == pytest.approx(v, abs=1e-12)


def test_material_velocity_is_the_slope_of_the_material_world_line(fig2):
    """Independent of the interface's own rapidity: a centred difference of positions along the world-line."""
    moving = math.atanh(-0.6)
    for sigma in (0.0, 0.3, 0.77, 1.0):
        line = fig2.material_worldline(sigma).seen_from(moving)
        for t in (0.3, 1.2, 1.9, 2.6, 3.4):
            h = 1e-6
            slope = (line.event_at_time(t + h).x - line.event_at_time(t - h).x) / (2 * h)
            assert fig2.material_velocity(sigma, moving, t) == pytest.approx(slope, abs=1e-6)


def test_energy_momentum_on_every_slice_adds_up_to_the_initial_total(fig2):
    for eta in (0.0, math.atanh(-0.6), math.atanh(0.3)):
        total = fig2.initial_total(eta)
        for t in np.linspace(-1.0, 5.0, 41):
            s = fig2.energy_momentum(eta, float(t))
            summed = s.kinetic + s.hidden
            assert (summed.E, summed.p) == pytest.approx((total.E, total.p), abs=1e-12)
            assert sum(em.E for _, em in s.bodies) == pytest.approx(s.kinetic.E, abs=1e-12)


def test_the_rigid_parts_own_lines_keep_the_rod_at_proper_length_L(fig2):
    for a, b in fig2.turning.now_lines():
        assert (b.x - a.x) ** 2 - (b.t - a.t) ** 2 == pytest.approx(1.0, abs=1e-12)
    moving = math.atanh(-0.6)
    times = fig2.turning.turn_times(moving)
    assert times == sorted(times) and len(times) >= 2
    assert all(fig2.turning.turn_interval(turn, moving)[0] in times for turn in fig2.turns)


@dataclass(frozen=True)
class _WithoutRigidPart:
    """A model that implements the interface but has no rigid part (as the causal rod will)."""

    inner: History

    def __getattr__(self, name):
        return getattr(self.inner, name)

    @property
    def turning(self):
        return None


def test_a_model_without_a_rigid_part_is_drawn_and_tabulated_without_its_lines(fig2):
    from rodparadox import render
    from rodparadox.physics.frames import paper_frames
    from rodparadox.tables.build import events_tables

    other = _WithoutRigidPart(fig2)
    assert isinstance(other, RodHistory)
    options = render.Options(rod_now=True, rod_lines=3)
    diagram = render.draw_into(__import__("matplotlib.figure").figure.Figure(figsize=(10, 6)), other,
                               paper_frames(0.6), "default", options)
    assert not any(diagram.artists.get("rod-now", {}).values())
    assert all(len(lines) > 0 for lines in diagram.artists["rod-lines"].values())
    assert len(events_tables(other, paper_frames(0.6))) == 2
