"""Elastic collisions of point masses and the whole rod (PHYSICS.md rules 2 and 5). Pure.

Velocities are rapidities measured in the rod's rest frame at the impact,
masses in units of the rod's mass M. Every collision uses one rule:

    in the centre-of-momentum frame of all the bodies taking part,
    every velocity reverses.

That conserves relativistic energy and momentum exactly (each |p| and so each
energy is unchanged in that frame, and the total momentum there is zero
before and after). For a particle and the rod it is the usual 1-D elastic
collision: equal masses exchange velocities. For a particle at each end at
once (rule 5) it keeps the rod at rest when the impulses are equal and
opposite (Fig. 1a), and otherwise is the relativistic form of Newton's
restitution law at both contacts, e = 1, which it reduces to at low speed.
In rapidities the rule reads: new = 2*b - old, b the centre-of-momentum
rapidity.
"""

from __future__ import annotations

import math


def centre_of_momentum_rapidity(masses: tuple[float, ...], rapidities: tuple[float, ...]) -> float:
    momentum = sum(m * math.sinh(r) for m, r in zip(masses, rapidities))
    energy = sum(m * math.cosh(r) for m, r in zip(masses, rapidities))
    return math.atanh(momentum / energy)


def elastic(particle_masses: tuple[float, ...], particle_rapidities: tuple[float, ...]) -> tuple[float, tuple[float, ...]]:
    """Rod (mass 1, at rest) struck at once by the given particles.

    Returns the rod's new rapidity and the particles' new rapidities, all in
    the rod's rest frame before the impact.
    """
    b = centre_of_momentum_rapidity((1.0, *particle_masses), (0.0, *particle_rapidities))
    return 2.0 * b, tuple(2.0 * b - r for r in particle_rapidities)


def four_momentum(mass: float, rapidity_: float) -> tuple[float, float]:
    """(energy, momentum) of a body of the given mass and rapidity."""
    return mass * math.cosh(rapidity_), mass * math.sinh(rapidity_)
