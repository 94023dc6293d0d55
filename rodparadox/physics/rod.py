"""Inside the rod, for any rod model: the rod on a slice of any frame (where each material point is and how fast
it moves), its material lines, and a clock's tick step (docs/model.md, "Inside the rod"). Pure.

Every model gives the exact world-line of each material point (`RodHistory.material_worldline`); this module only
reads them.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rodparadox.numbers import nice_number
from rodparadox.physics.history import RodHistory


@dataclass(frozen=True)
class RodSlice:
    """The rod on the slice t = `t` of the frame of rapidity `frame_rapidity`: where each material point is, and its
    rapidity there (`velocity` = tanh of it), all in that frame."""

    frame_rapidity: float
    t: float
    sigma: np.ndarray
    x: np.ndarray
    rapidity: np.ndarray

    @property
    def velocity(self) -> np.ndarray:
        return np.tanh(self.rapidity)


def rod_slice(history: RodHistory, frame_rapidity: float, t: float, sigmas) -> RodSlice:
    """Where the material points `sigmas` cross the slice t of the frame, and their rapidities there."""
    sigmas = np.asarray(sigmas, dtype=float)
    xs, rapidities = np.empty(len(sigmas)), np.empty(len(sigmas))
    for k, sigma in enumerate(sigmas):
        event, rapidities[k] = history.material_worldline(float(sigma)).seen_from(frame_rapidity).event_and_rapidity_at_time(t)
        xs[k] = event.x
    return RodSlice(frame_rapidity, t, sigmas, xs, rapidities)


def material_lines(history: RodHistory, frame_rapidity: float, count: int, t_lo: float, t_hi: float,
                   tolerance: float) -> list[tuple[float, np.ndarray]]:
    """`count` interior material points, evenly spaced (sigma = k L/(count + 1)), as (sigma, (n, 2) points of
    [x, t]) in the frame's coordinates from t_lo to t_hi, every kink included, arcs within `tolerance`."""
    L = history.scenario.L
    out = []
    for k in range(1, count + 1):
        sigma = k * L / (count + 1)
        out.append((sigma, history.material_worldline(sigma).seen_from(frame_rapidity).sample(t_lo, t_hi, tolerance)))
    return out


def clock_step(span: float, ticks: int = 10) -> float:
    """A nice proper-time step (`numbers.nice_number`: 1, 2, 2.5 or 5 times a power of ten) giving about `ticks`
    clock ticks over a time `span`: a figure passes its longest panel's span, so that a body at rest in that frame
    gets no more than about `ticks` ticks, and uses the one step in every panel, as proper time is the same in every
    frame."""
    return nice_number(span / ticks, "at_least")
