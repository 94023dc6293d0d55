"""The layers of a rod driven by forces at its ends (docs/model.md, "Forces at the ends"): each force drawn as a band
along its end's world-line, as wide as the force, with arrows that press into the rod or pull out of it; and each
force's start and end marked and labelled.

Each applies (`ForceLayer.applies`) to a run with the `driving` capability alone (`RodHistory.driving` not None).

A force F is the push of its agent in the end's momentary rest frame, the same in every frame: so a band is drawn
the same number of points wide for the same F in every panel (`band_points` for the legend's force `force_scale`),
on the outside of its end, horizontally (in x, at the event of the end where the profile reads F). The force at a
point of the drawn end is read from the profile at that event's time in the profile's own frame, so the band
follows the world-line the panel draws, kinks and jumps included.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from matplotlib.legend_handler import HandlerBase
from matplotlib.lines import Line2D
from matplotlib.patches import FancyArrowPatch, Polygon, Rectangle

from rodparadox.numbers import nice_number, shown
from rodparadox.render.labels import Label
from rodparadox.render.layer_base import Layer, LayerArtists, impact_marker, line_kwargs
from rodparadox.render.styles import Style

#: the width of a band, in the style's type size (9 points in the default style), for the legend's force
#: (`force_scale`): no band is wider
BAND_EMS = 1.0
#: samples of a profile along its support (its corners and jumps besides): a sine^2 band smooth on any page
BAND_SAMPLES = 160
#: arrows along a force's support, at the middles of this many equal parts of it in the profile's time
ARROWS = 6
#: no arrow where the band is narrower than this fraction of `band_points` (its head would be larger than it)
ARROW_LEAST = 0.3
#: a pull's band is hatched as well, so that it is told from a push without colour
PULL_HATCH = "////"
#: the labels of a force's start and end, beside their markers
MOMENT_WORDS = {"start": "on", "end": "off"}


def band_points(style: Style) -> float:
    """The width in points of a band at the legend's force: BAND_EMS of the style's type size."""
    return BAND_EMS * style.font_size


def force_scale(history) -> float:
    """The force (units of M c^2/L) a band `band_points` wide shows: the least nice number not below the largest
    |F| of any profile, so no band is wider."""
    greatest = max(max(abs(p.least()), abs(p.greatest())) for _, p in history.driving.profiles())
    return nice_number(greatest, "at_least")


def profile_time(points: np.ndarray, panel_rapidity: float, profile_rapidity: float) -> np.ndarray:
    """The time, in the profile's frame, of each event (x, t) of a panel in the frame of rapidity `panel_rapidity`
    (both relative to S): t_F = cosh(d) t - sinh(d) x, d the profile's frame's rapidity relative to the panel's."""
    d = profile_rapidity - panel_rapidity
    return math.cosh(d) * points[:, 1] - math.sinh(d) * points[:, 0]


def band(points: np.ndarray, profile, panel_rapidity: float, profile_rapidity: float) -> tuple[np.ndarray, np.ndarray]:
    """The end's world-line as a panel draws it (`points`, (n, 2) of x/L, t/L) where the force acts, and the force
    there: (m, 2) points and m forces, at the drawn vertices and BAND_SAMPLES instants over the profile's support
    (a jump's instant twice, with the force before and after it), in the order of time; empty where the force
    acts outside the drawn part."""
    times = profile_time(points, panel_rapidity, profile_rapidity)  # rises along a time-like world-line
    lo, hi = profile.support()
    lo, hi = max(lo, times[0]), min(hi, times[-1])
    if not lo < hi:
        return np.empty((0, 2)), np.empty(0)
    instants, forces = profile_samples(profile, lo, hi, BAND_SAMPLES, times[(times > lo) & (times < hi)])
    x = np.interp(instants, times, points[:, 0])
    t = np.interp(instants, times, points[:, 1])
    return np.column_stack([x, t]), np.asarray(forces, dtype=float)


def profile_samples(profile, lo: float, hi: float, samples: int, extra=()) -> tuple[np.ndarray, np.ndarray]:
    """Instants of the profile's time from lo to hi (`samples` of them, its corners, `extra`) and the force at each,
    in order; a jump's instant twice, with the force before and after it."""
    corners = [b for b in profile.pieces() if lo <= b <= hi]
    instants = np.unique(np.concatenate([np.linspace(lo, hi, samples), np.asarray(extra, dtype=float), corners]))
    forces = profile.value(instants)  # right-continuous: at a jump, the force after it
    for b in (b for b in profile.jumps() if lo <= b <= hi):  # and the force before it, at the same instant
        k = int(np.searchsorted(instants, b))
        instants = np.insert(instants, k, b)
        forces = np.insert(forces, k, profile.piece_value(profile.piece_index(b) - 1, b))
    return instants, np.asarray(forces, dtype=float)


def outside(end: str) -> float:
    """The side of the end where its agent is, in x: -1 at the left end, +1 at the right."""
    return -1.0 if end == "left" else 1.0


class ForceLayer(Layer):
    """A layer only a rod driven by forces draws."""

    def applies(self, history):
        return history.driving is not None


@dataclass(frozen=True)
class ForceBands(ForceLayer):
    """Each force as a band along its end's world-line, on the outside, as wide as F (`band_points` for
    `force_scale`), with arrows into the rod where it presses and out of it where it pulls (a pull's band hatched)."""

    name = "forces"

    def draw(self, ax, panel):
        driving, st, eta = panel.history.driving, panel.style, panel.view.frame.rapidity
        per_force = band_points(st) / force_scale(panel.history) / panel.scale  # units of L per unit of force
        artists, edges = [], []
        for end, profile in driving.profiles():
            points, forces = band(panel.worldlines[f"rod_{end}"], profile, eta, driving.frame_rapidity(end))
            if not len(forces):
                continue
            side = outside(end)
            for sense, part in (("press", np.maximum(forces, 0.0)), ("pull", np.minimum(forces, 0.0))):
                if not part.any():
                    continue
                outer = points.copy()
                outer[:, 0] += side * per_force * np.abs(part)
                artists.append(ax.add_artist(Polygon(
                    np.concatenate([points, outer[::-1]]), closed=True, facecolor=st.force_fill, edgecolor="none",
                    hatch=PULL_HATCH if sense == "pull" else None, zorder=3.6, gid=f"{panel.letter}-force-{end}-{sense}")))
                edge = np.where((part != 0.0)[:, None], outer, np.nan)  # no edge where this sense has no force
                line, = ax.plot(edge[:, 0], edge[:, 1], **line_kwargs(st.force), zorder=3.7,
                                gid=f"{panel.letter}-force-edge-{end}-{sense}")
                artists.append(line)
                edges.append(outer[part != 0.0])
            artists += self._arrows(ax, panel, end, profile, points, forces, per_force)
        return LayerArtists(artists=tuple(artists), obstacles=tuple(e for e in edges if len(e) > 1))

    @staticmethod
    def _arrows(ax, panel, end: str, profile, points: np.ndarray, forces: np.ndarray, per_force: float) -> list:
        """Arrows at the middles of ARROWS equal parts of the support (in the profile's time) where the band is
        wide enough: pressing ones end on the rod's end, pulling ones start there."""
        st, eta = panel.style, panel.view.frame.rapidity
        times = profile_time(points, eta, panel.history.driving.frame_rapidity(end))
        lo, hi = profile.support()
        out = []
        least = ARROW_LEAST * force_scale(panel.history)
        for k in range(ARROWS):
            instant = lo + (k + 0.5) * (hi - lo) / ARROWS
            if not times[0] <= instant <= times[-1]:
                continue
            force = float(profile.value(instant))
            if abs(force) < least:
                continue
            x, t = float(np.interp(instant, times, points[:, 0])), float(np.interp(instant, times, points[:, 1]))
            tip_out = x + outside(end) * per_force * abs(force)
            tail, head = ((tip_out, t), (x, t)) if force > 0 else ((x, t), (tip_out, t))
            arrow = FancyArrowPatch(tail, head, arrowstyle="-|>", mutation_scale=0.55 * band_points(st),
                                    color=st.force.colour, linewidth=st.force.width, shrinkA=0.0, shrinkB=0.0,
                                    zorder=3.75, gid=f"{panel.letter}-force-arrow-{end}-{k}")
            out.append(ax.add_artist(arrow))
        return out

    def legend_entry(self, style, history, options, clock_step=None):
        if not self.applies(history):
            return None
        scale = shown(force_scale(history), 4)
        pulls = any(p.least() < 0 for _, p in history.driving.profiles())
        return ForceKey(style, pulls), (f"force on an end: this wide at {scale} $Mc^2/L$"
                                        + ("; hatched: a pull" if pulls else ""))


@dataclass(frozen=True)
class ForceMoments(ForceLayer):
    """Each force's start and end at its end: a marker, labelled on and off (the lines of simultaneity through
    them are the `Simultaneity` layers')."""

    name = "force-events"
    label_rank = 0  # beside its marker

    def draw(self, ax, panel):
        st, fs = panel.style, panel.fs
        markers, labels = [], []
        for label, end, x, t in panel.force_events():
            marker, = ax.plot([x], [t], **impact_marker(st), zorder=7, gid=f"{panel.letter}-force-event-{label}")
            markers.append(marker)
            labels.append(Label(f"{panel.letter}-force-event-label-{label}", MOMENT_WORDS[label.split("-")[1]],
                                ((x, t),), 180.0 if end == "left" else 0.0, st.impact_colour, fs["impact"],
                                avoid_radius=st.impact_size / 2 + 1.0))
        return LayerArtists(artists=tuple(markers), labels=tuple(labels))

    def legend_entry(self, style, history, options, clock_step=None):
        if not self.applies(history):
            return None
        return Line2D([], [], **impact_marker(style)), "a force starts (on) or ends (off)"


def strip_arrow(ax, style: Style, end: str, animated: bool) -> FancyArrowPatch:
    """The arrow of a strip's driven end (`strip.draw_strip`), placed and sized by `strip.update_strip`."""
    return ax.add_patch(FancyArrowPatch((0.0, 0.0), (0.0, 0.0), arrowstyle="-|>", mutation_scale=0.8 * band_points(style),
                                        color=style.force.colour, linewidth=1.5 * style.force.width, shrinkA=0.0,
                                        shrinkB=0.0, zorder=4, animated=animated))


@dataclass(frozen=True)
class ForceKey:
    """The legend's handle of the force bands: a band `band_points` wide against an end, with an arrow."""

    style: Style
    pulls: bool


class ForceKeyHandler(HandlerBase):
    """Draws a `ForceKey`: the rod's end on the right of the handle box, a band `band_points` wide left of it with
    an arrow pressing in (and, where a profile pulls, a hatched one beside it)."""

    def create_artists(self, legend, orig_handle, xdescent, ydescent, width, height, fontsize, trans):
        st = orig_handle.style
        wide = band_points(st)
        x1, y0, h = width - xdescent, -ydescent - 0.25 * height, 1.5 * height
        artists = []
        bands = ((x1 - wide, False),) if not orig_handle.pulls else ((x1 - wide, False), (x1 - 2.5 * wide, True))
        for left, pull in bands:
            artists.append(Rectangle((left, y0), wide, h, facecolor=st.force_fill, edgecolor=st.force.colour,
                                     linewidth=st.force.width, hatch=PULL_HATCH if pull else None, transform=trans))
            end = left + wide
            artists.append(Line2D([end, end], [y0, y0 + h], **line_kwargs(st.rod), transform=trans))
            tail, head = ((left, y0 + h / 2), (end, y0 + h / 2)) if not pull else ((end, y0 + h / 2), (left, y0 + h / 2))
            artists.append(FancyArrowPatch(tail, head, arrowstyle="-|>", mutation_scale=0.55 * wide,
                                           color=st.force.colour, linewidth=st.force.width, shrinkA=0.0, shrinkB=0.0,
                                           transform=trans))
        return artists


#: the legend's handlers of the force layers' handles
HANDLER_MAP = {ForceKey: ForceKeyHandler()}
