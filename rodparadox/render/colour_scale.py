"""The strip's colour scale (docs/animate.md, "The paradox in motion"): which velocity of the rod's material points each
colour means, in one frame, the same at every instant of the history. Pure: no matplotlib, so the animation's
timeline reads it before anything is drawn; `render.strip` maps it to a colour map.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from rodparadox.physics.history import RodHistory
from rodparadox.physics.frames import Frame
from rodparadox.tolerances import DIFFERENCE_ROUNDING

#: the colour scale's half-range, in rapidity, when the rod never changes velocity in a frame (every point at the
#: centre)
STILL_BOUND = 0.1
#: the largest rapidity a colour scale reaches (tanh 15 = 1 - 1.9e-13): a colour bar on a velocity scale drawn
#: past rapidity ~17 pads its ends to c, where arctanh is infinite (a pcolormesh traceback)
FASTEST_COLOUR = 15.0


@dataclass(frozen=True)
class ColourScale:
    """The strip's diverging colour scale, even in rapidity: `centre` (the frame's initial rod velocity) and
    `bound`, the half-range in rapidity about it, so near c, where every velocity after the impacts crowds into
    0.97..0.9995, the colours still spread (a colour bar is ticked in velocity, on this rapidity scale); `shown`
    is the part a colour bar shows, from the slowest to the fastest velocity any material point takes."""

    centre: float
    bound: float
    shown: tuple[float, float] | None = None

    @property
    def limits(self) -> tuple[float, float]:
        """The scale's two ends as velocities: tanh(atanh(centre) -+ bound), always inside (-c, c)."""
        eta = math.atanh(self.centre)
        return math.tanh(eta - self.bound), math.tanh(eta + self.bound)

    @property
    def ends(self) -> tuple[float, float]:
        """The velocities a colour bar spans: `shown`, or the limits for a rod that never turns."""
        return self.shown or self.limits


def colour_scale(history: RodHistory, frame: Frame) -> ColourScale:
    """Centred on the rod's velocity in `frame` before any impact; bound the largest distance in rapidity from it
    of any material point's velocity over the whole history, so the colours mean the same at every instant."""
    centre = frame.rod_velocity()
    eta = frame.rapidity
    rapidities = [r - eta for r in history.rapidity_range()]
    bound = max(abs(r - math.atanh(centre)) for r in rapidities)
    # a rod that never changes velocity, seen from a frame that leaves an ulp between its velocity and the centre
    # (fig1 from u = 0.3: -0.30000000000000004 against -0.3): still, not a scale zero wide
    if bound <= 0 or max(rapidities) - min(rapidities) <= DIFFERENCE_ROUNDING:
        return ColourScale(centre, STILL_BOUND)
    # a velocity is the scale's coordinate: past rapidity FASTEST_COLOUR it rounds to c (the causal rod's ends at
    # v = 0.999 seen from S'), where the norm's arctanh is infinite; the colours end at FASTEST_COLOUR
    bound = min(bound, FASTEST_COLOUR - abs(math.atanh(centre)))
    low, high = max(min(rapidities), -FASTEST_COLOUR), min(max(rapidities), FASTEST_COLOUR)
    return ColourScale(centre, bound, (math.tanh(low), math.tanh(high)))


def shared_scale(histories, frame: Frame) -> ColourScale:
    """One scale for rods compared in one frame (the rigid and the causal rod driven by the same forces): every
    rod starts at the frame's first velocity (the centre); the widest bound; `shown` from the slowest to the fastest
    velocity any of them takes (None where none changes), so a colour is one velocity in every rod's rows."""
    scales = [colour_scale(h, frame) for h in histories]
    shown = [s.shown for s in scales if s.shown is not None]
    return ColourScale(scales[0].centre, max(s.bound for s in scales),
                       (min(a for a, _ in shown), max(b for _, b in shown)) if shown else None)
