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
