"""Frames, and a history seen from one: events, velocities and world-lines in that frame's coordinates. Pure.

The frame conventions live here, once: `rest` is S, `moving` is the paper's S'
of velocity -v (`model.frame_velocity`), any other frame is its velocity u
relative to S, bounded by FASTEST_FRAME (`model.FASTEST`); a frame's word is
read by `frame_of_word`; velocities add by `relative_velocity`.
Shared by `export` (numbers) and `render` (pictures), so both show the same
events, over the same time window, sampled the same way.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

import numpy as np

from rodparadox.physics.types import Impact, WORLDLINE_NAMES
from rodparadox.physics.history import RodHistory
from rodparadox.errors import FrameError
from rodparadox.physics.kinematics import Event, Segment
from rodparadox.physics.model import FASTEST, FRAME_NAMES, frame_velocity
from rodparadox.numbers import decimal, exact, shown
from rodparadox.tolerances import ONE_INSTANT, SAMPLING_TOLERANCE

#: one panel per frame, lettered (a), (b), ...: at most eight in one figure
PANEL_LETTERS = "abcdefgh"
#: panels in one figure, lettered (a) to (h): the most frames one figure shows
MAX_PANELS = len(PANEL_LETTERS)
#: the fastest frame a user may give (to see, to boost to, or to time a particle in: `model.FASTEST`, the one
#: bound): faster, g exceeds 2000 and a particle's velocity in the frame, 1 - 1e-14 or closer, no longer has the
#: digits to tell it from c
FASTEST_FRAME = FASTEST


def check_velocity(u: float) -> float:
    """A frame velocity relative to S, -FASTEST_FRAME <= u <= FASTEST_FRAME (0 is S itself); -0 becomes 0."""
    if isinstance(u, bool) or not isinstance(u, (int, float)) or not (math.isfinite(u) and abs(u) <= FASTEST_FRAME):
        raise FrameError(f"a frame velocity must be a number U with {-FASTEST_FRAME!r} <= U <= {FASTEST_FRAME!r} "
                         f"(units of c) for double precision to place the events, got {u!r}.")
    return float(u) + 0.0


def relative_velocity(u: float, w: float) -> float:
    """Velocity, seen from a frame of velocity w, of a frame of velocity u (both relative to S): velocity addition."""
    return (u - w) / (1.0 - u * w)


def named_frame(name: str, v: float) -> "Frame":
    """`rest` (S) or `moving` (S', of velocity -v relative to S: `model.frame_velocity`), for the speed v."""
    if name not in FRAME_NAMES:
        raise ValueError(f"a named frame is one of {', '.join(FRAME_NAMES)}, got {name!r}")
    return Frame(name, frame_velocity(name, v))


def rest_frame() -> "Frame":
    """S: the frame in which the rod is at rest before any impact."""
    return named_frame("rest", 0.0)


def moving_frame(v: float) -> "Frame":
    """S': the paper's moving frame, of velocity -v relative to S (the rod moves at +v in it)."""
    return named_frame("moving", v)


def frame_of_velocity(u: float) -> "Frame":
    """The frame of velocity u relative to S, named `u=` and every digit of u (`u=0.3`, `u=-0.9999999`)."""
    u = check_velocity(u)
    return Frame(f"u={exact(u)}", u)


def frame_of_word(word: str, v: float) -> "Frame | None":
    """The frame one word names, for the speed v: `rest` (S), `moving` (S', `named_frame`) or a velocity U relative
    to S (`frame_of_velocity`: a FrameError past FASTEST_FRAME); None when the word is neither a name nor a
    number. The one reader of a frame's word: `parse_frames` and boost mode's ends (`animate.timeline`) use it."""
    word = word.strip()
    if word in FRAME_NAMES:
        return named_frame(word, v)
    try:
        u = decimal(word)  # -0 is 0; decimal digits only, as every number a user writes
    except ValueError:
        return None
    return frame_of_velocity(u)


@dataclass(frozen=True)
class Frame:
    """An inertial frame by its velocity relative to S: `rest` is S, `moving` is S' (velocity -v).

    Its invariant, |velocity| < 1, is what a Lorentz frame is (it moves slower than light), not a bound on what a
    user may give: every frame velocity a user gives (a frame to see, the ends of a boost, a scenario's timing
    frame) is bounded by FASTEST_FRAME (`check_velocity`, `frame_of_word`, `model.Timing`), where double
    precision still places the events and writes every velocity below c.
    """

    name: str
    velocity: float

    def __post_init__(self) -> None:
        if not (math.isfinite(self.velocity) and -1.0 < self.velocity < 1.0):
            raise FrameError(f"frame velocity must be a number u with -1 < u < 1 (units of c), got {self.velocity!r}.")

    @property
    def rapidity(self) -> float:
        return math.atanh(self.velocity)

    def rod_velocity(self) -> float:
        """The rod's velocity in this frame before any impact (0, never -0, in S)."""
        return 0.0 - self.velocity


def frame_symbol(frame: "Frame") -> str:
    """The frame's name as the paper writes it: S, S′, or u = ... for any other frame (plain text)."""
    return {"rest": "S", "moving": "S\N{PRIME}"}.get(frame.name, f"u = {shown(frame.velocity)}")


def frame_name(frame: "Frame") -> str:
    """The frame in running text: S, S′, or "the frame u = 0.3" (a handout's sentences, a strip's readout)."""
    symbol = frame_symbol(frame)
    return symbol if frame.name in FRAME_NAMES else f"the frame {symbol}"


def frame_heading(frame: "Frame") -> str:
    """The frame as the text tables head it (ASCII): `frame rest (S, the rod's rest frame)`, `frame moving (S',
    where the rod first moves at +v)`, `frame u=0.3`."""
    about = {"rest": "S, the rod's rest frame", "moving": "S', where the rod first moves at +v"}.get(frame.name)
    return f"frame {frame.name}" + (f" ({about})" if about else "")


def frame_word(frame: "Frame") -> str:
    """The frame in a file name: rest, moving, or u and every digit of its velocity (u0.3, u-0.5)."""
    return frame.name if frame.name in FRAME_NAMES else "u" + exact(frame.velocity)


def paper_frames(v: float, extra_velocity: float | None = None) -> tuple[Frame, ...]:
    """S and S', and optionally one more frame of the given velocity relative to S (`frame_of_velocity`)."""
    frames = [rest_frame(), moving_frame(v)]
    if extra_velocity is not None:
        frames.append(frame_of_velocity(extra_velocity))
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
        asked = [frame_of_word(word, v) for word in (FRAME_NAMES if item == "both" else (item,))]
        if None in asked:
            raise FrameError(f"a frame must be rest, moving, both or a velocity U with {-FASTEST_FRAME!r} <= U <= "
                             f"{FASTEST_FRAME!r} (or a comma-separated list of these), got {item!r}.")
        for frame in asked:
            same = next((k for k, f in enumerate(frames) if f.velocity == frame.velocity), None)
            if same is None:
                frames.append(frame)
            elif frame.name in FRAME_NAMES and frames[same].name.startswith("u="):
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

    def worldline_points(self, tolerance: float, times: tuple[float, float] | None = None) -> dict[str, np.ndarray]:
        """Each world-line as an (n, 2) array of [x, t], every kink included, arcs within `tolerance`; only its part
        within the frame's `times` (t_lo, t_hi) where given."""
        out = {}
        for name, pieces in self.segments:
            if times is not None:
                pieces = [c for c in (p.clipped(*times) for p in pieces) if c is not None]
            parts = [p.sample(tolerance) for p in pieces]
            out[name] = np.concatenate([parts[0]] + [p[1:] for p in parts[1:]]) if parts else np.empty((0, 2))
        return out


def time_order(times: Sequence[float], scale: float) -> list[int]:
    """Indices of `times` (given in the rod's own order) in the order of a frame's time: times within
    ONE_INSTANT * `scale` of each other are one instant, and keep the rod's own order (B₁ before A₁ in Fig. 2's
    S′, whatever the rounding of t′ says)."""
    by_time = sorted(range(len(times)), key=lambda k: times[k])
    instant, first_time, instants = -1, None, {}
    for k in by_time:
        if first_time is None or times[k] - first_time > ONE_INSTANT * scale:
            instant, first_time = instant + 1, times[k]
        instants[k] = instant
    return sorted(range(len(times)), key=lambda k: (instants[k], k))


def time_window(history: RodHistory, frame: Frame) -> tuple[float, float]:
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
    changes = [i.event.seen_from(eta).t for i in history.impacts]
    for name in WORLDLINE_NAMES:
        worldline = history.worldline(name)
        if worldline is not None:
            # a causal rod's ends ring for ever: their endless last segment has no end to show
            changes += [t for s in worldline.seen_from(eta).segments for t in (s.start.t, s.end.t) if math.isfinite(t)]
    if history.driving is not None:  # each force's start, peak and end (a causal rod's ends ring for ever)
        changes += [e.event.seen_from(eta).t for e in history.driving.force_events()]
    first, last = min(changes), max(changes)
    at_start = [e.seen_from(eta).t for _, e in history.starts]
    at_start += [Event(sign * L / 2, 0.0).seen_from(eta).t for sign in (-1, 1)]
    lead = min(max(first - min(at_start), 0.5 * L), 2.0 * L)
    if history.driving is not None:  # forces: at least L before the first force and after the last has ended
        lead = max(lead, L)
    return first - lead, last + lead


def view(history: RodHistory, frame: Frame, window: tuple[float, float] | None = None) -> FrameView:
    """The history in the frame, over `window` (the frame's times) or its own `time_window`."""
    eta = frame.rapidity
    t_lo, t_hi = window or time_window(history, frame)
    events = []
    for i in history.impacts:
        e = i.event.seen_from(eta)
        events.append(EventView(i, e.x, e.t, math.tanh(i.particle_rapidity_before - eta),
                                math.tanh(i.particle_rapidity_after - eta), math.tanh(i.rod_rapidity_before - eta),
                                math.tanh(i.rod_rapidity_after - eta)))
    segments = tuple((name, history.worldline(name).seen_from(eta).pieces(t_lo, t_hi))
                     for name in WORLDLINE_NAMES if history.worldline(name) is not None)
    return FrameView(frame, tuple(events), (t_lo, t_hi), segments)


def sampling_tolerance(history: RodHistory) -> float:
    return SAMPLING_TOLERANCE * history.scenario.L


def check_below_c(fv: FrameView) -> None:
    """Refuse a frame in which a body's velocity rounds to c: written as 1.0 it would be a lie (a body at c).

    A particle far heavier than the rod can throw it to a rapidity whose tanh, in a fast frame, is 1 in
    double precision though the speed is below c (mass 1e9, v = 0.9999999, frame u = 0.9999999).
    """
    eta = fv.frame.rapidity
    for e in fv.events:
        i = e.impact
        for body, phi, when in ((f"particle {i.particle}", i.particle_rapidity_before, "before"),
                                (f"particle {i.particle}", i.particle_rapidity_after, "after"),
                                ("rod", i.rod_rapidity_before, "before"), ("rod", i.rod_rapidity_after, "after")):
            if abs(math.tanh(phi - eta)) == 1.0:
                gap = 2.0 / (math.exp(min(2.0 * abs(phi - eta), 700.0)) + 1.0)  # 1 - |tanh|, without cancelling
                raise FrameError(f"in frame {fv.frame.name} the {body}'s velocity {when} {i.label} is within "
                                 f"{gap:.1e} of c, closer than double precision can write; choose a slower frame, "
                                 f"a slower v or a lighter particle.")
