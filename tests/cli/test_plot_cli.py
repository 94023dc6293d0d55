"""`sears-paradox plot`: file names, formats, quiet output, bad input (message + exit 2), determinism, make.

Each test runs in its own temporary folder (the default output folder is
./outputs). A few run the real command in a fresh process: what --help
imports, the Makefile (test_determinism checks the same bytes across processes).
"""

from __future__ import annotations

import errno
import os
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest
from click.testing import CliRunner

from sears_paradox_cli.main import main
from sears_paradox_cli.plot import plot

from helpers import blank_figure

ROOT = Path(__file__).resolve().parents[2]
#: plot's page of the documentation
PLOT_PAGE = (ROOT / "docs" / "plot.md").read_text()


@pytest.fixture(autouse=True)
def in_tmp(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    return tmp_path


def run(*args, expect=0):
    result = CliRunner().invoke(main, ["plot", *args])
    assert result.exit_code == expect, (result.output, result.exception)
    return result


def error_of(*args) -> str:
    """The one-sentence error a bad call prints; it must exit 2, print no traceback and write nothing."""
    before = _files(Path.cwd())
    result = run(*args, expect=2)
    assert isinstance(result.exception, SystemExit), result.exception  # a ClickException, not a crash
    assert result.output.count("\n") == 1 and result.output.startswith("Error: "), result.output
    assert _files(Path.cwd()) == before  # no figure, no temporary file
    return result.output[len("Error: "):].rstrip("\n")


def _files(folder: Path) -> set[str]:
    return {str(p.relative_to(folder)) for p in folder.rglob("*") if p.is_file()}


def command() -> list[str]:
    script = Path(sys.executable).parent / "sears-paradox"
    return [str(script)] if script.exists() else [sys.executable, "-c", "from sears_paradox_cli.main import main; main()"]


# --- names and places --------------------------------------------------------------------------------

def test_default_writes_outputs_fig2_svg_and_prints_only_its_path(in_tmp):
    result = run("fig2")
    assert result.output == "outputs/fig2.svg\n"
    assert (in_tmp / "outputs" / "fig2.svg").read_bytes().startswith(b"<?xml")
    assert _files(in_tmp) == {"outputs/fig2.svg"}


def test_an_unchanged_figure_is_not_rewritten_and_its_path_is_printed_as_unchanged(in_tmp):
    """fig2 in one panel (--frame rest; both before): the same comparison of bytes, less to draw four times."""
    run("fig2", "--frame", "rest")
    path = in_tmp / "outputs" / "fig2_rest.svg"
    old = time.time() - 1000
    os.utime(path, (old, old))
    assert run("fig2", "--frame", "rest").output == "outputs/fig2_rest.svg (unchanged)\n"
    assert path.stat().st_mtime == old
    # accepted, changes nothing
    assert run("fig2", "--frame", "rest", "--verbose").output == "outputs/fig2_rest.svg (unchanged)\n"
    assert run("fig2", "--frame", "rest", "--format", "svg,pdf").output == ("outputs/fig2_rest.svg (unchanged)\n"
                                                                           "outputs/fig2_rest.pdf\n")


@pytest.mark.parametrize("flag", ["-q", "--quiet"])
def test_quiet_prints_nothing_and_still_writes(in_tmp, flag, monkeypatch):
    """What is printed, written and then found unchanged: the figure is stood in for (`_figures_stood_in`)."""
    _figures_stood_in(monkeypatch)
    assert run("fig2", flag).output == ""
    assert _files(in_tmp) == {"outputs/fig2.svg"}
    assert run("fig2", flag).output == ""


@pytest.mark.parametrize("options, name", [
    ([], "fig2"),
    (["--v", "0.6"], "fig2"),  # the scenario's own value: the same figure, the same file
    (["--v", "0.8"], "fig2_v0.8"),
    (["--v", "0.8", "--L", "2"], "fig2_v0.8_L2"),
    (["--L", "2.5"], "fig2_L2.5"),
    (["--frame", "rest"], "fig2_rest"),
    (["--frame", "moving,0.3"], "fig2_moving_u0.3"),
    # the same panels asked for in other words: the same figure, the same file
    (["--frame", "both,both"], "fig2"),
    (["--frame", "rest,moving"], "fig2"),
    (["--frame", "both,rest,0.3,moving,0.30"], "fig2_both_u0.3"),
    (["--frame", "moving,rest"], "fig2_moving_rest"),
    (["--frame", "rest,0.3,moving"], "fig2_rest_u0.3_moving"),
    # a velocity that is S's or S''s is that frame, once, by its name
    (["--frame", "0,rest"], "fig2_rest"),
    (["--frame", "-0.6,moving"], "fig2_moving"),
    (["--frame", "0,-0.6,both"], "fig2"),
    (["--frame", "0.3,moving,-0.6,0.30,rest,-0"], "fig2_u0.3_moving_rest"),
    (["--frame", "moving", "--v", "0.8"], "fig2_v0.8_moving"),
    (["--frame", "-0.8,moving", "--v", "0.8"], "fig2_v0.8_moving"),
    # every digit the number has, no -0
    (["--frame", "-0"], "fig2_u0"),
    (["--frame", "0,-0.0"], "fig2_u0"),
    (["--frame", "0.9999999"], "fig2_u0.9999999"),
    (["--frame", "-0.9999999"], "fig2_u-0.9999999"),
    (["--v", "0.9999999"], "fig2_v0.9999999"),
    (["--L", "2.000000000000001"], "fig2_L2.000000000000001"),
    (["--style", "print"], "fig2_print"),
    (["--style", "slides", "--grid", "--other-axes"], "fig2_slides_axes_grid"),
    (["--light-cones", "--hyperbolae"], "fig2_cones_hyperbolae"),
])
def test_every_non_default_option_is_in_the_file_name(options, name, monkeypatch):
    """The name is the planning's: the figure itself (drawn and checked everywhere else) is stood in for here,
    so that these 27 cases cost what naming costs, not 27 drawings."""
    _figures_stood_in(monkeypatch)
    assert run("fig2", *options).output == f"outputs/{name}.svg\n"


def _figures_stood_in(monkeypatch) -> None:
    """`plot` draws no figure: each stands in as (its history, frames, style, options), and its bytes are those of
    its frames and style (the same figure, the same bytes; another, others). For the tests whose checks are made
    before the drawing (names, folders, messages) or after it (what is printed, written, left unchanged): the
    figures themselves are drawn and checked in every other test."""
    from rodparadox import render
    from sears_paradox_cli import plot

    monkeypatch.setattr(plot, "_figure", lambda run, frames, style, options: (run, frames, style, options))
    monkeypatch.setattr(render, "figure_bytes", lambda figure, fmt, style="default": repr(figure[1:3]).encode())


def test_several_scenarios_and_formats_in_one_call(in_tmp, monkeypatch):
    _blank_figures(monkeypatch)  # the planning and the writers are checked, not what is drawn
    (in_tmp / "figs").mkdir()
    shutil.copy(ROOT / "configs" / "fig1.yaml", in_tmp / "mine.yaml")
    # one panel each (--frame rest; both before): the same planning of several scenarios and formats, a third
    # of the drawing
    result = run("fig1", "fig2", "mine.yaml", "--format", "svg,pdf,png", "-o", "figs", "--frame", "rest")
    expected = [f"figs/{n}_rest.{f}" for n in ("fig1", "fig2", "mine") for f in ("svg", "pdf", "png")]
    assert result.output.splitlines() == expected
    assert (in_tmp / "figs" / "fig2_rest.pdf").read_bytes().startswith(b"%PDF-")
    assert (in_tmp / "figs" / "fig2_rest.png").read_bytes().startswith(b"\x89PNG")


def test_o_may_name_the_file_and_its_extension_gives_the_format(in_tmp, monkeypatch):
    _blank_figures(monkeypatch)  # the names and the format written are checked, not what is drawn
    assert run("fig1", "-o", "paper-figure.pdf").output == "paper-figure.pdf\n"
    assert (in_tmp / "paper-figure.pdf").read_bytes().startswith(b"%PDF-")
    assert run("fig1", "-o", "slide.png", "--format", "png", "--style", "slides").output == "slide.png\n"


def _blank_figures(monkeypatch) -> None:
    """`plot` draws each figure blank (an empty 2 x 2 inch figure) and writes it with its real writer
    (`render.figure_bytes`): for the tests that check names and formats written, not what is drawn."""
    from sears_paradox_cli import plot

    monkeypatch.setattr(plot, "_figure", blank_figure)


def test_the_default_folder_is_created_but_no_other(in_tmp, monkeypatch):
    _figures_stood_in(monkeypatch)
    run("fig1")
    assert (in_tmp / "outputs").is_dir()


def test_same_scenario_twice_is_drawn_and_written_once(monkeypatch):
    """Each draw is counted, then stood in for (an object whose figure is its scenario's name): what is drawn and
    written is checked here, not how."""
    from types import SimpleNamespace

    from rodparadox import render

    drawn = []
    monkeypatch.setattr(render, "draw", lambda history, *args: drawn.append(history.scenario.name) or
                        SimpleNamespace(figure=history.scenario.name))
    monkeypatch.setattr(render, "figure_bytes", lambda figure, fmt, style="default": repr((figure, fmt)).encode())
    assert run("fig2", "fig2", "fig1", "fig2").output == "outputs/fig2.svg\noutputs/fig1.svg\n"
    assert drawn == ["fig2", "fig1"]


def test_a_dollar_in_a_scenario_file_name_is_drawn(in_tmp):
    Path("cost$1.yaml").write_text("v: 0.6\nparticles: {B: {gap: 0.5}}\n")  # one $, no pair for mathtext to take as math
    assert run("fig2", "cost$1.yaml", "-o", ".").output == "fig2.svg\ncost$1.svg\n"
    assert _files(in_tmp) == {"cost$1.yaml", "fig2.svg", "cost$1.svg"}


def test_every_figure_is_laid_out_before_any_file_is_written(in_tmp, monkeypatch):
    from rodparadox import render

    real, calls = render.draw, []

    def fails_second_time(*args, **kwargs):
        calls.append(args)
        if len(calls) == 2:
            raise RuntimeError("layout failed")
        return real(*args, **kwargs)

    monkeypatch.setattr(render, "draw", fails_second_time)
    result = run("fig2", "fig1", expect=1)
    assert result.output == "" and _files(in_tmp) == set()


# --- bad input: one sentence, exit 2, nothing written ----------------------------------------------------

def test_missing_output_folder():
    assert error_of("fig2", "-o", "nope") == "the output folder nope does not exist; create it first."
    assert error_of("fig2", "-o", "nope/fig.svg") == (
        "cannot write nope/fig.svg: the folder nope does not exist; create it first.")


def test_output_folder_that_is_a_file(in_tmp):
    (in_tmp / "afile").write_text("x")
    assert error_of("fig2", "-o", "afile") == (
        "option -o: afile is a file, not a folder; give a folder or a name ending in .svg, .pdf, .png.")
    assert error_of("fig2", "-o", "afile/fig.svg") == "cannot write afile/fig.svg: afile is a file, not a folder."


def test_unwritable_output_folder(in_tmp, unwritable_folder):
    folder = unwritable_folder
    message = error_of("fig2", "-o", str(folder))
    assert message == f"cannot write {folder}/fig2.svg: permission denied in the folder {folder}."


def test_bad_frame():
    assert error_of("fig2", "--frame", "sideways") == (
        "option --frame: a frame must be rest, moving, both, rod (the rod's own view) or a velocity U with "
        "-0.9999999 <= U <= 0.9999999 (or a comma-separated list of these), got 'sideways'.")
    assert error_of("fig2", "--frame", "rest,1.5") == (
        "option --frame: a frame velocity must be a number U with -0.9999999 <= U <= 0.9999999 (units of c) "
        "for double precision to place the events, got 1.5.")


def test_more_panels_than_a_figure_holds(monkeypatch):
    _figures_stood_in(monkeypatch)  # the last call's name is checked: its frames are fig2's two, drawn above
    nine = ",".join(str(k / 10) for k in range(1, 10))
    assert error_of("fig2", "--frame", nine) == (
        "option --frame: 9 different frames asked for; at most 8 panels fit in one figure.")
    assert error_of("fig2", "--frame", "both,0.1,0.2,0.3,0.4,0.5,0.6,0.7") == (
        "option --frame: 9 different frames asked for; at most 8 panels fit in one figure.")
    assert run("fig2", "--frame", "both,both,both,both,both,both,both,both,both").output == "outputs/fig2.svg\n"


def test_the_panel_limit_is_the_number_of_panel_letters():
    from rodparadox import render
    from rodparadox.physics.frames import MAX_PANELS

    assert MAX_PANELS == len(render.PANEL_LETTERS)


def test_bad_format():
    assert error_of("fig2", "--format", "jpg") == (
        "option --format must be one or more of svg, pdf, png, comma-separated, got 'jpg'.")
    assert error_of("fig2", "-o", "fig.jpg").startswith("the output folder fig.jpg does not exist")


def test_one_file_for_several_outputs():
    assert error_of("fig1", "fig2", "-o", "f.svg") == (
        "option -o names one file, 'f.svg', but 2 scenarios were given; give a folder instead.")
    assert error_of("fig2", "-o", "f.svg", "--format", "svg,pdf") == (
        "option -o names one file, 'f.svg', but --format asks for 2 formats; give a folder instead.")
    assert error_of("fig2", "-o", "f.svg", "--format", "pdf") == "option -o names 'f.svg' but --format is pdf; make them agree."


def test_bad_scenario_and_bad_override_write_nothing_even_for_the_good_ones():
    assert error_of("fig2", "nosuch").startswith("there is no built-in scenario 'nosuch'")
    assert error_of("fig2", "--v", "1.2") == "option --v: v must be a number with 0 < v < 1 (units of c), got 1.2."
    Path("early.yaml").write_text("v: 0.5\nparticles:\n  A: {timed_with: {particle: B, frame: rest, delay: -0.3}}\n"
                                  "  B: {gap: 0.1}\n")
    message = error_of("fig1", "early.yaml")
    assert message.startswith("early.yaml: particles.A.timed_with: A cannot strike the rod")


def test_a_failed_write_leaves_no_partial_file(in_tmp, monkeypatch):
    import rodparadox.io.output

    def full_disk(src, dst):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(rodparadox.io.output.os, "replace", full_disk)
    _figures_stood_in(monkeypatch)  # the write fails, whatever is written
    result = run("fig2", expect=1)  # the system failed, not the input: exit status 1
    assert result.output == "Error: cannot write outputs/fig2.svg: no space left on device.\n"
    assert _files(in_tmp) == set()


def test_a_failure_while_drawing_exits_non_zero_and_leaves_finished_files_whole(in_tmp, monkeypatch):
    from rodparadox import render

    real, calls = render.figure_bytes, []

    def fails_second_time(*args, **kwargs):
        calls.append(args[1])
        if len(calls) == 2:
            raise RuntimeError("renderer crashed")
        return real(*args, **kwargs)

    monkeypatch.setattr(render, "figure_bytes", fails_second_time)
    result = run("fig2", "--format", "svg,pdf", expect=1)
    assert result.output == "outputs/fig2.svg\n"
    assert _files(in_tmp) == {"outputs/fig2.svg"}
    assert (in_tmp / "outputs" / "fig2.svg").read_bytes().rstrip().endswith(b"</svg>")


# --- processes: imports, make --------------------------------------------------------------------------

def test_help_does_not_import_matplotlib_and_plot_never_imports_pyplot(in_tmp):
    probe = (
        "import sys\n"
        "from sears_paradox_cli.main import main\n"
        "def call(*args):\n"
        "    try:\n"
        "        main([*args])\n"
        "    except SystemExit:\n"
        "        pass\n"
        "call('plot', '--help')\n"
        "print('probe', 'matplotlib' in sys.modules, 'numpy' in sys.modules)\n"
        "call('plot', 'fig1', '-o', '.')\n"
        "print('probe', 'matplotlib' in sys.modules, 'matplotlib.pyplot' in sys.modules)\n"
        f"print('probe', sorted(m for m in sys.modules if m.startswith({NOT_FOR_A_RIGID_PLOT!r})))\n"
    )
    out = subprocess.run([sys.executable, "-c", probe], check=True, capture_output=True, text=True).stdout
    assert [line for line in out.splitlines() if line.startswith("probe")] == [
        "probe False False", "probe True False", "probe []"]


#: what a rigid rod's figure draws nothing with, so `plot` of one never imports it (each costs the process time):
#: the causal rod (its physics, scipy's integrator, its layers and their colour scale), the rod's own view's
#: Gauss-Legendre nodes (numpy.polynomial), the other commands' packages; and, the probe's figure being an SVG
#: (plot's default), the PDF's font subsets (fontTools.subset, matplotlib's PDF backend: 0.09 s)
NOT_FOR_A_RIGID_PLOT = ("scipy", "rodparadox.physics.causal", "rodparadox.render.causal", "rodparadox.render.colour_scale",
                        "rodparadox.render.rod_panel", "numpy.polynomial", "rodparadox.web", "rodparadox.handout",
                        "rodparadox.animate", "rodparadox.tables", "rodparadox.render.pdf_fonts", "fontTools.subset",
                        "matplotlib.backends.backend_pdf")


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("make") is None, reason="needs make")
def test_make_figures_has_a_rule_for_every_config_builds_in_parallel_and_then_only_what_changed(in_tmp):
    out = in_tmp / "made"
    tool = " ".join(f"'{part}'" for part in command())
    args = ["make", "-C", str(ROOT), "--no-print-directory", f"OUTPUTS={out}", "FORMATS=svg",
            f"SEARS_PARADOX={tool}"]
    # every config has its rule (a dry run: what make would run), and two of them are built for real, in parallel
    planned = subprocess.run(args + ["-n", "figures"], check=True, capture_output=True, text=True).stdout
    names = sorted(p.stem for p in (ROOT / "configs").glob("*.yaml"))  # forces too: plot draws them
    assert sorted(re.findall(r"plot configs/(\w+)\.yaml --format svg -o " + re.escape(str(out)), planned)) == names
    args.append("CONFIGS=configs/fig1.yaml configs/single.yaml")
    first = subprocess.run(args + ["-j2", "figures"], check=True, capture_output=True, text=True).stdout
    assert sorted(p.stem for p in out.glob("*.svg")) == ["fig1", "single"]
    assert sorted(re.findall(r"made/(\w+)\.svg", first)) == ["fig1", "single"]

    again = subprocess.run(args + ["figures"], check=True, capture_output=True, text=True).stdout
    assert "Nothing to be done" in again

    stamp, svg = out / ".stamps" / "fig1", out / "fig1.svg"
    old = (ROOT / "configs" / "fig1.yaml").stat().st_mtime - 1000  # not now - 1000: older than the scenario whatever its age
    os.utime(stamp, (old, old))  # as if configs/fig1.yaml had changed since
    mtime = svg.stat().st_mtime
    third = subprocess.run(args + ["figures"], check=True, capture_output=True, text=True).stdout
    assert re.findall(r"plot configs/(\w+)\.yaml", third) == ["fig1"]
    assert svg.stat().st_mtime == mtime  # same bytes: left untouched


# --- the documentation --------------------------------------------------------------------------------------------

def _readme_plot_section() -> str:
    return PLOT_PAGE


def test_readme_documents_every_plot_option_and_style():
    section = _readme_plot_section()
    for param in plot.params:
        for flag in getattr(param, "opts", []):
            if flag.startswith("--"):
                assert f"`{flag}" in section, flag
    for style in ("default", "print", "slides"):
        assert f"`{style}`" in section


def test_readme_figures_are_what_the_tool_draws_now():
    """The README's figures are generated by `make readme-figures`; redraw them and compare."""
    import matplotlib

    from rodparadox import render
    from rodparadox.physics.rigid import run as simulate
    from rodparadox.physics.frames import paper_frames
    from rodparadox.io.scenario import load

    section = _readme_plot_section()
    made_with = (ROOT / "outputs" / "readme" / "made-with.txt").read_text().split()
    for name in ("fig1", "fig2"):
        path = ROOT / "outputs" / "readme" / f"{name}.svg"
        assert f"outputs/readme/{name}.svg" in section
        scenario = load(name)
        drawn = render.figure_bytes(render.draw(simulate(scenario), paper_frames(scenario.v)).figure, "svg")
        committed = path.read_bytes()
        if made_with == ["matplotlib", matplotlib.__version__]:
            assert drawn == committed, f"{path} is out of date: run `make readme-figures`"
        else:  # another matplotlib writes other bytes: compare what is drawn, to 0.01 pt
            assert _geometry(drawn) == _geometry(committed), f"{path} is out of date: run `make readme-figures`"


def _geometry(svg: bytes) -> dict[str, list[float]]:
    import xml.etree.ElementTree as ET

    ns = "{http://www.w3.org/2000/svg}"
    out = {}
    for group in ET.fromstring(svg).iter(f"{ns}g"):
        gid = group.get("id", "")
        if re.match(r"[ab]-(rod_left|rod_right|A|B|impact-\w+|simultaneity-.*)$", gid):
            numbers = [round(float(n), 2) for p in group.iter(f"{ns}path") for n in re.findall(r"-?\d+\.?\d*", p.get("d", ""))]
            out[gid] = numbers
    return out


# --- edges of the command line (issue 6: items 11, 12, 14) ------------------------------------------------------

def test_a_dangling_link_as_output_says_where_it_leads(in_tmp):
    Path("d.svg").symlink_to("gone/fig.svg")
    assert error_of("fig2", "-o", "d.svg") == (
        f"cannot write d.svg: it is a symbolic link to gone/fig.svg, whose folder {in_tmp}/gone does not exist.")
    Path("figs").symlink_to("nowhere")
    assert error_of("fig2", "-o", "figs") == (
        "the output folder figs is a symbolic link to nowhere, which does not exist; create it first.")


@pytest.mark.parametrize("args, message", [
    (("--format", ""), "option --format must be one or more of svg, pdf, png, comma-separated, got ''."),
    (("--format", "svg,"), "option --format must be one or more of svg, pdf, png, comma-separated, got 'svg,'."),
    (("--format", ",pdf"), "option --format must be one or more of svg, pdf, png, comma-separated, got ',pdf'."),
    (("-o", ""), "option -o must name a file or folder, got ''."),
])
def test_empty_values_are_refused(args, message):
    assert error_of("fig2", *args) == message


def test_a_local_file_wins_over_the_builtin_and_yaml_extensions_in_any_case(in_tmp):
    Path("fig2").write_text("name: mine\nv: 0.3\nparticles: {B: {gap: 0.5}}\n")
    Path("X.YAML").write_text("v: 0.6\nparticles: {B: {gap: 0.5}}\n")
    Path("y.Yml").write_text("v: 0.6\nparticles: {A: {gap: 0.5}}\n")
    assert run("fig2", "X.YAML", "y.Yml", "-o", ".").output == "fig2.svg\nX.svg\ny.svg\n"
    assert b"mine" in Path("fig2.svg").read_bytes()
