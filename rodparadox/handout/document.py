"""A handout as frozen blocks: what it says, not how it is set. Pure, no drawing, no LaTeX.

`handout.build` builds these from a scenario's history; `handout.pdf` sets them
on pages with matplotlib and `handout.tex` writes them as LaTeX, so the PDF and
the LaTeX say the same words and show the same numbers.

Text is plain Unicode (B₁, t′, γ, −, ×), one paragraph per `Paragraph`; a
renderer wraps it. A table is a `tables.table.Table` of `Cell`s (re-exported
here), cells of text as they should be printed; a cell marked `blank` is one a
worksheet leaves empty (ruled) for the student to fill in, and the answer key
prints the same table with every cell filled.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Union

from rodparadox.physics.history import RodHistory
from rodparadox.physics.frames import Frame, frame_symbol
from rodparadox.tables.table import ALIGNS, Cell, Table  # noqa: F401 (a handout's tables: re-exported)

#: paper sizes in inches (width, height): ISO A4 (210 x 297 mm) and US Letter
PAPERS = {"a4": (210 / 25.4, 297 / 25.4), "letter": (8.5, 11.0)}


@dataclass(frozen=True)
class Heading:
    """A heading: level 1 a scenario's section, level 2 a part of it."""

    text: str
    level: int = 1

    def __post_init__(self) -> None:
        if self.level not in (1, 2):
            raise ValueError(f"a heading's level is 1 or 2, got {self.level!r}")


@dataclass(frozen=True)
class Paragraph:
    """One paragraph of running text."""

    text: str


@dataclass(frozen=True)
class DiagramBlock:
    """A place in the document for the two-frame (or more) Minkowski diagram of a history, as `plot` draws it, full
    text width (the drawn diagram is `render.Diagram`)."""

    name: str
    history: RodHistory
    frames: tuple[Frame, ...]
    caption: str
    #: the panels' titles give the rod's velocity before and after (a worksheet asks it: only "(a) frame S" there)
    tell: bool = True
    #: every panel drawn to one scale (one length of L as long on the page in each)
    equal_scales: bool = False
    #: the causal rod's history of the same scenario: its row of panels drawn under the rigid rod's, in the same
    #: frames, each frame's two panels on one scale (`render.draw_both`)
    compared: object = None

    @property
    def drawn(self):
        """What the renderer draws: the history, or (rigid, causal) for two rows."""
        return self.history if self.compared is None else (self.history, self.compared)

    def retitle(self, diagram) -> None:
        """After `render.draw_into` or `render.draw` (a `render.Diagram`): a block that does not tell names only
        each panel's frame in its title, "(b) frame S′", never "rod first at +0.6, finally at +0.3846"."""
        if not self.tell:
            for panel in diagram.panels:
                panel.axes.title.set_text(f"({panel.letter}) frame {frame_symbol(panel.frame)}")


@dataclass(frozen=True)
class RodViewBlock:
    """The rod's own view (`--frame rod`): each history's chart, the rod a fixed strip, side by side (the rigid rod
    first, then the causal rod), full text width (`render.draw_rod_view_into`)."""

    name: str
    histories: tuple
    caption: str

    @property
    def history(self):
        return self.histories[0]


@dataclass(frozen=True)
class Strips:
    """The rod and the particles in one frame's space at successive instants of that frame's time (the strip of
    `animate`, as stills), earliest first. `subject`: what the heading of a part set on the next page calls the
    rod ("The causal rod" beside the rigid one). `partners`: the other rods compared in this frame, each with its
    block's instants, whose blocks share this one's x range and colour scale (`render.draw_strips_into`)."""

    name: str
    history: RodHistory
    frame: Frame
    times: tuple[float, ...]
    caption: str
    subject: str = "The rod"
    partners: tuple[tuple[RodHistory, tuple[float, ...]], ...] = ()


@dataclass(frozen=True)
class Fact:
    """One thing a question asks for, as every text that would state it: a number's printed forms (`number`: found
    only standing alone, no digit either side: 0.8824 is not in 10.88241) or a claim's phrases ("B₁ and A₁",
    "simultaneous in S′"). A worksheet prints none of them before its answer key (a question may ask in words its
    own claim, never print its own number)."""

    what: str
    forms: tuple[str, ...]
    number: bool = False


@dataclass(frozen=True)
class Question:
    """A worksheet question, its worked answer (paragraphs), which the answer key prints, and the facts it asks."""

    number: int
    text: str
    answer: tuple[str, ...]
    asks: tuple[Fact, ...] = ()


@dataclass(frozen=True)
class PageBreak:
    """Start a new page here."""


Block = Union[Heading, Paragraph, Table, DiagramBlock, RodViewBlock, Strips, Question, PageBreak]


@dataclass(frozen=True)
class Section:
    """One scenario's part of the document; `name` is its stem (fig2), file-safe."""

    name: str
    title: str
    blocks: tuple[Block, ...]


@dataclass(frozen=True)
class Handout:
    """The whole document: a title, a section per scenario, and for a worksheet the answer key's blocks (the filled
    tables and the worked answers), printed from a new page at the end."""

    title: str
    sections: tuple[Section, ...]
    worksheet: bool = False
    answer_key: tuple[Block, ...] = ()

    def blocks(self) -> tuple[Block, ...]:
        """Every block in order, sections first, then the answer key."""
        return tuple(b for s in self.sections for b in s.blocks) + self.answer_key
