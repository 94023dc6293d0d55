"""Boost mode (README, "Animating"): one panel over fixed axes whose frame runs smoothly from one velocity to
another, the world-lines redrawn in the frame of each instant. matplotlib (Agg) is imported here; import this
module only after every input has been checked.
"""

from __future__ import annotations

from typing import Iterator

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from rodparadox.animate.images import blitted, dpi
from rodparadox.animate.timeline import BoostTimeline
from rodparadox.physics.engine import History
from rodparadox.physics.frames import Frame, sampling_tolerance
from rodparadox.numbers import shown
from rodparadox.render.styles import STYLES


#: boost mode's figure, inches: the page's (or slide's) width, and at most its height; the panel is square, the
#: key to its right
_BOOST_SIZE = {"default": (7.0, 6.0), "print": (7.0, 6.0), "slides": (13.33, 7.5)}


def boost_images(history: History, timeline: BoostTimeline, style: str) -> Iterator[np.ndarray]:
    """Each instant of the boost as an image: `BoostScene` drawn once, then at each instant only what moves, over
    the saved background (blitting)."""
    from rodparadox import render

    with render.style_context(style):
        scene = BoostScene(history, timeline, style)
        yield from blitted(scene.canvas, (scene.update(k) for k in range(len(timeline))))


class BoostScene:
    """Boost mode's figure: one panel over fixed axes (equal scales: light at 45 degrees); `update(k)` redraws in
    the frame of instant k the world-lines, the rod's world-sheet, the impacts and the axes of S and S' (tilted,
    through the shared origin; S's in the ink of its lines of simultaneity, S''s in theirs, as `plot` draws them),
    and returns the artists it moved, in drawing order. A key to the right names every line; the title names the
    frame of the instant. Build it inside `render.style_context(style)`."""

    def __init__(self, history: History, timeline: BoostTimeline, style: str):
        from matplotlib.lines import Line2D
        from matplotlib.patches import Polygon

        from rodparadox import render
        from rodparadox.render.layers import impact_marker, line_kwargs

        self.history, self.timeline = history, timeline
        st = STYLES[style]
        L = history.scenario.L
        fs = st.font_size
        big = 1.35 * fs  # the axes' names and the particles' letters: read from the back of a lecture hall
        ground = {"boxstyle": "round,pad=0.12", "facecolor": "white", "edgecolor": "none", "alpha": 0.85}
        inks = {name: (st.rod if name.startswith("rod_") else st.particles[name]) for name, _ in history.worldlines}
        axis_inks = {"rest": st.rest_simultaneity, "moving": st.moving_simultaneity}
        axis_inks = {frame: ink._replace(width=1.3 * ink.width) for frame, ink in axis_inks.items()}
        key = [(Line2D([], [], **line_kwargs(st.rod)), "rod")]
        key += [(Line2D([], [], **line_kwargs(inks[name])), f"particle {name}") for name in ("A", "B") if name in inks]
        key += [(Line2D([], [], **impact_marker(st)), "impact"),
                (Line2D([], [], **line_kwargs(axis_inks["rest"])), "axes of S"),
                (Line2D([], [], **line_kwargs(axis_inks["moving"])), "axes of S\N{PRIME}")]
        key_width = (3.4 * fs + max(render.text_size(text, fs)[0] for _, text in key)) / 72  # inches
        width, most = _BOOST_SIZE.get(style, _BOOST_SIZE["default"])
        left, bottom, top = 4.6 * fs / 72, 3.4 * fs / 72, 3.2 * fs / 72  # inches: tick labels and names; title
        side = min(most - bottom - top, width - left - key_width - 0.5)
        height = side + bottom + top
        self.figure = figure = Figure(figsize=(width, height), dpi=dpi(style))
        self.canvas = FigureCanvasAgg(figure)
        self.ax = ax = figure.add_axes((left / width, bottom / height, side / width, side / height))
        (x0, x1), (t0, t1) = (np.array(timeline.x_window) / L), (np.array(timeline.t_window) / L)
        span = 1.04 * max(x1 - x0, t1 - t0)  # a square panel with equal scales: the shorter side widened
        (x0, x1), (t0, t1) = [(0.5 * (a + b) - span / 2, 0.5 * (a + b) + span / 2) for a, b in ((x0, x1), (t0, t1))]
        self.box = (x0, x1, t0, t1)
        ax.set_xlim(x0, x1)
        ax.set_ylim(t0, t1)
        ax.set_xlabel("x/L in the frame of the instant", fontsize=1.1 * fs)
        ax.set_ylabel("t/L", fontsize=1.1 * fs)
        ax.tick_params(labelsize=fs)
        self.title = ax.set_title("", fontsize=1.2 * fs, loc="left", pad=0.6 * fs)
        self.title.set_animated(True)
        self.tolerance = sampling_tolerance(history)
        self.sheet = ax.add_patch(Polygon(np.zeros((3, 2)), closed=True, facecolor=st.sheet, edgecolor="none",
                                          zorder=1, animated=True))
        self.lines = {name: ax.plot([], [], **line_kwargs(ink), zorder=4, animated=True)[0]
                      for name, ink in inks.items()}
        self.axes_of = {(frame, axis): ax.plot([], [], **line_kwargs(axis_inks[frame]), zorder=2, animated=True)[0]
                        for frame in ("rest", "moving") for axis in ("x", "t")}
        self.names = {(frame, axis): ax.text(0, 0, axis + ("\N{PRIME}" if frame == "moving" else ""), ha="center",
                                             va="center", color=axis_inks[frame].colour, fontsize=big, style="italic",
                                             zorder=9, bbox=ground, animated=True)
                      for frame, axis in self.axes_of}
        self.particles = {name: ax.text(0, 0, name, ha="left", va="center", color=ink.colour, fontsize=big,
                                        style="italic", zorder=9, bbox=ground, animated=True)
                          for name, ink in inks.items() if not name.startswith("rod_")}
        self.dots = ax.plot([], [], **impact_marker(st), zorder=7, animated=True)[0]
        self.labels = [ax.text(0, 0, render.impact_text(i.label), fontsize=1.1 * fs, va="center", zorder=9,
                               bbox=ground, animated=True) for i in history.impacts]
        figure.legend([h for h, _ in key], [text for _, text in key], loc="upper left",
                      bbox_to_anchor=((left + side + 0.3) / width, 1 - top / height), fontsize=fs,
                      handlelength=2.6, labelspacing=0.7, borderaxespad=0.0)
        self.reach = 2.0 * max(abs(x0), abs(x1), abs(t0), abs(t1))  # the axes run past the panel's every side

    def update(self, k: int) -> tuple:
        from rodparadox import render

        history, L, v = self.history, self.history.scenario.L, self.history.scenario.v
        box, reach = self.box, self.reach
        frame = self.timeline.frames[k]
        eta = frame.rapidity
        points = {name: w.boosted(eta).sample(*self.timeline.t_window, self.tolerance) / L
                  for name, w in history.worldlines}
        for name, line in self.lines.items():
            line.set_data(points[name][:, 0], points[name][:, 1])
        self.sheet.set_xy(np.concatenate([points["rod_left"], points["rod_right"][::-1]]))
        for (other, axis), line in self.axes_of.items():
            u = render.relative_velocity(0.0 if other == "rest" else -v, frame.velocity)  # that frame, seen here
            dx, dt = (u, 1.0) if axis == "t" else (1.0, u)
            line.set_data([-reach * dx, reach * dx], [-reach * dt, reach * dt])
            self.names[(other, axis)].set_position(_inside_end(dx, dt, box))
        for name, text in self.particles.items():  # beside the world-line, as high up as it is inside the panel
            place = _letter_place(history.worldline(name).boosted(eta), L, box)
            text.set_visible(place is not None)
            if place is not None:
                text.set_position(place)
        events = [i.event.boosted(eta) for i in history.impacts]
        self.dots.set_data([e.x / L for e in events], [e.t / L for e in events])
        for text, e in zip(self.labels, events):
            text.set_position((e.x / L + 0.025 * (box[1] - box[0]), e.t / L))
        self.title.set_text(_boost_title(frame))
        return (self.sheet, *self.axes_of.values(), *self.lines.values(), self.dots, *self.labels,
                *self.names.values(), *self.particles.values(), self.title)


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
        return "seen from S, the rod's rest frame"
    if frame.name == "moving":
        return f"seen from S\N{PRIME} (velocity {shown(frame.velocity, 4)} relative to S)"
    return f"seen from the frame of velocity {shown(frame.velocity, 3)} relative to S"


def _inside_end(dx: float, dt: float, box) -> tuple[float, float]:
    """Where the axis through the origin along (dx, dt), its positive direction (x: dx > 0, t: dt > 0), leaves
    the box (x0, x1, t0, t1), pulled in by AXIS_NAME_AT: where the axis's name goes, at its positive end."""
    x0, x1, t0, t1 = box
    limits = [(t1 if dt > 0 else t0) / dt] if dt != 0 else []
    limits += [(x1 if dx > 0 else x0) / dx] if dx != 0 else []
    positive = [limit for limit in limits if limit > 0]
    scale = AXIS_NAME_AT * min(positive) if positive else 0.0
    return dx * scale, dt * scale


#: an axis's name sits this fraction of the way from the origin to where the axis leaves the panel
AXIS_NAME_AT = 0.86
