"""Figures legible at every speed (issue 14 item 4, issue 15 item 14): legends told apart in grey, material lines
thinned to what a panel can hold, the magnified inset of a thin world-sheet, `--equal-scales`.

Every figure here is drawn once (cached) and checked several ways; the thresholds are recomputed from the drawn
world-lines and the axes' own transforms, never read back from the code under test.
"""

from __future__ import annotations

import itertools
from functools import lru_cache

import numpy as np
import pytest
from matplotlib.legend_handler import HandlerTuple  # noqa: F401  (the rod's entry is a tuple of handles)
from matplotlib.lines import Line2D
from matplotlib.colors import to_rgb
from matplotlib.patches import Patch

from conftest import history
from rodparadox import render
from rodparadox.physics.frames import paper_frames
from rodparadox.render.layers import legend_entries
from rodparadox.render.styles import STYLE_NAMES, STYLES

EVERYTHING = render.Options(other_axes=True, light_cones=True, hyperbolae=True, grid=False, rod_lines=3, rod_now=True,
                            proper_time=True)
MM = 72 / 25.4  # points per millimetre


@lru_cache(maxsize=None)
def diagram(name: str, v: float, style: str = "default", options: render.Options = render.Options()):
    h = history(name, v)
    return render.draw(h, paper_frames(h.scenario.v), style, options)


# --- legends in grey --------------------------------------------------------------------------------------

def _grey_look(handle) -> tuple:
    """What a legend handle shows without colour: its line's dash pattern and width, its marker, a shaded patch."""
    parts = handle if isinstance(handle, tuple) else (handle,)
    lines = [p for p in parts if isinstance(p, Line2D)]
    patch = any(isinstance(p, Patch) for p in parts)
    line = lines[0]
    pattern = line._unscaled_dash_pattern[1]  # the style's dashes in units of the width (no public getter)
    marker = line.get_marker() if line.get_marker() not in (None, "None", "none", "") else None
    if marker:  # a filled dot and a hollow ring differ in grey: the face's lightness says which
        marker = (marker, round(float(np.dot(to_rgb(line.get_markerfacecolor()), (0.299, 0.587, 0.114))), 1))
    width = line.get_linewidth() if line.get_linestyle() not in ("None", "none", "") else 0.0
    return tuple(pattern) if pattern else None, width, marker, patch


def _told_apart(one: tuple, other: tuple) -> bool:
    """In grey: another dash pattern, another marker, a shaded patch, or a width at least 1.5 times the other's."""
    (d1, w1, m1, p1), (d2, w2, m2, p2) = one, other
    if d1 != d2 or m1 != m2 or p1 != p2:
        return True
    return min(w1, w2) > 0 and max(w1, w2) / min(w1, w2) >= 1.5


@pytest.mark.parametrize("style", STYLE_NAMES)
def test_every_legend_entry_differs_from_every_other_without_colour(style):
    """Issue 14.4: in grey the default legend's particles A and B were one dashed line; the hyperbolae and the
    material lines two thin solid ones. Every pair of entries must differ in dashes, width, marker or patch."""
    h = history("fig2", 0.6)
    handles, texts = legend_entries(STYLES[style], h, EVERYTHING, 1.0)
    assert len(texts) == 12  # every layer's entry is there
    looks = {text: _grey_look(handle) for handle, text in zip(handles, texts)}
    same = [(a, b) for (a, la), (b, lb) in itertools.combinations(looks.items(), 2) if not _told_apart(la, lb)]
    assert same == []
    # the pairs the issue named, by name
    assert looks["particle A"][0] != looks["particle B"][0]
    assert looks["material points inside the rod"][0] != looks["the rod's own lines of simultaneity"][0]


def test_the_grey_test_sees_a_planted_twin():
    """The check above has power: two entries that differ only in colour are caught."""
    a = Line2D([], [], color="#D55E00", linewidth=1.3, linestyle=(0, (5.0, 2.5)))
    b = Line2D([], [], color="#009E73", linewidth=1.3, linestyle=(0, (5.0, 2.5)))
    assert not _told_apart(_grey_look(a), _grey_look(b))
    assert _told_apart(_grey_look(a), _grey_look(Line2D([], [], linewidth=1.3, linestyle=(0, (8.0, 2.0, 3.0, 2.0)))))
