"""Frames, boosts and exact world-line segments (docs/model.md, "The model": frames and coordinates).

Pure: plain floats in, plain floats out; numpy only to return sampled points.
Every velocity is also carried as a rapidity (velocity = tanh(rapidity)),
because boosts add rapidities and a hyperbolic arc boosts by shifting its angle.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Union

import numpy as np

from rodparadox.tolerances import PROPER_TIME_TICK


_new = object.__new__


def _event(x: float, t: float) -> "Event":
    """`Event(x, t)`, built without the frozen dataclass's __init__ (one object.__setattr__ per field): world-lines
    build millions of events, and this takes 0.42 us where Event(x, t) takes 0.74 (Python 3.11). The same object:
    equal, hashed, printed and pickled alike."""
    e = _new(Event)
    d = e.__dict__
    d["x"] = x
    d["t"] = t
    return e


class _once:
    """A property of an immutable object, computed at its first reading and then kept in the object's __dict__ (which
    an instance attribute's lookup finds before this non-data descriptor): functools.cached_property, without its
    lock, which in Python 3.11 costs 0.95 us at the first reading where this costs 0.45."""

    __slots__ = ("function", "name")

    def __init__(self, function):
        self.function, self.name = function, function.__name__

    def __get__(self, obj, owner=None):
        if obj is None:
            return self
        value = obj.__dict__[self.name] = self.function(obj)
        return value


def _built(cls, **fields):
    """`cls(**fields)` for a frozen dataclass with no __post_init__ to run, without its __init__ (as `_event`)."""
    obj = _new(cls)
    obj.__dict__.update(fields)
    return obj


@dataclass(frozen=True)
class Event:
    """A point of spacetime, (x, t), in the coordinates of the frame it was read in."""

    x: float
    t: float

    def seen_from(self, frame_rapidity: float) -> "Event":
        """The same event in the coordinates of a frame moving at tanh(frame_rapidity) relative to this one's
        (a change of frame, not a motion: the event stays where it is).

        x' = g(x - u t), t' = g(t - u x); with u = -v this is the paper's
        x' = g(x + v t), t' = g(t + v x) (its printed t' = g(t - v x) is a misprint).
        """
        c, s = math.cosh(frame_rapidity), math.sinh(frame_rapidity)
        x, t = self.x, self.t
        return _event(c * x - s * t, c * t - s * x)

    def displaced(self, distance: float, rapidity_: float) -> "Event":
        """The event at proper distance `distance` along the simultaneity line of rapidity `rapidity_`."""
        return _event(self.x + distance * math.cosh(rapidity_), self.t + distance * math.sinh(rapidity_))

    def time_in(self, frame_rapidity: float) -> float:
        """This event's time coordinate in the frame of rapidity `frame_rapidity`."""
        return math.cosh(frame_rapidity) * self.t - math.sinh(frame_rapidity) * self.x


@dataclass(frozen=True)
class Line:
    """A straight piece of world-line from event `start` to the later event `end`."""

    start: Event
    end: Event

    @property
    def rapidity_at_start(self) -> float:
        return math.atanh((self.end.x - self.start.x) / (self.end.t - self.start.t))

    rapidity_at_end = rapidity_at_start

    def seen_from(self, frame_rapidity: float) -> "Line":
        """The same piece in the coordinates of the frame of rapidity `frame_rapidity` relative to this one's."""
        return _built(Line, start=self.start.seen_from(frame_rapidity), end=self.end.seen_from(frame_rapidity))

    def event_at_time(self, t: float) -> Event:
        f = (t - self.start.t) / (self.end.t - self.start.t)
        return _event(self.start.x + f * (self.end.x - self.start.x), t)

    def clipped(self, t_lo: float, t_hi: float) -> "Line | None":
        a, b = max(t_lo, self.start.t), min(t_hi, self.end.t)
        if a >= b:
            return None
        return Line(self.event_at_time(a), self.event_at_time(b))

    def sample(self, tolerance: float) -> np.ndarray:
        return np.array([[self.start.x, self.start.t], [self.end.x, self.end.t]])


@dataclass(frozen=True)
class HyperbolicArc:
    """Part of the hyperbola (x - x_E)^2 - (t - t_E)^2 = d^2 centred on the event E (docs/model.md, "The model", rule 3).

    Its points are E + side * d * (cosh phi, sinh phi); the world-line there has
    rapidity phi, and the straight line from E through it is the rod's line of
    simultaneity at that instant. phi runs from `phi_start` to `phi_end`
    (increasing when side = +1, decreasing when side = -1, so t always increases).
    """

    centre: Event
    radius: float
    side: int
    phi_start: float
    phi_end: float

    @property
    def rapidity_at_start(self) -> float:
        return self.phi_start

    @property
    def rapidity_at_end(self) -> float:
        return self.phi_end

    def point(self, phi: float) -> Event:
        # `self.centre.displaced(self.side * self.radius, phi)`, inlined: the hottest call of the world-lines
        centre, distance = self.centre, self.side * self.radius
        return _event(centre.x + distance * math.cosh(phi), centre.t + distance * math.sinh(phi))

    # the ends of an immutable arc, found once: every search along a world-line reads them (`WorldLine.first`)
    @_once
    def start(self) -> Event:
        return self.point(self.phi_start)

    @_once
    def end(self) -> Event:
        return self.point(self.phi_end)

    def seen_from(self, frame_rapidity: float) -> "HyperbolicArc":
        """The same arc in the frame of rapidity `frame_rapidity`: the centre seen from it, every angle shifted by
        -frame_rapidity; d and side stay."""
        return _built(HyperbolicArc, centre=self.centre.seen_from(frame_rapidity), radius=self.radius, side=self.side,
                      phi_start=self.phi_start - frame_rapidity, phi_end=self.phi_end - frame_rapidity)

    def phi_at_time(self, t: float) -> float:
        return math.asinh((t - self.centre.t) / (self.side * self.radius))

    def event_at_time(self, t: float) -> Event:
        return self.point(self.phi_at_time(t))

    def clipped(self, t_lo: float, t_hi: float) -> "HyperbolicArc | None":
        a, b = max(t_lo, self.start.t), min(t_hi, self.end.t)
        if a >= b:
            return None
        phi_a = self.phi_start if a == self.start.t else self.phi_at_time(a)
        phi_b = self.phi_end if b == self.end.t else self.phi_at_time(b)
        return HyperbolicArc(self.centre, self.radius, self.side, phi_a, phi_b)

    def sample(self, tolerance: float) -> np.ndarray:
        """Points whose polyline lies within `tolerance` of the arc everywhere.

        On a hyperbola the tangent is parallel to the chord from phi_a to phi_b
        exactly at the mid-angle, so the chord's largest error is the distance of
        that mid-angle point from it: bisecting until it is small is exact.
        """
        centre, distance = self.centre, self.side * self.radius
        cx, ct, cosh, sinh = centre.x, centre.t, math.cosh, math.sinh

        def at(phi: float) -> tuple[float, float]:  # `point(phi)`'s (x, t), the same arithmetic, no event built
            return cx + distance * cosh(phi), ct + distance * sinh(phi)

        phis = [self.phi_start]
        stack = [(self.phi_start, self.phi_end)]
        while stack:
            a, b = stack.pop()
            (ax, at_), (bx, bt), (mx, mt) = at(a), at(b), at(0.5 * (a + b))
            dx, dt = bx - ax, bt - at_
            chord = math.hypot(dx, dt)
            error = abs(dx * (mt - at_) - dt * (mx - ax)) / chord if chord > 0 else 0.0
            if error > tolerance:
                stack.append((0.5 * (a + b), b))
                stack.append((a, 0.5 * (a + b)))
            else:
                phis.append(b)
        return np.array([at(phi) for phi in phis])


Segment = Union[Line, HyperbolicArc]


@dataclass(frozen=True)
class WorldLine:
    """A continuous time-like world-line: straight before `segments`, the exact segments, straight after.

    `rapidity_before` continues the world-line into the past from the first
    segment's start, `rapidity_after` into the future from the last segment's
    end. A world-line with no segments is the straight line through `origin`.
    """

    origin: Event
    rapidity_before: float
    segments: tuple[Segment, ...] = ()
    rapidity_after: float | None = None

    def __post_init__(self) -> None:
        if self.rapidity_after is None:
            object.__setattr__(self, "rapidity_after", self.rapidity_before)

    # the ends of the segments, found once: every event, rapidity and piece at a time starts from them
    @_once
    def first(self) -> Event:
        return self.segments[0].start if self.segments else self.origin

    @_once
    def last(self) -> Event:
        return self.segments[-1].end if self.segments else self.origin

    def seen_from(self, frame_rapidity: float) -> "WorldLine":
        """The same world-line in the coordinates of the frame of rapidity `frame_rapidity` relative to this one's."""
        # the last frame's world-line is kept: a slice of the rod, a grid of instants, reads one material point in one
        # frame many times (History.material_worldline keeps the points). The same value of the same type: -0.0 boosts
        # as -0.0, not as 0.0, and a numpy scalar gives numpy scalars.
        last = self.__dict__.get("_seen")
        if last is not None and last[0] == frame_rapidity and type(last[0]) is type(frame_rapidity) \
                and math.copysign(1.0, last[0]) == math.copysign(1.0, frame_rapidity):
            return last[1]
        seen = self._boosted(frame_rapidity)
        self.__dict__["_seen"] = (frame_rapidity, seen)
        return seen

    def _boosted(self, frame_rapidity: float) -> "WorldLine":
        return _built(WorldLine, origin=self.origin.seen_from(frame_rapidity),
                      rapidity_before=self.rapidity_before - frame_rapidity,
                      segments=tuple([s.seen_from(frame_rapidity) for s in self.segments]),
                      rapidity_after=self.rapidity_after - frame_rapidity)

    def pieces(self, t_lo: float, t_hi: float) -> tuple[Segment, ...]:
        """Exact segments covering t_lo <= t <= t_hi, the straight ends included as Lines."""
        first, last = self.first, self.last
        before = Line(_along(first, self.rapidity_before, min(t_lo, first.t) - first.t), first)
        # a causal rod that rings for ever ends on an endless chart curve: nothing straight after it
        after = (Line(last, _along(last, self.rapidity_after, max(t_hi, last.t) - last.t)),) if math.isfinite(last.t) else ()
        out = []
        for piece in (before, *self.segments, *after):
            clipped = piece.clipped(t_lo, t_hi)
            if clipped is not None:
                out.append(clipped)
        return tuple(out)

    def event_at_time(self, t: float) -> Event:
        """The world-line's event at time t (time-like, so there is exactly one)."""
        first, last = self.first, self.last
        if t <= first.t:
            return _along(first, self.rapidity_before, t - first.t)
        if t >= last.t:
            return _along(last, self.rapidity_after, t - last.t)
        # boosted one by one, consecutive segments may meet with a rounding gap of an ulp or two:
        # the first segment that ends at or after t holds t, or t falls in the gap just before it
        return next(s for s in self.segments if t <= s.end.t).event_at_time(t)

    def event_and_rapidity_at_time(self, t: float) -> tuple[Event, float]:
        """(`event_at_time(t)`, `rapidity_at_time(t)`), the same values, with the ends and the piece found once."""
        first, last = self.first, self.last
        if t <= first.t:
            return _along(first, self.rapidity_before, t - first.t), self.rapidity_before
        if t > last.t or not self.segments:
            return _along(last, self.rapidity_after, t - last.t), self.rapidity_after
        if t == last.t:  # the event on the straight end, the rapidity of the segment before it
            return self.event_at_time(t), self.rapidity_at_time(t)
        piece = next(s for s in self.segments if t <= s.end.t)
        return piece.event_at_time(t), piece.rapidity_at_start if isinstance(piece, Line) else piece.phi_at_time(t)

    def piece_at_time(self, t: float, after: bool = False) -> Segment | float:
        """The segment holding time t, or the rapidity of the straight end (before or after the segments) that does.

        At a kink, the piece before it; with `after`, the piece after it.
        """
        first, last = self.first, self.last
        if t < first.t or (t == first.t and not after):
            return self.rapidity_before
        if t > last.t or (t == last.t and after) or not self.segments:
            return self.rapidity_after
        if after:
            return next((s for s in self.segments if t < s.end.t), self.segments[-1])
        return next(s for s in self.segments if t <= s.end.t)

    def rapidity_at_time(self, t: float, after: bool = False) -> float:
        """The world-line's rapidity at time t (at a kink: the one before it, or after it with `after`)."""
        piece = self.piece_at_time(t, after)
        if isinstance(piece, float):
            return piece
        if isinstance(piece, Line):
            return piece.rapidity_at_start
        return piece.phi_at_time(t)

    def sample(self, t_lo: float, t_hi: float, tolerance: float) -> np.ndarray:
        """(n, 2) array of [x, t] points from t_lo to t_hi, every kink included."""
        parts = [p.sample(tolerance) for p in self.pieces(t_lo, t_hi)]
        if not parts:
            e = self.event_at_time(t_lo)
            return np.array([[e.x, e.t]])
        points = [parts[0]] + [p[1:] for p in parts[1:]]
        return np.concatenate(points)


def proper_time_events(worldline: WorldLine, step: float, t_lo: float, t_hi: float) -> list[tuple[float, Event]]:
    """The events between times t_lo and t_hi where the world-line's proper time is a multiple of `step`.

    Proper time is counted from the world-line's event at t = 0 of its own
    coordinates: along a straight piece of rapidity r it runs dt / cosh r,
    along a hyperbolic arc of radius d it is d times the change of rapidity.
    Returns (proper time, event) pairs in time order; a clock every `step`. Only
    the ticks inside the window are reached, so the cost is the window's proper
    time over `step`, however far the window lies from t = 0.
    """
    if not (step > 0 and t_hi > t_lo):
        return []
    pieces = worldline.pieces(min(t_lo, 0.0), max(t_hi, 0.0))
    # proper time at the start of each piece, then shift so that tau = 0 at t = 0
    starts, tau = [], 0.0
    for piece in pieces:
        starts.append(tau)
        tau += _proper_duration(piece)
    zero = next(start + _proper_duration_to(piece, 0.0) for start, piece in zip(starts, pieces)
                if piece.start.t <= 0.0 <= piece.end.t)
    out = []
    for start, piece in zip(starts, pieces):
        if piece.end.t < t_lo or piece.start.t > t_hi:
            continue
        lo = start - zero
        # only the ticks inside the window: the pieces from t = 0 to a distant window may hold countless ticks
        first = lo + _proper_duration_to(piece, max(t_lo, piece.start.t))
        last = lo + _proper_duration_to(piece, min(t_hi, piece.end.t))
        for k in range(math.ceil(first / step - PROPER_TIME_TICK), math.floor(last / step + PROPER_TIME_TICK) + 1):
            event = _at_proper_time(piece, k * step - lo)
            if t_lo <= event.t <= t_hi and not (out and out[-1][0] == k * step):
                out.append((k * step, event))
    return out


def _proper_duration(piece: Segment) -> float:
    if not isinstance(piece, (Line, HyperbolicArc)):  # a piece that knows its own proper time (a driven rod's)
        return piece.proper_duration()
    if isinstance(piece, Line):
        return (piece.end.t - piece.start.t) / math.cosh(piece.rapidity_at_start)
    return abs(piece.phi_end - piece.phi_start) * piece.radius


def _proper_duration_to(piece: Segment, t: float) -> float:
    """Proper time from the piece's start to its event at time t."""
    if not isinstance(piece, (Line, HyperbolicArc)):
        return piece.proper_duration_to(t)
    if isinstance(piece, Line):
        return (t - piece.start.t) / math.cosh(piece.rapidity_at_start)
    return abs(piece.phi_at_time(t) - piece.phi_start) * piece.radius


def _at_proper_time(piece: Segment, tau: float) -> Event:
    """The event a proper time tau after the piece's start."""
    if not isinstance(piece, (Line, HyperbolicArc)):
        return piece.at_proper_time(tau)
    if isinstance(piece, Line):
        r = piece.rapidity_at_start
        return _along(piece.start, r, tau * math.cosh(r))
    return piece.point(piece.phi_start + piece.side * tau / piece.radius)


def _along(event: Event, rapidity_: float, dt: float) -> Event:
    """The event a time dt after `event` on the straight world-line of the given rapidity."""
    return _event(event.x + math.tanh(rapidity_) * dt, event.t + dt)


class ChartCurve:
    """The world-line of the causal rod's material point X between chart times T_start and T_end (the docs, "The
    causal rod"): t + x = e^-f a(T + X), t - x = e^f b(T - X), exact at any T; its rapidity there is
    (r+(T + X) - r-(T - X))/2 - f. A boost by rapidity f' only adds f' to f (`seen_from`). `chart` gives a, b,
    r_plus, r_minus and `breaks(X, T_lo, T_hi)` (the chart times where a front crosses the line, where it kinks).
    T_end may be infinite (a rod that rings for ever): the curve then has no end event.
    """

    def __init__(self, chart, X: float, T_start: float, T_end: float, f: float = 0.0):
        self.chart, self.X, self.T_start, self.T_end, self.f = chart, X, T_start, T_end, f

    def point(self, T: float) -> Event:
        U = math.exp(-self.f) * self.chart.a(T + self.X)
        V = math.exp(self.f) * self.chart.b(T - self.X)
        return _event(0.5 * (U - V), 0.5 * (U + V))

    def _time_at(self):
        """`lambda T: self.point(T).t`, the same arithmetic with e^-f and e^f found once and no event built: the
        bisection of `chart_time` calls it some 60 times a search."""
        a, b, X = self.chart.a, self.chart.b, self.X
        e_minus, e_plus = math.exp(-self.f), math.exp(self.f)

        def time(T: float) -> float:
            return 0.5 * (e_minus * a(T + X) + e_plus * b(T - X))
        return time

    def rapidity(self, T: float) -> float:
        return 0.5 * (self.chart.r_plus(T + self.X) - self.chart.r_minus(T - self.X)) - self.f

    @property
    def start(self) -> Event:
        return self.point(self.T_start)

    @property
    def end(self) -> Event:
        return self.point(self.T_end) if math.isfinite(self.T_end) else Event(math.nan, math.inf)

    @property
    def rapidity_at_start(self) -> float:
        return self.rapidity(self.T_start)

    @property
    def rapidity_at_end(self) -> float:
        return self.rapidity(self.T_end)

    def seen_from(self, frame_rapidity: float) -> "ChartCurve":
        return ChartCurve(self.chart, self.X, self.T_start, self.T_end, self.f + frame_rapidity)

    def chart_time(self, t: float) -> float:
        """The chart time where the curve is at time t (t rises with T: the curve is time-like)."""
        time = self._time_at()  # point(T).t; each bracket end's time read once
        lo, hi = self.T_start, self.T_end
        scale = getattr(self.chart, "L", 1.0)  # steps in units of the rod's length: L may be 1e-100 or 1e100
        if not math.isfinite(lo):  # endless into the past too (the rod at rest before any contact)
            lo = hi if math.isfinite(hi) else (t if scale != 1.0 else 0.0)
            step = scale
            while (t_lo := time(lo)) > t:
                lo, step = lo - step, 2.0 * step
        else:
            t_lo = time(lo)
        t_hi = None
        if not math.isfinite(hi):
            step = max(scale, t - t_lo)
            hi = lo + step
            while (t_hi := time(hi)) < t:
                step *= 2.0
                hi = lo + step
        if t <= t_lo:
            return lo
        if t >= (time(hi) if t_hi is None else t_hi):
            return hi
        for _ in range(200):  # bisection to the last bit: exact to rounding, whatever the pieces are
            mid = 0.5 * (lo + hi)
            if mid in (lo, hi):
                break
            if time(mid) < t:
                lo = mid
            else:
                hi = mid
        return hi

    def event_at_time(self, t: float) -> Event:
        return self.point(self.chart_time(t))

    def phi_at_time(self, t: float) -> float:
        """The rapidity at time t (named as HyperbolicArc's, so WorldLine.rapidity_at_time reads both). At a finite
        end of the curve, the rapidity on the curve's side: a particle's contact ends where a front arrives (the
        tension that separates it), and the end's rapidity after that front is not the particle's."""
        T = self.chart_time(t)
        if T == self.T_end:
            T = math.nextafter(T, -math.inf)
        elif T == self.T_start:
            T = math.nextafter(T, math.inf)
        return self.rapidity(T)

    def clipped(self, t_lo: float, t_hi: float) -> "ChartCurve | None":
        a = self.T_start if t_lo <= self.start.t else self.chart_time(t_lo)
        b = self.T_end if math.isfinite(self.T_end) and t_hi >= self.end.t else self.chart_time(t_hi)
        return ChartCurve(self.chart, self.X, a, b, self.f) if b > a else None

    def sample(self, tolerance: float) -> np.ndarray:
        """Points whose polyline lies within `tolerance` of the curve: split at every front (a kink), then bisected
        in chart time until the chord's distance from the mid point is within tolerance."""
        if not math.isfinite(self.T_end):
            raise ValueError("an endless chart curve is sampled only when clipped to a window")
        knots = [self.T_start, *self.chart.breaks(self.X, self.T_start, self.T_end), self.T_end]
        known: dict[float, tuple[float, float]] = {}  # each chart time's point once: a half's ends are its parent's
        a_, b_, X = self.chart.a, self.chart.b, self.X  # end and middle; as (x, t), the arithmetic of `point`
        e_minus, e_plus = math.exp(-self.f), math.exp(self.f)

        def at(T: float) -> tuple[float, float]:
            if T not in known:
                U, V = e_minus * a_(T + X), e_plus * b_(T - X)
                known[T] = (0.5 * (U - V), 0.5 * (U + V))
            return known[T]

        out = [at(self.T_start)]
        for a0, b0 in zip(knots, knots[1:]):
            if b0 - a0 <= 1e-14 * (abs(a0) + abs(b0) + 1e-300):
                continue  # a front through an end of the curve, read an ulp apart
            stack = [(a0, b0, 0)]
            while stack:
                a, b, depth = stack.pop()
                (ax, at_), pb, (mx, mt) = at(a), at(b), at(0.5 * (a + b))
                dx, dt = pb[0] - ax, pb[1] - at_
                chord = math.hypot(dx, dt)
                error = abs(dx * (mt - at_) - dt * (mx - ax)) / chord if chord > 0 else 0.0
                if (error > tolerance or depth < 2) and depth < 40:
                    stack.append((0.5 * (a + b), b, depth + 1))
                    stack.append((a, 0.5 * (a + b), depth + 1))
                else:
                    out.append(pb)
        return np.array(out)
