"""A `document.Table` as Markdown (a GitHub pipe table) or as a LaTeX fragment (booktabs and siunitx). Pure text.

The LaTeX fragment is meant to be `\\input` into a document that loads
booktabs and siunitx: a `tabular` with `\\toprule`, `\\midrule` and
`\\bottomrule`, every number column an siunitx `S` column aligned at the
decimal point and printing each number with the digits and sign it has here
(`+0.5000000`, never rounded or regrouped). The caption is a comment line at
the top, because the including document places its own `\\caption`; the notes
are small paragraphs after the tabular, not a `\\multicolumn` row under it, so
that a long note wraps at the text's width instead of widening the table's
last column.

`latex_text` is the one mapping from this project's plain Unicode text
(B₁, t′, γ, −, ², ×, xᵤ) to LaTeX; other writers of LaTeX reuse it.
"""

from __future__ import annotations

import re
from functools import lru_cache
from typing import Sequence

from rodparadox.tables.table import Cell, Table

# --- plain Unicode text to LaTeX ------------------------------------------------------------------------

#: characters with a meaning of their own in LaTeX text, and how to print them
_SPECIAL = {"\\": r"\textbackslash{}", "_": r"\_", "&": r"\&", "%": r"\%", "#": r"\#", "$": r"\$", "{": r"\{",
            "}": r"\}", "~": r"\textasciitilde{}", "^": r"\textasciicircum{}",
            # the default (OT1) text fonts print ¡, ¿ and an em rule for these three
            "<": r"\textless{}", ">": r"\textgreater{}", "|": r"\textbar{}"}
#: text characters LaTeX writes its own way
_TEXT = {"\N{EN DASH}": "--", "\N{EM DASH}": "---", "\N{LEFT SINGLE QUOTATION MARK}": "`",
         "\N{RIGHT SINGLE QUOTATION MARK}": "'", "\N{LEFT DOUBLE QUOTATION MARK}": "``",
         "\N{RIGHT DOUBLE QUOTATION MARK}": "''", "\N{HORIZONTAL ELLIPSIS}": r"\ldots{}",
         "\N{NO-BREAK SPACE}": "~", "\N{THIN SPACE}": r"\,", "\N{NARROW NO-BREAK SPACE}": r"\,"}
#: characters that are mathematics: each becomes a piece of math mode, merged with its neighbours
_MATH = {"\N{MINUS SIGN}": "-", "\N{MULTIPLICATION SIGN}": r"\times", "\N{PLUS-MINUS SIGN}": r"\pm",
         "\N{MINUS-OR-PLUS SIGN}": r"\mp", "\N{MIDDLE DOT}": r"\cdot", "\N{DOT OPERATOR}": r"\cdot",
         "\N{LESS-THAN OR EQUAL TO}": r"\le", "\N{GREATER-THAN OR EQUAL TO}": r"\ge",
         "\N{ALMOST EQUAL TO}": r"\approx", "\N{NOT EQUAL TO}": r"\ne", "\N{RIGHTWARDS ARROW}": r"\to",
         "\N{INFINITY}": r"\infty", "\N{SQUARE ROOT}": r"\surd", "\N{DEGREE SIGN}": r"^\circ",
         "\N{INTEGRAL}": r"\int",
         "\N{PRIME}": "'", "\N{DOUBLE PRIME}": "''",
         "\N{GREEK SMALL LETTER ALPHA}": r"\alpha", "\N{GREEK SMALL LETTER BETA}": r"\beta",
         "\N{GREEK SMALL LETTER GAMMA}": r"\gamma", "\N{GREEK SMALL LETTER DELTA}": r"\delta",
         "\N{GREEK CAPITAL LETTER DELTA}": r"\Delta", "\N{GREEK SMALL LETTER EPSILON}": r"\epsilon",
         "\N{GREEK SMALL LETTER ETA}": r"\eta", "\N{GREEK SMALL LETTER THETA}": r"\theta",
         "\N{GREEK SMALL LETTER LAMDA}": r"\lambda", "\N{GREEK SMALL LETTER MU}": r"\mu",
         "\N{GREEK SMALL LETTER PI}": r"\pi", "\N{GREEK SMALL LETTER SIGMA}": r"\sigma",
         "\N{GREEK SMALL LETTER TAU}": r"\tau", "\N{GREEK SMALL LETTER PHI}": r"\phi",
         "\N{GREEK SMALL LETTER PSI}": r"\psi", "\N{GREEK SMALL LETTER OMEGA}": r"\omega"}
_SUBSCRIPTS = dict(zip("₀₁₂₃₄₅₆₇₈₉₊₋ₐₑₒₓᵢⱼₖₙₚₛₜᵤᵥ", "0123456789+-aeoxijknpstuv"))
_SUPERSCRIPTS = dict(zip("⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻ⁿ", "0123456789+-n"))
#: marks that make the single letter before them a mathematical symbol: t′ is $t'$, xᵤ is $x_u$; digit
#: subscripts do not (B₁ is the impact B$_1$, its letter upright like the figures' labels)
_SYMBOL_MARKS = {"\N{PRIME}", "\N{DOUBLE PRIME}", *(c for c, letter in _SUBSCRIPTS.items() if letter.isalpha())}


@lru_cache(maxsize=8192)  # a table repeats its headers and numbers, a handout its tables in the key; bounded
def latex_text(text: str) -> str:
    """Plain Unicode text as LaTeX text: the special characters escaped, and B₁, t′, x′, xᵤ, γ, −, ², × written
    in math mode (B$_{1}$, $t'$, $x_{u}$, $\\gamma$, $-$, $^{2}$, $\\times$), consecutive math in one $...$.

    ASCII and the Latin-1 letters (é) that LaTeX's utf8 input reads pass through; any other character is
    refused with a ValueError naming it, since pdflatex would stop on it.
    """
    pieces: list[tuple[bool, str]] = []  # (is math, LaTeX)
    k = 0
    while k < len(text):
        c = text[k]
        if c in _SUBSCRIPTS or c in _SUPERSCRIPTS:
            table, mark = (_SUBSCRIPTS, "_") if c in _SUBSCRIPTS else (_SUPERSCRIPTS, "^")
            run = ""
            while k < len(text) and text[k] in table:
                run += table[text[k]]
                k += 1
            pieces.append((True, f"{mark}{{{run}}}"))
            continue
        if c in _SPECIAL:
            pieces.append((False, _SPECIAL[c]))
        elif c in _TEXT:
            pieces.append((False, _TEXT[c]))
        elif c in _MATH:
            pieces.append((True, _MATH[c]))
        elif c.isascii() or ("\u00c0" <= c <= "\u00ff" and c.isalpha()):
            # a lone letter marked as a symbol (t′, xᵤ) goes into the math with its mark
            if (c.isalpha() and k + 1 < len(text) and text[k + 1] in _SYMBOL_MARKS and c.isascii()
                    and (k == 0 or not text[k - 1].isalnum() or text[k - 1] in _MATH)):  # γt′: a word of math
                pieces.append((True, c))
            else:
                pieces.append((False, c))
        else:
            raise ValueError(f"no LaTeX spelling for the character {c!r} (U+{ord(c):04X}) in {text!r}")
        k += 1
    out = []
    for is_math, group in _runs(pieces):
        out.append(f"${_join_math(group)}$" if is_math else "".join(group))
    return "".join(out)


def _runs(pieces: list[tuple[bool, str]]):
    """Consecutive pieces of the same kind, as (is math, [pieces])."""
    runs: list[tuple[bool, list[str]]] = []
    for is_math, piece in pieces:
        if runs and runs[-1][0] == is_math:
            runs[-1][1].append(piece)
        else:
            runs.append((is_math, [piece]))
    return runs


def _join_math(group: list[str]) -> str:
    """Math pieces in one string: a control word (\\gamma) keeps a space before a letter that follows it."""
    out = ""
    for piece in group:
        if re.search(r"\\[A-Za-z]+$", out) and piece[:1].isalpha():
            out += " "
        out += piece
    return out


# --- Markdown ---------------------------------------------------------------------------------------

#: what a blank (worksheet) cell prints in Markdown and plain text
BLANK_TEXT = "____"
_MARKDOWN_ESCAPE = str.maketrans({"\\": "\\\\", "|": "\\|", "*": "\\*", "_": "\\_", "`": "\\`"})


def _markdown_cell(cell: Cell) -> str:
    return BLANK_TEXT if cell.blank else cell.text.translate(_MARKDOWN_ESCAPE)


def to_markdown(table: Table) -> str:
    """A GitHub-flavoured pipe table: the caption as a bold line above it, a blank cell as `____`, numbers flush
    right, the notes as lines below; columns padded to one width so the text reads as a table too."""
    header = [h.translate(_MARKDOWN_ESCAPE) for h in table.header]
    rows = [[_markdown_cell(c) for c in row] for row in table.rows]
    widths = [max([len(header[k]), 4] + [len(row[k]) for row in rows]) for k in range(len(header))]

    def line(cells: list[str]) -> str:
        return "| " + " | ".join(c.rjust(w) if a != "l" else c.ljust(w)
                                 for c, w, a in zip(cells, widths, table.align)) + " |"

    rule = "| " + " | ".join(":" + "-" * (w - 1) if a == "l" else "-" * (w - 1) + ":"
                             for a, w in zip(table.align, widths)) + " |"
    lines = [f"**{table.caption.translate(_MARKDOWN_ESCAPE)}**", "", line(header), rule, *map(line, rows)]
    for note in table.notes:  # a paragraph each
        lines += ["", note.translate(_MARKDOWN_ESCAPE)]
    return "\n".join(lines) + "\n"


# --- LaTeX: booktabs and siunitx ------------------------------------------------------------------------

#: the ruled space a worksheet leaves for a student's answer: a rule wide enough to write +1.416667 by hand, with
#: an invisible strut that makes its row tall enough to write above it (only rows with blanks grow)
BLANK_RULE = r"\rule{0pt}{3.2ex}\rule{5em}{0.4pt}"
#: every S column prints its numbers as given: the explicit plus kept, no rounding, no digit groups, and an exponent
#: as the text tables write it, 1.583333e−5, not 1.583333 × 10⁻⁵, which would not fit a page in the events table
#: (set in a group around the tabular, so the including document's own siunitx settings are untouched)
SIUNITX_OPTIONS = r"retain-explicit-plus, round-mode=none, group-digits=none, output-exponent-marker=\ensuremath{\mathrm{e}}"
#: the line of fractions sits this much closer under its numbers than a row would
FRACTION_LINE_SKIP = "-0.6ex"
#: a number as the tables print it, optionally followed by its exact fraction: +1.416667 (17/12), 1.110223e−16
_NUMBER = re.compile(r"(?P<sign>[+\-\N{MINUS SIGN}]?)(?P<integer>\d+)(?:\.(?P<decimal>\d*))?"
                     r"(?:[eE](?P<exponent_sign>[+\-\N{MINUS SIGN}]?)(?P<exponent>\d+))?"
                     r"(?: \((?P<fraction>[^()]*)\))?")


def _number(text: str) -> re.Match | None:
    return _NUMBER.fullmatch(text.strip())


def table_format(texts: list[str]) -> str | None:
    """siunitx's `table-format` for the numbers among `texts`, from the widest of each part: `+1.7` for
    +0.5000000 and −1.250000, `1.6e-2` for 1.110223e−16; None when no text is a number."""
    numbers = [m for m in map(_number, texts) if m]
    if not numbers:
        return None
    signed = any(m["sign"] for m in numbers)
    integer = max(len(m["integer"]) for m in numbers)
    decimal = max(len(m["decimal"] or "") for m in numbers)
    spec = ("+" if signed else "") + str(integer) + (f".{decimal}" if decimal else "")
    exponents = [m for m in numbers if m["exponent"]]
    if exponents:
        spec += "e" + ("-" if any(m["exponent_sign"] for m in exponents) else "")
        spec += str(max(len(str(int(m["exponent"]))) for m in exponents))  # siunitx drops leading zeros: e−05 is e−5
    return spec


def _siunitx_number(m: re.Match) -> str:
    """The number part of a match, as siunitx parses it (a hyphen for the minus sign)."""
    text = m["sign"] + m["integer"] + (f".{m['decimal']}" if m["decimal"] is not None else "")
    if m["exponent"]:
        text += "e" + m["exponent_sign"] + m["exponent"]
    return text.replace("\N{MINUS SIGN}", "-")


def _column_spec(table: Table, k: int) -> str:
    """Column k's tabular spec: l or r for text, an siunitx S column with the table-format of its numbers."""
    if table.align[k] != "n":
        return table.align[k]
    fmt = table_format([row[k].text for row in table.rows])
    return f"S[table-format={fmt}]" if fmt else "S"


#: a header longer than this (in characters) in a number column is set on two lines, split at a space, so that
#: `particle before` and `rod before` are not wider than their numbers
HEADER_WRAP = 8


def _latex_header(head: str, align: str) -> str:
    """A column's header: a lone letter (x, t) is a coordinate, in math as x′ is; long ones on two lines."""
    text = f"${head}$" if len(head) == 1 and head.isascii() and head.isalpha() else latex_text(head)
    if align != "n":
        return text
    words = head.split(" ")
    if len(head) > HEADER_WRAP and len(words) > 1:
        # split at the space nearest the middle
        cut = min(range(1, len(words)), key=lambda j: abs(len(" ".join(words[:j])) - len(" ".join(words[j:]))))
        top, bottom = latex_text(" ".join(words[:cut])), latex_text(" ".join(words[cut:]))
        text = rf"\begin{{tabular}}[b]{{@{{}}c@{{}}}}{top}\\ {bottom}\end{{tabular}}"
    return "{" + text + "}"  # braced: siunitx reads it as text


def _latex_cell(cell: Cell, align: str) -> str:
    """One cell: a number (without its fraction) as siunitx reads it, anything else as braced text."""
    if align != "n":
        return BLANK_RULE if cell.blank else latex_text(cell.text)
    if cell.blank:
        return "{" + BLANK_RULE + "}"
    m = _number(cell.text)
    if m:
        return _siunitx_number(m)
    return "{" + latex_text(cell.text) + "}" if cell.text.strip() else "{}"


def _fraction_cell(cell: Cell, align: str) -> str:
    """The exact fraction of a number cell, in small type, for the line under it; else nothing."""
    m = None if cell.blank or align != "n" else _number(cell.text)
    return r"{\footnotesize(" + latex_text(m["fraction"]) + ")}" if m and m["fraction"] else ""


#: after the tabular (kept in a macro): set it in a box; if it is wider than the line, set it again in footnote
#: size with half the column gap; if still wider, scale it to the line (with graphicx's \resizebox, when loaded)
FIT_TO_LINE = (r"\setbox0=\hbox{\rodparadoxtable}%",
               r"\ifdim\wd0>\linewidth\footnotesize\setlength{\tabcolsep}{3pt}\setbox0=\hbox{\rodparadoxtable}\fi",
               r"\ifdim\wd0>\linewidth\ifdefined\resizebox\setbox0=\hbox{\resizebox{\linewidth}{!}{\box0}}\fi\fi",
               r"\leavevmode\box0")


def to_latex(table: Table) -> str:
    """The table as a LaTeX fragment to `\\input` into a document that loads booktabs and siunitx.

    The caption is the first line, as a comment; number columns are siunitx S columns with a `table-format` from
    their widest number, each number printed as given (explicit plus, every digit); a number's exact fraction
    (`+1.416667 (17/12)`) is set in small type on a line of its own under the number, so that a column is as
    wide as its numbers and the events table fits a page; a blank cell is a rule of fixed width in a row tall enough
    to write in (BLANK_RULE); the notes follow the tabular as small paragraphs. A tabular wider than the line
    (masses of 1e-6 and 1e6 make a ledger's numbers twelve digits long) is set again smaller (FIT_TO_LINE).
    """
    lines = [f"% {' '.join(table.caption.split())}", f"% table {table.name}: booktabs and siunitx",
             rf"\begingroup\sisetup{{{SIUNITX_OPTIONS}}}%", r"\def\rodparadoxtable{%"]
    lines += [r"\begin{tabular}{" + " ".join(_column_spec(table, k) for k in range(len(table.align))) + "}",
              r"\toprule",
              " & ".join(_latex_header(h, a) for h, a in zip(table.header, table.align)) + r" \\",
              r"\midrule"]
    for row in table.rows:
        fractions = [_fraction_cell(c, a) for c, a in zip(row, table.align)]
        cells = " & ".join(_latex_cell(c, a) for c, a in zip(row, table.align))
        if any(fractions):
            lines += [cells + rf" \\[{FRACTION_LINE_SKIP}]", " & ".join(fractions) + r" \\"]
        else:
            lines.append(cells + r" \\")
    lines += [r"\bottomrule", r"\end{tabular}}%", *FIT_TO_LINE, r"\endgroup"]
    for k, note in enumerate(table.notes):
        space = r"\par\smallskip" if k == 0 else r"\par"
        lines.append(space + r"\noindent{\footnotesize " + latex_text(note) + r"\par}")
    return "\n".join(lines) + "\n"


# --- several tables as one text -------------------------------------------------------------------------

def tables_markdown(heading: str, tables: Sequence[Table]) -> str:
    """A heading line, then each table (to_markdown), a blank line between."""
    return "\n".join([heading.translate(_MARKDOWN_ESCAPE) + "\n", *(to_markdown(t) for t in tables)])


def tables_latex(heading: str, tables: Sequence[Table]) -> str:
    """The heading as a comment, then each table's fragment (to_latex), a \\bigskip between: one file to \\input."""
    body = "\n\\bigskip\n\n".join(to_latex(t) for t in tables)  # the blank line before \bigskip ends a paragraph
    return f"% {' '.join(heading.split())}\n\n" + body
