"""The animation's frames (README, "Animations"): now mode over `plot`'s diagram, boost mode over fixed axes.

Now mode draws the diagram once, as `plot` does, grows the figure downward by a band of strips, and
for each instant redraws only what moves over the saved background (blitting): each frame's own line
of simultaneity sweeping up its panel, and under the panel, on the same x scale, that frame's space at
that instant (the rod as a bar coloured by its material points' velocities, the particles as labelled
dots, an impact flashing as a star). Boost mode redraws the world-lines in the frame of each instant over
fixed axes. matplotlib (Agg) is imported here; import this module only after every input has been checked.

The interface the real drawing keeps:

    frames_of(history, frames, mode, style, timeline) -> Iterator[np.ndarray]

* `history`: `engine.History`; `frames`: the panels (now) or the two ends of the boost (boost), as
  `frames.Frame`s; `mode`: "now" or "boost"; `style`: a name of `styles.STYLE_NAMES`;
* `timeline`: `animation.NowTimeline` (its `times[k, p]`, `windows`, `scales`, and `strip(history, k, p)`)
  or `animation.BoostTimeline` (its `frames[k]`, `t_window`, `x_window`);
* yields len(timeline) frames, each an (H, W, 3) uint8 RGB array, all of one size, drawn the same way
  every run (Agg), by updating artists on one figure rather than building a figure per frame.
"""

from __future__ import annotations

from typing import Iterator

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from .animation import BoostTimeline, NowTimeline
from .engine import History
from .frames import Frame, sampling_tolerance
from .numbers import shown
from .styles import STYLES

_DPI = 100


def frames_of(history: History, frames: tuple[Frame, ...], mode: str, style: str,
              timeline: NowTimeline | BoostTimeline) -> Iterator[np.ndarray]:
    """Each instant of the timeline as an RGB array (see the module's docstring)."""
    if mode == "now":
        return _now(history, timeline, style)
    return _boost(history, timeline, style)


#: the band under the diagram holding one strip per panel, inches: title, strip, colour bar and its ticks
_STRIP_BAND = {"default": 1.25, "print": 1.25, "slides": 1.9}


def _now(history: History, timeline: NowTimeline, style: str) -> Iterator[np.ndarray]:
    """The diagram as `plot` draws it, with each frame's own line of simultaneity (its "now", horizontal in its
    own panel) sweeping up, and under each panel a strip of that frame's space at that instant, on the panel's
    x scale. Drawn once; each instant only redraws the moving artists over the saved background (blitting)."""
    from . import render

    with render.style_context(style):
        scene = NowScene(history, timeline, style)
        canvas = scene.canvas
        canvas.draw()
        background = canvas.copy_from_bbox(scene.figure.bbox)
        for k in range(len(timeline)):
            canvas.restore_region(background)
            for artist in scene.update(k):
                artist.axes.draw_artist(artist)
            yield np.asarray(canvas.buffer_rgba())[..., :3].copy()


class NowScene:
    """Now mode's figure: `plot`'s diagram with a band of strips below, drawn once; `update(k)` moves each panel's
    now-line and strip to instant k and returns the artists it moved, in drawing order. Build it inside
    `render.style_context(style)`."""

    def __init__(self, history: History, timeline: NowTimeline, style: str):
        from . import render
        from .render.strip import FLASH_COLOUR, draw_strip

        st = STYLES[style]
        self.history, self.timeline, self.L = history, timeline, history.scenario.L
        L = self.L
        figure = render.draw(history, timeline.frames, style)
        width, height = figure.get_size_inches()
        band = _STRIP_BAND.get(style, 1.25)
        panels = [ax for ax in figure.axes if (ax.get_gid() or "").endswith("-axes")]
        rows = sorted({round(ax.get_position().y0, 6) for ax in panels}, reverse=True)
        total = height + band * len(rows)
        _make_room_below(figure, height, total, band * len(rows))
        figure.set_dpi(_NOW_DPI.get(style, _DPI))
        self.figure, self.canvas = figure, FigureCanvasAgg(figure)
        self.panels = []
        for p, (ax, frame, scale) in enumerate(zip(panels, timeline.frames, timeline.scales)):
            letter = (ax.get_gid() or "a")[0]
            now = ax.axhline(timeline.times[0, p] / L, color=FLASH_COLOUR[style], linewidth=2.0 * st.rod.width / 1.7,
                             zorder=8, animated=True, gid=f"{letter}-now")
            # the strip: under the panel, on its x scale, in the band of the panel's row
            pos = ax.get_position()
            # which row of panels it is in: its place before the band was added
            row = min(range(len(rows)), key=lambda r: abs(rows[r] - (pos.y0 * total - band * len(rows)) / height))
            base = band * (len(rows) - 1 - row)
            strip_ax = figure.add_axes((pos.x0, (base + band * 0.52) / total, pos.width, band * 0.24 / total))
            strip_ax.set_xlim(ax.get_xlim())
            strip_ax.set_gid(f"{letter}-strip")
            colour_ax = figure.add_axes((pos.x0 + 0.15 * pos.width, (base + band * 0.27) / total, 0.7 * pos.width,
                                         band * 0.06 / total))
            strip = draw_strip(strip_ax, timeline.strip(history, 0, p), st, scale, frame, L=L, colour_ax=colour_ax,
                               bar_width=band * 0.24 * 72 * 0.5, animated=True)
            self.panels.append((frame, now, strip))

    def update(self, k: int) -> list:
        from .render.strip import update_strip

        L, moved = self.L, []
        for p, (frame, now, strip) in enumerate(self.panels):
            shown_now = self.timeline.strip(self.history, k, p)
            now.set_ydata([shown_now.t / L, shown_now.t / L])
            moved += [now, *update_strip(strip, shown_now, frame, L)]
        return moved


#: pixels per inch of the now-mode frames: about 1050 px wide on the 7 in page, 1330 px on the 13.3 in slide
_NOW_DPI = {"default": 150, "print": 150, "slides": 100}


def _make_room_below(figure: Figure, height: float, total: float, band: float) -> None:
    """Grow the figure downward by `band` inches, keeping everything already in it where it was on the page."""
    width = figure.get_size_inches()[0]
    figure.set_size_inches(width, total)
    squeeze = height / total
    for ax in figure.axes:
        pos = ax.get_position()
        ax.set_position((pos.x0, (pos.y0 * height + band) / total, pos.width, pos.height * squeeze))
    for text in figure.texts:
        x, y = text.get_position()
        text.set_position((x, (y * height + band) / total))
    for legend in figure.legends:
        anchor = legend.get_bbox_to_anchor().transformed(figure.transFigure.inverted())
        legend.set_bbox_to_anchor((anchor.x0, (anchor.y0 * height + band) / total), transform=figure.transFigure)


def _boost(history: History, timeline: BoostTimeline, style: str) -> Iterator[np.ndarray]:
    """One panel over fixed axes; at each instant the world-lines, the rod's world-sheet, the impacts and the axes
    of S and S' (tilted, through the shared origin) redrawn in the frame of that instant, over the saved
    background (blitting)."""
    from matplotlib.patches import Polygon

    from . import render

    st = STYLES[style]
    L, v = history.scenario.L, history.scenario.v
    fs = st.font_size
    with render.style_context(style):
        side = min(st.max_width, st.max_height) * 0.8
        figure = Figure(figsize=(side, side), dpi=_NOW_DPI.get(style, _DPI))
        canvas = FigureCanvasAgg(figure)
        ax = figure.add_axes((0.14, 0.1, 0.8, 0.78))
        (x0, x1), (t0, t1) = (np.array(timeline.x_window) / L), (np.array(timeline.t_window) / L)
        ax.set_xlim(x0, x1)
        ax.set_ylim(t0, t1)
        ax.set_xlabel("x/L in the frame of the instant", fontsize=1.05 * fs)
        ax.set_ylabel("t/L", fontsize=1.05 * fs)
        ax.tick_params(labelsize=fs)
        title = ax.set_title("", fontsize=1.1 * fs)
        title.set_animated(True)
        tolerance = sampling_tolerance(history)
        sheet = ax.add_patch(Polygon(np.zeros((3, 2)), closed=True, facecolor=st.sheet, edgecolor="none", zorder=1,
                                     animated=True))
        inks = {name: (st.rod if name.startswith("rod_") else st.particles[name]) for name, _ in history.worldlines}
        lines = {name: ax.plot([], [], color=ink.colour, linewidth=ink.width, linestyle=ink.dashes, zorder=4,
                               animated=True)[0] for name, ink in inks.items()}
        axes_of = {(frame, axis): ax.plot([], [], color=st.other_axes.colour, linewidth=st.other_axes.width,
                                          linestyle=st.other_axes.dashes, zorder=2, animated=True)[0]
                   for frame in ("rest", "moving") for axis in ("x", "t")}
        names = {key: ax.text(0, 0, "", color=st.other_axes.colour, fontsize=fs, style="italic", animated=True)
                 for key in axes_of}
        dots = ax.plot([], [], "o", color=st.impact_colour, markersize=st.impact_size, markeredgecolor="white",
                       zorder=7, animated=True)[0]
        labels = [ax.text(0, 0, render.impact_text(i.label), fontsize=fs, animated=True) for i in history.impacts]
        canvas.draw()
        background = canvas.copy_from_bbox(figure.bbox)
        reach = 2.0 * max(abs(x0), abs(x1), abs(t0), abs(t1))
        for frame in timeline.frames:
            canvas.restore_region(background)
            eta = frame.rapidity
            points = {name: w.boosted(eta).sample(*timeline.t_window, tolerance) / L for name, w in history.worldlines}
            for name, line in lines.items():
                line.set_data(points[name][:, 0], points[name][:, 1])
            sheet.set_xy(np.concatenate([points["rod_left"], points["rod_right"][::-1]]))
            for (other, axis), line in axes_of.items():
                u = render.relative_velocity(0.0 if other == "rest" else -v, frame.velocity)  # that frame, seen here
                dx, dt = (u, 1.0) if axis == "t" else (1.0, u)
                line.set_data([-reach * dx, reach * dx], [-reach * dt, reach * dt])
                names[(other, axis)].set_text(axis + ("\N{PRIME}" if other == "moving" else ""))
                names[(other, axis)].set_position(_inside_end(dx, dt, (x0, x1, t0, t1)))
            events = [i.event.boosted(eta) for i in history.impacts]
            dots.set_data([e.x / L for e in events], [e.t / L for e in events])
            for text, e in zip(labels, events):
                text.set_position((e.x / L + 0.03 * (x1 - x0), e.t / L))
            title.set_text(f"frame of velocity {shown(frame.velocity, 4)} relative to S")
            for artist in (sheet, *axes_of.values(), *names.values(), *lines.values(), dots, *labels, title):
                ax.draw_artist(artist)
            yield np.asarray(canvas.buffer_rgba())[..., :3].copy()


def _inside_end(dx: float, dt: float, box) -> tuple[float, float]:
    """Where the line through the origin along (dx, dt) leaves the box (x0, x1, t0, t1), on its upper or right
    side, pulled in a little: where the axis's name goes."""
    x0, x1, t0, t1 = box
    if dt < 0 or (dt == 0 and dx < 0):
        dx, dt = -dx, -dt
    limits = [t1 * 0.9 / dt] if dt > 0 else []
    limits += [x1 * 0.9 / dx] if dx > 0 else [x0 * 0.9 / dx] if dx < 0 else []
    scale = min(limit for limit in limits if limit > 0) if any(limit > 0 for limit in limits) else 0.0
    return dx * scale, dt * scale
