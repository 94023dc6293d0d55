"""The animation's timeline: each panel's "now", the strip under it (bar ends, colours, particles, flashes), the
colour scale, the boost, and the checks of --fps and --seconds. Values are checked against hand formulas and
against the exact world-lines, never against the timeline's own output."""

import math

import numpy as np
import pytest

from rodparadox.animate.timeline import (FLASH_FRACTION, MAX_IMAGES, boost_ends, boost_timeline, boost_velocities,
                                         image_count, now_timeline, now_times)
from rodparadox.physics.rigid import run
from rodparadox.errors import OptionError
from rodparadox.physics.frames import Frame, paper_frames, time_window
from rodparadox.physics.kinematics import Event
from rodparadox.physics.rigid.turns import material_worldline
from rodparadox.physics.snapshot import strip_at
from rodparadox.io.scenario import load
from rodparadox.render.colour_scale import colour_scale

#: a position or time computed two ways (engine world-line, material world-line, hand formula) agrees to
#: this, in units of L: a few hundred ulps of the coordinates involved (up to about 10 L)
AGREE = 1e-12


def history(name="fig2", v=None):
    return run(load(name).with_overrides(v=v, L=None))


def frames_at(v):
    return (Frame("rest", 0.0), Frame("moving", -v), Frame("u=0.3", 0.3))


def boost(event: Event, u: float) -> Event:
    """The event in the frame of velocity u relative to S, by hand: x' = g(x - u t), t' = g(t - u x)."""
    g = 1 / math.sqrt(1 - u * u)
    return Event(g * (event.x - u * event.t), g * (event.t - u * event.x))


@pytest.mark.parametrize("name", ["fig1", "fig2", "single", "while_turning"])
@pytest.mark.parametrize("v", [0.3, 0.6, 0.95])
def test_the_bar_runs_from_the_left_end_to_the_right_end_of_the_rod(name, v):
    h = history(name, v)
    for frame in frames_at(v):
        eta = frame.rapidity
        t_lo, t_hi = time_window(h, frame)
        for t in np.linspace(t_lo, t_hi, 9):
            strip = strip_at(h, frame, float(t), flash=0.0, points=17)
            left = h.worldline("rod_left").seen_from(eta).event_at_time(t).x
            right = h.worldline("rod_right").seen_from(eta).event_at_time(t).x
            scale = 1 + abs(t) + abs(left)
            assert strip.x[0] == pytest.approx(left, abs=AGREE * scale)
            assert strip.x[-1] == pytest.approx(right, abs=AGREE * scale)
            assert np.all(np.diff(strip.x) > 0)  # material points keep their order along the rod
            for pname, x in strip.particles:
                assert x == pytest.approx(h.worldline(pname).seen_from(eta).event_at_time(t).x, abs=AGREE * scale)


@pytest.mark.parametrize("v", [0.3, 0.6, 0.95])
def test_the_bar_velocities_are_the_material_points_velocities(v):
    h = history("fig2", v)
    for frame in frames_at(v):
        t_lo, t_hi = time_window(h, frame)
        for t in np.linspace(t_lo, t_hi, 7):
            strip = strip_at(h, frame, float(t), flash=0.0, points=9)
            for sigma, x, velocity in zip(strip.sigma, strip.x, strip.velocity):
                w = material_worldline(h, float(sigma)).seen_from(frame.rapidity)
                assert velocity == pytest.approx(math.tanh(w.rapidity_at_time(t)), abs=1e-12)
                assert x == pytest.approx(w.event_at_time(t).x, abs=AGREE * (1 + abs(t)))


def test_single_in_S_the_bar_follows_the_hand_formula_of_the_rigid_turn():
    """`single`: B strikes the right end P = (L/2, L/2v) at rest; the point at distance d from P moves on
    x = x_P - sqrt(d^2 + (t - t_P)^2) with velocity -(t - t_P)/sqrt(d^2 + (t - t_P)^2) until its velocity is
    -v (at t - t_P = g v d), then straight on at -v; before t_P everything rests (README, rule 3)."""
    v, L = 0.6, 1.0
    h = history("single", v)
    g = 1 / math.sqrt(1 - v * v)
    x_p, t_p = L / 2, L / (2 * v)
    for t in (0.2, t_p, t_p + 0.1, t_p + 0.4, t_p + 0.75, t_p + 2.0):
        strip = strip_at(h, Frame("rest", 0.0), t, flash=0.0, points=11)
        for sigma, x, velocity in zip(strip.sigma, strip.x, strip.velocity):
            d, a = L - sigma, t - t_p
            if a <= 0:
                want_x, want_v = sigma - L / 2, 0.0
            elif a <= g * v * d:
                want_x, want_v = x_p - math.sqrt(d * d + a * a), -a / math.sqrt(d * d + a * a)
            else:
                want_x, want_v = x_p - g * d - v * (a - g * v * d), -v
            assert x == pytest.approx(want_x, abs=1e-12) and velocity == pytest.approx(want_v, abs=1e-12)


def test_an_impact_flashes_near_its_instant_only_and_every_impact_flashes():
    v, count = 0.6, 40
    h = history("fig2", v)
    frames = frames_at(v)
    line = now_timeline(h, frames, count)
    for p, frame in enumerate(frames):
        t_lo, t_hi = line.windows[p]
        flash = max(FLASH_FRACTION * (t_hi - t_lo), 0.5 * (t_hi - t_lo) / (count - 1))
        assert line.flash[p] == pytest.approx(flash)
        seen = set()
        for k in range(count):
            strip = line.strip(h, k, p)
            want = {i.label for i in h.impacts if abs(boost(i.event, frame.velocity).t - strip.t) <= flash}
            assert set(strip.flashing) == want
            seen |= want
        assert seen == {"B1", "A1", "B2"}


def test_panels_sweep_their_own_window_in_lock_step():
    h = history("fig2", 0.6)
    frames = frames_at(0.6)
    times = now_times(h, frames, 11)
    assert times.shape == (11, 3)
    for p, frame in enumerate(frames):
        t_lo, t_hi = time_window(h, frame)
        assert times[0, p] == t_lo and times[-1, p] == t_hi
        # the same fraction of its window in every panel at every instant
        assert np.allclose((times[:, p] - t_lo) / (t_hi - t_lo), np.linspace(0, 1, 11), atol=1e-14)


@pytest.mark.parametrize("name", ["fig2", "while_turning"])
def test_the_rod_centre_proper_time_would_also_be_monotonic_in_every_frame(name):
    """The claim in `now_times`' docstring: the centre's events come in the same order in every frame."""
    h = history(name, 0.9)
    centre = material_worldline(h, h.scenario.L / 2)
    events = [centre.event_at_time(t) for t in np.linspace(-1, 8, 400)]
    for u in (-0.99, -0.9, -0.3, 0.0, 0.5, 0.99):
        times = [boost(e, u).t for e in events]
        assert all(b > a for a, b in zip(times, times[1:]))


@pytest.mark.parametrize("v", [0.3, 0.6, 0.95])
def test_the_colour_scale_is_centred_on_the_rod_and_holds_every_velocity(v):
    """fig2: in S the rod goes 0 -> -v -> +v -> 0, in S' +v -> 0 -> 2v/(1+v^2) -> +v (README, events)."""
    h = history("fig2", v)
    rest, moving = colour_scale(h, Frame("rest", 0.0)), colour_scale(h, Frame("moving", -v))
    # the bound is a rapidity (the colours are even in rapidity): S: atanh v; S': the larger of atanh v (0 from +v)
    # and atanh(2v/(1+v^2)) - atanh v = atanh v (rapidities add)
    assert (rest.centre, rest.bound) == (0.0, pytest.approx(math.atanh(v), abs=1e-12))
    assert moving.centre == v
    assert moving.bound == pytest.approx(math.atanh(v), abs=1e-12)
    assert moving.limits == (pytest.approx(0.0, abs=1e-12), pytest.approx(2 * v / (1 + v * v), abs=1e-12))
    frames = frames_at(v)
    line = now_timeline(h, frames, 25)
    for p in range(3):
        lo, hi = line.scales[p].limits
        assert line.scales[p].centre == pytest.approx(-frames[p].velocity, abs=0)
        for k in range(25):
            velocity = line.strip(h, k, p).velocity
            assert np.all(velocity >= lo - 1e-12) and np.all(velocity <= hi + 1e-12)


def test_a_rod_that_never_changes_velocity_gets_a_positive_scale():
    h = history("fig1", 0.6)  # equal and opposite impulses on one rod line: the rod keeps its velocity
    scale = colour_scale(h, Frame("rest", 0.0))
    assert scale.centre == 0.0 and scale.bound > 0


def test_boost_velocities_ease_in_rapidity_between_exact_ends():
    u = boost_velocities(0.0, -0.6, 9)
    assert u[0] == 0.0 and u[-1] == -0.6 and not math.copysign(1, u[0]) < 0
    eta = np.arctanh(u)
    b = math.atanh(-0.6)
    for k, s in enumerate(np.linspace(0, 1, 9)):
        assert eta[k] == pytest.approx(b * (1 - math.cos(math.pi * s)) / 2, abs=1e-12)
    assert np.all(np.diff(u) < 0)
    assert eta[4] == pytest.approx(b / 2)  # halfway in rapidity at halftime


def test_boost_timeline_holds_every_frame_window_and_keeps_the_end_names():
    h = history("fig2", 0.8)
    start, end = boost_ends("both", 0.8)
    line = boost_timeline(h, start, end, 12)
    assert len(line) == 12 and line.frames[0].name == "rest" and line.frames[-1].name == "moving"
    assert line.frames[-1].velocity == -0.8
    for frame in line.frames:
        t_lo, t_hi = time_window(h, frame)
        assert line.t_window[0] <= t_lo and t_hi <= line.t_window[1]
        for name in ("A", "B", "rod_left", "rod_right"):
            w = h.worldline(name).seen_from(frame.rapidity)
            for t in (t_lo, t_hi):
                assert line.x_window[0] - 1e-12 <= w.event_at_time(t).x <= line.x_window[1] + 1e-12


@pytest.mark.parametrize("spec, ends", [("rest..moving", (0.0, -0.6)), ("0.3..-0.9", (0.3, -0.9)),
                                        ("moving..rest", (-0.6, 0.0)), (" rest .. 0.5 ", (0.0, 0.5))])
def test_boost_ends_read_names_and_velocities(spec, ends):
    assert tuple(f.velocity for f in boost_ends(spec, 0.6)) == ends


@pytest.mark.parametrize("spec, message", [
    ("rest", "frame: in boost mode give the frames to boost between as A..B (each rest, moving or a "
             "velocity U relative to S), e.g. rest..moving, got 'rest'."),
    ("rest..rest", "frame: rest..rest boosts from a frame to itself; give two different frames."),
    ("rest..fast", "frame: each end of A..B must be rest, moving or a velocity U relative to S; not a "
                   "velocity: 'fast'."),
])
def test_boost_ends_refuse_in_one_sentence(spec, message):
    """The facts (which choice, what value) and the library's sentence; the command line's: test_animate_cli."""
    with pytest.raises(OptionError) as e:
        boost_ends(spec, 0.6)
    assert str(e.value) == message and (e.value.what, e.value.value) == ("frame", spec)


@pytest.mark.parametrize("seconds, fps, count", [(6, 25, 150), (2, 10, 20), (0.1, 20, 2), (120, 25, 3000),
                                                 (1.02, 50, 51)])
def test_image_count_is_seconds_times_fps(seconds, fps, count):
    assert image_count(seconds, fps) == count


@pytest.mark.parametrize("seconds, fps, what, message", [
    (6, 0, "fps", "fps must be a whole number of frames per second above 0, got 0."),
    (-1, 25, "seconds", "seconds must be a duration above 0 and at most 120 seconds, got -1."),
    (0, 25, "seconds", "seconds must be a duration above 0 and at most 120 seconds, got 0."),
    (121, 25, "seconds", "seconds must be a duration above 0 and at most 120 seconds, got 121."),
    (float("nan"), 25, "seconds", "seconds must be a duration above 0 and at most 120 seconds, got nan."),
    (0.01, 25, "seconds", "seconds 0.01 at fps 25 gives 0 frames; an animation needs at least 2."),
    (100, 50, "seconds", f"seconds 100 at fps 50 gives 5000 frames; at most {MAX_IMAGES} are drawn, so lower one "
                         f"of them."),
])
def test_image_count_refuses_in_one_sentence(seconds, fps, what, message):
    """The facts and the library's sentence; the command line's (`option --fps`): test_animate_cli."""
    with pytest.raises(OptionError) as e:
        image_count(seconds, fps)
    assert str(e.value) == message and e.value.what == what


@pytest.mark.parametrize("mode", ["now", "boost"])
def test_images_waiting_between_instants_leave_the_process_rcparams_alone(mode):
    """A generator of images applies its style only while it draws an image: one left waiting (`animate` refusing a
    long run after the first image) kept the style's rcParams (figure.dpi 72) on the whole process until collected,
    and a handout's LaTeX figures made meanwhile changed in their last digits."""
    import matplotlib

    from rodparadox.animate.scenes import images_of
    from rodparadox.animate.timeline import timeline as make_timeline

    h = run(load("fig2"))
    frames = paper_frames(0.6)
    before = dict(matplotlib.rcParams)
    drawn = images_of(h, frames, mode, "default", make_timeline(h, frames, mode, 2))
    assert next(drawn).ndim == 3
    assert dict(matplotlib.rcParams) == before
    drawn.close()
    assert dict(matplotlib.rcParams) == before


def test_now_images_show_the_diagram_with_a_moving_now_line_and_are_reproducible():
    """The drawing: every image the same size; the now-line's colour (#CC0033) appears on a row of pixels that climbs
    from image to image (t grows upward); two runs give identical pixels."""
    from rodparadox.animate.scenes import images_of
    from rodparadox.animate.timeline import timeline as make_timeline

    h = run(load("fig2"))
    frames = paper_frames(0.6)
    line = make_timeline(h, frames, "now", 4)
    first = list(images_of(h, frames, "now", "default", line))
    again = list(images_of(h, frames, "now", "default", line))
    assert len(first) == 4 and len({f.shape for f in first}) == 1
    assert all(np.array_equal(a, b) for a, b in zip(first, again))
    rows = []
    for image in first:
        red = np.all(np.abs(image.astype(int) - [0xCC, 0x00, 0x33]) <= 8, axis=2)
        counts = red.sum(axis=1)
        rows.append(int(np.argmax(counts)))  # the row where the now-line runs across a panel
        assert counts.max() > 0.2 * image.shape[1]
    assert rows == sorted(rows, reverse=True) and len(set(rows)) == 4  # image rows count down as t goes up
