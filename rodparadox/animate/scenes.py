"""The animation's frames (README, "Animations"): now mode over `plot`'s diagram, boost mode over fixed axes.

Now mode draws the diagram once, as `plot` does, grows the figure downward by a band of strips, and
for each instant redraws only what moves over the saved background (blitting): each frame's own line
of simultaneity sweeping up its panel, and under the panel, on the same x scale, that frame's space at
that instant (the rod as a bar coloured by its material points' velocities, the particles as labelled
dots, an impact flashing as a star: `render.strip`), magnified in a lens under it where the rod is small
on the panel's scale. Boost mode redraws the world-lines in the frame of each instant over fixed axes. matplotlib (Agg) is imported here; import this module only after every input has been checked.

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

from dataclasses import replace
from typing import Iterator, NamedTuple

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from rodparadox.animate.timeline import BoostTimeline, NowTimeline
from rodparadox.physics.engine import History
from rodparadox.physics.frames import Frame, sampling_tolerance
from rodparadox.physics.model import frame_velocity
from rodparadox.numbers import impact_name, nice_number, shown
from rodparadox.render.styles import STYLES

_DPI = 100


def frames_of(history: History, frames: tuple[Frame, ...], mode: str, style: str,
              timeline: NowTimeline | BoostTimeline) -> Iterator[np.ndarray]:
    """Each instant of the timeline as an RGB array (see the module's docstring)."""
    if mode == "now":
        return _now(history, timeline, style)
    return _boost(history, timeline, style)


def _now(history: History, timeline: NowTimeline, style: str) -> Iterator[np.ndarray]:
    """The diagram as `plot` draws it, with each frame's own line of simultaneity (its "now", horizontal in its
    own panel) sweeping up, and under each panel a strip of that frame's space at that instant, on the panel's
    x scale. Drawn once; each instant only redraws the moving artists over the saved background (blitting)."""
    from rodparadox import render

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


#: a lens is added under a strip whose rod is never longer than this fraction of the strip's width
LENS_BELOW = 0.2
#: the lens's magnification makes the rod's longest length about this fraction of the lens's width
LENS_FILL = 0.6
#: instants sampled to find the rod's longest length in a panel (for the magnification only, not for drawing)
LENS_SAMPLES = 41


class PanelMotion(NamedTuple):
    """What moves in one panel of now mode: its now-line, its strip, and its lens (None without one) with the
    lens's magnification (1 without one)."""

    frame: Frame
    now: object
    strip: object
    lens: object | None
    magnification: float


class NowScene:
    """Now mode's figure: `plot`'s diagram with a band of strips below, drawn once; `update(k)` moves each panel's
    now-line, strip and lens to instant k and returns the artists it moved, in drawing order. Build it inside
    `render.style_context(style)`.

    The band under each row of panels holds, for each panel, from the top: the readout (the frame and its
    time), the strip on the panel's x scale with the panel's ticks, the lens when the rod is small on that
    scale (the strip again, magnified about the midpoint of the rod's ends, which it follows), and the colour
    bar.
    """

    def __init__(self, history: History, timeline: NowTimeline, style: str):
        from rodparadox import render
        from rodparadox.render.strip import FLASH_COLOUR, draw_strip

        st = STYLES[style]
        self.history, self.timeline, self.L = history, timeline, history.scenario.L
        L = self.L
        figure = render.draw(history, timeline.frames, style)
        width, height = figure.get_size_inches()
        panels = [ax for ax in figure.axes if (ax.get_gid() or "").endswith("-axes")]
        rows = sorted({round(ax.get_position().y0, 6) for ax in panels}, reverse=True)
        magnifications = [self._magnification(p, ax) for p, ax in enumerate(panels)]
        b = _Band(st, any(m > 1 for m in magnifications))
        band = b.height / 72  # inches, per row of panels
        total = height + band * len(rows)
        _make_room_below(figure, height, total, band * len(rows))
        figure.set_dpi(_NOW_DPI.get(style, _DPI))
        self.figure, self.canvas = figure, FigureCanvasAgg(figure)
        self.panels: list[PanelMotion] = []
        for p, (ax, frame, scale) in enumerate(zip(panels, timeline.frames, timeline.scales)):
            letter = (ax.get_gid() or "a")[0]
            now = ax.axhline(timeline.times[0, p] / L, color=FLASH_COLOUR[style], linewidth=2.0 * st.rod.width / 1.7,
                             zorder=8, animated=True, gid=f"{letter}-now")
            pos = ax.get_position()
            # which row of panels it is in: its place before the band was added
            row = min(range(len(rows)), key=lambda r: abs(rows[r] - (pos.y0 * total - band * len(rows)) / height))
            base = 72 * band * (len(rows) - 1 - row)  # points from the figure's bottom to this row's band

            def at(y: float, h: float, x0: float = pos.x0, w: float = pos.width):
                return x0, (base + y) / (72 * total), w, h / (72 * total)

            strip_ax = figure.add_axes(at(b.strip_y, b.strip_h))
            strip_ax.set_xlim(ax.get_xlim())
            strip_ax.set_gid(f"{letter}-strip")
            strip_ax.set_xticks(ax.get_xticks())  # the panel's ticks, labelled as the panel labels them
            strip_ax.xaxis.set_major_formatter(_same_labels(ax))
            colour_ax = figure.add_axes(at(b.colour_y, b.colour_h, pos.x0 + 0.15 * pos.width, 0.7 * pos.width))
            first = timeline.strip(history, 0, p)
            strip = draw_strip(strip_ax, first, st, scale, frame, L=L, colour_ax=colour_ax,
                               bar_width=0.5 * b.strip_h, animated=True)
            strip.readout.set_y(1.0 + b.readout_pad / b.strip_h)
            strip.readout.set_fontsize(self._readout_size(p, frame, pos.width * 72 * width, st.font_size))
            strip_ax.tick_params(length=b.tick_len, pad=b.tick_pad)
            lens, m = None, magnifications[p]
            if m > 1:
                lens_ax = figure.add_axes(at(b.lens_y, b.lens_h))
                lens_ax.set_gid(f"{letter}-lens")
                half = (ax.get_xlim()[1] - ax.get_xlim()[0]) / (2 * m)
                lens_ax.set_xlim(-half, half)
                ticks, step = _offset_ticks(half)
                lens_ax.set_xticks(ticks)
                lens_ax.xaxis.set_major_formatter(_signed_labels(step))
                lens = draw_strip(lens_ax, first, st, scale, frame, L=L, bar_width=0.5 * b.lens_h, animated=True,
                                  readout=False)
                lens_ax.tick_params(length=b.tick_len, pad=b.tick_pad)
                lens_ax.set_title(f"\N{MULTIPLICATION SIGN}{m:g}, about the rod's midpoint", loc="left",
                                  fontsize=b.small, pad=b.lens_pad)
            self.panels.append(PanelMotion(frame, now, strip, lens, m))

    def _readout_size(self, p: int, frame: Frame, room: float, size: float) -> float:
        """The readout's type size: the style's, or less so that its longest text (the window's ends, with every
        impact flashing) fits over the strip (`room` points), a narrow panel's on slides."""
        from dataclasses import replace as with_

        from rodparadox.render import text_size
        from rodparadox.render.strip import readout_text

        labels = tuple(i.label for i in self.history.impacts)
        longest = max(text_size(readout_text(with_(self.timeline.strip(self.history, k, p), flashing=labels), frame,
                                              self.L), size)[0] for k in (0, len(self.timeline) - 1))
        return size if longest <= room else max(0.7 * size, size * room / longest)

    def _magnification(self, p: int, ax) -> float:
        """1 (no lens) when the rod is never shorter than LENS_BELOW of the panel's width; else a round number
        (1, 2, 2.5 or 5 times a power of ten) making its longest length about LENS_FILL of the lens's width."""
        span = ax.get_xlim()[1] - ax.get_xlim()[0]
        ks = np.unique(np.linspace(0, len(self.timeline) - 1, LENS_SAMPLES).round().astype(int))
        longest = max(float(np.ptp(self.timeline.strip(self.history, int(k), p).x)) for k in ks) / self.L
        if longest >= LENS_BELOW * span:
            return 1.0
        return nice_number(LENS_FILL * span / longest, "at_most")

    def update(self, k: int) -> list:
        from rodparadox.render.strip import update_strip

        L, moved = self.L, []
        for p, motion in enumerate(self.panels):
            shown_now = self.timeline.strip(self.history, k, p)
            motion.now.set_ydata([shown_now.t / L, shown_now.t / L])
            moved += [motion.now, *update_strip(motion.strip, shown_now, motion.frame, L)]
            if motion.lens is not None:
                moved += update_strip(motion.lens, _about_midpoint(shown_now), motion.frame, L)
        return moved


def _about_midpoint(strip):
    """The strip with every x measured from the midpoint of the rod's two ends: what the lens shows."""
    c = 0.5 * (strip.x[0] + strip.x[-1])
    return replace(strip, x=strip.x - c, particles=tuple((name, x - c) for name, x in strip.particles),
                   flash_x=tuple(x - c for x in strip.flash_x))


def _same_labels(ax):
    """A formatter writing what the panel `ax` writes at its x ticks."""
    from matplotlib.ticker import FuncFormatter

    return FuncFormatter(ax.xaxis.get_major_formatter().func)


def _offset_ticks(half: float) -> tuple[np.ndarray, float]:
    """The lens's ticks over -half..half: the midpoint and a round step each side of it; and the step."""
    from rodparadox.render.text import ticks_at

    step = nice_number(0.9 * half, "at_most")
    return ticks_at(-half, half, step), step


def _signed_labels(step: float):
    """Offsets written with their sign (−0.1, 0, +0.1), with as many decimals as the step has."""
    from matplotlib.ticker import FuncFormatter

    from rodparadox.render.text import tick_text

    def label(value: float, _pos=None) -> str:
        if abs(value) < 0.5 * step:
            return "0"
        text = tick_text(value, step)
        return "+" + text if value > 0 else text

    return FuncFormatter(label)


class _Band:
    """The band under a row of panels, in points from its bottom: the colour bar (with its tick labels and name),
    the lens (when any panel has one), the strip, and the readout above it, with room for the particles' letters
    (which start at LETTER_Y of a strip and may reach above it)."""

    def __init__(self, st, with_lens: bool):
        from rodparadox.render.strip import LETTER_Y

        fs = st.font_size
        self.small = 0.8 * fs
        self.tick_len, self.tick_pad = (4.0, 2.5) if st.name == "slides" else (2.5, 2.0)
        ticks = self.tick_len + self.tick_pad + 1.25 * self.small
        self.strip_h = self.lens_h = 2.4 * fs
        overflow = max(0.0, (1 + LETTER_Y) / 2 * self.strip_h + 1.05 * fs - self.strip_h)
        self.readout_pad = overflow + 3.0
        self.lens_pad = overflow + 2.0
        self.colour_h = max(5.0, 0.45 * fs)
        self.colour_y = 4.0 + 2.5 * self.small + 4.0  # above the colour bar's name and tick labels
        y = self.colour_y + self.colour_h + 8.0
        if with_lens:
            self.lens_y = y + ticks
            y = self.lens_y + self.lens_h + self.lens_pad + 1.3 * self.small
        self.strip_y = y + ticks
        self.height = self.strip_y + self.strip_h + self.readout_pad + 1.3 * fs + 4.0


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


#: boost mode's figure, inches: the page's (or slide's) width, and at most its height; the panel is square, the
#: key to its right
_BOOST_SIZE = {"default": (7.0, 6.0), "print": (7.0, 6.0), "slides": (13.33, 7.5)}


def _boost(history: History, timeline: BoostTimeline, style: str) -> Iterator[np.ndarray]:
    """One panel over fixed axes (equal scales: light at 45 degrees); at each instant the world-lines, the rod's
    world-sheet, the impacts and the axes of S and S' (tilted, through the shared origin; S's in the ink of its
    lines of simultaneity, S''s in theirs, as `plot` draws them) redrawn in the frame of that instant, over the
    saved background (blitting). A key to the right names every line; the title names the frame of the instant."""
    from matplotlib.lines import Line2D
    from matplotlib.patches import Polygon

    from rodparadox import render
    from rodparadox.render.layers import impact_marker, line_kwargs

    st = STYLES[style]
    L, v = history.scenario.L, history.scenario.v
    fs = st.font_size
    big = 1.35 * fs  # the axes' names and the particles' letters: read from the back of a lecture hall
    ground = {"boxstyle": "round,pad=0.12", "facecolor": "white", "edgecolor": "none", "alpha": 0.85}
    with render.style_context(style):
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
        figure = Figure(figsize=(width, height), dpi=_NOW_DPI.get(style, _DPI))
        canvas = FigureCanvasAgg(figure)
        ax = figure.add_axes((left / width, bottom / height, side / width, side / height))
        (x0, x1), (t0, t1) = (np.array(timeline.x_window) / L), (np.array(timeline.t_window) / L)
        span = 1.04 * max(x1 - x0, t1 - t0)  # a square panel with equal scales: the shorter side widened
        (x0, x1), (t0, t1) = [(0.5 * (a + b) - span / 2, 0.5 * (a + b) + span / 2) for a, b in ((x0, x1), (t0, t1))]
        ax.set_xlim(x0, x1)
        ax.set_ylim(t0, t1)
        ax.set_xlabel("x/L in the frame of the instant", fontsize=1.1 * fs)
        ax.set_ylabel("t/L", fontsize=1.1 * fs)
        ax.tick_params(labelsize=fs)
        title = ax.set_title("", fontsize=1.2 * fs, loc="left", pad=0.6 * fs)
        title.set_animated(True)
        tolerance = sampling_tolerance(history)
        sheet = ax.add_patch(Polygon(np.zeros((3, 2)), closed=True, facecolor=st.sheet, edgecolor="none", zorder=1,
                                     animated=True))
        lines = {name: ax.plot([], [], **line_kwargs(ink), zorder=4, animated=True)[0] for name, ink in inks.items()}
        axes_of = {(frame, axis): ax.plot([], [], **line_kwargs(axis_inks[frame]), zorder=2, animated=True)[0]
                   for frame in ("rest", "moving") for axis in ("x", "t")}
        names = {(frame, axis): ax.text(0, 0, axis + ("\N{PRIME}" if frame == "moving" else ""), ha="center",
                                        va="center", color=axis_inks[frame].colour, fontsize=big, style="italic",
                                        zorder=9, bbox=ground, animated=True)
                 for frame, axis in axes_of}
        particles = {name: ax.text(0, 0, name, ha="left", va="center", color=ink.colour, fontsize=big,
                                   style="italic", zorder=9, bbox=ground, animated=True)
                     for name, ink in inks.items() if not name.startswith("rod_")}
        dots = ax.plot([], [], **impact_marker(st), zorder=7, animated=True)[0]
        labels = [ax.text(0, 0, impact_name(i.label, math_text=True), fontsize=1.1 * fs, va="center", zorder=9, bbox=ground,
                          animated=True) for i in history.impacts]
        figure.legend([h for h, _ in key], [text for _, text in key], loc="upper left",
                      bbox_to_anchor=((left + side + 0.3) / width, 1 - top / height), fontsize=fs,
                      handlelength=2.6, labelspacing=0.7, borderaxespad=0.0)
        canvas.draw()
        background = canvas.copy_from_bbox(figure.bbox)
        reach = 2.0 * max(abs(x0), abs(x1), abs(t0), abs(t1))
        for frame in timeline.frames:
            canvas.restore_region(background)
            eta = frame.rapidity
            points = {name: w.seen_from(eta).sample(*timeline.t_window, tolerance) / L for name, w in history.worldlines}
            for name, line in lines.items():
                line.set_data(points[name][:, 0], points[name][:, 1])
            sheet.set_xy(np.concatenate([points["rod_left"], points["rod_right"][::-1]]))
            for (other, axis), line in axes_of.items():
                u = render.relative_velocity(frame_velocity(other, v), frame.velocity)  # that frame, seen here
                dx, dt = (u, 1.0) if axis == "t" else (1.0, u)
                line.set_data([-reach * dx, reach * dx], [-reach * dt, reach * dt])
                names[(other, axis)].set_position(_inside_end(dx, dt, (x0, x1, t0, t1)))
            for name, text in particles.items():  # beside the world-line, as high up as it is inside the panel
                place = _letter_place(history.worldline(name).seen_from(eta), L, (x0, x1, t0, t1))
                text.set_visible(place is not None)
                if place is not None:
                    text.set_position(place)
            events = [i.event.seen_from(eta) for i in history.impacts]
            dots.set_data([e.x / L for e in events], [e.t / L for e in events])
            for text, e in zip(labels, events):
                text.set_position((e.x / L + 0.025 * (x1 - x0), e.t / L))
            title.set_text(_boost_title(frame))
            for artist in (sheet, *axes_of.values(), *lines.values(), dots, *labels, *names.values(),
                           *particles.values(), title):
                ax.draw_artist(artist)
            yield np.asarray(canvas.buffer_rgba())[..., :3].copy()


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
