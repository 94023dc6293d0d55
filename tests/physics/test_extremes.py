"""Extreme inputs (issue 15): the cost of a figure is bounded by what it shows, whatever v, L, gaps and masses;
boost mode's axes stay readable at tiny v. Memory is measured through a cheap proxy: the points drawn."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rodparadox import render
from rodparadox.animate.timeline import boost_ends, timeline
from rodparadox.io.scenario import load
from rodparadox.physics import kinematics
from rodparadox.physics.rigid import run
from rodparadox.physics.frames import paper_frames
from rodparadox.physics.kinematics import Event, WorldLine


def history(name, **overrides):
    return run(load(name).with_overrides(**overrides))


# --- 1: calibration hyperbolae -----------------------------------------------------------------------------------

@pytest.mark.parametrize("v", [0.6, 0.99999, 0.9999999])
def test_hyperbolae_are_sampled_inside_the_box_with_a_bounded_number_of_points(v):
    """At v = 0.9999999 fig2's S' panel is 1e7 L wide; sampled to 1e-4 L over whole branches it took 16.9 GB.
    Six radii x two families x two sides, each piece inside the box: a few hundred points each at most."""
    diagram = render.draw(history("fig2", v=v), paper_frames(v), options=render.Options(hyperbolae=True))
    total = 0
    for letter, curves in diagram.artists["hyperbolae"].items():
        ax = curves[0].axes
        (x0, x1), (t0, t1) = ax.get_xlim(), ax.get_ylim()
        slack = 1e-9 * max(x1 - x0, t1 - t0)
        for curve in curves:
            xs, ts = curve.get_data()
            total += len(xs)
            assert ((xs >= x0 - slack) & (xs <= x1 + slack) & (ts >= t0 - slack) & (ts <= t1 + slack)).all()
            # still on its hyperbola t^2 - x^2 = +-k^2
            k2 = abs(ts[0] ** 2 - xs[0] ** 2)
            assert np.allclose(np.abs(ts ** 2 - xs ** 2), k2, rtol=1e-6, atol=1e-9 * max(x1 - x0, t1 - t0) ** 2)
    assert 0 < total < 10_000


# --- 2: clocks -----------------------------------------------------------------------------------------------

def test_clock_ticks_are_sought_only_inside_the_window(monkeypatch):
    """A clock at rest: tau = t. Ticks in the window [1e12, 1e12 + 10] at step 1 are the eleven events t = 1e12 + k,
    found without walking the 1e12 ticks from t = 0 (which never ended)."""
    calls = []
    original = kinematics._at_proper_time
    monkeypatch.setattr(kinematics, "_at_proper_time", lambda piece, tau: calls.append(tau) or original(piece, tau))
    ticks = kinematics.proper_time_events(WorldLine(Event(0.0, 0.0), 0.0), 1.0, 1e12, 1e12 + 10)
    assert [tau for tau, _ in ticks] == [1e12 + k for k in range(11)]
    assert [(e.x, e.t) for _, e in ticks] == [(0.0, 1e12 + k) for k in range(11)]
    assert len(calls) <= 11


def test_clocks_of_a_far_slow_particle_are_few(tmp_path):
    """B 1e6 L away at 1e-6 reaches the rod at t = 1e12 L: the clocks in the window, at most a dozen or so per
    world-line and panel (the step is a tenth of the longest panel's time span)."""
    scenario = tmp_path / "far.yaml"
    scenario.write_text("name: far\nv: 0.6\nparticles:\n  A:\n    gap: 0.5\n"
                        "  B:\n    gap: 1.0e+6\n    speed: 1.0e-6\n")
    v = 0.6
    diagram = render.draw(run(load(str(scenario))), paper_frames(v), options=render.Options(proper_time=True))
    for letter, marks in diagram.artists["clocks"].items():
        for mark in marks:
            assert len(mark.get_xdata()) <= 25


# --- 3: boost mode at tiny v ---------------------------------------------------------------------------------

@pytest.mark.parametrize("v", [1e-6, 1e-5])
def test_boost_at_tiny_v_draws_real_times_and_no_offset(v):
    """fig2 at v = 1e-6 happens near t = 5e5 L: the t ticks read 500000.0 and so on, no "+5e5" offset over the
    title, and the frame is drawn without FreeType's raster overflow (axis names far outside are hidden)."""
    from rodparadox.animate.boost_scene import BoostScene

    h = history("fig2", v=v)
    line = timeline(h, boost_ends("both", v), "boost", 4)
    with render.style_context("default"):
        scene = BoostScene(h, line, "default")
        for k in range(4):
            scene.update(k)
            scene.canvas.draw()
        t_labels = [t.get_text() for t in scene.ax.get_yticklabels() if t.get_text()]
        assert scene.ax.yaxis.get_offset_text().get_text() == ""
        assert scene.ax.xaxis.get_offset_text().get_text() == ""
        centre = 0.5 / v  # the impacts lie near t = L / (2 v)
        assert all(abs(float(text.replace("\N{MINUS SIGN}", "-")) - centre) < 5 for text in t_labels)
        assert not any(name.get_visible() for (frame, axis), name in scene.names.items() if axis == "x")


def test_boost_at_a_window_1e12_away_writes_each_tick_with_its_power_of_ten(tmp_path):
    """Real values whose plain digits would not fit: each label its own 2×10¹¹ (as plot writes them)."""
    from rodparadox.animate.boost_scene import BoostScene

    scenario = tmp_path / "far.yaml"
    scenario.write_text("name: far\nv: 0.6\nparticles:\n  A:\n    gap: 0.5\n"
                        "  B:\n    gap: 1.0e+6\n    speed: 1.0e-6\n")
    h = run(load(str(scenario)))
    line = timeline(h, boost_ends("both", 0.6), "boost", 3)
    with render.style_context("default"):
        scene = BoostScene(h, line, "default")
        scene.update(1)
        scene.canvas.draw()
        labels = [t.get_text() for t in scene.ax.get_yticklabels() if t.get_text()]
        assert "1\N{MULTIPLICATION SIGN}10\N{SUPERSCRIPT ONE}\N{SUPERSCRIPT TWO}" in labels
        # x labels do not touch: each narrower than the distance between ticks
        renderer = scene.canvas.get_renderer()
        boxes = sorted((t.get_window_extent(renderer) for t in scene.ax.get_xticklabels() if t.get_text()),
                       key=lambda b: b.x0)
        assert all(a.x1 < b.x0 for a, b in zip(boxes, boxes[1:]))


# --- 6: fractions and zeros at v = 0.9999999 seen from u = 0.9999999 ----------------------------------------------

def test_a_fraction_is_written_only_where_the_match_means_something():
    """17/12 and 15/17 (numbers of order 1, matched to 1e-15) stay fractions; 909999955/91 for a number near 1e7,
    which FRACTION_MATCH (1e-12 of it: 1e-5) lets match some q <= 100 by chance once in sixteen, does not."""
    from rodparadox.numbers import fraction_text

    assert fraction_text(17 / 12) == "17/12"
    assert fraction_text(-15 / 17) == "\N{MINUS SIGN}15/17"
    assert fraction_text(909999955 / 91) is None
    assert fraction_text(-949999953 / 95) is None
    assert fraction_text(4250 / 3) == "4250/3"  # thirds of a thousand: one chance in a hundred million


def test_events_tables_at_the_extreme_frame_carry_no_chance_fractions():
    from click.testing import CliRunner
    from sears_paradox_cli.main import main

    for fmt in ("markdown", "latex"):
        result = CliRunner().invoke(main, ["events", "fig2", "--v", "0.9999999", "--frame-velocity", "0.9999999",
                                           "--format", fmt])
        assert result.exit_code == 0, result.output
        assert "/91" not in result.output and "/95" not in result.output


def test_the_handout_reads_a_time_against_its_own_impacts_rounding():
    """B₁ (B from x = L at speed v to the right end x = L/2) is at t = L/(2v); in the frame u = v,
    t_u = g (t - v x) = g (1 - v^2) L / (2 v) = L / (2 g v) = 2.236e-4 L at v = 0.9999999: far above the rounding
    of B₁'s own coordinates (1e-9 of about L, stretched by g (1 + v) ~ 4472), though below 1e-9 of A₁'s 1e7 L,
    against which the handout read it as 0."""
    from rodparadox.handout.reading import Reading
    from rodparadox.physics.frames import frame_of_velocity

    v = 0.9999999
    g = 1 / math.sqrt(1 - v * v)
    h = history("fig2", v=v)
    frame = frame_of_velocity(v)
    r = Reading(h, (frame,))
    b1 = next(i for i in h.impacts if i.label == "B1")
    assert r.length(r.t(b1, frame), [b1], frame) == pytest.approx(1 / (2 * g * v), rel=1e-5)
    assert "2.236" in r.when([b1], frame)
    from rodparadox.handout.narrative import _simultaneity
    assert "(tᵤ = 0)" not in _simultaneity(r)
    assert "/91" not in _simultaneity(r)
    # the rounding-sized x' = 0 of A₁ in Fig. 1 (6e-17) is still 0
    f1 = history("fig1", v=0.6)
    r1 = Reading(f1, (frame_of_velocity(-0.6),))
    a1 = next(i for i in f1.impacts if i.label == "A1")
    assert abs(r1.x(a1, r1.frames[0])) < 1e-12 and r1.length(r1.x(a1, r1.frames[0]), [a1], r1.frames[0]) == 0.0


# --- 10: one scenario, one verdict --------------------------------------------------------------------------------

HEAVY = ("name: heavy\nv: 0.9999999\nparticles:\n  A:\n    mass: 1.0e+9\n    gap: 0.5\n"
         "  B:\n    mass: 1.0e-9\n    gap: 0.5\n")


@pytest.mark.parametrize("command", [["events"], ["export"], ["plot"], ["ledger"], ["ledger", "--format", "text"],
                                     ["animate"], ["animate", "--mode", "boost"], ["handout"]])
def test_every_command_gives_the_heavy_scenario_the_same_verdict(tmp_path, monkeypatch, command):
    """Mass 1e9 against 1e-9 at v = 0.9999999: B, struck together with A's blow, leaves at a rapidity whose tanh is
    1.0 in double precision (its gap to c, 2 / (e^(2 phi) + 1), is about 2.5e-22). Every command refuses it with
    the same sentence, exit 2, nothing written."""
    from click.testing import CliRunner
    from sears_paradox_cli.main import main

    monkeypatch.chdir(tmp_path)
    (tmp_path / "heavy.yaml").write_text(HEAVY)
    out = tmp_path / "out"
    out.mkdir()
    extra = [] if command[0] in ("events", "export") or "--format" in command else ["-o", str(out)]
    result = CliRunner().invoke(main, [command[0], "heavy.yaml", *command[1:], *extra])
    assert result.exit_code == 2, result.output
    assert result.output.startswith("Error: in frame rest the particle B's velocity after B1 is within 2.5e-22 of c")
    assert list(out.iterdir()) == []


def test_the_ledger_keeps_the_rods_rest_energy_beside_a_particle_of_2e12():
    """A of mass 1e9 at v = 0.9999999 (g = 2236.068: E = 2.236068e12) strikes the rod at rest in S: the rod's rest
    energy 1 is no rounding of a difference and is printed 1, not 0."""
    from rodparadox.io.ledger_report import to_text
    from rodparadox.io.scenario import parse
    from rodparadox.physics.frames import rest_frame
    from rodparadox.tables.build import ledger_table

    s = run(parse("name: heavyA\nv: 0.9999999\nparticles:\n  A:\n    mass: 1.0e+9\n    gap: 0.5\n", "heavyA.yaml", "heavyA"))
    text = to_text(s, (rest_frame(),))
    row = next(line for line in text.splitlines() if line.strip().startswith("rod, kinetic"))
    assert row.split()[2:] == ["1.0000", "0.0000", "1.0000", "0.0000"]  # four decimals in every ledger column
    before = next(line for line in text.splitlines() if line.strip().startswith("rod, dynamical"))
    assert before.split("E ")[1].split(" ->")[0] == "1.0000"  # its rest energy before A1
    table = ledger_table(s, rest_frame())
    kinetic = next(row for row in table.rows if row[2].text == "rod, kinetic")
    dynamical = next(row for row in table.rows if row[2].text.startswith("rod, dynamical"))
    assert (kinetic[3].text, dynamical[3].text) == ("1.0000", "1.0000")
