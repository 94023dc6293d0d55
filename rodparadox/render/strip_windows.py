"""Which stretch of a frame's x each row of a block of stills shows (`render.strip_block.draw_strips_into`). Pure: no
matplotlib, so a handout's caption can say which way its strips are drawn before anything is drawn.

One x range for every row, as long as the rod stays readable in it. Where the rod drifts far compared with its
own length (the causal rod in S′ at v = 0.95: it drifts 15 L, while it is 0.2 to 0.6 L long), one shared range
would shrink it to a blob; then each row follows the rod: every row is as wide (one scale, so lengths compare row
to row), centred on the rod at its instant, with its own ticks.
"""

from __future__ import annotations

import math
from functools import lru_cache
from typing import Sequence

import numpy as np

from rodparadox.physics.frames import Frame
from rodparadox.physics.history import RodHistory
from rodparadox.physics.snapshot import Strip, strip_at
from rodparadox.tolerances import ONE_INSTANT

#: the rows follow the rod when it spans, at its longest, less than this fraction of the range every rod end and
#: particle of the rows take (fig1's rigid rod in S′ at v = 0.95 spans 0.06 of it and reads well; its causal rod
#: 0.04, unequal_masses' 0.009: blobs)
FOLLOW_BELOW = 0.05
#: a following row is this many times the rod's greatest length wide
FOLLOW_WIDTH = 3.0
#: the margin of a shared range, a fraction of its width, and at least this many L
MARGIN, LEAST_MARGIN = 0.06, 0.1


def shared_range(strips: Sequence[Strip], L: float, reach: float = 0.0, width: float = 1.0) -> tuple[float, float]:
    """Every rod end and particle of the strips, with a margin: the x range (units of L) all rows share; `reach`
    points beyond each end kept free on rows `width` points wide (a force's longest arrow)."""
    xs = np.concatenate([np.concatenate([s.x, [x for _, x in s.particles]]) for s in strips]) / L
    lo, hi = float(xs.min()), float(xs.max())
    margin = max(MARGIN * (hi - lo), LEAST_MARGIN)
    if reach:
        margin = max(margin, reach * (hi - lo) / (width - 2.0 * reach))
    return lo - margin, hi + margin


def follows_rod(strips: Sequence[Strip], L: float) -> bool:
    """Whether rows of these instants each follow the rod (`FOLLOW_BELOW`)."""
    lo, hi = shared_range(strips, L)
    longest = max(float(s.x[-1] - s.x[0]) for s in strips) / L
    return longest < FOLLOW_BELOW * (hi - lo)


def row_ranges(strips: Sequence[Strip], L: float, span: Sequence[Strip] | None = None
               ) -> tuple[tuple[float, float], ...] | None:
    """Each row's x range (units of L), as wide as every other, centred on the rod at its instant; None where one
    shared range serves (`follows_rod`). `span`: the whole block's strips, when these are a part of it set on one
    page: the parts' rows are then as wide as each other."""
    whole = strips if span is None else span
    if not follows_rod(whole, L):
        return None
    half = 0.5 * FOLLOW_WIDTH * max(float(s.x[-1] - s.x[0]) for s in whole) / L
    return tuple((c - half, c + half) for c in (0.5 * float(s.x[0] + s.x[-1]) / L for s in strips))


def strips_follow_rod(history: RodHistory, frame: Frame, times: Sequence[float]) -> bool:
    """Whether the block of stills of `history` at these instants of `frame` draws each row following the rod: what
    its caption must say."""
    L = history.scenario.L
    return follows_rod(strips_at(history, frame, tuple(sorted(float(t) for t in times)), ONE_INSTANT * L), L)


@lru_cache(maxsize=64)
def strips_at(history: RodHistory, frame: Frame, times: tuple[float, ...], flash: float) -> tuple[Strip, ...]:
    """The strips (`physics.snapshot.strip_at`) of these instants, kept: a handout measures a block of strips for
    every row count it tries, then draws it, and its caption says whether the rows follow the rod
    (`strips_follow_rod`). Their arrays are made read-only, as they are shared."""
    return tuple(_strip_at(history, frame, t, flash, math.copysign(1.0, t)) for t in times)


@lru_cache(maxsize=512, typed=True)
def _strip_at(history: RodHistory, frame: Frame, t: float, flash: float, sign: float) -> Strip:
    """One instant's strip, kept: the blocks of one frame share instants (a block measured, its partner's rows, the
    caption's question), each asked for as a whole (a handout of the forces presets read a third of its strips
    twice). Its arrays are made read-only, as it is shared. `sign`: t's, keeping -0.0 apart from 0.0."""
    strip = strip_at(history, frame, t, flash)
    for array in (strip.sigma, strip.x, strip.velocity):
        array.flags.writeable = False
    return strip


def outside(strip: Strip, window: tuple[float, float], L: float) -> tuple[tuple[str, str], ...]:
    """The particles a row's window leaves out, each with the side it is beyond: (name, "left" | "right")."""
    lo, hi = window
    return tuple((name, "left" if x / L < lo else "right") for name, x in strip.particles if not lo <= x / L <= hi)
