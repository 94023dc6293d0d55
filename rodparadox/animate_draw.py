"""A stand-in for the animation's drawing, until `rodparadox.render.animate.frames_of` replaces it.

It draws only what the timeline says, plainly, so the whole pipeline (timeline -> frames -> GIF, MP4, PNG)
runs end to end and is tested: in now mode, one strip per panel (the rod as a bar coloured by its material
points' velocities, the particles as labelled dots, the impacts that flash, the panel's time); in boost
mode, the world-lines in the frame of the instant, over fixed axes. matplotlib (Agg) is imported here;
import this module only after every input has been checked.

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
from matplotlib.collections import LineCollection
from matplotlib.colors import Normalize
from matplotlib.figure import Figure

from .animation import BoostTimeline, NowTimeline
from .engine import History
from .frames import Frame, sampling_tolerance, view

_SIZES = {"default": 10.0, "print": 10.0, "slides": 14.0}
_MAPS = {"default": "RdBu_r", "print": "PuOr_r", "slides": "RdBu_r"}
_DPI = 100


def frames_of(history: History, frames: tuple[Frame, ...], mode: str, style: str,
              timeline: NowTimeline | BoostTimeline) -> Iterator[np.ndarray]:
    """Each instant of the timeline as an RGB array (see the module's docstring)."""
    if mode == "now":
        return _now(history, timeline, style)
    return _boost(history, timeline, style)


def _rgb(canvas: FigureCanvasAgg) -> np.ndarray:
    canvas.draw()
    return np.asarray(canvas.buffer_rgba())[..., :3].copy()


def _now(history: History, timeline: NowTimeline, style: str) -> Iterator[np.ndarray]:
    size = _SIZES.get(style, 10.0)
    n = len(timeline.frames)
    figure = Figure(figsize=(8.0, 1.3 * n + 0.3), dpi=_DPI)
    canvas = FigureCanvasAgg(figure)
    tolerance = sampling_tolerance(history)
    bars, dots, labels, readouts = [], [], [], []
    for p, (frame, window, scale) in enumerate(zip(timeline.frames, timeline.windows, timeline.scales)):
        ax = figure.add_axes((0.06, 1 - (p + 1) / n + 0.28 / n, 0.78, 0.5 / n))
        points = view(history, frame).worldline_points(tolerance)
        xs = np.concatenate([pts[:, 0] for pts in points.values()])
        pad = 0.05 * (xs.max() - xs.min())
        ax.set_xlim(xs.min() - pad, xs.max() + pad)
        ax.set_ylim(-1, 1)
        ax.set_yticks([])
        ax.tick_params(labelsize=0.8 * size)
        norm = Normalize(*scale.limits)
        bar = LineCollection([], cmap=_MAPS.get(style, "RdBu_r"), norm=norm, linewidths=10, capstyle="butt")
        ax.add_collection(bar)
        colour_axes = figure.add_axes((0.87, 1 - (p + 1) / n + 0.28 / n, 0.015, 0.5 / n))
        figure.colorbar(bar, cax=colour_axes).ax.tick_params(labelsize=0.7 * size)
        bars.append(bar)
        dots.append(ax.plot([], [], "o", color="black", markersize=5)[0])
        labels.append([ax.text(0, 0.35, name, ha="center", fontsize=size) for name, _ in
                       timeline.strip(history, 0, p).particles])
        readouts.append(ax.set_title("", fontsize=size, loc="left"))
    for k in range(len(timeline)):
        for p, frame in enumerate(timeline.frames):
            strip = timeline.strip(history, k, p)
            mid = 0.5 * (strip.velocity[1:] + strip.velocity[:-1])
            bars[p].set_segments([[(a, 0), (b, 0)] for a, b in zip(strip.x[:-1], strip.x[1:])])
            bars[p].set_array(mid)
            dots[p].set_data([x for _, x in strip.particles], [0.0] * len(strip.particles))
            for text, (name, x) in zip(labels[p], strip.particles):
                text.set_position((x, 0.35))
            flash = f"   impact {', '.join(strip.flashing)}" if strip.flashing else ""
            readouts[p].set_text(f"{frame.name}: t = {strip.t:+.3f}{flash}")
            readouts[p].set_color("crimson" if strip.flashing else "black")
        yield _rgb(canvas)


def _boost(history: History, timeline: BoostTimeline, style: str) -> Iterator[np.ndarray]:
    size = _SIZES.get(style, 10.0)
    figure = Figure(figsize=(6.0, 6.0), dpi=_DPI)
    canvas = FigureCanvasAgg(figure)
    ax = figure.add_axes((0.12, 0.1, 0.83, 0.8))
    ax.set_xlim(*timeline.x_window)
    ax.set_ylim(*timeline.t_window)
    ax.set_xlabel("x / L", fontsize=size)
    ax.set_ylabel("t / L", fontsize=size)
    tolerance = sampling_tolerance(history)
    lines = {}
    for frame in timeline.frames:
        for name, worldline in history.worldlines:  # over the whole fixed window, so lines reach the axes' edges
            points = worldline.boosted(frame.rapidity).sample(*timeline.t_window, tolerance)
            if name not in lines:
                lines[name] = ax.plot([], [], "-" if name.startswith("rod") else "--",
                                      color="tab:blue" if name.startswith("rod") else "black")[0]
            lines[name].set_data(points[:, 0], points[:, 1])
        ax.set_title(f"frame {frame.name}: velocity {frame.velocity:+.4f} relative to S", fontsize=size)
        yield _rgb(canvas)
