"""What a teacher reading every page in greyscale found (issue 14 item 7), each kept fixed by a cheap unit check."""

from __future__ import annotations

import functools
import math

import pytest

from helpers import history, particle_presets
from rodparadox.handout.narrative import setup_text


@functools.lru_cache(maxsize=None)
def fig1_compared(worksheet: bool = False):
    """fig1 at 0.6 with the causal rod beside the rigid one, as a handout or a worksheet: built once for the tests
    that read it."""
    from helpers import causal_history
    from rodparadox.handout.build import build

    return build([("fig1", history("fig1", 0.6), None, causal_history("fig1", 0.6))], worksheet=worksheet)


@pytest.mark.parametrize("name", particle_presets())
def test_the_setup_counts_its_particles(name):
    """`single` has one particle: its set-up said "the particles are where this paragraph puts them"."""
    h = history(name, 0.6)
    text = setup_text(h)
    if len(h.scenario.particles) == 1:
        assert "at which the particle is where this paragraph puts it." in text and "particles" not in text
    else:
        assert "at which the particles are where this paragraph puts them." in text


@pytest.mark.parametrize("name", ["fig2", "single"])
def test_every_sentence_of_a_ledger_tables_note_starts_with_a_capital(name):
    """The note under every ledger table read "... one row group. rod, dynamical (not a summand): E and p ...":
    a sentence starting in lower case. Each sentence of every note starts with a capital letter."""
    import re

    from rodparadox.physics.frames import paper_frames
    from rodparadox.tables import build as tables

    h = history(name, 0.6)
    for frame in paper_frames(h.scenario.v):
        for note in tables.ledger_table(h, frame).notes:
            starts = [m.group(1) for m in re.finditer(r"(?:^|\.\s+)(\w)", note)]
            assert starts and all(c.isupper() for c in starts), note


@pytest.mark.parametrize("name", ["single", "fig2"])
def test_the_last_question_before_the_key_takes_its_page_s_rest_to_write_on(name):
    """Worksheets at v = 0.3 (A4) left question 7 with five lines on a page 72-80 % empty before the key (a
    section's last page, so the page rules allowed it): its lines now fill the page, which is at most a quarter
    empty. Read from the page plan (nothing drawn)."""
    from rodparadox.handout.build import build
    from rodparadox.handout.pdf import page_plan

    plan = page_plan(build([(name, history(name, 0.3))], worksheet=True), "a4")
    placed = [b for b in plan.blocks if b.pieces or b.kind == "break"]
    last = next(b for b, f in zip(placed, placed[1:]) if f.kind == "break" and b.kind == "question")
    page = last.pieces[-1][0]
    bottom = max(bottom for b in plan.blocks for p, _, bottom in b.pieces if p == page)
    assert bottom >= 0.75 * plan.text_height
    assert len({p for p, _, _ in last.pieces}) == 1  # the question and all its lines on one page


@pytest.mark.parametrize("name", particle_presets())
def test_the_caption_names_each_particles_dashes_as_the_styles_draw_them(name):
    """The caption said "the particles A and B are dashed" after B became long-and-short dashed (told from S′'s
    dash-dotted lines in grey). Each particle's word is checked against its dash pattern in every style: A's an
    even on-off dash, B's two dashes of different lengths."""
    from rodparadox.handout.narrative import diagram_caption
    from rodparadox.physics.frames import paper_frames
    from rodparadox.render.styles import STYLES

    h = history(name)
    caption = diagram_caption(h, paper_frames(h.scenario.v))
    words = {"A": "dashed", "B": "long-and-short dashed"}
    for p in h.scenario.particles:
        assert f"the particle {p.name} is {words[p.name]}" in caption
        for style in STYLES.values():
            offset, pattern = style.particles[p.name].dashes
            dashes = set(pattern[0::2])
            assert len(dashes) == (2 if p.name == "B" else 1), (style.name, p.name, pattern)
    assert "are dashed" not in caption


# --- issue 24 item 8: every page of every preset's handout, worksheet and key at 0.3, 0.6, 0.95 in greyscale ------

def test_a_colour_bar_whose_end_is_its_centre_reads_in_few_digits():
    """single's causal rod from S′ at v = 0.3 moves from -0.3 to +0.3 c, and +0.3 is also the rod's velocity
    before the impact (the scale's centre): the end came out as +0.30000000000000004, and the ticks were written
    with 17 digits (−0.300000000000000032, 0.30000000000000004) to tell the end from the centre. A centre equal to an
    end up to rounding is that end: the bar reads −0.3 and 0.3."""
    from rodparadox.render.colour_scale import ColourScale
    from rodparadox.render.strip import colour_bar_ticks

    v = 0.3
    end = math.tanh(2 * math.atanh(v) - math.atanh(v))  # the rapidity 2θ less S′'s: v up to an ulp
    scale = ColourScale(v, 2 * math.atanh(v), (-end, end + 5.6e-17))
    assert scale.ends[1] != v  # the rounding the engine leaves
    assert colour_bar_ticks(scale, 150.0, 8.0)[1] == ["−0.3", "0.3"]
    # a centre truly inside keeps its tick (fig2 from S′ at 0.6: 0, 0.6, 0.882)
    inside = ColourScale(0.6, math.atanh(15 / 17) - math.atanh(0.6), (0.0, 15 / 17))
    assert colour_bar_ticks(inside, 150.0, 8.0)[1] == ["0", "0.6", "0.882"]


def test_the_causal_rods_stills_name_separations_and_contacts_not_impacts():
    """The causal rod's stills (fig1 at 0.3, S) labelled the row where both particles leave the ends "impacts A′₁,
    B′₁", though the diagram's key calls them separations (a hollow dot) and the contacts "contact (A₁)". Each row's
    note names what happens: contacts, separations; the rigid rod's rows still say impacts."""
    from matplotlib.figure import Figure

    from helpers import causal_history
    from rodparadox import render
    from rodparadox.handout.causal_compare import causal_strip_times
    from rodparadox.physics.frames import rest_frame

    def notes(h, times):
        figure = Figure(figsize=(6.5, 7.0), dpi=72)
        with render.style_context("print"):
            render.draw_strips_into(figure, h, rest_frame(), times, "print")
        return [t.get_text() for t in figure.findobj(lambda a: str(a.get_gid()).startswith("strips-impacts-"))]

    causal = causal_history("fig1", 0.3)
    found = notes(causal, causal_strip_times(causal, rest_frame()))
    assert found == ["contacts $A_{1}$, $B_{1}$", "separations $A$′$_{1}$, $B$′$_{1}$"]
    rigid = history("fig1", 0.3)
    assert notes(rigid, (5 / 3,)) == ["impacts $A_{1}$, $B_{1}$"]


def test_the_stills_caption_claims_no_centre_the_printed_scale_lacks():
    """The caption said "(the scale is centred on +0.6 c, the rod's velocity in S′ before it is struck)"; in print
    the scale runs from the slowest velocity (light) to the fastest (dark), and single's rod in S′ only slows from
    +0.6 c to rest: +0.6 c is the scale's dark end, not its centre. The caption names no centre."""
    from rodparadox.handout.strips import strip_times, strips_caption
    from rodparadox.physics.frames import paper_frames
    from rodparadox.render.colour_scale import colour_scale
    from rodparadox.render.strip import colour_norm

    h = history("single", 0.6)
    moving = paper_frames(0.6)[1]
    assert float(colour_norm(colour_scale(h, moving), "print")(0.6)) == pytest.approx(1.0)  # the dark end
    caption = strips_caption(h, moving, strip_times(h, moving))
    assert "centred" not in caption and "shaded by the velocity in S′" in caption


@pytest.mark.parametrize("worksheet", [False, True])
def test_no_paragraph_of_a_section_says_a_sentence_twice(worksheet):
    """Every table's paragraph was said in full for S and again for S′ ("The ledger in S′: at each instant of S′ at
    which the rod is struck (impacts at one instant taken together), the energy E and momentum p ...", and the
    causal rod's two), so each page held the same sentences twice. fig1 at 0.6 with the causal rod, as a handout
    and as a worksheet and its key: no sentence of the paragraphs (S′ read as S) comes twice in a section."""
    import collections
    import re

    from rodparadox.handout.document import Paragraph

    doc = fig1_compared(worksheet)
    for blocks in [s.blocks for s in doc.sections] + [doc.answer_key]:
        sentences = collections.Counter(
            s for b in blocks if isinstance(b, Paragraph)
            for s in re.split(r"(?<=[.:;])\s+", re.sub(r"([Sxt])\N{PRIME}", r"\1", b.text)) if len(s) > 40)
        assert not [s for s, k in sentences.items() if k > 1]


def test_the_causal_rods_table_heads_its_first_column_event():
    """The causal rod's table of contacts and separations headed its first column "impact", over rows such as A′₁,
    a particle leaving the end; its ledger says "event". Both say event; the rigid rod's table keeps "impact"."""
    from helpers import causal_history
    from rodparadox.handout.causal_compare import events_table
    from rodparadox.physics.frames import paper_frames
    from rodparadox.tables import build as tables

    for frame in paper_frames(0.6):
        assert events_table(causal_history("single", 0.6), frame).header[0] == "event"
        assert tables.events_table(history("single", 0.6), frame).header[0] == "impact"


def test_the_comparison_says_where_the_first_impacts_fall_once():
    """The comparison's paragraph said "Each particle's first impact: on the rigid rod A₁ and B₁ are simultaneous in
    S and 0.3145 L apart in S′; ..." just above the diagram whose note says the same ("The rigid rod: A₁ and B₁ are
    simultaneous in S (at 1.667 L), not in S′ (A₁ at 1.59 L, B₁ at 1.904 L)"). The note says it; the paragraph
    says where the particles start."""
    from helpers import causal_history
    from rodparadox.handout.build import build
    from rodparadox.handout.document import DiagramBlock, Paragraph
    from rodparadox.tables.comparison import comparison_note

    rigid, causal = history("fig1", 0.3), causal_history("fig1", 0.3)
    blocks = build([("fig1", rigid, None, causal)]).sections[1].blocks
    diagram = next(b for b in blocks if isinstance(b, DiagramBlock) and b.compared is not None)
    assert "A₁ and B₁ are simultaneous in S" in comparison_note((rigid, causal), diagram.frames)
    said = " ".join(b.text for b in blocks if isinstance(b, Paragraph))
    assert "first impact:" not in said and "A at x = −1 L and B at x = 1 L" in said


def test_the_ledgers_paragraph_leaves_to_its_note_what_the_note_says():
    """The paragraph above each ledger table ended "... which add up to the total, the same as before the first
    impact. Below them, apart, the rod's dynamical E and p, those of its momentum, which takes each impulse at once:
    not a summand.", and the note under the table says both again ("add up to the total, the total before the first
    impact ...; Rod, dynamical (not a summand): ..."). The paragraph says what the rows are; the note, once, how they
    add up and what the dynamical row is."""
    from rodparadox.handout.document import Paragraph, Table

    blocks = fig1_compared().sections[1].blocks
    ledgers = [(b.text, t) for b, t in zip(blocks, blocks[1:])
               if isinstance(b, Paragraph) and isinstance(t, Table) and t.name.startswith("ledger")]
    assert len(ledgers) == 4  # the rigid rod's in S and S′, the causal rod's (its note says the same of its parts)
    for text, table in ledgers:
        note = " ".join(table.notes)
        assert "add up to the total" in note and "add up to the total" not in text
        assert "not a summand" not in text and ("not a summand" in note or "causal" in table.name)


def test_a_particle_strikes_it_is_not_struck():
    """fig1's explanation said "Between them in S′, A has already been struck and B not yet": the particles strike
    the rod's ends (every other sentence says so); A has already struck."""
    from rodparadox.handout.narrative import explanation
    from rodparadox.physics.frames import paper_frames

    said = " ".join(p.text for p in explanation(history("fig1", 0.6), paper_frames(0.6)))
    assert "A has already struck and B not yet" in said and "been struck" not in said


def test_the_far_end_question_leaves_b1s_time_to_the_table():
    """fig1's worksheet asked "A₁ strikes the left end ... at the time t your table of S gives for A₁. B₁ strikes the
    right end at the same instant of S.", while the table of S leaves B₁'s t blank: the question filled it. It points
    to the table for B₁ as for A₁, and still says its time in the key."""
    from helpers import causal_history
    from rodparadox.handout.causal_reading import compare
    from rodparadox.handout.worksheet_causal import question_far_end
    from rodparadox.physics.frames import paper_frames

    rigid, causal = history("fig1", 0.6), causal_history("fig1", 0.6)
    asked = question_far_end(compare(rigid, causal, paper_frames(0.6)))
    assert "same instant" not in asked.text and "the time your table of S gives for B₁" in asked.text
    assert "t = 5/6 L" in " ".join(asked.answer)
