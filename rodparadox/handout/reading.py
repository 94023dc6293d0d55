"""The reading of a history for a handout's text: `Reading`, computed once per history and frames shown. Pure.

Each impact's coordinates in each frame; the impacts grouped by instant of a
frame's time; the rod's collisions and lines of simultaneity in its own order;
which impacts started each turn (`turn_cause`) and where the whole rod stands
still in a frame (`rests`); the velocity in a frame of a body of given rapidity
and the rod's before and after each collision; whether the rod zig-zags. Lengths
and times are read as multiples of L, rounding-sized values as 0.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import Sequence

from rodparadox.handout.words import PROSE_DIGITS, impact_names, in_l, listed, time_name
from rodparadox.physics.history import RodHistory, Turn
from rodparadox.physics.types import Impact
from rodparadox.physics.frames import Frame, rest_frame, time_order
from rodparadox.tolerances import ONE_INSTANT, SAME_RAPIDITY


@dataclass(frozen=True)
class Reading:
    """A history and the frames shown, with what the text needs computed once: each impact's coordinates in each
    frame, the instants at which impacts coincide, the rod's collisions in its own order, the impacts that started
    each turn, velocities."""

    history: RodHistory
    frames: tuple[Frame, ...]

    @property
    def L(self) -> float:
        return self.history.scenario.L

    @property
    def v(self) -> float:
        return self.history.scenario.v

    @cached_property
    def scale(self) -> float:
        """L plus the largest |x| or |t| of an impact in any frame shown (or in S): what rounding is measured against."""
        values = [abs(c) for f in (*self.frames, rest_frame()) for i in self.history.impacts
                  for c in (self.t(i, f), self.x(i, f))]
        return self.L + max(values, default=0.0)

    @staticmethod
    def t(impact: Impact, frame: Frame) -> float:
        return impact.event.time_in(frame.rapidity)

    @staticmethod
    def x(impact: Impact, frame: Frame) -> float:
        return impact.event.seen_from(frame.rapidity).x

    def length(self, value: float, impacts: Sequence[Impact] = (), frame: Frame | None = None) -> float:
        """A coordinate or time as a multiple of L, rounding-sized values 0 (x′ = 0 of A₁ in Fig. 1 is 6e-17).

        Rounding is measured against the impacts the value was computed from, where given (`rounding`), else
        against the whole history's `scale`: in a fast frame one impact may lie 1e7 L out while another's time is
        2e-4 L, far above its own rounding."""
        scale = self.rounding(impacts, frame) if impacts and frame is not None else self.scale
        return 0.0 if abs(value) <= ONE_INSTANT * scale else value / self.L

    def rounding(self, impacts: Sequence[Impact], frame: Frame) -> float:
        """What the coordinates of these impacts in `frame` are exact relative to: L plus their S coordinates (the
        engine places them to ONE_INSTANT of that), times the most a boost to the frame can stretch them."""
        stretch = math.exp(abs(frame.rapidity))
        return self.L + stretch * max(abs(i.event.x) + abs(i.event.t) for i in impacts)

    def same_time(self, a: float, b: float) -> bool:
        return abs(a - b) <= ONE_INSTANT * self.scale

    def instants(self, frame: Frame) -> tuple[tuple[float, tuple[Impact, ...]], ...]:
        """The impacts grouped by instant of the frame's time, in its order (each group in the rod's order)."""
        impacts = self.history.impacts
        times = [self.t(i, frame) for i in impacts]
        out: list[tuple[float, list[Impact]]] = []
        for k in time_order(times, self.scale):
            if out and self.same_time(out[-1][0], times[k]):
                out[-1][1].append(impacts[k])
            else:
                out.append((times[k], [impacts[k]]))
        return tuple((t, tuple(group)) for t, group in out)

    @cached_property
    def collisions(self) -> tuple[tuple[Impact, ...], ...]:
        """The rod's collisions in its own order, each the impacts on one of its lines of simultaneity (rule 5)."""
        out: list[list[Impact]] = []
        for i in self.history.impacts:
            if out and out[-1][0].collision == i.collision:
                out[-1].append(i)
            else:
                out.append([i])
        return tuple(tuple(c) for c in out)

    @cached_property
    def lines(self) -> tuple[tuple[Impact, ...], ...]:
        """The rod's lines of simultaneity it is struck on, in its own order, each with its impacts: one collision,
        or several when a particle strikes again at once (rule 7). Consecutive impacts on one line share its
        rapidity and their time along it."""
        out: list[list[Impact]] = []
        for i in self.history.impacts:
            last = out[-1][-1] if out else None
            if (last is not None and last.line_rapidity == i.line_rapidity
                    and abs(last.event.time_in(i.line_rapidity) - i.event.time_in(i.line_rapidity))
                    <= ONE_INSTANT * self.scale):
                out[-1].append(i)
            else:
                out.append([i])
        return tuple(tuple(line) for line in out)

    @cached_property
    def turn_causes(self) -> tuple[tuple[Impact, ...], ...]:
        """For each of `RodHistory.turns`, the impacts that started it: those on the line after which the rod's
        momentum no longer matches the line (engine: a turn starts where the rod's rapidity differs from the
        line's). Should the count ever differ, the impacts at each turn's pivot."""
        starting = [line for line in self.lines if line[-1].rod_rapidity_after != line[-1].line_rapidity]
        if len(starting) == len(self.history.turning.turns):
            return tuple(starting)
        return tuple(self.impacts_at(turn.pivot) for turn in self.history.turning.turns)

    def turn_cause(self, turn: Turn) -> tuple[Impact, ...]:
        """The impacts that started the turn (one of `RodHistory.turns`)."""
        return self.turn_causes[next(k for k, t in enumerate(self.history.turning.turns) if t is turn)]

    def rests(self, frame: Frame) -> list[tuple[Turn, float, float | None, Turn | None]]:
        """Each stretch of the frame's time in which the whole rod stands still in it after a turn that completes:
        (the turn, when it ends, when the next turn starts or None, that next turn or None). The turn's last line is
        a line of simultaneity of the frame, so every point reaches rest at one instant of it, at the rod's full
        length."""
        out = []
        turns = self.history.turning.turns
        for k, turn in enumerate(turns):
            if not turn.completed or abs(turn.rapidity_stop - frame.rapidity) > SAME_RAPIDITY:
                continue
            end = turn.interval(frame.rapidity)[1]
            later = sorted(((t.interval(frame.rapidity)[0], t) for t in turns[k + 1:]), key=lambda st: st[0])
            if later and later[0][0] < end - ONE_INSTANT * self.scale:
                continue  # another turn already moves part of the rod
            # the next turn is the next in the rod's own order (two turns may start at one instant of the frame,
            # and a rounding must not let a later one stand for it)
            following = turns[k + 1] if k + 1 < len(turns) else None
            start = following.interval(frame.rapidity)[0] if following is not None else None
            out.append((turn, end, start, following))
        return out

    def turn_steps(self, frame: Frame) -> tuple[tuple[float, float, tuple[Impact, ...]], ...]:
        """What the rod's material does in each turn, in the rod's own order, seen in the frame: (the velocity it
        turns from, the velocity it reaches, the impacts that started the turn). A turn cut short by an impact on
        the far end reaches only `rapidity_stop`, never the rod's velocity after the impact."""
        return tuple((self.velocity(t.rapidity_from, frame), self.velocity(t.rapidity_stop, frame), self.turn_cause(t))
                     for t in self.history.turning.turns)

    def velocity(self, rapidity: float, frame: Frame) -> float:
        """The velocity in the frame of a body of this rapidity in S; a rounding-sized one is 0."""
        return 0.0 if abs(rapidity - frame.rapidity) <= SAME_RAPIDITY else math.tanh(rapidity - frame.rapidity)

    def rod_velocities(self, frame: Frame) -> tuple[float, ...]:
        """The rod's (dynamical) velocity in the frame before the first collision and after each, in its own order."""
        rapidities = [0.0] + [c[-1].rod_rapidity_after for c in self.collisions]
        return tuple(self.velocity(r, frame) for r in rapidities)

    def when(self, impacts: Sequence[Impact], frame: Frame, digits: int = PROSE_DIGITS) -> str:
        """t′ = 17/12 L for impacts at one instant of the frame; t′ = 2/3 L and 17/12 L (in the frame's order) for
        impacts the rod takes together but the frame at different instants."""
        times = sorted(self.t(i, frame) for i in impacts)
        distinct = [t for k, t in enumerate(times) if k == 0 or not self.same_time(times[k - 1], t)]
        return f"{time_name(frame)} = " + listed([in_l(self.length(t, impacts, frame), digits) for t in distinct])

    def at_instant(self, impact: Impact) -> str:
        """The label of the impact(s) at this impact's event: B₂, or A₁ and B₁ when the rod takes them together."""
        return impact_names(next(c for c in self.collisions if impact in c))

    def impacts_at(self, event) -> tuple[Impact, ...]:
        """The impacts at an event (a turn's pivot), in the rod's order."""
        return tuple(i for i in self.history.impacts
                     if math.hypot(i.event.x - event.x, i.event.t - event.t) <= ONE_INSTANT * self.scale)


def zigzags(rapidities: Sequence[float]) -> bool:
    """Whether the rod zig-zags: its velocity changes direction (up, then down, or down, then up) more than once,
    or returns to a value it had before. Rapidities, so the answer is the same in every frame."""
    changes = [b - a for a, b in zip(rapidities, rapidities[1:]) if abs(b - a) > SAME_RAPIDITY]
    reversals = sum(1 for a, b in zip(changes, changes[1:]) if (a > 0) != (b > 0))
    returns = any(abs(rapidities[j] - rapidities[i]) <= SAME_RAPIDITY and any(
        abs(r - rapidities[i]) > SAME_RAPIDITY for r in rapidities[i:j]) for i in range(len(rapidities))
        for j in range(i + 2, len(rapidities)))
    return reversals > 1 or returns
