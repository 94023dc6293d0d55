"""The architecture, read from the source (README, "Layout"): every module's imports run one way between the layers,
no private name crosses a module, no module grows past MAX_LINES, and the library never words the command line.

Imports are read with `ast` from every file, so an import inside a function (the lazy imports that keep `--help`
light) counts as much as one at the top, and a module named in a string (`importlib.import_module`) counts too.
Each check is also run once on a planted violation, to show it can fail.
"""

from __future__ import annotations

import ast
import functools
from pathlib import Path

import pytest

#: one worker runs this file: every module is parsed once (0.7 CPU-s), not once on each worker
pytestmark = pytest.mark.xdist_group("layers")

ROOT = Path(__file__).resolve().parent.parent
#: the installed packages and the folders that hold them
PACKAGES = {"rodparadox": ROOT / "rodparadox", "sears_paradox_cli": ROOT / "cli"}
#: the base every layer may import: the errors, numbers as text, the named tolerances
BASE = {"errors", "numbers", "tolerances"}
#: each part of rodparadox (a subpackage, or a module beside them) and the other parts it may import
MAY_IMPORT = {
    "tolerances": set(),
    "errors": set(),
    "numbers": {"tolerances"},
    "physics": BASE,
    "io": BASE | {"physics"},
    "tables": BASE | {"physics"},
    "render": BASE | {"physics", "io", "tables"},
    "animate": BASE | {"physics", "io", "tables", "render"},
    "handout": BASE | {"physics", "io", "tables", "render"},
    "web": BASE | {"physics", "io", "tables", "render"},  # of render, only its styles (no matplotlib: tested)
}
#: a module longer than this is doing two jobs (README, "Layout")
MAX_LINES = 520
#: how the command line names an option; the library keeps facts and calls a choice by its parameter's name
CLI_WORDING = "option -"


def module_name(path: Path) -> str:
    """The dotted name a file is imported as (cli/words.py is sears_paradox_cli.words)."""
    for package, folder in PACKAGES.items():
        if path.is_relative_to(folder):
            parts = (package, *path.relative_to(folder).with_suffix("").parts)
            return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)
    raise ValueError(f"{path} is in no package")


def sources() -> dict[str, Path]:
    """Every module of the library and the command line, by its dotted name."""
    return {module_name(path): path for folder in PACKAGES.values() for path in sorted(folder.rglob("*.py"))}


MODULES = sources()


def is_ours(name: str) -> bool:
    return name.split(".")[0] in PACKAGES


def imports(source: str, modules=MODULES) -> list[tuple[str, str | None, int]]:
    """(module, name or None, line) for everything a module imports of ours: `import a.b` gives (a.b, None);
    `from a import b` gives (a.b, None) when a.b is a module, else (a, b); a string that is a module's whole dotted
    name (`importlib.import_module("rodparadox.render.diagram")`) gives that module."""
    found = []
    for node in nodes(source):
        if isinstance(node, ast.Import):
            found += [(alias.name, None, node.lineno) for alias in node.names if is_ours(alias.name)]
        elif isinstance(node, ast.ImportFrom) and node.module and is_ours(node.module):
            assert node.level == 0, f"line {node.lineno}: a relative import; name the module in full"
            for alias in node.names:
                whole = f"{node.module}.{alias.name}"
                found.append((whole, None, node.lineno) if whole in modules else (node.module, alias.name, node.lineno))
        elif isinstance(node, ast.Constant) and isinstance(node.value, str) and node.value in modules:
            found.append((node.value, None, node.lineno))
    return found


def part(module: str) -> str:
    """The layer a module of ours belongs to: `rodparadox.physics.frames` -> physics, `rodparadox.numbers` -> numbers,
    `sears_paradox_cli.words` -> cli, `rodparadox` (the package's own __init__) -> rodparadox."""
    names = module.split(".")
    if names[0] == "sears_paradox_cli":
        return "cli"
    return names[1] if len(names) > 1 else "rodparadox"


def layer_violations(module: str, source: str, modules=MODULES) -> list[str]:
    """What `module` (whose text is `source`) imports against the layers' direction."""
    me = part(module)
    if me == "cli":
        return []  # the command line may import every layer
    allowed = MAY_IMPORT.get(me, set()) | {me}
    if me not in MAY_IMPORT and me != "rodparadox":
        return [f"{module}: part {me!r} has no rule in MAY_IMPORT; say which layers it may import"]
    out = []
    for target, _, line in imports(source, modules):
        theirs = part(target)
        if theirs == "cli":
            out.append(f"{module}, line {line}: imports the command line ({target})")
        elif theirs not in allowed:
            out.append(f"{module}, line {line}: {me} imports {theirs} ({target}); {me} may import only "
                       f"{', '.join(sorted(allowed - {me})) or 'nothing of ours'}")
    return out


def private_imports(module: str, source: str, modules=MODULES) -> list[str]:
    """Every private name (a leading underscore, not a dunder) `module` takes from another module: imported by name,
    or read as an attribute of a module it imported."""
    out = []
    bound: dict[str, str] = {}  # local name -> our module it stands for
    for node in nodes(source):
        if isinstance(node, ast.Import):
            for alias in node.names:
                if is_ours(alias.name) and alias.asname:
                    bound[alias.asname] = alias.name
        elif isinstance(node, ast.ImportFrom) and node.module and is_ours(node.module):
            for alias in node.names:
                whole = f"{node.module}.{alias.name}"
                if whole in modules:
                    bound[alias.asname or alias.name] = whole
                elif _private(alias.name) and node.module != module:
                    out.append(f"{module}, line {node.lineno}: imports {alias.name} from {node.module}")
    for node in nodes(source):
        if (isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id in bound
                and _private(node.attr) and bound[node.value.id] != module):
            out.append(f"{module}, line {node.lineno}: reads {node.attr} of {bound[node.value.id]}")
    return out


@functools.lru_cache(maxsize=None)
def nodes(source: str) -> tuple[ast.AST, ...]:
    """Every node of a module's tree in `ast.walk`'s order, parsed and walked once for all the checks that read them
    (none changes them)."""
    return tuple(ast.walk(ast.parse(source)))


def _private(name: str) -> bool:
    return name.startswith("_") and not name.startswith("__")


def read(path: Path) -> str:
    return path.read_text(encoding="utf-8")


# --- the tree as it is ------------------------------------------------------------------------------------------

def test_every_module_is_found():
    assert {"rodparadox.physics.rigid.engine", "rodparadox.physics.causal.solve", "rodparadox.render.diagram", "rodparadox.animate.timeline",
            "rodparadox.handout.pdf", "rodparadox.tolerances", "sears_paradox_cli.main"} <= set(MODULES)
    assert all(part(m) in MAY_IMPORT or part(m) in ("cli", "rodparadox") for m in MODULES), \
        "a part of rodparadox with no rule in MAY_IMPORT"


def test_imports_run_one_way_between_the_layers():
    """physics imports only the base; io and tables physics; render physics, io and tables; animate and handout
    render and below; nothing in rodparadox imports the command line."""
    violations = [v for module, path in MODULES.items() for v in layer_violations(module, read(path))]
    assert not violations, "\n".join(violations)


def test_no_private_name_crosses_a_module():
    violations = [v for module, path in MODULES.items() for v in private_imports(module, read(path))]
    assert not violations, "\n".join(violations)


def test_no_module_is_doing_two_jobs():
    long = {module: n for module, path in MODULES.items() if (n := len(read(path).splitlines())) > MAX_LINES}
    assert not long, f"modules over {MAX_LINES} lines: {long}"


def test_the_library_never_names_an_option():
    """The library's errors keep facts; only `sears_paradox_cli.words` turns them into sentences naming options."""
    worded = [module for module, path in MODULES.items() if part(module) != "cli" and CLI_WORDING in read(path)]
    assert not worded, f"the library names options (\"{CLI_WORDING}...\") in {worded}"


def import_graph(sources: dict[str, str], modules=MODULES) -> dict[str, set[str]]:
    """Each module of ours -> the modules of ours it imports (anywhere in it: at the top, inside a function, or
    under TYPE_CHECKING), `from a import b` of a name counted as an import of a."""
    return {module: {target for target, _, _ in imports(source, modules) if target != module}
            for module, source in sources.items()}


def import_cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """Every strongly connected set of modules larger than one (Tarjan): each is an import cycle."""
    index, low, stack, on_stack, out = {}, {}, [], set(), []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                out.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


def test_no_import_cycle():
    """No module imports, directly or through others, a module that imports it (not even inside a function, the
    old way of dodging a cycle)."""
    graph = import_graph({module: read(path) for module, path in MODULES.items()})
    assert not import_cycles(graph), import_cycles(graph)


#: the rod models' own packages; nothing shared imports them but the one door, `physics.models`
MODEL_PACKAGES = ("rodparadox.physics.rigid", "rodparadox.physics.causal")
THE_DOOR = "rodparadox.physics.models"


def model_package_imports(sources: dict[str, str], modules=MODULES) -> list[str]:
    """Imports of a model's package from outside it: only the door may, and one model never imports another."""
    out = []
    for module, targets in import_graph(sources, modules).items():
        mine = next((p for p in MODEL_PACKAGES if module == p or module.startswith(p + ".")), None)
        for target in sorted(targets):
            theirs = next((p for p in MODEL_PACKAGES if target == p or target.startswith(p + ".")), None)
            if theirs is not None and theirs != mine and module != THE_DOOR:
                out.append(f"{module} imports {target}")
    return out


def test_only_the_door_opens_a_rod_model():
    """render, tables, io, animate, handout, web and cli read a run through the rod interface and run one through
    `physics.models`; the rigid and the causal rod never import each other."""
    library = {m: read(p) for m, p in MODULES.items() if not m.startswith("sears_paradox_cli.__")}
    assert model_package_imports(library) == []


def model_branches(module: str, source: str) -> list[str]:
    """Places that test a history's or a chart's model by name: `getattr(x, "kind"...)`, or a comparison of an
    attribute `kind` or `model` with "rigid" or "causal". A consumer asks for a capability instead."""
    out = []
    for node in nodes(source):
        if (isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "getattr"
                and len(node.args) >= 2 and isinstance(node.args[1], ast.Constant) and node.args[1].value == "kind"):
            out.append(f"{module}, line {node.lineno}: getattr(..., 'kind')")
        if isinstance(node, ast.Compare):
            sides = [node.left, *node.comparators]
            named = any(isinstance(x, ast.Attribute) and x.attr in ("kind", "model") for x in sides)
            words = any(isinstance(x, ast.Constant) and x.value in ("rigid", "causal") for x in sides)
            if named and words:
                out.append(f"{module}, line {node.lineno}: compares a model's name")
    return out


def test_no_consumer_branches_on_a_models_name():
    found = [b for module, path in MODULES.items() if not module.startswith("rodparadox.physics")
             for b in model_branches(module, read(path))]
    assert not found, "\n".join(found)


# --- each check fails on a planted violation -----------------------------------------------------------------

def test_a_planted_cycle_is_found_even_inside_a_function():
    sources = {"rodparadox.physics.a": "def f():\n    from rodparadox.physics.b import g\n",
               "rodparadox.physics.b": "from rodparadox.physics.c import h\n",
               "rodparadox.physics.c": "from rodparadox.physics.a import f\n",
               "rodparadox.physics.d": "from rodparadox.physics.a import f\n"}
    modules = set(sources)
    assert import_cycles(import_graph(sources, modules)) == [["rodparadox.physics.a", "rodparadox.physics.b",
                                                              "rodparadox.physics.c"]]


def test_a_planted_side_door_is_found():
    sources = {"rodparadox.render.strip": "from rodparadox.physics.causal.history import run\n",
               "rodparadox.physics.rigid.engine": "from rodparadox.physics.causal.solve import solve\n",
               "rodparadox.physics.models": "from rodparadox.physics.causal.history import run\n",
               "rodparadox.physics.causal.history": "", "rodparadox.physics.causal.solve": ""}
    assert sorted(model_package_imports(sources, set(sources))) == [
        "rodparadox.physics.rigid.engine imports rodparadox.physics.causal.solve",
        "rodparadox.render.strip imports rodparadox.physics.causal.history"]


@pytest.mark.parametrize("source", ['if getattr(history, "kind", "") == "causal":\n    pass\n',
                                    'x = 1 if chart.kind == "rigid" else 2\n',
                                    'ok = history.model != "causal"\n'])
def test_a_planted_model_branch_is_found(source):
    assert len(model_branches("rodparadox.render.strip", source)) == 1
    assert model_branches("rodparadox.render.strip", 'if impact.kind == "separation":\n    pass\n') == []

@pytest.mark.parametrize("module, source, expected", [
    ("rodparadox.physics.frames", "from rodparadox.render.diagram import draw\n", "physics imports render"),
    ("rodparadox.physics.frames", "def f():\n    from rodparadox import render\n", "physics imports render"),
    ("rodparadox.physics.frames", "import rodparadox.io.scenario\n", "physics imports io"),
    ("rodparadox.tables.build", "from rodparadox.io.export import rows\n", "tables imports io"),
    ("rodparadox.render.strip", "from rodparadox.animate.timeline import sweep\n", "render imports animate"),
    ("rodparadox.handout.pdf", "import importlib\nimportlib.import_module('rodparadox.animate.scenes')\n",
     "handout imports animate"),
    ("rodparadox.numbers", "from rodparadox.errors import FrameError\n", "numbers imports errors"),
    ("rodparadox.render.strip", "from sears_paradox_cli.words import option\n", "imports the command line"),
])
def test_a_planted_import_against_the_layers_is_found(module, source, expected):
    found = layer_violations(module, source)
    assert len(found) == 1 and expected in found[0]


def test_an_import_along_the_layers_is_allowed():
    source = ("from rodparadox.physics.frames import Frame\nfrom rodparadox import render\n"
              "from rodparadox.tolerances import ONE_INSTANT\nimport numpy as np\n")
    assert layer_violations("rodparadox.animate.now_scene", source) == []
    assert layer_violations("sears_paradox_cli.plot", "from rodparadox.handout.pdf import to_pdf\n") == []


@pytest.mark.parametrize("source, expected", [
    ("from rodparadox.render.diagram import _METADATA\n", "imports _METADATA from rodparadox.render.diagram"),
    ("from rodparadox.render import diagram\nx = diagram._METADATA\n", "reads _METADATA of rodparadox.render.diagram"),
    ("import rodparadox.io.ledger_report as report\nreport._measured(1)\n",
     "reads _measured of rodparadox.io.ledger_report"),
])
def test_a_planted_private_import_is_found(source, expected):
    found = private_imports("rodparadox.tables.build", source)
    assert len(found) == 1 and expected in found[0]
    assert private_imports("rodparadox.tables.build", "from rodparadox.render import __all__\n") == []
