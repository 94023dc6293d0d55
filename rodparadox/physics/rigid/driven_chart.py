"""The rigid rod driven by forces in its own chart (the rod's own view, `--frame rod`). Pure.

Born-rigid motion is fixed by the left end's world-line z(tau) (tau its proper time, phi its rapidity): the rod's
"now" at tau is the normal line through z(tau), on which the material point at proper distance X from the left end
is z(tau) + X (cosh phi, sinh phi) in (x, t). The chart is (T, X): X that distance (the rod is the strip 0 <= X <= L
at every T), T the left end's proper time, counted so that T = t of S while the rod rests in S before the first
force. Every level line T is one of the rod's own lines of simultaneity, as in the struck rigid rod's chart. The map
is exact (the history's own solution); an event of the rod is found on its normal line by Newton's method on
g(tau) = dx sinh phi - dt cosh phi (d = the event minus z(tau)), whose slope 1 + alpha X is positive throughout the
rod: the pull limits keep each normal line's crossing with its neighbours (at X = -1/alpha) off the rod. A material
point's clock runs d tau_X = (1 + alpha X) dT.
"""

from __future__ import annotations

import math

import numpy as np

from rodparadox.physics.kinematics import Event
from rodparadox.physics.rigid.driven import PHI, T_, X_, CollocatedStage
from rodparadox.physics.rod_view import Clock, quiet_start

#: an event this far outside the rod (in units of L, X below 0 or above L) is still placed: rounding of its ends
EDGE = 1e-9
#: at most this many chart times' alpha kept (`DrivenChart.alpha`): the clocks of the rod's material points read it
#: at the same Gauss-Legendre nodes of each span, one clock after another
KEEP_ALPHAS = 20_000


class DrivenChart:
    """The rigid driven rod's own chart (module docstring): `to_chart`, `placed`, `to_event`, the clocks."""

    turns: tuple = ()  # a driven rod's lines of simultaneity turn smoothly: no turn of rule 3, no pivot

    def __init__(self, history):
        self.history, self.L = history, history.scenario.L
        self._T0 = float(history._y0[0, T_])  # chart time (units of L) of tau = 0: the first force's start
        taus = list(history._tau0)
        for stage in history.stages:
            if isinstance(stage, CollocatedStage):
                taus.extend(stage.step_bounds())
        self._breaks = sorted(self.L * (tau + self._T0) for tau in taus)  # where alpha may have a kink or a jump
        self._alphas: dict[tuple[float, float], float] = {}  # alpha at the chart times asked for (`alpha`)

    def _tau(self, T: float) -> float:
        return T / self.L - self._T0

    def alpha(self, T: float) -> float:
        """The left end's proper acceleration (units of 1/L) at chart time T."""
        key = (T, math.copysign(1.0, T))
        kept = self._alphas.get(key)
        if kept is None:
            if len(self._alphas) >= KEEP_ALPHAS:
                self._alphas.clear()
            _, a, _ = self.history._motion_alpha_forces(np.array([self._tau(T)]))  # alpha of the state: computed once
            kept = self._alphas[key] = float(a[0])
        return kept

    def to_event(self, T: float, X: float) -> Event | None:
        """The event at (T, X) (units of the scenario), or None off the rod."""
        s = X / self.L
        if not -EDGE <= s <= 1 + EDGE:
            return None
        Y = self.history._states(np.array([self._tau(T)]))[0]
        return Event(self.L * float(Y[X_] + s * math.cosh(Y[PHI])), self.L * float(Y[T_] + s * math.sinh(Y[PHI])))

    def to_chart(self, e: Event) -> tuple[float, float] | None:
        """(T, X) of an event of the rod's world-sheet, or None off it."""
        h = self.history
        ex, et = e.x / self.L, e.t / self.L

        def g_s(tau: float) -> tuple[float, float, float]:
            Y = h._states(np.array([tau]))[0]
            dx, dt = ex - Y[X_], et - Y[T_]
            ch, sh = math.cosh(Y[PHI]), math.sinh(Y[PHI])
            return dx * sh - dt * ch, dx * ch - dt * sh, tau

        starts = [g_s(float(tau)) for tau in h._tau0]
        k = sum(1 for g, _, _ in starts if g <= 0.0) - 1
        if k < 0:  # at rest in S before the first force
            tau = et - float(h._y0[0, T_])
            s = ex - float(h._y0[0, X_])
        else:
            lo = float(h._tau0[k])
            hi = float(h._tau0[k + 1]) if k + 1 < len(h._tau0) else math.inf
            tau, s = self._newton(g_s, lo, hi)
        if not -EDGE <= s <= 1 + EDGE:
            return None
        return self.L * (tau + self._T0), self.L * s

    def _newton(self, g_s, lo: float, hi: float) -> tuple[float, float]:
        """The root of g in [lo, hi] (hi may be infinite: the last stage), g increasing there: Newton's method kept
        in its bracket, halving where a step would leave it."""
        tau = lo
        g, s, _ = g_s(tau)
        if g == 0.0:
            return tau, s
        for _ in range(200):
            slope = 1.0 + self.alpha(self.L * (tau + self._T0)) * s
            new = tau - g / slope if slope > 0 else math.nan
            if not lo < new < hi:
                new = 0.5 * (lo + hi) if math.isfinite(hi) else tau + 2.0 * (1.0 + abs(tau - lo))
            tau = new
            g, s, _ = g_s(tau)
            if g < 0.0:
                lo = tau
            elif g > 0.0:
                hi = tau
            if abs(g) <= 1e-15 * (1.0 + abs(tau)) or (math.isfinite(hi) and hi - lo <= 4e-16 * (1.0 + abs(tau))):
                break
        return tau, s

    def placed(self, e: Event) -> list[tuple[float, float, int]]:
        """Where the chart puts e, as (T, X, piece): one place on the rod, none off it."""
        found = self.to_chart(e)
        return [(found[0], found[1], 0)] if found is not None else []

    def beyond_horizon(self, e: Event) -> bool:
        return self.to_chart(e) is None

    def _clock(self, X: float, T0: float, T1: float, offset: float = 0.0) -> Clock:
        s = X / self.L
        breaks = [b for b in self._breaks if T0 < b < T1]
        return Clock(lambda T: 1.0 + self.alpha(T) * s, breaks, T0, T1, self.L, offset)

    def proper_time(self, X: float, T0: float, T1: float) -> float:
        """The proper time of material point X from chart time T0 to T1: the integral of (1 + alpha X) dT."""
        return self._clock(X, T0, T1).total if T1 > T0 else 0.0

    def clock_ticks(self, X: float, step: float, T_lo: float, T_hi: float) -> list[tuple[float, float]]:
        """(proper time, chart time) of material point X's clock ticks every `step`, counted from chart time 0."""
        lo, offset = quiet_start(T_lo, self._breaks[0] if self._breaks else math.inf, self.L)
        return self._clock(X, lo, T_hi, offset).ticks(step, T_lo)
