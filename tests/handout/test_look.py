"""What a teacher reading every page in greyscale found (issue 14 item 7), each kept fixed by a cheap unit check."""

from __future__ import annotations

import pytest

from helpers import history, particle_presets
from rodparadox.handout.narrative import setup_text


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
