"""A handout set on pages as a PDF: `to_pdf(handout, paper, style) -> bytes` (issue 9, items 1-2, 5-7).

The blocks of `document.Handout` are set top to bottom on pages of the paper's
size, with matplotlib's own PDF backend (`PdfPages`, one `Figure` per page,
never pyplot): the diagrams and the strips are drawn into the page by
`render.draw_into` and `render.draw_strips_into`, so they stay vector and use
the same fonts as the text. The page is laid out in points from measured text
widths (`render.text_size`, no renderer): each block is measured once, then
placed; a block that does not fit the rest of a page starts the next one.

* margins of 20 mm, everything (the running footer too) inside them; the
  footer holds the handout's title and "page k of n";
* headings (a level-1 heading after the document's first starts a new page;
  a heading is never left alone at the foot of a page), paragraphs wrapped
  ragged-right, split between lines only (at least two lines on each side);
* tables in booktabs' manner (caption above, rules above and below the header
  and at the end, notes below in smaller type), numbers aligned at the decimal
  point; a table that does not fit the rest of the page starts a new one, a
  table longer than a page is split only between rows (a ledger's rows of one
  impact stay together) with its header repeated; a worksheet's blank cells
  are empty ruled boxes at least as wide as the number they leave out;
* diagrams and strips at the full text width, their captions below, never
  split by a page break;
* questions: in a worksheet followed by ruled lines to write the answer on,
  in the answer key (and in a handout that is not a worksheet) by the worked
  answer; the answer key starts on a new page.

The same handout gives the same bytes (no dates, no producer versions); fonts
are embedded as TrueType (`pdf.fonttype` 42, every style), so a PDF reader's
text extraction gives back the words and numbers, Unicode minus, primes and
subscripts included.
"""

from __future__ import annotations

import io
from functools import lru_cache
from typing import Callable, NamedTuple, Sequence

import matplotlib
from matplotlib.artist import Artist
from matplotlib.backends.backend_pdf import PdfPages
from matplotlib.font_manager import FontProperties
from matplotlib.figure import Figure
from matplotlib.gridspec import GridSpec
from matplotlib.lines import Line2D
from matplotlib.patches import Rectangle

from rodparadox import render
from rodparadox.handout.document import (PAPERS, Block, DiagramBlock, Handout, Heading, PageBreak, Paragraph, Question, Strips, Table)
from rodparadox.render.diagram import FIGURE_METADATA
from rodparadox.render.styles import STYLES, Style

#: points per millimetre
MM = 72 / 25.4
#: the page's margins on every side, points
MARGIN = 20 * MM
#: running text's size in each style, points (tables, captions and the footer are scaled from it)
BODY_SIZE = {"print": 10.0, "default": 9.5, "slides": 12.0}
#: a worksheet's ruled answer lines: their distance (about that of ruled paper), and how many at least and at most
ANSWER_LINE_GAP = 8 * MM
ANSWER_LINES = (3, 8)
#: a measured line is set this much narrower than the text width: the drawn glyphs' kerning may differ a little
WRAP_SLACK = 1.0
#: a strip's row in a handout, in units of the least row `draw_strips_into` accepts: room for the particles' letters
STRIP_ROWS = 1.25
#: dark enough to survive a black-and-white photocopy, light enough to read as a rule rather than text
RULE_GREY = "#4d4d4d"


class Type(NamedTuple):
    """The type sizes and distances of a style's handout, points."""

    body: float
    leading: float  # baseline to baseline of running text
    h1: float
    h2: float
    table: float
    caption: float
    small: float  # a table's notes, the footer

    @classmethod
    def of(cls, style: Style) -> "Type":
        body = BODY_SIZE.get(style.name, 10.0)
        return cls(body, 1.35 * body, 1.55 * body, 1.15 * body, 0.9 * body, 0.9 * body, 0.8 * body)


class Run(NamedTuple):
    """A piece of one line of text in one font, `x` points from the line's start."""

    text: str
    x: float
    bold: bool = False
    italic: bool = False


Line = tuple[Run, ...]


def _width(text: str, size: float, bold: bool = False, italic: bool = False) -> float:
    return render.text_size(text, size, italic=italic, ismath=False, bold=bold)[0]


def wrap(words: Sequence[tuple[str, bool, bool]], size: float, width: float) -> list[Line]:
    """Words (text, bold, italic) set in lines no wider than `width` points, ragged-right, each word measured once.

    A word wider than a whole line (a long number, a path) is cut between characters, so nothing runs off the page.
    """
    lines: list[list[tuple[str, bool, bool, float]]] = [[]]  # (word, bold, italic, x)
    x = 0.0
    room = width - WRAP_SLACK
    for text, bold, italic in words:
        w = _width(text, size, bold, italic)
        space = _width(" ", size, bold, italic)
        if w > room:  # cut it into pieces that fit
            for piece in _cut(text, size, bold, italic, room):
                if lines[-1]:
                    lines.append([])
                lines[-1].append((piece, bold, italic, 0.0))
            x = _width(lines[-1][-1][0], size, bold, italic)
            continue
        if lines[-1] and x + space + w > room:
            lines.append([])
            x = 0.0
        start = x + space if lines[-1] else 0.0
        lines[-1].append((text, bold, italic, start))
        x = start + w
    return [_runs(line) for line in lines if line]


def _cut(text: str, size: float, bold: bool, italic: bool, room: float) -> list[str]:
    pieces, piece = [], ""
    for character in text:
        if piece and _width(piece + character, size, bold, italic) > room:
            pieces.append(piece)
            piece = ""
        piece += character
    return pieces + [piece]


def _runs(line: list[tuple[str, bool, bool, float]]) -> Line:
    """Consecutive words in one font joined into one run (one text in the PDF, read back as it was written)."""
    runs: list[Run] = []
    for text, bold, italic, x in line:
        if runs and (runs[-1].bold, runs[-1].italic) == (bold, italic):
            runs[-1] = runs[-1]._replace(text=f"{runs[-1].text} {text}")
        else:
            runs.append(Run(text, x, bold, italic))
    return tuple(runs)


def words_of(text: str, bold: bool = False, italic: bool = False) -> list[tuple[str, bool, bool]]:
    return [(word, bold, italic) for word in text.split()]


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
        width = _width(text, size, bold, italic) if ha != "left" else 0.0
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


class Pages:
    """The pages being filled: one Figure each, the paper's size; `used` is how far down the text area (points
    from its top) the current page is filled. Text areas: MARGIN inside the paper's edges, less the footer's band."""

    def __init__(self, paper: str, style: Style, type_: Type):
        width, height = PAPERS[paper]
        self.width, self.height = width * 72, height * 72  # points
        self.style, self.type = style, type_
        self.left, self.top = MARGIN, MARGIN
        self.text_width = self.width - 2 * MARGIN
        self.footer_band = 2.2 * type_.small
        self.text_height = self.height - 2 * MARGIN - self.footer_band
        self.figures: list[Figure] = []
        self.texts: list[TextRuns] = []  # each page's text
        self.used = 0.0

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
        if not self.figures or (not self.at_top and gap + height > self.room + 1e-6):
            self.new_page()
        if not self.at_top:
            self.used += gap
        y = self.top + self.used
        self.used += height
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
    if _width(text, size, italic=True) <= width:
        return text
    while text and _width(text + "\N{HORIZONTAL ELLIPSIS}", size, italic=True) > width:
        text = text[:-1]
    return text.rstrip() + "\N{HORIZONTAL ELLIPSIS}"


# --- blocks, measured -------------------------------------------------------------------------------------

class Measured:
    """A block measured for the page: `lead` is the least height it needs to start on a page (what a heading
    before it must find room for), `set(pages)` places it."""

    lead: float = 0.0

    def set(self, pages: Pages) -> None:
        raise NotImplementedError


class TextBlock(Measured):
    """Lines of one size: a paragraph (split between lines, never leaving one line alone) or a heading."""

    def __init__(self, lines: list[Line], size: float, leading: float, gap: float, indent: float = 0.0,
                 breakable: bool = True, heading: bool = False):
        self.lines, self.size, self.leading, self.gap, self.indent = lines, size, leading, gap, indent
        self.heading = heading
        self.breakable = breakable and not heading and len(lines) >= 4
        self.lead = leading * (min(2, len(lines)) if self.breakable else len(lines))

    def set(self, pages: Pages, keep: float = 0.0) -> None:
        """`keep`: room the next block needs on the same page (a heading's); at the top of a page it is not asked."""
        lines, leading = self.lines, self.leading
        while lines:
            if not pages.figures:
                pages.new_page()
            top = pages.at_top
            gap = 0.0 if top else self.gap
            whole = len(lines) * leading
            if gap + whole + (0.0 if top else keep) <= pages.room + 1e-6:
                y = pages.start(whole, self.gap)
                pages.lines(lines, pages.left + self.indent, y, self.size, leading)
                return
            fit = int((pages.room - gap + 1e-6) // leading)
            if self.breakable:  # two lines at least on this page, two at least on the next
                fit = min(fit, len(lines) - 2) if not top else fit
            elif not top:
                fit = 0  # a heading or a short paragraph moves whole
            if fit >= 2 or (top and fit >= 1):
                y = pages.start(fit * leading, self.gap)
                pages.lines(lines[:fit], pages.left + self.indent, y, self.size, leading)
                lines = lines[fit:]
            pages.new_page()


class Break(Measured):
    """A new page, unless the current one is still empty."""

    def set(self, pages: Pages) -> None:
        if not pages.at_top:
            pages.new_page()


class TableSet(Measured):
    """A table measured: its type size (shrunk if the natural width exceeds the text width), column widths and
    positions, the height of its parts; `set` places it whole, or split between groups of rows."""

    def __init__(self, table: Table, pages: Pages, gap: float):
        self.table, self.gap = table, gap
        t = pages.type
        size = t.table
        blanks = [any(row[j].blank for row in table.rows) for j in range(len(table.header))]
        widths, heads, tails = self._columns(size)
        gap_w = 1.1 * size
        natural = sum(widths) + gap_w * (len(widths) - 1)
        if natural > pages.text_width:  # smaller type, as widths scale with it
            scale = pages.text_width / natural
            size *= scale
            widths, heads, tails = ([w * scale for w in ws] for ws in (widths, heads, tails))
            gap_w *= scale
            natural *= scale
        spare = pages.text_width - natural
        if any(blanks) and spare > 0:  # room to write: widen the blank columns, up to half as wide again
            share = spare / sum(blanks)
            widths = [w + min(share, 0.5 * w) if b else w for w, b in zip(widths, blanks)]
        self.size, self.widths, self.gap_w = size, widths, gap_w
        self.width = sum(widths) + gap_w * (len(widths) - 1)
        self.x = pages.left + (pages.text_width - self.width) / 2
        self.xs = []
        x = self.x
        for w in widths:
            self.xs.append(x)
            x += w + gap_w
        # a numbers column's decimal point: the block of its numbers (widest head, widest tail) centred in it
        self.decimals = [x + (w - head - tail) / 2 + head for x, w, head, tail in zip(self.xs, widths, heads, tails)]
        # vertical: caption lines, the header between rules, the rows (taller where a student writes), notes
        self.caption_size, self.caption_leading = t.caption, 1.3 * t.caption
        caption_width = pages.left + pages.text_width - self.x  # from the table's left edge to the text's right
        self.caption_lines = wrap(words_of(table.caption, italic=True), t.caption, caption_width)
        self.caption_more = wrap(words_of(table.caption + " (continued)", italic=True), t.caption, caption_width)
        self.notes_lines = [line for note in table.notes for line in wrap(words_of(note), t.small, caption_width)]
        self.notes_leading = 1.3 * t.small
        self.rule_heavy, self.rule_light = 0.8, 0.5
        self.header_h = 1.6 * size
        self.row_h = (2.4 if table.has_blanks else 1.45) * size
        self.group_gap = 0.35 * size
        self.groups = _groups(table) or [[]]  # a table without rows still has its caption, header and rules
        # the least start on a page: the whole table if it fits a page (it is then never split), else its caption,
        # header and first group of rows
        whole = self.height(self.groups, True, True)
        self.lead = whole if whole <= pages.text_height else self.height(self.groups[:1], True, False)

    def _columns(self, size: float) -> tuple[list[float], list[float], list[float]]:
        """Each column's width, and for a numbers column the widths of its widest parts before and from the
        decimal point."""
        widths, heads, tails = [], [], []
        for j, (name, align) in enumerate(zip(self.table.header, self.table.align)):
            texts = [row[j].text for row in self.table.rows]
            if align == "n":
                parts = [_split_number(text) for text in texts]
                head = max((_width(a, size) for a, _ in parts), default=0.0)
                tail = max((_width(b, size) for _, b in parts), default=0.0)
                widths.append(max(head + tail, _width(name, size)))
                heads.append(head)
                tails.append(tail)
            else:
                widths.append(max([_width(name, size)] + [_width(text, size) for text in texts]))
                heads.append(0.0)
                tails.append(0.0)
        return widths, heads, tails

    def _head_h(self, caption: list[Line]) -> float:
        return len(caption) * self.caption_leading + 0.3 * self.size + self.rule_heavy + self.header_h + self.rule_light

    def _rows_h(self, groups: list[list[int]]) -> float:
        return sum(len(g) for g in groups) * self.row_h + self.group_gap * max(len(groups) - 1, 0)

    def _foot_h(self, last: bool) -> float:
        notes = 0.35 * self.size + len(self.notes_lines) * self.notes_leading if last and self.notes_lines else 0.0
        return 0.2 * self.size + self.rule_heavy + notes

    def height(self, groups: list[list[int]], first: bool, last: bool) -> float:
        return (self._head_h(self.caption_lines if first else self.caption_more) + self._rows_h(groups)
                + self._foot_h(last))

    def set(self, pages: Pages) -> None:
        groups = self.groups
        whole = self.height(groups, True, True)
        if pages.figures and not pages.at_top and self.gap + whole > pages.room and whole <= pages.text_height:
            pages.new_page()  # a table that fits a page is never split
        first = True
        while groups:
            room = pages.text_height if not pages.figures or pages.at_top else pages.room - self.gap
            take = len(groups)
            while take > 0 and self.height(groups[:take], first, take == len(groups)) > room + 1e-6:
                take -= 1
            if take == 0:
                if pages.figures and not pages.at_top:
                    pages.new_page()
                    continue
                take = 1  # one group taller than a page: set it anyway (it cannot be split)
            part = groups[:take]
            groups = groups[take:]
            y = pages.start(self.height(part, first, not groups), self.gap)
            self._draw(pages, y, part, first, not groups)
            first = False

    def _draw(self, pages: Pages, y: float, groups: list[list[int]], first: bool, last: bool) -> None:
        size, table = self.size, self.table
        caption = self.caption_lines if first else self.caption_more
        pages.lines(caption, self.x, y, self.caption_size, self.caption_leading)
        y += len(caption) * self.caption_leading + 0.3 * size
        pages.line(self.x, y + self.rule_heavy / 2, self.width, self.rule_heavy)
        y += self.rule_heavy
        baseline = y + self.header_h / 2 + 0.33 * size
        for j, (name, align) in enumerate(zip(table.header, table.align)):
            x, ha = self._anchor(j, align)
            pages.text(x, baseline, name, size, ha=ha)
        y += self.header_h
        pages.line(self.x, y + self.rule_light / 2, self.width, self.rule_light)
        y += self.rule_light
        for k, group in enumerate(groups):
            if k:
                y += self.group_gap
            for i in group:
                baseline = y + self.row_h / 2 + 0.33 * size
                for j, cell in enumerate(table.rows[i]):
                    if cell.blank:  # into the gaps beside the column, never beyond the table's rules
                        x0 = max(self.xs[j] - 0.4 * self.gap_w, self.x)
                        x1 = min(self.xs[j] + self.widths[j] + 0.4 * self.gap_w, self.x + self.width)
                        pages.box(x0, y + 0.12 * self.row_h, x1 - x0, 0.76 * self.row_h, 0.5, RULE_GREY,
                                  gid=f"{table.name}-r{i}-c{j}-blank")
                    elif cell.text:
                        align = table.align[j]
                        if align == "n":
                            head, _ = _split_number(cell.text)
                            x = self.decimals[j] - _width(head, size)
                            pages.text(x, baseline, cell.text, size, gid=f"{table.name}-r{i}-c{j}")
                        else:
                            x, ha = self._anchor(j, align)
                            pages.text(x, baseline, cell.text, size, ha=ha, gid=f"{table.name}-r{i}-c{j}")
                y += self.row_h
        y += 0.2 * size
        pages.line(self.x, y + self.rule_heavy / 2, self.width, self.rule_heavy)
        y += self.rule_heavy
        if last and self.notes_lines:
            y += 0.35 * size
            pages.lines(self.notes_lines, self.x, y, pages.type.small, self.notes_leading)

    def _anchor(self, j: int, align: str) -> tuple[float, str]:
        """Where a column's header (and text cells) go: its left edge, right edge, or centre for numbers."""
        x, w = self.xs[j], self.widths[j]
        return {"l": (x, "left"), "r": (x + w, "right"), "n": (x + w / 2, "center")}[align]


def _split_number(text: str) -> tuple[str, str]:
    """A number's text at its decimal point (`+1.416667 (17/12)` -> `+1`, `.416667 (17/12)`); without one, after
    the number (`0 (0)`: `0`, ` (0)`)."""
    point = text.find(".")
    if point < 0:
        space = text.find(" ")
        point = len(text) if space < 0 else space
    return text[:point], text[point:]


def _groups(table: Table) -> list[list[int]]:
    """Rows that belong together: a row whose first cell is empty continues the one above (a ledger's impact)."""
    groups: list[list[int]] = []
    for i, row in enumerate(table.rows):
        if groups and not row[0].text and table.align[0] != "n":
            groups[-1].append(i)
        else:
            groups.append([i])
    return groups


class Picture(Measured):
    """A diagram or a block of strips over the full text width, its caption below; never split."""

    def __init__(self, height: float, caption: list[Line], pages: Pages, gap: float, draw: Callable):
        self.picture_h, self.caption, self.gap, self.draw = height, caption, gap, draw
        t = pages.type
        self.caption_leading = 1.3 * t.caption
        self.caption_gap = 0.5 * t.body
        self.lead = height + self.caption_gap + len(caption) * self.caption_leading

    def set(self, pages: Pages) -> None:
        y = pages.start(self.lead, self.gap)
        self.draw(pages.target(y, self.picture_h))
        pages.lines(self.caption, pages.left, y + self.picture_h + self.caption_gap, pages.type.caption,
                    self.caption_leading)


class QuestionSet(Measured):
    """`Question k.` and its text; then ruled lines to write on (a worksheet) or the worked answer."""

    def __init__(self, question: Question, pages: Pages, gap: float, ruled: bool):
        t = pages.type
        words = [("Question", True, False), (f"{question.number}.", True, False)] + words_of(question.text)
        self.text = TextBlock(wrap(words, t.body, pages.text_width), t.body, t.leading, gap, breakable=False)
        self.ruled = ruled
        answer_width = pages.text_width - 1.5 * t.body
        answers = [wrap(words_of(p), t.body, answer_width) for p in question.answer]
        if ruled:  # room in proportion to the worked answer: handwriting is larger than type
            count = sum(len(lines) for lines in answers)
            self.count = min(max(round(1.5 * count) + 1, ANSWER_LINES[0]), ANSWER_LINES[1])
            self.lead = self.text.lead + self.count * ANSWER_LINE_GAP
        else:
            first = [("Answer.", True, False)]
            self.answers = [TextBlock(wrap((first if k == 0 else []) + words_of(p), t.body, answer_width), t.body,
                                      t.leading, (0.3 if k == 0 else 0.4) * t.body, indent=1.5 * t.body)
                            for k, p in enumerate(question.answer)]
            self.lead = self.text.lead + (self.answers[0].lead if self.answers else 0.0)

    def set(self, pages: Pages) -> None:
        if self.ruled:  # the question with all its lines on one page
            y = pages.start(self.lead, self.text.gap)
            pages.lines(self.text.lines, pages.left, y, self.text.size, self.text.leading)
            y += self.text.lead
            for k in range(self.count):
                pages.line(pages.left, y + (k + 1) * ANSWER_LINE_GAP, pages.text_width, 0.5, RULE_GREY,
                           gid="answer-line")
            return
        self.text.set(pages, keep=self.answers[0].lead if self.answers else 0.0)
        for answer in self.answers:
            answer.set(pages)


def _heading(block: Heading, pages: Pages) -> TextBlock:
    """Bold, level 1 larger; the gap above it is dropped at the top of a page."""
    t = pages.type
    size = t.h1 if block.level == 1 else t.h2
    lines = wrap(words_of(block.text, bold=True), size, pages.text_width)
    return TextBlock(lines, size, 1.25 * size, (1.4 if block.level == 1 else 1.1) * t.body, heading=True)


def measure(block: Block, pages: Pages, style: Style, ruled: bool) -> Measured:
    """A block measured for the pages (the diagram's height from its layout at the text width)."""
    t = pages.type
    if isinstance(block, Heading):
        return _heading(block, pages)
    if isinstance(block, Paragraph):
        return TextBlock(wrap(words_of(block.text), t.body, pages.text_width), t.body, t.leading, 0.55 * t.body)
    if isinstance(block, Table):
        return TableSet(block, pages, 1.2 * t.body)
    if isinstance(block, Question):
        return QuestionSet(block, pages, 0.9 * t.body, ruled)
    if isinstance(block, PageBreak):
        return Break()
    caption = wrap(words_of(block.caption), t.caption, pages.text_width)
    room = pages.text_height - 0.5 * t.body - len(caption) * 1.3 * t.caption
    if isinstance(block, DiagramBlock):
        _, height = render.natural_size(block.history, block.frames, pages.text_width, room, style.name)

        def draw_diagram(target, block=block):
            render.draw_into(target, block.history, block.frames, style.name)
        return Picture(height, caption, pages, 1.2 * t.body, draw_diagram)
    if isinstance(block, Strips):
        height = min(room, render.strips_size(block.history, block.frame, block.times, style.name, STRIP_ROWS)[1])

        def draw_strips(target, block=block):
            render.draw_strips_into(target, block.history, block.frame, block.times, style.name)
        return Picture(height, caption, pages, 1.2 * t.body, draw_strips)
    raise TypeError(f"a handout has no block of type {type(block).__name__}")


# --- the document ------------------------------------------------------------------------------------------

def page_figures(handout: Handout, paper: str = "a4", style: str = "print") -> tuple[Figure, ...]:
    """The handout's pages as Figures (paper size, dpi 72: one unit a point), drawn in the style's fonts.

    Save them inside `render.style_context(style)`, as `to_pdf` does, for the style's PDF settings.
    """
    if paper not in PAPERS:
        raise ValueError(f"unknown paper size {paper!r}; use one of {', '.join(PAPERS)}")
    if style not in STYLES:
        raise ValueError(f"unknown style {style!r}; use one of {', '.join(STYLES)}")
    with render.style_context(style) as st:
        pages = Pages(paper, st, Type.of(st))
        parts = [(block, False) for section in handout.sections for block in section.blocks]
        parts += [(block, True) for block in handout.answer_key]
        measured: list[Measured] = []
        headings = key_started = False
        for block, in_key in parts:
            if in_key and not key_started:  # the answer key starts on a new page
                measured.append(Break())
                key_started = True
            if isinstance(block, Heading) and block.level == 1 and headings:
                measured.append(Break())  # a section's heading, after the document's first
            headings = headings or isinstance(block, Heading)
            measured.append(measure(block, pages, st, ruled=handout.worksheet and not in_key))
        for item, following in zip(measured, measured[1:] + [None]):
            if isinstance(item, TextBlock) and item.heading and following and not isinstance(following, Break):
                item.set(pages, keep=following.lead)  # a heading is never left alone at the foot of a page
            else:
                item.set(pages)
        if not pages.figures:
            pages.new_page()
        pages.footers(handout.title)
        return tuple(pages.figures)


def to_pdf(handout: Handout, paper: str = "a4", style: str = "print") -> bytes:
    """The handout as a PDF, one page of `paper` (a4, letter) after another; the same handout gives the same bytes."""
    figures = page_figures(handout, paper, style)
    buffer = io.BytesIO()
    with render.style_context(style):
        with PdfPages(buffer, metadata=dict(FIGURE_METADATA["pdf"])) as pdf:
            for figure in figures:
                pdf.savefig(figure)
    return buffer.getvalue()


#: pixels per inch of a page shown as a picture (the README's): A4 at 60 dpi is 496 x 702 pixels
PAGE_PICTURE_DPI = 60


def page_png(handout: Handout, page: int = 0, paper: str = "a4", style: str = "print",
             dpi: int = PAGE_PICTURE_DPI) -> bytes:
    """One page (from 0) as a PNG picture, to show a handout where a PDF cannot be (the README)."""
    figure = page_figures(handout, paper, style)[page]
    with render.style_context(style):
        buffer = io.BytesIO()
        figure.savefig(buffer, format="png", dpi=dpi, metadata={"Software": None})
        return buffer.getvalue()
