"""A worksheet asks and never tells before its key (issue 14, item 1), read as the student gets it: the text of
every page before the answer key (the pages' drawn text, tick labels and panel titles included; the PDF's own text
at one speed; the LaTeX of --format tex) searched for every fact each question asks (`document.Fact`: a number in
every printed form, a claim as its phrases), for every preset at v = 0.3, 0.6, 0.95; at 0.6 three with the causal rod's
comparison and its questions (`handout --rod both --worksheet`)
and the rod's own view of both rods after their diagrams (`--frame both,rod`).

One worksheet of all the presets per speed, built once per session and split into its sections by their headings,
so each question's facts are searched in its own scenario's pages."""

from __future__ import annotations

import dataclasses
import functools
import io
import math
import re

import pypdf
import pytest
from matplotlib.backends.backend_pdf import PdfPages
from matplotlib.text import Text

from handout_shared import causal_alike, rods
from helpers import history, particle_presets
from rodparadox import render
from rodparadox.handout.build import build
from rodparadox.handout.document import Cell, DiagramBlock, Fact, Heading, Paragraph, Question, Table
from rodparadox.handout.own_view import with_rod_views
from rodparadox.handout.pdf import page_figures
from rodparadox.handout.pdf_text import TextRuns
from rodparadox.handout.tex import ANSWER_KEY_MARK, prose, tex_sources
from rodparadox.handout.words import told_number
from rodparadox.render.pdf_fonts import kept_subsets
from rodparadox.physics.frames import paper_frames


#: one worker runs this file, so its shared fixtures are built once (`--dist loadgroup`, pyproject.toml), with
#: test_handout_words, which builds documents of the same causal rods (`handout_shared.causal_alike`); the forces
#: worksheets' tests run with test_handout_forces instead (ON_FORCES), which runs the same driven rods
ON_SHEETS = pytest.mark.xdist_group("worksheet_tells_nothing")
ON_FORCES = pytest.mark.xdist_group("handout_forces")

SPEEDS = (0.3, 0.6, 0.95)
#: the speeds as test parameters: 0.6 every day, the other two in the full run (`-m slow` leaves them out)
SPEED_PARAMS = [pytest.param(0.3, marks=pytest.mark.slow), 0.6, pytest.param(0.95, marks=pytest.mark.slow)]
#: the speed whose worksheet is also saved as a PDF and read back with pypdf (saving is the costly part)
PDF_SPEED = 0.95
#: the speed and presets whose worksheet also compares the causal rod (`--rod both`) and asks its questions: one
#: particle (its far end moved by light), two at once, two at different times (a re-contact); the pages cost 0.5 s each
CAUSAL_SPEED, CAUSAL_PRESETS = 0.6, ("single", "fig1", "fig2")
SUBSCRIPTS = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def _plain(text: str) -> str:
    """A figure's mathtext label as the PDF prints it ($A_{1}$ -> A₁), whitespace as single spaces."""
    text = re.sub(r"_\{(\d+)\}", lambda m: m.group(1).translate(SUBSCRIPTS), text).replace("$", "")
    return " ".join(text.split())


def _ascii(text: str) -> str:
    return text.translate({ord(c): str(k) for k, c in enumerate("₀₁₂₃₄₅₆₇₈₉")})


def leaks(fact: Fact, text: str, latex: bool = False, ascii_digits: bool = False) -> list[str]:
    """The forms of the fact found in the text: a number standing alone (no digit or point-digit either side), a
    phrase anywhere; in LaTeX each form as `tex.prose` writes it; with `ascii_digits` (a PDF's text) B₁ as B1."""
    text = text.replace("’", "'")  # the pages set every apostrophe typographic: either is the same word
    found = []
    for form in fact.forms:
        written, pattern = _pattern(form, fact.number, latex, ascii_digits)
        if written in text and pattern.search(text):  # the plain substring first: a regex opening with a
            found.append(form)                         # look-behind scans the text character by character
    return found


@functools.lru_cache(maxsize=None)
def _pattern(form: str, number: bool, latex: bool, ascii_digits: bool) -> tuple[str, re.Pattern]:
    """A fact's form as `leaks` searches for it (as written, and compiled once: the search meets each form
    thousands of times)."""
    form = form.replace("’", "'")
    written = prose(form) if latex else _ascii(form) if ascii_digits else form
    return written, re.compile(rf"(?<![0-9.]){re.escape(written)}(?![0-9]|\.[0-9])" if number else
                               re.escape(written) + ("(?![′'])" if not latex else r"(?!')"))  # "in S" is not "in S′"


def _page_texts(figures) -> list[str]:
    """Each page's drawn text: the runs of the page and every visible Text of its diagrams, tick labels too."""
    out = []
    for figure in figures:
        for ax in figure.findobj(lambda a: hasattr(a, "xaxis")):
            ax.xaxis.get_majorticklabels()
            ax.yaxis.get_majorticklabels()
        texts = []
        for artist in figure.findobj(lambda a: isinstance(a, (Text, TextRuns))):
            if isinstance(artist, TextRuns):
                texts += [run.text for run in artist.runs]
            elif artist.get_visible() and artist.get_text():
                texts.append(artist.get_text())
        out.append(_plain("\n".join(texts)))
    return out


def _by_section(doc, pages: list[str]) -> list[str]:
    """The pages' text gathered per section of the document: each scenario's section starts a new page, the one
    holding its set-up ("A rod of proper length"); the first section is the introduction."""
    out = [""] * len(doc.sections)
    k = 0
    for page in pages:
        if "A rod of proper length" in page:
            k += 1
        out[k] += " " + page
    assert k == len(doc.sections) - 1, "every scenario's section starts a page with its set-up"
    return out


@pytest.fixture(scope="session")
def worksheets():
    """Per speed: the worksheet of every preset, and per section the text before the key as the figures draw it
    (and at PDF_SPEED as the PDF's text), and as handout.tex and its tables give it; each speed built when a test
    first asks for it, once."""
    return _Lazy(_worksheets_at)


class _Lazy(dict):
    """A dict whose values are made on first reading."""

    def __init__(self, make):
        super().__init__()
        self.make = make

    def __missing__(self, key):
        self[key] = self.make(key)
        return self[key]


def _worksheets_at(v: float):
    """The worksheets of every preset at v, read as the fixture `worksheets` says."""
    # with the causal rod's comparison and its questions at one speed (a causal run and its pages cost)
    doc = build([(name, history(name, v), None,
                  causal_alike(name, v) if v == CAUSAL_SPEED and name in CAUSAL_PRESETS else None)
                 for name in particle_presets()], worksheet=True)
    if v == CAUSAL_SPEED:  # and the rod's own view after their diagrams (handout --frame both,rod): its captions
        doc = with_rod_views(doc, {name: (history(name, v), causal_alike(name, v)) for name in CAUSAL_PRESETS})
    before_key = dataclasses.replace(doc, answer_key=())
    figures = page_figures(before_key)
    drawn = _by_section(doc, _page_texts(figures))
    pdf = None
    if v == PDF_SPEED:
        # the figures' labels (mathtext) come back as A1, the text's as A₁: read both as A1
        pdf = _by_section(doc, [_ascii(" ".join(p.extract_text().split()))
                                for p in pypdf.PdfReader(io.BytesIO(_pdf_of(figures))).pages])
    sources = tex_sources(doc)
    main = sources["handout.tex"].split(ANSWER_KEY_MARK)[0]
    main = re.sub(r"\\input\{([^}]*)\}", lambda m: sources[m.group(1)].replace("\\", "\\\\"), main)
    latex = main.split(r"\section*{")[1:]
    assert len(latex) == len(doc.sections)
    return doc, drawn, pdf, latex


def _pdf_of(figures) -> bytes:
    """The pages saved as one PDF, as `handout.pdf.to_pdf` saves them: in the print style, each font subset and text
    layout kept for the process (`render.pdf_fonts.kept_subsets`, which leaves the bytes as they are: measured, the
    same file with and without it; without it the 0.95 worksheet's pages took 1.0 s to save, with it 0.35-0.6 s)."""
    buffer = io.BytesIO()
    with render.style_context("print"), kept_subsets(), PdfPages(buffer) as pages:
        for figure in figures:
            pages.savefig(figure)
    return buffer.getvalue()


def _questions(section) -> list[Question]:
    return [b for b in section.blocks if isinstance(b, Question)]


#: a number in a cell's text: +0.8333333 (5/6) -> 0.8333333
NUMBER = re.compile(r"[−+-]?\d+(?:\.\d+)?")


def blank_facts(section) -> list[Fact]:
    """What each blank cell of the section's tables expects the student to write, as a fact: its number in every
    printed form (`words.number_forms`; a round number, 0.5 or 0.6, has none: the set-up gives such numbers)."""
    facts = []
    for table in (b for b in section.blocks if isinstance(b, Table)):
        for row in table.rows:
            for column, cell in zip(table.header, row):
                if cell.blank and NUMBER.search(cell.text):
                    value = float(NUMBER.search(cell.text).group().replace("−", "-"))
                    facts.append(told_number(f"{table.caption}: {row[0].text}, {column}", value))
    return facts


def asked_facts(section) -> list[tuple[str, Fact]]:
    """Every fact a student is asked for in the section before the key: each question's (`Question.asks`) and each
    blank cell's (`blank_facts`), with where it is asked."""
    return ([(f"question {q.number}", fact) for q in _questions(section) for fact in q.asks]
            + [("blank cell", fact) for fact in blank_facts(section)])


def found_leaks(section, texts: list[tuple[str, str]]) -> list[tuple]:
    """The facts of `asked_facts` found in the section's texts ((where, text): drawn, latex, pdf, model). A sentence
    that asks ("Are they simultaneous in S′?") states nothing: a claim's phrases are not searched in it; a number
    is searched everywhere."""
    asked = _questions(section)
    asking = [sentence for q in asked for sentence in re.findall(r"[^.?]*\?", q.text)]
    asking = [t for sentence in asking for t in (sentence.strip(), prose(sentence.strip()))]
    found = []
    for place, fact in asked_facts(section):
        own = [] if fact.number else asking
        for where, text in texts:
            for phrase in own:
                text = text.replace(_ascii(phrase) if where == "pdf" else phrase, "")
            hits = leaks(fact, text, latex=where == "latex", ascii_digits=where == "pdf")
            if hits:
                found.append((section.name, place, fact.what, where, hits))
    return found


@ON_SHEETS
@pytest.mark.parametrize("v", SPEED_PARAMS)
def test_no_page_before_the_key_states_what_a_question_asks_or_a_blank_cell_expects(worksheets, v):
    """Every question's facts and every blank cell's number, in every frame, searched in the pages as drawn (text,
    tables, captions, the diagrams' labels and ticks), as LaTeX, and at one speed in the PDF's own text."""
    doc, drawn, pdf, latex = worksheets[v]
    found = []
    for k, section in enumerate(doc.sections[1:], start=1):
        asked = _questions(section)
        assert asked and all(q.asks for q in asked), (section.name, "every question names the facts it asks")
        assert blank_facts(section), (section.name, "the tables ask numbers")
        texts = [("drawn", drawn[k]), ("latex", latex[k])] + ([("pdf", pdf[k])] if pdf else [])
        found += found_leaks(section, texts)
    assert not found, "\n".join(map(str, found))


@ON_SHEETS
@pytest.mark.parametrize("v", SPEED_PARAMS)
def test_the_facts_are_what_the_key_answers(worksheets, v):
    """The facts are real: every number is printed in the key's worked answer of its question (in one of its forms),
    and the rod's velocity after each collision in S′, computed here independently as tanh of the engine's rapidity
    less S′'s, is among the facts of the velocity question wherever that question asks about the rod."""
    doc = worksheets[v][0]
    asked = [(section, q) for section in doc.sections[1:] for q in _questions(section)]
    answered = [b for b in doc.answer_key if isinstance(b, Question)]
    assert [q.text for _, q in asked] == [q.text for q in answered]  # the key's, in the same order
    for (section, q), key in zip(asked, answered):
        answer = " ".join(key.answer)
        for fact in q.asks:
            if fact.number and fact.forms:
                assert leaks(fact, answer), (section.name, q.number, fact.what, answer)
    for section in doc.sections[1:]:
        velocity = next(q for q in _questions(section) if "relativistic addition" in q.text)
        h = history(section.name, v)
        eta = paper_frames(v)[1].rapidity
        for i in h.impacts:
            u = math.tanh(i.rod_rapidity_after - eta)
            what = f"the rod's velocity after {i.label[0]}{i.label[1:].translate(SUBSCRIPTS)} in S′"
            asked_here = [f for f in velocity.asks if f.what == what]
            if asked_here and asked_here[0].forms:
                assert f"{abs(u):.4f}" in asked_here[0].forms, (section.name, what, u, asked_here[0].forms)


@ON_SHEETS
def test_a_planted_leak_is_found():
    """The search's power: a sentence planted before the key that states a question's fact is found, in the model's
    text and as LaTeX (fig2 at 0.6: the rod's velocity after A₁ in S′ is 15/17; B₁ and A₁ share t′ = 17/12)."""
    doc = build([("fig2", history("fig2", 0.6))], worksheet=True)
    asks = {f.what: f for q in _questions(doc.sections[1]) for f in q.asks}
    velocity = asks["the rod's velocity after A₁ in S′"]
    together = next(f for what, f in asks.items() if what.endswith(" simultaneous in S′") and "not" not in what)
    for planted in ("the rod moves at +0.8824 c after A₁", "a colour bar's tick 0.882", "15/17"):
        assert leaks(velocity, planted) and leaks(velocity, prose(planted), latex=True)
    assert not leaks(velocity, "x = 10.88241 L, t = 0.88245")
    for planted in ("B₁ and A₁", "Impacts simultaneous in the moving frame", "at the same instant of S′ as B's"):
        assert leaks(together, planted) and leaks(together, prose(planted), latex=True)
    # and planted into the worksheet itself, the section's text as the test above reads it finds it
    section = doc.sections[1]
    planted = dataclasses.replace(section, blocks=section.blocks + (Paragraph("After A₁ the rod moves at +15/17 c."),))
    text = " ".join(b.text for b in planted.blocks if isinstance(b, Paragraph))
    assert leaks(velocity, text)


# --- the search's power: a leak planted in each place is found ---------------------------------------------------

def model_text(section) -> str:
    """The section's words as its blocks hold them: headings, paragraphs, captions, every filled cell, the tables'
    headers and notes, the questions."""
    out = []
    for b in section.blocks:
        if isinstance(b, (Heading, Paragraph)):
            out.append(b.text)
        elif isinstance(b, Table):
            out += [b.caption, *b.header, *b.notes] + [c.text for row in b.rows for c in row if not c.blank]
        elif isinstance(b, Question):
            out.append(b.text)
        elif hasattr(b, "caption"):
            out.append(b.caption)
    return "\n".join(out)


def _latex_of(doc) -> list[str]:
    sources = tex_sources(doc)
    main = sources["handout.tex"].split(ANSWER_KEY_MARK)[0]
    main = re.sub(r"\\input\{([^}]*)\}", lambda m: sources[m.group(1)].replace("\\", "\\\\"), main)
    return main.split(r"\section*{")[1:]


#: fig2 at 0.6: A₁'s t in S, a blank cell (19/12 = 1.583333), and the rod's velocity after A₁ in S′ (15/17), which
#: question 3 asks
PLANTS = ("t = 1.583333 L", "+15/17 c")


def _planted(section, place: str, text: str):
    """The section with `text` planted in one place: a paragraph, a figure's caption, a filled cell, a table's note,
    a question's text."""
    blocks = list(section.blocks)
    k, b = next((k, b) for k, b in enumerate(blocks) if isinstance(b, {
        "paragraph": Paragraph, "caption": DiagramBlock, "cell": Table, "note": Table, "question": Question}[place]))
    if place == "paragraph":
        blocks[k] = Paragraph(b.text + " " + text)
    elif place == "caption":
        blocks[k] = dataclasses.replace(b, caption=b.caption + " " + text)
    elif place == "cell":
        row = (dataclasses.replace(b.rows[0][0], text=b.rows[0][0].text), Cell(text)) + b.rows[0][2:]
        blocks[k] = dataclasses.replace(b, rows=(row,) + b.rows[1:])
    elif place == "note":
        blocks[k] = dataclasses.replace(b, notes=b.notes + (text,))
    else:
        blocks[k] = dataclasses.replace(b, text=b.text + " " + text + ".")
    return dataclasses.replace(section, blocks=tuple(blocks))


@pytest.fixture(scope="module")
def fig2_sheet():
    return build([("fig2", history("fig2", 0.6))], worksheet=True)


@ON_SHEETS
@pytest.mark.parametrize("place", ["paragraph", "caption", "cell", "note", "question"])
def test_a_leak_planted_in_each_place_is_found_in_the_words_and_the_latex(fig2_sheet, place):
    section = fig2_sheet.sections[1]
    assert not found_leaks(section, [("model", model_text(section)), ("latex", _latex_of(fig2_sheet)[1])])
    for plant, expected in zip(PLANTS, ("blank cell", "question 3")):
        planted = _planted(section, place, plant)
        doc = dataclasses.replace(fig2_sheet, sections=(fig2_sheet.sections[0], planted))
        for where, text in (("model", model_text(planted)), ("latex", _latex_of(doc)[1])):
            assert any(leak[1] == expected and leak[3] == where for leak in found_leaks(planted, [(where, text)])), \
                (place, plant, where)


@ON_SHEETS
def test_a_leak_planted_in_a_figure_is_found_in_the_drawn_pages_and_the_pdf(fig2_sheet, monkeypatch):
    """A panel's title stating a blank cell's number and a question's: found among the drawn labels, and in the
    PDF's own text."""
    def retitle(self, diagram):
        diagram.panels[0].axes.title.set_text("(a) " + " ".join(PLANTS))
    monkeypatch.setattr(DiagramBlock, "retitle", retitle)
    figures = page_figures(dataclasses.replace(fig2_sheet, answer_key=()))
    drawn = _by_section(fig2_sheet, _page_texts(figures))[1]
    pdf = _ascii(" ".join(" ".join(p.extract_text().split()) for p in pypdf.PdfReader(io.BytesIO(_pdf_of(figures))).pages))
    for where, text in (("drawn", drawn), ("pdf", pdf)):
        places = {leak[1] for leak in found_leaks(fig2_sheet.sections[1], [(where, text)])}
        assert {"blank cell", "question 3"} <= places, (where, places)


# --- scenarios no preset has --------------------------------------------------------------------------------------

#: generated scenarios: masses, gaps, timings and speeds no preset has (a fixed draw, so the run is the same)
GENERATED = [
    ("gen1", 0.47, "A: {mass: 1.5, gap: 0.35}\n  B: {mass: 0.7, gap: 0.8}"),
    ("gen2", 0.83, "B: {mass: 1.0, gap: 0.3}\n  A:\n    mass: 1.25\n    timed_with: {particle: B, frame: moving, delay: 0.4}"),
    ("gen3", 0.735, "A: {mass: 0.8, gap: 0.6}"),
    ("gen4", 0.62, "B: {mass: 2.0, gap: 0.45}\n  A: {mass: 1.0, gap: 0.55}"),
]


@ON_SHEETS
@pytest.mark.parametrize("name, v, particles", GENERATED)
def test_a_generated_scenario_s_worksheet_tells_nothing_it_asks(name, v, particles):
    """A worksheet of a scenario no preset has, with the causal rod's comparison: no question's fact and no blank
    cell's number in its words or its LaTeX before the key."""
    from rodparadox.io.scenario import parse
    from rodparadox.physics.models import run_rods

    scenario = parse(f"name: {name}\nv: {v}\nparticles:\n  {particles}\n", f"{name}.yaml", name)
    rigid, causal = run_rods(scenario, "both")  # struck by the same particles
    doc = build([(name, rigid, None, causal)], worksheet=True)
    section = doc.sections[1]
    assert blank_facts(section) and _questions(section)
    found = found_leaks(section, [("model", model_text(section)), ("latex", _latex_of(doc)[1])])
    assert not found, "\n".join(map(str, found))


@ON_SHEETS
@pytest.mark.parametrize("v", SPEED_PARAMS)
def test_the_drawn_pages_name_no_software(worksheets, v):
    """The words of the pages as drawn (the diagrams' legends, titles and labels too) hold none of the word list of
    `test_handout_words`."""
    from test_handout_words import SOFTWARE

    found = [(k, m.group()) for k, text in enumerate(worksheets[v][1]) for m in SOFTWARE.finditer(text)]
    assert not found, found


#: an apostrophe between letters set straight (rod's), where print sets a typographic one (rod’s)
STRAIGHT_APOSTROPHE = re.compile(r"[A-Za-z]'[A-Za-z]")


@ON_SHEETS
@pytest.mark.parametrize("v", SPEED_PARAMS)
def test_the_drawn_pages_set_every_apostrophe_typographic(worksheets, v):
    """Issue 24: the pages as drawn, the diagrams' legends, colour bars (rod’s material points) and the rod's own
    view included, and at PDF_SPEED the PDF's text, set no apostrophe straight."""
    _, drawn, pdf, _ = worksheets[v]
    found = [(k, text[max(0, m.start() - 30):m.end() + 10]) for k, text in enumerate(drawn + (pdf or []))
             for m in STRAIGHT_APOSTROPHE.finditer(text)]
    assert not found, found


#: a letter subscripted as source code writes it (x_P), which a page prints as it stands
UNDERSCORED = re.compile(r"[A-Za-z]_[A-Za-z]")


@ON_SHEETS
@pytest.mark.parametrize("v", SPEED_PARAMS)
def test_the_drawn_pages_write_no_subscript_as_code_does(worksheets, v):
    """Issue 24, found looking at the pages: the question on a turn (off_timing, while_turning) printed
    "(x − x_P)² − (t − t_P)² = L²" as it stands; it now writes P = (x₀, t₀), subscripts a page sets."""
    _, drawn, pdf, _ = worksheets[v]
    found = [(k, text[max(0, m.start() - 30):m.end() + 10]) for k, text in enumerate(drawn + (pdf or []))
             for m in UNDERSCORED.finditer(text)]
    assert not found, found


# --- rods driven by forces (Sears's own paradox) ------------------------------------------------------------------

#: the presets whose rod is driven by forces at its ends
FORCE_PRESETS = ("sears", "sears_moving", "push")


@functools.lru_cache(maxsize=None)
def forces_sheet(v: float, compared: bool = False, names: tuple[str, ...] = FORCE_PRESETS):
    """The worksheet of the forces presets at v, one section each (with the causal rod's comparison: `compared`); the
    rods are test_handout_forces's, run once (`handout_shared.rods`)."""
    items = []
    for name in names:
        histories = rods(name, v, "both" if compared else "rigid")  # run_rods(load(name).with_overrides(v=v), ...)
        items.append((name, histories[0], None, histories[1] if compared else None))
    return build(items, worksheet=True)


@ON_FORCES
@pytest.mark.parametrize("v", SPEED_PARAMS)
def test_a_forces_worksheet_tells_nothing_it_asks(v):
    """The forces presets' worksheet (both rods at 0.6): every question's facts and every blank cell's number, in the
    words and the LaTeX before the key, in every frame."""
    doc = forces_sheet(v, compared=v == CAUSAL_SPEED)
    latex = _latex_of(doc)
    found = []
    for k, section in enumerate(doc.sections[1:], start=1):
        assert _questions(section) and all(q.asks for q in _questions(section)), section.name
        assert blank_facts(section), section.name
        found += found_leaks(section, [("model", model_text(section)), ("latex", latex[k])])
    assert not found, "\n".join(map(str, found))
    # the facts are real: every number is in the key's worked answer of its question
    asked = [q for section in doc.sections[1:] for q in _questions(section)]
    answered = [b for b in doc.answer_key if isinstance(b, Question)]
    assert [q.text for q in asked] == [q.text for q in answered]
    for q, key in zip(asked, answered):
        for fact in q.asks:
            if fact.number and fact.forms:
                assert leaks(fact, " ".join(key.answer)), (q.number, fact.what)


@ON_FORCES
def test_a_forces_worksheet_s_drawn_pages_tell_nothing():
    """sears at 0.95, the pages as drawn (the diagrams' labels, ticks and titles): no fact asked."""
    doc = forces_sheet(0.95, names=("sears",))
    figures = page_figures(dataclasses.replace(doc, answer_key=()))
    drawn = _by_section(doc, _page_texts(figures))
    found = [leak for k, section in enumerate(doc.sections[1:], start=1)
             for leak in found_leaks(section, [("drawn", drawn[k])])]
    assert not found, "\n".join(map(str, found))


@ON_FORCES
def test_a_leak_planted_in_a_forces_worksheet_is_found():
    """sears at 0.6: the momentum delivered in S′ by the slice the question names, and which force starts first in
    S′, planted in a paragraph, a cell and a caption, are found in the words and the LaTeX."""
    doc = forces_sheet(0.6, names=("sears",))
    section = doc.sections[1]
    asks = {f.what: f for q in _questions(section) for f in q.asks}
    delivered = next(f for what, f in asks.items() if what.startswith("the momentum delivered"))
    plants = (f"together +{delivered.forms[-1]} M c", "In S′ the left force starts first.")
    for place in ("paragraph", "cell", "caption", "question"):
        for plant in plants:
            planted = _planted(section, place, plant)
            copy = dataclasses.replace(doc, sections=(doc.sections[0], planted))
            for where, text in (("model", model_text(planted)), ("latex", _latex_of(copy)[1])):
                assert found_leaks(planted, [(where, text)]), (place, plant, where)
