"""The world-lines of a driven rigid rod's material points, stage by stage (`driven`): each a `Line` or a
`HyperbolicArc` where the stage's alpha is constant, else a `DrivenArc`, exact to the stage's tolerance at any tau
and in any frame. Pure; numpy only."""

from __future__ import annotations

import math

import numpy as np

from rodparadox.physics.kinematics import Event, HyperbolicArc, Line
from rodparadox.physics.rigid.driven import CLOSED_FORM_ALPHA, PHI, T_, X_, ConstantStage, Stage, rising_root


class DrivenArc:
    """The world-line of the material point sigma during one stage, tau in [tau0, tau1], seen from the frame of
    rapidity f: the event z(tau) + sigma (sinh phi, cosh phi) of S, boosted; its rapidity phi(tau) - f. Exact to the
    stage's tolerance at every tau (`Stage.state`). Proper time along it is (tau - tau0) + sigma (phi - phi0)."""

    def __init__(self, stage: Stage, sigma: float, tau0: float, tau1: float, f: float = 0.0, scale: float = 1.0):
        self.stage, self.sigma, self.tau0, self.tau1, self.f, self.scale = stage, sigma, tau0, tau1, f, scale
        self._last_time = None  # (t, its sign, tau_at_time(t)): a strip reads the event, then the rapidity, at one t

    def point(self, tau: float) -> Event:
        y = self.stage.state(tau)[0]
        k = self.scale
        return Event(float(k * (y[X_] + self.sigma * math.cosh(y[PHI]))),
                     float(k * (y[T_] + self.sigma * math.sinh(y[PHI])))).seen_from(self.f)

    def points(self, tau) -> np.ndarray:
        """(n, 2) array of [x, t] at many tau."""
        Y = self.stage.state(tau)
        x = self.scale * (Y[:, X_] + self.sigma * np.cosh(Y[:, PHI]))
        t = self.scale * (Y[:, T_] + self.sigma * np.sinh(Y[:, PHI]))
        c, s = math.cosh(self.f), math.sinh(self.f)
        return np.column_stack([c * x - s * t, c * t - s * x])

    def rapidity(self, tau: float) -> float:
        return float(self.stage.state(tau)[0, PHI]) - self.f

    @property
    def start(self) -> Event:
        return self.point(self.tau0)

    @property
    def end(self) -> Event:
        return self.point(self.tau1)

    @property
    def rapidity_at_start(self) -> float:
        return self.rapidity(self.tau0)

    @property
    def rapidity_at_end(self) -> float:
        return self.rapidity(self.tau1)

    def seen_from(self, frame_rapidity: float) -> "DrivenArc":
        return DrivenArc(self.stage, self.sigma, self.tau0, self.tau1, self.f + frame_rapidity, self.scale)

    def _time(self, tau: float) -> float:
        """`point(tau).t`, the same number, without its two Events (a root's every step reads it)."""
        y = self.stage.state(tau)[0]
        k = self.scale
        x = float(k * (y[X_] + self.sigma * math.cosh(y[PHI])))
        t = float(k * (y[T_] + self.sigma * math.sinh(y[PHI])))
        return math.cosh(self.f) * t - math.sinh(self.f) * x

    def tau_at_time(self, t: float) -> float:
        """The tau at which the arc is at time t of its frame (clamped to the arc); the last one kept."""
        last = self._last_time
        if last is not None and last[0] == t and last[1] == math.copysign(1.0, t):
            return last[2]
        tau = rising_root(lambda tau: self._time(tau) - t, self.tau0, self.tau1)
        self._last_time = (t, math.copysign(1.0, t), tau)
        return tau

    def event_at_time(self, t: float) -> Event:
        return self.point(self.tau_at_time(t))

    def phi_at_time(self, t: float) -> float:
        return self.rapidity(self.tau_at_time(t))

    def clipped(self, t_lo: float, t_hi: float) -> "DrivenArc | None":
        a = self.tau0 if t_lo <= self.start.t else self.tau_at_time(t_lo)
        b = self.tau1 if t_hi >= self.end.t else self.tau_at_time(t_hi)
        return DrivenArc(self.stage, self.sigma, a, b, self.f, self.scale) if b > a else None

    def proper_duration(self) -> float:
        return self.proper_duration_to_tau(self.tau1)

    def proper_duration_to_tau(self, tau: float) -> float:
        phi = self.stage.state([self.tau0, tau])[:, PHI]
        return self.scale * ((tau - self.tau0) + self.sigma * float(phi[1] - phi[0]))

    def proper_duration_to(self, t: float) -> float:
        return self.proper_duration_to_tau(self.tau_at_time(t))

    def at_proper_time(self, s: float) -> Event:
        return self.point(rising_root(lambda tau: self.proper_duration_to_tau(tau) - s, self.tau0, self.tau1))

    def sample(self, tolerance: float) -> np.ndarray:
        """Points whose polyline lies within `tolerance` of the arc: every piece of tau whose chord is farther than
        `tolerance` from the point at its middle is halved (all pieces at once), from 4 pieces on."""
        taus = np.linspace(self.tau0, self.tau1, 5)
        pts = self.points(taus)
        for _ in range(40):
            mids = 0.5 * (taus[:-1] + taus[1:])
            pm = self.points(mids)
            d = pts[1:] - pts[:-1]
            chord = np.hypot(d[:, 0], d[:, 1])
            cross = np.abs(d[:, 0] * (pm[:, 1] - pts[:-1, 1]) - d[:, 1] * (pm[:, 0] - pts[:-1, 0]))
            with np.errstate(invalid="ignore", divide="ignore"):
                error = np.where(chord > 0, cross / chord, 0.0)
            split = error > tolerance
            if not np.any(split):
                break
            taus = np.insert(taus, np.nonzero(split)[0] + 1, mids[split])
            pts = np.insert(pts, np.nonzero(split)[0] + 1, pm[split], axis=0)
        return pts


def _end_states(stage: Stage) -> np.ndarray:
    """`stage.state([stage.tau0, stage.tau1])`, kept on the stage for its ends: a strip's material points (96 of
    them) each ask for it, stage by stage. Read-only, as it is shared."""
    kept = getattr(stage, "_ends", None)
    if kept is None or kept[0] != (stage.tau0, stage.tau1):
        states = stage.state([stage.tau0, stage.tau1])
        states.flags.writeable = False
        kept = stage._ends = ((stage.tau0, stage.tau1), states)
    return kept[1]


def stage_piece(stage: Stage, sigma: float, scale: float = 1.0):
    """The material point sigma (units of L) world-line in S during the stage, for a rod of length `scale`: a Line,
    a HyperbolicArc or a DrivenArc."""
    y0, y1 = _end_states(stage)
    k = scale
    e0 = Event(float(k * (y0[X_] + sigma * math.cosh(y0[PHI]))), float(k * (y0[T_] + sigma * math.sinh(y0[PHI]))))
    e1 = Event(float(k * (y1[X_] + sigma * math.cosh(y1[PHI]))), float(k * (y1[T_] + sigma * math.sinh(y1[PHI]))))
    if isinstance(stage, ConstantStage):
        a = stage.a
        if a == 0.0:
            return Line(e0, e1)
        if abs(a) >= CLOSED_FORM_ALPHA:
            centre = Event(float(k * (y0[X_] - math.cosh(y0[PHI]) / a)), float(k * (y0[T_] - math.sinh(y0[PHI]) / a)))
            radius = k * abs(1.0 / a + sigma)
            return HyperbolicArc(centre, radius, 1 if a > 0 else -1, float(y0[PHI]), float(y1[PHI]))
    return DrivenArc(stage, sigma, stage.tau0, stage.tau1, 0.0, scale)
