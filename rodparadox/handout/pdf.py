"""A handout set on pages as a PDF: `to_pdf(handout, paper, style) -> bytes` (docs/handout.md, "Teaching handouts").

The blocks of `document.Handout` are set top to bottom on pages of the paper's
size, with matplotlib's own PDF backend (`PdfPages`, one `Figure` per page,
never pyplot): the diagrams and the strips are drawn into the page by
`render.draw_into` and `render.draw_strips_into`, so they stay vector and use
the same fonts as the text. The page is laid out in points from measured text
widths (`render.text_size`, no renderer): each block is measured once, then
placed; a block that does not fit the rest of a page starts the next one.
The type, the wrapping of words into lines and the pages themselves are
`handout.pdf_text`'s, each block measured and set by `handout.pdf_blocks`;
this module decides where each block goes (the page plan).

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
* diagrams and strips at the full text width, their captions below; rather
  than leave a page more than a quarter empty (EMPTY_MOST; a section's last
  page may be), a diagram is set smaller (`pdf_blocks.PICTURE_LEAST`), a block
  of strips is split between rows, a table of several instants between them,
  and a worksheet's question takes the page's rest as ruled lines (`_fit`);
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
from typing import NamedTuple

from matplotlib.backends.backend_pdf import PdfPages
from matplotlib.figure import Figure

from rodparadox import render
from rodparadox.handout.document import PAPERS, Handout, Heading
from rodparadox.handout.pdf_blocks import (Break, Measured, Picture, QuestionSet, SectionBreak, StripsSet, TableSet,
                                         TextBlock, measure)
from rodparadox.handout.pdf_text import Pages, Type
from rodparadox.render.diagram import FIGURE_METADATA
from rodparadox.render.pdf_fonts import kept_subsets
from rodparadox.render.styles import STYLES
from rodparadox.tolerances import FIT_SLACK

#: a page, but a section's last, is left at most this part empty (a picture shrinks, a question's lines stretch)
EMPTY_MOST = 0.25
#: a section starts a new page only where less than this part of the page is left: else it runs on after the last
#: (a handout's first page held the paradox alone, 60 % empty), so no page but the last is left more than a third
#: empty
SECTION_ROOM = 1 / 3
#: a picture shrunk to fit is made this much smaller again (points), so the sums of heights never miss by a rounding
ROUNDING = 0.01

# --- the document ------------------------------------------------------------------------------------------

def _introduces(item: Measured, following: Measured | None) -> bool:
    """A paragraph before a table or a figure: its introduction, kept on the page where that starts."""
    return isinstance(item, TextBlock) and not item.heading and isinstance(following, (TableSet, Picture))


def _kept_with_next(item: Measured, following: Measured | None) -> bool:
    """A heading (with what follows it, unless a page break) or an introduction that moves whole (with its table or
    figure): never set apart from the next block."""
    heading = isinstance(item, TextBlock) and item.heading and following is not None and not isinstance(following,
                                                                                                         Break)
    return heading or (_introduces(item, following) and not item.breakable)


def _needs(measured: list[Measured]) -> list[float]:
    """The room each block needs at a page's foot to start there with what must stay with it: a heading with the
    next block's need, an introduction that moves whole with its table's or figure's start (one that may be split
    needs only its first lines: the rest go with the table). One more entry, 0, for after the last block."""
    needs = [0.0] * (len(measured) + 1)
    for k in range(len(measured) - 1, -1, -1):
        item = measured[k]
        following = measured[k + 1] if k + 1 < len(measured) else None
        needs[k] = item.lead
        if _kept_with_next(item, following):
            needs[k] += getattr(following, "gap", 0.0) + needs[k + 1]
    return needs


def _gap(item: Measured) -> float:
    """The space a block leaves above itself (dropped at the top of a page)."""
    return item.text.gap if isinstance(item, QuestionSet) else getattr(item, "gap", 0.0)


def _fit(measured: list[Measured], needs: list[float], k: int, pages: Pages) -> bool:
    """Before block k is set, rather than leave the page more than EMPTY_MOST empty (a book's way): a picture is set
    smaller, down to its least, so that it fits the rest of the page with what is kept before it, or so that what
    comes after it does; a worksheet's question takes the rest of its page as ruled lines when the next block does
    not fit there, or when it is the last before the answer key. True if a block's size changed (the needs are then
    measured again)."""
    item = measured[k]
    least_room = EMPTY_MOST * pages.text_height  # moving on with less room than this leaves the page full enough
    if isinstance(item, QuestionSet) and item.ruled and (k + 1 == len(measured) or isinstance(measured[k + 1], Break)):
        # the last question before the key: the page's rest is room to write (single, v = 0.3: 72 % left empty)
        after = pages.room - _gap(item) - item.lead  # on this page, or at the next one's top
        after = after if after >= -FIT_SLACK else pages.text_height - item.lead
        return after > least_room and item.stretch(after) is None
    if not pages.figures or pages.at_top or isinstance(item, Break):
        return False
    following = measured[k + 1] if k + 1 < len(measured) else None
    if _introduces(item, following) and isinstance(following, Picture) and not isinstance(following, StripsSet):
        # a figure with its introduction: set smaller to fit after it where floating it to the next page would
        # leave this one more than EMPTY_MOST empty (single at 0.3 and 0.6: 33 %)
        missing = _gap(item) + len(item.lines) * item.leading + _gap(following) + needs[k + 1] - pages.room
        if (missing > FIT_SLACK and pages.room > least_room and _floated_room(measured, needs, k, pages) > least_room
                and following.shrink(missing + ROUNDING)):
            return True
    short = _gap(item) + needs[k] - pages.room  # by how much the block (with what it keeps) misses this page
    if short > FIT_SLACK:
        end = k
        while end + 1 < len(measured) and _kept_with_next(measured[end], measured[end + 1]):
            end += 1
        return pages.room > least_room and isinstance(measured[end], Picture) and measured[end].shrink(short + ROUNDING)
    if k + 1 == len(measured) or isinstance(measured[k + 1], Break) or not isinstance(item, (Picture, QuestionSet)):
        return False
    after = pages.room - _gap(item) - getattr(item, "whole", item.lead)  # the page's rest once this block is set
    missing = _gap(measured[k + 1]) + needs[k + 1] - after
    if missing <= FIT_SLACK or after <= least_room:
        return False
    if isinstance(item, Picture):
        return item.shrink(missing + ROUNDING)
    if not item.ruled:
        return False
    item.stretch(after)
    return True


class Placed(NamedTuple):
    """Where a block was set: its kind (heading1, heading2, paragraph, table, picture, question, break) and its
    pieces, (page from 0, top, bottom) in points from the text area's top, one per page it spans."""

    kind: str
    pieces: tuple[tuple[int, float, float], ...]


class PagePlan(NamedTuple):
    """The pages' plan: the text area's height (points) and every block where it was set, in order."""

    text_height: float
    blocks: tuple[Placed, ...]
    pages: int


def page_figures(handout: Handout, paper: str = "a4", style: str = "print") -> tuple[Figure, ...]:
    """The handout's pages as Figures (paper size, dpi 72: one unit a point), drawn in the style's fonts.

    Save them inside `render.style_context(style)`, as `to_pdf` does, for the style's PDF settings.
    """
    return _set_pages(handout, paper, style)[0]


def page_plan(handout: Handout, paper: str = "a4", style: str = "print") -> PagePlan:
    """Where each block of the handout lands on its pages (the rules of setting, tested: tests/handout/test_page_rules.py)."""
    return _set_pages(handout, paper, style, drawing=False)[1]


def _set_pages(handout: Handout, paper: str, style: str, drawing: bool = True
               ) -> tuple[tuple[Figure, ...], PagePlan]:
    """The pages set; without `drawing` the diagrams and strips are measured and placed but not drawn (the plan)."""
    if paper not in PAPERS:
        raise ValueError(f"unknown paper size {paper!r}; use one of {', '.join(PAPERS)}")
    if style not in STYLES:
        raise ValueError(f"unknown style {style!r}; use one of {', '.join(STYLES)}")
    with render.style_context(style) as st:
        pages = Pages(paper, st, Type.of(st))
        pages.drawing = drawing
        parts = [(block, False) for section in handout.sections for block in section.blocks]
        parts += [(block, True) for block in handout.answer_key]
        measured: list[Measured] = []
        headings = key_started = False
        for block, in_key in parts:
            if in_key and not key_started:  # the answer key starts on a new page
                measured.append(Break())
                key_started = True
            if isinstance(block, Heading) and block.level == 1 and headings:
                # a section's heading, after the document's first: a new page where the page is nearly full
                measured.append(SectionBreak(SECTION_ROOM))
            headings = headings or isinstance(block, Heading)
            measured.append(measure(block, pages, st, ruled=handout.worksheet and not in_key))
        plan: dict[int, Placed] = {}
        order = list(range(len(measured)))  # each set block's place in the document (a picture may float)
        needs = _needs(measured)
        floated: set[int] = set()
        k = 0
        while k < len(measured):
            item, following = measured[k], measured[k + 1] if k + 1 < len(measured) else None
            if _fit(measured, needs, k, pages):
                needs = _needs(measured)
            at, moved = _float(measured, needs, k, pages)
            if moved:  # the text after a picture that misses the page fills it; the picture tops the next
                floated.add(id(measured[at + moved]))  # set before the picture, not as its introduction
                measured[at:at + moved + 1] = measured[at + 1:at + moved + 1] + [measured[at]]
                order[at:at + moved + 1] = order[at + 1:at + moved + 1] + [order[at]]
                needs = _needs(measured)
                continue
            marks = len(pages.marks)
            keep = getattr(following, "gap", 0.0) + needs[k + 1] if following is not None else 0.0
            if isinstance(item, TextBlock) and item.heading and following and not isinstance(following, Break):
                item.set(pages, keep=keep)  # a heading is never left alone at the foot of a page
            elif _introduces(item, following) and id(item) not in floated:
                item.set(pages, keep=keep)  # nor an introduction, apart from its table or figure
            else:
                item.set(pages)
            plan[order[k]] = Placed(item.kind, tuple(pages.marks[marks:]))
            k += 1
        if not pages.figures:
            pages.new_page()
        pages.footers(handout.title)
        return tuple(pages.figures), PagePlan(pages.text_height, tuple(plan[j] for j in sorted(plan)),
                                              len(pages.figures))


def _float(measured: list[Measured], needs: list[float], k: int, pages: Pages) -> tuple[int, int]:
    """As a book floats a figure: where a picture (shrunk as far as it goes), or the paragraph introducing it with
    it, misses the page and would leave more than EMPTY_MOST of it empty, the headings and paragraphs after the
    picture that fit the page (whole, or the last split between lines; none an introduction to a table or a figure,
    the last no heading) fill it, and the picture starts the next page. (the picture's index, how many blocks to set before it); (k, 0): none."""
    item = measured[k]
    if pages.at_top or not pages.figures:
        return k, 0
    room = pages.room
    if isinstance(item, TextBlock) and _introduces(item, measured[k + 1] if k + 1 < len(measured) else None):
        at = k + 1
        room -= _gap(item) + len(item.lines) * item.leading  # the introduction set whole here
    else:
        at = k
    picture = measured[at]
    if not isinstance(picture, Picture) or isinstance(picture, StripsSet) or room < 0.0:
        return k, 0
    if _gap(picture) + needs[at] <= room + FIT_SLACK or room <= EMPTY_MOST * pages.text_height:
        return k, 0
    count = best = 0
    for j in range(at + 1, len(measured)):
        block = measured[j]
        following = measured[j + 1] if j + 1 < len(measured) else None
        if not isinstance(block, TextBlock) or _introduces(block, following):
            break
        height = _gap(block) + len(block.lines) * block.leading
        if height > room + FIT_SLACK:
            if block.breakable and room >= _gap(block) + 2 * block.leading:  # it fills the page, its rest goes on
                best = count + 1                                              # the next, before the picture
            break
        room -= height
        count += 1
        if not block.heading:
            best = count
    return at, best


def _floated_room(measured: list[Measured], needs: list[float], k: int, pages: Pages) -> float:
    """The room `_float` would leave on this page before block k: 0 where nothing floats or a split paragraph
    fills the page."""
    at, moved = _float(measured, needs, k, pages)
    if not moved:
        return 0.0
    room = pages.room
    for block in measured[k:at] + measured[at + 1:at + moved + 1]:  # the introduction, then the text floated up
        room -= _gap(block) + len(block.lines) * block.leading
    return max(room, 0.0)


def to_pdf(handout: Handout, paper: str = "a4", style: str = "print") -> bytes:
    """The handout as a PDF, one page of `paper` (a4, letter) after another; the same handout gives the same bytes."""
    figures = page_figures(handout, paper, style)
    buffer = io.BytesIO()
    with render.style_context(style), kept_subsets():  # each font subset made once per process
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
