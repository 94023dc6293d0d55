"""The rod's own view (`--frame rod`, docs "The rod's own view"): charts in which the rod is a fixed strip. Pure.

Not a Lorentz frame: a chart (T, X) of spacetime built from the rod's own motion, X the material label (the rod is
the strip 0 <= X <= L at every T), T the rod's own time. Each model gives its own chart (`RodHistory.own_chart`:
`rigid.chart.RigidChart`, `causal.chart.CausalChart`); every map is exact, and points are sampled only to draw.
This module holds what every chart shares: the view's word, a material clock, and polylines carried into a chart.
"""

from __future__ import annotations

import bisect
import functools
import math
from dataclasses import dataclass

import numpy as np

from rodparadox.errors import OptionError, ScenarioError
from rodparadox.physics.kinematics import Event
#: the rod's own view, as a frame word (`--frame rod`); not a Lorentz frame, so not a `frames.Frame`
ROD_WORD = "rod"


@dataclass(frozen=True)
class RodView:
    """The rod's own view, where a list of frames names it (`--frame rod,rest`): a panel in the rod's chart."""

    name: str = ROD_WORD


ROD_VIEW = RodView()

#: the teacher's extras (`render.Options`) that draw on the frames' panels only: the rod's own view shows none
FRAME_EXTRAS = ("other_axes", "light_cones", "hyperbolae", "grid", "rod_lines", "rod_now", "proper_time",
                "equal_scales")


def refuse_frame_extras(frames, **extras) -> None:
    """Extras asked for (`FRAME_EXTRAS`, true or non-zero) with no frame's panel to draw them on, every panel of
    `frames` the rod's own view: an OptionError naming the first, since the figure would be the one without it."""
    asked = [name for name in FRAME_EXTRAS if extras.get(name)]
    if asked and frames and all(frame == ROD_VIEW for frame in frames):
        raise OptionError(asked[0], extras[asked[0]], template="{what} draws on the frames' panels, and {frame} "
                          "{view} has only the rod's own view: leave it out, or give a frame beside it ({frame} "
                          "rest,{view}).", view=ROD_WORD)

@functools.cache
def _gauss_legendre() -> tuple[np.ndarray, np.ndarray]:
    """Gauss-Legendre nodes and weights for a material clock between fronts (the integrand is analytic there);
    made on first use: numpy.polynomial is not loaded by what never reads a clock (`--frame rod` does)."""
    return np.polynomial.legendre.leggauss(24)


def chart_of(history):
    """The rod's own chart for a history of any model (`RodHistory.own_chart`)."""
    return history.own_chart()


#: the longest span of the rod's own time its view shows, in units of L (the presets, at any speed: 2 to 36; a
#: particle 1e6 L away: 1.3e6, a sliver with every label on the next, issue 27)
MAX_VIEW_SPAN = 1000.0


def thin_view(span: float) -> ScenarioError:
    """The refusal of a rod's own view `span` L of chart time tall: too thin to read."""
    from rodparadox.numbers import shown

    return ScenarioError(f"the rod's own view would be {shown(span, 2)} L of the rod's time tall and 1 L wide, too "
                         f"thin to read (its events lie that far apart: a particle far from the rod, or a very small "
                         f"v); leave the rod's own view out, or bring the impacts within {MAX_VIEW_SPAN:g} L of each "
                         f"other.", "particles")


def refuse_thin_view(history) -> None:
    """Refuse (`thin_view`) the rod's own view of a history whose impacts alone span more than MAX_VIEW_SPAN of its
    chart time: said before anything is drawn or written (the view's box, `render.rod_panel.rod_box`, checks the
    same with everything it shows)."""
    L, chart = history.scenario.L, chart_of(history)
    times = [chart.to_chart(i.event)[0] / L for i in history.impacts]
    if times and max(times) - min(times) > MAX_VIEW_SPAN:
        raise thin_view(max(times) - min(times))


#: a clock whose first tick shown comes this many L after chart time 0, with the rod at rest until then, starts
#: there (its proper time so far is the chart time itself): at v = 1e-6 the first impact comes 5e5 L after 0, and
#: integrating the clock across that quiet stretch cost time growing as 1/v
QUIET_START = 64.0


def quiet_start(T_lo: float, quiet_until: float, L: float) -> tuple[float, float]:
    """Where a material clock counted from chart time 0 starts integrating, and its proper time there, the rod
    resting unstressed in S up to chart time `quiet_until`."""
    start = min(T_lo, quiet_until)
    if start > QUIET_START * L:
        return start, start  # at rest, unstressed, since chart time 0: d tau = dT
    return min(0.0, T_lo), 0.0


#: the most Gauss-Legendre spans between two knots of a clock's rate: a rate smooth over a long stretch (the rigid
#: rod at rest for 1e6 L while a far particle comes) needs no more, and 4 a crossing time would be millions
MAX_SPANS = 64


class Clock:
    """A material clock from chart time T0 to T1: d tau / dT = rate(T), smooth between the knots (the fronts, or a
    turn's ends), integrated by Gauss-Legendre on spans of at most L / 4; tau(0) = 0 when 0 lies in the span."""

    def __init__(self, rate, breaks, T0: float, T1: float, L: float, offset: float = 0.0):
        self.rate = rate
        knots = [T0]
        for b in [*sorted(breaks), T1]:
            a = knots[-1]
            if b <= a:
                continue
            n = min(MAX_SPANS, max(1, math.ceil((b - a) / (0.25 * L))))
            knots += [a + (b - a) * (k + 1) / n for k in range(n)]
        self.knots = knots
        self.taus = [offset]  # the proper time at T0 (0 unless counted from before T0: `quiet_start`)
        for a, b in zip(knots, knots[1:]):
            self.taus.append(self.taus[-1] + self._integral(a, b))
        self.total = self.taus[-1]
        self.zero = self.tau(0.0) if T0 <= 0.0 <= T1 else 0.0

    def _integral(self, a: float, b: float) -> float:
        mid, half = 0.5 * (a + b), 0.5 * (b - a)
        return half * sum(w * self.rate(mid + half * s) for s, w in zip(*_gauss_legendre()))

    def tau(self, T: float) -> float:
        k = max(0, min(len(self.knots) - 2, bisect.bisect_right(self.knots, T) - 1))
        return self.taus[k] + self._integral(self.knots[k], T)

    def ticks(self, step: float, T_lo: float) -> list[tuple[float, float]]:
        """(tau, T) where tau crosses each multiple of step, T >= T_lo: Newton in each span, kept in its bracket."""
        out: list[tuple[float, float]] = []
        for k, (a, b) in enumerate(zip(self.knots, self.knots[1:])):
            tau_a, tau_b = self.taus[k] - self.zero, self.taus[k + 1] - self.zero
            n = math.ceil(tau_a / step - 1e-12)
            while tau_b > tau_a and n * step <= tau_b + 1e-12 * step:
                target, lo, hi = n * step, a, b
                T = a + (b - a) * (target - tau_a) / (tau_b - tau_a)
                for _ in range(60):
                    f = tau_a + self._integral(a, T) - target
                    if abs(f) <= 1e-14 * (1 + abs(target)):
                        break
                    lo, hi = (T, hi) if f < 0 else (lo, T)
                    rate = self.rate(T)
                    T = T - f / rate if rate > 0 and lo < T - f / rate < hi else 0.5 * (lo + hi)
                if T >= T_lo and (not out or target > out[-1][0] + 1e-12 * step):
                    out.append((target, T))
                n += 1
        return out

# --- lines carried into a chart ------------------------------------------------------------------------------------

def chart_polyline(chart, points: np.ndarray) -> np.ndarray:
    """An (n, 2) array of [x, t] points in S as [X, T] chart points (each event where `chart.placed` puts it), a row
    of NaN (a break in a drawn line) where an
    event is beyond a horizon and between two points on either side of a turn (a line through a turn's pivot
    leaves it at the turn's end, where it arrived at the start)."""
    out, last = [], None
    for x, t in points:
        e = Event(float(x), float(t))
        found = chart.placed(e)
        if not found:
            out.append((math.nan, math.nan))
            last = None
            continue
        T, X, piece = min(found, key=lambda f: abs(f[2] - last)) if last is not None else found[0]
        if last is not None and abs(piece - last) > 1:
            out.append((math.nan, math.nan))
        if len(found) > 1 and last is not None:  # a pivot reached: the line goes on from the turn's end
            out.append((X, T))
            T, X, piece = max(found, key=lambda f: f[2])
            out.append((math.nan, math.nan))
        out.append((X, T))
        last = piece
    return np.array(out, dtype=float).reshape(-1, 2)


def densified(points: np.ndarray, spacing: float) -> np.ndarray:
    """The polyline with points added along each chord, at most `spacing` apart (a chart map bends straight lines)."""
    out = [points[:1]]
    for p, q in zip(points[:-1], points[1:]):
        n = max(1, math.ceil(float(np.hypot(*(q - p))) / spacing))
        out.append(p + np.outer(np.arange(1, n + 1) / n, q - p))
    return np.concatenate(out)
