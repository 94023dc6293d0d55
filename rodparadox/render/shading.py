"""How the causal rod's world-sheet is cut into cells of compression, shared by the figures (`causal_layers`) and the
html page (`web.causal_data`). Pure: no matplotlib, so the page, which never imports it, reads the same numbers.

The material chart is cut along the light lines u = T + X and w = T - X at every piece boundary of an invariant
and, inside a piece where the invariant varies, into cells no longer than CELL L and short enough that r changes by
about one shade of the compression scale (SHADES of them) from one cell to the next.
"""

from __future__ import annotations

import math
from typing import Callable, Sequence

import numpy as np

#: a varying piece of an invariant is cut into cells this long, as a fraction of L (the shading is flat per cell)
CELL = 1.0 / 24
#: a jump of an invariant smaller than this is no front (a piece boundary where r is continuous: a kink)
FRONT_JUMP = 1e-9
#: shades of the compression scale a cell may differ from its neighbour by at most about one of
SHADES = 64


def cell_edges(r: Callable[[float], float], breaks: Sequence[float], lo: float, hi: float, L: float, step: float,
               most: int | None = None, vectorised: bool = False) -> np.ndarray | None:
    """The cuts of [lo, hi]: each of `breaks` (the invariant's piece boundaries the caller takes inside), and inside
    a piece where r varies, cells no longer than CELL L and enough of them that r changes by about `step` (a shade
    of the scale) from one to the next. None where they would be more than `most`. `vectorised`: r takes an array
    (the page's tables: one call a piece)."""
    edges = [lo]
    cuts = [lo, *breaks, hi]
    for a, b in zip(cuts, cuts[1:]):
        at = (a + 1e-9 * (b - a), 0.5 * (a + b), b - 1e-9 * (b - a))
        ends = [float(x) for x in r(np.array(at))] if vectorised else [float(r(s)) for s in at]
        varies = max(ends) - min(ends)
        n = min(math.ceil((b - a) / (CELL * L)), math.ceil(2 * varies / step)) if varies > FRONT_JUMP else 1
        if most is not None and len(edges) + n > most:
            return None
        edges += list(np.linspace(a, b, max(n, 1) + 1)[1:])
    return np.array(edges)
