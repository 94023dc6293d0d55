"""Now mode (docs/animate.md, "The paradox in motion"): `plot`'s diagram with each frame's "now" sweeping up and its space below.

Draws the diagram once, as `plot` does, grows the figure downward by a band of strips, and for each
instant redraws only what moves over the saved background (blitting): each frame's own line of
simultaneity sweeping up its panel, and under the panel, on the same x scale, that frame's space at that
instant (the rod as a bar coloured by its material points' velocities, the particles as labelled dots, an
impact flashing as a star: `render.strip`), magnified in a lens under it where the rod is small on the
panel's scale. matplotlib (Agg) is imported here; import this module only after every input has been
checked.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Iterator, NamedTuple

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from rodparadox.animate.images import blitted, in_style
from rodparadox.animate.timeline import NowTimeline
from rodparadox.physics.history import RodHistory
from rodparadox.numbers import nice_number
from rodparadox.physics.frames import Frame
from rodparadox.render.styles import STYLES


def now_images(history: RodHistory, timeline: NowTimeline, style: str, rod_view: str | None = None) -> Iterator[np.ndarray]:
    """The diagram as `plot` draws it, with each frame's own line of simultaneity (its "now", horizontal in its
    own panel) sweeping up, and under each panel a strip of that frame's space at that instant, on the panel's
    x scale. Drawn once; each instant only redraws the moving artists over the saved background (blitting).
    `rod_view` ("first", "last"): the rod's own view beside the panels (alone without frames), its "now" a level
    line sweeping its chart time at an even pace, in lock-step with the panels."""
    def draw() -> Iterator[np.ndarray]:
        scene = NowScene(history, timeline, style, rod_view) if timeline.frames else RodNowScene(history, style)
        count = len(timeline)
        return blitted(scene.canvas, (scene.update(k, count) if not timeline.frames else scene.update(k)
                                      for k in range(count)))

    return in_style(style, draw)  # the style's rcParams only while an image is drawn


#: a lens is added under a strip whose rod is never longer than this fraction of the strip's width
LENS_BELOW = 0.2
#: the lens's magnification makes the rod's longest length about this fraction of the lens's width
LENS_FILL = 0.6
#: the rod in a lens is never shorter than this fraction of the lens's width: where one magnification cannot hold
#: the rod's shortest and longest lengths (fig2 at 0.97 in S′: 0.24 L, then 0.03 L), the lens follows it
LENS_LEAST = 1 / 3
#: nor longer than this fraction
LENS_MOST = 0.9
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
    #: a lens whose magnification follows the rod's length (`LENS_LEAST`): its title, rewritten at each instant
    lens_title: object | None = None


class NowScene:
    """Now mode's figure: `plot`'s diagram with a band of strips below, drawn once; `update(k)` moves each panel's
    now-line, strip and lens to instant k and returns the artists it moved, in drawing order. Build it inside
    `render.style_context(style)`.

    The band under each row of panels holds, for each panel, from the top: the readout (the frame and its
    time), the strip on the panel's x scale with the panel's ticks, the lens when the rod is small on that
    scale (the strip again, magnified about the midpoint of the rod's ends, which it follows), and the colour
    bar.
    """

    def __init__(self, history: RodHistory, timeline: NowTimeline, style: str, rod_view: str | None = None):
        from rodparadox import render
        from rodparadox.render.strip import draw_strip

        st = STYLES[style]
        self.history, self.timeline, self.L = history, timeline, history.scenario.L
        L = self.L
        # no inset: the strips' lens magnifies the rod, and an inset would not follow the now-line
        diagram = render.draw(history, timeline.frames, style, render.Options(insets=False))
        figure = diagram.figure
        if rod_view:
            render.draw_rod_view((history,), style, diagram, first=rod_view == "first")
        width, height = figure.get_size_inches()
        panels = [ax for ax in figure.axes if (ax.get_gid() or "").endswith("-axes")]
        rows = sorted({round(ax.get_position().y0, 6) for ax in panels}, reverse=True)
        magnifications = [self._magnification(p, ax) for p, ax in enumerate(panels)]
        self._lengths = [self._lengths_in(p) for p in range(len(panels))]
        self._span = [ax.get_xlim()[1] - ax.get_xlim()[0] for ax in panels]
        b = _Band(st, any(m > 1 for m in magnifications))
        forces = None  # a rod driven by forces: an arrow on each driven end of a strip, to plot's scale
        if history.driving is not None:
            from rodparadox.render.force_layers import force_scale

            forces = force_scale(history)
        band = b.height / 72  # inches, per row of panels
        total = height + band * len(rows)
        _make_room_below(figure, height, total, band * len(rows))
        figure.set_dpi(st.animation_dpi)
        self.figure, self.canvas = figure, FigureCanvasAgg(figure)
        self.panels: list[PanelMotion] = []
        for p, (ax, frame, scale) in enumerate(zip(panels, timeline.frames, timeline.scales)):
            letter = (ax.get_gid() or "a")[0]
            now = ax.axhline(timeline.times[0, p] / L, color=st.flash_colour, linewidth=2.0 * st.rod.width / 1.7,
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
                               bar_width=0.5 * b.strip_h, animated=True, force_scale=forces)
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
                                  readout=False, force_scale=forces)
                lens_ax.tick_params(length=b.tick_len, pad=b.tick_pad)
                title = lens_ax.set_title(f"\N{MULTIPLICATION SIGN}{m:g}, about the rod’s midpoint", loc="left",
                                          fontsize=b.small, pad=b.lens_pad)
                shortest, longest = self._lengths[p]
                span = 2 * half * m
                if shortest * m < LENS_LEAST * span or longest * m > LENS_MOST * span:
                    # one magnification cannot hold the rod's range of lengths: the lens follows it, untick'd
                    # (its title says the magnification now); its x runs in units of the lens's half-width
                    lens_ax.set_xlim(-1.0, 1.0)
                    lens_ax.set_xticks([0.0])
                    lens_ax.xaxis.set_major_formatter(_signed_labels(1.0))
                    title.set_animated(True)
                    self.panels.append(PanelMotion(frame, now, strip, lens, m, title))
                    continue
            self.panels.append(PanelMotion(frame, now, strip, lens, m))
        self.rod_now = _rod_now(figure, st)

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

        L, moved = self.L, list(_move_rod_now(self.rod_now, k, len(self.timeline)))
        for p, motion in enumerate(self.panels):
            shown_now = self.timeline.strip(self.history, k, p)
            motion.now.set_ydata([shown_now.t / L, shown_now.t / L])
            moved += [motion.now, *update_strip(motion.strip, shown_now, motion.frame, L)]
            if motion.lens is not None and motion.lens_title is None:
                moved += update_strip(motion.lens, _about_midpoint(shown_now), motion.frame, L)
            elif motion.lens is not None:
                span = self._span[p]
                m = nice_number(LENS_MOST * span / max(float(np.ptp(shown_now.x)) / L, 1e-300), "at_most")
                motion.lens_title.set_text(f"\N{MULTIPLICATION SIGN}{m:g}, about the rod’s midpoint")
                moved += [motion.lens_title, *update_strip(motion.lens, _scaled(_about_midpoint(shown_now),
                                                                                  2 * m / span), motion.frame, L)]
        return moved

    def _lengths_in(self, p: int) -> tuple[float, float]:
        """The rod's shortest and longest length in panel p over the animation, in units of L (sampled)."""
        ks = np.unique(np.linspace(0, len(self.timeline) - 1, LENS_SAMPLES).round().astype(int))
        lengths = [float(np.ptp(self.timeline.strip(self.history, int(k), p).x)) / self.L for k in ks]
        return min(lengths), max(lengths)


def _rod_now(figure: Figure, st) -> list:
    """The rod's own "now" on each panel of its own view (`render.rod_panel`): a level line of its chart."""
    out = []
    for ax in figure.axes:
        if (ax.get_gid() or "").endswith("-view"):
            T0 = ax.get_ylim()[0]
            out.append(ax.axhline(T0, color=st.flash_colour, linewidth=2.0 * st.rod.width / 1.7, zorder=8,
                                  animated=True, gid=f"{ax.get_gid()}-now"))
    return out


def _move_rod_now(lines: list, k: int, count: int) -> list:
    """The rod's "now" at instant k: its chart time sweeps the panel's window at an even pace (`timeline.sweep`)."""
    s = k / max(count - 1, 1)
    for line in lines:
        T0, T1 = line.axes.get_ylim()
        line.set_ydata([T0 + s * (T1 - T0)] * 2)
    return lines


class RodNowScene:
    """Now mode with the rod's own view alone (`--frame rod`): its panel, its "now" sweeping up."""

    def __init__(self, history: RodHistory, style: str):
        from rodparadox import render

        st = STYLES[style]
        self.figure = render.draw_rod_view((history,), style)
        self.figure.set_dpi(st.animation_dpi)
        self.canvas = FigureCanvasAgg(self.figure)
        self.rod_now = _rod_now(self.figure, st)

    def update(self, k: int, count: int) -> list:
        return _move_rod_now(self.rod_now, k, count)


def _scaled(strip, factor: float):
    """The strip with every x multiplied by `factor` (a lens whose x runs in units of its half-width)."""
    return replace(strip, x=strip.x * factor, particles=tuple((name, x * factor) for name, x in strip.particles),
                   flash_x=tuple(x * factor for x in strip.flash_x))


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
        self.tick_len, self.tick_pad = st.animation_ticks
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
