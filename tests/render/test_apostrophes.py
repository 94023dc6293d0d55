"""Issue 24: what a reader sees sets every apostrophe typographic (rod’s), as print does. Read from the source: the
strings of the figures, animations and the page (`rodparadox/render`, `animate`, `web`, docstrings left out) and
the page's scripts (comments left out) hold no apostrophe set straight between letters (the colour bar's "rod's
material points", the rod's own view's keys). The handout's text is set typographic by its pages (`pdf_text`), the
shared tables' ASCII text by the page (`web.data.typographic`); the drawn worksheets are read by
`test_worksheet_tells_nothing`."""

from __future__ import annotations

import ast
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2] / "rodparadox"
#: what a reader sees is drawn or written by these parts (and the comparison's note under a figure of both rods)
READ = ("render", "animate", "web")
ALSO = ("tables/comparison.py",)
STRAIGHT = re.compile(r"[A-Za-z]'[A-Za-z]")


def straight_in_python(source: str) -> list[str]:
    """The string constants of a module, its docstrings left out, that set an apostrophe straight."""
    tree = ast.parse(source)
    docstrings = {id(node.body[0].value) for node in ast.walk(tree)
                  if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef))
                  and node.body and isinstance(node.body[0], ast.Expr) and isinstance(node.body[0].value, ast.Constant)}
    return [node.value for node in ast.walk(tree) if isinstance(node, ast.Constant) and isinstance(node.value, str)
            and id(node) not in docstrings and STRAIGHT.search(node.value)]


def straight_in_script(source: str) -> list[str]:
    """The lines of a script, its comments left out, that set an apostrophe straight."""
    source = re.sub(r"/\*.*?\*/", "", source, flags=re.S)
    return [line.rstrip() for line in (re.sub(r"(^|\s)//.*$", "", line) for line in source.splitlines())
            if STRAIGHT.search(line)]


def test_no_string_a_reader_sees_sets_an_apostrophe_straight():
    found = []
    for part in READ:
        for path in sorted((ROOT / part).rglob("*.py")):
            found += [(path.name, text[:80]) for text in straight_in_python(path.read_text(encoding="utf-8"))]
        for path in sorted((ROOT / part).rglob("*.js")):
            found += [(path.name, line.strip()[:80]) for line in straight_in_script(path.read_text(encoding="utf-8"))]
    for name in ALSO:
        found += [(name, text[:80]) for text in straight_in_python((ROOT / name).read_text(encoding="utf-8"))]
    assert not found, found


def test_a_straight_apostrophe_is_found_in_a_string_and_a_script_not_in_a_docstring_or_comment():
    module = '"""The rod\'s docs."""\n# the rod\'s comment\nLABEL = "velocity of the rod\'s material points"\n'
    assert straight_in_python(module) == ["velocity of the rod's material points"]
    assert straight_in_python(module.replace("rod's material", "rod\N{RIGHT SINGLE QUOTATION MARK}s material")) == []
    script = '// the page\'s script\nf(ctx, "the rod\'s material points");  // the dot\'s edge\n/* a block\'s */'
    assert straight_in_script(script) == ['f(ctx, "the rod\'s material points");']


def test_the_page_sets_the_shared_tables_and_the_scenarios_apostrophes_typographic():
    from rodparadox.web.data import typographic

    assert typographic("The paper's Fig. 1; the rod's mass, 'quoted'") == (
        "The paper\N{RIGHT SINGLE QUOTATION MARK}s Fig. 1; the rod\N{RIGHT SINGLE QUOTATION MARK}s mass, 'quoted'")
