"""Pages set like a book (issue 14, item 5), read from the page plan (`pdf.page_plan`: where each block lands) for
every preset, A4 and Letter, handout and worksheet: no heading or introduction left at a page's foot apart from
what follows it; a short table on one page with its introduction; every strip block under its frame's heading on
its page; a question with its answer lines on one page; no page more than a quarter empty but a section's last.

The plan is measured without drawing (no figure is rendered: `page_plan` lays out the same blocks `to_pdf` sets)."""

from __future__ import annotations

import functools

import pytest

from helpers import history, particle_presets
from rodparadox.handout.build import build
from rodparadox.handout.pdf import page_plan

#: one worker runs this file, so its shared fixtures are built once (`--dist loadgroup`, pyproject.toml)
pytestmark = pytest.mark.xdist_group("page_rules")

#: the speeds the plans are read at
#: the rules' quarter of a page (not the code's constant: a change of it must show here)
QUARTER = 0.25
THIRD = 1 / 3


SPEEDS = (0.6, 0.95)  # 0.3 too when the rules change (it found nothing 0.6 and 0.95 did not; each speed costs 3 s)


PAPERS = ("a4", "letter")


@functools.lru_cache(maxsize=None)
def _all_plans() -> dict[str, list]:
    """Per paper: each preset's handout and worksheet at each speed, and the plan of its pages. A document's plans
    on both papers are made one after the other: they measure the same blocks of strips, which
    `render.strip_windows.strips_at` keeps in a small cache that the other documents' strips would push out in between."""
    out: dict[str, list] = {paper: [] for paper in PAPERS}
    for v in SPEEDS:
        for name in particle_presets():
            for worksheet in (False, True):
                doc = build([(name, history(name, v))], worksheet=worksheet)
                for paper in PAPERS:
                    out[paper].append((f"{name} {'worksheet' if worksheet else 'handout'} v={v} {paper}", doc,
                                       page_plan(doc, paper)))
    return out


@pytest.fixture(scope="module", params=PAPERS)
def plans(request):
    """Per paper: each preset's handout and worksheet at each speed, and the plan of its pages."""
    return _all_plans()[request.param]


def _pairs(plan):
    blocks = [b for b in plan.blocks if b.pieces]
    return list(zip(blocks, blocks[1:]))


def test_no_heading_or_introduction_is_left_apart_from_what_follows_it(plans):
    """Unless, as a book floats a figure, the text after a picture fills the page the picture misses: the picture
    then starts the next page (after the rest of a paragraph split there), and a later block is on the
    introduction's page."""
    for label, _, plan in plans:
        pairs = _pairs(plan)
        for k, (block, following) in enumerate(pairs):
            if block.kind.startswith("heading") or (block.kind == "paragraph" and following.kind in
                                                     ("table", "picture")):
                page = block.pieces[-1][0]
                floated = (following.kind == "picture" and following.pieces[0][0] == page + 1
                           and any(later.pieces[0][0] == page for later, _ in pairs[k + 1:]))
                # its last line and the next block's first piece on one page
                assert block.pieces[-1][0] == following.pieces[0][0] or floated, (label, block, following)


def test_a_short_table_is_whole_and_on_its_introduction_s_page(plans):
    for label, _, plan in plans:
        for block, following in _pairs(plan):
            if following.kind == "table" and len(following.pieces) == 1:
                continue
            if following.kind == "table":
                top, bottom = following.pieces[0][1], following.pieces[-1][2]
                assert bottom - top > QUARTER * plan.text_height or len(following.pieces) > 1, (label,)
        for block in plan.blocks:
            if block.kind == "table" and len(block.pieces) > 1:
                height = sum(bottom - top for _, top, bottom in block.pieces)
                assert height > QUARTER * plan.text_height, (label, "a short table was split", block)


def test_every_strip_block_is_under_its_frame_s_heading_and_every_question_with_its_lines(plans):
    for label, doc, plan in plans:
        kinds = [b.kind for b in plan.blocks if b.kind != "break"]
        placed = [b for b in plan.blocks if b.kind != "break"]
        strips = [k for k, b in enumerate(doc.blocks()) if type(b).__name__ == "Strips"]
        headings = [b for b in doc.blocks() if type(b).__name__ == "Heading"]
        assert len(strips) == len([h for h in headings if h.text.startswith("The rod at successive instants of")])
        for k, block in enumerate(doc.blocks()):
            if type(block).__name__ == "Strips":
                before = doc.blocks()[k - 1]
                assert type(before).__name__ == "Heading" and before.text.endswith(
                    "of S" if block.frame.name == "rest" else "of S′"), (label, before)
                assert kinds[k - 1] == "heading2" and placed[k - 1].pieces[-1][0] == placed[k].pieces[0][0]
            if type(block).__name__ == "Question" and doc.worksheet and k < sum(len(x.blocks) for x in doc.sections):
                assert len({page for page, _, _ in placed[k].pieces}) == 1, (label, block.number)


def test_no_page_is_more_than_a_quarter_empty_but_a_section_s_last(plans):
    """A figure shrinks, a block of strips or a table is split between rows, a question's lines take a page's rest:
    only the last page of a section (or of the answer key, or the document) may be more than a quarter empty."""
    empty = []
    for label, _, plan in plans:
        ends = {}  # each page's lowest filled point
        for block in plan.blocks:
            for page, _, bottom in block.pieces:
                ends[page] = max(ends.get(page, 0.0), bottom)
        lasts = set()  # the pages after which a section (or the answer key) starts
        placed = [b for b in plan.blocks if b.pieces or b.kind == "break"]
        for block, following in zip(placed, placed[1:]):
            if following.kind in ("break", "heading1") and block.pieces:
                lasts.add(block.pieces[-1][0])
        for page in range(plan.pages - 1):
            if page not in lasts and ends.get(page, 0.0) < (1 - QUARTER) * plan.text_height:
                empty.append((label, page + 1, round(1 - ends.get(page, 0.0) / plan.text_height, 2)))
    assert not empty, empty


def _third_rule_pages(plans) -> list[tuple[str, int, float]]:
    """Every page the third rule reads (all but a document's last and the last before its key): (label, page,
    the part of it left empty)."""
    out = []
    for label, doc, plan in plans:
        ends = {}
        for block in plan.blocks:
            for page, _, bottom in block.pieces:
                ends[page] = max(ends.get(page, 0.0), bottom)
        in_sections = sum(len(s.blocks) for s in doc.sections)
        blocks = [b for b in plan.blocks if b.kind != "break"]
        key_pages = [p for b in blocks[in_sections:] for p, _, _ in b.pieces]
        before_key = min(key_pages) - 1 if key_pages else None
        out += [(label, page + 1, 1 - ends.get(page, 0.0) / plan.text_height) for page in range(plan.pages - 1)
                if page != before_key]
    return out


def test_a_figure_that_would_float_leaving_its_page_a_third_empty_shrinks_to_follow_its_introduction(plans):
    """Issue 24: single at 0.6 (and 0.3) floated its diagram to page 2, the text after it leaving page 1 33 % empty,
    at the third rule's very limit; a figure is set smaller after its introduction where floating would leave more
    than a quarter of the page: no page the third rule reads now comes within 5 % of it (the worst, 25 %)."""
    single = [(label, page, round(e, 3)) for label, page, e in _third_rule_pages(plans) if label.startswith("single")]
    assert single and all(e <= 0.25 for _, _, e in single), single
    assert max(e for _, _, e in _third_rule_pages(plans)) <= THIRD - 0.05


def test_no_page_is_more_than_a_third_empty_but_the_last_before_the_key_and_the_document_s_last(plans):
    """Issue 24: a section runs on after the last where a third of the page or more is left (a handout's first page
    held the paradox alone, 60 % empty); so a section's last page too is at most a third empty."""
    empty = [(label, page, round(e, 2)) for label, page, e in _third_rule_pages(plans) if e > THIRD]
    assert not empty, empty


def test_a_block_of_strips_split_between_pages_is_headed_again_on_the_next():
    """A block of strips split between rows went on at the next page's top with no heading (fig1 and fig2 at
    0.95): its rest is now headed "The rod at successive instants of S′ (continued)", a caption-sized line at the
    top of the page, set before the rows. Read off the plan: the block's first piece on a later page starts at the
    text area's top and is one line high (not a row of strips); at least one block is split, so this asks
    something."""
    split = 0
    for name in ("fig1", "fig2"):
        # the plans' own: build([(name, history(name, 0.95))]) and page_plan(doc, "a4"), made once
        [(doc, plan)] = [(d, p) for label, d, p in _all_plans()["a4"] if label == f"{name} handout v=0.95 a4"]
        for placed, block in zip([b for b in plan.blocks if b.kind != "break"], doc.blocks()):
            if type(block).__name__ != "Strips" or len({page for page, _, _ in placed.pieces}) < 2:
                continue
            split += 1
            first_page = placed.pieces[0][0]
            page, top, bottom = next(p for p in placed.pieces if p[0] > first_page)
            assert top == 0.0 and 0.0 < bottom - top <= 2 * 1.3 * 12, (name, placed.pieces)
    assert split >= 1


def test_a_worksheet_question_s_last_ruled_line_keeps_clear_of_the_footer_rule():
    """Found looking at every page: a question's lines ran to the text area's foot, 2 to 7 points above the
    footer's rule, and printed as a double rule (unequal_masses at 0.95 with both rods, page 4: 4 points). Read off
    the drawn pages: every answer line stays at least ANSWER_FOOT above its page's footer rule."""
    from rodparadox.handout.pdf import page_figures
    from rodparadox.handout.pdf_blocks import ANSWER_FOOT

    # the plans' worksheet whose lines came nearest the footer (5.7 points on page 2), a page set as any other
    doc = next(d for label, d, _ in _all_plans()["letter"] if label == "fig1 worksheet v=0.95 letter")
    gaps = []
    for figure in page_figures(doc, "letter", "print"):
        height = figure.get_size_inches()[1] * 72.0
        ys = {}
        for artist in figure.artists:
            if artist.get_gid() in ("answer-line", "footer-rule"):
                ys.setdefault(artist.get_gid(), []).append(float(artist.get_ydata()[0]) * height)
        if "answer-line" in ys:
            gaps.append(min(ys["answer-line"]) - max(ys["footer-rule"]))  # points, upward from the footer rule
    assert len(gaps) >= 2 and min(gaps) >= ANSWER_FOOT, gaps
