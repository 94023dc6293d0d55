"""What every layer shares: the options, the panel a layer draws into, what it gives back, the `Layer` base class,
and how a style's ink becomes matplotlib keywords (docs/plot.md, "Drawing the figures"). `layers` holds the layers."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, NamedTuple

import numpy as np
from matplotlib.lines import Line2D

from rodparadox.physics.history import RodHistory
from rodparadox.physics.frames import FrameView
from rodparadox.render.styles import Ink, Style


def has_fronts(history) -> bool:
    """The run has fronts (the causal rod's capability, whose chart its own layers read); any other draws none of them."""
    return history.fronts is not None


class Options(NamedTuple):
    """The teacher's extras, all off by default because they crowd a printed figure; and what keeps a fast
    scenario legible (`insets`, on by default; `equal_scales`)."""

    other_axes: bool = False  # the other frame's x and t axes, tilted
    light_cones: bool = False  # the light cone of every impact
    hyperbolae: bool = False  # calibration hyperbolae t^2 - x^2 = +-k^2 about the shared origin
    grid: bool = False
    titled: bool = True  # the scenario's name and v above the panels (a handout's section heading says it instead)
    rod_lines: int = 0  # this many interior material world-lines of the rod
    rod_now: bool = False  # the rod's own lines of simultaneity: each turn's fan, and lines between turns
    proper_time: bool = False  # clock ticks of equal proper time along each particle and each rod end
    equal_scales: bool = False  # every panel drawn to one scale (points per L), not each filling its panel
    insets: bool = True  # a magnified inset where the world-sheet is drawn thinner than a few millimetres
    simultaneity: bool = True  # the lines of simultaneity of S and S' through every impact (a worksheet asks them)


# --- ink: how the style says a line or a marker is drawn, in one place ---------------------------------------

def line_kwargs(ink: Ink) -> dict[str, Any]:
    """matplotlib's keywords for a line drawn in `ink`."""
    return {"color": ink.colour, "linewidth": ink.width, "linestyle": ink.dashes}


def marker_kwargs(size: float, face: str, edge: str, edge_width: float) -> dict[str, Any]:
    """matplotlib's keywords for round markers without a line."""
    return {"linestyle": "none", "marker": "o", "markersize": size, "markerfacecolor": face,
            "markeredgecolor": edge, "markeredgewidth": edge_width}


def impact_marker(style: Style) -> dict[str, Any]:
    """An impact: a filled dot with a white rim, so it reads on top of any line."""
    return marker_kwargs(style.impact_size, style.impact_colour, "white", 0.6)


def clock_marker(style: Style, ink: Ink) -> dict[str, Any]:
    """A tick of proper time: a hollow circle in the world-line's colour."""
    return marker_kwargs(style.clock_size, "white", ink.colour, 0.8)


def separation_marker(style: Style) -> dict:
    """A separation: a hollow marker, told from a contact (filled) in any ink."""
    return marker_kwargs(style.impact_size, "white", style.impact_colour, 1.0)


def line_handle(ink: Ink) -> Line2D:
    return Line2D([], [], **line_kwargs(ink))


def widest_line(style: Style) -> float:
    """The widest line a label must keep clear of."""
    return max(ink.width for ink in (style.rod, *style.particles.values(), style.rest_simultaneity,
                                     style.moving_simultaneity, style.other_axes, style.light_cone, style.hyperbola))


#: a rod driven by forces: its own lines of simultaneity at each stage's start and this many more while driven
#: (12 hatched Sears's one-L pulse into a solid block)
NOW_LINES_DRIVEN = 6


def own_now_lines(history) -> list:
    """The rod's own lines of simultaneity, (left end, right end) event pairs in S: a rigid rod's turns and the
    lines between them (`turning`), or a rigid rod driven by forces (`driving`); none for a rod without them."""
    if history.turning is not None:
        return history.turning.now_lines()
    return history.driving.now_lines(NOW_LINES_DRIVEN) if history.driving is not None else []


def contacts_last(history) -> bool:
    """Whether the rod's contacts last, each ended by a separation (the causal rod's): its ends crowd with contacts,
    re-contacts and separations, and its impacts are named contacts."""
    return any(i.is_separation for i in history.impacts)


# --- what a layer is given and gives back ------------------------------------------------------------------

@dataclass(frozen=True)
class PanelContext:
    """One panel as the layers see it: the history in one frame, the axes' limits and tick steps, the style."""

    history: RodHistory
    style: Style
    options: Options
    fs: dict[str, float]  # type sizes, points
    letter: str
    view: FrameView
    worldlines: dict[str, np.ndarray]  # units of L
    box: tuple[float, float, float, float]  # the axes' limits x0, x1, t0, t1, units of L
    steps: tuple[float, float]  # the x and t tick steps, units of L
    clock_step: float  # proper time between two clock ticks, same units as L
    rod_lines: int | None = None  # material lines drawn here (fewer than asked where they would crowd); None: asked
    scale: float | None = None  # points per L on the page (a force's band is as wide in points in every panel)

    @property
    def L(self) -> float:
        return self.history.scenario.L

    @property
    def v(self) -> float:
        return self.history.scenario.v

    def events(self) -> list[tuple[str, str, float, float]]:
        """Every impact in this frame: (label, end of the rod, x/L, t/L)."""
        return [(e.impact.label, e.impact.end, e.x / self.L, e.t / self.L) for e in self.view.events]

    def force_events(self) -> list[tuple[str, str, float, float]]:
        """Each force's start and end in this frame, for a rod driven by forces (`RodHistory.driving`; none
        otherwise): (label `left-start`, ..., end of the rod, x/L, t/L), ends in order, moments in order."""
        driving = self.history.driving
        if driving is None:
            return []
        eta = self.view.frame.rapidity
        return [(f"{e.end}-{e.moment}", e.end, e.event.seen_from(eta).x / self.L, e.event.seen_from(eta).t / self.L)
                for e in driving.force_events() if e.moment in ("start", "end")]

    @property
    def contact_labels(self) -> frozenset[str]:
        """The labels of this frame's contacts (every rigid impact; a causal rod's separations are not)."""
        return frozenset(e.impact.label for e in self.view.events if not e.impact.is_separation)

    @property
    def simultaneity_labels(self) -> frozenset[str]:
        """The events lines of simultaneity go through: every impact of a rod whose impacts are instantaneous; of a
        rod whose contacts last (a causal rod), each particle's first contact (its re-contacts and separations crowd
        one end: more lines there would hide them)."""
        if not contacts_last(self.history):  # every impact instantaneous: each gets its line
            return self.contact_labels
        first = {}
        for e in self.view.events:
            if not e.impact.is_separation:
                first.setdefault(e.impact.particle, e.impact.label)
        return frozenset(first.values())

    def plot(self, ax, points: np.ndarray, ink: Ink, zorder: float, gid: str):
        """A polyline in `ink`: the one way layers draw a line."""
        line, = ax.plot(points[:, 0], points[:, 1], **line_kwargs(ink), zorder=zorder, gid=gid)
        return line


class LayerArtists(NamedTuple):
    """What a layer drew in one panel."""

    artists: tuple = ()
    obstacles: tuple = ()  # polylines (n x 2, units of L) that no label may cross
    guides: tuple = ()  # polylines a label may cross, on a white ground
    labels: tuple = ()  # Labels to place once every layer has drawn


class Layer:
    """One element of the diagram; see the module's docstring."""

    name = ""
    label_rank = 0

    def enabled(self, options: Options) -> bool:
        return True

    def applies(self, history) -> bool:
        """Whether the layer draws anything for this rod model (the causal rod's own layers: only for it)."""
        return True

    def draw(self, ax, panel: PanelContext) -> LayerArtists:
        raise NotImplementedError

    def legend_entry(self, style: Style, history: RodHistory, options: Options,
                     clock_step: float | None = None) -> tuple[Any, str] | None:
        return None


def line_in_box(x: float, t: float, dx: float, dt: float, box, lo: float = -math.inf) -> tuple[float, float] | None:
    """The parameters (lo, hi) of the line (x, t) + s (dx, dt), s >= `lo`, inside box = (x0, x1, t0, t1), or None
    if it misses the box."""
    x0, x1, t0, t1 = box
    hi = math.inf
    for p, a, b in ((dx, x0 - x, x1 - x), (dt, t0 - t, t1 - t)):
        if p == 0.0:
            if a > 0 or b < 0:
                return None
            continue
        s0, s1 = sorted((a / p, b / p))
        lo, hi = max(lo, s0), min(hi, s1)
    return (lo, hi) if lo < hi else None


def clip_line(x: float, t: float, dx: float, dt: float, box) -> np.ndarray | None:
    """The part inside box = (x0, x1, t0, t1) of the infinite line through (x, t) along (dx, dt), or None."""
    inside = line_in_box(x, t, dx, dt, box)
    if inside is None:
        return None
    lo, hi = inside
    return np.array([[x + lo * dx, t + lo * dt], [x + hi * dx, t + hi * dt]])
