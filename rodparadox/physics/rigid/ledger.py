"""The rigid rod's energy-momentum ledger (docs, "Energy and momentum: the ledger"): each body's (E, p) on any
slice of any frame, the hidden part, and every body just before and after each impact.


Pure. Units: energy in M c^2, momentum in M c (c = 1). A particle of mass m
and rapidity a has m (cosh a, sinh a). The rod's *kinetic* (E, p) on the slice
t = tau of a frame is (M/L) times the integral over its material points sigma
of (cosh psi, sinh psi), psi the point's rapidity where it crosses the slice
(rest mass flows along material lines). The *hidden* part is the system's
total before the first impact minus the kinetic total on the slice: what the
rod's stress carries (Sears's "hidden momentum").

The integral is exact, in closed form: the slice crosses the boundaries of
the turns' fans at points found in closed form, which split [0, L] into
pieces where every point is either straight (one rapidity) or on the
hyperbolae of one turn, where sinh psi = a/d (d the distance from the pivot)
and the integrals of cosh psi and sinh psi over d are elementary.
"""

from __future__ import annotations

import math

from rodparadox.physics.history import RodHistory
from rodparadox.physics.kinematics import HyperbolicArc, Line
from rodparadox.physics.ledger import initial_total, particle_on_slice
from rodparadox.physics.rigid.turns import material_worldline
from rodparadox.physics.types import EnergyMomentum, Slice, ZERO
def rod_kinetic(history: RodHistory, frame_rapidity: float, t: float) -> EnergyMomentum:
    """The rod's kinetic (E, p) on the slice t of the frame, exactly (closed form on each piece of [0, L])."""
    L = history.scenario.L
    cuts = {0.0, L}
    for turn in history.turns:
        pivot = turn.pivot.seen_from(frame_rapidity)
        for rapidity in (turn.rapidity_from, turn.rapidity_stop):
            sinh = math.sinh(rapidity - frame_rapidity)
            if sinh == 0.0:
                continue  # this fan line is a slice of the frame: it bounds nothing on another slice
            d = (t - pivot.t) / (turn.side * sinh)
            if 0.0 < d < L:
                cuts.add(turn.distance(d))  # distance(.) maps d to sigma and back: it is its own inverse
    cuts = sorted(cuts)
    T = p = 0.0
    for lo, hi in zip(cuts, cuts[1:]):
        if hi - lo <= 0.0:
            continue
        w = material_worldline(history, 0.5 * (lo + hi)).seen_from(frame_rapidity)
        piece = w.piece_at_time(t)
        if isinstance(piece, HyperbolicArc) and piece.radius > 0:
            dT, dp = _across_arc(piece, t, lo, hi, L)
        else:
            psi = piece if isinstance(piece, float) else piece.rapidity_at_start if isinstance(piece, Line) else piece.phi_at_time(t)
            dT, dp = (hi - lo) * 2.0 * math.sinh(0.5 * psi) ** 2, (hi - lo) * math.sinh(psi)
        T, p = T + dT, p + dp
    return EnergyMomentum(1.0, T / L, p / L)


def _across_arc(arc: HyperbolicArc, t: float, sigma_lo: float, sigma_hi: float, L: float) -> tuple[float, float]:
    """Integral over sigma in [sigma_lo, sigma_hi] of (cosh psi - 1, sinh psi), every point on a hyperbola about one pivot.

    The point at distance d from the pivot P crosses the slice where
    t - t_P = side d sinh psi: sinh psi = a/d with a = side (t - t_P). Then
    integral of sinh psi dd = a ln(d2/d1) and integral of cosh psi dd =
    integral of sqrt(d^2 + a^2)/d dd = [sqrt(d^2 + a^2) - |a| asinh(|a|/d)];
    less the rest energy d: [a^2/(sqrt(d^2 + a^2) + d) - |a| asinh(|a|/d)], which keeps its digits for small a.
    """
    # the pivot's distance from sigma: the arc's radius at the midpoint says which end the pivot is
    mid = 0.5 * (sigma_lo + sigma_hi)
    pivot_at_left = abs(arc.radius - mid) < abs(arc.radius - (L - mid))
    d1, d2 = sorted((sigma_lo, sigma_hi) if pivot_at_left else (L - sigma_hi, L - sigma_lo))
    a = arc.side * (t - arc.centre.t)
    if a == 0.0:
        return 0.0, 0.0
    if d1 <= 0.0:
        # only a slice through the pivot itself (a rounding-sized a) puts the pivot on the arcs: the piece is
        # then rounding-sized too, and its midpoint's rapidity is as good as the exact integral
        psi = math.asinh(a / (0.5 * d2))
        return d2 * 2.0 * math.sinh(0.5 * psi) ** 2, d2 * math.sinh(psi)
    b = abs(a)

    def primitive(d: float) -> float:
        return a * a / (math.hypot(d, a) + d) - b * math.asinh(b / d)

    return primitive(d2) - primitive(d1), a * math.log(d2 / d1)


def ledger_slice(history: RodHistory, frame_rapidity: float, t: float) -> Slice:
    """Each body's kinetic (E, p) on the slice t of the frame (particles just after any impact at t), and the hidden part."""
    bodies = [(p.name, particle_on_slice(history, p.name, frame_rapidity, t)) for p in sorted(history.scenario.particles,
                                                                                               key=lambda p: p.name)]
    bodies.append(("rod", rod_kinetic(history, frame_rapidity, t)))
    kinetic = ZERO
    for _, em in bodies:
        kinetic += em
    return Slice(t, tuple(bodies), kinetic, initial_total(history, frame_rapidity) - kinetic)
