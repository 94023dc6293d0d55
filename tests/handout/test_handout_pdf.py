"""`handout_pdf.to_pdf`: a handout's blocks set on pages as a PDF (issue 9, items 1-2, 5-7). Handouts are built by
hand from document blocks (`handout_samples`); the PDF is read back with pypdf (page sizes, text, fonts)."""

from __future__ import annotations

import functools
import io
import re

import matplotlib
import pypdf
import pytest
from matplotlib.axes import Axes
from matplotlib.backends.backend_mixed import MixedModeRenderer
from matplotlib.backends.backend_pdf import PdfFile, RendererPdf
from matplotlib.lines import Line2D
from matplotlib.patches import Rectangle
from matplotlib.transforms import Bbox
from matplotlib.text import Text

from handout_samples import handout
from rodparadox import render
from rodparadox.tables import build as tables
from rodparadox.handout.document import Cell, Handout, Heading, PageBreak, Paragraph, Question, Section, Table
from rodparadox.physics.rigid import run
from rodparadox.physics.frames import paper_frames
from rodparadox.handout.pdf import page_figures, to_pdf
from rodparadox.handout.pdf_text import MARGIN, TextRuns, Type
from rodparadox.io.scenario import load
from rodparadox.render.styles import STYLES

LOREM = ("The rod is struck at both ends by equal and opposite impulses that are simultaneous in its rest frame, "
         "and keeps its velocity in every frame, even where the impacts are not simultaneous.")


def pages_text(pdf: bytes) -> list[str]:
    return [page.extract_text() for page in pypdf.PdfReader(io.BytesIO(pdf)).pages]


def text_only(*sections: Section, worksheet: bool = False, key=()) -> Handout:
    return Handout("A test handout", tuple(sections), worksheet, tuple(key))


#: the tests that read `fig2_handout` run in one worker, which builds it once
ON_FIG2_HANDOUT = pytest.mark.xdist_group("fig2_handout")


@functools.lru_cache(maxsize=None)
def fig2_printed():
    """`handout_samples`' fig2 handout, `to_pdf(h)`, and the pages that call set (`page_figures(h, "a4", "print")`,
    which `to_pdf` calls through the module `rodparadox.handout.pdf`: caught on its way out, not set again), for the
    tests of the PDF and the margins test of the same pages. Read only."""
    from rodparadox.handout import pdf as pdf_module

    h = handout("fig2")
    set_pages, caught = pdf_module.page_figures, []

    def catching(*args, **kwargs):
        caught.append((args, kwargs, set_pages(*args, **kwargs)))
        return caught[-1][2]

    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(pdf_module, "page_figures", catching)
        pdf = to_pdf(h)
    [(args, kwargs, figures)] = caught
    assert (args, kwargs) == ((h, "a4", "print"), {})  # the pages the margins test would set
    return h, pdf, figures


@pytest.fixture(scope="module")
def fig2_handout():
    h, pdf, _ = fig2_printed()
    return h, pdf


@pytest.fixture(scope="module")
def fig2_worksheet():
    h = handout("fig2", worksheet=True)
    return h, to_pdf(h)


# --- the paper ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("paper, size", [("a4", (595.28, 841.89)), ("letter", (612.0, 792.0))])
def test_every_page_has_the_paper_s_size(paper, size):
    pdf = to_pdf(text_only(Section("s", "s", (Heading("One"), Paragraph(LOREM), PageBreak(), Paragraph(LOREM)))),
                 paper)
    reader = pypdf.PdfReader(io.BytesIO(pdf))
    assert len(reader.pages) == 2
    for page in reader.pages:
        assert (float(page.mediabox.width), float(page.mediabox.height)) == pytest.approx(size, abs=0.01)


def test_unknown_paper_or_style_is_refused_in_one_sentence():
    h = text_only(Section("s", "s", (Paragraph(LOREM),)))
    with pytest.raises(ValueError, match=r"^unknown paper size 'a5'; use one of a4, letter$"):
        to_pdf(h, "a5")
    with pytest.raises(ValueError, match=r"^unknown style 'poster'; use one of default, print, slides$"):
        to_pdf(h, style="poster")


# --- pages: how many, and where they break ---------------------------------------------------------------

def test_page_count_of_a_handout_of_known_length():
    """Three sections (a level-1 heading after the first starts a page only where less than a third of the page is
    left: "two" runs on after "one"), a page break in the second, and a worksheet's answer key on a page of its own:
    4 pages; a page break at the top of a page adds none."""
    sections = [Section("one", "one", (Heading("One"), Paragraph(LOREM))),
                Section("two", "two", (Heading("Two"), Paragraph(LOREM), PageBreak(), Paragraph(LOREM))),
                Section("three", "three", (PageBreak(), Heading("Three"), Paragraph(LOREM)))]
    key = (Heading("Answer key"), Question(1, "Why?", ("Because.",)))
    sheet = text_only(*sections, worksheet=True, key=key)
    texts = pages_text(to_pdf(sheet))
    assert len(texts) == 4
    assert [t.split("\n")[0][:17] for t in texts] == ["One", "The rod is struck", "Three", "Answer key"]
    assert "\nTwo\n" in texts[0]
    for k, text in enumerate(texts, start=1):
        assert f"page {k} of 4" in text and "A test handout" in text


def test_paragraphs_fill_pages_and_are_split_between_lines_only():
    """Sixty paragraphs of two or three lines: more than two pages; every word of every paragraph is on some page,
    in order."""
    paragraphs = tuple(Paragraph(f"Paragraph {k}. {LOREM}") for k in range(60))
    texts = pages_text(to_pdf(text_only(Section("s", "s", paragraphs))))
    assert len(texts) >= 3
    body = " ".join(re.sub(r"A test handout\s*page \d+ of \d+", "", t) for t in texts).split()
    assert body == " ".join(p.text for p in paragraphs).split()


def fillers(n: int) -> tuple[Paragraph, ...]:
    return tuple(Paragraph(f"Filler {k}. {LOREM}") for k in range(n))


#: the two tests that ask `most_fillers_on_one_page` run in one worker, which searches once
ON_FILLERS = pytest.mark.xdist_group("handout_pdf_fillers")


@functools.lru_cache(maxsize=None)  # two tests ask; the search sets a page a dozen times
def most_fillers_on_one_page() -> int:
    n = 1
    while len(page_figures(text_only(Section("s", "s", fillers(n + 1))))) == 1:
        n += 1
    return n


def long_table(rows: int, grouped: bool = False) -> Table:
    """A table of `rows` rows with distinct cells; grouped: rows in threes, the 2nd and 3rd with an empty first cell
    (a ledger's impact)."""
    body = tuple((Cell(f"R{i}" if not grouped or i % 3 == 0 else ""), Cell(f"row{i}left"),
                  Cell(f"{i}.{i:04d}"), Cell(f"−{i}.5")) for i in range(rows))
    return Table("long", "A long table", ("name", "words", "value", "other"), body, "llnn", ("A note.",))


@pytest.mark.parametrize("grouped", [False, True])
def test_a_table_longer_than_a_page_is_split_between_rows_with_its_header_repeated(grouped):
    table = long_table(120, grouped)
    texts = pages_text(to_pdf(text_only(Section("s", "s", (Heading("Tables"), Paragraph(LOREM), table)))))
    on = [[k for k, t in enumerate(texts) if re.search(rf"\brow{i}left\b", t)] for i in range(120)]
    assert all(len(pages) == 1 for pages in on)  # every row once
    for i, row in enumerate(table.rows):  # every cell of a row on the row's page
        for cell in row:
            if cell.text:
                assert cell.text in texts[on[i][0]], (i, cell.text)
    pages = sorted({p[0] for p in on})
    assert len(pages) >= 3
    for k in pages:  # the header on every page the table is on; its caption, continued after the first
        assert "name words value other" in texts[k]
        assert ("A long table (continued)" in texts[k]) == (k != pages[0])
    assert "A note." in texts[pages[-1]] and all("A note." not in texts[k] for k in pages[:-1])
    if grouped:  # a group of three rows is never split
        for i in range(0, 120, 3):
            assert on[i] == on[i + 1] == on[i + 2]


@ON_FILLERS
def test_a_table_that_does_not_fit_the_rest_of_the_page_is_split_between_rows_rather_than_leave_it_empty():
    """Three fillers fewer than fill a page leave room for a two-row table, and for the start of a twelve-row table
    but not all of it: that one starts there, taller than a quarter page, and goes on on the next page under its
    header again, every row once (a page is not left a quarter empty for a table that can be split)."""
    n = most_fillers_on_one_page() - 3
    short = pages_text(to_pdf(text_only(Section("s", "s", fillers(n) + (long_table(2),)))))
    assert len(short) == 1 and "row1left" in short[0]
    texts = pages_text(to_pdf(text_only(Section("s", "s", fillers(n) + (long_table(12),)))))
    assert len(texts) == 2
    assert f"Filler {n - 1}." in texts[0] and "A long table" in texts[0] and "row0left" in texts[0]
    assert "A long table (continued)" in texts[1]
    assert [sum(f"row{i}left" in t for t in texts) for i in range(12)] == [1] * 12


@ON_FILLERS
def test_a_heading_is_never_left_alone_at_the_foot_of_a_page():
    """After one filler fewer than fill a page, a heading alone fits, a heading and the start of a table do not:
    the heading goes to the next page with the table."""
    n = most_fillers_on_one_page() - 1
    alone = pages_text(to_pdf(text_only(Section("s", "s", fillers(n) + (Heading("Late heading", 2),)))))
    assert len(alone) == 1 and "Late heading" in alone[0]
    texts = pages_text(to_pdf(text_only(Section("s", "s", fillers(n) + (Heading("Late heading", 2),
                                                                        long_table(5))))))
    assert len(texts) == 2 and "Late heading" not in texts[0]
    assert "Late heading" in texts[1] and "row0left" in texts[1]
    # three fillers fewer: room for the heading and the start of a twelve-row table, which is not split but moves
    # to the next page whole, and takes its heading along
    n -= 2
    texts = pages_text(to_pdf(text_only(Section("s", "s", fillers(n) + (Heading("Late heading", 2),
                                                                        long_table(12))))))
    assert len(texts) == 2 and "Late heading" not in texts[0]
    assert "Late heading" in texts[1] and "row0left" in texts[1]


# --- the text read back ---------------------------------------------------------------------------------------

@ON_FIG2_HANDOUT
def test_the_text_holds_every_events_cell_and_every_paragraph_s_words(fig2_handout):
    h, pdf = fig2_handout
    text = "\n".join(pages_text(pdf))
    history = run(load("fig2"))
    for frame in paper_frames(0.6):
        table = tables.events_table(history, frame)
        assert table.caption in text
        for row in table.rows:
            for cell in row:
                assert cell.text in text, cell.text
    words = set(text.split())
    for block in h.sections[0].blocks:
        if isinstance(block, Paragraph):  # every apostrophe set typographic (issue 24): observer's as observer’s
            assert set(block.text.replace("'", "’").split()) <= words
    headings = [b.text for b in h.sections[0].blocks if isinstance(b, Heading) and "'" in b.text]
    assert headings and all(t.replace("'", "’") in text and t not in text for t in headings)
    # Unicode minus, primes and subscripts come back as written
    for sample in ("−0.600000", "+1.416667 (17/12)", "t′", "x′", "B₁", "A₁", "frame S′", "E in M c²"):
        assert sample in text
    assert "page 1 of" in text and h.title in text


def test_a_worksheet_leaves_its_blank_cells_out_of_its_sections_and_its_answer_key_holds_them(fig2_worksheet):
    h, pdf = fig2_worksheet
    texts = pages_text(pdf)
    key = next(k for k, t in enumerate(texts) if t.startswith("Answer key"))
    sections, answers = "\n".join(texts[:key]), "\n".join(texts[key:])
    events = [b for b in h.sections[0].blocks if isinstance(b, Table) and b.name.startswith("events")]
    assert len(events) == 2
    blank = {c.text for table in events for row in table.rows for c in row if c.blank}
    assert len(blank) >= 10
    for number in blank:
        assert number not in sections, number
        assert number in answers, number
    # labels stay: the impacts and ends are printed in the worksheet too
    assert all(word in sections for word in ("B₁", "A₁", "B₂", "right", "left"))


def test_fonts_are_embedded_truetype():
    pdf = to_pdf(text_only(Section("s", "s", (Heading("One"), Paragraph(LOREM + " t′ = −17/12, B₁")))))
    reader = pypdf.PdfReader(io.BytesIO(pdf))
    fonts = reader.pages[0]["/Resources"]["/Font"]
    assert len(fonts) >= 2
    for ref in fonts.values():
        font = ref.get_object()
        descendant = font["/DescendantFonts"][0].get_object()
        assert font["/Subtype"] == "/Type0" and "/ToUnicode" in font
        assert "/FontFile2" in descendant["/FontDescriptor"]  # TrueType, embedded


@ON_FIG2_HANDOUT
def test_the_diagrams_and_strips_are_vector(fig2_handout):
    _, pdf = fig2_handout
    assert b"/Subtype /Image" not in pdf


# --- the same bytes -----------------------------------------------------------------------------------------

@ON_FIG2_HANDOUT
def test_two_runs_give_the_same_bytes(fig2_handout):
    h, pdf = fig2_handout
    # built again in one process, the same bytes: test_handout_cli's first test (`handout fig2 --v 0.6` twice, the
    # second reported unchanged) calls to_pdf twice on a fig2 handout, new histories and figures; here it is read
    assert b"CreationDate" not in pdf and b"Producer" not in pdf and b"matplotlib" not in pdf.lower()
    # across processes (other hash seeds): test_determinism, with `handout fig1 --worksheet`


# --- inside the margins ------------------------------------------------------------------------------------

def pdf_renderer(figure):
    """The renderer the PDF is drawn with (Agg's hinting at 72 dpi would widen texts by several per cent)."""
    return RendererPdf(PdfFile(io.BytesIO()), 72, figure.bbox.height, figure.bbox.width)


#: each run's (width, height, descent) as the PDF renderer measures it (unhinted, in points, whatever the page), by
#: text, font and the style's font settings: the pages repeat their words, headers and numbers
_RUN_SIZES: dict = {}


def run_box(run, renderer) -> Bbox:
    """Where a run of the page's text is drawn, as the PDF renderer measures it (not the typesetter's widths)."""
    rc = matplotlib.rcParams
    key = (type(renderer), run.text, run.font, tuple(rc["font.family"]), tuple(rc["font.sans-serif"]),
           tuple(rc["font.serif"]), rc["pdf.use14corefonts"], rc["text.kerning_factor"])
    if key not in _RUN_SIZES:
        _RUN_SIZES[key] = renderer.get_text_width_height_descent(run.text, run.font, ismath=False)
    w, h, d = _RUN_SIZES[key]
    left = run.x - {"left": 0.0, "center": 0.5, "right": 1.0}[run.ha] * w
    return Bbox([[left, run.y - d], [left + w, run.y - d + h]])


def page_runs(figure) -> list:
    return [run for artist in figure.findobj(TextRuns) for run in artist.runs]


class MeasuringPdf(RendererPdf):
    """The PDF renderer, measuring texts as it does but writing nothing: where an artist goes is worked out before
    it calls a draw_* method (axis labels from their tick labels' extents, measured by the renderer), so a page
    drawn with it places everything where the PDF renderer does; writing the page's content (text set glyph by
    glyph) was most of the drawing's time."""

    def _nothing(self, *args, **kwargs):
        return None

    draw_path = draw_markers = draw_path_collection = draw_quad_mesh = draw_gouraud_triangles = _nothing
    draw_image = draw_text = draw_mathtext = draw_tex = _nothing


def draw_as_pdf(figure) -> None:
    """Draw a page as `savefig(format="pdf")` does (matplotlib's `FigureCanvasPdf.print_pdf`), without finishing the
    file or writing its content (`MeasuringPdf`): this places what is placed at drawing time (axis labels);
    finishing, which embeds the fonts, places nothing and took most of this file's time."""
    width, height = figure.get_size_inches()
    file = PdfFile(io.BytesIO())
    file.newPage(width, height)
    renderer = MixedModeRenderer(figure, width, height, 72, MeasuringPdf(file, 72, height, width))
    figure.draw(renderer)
    renderer.finalize()


def drawn_extents(figure, style):
    """Every visible text's and every axes' extent on a page (points, y up), as the PDF renderer draws them: the
    page's own text runs, and the texts and axes of the diagrams and strips drawn into it."""
    with render.style_context(style):
        draw_as_pdf(figure)  # places what is placed at drawing time (axis labels)
        renderer = pdf_renderer(figure)
        texts = [a for a in figure.findobj(Text) if a.get_visible() and a.get_text().strip()]
        axes = [a for a in figure.findobj(lambda a: isinstance(a, Axes))]
        return ([(run.text, run_box(run, renderer)) for run in page_runs(figure)]
                + [(t.get_text(), t.get_window_extent(renderer)) for t in texts]
                + [(a.get_gid() or "axes", a.get_tightbbox(renderer)) for a in axes])


@pytest.mark.parametrize("paper, style, worksheet", [pytest.param("a4", "print", False, marks=ON_FIG2_HANDOUT),
                                                     ("letter", "print", True), ("a4", "default", True),
                                                     ("letter", "slides", False)])
def test_nothing_is_drawn_outside_the_margins(paper, style, worksheet):
    if (paper, style, worksheet) == ("a4", "print", False):  # the pages `fig2_handout`'s to_pdf set and saved
        figures = fig2_printed()[2]
    else:
        figures = page_figures(handout("fig2", worksheet=worksheet), paper, style)
    for k, figure in enumerate(figures):
        width, height = figure.bbox.width, figure.bbox.height  # points: dpi 72
        assert figure.dpi == 72
        for what, box in drawn_extents(figure, style):
            assert MARGIN - 0.5 <= box.x0 and box.x1 <= width - MARGIN + 0.5, (k, what, box)
            assert MARGIN - 0.5 <= box.y0 and box.y1 <= height - MARGIN + 0.5, (k, what, box)


def test_a_worksheet_s_blank_cells_are_boxes_at_least_as_wide_as_their_numbers():
    history = run(load("fig2"))
    rest, moving = paper_frames(0.6)
    blank = (tables.events_table(history, moving, blank=True), tables.ledger_table(history, rest, blank=True))
    sheet = text_only(Section("s", "s", blank))
    filled = text_only(Section("s", "s", tuple(t.filled() for t in blank)))
    [sheet_page], [filled_page] = page_figures(sheet), page_figures(filled)
    boxes = {a.get_gid(): a for a in sheet_page.findobj(Rectangle) if (a.get_gid() or "").endswith("-blank")}
    numbers = {run.gid: run for run in page_runs(filled_page) if run.gid}
    assert len(boxes) == sum(c.blank for t in blank for row in t.rows for c in row) == 18 + 3 + 72  # the events: 3 x 6 numbers; the ledger: 3 times, 3 x 6 rows x 4 numbers
    assert not [run for run in page_runs(sheet_page) if run.gid in numbers and (run.gid + "-blank") in boxes]
    with render.style_context("print"):
        renderer = pdf_renderer(filled_page)
        for gid, box in boxes.items():
            number = run_box(numbers[gid.removesuffix("-blank")], renderer)
            w = box.get_width() * sheet_page.bbox.width
            assert w >= number.width, (gid, w, number.width)
            assert box.get_height() * sheet_page.bbox.height >= 1.2 * Type.of(STYLES["print"]).table


def test_numbers_columns_are_aligned_at_the_decimal_point():
    numbers = ("+1.5", "−12.25", "0", "3.333 (10/3)")
    table = Table("t", "Numbers", ("value",), tuple((Cell(text),) for text in numbers), "n")
    [page] = page_figures(text_only(Section("s", "s", (table,))))
    runs = {run.text: run for run in page_runs(page) if run.gid and run.gid.startswith("t-")}
    with render.style_context("print"):
        renderer = pdf_renderer(page)
        size = Type.of(STYLES["print"]).table
        points = [run_box(runs[s], renderer).x0 + render.text_size(head, size)[0]
                  for s, head in (("+1.5", "+1"), ("−12.25", "−12"), ("0", "0"), ("3.333 (10/3)", "3"))]
    assert max(points) - min(points) < 0.5


# --- questions ------------------------------------------------------------------------------------------------

def test_a_worksheet_question_has_ruled_lines_and_the_answer_key_its_worked_answer():
    question = Question(3, "What is the rod's velocity in S′ just after A₁?", ("It is +0.882353 (15/17).",))
    sheet = text_only(Section("s", "s", (Heading("Questions"), question)), worksheet=True,
                      key=(Heading("Answer key"), question))
    figures = page_figures(sheet)
    texts = pages_text(to_pdf(sheet))
    assert len(texts) == 2
    assert "Question 3." in texts[0] and "+0.882353" not in texts[0]
    assert "Question 3." in texts[1] and "It is +0.882353 (15/17)." in texts[1]
    ruled = [line for line in figures[0].findobj(Line2D) if line.get_gid() == "answer-line"]
    assert len(ruled) >= 3  # as the last question before the key, its page's rest (tests/handout/test_look.py)
    assert not [line for line in figures[1].findobj(Line2D) if line.get_gid() == "answer-line"]


# --- the sizes the page leaves for a diagram and for strips ----------------------------------------------------

@pytest.mark.parametrize("style", ["print", "default", "slides"])
def test_natural_size_is_the_size_draw_gives_on_the_style_s_page(style):
    history, frames = run(load("fig2")), paper_frames(0.6)
    st = STYLES[style]
    figure = render.draw(history, frames, style).figure
    size = render.natural_size(history, frames, st.max_width * 72, st.max_height * 72, style)
    assert size == pytest.approx((figure.bbox.width, figure.bbox.height), abs=1e-6)
    width, height = render.natural_size(history, frames, 400.0, 1000.0, style)  # a narrower page bounds it
    assert width <= 400.0 and height <= 1000.0 and (width, height) != pytest.approx(size)


@pytest.mark.parametrize("style", ["print", "slides"])
def test_strips_size_is_the_least_target_draw_strips_into_accepts(style):
    from matplotlib.figure import Figure

    history = run(load("fig2"))
    frame = paper_frames(0.6)[1]
    times = (0.5, 1.0, 1.416666666666667, 2.0)
    width, height = render.strips_size(history, frame, times, style)
    assert render.strips_size(history, frame, times, style, 1.5)[1] > height
    render.draw_strips_into(Figure(figsize=(6.0, height / 72), dpi=72), history, frame, times, style)
    with pytest.raises(ValueError, match="4 strips need at least"):
        render.draw_strips_into(Figure(figsize=(6.0, (height - 2.0) / 72), dpi=72), history, frame, times, style)


def test_a_table_without_rows_and_a_table_wider_than_the_page_are_set_inside_the_margins():
    empty = Table("empty", "Nothing happened", ("impact", "x"), (), "ln", ("No impact.",))
    wide = Table("wide", "Twelve long columns", tuple(f"column {k}" for k in range(12)),
                 ((tuple(Cell(f"+{k}.123456 ({k}/7)") for k in range(12))),), "n" * 12)
    [page] = page_figures(text_only(Section("s", "s", (empty, wide))))
    texts = [run.text for run in page_runs(page)]
    assert {"Nothing happened", "impact", "x", "No impact.", "column 11", "+11.123456 (11/7)"} <= set(texts)
    for what, box in drawn_extents(page, "print"):
        assert MARGIN - 0.5 <= box.x0 and box.x1 <= page.bbox.width - MARGIN + 0.5, (what, box)
