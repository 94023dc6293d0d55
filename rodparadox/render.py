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
from functools import lru_cache
from typing import Iterator, NamedTuple, Sequence

import matplotlib
import numpy as np
from matplotlib.cbook import is_math_text
from matplotlib.figure import Figure
from matplotlib.font_manager import FontProperties
from matplotlib.legend_handler import HandlerTuple
from matplotlib.lines import Line2D
from matplotlib.patches import Patch, Polygon
from matplotlib.textpath import text_to_path
from matplotlib.ticker import FixedLocator, FuncFormatter

from . import kinematics, rod
from .engine import History
from .frames import Frame, FrameView, sampling_tolerance, view
from .kinematics import Event, HyperbolicArc
from .numbers import MINUS, SCIENTIFIC_ABOVE, shown
from .styles import FORMATS, STYLES, Ink, Style

#: one panel per frame, lettered (a), (b), ...: at most eight side by side
PANEL_LETTERS = "abcdefgh"

#: smallest and largest width/height of a panel's data box; a box outside is padded with empty space
ASPECT_RANGE = (0.62, 1.6)
#: empty margin around the world-lines, as a fraction of the larger side of the data box
MARGIN = 0.09
#: of the arrangements of panels into rows, the one with the most to a row whose panels are at least this
#: fraction of the tallest any arrangement allows, and at least READABLE_PANEL tick labels tall
ROW_PREFERENCE = 0.55
READABLE_PANEL = 12.0
#: an impact's label sits within this many points of its marker's edge, or a thin leader line ties it to the marker
LABEL_REACH = 12.0
#: a panel's title wraps onto at most this many lines
TITLE_LINES = 3
#: length of a light cone's arms (each way, in t) as a fraction of the shorter side of the panel
CONE_REACH = 0.16

# metadata that would make two runs differ (dates, versions) is left out
_METADATA = {
    "svg": {"Date": None, "Creator": None},
    "pdf": {"Creator": None, "Producer": None, "CreationDate": None, "ModDate": None},
    "png": {"Software": None},
}


class Options(NamedTuple):
    """The teacher's extras, all off by default because they crowd a printed figure."""

    other_axes: bool = False  # the other frame's x and t axes, tilted
    light_cones: bool = False  # the light cone of every impact
    hyperbolae: bool = False  # calibration hyperbolae t^2 - x^2 = +-k^2 about the shared origin
    grid: bool = False
    rod_lines: int = 0  # this many interior material world-lines of the rod
    rod_now: bool = False  # the rod's own lines of simultaneity: each turn's fan, and lines between turns
    proper_time: bool = False  # clock ticks of equal proper time along each particle and each rod end


@contextmanager
def style_context(style: Style | str) -> Iterator[Style]:
    """Apply a style's rcParams while drawing or saving; restore them afterwards."""
    style = STYLES[style] if isinstance(style, str) else style
    with matplotlib.rc_context(style.rc):
        yield style


def draw(history: History, frames: Sequence[Frame], style: str = "default", options: Options = Options()) -> Figure:
    """The figure of a scenario's history: one panel per frame, side by side, in the given order."""
    if not 1 <= len(frames) <= len(PANEL_LETTERS):
        raise ValueError(f"draw takes 1 to {len(PANEL_LETTERS)} frames (panels (a) to (h)), got {len(frames)}")
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
    """The frame's name as the paper writes it: S, S′, or u = ... for any other frame."""
    return {"rest": "S", "moving": "S\N{PRIME}"}.get(frame.name, f"u = {shown(frame.velocity)}")


def coordinate_names(frame: Frame) -> tuple[str, str]:
    """The frame's (x, t) as plain italic text, or mathtext for a frame of velocity u (x_u, t_u)."""
    return {"rest": ("x", "t"), "moving": ("x\N{PRIME}", "t\N{PRIME}")}.get(frame.name, ("$x_u$", "$t_u$"))


def axis_label(name: str) -> str:
    """x -> x/L (set in italics), $x_u$ -> $x_u/L$ (mathtext)."""
    return f"{name[:-1]}/L$" if name.endswith("$") else f"{name}/L"


def impact_text(label: str) -> str:
    """An impact's label in mathtext: B1 -> $B_1$."""
    m = re.fullmatch(r"([A-Za-z]+)(\d+)", label)
    return f"${m.group(1)}_{{{m.group(2)}}}$" if m else label


def impact_text_size(label: str, size: float) -> tuple[float, float, float]:
    """A box at least as large as `impact_text(label)` draws, from plain glyph metrics (no mathtext parse).

    The letter in italics, then the digits at 0.7 of the size, then a tenth of
    the size to spare; height: the letter's plus the subscript's drop. It is a
    few per cent larger than mathtext's own box in every style (tested), which
    is safe for placing the label: the drawn text lies inside it.
    """
    m = re.fullmatch(r"([A-Za-z]+)(\d+)", label)
    letter, digits = (m.group(1), m.group(2)) if m else (label, "")
    w_letter, h_letter, _ = text_size(letter, size, italic=True)
    w_digits = text_size(digits, 0.7 * size)[0] if digits else 0.0
    return w_letter + w_digits + 0.1 * size, h_letter + 0.22 * size, 0.22 * size


def relative_velocity(u: float, w: float) -> float:
    """Velocity, seen from a frame of velocity w, of a frame of velocity u (both relative to S)."""
    return (u - w) / (1.0 - u * w)


def _signed(value: float) -> str:
    return ("+" if value > 0 else "") + shown(value, 4)


def _velocity_phrase(before: float, after: float) -> str:
    """The rod's velocity in a panel's frame, before the first impact and after the last."""
    def at(u: float) -> str:
        return "at rest" if abs(u) < 5e-13 else f"at {_signed(u)}"
    if abs(before - after) < 5e-13:
        return f"rod {at(before)} before and after"
    return f"rod first {at(before)}, finally {at(after)}"


def _panel_title(letter: str, fv: FrameView) -> str:
    """Plain text, no mathtext (each mathtext string costs milliseconds to lay out): the frame and the rod's velocity."""
    frame = fv.frame
    after = fv.events[-1].rod_velocity_after if fv.events else frame.rod_velocity()
    return f"({letter}) frame {frame_symbol(frame)}: {_velocity_phrase(frame.rod_velocity(), after)}"


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


def _boxes_hit_segments(boxes: np.ndarray, segments: np.ndarray) -> np.ndarray:
    """For each box (k, 4: xmin ymin xmax ymax), how many segments (n, 4: x0 y0 x1 y1) cross it (Liang-Barsky)."""
    if len(segments) == 0:
        return np.zeros(len(boxes), dtype=int)
    x0, y0, x1, y1 = (segments[:, i][None, :] for i in range(4))
    dx, dy = x1 - x0, y1 - y0
    lo = np.zeros((len(boxes), len(segments)))
    hi = np.ones_like(lo)
    ok = np.ones(lo.shape, dtype=bool)
    b = [boxes[:, i][:, None] for i in range(4)]
    with np.errstate(divide="ignore", invalid="ignore"):
        for p, q in ((-dx, x0 - b[0]), (dx, b[2] - x0), (-dy, y0 - b[1]), (dy, b[3] - y0)):
            zero = p == 0
            ok &= ~(zero & (q < 0))
            r = q / np.where(zero, 1.0, p)
            lo = np.where(p < 0, np.maximum(lo, r), lo)
            hi = np.where(p > 0, np.minimum(hi, r), hi)
    return np.count_nonzero(ok & (lo <= hi), axis=1)


def text_size(text: str, size: float, italic: bool = False, ismath: bool | None = None) -> tuple[float, float, float]:
    """(width, height, descent) in points of a text as the SVG and PDF backends lay it out (current rcParams).

    `ismath` None reads the text as a Text artist does: mathtext if it holds an
    even number of unescaped $ (matplotlib.cbook.is_math_text), else plain.
    Drawing calls it for plain text only: parsing mathtext costs milliseconds
    and the renderer parses each string again, so mathtext is sized from its
    glyphs instead (`approximate_size`, `impact_text_size`).
    """
    rc = matplotlib.rcParams
    return _measured(text, float(size), italic, is_math_text(text) if ismath is None else bool(ismath),
                     rc["mathtext.fontset"], tuple(rc["font.family"]), tuple(rc["font.sans-serif"]),
                     tuple(rc["font.serif"]))


@lru_cache(maxsize=2048)  # a figure measures a few hundred texts; bounded, as a long-lived process draws many
def _measured(text: str, size: float, italic: bool, ismath: bool, *fonts) -> tuple[float, float, float]:
    """`text_size` for the current rcParams, whose font settings are `fonts` (part of the cache key only)."""
    prop = FontProperties(size=size, style="italic" if italic else "normal")
    w, h, d = text_to_path.get_text_width_height_descent(text, prop, ismath=ismath)
    return float(w), float(h), float(d)


# mathtext -> the plain characters it draws, roughly: the braces of groups vanish, \$ is a dollar sign
_MATH_AS_PLAIN = {"\\$": "$", "\\pm": "\N{PLUS-MINUS SIGN}", "\\times": "\N{MULTIPLICATION SIGN}",
                  "^2": "\N{SUPERSCRIPT TWO}", "{": "", "}": "", "'": "\N{PRIME}"}


def approximate_size(text: str, size: float) -> tuple[float, float, float]:
    """A slight over-estimate of what a Text artist draws for `text`, without parsing mathtext.

    Plain text (no pair of unescaped $) is measured as it is. Mathtext is
    measured as plain characters, each $...$ part by the characters it draws,
    each \\$ outside them as a dollar sign, plus 4 %.
    """
    if not is_math_text(text):
        return text_size(text, size, ismath=False)
    parts = re.split(r"(?<!\\)\$", text)  # even: plain text between the math parts; odd: math
    plain = "".join(part.replace("\\$", "$") if i % 2 == 0 else
                    re.sub(r"\\\$|\\pm|\\times|\^2|[{}']", lambda m: _MATH_AS_PLAIN[m.group(0)], part)
                    for i, part in enumerate(parts))
    w, h, d = text_size(plain, size, ismath=False)
    return w * 1.04 + 2.0, max(h, size * 1.1), max(d, size * 0.25)


class _Label(NamedTuple):
    """A text to place beside one of its anchors (data units, best first), clear of every line, marker and label."""

    gid: str
    text: str
    anchors: tuple[tuple[float, float], ...]
    preferred: float  # direction, degrees, counter-clockwise from +x
    colour: str
    size: float
    avoid_radius: float = 0.0  # points kept clear around the first anchor (a marker)
    italic: bool = False  # plain text in italics: a single letter needs no mathtext
    guides_block: bool = False  # an axis's name: it must not sit on any line, its own included
    box_size: tuple[float, float] | None = None  # (width, height) in points, if not measured from `text`


def _next_step(step: float) -> float:
    """The next nice tick step above `step`: 1, 2, 2.5, 5, 10 times a power of ten."""
    magnitude = 10.0 ** math.floor(math.log10(step) + 1e-9)
    return next(k * magnitude for k in (2, 2.5, 5, 10, 20) if k * magnitude > step * (1 + 1e-9))


class _Metrics:
    """The sizes, in points, of everything around the panels in a style: bands for titles, ticks, labels, legend."""

    def __init__(self, style: Style, fs: dict[str, float]):
        self.fs = fs
        self.tick_len = 6.0 if style.name == "slides" else 3.5
        self.tick_pad, self.label_pad, self.gap, self.right, self.row_gap = 3.5, 4.0, 6.0, 10.0, 6.0
        self.label_h = approximate_size("$x_u/L$", fs["label"])[1]  # the tallest axis label
        self.tick_h = approximate_size("0123456789", fs["tick"])[1]
        self.tick_gap = 0.6 * fs["tick"]  # the least room between two tick labels
        self.bottom_axis = self.tick_len + self.tick_pad + self.tick_h + self.label_pad + self.label_h + 6
        self.title_line = 1.2 * fs["title"]  # matplotlib's line spacing
        self.title_pad = style.rc["axes.titlepad"] + 8
        self.least_panel = 6 * fs["tick"]  # below this a panel has no room for its ticks: shrink no further
        self.gutters: dict[str, float] = {}  # each panel's room on the left
        self.rights: dict[str, float] = {}  # the room right of each panel, were it last in its row

    def gutter(self, p: _Panel, steps: tuple[float, float], diagram: "_Diagram") -> float:
        """Room left of a panel for its t tick labels and t axis label, and for half its first x tick label."""
        x_step, t_step = steps
        widest = max((approximate_size(diagram._tick_text(value, t_step), self.fs["tick"])[0]
                      for value in diagram._ticks_at(p.data_box[2], p.data_box[3], t_step)), default=0.0)
        return max(widest + self.tick_len + self.tick_pad + self.label_pad + self.label_h + 4,
                   self.overhang(p, x_step, diagram))

    def overhang(self, p: _Panel, x_step: float, diagram: "_Diagram") -> float:
        """How far an x tick label at the panel's edge can reach beyond it: half the widest, and a little."""
        return max((approximate_size(diagram._tick_text(value, x_step), self.fs["tick"])[0] / 2 + 2
                    for value in diagram._ticks_at(p.data_box[0], p.data_box[1], x_step)), default=0.0)

    def row_width(self, row: list[_Panel]) -> float:
        return self.rights[row[-1].letter] + sum(self.gutters[p.letter] + p.width for p in row) + self.gap * (len(row) - 1)

    def title_band(self, row: list[_Panel]) -> float:
        return max(len(p.title_lines) for p in row) * self.title_line + self.title_pad

    def top(self, suptitle: str) -> float:
        return approximate_size(suptitle, self.fs["suptitle"])[1] + 14

    def legend_height(self, rows: int) -> float:
        return rows * self.fs["legend"] * 1.75 + 6

    def one_line(self, title: str) -> float:
        """The width a panel needs for its title on one line."""
        return approximate_size(title, self.fs["title"])[0] + 6

    def _fits(self, text: str, width: float) -> bool:
        return self.one_line(text) <= width

    def wrap(self, title: str, width: float) -> list[str]:
        """A panel's title in lines no wider than `width`: one line, else broken after its colon, then word by word."""
        if self._fits(title, width):
            return [title]
        head, colon, tail = title.partition(": ")
        if colon and self._fits(head + ":", width):  # the frame on one line, the rod's velocity after it
            return [head + ":"] + self.wrap(tail, width)
        lines: list[str] = []
        for word in title.split(" "):
            if lines and self._fits(f"{lines[-1]} {word}", width):
                lines[-1] += f" {word}"
            else:
                lines.append(word)
        return lines

    def narrowest_title(self, title: str) -> float:
        """The least width in which the title wraps onto at most TITLE_LINES lines."""
        lo = max(approximate_size(word, self.fs["title"])[0] for word in title.split(" ")) + 6
        hi = approximate_size(title, self.fs["title"])[0] + 6
        if len(self.wrap(title, lo)) <= TITLE_LINES:
            return lo
        for _ in range(30):
            mid = 0.5 * (lo + hi)
            lo, hi = (lo, mid) if len(self.wrap(title, mid)) <= TITLE_LINES else (mid, hi)
        return hi


# --- the diagram ---------------------------------------------------------------------------------

class _Panel:
    """One frame's panel while the figure is laid out."""

    def __init__(self, letter: str, view_: FrameView, worldlines: dict[str, np.ndarray], box: list[float], title: str):
        self.letter, self.view, self.worldlines, self.title = letter, view_, worldlines, title
        self.data_box = tuple(box)  # x0, x1, t0, t1: the world-lines with their margin, units of L
        self.box = list(box)  # the axes limits: the data box, widened where the title needs room
        self.width = self.height = 0.0  # points
        self.title_lines: list[str] = [title]


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
        self.clock_step = rod.clock_step(max(p.view.t_range[1] - p.view.t_range[0] for p in self.panels))
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
    def _build(self) -> Figure:
        """Lay the figure out in points: suptitle; rows of panels, each with its title, axes and tick labels; legend.

        The panels share one height (equal scales within a panel; one size for
        all), and fill rows no wider than the style's page. Of the arrangements
        into rows that fit the page's width and height, the one with the most
        panels to a row is taken whose panels are at least ROW_PREFERENCE of the
        tallest any arrangement allows: two panels side by side, eight in three
        rows. Tick steps are then widened until no two tick labels touch, and
        the layout redone with them.
        """
        st, fs = self.style, self.fs
        m = _Metrics(st, fs)
        steps = [(self._tick_step(p.data_box),) * 2 for p in self.panels]  # (x step, t step) of each panel
        for _ in range(6):  # steps only grow, and each growth is a nice step: this settles in two or three rounds
            rows, height, width, (legend_rows, legend_cols) = self._arrange(m, steps)
            readable = [self._readable_steps(p, step, m) for p, step in zip(self.panels, steps)]
            if readable == steps:
                break
            steps = readable

        handles, labels = self._legend_entries()
        legend_h = m.legend_height(legend_rows)
        suptitle = self._suptitle(width)
        top = m.top(suptitle)
        blocks = [m.title_band(row) + height + m.bottom_axis for row in rows]
        fig_h = top + sum(blocks) + m.row_gap * (len(rows) - 1) + legend_h

        figure = Figure(figsize=(width / 72, fig_h / 72), dpi=72)
        y = fig_h - top
        for row, block in zip(rows, blocks):
            y -= block
            x = (width - m.row_width(row)) / 2
            for p in row:
                step = steps[self.panels.index(p)]
                x += m.gutter(p, step, self)
                ax = figure.add_axes((x / width, (y + m.bottom_axis) / fig_h, p.width / width, p.height / fig_h))
                x += p.width + m.gap
                ax.set_gid(f"{p.letter}-axes")
                self._axes(ax, p, step, m.tick_len, m.tick_pad, m.label_pad)
            y -= m.row_gap
        figure.text(0.5, 1 - 7 / fig_h, suptitle, ha="center", va="top", fontsize=fs["suptitle"], gid="title")
        legend = figure.legend(handles, labels, loc="upper center", bbox_to_anchor=(0.5, (legend_h - 2) / fig_h),
                               ncol=legend_cols, fontsize=fs["legend"], handlelength=3.2, handletextpad=0.6,
                               columnspacing=1.6, borderaxespad=0.0, borderpad=0.0, labelspacing=0.5,
                               handler_map={tuple: HandlerTuple(ndivide=1)})  # the rod: strip and line in one
        legend.set_gid("legend")
        return figure

    def _arrange(self, m: "_Metrics", steps: list) -> tuple[list[list[_Panel]], float, float, tuple[int, int]]:
        """(rows of panels, the panels' height, the figure's width, the legend's rows and columns).

        Every panel's width, box and title lines are set.
        """
        st = self.style
        page_w, page_h = st.max_width * 72, st.max_height * 72
        panels = self.panels
        gutters = {p.letter: m.gutter(p, step, self) for p, step in zip(panels, steps)}
        # right of a row's last panel: its last x tick label's overhang, and a margin
        rights = {p.letter: max(m.right, m.overhang(p, step[0], self)) for p, step in zip(panels, steps)}
        aspects = {p.letter: (p.data_box[1] - p.data_box[0]) / (p.data_box[3] - p.data_box[2]) for p in panels}
        narrowest = {p.letter: m.narrowest_title(p.title) for p in panels}

        def widths(row: list[_Panel], h: float) -> list[float]:
            return [max(h * aspects[p.letter], narrowest[p.letter]) for p in row]

        def row_width(row: list[_Panel], h: float) -> float:
            return rights[row[-1].letter] + sum(gutters[p.letter] for p in row) + m.gap * (len(row) - 1) + sum(widths(row, h))

        labels = self._legend_entries()[1]
        cap = st.panel_height * 72
        shapes: dict = {}  # legend shapes by arrangement, each sought once

        def legend(rows: list[list[_Panel]], wide: bool) -> tuple[int, int, float]:
            """The legend's (rows, columns, width) for an arrangement: as wide as the page, or as its rows at the
            tallest panels. Fixed before the panels' height is sought, so a lower panel never makes a taller legend."""
            key = (tuple(len(row) for row in rows), wide)  # panels to each row: the arrangement
            if key not in shapes:
                shapes[key] = self._legend_shape(labels, page_w if wide else min(page_w, max(row_width(row, cap) for row in rows)))
            return shapes[key]

        def figure_width(rows: list[list[_Panel]], wide: bool, h: float) -> float:
            return min(page_w, max(legend(rows, wide)[2], *(row_width(row, h) for row in rows)))

        def figure_height(rows: list[list[_Panel]], wide: bool, h: float) -> float:
            width = figure_width(rows, wide, h)
            bands = sum(max(len(m.wrap(p.title, w)) for p, w in zip(row, widths(row, h))) for row in rows)
            return (m.top(self._suptitle(width)) + bands * m.title_line + len(rows) * (m.title_pad + h + m.bottom_axis)
                    + m.row_gap * (len(rows) - 1) + m.legend_height(legend(rows, wide)[0]))

        def tallest(rows: list[list[_Panel]], wide: bool, page_h: float) -> float:
            """The tallest panels (points) with which every row fits the page's width and the figure its height; 0 if none."""
            fits = lambda h: all(row_width(row, h) <= page_w for row in rows) and figure_height(rows, wide, h) <= page_h
            if fits(cap):
                return cap
            if not fits(m.least_panel):
                return 0.0
            lo, hi = m.least_panel, cap
            for _ in range(24):  # bisection to a small fraction of a point
                mid = 0.5 * (lo + hi)
                lo, hi = (mid, hi) if fits(mid) else (lo, mid)
            return lo

        n = len(panels)
        # most panels to a row first; for each, a legend as wide as the panels, then one as wide as the page
        arrangements = [([panels[k:k + columns] for k in range(0, n, columns)], wide)
                        for columns in range(n, 0, -1) for wide in (False, True)]
        options = [(rows, wide, tallest(rows, wide, page_h)) for rows, wide in arrangements]
        best = max(h for *_, h in options)
        if best > 0.0:
            enough = max(ROW_PREFERENCE * best, min(best, READABLE_PANEL * self.fs["tick"]))
            rows, wide, height = next(option for option in options if option[2] >= enough)
            # the same rows with the narrower legend, if that loses nothing
            rows, wide, height = max((o for o in options if o[0] == rows), key=lambda o: (o[2], not o[1]))
        else:  # too many panels for the page's height at this type size (slides): the least tall figure of the page's width
            options = [(rows, wide, tallest(rows, wide, math.inf)) for rows, wide in arrangements]
            options = [o for o in options if o[2] > 0.0] or [(arrangements[-1][0], True, m.least_panel)]
            rows, wide, height = min(options, key=lambda option: figure_height(*option))
        width = figure_width(rows, wide, height)
        for row in rows:
            spare = width - row_width(row, height)  # room the figure has anyway (a wide legend): titles may use it
            row_widths = []
            for p, w in zip(row, widths(row, height)):
                grow = min(max(0.0, m.one_line(p.title) - w), spare)
                row_widths.append(w + grow)
                spare -= grow
            for p, w in zip(row, row_widths):
                p.height, p.width = height, w
                p.box = list(p.data_box)
                extra = (w / height - aspects[p.letter]) * (p.box[3] - p.box[2]) / 2
                if extra > 0:  # pad the box with empty space on both sides, to make room for the title
                    p.box[0] -= extra
                    p.box[1] += extra
                p.title_lines = m.wrap(p.title, w)
        m.gutters, m.rights = gutters, rights
        return rows, height, width, legend(rows, wide)[:2]

    def _readable_steps(self, p: _Panel, steps: tuple[float, float], m: "_Metrics") -> tuple[float, float]:
        """The least nice steps, from `steps` up, at which no two tick labels of the panel touch: (x step, t step).

        The t labels stand one above the other, so their height sets the t step;
        the x labels stand side by side, so their width sets the x step, which
        may be larger (long labels such as \N{MINUS SIGN}40000). Each axis keeps at least two ticks.
        """
        scale = p.height / (p.box[3] - p.box[2])  # points per unit of L, both axes

        def grown(step: float, lo: float, hi: float, room) -> float:
            while step * scale < room(step) and len(self._ticks_at(lo, hi, _next_step(step))) >= 2:
                step = _next_step(step)
            return step

        x_step, t_step = steps
        t_step = grown(t_step, p.box[2], p.box[3], lambda step: m.tick_h + m.tick_gap / 2)
        x_step = grown(max(x_step, t_step), p.box[0], p.box[1], lambda step: m.tick_gap + max(
            (approximate_size(self._tick_text(x, step), self.fs["tick"])[0] for x in self._ticks_at(p.box[0], p.box[1], step)),
            default=0.0))
        return x_step, t_step

    @staticmethod
    def _tick_step(box: list[float]) -> float:
        """One tick step for both axes (equal scales): about five ticks on the shorter side, at most ten on the longer."""
        sides = sorted((box[1] - box[0], box[3] - box[2]))
        raw = max(sides[1] / 10.0, sides[0] / 5.0)
        magnitude = 10.0 ** math.floor(math.log10(raw))
        return next(m * magnitude for m in (1, 2, 2.5, 5, 10) if m * magnitude >= raw * (1 - 1e-9))

    @staticmethod
    def _ticks_at(lo: float, hi: float, step: float) -> np.ndarray:
        k = np.arange(math.ceil(lo / step - 1e-9), math.floor(hi / step + 1e-9) + 1)
        return k * step

    @staticmethod
    def _tick_text(value: float, step: float) -> str:
        """A tick label with as many decimals as the step has (0.25 -> 2), a real minus sign, no -0; 2×10⁶ for steps of 10⁵ on."""
        if step >= SCIENTIFIC_ABOVE / 10:
            return shown(value, 3)
        decimals = next(d for d in range(12) if abs(round(step, d) - step) <= 1e-9 * step)
        text = f"{value:.{decimals}f}"
        if float(text) == 0:
            text = "0" if decimals == 0 else f"{0:.{decimals}f}"
        return text.replace("-", MINUS)

    def _suptitle(self, width: float) -> str:
        """The scenario's name and v, with its description's first clause if that fits; a long name is cut with an ellipsis."""
        s = self.history.scenario
        room = width - 10

        def fits(text: str) -> bool:
            return approximate_size(text, self.fs["suptitle"])[0] <= room

        tail = f", $v = {shown(s.v, math_text=True)}$"
        head = f"{_mathtext_safe(s.name)}{tail}"
        if not fits(head):  # the longest start of the name that fits, then an ellipsis: visibly cut, never off the page
            lo, hi = 0, len(s.name)
            while lo < hi:
                mid = (lo + hi + 1) // 2
                lo, hi = (mid, hi) if fits(f"{_mathtext_safe(s.name[:mid].rstrip())}\N{HORIZONTAL ELLIPSIS}{tail}") else (lo, mid - 1)
            return f"{_mathtext_safe(s.name[:lo].rstrip())}\N{HORIZONTAL ELLIPSIS}{tail}"
        # the description's first clause: up to a semicolon or the end of its first sentence
        clause = re.split(r";|\.(?=\s+[A-Z]|\s*$)", " ".join(s.description.split()))[0].strip()
        if clause:
            clause = re.sub(r"\b([SxXtT])'", "\\1\N{PRIME}", clause)  # S' as in the panels: S′
            full = f"{head}: {_mathtext_safe(clause)}"
            if fits(full):
                return full
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
        entries.append((self._line_handle(st.rest_simultaneity), "line of simultaneity of S"))
        entries.append((self._line_handle(st.moving_simultaneity), "line of simultaneity of S\N{PRIME}"))
        if o.other_axes:
            entries.append((self._line_handle(st.other_axes), "axes of the other frame"))
        if o.light_cones:
            entries.append((self._line_handle(st.light_cone), "light cone of an impact"))
        if o.rod_lines:
            entries.append((self._line_handle(st.rod_interior), "material points inside the rod"))
        if o.rod_now:
            entries.append((self._line_handle(st.rod_now), "the rod's own lines of simultaneity"))
        if o.proper_time:
            entries.append((Line2D([], [], linestyle="none", marker="o", markersize=st.clock_size,
                                   markerfacecolor="white", markeredgecolor=st.rod.colour, markeredgewidth=0.8),
                            f"proper time: a tick every {shown(self.clock_step / self.L, 4)} L"))
        if o.hyperbolae:
            entries.append((self._line_handle(st.hyperbola), "calibration hyperbolae t\N{SUPERSCRIPT TWO} \N{MINUS SIGN} x\N{SUPERSCRIPT TWO} = \N{PLUS-MINUS SIGN}k\N{SUPERSCRIPT TWO}"))
        return [h for h, _ in entries], [label for _, label in entries]

    def _legend_entry_widths(self, labels: list[str]) -> np.ndarray:
        fs = self.fs["legend"]
        # handle 3.2 em, gap 0.6 em, and 8 % for the renderers' own text widths (hinting)
        return np.array([approximate_size(label, fs)[0] * 1.08 + (3.2 + 0.6) * fs for label in labels])

    def _legend_shape(self, labels: list[str], width: float) -> tuple[int, int, float]:
        """(rows, columns, width needed) of the widest legend that fits; columns filled as matplotlib does (array_split)."""
        entry = self._legend_entry_widths(labels)
        for cols in range(len(labels), 0, -1):
            columns = [c for c in np.array_split(entry, cols) if len(c)]
            needed = sum(c.max() for c in columns) + 1.6 * self.fs["legend"] * (len(columns) - 1) + 16
            if needed <= width or cols == 1:
                return math.ceil(len(labels) / cols), cols, needed

    # one panel -------------------------------------------------------------------------------------
    def _axes(self, ax, p: _Panel, steps: tuple[float, float], tick_len: float, tick_pad: float, label_pad: float) -> None:
        st, fs, o = self.style, self.fs, self.options
        x0, x1, t0, t1 = p.box
        x_step, step = steps  # the t step is the finer: the grid of the hyperbolae
        xt, tt = self._ticks_at(x0, x1, x_step), self._ticks_at(t0, t1, step)
        xname, tname = coordinate_names(p.view.frame)
        ax.set_xlim(x0, x1)
        ax.set_ylim(t0, t1)
        ax.set_aspect("equal", adjustable="box")
        ax.xaxis.set_major_locator(FixedLocator(xt))
        ax.yaxis.set_major_locator(FixedLocator(tt))
        ax.xaxis.set_major_formatter(FuncFormatter(lambda value, _pos: self._tick_text(value, x_step)))
        ax.yaxis.set_major_formatter(FuncFormatter(lambda value, _pos: self._tick_text(value, step)))
        ax.tick_params(labelsize=fs["tick"], length=tick_len, pad=tick_pad)
        italic = "normal" if "$" in xname else "italic"
        ax.set_xlabel(axis_label(xname), fontsize=fs["label"], fontstyle=italic, labelpad=label_pad)
        ax.set_ylabel(axis_label(tname), fontsize=fs["label"], fontstyle=italic, labelpad=label_pad)
        ax.set_title("\n".join(p.title_lines), fontsize=fs["title"], y=1.0)  # y given: no search for tick labels above the axes
        if o.grid:
            ax.grid(True, color=st.grid.colour, linewidth=st.grid.width, linestyle=st.grid.dashes, zorder=0)
            ax.set_axisbelow(True)

        obstacles: list[np.ndarray] = []  # polylines in data units that labels must not cross
        guides: list[np.ndarray] = []  # the extras' lines: a label may cross them, on a white ground
        letter = p.letter
        frame = p.view.frame

        # the rod's world-sheet, then its ends
        left, right = p.worldlines["rod_left"], p.worldlines["rod_right"]
        # add_artist, not fill: the limits are fixed, and fill would walk every vertex to update them
        ax.add_artist(Polygon(np.concatenate([left, right[::-1]]), closed=True, facecolor=st.sheet, edgecolor="none",
                              zorder=1, gid=f"{letter}-sheet"))
        guides += self._interior(ax, p)
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
                    guides.append(segment)
                    end = segment[1]
                    inward = math.degrees(math.atan2((t0 + t1) / 2 - end[1], (x0 + x1) / 2 - end[0]))
                    labels.append(_Label(f"{letter}-axis-label-{other}-{axis}", name,
                                         ((end[0], end[1]),), inward, st.other_axes.colour, fs["impact"], italic=True,
                                         guides_block=True))
        if o.light_cones:
            reach = CONE_REACH * min(x1 - x0, t1 - t0)  # short arms: a cone per impact, not a lattice of lines
            for label, _, x, t in events:
                for side, slope in (("right", 1.0), ("left", -1.0)):
                    segment = _clip_line(x, t, 1.0, slope, (x - reach, x + reach, t - reach, t + reach))
                    segment = None if segment is None else _clip_line(x, t, 1.0, slope, p.box)
                    if segment is not None:
                        segment = np.clip(segment, [[x - reach, t - reach]], [[x + reach, t + reach]])
                        ax.plot(segment[:, 0], segment[:, 1], color=st.light_cone.colour,
                                linewidth=st.light_cone.width, linestyle=st.light_cone.dashes, zorder=1.5,
                                gid=f"{letter}-light-cone-{label}-{side}")
                        guides.append(segment)
        if o.hyperbolae:
            for k, points in enumerate(self._hyperbolae(p.box, step)):
                ax.plot(points[:, 0], points[:, 1], color=st.hyperbola.colour, linewidth=st.hyperbola.width,
                        linestyle=st.hyperbola.dashes, zorder=1.2, gid=f"{letter}-hyperbola-{k}")
                guides.append(points)

        # impacts: markers on top, labelled the same in every panel
        for label, end, x, t in events:
            ax.plot([x], [t], linestyle="none", marker="o", markersize=st.impact_size,
                    markerfacecolor=st.impact_colour, markeredgecolor="white", markeredgewidth=0.6,
                    zorder=7, gid=f"{letter}-impact-{label}")
            labels.insert(len([l for l in labels if "-impact-label-" in l.gid]),
                          _Label(f"{letter}-impact-label-{label}", impact_text(label), ((x, t),),
                                 0.0 if end == "right" else 180.0, st.impact_colour, fs["impact"],
                                 avoid_radius=st.impact_size / 2 + 1.0,
                                 box_size=impact_text_size(label, fs["impact"])[:2]))
        # particles: their letter beside the first part of the world-line, else further along where there is room
        for name in ("A", "B"):
            if name in p.worldlines:
                points = p.worldlines[name]
                first = next((e.t / self.L for e in p.view.events if e.impact.particle == name), points[-1, 1])
                span = points[-1, 1] - points[0, 1]
                times = [points[0, 1] + min(0.1 * (p.box[3] - p.box[2]), 0.6 * (first - points[0, 1]))]
                times += [points[0, 1] + f * span for f in (0.35, 0.65, 0.9)]
                anchors = tuple((float(np.interp(t, points[:, 1], points[:, 0])), t) for t in times)
                labels.append(_Label(f"{letter}-particle-label-{name}", name, anchors,
                                     180.0 if name == "A" else 0.0, st.particles[name].colour, fs["particle"],
                                     italic=True))
        self._place(ax, p, labels, obstacles, guides)

    def _interior(self, ax, p: _Panel) -> list[np.ndarray]:
        """The inside of the rod (README, "Inside the rod"): material world-lines, the rod's own lines of
        simultaneity, and clock ticks of proper time on every world-line, as the options ask. Returns the lines
        drawn, which labels may cross."""
        st, o, L = self.style, self.options, self.L
        letter, eta = p.letter, p.view.frame.rapidity
        t_lo, t_hi = p.view.t_range
        drawn: list[np.ndarray] = []
        if o.rod_lines:
            tolerance = sampling_tolerance(self.history)
            for k, (sigma, points) in enumerate(rod.material_lines(self.history, eta, o.rod_lines, t_lo, t_hi,
                                                                    tolerance), start=1):
                points = points / L
                ax.plot(points[:, 0], points[:, 1], color=st.rod_interior.colour, linewidth=st.rod_interior.width,
                        linestyle=st.rod_interior.dashes, zorder=3, gid=f"{letter}-rod-line-{k}")
                drawn.append(points)
        if o.rod_now:
            lines = [(a.boosted(eta), b.boosted(eta)) for a, b in rod.now_lines(self.history)]
            for k, (a, b) in enumerate((a, b) for a, b in lines if min(a.t, b.t) >= t_lo and max(a.t, b.t) <= t_hi):
                segment = np.array([[a.x, a.t], [b.x, b.t]]) / L
                ax.plot(segment[:, 0], segment[:, 1], color=st.rod_now.colour, linewidth=st.rod_now.width,
                        linestyle=st.rod_now.dashes, zorder=3.5, gid=f"{letter}-rod-now-{k}")
                drawn.append(segment)
        if o.proper_time:
            # the same events in every panel: counted in S (tau = 0 at t = 0 there), then boosted
            x0, x1, t0, t1 = (value * L for value in p.box)
            corners = [Event(x, t).boosted(-eta).t for x in (x0, x1) for t in (t0, t1)]
            for name, worldline in self.history.worldlines:
                ink = st.rod if name.startswith("rod_") else st.particles[name]
                marks = [e.boosted(eta) for _, e in kinematics.proper_time_events(
                    worldline, self.clock_step, min(corners), max(corners))]
                # within the frame's time window, where the world-lines are drawn
                marks = np.array([[e.x, e.t] for e in marks if t_lo <= e.t <= t_hi and x0 <= e.x <= x1]).reshape(-1, 2) / L
                ax.plot(marks[:, 0], marks[:, 1], linestyle="none", marker="o", markersize=st.clock_size,
                        markerfacecolor="white", markeredgecolor=ink.colour, markeredgewidth=0.8, zorder=6,
                        gid=f"{letter}-clock-{name}")
        return drawn

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
    def _place(self, ax, p: _Panel, labels: list[_Label], obstacles: list[np.ndarray], guides: list[np.ndarray]) -> None:
        """Put each label near its anchor where its box crosses no line, marker or earlier label.

        Candidates ring the anchor (24 directions, growing distances). The first
        free one wins: nearest ring first, then nearest the preferred direction.
        Crossing a guide (an extra's line) costs as much as three rings outwards,
        and such a label gets a white ground; crossing anything else is a last resort.
        """
        x0, x1, t0, t1 = p.box
        sx, st_ = p.width / (x1 - x0), p.height / (t1 - t0)  # points per unit of L (equal, up to rounding)

        def to_pt(points: np.ndarray) -> np.ndarray:
            return np.column_stack([(points[:, 0] - x0) * sx, (points[:, 1] - t0) * st_])

        def segments_of(polylines: list[np.ndarray]) -> np.ndarray:
            parts = [np.column_stack([q[:-1], q[1:]]) for q in map(to_pt, polylines) if len(q) > 1]
            return np.concatenate(parts) if parts else np.empty((0, 4))

        def crossings(boxes: np.ndarray, segments: np.ndarray) -> np.ndarray:
            lo, hi = boxes[:, :2].min(0), boxes[:, 2:].max(0)  # only nearby segments can be hit
            near = ((np.maximum(segments[:, 0], segments[:, 2]) >= lo[0]) & (np.minimum(segments[:, 0], segments[:, 2]) <= hi[0])
                    & (np.maximum(segments[:, 1], segments[:, 3]) >= lo[1]) & (np.minimum(segments[:, 1], segments[:, 3]) <= hi[1]))
            return _boxes_hit_segments(boxes, segments[near])

        hard, soft = segments_of(obstacles), segments_of(guides)
        taken = [self._marker_box(to_pt(np.array(l.anchors[:1]))[0], l.avoid_radius) for l in labels if l.avoid_radius]
        pad, edge = 2.0 + self._widest_line / 2, 2.0  # clear of every line's stroke, and of the frame
        radii = np.array([2.0, 4.0, 7.0, 11.0, 16.0, 22.0, 29.0, 37.0, 46.0])
        angles = np.arange(0.0, 360.0, 15.0)
        never = 10 ** 9
        for label in labels:
            w, h = label.box_size or text_size(label.text, label.size, label.italic)[:2]
            anchors = to_pt(np.array(label.anchors))
            turn = np.abs((angles - label.preferred + 180) % 360 - 180)
            order = angles[np.lexsort((angles, turn))]
            # candidates ordered by ring, then anchor, then direction: that order breaks ties in cost
            ring = np.repeat(np.arange(len(radii)), len(anchors) * len(order))
            which = np.tile(np.repeat(np.arange(len(anchors)), len(order)), len(radii))
            a = np.radians(np.tile(order, len(radii) * len(anchors)))
            r = radii[ring] + label.avoid_radius
            c, s_ = np.cos(a), np.sin(a)
            px, py = anchors[which, 0] + r * c, anchors[which, 1] + r * s_
            ha = np.where(c > 0.3, 0, np.where(c < -0.3, 2, 1))  # left, center, right
            va = np.where(s_ > 0.3, 0, np.where(s_ < -0.3, 2, 1))  # bottom, center, top
            bx, by = px - ha * w / 2, py - va * h / 2
            boxes = np.column_stack([bx - pad, by - pad, bx + w + pad, by + h + pad])
            inside = ((boxes[:, 0] >= edge) & (boxes[:, 1] >= edge) & (boxes[:, 2] <= p.width - edge)
                      & (boxes[:, 3] <= p.height - edge))
            cost = np.full(len(boxes), never)
            crossed_guides = np.zeros(len(boxes), dtype=int)
            for first, last in ((0, 3), (3, 6), (6, len(radii))):  # nearest rings first; stop once one is free
                chunk = np.flatnonzero(inside & (ring >= first) & (ring < last))
                if len(chunk) == 0:
                    continue
                b = boxes[chunk]
                blocked = crossings(b, hard)
                if taken:
                    other = np.array(taken)
                    blocked += ((b[:, None, 0] < other[None, :, 2]) & (other[None, :, 0] < b[:, None, 2])
                                & (b[:, None, 1] < other[None, :, 3]) & (other[None, :, 1] < b[:, None, 3])).sum(1)
                crossed_guides[chunk] = crossings(b, soft)
                if label.guides_block:
                    blocked, crossed_guides[chunk] = blocked + crossed_guides[chunk], 0
                cost[chunk] = 1000 * blocked + 3 * crossed_guides[chunk] + ring[chunk] + which[chunk]
                if (blocked + crossed_guides[chunk] == 0).any():
                    break
            k = int(np.lexsort((np.arange(len(boxes)), cost))[0])  # cheapest; among equals, the earliest candidate
            if cost[k] == never:  # no room inside the panel at all: centre it on the first anchor
                anchor = anchors[0]
                box = (anchor[0] - w / 2, anchor[1] - h / 2, anchor[0] + w / 2, anchor[1] + h / 2)
                position, alignment, ground = anchor, ("center", "center"), True
            else:
                box = tuple(boxes[k])
                position = (px[k], py[k])
                alignment = (("left", "center", "right")[ha[k]], ("bottom", "center", "top")[va[k]])
                ground = crossed_guides[k] > 0 or cost[k] >= 1000
            taken.append(box)
            ax.text(x0 + position[0] / sx, t0 + position[1] / st_, label.text, ha=alignment[0], va=alignment[1],
                    fontsize=label.size, fontstyle="italic" if label.italic else "normal", color=label.colour,
                    zorder=8, gid=label.gid,
                    bbox=dict(boxstyle="square,pad=0.1", facecolor="white", edgecolor="none") if ground else None)
            if label.avoid_radius and cost[k] != never:
                leader = self._leader(anchors[0], (bx[k], by[k], bx[k] + w, by[k] + h), label.avoid_radius - 1.0)
                if leader is not None:  # a label that could not sit close is tied to its marker
                    ax.plot(x0 + leader[:, 0] / sx, t0 + leader[:, 1] / st_, color=label.colour,
                            linewidth=0.6 * label.size / self.fs["impact"] * self.style.font_size / 9.0,
                            linestyle="solid", zorder=6.5, gid=label.gid.replace("-label-", "-leader-"))
                    hard = np.concatenate([hard, leader.reshape(1, 4)])

    @staticmethod
    def _leader(centre: np.ndarray, text_box: tuple[float, float, float, float], radius: float) -> np.ndarray | None:
        """A leader (points, 2 x 2) from the marker's edge to the nearest point of the label's box, if farther than LABEL_REACH."""
        nearest = np.array([min(max(centre[0], text_box[0]), text_box[2]), min(max(centre[1], text_box[1]), text_box[3])])
        distance = float(np.hypot(*(nearest - centre)))
        if distance - radius <= LABEL_REACH:
            return None
        start = centre + (nearest - centre) * (radius / distance)
        return np.array([start, nearest])

    @staticmethod
    def _marker_box(centre, radius: float):
        return (centre[0] - radius, centre[1] - radius, centre[0] + radius, centre[1] + radius)
