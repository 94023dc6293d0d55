"""The README and the documentation site (docs/): every example runs and prints what it shows, the site builds with
warnings as errors, the notebook runs, the gallery is current, and the project's own facts agree (the CI command,
the version in the changelog).

The rules for examples (docs/contributing.md, "The documentation"):
* a `console` block: each `$ ` line runs, in one temporary folder per page, in order; the lines under it up to the
  next `$ ` are exactly what it prints on standard output, and every file or folder it prints exists and is what its
  name says (SVG, PDF, PNG, GIF, HTML, JSON). `sears-paradox` runs in this process (click's runner); another
  command (`mkdir`) in a shell. `html` runs on a coarser speed grid (2 speeds, 3 ledger instants): the same
  command and output path; tests/web/test_html.py checks the full page.
* a `python` block runs in that folder; `print(...)  # -> TEXT` must print TEXT (`...` in TEXT stands for any
  text), and every file name it writes (a string ending in .png, .pdf, .svg, .gif) must exist afterwards.
* every `sears-paradox ...` command written out in prose or in a `sh` block is parsed by the command's own options
  (without running it), so a renamed option or a word it no longer takes fails here.
"""

from __future__ import annotations

import contextlib
import hashlib
import importlib.util
import io
import json
import os
import re
import shlex
import subprocess
import sys
from pathlib import Path

import click
import pytest
from click.testing import CliRunner

from sears_paradox_cli.main import main

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"
PAGES = [ROOT / "README.md", *sorted(DOCS.glob("*.md"))]
FENCE = re.compile(r"^```(\w*)[^\n]*\n(.*?)^```", re.S | re.M)

#: python blocks another test runs and checks more closely than this one can
RUN_ELSEWHERE = {("docs/python.md", 0): "tests/test_docs_python.py runs it and checks the panel it draws"}

MAGIC = {".svg": b"<?xml", ".pdf": b"%PDF-", ".png": b"\x89PNG\r\n\x1a\n", ".gif": b"GIF8", ".html": b"<!DOCTYPE html>"}


def _name(page: Path) -> str:
    return str(page.relative_to(ROOT))


def blocks(page: Path, language: str) -> list[str]:
    return [body for lang, body in FENCE.findall(page.read_text()) if lang == language]


# --- the project's own facts -------------------------------------------------------------------------------------

def _readme_test_command() -> str:
    commands = [line for body in blocks(ROOT / "README.md", "sh") for line in body.splitlines() if "pytest" in line]
    assert len(commands) == 1, commands
    return commands[0]


def test_ci_runs_exactly_the_readmes_test_command():
    ci = (ROOT / ".ci" / "run").read_text().splitlines()
    assert ci[-1] == _readme_test_command()
    assert _readme_test_command() in blocks(DOCS / "contributing.md", "sh")[0].splitlines()
    assert "'.[test,docs]'" in _readme_test_command()  # CI builds the site too (test_the_site_builds...)


def test_readme_keeps_the_install_and_run_command_and_is_short():
    readme = (ROOT / "README.md").read_text()
    assert ("python3 -m venv .venv && .venv/bin/python -m pip install . && .venv/bin/sears-paradox plot fig2 --v 0.6"
            in blocks(ROOT / "README.md", "sh")[0].splitlines())
    assert len(readme.split()) <= 1500  # `wc -w README.md`: a page a new user reads in five minutes


def test_version_is_the_changelogs_latest():
    from rodparadox import __version__

    versions = re.findall(r"^## \[?(\d+\.\d+\.\d+)\]?", (ROOT / "CHANGELOG.md").read_text(), re.M)
    assert versions and versions[0] == __version__
    printed = CliRunner().invoke(main, ["--version"]).output.strip()
    assert printed == f"sears-paradox, version {versions[0]}"
    citation = (ROOT / "CITATION.cff").read_text()
    assert re.search(rf"^version: \"?{re.escape(__version__)}\"?$", citation, re.M)


def test_licence_is_the_one_pyproject_names():
    assert "license = { text = \"MIT\" }" in (ROOT / "pyproject.toml").read_text()
    assert (ROOT / "LICENSE").read_text().startswith("MIT License")


def test_every_relative_link_of_the_readme_and_the_pages_reaches_a_file():
    for page in PAGES:
        text = FENCE.sub("", page.read_text())
        for target in re.findall(r"\]\(([^)#\s]+)(?:#[^)]*)?\)", text):
            if "://" in target:
                continue
            assert (page.parent / target).exists(), f"{_name(page)} links to {target}, which does not exist"


def test_every_test_file_the_pages_the_code_and_the_tests_name_exists():
    """A path like tests/web/test_html.py named anywhere (the pages tell readers to run it; comments send the next
    reader to it) is a file of the repository: when the tests moved into folders by layer, eight such names in
    fifteen places were left pointing at files that no longer existed."""
    sources = [*PAGES, ROOT / "pyproject.toml", ROOT / "Makefile",
               *(p for folder in ("rodparadox", "cli", "tests") for p in (ROOT / folder).rglob("*.py"))]
    missing = {(str(source.relative_to(ROOT)), name) for source in sources
               for name in re.findall(r"\btests/[\w/]+\.py\b", source.read_text(encoding="utf-8"))
               if not (ROOT / name).is_file()}
    assert not missing, sorted(missing)


# --- commands written out: parsed by their own options -------------------------------------------------------------

def _written_commands(page: Path) -> list[str]:
    text = page.read_text()
    found = re.findall(r"`(sears-paradox [^`]+)`", FENCE.sub("", text))
    for lang, body in FENCE.findall(text):
        if lang == "sh":
            found += [line.split(" #")[0].strip() for line in body.splitlines() if line.startswith("sears-paradox ")]
    # a synopsis or a pattern (SCENARIO, NAME, [options], A|B) is not a command
    return [c for c in found if not re.search(r"[A-Z]{2,}|\[|\||\.\.\.|<", c.replace("--L", "").replace("-L", ""))]


@pytest.mark.parametrize("page", PAGES, ids=_name)
def test_commands_in_prose_and_sh_blocks_parse(page):
    for command in _written_commands(page):
        words = shlex.split(command)[1:]
        if words[0] in ("-h", "--help", "--version") or len(words) == 1:  # a command named, not given
            continue
        sub = main.get_command(None, words[0])
        assert sub is not None, f"{_name(page)}: no command {words[0]!r} ({command})"
        # under the group's own context, as the command line parses it (a context of its own would leave click
        # caching the command's help option without the group's -h, which test_cli then misses)
        parent = click.Context(main, info_name="sears-paradox", **main.context_settings)
        try:
            try:
                sub.make_context(words[0], words[1:], parent=parent)
            except click.MissingParameter as missing:  # prose naming a command's options, without a scenario
                if missing.param is None or missing.param.name != "scenario":
                    raise
                sub.make_context(words[0], [*words[1:], "fig2"], parent=parent)
        except click.ClickException as error:  # UsageError, BadParameter: the message says what is wrong
            raise AssertionError(f"{_name(page)}: `{command}` does not parse: {error.format_message()}") from None


# --- console and python blocks: run ----------------------------------------------------------------------------------

def _console_steps(body: str) -> list[tuple[str, str]]:
    steps = []
    for line in body.splitlines():
        if line.startswith("$ "):
            steps.append((line[2:], ""))
        else:
            assert steps, f"output before any command: {line!r}"
            steps[-1] = (steps[-1][0], steps[-1][1] + line + "\n")
    return steps


def _check_written(folder: Path, printed: str, where: str) -> None:
    for line in printed.splitlines():
        path = line.removesuffix(" (unchanged)")
        if " " in path or not ("/" in path or Path(path).suffix in (*MAGIC, ".json", ".csv")):
            continue
        target = folder / path
        assert target.exists(), f"{where}: printed {path}, which does not exist"
        if target.is_dir():
            assert any(target.iterdir()), f"{where}: {path} is empty"
            continue
        magic = MAGIC.get(target.suffix)
        if magic:
            assert target.read_bytes().startswith(magic), f"{where}: {path} is not a {target.suffix} file"
        elif target.suffix == ".json":
            json.loads(target.read_text())


def _run_console(body: str, folder: Path, where: str) -> None:
    for command, shown in _console_steps(body):
        words = shlex.split(command, comments=True)
        if words[0] == "sears-paradox":
            result = CliRunner().invoke(main, words[1:])
            assert result.exit_code == 0, f"{where}: `{command}` failed:\n{result.output}{result.exception!r}"
            printed = result.stdout
        else:
            done = subprocess.run(command, shell=True, cwd=folder, capture_output=True, text=True)
            assert done.returncode == 0, f"{where}: `{command}` failed: {done.stderr}"
            printed = done.stdout
        assert printed == shown, f"{where}: `{command}` printed\n{printed}\nnot what the page shows:\n{shown}"
        _check_written(folder, printed, where)


def _matches(expected: str, printed: str) -> bool:
    return re.fullmatch(".*".join(re.escape(part) for part in expected.split("...")), printed, re.S) is not None


def _run_python(code: str, folder: Path, where: str) -> None:
    import matplotlib

    matplotlib.use("Agg")  # no screen: pyplot draws off-screen
    expected = [m.group(1) for m in re.finditer(r"^\s*print\(.*\)\s*# -> (.*)$", code, re.M)]
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed):
        exec(compile(code, where, "exec"), {"__name__": "__docs__"})
    lines = printed.getvalue().splitlines()
    assert len(lines) == len(expected), f"{where}: printed {lines}, the page shows {expected}"
    for want, got in zip(expected, lines):
        assert _matches(want, got), f"{where}: printed {got!r}, the page shows {want!r}"
    for name in re.findall(r"[\"']([\w./-]+\.(?:png|pdf|svg|gif))[\"']", code):
        path = folder / name
        assert path.exists() and path.read_bytes().startswith(MAGIC[path.suffix]), f"{where}: {name} not written"


def documented_console_commands() -> set[str]:
    """Every command a `console` block of the README or the documentation runs (test_cli leaves these to this file)."""
    return {command.split(" #")[0].strip() for page in PAGES for body in blocks(page, "console")
            for command, _ in _console_steps(body)}


PAGES_WITH_EXAMPLES = [p for p in PAGES if blocks(p, "console") or blocks(p, "python")]


@pytest.mark.slow
@pytest.mark.parametrize("page", PAGES_WITH_EXAMPLES, ids=_name)
def test_every_example_runs_and_prints_what_the_page_shows(page, tmp_path, monkeypatch):
    import matplotlib.pyplot as plt
    import rodparadox.web.data as web_data

    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(web_data, "SPEED_STEPS", 2)  # html on a coarser grid: see the module's docstring
    monkeypatch.setattr(web_data, "LEDGER_INSTANTS", 3)
    name = _name(page)
    python_blocks = 0
    try:
        for lang, body in FENCE.findall(page.read_text()):
            where = f"{name}, {lang} block"
            if lang == "console":
                _run_console(body, tmp_path, where)
            elif lang == "python":
                if (name, python_blocks) not in RUN_ELSEWHERE:
                    _run_python(body, tmp_path, where + f" {python_blocks + 1}")
                python_blocks += 1
    finally:
        plt.close("all")


# --- the gallery -------------------------------------------------------------------------------------------------

def _gallery():
    spec = importlib.util.spec_from_file_location("docs_gallery", DOCS / "gallery.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_gallery_shows_every_scenario_in_every_style_from_the_current_configs():
    gallery = _gallery()
    assert (DOCS / "gallery.md").read_text() == gallery.page(), "docs/gallery.md is out of date: run `make gallery`"
    wanted = {gallery.picture_name(n, s) for n in gallery.scenarios() for s in gallery.STYLES}
    assert {p.name for p in (DOCS / "gallery").glob("*.png")} == wanted
    assert len(wanted) == 3 * len(list((ROOT / "configs").glob("*.yaml")))
    made_from = dict(line.split(" ", 1) for line in (DOCS / "gallery" / "made-from.txt").read_text().splitlines())
    for name in gallery.scenarios():  # each drawn from the scenario file as it is now
        config = hashlib.sha256((ROOT / "configs" / f"{name}.yaml").read_bytes()).hexdigest()
        assert f"config={config}" in made_from[name], f"{name}'s pictures are out of date: run `make gallery`"
    assert sum(p.stat().st_size for p in (DOCS / "gallery").glob("*.png")) < 3_000_000


@pytest.mark.parametrize("name, style", [("single", "default")])
def test_gallery_pictures_are_what_the_tool_draws_now(name, style):
    """One of the gallery's pictures drawn again (a second) and compared byte for byte, where the matplotlib is
    the one that drew them (another draws other pixels; test_plot_cli compares the README's SVGs by geometry)."""
    import matplotlib

    gallery = _gallery()
    made_with = dict(line.split(" ", 1) for line in (DOCS / "gallery" / "made-from.txt").read_text().splitlines())
    if f"matplotlib={matplotlib.__version__}" not in made_with[name]:
        pytest.skip(f"the gallery was drawn with another matplotlib than {matplotlib.__version__}")
    committed = (DOCS / "gallery" / gallery.picture_name(name, style)).read_bytes()
    assert gallery.draw(name, style) == committed, f"docs/gallery/{name}_{style}.png is out of date: run `make gallery`"


# --- the site and the notebook (the docs extra) -------------------------------------------------------------------

def _missing(*modules: str) -> list[str]:
    return [m for m in modules if importlib.util.find_spec(m) is None]


@pytest.mark.slow
def test_the_site_builds_with_warnings_as_errors_and_has_every_option(tmp_path):
    missing = _missing("sphinx", "furo", "myst_parser", "sphinx_click")
    if missing:
        pytest.skip(f"the docs extra is not installed ({', '.join(missing)} missing): pip install -e '.[docs]'")
    out = tmp_path / "html"
    done = subprocess.run([sys.executable, "-m", "sphinx", "-b", "html", "-j", "1", "-W", "--keep-going", "-q",
                           "-d", str(tmp_path / "doctrees"), str(DOCS), str(out)],
                          capture_output=True, text=True, timeout=300)
    # a process of its own: sphinx-click makes contexts of its own, which leave click's commands caching a help
    # option without the group's -h (as test_commands_in_prose_and_sh_blocks_parse would without its parent)
    assert done.returncode == 0, done.stderr
    reference = (out / "commands.html").read_text()
    for name, command in main.commands.items():  # the generated reference: every command, option and example
        assert f'id="sears-paradox-{name}"' in reference, name
        for param in command.params:
            for flag in [] if getattr(param, "hidden", False) else getattr(param, "opts", []):
                if flag.startswith("--"):
                    assert f'id="cmdoption-sears-paradox-{name}-{flag.lstrip("-")}"' in reference, f"{name} {flag}"
        example = re.search(r"Example: (sears-paradox .+)", command.help).group(1)
        assert example in reference.replace("&#8211;", "--"), example
    assert (out / "_images").is_dir() and (out / "python.html").read_text().count('class="sig-name') >= 20


@pytest.mark.slow
def test_the_notebook_runs(tmp_path):
    missing = _missing("nbclient", "nbformat", "ipykernel")
    if missing:
        pytest.skip(f"the docs extra is not installed ({', '.join(missing)} missing): pip install -e '.[docs]'")
    import nbformat
    from nbclient import NotebookClient

    notebook = nbformat.read(DOCS / "notebook.ipynb", as_version=4)
    assert all(not cell.get("outputs") for cell in notebook.cells if cell.cell_type == "code")  # kept clean
    NotebookClient(notebook, timeout=120, kernel_name="python3",
                   resources={"metadata": {"path": str(tmp_path)}}).execute()  # a failing cell raises
    outputs = [o for cell in notebook.cells if cell.cell_type == "code" for o in cell.outputs]
    pictures = [o for o in outputs if "image/png" in o.get("data", {})]
    assert len(pictures) == 2  # the diagram (it shows itself) and the panel beside the plot
    printed = "".join(o.get("text", "") for o in outputs if o.output_type == "stream")
    assert "B1: t = 0.8333 L in S, t' = 1.4167 L in S'" in printed and "A1: t = 1.5833 L in S, t' = 1.4167 L" in printed
    assert "v = 0.8: A1 comes 1.3333 L after B1 in S (g v L = 1.3333)" in printed
    assert (tmp_path / "fig2.svg").read_bytes().startswith(b"<?xml")
