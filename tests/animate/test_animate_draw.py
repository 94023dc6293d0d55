"""What an animation's images show (README, "The paradox in motion"), checked on the drawn artists and on the
pixels against the exact world-lines (the engine's, boosted; and hand formulas for `single`), never against
the drawing's own output: the now-line at each frame's instant, the bar from the rod's left end to its right
end, the bar's colours the material points' velocities through the colour scale, the lens, boost mode's axes."""

import math

import numpy as np
import pytest

from rodparadox import render
from rodparadox.animate.now_scene import LENS_BELOW, NowScene
from rodparadox.animate.scenes import images_of
from rodparadox.animate.timeline import timeline
from rodparadox.physics.rigid import run
from rodparadox.physics.frames import Frame, paper_frames, time_window
from rodparadox.render.strip import PRINT_RAMP, colour_map
from rodparadox.physics.rigid.turns import material_worldline
from rodparadox.io.scenario import load
from rodparadox.render.colour_scale import colour_scale

#: drawn coordinates against exact ones, in units of L: rounding only
AGREE = 1e-12


def history(name="fig2", v=0.6):
    return run(load(name).with_overrides(v=v, L=None))


def scene(h, frames, count, style="default"):
    line = timeline(h, frames, "now", count)
    with render.style_context(style):
        return NowScene(h, line, style), line


def instant(h, frame, k, count):
    """The k-th of `count` instants of a panel, by the README's rule: t_lo + k/(count - 1) (t_hi - t_lo)."""
    t_lo, t_hi = time_window(h, frame)
    return t_lo + k / (count - 1) * (t_hi - t_lo)


def bar_ends(strip):
    segments = strip.bar.get_segments()
    return segments[0][0][0], segments[-1][-1][0]


@pytest.mark.parametrize("name, v", [("fig2", 0.6), ("while_turning", 0.95), ("single", 0.3)])
def test_now_line_and_bar_ends_are_the_exact_world_lines_at_each_instant(name, v):
    h = history(name, v)
    frames = paper_frames(v)
    count = 9
    s, _ = scene(h, frames, count)
    for k in (0, 3, 4, 8):
        s.update(k)
        for motion in s.panels:
            t = instant(h, motion.frame, k, count)
            eta = motion.frame.rapidity
            assert motion.now.get_ydata()[0] == pytest.approx(t, abs=AGREE * (1 + abs(t)))
            left = h.worldline("rod_left").seen_from(eta).event_at_time(t).x
            right = h.worldline("rod_right").seen_from(eta).event_at_time(t).x
            a, b = bar_ends(motion.strip)
            assert (a, b) == (pytest.approx(left, abs=AGREE * (1 + abs(t))), pytest.approx(right, abs=AGREE * (1 + abs(t))))
            for pname, x in zip([n for n in ("A", "B") if h.worldline(n) is not None], motion.strip.dots.get_xdata()):
                assert x == pytest.approx(h.worldline(pname).seen_from(eta).event_at_time(t).x, abs=AGREE * (1 + abs(t)))
            if motion.lens is not None:  # the lens: the same rod, measured from the midpoint of its ends
                a, b = bar_ends(motion.lens)
                assert a == pytest.approx((left - right) / 2, abs=AGREE * (1 + abs(t)))
                assert b == pytest.approx((right - left) / 2, abs=AGREE * (1 + abs(t)))


def test_single_in_S_the_drawn_bar_follows_the_hand_formula_of_the_rigid_turn():
    """`single` at v = 0.6 in S: B strikes the right end P = (L/2, L/2v) of the rod at rest; the left end
    (d = L from P) then moves on x = x_P - sqrt(L^2 + (t - t_P)^2) until its speed is v, at t - t_P = g v L;
    the right end moves off at -v at once (README, rule 3)."""
    v, L = 0.6, 1.0
    g = 1 / math.sqrt(1 - v * v)
    h = history("single", v)
    count = 11
    s, _ = scene(h, (Frame("rest", 0.0),), count)
    t_p = L / (2 * v)
    for k in range(count):
        s.update(k)
        t = instant(h, Frame("rest", 0.0), k, count)
        a = t - t_p
        left = -L / 2 if a <= 0 else L / 2 - math.sqrt(L * L + a * a) if a <= g * v * L else \
            L / 2 - g * L - v * (a - g * v * L)
        right = L / 2 if a <= 0 else L / 2 - v * a
        assert bar_ends(s.panels[0].strip) == (pytest.approx(left, abs=1e-12), pytest.approx(right, abs=1e-12))


@pytest.mark.parametrize("style", ["default", "print"])
def test_the_bar_colours_are_the_material_points_velocities_through_the_colour_scale(style):
    v = 0.6
    h = history("fig2", v)
    frames = paper_frames(v)
    count = 7
    s, _ = scene(h, frames, count, style)
    for k in (2, 3, 5):
        s.update(k)
        for motion in s.panels:
            t = instant(h, motion.frame, k, count)
            bar = motion.strip.bar
            # neighbours of one colour are merged into one segment (no seams): the segments' ends are material
            # points, and each is coloured by the velocity at its first piece's middle
            starts = [seg[0][0] for seg in bar.get_segments()]
            eta = motion.frame.rapidity
            grid = np.linspace(0.0, h.scenario.L, 96)  # the strip's material points (snapshot.STRIP_POINTS)
            xs = [material_worldline(h, float(sg)).seen_from(eta).event_at_time(t).x for sg in grid]
            velocity = [math.tanh(material_worldline(h, float(sg)).seen_from(eta).rapidity_at_time(t)) for sg in grid]
            mids = 0.5 * (np.array(velocity[1:]) + np.array(velocity[:-1]))
            want = [mids[int(np.argmin(np.abs(np.array(xs[:-1]) - x)))] for x in starts]
            assert np.allclose(bar.get_array(), want, atol=1e-12)
            assert starts[0] == pytest.approx(xs[0], abs=1e-12) and bar.get_segments()[-1][1][0] == pytest.approx(xs[-1])
            scale = colour_scale(h, motion.frame)
            # centred on the frame's rod velocity before any impact (S: 0, S': +v), wide enough for every velocity
            assert scale.centre == pytest.approx(-motion.frame.velocity, abs=0)
            lo, hi = scale.ends if style == "print" else scale.limits
            assert (bar.norm.vmin, bar.norm.vmax) == (lo, hi)
            rgba = bar.to_rgba(bar.get_array())
            # even in rapidity: atanh maps the ends to 0 and 1
            a, b = math.atanh(lo), math.atanh(hi)
            assert np.allclose(rgba, colour_map(style)((np.arctanh(want) - a) / (b - a)))


def test_the_now_line_and_the_bar_colour_are_where_they_should_be_in_the_pixels():
    """End to end: in the RGB image, the now-line's red row is where panel (a)'s transform puts t, and the
    pixel in the middle of the bar is the colour of the velocity of the material point there."""
    v = 0.6
    h = history("fig2", v)
    frames = paper_frames(v)
    count = 5
    line = timeline(h, frames, "now", count)
    with render.style_context("default"):
        s = NowScene(h, line, "default")
        s.canvas.draw()
        images = list(images_of(h, frames, "now", "default", line))
        height = images[0].shape[0]
        for k in (1, 3):
            s.update(k)
            motion = s.panels[0]
            t = instant(h, frames[0], k, count)
            ax = motion.now.axes
            x_mid = 0.5 * sum(ax.get_xlim())
            row = height - ax.transData.transform((x_mid, t))[1]
            column = int(ax.transData.transform((x_mid, t))[0])
            red = np.all(np.abs(images[k][:, column].astype(int) - [0xCC, 0x00, 0x33]) <= 6, axis=1)
            assert abs(np.flatnonzero(red).mean() - row) <= 1.0
            # the bar's middle pixel: the material point half-way along the rod
            strip_ax = motion.strip.bar.axes
            a, b = bar_ends(motion.strip)
            px, py = strip_ax.transData.transform((0.5 * (a + b), 0.0))
            pixel = images[k][int(height - py), int(px)].astype(int)
            middle = material_worldline(h, h.scenario.L / 2).seen_from(frames[0].rapidity)
            velocity = math.tanh(middle.rapidity_at_time(t))
            want = np.array(motion.strip.bar.cmap(motion.strip.bar.norm(velocity))[:3]) * 255
            assert np.abs(pixel - want).max() <= 10, (pixel, want)


def test_a_small_rod_gets_a_lens_with_a_round_magnification_and_a_large_one_none():
    h = history("fig2", 0.95)
    s, line = scene(h, paper_frames(0.95), 9)
    for p, motion in enumerate(s.panels):
        ax = motion.now.axes
        span = ax.get_xlim()[1] - ax.get_xlim()[0]
        longest = max(float(np.ptp(line.strip(h, k, p).x)) for k in range(9))
        if longest < LENS_BELOW * span:
            assert motion.lens is not None and motion.magnification > 1
            mantissa = motion.magnification / 10 ** math.floor(math.log10(motion.magnification))
            assert round(mantissa, 9) in (1, 2, 2.5, 5)
            lo, hi = motion.lens.bar.axes.get_xlim()
            if motion.lens_title is None:  # one magnification holds the rod at every instant
                assert hi - lo == pytest.approx(span / motion.magnification)
                assert longest <= hi - lo  # the rod fits in the lens at every instant
            else:  # the lens follows the rod's length (tests/render/test_legibility.py), in units of its half-width
                assert (lo, hi) == (-1.0, 1.0)
    assert s.panels[1].lens is not None  # S' at v = 0.95: the rod is L/g = 0.31 L on a panel about 30 L wide
    big = history("fig2", 0.3)
    s, _ = scene(big, (Frame("rest", 0.0),), 5)
    assert s.panels[0].lens is None  # S at v = 0.3: the rod is a third of its panel


def test_the_print_colour_map_reads_in_grey_its_lightness_runs_one_way():
    """Black-and-white print: the lightness (CIE L*) of the bar's colours falls steadily from the slowest to the
    fastest, over a wide range, so a grey shade names one velocity."""
    colours = colour_map("print")(np.linspace(0, 1, 64))[:, :3]
    assert np.allclose(colours[:, 0], colours[:, 1]) and np.allclose(colours[:, 1], colours[:, 2])  # grey only
    linear = np.where(colours <= 0.04045, colours / 12.92, ((colours + 0.055) / 1.055) ** 2.4)
    y = linear @ [0.2126, 0.7152, 0.0722]
    lightness = 116 * np.cbrt(y) - 16
    assert np.all(np.diff(lightness) < 0)
    assert lightness[0] - lightness[-1] > 60 and PRINT_RAMP[0] > 0  # never white: the page is white


def test_boost_images_show_the_axes_of_S_and_S_prime_at_the_frame_velocity():
    """In the frame of velocity u, S's t axis (x = 0 of S) has slope dx/dt = -u and S''s (velocity -v) the
    relative velocity (-v - u)/(1 + v u) (velocity addition): read from the pixels' colours is too loose, so the drawn lines'
    direction is checked, at the first, middle and last image."""
    import rodparadox.animate.boost_scene as drawing

    v = 0.6
    h = history("fig2", v)
    start, end = Frame("rest", 0.0), Frame("moving", -v)
    line = timeline(h, (start, end), "boost", 5)
    captured = []
    original = drawing._inside_end
    drawing._inside_end = lambda dx, dt, box: captured.append((dx, dt)) or original(dx, dt, box)
    try:
        images = list(images_of(h, (start, end), "boost", "default", line))
    finally:
        drawing._inside_end = original
    assert len(images) == 5 and len({i.shape for i in images}) == 1
    for k, frame in enumerate(line.frames):
        u = frame.velocity
        rest_x, rest_t, moving_x, moving_t = captured[4 * k:4 * k + 4]
        for (dx, dt), w in ((rest_t, -u), (moving_t, (-v - u) / (1 + v * u))):
            assert dx / dt == pytest.approx(w, abs=1e-12)
        assert rest_x[1] / rest_x[0] == pytest.approx(-u, abs=1e-12)


def test_boost_draws_plots_layers_on_the_exact_world_lines_of_each_instant():
    """Boost mode's world-sheet, world-lines and impact markers are `plot`'s layers (their gids), drawn anew at each
    instant (the last instant's taken away), on the exact world-lines boosted into the frame of the instant."""
    from rodparadox.animate.boost_scene import BoostScene

    v = 0.6
    h = history("fig2", v)
    line = timeline(h, (Frame("rest", 0.0), Frame("moving", -v)), "boost", 5)
    L = h.scenario.L
    with render.style_context("default"):
        s = BoostScene(h, line, "default")
        for k in (0, 2, 4):
            drawn = {a.get_gid(): a for a in s.update(k) if a.get_gid()}
            want = {"boost-sheet", "boost-A", "boost-B", "boost-rod_left", "boost-rod_right",
                    *(f"boost-impact-{i.label}" for i in h.impacts)}
            assert want <= set(drawn)
            in_axes = [a.get_gid() for a in (*s.ax.lines, *s.ax.patches, *s.ax.artists) if a.get_gid()]
            assert sorted(in_axes) == sorted(set(in_axes))  # one of each: the last instant's were taken away
            eta = line.frames[k].rapidity
            for name in ("A", "rod_left", "rod_right"):
                xs, ts = drawn[f"boost-{name}"].get_data()
                exact = h.worldline(name).seen_from(eta)
                for x, t in list(zip(xs, ts))[::7]:
                    assert x == pytest.approx(exact.event_at_time(t * L).x / L, abs=AGREE * (1 + abs(x)))
            for i in h.impacts:
                e = i.event.seen_from(eta)
                xs, ts = drawn[f"boost-impact-{i.label}"].get_data()
                assert (xs[0], ts[0]) == pytest.approx((e.x / L, e.t / L), abs=AGREE)
