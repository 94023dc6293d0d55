"""The timeline of an animation: what each panel shows at each instant (the docs, "The paradox
in motion"). Pure, no matplotlib.

Two modes:

* **now**: each panel is one frame; its line of simultaneity sweeps up its
  time window (`frames.time_window`, the same as `plot`'s) and a strip under
  it shows the frame's space at that instant (`physics.snapshot.strip_at`,
  coloured on `render.colour_scale`).
* **boost**: one panel whose frame runs smoothly from one velocity to another
  (`boost_velocities`), over one fixed window that holds every frame's.

The timeline runs over an animation's images: `image_count` of them, each one instant. (A "frame" here is
always a Lorentz frame.) The drawing reads a `NowTimeline` or `BoostTimeline` and nothing else.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from rodparadox.physics.history import RodHistory
from rodparadox.errors import OptionError
from rodparadox.physics.frames import Frame, sampling_tolerance, time_window, view
from rodparadox.numbers import exact
from rodparadox.physics.kinematics import WorldLine
from rodparadox.physics.snapshot import material_points, Strip, strip_at
from rodparadox.render.colour_scale import ColourScale, colour_scale

MODES = ("now", "boost")
#: the longest animation, and the most images one may have: enough for two minutes at 25 images per second
MAX_SECONDS = 120.0
MAX_IMAGES = 3000
#: the most pixels (images x width x height) drawn unless the caller allows a long animation: the default
#: animation of fig2 is 150 images of 1049 x 1101, 173 million; this bound, about 350 such images, takes under a
#: minute on a 2-core machine, where drawing costs about 0.1 s per million pixels
MAX_PIXELS = 400_000_000
#: an impact flashes while the panel's time is within this fraction of its window of the impact's time
#: (or half an image's step, if that is longer, so that every impact flashes in at least one image)
FLASH_FRACTION = 0.02


def image_count(seconds: float, fps: int) -> int:
    """round(seconds * fps) images, checked: 0 < seconds <= MAX_SECONDS, at least 2 and at most MAX_IMAGES."""
    if isinstance(fps, bool) or not isinstance(fps, int) or fps <= 0:
        raise OptionError("fps", fps, "a whole number of frames per second above 0")
    if not (isinstance(seconds, (int, float)) and math.isfinite(seconds) and 0 < seconds <= MAX_SECONDS):
        raise OptionError("seconds", seconds, f"a duration above 0 and at most {MAX_SECONDS:g} seconds")
    count = round(seconds * fps)
    if count < 2:
        raise OptionError("seconds", seconds, 2, "{seconds} {value:g} at {fps} {fps_value} gives {count} "
                          "frame{plural}; an animation needs at least {allowed}.", fps_value=fps, count=count,
                          plural="s" if count != 1 else "")
    if count > MAX_IMAGES:
        raise OptionError("seconds", seconds, MAX_IMAGES, "{seconds} {value:g} at {fps} {fps_value} gives {count} "
                          "frames; at most {allowed} are drawn, so lower one of them.", fps_value=fps, count=count)
    return count


def check_cost(count: int, width: int, height: int, seconds: float, fps: int, allow_long: bool = False) -> None:
    """Refuse `count` images of `width` x `height` pixels past MAX_PIXELS in all, unless `allow_long`: a long
    animation is asked for, not stumbled into (docs/animate.md, "Animating": Length)."""
    pixels = count * width * height
    if pixels > MAX_PIXELS and not allow_long:
        raise OptionError("seconds", seconds, MAX_PIXELS // 1_000_000, "{seconds} {value:g} at {fps} {fps_value} "
                          "gives {count} frames of {width} x {height} pixels, {millions:,} million pixels in all, more "
                          "than the {allowed} million drawn without asking (minutes of work); give {allow_long} to "
                          "draw them, or lower {seconds} or {fps}.", fps_value=fps, count=count, width=width,
                          height=height, millions=round(pixels / 1e6))


def sweep(count: int) -> np.ndarray:
    """The lock-step parameter s of each of `count` images: evenly from 0 (first image) to 1 (last)."""
    return np.linspace(0.0, 1.0, count)


# --- now mode --------------------------------------------------------------------------------------

def now_times(history: RodHistory, frames: tuple[Frame, ...], count: int) -> np.ndarray:
    """(count, len(frames)): the time each panel shows at each instant, in that panel's frame.

    The panels move in lock-step on one parameter s, running evenly from 0 to 1: each frame's own time,
    scaled to its window, t = t_lo + s (t_hi - t_lo). So every panel sweeps exactly the window `plot` draws,
    from before the first change to after the last, at an even pace of its own clock, and the readout of
    each panel's "now" advances steadily.

    Why not the rod's proper time at its centre? It is monotonic in every frame's time (the centre's
    world-line is time-like, so its events come in the same order in every frame: tested), so it would
    work as a parameter. But each frame's window maps to a different span of it (in S' the window starts
    and ends at other centre events than in S), so some panels would stand still at the ends, and along
    it a frame's time runs at dt/dtau = cosh(rapidity of the centre), which jumps at every turn: the
    now-line would speed up and slow down. The cost of the choice made: at one instant the panels' now
    lines need not cross the rod's centre at one event (they could not all do so at every point anyway).
    """
    s = sweep(count)
    out = np.empty((count, len(frames)))
    for k, frame in enumerate(frames):
        t_lo, t_hi = time_window(history, frame)
        out[:, k] = t_lo + s * (t_hi - t_lo)
        out[-1, k] = t_hi  # exactly the window's end, not its rounding
    return out


def flash_time(window: tuple[float, float], count: int) -> float:
    """How long before and after its instant an impact flashes: FLASH_FRACTION of the window, or half an image's
    step if longer, so that every impact flashes in at least one image."""
    span = window[1] - window[0]
    return max(FLASH_FRACTION * span, 0.5 * span / max(count - 1, 1))


@dataclass(frozen=True)
class NowTimeline:
    """Now mode: the panels' frames, windows, each instant's times (count, panels), flash times, colour scales."""

    frames: tuple[Frame, ...]
    windows: tuple[tuple[float, float], ...]
    times: np.ndarray
    flash: tuple[float, ...]
    scales: tuple[ColourScale, ...]
    #: each panel's `material_points`, built once
    material: tuple[tuple[WorldLine, ...], ...] = field(default=(), compare=False, repr=False)

    mode = "now"

    def __len__(self) -> int:
        return len(self.times)

    def strip(self, history: RodHistory, k: int, panel: int) -> Strip:
        return strip_at(history, self.frames[panel], float(self.times[k, panel]), self.flash[panel],
                        material=self.material[panel] if self.material else None)


def now_timeline(history: RodHistory, frames: tuple[Frame, ...], count: int) -> NowTimeline:
    times = now_times(history, frames, count)
    windows = tuple(time_window(history, f) for f in frames)
    return NowTimeline(tuple(frames), windows, times, tuple(flash_time(w, count) for w in windows),
                       tuple(colour_scale(history, f) for f in frames),
                       tuple(material_points(history, f) for f in frames))


# --- boost mode ------------------------------------------------------------------------------------

def boost_velocities(v_from: float, v_to: float, count: int) -> np.ndarray:
    """`count` frame velocities from v_from to v_to (both exactly), eased in and out.

    The ease is in rapidity, the quantity boosts add: eta = eta_from + (eta_to - eta_from)(1 - cos(pi s))/2,
    s from 0 to 1 evenly; so equal steps are equal boosts, the boost starts and stops gently, and near c the
    frames do not crowd together as they would evenly in velocity.
    """
    a, b = math.atanh(v_from), math.atanh(v_to)
    ease = (1.0 - np.cos(np.pi * sweep(count))) / 2.0
    out = np.tanh(a + (b - a) * ease)
    out[0], out[-1] = v_from, v_to
    return out + 0.0  # no -0


def boost_ends(spec: str, v: float) -> tuple[Frame, Frame]:
    """The frames of boost mode: `A..B`, each a name (rest, moving) or a velocity U relative to S; `both` is
    `rest..moving` (the default). The two ends must differ."""
    from rodparadox.errors import FrameError
    from rodparadox.physics.frames import frame_of_word

    spec = spec.strip()
    if spec == "both":
        spec = "rest..moving"
    parts = spec.split("..")
    if len(parts) != 2:
        raise OptionError("frame", spec, template="{what}: in boost mode give the frames to boost between as A..B "
                          "(each rest, moving or a velocity U relative to S), e.g. rest..moving, got {value!r}.")
    ends = []
    for part in (p.strip() for p in parts):
        try:
            end = frame_of_word(part, v)
            reason = None if end is not None else f"not a velocity: {part!r}"
        except FrameError as e:
            reason = str(e)
        if reason is not None:
            raise OptionError("frame", spec, template="{what}: each end of A..B must be rest, moving or a velocity "
                              "U relative to S; {reason}.", end=part, reason=reason.rstrip("."))
        ends.append(end)
    if ends[0].velocity == ends[1].velocity:
        raise OptionError("frame", spec, template="{what}: {value} boosts from a frame to itself; give two "
                          "different frames.")
    return ends[0], ends[1]


@dataclass(frozen=True)
class BoostTimeline:
    """Boost mode: the frame at each instant, and one time and x window holding every one of them."""

    frames: tuple[Frame, ...]
    t_window: tuple[float, float]
    x_window: tuple[float, float]

    mode = "boost"

    def __len__(self) -> int:
        return len(self.frames)


#: in boost mode the axes hold every frame's window: seen from a frame near c that is thousands of L, where the
#: causal rod rings thousands of times; its world-lines are sampled to this fraction of the window's extent where
#: that is coarser than the sampling tolerance (a window of at most 100 L: unchanged), so the points drawn, and
#: their cost, are bounded by the panel, not by the frame's speed
BOOST_SAMPLING = 1e-6
#: the longest time window (units of L) a boost of the causal rod may span: its world-sheet is shaded in cells
#: of the rod's own light-line chart, tens of them every crossing time, so the cost grows with the window
MAX_CAUSAL_BOOST = 400


def boost_tolerance(tolerance: float, t_window: tuple[float, float]) -> float:
    """The sampling tolerance of a boost's world-lines over the time window `t_window` (`BOOST_SAMPLING`)."""
    return max(tolerance, BOOST_SAMPLING * (t_window[1] - t_window[0]))


def boost_timeline(history: RodHistory, start: Frame, end: Frame, count: int) -> BoostTimeline:
    """The frames from `start` to `end` (`boost_velocities`; the ends keep their names), and the union of every
    frame's window: its time window (`time_window`, as `plot`) and the x its world-lines reach within it, so the
    axes stay still while the world-lines move."""
    velocities = boost_velocities(start.velocity, end.velocity, count)
    frames = [start] + [Frame(f"u={exact(float(u))}", float(u)) for u in velocities[1:-1]] + [end]
    tolerance = sampling_tolerance(history)
    t_lo = x_lo = math.inf
    t_hi = x_hi = -math.inf
    L = history.scenario.L
    for frame in frames:
        fv = view(history, frame)
        t_lo, t_hi = min(t_lo, fv.t_range[0]), max(t_hi, fv.t_range[1])
        if history.fronts is not None and t_hi - t_lo > MAX_CAUSAL_BOOST * L:  # the causal rod: its cells
            raise OptionError("frame", f"{exact(start.velocity)}..{exact(end.velocity)}", template="{what}: a boost of "
                              "the causal rod to the frame of velocity {u} spans more than {most} L of time, over "
                              "which the rod rings hundreds of times, too fine to draw; boost between slower frames "
                              "(|U| up to about 0.99), or use --mode now.", u=exact(frame.velocity),
                              most=MAX_CAUSAL_BOOST)
        for points in fv.worldline_points(boost_tolerance(tolerance, fv.t_range)).values():
            x_lo, x_hi = min(x_lo, float(points[:, 0].min())), max(x_hi, float(points[:, 0].max()))
    return BoostTimeline(tuple(frames), (t_lo, t_hi), (x_lo, x_hi))


def timeline(history: RodHistory, frames: tuple[Frame, ...], mode: str, count: int) -> NowTimeline | BoostTimeline:
    """The timeline of `count` images: now mode over the panels `frames`, boost mode from frames[0] to frames[1]."""
    if mode == "now":
        return now_timeline(history, frames, count)
    if mode == "boost":
        return boost_timeline(history, frames[0], frames[1], count)
    raise OptionError("mode", mode, MODES)
