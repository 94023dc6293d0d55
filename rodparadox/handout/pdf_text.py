"""The text of a handout's pages: type sizes, words measured and wrapped into lines of runs, and the pages they
are set on (matplotlib Figures, never pyplot). `handout.pdf` sets the document's blocks with these.

* `Type`: a style's sizes and leading, points; `wrap` sets words (`words_of`) in
  lines of `Run`s no wider than the text, ragged-right, each word measured once
  (`width_of`, from `render.text_size`, no renderer), a word wider than a line cut
  between characters;
* `TextRuns`: a page's plain text drawn straight with the renderer's `draw_text`,
  measured once when placed and never laid out again;
* `Pages`: the pages being filled, margins of 20 mm on every side with the running
  footer (the handout's title and "page k of n") inside them; text, rules, boxes
  and sub-figures placed in points from the paper's top left corner.
"""

from __future__ import annotations

from functools import lru_cache
from typing import NamedTuple, Sequence

import matplotlib
from matplotlib.artist import Artist
from matplotlib.font_manager import FontProperties
from matplotlib.figure import Figure
from matplotlib.gridspec import GridSpec
from matplotlib.lines import Line2D
from matplotlib.patches import Rectangle

from rodparadox import render
from rodparadox.handout.document import PAPERS
from rodparadox.handout.words import math_pieces
from rodparadox.render.styles import Style
from rodparadox.tolerances import FIT_SLACK

#: points per millimetre
MM = 72 / 25.4
#: the page's margins on every side, points
MARGIN = 20 * MM
#: a measured line is set this much narrower than the text width: the drawn glyphs' kerning may differ a little
WRAP_SLACK = 1.0
#: dark enough to survive a black-and-white photocopy, light enough to read as a rule rather than text
RULE_GREY = "#4d4d4d"


class Type(NamedTuple):
    """The type sizes and distances of a style's handout, points: tables, captions and the footer are scaled from
    the running text's (`Style.handout_body_size`)."""

    body: float
    leading: float  # baseline to baseline of running text
    h1: float
    h2: float
    table: float
    caption: float
    small: float  # a table's notes, the footer

    @classmethod
    def of(cls, style: Style) -> "Type":
        body = style.handout_body_size
        return cls(body, 1.35 * body, 1.55 * body, 1.15 * body, 0.9 * body, 0.9 * body, 0.8 * body)


class Run(NamedTuple):
    """A piece of one line of text in one font, `x` points from the line's start."""

    text: str
    x: float
    bold: bool = False
    italic: bool = False


Line = tuple[Run, ...]


def width_of(text: str, size: float, bold: bool = False, italic: bool = False) -> float:
    """The width of a text set in one font, points (`render.text_size`, measured without a renderer)."""
    return render.text_size(text, size, italic=italic, ismath=False, bold=bold)[0]


measured_width = width_of  # `wrap`'s own width_of keeps each paragraph's widths and asks this for new ones


def wrap(words: Sequence[tuple], size: float, width: float) -> list[Line]:
    """Words (text, bold, italic[, glued]) set in lines no wider than `width` points, ragged-right, each word measured
    once; a glued piece (a variable's italics inside a word: "t" of "t′") follows the one before it with no space
    and never starts a line.

    A word wider than a whole line (a long number, a path) is cut between characters, so nothing runs off the page.

    Each text is set once per process for its size, width and the rcParams' fonts (`_wrapped`): a worksheet and its
    key, a handout of the same run on A4 and Letter, set the same paragraphs, questions and captions again.
    """
    return list(_wrapped(tuple(words), float(size), float(width), *render.measuring_fonts()))


@lru_cache(maxsize=4096)  # a handout sets a few hundred texts; bounded for a long-lived process
def _wrapped(words: tuple, size: float, width: float, *fonts) -> tuple[Line, ...]:
    """`wrap` for the current rcParams, whose font settings are `fonts` (part of the cache key only)."""
    return tuple(_wrap(words, size, width))


def _wrap(words: Sequence[tuple], size: float, width: float) -> list[Line]:
    lines: list[list[tuple[str, bool, bool, float, bool]]] = [[]]  # (word, bold, italic, x, glued)
    x = 0.0
    room = width - WRAP_SLACK
    widths: dict[tuple[str, bool, bool], float] = {}  # a paragraph repeats its words and spaces: measure each once

    def width_of(text: str, size: float, bold: bool, italic: bool) -> float:
        key = (text, bold, italic)
        if key not in widths:
            widths[key] = measured_width(text, size, bold, italic)
        return widths[key]

    for word in _whole_words(words):
        w = sum(width_of(text, size, bold, italic) for text, bold, italic in word)
        text, bold, italic = word[0]
        space = width_of(" ", size, bold, italic)
        if len(word) == 1 and w > room:  # cut it into pieces that fit
            for piece in _cut(text, size, bold, italic, room):
                if lines[-1]:
                    lines.append([])
                lines[-1].append((piece, bold, italic, 0.0, False))
            x = width_of(lines[-1][-1][0], size, bold, italic)
            continue
        if lines[-1] and x + space + w > room:
            lines.append([])
            x = 0.0
        x = x + space if lines[-1] else 0.0
        for k, (text, bold, italic) in enumerate(word):
            lines[-1].append((text, bold, italic, x, k > 0))
            x += width_of(text, size, bold, italic)
    return [_runs(line) for line in lines if line]


def _whole_words(words: Sequence[tuple]) -> list[list[tuple[str, bool, bool]]]:
    """The words as lists of their pieces: a glued piece joins the word before it."""
    out: list[list[tuple[str, bool, bool]]] = []
    for text, bold, italic, *glued in words:
        if glued and glued[0] and out:
            out[-1].append((text, bold, italic))
        else:
            out.append([(text, bold, italic)])
    return out


def _cut(text: str, size: float, bold: bool, italic: bool, room: float) -> list[str]:
    pieces, piece = [], ""
    for character in text:
        if piece and width_of(piece + character, size, bold, italic) > room:
            pieces.append(piece)
            piece = ""
        piece += character
    return pieces + [piece]


def _runs(line: list[tuple[str, bool, bool, float, bool]]) -> Line:
    """Consecutive words in one font joined into one run (one text in the PDF, read back as it was written)."""
    runs: list[Run] = []
    for text, bold, italic, x, glued in line:
        if runs and (runs[-1].bold, runs[-1].italic) == (bold, italic):
            runs[-1] = runs[-1]._replace(text=runs[-1].text + ("" if glued else " ") + text)
        else:
            runs.append(Run(text, x, bold, italic))
    return tuple(runs)


def words_of(text: str, bold: bool = False, italic: bool = False) -> list[tuple[str, bool, bool, bool]]:
    """The text's words (text, bold, italic, glued); a variable (`words.math_pieces`: v, L, t′, x, E, p, u) is a
    piece of its word set in math italics, glued to the piece before it (upright text around it stays upright; in
    italic text it stays italic). An apostrophe is set as a typographic one (rod’s), as the LaTeX sets it."""
    out = []
    for word in text.replace("'", "\N{RIGHT SINGLE QUOTATION MARK}").split():
        for k, (piece, variable) in enumerate(math_pieces(word)):
            out.append((piece, bold, italic or variable, k > 0))
    return out


# --- the page ---------------------------------------------------------------------------------------------

class PlacedText(NamedTuple):
    """One run of plain text as drawn: its anchor (points from the paper's bottom left: `x` where `ha` says, `y` the
    baseline), its text and font, and its measured width; `gid` names a table's cell."""

    x: float
    y: float
    text: str
    font: FontProperties
    ha: str
    width: float
    gid: str | None

    @property
    def left(self) -> float:
        return self.x - {"left": 0.0, "center": 0.5, "right": 1.0}[self.ha] * self.width


@lru_cache(maxsize=64)
def _font(size: float, bold: bool, italic: bool, *families) -> FontProperties:
    """A font of the current rcParams' family (part of the key only)."""
    return FontProperties(size=size, weight="bold" if bold else "normal", style="italic" if italic else "normal")


class TextRuns(Artist):
    """A page's plain text: runs drawn straight with the renderer's `draw_text`, each at its baseline.

    A `Text` artist lays its text out again before drawing it (the PDF renderer then lays it out once more), which
    doubled the cost of a page of tables (300 cells: 1.2 s as Texts, 0.65 s here); the runs are measured once when
    placed (`render.text_size`, as the PDF renderer lays them out) and never again.
    """

    zorder = 3

    def __init__(self):
        super().__init__()
        self.runs: list[PlacedText] = []

    def add(self, x: float, y: float, text: str, size: float, bold: bool, italic: bool, ha: str,
            gid: str | None) -> None:
        rc = matplotlib.rcParams
        font = _font(float(size), bold, italic, tuple(rc["font.family"]), tuple(rc["font.serif"]),
                     tuple(rc["font.sans-serif"]))
        width = width_of(text, size, bold, italic) if ha != "left" else 0.0
        self.runs.append(PlacedText(x, y, text, font, ha, width, gid))

    def draw(self, renderer) -> None:
        if not self.get_visible():
            return
        scale = renderer.points_to_pixels(1.0)  # 1 in a PDF (72 dpi); Agg's dpi in a PNG
        gc = renderer.new_gc()
        gc.set_foreground("black")
        # renderers that count y down from the top (Agg, for a PNG picture of a page) take it flipped, as Text does
        height = renderer.get_canvas_width_height()[1] if renderer.flipy() else None
        for run in self.runs:
            y = run.y * scale if height is None else height - run.y * scale
            renderer.draw_text(gc, run.left * scale, y, run.text, run.font, 0.0)
        gc.restore()
        self.stale = False


def text_width(paper: str) -> float:
    """The width of the text on a page of `paper`, in points: the paper less MARGIN each side."""
    return PAPERS[paper][0] * 72 - 2 * MARGIN


class Pages:
    """The pages being filled: one Figure each, the paper's size; `used` is how far down the text area (points
    from its top) the current page is filled. Text areas: MARGIN inside the paper's edges, less the footer's band."""

    def __init__(self, paper: str, style: Style, type_: Type):
        width, height = PAPERS[paper]
        self.width, self.height = width * 72, height * 72  # points
        self.style, self.type = style, type_
        self.left, self.top = MARGIN, MARGIN
        self.text_width = text_width(paper)
        self.footer_band = 2.2 * type_.small
        self.text_height = self.height - 2 * MARGIN - self.footer_band
        self.figures: list[Figure] = []
        self.texts: list[TextRuns] = []  # each page's text
        self.used = 0.0
        self.drawing = True  # False: the pictures are placed, not drawn (`pdf.page_plan`)
        self.marks: list[tuple[int, float, float]] = []  # each room made: (page, top, bottom), from the text's top

    # where things are
    @property
    def room(self) -> float:
        return self.text_height - self.used if self.figures else 0.0

    @property
    def at_top(self) -> bool:
        return bool(self.figures) and self.used == 0.0

    @property
    def figure(self) -> Figure:
        return self.figures[-1]

    def new_page(self) -> None:
        figure = Figure(figsize=(self.width / 72, self.height / 72), dpi=72)
        self.figures.append(figure)
        self.texts.append(figure.add_artist(TextRuns()))
        self.used = 0.0

    def start(self, height: float, gap: float) -> float:
        """Make room for `height` points after a gap of `gap` (dropped at the top of a page), on a new page if
        the rest of this one is too short; returns the y (points from the paper's top) of the room's top."""
        if not self.figures or (not self.at_top and gap + height > self.room + FIT_SLACK):
            self.new_page()
        if not self.at_top:
            self.used += gap
        y = self.top + self.used
        self.used += height
        self.marks.append((len(self.figures) - 1, self.used - height, self.used))
        return y

    # drawing, in points from the paper's top left corner, on the current page or on page `on` (from 0)
    def text(self, x: float, baseline: float, text: str, size: float, bold: bool = False, italic: bool = False,
             ha: str = "left", gid: str | None = None, on: int = -1) -> None:
        self.texts[on].add(x, self.height - baseline, text, size, bold, italic, ha, gid)

    def line(self, x: float, y: float, width: float, linewidth: float, colour: str = "black",
             gid: str | None = None, on: int = -1) -> None:
        f = self.figures[on]
        f.add_artist(Line2D([x / self.width, (x + width) / self.width], [1 - y / self.height] * 2,
                            transform=f.transFigure, linewidth=linewidth, color=colour, solid_capstyle="butt",
                            gid=gid))

    def box(self, x: float, y: float, width: float, height: float, linewidth: float, colour: str,
            gid: str | None = None) -> None:
        f = self.figure
        f.add_artist(Rectangle((x / self.width, 1 - (y + height) / self.height), width / self.width,
                               height / self.height, transform=f.transFigure, fill=False, linewidth=linewidth,
                               edgecolor=colour, gid=gid))

    def target(self, y: float, height: float):
        """A SubFigure over the full text width, from `y` (points from the paper's top) down `height` points."""
        ratios_w = [self.left, self.text_width, self.width - self.left - self.text_width]
        ratios_h = [y, height, self.height - y - height]
        grid = GridSpec(3, 3, figure=self.figure, width_ratios=ratios_w, height_ratios=ratios_h, wspace=0, hspace=0)
        return self.figure.add_subfigure(grid[1, 1])

    def lines(self, lines: Sequence[Line], x: float, y: float, size: float, leading: float) -> None:
        """Set lines of runs from `y` down, one per `leading`."""
        for k, line in enumerate(lines):
            baseline = y + _baseline(size, leading) + k * leading
            for run in line:
                self.text(x + run.x, baseline, run.text, size, run.bold, run.italic)

    def footers(self, title: str) -> None:
        """The running footer on every page: a thin rule, the title on the left, `page k of n` on the right."""
        n = len(self.figures)
        size = self.type.small
        baseline = self.height - MARGIN - 0.25 * size
        rule = self.height - MARGIN - self.footer_band + 0.3 * size
        title = _fitted(title, size, self.text_width * 0.7)
        for k in range(n):
            self.line(self.left, rule, self.text_width, 0.4, RULE_GREY, gid="footer-rule", on=k)
            self.text(self.left, baseline, title, size, italic=True, gid="footer-title", on=k)
            self.text(self.left + self.text_width, baseline, f"page {k + 1} of {n}", size, ha="right",
                      gid="footer-page", on=k)


def _baseline(size: float, leading: float) -> float:
    """From the top of a line's box to its baseline: the box's spare height split above and below the type."""
    return 0.5 * (leading - size) + 0.8 * size


def _fitted(text: str, size: float, width: float) -> str:
    """The text, or its longest start that fits `width` with an ellipsis."""
    if width_of(text, size, italic=True) <= width:
        return text
    while text and width_of(text + "\N{HORIZONTAL ELLIPSIS}", size, italic=True) > width:
        text = text[:-1]
    return text.rstrip() + "\N{HORIZONTAL ELLIPSIS}"
