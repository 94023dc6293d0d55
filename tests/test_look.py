"""What a teacher reading every page in greyscale found (issue 14 item 7), each kept fixed by a cheap unit check."""

from __future__ import annotations

import pytest

from conftest import history
from rodparadox.handout.narrative import setup_text
from rodparadox.io.scenario import builtin_names


@pytest.mark.parametrize("name", builtin_names())
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
