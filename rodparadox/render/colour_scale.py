"""The strip's colour scale (README, "The paradox in motion"): which velocity of the rod's material points each
colour means, in one frame, the same at every instant of the history. Pure: no matplotlib, so the animation's
timeline reads it before anything is drawn; `render.strip` maps it to a colour map.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from rodparadox.physics.engine import History
from rodparadox.physics.frames import Frame
from rodparadox.physics.snapshot import rod_rapidities
from rodparadox.tolerances import DIFFERENCE_ROUNDING

#: the colour scale's half-range when the rod never changes velocity in a frame (every point at the centre)
STILL_BOUND = 0.1


@dataclass(frozen=True)
class ColourScale:
    """The strip's diverging colour scale: `centre` (the frame's initial rod velocity) +- `bound`; `shown` is the
    part a colour bar shows, from the slowest to the fastest velocity any material point takes (never past c,
    which centre +- bound can be: 0.6 +- 0.6 in Fig. 2's S′)."""

    centre: float
    bound: float
    shown: tuple[float, float] | None = None

    @property
    def limits(self) -> tuple[float, float]:
        return self.centre - self.bound, self.centre + self.bound


def colour_scale(history: History, frame: Frame) -> ColourScale:
    """Centred on the rod's velocity in `frame` before any impact; bound the largest distance from it of any
    material point's velocity over the whole history, so the colours mean the same at every instant."""
    centre = frame.rod_velocity()
    eta = frame.rapidity
    velocities = [math.tanh(r - eta) for r in rod_rapidities(history)]
    bound = max(abs(u - centre) for u in velocities)
    # a rod that never changes velocity, seen from a frame that leaves an ulp between its velocity and the centre
    # (fig1 from u = 0.3: -0.30000000000000004 against -0.3): still, not a scale zero wide
    if bound <= 0 or max(velocities) - min(velocities) <= DIFFERENCE_ROUNDING:
        return ColourScale(centre, STILL_BOUND)
    return ColourScale(centre, bound, (min(velocities), max(velocities)))
