"""The strip's colour scale (README, "The paradox in motion"): which velocity of the rod's material points each
colour means, in one frame, the same at every instant of the history. Pure: no matplotlib, so the animation's
timeline reads it before anything is drawn; `render.strip` maps it to a colour map.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from rodparadox.physics.engine import History
from rodparadox.physics.frames import Frame
from rodparadox.physics.snapshot import rod_rapidities
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


def colour_scale(history: History, frame: Frame) -> ColourScale:
    """Centred on the rod's velocity in `frame` before any impact; bound the largest distance in rapidity from it
    of any material point's velocity over the whole history, so the colours mean the same at every instant."""
    centre = frame.rod_velocity()
    eta = frame.rapidity
    extremes = causal_rapidity_range(history) if getattr(history, "kind", "") == "causal" else rod_rapidities(history)
    rapidities = [r - eta for r in extremes]
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


# --- the causal rod (README, "The causal rod"): its fields' extremes over its whole history ---------------------

def _chart_extremes(history) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """r+(u), r-(w) on a grid of each invariant's pieces (both sides of every jump, and inside), over the whole
    history (the ringing tail is periodic: one period of it is all of it), and which (u, w) pairs lie in the rod."""
    sol, L = history.solution, history.scenario.L
    lo = min(sol.plus.starts[0], sol.minus.starts[0]) - 2 * L
    hi = max(sol.plus.tail_start, sol.minus.tail_start) + 3 * L
    us, ws = _knots(sol.plus, lo, hi), _knots(sol.minus, lo, hi)
    rp = np.array([sol.r_plus(u) for u in us])
    rm = np.array([sol.r_minus(w) for w in ws])
    inside = (us[None, :] - ws[:, None] >= -1e-12) & (us[None, :] - ws[:, None] <= 2 * L + 1e-12)
    return rp, rm, inside


def _knots(invariant, lo: float, hi: float) -> np.ndarray:
    cuts = [lo, *invariant.breaks(lo, hi), hi]
    out = []
    for a, b in zip(cuts, cuts[1:]):
        out += list(np.linspace(a, b, 9)[:-1]) + [np.nextafter(b, -math.inf)]
    return np.array(out)


@functools.lru_cache(maxsize=16)
def compression_range(history) -> tuple[float, float]:
    """The least and largest ln lam (lam = exp(-(r+ + r-)/2)) anywhere in the causal rod over its whole history,
    with 0 (unstressed) always inside."""
    rp, rm, inside = _chart_extremes(history)
    ln_lam = -0.5 * (rp[None, :] + rm[:, None])
    return float(min(0.0, ln_lam[inside].min())), float(max(0.0, ln_lam[inside].max()))


@functools.lru_cache(maxsize=16)
def causal_rapidity_range(history) -> tuple[float, float]:
    """The least and largest rapidity in S (th = (r+ - r-)/2) of any material point of the causal rod, 0 included."""
    rp, rm, inside = _chart_extremes(history)
    th = 0.5 * (rp[None, :] - rm[:, None])
    return float(min(0.0, th[inside].min())), float(max(0.0, th[inside].max()))
