"""A history seen from one frame (`rodparadox.frames`): the time window every panel and export covers.

Expected values come from the engine's raw world-line segments and impacts,
boosted here with x' = g(x - u t), t' = g(t - u x) written out, never from
`time_window` itself.
"""

from __future__ import annotations

import math
from functools import lru_cache

import pytest

from rodparadox.engine import run
from rodparadox.errors import ScenarioError
from rodparadox.frames import Frame, view
from rodparadox.kinematics import Line
from rodparadox.scenario import builtin_names, load

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
@pytest.mark.parametrize("name", builtin_names())
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
@pytest.mark.parametrize("name", builtin_names())
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
