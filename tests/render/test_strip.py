"""The strip as a layer (`render.strip`): `draw_strips_into` draws one row per instant, earliest on top, each bar
from the rod's exact left end to its exact right end at that instant, the particles where their world-lines are,
the impacts of that instant marked; `draw_strip`/`update_strip` move one strip. Positions are checked against the
engine's world-lines evaluated at the instant (and hand formulas), never against the strip's own output."""

import math

import numpy as np
import pytest
from matplotlib.figure import Figure

from rodparadox.physics.rigid import run
from rodparadox.physics.frames import Frame, time_window
from rodparadox.physics.snapshot import strip_at
from rodparadox.render import draw_strips_into, style_context
from rodparadox.render.colour_scale import colour_scale
from rodparadox.render.strip import COLOUR_BAR_LABEL, draw_strip, update_strip
from rodparadox.io.scenario import load

#: drawn coordinates against the exact world-lines, in units of L: rounding only
AGREE = 1e-12


def history(name="fig2", v=0.6):
    return run(load(name).with_overrides(v=v, L=None))


def block(h, frame, times, style="default", size=(7.0, 5.0)):
    with style_context(style):
        figure = Figure(figsize=size, dpi=72)
        rows = draw_strips_into(figure, h, frame, times, style)
    return figure, rows


def drawn(ax, name):
    """The artist of a strip by its id: bar, outline, particles, impacts, particle-A ..."""
    found = [a for a in ax.get_children() if (a.get_gid() or "").endswith(f"-{name}")]
    assert len(found) == 1, (name, [a.get_gid() for a in ax.get_children()])
    return found[0]


def bar_ends(ax) -> tuple[float, float]:
    segments = drawn(ax, "bar").get_segments()
    return segments[0][0][0], segments[-1][-1][0]


@pytest.mark.parametrize("name, v", [("fig2", 0.6), ("single", 0.3), ("while_turning", 0.95), ("fig1", 0.6)])
@pytest.mark.parametrize("which", ["rest", "moving"])
def test_one_row_per_time_earliest_on_top_each_bar_the_exact_rod(name, v, which):
    h = history(name, v)
    frame = Frame(which, 0.0 if which == "rest" else -v)
    eta = frame.rapidity
    t_lo, t_hi = time_window(h, frame)
    times = [t_hi, t_lo, 0.5 * (t_lo + t_hi), t_lo + 0.3 * (t_hi - t_lo)]  # any order in; sorted out
    _, rows = block(h, frame, times)
    assert len(rows) == 4
    tops = [ax.get_position().y0 for ax in rows]
    assert tops == sorted(tops, reverse=True)  # top to bottom
    for ax, t in zip(rows, sorted(times)):
        left = h.worldline("rod_left").seen_from(eta).event_at_time(t).x
        right = h.worldline("rod_right").seen_from(eta).event_at_time(t).x
        a, b = bar_ends(ax)
        assert a == pytest.approx(left, abs=AGREE * (1 + abs(t))) and b == pytest.approx(right, abs=AGREE * (1 + abs(t)))
        dots = drawn(ax, "particles").get_xdata()
        want = [h.worldline(p).seen_from(eta).event_at_time(t).x for p in ("A", "B") if h.worldline(p) is not None]
        assert np.allclose(dots, want, atol=AGREE * (1 + abs(t)), rtol=0)
        assert ax.get_xlim() == rows[0].get_xlim()  # one shared x axis


def test_rows_are_labelled_with_their_time_and_marked_impacts_only_at_their_instant():
    """fig2 in S': B1 and A1 at t' = 17/12 g... : t'_B = (gL/2v)(1 + v^2) (the README's table: 1.416667 at v = 0.6),
    B2 at 3.291667."""
    v = 0.6
    g = 1 / math.sqrt(1 - v * v)
    h = history("fig2", v)
    t_b = g / (2 * v) * (1 + v * v)
    figure, rows = block(h, Frame("moving", -v), [0.5, t_b, 3.291666666666667, 4.0])
    texts = [[t.get_text() for t in ax.texts if (t.get_gid() or "").startswith(("strips-time-", "strips-impacts-"))]
             for ax in rows]
    assert texts[0] == ["$t$\N{PRIME} = 0.5 $L$"]
    assert texts[1] == ["$t$\N{PRIME} = 1.417 $L$", "impacts $B_{1}$, $A_{1}$"]
    assert texts[2] == ["$t$\N{PRIME} = 3.292 $L$", "impact $B_{2}$"]
    assert texts[3] == ["$t$\N{PRIME} = 4 $L$"]
    stars = [drawn(ax, "impacts").get_xdata() for ax in rows]
    assert len(stars[0]) == 0 and len(stars[3]) == 0
    # the impacts' x in S', by hand: x' = g(x + v t) of B1 = (L/2, L/2v) and A1 = (-3L/4, ...) (README's table)
    assert sorted(stars[1]) == pytest.approx([0.25, 1.25], abs=1e-12)
    assert list(stars[2]) == pytest.approx([2.375], abs=1e-12)
    assert rows[-1].get_xlabel() == "x\N{PRIME}/L"
    colour_bars = [ax for ax in figure.axes if ax.get_gid() == "strips-colour-bar"]
    assert len(colour_bars) == 1 and colour_bars[0].get_xlabel() == COLOUR_BAR_LABEL
    # S' of fig2: the rod first moves at v = 0.6, stops (0) and, after A1, moves at 2v/(1 + v^2) = 15/17 = 0.882:
    # the bar shows 0 to 15/17 with the starting velocity marked, never the scale's end 2v = 1.2, past c
    assert [t.get_text() for t in colour_bars[0].get_xticklabels()] == ["0", "0.6", "0.882"]
    assert colour_bars[0].get_xlim() == pytest.approx((0.0, 15 / 17), abs=1e-12)


def test_the_bar_colours_are_the_material_points_velocities_on_the_frames_scale():
    v = 0.6
    h = history("fig2", v)
    frame = Frame("moving", -v)
    t = 2.0
    _, rows = block(h, frame, [t])
    bar = drawn(rows[0], "bar")
    strip = strip_at(h, frame, t, 0.0)
    assert np.allclose(bar.get_array(), 0.5 * (strip.velocity[1:] + strip.velocity[:-1]), atol=1e-15)
    scale = colour_scale(h, frame)
    assert (bar.norm.vmin, bar.norm.vmax) == scale.limits


def test_draw_into_a_subfigure_and_a_too_small_target_is_refused():
    h = history()
    with style_context("slides"):
        figure = Figure(figsize=(13.33, 7.5), dpi=72)
        left, right = figure.subfigures(1, 2)
        rows = draw_strips_into(right, h, Frame("rest", 0.0), [0.5, 1.0, 1.5], "slides")
    half = figure.bbox.width / 2
    assert len(rows) == 3 and all(ax.get_window_extent().x0 >= half for ax in rows)
    with pytest.raises(ValueError, match="need at least"):
        block(h, Frame("rest", 0.0), [0.5] * 12, size=(3.0, 2.0))


def test_update_strip_moves_the_bar_to_the_exact_rod_at_another_instant():
    v = 0.95
    h = history("while_turning", v)
    frame = Frame("moving", -v)
    scale = colour_scale(h, frame)
    figure = Figure(figsize=(5, 1), dpi=72)
    ax = figure.add_axes((0.1, 0.3, 0.8, 0.4))
    artists = draw_strip(ax, strip_at(h, frame, 0.0, 0.0), "default", scale, frame)
    for t in (0.5, 2.0, 3.7):
        update_strip(artists, strip_at(h, frame, t, 0.0), frame)
        eta = frame.rapidity
        a, b = bar_ends(ax)
        assert a == pytest.approx(h.worldline("rod_left").seen_from(eta).event_at_time(t).x, abs=1e-11)
        assert b == pytest.approx(h.worldline("rod_right").seen_from(eta).event_at_time(t).x, abs=1e-11)
        said = artists.readout.get_text()
        assert said.startswith("$t$\N{PRIME} = ") and said.endswith(" $L$ in S\N{PRIME}"), said
