"""A handout for authors (`handout --format tex`; docs/handout.md, "Teaching handouts"): a folder of LaTeX, figures and
pgfplots data.

`tex_files` turns a `document.Handout` into files, relative name -> bytes, for
the command to write atomically into one folder:

* `handout.tex`: a standalone document for `pdflatex` with standard packages only
  (article, geometry, graphicx, booktabs, siunitx, amsmath, caption) setting every
  block of the handout in order;
* `NAME.tex`: each table, the booktabs/siunitx fragment of `to_latex`, `\\input` by
  handout.tex (a worksheet's table with its blank cells, the answer key's filled copy
  as `NAME_key.tex`);
* `NAME.pdf`: each figure, the diagram `plot` draws and the strips `animate` draws,
  vector, in the handout's style;
* `SECTION_FRAME_WORLDLINE.dat`, `SECTION_FRAME_events.dat`: each section's world-lines
  and impacts in each frame its diagram shows, as whitespace-separated columns under a
  header line (`x t`, `label x t`), every float as `repr` writes it (it reads back to the
  same double), so pgfplots' `\\addplot table {...}` reads them directly;
* `README.txt`: what the files are and the pgfplots lines that read them.

No dates, no versions: the same handout gives the same bytes. matplotlib is imported only
when a figure is drawn, so nothing that merely imports this module pays for it.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import lru_cache

from rodparadox.handout.document import (PAPERS, Block, DiagramBlock, Handout, Heading, PageBreak, Paragraph, Question,
                                         RodViewBlock, Section, Strips, Table)
from rodparadox.handout.words import math_pieces
from rodparadox.physics.history import RodHistory
from rodparadox.physics.frames import Frame, frame_word, sampling_tolerance, view
from rodparadox.render.styles import STYLES
from rodparadox.tables.formats import latex_text, to_latex

#: the margin on every side of the page; the figures of the strips are drawn at the width this leaves
MARGIN_MM = 20.0
#: LaTeX's name for each paper size of `document.PAPERS`
_LATEX_PAPER = {"a4": "a4paper", "letter": "letterpaper"}
#: the comment line before a worksheet's answer key in handout.tex: what precedes it is what the student sees
ANSWER_KEY_MARK = "% the answer key"
#: ruled lines a worksheet leaves under each question for the student's answer
ANSWER_LINES = 5
#: a strip block's height: room for the time axis and the colour bar, plus one row per instant (inches)
_STRIPS_BELOW_IN, _STRIPS_ROW_IN = 1.45, 0.5
#: where the type needs more (slides), each row this many times the least row `draw_strips_into` accepts, as a PDF
#: handout's rows (room for the particles' letters)
_STRIPS_ROW_SCALE = 1.25
#: characters a file name keeps; a dot would end the name for graphicx (`u0.3` -> `u0p3`), anything else is `-`
_UNSAFE = re.compile(r"[^A-Za-z0-9_-]")


def file_stem(name: str) -> str:
    """A name as a file stem pdflatex, graphicx and pgfplots all read: `u0.3` -> `u0p3`, `a b` -> `a-b`."""
    return _UNSAFE.sub(lambda m: "p" if m.group() == "." else "-", name)


def number(value: float) -> str:
    """A float as the .dat files write it: `repr`, which reads back to the same double; no −0."""
    return repr(float(value) + 0.0)


# --- where each block's file goes ----------------------------------------------------------------------------


@dataclass(frozen=True)
class _Placed:
    """A block of the document and, for a table or a figure, the stem of its file."""

    block: Block
    stem: str | None
    in_answer_key: bool


def _prefixed(section: Section, name: str) -> str:
    """A block's name with its section's in front (fig2_events_rest), unless it has it already."""
    stem = file_stem(section.name)
    return name if name == stem or name.startswith(stem + "_") else f"{stem}_{name}"


def _content_key(block: Block) -> tuple:
    """What makes two blocks' files the same: a table's fragment, a figure's history, frames and times."""
    if isinstance(block, Table):
        return ("table", to_latex(block))
    if isinstance(block, DiagramBlock):
        return ("diagram", id(block.history), id(block.compared), block.frames)
    if isinstance(block, RodViewBlock):
        return ("rod view", tuple(id(h) for h in block.histories))
    assert isinstance(block, Strips)
    return ("strips", id(block.history), block.frame, tuple(block.times))


def _same_origin(section_block: Block, key_block: Block) -> bool:
    """Whether an answer-key block is a copy of a section's block: the filled copy of its table, or its figure."""
    if type(section_block) is not type(key_block) or section_block.name != key_block.name:
        return False
    if isinstance(key_block, Table):
        return section_block.filled() == key_block.filled()
    return section_block.history is key_block.history


def _place(handout: Handout) -> list[_Placed]:
    """Every block in order, each table and figure with a file stem of its own.

    A block's stem is its name with its section's in front (so fig1 and fig2 can both have `events_rest`); an
    answer-key block takes the stem of the section's block it copies (a worksheet's table filled, found by its
    cells), with `_key` when its content differs; a stem already taken by other content gets `_2`, `_3`, ...
    """
    taken: dict[str, tuple] = {}

    def claim(wanted: str, key: tuple, answer_key: bool) -> str:
        candidates = [wanted] + ([wanted + "_key"] if answer_key else [])
        candidates += [f"{candidates[-1]}_{k}" for k in range(2, len(taken) + 3)]
        for stem in candidates:
            if taken.get(stem, key) == key:
                taken[stem] = key
                return stem
        raise AssertionError("unreachable: more candidates than stems taken")

    placed = []
    for section in handout.sections:
        for block in section.blocks:
            stem = None
            if isinstance(block, (Table, DiagramBlock, RodViewBlock, Strips)):
                stem = claim(file_stem(_prefixed(section, block.name)), _content_key(block), False)
            placed.append(_Placed(block, stem, False))
    in_sections = [p for p in placed if p.stem is not None]
    for block in handout.answer_key:
        stem = None
        if isinstance(block, (Table, DiagramBlock, RodViewBlock, Strips)):
            origin = next((p.stem for p in in_sections if _same_origin(p.block, block)), None)
            stem = claim(origin or file_stem(block.name), _content_key(block), True)
        placed.append(_Placed(block, stem, True))
    return placed


# --- handout.tex ---------------------------------------------------------------------------------------------

_PREAMBLE = r"""%% handout.tex, written by sears-paradox handout --format tex: compile with pdflatex handout.tex
%% (standard packages only; the figures NAME.pdf and the tables NAME.tex are in this folder)
\documentclass[11pt]{article}
\usepackage[%(paper)s,margin=%(margin)smm]{geometry}
\usepackage[utf8]{inputenc}
\usepackage{amsmath}
\usepackage{graphicx}
\usepackage{booktabs}
\usepackage{siunitx}
\usepackage[font=small,labelfont=bf,skip=6pt]{caption}
\captionsetup[table]{position=top}
%% the same PDF from the same sources: no date, no random ID, no pdfTeX banner in the file (pdfTeX only)
\ifdefined\pdfinfoomitdate \pdfinfoomitdate=1 \pdftrailerid{} \pdfsuppressptexinfo=-1 \fi
\setlength{\parindent}{0pt}
\setlength{\parskip}{0.6\baselineskip plus 2pt}
%% a worksheet's room to write: #1 ruled lines the width of the text
\newcount\answerline
\newcommand{\answerlines}[1]{\par\answerline=0
  \loop\ifnum\answerline<#1 \advance\answerline by 1
  \vspace{1.7\baselineskip}\noindent\rule{\linewidth}{0.4pt}\par\repeat}
%% a question, its number hanging in the margin of its paragraph
\newcommand{\question}[2]{\par\noindent\hangindent=1.8em\hangafter=1\makebox[1.8em][l]{\textbf{#1.}}#2\par}
\newenvironment{answer}{\par\nopagebreak\begin{list}{}{\setlength{\leftmargin}{1.8em}%%
  \setlength{\topsep}{0pt}\setlength{\parsep}{0.4\baselineskip}}\item[]}{\end{list}}
"""


_PRIMES = re.compile(r"['′]")
#: two pieces of math side by side ($-$ then $L$): one $...$ (never $$, which TeX reads as display math)
_ADJACENT_MATH = re.compile(r"(?<!\\)\$\$")
#: the same after a control word and before a letter ($\Delta$ then $t$): a space keeps \Delta t from \Deltat
_ADJACENT_AFTER_WORD = re.compile(r"(?<!\\)(\\[A-Za-z]+)\$\$(?=[A-Za-z])")


def _variable(token: str) -> str:
    """A variable (`words.VARIABLE`) as math: t′ -> $t'$, tᵤ -> $t_{u}$, x_P -> $x_{P}$, u² -> $u^{2}$."""
    letter, rest = token[0], token[1:]
    body = letter + "'" * len(_PRIMES.findall(rest))
    rest = _PRIMES.sub("", rest)
    power = "^{2}" if rest.endswith("²") else ""
    rest = rest.rstrip("²").lstrip("_")
    if rest:
        body += "_{" + rest.translate(_SUBSCRIPT_LETTERS) + "}"
    return f"${body}{power}$"


_SUBSCRIPT_LETTERS = str.maketrans("ᵤ₀₁₂₃₄₅₆₇₈₉", "u0123456789")


@lru_cache(maxsize=4096)  # a worksheet and its key, a handout and its worksheet, say the same sentences; bounded
def prose(text: str) -> str:
    """Running text as LaTeX (`latex_text`), its variables (`words.math_pieces`: v, L, t′, x, E, p, u) in math
    italics, as the PDF sets them; units (c, M), frames (S′) and labels (A, B₁) upright."""
    latex = "".join(_variable(piece) if variable else latex_text(piece).replace("$S'$", "S$'$")  # S′: a label
                    for piece, variable in math_pieces(text))
    return _ADJACENT_MATH.sub("", _ADJACENT_AFTER_WORD.sub(r"\1 ", latex))


def _figure(stem: str, caption: str) -> str:
    # not a float: the figure stays where the handout puts it, whole on one page, with its caption under it; at the
    # width of the text unless that would be taller than most of a page
    return "\n".join([r"\par\medskip\noindent\begin{minipage}{\linewidth}", r"\centering",
                      rf"\includegraphics[width=\textwidth,height=0.8\textheight,keepaspectratio]{{{stem}.pdf}}",
                      rf"\captionof{{figure}}{{{prose(caption)}}}", r"\end{minipage}\par\medskip", ""])


def _table(stem: str, table: Table) -> str:
    # not a float either: in its place, never split across pages, its caption above it
    return "\n".join([r"\par\medskip\noindent\begin{minipage}{\linewidth}", r"\centering",
                      rf"\captionof{{table}}{{{prose(table.caption)}}}", rf"\input{{{stem}.tex}}",
                      r"\end{minipage}\par\medskip", ""])


def _question(q: Question, worksheet: bool, in_answer_key: bool) -> str:
    """A worksheet's question with room to write; in the answer key (or a handout) with its worked answer."""
    lines = [rf"\question{{{q.number}}}{{{prose(q.text)}}}"]
    if worksheet and not in_answer_key:
        # the question and its lines on one page
        return "\n".join([r"\par\noindent\begin{minipage}{\linewidth}", *lines, rf"\answerlines{{{ANSWER_LINES}}}",
                          r"\end{minipage}\par\bigskip", ""])
    if q.answer:
        lines += [r"\begin{answer}", "\n\n".join(prose(a) for a in q.answer), r"\end{answer}"]
    return "\n".join(lines + [""])


def _block(p: _Placed, worksheet: bool) -> str:
    b = p.block
    if isinstance(b, Heading):
        return (r"\section*{" if b.level == 1 else r"\subsection*{") + prose(b.text) + "}\n"
    if isinstance(b, Paragraph):
        return prose(b.text) + "\n"
    if isinstance(b, Table):
        return _table(p.stem, b)
    if isinstance(b, (DiagramBlock, RodViewBlock, Strips)):
        return _figure(p.stem, b.caption)
    if isinstance(b, Question):
        return _question(b, worksheet, p.in_answer_key)
    if isinstance(b, PageBreak):
        return "\\clearpage\n"
    raise TypeError(f"a handout has no block of type {type(b).__name__}")


def handout_tex(handout: Handout, placed: list[_Placed], paper: str) -> str:
    """The standalone document: the preamble, the title, then every block in order (the answer key from a new
    page), each block a paragraph of its own."""
    parts = [_PREAMBLE % {"paper": _LATEX_PAPER[paper], "margin": f"{MARGIN_MM:g}"}, r"\begin{document}", "",
             r"\begin{center}{\LARGE\bfseries " + prose(handout.title) + r"\par}\end{center}", ""]
    key_started = False
    for p in placed:
        if p.in_answer_key and not key_started:
            parts += [ANSWER_KEY_MARK, r"\clearpage", ""]
            key_started = True
        parts.append(_block(p, handout.worksheet))
    parts += [r"\end{document}", ""]
    return "\n".join(parts)


# --- figures -------------------------------------------------------------------------------------------------


#: the resolution the rod view's and the strips' figures are laid out at (their vector files do not depend on it
#: but for rounding in the last printed digit): matplotlib's default, given, not read from the process's
#: rcParams, so a caller's figure.dpi (a style left applied, a notebook's) never changes a byte
FIGURE_DPI = 100.0


def text_width_in(paper: str) -> float:
    """The width of the text on the page, in inches: the paper less a margin each side."""
    return PAPERS[paper][0] - 2 * MARGIN_MM / 25.4


def figure_pdf(block: DiagramBlock | RodViewBlock | Strips, paper: str, style: str) -> bytes:
    """A figure block as PDF bytes: the diagram as `plot` draws it, or the strips as `animate` draws them, at the
    width of the text so their type prints at its size."""
    from rodparadox import render

    if isinstance(block, DiagramBlock):
        # a worksheet's diagram without the scenario's title (a preset's may say what it asks), the panels' velocities
        # or the lines of simultaneity through the impacts (which impacts share one is asked)
        # no title above the panels, as in the PDF: the plot's title names the scenario by its file name (fig2),
        # which a student never reads; the section's heading and the caption say what it shows
        options = render.Options(titled=False, equal_scales=block.equal_scales, simultaneity=block.tell)
        diagram = render.draw(block.drawn, block.frames, style, options)
        block.retitle(diagram)
        figure = diagram.figure
    elif isinstance(block, RodViewBlock):
        from matplotlib.figure import Figure

        width, height = render.rod_view_size(block.histories, style, text_width_in(paper) * 72)
        figure = Figure(figsize=(text_width_in(paper), height / 72), dpi=FIGURE_DPI)
        render.draw_rod_view_into(figure, block.histories, style)
    else:
        from matplotlib.figure import Figure

        # the least block the strips take in this style (large type in slides) grows the figure past the default
        least = render.strips_size(block.history, block.frame, block.times, style, _STRIPS_ROW_SCALE,
                                   partners=block.partners)[1] / 72
        figure = Figure(figsize=(text_width_in(paper),
                                 max(_STRIPS_BELOW_IN + _STRIPS_ROW_IN * len(block.times), least)), dpi=FIGURE_DPI)
        render.draw_strips_into(figure, block.history, block.frame, block.times, style, partners=block.partners)
    return render.figure_bytes(figure, "pdf", style)


# --- pgfplots data -------------------------------------------------------------------------------------------


def worldline_dat(points) -> str:
    """One world-line: the header `x t`, then one point a line."""
    return "x t\n" + "".join(f"{number(x)} {number(t)}\n" for x, t in points)


def events_dat(history: RodHistory, frame: Frame) -> str:
    """The impacts in one frame, in its time order (the rod's order at one instant): `label x t`."""
    events = sorted(view(history, frame).events, key=lambda e: e.t)
    return "label x t\n" + "".join(f"{e.impact.label} {number(e.x)} {number(e.t)}\n" for e in events)


def _shown_frames(section: Section) -> list[tuple[str, RodHistory, Frame]]:
    """The (file prefix, history, frame) of each frame the section's diagrams show, each once: the prefix is the
    section's name, or the diagram's where the section draws more than one history."""
    diagrams = [b for b in section.blocks if isinstance(b, DiagramBlock) and b.compared is None]
    several = len({id(d.history) for d in diagrams}) > 1
    out, seen = [], set()
    for d in diagrams:
        prefix = file_stem(_prefixed(section, d.name) if several else section.name)
        for frame in d.frames:
            key = (prefix, file_stem(frame_word(frame)))
            if key not in seen:
                seen.add(key)
                out.append((prefix, d.history, frame))
    return out


def data_files(handout: Handout) -> dict[str, str]:
    """Each section's world-lines and events in each frame its diagrams show, as pgfplots reads them."""
    files = {}
    for section in handout.sections:
        for prefix, history, frame in _shown_frames(section):
            stem = f"{prefix}_{file_stem(frame_word(frame))}"
            points = view(history, frame).worldline_points(sampling_tolerance(history))
            for name, xt in points.items():
                files[f"{stem}_{name}.dat"] = worldline_dat(xt)
            files[f"{stem}_events.dat"] = events_dat(history, frame)
    return files


#: each frame's coordinates as the README's pgfplots example names them (ASCII inside $...$)
def _axis_names(frame: Frame) -> tuple[str, str]:
    return {"rest": ("x", "t"), "moving": ("x'", "t'")}.get(frame.name, ("x_u", "t_u"))


def readme(handout: Handout) -> str:
    """What the folder holds, and the pgfplots lines that draw the first frame's world-lines from its .dat files."""
    lines = ["Files of a handout, written by sears-paradox handout --format tex.", "",
             "  handout.tex   the whole handout; compile it here with: pdflatex handout.tex",
             "                (packages: geometry, graphicx, booktabs, siunitx, amsmath, caption)",
             "  NAME.pdf      each figure, vector, to \\includegraphics",
             "  NAME.tex      each table, a booktabs/siunitx tabular to \\input (load booktabs and siunitx);",
             "                NAME_key.tex is the answer key's filled copy of a worksheet's table",
             "  *.dat         world-lines and impacts, one file per section, frame and world-line:",
             "                SECTION_FRAME_WORLDLINE.dat has the columns x t, SECTION_FRAME_events.dat",
             "                has label x t; x and t in that frame (c = 1, in the unit L is given in),",
             "                every number written so that it reads back to the same double", ""]
    shown = [s for section in handout.sections for s in _shown_frames(section)]
    if shown:
        prefix, history, frame = shown[0]
        stem = f"{prefix}_{file_stem(frame_word(frame))}"
        x, t = _axis_names(frame)
        lines += [f"pgfplots reads them directly; for instance {prefix} in its frame {x}, {t}:", "",
                  "  \\usepackage{pgfplots}  % in the preamble", "",
                  "  \\begin{tikzpicture}",
                  f"  \\begin{{axis}}[axis equal image, xlabel={{${x}$}}, ylabel={{${t}$}}]"]
        for name, _ in view(history, frame).segments:
            dashed = ", dashed" if name in ("A", "B") else ""  # the particles dashed, as the figures draw them
            lines.append(f"    \\addplot[no markers{dashed}] table {{{stem}_{name}.dat}};")
        lines += ["    \\addplot[only marks, nodes near coords, point meta=explicit symbolic]",
                  f"      table[x=x, y=t, meta=label] {{{stem}_events.dat}};",
                  "  \\end{axis}", "  \\end{tikzpicture}", ""]
    return "\n".join(lines)


# --- the folder ----------------------------------------------------------------------------------------------


def tex_sources(handout: Handout, paper: str = "a4", placed: list[_Placed] | None = None) -> dict[str, str]:
    """The folder's LaTeX text, without drawing a figure: handout.tex and each table's NAME.tex."""
    placed = _place(handout) if placed is None else placed
    text = {"handout.tex": handout_tex(handout, placed, paper)}
    for p in placed:
        if isinstance(p.block, Table):
            text.setdefault(f"{p.stem}.tex", to_latex(p.block))
    return text


def tex_files(handout: Handout, paper: str = "a4", style: str = "print") -> dict[str, bytes]:
    """The folder of a handout for authors: relative file name -> bytes (module docstring), sorted by name.

    Raises ValueError for a paper not in `document.PAPERS` or a style not in `styles.STYLES`.
    """
    if paper not in PAPERS:
        raise ValueError(f"unknown paper size {paper!r}; use one of {', '.join(PAPERS)}.")
    if style not in STYLES:
        raise ValueError(f"unknown style {style!r}; use one of {', '.join(STYLES)}.")
    placed = _place(handout)
    text = tex_sources(handout, paper, placed)
    figures = {}
    for p in placed:
        name = f"{p.stem}.pdf"
        if isinstance(p.block, (DiagramBlock, RodViewBlock, Strips)) and name not in figures:
            figures[name] = figure_pdf(p.block, paper, style)
    text.update(data_files(handout))
    text["README.txt"] = readme(handout)
    files = {name: data.encode("utf-8") for name, data in text.items()}
    files.update(figures)
    return dict(sorted(files.items()))
