"""The layout in points: each panel's data box, the arrangement of panels into rows, tick steps, title lines and the
legend's shape. Computed from text metrics rather than by matplotlib's layout engines: it needs no renderer, so it
is fast and byte-for-byte reproducible."""

from __future__ import annotations

import math
from typing import NamedTuple, Sequence

import numpy as np

from rodparadox.physics.history import RodHistory
from rodparadox.physics.frames import Frame, FrameView, sampling_tolerance, view
from rodparadox.numbers import nice_number
from rodparadox.render.styles import Style
from rodparadox.render.text import approximate_size, note_lines, panel_title, suptitle, tick_text, ticks_at

#: smallest and largest width/height of a panel's data box; a box outside is padded with empty space
ASPECT_RANGE = (0.62, 1.6)
#: empty margin around the world-lines, as a fraction of the larger side of the data box
MARGIN = 0.09
#: of the arrangements of panels into rows, the one with the most to a row whose panels are at least this
#: fraction of the tallest any arrangement allows, and at least READABLE_PANEL tick labels tall
ROW_PREFERENCE = 0.55
READABLE_PANEL = 12.0
#: a panel's title wraps onto at most this many lines
TITLE_LINES = 3


def font_sizes(style: Style) -> dict[str, float]:
    """The type sizes, in points, of a style's texts, from its base size."""
    fs = style.font_size
    return {"tick": fs, "label": fs * 1.1, "title": fs * 1.1, "suptitle": fs * 1.25, "legend": fs,
            "impact": fs * 1.1, "particle": fs * 1.25}


class Panel:
    """One frame's panel while the figure is laid out."""

    def __init__(self, letter: str, view_: FrameView, worldlines: dict[str, np.ndarray], box: list[float], title: str):
        self.letter, self.view, self.worldlines, self.title = letter, view_, worldlines, title
        self.data_box = tuple(box)  # x0, x1, t0, t1: the world-lines with their margin, units of L
        self.box = list(box)  # the axes limits: the data box, widened where the title needs room
        self.width = self.height = 0.0  # points
        self.title_lines: list[str] = [title]
        self.history = None  # the run this panel draws (`panel_of`): two rod models draw in one figure (--rod both)
        self.ringing: float | None = None  # the velocity its title says the rod rings about, if it does
        self.inset_room = False  # its box widened for the inset of a driven rod's small motion (`legibility.inset_room`)
        self.motion_inset = False  # it draws that inset, whose dashed lines the legend names


def panel_of(history: RodHistory, letter: str, frame: Frame, window: tuple[float, float] | None = None) -> Panel:
    """A frame's panel: its world-lines in units of L and its data box, before the layout sizes it (over the
    frame's times `window`, else the history's own `frames.time_window`)."""
    L = history.scenario.L
    fv = view(history, frame, window)
    tolerance = sampling_tolerance(history)
    worldlines = {name: points / L for name, points in fv.worldline_points(tolerance).items()}
    everything = np.concatenate(list(worldlines.values()))
    x0, x1 = float(everything[:, 0].min()), float(everything[:, 0].max())
    t0, t1 = fv.t_range[0] / L, fv.t_range[1] / L
    margin = MARGIN * max(x1 - x0, t1 - t0)
    box = [x0 - margin, x1 + margin, t0 - margin, t1 + margin]
    fit_aspect(box, *ASPECT_RANGE)
    ringing = math.tanh(history.final_rapidity - frame.rapidity) if history.fronts is not None else None
    # a rod driven by forces has no impacts to read its last velocity from: its history's final rapidity
    after = math.tanh(history.final_rapidity - frame.rapidity) if history.driving is not None else None
    panel = Panel(letter, fv, worldlines, box, panel_title(letter, fv, ringing, after))
    panel.history = history
    panel.ringing = ringing
    return panel


def one_scale(panels: list[Panel]) -> None:
    """Options.equal_scales: pad every panel's data box (both sides equally) to the widest width and the tallest
    height among them, so that panels of one height draw one length of L as one length on the page."""
    width = max(p.data_box[1] - p.data_box[0] for p in panels)
    height = max(p.data_box[3] - p.data_box[2] for p in panels)
    for p in panels:
        x0, x1, t0, t1 = p.data_box
        dx, dt = (width - (x1 - x0)) / 2, (height - (t1 - t0)) / 2
        p.data_box = (x0 - dx, x1 + dx, t0 - dt, t1 + dt)
        p.box = list(p.data_box)


def fit_aspect(box: list[float], low: float, high: float) -> None:
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


# --- tick steps -----------------------------------------------------------------------------------------

def tick_step(box: Sequence[float]) -> float:
    """One nice tick step for both axes (equal scales): about five ticks on the shorter side, at most ten on the
    longer."""
    sides = sorted((box[1] - box[0], box[3] - box[2]))
    return nice_number(max(sides[1] / 10.0, sides[0] / 5.0), "at_least")


class Metrics:
    """The sizes, in points, of everything around the panels in a style: bands for titles, ticks, labels, legend."""

    def __init__(self, style: Style, fs: dict[str, float]):
        self.fs = fs
        self.tick_len = style.tick_length
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
        self._one_line: dict[str, float] = {}  # titles and their pieces measured, as wrapping tries many widths

    def gutter(self, p: Panel, steps: tuple[float, float]) -> float:
        """Room left of a panel for its t tick labels and t axis label, and for half its first x tick label."""
        x_step, t_step = steps
        widest = max((approximate_size(tick_text(value, t_step), self.fs["tick"])[0]
                      for value in ticks_at(p.data_box[2], p.data_box[3], t_step)), default=0.0)
        return max(widest + self.tick_len + self.tick_pad + self.label_pad + self.label_h + 4,
                   self.overhang(p, x_step))

    def overhang(self, p: Panel, x_step: float) -> float:
        """How far an x tick label at the panel's edge can reach beyond it: half the widest, and a little."""
        return max((approximate_size(tick_text(value, x_step), self.fs["tick"])[0] / 2 + 2
                    for value in ticks_at(p.data_box[0], p.data_box[1], x_step)), default=0.0)

    def row_width(self, row: list[Panel]) -> float:
        return self.rights[row[-1].letter] + sum(self.gutters[p.letter] + p.width for p in row) + self.gap * (len(row) - 1)

    def title_band(self, row: list[Panel]) -> float:
        return max(len(p.title_lines) for p in row) * self.title_line + self.title_pad

    def top(self, suptitle: str) -> float:
        return approximate_size(suptitle, self.fs["suptitle"])[1] + 14

    def legend_height(self, rows: int) -> float:
        return rows * self.fs["legend"] * 1.75 + 6

    def note_lines(self, note: str, width: float) -> list[str]:
        """A note below the legend (what a comparison of rods states first) in lines no wider than `width` less
        the margins, at the legend's type size."""
        return note_lines(note, width - 2 * self.right, self.fs["legend"])

    def note_height(self, lines: list[str]) -> float:
        return len(lines) * 1.2 * self.fs["legend"] + 10 if lines else 0.0

    def one_line(self, title: str) -> float:
        """The width a panel needs for its title on one line."""
        if title not in self._one_line:
            self._one_line[title] = approximate_size(title, self.fs["title"])[0] + 6
        return self._one_line[title]

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


def readable_steps(p: Panel, steps: tuple[float, float], m: Metrics) -> tuple[float, float]:
    """The least nice steps, from `steps` up, at which no two tick labels of the panel touch: (x step, t step).

    The t labels stand one above the other, so their height sets the t step;
    the x labels stand side by side, so their width sets the x step, which
    may be larger (long labels such as \N{MINUS SIGN}40000). Each axis keeps at least two ticks.
    """
    scale = p.height / (p.box[3] - p.box[2])  # points per unit of L, both axes

    def grown(step: float, lo: float, hi: float, room) -> float:
        while step * scale < room(step) and len(ticks_at(lo, hi, nice_number(step, "above"))) >= 2:
            step = nice_number(step, "above")
        return step

    x_step, t_step = steps
    t_step = grown(t_step, p.box[2], p.box[3], lambda step: m.tick_h + m.tick_gap / 2)
    x_step = grown(max(x_step, t_step), p.box[0], p.box[1], lambda step: m.tick_gap + max(
        (approximate_size(tick_text(x, step), m.fs["tick"])[0] for x in ticks_at(p.box[0], p.box[1], step)),
        default=0.0))
    return x_step, t_step


# --- the legend's shape ---------------------------------------------------------------------------------

def legend_entry_widths(labels: list[str], fs: float) -> np.ndarray:
    # handle 3.2 em, gap 0.6 em, and 8 % for the renderers' own text widths (hinting)
    return np.array([approximate_size(label, fs)[0] * 1.08 + (3.2 + 0.6) * fs for label in labels])


def legend_shape(labels: list[str], width: float, fs: float) -> tuple[int, int, float]:
    """(rows, columns, width needed) of the widest legend that fits; columns filled as matplotlib does (array_split)."""
    entry = legend_entry_widths(labels, fs)
    for cols in range(len(labels), 0, -1):
        columns = [c for c in np.array_split(entry, cols) if len(c)]
        needed = sum(c.max() for c in columns) + 1.6 * fs * (len(columns) - 1) + 16
        if needed <= width or cols == 1:
            return math.ceil(len(labels) / cols), cols, needed


# --- the whole figure ------------------------------------------------------------------------------------

class Page(NamedTuple):
    """The room a diagram may take, points: at most `width` x `height`, its panels at most `panel_height` tall."""

    width: float
    height: float
    panel_height: float

    @classmethod
    def of_style(cls, style: Style) -> "Page":
        """The style's page: its text width and height, and its largest panel."""
        return cls(style.max_width * 72, style.max_height * 72, style.panel_height * 72)


class Layout(NamedTuple):
    """Where everything goes, in points, on a canvas `width` x `height` (y up from its bottom)."""

    width: float
    height: float
    rows: list[list[Panel]]
    steps: dict[str, tuple[float, float]]  # each panel's (x step, t step), by letter
    suptitle: str
    top: float  # the band of the suptitle
    blocks: list[float]  # each row's height: title band, panels, axis below
    legend_height: float
    legend_columns: int
    metrics: Metrics
    note_lines: list[str]  # the note below the legend, wrapped (a comparison of rods: what every rod is struck by)
    note_height: float


def lay_out(history: RodHistory, panels: list[Panel], style: Style, fs: dict[str, float], legend_labels: list[str],
            page: Page, titled: bool = True, per_row: int | None = None, note: str = "") -> Layout:
    """Lay the figure out in points: suptitle; rows of panels, each with its title, axes and tick labels; legend.

    The panels share one height (equal scales within a panel; one size for
    all), and fill rows no wider than the page. Of the arrangements into rows
    that fit the page's width and height, the one with the most panels to a
    row is taken whose panels are at least ROW_PREFERENCE of the tallest any
    arrangement allows: two panels side by side, eight in three rows. Tick
    steps are then widened until no two tick labels touch, and the layout
    redone with them. Every panel's width, box and title lines are set. `per_row`, if given, fixes the panels
    to a row (two rod models: one row each); `note`, a paragraph below the legend.
    """
    m = Metrics(style, fs)
    steps = [(tick_step(p.data_box),) * 2 for p in panels]  # (x step, t step) of each panel
    for _ in range(6):  # steps only grow, and each growth is a nice step: this settles in two or three rounds
        rows, height, width, (legend_rows, legend_cols) = _arrange(history, panels, m, steps, fs, legend_labels, page,
                                                                    titled, per_row, note)
        readable = [readable_steps(p, step, m) for p, step in zip(panels, steps)]
        if readable == steps:
            break
        steps = readable

    legend_h = m.legend_height(legend_rows)
    title = suptitle(history.scenario, width, fs["suptitle"]) if titled else ""
    top = m.top(title) if titled else 0.0
    blocks = [m.title_band(row) + height + m.bottom_axis for row in rows]
    note_lines = m.note_lines(note, width)
    note_h = m.note_height(note_lines)
    fig_h = top + sum(blocks) + m.row_gap * (len(rows) - 1) + legend_h + note_h
    return Layout(width, fig_h, rows, {p.letter: step for p, step in zip(panels, steps)}, title, top, blocks,
                  legend_h, legend_cols, m, note_lines, note_h)


def _arrange(history: RodHistory, panels: list[Panel], m: Metrics, steps: list, fs: dict[str, float],
             labels: list[str], page: Page, titled: bool = True,
             per_row: int | None = None, note: str = "") -> tuple[list[list[Panel]], float, float, tuple[int, int]]:
    """(rows of panels, the panels' height, the figure's width, the legend's rows and columns).

    Every panel's width, box and title lines are set.
    """
    page_w, page_h = page.width, page.height
    gutters = {p.letter: m.gutter(p, step) for p, step in zip(panels, steps)}
    # right of a row's last panel: its last x tick label's overhang, and a margin
    rights = {p.letter: max(m.right, m.overhang(p, step[0])) for p, step in zip(panels, steps)}
    aspects = {p.letter: (p.data_box[1] - p.data_box[0]) / (p.data_box[3] - p.data_box[2]) for p in panels}
    narrowest = {p.letter: m.narrowest_title(p.title) for p in panels}

    def widths(row: list[Panel], h: float) -> list[float]:
        return [max(h * aspects[p.letter], narrowest[p.letter]) for p in row]

    def row_width(row: list[Panel], h: float) -> float:
        return rights[row[-1].letter] + sum(gutters[p.letter] for p in row) + m.gap * (len(row) - 1) + sum(widths(row, h))

    cap = page.panel_height
    shapes: dict = {}  # legend shapes by arrangement, each sought once

    def legend(rows: list[list[Panel]], wide: bool) -> tuple[int, int, float]:
        """The legend's (rows, columns, width) for an arrangement: as wide as the page, or as its rows at the
        tallest panels. Fixed before the panels' height is sought, so a lower panel never makes a taller legend."""
        key = (tuple(len(row) for row in rows), wide)  # panels to each row: the arrangement
        if key not in shapes:
            shapes[key] = legend_shape(labels, page_w if wide else min(page_w, max(row_width(row, cap) for row in rows)),
                                       fs["legend"])
        return shapes[key]

    def figure_width(rows: list[list[Panel]], wide: bool, h: float) -> float:
        return min(page_w, max(legend(rows, wide)[2], *(row_width(row, h) for row in rows)))

    tops: dict[float, float] = {}  # the title's band by the figure's width: the bisections meet a width many times

    def figure_height(rows: list[list[Panel]], wide: bool, h: float) -> float:
        width = figure_width(rows, wide, h)
        bands = sum(max(len(m.wrap(p.title, w)) for p, w in zip(row, widths(row, h))) for row in rows)
        if width not in tops:
            tops[width] = ((m.top(suptitle(history.scenario, width, fs["suptitle"])) if titled else 0.0)
                           + m.note_height(m.note_lines(note, width)))
        top = tops[width]
        return (top + bands * m.title_line
                + len(rows) * (m.title_pad + h + m.bottom_axis)
                + m.row_gap * (len(rows) - 1) + m.legend_height(legend(rows, wide)[0]))

    def tallest(rows: list[list[Panel]], wide: bool, page_h: float) -> float:
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
                    for columns in ((per_row,) if per_row else range(n, 0, -1)) for wide in (False, True)]
    options = [(rows, wide, tallest(rows, wide, page_h)) for rows, wide in arrangements]
    best = max(h for *_, h in options)
    if best > 0.0:
        enough = max(ROW_PREFERENCE * best, min(best, READABLE_PANEL * fs["tick"]))
        rows, wide, height = next(option for option in options if option[2] >= enough)
        # the same rows with the narrower legend, if that loses nothing
        rows, wide, height = max((o for o in options if o[0] == rows), key=lambda o: (o[2], not o[1]))
    else:  # too many panels for the page's height at this type size (slides): the least tall figure of the page's width
        options = [(rows, wide, tallest(rows, wide, math.inf)) for rows, wide in arrangements]
        options = [o for o in options if o[2] > 0.0] or [(arrangements[-1][0], True, m.least_panel)]
        rows, wide, height = min(options, key=lambda option: figure_height(*option))
    width = figure_width(rows, wide, height)
    shares = []
    for row in rows:
        spare = width - row_width(row, height)  # room the figure has anyway (a wide legend): titles may use it
        # long titles of a rod that rings ("finally at ..., ringing") share the room; other figures keep theirs
        fair = per_row is not None or any(p.ringing is not None for p in row)
        shares.append(_share(widths(row, height), [m.one_line(p.title) for p in row], spare, fair))
    if per_row is not None and len({len(row) for row in rows}) == 1:  # --rod both: a frame's panels one above the other
        columns = [max(share[k] for share in shares) for k in range(len(rows[0]))]  # keep one data box
        if all(row_width(row, height) - sum(widths(row, height)) + sum(columns) <= width + 1e-9 for row in rows):
            shares = [columns] * len(rows)
    for row, row_widths in zip(rows, shares):
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


def _share(widths: list[float], wanted: list[float], spare: float, fair: bool = True) -> list[float]:
    """The panels' widths grown towards `wanted` (their titles on one line) out of `spare` points, shared evenly
    among those still wanting (water-filling: a first panel's long title no longer takes all the room, leaving
    its neighbour's title on three lines and its labels crowded); not `fair`: first come, first served."""
    out = list(widths)
    if not fair:
        for k in range(len(out)):
            grow = min(max(0.0, wanted[k] - out[k]), spare)
            out[k] += grow
            spare -= grow
        return out
    for _ in range(len(out)):
        wanting = [k for k in range(len(out)) if wanted[k] - out[k] > 1e-9]
        if not wanting or spare <= 1e-9:
            break
        share = spare / len(wanting)
        for k in wanting:
            grow = min(wanted[k] - out[k], share)
            out[k] += grow
            spare -= grow
    return out
