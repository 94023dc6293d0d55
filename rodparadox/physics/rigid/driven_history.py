"""The rigid rod driven by forces as a `RodHistory` (docs/model.md, "Forces at the ends"), with the `driving`
capability: the profiles, the momentum each agent delivered up to a slice, the force events, the stress. Pure.

Energy and momentum on the slice t of a frame (rapidity f): each material point sigma crosses it at rapidity psi
(that of the normal line it is on there) and stress p; the rod's T^{0 mu} = rho0 u^0 u^mu + p (eta^{0 mu} + u^0
u^mu) integrated over the slice, with dx = d sigma / cosh psi, splits into its *kinetic* part (M/L) int (cosh psi,
sinh psi) d sigma and its *stress* part int p tanh psi (sinh psi, cosh psi) d sigma (Sears's hidden momentum, zero on
the rod's own lines of simultaneity, where psi = 0 in the rod's frame). Together they equal the rod's (E, p) before
the forces plus what the two agents delivered up to the slice's end events (`Driving.delivered`). The integrals are
Gauss-Legendre sums on the pieces of [0, L] between the normal lines where a stage or a step begins (there the
integrand is analytic).
"""

from __future__ import annotations

import math

import numpy as np

from rodparadox.physics.forces import ENDS, ForceProfile, Forces, centre_velocity
from rodparadox.physics.kinematics import Event, WorldLine
from rodparadox.physics.model import Scenario
from rodparadox.physics.rigid.driven import (EL, ER, PHI, PL, PR, T_, X_, Drive, CollocatedStage, ConstantStage, GAUSS_W,
                                             GAUSS_X, Solution, solve)
from rodparadox.physics.rigid.driven_worldlines import stage_piece
from rodparadox.physics.types import FORCE_MOMENTS, EnergyMomentum, ForceEvent, Slice

#: at most this many slices' nodes kept per history (`DrivenHistory.slice_nodes`): a ledger's row reads its slice's
#: parts, then its centre of energy; a handout's key slice is read twice. A slice is a pure function of (frame, t).
KEEP_SLICES = 1024

def run_forces(scenario: Scenario) -> "DrivenHistory":
    """The rigid rod of the scenario driven by its forces."""
    scenario.forces.check_pull("rigid")
    return DrivenHistory(scenario)


class DrivenHistory:
    """A run of the rigid rod driven by forces at its ends (the rod interface, `physics.history.RodHistory`)."""

    model = "rigid"
    fronts = None
    turning = None
    impacts: tuple = ()
    starts: tuple = ()

    def __init__(self, scenario: Scenario):
        self.scenario = scenario
        self.L = scenario.L
        drives = {end: Drive(end, p, math.atanh(p.frame_velocity(scenario.v))) for end, p in scenario.forces.items()}
        self.solution: Solution = solve(1.0, drives)
        stages = self.solution.stages
        self.stages = stages
        self._tau0 = np.array([st.tau0 for st in stages])
        self._y0 = np.array([st.state(st.tau0)[0] for st in stages])
        self.final_rapidity = float(self._y0[-1, PHI])
        self.driving = Driving(self)
        self._chart = None
        self._cut_states = None  # the states where a stage or a step begins (`_cuts`), read on every slice
        self._slices: dict[tuple, dict[str, np.ndarray]] = {}  # the slices' nodes asked for (`slice_nodes`)

    # --- the interface ----------------------------------------------------------------------------------------------

    def own_chart(self):
        """The rod's own chart: T the left end's proper time, X the distance from it (`driven_chart.DrivenChart`),
        made once per history (it keeps the alpha its clocks read)."""
        if self._chart is None:
            from rodparadox.physics.rigid.driven_chart import DrivenChart

            self._chart = DrivenChart(self)
        return self._chart

    def worldline(self, name: str) -> WorldLine | None:
        if name == "rod_left":
            return self.material_worldline(0.0)
        if name == "rod_right":
            return self.material_worldline(self.L)
        return None

    def material_worldline(self, sigma: float) -> WorldLine:
        """The world-line in S of the material point at proper distance sigma from the left end."""
        s = sigma / self.L
        pieces = tuple(stage_piece(st, s, self.L) for st in self.stages[:-1] if st.tau1 > st.tau0)
        y0 = self._y0[0]
        origin = Event(float(self.L * (y0[X_] + s)), float(self.L * y0[T_]))
        return WorldLine(origin, 0.0, pieces, self.final_rapidity)

    def material_velocity(self, sigma: float, frame_rapidity: float, t: float) -> float:
        tau = self._crossings(np.array([sigma / self.L]), frame_rapidity, t / self.L)
        return math.tanh(float(self._states(tau)[0, PHI]) - frame_rapidity)

    def rapidity_range(self) -> tuple[float, float]:
        """The least and largest rapidity of the rod (all its points share it) over the history, 0 included."""
        values = [0.0, *self._y0[:, PHI]]
        for st in self.stages[:-1]:
            if isinstance(st, CollocatedStage):
                taus = np.linspace(st.tau0, st.tau1, 8 * len(st.steps) + 1)
                values.extend(st.state(taus)[:, PHI])
        return float(min(values)), float(max(values))

    def initial_total(self, frame_rapidity: float) -> EnergyMomentum:
        """The rod before any force: at rest in S. (Not conserved: the agents deliver (E, p), `Driving.delivered`.)"""
        return EnergyMomentum.of(1.0, -frame_rapidity)

    def energy_momentum(self, frame_rapidity: float, t: float) -> Slice:
        """The rod's kinetic (E, p) on the slice t of the frame, and its stress part as `hidden`."""
        kinetic, stress = self.rod_parts(frame_rapidity, t)
        return Slice(t, (("rod", kinetic),), kinetic, stress)

    # --- the solution, for any L --------------------------------------------------------------------------------------

    def _states(self, tau: np.ndarray) -> np.ndarray:
        """The state (`driven.T_` ...) at each tau of the unit solution (before the first stage: at rest)."""
        tau = np.asarray(tau, dtype=float)
        out = np.empty((len(tau), 7))
        k = np.searchsorted(self._tau0, tau, side="right") - 1
        before = k < 0
        if np.any(before):
            y0 = self._y0[0]
            out[before] = y0
            out[before, T_] = y0[T_] + tau[before]
        for i in np.unique(k[~before]):
            sel = k == i
            out[sel] = self.stages[i].state(tau[sel])
        return out

    def _motion_alpha_forces(self, tau: np.ndarray):
        """The left end's (t, x, phi) (`_states(tau)[:, :3]`) and `_alpha_forces(tau)`'s alpha and F_L, the same
        numbers, each stage's states computed once: alpha and the forces are functions of the state (`Stage.alpha`,
        `Stage.forces`)."""
        tau = np.asarray(tau, dtype=float)
        out = np.empty((len(tau), PHI + 1))
        a, FL = np.zeros(len(tau)), np.zeros(len(tau))
        k = np.searchsorted(self._tau0, tau, side="right") - 1
        before = k < 0
        if np.any(before):
            y0 = self._y0[0, :PHI + 1]
            out[before] = y0
            out[before, T_] = y0[T_] + tau[before]
        for i in np.unique(k[~before]):
            sel = k == i
            st = self.stages[i]
            if isinstance(st, ConstantStage):
                out[sel] = st.state(tau[sel])[:, :PHI + 1]
                a[sel], FL[sel] = st.alpha(tau[sel]), st.FL
            else:
                Y = out[sel] = st.state(tau[sel], motion_only=True)
                F = st.rates.forces(Y[:, T_], Y[:, X_], Y[:, PHI])
                a[sel], FL[sel] = st.rates.alpha(*F), F[0]
        return out, a, FL

    def _alpha_forces(self, tau: np.ndarray):
        """alpha and (F_L, F_R) at each tau (zero before the first stage)."""
        tau = np.asarray(tau, dtype=float)
        a, FL, FR = np.zeros(len(tau)), np.zeros(len(tau)), np.zeros(len(tau))
        k = np.searchsorted(self._tau0, tau, side="right") - 1
        for i in np.unique(k[k >= 0]):
            sel = k == i
            st = self.stages[i]
            a[sel] = st.alpha(tau[sel])
            FL[sel], FR[sel] = st.forces(tau[sel])
        return a, FL, FR

    def _crossings(self, sigma: np.ndarray, f: float, T: float) -> np.ndarray:
        """The tau (unit solution) at which each material point sigma (units of L) reaches the time T (units of L)
        of the frame of rapidity f."""
        sigma = np.asarray(sigma, dtype=float)
        ch, sh = math.cosh(f), math.sinh(f)
        y0 = self._y0
        tf0 = ch * y0[:, T_] - sh * y0[:, X_]
        h = tf0[None, :] + sigma[:, None] * np.sinh(y0[None, :, PHI] - f) - T  # at each stage's start
        k = np.sum(h <= 0.0, axis=1) - 1
        out = np.empty(len(sigma))
        before = k < 0
        if np.any(before):  # at rest in S before the first force
            x = y0[0, X_] + sigma[before]
            out[before] = (T + sh * x) / ch - y0[0, T_]
        for i in np.unique(k[~before]):
            sel = k == i
            st = self.stages[i]
            if isinstance(st, ConstantStage):
                out[sel] = st.crossing(sigma[sel], f, T)
            else:
                out[sel] = _newton_crossing(st, sigma[sel], f, T)
        return out

    # --- energy and momentum --------------------------------------------------------------------------------------------

    def _cuts(self, f: float, T: float) -> list[float]:
        """Where the slice meets the normal lines at which a stage or a step begins (units of L), within (0, 1)."""
        if self._cut_states is None:
            taus = list(self._tau0)
            for st in self.stages:
                if isinstance(st, CollocatedStage):
                    taus.extend(st.step_bounds())
            self._cut_states = self._states(np.array(taus)) if taus else np.empty((0, 7))
        Y = self._cut_states
        if not len(Y):
            return []
        s = np.sinh(Y[:, PHI] - f)
        tf = math.cosh(f) * Y[:, T_] - math.sinh(f) * Y[:, X_]
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):  # inf, nan: no crossing in (0, 1)
            sig = np.where(s != 0.0, (T - tf) / s, -1.0)
        return sorted(float(v) for v in sig if 0.0 < v < 1.0)

    def slice_nodes(self, frame_rapidity: float, t: float) -> dict[str, np.ndarray]:
        """The Gauss-Legendre nodes of the slice t of the frame (units of L): each material point sigma, its weight,
        its rapidity psi in the frame where it crosses the slice, the stress p there (units of M c^2/L), and its x
        in the frame (the scenario's unit). Kept per slice (`KEEP_SLICES`), read-only."""
        key = (frame_rapidity, t, math.copysign(1.0, frame_rapidity), math.copysign(1.0, t))  # -0.0 apart from 0.0
        kept = self._slices.get(key)
        if kept is None:
            if len(self._slices) >= KEEP_SLICES:
                self._slices.clear()
            kept = self._slices[key] = self._slice_nodes(frame_rapidity, t)
            for array in kept.values():
                array.flags.writeable = False
        return dict(kept)

    def _slice_nodes(self, frame_rapidity: float, t: float) -> dict[str, np.ndarray]:
        f, T = frame_rapidity, t / self.L
        cuts = [0.0, *self._cuts(f, T), 1.0]
        edges = sorted(set(np.concatenate([np.linspace(a, b, 3) for a, b in zip(cuts, cuts[1:])])))
        sig, w = [], []
        for a, b in zip(edges, edges[1:]):
            sig.append(0.5 * (a + b) + 0.5 * (b - a) * GAUSS_X)
            w.append(0.5 * (b - a) * GAUSS_W)
        sig, w = np.concatenate(sig), np.concatenate(w)
        tau = self._crossings(sig, f, T)
        Y, a, FL = self._motion_alpha_forces(tau)
        x_s = Y[:, X_] + sig * np.cosh(Y[:, PHI])
        t_s = Y[:, T_] + sig * np.sinh(Y[:, PHI])
        return {"sigma": sig, "weight": w, "psi": Y[:, PHI] - f,
                "p": (FL - a * sig) / (1.0 + a * sig),  # (rho0 + F_L)/(1 + alpha sigma) - rho0, rho0 = 1
                "x": self.L * (math.cosh(f) * x_s - math.sinh(f) * t_s)}

    def rod_parts(self, frame_rapidity: float, t: float) -> tuple[EnergyMomentum, EnergyMomentum]:
        """The rod's (E, p) on the slice t of the frame split into its kinetic part and its stress part."""
        n = self.slice_nodes(frame_rapidity, t)
        w, psi, p = n["weight"], n["psi"], n["p"]
        kinetic = EnergyMomentum(1.0, float(np.sum(w * 2.0 * np.sinh(0.5 * psi) ** 2)), float(np.sum(w * np.sinh(psi))))
        stress = EnergyMomentum(0.0, float(np.sum(w * p * np.sinh(psi) * np.tanh(psi))), float(np.sum(w * p * np.sinh(psi))))
        return kinetic, stress


def _newton_crossing(stage: CollocatedStage, sigma: np.ndarray, f: float, T: float) -> np.ndarray:
    """tau in the collocated stage where the points sigma reach time T of the frame f: safeguarded Newton."""
    lo = np.full(len(sigma), stage.tau0)
    hi = np.full(len(sigma), stage.tau1)
    tau = 0.5 * (lo + hi)
    ch, sh = math.cosh(f), math.sinh(f)
    for _ in range(100):
        Y = stage.state(tau, motion_only=True)  # (t, x, phi) alone: the same numbers, 3/7 of the sums
        FL, FR = stage.rates.forces(Y[:, T_], Y[:, X_], Y[:, PHI])
        a = stage.rates.alpha(FL, FR)
        psi = Y[:, PHI] - f
        g = ch * Y[:, T_] - sh * Y[:, X_] + sigma * np.sinh(psi) - T
        dg = (1.0 + a * sigma) * np.cosh(psi)
        lo = np.where(g <= 0.0, tau, lo)
        hi = np.where(g >= 0.0, tau, hi)
        new = tau - g / dg
        bad = ~((new > lo) & (new < hi))
        new = np.where(bad, 0.5 * (lo + hi), new)
        new = np.where(g == 0.0, tau, new)
        done = np.abs(new - tau).max() <= 2e-16 * (np.abs(tau).max() + 1.0)
        tau = new
        if done:
            break
    return tau


class Driving:
    """The part of a run only a rod driven by forces has (`physics.history.Driving`)."""

    def __init__(self, history: DrivenHistory):
        self.history = history
        self._force_events = None
        # each end's tau and delivered (E, p) on the slices asked for (a ledger's row reads each twice: alone and in
        # `total`), KEEP_SLICES of each at most
        self._end_taus: dict[tuple, float] = {}
        self._delivered: dict[tuple, EnergyMomentum] = {}

    @property
    def forces(self) -> Forces:
        return self.history.scenario.forces

    def profiles(self) -> tuple[tuple[str, ForceProfile], ...]:
        return self.forces.items()

    def frame_rapidity(self, end: str) -> float:
        """The rapidity relative to S of the frame the end's profile is timed in."""
        return math.atanh(self.forces.at(end).frame_velocity(self.history.scenario.v))

    def end_tau(self, end: str, frame_rapidity: float, t: float) -> float:
        key = (end, frame_rapidity, t, math.copysign(1.0, frame_rapidity), math.copysign(1.0, t))
        kept = self._end_taus.get(key)
        if kept is None:
            if len(self._end_taus) >= KEEP_SLICES:
                self._end_taus.clear()
            h = self.history
            kept = self._end_taus[key] = float(h._crossings(np.array([0.0 if end == "left" else 1.0]), frame_rapidity,
                                                            t / h.L)[0])
        return kept

    def delivered(self, end: str, frame_rapidity: float, t: float) -> EnergyMomentum:
        """The (E, p), in the frame, the agent at `end` delivered up to that end's event on the slice t of the
        frame."""
        key = (end, frame_rapidity, t, math.copysign(1.0, frame_rapidity), math.copysign(1.0, t))
        kept = self._delivered.get(key)
        if kept is None:
            if len(self._delivered) >= KEEP_SLICES:
                self._delivered.clear()
            kept = self._delivered[key] = self._delivered_afresh(end, frame_rapidity, t)
        return kept

    def _delivered_afresh(self, end: str, frame_rapidity: float, t: float) -> EnergyMomentum:
        h = self.history
        if self.forces.at(end) is None:
            return EnergyMomentum(0.0, 0.0, 0.0)
        y = h._states(np.array([self.end_tau(end, frame_rapidity, t)]))[0]
        E, p = (y[EL], y[PL]) if end == "left" else (y[ER], y[PR])
        c, s = math.cosh(frame_rapidity), math.sinh(frame_rapidity)
        return EnergyMomentum(0.0, c * E - s * p, c * p - s * E)

    def total(self, frame_rapidity: float, t: float) -> EnergyMomentum:
        """The rod's (E, p) before the forces plus what both agents delivered up to the slice: what the rod holds."""
        h = self.history
        out = h.initial_total(frame_rapidity)
        for end in ENDS:
            out = out + self.delivered(end, frame_rapidity, t)
        return out

    def force_at(self, end: str, frame_rapidity: float, t: float) -> float:
        """The force at the end's event on the slice t of the frame (units of M c^2/L)."""
        h = self.history
        if self.forces.at(end) is None:
            return 0.0
        _, FL, FR = h._alpha_forces(np.array([self.end_tau(end, frame_rapidity, t)]))
        return float(FL[0] if end == "left" else FR[0])

    def stress(self, frame_rapidity: float, t: float, sigmas) -> np.ndarray:
        """The stress p (units of M c^2/L, > 0 compression) at each material point sigma where it crosses the slice."""
        h = self.history
        s = np.asarray(sigmas, dtype=float) / h.L
        tau = h._crossings(s, frame_rapidity, t / h.L)
        a, FL, _ = h._alpha_forces(tau)
        return (FL - a * s) / (1.0 + a * s)

    def centre_of_energy(self, frame_rapidity: float, t: float) -> tuple[float, float]:
        """The rod's centre of energy on the slice t of the frame, x_E = int x e dx / int e dx (e the energy density,
        e dx = (rho0 cosh psi + p sinh psi tanh psi) d sigma), and its energy int e dx."""
        n = self.history.slice_nodes(frame_rapidity, t)
        e = n["weight"] * (np.cosh(n["psi"]) + n["p"] * np.sinh(n["psi"]) * np.tanh(n["psi"]))
        return float(np.sum(e * n["x"]) / np.sum(e)), float(np.sum(e))

    def centre_velocity(self, frame_rapidity: float, t: float) -> float:
        """d x_E / dt on the slice t of the frame (`forces.centre_velocity`, over 1e-3 L)."""
        return centre_velocity(lambda s: self.centre_of_energy(frame_rapidity, s), t, 1e-3 * self.history.L)

    def now_lines(self, count: int = 12) -> list[tuple[Event, Event]]:
        """The rod's own lines of simultaneity (the normal lines through the left end) as (left, right) event pairs
        in S: at each stage's start and `count` more spread over the stages with force."""
        h = self.history
        first, last = h._tau0[0], h._tau0[-1]
        taus = sorted(set([*h._tau0, *np.linspace(first, last, count + 2)]))
        Y = h._states(np.array(taus))
        out = []
        for y in Y:
            left = Event(h.L * y[X_], h.L * y[T_])
            out.append((left, left.displaced(h.L, float(y[PHI]))))
        return out

    def force_events(self) -> tuple[ForceEvent, ...]:
        """Each force's start, peak and end at its end, in S (`_computed_force_events`), computed once per run: the
        page and the tables ask for them several times."""
        if self._force_events is None:
            self._force_events = self._computed_force_events()
        return self._force_events

    def _computed_force_events(self) -> tuple[ForceEvent, ...]:
        """Each force's start, peak and end at its end, in S (see them in any frame with `Event.seen_from`)."""
        h = self.history
        out = []
        for end, profile in self.profiles():
            f = self.frame_rapidity(end)
            first, last = profile.support()
            for moment, instant in zip(FORCE_MOMENTS, (first, profile.peak_time(), last)):
                tau = self.end_tau(end, f, instant * h.L)
                y = h._states(np.array([tau]))[0]
                sigma = 0.0 if end == "left" else 1.0
                event = Event(float(h.L * (y[X_] + sigma * math.cosh(y[PHI]))),
                              float(h.L * (y[T_] + sigma * math.sinh(y[PHI]))))
                force = (profile.piece_value(profile.piece_index(instant) - 1, instant) if moment == "end"
                         else profile.value(instant))
                out.append(ForceEvent(end, moment, event, float(y[PHI]), float(force), instant))
        return tuple(out)
