"""Variables in math italics (issue 14, textbook form): v, L, t, t′, x, E, p, u set in italics in the PDF's running
text and as $...$ in the LaTeX; units (c, M), frames (S, S′), labels (A, B₁) and numbers upright. Read from the
PDF's own text spans (pypdf: each span's font) and from handout.tex."""

from __future__ import annotations

import io

import pypdf

from rodparadox.handout.document import Handout, Heading, Paragraph, Section
from rodparadox.handout.pdf import to_pdf
from rodparadox.handout.tex import prose, tex_sources
from rodparadox.handout.words import math_pieces

SENTENCE = "In S′ B₁ strikes at x′ = 5/4 L, t′ = 17/12 L, v = 0.6; E and p of A in M c; a body at u moves at +0.6 c."
ITALIC = {"x′", "t′", "L", "v", "E", "p", "u"}
UPRIGHT = {"S′", "B₁", "A", "M", "c", "5/4", "17/12", "0.6", "+0.6", "In", "strikes", "at", "moves"}


def _spans(pdf: bytes) -> list[tuple[str, str]]:
    """Each text span of the PDF's pages with its font's name."""
    spans = []

    def visit(text, cm, tm, font, size):
        if text.strip() and font is not None:
            spans.append((text, str(font.get("/BaseFont", ""))))
    for page in pypdf.PdfReader(io.BytesIO(pdf)).pages:
        page.extract_text(visitor_text=visit)
    return spans


def test_the_pieces_are_the_variables_and_nothing_else():
    pieces = math_pieces(SENTENCE)
    assert {p.strip(",.;") for p, variable in pieces if variable} == ITALIC
    words = " ".join(p for p, variable in pieces if not variable).replace(",", " ").replace(";", " ").split()
    assert UPRIGHT <= set(words) and not ITALIC & set(words)
    # standing alone only: the letters of words and labels are never variables
    assert not any(variable for _, variable in math_pieces("the rod's pivot, Temple University, Sears, don’t, v2"))


def test_the_pdf_sets_the_variables_in_italics_and_the_rest_upright():
    doc = Handout("Math", (Section("s", "Math", (Heading("Italics"), Paragraph(SENTENCE))),))
    spans = _spans(to_pdf(doc))
    italic = [text for text, font in spans if "Italic" in font or "Oblique" in font]
    upright = " ".join(text for text, font in spans if "Italic" not in font and "Oblique" not in font)
    # every variable of the sentence is an italic span of its own (primes with it), and nothing else is italic
    # (the prime is drawn from the fallback font when the italic one lacks it: a span of its own after its letter)
    assert sorted(t.strip() for t in italic if t.strip() not in ("Math", "page 1 of 1", "′")) == sorted(
        ["x", "L", "t", "L", "v", "E", "p", "u"]), italic
    for word in ("S′", "B₁", "5/4", "17/12", "M c", "+0.6 c", "strikes at"):  # spans split at the fallback's glyphs
        assert word.replace(" ", "") in upright.replace(" ", ""), (word, upright)


def test_the_latex_writes_the_variables_in_math_and_the_rest_in_text():
    assert prose("x′ = 5/4 L at v = 0.6 in S′; E, p, u²") == "$x'$ = 5/4 $L$ at $v$ = 0.6 in S$'$; $E$, $p$, $u^{2}$"
    assert prose("x = −L/2") == "$x$ = $-L$/2"  # adjacent math joined, never $$ (display math)
    doc = Handout("Math", (Section("s", "Math", (Paragraph(SENTENCE),)),))
    tex = tex_sources(doc)["handout.tex"]
    assert ("In S$'$ B$_{1}$ strikes at $x'$ = 5/4 $L$, $t'$ = 17/12 $L$, $v$ = 0.6; $E$ and $p$ of A in M c; "
            "a body at $u$ moves at +0.6 c.") in tex
