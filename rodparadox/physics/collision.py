"""Elastic collisions of point masses and the whole rod (docs/model.md, "The model", rules 2 and 5). Pure.

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
    """atanh(P/E), computed as (log(E + P) - log(E - P))/2 with E +- P = sum of m*exp(+-r).

    Every term is positive, so nothing cancels: at rapidities near 7 (v = 0.999999)
    atanh(P/E) would lose ten digits, this form none.
    """
    return 0.5 * (_log_sum(masses, rapidities) - _log_sum(masses, tuple(-r for r in rapidities)))


def _log_sum(masses: tuple[float, ...], exponents: tuple[float, ...]) -> float:
    """log(sum of m * exp(e)), without overflow; fsum rounds once, so mirror-image collisions give b = 0 exactly."""
    top = max(exponents)
    return top + math.log(math.fsum(m * math.exp(e - top) for m, e in zip(masses, exponents)))


def elastic(particle_masses: tuple[float, ...], particle_rapidities: tuple[float, ...]) -> tuple[float, tuple[float, ...]]:
    """Rod (mass 1, at rest) struck at once by the given particles.

    Returns the rod's new rapidity and the particles' new rapidities, all in
    the rod's rest frame before the impact.
    """
    b = centre_of_momentum_rapidity((1.0, *particle_masses), (0.0, *particle_rapidities))
    return 2.0 * b, tuple(2.0 * b - r for r in particle_rapidities)

