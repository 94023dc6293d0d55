"""The ledger figure of a rod driven by forces (issue 26, item 4 `ledger`): per slice what each agent delivered, the
rod's parts and its whole, with the conservation check on the table's slices. Checked against hand derivations
(Sears's sine^2 pulses: area peak duration / 2; the rigid rod held at rest in S, seen from S' at v) and the
history's own conservation law, never against the drawing code's numbers alone.

Runs are made once per process; the figure's curves are sampled on few slices (`SLICES` patched) to stay cheap.
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np
import pytest

from rodparadox.io.scenario import load
from rodparadox.physics.frames import paper_frames
from rodparadox.physics.models import run_rods
from rodparadox.render import forces_ledger_figure as figure_module

V = 0.6
GAMMA = 1 / math.sqrt(1 - V * V)
#: Sears's pulses: peak 0.2 M c^2/L for L: the momentum each delivers in S, its area
AREA = 0.2 * 1.0 / 2


@lru_cache(maxsize=None)
def runs(name: str):
    return run_rods(load(name), "both")


@pytest.fixture
def few_slices(monkeypatch):
    monkeypatch.setattr(figure_module, "SLICES", 12)


def test_sears_rigid_rod_curves_are_the_hand_derived_ones_in_S_and_S_prime(few_slices):
    """Held at rest in S: its kinetic p is 0 in S and gamma v M c in S' on every slice, no stress in S; each agent has
    delivered its pulse's area, +-0.1 M c, in S (no energy: the ends do not move) and gamma times that in S'."""
    rigid, _ = runs("sears")
    rest, moving = paper_frames(V)
    times, values, _ = figure_module.series(rigid, rest)
    assert np.max(np.abs(values["p"]["part"])) <= 1e-12 and np.max(np.abs(values["p"]["stress"])) <= 1e-12
    assert np.max(np.abs(values["E"]["left"])) <= 1e-12 and np.max(np.abs(values["E"]["part"] - 1)) <= 1e-12
    assert math.isclose(values["p"]["left"][-1], AREA, rel_tol=1e-12)
    assert math.isclose(values["p"]["right"][-1], -AREA, rel_tol=1e-12)
    times, values, _ = figure_module.series(rigid, moving)
    assert np.max(np.abs(values["p"]["part"] - GAMMA * V)) <= 1e-12
    assert math.isclose(values["p"]["left"][-1], GAMMA * AREA, rel_tol=1e-12)
    assert values["p"]["initial"] == pytest.approx(GAMMA * V, abs=1e-15)
    assert np.max(values["p"]["stress"]) > 0.05  # Sears's hidden momentum, in S' alone


@pytest.mark.parametrize("k", [0, 1])
def test_the_check_circles_sit_on_the_rods_whole_on_the_tables_slices(k, few_slices):
    """Before the forces + delivered (the circles) equals the rod's kinetic (matter) plus stress part on each of the
    ledger table's slices, for both rods, in S'."""
    history = runs("sears_moving")[k]
    frame = paper_frames(V)[1]
    _, _, (at, check) = figure_module.series(history, frame)
    assert len(at) == 9
    for t, E, p in zip(at, check["E"], check["p"]):
        part, stress = history.rod_parts(frame.rapidity, t)
        assert abs(part.E + stress.E - E) <= 1e-9 and abs(part.p + stress.p - p) <= 1e-9


def test_force_starts_and_ends_are_named_once_per_instant():
    """sears_moving's forces start together at t' = 0.5 and end at 1.5 in S' (one name each); in S the right end's
    starts first, at t = t'/gamma - v x = 0.4 - 0.3 = 0.1 (the end at rest at x = L/2 until then)."""
    rigid, _ = runs("sears_moving")
    rest, moving = paper_frames(V)
    assert [(n, round(t, 12)) for n, _, t in figure_module.events(rigid, moving)] == [("on", 0.5), ("off", 1.5)]
    in_S = figure_module.events(rigid, rest)
    assert [n for n, _, _ in in_S] == ["right on", "left on", "right off", "left off"]
    assert math.isclose(in_S[0][2], 0.1, rel_tol=1e-12)


def test_both_rods_figure_has_every_curve_one_scale_and_the_legend(few_slices):
    rigid, causal = runs("sears")
    figure = figure_module.draw((rigid, causal), paper_frames(V)[1:], "print")
    gids = {a.get_gid() for ax in figure.axes for a in [*ax.lines, *ax.collections, *ax.texts]}
    for letter in "ab":
        for q in "pE":
            for curve in ("left", "right", "rod_part", "rod", "stress", "check", "initial"):
                assert f"{letter}-{q}-{curve}" in gids
    assert {"a-label-left on", "a-label-right off"} <= gids
    by_gid = {ax.get_gid(): ax for ax in figure.axes}
    assert by_gid["a-p-axes"].get_ylim() == by_gid["b-p-axes"].get_ylim()
    words = [t.get_text() for t in figure.legends[0].get_texts()]
    assert "delivered by the force on the left end" in words and "rigid rod: hidden = stress = whole − kinetic" in words
    assert not any("particle" in w for w in words)


def test_force_events_simultaneous_in_a_frame_give_one_slice_of_the_table():
    """sears_moving's forces start together at t' = 0.5 of S' (and peak and end together): one slice each, not one per
    force (their two S events boosted to S' differ by rounding); the slices are the window's ends, the three instants
    and the midpoints between them."""
    from rodparadox.tables.forces_ledger import slice_times

    times = slice_times(runs("sears_moving")[0], paper_frames(V)[1])
    assert all(b - a > 1e-9 for a, b in zip(times, times[1:])) and len(times) == 9
    assert [round(t, 9) for t in times if 0.4 < t < 1.6] == [0.5, 0.75, 1.0, 1.25, 1.5]
