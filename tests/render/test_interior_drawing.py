"""`plot --rod-lines N`, `--rod-now`, `--proper-time`: the inside of the rod as drawn, checked against the exact
world-lines, the model's rules and invariance (the drawn objects, not pixels)."""

from __future__ import annotations

import math
import re
from functools import lru_cache

import numpy as np
import pytest
from click.testing import CliRunner

from rodparadox import render
from rodparadox.physics.rigid import run
from rodparadox.physics.frames import paper_frames, time_window
from rodparadox.physics.kinematics import Event
from rodparadox.physics.rod import clock_step
from rodparadox.physics.rigid.turns import material_worldline
from rodparadox.io.scenario import load
from sears_paradox_cli.main import main

INSIDE = render.Options(rod_lines=5, rod_now=True, proper_time=True)


def drawn_afresh(name: str, v: float = 0.6, style: str = "default", options=INSIDE):
    h = run(load(name).with_overrides(v=v))
    return h, render.draw(h, paper_frames(h.scenario.v), style, options).figure


def drawn(name: str, v: float = 0.6, style: str = "default", options=INSIDE):
    """`drawn_afresh`, once per process (`drawn("fig2")` and `drawn("fig2", 0.6)` alike): the tests only read it."""
    return _kept(name, v, style, options)


@lru_cache(maxsize=None)
def _kept(name, v, style, options):
    return drawn_afresh(name, v, style, options)


def lines_of(fig, pattern: str) -> dict[str, np.ndarray]:
    return {a.get_gid(): np.column_stack([a.get_xdata(), a.get_ydata()]).astype(float)
            for a in fig.findobj(lambda a: bool(a.get_gid()) and re.fullmatch(pattern, a.get_gid()))}


def test_off_by_default_and_in_the_legend_when_on():
    _, plain = drawn("fig2", options=render.Options())
    assert lines_of(plain, r".-(rod-line|rod-now|clock)-.*") == {}
    _, fig = drawn("fig2")
    legend = [t.get_text() for t in fig.legends[0].get_texts()]
    # "material points inside the rod", with how many where fewer fit 1 mm apart (test_legible_panels)
    assert any(t.startswith("material points inside the rod") for t in legend)
    assert "the rod’s own lines of simultaneity" in legend
    assert any(re.fullmatch(r"proper time: a tick every [\d.]+ \$L\$", t) for t in legend)


@pytest.mark.parametrize("name, v", [("fig2", 0.3), ("fig2", 0.95), ("while_turning", 0.6), ("single", 0.8)])
def test_material_lines_are_the_exact_world_lines_of_evenly_spaced_points(name, v):
    h, fig = drawn(name, v)
    L = h.scenario.L
    for letter, frame in zip("ab", paper_frames(h.scenario.v)):
        lines = lines_of(fig, rf"{letter}-rod-line-\d+")
        n = len(lines)  # 5, or fewer where 5 would not stay 1 mm apart on the page (test_legible_panels)
        assert sorted(lines) == [f"{letter}-rod-line-{k}" for k in range(1, n + 1)] and (n == 5 or v >= 0.8)
        for k in range(1, n + 1):
            exact = material_worldline(h, k * L / (n + 1)).seen_from(frame.rapidity)
            points = lines[f"{letter}-rod-line-{k}"]
            x = np.array([exact.event_at_time(t * L).x / L for t in points[:, 1]])
            assert np.abs(x - points[:, 0]).max() <= 1.1e-4  # every vertex on the exact curve (sampled within 1e-4 L)


@pytest.mark.parametrize("name", ["fig2", "while_turning", "unequal_masses"])
def test_the_rods_own_lines_are_L_long_end_to_end_and_fan_out_from_each_pivot(name):
    h, fig = drawn(name)
    L = h.scenario.L
    for letter, frame in zip("ab", paper_frames(h.scenario.v)):
        segments = lines_of(fig, rf"{letter}-rod-now-\d+")
        assert segments
        left, right = (h.worldline(end).seen_from(frame.rapidity) for end in ("rod_left", "rod_right"))
        ends = []
        for (x0, t0), (x1, t1) in segments.values():
            assert (x1 - x0) ** 2 - (t1 - t0) ** 2 == pytest.approx(1.0, abs=1e-9)  # proper length L (units of L)
            assert left.event_at_time(t0 * L).x / L == pytest.approx(x0, abs=1e-9)
            assert right.event_at_time(t1 * L).x / L == pytest.approx(x1, abs=1e-9)
            ends += [(x0, t0), (x1, t1)]
        for turn in h.turns:
            p = turn.pivot.seen_from(frame.rapidity)
            through = sum(math.hypot(x - p.x / L, t - p.t / L) < 1e-9 for x, t in ends)
            assert through >= 4 or not turn.completed  # the fan: four lines through the pivot


@pytest.mark.parametrize("name, v", [("fig2", 0.6), ("off_timing", 0.8)])
def test_clock_ticks_are_the_same_events_in_every_panel_and_a_step_of_proper_time_apart(name, v):
    h, fig = drawn(name, v)
    frames = paper_frames(h.scenario.v)
    L = h.scenario.L
    step = clock_step(max(w - u for u, w in (time_window(h, f) for f in frames)))
    in_s = lines_of(fig, r"a-clock-.*")
    in_moving = lines_of(fig, r"b-clock-.*")
    assert sorted(in_s) == sorted(f"a-clock-{n}" for n, _ in h.worldlines)
    shared = 0
    for name_, points in in_moving.items():
        body = name_[len("b-clock-"):]
        back = [Event(x * L, t * L).seen_from(-frames[1].rapidity) for x, t in points]  # to S
        window = (frames[0], in_s[f"a-clock-{body}"])
        ticks_s = {(round(x, 6), round(t, 6)) for x, t in window[1]}
        lo, hi = window[1][:, 1].min(), window[1][:, 1].max()
        common = [(round(e.x / L, 6), round(e.t / L, 6)) for e in back if lo <= e.t / L <= hi]
        assert set(common) <= ticks_s, body
        shared += len(common)
    assert shared >= 3  # ticks seen in both panels, at the same events
    # consecutive ticks are one step of proper time apart along the world-line: summed over a fine polyline of the
    # world-line read in S (chords converge to the proper time from above, the twin paradox), not from the clocks' code
    for body, worldline in h.worldlines:
        ticks = sorted(in_s[f"a-clock-{body}"][:, 1] * L)
        for t0, t1 in zip(ticks, ticks[1:]):
            kinks = [e.t for e in (worldline.first, worldline.last, *(x for seg in worldline.segments for x in (seg.start, seg.end)))
                     if t0 < e.t < t1]
            ts = np.unique(np.concatenate([np.linspace(t0, t1, 4001), kinks]))
            xs = np.array([worldline.event_at_time(t).x for t in ts])
            tau = np.sqrt(np.diff(ts) ** 2 - np.diff(xs) ** 2).sum()
            assert tau == pytest.approx(step, rel=1e-6), (body, t0, t1)
    # before any impact the rod rests in S: its ends' ticks are at t = k * step
    first = min(i.event.t for i in h.impacts)
    for end in ("rod_left", "rod_right"):
        early = [t for _, t in in_s[f"a-clock-{end}"] if t * L < first]
        assert early and all(abs(t * L / step - round(t * L / step)) < 1e-9 for t in early)


def test_file_names_say_which_interior_layers_are_drawn(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(main, ["plot", "fig2", "--rod-lines", "7", "--rod-now", "--proper-time"])
    assert result.output == "outputs/fig2_now_clocks_lines7.svg\n"
    result = CliRunner().invoke(main, ["plot", "fig2", "--rod-lines", "51"])
    assert result.exit_code == 2 and "51 is not in the range 0<=x<=50" in result.output


@pytest.mark.parametrize("style", ["default", "print", "slides"])
def test_every_style_draws_the_interior_and_stays_deterministic(style):
    _, fig = drawn("fig2", 0.6, style)
    one = render.figure_bytes(fig, "svg", style)
    _, again = drawn_afresh("fig2", 0.6, style)  # a second drawing, not the kept one
    assert one == render.figure_bytes(again, "svg", style)
    assert b"a-rod-now-0" in one and b"b-clock-A" in one and b"a-rod-line-5" in one


@pytest.mark.parametrize("name", ["fig1", "while_turning", "unequal_masses"])
def test_clock_ticks_do_not_crowd_even_at_high_speed(name):
    """The step follows the longest panel's time span: a body at rest in S' at v = 0.95 gets about ten ticks, not
    fifty (found in review: a solid chain of circles)."""
    _, fig = drawn(name, 0.95)
    for gid, points in lines_of(fig, r"[ab]-clock-.*").items():
        assert len(points) <= 13, (gid, len(points))
