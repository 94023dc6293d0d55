"""The handout for authors (`handout_tex.tex_files`): the folder's files, the pgfplots data read back exactly, the
table fragments, handout.tex set in the blocks' order, and (where pdflatex is installed) the document compiled.

The handouts here are built by hand from document blocks for fig1 and fig2 at v = 0.6, independently of the
generator of the real handout's blocks.
"""

import math
import re
import shutil
import subprocess
import sys

import numpy as np
import pytest

from rodparadox.handout.document import DiagramBlock, Handout, Heading, PageBreak, Paragraph, Question, Section, Strips, Table
from rodparadox.physics.rigid import run
from rodparadox.physics.frames import frame_of_velocity, frame_symbol, frame_word, paper_frames, sampling_tolerance, view
from rodparadox.handout.tex import data_files, file_stem, number, tex_files
from rodparadox.io.scenario import load
from rodparadox.tables.formats import BLANK_RULE
from rodparadox.tables.build import events_table, hidden_table, ledger_table

V = 0.6
G = 1 / math.sqrt(1 - V * V)  # 1.25
#: plain Unicode the handout's text uses; every one of these must come out of pdflatex right
UNICODE = "In S′ B₁ and A₁ share t′ = 17/12 L ≈ 1.416667 L; γ = 1.25, γ²v² = 0.5625, the rod at −0.6, xᵤ, 2 × 3."


def section(name: str, worksheet: bool, first: bool = True) -> tuple[Section, list]:
    """A scenario's section, as a handout sets it: from a new page unless it is the first, heading, text, the
    diagram, per frame the tables and the strips, the questions of a worksheet; with its answer-key blocks (the
    filled tables and the worked answers) for a worksheet."""
    history = run(load(name).with_overrides(v=V))
    frames = paper_frames(V)
    blocks = [] if first else [PageBreak()]
    blocks += [Heading(f"{name}: the rod struck at both ends"), Paragraph(UNICODE),
              DiagramBlock("diagram", history, frames, "The rod in S and in S′: B₁ and A₁ on one line of t′.")]
    key = []
    for frame in frames:
        blocks.append(Heading(f"In frame {frame_symbol(frame)}", 2))
        for table in (events_table(history, frame, worksheet), ledger_table(history, frame, worksheet),
                      hidden_table(history, frame, worksheet)):
            if table is not None:
                blocks.append(table)
                key.append(table.filled())
        lo, hi = view(history, frame).t_range
        blocks.append(Strips(f"strips_{frame_word(frame)}", history, frame, tuple(np.linspace(lo, hi, 6)[1:-1]),
                             f"The rod at successive instants of {frame_symbol(frame)}"))
    questions = [Question(1, f"{name}: read the coordinates of B₁ in S′ off panel (b).",
                          ("x′ = 1.25 L and t′ = γ(1 + v²)/2v L = 17/12 L.", "So B₁ is at t′ ≈ 1.416667 L.")),
                 Question(2, "Are A₁ and B₁ simultaneous in S?", ("Check with t = γ(t′ − v x′).",))]
    if worksheet:
        blocks += questions
        key = [Heading(f"{name}: answers", 2), *key, *questions]
    else:
        key = []
    return Section(name, f"{name} at v = {V}", tuple(blocks)), key


def handout(names: tuple[str, ...], worksheet: bool) -> Handout:
    sections, key = zip(*(section(n, worksheet, k == 0) for k, n in enumerate(names)))
    answer_key = (Heading("Answer key"), *(b for k in key for b in k)) if worksheet else ()
    return Handout("The Sears paradox", tuple(sections), worksheet, answer_key)


#: most tests read the one worksheet (a module fixture): in one worker, so it is made once
pytestmark = pytest.mark.xdist_group("handout_tex")


@pytest.fixture(scope="module")
def worksheet():
    h = handout(("fig1", "fig2"), worksheet=True)
    return h, tex_files(h)


def tables_of(h: Handout, in_key: bool) -> list[Table]:
    blocks = h.answer_key if in_key else [b for s in h.sections for b in s.blocks]
    return [b for b in blocks if isinstance(b, Table)]


# --- the folder ----------------------------------------------------------------------------------------------


def test_the_folder_holds_every_table_figure_and_world_line(worksheet):
    h, files = worksheet
    expected = {"handout.tex", "README.txt"}
    for s in h.sections:
        history = next(b.history for b in s.blocks if isinstance(b, DiagramBlock))
        expected |= {f"{s.name}_diagram.pdf", f"{s.name}_strips_rest.pdf", f"{s.name}_strips_moving.pdf"}
        for frame in paper_frames(V):
            word = frame_word(frame)
            expected |= {f"{s.name}_{word}_{w}.dat" for w in ("A", "B", "rod_left", "rod_right", "events")}
            # a worksheet's tables blank in the section, filled in the answer key
            kinds = ["events", "ledger"] + (["hidden"] if hidden_table(history, frame) is not None else [])
            expected |= {f"{s.name}_{kind}_{word}{key}.tex" for kind in kinds for key in ("", "_key")}
    assert set(files) == expected
    assert "fig1_hidden_rest.tex" not in files  # fig1 in S: nothing hidden on any slice (README, the ledger)
    assert list(files) == sorted(files)
    assert all(isinstance(b, bytes) and b for b in files.values())
    assert all(files[n].startswith(b"%PDF-") for n in files if n.endswith(".pdf"))


def test_the_same_handout_gives_the_same_bytes(worksheet):
    h, files = worksheet
    again = tex_files(handout(("fig1", "fig2"), worksheet=True))  # new histories, new figures; in two processes:
    assert again == files                                         # test_determinism (`handout fig1 --format tex`)
    assert all(b"CreationDate" not in b and b"ModDate" not in b for b in files.values())


def test_a_figure_does_not_depend_on_the_process_figure_dpi(worksheet):
    """A figure's bytes never depend on the process's rcParams: the strips were laid out at whatever figure.dpi the
    process had (a style a suspended animation left applied: 72), which moved a bar's edge in the last printed
    digit (146.495562 against 146.495563 pt)."""
    import matplotlib

    from rodparadox.handout.tex import figure_pdf

    h, files = worksheet
    strips = [(s.name, b) for s in h.sections for b in s.blocks if isinstance(b, Strips)]
    assert len(strips) == 4  # fig1 and fig2, each in S and S'
    with matplotlib.rc_context({"figure.dpi": 72}):
        for name, block in strips:
            assert figure_pdf(block, "a4", "print") == files[f"{name}_strips_{frame_word(block.frame)}.pdf"], name


def test_paper_and_style_are_checked_and_chosen(worksheet):
    h, files = worksheet
    one = Handout("t", (Section("s", "s", (Paragraph("x"),)),))
    with pytest.raises(ValueError, match="unknown paper size 'a5'"):
        tex_files(one, paper="a5")
    with pytest.raises(ValueError, match="unknown style 'grey'"):
        tex_files(one, style="grey")
    assert b"\\usepackage[a4paper," in files["handout.tex"]
    assert b"\\usepackage[letterpaper," in tex_files(one, paper="letter")["handout.tex"]
    assert set(tex_files(one)) == {"handout.tex", "README.txt"}


# --- pgfplots data -------------------------------------------------------------------------------------------


def test_every_world_line_reads_back_to_the_exact_points(worksheet):
    h, files = worksheet
    for s in h.sections:
        history = next(b.history for b in s.blocks if isinstance(b, DiagramBlock))
        for frame in paper_frames(V):
            points = view(history, frame).worldline_points(sampling_tolerance(history))
            assert set(points) == {"A", "B", "rod_left", "rod_right"}
            for name, xt in points.items():
                text = files[f"{s.name}_{frame_word(frame)}_{name}.dat"].decode()
                assert text.splitlines()[0] == "x t"
                read = np.loadtxt(text.splitlines(), skiprows=1, ndmin=2)
                assert read.shape == xt.shape and len(xt) >= 2
                assert np.array_equal(read, xt)  # exact: repr round-trips every double
                assert not re.search(r"(^|\s)-0(\.0*)?(e[-+]?\d+)?(\s|$)", text)  # no −0


def test_the_events_files_hold_each_frames_coordinates(worksheet):
    h, files = worksheet
    for s in h.sections:
        history = next(b.history for b in s.blocks if isinstance(b, DiagramBlock))
        rest = {e.impact.label: (e.x, e.t) for e in view(history, paper_frames(V)[0]).events}
        for frame in paper_frames(V):
            lines = files[f"{s.name}_{frame_word(frame)}_events.dat"].decode().splitlines()
            assert lines[0] == "label x t"
            rows = [line.split() for line in lines[1:]]
            read = {label: (float(x), float(t)) for label, x, t in rows}
            fv = view(history, frame)
            assert read == {e.impact.label: (e.x, e.t) for e in fv.events}
            assert [float(t) for _, _, t in rows] == sorted(float(t) for _, _, t in rows)  # the frame's time order
            # independently: the Lorentz transformation of S's coordinates (S' moves at -v: x' = g(x + vt))
            u = -frame.velocity
            g = 1 / math.sqrt(1 - u * u)
            for label, (x, t) in rest.items():
                assert read[label] == pytest.approx((g * (x + u * t), g * (t + u * x)), abs=1e-12)
    fig2_moving = dict((r.split()[0], r.split()[1:]) for r in files["fig2_moving_events.dat"].decode().splitlines())
    assert float(fig2_moving["B1"][1]) == pytest.approx(17 / 12, abs=1e-12)  # the paper's t'_B = g(1 + v^2)/2v
    assert float(fig2_moving["A1"][1]) == pytest.approx(G * (1 + V * V) / (2 * V), abs=1e-12)


def test_numbers_are_repr_exact_without_negative_zero():
    assert number(-0.0) == "0.0"
    assert number(17 / 12) == "1.4166666666666667"
    assert float(number(0.1 + 0.2)) == 0.1 + 0.2
    assert number(np.float64(-1e-300)) == "-1e-300"


def test_a_frame_of_any_velocity_gets_a_file_name_graphicx_reads():
    history = run(load("fig2").with_overrides(v=V))
    frames = (paper_frames(V)[0], frame_of_velocity(0.3), frame_of_velocity(-0.25))
    h = Handout("t", (Section("fig2", "fig2", (DiagramBlock("diagram", history, frames, "c"),)),))
    names = set(data_files(h))
    assert {"fig2_u0p3_A.dat", "fig2_u-0p25_rod_right.dat", "fig2_rest_events.dat"} <= names
    assert len(names) == 3 * 5
    assert file_stem("u0.3") == "u0p3" and file_stem("my scenario") == "my-scenario"


def test_the_readme_shows_pgfplots_lines_for_files_that_exist(worksheet):
    h, files = worksheet
    readme = files["README.txt"].decode()
    read = re.findall(r"\\addplot\[[^\]]*\] table \{([^}]+)\};", readme)
    assert read == ["fig1_rest_A.dat", "fig1_rest_B.dat", "fig1_rest_rod_left.dat", "fig1_rest_rod_right.dat"]
    assert "table[x=x, y=t, meta=label] {fig1_rest_events.dat}" in readme
    assert readme.isascii()


# --- the tables and handout.tex ------------------------------------------------------------------------------


def data_rows(fragment: str) -> list[str]:
    """The lines of a tabular's body that start a row of the table (a line of small fractions under a row's
    numbers, whose cells are all empty or fractions, continues the row above)."""
    body = fragment.split("\\midrule\n", 1)[1].split("\\bottomrule", 1)[0]
    rows = []
    for line in body.splitlines():
        cells = [c.strip() for c in re.sub(r"\\\\(\[[^\]]*\])?\s*$", "", line).split("&")]
        if any(c and not re.fullmatch(r"\{\\footnotesize\s*\([^()]*\)\}", c) for c in cells):
            rows.append(line)
    return rows


def test_each_table_is_its_fragment_with_a_row_per_table_row(worksheet):
    h, files = worksheet
    tex = files["handout.tex"].decode()
    inputs = re.findall(r"\\input\{([^}]+)\.tex\}", tex)
    tables = tables_of(h, False) + tables_of(h, True)
    assert len(inputs) == len(tables) == len(set(inputs))
    for stem, table in zip(inputs, tables):
        fragment = files[f"{stem}.tex"].decode()
        assert [m for m in re.findall(r"\\(toprule|midrule|bottomrule)", fragment)] == ["toprule", "midrule",
                                                                                         "bottomrule"]
        assert fragment.count("\\begin{tabular}") == fragment.count("\\end{tabular}")
        assert len(data_rows(fragment)) == len(table.rows)
        blanks = sum(c.blank for row in table.rows for c in row)
        assert fragment.count(BLANK_RULE) == blanks
        assert (blanks > 0) == (not stem.endswith("_key"))  # blank in the worksheet, filled in the answer key
    key = files["fig2_events_moving_key.tex"].decode()
    assert "+1.416667" in key and "17/12" in key  # B₁'s t′ in S′, the paper's 17/12 L


def test_handout_tex_sets_every_block_in_order(worksheet):
    h, files = worksheet
    tex = files["handout.tex"].decode()
    assert tex.isascii()
    assert tex.startswith("%") and tex.rstrip().endswith("\\end{document}")
    for package in ("graphicx", "booktabs", "siunitx", "geometry"):
        assert re.search(r"\\usepackage(\[[^\]]*\])?\{" + package + "}", tex)
    assert "fontspec" not in tex
    # each figure and table where its block is, in the blocks' order
    refs = re.findall(r"\\(?:includegraphics\[[^\]]*\]|input)\{([^}]+)\}", tex)
    shown = [b for b in h.blocks() if isinstance(b, (Table, DiagramBlock, Strips))]
    assert len(refs) == len(shown)
    for ref, block in zip(refs, shown):
        assert ref in files and ref.endswith(".tex" if isinstance(block, Table) else ".pdf")
        assert block.name in ref
    assert tex.count("\\section*{") == 3 and tex.count("\\subsection*{") == 6  # two scenarios, the answer key
    assert "\\section*{Answer key}" in tex
    body, key = tex.split("\\section*{Answer key}")
    assert body.rstrip().endswith("\\clearpage")  # the answer key from a new page
    assert body.count("\\clearpage") == 2  # the second section's PageBreak, then the answer key's page
    # the worksheet's questions with room to write and no answers; the answer key's with their worked answers
    assert body.count("\\answerlines{") == 4 and key.count("\\answerlines{") == 0
    assert key.count("\\begin{answer}") == 4
    assert "$x'$ = 1.25 $L$ and $t'$ = $\\gamma$(1 + $v^{2}$)/2$v$ $L$ = 17/12 $L$." in key
    assert "$x'$ = 1.25 $L$" not in body


def test_a_handout_prints_its_questions_with_their_answers():
    blocks = (Heading("fig2"), Paragraph("What is γ?"), Question(1, "What is γ at v = 0.6?", ("γ = 1.25.",)))
    tex = tex_files(Handout("t", (Section("fig2", "fig2", blocks),)))["handout.tex"].decode()
    assert "\\answerlines" not in tex.split("\\begin{document}")[1]
    assert "\\begin{answer}\n$\\gamma$ = 1.25.\n\\end{answer}" in tex


def test_importing_the_writer_does_not_import_matplotlib():
    code = "import sys, rodparadox.handout.tex; print('matplotlib' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "False"


# --- compiled ------------------------------------------------------------------------------------------------


def write(files: dict[str, bytes], folder) -> None:
    for name, data in files.items():
        (folder / name).write_bytes(data)


def pdflatex(folder, name: str = "handout.tex") -> str:
    done = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error", name], cwd=folder,
                          capture_output=True, text=True, timeout=120)
    log = (folder / name.replace(".tex", ".log")).read_text(errors="replace")
    assert done.returncode == 0, log[-3000:]
    return log


@pytest.mark.skipif(shutil.which("pdflatex") is None, reason="pdflatex is not installed")
def test_handout_tex_compiles_with_pdflatex_and_holds_the_events(worksheet, tmp_path):
    h, files = worksheet
    write(files, tmp_path)
    log = pdflatex(tmp_path)
    assert "Missing character" not in log
    assert "Undefined control sequence" not in log
    assert "! " not in log
    assert "Overfull \\vbox" not in log  # nothing runs off a page
    assert (tmp_path / "handout.pdf").stat().st_size > 0
    if shutil.which("pdftotext") is None:
        pytest.skip("pdftotext is not installed")
    text = subprocess.run(["pdftotext", "-layout", "handout.pdf", "-"], cwd=tmp_path, capture_output=True,
                          text=True, check=True).stdout
    # B₁ of fig2 in S′, as the answer key's events table prints it: in S it is at x = L/2, t_B = L/2v (the
    # paper), so x′ = g(L/2 + v t_B) = 1.25 L and t′ = g(t_B + v L/2) = 17/12 L
    t_b = 1 / (2 * V)
    assert f"+{G * (0.5 + V * t_b):.6f}" in text and f"+{G * (t_b + V * 0.5):.6f} " in text
    assert "(17/12)" in text and "Answer key" in text


@pytest.mark.skipif(shutil.which("pdflatex") is None or shutil.which("kpsewhich") is None,
                    reason="pdflatex is not installed")
def test_pgfplots_reads_the_world_lines_as_the_readme_shows(worksheet, tmp_path):
    found = subprocess.run(["kpsewhich", "pgfplots.sty"], capture_output=True, text=True).stdout.strip()
    if not found:
        pytest.skip("pgfplots is not installed")
    h, files = worksheet
    write({n: b for n, b in files.items() if n.endswith(".dat")}, tmp_path)
    readme = files["README.txt"].decode()
    picture = readme[readme.index("\\begin{tikzpicture}"):readme.index("\\end{tikzpicture}") + len("\\end{tikzpicture}")]
    (tmp_path / "plot.tex").write_text("\n".join([r"\documentclass{article}", r"\usepackage{pgfplots}",
                                                  r"\begin{document}", picture, r"\end{document}", ""]))
    log = pdflatex(tmp_path, "plot.tex")
    assert "Undefined control sequence" not in log and "! " not in log
    assert "fig1_rest_rod_left.dat" in log and "fig1_rest_events.dat" in log  # the tables were read
