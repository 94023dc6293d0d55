"""A handout's blocks measured for the page and set on it (`handout.pdf` decides where each goes).

Each block of `document.Handout` becomes a `Measured`: its height measured once from the text widths
(`render.text_size`, no renderer) and the diagrams' layouts, then `set(pages)` places it on `pdf_text.Pages`:

* headings and paragraphs (`TextBlock`), a paragraph split between lines only (at least two lines on each side);
* tables in booktabs' manner (`TableSet`): caption above, rules above and below the header and at the end, notes
  below in smaller type, numbers aligned at the decimal point; a table that does not fit the rest of the page
  starts a new one, a table longer than a page is split only between rows (a ledger's rows of one instant stay
  together) with its header repeated; a worksheet's blank cells are empty ruled boxes at least as wide as the
  number they leave out;
* diagrams and strips at the full text width, their captions below, never split (`Picture`); a picture may be
  set smaller, down to `Picture.least`, to fit the rest of a page (`handout.pdf` decides when);
* questions (`QuestionSet`): in a worksheet followed by ruled lines to write the answer on, in the answer key by
  the worked answer.
"""

from __future__ import annotations

from typing import Callable

from rodparadox import render
from rodparadox.handout.document import (Block, DiagramBlock, Heading, PageBreak, Paragraph, Question, RodViewBlock,
                                         Strips, Table)
from rodparadox.handout.pdf_text import MM, RULE_GREY, Line, Pages, width_of, words_of, wrap
from rodparadox.physics.frames import frame_name
from rodparadox.render.styles import Style
from rodparadox.tolerances import FIT_SLACK

#: a worksheet's ruled answer lines: their distance (about that of ruled paper), and how many at least and at most
ANSWER_LINE_GAP = 8 * MM
ANSWER_LINES = (3, 8)
#: room kept under a worksheet question's last ruled line, so that a line at the foot of a page does not read as a
#: second footer rule (the footer's rule is a few points under the text area; 2 to 7 points were left)
ANSWER_FOOT = 0.5 * ANSWER_LINE_GAP
#: a strip's row in a handout, in units of the least row `draw_strips_into` accepts: room for the particles' letters
STRIP_ROWS = 1.25
#: a table at most this part of a page high is short: it moves whole, with its introduction
SHORT_TABLE = 0.25
#: a picture may be set down to this part of its natural height to fit the rest of a page (a diagram's panels
#: narrower, a strip's rows lower), never below what its drawing accepts
PICTURE_LEAST = 0.75
#: ... and a block of strips never below this many times the least row `draw_strips_into` accepts
STRIP_ROWS_LEAST = 1.0


class Measured:
    """A block measured for the page: `lead` is the least height it needs to start on a page (what a heading
    before it must find room for), `set(pages)` places it; `kind` names it in the page plan."""

    lead: float = 0.0
    kind: str = "block"

    def set(self, pages: Pages) -> None:
        raise NotImplementedError


class TextBlock(Measured):
    """Lines of one size: a paragraph (split between lines, never leaving one line alone) or a heading."""

    def __init__(self, lines: list[Line], size: float, leading: float, gap: float, indent: float = 0.0,
                 breakable: bool = True, heading: bool = False):
        self.lines, self.size, self.leading, self.gap, self.indent = lines, size, leading, gap, indent
        self.heading = heading
        self.kind = "heading" if heading else "paragraph"
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
            if gap + whole + (0.0 if top else keep) <= pages.room + FIT_SLACK:
                y = pages.start(whole, self.gap)
                pages.lines(lines, pages.left + self.indent, y, self.size, leading)
                return
            fit = int((pages.room - gap + FIT_SLACK) // leading)
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

    kind = "break"

    def set(self, pages: Pages) -> None:
        if not pages.at_top:
            pages.new_page()


class SectionBreak(Break):
    """Before a section's heading: a new page only where less than `room` of the page is left (a part of the text
    height), so that no page is left more than that empty where a section ends; else the section runs on."""

    def __init__(self, room: float):
        self.least = room

    def set(self, pages: Pages) -> None:
        if not pages.at_top and pages.room < self.least * pages.text_height:
            pages.new_page()


class TableSet(Measured):
    """A table measured: its type size (shrunk if the natural width exceeds the text width), column widths and
    positions, the height of its parts; `set` places it whole, or split between groups of rows."""

    kind = "table"

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
        # the least start on a page: a short table whole (it is never split), else its caption, header and first
        # two groups of rows (a longer table is split between groups rather than leave a page a quarter empty)
        whole = self.height(self.groups, True, True)
        self.short = whole <= SHORT_TABLE * pages.text_height or len(self.groups) == 1
        least = 1 if len(self.groups[0]) > 1 else 2  # on each side of a split: an instant's rows, or two rows
        self.lead = whole if self.short and whole <= pages.text_height else self.height(self.groups[:least], True,
                                                                                        least == len(self.groups))

    def _columns(self, size: float) -> tuple[list[float], list[float], list[float]]:
        """Each column's width, and for a numbers column the widths of its widest parts before and from the
        decimal point."""
        widths, heads, tails = [], [], []
        for j, (name, align) in enumerate(zip(self.table.header, self.table.align)):
            texts = [row[j].text for row in self.table.rows]
            if align == "n":
                parts = [_split_number(text) for text in texts]
                head = max((width_of(a, size) for a, _ in parts), default=0.0)
                tail = max((width_of(b, size) for _, b in parts), default=0.0)
                widths.append(max(head + tail, width_of(name, size)))
                heads.append(head)
                tails.append(tail)
            else:
                widths.append(max([width_of(name, size)] + [width_of(text, size) for text in texts]))
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
        if (pages.figures and not pages.at_top and self.gap + whole > pages.room and whole <= pages.text_height
                and (self.short or self.gap + self.lead > pages.room + FIT_SLACK)):
            pages.new_page()  # a short table is never split; a longer one starts here if two groups fit
        first = True
        while groups:
            room = pages.text_height if not pages.figures or pages.at_top else pages.room - self.gap
            take = len(groups)
            while take > 0 and self.height(groups[:take], first, take == len(groups)) > room + FIT_SLACK:
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
                            x = self.decimals[j] - width_of(head, size)
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
    """A diagram or a block of strips over the full text width, its caption below; never split. It may be set
    smaller (`shrink`), down to `least` points high (its drawing's own least, at least PICTURE_LEAST of its
    natural height), to fit the rest of a page."""

    def __init__(self, height: float, caption: list[Line], pages: Pages, gap: float, draw: Callable,
                 least: float = 0.0):
        self.picture_h, self.caption, self.gap, self.draw = height, caption, gap, draw
        self.natural_h, self.least = height, min(height, max(least, PICTURE_LEAST * height))
        t = pages.type
        self.caption_leading = 1.3 * t.caption
        self.caption_gap = 0.5 * t.body
        self.lead = height + self.caption_gap + len(caption) * self.caption_leading

    kind = "picture"

    def shrink(self, by: float) -> bool:
        """Set the picture `by` points lower, if that leaves it at least `least` high; False (unchanged) if not."""
        if by <= 0.0 or self.picture_h - by < self.least - FIT_SLACK:
            return False
        self.picture_h -= by
        self.lead -= by
        return True

    def set(self, pages: Pages) -> None:
        y = pages.start(self.lead, self.gap)
        if pages.drawing:
            self.draw(pages.target(y, self.picture_h))
        pages.lines(self.caption, pages.left, y + self.picture_h + self.caption_gap, pages.type.caption,
                    self.caption_leading)


class StripsSet(Picture):
    """A block of strips: a picture that, of four rows or more, is split between rows (two at least on each side)
    rather than leave the rest of a page empty; each part has its own x axis and colour bar (one scale, the whole
    history's), the caption goes under the last. `whole` is its height unsplit, `lead` that of its first two rows."""

    def __init__(self, block: Strips, style: str, caption: list[Line], pages: Pages, gap: float, room: float):
        self.block, self.style = block, style
        height = min(room, self._height(block.times))
        least = render.strips_size(block.history, block.frame, block.times, style, STRIP_ROWS_LEAST,
                                   partners=block.partners)[1]
        super().__init__(height, caption, pages, gap, self._draw_rows(block.times), least)
        self.whole = self.lead
        self.splits = len(block.times) >= 4
        if self.splits:  # a split's first part may have rows as low as the drawing accepts
            self.lead = min(self.whole, self._height(block.times[:2], STRIP_ROWS_LEAST))

    def _height(self, times, rows: float = STRIP_ROWS) -> float:
        return render.strips_size(self.block.history, self.block.frame, times, self.style, rows, self.block.times,
                                  self.block.partners)[1]

    def _draw_rows(self, times) -> Callable:
        def draw(target, block=self.block, times=tuple(times)):
            render.draw_strips_into(target, block.history, block.frame, times, self.style, span=block.times,
                                    partners=block.partners)
        return draw

    def shrink(self, by: float) -> bool:
        """Only a block that cannot be split is set smaller: a longer one is split instead."""
        if self.splits:
            return False
        ok = super().shrink(by)
        self.whole = self.lead
        return ok

    def set(self, pages: Pages) -> None:
        times, self.lead = self.block.times, self.whole
        if self.splits and pages.figures and not pages.at_top and self.gap + self.whole > pages.room + FIT_SLACK:
            room = pages.room - self.gap
            rows = max((n for n in range(2, len(times) - 1)
                        if self._height(times[:n], STRIP_ROWS_LEAST) <= room + FIT_SLACK), default=0)
            if rows:  # the first rows here (as high as fits), the rest and the caption at the top of the next page
                first = min(room, self._height(times[:rows]))
                y = pages.start(first, self.gap)
                if pages.drawing:
                    self._draw_rows(times[:rows])(pages.target(y, first))
                pages.new_page()
                # the rest is headed again by its frame, as a table's continuation is (issue 14.5)
                t = pages.type
                more = wrap(words_of(f"{self.block.subject} at successive instants of {frame_name(self.block.frame)} (continued)",
                                     italic=True), t.caption, pages.text_width)
                pages.lines(more, pages.left, pages.start(len(more) * 1.3 * t.caption, 0.0), t.caption,
                            1.3 * t.caption)
                self.picture_h, self.draw = self._height(times[rows:]), self._draw_rows(times[rows:])
                self.lead = self.picture_h + self.caption_gap + len(self.caption) * self.caption_leading
        super().set(pages)


class QuestionSet(Measured):
    """`Question k.` and its text; then ruled lines to write on (a worksheet) or the worked answer."""

    kind = "question"

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
            self.lead = self.text.lead + self.count * ANSWER_LINE_GAP + ANSWER_FOOT
        else:
            first = [("Answer.", True, False)]
            self.answers = [TextBlock(wrap((first if k == 0 else []) + words_of(p), t.body, answer_width), t.body,
                                      t.leading, (0.3 if k == 0 else 0.4) * t.body, indent=1.5 * t.body)
                            for k, p in enumerate(question.answer)]
            self.lead = self.text.lead + (self.answers[0].lead if self.answers else 0.0)

    def stretch(self, room: float) -> None:
        """A worksheet's question: as many more ruled lines as `room` points hold (the rest of a page the next
        block does not fit on is room to write, not an empty page)."""
        more = int((room + FIT_SLACK) // ANSWER_LINE_GAP) if self.ruled else 0
        self.count += more
        self.lead += more * ANSWER_LINE_GAP

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
    heading = TextBlock(lines, size, 1.25 * size, (1.4 if block.level == 1 else 1.1) * t.body, heading=True)
    heading.kind = f"heading{block.level}"
    return heading


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
        # no title above the panels: the section's heading and the caption say what it shows; a worksheet's without
        # the lines of simultaneity through the impacts (which impacts share one is asked)
        untitled = render.Options(titled=False, equal_scales=block.equal_scales, simultaneity=block.tell)
        _, height = render.natural_size(block.drawn, block.frames, pages.text_width, room, style.name, untitled)

        def draw_diagram(target, block=block):
            block.retitle(render.draw_into(target, block.drawn, block.frames, style.name, untitled))
        return Picture(height, caption, pages, 1.2 * t.body, draw_diagram)
    if isinstance(block, Strips):
        return StripsSet(block, style.name, caption, pages, 1.2 * t.body, room)
    if isinstance(block, RodViewBlock):
        _, height = render.rod_view_size(block.histories, style.name, pages.text_width)

        def draw_rod_view(target, block=block):
            render.draw_rod_view_into(target, block.histories, style.name)
        # never lower than its keys (`render.least_height`): a smaller picture would set them on its caption
        return Picture(min(height, room), caption, pages, 1.2 * t.body, draw_rod_view,
                       render.least_height(block.histories, style.name))
    raise TypeError(f"a handout has no block of type {type(block).__name__}")
