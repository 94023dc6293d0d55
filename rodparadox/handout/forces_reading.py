"""A rod driven by forces, read once for a handout's text and tables (`read`): each force's start, peak and end seen
from each frame shown (where, when, the force, the end's velocity), and on chosen slices of each frame the momentum
each agent has delivered, the rod's kinetic (rigid) or matter (causal) part, its stress part, their sum, p/E and the
velocity of the rod's centre of energy; the causal rod's steps under a constant force and when its far end starts.
Pure: numbers from the history's `driving` capability, no text but `signed`.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import Sequence

from rodparadox.handout.words import numeral
from rodparadox.io.export_forces import force_rows
from rodparadox.numbers import MINUS
from rodparadox.physics.frames import Frame, time_window
from rodparadox.physics.types import EnergyMomentum
from rodparadox.tables.forces_ledger import slice_row

#: momenta below this (units of M c) are rounding: printed as 0, never as "the rod moves"
ZERO = 1e-9

def zero(x: float) -> float:
    return 0.0 if abs(x) < ZERO else x + 0.0


def signed(x: float, digits: int = 4) -> str:
    """+0.1250, −0.03831, 0: a momentum with its sign, `digits` significant digits (a fraction where one fits)."""
    x = zero(x)
    if x == 0.0:
        return "0"
    text = numeral(x, digits)
    return text if text.startswith(MINUS) else "+" + text


@dataclass(frozen=True)
class Moment:
    """A force's start, peak or end seen from a frame: its end, where and when (units of L), the force (M c²/L) and
    the end's velocity there."""

    end: str
    moment: str
    x: float
    t: float
    force: float
    velocity: float


@dataclass(frozen=True)
class Momenta:
    """One slice t of a frame: the momentum (and energy) each agent delivered up to it, the rod's kinetic (matter)
    part and its stress part, their sum, p/E and the centre of energy's velocity."""

    t: float
    left: EnergyMomentum
    right: EnergyMomentum
    moving: EnergyMomentum
    stress: EnergyMomentum
    rod: EnergyMomentum
    p_over_E: float
    v_E: float

    @property
    def delivered(self) -> float:
        return self.left.p + self.right.p


@dataclass(frozen=True)
class FrameForces:
    """A frame's view of the forces: their moments in its time order, the slices its table prints, and the key
    slice (where the stress holds most momentum)."""

    frame: Frame
    moments: tuple[Moment, ...]
    slices: tuple[Momenta, ...]
    key: Momenta
    initial: EnergyMomentum

    def when(self, end: str, moment: str) -> Moment:
        return next(m for m in self.moments if m.end == end and m.moment == moment)

    @property
    def ends(self) -> tuple[str, ...]:
        return tuple(dict.fromkeys(m.end for m in self.moments))

    def together(self, moment: str) -> bool:
        """Both forces' `moment` at one instant of the frame (False with one force)."""
        if len(self.ends) < 2:
            return False
        a, b = (self.when(end, moment).t for end in ("left", "right"))
        return abs(a - b) <= 1e-9 * (1.0 + abs(a) + abs(b))

    @property
    def first(self) -> str | None:
        """The end whose force starts first in this frame (None: both at once, or one force)."""
        if len(self.ends) < 2 or self.together("start"):
            return None
        return min(("left", "right"), key=lambda end: self.when(end, "start").t)


@dataclass(frozen=True)
class ForcesReading:
    """A driven history read once for the text: the model's name as the text says it, the velocity after the
    forces in S, each profile's area (the momentum it delivers in its own frame), and each frame's forces."""

    history: object
    frames: tuple[FrameForces, ...]
    final_velocity: float
    areas: tuple[tuple[str, float], ...]

    @property
    def fronts(self) -> bool:
        """The rod carries its stress as fronts at c (the causal rod): its moving part is 'matter'."""
        return self.history.fronts is not None

    def frame(self, name: str) -> FrameForces:
        return next(f for f in self.frames if f.frame.name == name)


def _momenta(history, frame: Frame, t: float) -> Momenta:
    """The slice t of the frame (t in the scenario's unit of length; the `Momenta` holds it in units of L)."""
    row = slice_row(history, frame, t)
    left, right, moving, stress, rod, _ = row["parts"].values()
    return Momenta(t / history.scenario.L, left, right, moving, stress, rod, row["p_over_E"], row["v_E"])


def slice_times(history, frame: Frame, moments: Sequence[Moment]) -> tuple[float, ...]:
    """The slices a frame's table prints: each force's start, peak and end (one row per instant; at the first start
    nothing is delivered yet), and after the last, halfway to the window's end."""
    hi = time_window(history, frame)[1] / history.scenario.L
    times = sorted({m.t for m in moments})
    out: list[float] = []
    for t in times:
        if not out or t - out[-1] > 1e-9 * (1.0 + abs(t)):
            out.append(t)
    return (*out, out[-1] + 0.5 * (hi - out[-1]))


def read(history, frames: Sequence[Frame]) -> ForcesReading:
    """The reading of `history` (driven: `history.driving` not None) in each frame (read once per history and
    frames: a worksheet and its key, a handout of the same run, read the same slices)."""
    return _read(history, tuple(frames))


@functools.lru_cache(maxsize=16)
def _read(history, frames: tuple[Frame, ...]) -> ForcesReading:
    driving = history.driving
    seen = []
    for frame in frames:
        rows = force_rows(history, frame)
        L = history.scenario.L
        moments = tuple(Moment(r["end"], r["moment"], r["x"] / L, r["t"] / L, r["force"], r["end_velocity"])
                        for r in rows)
        times = tuple(t * L for t in slice_times(history, frame, moments))
        # the key slice: halfway between two of the forces' moments (never at one: a worksheet asks those instants),
        # where the stress holds the most momentum
        halves = [0.5 * (a + b) for a, b in zip(times[:-2], times[1:-1])]
        key = _momenta(history, frame, max(halves, key=lambda t: abs(history.rod_parts(frame.rapidity, t)[1].p))) \
            if halves else None
        slices = tuple(sorted([_momenta(history, frame, t) for t in times] + ([key] if key else []),
                              key=lambda s: s.t))
        seen.append(FrameForces(frame, moments, slices, key or slices[-1], slices[0].rod))
    areas = tuple((end, p.area()) for end, p in driving.profiles())
    return ForcesReading(history, tuple(seen), math.tanh(history.final_rapidity), areas)


def staircase(history, end: str, t0: float, t1: float, samples: int = 400) -> tuple[float, ...]:
    """The distinct velocities (in S) of the driven end while its force acts (the causal rod's steps), in order."""
    sigma = 0.0 if end == "left" else history.scenario.L
    out: list[float] = []
    for k in range(1, samples):
        w = history.material_velocity(sigma, 0.0, t0 + (t1 - t0) * k / samples)
        if not out or abs(w - out[-1]) > 1e-9:
            out.append(w)
    return tuple(out)


def far_start(history, end: str, t0: float, t1: float) -> float:
    """The first instant of S at which the far end moves (bisection on its velocity)."""
    sigma = 0.0 if end == "left" else history.scenario.L
    lo, hi = t0, t1
    if abs(history.material_velocity(sigma, 0.0, hi)) < 1e-12:
        return hi
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if abs(history.material_velocity(sigma, 0.0, mid)) < 1e-12 else (lo, mid)
    return hi
