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
from rodparadox.render.strip_windows import follows_rod
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
        lo, hi = ax.get_xlim()
        assert hi - lo == pytest.approx(np.diff(rows[0].get_xlim())[0], rel=1e-12)  # one scale
        # one shared x axis, unless the rod drifts far for its length and each row follows it (while_turning in S′)
        shared = not follows_rod([strip_at(h, frame, t, 0.0) for t in times], h.scenario.L)
        assert (ax.get_xlim() == rows[0].get_xlim()) == shared or ax is rows[0]
    assert (which, name) != ("moving", "while_turning") or not shared


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


def test_the_parts_of_a_block_split_between_pages_keep_one_tick_step_and_one_axes_width():
    """Issue 24: a block of strips split over two pages changed its tick step (each part's room was made for its
    own labels, so its axes' width, and so the step, differed). With `span`, the whole block's."""
    from matplotlib.figure import Figure

    from rodparadox import render
    from rodparadox.handout.strips import strip_times
    from rodparadox.physics.rigid import run
    from rodparadox.physics.frames import paper_frames
    from rodparadox.io.scenario import load

    h = run(load("while_turning").with_overrides(v=0.95))
    frame = paper_frames(0.95)[1]
    times = strip_times(h, frame)
    parts = []
    for part in (times[:2], times[2:]):
        figure = Figure(figsize=(6.5, 1.2 * len(part) + 1.2))
        with render.style_context("print"):
            rows = render.draw_strips_into(figure, h, frame, part, "print", span=times)
        ticks = rows[0].get_xticks()
        parts.append((round(ticks[1] - ticks[0], 12), np.diff(rows[0].get_xlim())[0].round(12),
                      rows[0].get_position().x0, rows[0].get_position().x1))
    assert parts[0] == parts[1]  # one step, one width in L (each row follows the rod here), one axes width


def test_a_colour_bar_only_where_the_rod_s_velocity_varies():
    """Issue 24: fig1's rod never changes velocity (it takes both impulses together), yet its strips had a colour bar
    from −0.0997 to +0.0997; now none, and less room under the rows. fig2's rod zig-zags: its bar stays."""
    from matplotlib.figure import Figure

    from rodparadox import render
    from rodparadox.handout.strips import strip_times
    from rodparadox.io.scenario import load
    from rodparadox.physics.frames import paper_frames
    from rodparadox.physics.rigid import run

    heights = {}
    for name in ("fig1", "fig2"):
        h = run(load(name))
        frame = paper_frames(0.6)[1]
        times = strip_times(h, frame)
        figure = Figure(figsize=(6.5, 6.0))
        with render.style_context("print"):
            render.draw_strips_into(figure, h, frame, times, "print")
        bars = [ax for ax in figure.axes if ax.get_gid() == "strips-colour-bar"]
        assert len(bars) == (0 if name == "fig1" else 1), name
        heights[name] = render.strips_size(h, frame, times[:6], "print")[1]
    assert heights["fig1"] < heights["fig2"]


def test_where_the_rod_drifts_far_each_row_follows_it_at_one_scale_and_marks_the_particles_beyond():
    """Issue 24: the causal rod in S′ at v = 0.95 drifts 15 L while it is 0.2 to 0.6 L long, so on one shared axis
    it was a blob. Each row now follows it: every row as wide, centred on the rod at its instant, its own ticks; a
    particle beyond a row's edge is an arrowhead there. fig1's rigid rod at 0.95 (0.06 of the range) keeps the
    shared axis."""
    from helpers import causal_history

    from rodparadox.handout.causal_compare import causal_strip_times
    from rodparadox.handout.strips import strip_times
    from rodparadox.physics.frames import moving_frame

    frame = moving_frame(0.95)
    h = causal_history("fig1", 0.95)
    times = causal_strip_times(h, frame)
    figure, rows = block(h, frame, times, "print", size=(6.5, 8.5))
    widths = {round(ax.get_xlim()[1] - ax.get_xlim()[0], 12) for ax in rows}
    assert len(widths) == 1  # one scale
    for ax, t in zip(rows, sorted(times)):
        a, b = bar_ends(ax)
        lo, hi = ax.get_xlim()
        assert lo < a < b < hi and (b - a) / (hi - lo) > 0.08  # the rod in view, at least 8 % of the row (was 1 %)
        assert abs(0.5 * (a + b) - 0.5 * (lo + hi)) < 1e-9  # centred on it
        assert any(label.get_visible() and label.get_text()
                   for label in ax.get_xticklabels())  # each row its own ticks
        beyond = {str(artist.get_gid()).rsplit("-", 1)[-1] for artist in ax.get_children()
                  if str(artist.get_gid()).startswith(f"{ax.get_gid()}-beyond-") and not artist.get_gid().endswith("letter")}
        for name, x in strip_at(h, frame, t, 0.0).particles:
            assert (name in beyond) == (not lo <= x <= hi), (t, name)  # a particle out of view is marked
    assert render_size_fits(h, frame, times)
    rigid = history("fig1", 0.95)
    _, shared = block(rigid, frame, strip_times(rigid, frame), "print", size=(6.5, 7.0))
    assert len({ax.get_xlim() for ax in shared}) == 1  # the rigid rod reads on one axis: it keeps it


def render_size_fits(h, frame, times) -> bool:
    """A target of the least size `strips_size` gives, rows and each row's ticks included, is accepted."""
    from rodparadox import render

    w, hh = render.strips_size(h, frame, times, "print")
    with style_context("print"):
        render.draw_strips_into(Figure(figsize=(w / 72 + 0.01, hh / 72 + 0.01), dpi=72), h, frame, times, "print")
    return True


def test_a_kept_instants_strip_is_the_strip_computed_afresh():
    """`strips_at` keeps each instant's strip: blocks sharing an instant share it, read-only, and it is the strip
    `strip_at` computes afresh."""
    from rodparadox.render.strip_windows import strips_at

    h, frame = history(), Frame("moving", -0.6)
    first, second = strips_at(h, frame, (0.5, 1.5), 0.01), strips_at(h, frame, (1.5, 2.5), 0.01)
    assert first[1] is second[0] and not first[1].x.flags.writeable
    fresh = strip_at(h, frame, 1.5, 0.01)
    assert np.array_equal(first[1].x, fresh.x) and np.array_equal(first[1].velocity, fresh.velocity)
    assert first[1].t == fresh.t and first[1].particles == fresh.particles
