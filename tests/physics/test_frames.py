"""A history seen from one frame (`rodparadox.physics.frames`): the time window every panel and export covers.

Expected values come from the engine's raw world-line segments and impacts,
boosted here with x' = g(x - u t), t' = g(t - u x) written out, never from
`time_window` itself.
"""

from __future__ import annotations

import math
from functools import lru_cache

import pytest
from hypothesis import given
from hypothesis import strategies as st

from rodparadox.physics.rigid import run
from rodparadox.errors import FrameError, ScenarioError
from rodparadox.physics.frames import check_velocity, FASTEST_FRAME, Frame, frame_heading, MAX_PANELS, moving_frame, named_frame, parse_frames, rest_frame, view
from rodparadox.physics.model import FASTEST, frame_velocity, Timing
from rodparadox.physics.kinematics import Line
from rodparadox.io.scenario import load

from helpers import particle_presets

SPEEDS = (0.3, 0.6, 0.9, 0.95, 0.99)
#: the frames of the checks: S, S', and frames on either side of both, up to u = 0.9
FRAME_VELOCITIES = ("rest", "moving", 0.3, -0.5, 0.9)
#: the least lead the window keeps before the first change and after the last, in units of L
LEAD = 0.5


@lru_cache(maxsize=None)
def history(name: str, v: float):
    return run(load(name).with_overrides(v=v))


def frame_of(spec, v: float) -> Frame:
    return {"rest": Frame("rest", 0.0), "moving": Frame("moving", -v)}.get(spec) or Frame(f"u={spec}", spec)


def time_in(x: float, t: float, u: float) -> float:
    return (t - u * x) / math.sqrt(1.0 - u * u)


def changes(h, u: float) -> list[float]:
    """Every impact and every segment's start and end of every world-line, in the time of the frame of velocity u."""
    times = [time_in(i.event.x, i.event.t, u) for i in h.impacts]
    for _, worldline in h.worldlines:
        for segment in worldline.segments:
            times += [time_in(e.x, e.t, u) for e in (segment.start, segment.end)]
    return times


@pytest.mark.parametrize("spec", FRAME_VELOCITIES)
@pytest.mark.parametrize("v", SPEEDS)
@pytest.mark.parametrize("name", particle_presets())
def test_the_time_window_holds_every_change_of_every_worldline_with_a_lead(name, v, spec):
    """Issue 6.1: `single` at v = 0.95 stopped in the middle of the far end's turn (t = 1.05 of 3.57)."""
    try:
        h = history(name, v)
    except ScenarioError:
        pytest.skip(f"{name} is refused at v = {v}")
    frame = frame_of(spec, v)
    t_lo, t_hi = view(h, frame).t_range
    times = changes(h, frame.velocity)
    L = h.scenario.L
    scale = 1e-12 * (abs(t_lo) + abs(t_hi) + L)
    assert t_lo <= min(times) - LEAD * L + scale
    assert max(times) + LEAD * L - scale <= t_hi


@pytest.mark.parametrize("spec", FRAME_VELOCITIES)
@pytest.mark.parametrize("v", (0.6, 0.95, 0.99))
@pytest.mark.parametrize("name", particle_presets())
def test_every_worldline_is_shown_from_its_first_state_to_its_last(name, v, spec):
    """Each world-line's view starts and ends with a straight piece at its velocity before anything and after everything.

    So a panel titled "rod first at rest, finally at -0.95" shows the rod at rest, then at -0.95.
    """
    try:
        h = history(name, v)
    except ScenarioError:
        pytest.skip(f"{name} is refused at v = {v}")
    frame = frame_of(spec, v)
    fv = view(h, frame)
    for name_, pieces in fv.segments:
        worldline = h.worldline(name_)
        first, last = pieces[0], pieces[-1]
        assert isinstance(first, Line) and isinstance(last, Line), name_
        before = math.tanh(worldline.rapidity_before - frame.rapidity)
        after = math.tanh(worldline.rapidity_after - frame.rapidity)
        for piece, velocity in ((first, before), (last, after)):
            slope = (piece.end.x - piece.start.x) / (piece.end.t - piece.start.t)
            assert slope == pytest.approx(velocity, abs=1e-9), name_
            assert piece.end.t - piece.start.t >= 0.9 * LEAD * h.scenario.L, name_


# --- parse_frames: the panels a --frame list asks for ------------------------------------------------

@pytest.mark.parametrize("spec, v, expected", [
    ("both", 0.6, (("rest", 0.0), ("moving", -0.6))),
    ("rest,moving", 0.6, (("rest", 0.0), ("moving", -0.6))),
    ("0,rest", 0.6, (("rest", 0.0),)),  # issue 6.5: one frame, by its name
    ("rest,0", 0.6, (("rest", 0.0),)),
    ("-0.6,moving", 0.6, (("moving", -0.6),)),
    ("0.3,-0.8,0,both", 0.8, (("u=0.3", 0.3), ("moving", -0.8), ("rest", 0.0))),
    ("-0", 0.6, (("u=0", 0.0),)),  # a number alone keeps its number
    ("0.9999999", 0.6, (("u=0.9999999", 0.9999999),)),  # the fastest frame
    (" 0.30 , 0.3 ", 0.6, (("u=0.3", 0.3),)),
])
def test_each_frame_once_by_velocity_and_a_name_wins_over_a_number(spec, v, expected):
    assert parse_frames(spec, v) == tuple(Frame(name, u) for name, u in expected)


@pytest.mark.parametrize("spec", ["sideways", "rest,", "", "0.3,fast"])
def test_a_frame_that_is_no_frame_is_refused_with_a_frame_error(spec):
    with pytest.raises(FrameError, match=r"a frame must be rest, moving, both or a velocity U"):
        parse_frames(spec, 0.6)


@pytest.mark.parametrize("spec", ["0.9999999999999999", "-0.99999995", "rest,0.99999999", "1", "-1", "nan", "inf",
                                  "0.1,1.5"])
def test_a_frame_too_fast_for_double_precision_is_refused(spec):
    with pytest.raises(FrameError, match=r"a frame velocity must be a number U with -0.9999999 <= U <= 0.9999999"):
        parse_frames(spec, 0.6)


def test_more_frames_than_panels_are_refused():
    nine = ",".join(str(k / 10) for k in range(1, 10))
    with pytest.raises(FrameError, match=f"9 different frames asked for; at most {MAX_PANELS} panels"):
        parse_frames(nine, 0.6)
    # repeats and a velocity that is S' count once: eight panels
    assert len(parse_frames("0.1,0.2,0.3,0.4,0.5,0.6,both,0.6,-0.95", 0.95)) == 8


@given(items=st.lists(st.one_of(st.sampled_from(["rest", "moving", "both"]),
                                st.sampled_from([0.0, -0.0, 0.3, -0.6, 0.6, -0.5]).map(repr)), min_size=1, max_size=12))
def test_every_velocity_asked_for_is_one_panel(items):
    v = 0.6
    frames = parse_frames(",".join(items), v)
    velocities = [f.velocity for f in frames]
    assert len(set(velocities)) == len(velocities)
    asked = set()
    for item in items:
        named = {"rest": {0.0}, "moving": {-v}, "both": {0.0, -v}}
        asked |= named[item] if item in named else {float(item)}
    assert set(velocities) == asked
    names = {0.0: ("rest", "both"), -v: ("moving", "both")}
    for f in frames:  # by its name wherever a name asked for its velocity, else by its number
        if any(item in names.get(f.velocity, ()) for item in items):
            assert f.name == {0.0: "rest", -v: "moving"}[f.velocity]
        else:
            assert f.name.startswith("u=") and float(f.name[2:]) == f.velocity


# --- the frame conventions, written once -----------------------------------------------------------------------

@pytest.mark.parametrize("v", [1e-6, 0.6, 0.9999999])
def test_S_prime_moves_at_minus_v_relative_to_S_wherever_a_frame_is_named(v):
    """`model.frame_velocity` is the one place S' = -v is written: every way of naming a frame agrees with it."""
    assert frame_velocity("rest", v) == 0.0 and frame_velocity("moving", v) == -v and frame_velocity(0.25, v) == 0.25
    assert named_frame("rest", v) == rest_frame() == Frame("rest", 0.0)
    assert named_frame("moving", v) == moving_frame(v) == Frame("moving", -v)
    assert parse_frames("both", v) == (Frame("rest", 0.0), Frame("moving", -v))
    assert moving_frame(v).rod_velocity() == v  # the rod first moves at +v in S'
    with pytest.raises(ValueError, match="a named frame is one of rest, moving"):
        named_frame("both", v)


def test_a_frame_shown_is_bounded_by_the_fastest_v_and_any_frame_by_c():
    """Every frame velocity a user gives, a frame to see or a scenario's timing frame, is bounded by FASTEST_FRAME
    (double precision places its events and writes its velocities below c); a Lorentz frame as such only by c."""
    assert FASTEST_FRAME == FASTEST
    assert check_velocity(-FASTEST_FRAME) == -FASTEST_FRAME
    assert Timing("B", -FASTEST_FRAME).frame == -FASTEST_FRAME
    with pytest.raises(FrameError):
        check_velocity(0.99999995)
    with pytest.raises(ScenarioError, match=r"^timed_with\.frame must be rest, moving or a velocity u with -0\.9999999 "
                                            r"<= u <= 0\.9999999, got 0\.99999995\.$"):
        Timing("B", 0.99999995)
    assert Frame("u=0.99999995", 0.99999995).velocity == 0.99999995
    for u in (1.0, -1.0):
        with pytest.raises(FrameError, match="-1 < u < 1"):
            Frame("u", u)
        with pytest.raises(ScenarioError, match="-0.9999999 <= u <= 0.9999999"):
            Timing("B", u)


def test_a_frame_heads_a_text_table_with_its_name_and_what_it_is():
    assert frame_heading(rest_frame()) == "frame rest (S, the rod's rest frame)"
    assert frame_heading(moving_frame(0.6)) == "frame moving (S', where the rod first moves at +v)"
    assert frame_heading(Frame("u=0.3", 0.3)) == "frame u=0.3"

