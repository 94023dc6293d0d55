"""A history seen from one frame: events, velocities and world-lines in that frame's coordinates. Pure.

Shared by `export` (numbers) and `render` (pictures), so both show the same
events, over the same time window, sampled the same way.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .engine import WORLDLINE_NAMES, History, Impact
from .errors import FrameError
from .kinematics import SAMPLING_TOLERANCE, Event, Segment
from .numbers import exact

#: panels in one figure, lettered (a) to (h): the most frames one figure shows
MAX_PANELS = 8


@dataclass(frozen=True)
class Frame:
    """An inertial frame by its velocity relative to S: `rest` is S, `moving` is S' (velocity -v)."""

    name: str
    velocity: float

    def __post_init__(self) -> None:
        if not (math.isfinite(self.velocity) and -1.0 < self.velocity < 1.0):
            raise FrameError(f"frame velocity must be a number u with -1 < u < 1 (units of c), got {self.velocity!r}.")

    @property
    def rapidity(self) -> float:
        return math.atanh(self.velocity)

    def rod_velocity(self) -> float:
        """The rod's velocity in this frame before any impact."""
        return -self.velocity


def paper_frames(v: float, extra_velocity: float | None = None) -> tuple[Frame, ...]:
    """S and S', and optionally one more frame of the given velocity relative to S."""
    frames = [Frame("rest", 0.0), Frame("moving", -v)]
    if extra_velocity is not None:
        frames.append(Frame(f"u={extra_velocity:g}", extra_velocity))
    return tuple(frames)


def parse_frames(spec: str, v: float) -> tuple[Frame, ...]:
    """Frames from `rest`, `moving`, `both` or a velocity U relative to S, or a comma-separated list of these.

    In the order given, each frame once: frames are told apart by their velocity,
    where a frame first appears, and a named frame wins over the same velocity
    given as a number (`0,rest` is S, once; `-0.6,moving` at v = 0.6 is S'); a
    velocity alone keeps its number (`0` is `u=0`). `both` is `rest,moving`.
    At most MAX_PANELS frames.
    """
    frames: list[Frame] = []
    for item in (part.strip() for part in spec.split(",")):
        named = {"rest": ("rest",), "moving": ("moving",), "both": ("rest", "moving")}.get(item)
        if named is not None:
            asked = [Frame(name, 0.0 if name == "rest" else -v) for name in named]
        else:
            try:
                u = float(item) + 0.0  # -0 is 0
            except ValueError:
                u = math.nan
            if not (math.isfinite(u) and -1.0 < u < 1.0):
                raise FrameError(f"a frame must be rest, moving, both or a velocity U with -1 < U < 1 "
                                 f"(or a comma-separated list of these), got {item!r}.")
            asked = [Frame(f"u={exact(u)}", u)]
        for frame in asked:
            same = next((k for k, f in enumerate(frames) if f.velocity == frame.velocity), None)
            if same is None:
                frames.append(frame)
            elif named is not None and frames[same].name.startswith("u="):
                frames[same] = frame  # the name says more than the number: S, not u = 0
    if len(frames) > MAX_PANELS:
        raise FrameError(f"{len(frames)} different frames asked for; at most {MAX_PANELS} panels fit in one figure.")
    return tuple(frames)


@dataclass(frozen=True)
class EventView:
    """An impact in one frame: where, when, and the velocities just before and after."""

    impact: Impact
    x: float
    t: float
    particle_velocity_before: float
    particle_velocity_after: float
    rod_velocity_before: float
    rod_velocity_after: float


@dataclass(frozen=True)
class FrameView:
    frame: Frame
    events: tuple[EventView, ...]
    t_range: tuple[float, float]
    segments: tuple[tuple[str, tuple[Segment, ...]], ...]  # exact pieces within t_range, per world-line

    def worldline_points(self, tolerance: float) -> dict[str, np.ndarray]:
        """Each world-line as an (n, 2) array of [x, t], every kink included, arcs within `tolerance`."""
        out = {}
        for name, pieces in self.segments:
            parts = [p.sample(tolerance) for p in pieces]
            out[name] = np.concatenate([parts[0]] + [p[1:] for p in parts[1:]]) if parts else np.empty((0, 2))
        return out


def time_window(history: History, frame: Frame) -> tuple[float, float]:
    """The frame's times to show: every body's whole history that changes, with a lead before and after.

    The changes are every impact and the start and end of every exact segment
    of every world-line (a kink, a turn's hyperbola, a particle between two
    impacts), read in this frame's time: in a frame where the rod moves, the far
    end can start its turn before the impact that causes it, and a turn can end
    long after the last impact. The window runs from the first change to the
    last, widened at both ends by a lead: the time from the scenario's start
    (the particles and the rod's ends at t = 0 in S) to the first change,
    clamped to between L/2 and 2L, so the bodies are seen moving freely before
    anything happens and after everything has settled.
    """
    eta, L = frame.rapidity, history.scenario.L
    changes = [i.event.boosted(eta).t for i in history.impacts]
    for name in WORLDLINE_NAMES:
        worldline = history.worldline(name)
        if worldline is not None:
            changes += [t for s in worldline.boosted(eta).segments for t in (s.start.t, s.end.t)]
    first, last = min(changes), max(changes)
    at_start = [e.boosted(eta).t for _, e in history.starts]
    at_start += [Event(sign * L / 2, 0.0).boosted(eta).t for sign in (-1, 1)]
    lead = min(max(first - min(at_start), 0.5 * L), 2.0 * L)
    return first - lead, last + lead


def view(history: History, frame: Frame) -> FrameView:
    eta = frame.rapidity
    t_lo, t_hi = time_window(history, frame)
    events = []
    for i in history.impacts:
        e = i.event.boosted(eta)
        events.append(EventView(i, e.x, e.t, math.tanh(i.particle_rapidity_before - eta),
                                math.tanh(i.particle_rapidity_after - eta), math.tanh(i.rod_rapidity_before - eta),
                                math.tanh(i.rod_rapidity_after - eta)))
    segments = tuple((name, history.worldline(name).boosted(eta).pieces(t_lo, t_hi))
                     for name in WORLDLINE_NAMES if history.worldline(name) is not None)
    return FrameView(frame, tuple(events), (t_lo, t_hi), segments)


def sampling_tolerance(history: History) -> float:
    return SAMPLING_TOLERANCE * history.scenario.L
