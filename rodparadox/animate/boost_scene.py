"""Boost mode (docs/animate.md, "The paradox in motion"): one panel over fixed axes whose frame runs smoothly from one
velocity to another, the world-lines redrawn in the frame of each instant. matplotlib (Agg) is imported here; import this
module only after every input has been checked.

The world-sheet, the world-lines of the particles and of the rod's ends, and the impacts' markers are `plot`'s
own layers (`render.layers`), drawn into the panel in the frame of each instant, so they look as in `plot`'s
panels. Boost mode's own are what `plot` draws otherwise: the axes of both S and S' (plot's `OtherAxes` draws only
the other frame's, in another ink), and the letters and impact labels at fixed offsets on a white ground (plot
places them with its label placer, which would move them from instant to instant).
"""

from __future__ import annotations

import math
from typing import Iterator

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.ticker import FuncFormatter, MaxNLocator, ScalarFormatter

from rodparadox.animate.images import blitted, in_style
from rodparadox.animate.timeline import BoostTimeline, boost_tolerance
from rodparadox.numbers import impact_name, shown
from rodparadox.physics.types import WORLDLINE_NAMES
from rodparadox.physics.history import RodHistory
from rodparadox.physics.frames import Frame, sampling_tolerance, view
from rodparadox.physics.model import frame_velocity
from rodparadox.render.causal_layers import HANDLER_MAP, Compression, Fronts
from rodparadox.render.force_layers import HANDLER_MAP as FORCE_HANDLERS, ForceBands, ForceMoments
from rodparadox.render.layers import (Impacts, Options, PanelContext, Particle, RodEnds, Separations, WorldSheet,
                                      line_kwargs, separation_text)
from rodparadox.render.layer_base import line_in_box
from rodparadox.render.layout import font_sizes
from rodparadox.render.styles import STYLES
from rodparadox.render.text import text_size, tick_text

#: plot's layers drawn at each instant: the world-sheet (under the axes of S and S'), then the bodies (the
#: particles under the rod's ends), then the impacts' markers (over the bodies)
#: the sheet: plain for the rigid rod; the causal rod's shaded by compression, crossed by its fronts (`causal_layers`)
SHEET, BODIES, IMPACTS = (WorldSheet(), Compression(), Fronts()), (Particle("A"), Particle("B"), RodEnds()), Impacts()
#: a rod driven by forces: each force's band along its end, and its start and end marked (`force_layers`)
FORCES = (ForceBands(), ForceMoments())
SEPARATIONS = Separations()
#: the layers' options: none of plot's extras
OPTIONS = Options()


def boost_images(history: RodHistory, timeline: BoostTimeline, style: str) -> Iterator[np.ndarray]:
    """Each instant of the boost as an image: `BoostScene` drawn once, then at each instant only what moves, over
    the saved background (blitting)."""
    def draw() -> Iterator[np.ndarray]:
        scene = BoostScene(history, timeline, style)
        return blitted(scene.canvas, (scene.update(k) for k in range(len(timeline))))

    return in_style(style, draw)  # the style's rcParams only while an image is drawn


class BoostScene:
    """Boost mode's figure: one panel over fixed axes (equal scales: light at 45 degrees); `update(k)` redraws in
    the frame of instant k the world-lines, the rod's world-sheet, the impacts and the axes of S and S' (tilted,
    through the shared origin; S's in the ink of its lines of simultaneity, S''s in theirs, as `plot` draws them),
    and returns the artists it drew, in drawing order. A key to the right names every line; the title names the
    frame of the instant. Build it inside `render.style_context(style)`."""

    def __init__(self, history: RodHistory, timeline: BoostTimeline, style: str):
        from rodparadox import render

        self.history, self.timeline = history, timeline
        self.style = st = STYLES[style]
        fs = st.font_size
        big = 1.35 * fs  # the axes' names and the particles' letters: read from the back of a lecture hall
        ground = {"boxstyle": "round,pad=0.12", "facecolor": "white", "edgecolor": "none", "alpha": 0.85}
        axis_inks = {"rest": st.rest_simultaneity, "moving": st.moving_simultaneity}
        axis_inks = {frame: ink._replace(width=1.3 * ink.width) for frame, ink in axis_inks.items()}
        key = [(Line2D([], [], **line_kwargs(st.rod)), "rod")]
        key += [entry for entry in (layer.legend_entry(st, history, OPTIONS) for layer in FORCES) if entry]
        key += [entry for entry in (layer.legend_entry(st, history, OPTIONS) for layer in BODIES[:2]) if entry]
        key += [*(e for e in (layer.legend_entry(st, history, OPTIONS) for layer in (IMPACTS, SEPARATIONS, *SHEET[1:]))
                  if e),
                (Line2D([], [], **line_kwargs(axis_inks["rest"])), "axes of S"),
                (Line2D([], [], **line_kwargs(axis_inks["moving"])), "axes of S\N{PRIME}")]
        key_width = (3.4 * fs + max(render.text_size(text, fs)[0] for _, text in key)) / 72  # inches
        width, most = st.boost_size  # the page's (or slide's) width, and at most its height
        left, bottom, top = 4.6 * fs / 72, 3.4 * fs / 72, 3.2 * fs / 72  # inches: tick labels and names; title
        side = min(most - bottom - top, width - left - key_width - 0.5)
        height = side + bottom + top
        self.figure = figure = Figure(figsize=(width, height), dpi=st.animation_dpi)
        self.canvas = FigureCanvasAgg(figure)
        self.ax = ax = figure.add_axes((left / width, bottom / height, side / width, side / height))
        L = history.scenario.L
        (x0, x1), (t0, t1) = (np.array(timeline.x_window) / L), (np.array(timeline.t_window) / L)
        span = 1.04 * max(x1 - x0, t1 - t0)  # a square panel with equal scales: the shorter side widened
        (x0, x1), (t0, t1) = [(0.5 * (a + b) - span / 2, 0.5 * (a + b) + span / 2) for a, b in ((x0, x1), (t0, t1))]
        self.box = (x0, x1, t0, t1)
        self.scale = side * 72 / (x1 - x0)  # points per L: a force's band is as wide on the page as in plot
        ax.set_xlim(x0, x1)
        ax.set_ylim(t0, t1)
        # real times and places on the ticks, never an offset (+5e4 over the title) or a shared power of ten: a
        # boost at tiny v shows a window far from the origin; the figure widens for the t labels, x ticks thin out
        for axis in (ax.xaxis, ax.yaxis):
            _real_tick_labels(axis)
        widest_t = max(text_size(label, fs)[0] for label in _tick_labels(ax.yaxis))
        # the t labels, the tick and its pad, the axis name's pad and the height of its letters: the room they need
        grow = max(0.0, (widest_t + st.tick_length + 3.5 + 4.0 + 0.8 * 1.1 * fs) / 72 - left)
        if grow > 0.0:
            left, width = left + grow, width + grow
            figure.set_size_inches(width, height)
            ax.set_position((left / width, bottom / height, side / width, side / height))
        _thin_x_ticks(ax, side * 72, fs)
        ax.set_xlabel("x/L in the frame of the instant", fontsize=1.1 * fs)
        ax.set_ylabel("t/L", fontsize=1.1 * fs)
        ax.tick_params(labelsize=fs)
        self.title = ax.set_title("", fontsize=1.2 * fs, loc="left", pad=0.6 * fs)
        self.title.set_animated(True)
        self.axes_of = {(frame, axis): ax.plot([], [], **line_kwargs(axis_inks[frame]), zorder=2, animated=True)[0]
                        for frame in ("rest", "moving") for axis in ("x", "t")}
        self.names = {(frame, axis): ax.text(0, 0, axis + ("\N{PRIME}" if frame == "moving" else ""), ha="center",
                                             va="center", color=axis_inks[frame].colour, fontsize=big, style="italic",
                                             zorder=9, bbox=ground, animated=True)
                      for frame, axis in self.axes_of}
        self.particles = {name: ax.text(0, 0, name, ha="left", va="center", color=st.particles[name].colour,
                                        fontsize=big, style="italic", zorder=9, bbox=ground, animated=True)
                          for name in ("A", "B") if history.worldline(name) is not None}
        self.labels = [ax.text(0, 0, impact_name(i.label, math_text=True) if not i.is_separation else
                               separation_text(i.label, fs)[0], fontsize=1.1 * fs, va="center", zorder=9,
                               bbox=ground, animated=True) for i in history.impacts]
        figure.legend([h for h, _ in key], [text for _, text in key], loc="upper left",
                      bbox_to_anchor=((left + side + 0.3) / width, 1 - top / height), fontsize=fs,
                      handlelength=2.6, labelspacing=0.7, borderaxespad=0.0,
                      handler_map={**HANDLER_MAP, **FORCE_HANDLERS})
        self.reach = 2.0 * max(abs(x0), abs(x1), abs(t0), abs(t1))  # the axes run past the panel's every side
        self.font_sizes = font_sizes(st)
        self.layered: tuple = ()  # what the layers drew at the last instant, taken away at the next

    def panel(self, frame: Frame) -> PanelContext:
        """The panel as plot's layers see it, in `frame`: its world-lines sampled over the whole boost's time
        window (the axes stay still while they move)."""
        history, L = self.history, self.history.scenario.L
        tolerance = boost_tolerance(sampling_tolerance(history), self.timeline.t_window)
        named = ((name, history.worldline(name)) for name in WORLDLINE_NAMES)  # the rod interface's names
        points = {name: w.seen_from(frame.rapidity).sample(*self.timeline.t_window, tolerance) / L
                  for name, w in named if w is not None}
        # no layer drawn here has ticks or clocks: their steps are not needed
        return PanelContext(history, self.style, OPTIONS, self.font_sizes, "boost", view(history, frame), points,
                            self.box, (math.nan, math.nan), math.nan, scale=self.scale)

    def update(self, k: int) -> tuple:
        from rodparadox import render

        history, L, v = self.history, self.history.scenario.L, self.history.scenario.v
        box, reach, ax = self.box, self.reach, self.ax
        frame = self.timeline.frames[k]
        eta = frame.rapidity
        for artist in self.layered:
            artist.remove()
        panel = self.panel(frame)
        # each layer where the run has what it draws (the compression and fronts: a run with fronts)
        sheet = tuple(artist for layer in SHEET if layer.applies(history) for artist in layer.draw(ax, panel).artists)
        forces = tuple(artist for layer in FORCES if layer.applies(history) for artist in layer.draw(ax, panel).artists)
        bodies = tuple(artist for layer in BODIES if layer.applies(history) for artist in layer.draw(ax, panel).artists)
        impacts = IMPACTS.draw(ax, panel).artists
        self.layered = (*sheet, *forces, *bodies, *impacts)
        for (other, axis), line in self.axes_of.items():
            u = render.relative_velocity(frame_velocity(other, v), frame.velocity)  # that frame, seen here
            dx, dt = (u, 1.0) if axis == "t" else (1.0, u)
            line.set_data([-reach * dx, reach * dx], [-reach * dt, reach * dt])
            end = _inside_end(dx, dt, box)  # None: the axis's positive half misses the panel (a window far away)
            self.names[(other, axis)].set_visible(end is not None)
            if end is not None:
                self.names[(other, axis)].set_position(end)
        for name, text in self.particles.items():  # beside the world-line, as high up as it is inside the panel
            place = _letter_place(history.worldline(name).seen_from(eta), L, box)
            text.set_visible(place is not None)
            if place is not None:
                text.set_position(place)
        for text, e in zip(self.labels, panel.events()):
            place = (e[2] + 0.025 * (box[1] - box[0]), e[3])
            # a text far outside the panel is not drawn: Agg's glyph rasteriser overflows at such coordinates
            text.set_visible(_near(place, box))
            text.set_position(place)
        self.title.set_text(_boost_title(frame))
        return (*sheet, *self.axes_of.values(), *forces, *bodies, *impacts, *self.labels, *self.names.values(),
                *self.particles.values(), self.title)


def _letter_place(worldline, L: float, box) -> tuple[float, float] | None:
    """Where a particle's letter goes in boost mode: just right of its world-line at the highest of a few heights
    (from three quarters of the panel's height down) where the world-line and the letter are inside the panel;
    None if it is never inside."""
    x0, x1, t0, t1 = box
    for fraction in (0.78, 0.65, 0.5, 0.35, 0.2):
        t = t0 + fraction * (t1 - t0)
        x = worldline.event_at_time(t * L).x / L + 0.02 * (x1 - x0)
        if x0 <= x <= x1 - 0.06 * (x1 - x0):
            return x, t
    return None


def _boost_title(frame: Frame) -> str:
    """Which frame the instant shows: S, S′, or the frame of velocity u relative to S."""
    if frame.name == "rest":
        return "seen from S, the rod’s rest frame"
    if frame.name == "moving":
        return f"seen from S\N{PRIME} (velocity {shown(frame.velocity, 4)} relative to S)"
    return f"seen from the frame of velocity {shown(frame.velocity, 3)} relative to S"


def _inside_end(dx: float, dt: float, box) -> tuple[float, float] | None:
    """Where the axis through the origin along (dx, dt), its positive direction (x: dx > 0, t: dt > 0), leaves
    the box (x0, x1, t0, t1), pulled in by AXIS_NAME_AT from where it enters the box (from the origin, if that is
    inside): where the axis's name goes, at its positive end. None if its positive half misses the box."""
    inside = line_in_box(0.0, 0.0, dx, dt, box, lo=0.0)  # the positive half's parameters inside the box
    if inside is None:
        return None
    lo, hi = inside
    scale = lo + AXIS_NAME_AT * (hi - lo)
    return dx * scale, dt * scale


def _near(place: tuple[float, float], box) -> bool:
    """Whether a point lies within the box widened by its size each way: a text there may be seen."""
    x0, x1, t0, t1 = box
    return x0 - (x1 - x0) <= place[0] <= x1 + (x1 - x0) and t0 - (t1 - t0) <= place[1] <= t1 + (t1 - t0)


def _tick_labels(axis) -> list[str]:
    """The labels an axis will draw at its present limits, locator and formatter."""
    lo, hi = sorted(axis.get_view_interval())
    values = [value for value in axis.get_major_locator()() if lo <= value <= hi]
    return axis.get_major_formatter().format_ticks(values) or [""]


def _real_tick_labels(axis) -> None:
    """Tick labels that are real coordinates, never an offset (matplotlib's "+5e4", printed over the title) or
    a shared power of ten: plain numbers, or, past LONGEST_PLAIN_TICK characters, each its own 2.5×10¹¹ at
    steps large enough for that (`render.text.tick_text`, as plot writes its ticks)."""
    formatter = ScalarFormatter(useOffset=False)
    formatter.set_scientific(False)
    axis.set_major_formatter(formatter)
    values = sorted(axis.get_major_locator()())
    if len(values) >= 2 and max(map(len, _tick_labels(axis))) > LONGEST_PLAIN_TICK:
        step = values[1] - values[0]
        axis.set_major_formatter(FuncFormatter(lambda value, _pos: tick_text(value, step)))


def _thin_x_ticks(ax, length: float, fs: float) -> None:
    """Fewer x ticks where their labels (long: real places far from the origin) would touch on the axis's length
    (points); the locator is left alone where they fit."""
    gap = 0.5 * fs  # labels closer than half an em run together
    lo, hi = sorted(ax.get_xlim())
    for bins in range(8, 0, -1):
        values = sorted(ax.xaxis.get_major_locator()())
        widest = max(text_size(label, fs)[0] for label in _tick_labels(ax.xaxis))
        if len(values) < 2 or widest + gap <= length * (values[1] - values[0]) / (hi - lo):
            return
        ax.xaxis.set_major_locator(MaxNLocator(nbins=bins, steps=[1, 2, 2.5, 5, 10]))
        _real_tick_labels(ax.xaxis)


#: a tick label longer than this is written as a power of ten where its step allows
LONGEST_PLAIN_TICK = 9
#: an axis's name sits this fraction of the way from the origin to where the axis leaves the panel
AXIS_NAME_AT = 0.86
