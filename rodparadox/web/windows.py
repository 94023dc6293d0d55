"""The time window of every frame the page shows, computed once here and embedded (the page draws each frame over
its window; the ledger's slices spread evenly over it). Pure.

The window is `frames.time_window`'s, for whole arrays of frames at once: the changes of the history (its impacts,
the starts and ends of the exact segments of its world-lines, each force's start, peak and end) read in each
frame's time, from the first to the last, widened at both ends by the lead from the scenario's start (clamped to
[L/2, 2L]; at least L for a rod driven by forces). Boosting an event is exact, so each frame's window is that of
`time_window` to rounding.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rodparadox.physics.types import WORLDLINE_NAMES


@dataclass(frozen=True)
class Changes:
    """What a history's windows are made of, in S (units of the scenario's L, as its events): `changes` and
    `starts` are (n, 2) arrays of (x, t); `least` and `most` bound the lead."""

    changes: np.ndarray
    starts: np.ndarray
    least: float
    most: float

    def windows(self, rapidities) -> np.ndarray:
        """(n, 2): each frame's (first, last) time in its own coordinates, for frames of these rapidities."""
        f = np.atleast_1d(np.asarray(rapidities, dtype=float))
        c, s = np.cosh(f)[:, None], np.sinh(f)[:, None]
        times = c * self.changes[None, :, 1] - s * self.changes[None, :, 0]
        at_start = c * self.starts[None, :, 1] - s * self.starts[None, :, 0]
        first, last = times.min(axis=1), times.max(axis=1)
        lead = np.minimum(np.maximum(first - at_start.min(axis=1), self.least), self.most)
        return np.column_stack([first - lead, last + lead])


def changes(history) -> Changes:
    """The events a history's windows are read from (as `frames.time_window` reads them)."""
    L = history.scenario.L
    events = [(i.event.x, i.event.t) for i in history.impacts]
    for name in WORLDLINE_NAMES:
        worldline = history.worldline(name)
        if worldline is not None:  # a causal rod's ends ring for ever: their endless last segment has no end
            events += [(e.x, e.t) for s in worldline.segments for e in (s.start, s.end) if math.isfinite(e.t)]
    driven = history.driving is not None
    if driven:
        events += [(e.event.x, e.event.t) for e in history.driving.force_events()]
    starts = [(e.x, e.t) for _, e in history.starts] + [(-L / 2, 0.0), (L / 2, 0.0)]
    return Changes(np.array(events, dtype=float), np.array(starts, dtype=float), L if driven else 0.5 * L, 2.0 * L)


#: the frame slider's farthest step, in hundredths of c: a step of 100 would be a frame moving at c, which is no
#: frame (its window's rapidity infinite); S' beyond it is shown by the page's own button
MAX_SLIDER_STEPS = 99


def slider_steps(reach: float) -> int:
    """The frame slider's reach in hundredths of c (it runs from -steps to steps; the page reads its value / 100),
    never a frame at c (`MAX_SLIDER_STEPS`)."""
    return min(math.ceil(reach * 100), MAX_SLIDER_STEPS)


def slider_velocities(steps: int) -> np.ndarray:
    """The frame slider's velocities, as the page reads them: k / 100 for k from -steps to steps."""
    return np.arange(-steps, steps + 1) / 100.0
