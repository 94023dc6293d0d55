"""Student-facing text names no software (issue 24, item 2): every document of every preset (handout, worksheet and
its answer key; both rods compared, the rod's own view, L other than 1) searched for a word list: the README, the
command and its options, file names, internal labels (B1s, fig2), "the tool"; and units said as a textbook says
them. The figures' drawn words are searched by `test_worksheet_tells_nothing` (its pages) with the same list."""

from __future__ import annotations

import functools
import re

import pytest

from handout_shared import causal_alike
from helpers import history, particle_presets
from rodparadox.handout.build import build
from rodparadox.handout.document import Heading, Paragraph, Question, Table
from rodparadox.handout.own_view import with_rod_views

#: one worker runs this file: its module fixture is built once, not once per worker; with the worksheets of
#: test_worksheet_tells_nothing, which compare the same causal rods (`handout_shared.causal_alike`, run once)
pytestmark = pytest.mark.xdist_group("worksheet_tells_nothing")

#: what a student must never read: the software, its files and options, its internal names
SOFTWARE = re.compile(
    r"README|(?-i:sears[-_]paradox)|rodparadox|\bpython\b|matplotlib|\.ya?ml\b|\.pdf\b|\.tex\b|\.csv\b|\.json\b|(?<!\w)--\w"
    r"|\bthe tool\b|\btool[’']s\b|\bcommand\b|\boption\b|\bflag\b|as the ledger does|\bB1s\b|\b[AB]\d+s?\b"
    r"|\bfig[12]\b|\bunequal_masses\b|\boff_timing\b|\bwhile_turning\b|unit L is given in|\bcode\b",
    re.IGNORECASE)


def words_of(doc) -> list[str]:
    """Every piece of text of the document, the answer key included: headings, paragraphs, captions, tables (their
    captions, headers, cells and notes), questions and their worked answers."""
    out = [doc.title]
    for b in doc.blocks():
        if isinstance(b, (Heading, Paragraph)):
            out.append(b.text)
        elif isinstance(b, Table):
            out += [b.caption, *b.header, *b.notes] + [c.text for row in b.rows for c in row]
        elif isinstance(b, Question):
            out += [b.text, *b.answer]
        elif hasattr(b, "caption"):
            out.append(b.caption)
    return out


def software_words(doc) -> list[tuple[str, str]]:
    return [found for text in words_of(doc) for found in _software_in(text)]


@functools.lru_cache(maxsize=None)
def _software_in(text: str) -> tuple[tuple[str, str], ...]:
    """Each software word in one text, with its context: searched once per text (the documents share most of their
    texts, and a planted document all but one: the search of the word list took a second of this file)."""
    return tuple((m.group(), text[max(0, m.start() - 40):m.end() + 40]) for m in SOFTWARE.finditer(text))


@pytest.fixture(scope="module")
def documents():
    """Every preset's handout and worksheet with both rods compared and the rod's own view, at v = 0.6 (and fig2
    with L = 2, whose tables are in the unit of L's own length)."""
    names = particle_presets()
    items = [(n, history(n, 0.6), None, causal_alike(n, 0.6)) for n in names]
    views = {n: (history(n, 0.6), causal_alike(n, 0.6)) for n in names}
    long_rod = [("fig2", history("fig2", 0.6, 2.0), None, causal_alike("fig2", 0.6, 2.0))]
    return {f"{kind}{'' if not extra else ' L = 2'}": with_rod_views(build(chosen, worksheet=kind == "worksheet"),
                                                                      views if not extra else {})
            for kind in ("handout", "worksheet") for extra, chosen in ((False, items), (True, long_rod))}


@pytest.mark.parametrize("kind", ["handout", "worksheet", "handout L = 2", "worksheet L = 2"])
def test_no_document_names_the_software(documents, kind):
    found = software_words(documents[kind])
    assert not found, "\n".join(map(str, found))


def test_units_are_said_as_a_textbook_says_them(documents):
    text = " ".join(words_of(documents["handout L = 2"]))
    assert "in the unit of length in which L = 2" in text and "unit L is given in" not in text


@pytest.mark.parametrize("planted", ["(README, “The causal rod”)", "the tool runs the scenario again",
                                     "sears-paradox events", "(B1s)", "--rod both", "in the unit L is given in",
                                     "fig2_handout.pdf", "added up along it as the ledger does"])
def test_a_software_word_planted_in_a_document_is_found(documents, planted):
    import dataclasses

    doc = documents["worksheet"]
    section = doc.sections[1]
    planted_doc = dataclasses.replace(doc, sections=(dataclasses.replace(
        section, blocks=section.blocks + (Paragraph(f"Some words {planted} and more."),)),))
    assert software_words(planted_doc)
