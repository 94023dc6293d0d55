"""The tables as Markdown and LaTeX (`rodparadox.tables.formats`, `events`/`ledger --format markdown|latex`).

The numbers are checked against hand-derived values (Fig. 2 at v = 0.6: g = 5/4; in S, B₁ at t = L/2v = 5/6 and
A₁ at t = L/2v + gvL = 19/12; in S′ both at t′ = (gL/2v)(1 + v²) = 17/12, and the rod leaves A₁ at
2v/(1 + v²) = 15/17; Fig. 1 in S′ hides M (2g²v², 2g²v) = (1.125, 1.875) between its impacts) and against what
`sears-paradox events` prints; the LaTeX is compiled with pdflatex when it is installed.
"""

from __future__ import annotations

import re
import shutil
import subprocess
from fractions import Fraction
from pathlib import Path

import pytest
from click.testing import CliRunner

from rodparadox.handout.document import Cell, Table
from rodparadox.physics.rigid import run as simulate
from rodparadox.physics.frames import paper_frames
from rodparadox.io.scenario import load

from helpers import particle_presets
from rodparadox.tables.build import (events_table, hidden_table, latex_text, ledger_table, slices_table, to_latex,
                               to_markdown)
from rodparadox.tables.formats import BLANK_TEXT, table_format
from sears_paradox_cli.main import main

ROOT = Path(__file__).resolve().parents[2]

SUBSCRIPT_DIGITS = str.maketrans("₀₁₂₃₄₅₆₇₈₉", "0123456789")


def cli(*args: str, expect: int = 0) -> str:
    result = CliRunner().invoke(main, list(args))
    assert result.exit_code == expect, (result.output, result.exception)
    return result.output


def error_of(*args: str) -> str:
    """The one sentence a refused call prints (exit status 2, no traceback)."""
    result = CliRunner().invoke(main, list(args))
    assert result.exit_code == 2, result.output
    assert isinstance(result.exception, SystemExit), result.exception
    lines = [line for line in result.output.splitlines() if line.startswith("Error: ")]
    assert len(lines) == 1 and "Traceback" not in result.output, result.output
    return lines[0][len("Error: "):]


def history_of(name: str, v: float = 0.6, **overrides):
    return simulate(load(name).with_overrides(v=v, **overrides))


# --- reading Markdown back ---------------------------------------------------------------------------------

def split_row(line: str) -> list[str]:
    """The cells of a pipe-table line: split at | not escaped as \\|."""
    assert line.startswith("| ") and line.endswith(" |"), line
    return [cell.strip().replace("\\|", "|") for cell in re.split(r"(?<!\\)\|", line[1:-1])]


def markdown_tables(text: str) -> list[tuple[str, list[str], list[list[str]]]]:
    """Every (caption, header, rows) of a Markdown text: a bold caption line, then the pipe table under it."""
    out = []
    lines = text.splitlines()
    for k, line in enumerate(lines):
        if line.startswith("**") and line.endswith("**"):
            body = []
            for row in lines[k + 2:]:
                if not row.startswith("|"):
                    break
                body.append(row)
            header, rule, rows = body[0], body[1], body[2:]
            assert re.fullmatch(r"\|( :?-+:? \|)+", rule), rule
            out.append((line.strip("*"), split_row(header), [split_row(r) for r in rows]))
    return out


def number_of(cell: str) -> str:
    """A cell's number as the text table writes it: the fraction dropped, a hyphen for the minus sign."""
    return re.sub(r" \([^()]*\)$", "", cell).replace("\N{MINUS SIGN}", "-")


def events_text_rows(text: str) -> list[dict[str, tuple[str, ...]]]:
    """`sears-paradox events` as printed: per frame, label -> (end, x, t, particle before, after, rod before, after)."""
    frames: list[dict[str, tuple[str, ...]]] = []
    for line in text.splitlines():
        if line.startswith("frame "):
            frames.append({})
        m = re.match(r"  ([AB]\d+)\s+(left|right)\s+(\S+)\s+(\S+)\s+(\S+)\s+->\s+(\S+)\s+(\S+)\s+->\s+(\S+)", line)
        if m:
            frames[-1][m.group(1)] = m.groups()[1:]
    return frames


def events_markdown_rows(text: str) -> list[dict[str, tuple[str, ...]]]:
    return [{row[0].translate(SUBSCRIPT_DIGITS): (row[1], *map(number_of, row[2:])) for row in rows}
            for _, _, rows in markdown_tables(text)]


# --- Markdown ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("name", particle_presets())
def test_markdown_events_has_a_row_per_impact_and_the_header_columns_in_every_row(name):
    text = cli("events", name, "--v", "0.6", "--frame-velocity", "0.3", "--format", "markdown")
    printed = events_text_rows(cli("events", name, "--v", "0.6", "--frame-velocity", "0.3"))
    tables = markdown_tables(text)
    assert [caption for caption, _, _ in tables] == [
        "The impacts in frame S", "The impacts in frame S′", "The impacts in frame u = 0.3"]
    for (_, header, rows), impacts in zip(tables, printed):
        assert len(header) == 8 and all(len(row) == len(header) for row in rows)
        assert sorted(row[0].translate(SUBSCRIPT_DIGITS) for row in rows) == sorted(impacts)
    if name in ("fig1", "fig2"):  # the paper's figures: two impacts, and three (B strikes twice)
        assert {len(rows) for _, _, rows in tables} == {2 if name == "fig1" else 3}


def test_markdown_worksheet_leaves_every_number_blank_and_keeps_the_labels():
    history = history_of("fig2")
    for frame in paper_frames(0.6):
        [(_, header, rows)] = markdown_tables(to_markdown(events_table(history, frame, blank=True)))
        assert [row[:2] for row in rows] == [[r[0], r[1]] for r in
                                             markdown_tables(to_markdown(events_table(history, frame)))[0][2]]
        assert all(cell == BLANK_TEXT for row in rows for cell in row[2:])


def test_markdown_escapes_pipes_and_emphasis():
    table = Table("t", "a | b", ("x|y", "n"), ((Cell("a*b_c|d"), Cell("1")),), "ln")
    text = to_markdown(table)
    assert text.splitlines()[0] == "**a \\| b**"
    [(_, header, rows)] = markdown_tables(text)
    assert header == ["x|y", "n"] and rows == [["a\\*b\\_c|d", "1"]]


# --- the numbers: as `events` prints them, and by hand ----------------------------------------------------

@pytest.mark.parametrize("name", particle_presets())
@pytest.mark.parametrize("v", ["0.1", "0.6", "0.95"])
def test_events_tables_print_the_numbers_events_prints(name, v):
    for extra in ([], ["--frame-velocity", "0.3"]):
        text = cli("events", name, "--v", v, *extra)
        markdown = cli("events", name, "--v", v, *extra, "--format", "markdown")
        assert events_markdown_rows(markdown) == events_text_rows(text)


def test_events_tables_keep_their_own_digits_when_a_third_frame_is_much_faster():
    """The text table shares one velocity format over all its frames, so with --v 1e-6 and a frame at 0.3 it
    prints S's velocities with 6 decimals (+0.000001); each Markdown table formats its own frame and keeps the
    digits (+0.00000100000). The values agree to the coarser digits."""
    args = ("events", "fig2", "--v", "1e-6", "--frame-velocity", "0.3")
    text, markdown = events_text_rows(cli(*args)), events_markdown_rows(cli(*args, "--format", "markdown"))
    assert text[0]["B1"][3] == "-0.000001" and markdown[0]["B1"][3] == "-0.00000100000"
    for coarse, fine in zip(text, markdown):
        for label, cells in coarse.items():
            assert cells[:3] == fine[label][:3]  # end, x, t: the same text
            for a, b in zip(cells[3:], fine[label][3:]):
                assert abs(float(a) - float(b)) <= 0.5e-6


def fig2_cells(frame_name: str) -> dict[str, dict[str, str]]:
    history = history_of("fig2", 0.6)
    frame = {f.name: f for f in paper_frames(0.6)}[frame_name]
    [(_, header, rows)] = markdown_tables(to_markdown(events_table(history, frame)))
    return {row[0]: dict(zip(header, row)) for row in rows}


def decimal(q: Fraction, decimals: int = 6) -> str:
    """A fraction as the tables print it: signed, with its column's `decimals` (a coordinate: seven significant
    digits in the column's largest; a velocity: six), then the fraction itself."""
    text = f"{float(q):+.{decimals}f}"
    return f"{text.replace('-', chr(0x2212))} ({q.numerator}/{q.denominator})"


def test_fig2_at_0_6_by_hand():
    v, L = Fraction(3, 5), 1
    g = Fraction(5, 4)
    assert g * g * (1 - v * v) == 1  # g = 1/sqrt(1 - v²)
    t_B, t_A = L / (2 * v), L / (2 * v) + g * v * L
    assert (t_B, t_A) == (Fraction(5, 6), Fraction(19, 12))
    rest = fig2_cells("rest")
    # the t column's largest, B₂'s 7/3, has seven digits, so six decimals: every t with six
    assert rest["B₁"]["t"] == decimal(t_B, 6) == "+0.833333 (5/6)"
    assert rest["A₁"]["t"] == decimal(t_A, 6) == "+1.583333 (19/12)"
    assert rest["B₁"]["x"] == "+0.5000000" and rest["A₁"]["x"] == "\N{MINUS SIGN}0.7500000"  # x: 0.75 the largest
    t_prime = g * L / (2 * v) * (1 + v * v)  # the paper's (15), corrected
    u_after = 2 * v / (1 + v * v)
    assert (t_prime, u_after) == (Fraction(17, 12), Fraction(15, 17))
    moving = fig2_cells("moving")
    assert moving["A₁"]["t′"] == moving["B₁"]["t′"] == decimal(t_prime, 6) == "+1.416667 (17/12)"
    assert moving["A₁"]["rod after"] == decimal(u_after) == "+0.882353 (15/17)"
    # the same cells in the LaTeX fragment: the number in an S column, its fraction in small type under it
    latex = to_latex(events_table(history_of("fig2", 0.6), paper_frames(0.6)[1]))
    row = next(line for line in latex.splitlines() if line.startswith("A$_{1}$"))
    assert row.split(" & ")[3] == "+1.416667" and row.split(" & ")[7].startswith("+0.882353")
    under = latex.splitlines()[latex.splitlines().index(row) + 1].split(" & ")
    assert under[3] == r"{\footnotesize(17/12)}" and under[7].startswith(r"{\footnotesize(15/17)}")


def test_fig1_ledger_hides_2g2v2_and_2g2v_in_s_prime_by_hand():
    v = Fraction(3, 5)
    g2 = 1 / (1 - v * v)  # 25/16
    hidden = (2 * g2 * v * v, 2 * g2 * v)
    assert hidden == (Fraction(9, 8), Fraction(15, 8))  # 1.125, 1.875
    text = cli("ledger", "fig1", "--frame", "moving", "--at", "1", "--format", "markdown")
    tables = {caption: (header, rows) for caption, header, rows in markdown_tables(text)}
    header, rows = tables["Energy and momentum at each impact, frame S′"]
    hidden_rows = [dict(zip(header, r)) for r in rows if r[2] == "hidden"]
    assert (hidden_rows[0]["E after"], hidden_rows[0]["p after"]) == ("1.1250", "1.8750")  # after A₁
    assert (hidden_rows[1]["E before"], hidden_rows[1]["p before"]) == ("1.1250", "1.8750")  # before B₁
    header, rows = tables["Each body's kinetic energy and momentum at chosen instants, frame S′"]
    at_1 = {r[1]: (r[2], r[3]) for r in rows}
    # each column with one number of decimals: seven digits in its largest (E 3.25, p 1.875)
    assert rows[0][0] == "1.000000" and at_1["hidden"] == ("1.125000", "1.875000")
    # A has bounced to rest in S′, B still moves at 0: both have E = 1, p = 0; the rod keeps g(1, v) = (1.25, 0.75)
    assert at_1["particle A"] == at_1["particle B"] == ("1.000000", "0.000000")
    assert at_1["rod, kinetic"] == ("1.250000", "0.750000")


# --- LaTeX: text ------------------------------------------------------------------------------------------

@pytest.mark.parametrize("text, latex", [
    ("a_b", r"a\_b"), ("a & b", r"a \& b"), ("50%", r"50\%"), ("#1", r"\#1"), ("$5", r"\$5"),
    ("{x}", r"\{x\}"), ("~", r"\textasciitilde{}"), ("^", r"\textasciicircum{}"), ("\\", r"\textbackslash{}"),
    ("a<b>c|d", r"a\textless{}b\textgreater{}c\textbar{}d"),
    ("B₁", "B$_{1}$"), ("B₁₂", "B$_{12}$"), ("t′", "$t'$"), ("x′", "$x'$"), ("S′", "$S'$"), ("xᵤ", "$x_{u}$"),
    ("γ", r"$\gamma$"), ("γv", r"$\gamma$v"), ("γt′", r"$\gamma t'$"), ("2γ²", r"2$\gamma^{2}$"),
    ("−0.5", "$-$0.5"), ("M c²", "M c$^{2}$"), ("1×10⁻¹⁶", r"1$\times$10$^{-16}$"),
    ("particle before", "particle before"), ("rod's", "rod's"), ("B₁ at t′ = 17/12", "B$_{1}$ at $t'$ = 17/12"),
    ("a – b — c", "a -- b --- c"), ("café", "café"),
])
def test_latex_text_escapes_and_maps_unicode(text, latex):
    assert latex_text(text) == latex


def test_latex_text_refuses_a_character_it_cannot_spell():
    with pytest.raises(ValueError, match=r"U\+2603"):
        latex_text("a ☃")


@pytest.mark.parametrize("texts, spec", [
    (["+0.5000000", "\N{MINUS SIGN}1.250000", "+0"], "+1.7"),
    (["1.110223e\N{MINUS SIGN}16", "2.125", ""], "1.6e-2"),
    (["+1.583333e\N{MINUS SIGN}05", "+5.000000e+100"], "+1.6e-3"),  # siunitx prints e−5: no leading zero
    (["+1.416667 (17/12)", "+12.5"], "+2.6"),
    (["1", "0"], "1"),
    (["", "n/a"], None),
])
def test_table_format_comes_from_the_widest_number(texts, spec):
    assert table_format(texts) == spec


def test_latex_fragment_structure():
    table = Table("odd_one", "A caption with 50% & more", ("label", "value", "t′"),
                  ((Cell("a_b"), Cell("\N{MINUS SIGN}1.110223e\N{MINUS SIGN}16"), Cell("+1.416667 (17/12)")),
                   (Cell("B₁"), Cell("n/a"), Cell("+0.5000000", blank=True))), "lnn", ("A note: γ = 5/4.",))
    lines = to_latex(table).splitlines()
    assert lines[0] == "% A caption with 50% & more"  # a comment: the including document sets its own caption
    assert r"\begin{tabular}{l S[table-format=+1.6e-2] S[table-format=+1.7]}" in lines
    assert lines.index(r"\toprule") < lines.index(r"\midrule") < lines.index(r"\bottomrule")
    assert r"a\_b & -1.110223e-16 & +1.416667 \\[-0.6ex]" in lines  # U+2212 as -, the fraction on the line under
    assert r" &  & {\footnotesize(17/12)} \\" in lines
    assert r"B$_{1}$ & {n/a} & {\rule{0pt}{3.2ex}\rule{5em}{0.4pt}} \\" in lines  # text braced; a ruled blank
    assert lines[-1] == r"\par\smallskip\noindent{\footnotesize A note: $\gamma$ = 5/4.\par}"


# --- LaTeX: it compiles -----------------------------------------------------------------------------------

def all_tables(v: float) -> list[Table]:
    out = []
    for name in particle_presets():
        history = history_of(name, v)
        for frame in paper_frames(v):
            for blank in (False, True):
                out += [events_table(history, frame, blank), ledger_table(history, frame, blank)]
                hidden = hidden_table(history, frame, blank)
                out += [hidden] if hidden is not None else []
            out.append(slices_table(history, frame, (0.5, 1.0)))
    return out


@pytest.mark.skipif(shutil.which("pdflatex") is None,
                    reason="pdflatex is not installed (apt-get install texlive-latex-recommended)")
def test_every_fragment_compiles_and_fits_an_a4_page(tmp_path):
    """Events, ledger and hidden tables of every built-in at v = 0.6 and 0.95, blank and filled, the slices, odd
    numbers (L = 1e-5: exponents; v = 1e-6: long decimals), every character latex_text maps, and what
    `events` and `ledger --format latex` print, in one document."""
    tables = all_tables(0.6) + all_tables(0.95)
    tables.append(events_table(history_of("fig2", 0.6, L=1e-5), paper_frames(0.6)[0]))
    tables.append(events_table(history_of("fig2", 1e-6), paper_frames(1e-6, 0.3)[2]))
    tables.append(Table("odd", "odd", ("text", "n"), ((Cell("a_b & 50% #1 $5 {x} ~ ^ \\ <|>"),
                                                        Cell("1.110223e\N{MINUS SIGN}16")),
                                                       (Cell("B₁ t′ xᵤ γ − ² × ± ≤ → ·"), Cell("n/a"))), "ln"))
    fragments = [to_latex(table) for table in tables]
    # and the commands' whole files, several tables in each
    fragments += [cli("events", "fig2", "--frame-velocity", "0.3", "--format", "latex"),
                  cli("ledger", "while_turning", "--at", "0.5,1", "--format", "latex")]
    # a fragment byte-identical to an earlier one (a table with nothing to leave blank, or presets giving the same
    # table) compiles and fits exactly as the first: typeset each text once (22 of 169 repeat; pdflatex is the cost)
    fragments = list(dict.fromkeys(fragments))
    inputs = []
    for k, fragment in enumerate(fragments):
        (tmp_path / f"t{k}.tex").write_text(fragment, encoding="utf-8")
        inputs.append(rf"\noindent\input{{t{k}}}\par\bigskip")
    (tmp_path / "doc.tex").write_text("\n".join([
        r"\documentclass{article}", r"\usepackage[a4paper,margin=2.5cm]{geometry}", r"\usepackage{booktabs,siunitx}",
        r"\begin{document}", *inputs, r"\end{document}", ""]), encoding="utf-8")
    result = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error", "doc.tex"], cwd=tmp_path,
                            capture_output=True, text=True, timeout=300)
    log = (tmp_path / "doc.log").read_text(errors="replace")
    assert result.returncode == 0, "\n".join(line for line in log.splitlines() if line.startswith("!"))[:2000]
    assert "Overfull \\hbox" not in log  # every table fits the text width of an A4 page with 2.5 cm margins
    if shutil.which("pdftotext") is None:
        pytest.skip("pdftotext is not installed (apt-get install poppler-utils): the text was not checked")
    text = subprocess.run(["pdftotext", "doc.pdf", "-"], cwd=tmp_path, capture_output=True, text=True,
                          check=True).stdout
    # fig2 at v = 0.6 in S′: t′ = 17/12 and the rod's 15/17, printed with their digits and sign
    for expected in ("+1.416667", "(17/12)", "+0.882353", "(15/17)", "+0.5000000", "2.125", "1.875"):
        assert expected in text, expected


# --- the command line -------------------------------------------------------------------------------------

def test_events_text_format_is_the_default_byte_for_byte():
    assert cli("events", "fig2", "--format", "text") == cli("events", "fig2")
    assert cli("events", "fig2", "--format", "LaTeX") == cli("events", "fig2", "--format", "latex")


def test_events_latex_is_one_fragment_per_frame():
    text = cli("events", "fig2", "--frame-velocity", "0.3", "--format", "latex")
    assert text.startswith("% fig2: v = 0.6, L = 1 (c = 1; x and t in the unit L is given in)\n")
    assert text.count(r"\begin{tabular}{l l S") == 3 and text.count(r"\bottomrule") == 3
    assert "% The impacts in frame u = 0.3" in text and "{$x_{u}$}" in text


def test_unknown_format_is_refused_in_one_sentence():
    assert error_of("events", "fig2", "--format", "html") == (
        "Invalid value for '--format': 'html' is not one of 'text', 'markdown', 'latex'.")
    assert error_of("ledger", "fig2", "--format", "html") == (
        "option --format must be one of text, json, csv, markdown, latex, or one or more of svg, pdf, png "
        "comma-separated, got 'html'.")


def test_ledger_markdown_and_latex_to_a_file_by_extension(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert cli("ledger", "fig2", "-o", "l.md") == "l.md\n"
    assert cli("ledger", "fig2", "-o", "l.md") == "l.md (unchanged)\n"
    assert Path("l.md").read_text() == cli("ledger", "fig2", "--format", "markdown")
    assert cli("ledger", "fig2", "--at", "1,2", "-o", "l.tex", "-q") == ""
    latex = Path("l.tex").read_text()
    assert latex == cli("ledger", "fig2", "--at", "1,2", "--format", "latex")
    # per frame: the ledger, the hidden part between impacts (not zero in Fig. 2), the slices
    assert latex.count("% table ledger_") == latex.count("% table hidden_") == latex.count("% table slices_") == 2
    assert error_of("ledger", "fig2", "-o", "l.md", "--format", "latex") == (
        "option -o names 'l.md' but --format is latex; make them agree.")


def test_ledger_without_hidden_part_prints_no_hidden_table():
    """Fig. 1 in S: the rod takes both impacts together; nothing is ever hidden (README, the ledger)."""
    text = cli("ledger", "fig1", "--frame", "rest", "--format", "markdown")
    assert [c for c, _, _ in markdown_tables(text)] == ["Energy and momentum at each impact, frame S"]


# --- the documentation -----------------------------------------------------------------------------------------------

@pytest.mark.parametrize("page, command", [
    ("commands", "sears-paradox events fig1 --format markdown"),
    ("ledger", "sears-paradox ledger fig1 --frame moving --format markdown"),
])
def test_documented_markdown_examples_are_what_the_tool_prints_now(page, command):
    text = (ROOT / "docs" / f"{page}.md").read_text()
    printed = text.split(f"$ {command}\n")[1].split("```")[0]
    assert printed == cli(*command.split()[1:])
