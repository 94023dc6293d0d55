"""The causal rod's fields' extremes over its whole history: the least and largest compression and rapidity of
any material point (docs, "The causal rod"), for colour scales that mean the same at every instant. Pure.
"""

from __future__ import annotations

import functools
import math

import numpy as np


@functools.lru_cache(maxsize=16)
def _chart_extremes(history) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """r+(u), r-(w) on a grid of each invariant's pieces (both sides of every jump, and inside), over the whole
    history (the ringing tail is periodic: one period of it is all of it), and which (u, w) pairs lie in the rod.
    Read once per history (both ranges below read it; a history is immutable), bounded like them."""
    sol, L = history.solution, history.scenario.L
    lo = min(sol.plus.starts[0], sol.minus.starts[0]) - 2 * L
    hi = max(sol.plus.tail_start, sol.minus.tail_start) + 3 * L
    us, ws = _knots(sol.plus, lo, hi), _knots(sol.minus, lo, hi)
    rp = np.array([sol.r_plus(u) for u in us])
    rm = np.array([sol.r_minus(w) for w in ws])
    inside = (us[None, :] - ws[:, None] >= -1e-12) & (us[None, :] - ws[:, None] <= 2 * L + 1e-12)
    return rp, rm, inside


def _knots(invariant, lo: float, hi: float) -> np.ndarray:
    cuts = [lo, *invariant.breaks(lo, hi), hi]
    out = []
    for a, b in zip(cuts, cuts[1:]):
        out += list(np.linspace(a, b, 9)[:-1]) + [np.nextafter(b, -math.inf)]
    return np.array(out)


@functools.lru_cache(maxsize=16)
def compression_range(history) -> tuple[float, float]:
    """The least and largest ln lam (lam = exp(-(r+ + r-)/2)) anywhere in the causal rod over its whole history,
    with 0 (unstressed) always inside."""
    rp, rm, inside = _chart_extremes(history)
    ln_lam = -0.5 * (rp[None, :] + rm[:, None])
    return float(min(0.0, ln_lam[inside].min())), float(max(0.0, ln_lam[inside].max()))


@functools.lru_cache(maxsize=16)
def causal_rapidity_range(history) -> tuple[float, float]:
    """The least and largest rapidity in S (th = (r+ - r-)/2) of any material point of the causal rod, 0 included."""
    rp, rm, inside = _chart_extremes(history)
    th = 0.5 * (rp[None, :] - rm[:, None])
    return float(min(0.0, th[inside].min())), float(max(0.0, th[inside].max()))
