"""One frame's space at one instant: where the rod's material points are and how fast they move, where the
particles are, and which impacts happen then (docs/animate.md, "The paradox in motion"). Pure.

What a strip draws (`render.strip`) and an animation's now mode sweeps (`animate.timeline`): `strip_at(history,
frame, t, flash)` reads it off the exact world-lines, boosted into the frame; `material_points` builds those
world-lines once, for a caller that reads many instants of one frame.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from rodparadox.physics.history import RodHistory
from rodparadox.physics.frames import Frame
from rodparadox.physics.kinematics import WorldLine

#: material points along the strip's bar: enough that the colour varies smoothly along it
STRIP_POINTS = 96


@dataclass(frozen=True)
class Strip:
    """The frame's space at the instant t: the rod as a bar, its material points' velocities, the particles, and
    the impacts that flash now. Positions and velocities in the frame's coordinates (units of L, c = 1).

    `sigma` are the material points (proper distance from the left end, 0 to L), `x` where each is at t
    (x[0] the left end, x[-1] the right end), `velocity` its velocity there; `particles` is (name, x) for
    each particle; `flashing` the labels (B1, A1, ...) of the impacts within the flash time of t, and
    `flash_x` where each of them is (the impact's x in the frame, not the rod's now); `forces` is (end, F) for each
    end a force drives (`RodHistory.driving`: F at that end's event on the slice, units of M c^2/L).
    """

    t: float
    sigma: np.ndarray
    x: np.ndarray
    velocity: np.ndarray
    particles: tuple[tuple[str, float], ...]
    flashing: tuple[str, ...]
    flash_x: tuple[float, ...] = ()
    forces: tuple[tuple[str, float], ...] = ()


@lru_cache(maxsize=32)
def material_points(history: RodHistory, frame: Frame, points: int = STRIP_POINTS) -> tuple[WorldLine, ...]:
    """The exact world-lines, in `frame`, of `points` material points evenly spaced in proper distance from the
    left end (sigma = 0) to the right end (sigma = L): what a strip shows of the rod. Built once per history,
    frame and count, and kept (both are frozen): a handout reads the strips of one frame at many instants, first
    to measure their block, then to draw it."""
    eta = frame.rapidity
    return tuple(history.material_worldline(float(sigma)).seen_from(eta)
                 for sigma in np.linspace(0.0, history.scenario.L, points))


def strip_at(history: RodHistory, frame: Frame, t: float, flash: float, points: int = STRIP_POINTS,
             material: tuple[WorldLine, ...] | None = None) -> Strip:
    """The strip of frame `frame` at its time t; an impact flashes when |t - its time| <= `flash`. `material`:
    the world-lines `material_points(history, frame, points)` gives, when the caller keeps them."""
    eta = frame.rapidity
    if history.fronts is not None:  # the causal rod: read off its chart directly, not world-line by world-line
        sigmas = np.linspace(0.0, history.scenario.L, points if material is None else len(material))
        x, rapidity = history.fronts.points_on_slice(eta, t, sigmas)
    else:
        if material is None:
            material = material_points(history, frame, points)
        sigmas = np.linspace(0.0, history.scenario.L, len(material))
        # each world-line's event and rapidity with its ends and piece found once (the same numbers as
        # `event_at_time`, `rapidity_at_time`)
        both = [w.event_and_rapidity_at_time(t) for w in material]
        x = np.array([e.x for e, _ in both])
        rapidity = np.array([r for _, r in both])
    particles = tuple((name, history.worldline(name).seen_from(eta).event_at_time(t).x)
                      for name in ("A", "B") if history.worldline(name) is not None)
    lit = [i for i in history.impacts if abs(i.event.time_in(eta) - t) <= flash]
    driving = history.driving
    forces = () if driving is None else tuple((end, driving.force_at(end, eta, t)) for end, _ in driving.profiles())
    return Strip(t, sigmas, x, np.tanh(rapidity), particles, tuple(i.label for i in lit),
                 tuple(i.event.seen_from(eta).x for i in lit), forces)
