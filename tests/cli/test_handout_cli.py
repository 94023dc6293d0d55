"""`sears-paradox handout`: names, paper sizes, the PDF's text against `events`, the worksheet's answer key,
the LaTeX folder, determinism, and bad input (one sentence, exit 2, nothing written)."""

from __future__ import annotations

import io
import os
import re

import pytest
from click.testing import CliRunner

from sears_paradox_cli.main import main

from helpers import tex_figures_stood_in

pypdf = pytest.importorskip("pypdf")


def run(*args, expect=0):
    result = CliRunner().invoke(main, list(args))
    assert result.exit_code == expect, (result.output, result.exception)
    return result


def error_of(*args, expect=2) -> str:
    result = run("handout", *args, expect=expect)
    lines = [line for line in result.output.splitlines() if line.startswith("Error: ")]
    assert len(lines) == 1 and "Traceback" not in result.output, result.output
    return lines[0][len("Error: "):]


def pages_text(path) -> list[str]:
    return [page.extract_text() for page in pypdf.PdfReader(io.BytesIO(path.read_bytes())).pages]


def normalised(text: str) -> str:
    """Extracted text with the real minus written as '-' and runs of white space as one space."""
    return re.sub(r"\s+", " ", text.replace("\N{MINUS SIGN}", "-"))


def events_coordinates(*args) -> list[str]:
    """Every x and t `sears-paradox events` prints, as printed."""
    out = run("events", *args).output
    rows = [line.split() for line in out.splitlines() if re.match(r"\s+[AB]\d+\s", line)]
    return [cell for row in rows for cell in row[2:4]]


@pytest.mark.slow
def test_default_is_an_a4_pdf_in_outputs_and_the_same_bytes_twice(here):
    # `single`, the cheapest handout (one particle): the default paper and the unchanged report are the same for all
    assert run("handout", "single").output == "outputs/single_handout.pdf\n"
    path = here / "outputs" / "single_handout.pdf"
    reader = pypdf.PdfReader(io.BytesIO(path.read_bytes()))
    for page in reader.pages:
        assert float(page.mediabox.width) == pytest.approx(595.276, abs=0.01)
        assert float(page.mediabox.height) == pytest.approx(841.89, abs=0.01)
    assert len(reader.pages) >= 2
    stamp = os.stat(path).st_mtime_ns
    # built again in this process, the same bytes: reported unchanged and not rewritten (handout's -q is checked
    # with its LaTeX folder, tests/cli/test_robust_cli.py)
    assert run("handout", "single").output == f"{path.relative_to(here)} (unchanged)\n"
    assert os.stat(path).st_mtime_ns == stamp


#: one document read by the three tests below (built once per module: each build is ~1-3 s): two scenarios at
#: v = 0.73 on Letter paper. It is the same code path as the single-scenario builds these tests made before
#: (`handout fig2 --v 0.73`, `handout fig1 --paper letter`, `handout fig1 fig2`): every scenario's section is set
#: by the same writer, the paper and the speed name the file and size the pages alike for one scenario or two
SHARED_ARGS = ("fig1", "fig2", "--v", "0.73", "--paper", "letter")
SHARED_NAME = "outputs/fig1_fig2_handout_v0.73_letter.pdf"
#: the tests that read it run in one worker, which builds it once
ON_FIG1_FIG2_LETTER = pytest.mark.xdist_group("handout_cli_fig1_fig2_letter")


@pytest.fixture(scope="module")
def fig1_fig2_letter(tmp_path_factory):
    """(what `handout fig1 fig2 --v 0.73 --paper letter` printed, the PDF's path, its pages' text), run once in an
    empty folder and read back once (pypdf's extraction takes ~0.1 s a page)."""
    folder = tmp_path_factory.mktemp("fig1_fig2_letter")
    with pytest.MonkeyPatch.context() as mp:
        mp.chdir(folder)
        output = run("handout", *SHARED_ARGS).output
    return output, folder / SHARED_NAME, pages_text(folder / SHARED_NAME)


@ON_FIG1_FIG2_LETTER
def test_the_pdf_holds_the_event_coordinates_as_events_prints_them(fig1_fig2_letter):
    _, _, pages = fig1_fig2_letter
    # fig2's own section (from the page its title heads, a line of its own, to the end), so no cell is found in
    # fig1's section instead (the introduction names both titles in quotes, inside its lines)
    heads = [k for k, t in enumerate(pages) if re.search(r"(?m)^Impacts simultaneous in the moving frame", t)]
    first = heads[0]
    assert len(heads) == 1 and first > 1
    text = normalised(" ".join(pages[first:]))
    for cell in events_coordinates("fig2", "--v", "0.73"):
        assert cell in text, cell


@ON_FIG1_FIG2_LETTER
def test_letter_paper_and_names(fig1_fig2_letter):
    # the paper and the speed in the name (was `handout fig1 --paper letter` -> outputs/fig1_handout_letter.pdf)
    output, path, _ = fig1_fig2_letter
    assert output == SHARED_NAME + "\n"
    for page in pypdf.PdfReader(path).pages:
        assert (float(page.mediabox.width), float(page.mediabox.height)) == (612.0, 792.0)


@pytest.mark.slow
def test_the_worksheets_answer_key_holds_what_its_tables_leave_blank(here):
    assert run("handout", "fig2", "--worksheet").output == "outputs/fig2_worksheet.pdf\n"
    pages = [normalised(t) for t in pages_text(here / "outputs" / "fig2_worksheet.pdf")]
    key = next(k for k, t in enumerate(pages) if "Answer key" in t)
    before, after = " ".join(pages[:key]), " ".join(pages[key:])
    coordinates = events_coordinates("fig2")
    assert all(c in after for c in coordinates)
    assert not any(c in before for c in coordinates if len(c.strip("+-0.")) > 2)
    assert len(re.findall(r"Question \d+", before)) in range(5, 9)


@ON_FIG1_FIG2_LETTER
def test_several_scenarios_make_one_document_with_a_section_each(fig1_fig2_letter):
    # was `handout fig1 fig2` -> outputs/fig1_fig2_handout.pdf: the name's scenarios part is checked above
    output, _, pages = fig1_fig2_letter
    assert output.startswith("outputs/fig1_fig2_handout")
    text = " ".join(pages)
    # each section headed by its scenario's title (issue 14: no internal names in headings)
    assert "rod’s rest frame (the paper’s Fig. 1)" in text and "moving frame (the paper’s Fig. 2)" in text


def test_tex_writes_a_folder_of_pieces(here, monkeypatch):
    """The pieces' names: each figure stands in as a few bytes (its pieces are drawn and read in tests/handout and
    test_determinism)."""
    tex_figures_stood_in(monkeypatch)
    out = run("handout", "fig2", "--format", "tex").output.splitlines()
    folder = here / "outputs" / "fig2_handout"
    assert "outputs/fig2_handout/handout.tex" in out
    names = {p.name for p in folder.iterdir()}
    assert "handout.tex" in names
    assert any(n.endswith(".dat") for n in names) and any(n.endswith(".pdf") for n in names)
    # a second run reports each piece unchanged: tests/cli/test_robust_cli.py (handout --format tex -o DIR, twice)


@pytest.mark.parametrize("args, message", [
    (["fig2", "--paper", "a5"], "'--paper'"),
    (["fig2", "--format", "docx"], "'--format'"),
    (["fig2", "--v", "1"], "v must be"),
    (["no_such_scenario"], "no_such_scenario"),
    (["fig2", "--format", "tex", "-o", "x.pdf"], "writes a folder"),
    (["fig2", "-o", "missing/x.pdf"], "does not exist"),
    (["fig2", "--frame", "0.5,sideways"], "option --frame"),
])
def test_bad_input_is_one_sentence_and_writes_nothing(here, args, message):
    assert message in error_of(*args)
    assert not (here / "outputs").exists() or not any((here / "outputs").iterdir())


def test_an_unwritable_folder_is_refused(here, unwritable_folder):
    assert "cannot write" in error_of("fig2", "-o", str(unwritable_folder))


def _readme_handout_section() -> str:
    from pathlib import Path

    return (Path(__file__).resolve().parents[2] / "docs" / "handout.md").read_text()


def test_readme_lists_the_questions_fig2s_worksheet_asks():
    from rodparadox.physics.rigid import run as simulate
    from rodparadox.physics.frames import paper_frames
    from rodparadox.handout.build import questions
    from rodparadox.io.scenario import load

    section = _readme_handout_section()
    listed = section[section.index("<!-- fig2-questions:start -->"):section.index("<!-- fig2-questions:end -->")]
    history = simulate(load("fig2"))
    asked = [f"{q.number}. {q.text}" for q in questions(history, paper_frames(0.6))]
    assert listed.split("\n")[1:-1] == asked


def test_readme_page_picture_is_the_first_page_the_tool_sets_now():
    from pathlib import Path

    import matplotlib

    from rodparadox.handout.readme_pictures import handout_first_page

    root = Path(__file__).resolve().parents[2]
    assert "outputs/readme/fig2_handout_page1.png" in _readme_handout_section()
    committed = (root / "outputs" / "readme" / "fig2_handout_page1.png").read_bytes()
    made_with = (root / "outputs" / "readme" / "made-with.txt").read_text().split()
    drawn = handout_first_page()
    assert drawn[:8] == committed[:8] == b"\x89PNG\r\n\x1a\n"
    if made_with == ["matplotlib", matplotlib.__version__]:  # another matplotlib draws other pixels
        assert drawn == committed, "outputs/readme/fig2_handout_page1.png is out of date: run `make readme-figures`"


@pytest.mark.parametrize("args, message", [
    (["--sections", "paradox,strip"], "Error: option --sections must be parts among paradox, diagrams, strips, tables, "
                                      "ledger, comparison, rod, comma-separated, got 'paradox,strip'.\n"),
    (["--worksheet", "--sections", "diagrams,ledger"],
     "Error: option --sections leaves out tables, which a worksheet's questions read; add them.\n"),
])
def test_bad_sections_are_one_sentence_and_exit_2(tmp_path, args, message):
    result = CliRunner().invoke(main, ["handout", "single", "-o", str(tmp_path), *args])
    assert (result.exit_code, result.output) == (2, message)
    assert list(tmp_path.iterdir()) == []


def test_sections_choose_the_parts_of_each_document():
    """A teacher's choice: only what is asked, in the usual order; the paradox's section and its resolution in the key
    go with `paradox`; the comparison only with a causal history and `comparison`."""
    from helpers import causal_history, history
    from rodparadox.handout.build import Item, build
    from rodparadox.handout.document import DiagramBlock, Strips, Table

    rigid, causal = history("fig2", 0.6), causal_history("fig2", 0.6)
    full = build([Item("fig2", rigid, None, causal)])
    kinds = lambda doc: {type(b).__name__ for s in doc.sections for b in s.blocks}
    assert {"DiagramBlock", "Strips", "Table"} <= kinds(full) and full.sections[0].name == "introduction"
    only = build([Item("fig2", rigid, None, causal)], sections=("tables",))
    assert [s.name for s in only.sections] == ["fig2"]
    blocks = only.sections[0].blocks
    assert not any(isinstance(b, (DiagramBlock, Strips)) for b in blocks)
    assert [b.name for b in blocks if isinstance(b, Table)] == ["events_rest", "events_moving"]
    assert full.sections[1].blocks[:2] == blocks[:2]  # the heading and the set-up always
    drawn = build([Item("fig2", rigid, None, causal)], sections=("diagrams", "comparison"))
    assert [b.compared is causal for b in drawn.sections[0].blocks if isinstance(b, DiagramBlock)] == [False, True]
    sheet = build([Item("fig2", rigid)], worksheet=True, sections=("diagrams", "tables"))
    assert "The paradox and its resolution" not in [getattr(b, "text", "") for b in sheet.answer_key]
    with pytest.raises(ValueError, match="unknown handout sections"):
        build([Item("fig2", rigid)], sections=("figures",))
