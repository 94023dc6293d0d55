"""A run of the causal rod driven by forces at its ends (docs/model.md, "Forces at the ends"). Pure.

`run_forces(scenario)` solves the driven ends (`causal.driven`) and returns a `DrivenHistory`: the rod interface
(`history.RodHistory`) with the capability `fronts` (its chart, compression, matter and stress) and what the
forces add, `driving` (what each agent delivered up to a slice's end events). No particles: `impacts` and
`starts` are empty. Before the first force the rod rests in S (chart T = t, X = x + L/2); after the last it
rings for ever, as after a last separation.

Conservation with forces: on every slice of every frame the rod's (E, p) = its initial M (cosh, sinh)(-f) plus
what both agents delivered up to the slice's end events; `energy_momentum(...).hidden` is what is missing from
that sum (zero to rounding: nothing is hidden in the causal rod).
"""

from __future__ import annotations

import math

import numpy as np

from rodparadox.errors import ScenarioError
from rodparadox.physics.causal.budget import Budget
from rodparadox.physics.causal.driven import Drive, Work, solve_forces
from rodparadox.physics.causal.history import CONSERVED, CausalHistory
from rodparadox.physics.forces import centre_velocity
from rodparadox.physics.kinematics import ChartCurve
from rodparadox.physics.types import FORCE_MOMENTS, EnergyMomentum, ForceEvent, Slice

#: the work a forced run may take (windows, stretches, steps) when no budget is asked for
FORCED_BUDGET = 20000


def _profiles(scenario) -> dict:
    """Each end's profile (`forces.ForceProfile`), None where no force acts."""
    return {end: scenario.forces.at(end) for end in ("left", "right")}


def run_forces(scenario, budget: int | None = None) -> "DrivenHistory":
    """The causal rod's history under the scenario's forces; `budget`: a bound on its work (`budget.Budget`), by
    default FORCED_BUDGET. Refused in one sentence: a pull at or beyond M c^2/(2L), a run past its budget, a run
    double precision cannot keep to CONSERVED."""
    L = scenario.L
    scenario.forces.check_pull("causal")
    drives = {end: None if profile is None else
              Drive(profile.scaled(L), math.atanh(profile.frame_velocity(scenario.v)), L)
              for end, profile in _profiles(scenario).items()}
    spend = Work(FORCED_BUDGET) if budget is None else Budget(budget)
    history = DrivenHistory(scenario, solve_forces(L, drives, spend))
    _check_conserved(history)
    return history


def _check_conserved(history: "DrivenHistory") -> None:
    """Refuse a run whose ledger double precision cannot keep to CONSERVED, after the last force, in S and S'."""
    scenario = history.scenario
    last = max(T for T in history.solution.last.values() if math.isfinite(T))
    for f in (0.0, -math.atanh(scenario.v)):
        t = max(history._end_event(e, last).seen_from(f).t for e in ("left", "right")) + scenario.L
        missing = history.energy_momentum(f, t).hidden
        initial = history.initial_total(f)
        worst = max(abs(missing.T), abs(missing.p)) / (initial.rest + initial.T + history.driving.scale(f))
        if not worst <= CONSERVED:
            raise ScenarioError(f"the causal rod's run keeps energy and momentum only to {worst:.0e} of the total "
                                f"in double precision (its compressions are too extreme with these forces); choose "
                                f"smaller or shorter forces.", "forces")


class Driving:
    """What the forces add to a run (the capability `driving`, `history.Driving`): the profiles, what each agent
    delivered up to a slice's end events, the force and the stress on a slice, each force's start, peak and end.
    The causal rod has no lines of simultaneity of its own: `now_lines` is empty."""

    def __init__(self, history: "DrivenHistory"):
        self.history = history
        self._drives = history.solution.drives
        self._force_events = None

    @property
    def forces(self):
        return self.history.scenario.forces

    def profiles(self) -> tuple:
        """(end, `forces.ForceProfile`) for each end with a force, left first."""
        return self.forces.items()

    def frame_rapidity(self, end: str) -> float:
        """The rapidity relative to S of the frame the end's profile is timed in."""
        return math.atanh(self.forces.at(end).frame_velocity(self.history.scenario.v))

    def delivered(self, end: str, frame_rapidity: float, t: float) -> EnergyMomentum:
        """The (E, p), in the frame, the agent at `end` delivered up to the end's event on the slice t: +-F (dx, dt)
        integrated along the end, from I_U = int F dU and I_V = int F dV (zero for an end without force)."""
        return self.delivered_at(end, frame_rapidity, self.history.end_chart_time(end, frame_rapidity, t))

    def delivered_at(self, end: str, frame_rapidity: float, T: float) -> EnergyMomentum:
        """The same up to the end's chart time T."""
        I_z, I_y = self.history.solution.delivered[end].at(T)
        I_U, I_V = (I_z, I_y) if end == "left" else (I_y, I_z)
        ef = math.exp(frame_rapidity)
        sign = 1.0 if end == "left" else -1.0
        return EnergyMomentum(0.0, 0.5 * sign * (I_U / ef - ef * I_V), 0.5 * sign * (I_U / ef + ef * I_V))

    def total(self, frame_rapidity: float, t: float) -> EnergyMomentum:
        """The rod's (E, p) before the forces plus what both agents delivered up to the slice: what it holds."""
        return (self.history.initial_total(frame_rapidity) + self.delivered("left", frame_rapidity, t)
                + self.delivered("right", frame_rapidity, t))

    def scale(self, frame_rapidity: float) -> float:
        """The size of everything delivered in the frame (the scale conservation is checked against)."""
        return sum(abs(em.E) + abs(em.p) for em in (self.delivered_at(end, frame_rapidity, math.inf)
                                                    for end in ("left", "right")))

    def _profile_time(self, end: str, T: float) -> float:
        """The time, in the end's profile's frame, of the end's event at chart time T."""
        event = self.history._end_event(end, T)
        return self._drives[end].time(event.t + event.x, event.t - event.x)

    def force_at(self, end: str, frame_rapidity: float, t: float) -> float:
        """The force at the end's event on the slice t of the frame (units of M c^2/L)."""
        profile = self.forces.at(end)
        if profile is None:
            return 0.0
        T = self.history.end_chart_time(end, frame_rapidity, t)
        return float(profile.value(self._profile_time(end, T) / self.history.scenario.L))

    def stress(self, frame_rapidity: float, t: float, sigmas) -> np.ndarray:
        """The pressure p = (rho0/2)(lam^2 - 1) (units of M c^2/L, > 0 compression) at each material point sigma
        where it crosses the slice."""
        sol, out = self.history.solution, []
        for sigma in np.atleast_1d(np.asarray(sigmas, dtype=float)):
            T = ChartCurve(sol, float(sigma), -math.inf, math.inf, frame_rapidity).chart_time(t)
            out.append(0.5 * (math.exp(-(sol.r_plus(T + sigma) + sol.r_minus(T - sigma))) - 1.0))
        return np.array(out)

    def centre_of_energy(self, frame_rapidity: float, t: float) -> tuple[float, float]:
        """The rod's centre of energy on the slice t of the frame, x_E = int x e dx / int e dx, and its energy.
        With T_UV = rho0/4, T_UU = (rho0/4) e^(-2 r+), T_VV = (rho0/4) e^(-2 r-) (`causal.history`), e dx on the
        slice is (rho0/2) dx + (rho0/4) e^(f - r+) du + (rho0/4) e^(-f - r-) dw, and x there is e^-f a(u) - t on
        the light line u, t - e^f b(w) on the light line w: one-variable integrals over the invariants' pieces."""
        h, f, t = self.history, float(frame_rapidity), float(t)  # Python floats: numpy scalars cost more, same floats
        sol, L = h.solution, h.scenario.L
        T_L, T_R = h.end_chart_time("left", f, t), h.end_chart_time("right", f, t)
        ef, rho0 = math.exp(f), 1.0 / L
        x_L = ChartCurve(sol, 0.0, T_L, T_L, f).point(T_L).x
        x_R = ChartCurve(sol, L, T_R, T_R, f).point(T_R).x

        def plus(u: float) -> tuple[float, float]:
            weight = math.exp(f - sol.r_plus(u))
            return weight, (sol.a(u) / ef - t) * weight

        def minus(w: float) -> tuple[float, float]:
            weight = math.exp(-f - sol.r_minus(w))
            return weight, (t - ef * sol.b(w)) * weight

        I_plus, J_plus = _integral(plus, T_L, T_R + L, sol.plus.breaks(T_L, T_R + L), L)
        I_minus, J_minus = _integral(minus, T_R - L, T_L, sol.minus.breaks(T_R - L, T_L), L)
        E = 0.5 * rho0 * (x_R - x_L) + 0.25 * rho0 * (I_plus + I_minus)
        moment = 0.25 * rho0 * (x_R * x_R - x_L * x_L) + 0.25 * rho0 * (J_plus + J_minus)
        return moment / E, E

    def centre_velocity(self, frame_rapidity: float, t: float) -> float:
        """d x_E / dt on the slice t of the frame (`forces.centre_velocity`, over 1e-3 L)."""
        return centre_velocity(lambda s: self.centre_of_energy(frame_rapidity, s), t, 1e-3 * self.history.scenario.L)

    def now_lines(self, count: int = 12) -> list:
        """None: the causal rod's lines of simultaneity are not its own (its signals run at c)."""
        return []

    def _chart_time_at(self, end: str, instant: float) -> float:
        """The chart time at which the end's profile time is `instant` (t_F rises along the end)."""
        L = self.history.scenario.L
        lo, hi = -L, L
        while self._profile_time(end, lo) > instant:
            lo, hi = lo - 2.0 * (hi - lo), lo
        while self._profile_time(end, hi) < instant:
            lo, hi = hi, hi + 2.0 * (hi - lo)
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if mid in (lo, hi):
                break
            lo, hi = (mid, hi) if self._profile_time(end, mid) < instant else (lo, mid)
        return hi

    def force_events(self) -> tuple:
        """Each force's start, peak and end at its end, in S (`_computed_force_events`), computed once per run: the
        page and the tables ask for them several times."""
        if self._force_events is None:
            self._force_events = self._computed_force_events()
        return self._force_events

    def _computed_force_events(self) -> tuple:
        """Each force's start, peak and end at its end (`types.ForceEvent`, in S): the end's rapidity just after the
        start and the peak, just before the end (a step's switch-on and -off are fronts: it jumps there)."""
        history, out = self.history, []
        L = history.scenario.L
        for end, profile in self.profiles():
            X = 0.0 if end == "left" else L
            first, last = profile.support()
            for moment, instant in zip(FORCE_MOMENTS, (first, profile.peak_time(), last)):
                T = self._chart_time_at(end, instant * L)
                side = math.nextafter(T, -math.inf if moment == "end" else math.inf)
                rapidity = ChartCurve(history.solution, X, side, side).rapidity(side)
                force = (profile.piece_value(profile.piece_index(instant) - 1, instant) if moment == "end"
                         else profile.value(instant))
                out.append(ForceEvent(end, moment, history._end_event(end, T), rapidity, float(force), instant))
        return tuple(out)


_GAUSS_X, _GAUSS_W = np.polynomial.legendre.leggauss(16)


def _integral(g, lo: float, hi: float, breaks, L: float) -> tuple[float, float]:
    """Both components of g (a pair) integrated over [lo, hi], split at `breaks` (where g jumps or kinks), Gauss-
    Legendre on each piece halved until its halves agree with it to 1e-13 L."""

    def gauss(a: float, b: float) -> np.ndarray:
        values = np.array([g(float(s)) for s in 0.5 * (a + b) + 0.5 * (b - a) * _GAUSS_X])
        return 0.5 * (b - a) * (_GAUSS_W @ values)

    def adaptive(a: float, b: float, whole: np.ndarray, depth: int) -> np.ndarray:
        mid = 0.5 * (a + b)
        left, right = gauss(a, mid), gauss(mid, b)
        if depth >= 30 or np.max(np.abs(left + right - whole)) <= 1e-13 * (L + np.max(np.abs(whole))):
            return left + right
        return adaptive(a, mid, left, depth + 1) + adaptive(mid, b, right, depth + 1)

    cuts = [lo, *(s for s in breaks if lo < s < hi), hi]
    total = np.zeros(2)
    for a, b in zip(cuts, cuts[1:]):
        if b > a:
            total += adaptive(a, b, gauss(a, b), 0)
    return float(total[0]), float(total[1])


class DrivenHistory(CausalHistory):
    """The rod interface for the causal rod driven by forces (`history.RodHistory`, capabilities `fronts` and
    `driving`). Coordinates in S, units of L, M = 1."""

    def __init__(self, scenario, solution):
        self.scenario, self.solution = scenario, solution
        self._end_times = {}
        self.starts = ()
        self.impacts = ()
        self._first_left, self._first_right = solution.first["left"], solution.first["right"]
        L = scenario.L
        self._ends = {"left": self.material_worldline(0.0), "right": self.material_worldline(L)}
        self.final_rapidity = self._final_rapidity()
        self._particles = {}
        self.driving = Driving(self)

    @property
    def last_separation(self) -> float:
        """Chart time the last force ends: the rod rings freely from then on."""
        return self.solution.plus.tail_start

    def energy_momentum(self, frame_rapidity: float, t: float, split: bool = False) -> Slice:
        """The rod's (E, p) on the slice t of the frame, and what is missing from the initial total plus what the
        agents delivered up to the slice's end events (zero to rounding); with `split`, its matter and stress."""
        rod = self.rod_energy_momentum(frame_rapidity, t)
        expected = self.driving.total(frame_rapidity, t)
        parts = ()
        if split:
            matter, stress = self.rod_parts(frame_rapidity, t)
            parts = (("matter", matter), ("stress", stress))
        return Slice(t, (("rod", rod),), rod, expected - rod, parts)

    def initial_total(self, frame_rapidity: float) -> EnergyMomentum:
        """The rod at rest in S before the first force: M (cosh, sinh)(-f)."""
        return EnergyMomentum.of(1.0, -frame_rapidity)
