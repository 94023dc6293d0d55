"""World-lines -> matplotlib Figures: the paper's Minkowski diagrams (README, "Drawing the figures").

Never pyplot, never files: `draw` builds a `matplotlib.figure.Figure`
directly and `figure_bytes` serialises it deterministically; `output` writes.
Each panel is one frame's own coordinates in units of L (t up, x right, equal
scales, so light runs at 45 degrees) and shows, as in the paper's Figs. 1-2:
the rod's two end world-lines (solid) with its world-sheet shaded, the
particles' world-lines (dashed, labelled A and B), every impact (marker and
label, the same in every panel), and through every impact the line of
simultaneity of S and of S'. Every artist carries a gid (`a-rod_left`,
`b-impact-B1`, ...), which is also its id in the SVG.

The layout is computed here, in points, rather than by matplotlib's layout
engines: the figure's size follows from the data (equal scales), labels are
placed where they cross no line and no other label, and the result does not
depend on a renderer, so it is fast and byte-for-byte reproducible.
"""

from __future__ import annotations

import io
import math
import re
from contextlib import contextmanager
from dataclasses import dataclass
from typing import Iterator, Sequence

import matplotlib
import numpy as np
from matplotlib.figure import Figure
from matplotlib.font_manager import FontProperties
from matplotlib.lines import Line2D
from matplotlib.patches import Patch
from matplotlib.textpath import TextToPath
from matplotlib.ticker import FixedLocator, FuncFormatter

from .engine import History
from .frames import Frame, FrameView, sampling_tolerance, view
from .kinematics import Event, HyperbolicArc
from .styles import FORMATS, STYLES, Ink, Style

PANEL_LETTERS = "abcdefgh"

#: smallest and largest width/height of a panel's data box; a box outside is padded with empty space
ASPECT_RANGE = (0.62, 1.6)
#: empty margin around the world-lines, as a fraction of the larger side of the data box
MARGIN = 0.09

# metadata that would make two runs differ (dates, versions) is left out
_METADATA = {
    "svg": {"Date": None, "Creator": None},
    "pdf": {"Creator": None, "Producer": None, "CreationDate": None, "ModDate": None},
    "png": {"Software": None},
}


@dataclass(frozen=True)
class Options:
    """The teacher's extras, all off by default because they crowd a printed figure."""

    other_axes: bool = False  # the other frame's x and t axes, tilted
    light_cones: bool = False  # the light cone of every impact
    hyperbolae: bool = False  # calibration hyperbolae t^2 - x^2 = +-k^2 about the shared origin
    grid: bool = False


@contextmanager
def style_context(style: Style | str) -> Iterator[Style]:
    """Apply a style's rcParams while drawing or saving; restore them afterwards."""
    style = STYLES[style] if isinstance(style, str) else style
    with matplotlib.rc_context(style.rc):
        yield style


def draw(history: History, frames: Sequence[Frame], style: str = "default", options: Options = Options()) -> Figure:
    """The figure of a scenario's history: one panel per frame, side by side, in the given order."""
    if not frames:
        raise ValueError("draw needs at least one frame")
    with style_context(style) as st:
        return _Diagram(history, tuple(frames), st, options).figure


def figure_bytes(figure: Figure, fmt: str, style: str = "default") -> bytes:
    """The figure as SVG, PDF or PNG bytes; the same figure always gives the same bytes."""
    if fmt not in FORMATS:
        raise ValueError(f"unknown format {fmt!r}; use one of {', '.join(FORMATS)}")
    with style_context(style) as st:
        buffer = io.BytesIO()
        figure.savefig(buffer, format=fmt, metadata=_METADATA[fmt], dpi=st.png_dpi if fmt == "png" else 72)
        return buffer.getvalue()


# --- what the panels say --------------------------------------------------------------------------

def frame_symbol(frame: Frame) -> str:
    """The frame's name in the paper's notation (mathtext): S, S' or S_u for any other frame."""
    return {"rest": "S", "moving": "S'"}.get(frame.name, "S_u")


def coordinate_names(frame: Frame) -> tuple[str, str]:
    return {"rest": ("x", "t"), "moving": ("x'", "t'")}.get(frame.name, ("x_u", "t_u"))


def impact_text(label: str) -> str:
    """An impact's label in mathtext: B1 -> $B_1$."""
    m = re.fullmatch(r"([A-Za-z]+)(\d+)", label)
    return f"${m.group(1)}_{{{m.group(2)}}}$" if m else label


def relative_velocity(u: float, w: float) -> float:
    """Velocity, seen from a frame of velocity w, of a frame of velocity u (both relative to S)."""
    return (u - w) / (1.0 - u * w)


def _number(value: float) -> str:
    text = f"{value + 0.0:.3g}"
    return text.replace("-", "\N{MINUS SIGN}")


def _signed(value: float) -> str:
    return ("+" if value > 0 else "") + _number(value)


def _velocity_phrase(before: float, after: float) -> str:
    """The rod's velocity in a panel's frame, before the first impact and after the last."""
    def at(u: float) -> str:
        return "at rest" if abs(u) < 5e-13 else f"at ${_signed(u)}$"
    if abs(before - after) < 5e-13:
        return f"rod {at(before)} before and after"
    return f"rod first {at(before)}, finally {at(after)}"


def _panel_title(letter: str, fv: FrameView) -> str:
    frame = fv.frame
    after = fv.events[-1].rod_velocity_after if fv.events else frame.rod_velocity()
    name = f"frame ${frame_symbol(frame)}$"
    if frame.name not in ("rest", "moving"):
        name = f"frame ${frame_symbol(frame)}$ ($u = {_number(frame.velocity)}$)"
    return f"({letter}) {name}: {_velocity_phrase(frame.rod_velocity(), after)}"


def _mathtext_safe(text: str) -> str:
    return text.replace("$", r"\$")


# --- geometry in points ----------------------------------------------------------------------------

def _clip_line(x: float, t: float, dx: float, dt: float, box: tuple[float, float, float, float]):
    """The part inside box = (x0, x1, t0, t1) of the infinite line through (x, t) along (dx, dt), or None."""
    x0, x1, t0, t1 = box
    lo, hi = -math.inf, math.inf
    for p, a, b in ((dx, x0 - x, x1 - x), (dt, t0 - t, t1 - t)):
        if p == 0.0:
            if a > 0 or b < 0:
                return None
            continue
        s0, s1 = sorted((a / p, b / p))
        lo, hi = max(lo, s0), min(hi, s1)
    if not lo < hi:
        return None
    return np.array([[x + lo * dx, t + lo * dt], [x + hi * dx, t + hi * dt]])


def _boxes_hit_segments(box: np.ndarray, segments: np.ndarray) -> int:
    """How many of the segments (n, 4: x0 y0 x1 y1) cross the box (xmin, ymin, xmax, ymax) (Liang-Barsky)."""
    if len(segments) == 0:
        return 0
    x0, y0, x1, y1 = segments.T
    dx, dy = x1 - x0, y1 - y0
    lo = np.zeros(len(segments))
    hi = np.ones(len(segments))
    ok = np.ones(len(segments), dtype=bool)
    with np.errstate(divide="ignore", invalid="ignore"):
        for p, q in ((-dx, x0 - box[0]), (dx, box[2] - x0), (-dy, y0 - box[1]), (dy, box[3] - y0)):
            zero = p == 0
            ok &= ~(zero & (q < 0))
            r = q / np.where(zero, 1.0, p)
            lo = np.where(p < 0, np.maximum(lo, r), lo)
            hi = np.where(p > 0, np.minimum(hi, r), hi)
    return int(np.count_nonzero(ok & (lo <= hi)))


def _boxes_overlap(a, b) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


_TEXT_TO_PATH = TextToPath()


def text_size(text: str, size: float) -> tuple[float, float, float]:
    """(width, height, descent) in points of a text as the SVG and PDF backends lay it out."""
    w, h, d = _TEXT_TO_PATH.get_text_width_height_descent(text, FontProperties(size=size), ismath="$" in text)
    return float(w), float(h), float(d)


@dataclass
class _Label:
    gid: str
    text: str
    anchor: tuple[float, float]  # data units
    preferred: float  # direction, degrees, counter-clockwise from +x
    colour: str
    size: float
    avoid_radius: float = 0.0  # points kept clear around the anchor (a marker)


# --- the diagram ---------------------------------------------------------------------------------

@dataclass
class _Panel:
    letter: str
    view: FrameView
    worldlines: dict[str, np.ndarray]  # units of L
    box: list[float]  # x0, x1, t0, t1: the axes limits, units of L
    title: str
    width: float = 0.0  # points
    height: float = 0.0


class _Diagram:
    def __init__(self, history: History, frames: tuple[Frame, ...], style: Style, options: Options):
        self.history, self.style, self.options = history, style, options
        self.L = history.scenario.L
        self.v = history.scenario.v
        fs = style.font_size
        self.fs = {"tick": fs, "label": fs * 1.1, "title": fs * 1.1, "suptitle": fs * 1.25, "legend": fs,
                   "impact": fs * 1.1, "particle": fs * 1.25}
        self._widest_line = max(ink.width for ink in (style.rod, *style.particles.values(), style.rest_simultaneity,
                                                      style.moving_simultaneity, style.other_axes, style.light_cone,
                                                      style.hyperbola))
        self.panels = [self._panel(letter, frame) for letter, frame in zip(PANEL_LETTERS, frames)]
        self.figure = self._build()

    # data ------------------------------------------------------------------------------------------
    def _panel(self, letter: str, frame: Frame) -> _Panel:
        fv = view(self.history, frame)
        tolerance = sampling_tolerance(self.history)
        worldlines = {name: points / self.L for name, points in fv.worldline_points(tolerance).items()}
        everything = np.concatenate(list(worldlines.values()))
        x0, x1 = float(everything[:, 0].min()), float(everything[:, 0].max())
        t0, t1 = fv.t_range[0] / self.L, fv.t_range[1] / self.L
        margin = MARGIN * max(x1 - x0, t1 - t0)
        box = [x0 - margin, x1 + margin, t0 - margin, t1 + margin]
        self._fit_aspect(box, *ASPECT_RANGE)
        return _Panel(letter, fv, worldlines, box, _panel_title(letter, fv))

    @staticmethod
    def _fit_aspect(box: list[float], low: float, high: float) -> None:
        """Pad the box with empty space (both sides equally) until low <= width/height <= high."""
        w, h = box[1] - box[0], box[3] - box[2]
        if w < low * h:
            pad = (low * h - w) / 2
            box[0] -= pad
            box[1] += pad
        elif w > high * h:
            pad = (w / high - h) / 2
            box[2] -= pad
            box[3] += pad

    # layout ------------------------------------------------------------------------------------------
    def _ticks(self, box: list[float]) -> tuple[np.ndarray, np.ndarray, float]:
        """Ticks at one step for both axes (equal scales)."""
        sides = sorted((box[1] - box[0], box[3] - box[2]))
        raw = max(sides[1] / 8.0, sides[0] / 4.0)  # at least about four ticks on the shorter side, at most eight
        magnitude = 10.0 ** math.floor(math.log10(raw))
        step = next(m * magnitude for m in (1, 2, 2.5, 5, 10) if m * magnitude >= raw)
        def ticks(lo, hi):
            k = np.arange(math.ceil(lo / step - 1e-9), math.floor(hi / step + 1e-9) + 1)
            return k * step
        return ticks(box[0], box[1]), ticks(box[2], box[3]), step

    def _build(self) -> Figure:
        st, fs = self.style, self.fs
        names = [coordinate_names(p.view.frame) for p in self.panels]
        tick_len, tick_pad, label_pad = 3.5, 3.5, 4.0
        if st.name == "slides":
            tick_len = 6.0
        ticks = [self._ticks(p.box) for p in self.panels]
        fmt = [lambda value, step=step: self._tick_text(value, step) for _, _, step in ticks]

        tick_h = text_size("0123456789", fs["tick"])[1]
        label_h = text_size("$x/L$", fs["label"])
        left_gutters = []
        for (xt, tt, step), f in zip(ticks, fmt):
            widest = max((text_size(f(value), fs["tick"])[0] for value in tt), default=0.0)
            left_gutters.append(widest + tick_len + tick_pad + label_pad + label_h[0] * 0 + text_size("$t/L$", fs["label"])[1] + 4)
        bottom_axis = tick_len + tick_pad + tick_h + label_pad + label_h[1] + label_h[2] + 4
        title_h = text_size(self.panels[0].title, fs["title"])[1] + 5.0 + 8

        # panel sizes: one height for all, each width from its aspect, wide enough for its title
        aspects = [(p.box[1] - p.box[0]) / (p.box[3] - p.box[2]) for p in self.panels]
        right = 10.0
        fixed = sum(left_gutters) + right + 6.0 * (len(self.panels) - 1)
        height = min(st.panel_height * 72, (st.max_width * 72 - fixed) / sum(aspects))
        for p, aspect in zip(self.panels, aspects):
            p.height = height
            p.width = height * aspect
            title_w = text_size(p.title, fs["title"])[0] + 6
            if title_w > p.width:  # widen the box (empty space both sides) to make room for the title
                extra = (title_w / height - aspect) * (p.box[3] - p.box[2]) / 2
                p.box[0] -= extra
                p.box[1] += extra
                p.width = title_w
        ticks = [self._ticks(p.box)[:2] + (step,) for p, (_, _, step) in zip(self.panels, ticks)]
        ticks = [(self._ticks_at(p.box[0], p.box[1], step), self._ticks_at(p.box[2], p.box[3], step), step)
                 for p, (_, _, step) in zip(self.panels, ticks)]

        width = fixed + sum(p.width for p in self.panels)
        handles, labels = self._legend_entries()
        legend_rows, legend_cols = self._legend_shape(labels, width)
        legend_h = legend_rows * fs["legend"] * 1.75 + 6
        suptitle = self._suptitle(width)
        top = (text_size(suptitle, fs["suptitle"])[1] + 14) if suptitle else 6
        fig_w = width
        fig_h = top + title_h + height + bottom_axis + legend_h

        figure = Figure(figsize=(fig_w / 72, fig_h / 72), dpi=72)
        x = 0.0
        for p, gutter, (xt, tt, step), (xname, tname) in zip(self.panels, left_gutters, ticks, names):
            x += gutter
            ax = figure.add_axes((x / fig_w, (bottom_axis + legend_h) / fig_h, p.width / fig_w, p.height / fig_h))
            x += p.width + 6.0
            ax.set_gid(f"{p.letter}-axes")
            self._axes(ax, p, xt, tt, step, xname, tname, tick_len, tick_pad, label_pad)
        if suptitle:
            figure.text(0.5, 1 - 7 / fig_h, suptitle, ha="center", va="top", fontsize=fs["suptitle"], gid="title")
        legend = figure.legend(handles, labels, loc="upper center", bbox_to_anchor=(0.5, (legend_h - 2) / fig_h),
                               ncol=legend_cols, fontsize=fs["legend"], handlelength=3.2, handletextpad=0.6,
                               columnspacing=1.6, borderaxespad=0.0, borderpad=0.0, labelspacing=0.5,
                               handler_map=self._handler_map)
        legend.set_gid("legend")
        return figure

    @staticmethod
    def _ticks_at(lo: float, hi: float, step: float) -> np.ndarray:
        k = np.arange(math.ceil(lo / step - 1e-9), math.floor(hi / step + 1e-9) + 1)
        return k * step

    @staticmethod
    def _tick_text(value: float, step: float) -> str:
        decimals = max(0, -math.floor(math.log10(step) + 1e-9)) + (1 if round(step / 10 ** math.floor(math.log10(step) + 1e-9), 6) == 2.5 else 0)
        text = f"{value:.{decimals}f}"
        if float(text) == 0:
            text = "0" if decimals == 0 else f"{0:.{decimals}f}"
        return text.replace("-", "\N{MINUS SIGN}")

    def _suptitle(self, width: float) -> str:
        s = self.history.scenario
        head = f"{_mathtext_safe(s.name)}, $v = {_number(s.v)}$"
        # the description's first clause: up to a semicolon or the end of its first sentence
        clause = re.split(r";|\.(?=\s+[A-Z]|\s*$)", " ".join(s.description.split()))[0].strip()
        if clause:
            full = f"{head}: {_mathtext_safe(clause)}"
            try:
                if text_size(full, self.fs["suptitle"])[0] <= width - 10:
                    return full
            except ValueError:  # a description that is not valid mathtext
                pass
        return head

    # legend ----------------------------------------------------------------------------------------
    def _line_handle(self, ink: Ink, **kw) -> Line2D:
        return Line2D([], [], color=ink.colour, linewidth=ink.width, linestyle=ink.dashes, **kw)

    def _legend_entries(self):
        st, o = self.style, self.options
        sheet = Patch(facecolor=st.sheet, edgecolor="none")
        entries = [((sheet, self._line_handle(st.rod)), "rod: its ends (solid), world-sheet shaded")]
        for name in ("A", "B"):
            if self.history.worldline(name) is not None:
                entries.append((self._line_handle(st.particles[name]), f"particle {name}"))
        entries.append((Line2D([], [], linestyle="none", marker="o", markersize=st.impact_size,
                               markerfacecolor=st.impact_colour, markeredgecolor="white", markeredgewidth=0.6),
                        "impact"))
        entries.append((self._line_handle(st.rest_simultaneity), "simultaneous in $S$ ($t$ = const)"))
        entries.append((self._line_handle(st.moving_simultaneity), "simultaneous in $S'$ ($t'$ = const)"))
        if o.other_axes:
            entries.append((self._line_handle(st.other_axes), "axes of the other frame"))
        if o.light_cones:
            entries.append((self._line_handle(st.light_cone), "light cone of an impact"))
        if o.hyperbolae:
            entries.append((self._line_handle(st.hyperbola), "calibration hyperbolae $t^2 - x^2 = \\pm k^2$"))
        handles = [h for h, _ in entries]
        labels = [label for _, label in entries]
        from matplotlib.legend_handler import HandlerTuple  # noqa: PLC0415  (only the legend needs it)
        self._handler_map = {tuple: HandlerTuple(ndivide=1)}
        return handles, labels

    def _legend_shape(self, labels: list[str], width: float) -> tuple[int, int]:
        """(rows, columns) of the widest legend that fits; columns filled as matplotlib does (array_split)."""
        fs = self.fs["legend"]
        entry = np.array([text_size(label, fs)[0] + (3.2 + 0.6) * fs for label in labels])
        for cols in range(len(labels), 0, -1):
            columns = [c for c in np.array_split(entry, cols) if len(c)]
            if sum(c.max() for c in columns) + 1.6 * fs * (len(columns) - 1) <= width - 10:
                return math.ceil(len(labels) / cols), cols
        return len(labels), 1

    # one panel -------------------------------------------------------------------------------------
    def _axes(self, ax, p: _Panel, xt, tt, step, xname, tname, tick_len, tick_pad, label_pad) -> None:
        st, fs, o = self.style, self.fs, self.options
        x0, x1, t0, t1 = p.box
        ax.set_xlim(x0, x1)
        ax.set_ylim(t0, t1)
        ax.set_aspect("equal", adjustable="box")
        ax.xaxis.set_major_locator(FixedLocator(xt))
        ax.yaxis.set_major_locator(FixedLocator(tt))
        formatter = FuncFormatter(lambda value, _pos: self._tick_text(value, step))
        ax.xaxis.set_major_formatter(formatter)
        ax.yaxis.set_major_formatter(formatter)
        ax.tick_params(labelsize=fs["tick"], length=tick_len, pad=tick_pad)
        ax.set_xlabel(f"${xname}/L$", fontsize=fs["label"], labelpad=label_pad)
        ax.set_ylabel(f"${tname}/L$", fontsize=fs["label"], labelpad=label_pad)
        ax.set_title(p.title, fontsize=fs["title"])
        if o.grid:
            ax.grid(True, color=st.grid.colour, linewidth=st.grid.width, linestyle=st.grid.dashes, zorder=0)
            ax.set_axisbelow(True)

        obstacles: list[np.ndarray] = []  # polylines in data units, for placing labels
        letter = p.letter
        frame = p.view.frame

        # the rod's world-sheet, then its ends
        left, right = p.worldlines["rod_left"], p.worldlines["rod_right"]
        ax.fill(np.concatenate([left[:, 0], right[::-1, 0]]), np.concatenate([left[:, 1], right[::-1, 1]]),
                facecolor=st.sheet, edgecolor="none", zorder=1, gid=f"{letter}-sheet")
        for name in ("rod_left", "rod_right"):
            points = p.worldlines[name]
            ax.plot(points[:, 0], points[:, 1], color=st.rod.colour, linewidth=st.rod.width,
                    linestyle=st.rod.dashes, zorder=4, gid=f"{letter}-{name}")
            obstacles.append(points)
        for name in ("A", "B"):
            if name in p.worldlines:
                ink = st.particles[name]
                points = p.worldlines[name]
                ax.plot(points[:, 0], points[:, 1], color=ink.colour, linewidth=ink.width, linestyle=ink.dashes,
                        zorder=5, gid=f"{letter}-{name}")
                obstacles.append(points)

        # lines of simultaneity of S and S' through every impact (one line for impacts that share it)
        events = [(e.impact.label, e.impact.end, e.x / self.L, e.t / self.L) for e in p.view.events]
        families = (("rest", 0.0, st.rest_simultaneity, 2.2), ("moving", -self.v, st.moving_simultaneity, 2.1))
        for family, velocity, ink, zorder in families:
            slope = relative_velocity(velocity, frame.velocity)  # dt/dx of the line in this panel
            drawn: list[tuple[float, str, list[str]]] = []
            for label, _, x, t in events:
                intercept = t - slope * x
                same = next((d for d in drawn if abs(d[0] - intercept) <= 1e-9 * (1 + abs(intercept))), None)
                if same is not None:
                    same[2].append(label)
                else:
                    drawn.append((intercept, label, [label]))
            for intercept, label, labels in drawn:
                x, t = next((e[2], e[3]) for e in events if e[0] == label)
                segment = _clip_line(x, t, 1.0, slope, p.box)
                if segment is None:
                    continue
                ax.plot(segment[:, 0], segment[:, 1], color=ink.colour, linewidth=ink.width, linestyle=ink.dashes,
                        zorder=zorder, gid=f"{letter}-simultaneity-{family}-{'+'.join(labels)}")
                obstacles.append(segment)

        labels: list[_Label] = []
        if o.other_axes:
            for other, velocity in (("rest", 0.0), ("moving", -self.v)):
                if other == frame.name:
                    continue
                u = relative_velocity(velocity, frame.velocity)
                xn, tn = coordinate_names(Frame(other, velocity))
                for axis, (dx, dt), name in (("t", (u, 1.0), tn), ("x", (1.0, u), xn)):
                    segment = _clip_line(0.0, 0.0, dx, dt, p.box)
                    if segment is None:
                        continue
                    ax.plot(segment[:, 0], segment[:, 1], color=st.other_axes.colour, linewidth=st.other_axes.width,
                            linestyle=st.other_axes.dashes, zorder=2, gid=f"{letter}-axis-{other}-{axis}")
                    obstacles.append(segment)
                    end = segment[1]
                    inward = math.degrees(math.atan2((t0 + t1) / 2 - end[1], (x0 + x1) / 2 - end[0]))
                    labels.append(_Label(f"{letter}-axis-label-{other}-{axis}", f"${name}$", (end[0], end[1]),
                                         inward, st.other_axes.colour, fs["impact"]))
        if o.light_cones:
            for label, _, x, t in events:
                for side, slope in (("right", 1.0), ("left", -1.0)):
                    segment = _clip_line(x, t, 1.0, slope, p.box)
                    if segment is not None:
                        ax.plot(segment[:, 0], segment[:, 1], color=st.light_cone.colour,
                                linewidth=st.light_cone.width, linestyle=st.light_cone.dashes, zorder=1.5,
                                gid=f"{letter}-light-cone-{label}-{side}")
                        obstacles.append(segment)
        if o.hyperbolae:
            for k, points in enumerate(self._hyperbolae(p.box, step)):
                ax.plot(points[:, 0], points[:, 1], color=st.hyperbola.colour, linewidth=st.hyperbola.width,
                        linestyle=st.hyperbola.dashes, zorder=1.2, gid=f"{letter}-hyperbola-{k}")
                obstacles.append(points)

        # impacts: markers on top, labelled the same in every panel
        for label, end, x, t in events:
            ax.plot([x], [t], linestyle="none", marker="o", markersize=st.impact_size,
                    markerfacecolor=st.impact_colour, markeredgecolor="white", markeredgewidth=0.6,
                    zorder=7, gid=f"{letter}-impact-{label}")
            labels.insert(len([l for l in labels if "-impact-label-" in l.gid]),
                          _Label(f"{letter}-impact-label-{label}", impact_text(label), (x, t),
                                 0.0 if end == "right" else 180.0, st.impact_colour, fs["impact"],
                                 avoid_radius=st.impact_size / 2 + 1.0))
        # particles: their letter beside the first part of the world-line
        for name in ("A", "B"):
            if name in p.worldlines:
                points = p.worldlines[name]
                first = next((e.t / self.L for e in p.view.events if e.impact.particle == name), points[-1, 1])
                t_at = points[0, 1] + min(0.1 * (p.box[3] - p.box[2]), 0.6 * (first - points[0, 1]))
                x_at = float(np.interp(t_at, points[:, 1], points[:, 0]))
                labels.append(_Label(f"{letter}-particle-label-{name}", f"${name}$", (x_at, t_at),
                                     180.0 if name == "A" else 0.0, st.particles[name].colour, fs["particle"]))
        self._place(ax, p, labels, obstacles)

    def _hyperbolae(self, box: list[float], step: float) -> list[np.ndarray]:
        """t^2 - x^2 = +-k^2 about the shared origin, k a multiple of the tick step, sampled within 1e-4 L."""
        x0, x1, t0, t1 = box
        reach = max(abs(x0), abs(x1), abs(t0), abs(t1))
        out = []
        for m in range(1, 7):
            k = m * step
            if k > reach:
                break
            for swap in (False, True):  # x-branches (space-like), then t-branches (time-like)
                for side in (1, -1):
                    lo_c, hi_c = (x0, x1) if swap else (t0, t1)  # the coordinate that runs along the branch
                    lo = math.asinh(max(min(lo_c / k, 1e6), -1e6))
                    hi = math.asinh(max(min(hi_c / k, 1e6), -1e6))
                    if side == -1:
                        lo, hi = -hi, -lo
                    arc = HyperbolicArc(Event(0.0, 0.0), k, side, lo, hi)
                    points = arc.sample(sampling_tolerance(self.history) / self.L)
                    if swap:
                        points = points[:, ::-1]
                    inside = ((points[:, 0] >= x0) & (points[:, 0] <= x1) & (points[:, 1] >= t0) & (points[:, 1] <= t1))
                    if inside.any():
                        out.append(points)
        return out

    # label placement --------------------------------------------------------------------------------
    def _place(self, ax, p: _Panel, labels: list[_Label], obstacles: list[np.ndarray]) -> None:
        """Put each label near its anchor where its box crosses no line, marker or earlier label."""
        x0, x1, t0, t1 = p.box
        sx, st_ = p.width / (x1 - x0), p.height / (t1 - t0)  # points per unit of L (equal, up to rounding)

        def to_pt(points: np.ndarray) -> np.ndarray:
            return np.column_stack([(points[:, 0] - x0) * sx, (points[:, 1] - t0) * st_])

        segments = np.concatenate([np.column_stack([q[:-1], q[1:]]) for q in map(to_pt, obstacles) if len(q) > 1])
        taken = [self._marker_box(to_pt(np.array([l.anchor]))[0], l.avoid_radius) for l in labels if l.avoid_radius]
        pad, edge = 2.0 + self._widest_line / 2, 2.0  # clear of every line's stroke, and of the frame
        radii = (2.0, 4.0, 7.0, 11.0, 16.0, 22.0, 29.0, 37.0, 46.0)
        directions = np.arange(0, 360, 15)
        for label in labels:
            w, h, d = text_size(label.text, label.size)
            anchor = to_pt(np.array([label.anchor]))[0]
            order = sorted(directions, key=lambda a: (abs((a - label.preferred + 180) % 360 - 180), a))
            best = None
            for ri, r in enumerate(radii):
                for angle in order:
                    c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
                    px, py = anchor[0] + (r + label.avoid_radius) * c, anchor[1] + (r + label.avoid_radius) * s
                    ha = "left" if c > 0.3 else "right" if c < -0.3 else "center"
                    va = "bottom" if s > 0.3 else "top" if s < -0.3 else "center"
                    bx = px if ha == "left" else px - w if ha == "right" else px - w / 2
                    by = py if va == "bottom" else py - h if va == "top" else py - h / 2
                    box = (bx - pad, by - pad, bx + w + pad, by + h + pad)
                    if box[0] < edge or box[1] < edge or box[2] > p.width - edge or box[3] > p.height - edge:
                        continue
                    hits = _boxes_hit_segments(np.array(box), segments)
                    hits += sum(_boxes_overlap(box, other) for other in taken)
                    score = (hits, ri)
                    if best is None or score < best[0]:
                        best = (score, (px, py, ha, va, box))
                    if hits == 0:
                        break
                if best is not None and best[0][0] == 0:
                    break
            if best is None:  # no room inside the panel at all: put it on the anchor
                best = ((0, 0), (anchor[0], anchor[1], "center", "center", (0, 0, 0, 0)))
            px, py, ha, va, box = best[1]
            taken.append(box)
            # mathtext's baseline sits `d` above the box bottom; "bottom"/"top"/"center" align the full box
            ax.text(x0 + px / sx, t0 + py / st_, label.text, ha=ha, va=va, fontsize=label.size, color=label.colour,
                    zorder=8, gid=label.gid)

    @staticmethod
    def _marker_box(centre, radius: float):
        return (centre[0] - radius, centre[1] - radius, centre[0] + radius, centre[1] + radius)
