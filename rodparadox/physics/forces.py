"""Forces at the ends of the rod, as frozen, validated data: a profile F(t) per end (docs/model.md, "Forces at the
ends"). Pure: stdlib, numpy and `model`'s checks.

A profile is the push an agent exerts on one end in that end's momentary rest frame, F > 0 pressing into the rod,
F < 0 pulling, as a function of the time t, in the profile's frame, of the event where the end is. Times (`start`,
`duration`, the times of `points`) are in units of the rod's proper length L (c = 1), as a particle's `gap` is, so
that a longer rod stretches them; forces are in units of M c^2 / L. The momentum a force delivers, measured in the
frame its profile is timed in, is the profile's area (units of M c), whatever L.

Shapes:

* `step`: `peak` on [start, start + duration);
* `sine2`: `peak` sin^2(pi (t - start) / duration) on [start, start + duration];
* `points`: piecewise linear through `points` ((t0, F0), (t1, F1), ...; strictly increasing times), zero outside
  [t0, tn); a non-zero first or last value is a jump.

`frame` is `rest` (S), `moving` (the paper's S', velocity -v relative to S) or a velocity u relative to S, bounded
as every frame a user gives (`model.FASTEST`).
"""

from __future__ import annotations

import bisect
import functools
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from rodparadox.errors import ScenarioError
from rodparadox.physics.model import FASTEST, FRAME_NAMES, MAX_SPAN, check_number, described, frame_velocity

#: the ends a force may act on
ENDS = ("left", "right")
#: the shapes of a profile
SHAPES = ("step", "sine2", "points")
#: the largest |force| in a profile, units of M c^2 / L: past it a pulse of duration L moves the rod faster than
#: double precision places its ends
MAX_FORCE = 1e3
#: the most points a `points` profile may have (a scenario is a few lines of YAML)
MAX_POINTS = 200
#: the largest |area| of a profile (the momentum it delivers, units of M c): a rod pushed by more moves faster
#: than the fastest speed the tool computes (`model.FASTEST`, g about 2236)
MAX_AREA = 2e3
#: the pull limits, units of M c^2 / L: a rigid rod pulled with M c^2 / L or more has its horizon inside it; a
#: causal rod pulled with M c^2 / 2L or more would stretch without bound (lam_end^2 = 1 + 2F / rho0 <= 0)
PULL_LIMITS = {"rigid": 1.0, "causal": 0.5}


@dataclass(frozen=True)
class ForceProfile:
    """The force on one end as a function of the time t (units of L) of that end's event in the profile's frame."""

    shape: str
    peak: float | None = None
    start: float | None = None
    duration: float | None = None
    points: tuple[tuple[float, float], ...] = ()
    frame: str | float = "rest"
    #: the YAML key, for messages: forces.left or forces.right
    key: str = field(default="forces.left", compare=False, repr=False)

    def __post_init__(self) -> None:
        key = self.key
        if self.shape not in SHAPES:
            raise ScenarioError(f"{key}.shape must be step, sine2 or points, got {described(self.shape)}.",
                                f"{key}.shape")
        self._check_frame()
        if self.shape == "points":
            for name in ("peak", "start", "duration"):
                if getattr(self, name) is not None:
                    raise ScenarioError(f"{key}.{name} is not used by shape points (the points give the times and "
                                        f"forces); remove it.", f"{key}.{name}")
            object.__setattr__(self, "points", self._checked_points())
        else:
            for name in ("peak", "start", "duration"):
                if getattr(self, name) is None:
                    raise ScenarioError(f"{key} with shape {self.shape} needs the key {name}.", f"{key}.{name}")
            if self.points:
                raise ScenarioError(f"{key}.points is used only by shape points; remove it or give shape: points.",
                                    f"{key}.points")
            peak = check_number(self.peak, f"{key}.peak", low=-MAX_FORCE, high=MAX_FORCE, low_open=False,
                                 high_open=False, allowed=_FORCE_ALLOWED)
            if peak == 0:
                raise ScenarioError(f"{key}.peak must not be 0 (no force); leave the end out instead.", f"{key}.peak")
            check_number(self.start, f"{key}.start", low=-MAX_SPAN, high=MAX_SPAN, low_open=False,
                          high_open=False, allowed=f"a number between {-MAX_SPAN:g} and {MAX_SPAN:g} (units of L)")
            check_number(self.duration, f"{key}.duration", low=0, high=MAX_SPAN, high_open=False,
                          allowed=f"a number with 0 < duration <= {MAX_SPAN:g} (units of L)")
            object.__setattr__(self, "peak", float(self.peak))
            object.__setattr__(self, "start", float(self.start))
            object.__setattr__(self, "duration", float(self.duration))
        if abs(self.area()) > MAX_AREA:
            raise ScenarioError(f"{key} delivers a momentum of {self.area():g} M c (its area), more than "
                                f"{MAX_AREA:g} in size: the rod would move faster than the tool computes; give a "
                                f"smaller peak or a shorter duration.", key)

    def _check_frame(self) -> None:
        key, allowed = f"{self.key}.frame", f"rest, moving or a velocity u with {-FASTEST!r} <= u <= {FASTEST!r}"
        if isinstance(self.frame, str):
            if self.frame not in FRAME_NAMES:
                raise ScenarioError(f"{key} must be {allowed}, got {self.frame!r}.", key)
        elif abs(check_number(self.frame, key, allowed=allowed)) > FASTEST:
            raise ScenarioError(f"{key} must be {allowed}, got {self.frame!r}.", key)
        else:
            object.__setattr__(self, "frame", float(self.frame) + 0.0)

    def _checked_points(self) -> tuple[tuple[float, float], ...]:
        key = f"{self.key}.points"
        raw = self.points
        if not isinstance(raw, (list, tuple)) or len(raw) < 2:
            got = f"{len(raw)} point{'s' * (len(raw) != 1)}" if isinstance(raw, (list, tuple)) else described(raw)
            raise ScenarioError(f"{key} must be a list of at least two [t, F] pairs, got {got}.", key)
        if len(raw) > MAX_POINTS:
            raise ScenarioError(f"{key} must have at most {MAX_POINTS} points, got {len(raw)}.", key)
        out = []
        for i, pair in enumerate(raw):
            where = f"{key}[{i}]"
            if not isinstance(pair, (list, tuple)) or len(pair) != 2:
                raise ScenarioError(f"{where} must be a pair [t, F] (time in units of L, force in M c^2/L), got "
                                    f"{described(pair) if not isinstance(pair, (list, tuple)) else f'{len(pair)} values'}.",
                                    where)
            try:
                t = check_number(pair[0], f"{where} time", low=-MAX_SPAN, high=MAX_SPAN, low_open=False,
                                  high_open=False,
                                  allowed=f"a number between {-MAX_SPAN:g} and {MAX_SPAN:g} (units of L)")
                f = check_number(pair[1], f"{where} force", low=-MAX_FORCE, high=MAX_FORCE, low_open=False,
                                  high_open=False, allowed=_FORCE_ALLOWED)
            except ScenarioError as e:  # the key of the point, whose line the file knows
                raise ScenarioError(e.message, where) from None
            if out and t <= out[-1][0]:
                raise ScenarioError(f"{key} must have strictly increasing times, but point {i} (t = {t:g}) does not "
                                    f"come after point {i - 1} (t = {out[-1][0]:g}).", where)
            out.append((t, f))
        if all(f == 0 for _, f in out):
            raise ScenarioError(f"{key} are all 0 (no force); leave the end out instead.", key)
        return tuple(out)

    # --- the profile ------------------------------------------------------------------------------------------------

    def value(self, t):
        """F at time t (a number or an array; units of L in, M c^2 / L out), zero outside the profile's support."""
        t = np.asarray(t, dtype=float)
        if self.shape == "step":
            out = np.where((t >= self.start) & (t < self.start + self.duration), self.peak, 0.0)
        elif self.shape == "sine2":
            inside = (t >= self.start) & (t < self.start + self.duration)  # sin^2 is 0 at the end: exactly 0
            out = np.where(inside, self.peak * np.sin(np.pi * (t - self.start) / self.duration) ** 2, 0.0)
        else:
            times = np.array([p[0] for p in self.points])
            forces = np.array([p[1] for p in self.points])
            inside = (t >= times[0]) & (t < times[-1])
            out = np.where(inside, np.interp(t, times, forces), 0.0)
        return float(out) if out.ndim == 0 else out

    def area(self) -> float:
        """The integral of F over t, exact: the momentum (units of M c) the force delivers in the profile's frame."""
        if self.shape == "step":
            return self.peak * self.duration
        if self.shape == "sine2":
            return self.peak * self.duration / 2
        return math.fsum((t1 - t0) * (f0 + f1) / 2 for (t0, f0), (t1, f1) in zip(self.points, self.points[1:]))

    def primitive(self, t: float) -> float:
        """The integral of F from -infinity to t, exact (the momentum delivered up to t, in the profile's frame)."""
        if self.shape == "step":
            return self.peak * min(max(t - self.start, 0.0), self.duration)
        if self.shape == "sine2":
            s = min(max(t - self.start, 0.0), self.duration)
            w = 2 * math.pi / self.duration
            return self.peak * (s / 2 - math.sin(w * s) / (2 * w))
        total = []
        for (t0, f0), (t1, f1) in zip(self.points, self.points[1:]):
            if t <= t0:
                break
            s = min(t, t1) - t0
            slope = (f1 - f0) / (t1 - t0)
            total.append(f0 * s + slope * s * s / 2)
        return math.fsum(total)

    def support(self) -> tuple[float, float]:
        """The first and last instant with force (units of L)."""
        if self.shape != "points":
            return self.start, self.start + self.duration
        pts = self.points
        first = next(pts[i][0] for i in range(len(pts)) if pts[i][1] != 0 or (i + 1 < len(pts) and pts[i + 1][1] != 0))
        last = next(pts[i][0] for i in reversed(range(len(pts))) if pts[i][1] != 0 or (i > 0 and pts[i - 1][1] != 0))
        return first, last

    def pieces(self) -> tuple[float, ...]:
        """The instants where the profile is not smooth (switch on and off, jumps, the corners of `points`), in
        order: an ODE solver restarts there."""
        return self._pieces

    @functools.cached_property
    def _pieces(self) -> tuple[float, ...]:  # made once: the solvers ask for it at every step
        if self.shape != "points":
            return self.start, self.start + self.duration
        return tuple(t for t, _ in self.points)

    def piece_index(self, t: float) -> int:
        """Which piece holds time t: 0 before `pieces()[0]`, i on [pieces()[i-1], pieces()[i]), len(pieces()) after
        the last (right-continuous: at a piece's start, that piece)."""
        return bisect.bisect_right(self._pieces, t)

    def piece_value(self, index: int, t):
        """F on the piece `index` (`piece_index`) by that piece's own smooth formula, continued past its ends (an
        ODE solver's step may look beyond the instant where the piece ends; units of L and M c^2/L)."""
        t = np.asarray(t, dtype=float)
        n = len(self.pieces())
        if index <= 0 or index >= n:
            out = np.zeros_like(t)
        elif self.shape == "step":
            out = np.full_like(t, self.peak)
        elif self.shape == "sine2":
            out = self.peak * np.sin(np.pi * (t - self.start) / self.duration) ** 2
        else:
            (t0, f0), (t1, f1) = self.points[index - 1], self.points[index]
            out = f0 + (f1 - f0) * ((t - t0) / (t1 - t0))
        return float(out) if out.ndim == 0 else out

    def piece_constant(self, index: int) -> float | None:
        """F on the piece `index` where it is constant there (a step, no force, a flat stretch of points), else None."""
        n = len(self.pieces())
        if index <= 0 or index >= n:
            return 0.0
        if self.shape == "step":
            return self.peak
        if self.shape == "points" and self.points[index - 1][1] == self.points[index][1]:
            return self.points[index][1]
        return None

    def jumps(self) -> tuple[float, ...]:
        """The instants where F itself jumps (not only its slope)."""
        if self.shape == "step":
            return self.start, self.start + self.duration
        if self.shape == "sine2":
            return ()
        out = []
        if self.points[0][1] != 0:
            out.append(self.points[0][0])
        if self.points[-1][1] != 0:
            out.append(self.points[-1][0])
        return tuple(out)

    def least(self) -> float:
        """The profile's minimum, 0 included (it is zero outside its support): the strongest pull, negated."""
        if self.shape != "points":
            return min(self.peak, 0.0)
        return min(0.0, *(f for _, f in self.points))

    def greatest(self) -> float:
        """The profile's maximum, 0 included: the strongest push."""
        if self.shape != "points":
            return max(self.peak, 0.0)
        return max(0.0, *(f for _, f in self.points))

    def peak_time(self) -> float:
        """The instant of the largest |F| (units of L): the middle of a step, of a sine^2 pulse; for points the
        first point of largest |F|."""
        if self.shape != "points":
            return self.start + self.duration / 2
        largest = max(abs(f) for _, f in self.points)
        return next(t for t, f in self.points if abs(f) == largest)

    def frame_velocity(self, v: float) -> float:
        """The velocity relative to S of the frame the profile is timed in, for a scenario of speed v (S' is -v)."""
        return frame_velocity(self.frame, v)

    def scaled(self, L: float) -> "ScaledProfile":
        """The profile in absolute units for a rod of proper length L (times times L, forces over L, M = 1)."""
        return ScaledProfile(self, L)


@dataclass(frozen=True)
class ScaledProfile:
    """A profile in the engine's units for a rod of proper length L and mass 1: F(t) = profile.value(t / L) / L,
    t in the same units as L. Its area is the profile's (the momentum it delivers does not depend on L)."""

    profile: ForceProfile
    L: float

    def value(self, t):
        return self.profile.value(np.asarray(t, dtype=float) / self.L) / self.L

    def primitive(self, t: float) -> float:
        return self.profile.primitive(t / self.L)

    def area(self) -> float:
        return self.profile.area()

    def support(self) -> tuple[float, float]:
        a, b = self.profile.support()
        return a * self.L, b * self.L

    def pieces(self) -> tuple[float, ...]:
        return self._pieces

    @functools.cached_property
    def _pieces(self) -> tuple[float, ...]:
        return tuple(t * self.L for t in self.profile.pieces())

    def jumps(self) -> tuple[float, ...]:
        return tuple(t * self.L for t in self.profile.jumps())

    def piece_index(self, t: float) -> int:
        return bisect.bisect_right(self._pieces, t)

    def piece_value(self, index: int, t):
        return self.profile.piece_value(index, np.asarray(t, dtype=float) / self.L) / self.L

    def piece_constant(self, index: int) -> float | None:
        value = self.profile.piece_constant(index)
        return None if value is None else value / self.L

    def peak_time(self) -> float:
        return self.profile.peak_time() * self.L


_FORCE_ALLOWED = f"a number between {-MAX_FORCE:g} and {MAX_FORCE:g} (units of M c^2/L; > 0 pushes, < 0 pulls)"


@dataclass(frozen=True)
class Forces:
    """The forces on the two ends: either may be None (no force there), not both."""

    left: ForceProfile | None = None
    right: ForceProfile | None = None

    def __post_init__(self) -> None:
        if self.left is None and self.right is None:
            raise ScenarioError("forces must give a profile for left, right or both.", "forces")

    def items(self) -> tuple[tuple[str, ForceProfile], ...]:
        """(end, profile) for each end with a force, left first."""
        return tuple((end, p) for end, p in (("left", self.left), ("right", self.right)) if p is not None)

    def at(self, end: str) -> ForceProfile | None:
        return self.left if end == "left" else self.right

    def check_pull(self, model: str) -> None:
        """Refuse, in one sentence naming the limit, a pull the model cannot carry: rigid, M c^2/L or more (the
        horizon inside the rod); causal, M c^2/2L or more (an infinite stretch)."""
        limit = PULL_LIMITS[model]
        for end, profile in self.items():
            if profile.least() <= -limit:
                why = ("the rigid rod's horizon would lie inside the rod" if model == "rigid"
                       else "the causal rod would stretch without bound")
                text = "M c^2/L" if limit == 1.0 else "M c^2/(2L)"
                raise ScenarioError(f"{profile.key} pulls with {-profile.least():g} M c^2/L, but the {model} rod "
                                    f"carries a pull only below {text}: {why}; give a weaker pull.", profile.key)


def profile_from(data: Any, key: str) -> ForceProfile:
    """A profile from the mapping of YAML (or JSON) values under `key` (forces.left or forces.right)."""
    if not isinstance(data, dict):
        raise ScenarioError(f"{key} must be a mapping (shape, peak, start, duration, points, frame), got "
                            f"{described(data)}.", key)
    if "shape" not in data:
        raise ScenarioError(f"{key} needs the key shape (step, sine2 or points).", f"{key}.shape")
    fields = dict(data)
    if "points" in fields and isinstance(fields["points"], list):
        fields["points"] = tuple(tuple(p) if isinstance(p, list) else p for p in fields["points"])
    return ForceProfile(**fields, key=key)


def centre_velocity(centre_of_energy, t: float, h: float) -> float:
    """d x_E / dt of a driven rod's centre of energy (`centre_of_energy(t)` -> (x_E, E) on the slice t of one frame):
    central differences over h, h/2 and h/4 extrapolated twice (Richardson), to about 1e-12 of the velocity where
    nothing jumps within h of t (a force's switch-on, a front reaching an end, blur it over that span)."""
    def slope(step: float) -> float:
        return (centre_of_energy(t + step)[0] - centre_of_energy(t - step)[0]) / (2.0 * step)

    d1, d2, d4 = slope(h), slope(h / 2), slope(h / 4)
    r1, r2 = (4.0 * d2 - d1) / 3.0, (4.0 * d4 - d2) / 3.0
    return (16.0 * r2 - r1) / 15.0
