"""Scenarios: YAML -> the validated frozen dataclasses of `model`. The only module that knows YAML.

The schema is documented in docs/scenarios.md; every error names
the file, the key path and the line.
"""

from __future__ import annotations

import difflib
import importlib.util
import re
from functools import lru_cache
from pathlib import Path
from typing import Any

import yaml

from rodparadox.errors import ScenarioError
from rodparadox.physics.forces import ENDS, Forces, profile_from
from rodparadox.physics.model import described, Particle, PARTICLE_NAMES, Scenario, Timing

#: the largest scenario file read: a scenario is a few hundred bytes, and PyYAML reads about 100 kB a second
MAX_FILE_BYTES = 100_000
#: the deepest nesting of lists and mappings read; a scenario needs 4 (particles.A.timed_with.frame,
#: forces.left.points[i][j])
MAX_DEPTH = 16
#: the most YAML nodes (keys and values) a document may stand for once every alias and merge key (<<) is
#: expanded: the whole schema is about 40, so this leaves room for anchors and stays milliseconds of work
MAX_EXPANDED_NODES = 1_000
#: file name extensions read as YAML, whatever their case
YAML_SUFFIXES = (".yaml", ".yml")

__all__ = ["Particle", "Scenario", "Timing", "builtin_names", "configs_folder", "describe", "load", "parse",
           "stem_of"]

# --- YAML --------------------------------------------------------------------------------

class _ListOf:
    """A list in the schema (the points of a force profile): each item read by `item`'s schema."""

    def __init__(self, item: Any):
        self.item = item


#: a force profile (physics/forces.py): its points are a list of [t, F] pairs
_PROFILE = {"shape": None, "peak": None, "start": None, "duration": None, "points": _ListOf(_ListOf(None)),
            "frame": None}

_SCHEMA = {
    "name": None,
    "description": None,
    "title": None,
    "v": None,
    "L": None,
    "rod": None,
    "sound_speed": None,
    "particles": {
        "A": {"mass": None, "speed": None, "gap": None, "timed_with": {"particle": None, "frame": None, "delay": None}},
        "B": {"mass": None, "speed": None, "gap": None, "timed_with": {"particle": None, "frame": None, "delay": None}},
    },
    "forces": {"left": _PROFILE, "right": _PROFILE},
}


class _Loader(yaml.SafeLoader):
    """PyYAML's safe loader, also reading exponent floats without a dot (1e-6, 2E9) as numbers, as YAML 1.2 does.

    It refuses nesting deeper than MAX_DEPTH while composing (PyYAML's composer recurses once per level,
    so a file of 500 `[` would otherwise end in a RecursionError), and stops composing after
    MAX_EXPANDED_NODES nodes, so a long file is refused after a few milliseconds, not read to its end.
    """

    _depth = 0
    _composed = 0

    def compose_node(self, parent, index):
        line = self.peek_event().start_mark.line + 1
        if self._depth >= MAX_DEPTH:
            raise ScenarioError(f"the lists and mappings are nested more than {MAX_DEPTH} deep; "
                                f"a scenario needs 4.", line=line)
        self._composed += 1
        if self._composed > MAX_EXPANDED_NODES:
            raise _too_many(line)
        self._depth += 1
        try:
            return super().compose_node(parent, index)
        finally:
            self._depth -= 1


_Loader.yaml_implicit_resolvers = {k: list(v) for k, v in yaml.SafeLoader.yaml_implicit_resolvers.items()}
_Loader.add_implicit_resolver(
    "tag:yaml.org,2002:float",
    re.compile(r"^[-+]?(?:[0-9][0-9_]*(?:\.[0-9_]*)?|\.[0-9_]+)[eE][-+]?[0-9]+$"),
    list("-+0123456789."))


class _Document:
    """A YAML document read into plain values, with the line of every key path."""

    def __init__(self, text: str):
        self.lines: dict[str, int] = {}
        loader = _Loader(text)
        try:
            node = loader.get_single_node()
            if node is not None:
                _check_expanded_size(node)
            self.data = None if node is None else self._value(loader, node, "", _SCHEMA)
        finally:
            loader.dispose()

    def _value(self, loader: _Loader, node: yaml.Node, path: str, schema: Any) -> Any:
        self.lines[path] = node.start_mark.line + 1
        if isinstance(node, yaml.MappingNode) and isinstance(schema, dict):
            loader.flatten_mapping(node)
            out: dict[str, Any] = {}
            for key_node, value_node in node.value:
                if not isinstance(key_node, yaml.ScalarNode):
                    raise ScenarioError(f"a key in {path or 'the top level'} is {_shape(key_node)}; "
                                        f"keys are words.", path or None, key_node.start_mark.line + 1)
                key = loader.construct_object(key_node, deep=True)
                where = f"{path}.{key}" if path else str(key)
                line = key_node.start_mark.line + 1
                if not isinstance(key, str):
                    raise ScenarioError(f"key {key!r} in {path or 'the top level'} must be a word.", where, line)
                if key in out:
                    raise ScenarioError(f"{where} is given twice (first on line {self.lines[where]}); "
                                        f"keep one.", where, line)
                if key not in schema:
                    allowed = ", ".join(schema)
                    close = difflib.get_close_matches(key, list(schema), n=1)
                    hint = f"; did you mean {close[0]}?" if close else "."
                    raise ScenarioError(f"unknown key {key!r} in {path or 'the top level'} "
                                        f"(allowed: {allowed}){hint}", where, line)
                self.lines[where] = line
                out[key] = self._value(loader, value_node, where, schema[key])
            return out
        if isinstance(schema, _ListOf) and isinstance(node, yaml.SequenceNode):
            return [self._value(loader, item, f"{path}[{i}]", schema.item) for i, item in enumerate(node.value)]
        if isinstance(schema, dict):
            got = _shape(node) if not isinstance(node, yaml.ScalarNode) else repr(loader.construct_object(node))
            raise ScenarioError(f"{path or 'the scenario'} must be a mapping of keys ({', '.join(schema)}), "
                                f"got {got}.", path, node.start_mark.line + 1 if path else None)
        if not isinstance(node, yaml.ScalarNode):
            # every leaf of the schema is one number or word: a list or mapping is refused unbuilt, as an empty
            # one, so that the key's own check (model.py) words the sentence
            return [] if isinstance(node, yaml.SequenceNode) else {}
        value = loader.construct_object(node)
        _check_decimal(node, value, path)
        return value


#: a number as YAML 1.2 and the command line write it: decimal digits, an optional point and exponent
_DECIMAL = re.compile(r"[-+]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][-+]?[0-9]+)?")
#: YAML's words for infinity and not-a-number, which the scenario's own checks refuse as not finite
_SPECIAL = re.compile(r"[-+]?\.(?:inf|Inf|INF)|\.(?:nan|NaN|NAN)")
#: YAML 1.1's other ways to write a number, which PyYAML reads silently: `1:30` is 90, `010` is 8, `0x10` is 16
_NOT_DECIMAL = ((re.compile(r"[-+]?[0-9][0-9_]*(?::[0-5]?[0-9])+(?:\.[0-9_]*)?"), "in base 60 as"),
                (re.compile(r"[-+]?0x[0-9a-fA-F_]+"), "in hexadecimal as"),
                (re.compile(r"[-+]?0b[01_]+"), "in binary as"),
                (re.compile(r"[-+]?0[0-7_]+"), "in octal as"))


def _check_decimal(node: yaml.ScalarNode, value: Any, path: str) -> None:
    """Refuse a number that YAML 1.1 reads as another than its decimal digits say (base 60 `1:30`, octal `010`,
    hexadecimal, binary, underscores): the rule of the command line's numbers too (`numbers.decimal`)."""
    if node.style is not None or isinstance(value, bool) or not isinstance(value, (int, float)):
        return
    text = node.value
    if (_DECIMAL.fullmatch(text) and float(text) == value) or _SPECIAL.fullmatch(text):
        return
    how = next((how for pattern, how in _NOT_DECIMAL if pattern.fullmatch(text)), "as")
    if how == "as" and "_" in text:
        how = "skipping the underscores, as"
    raise ScenarioError(f"{path or 'the value'} is {text}, which YAML 1.1 reads {how} {value!r}; write the number "
                        f"in plain decimal digits.", path or None, node.start_mark.line + 1)


def _shape(node: yaml.Node) -> str:
    return "a list" if isinstance(node, yaml.SequenceNode) else "a mapping" if isinstance(node, yaml.MappingNode) \
        else "a value"


def _too_many(line: int) -> ScenarioError:
    return ScenarioError(f"the file stands for more than {MAX_EXPANDED_NODES:,} keys and values once its aliases "
                         f"(*name) and merge keys (<<) are expanded; a scenario needs a few dozen.", line=line)


def _check_expanded_size(root: yaml.Node) -> None:
    """Refuse a document that stands for more than MAX_EXPANDED_NODES nodes, or nests deeper than MAX_DEPTH,
    once its aliases and merge keys are expanded (a "billion laughs" in any value, list or mapping).

    The composed graph is as large as the file; each node's expanded size and depth are counted once
    (memoised) and capped, without recursion, so the check costs time in proportion to the file's size.
    """
    size: dict[int, int] = {}
    depth: dict[int, int] = {}
    stack: list[tuple[yaml.Node, bool]] = [(root, False)]
    on_path: set[int] = set()
    while stack:
        node, children_done = stack.pop()
        if id(node) in size:
            continue
        children = ([n for pair in node.value for n in pair] if isinstance(node, yaml.MappingNode)
                    else list(node.value) if isinstance(node, yaml.SequenceNode) else [])
        if not children_done:
            on_path.add(id(node))
            stack.append((node, True))
            for child in children:
                if id(child) in on_path:
                    raise ScenarioError("an alias refers to a list or mapping that contains it; "
                                        "write the values out instead.", line=child.start_mark.line + 1)
                if id(child) not in size:
                    stack.append((child, False))
            continue
        on_path.discard(id(node))
        size[id(node)] = min(1 + sum(size[id(c)] for c in children), MAX_EXPANDED_NODES + 1)
        depth[id(node)] = 1 + max((depth[id(c)] for c in children), default=0)
        if size[id(node)] > MAX_EXPANDED_NODES:
            raise _too_many(node.start_mark.line + 1)
        if depth[id(node)] > MAX_DEPTH:
            raise ScenarioError(f"the lists and mappings are nested more than {MAX_DEPTH} deep once the "
                                f"aliases (*name) are expanded; a scenario needs 4.", line=node.start_mark.line + 1)


def parse(text: str, source: str, default_name: str) -> Scenario:
    """Read a scenario from YAML text; every error names `source`, the key path and its line.

    The same text, source and name give the same (frozen) Scenario, read once per process: PyYAML's pure-Python
    composer takes 1.2-1.6 ms for a built-in scenario, and a notebook's long-lived process (and the tests: about
    600 commands and thousands of loads in one process) reads the same built-in scenarios again and again. A text
    that is refused is read again each time (an error is not kept)."""
    return _parsed(text, source, default_name)


@lru_cache(maxsize=256)  # a few hundred scenarios' texts, each a few hundred bytes; bounded for a long-lived process
def _parsed(text: str, source: str, default_name: str) -> Scenario:
    try:
        document = _Document(text)
    except ScenarioError as e:
        raise e.located(source, e.line)
    except yaml.MarkedYAMLError as e:
        mark = e.problem_mark or e.context_mark
        line = mark.line + 1 if mark else None
        raise ScenarioError(f"YAML syntax error: {e.problem or e.context}.", line=line, source=source)
    except yaml.YAMLError as e:
        raise ScenarioError(f"not valid YAML ({e}).", source=source)
    data = document.data
    if data is None:
        raise ScenarioError("the file is empty; a scenario needs at least v and particles.", source=source)
    try:
        return _scenario(data, default_name)
    except ScenarioError as e:
        key = e.key
        while key and key not in document.lines:
            key = key.rpartition(".")[0]
        raise e.located(source, document.lines.get(key) if key else None)


def _scenario(data: dict[str, Any], default_name: str) -> Scenario:
    if "v" not in data:
        raise ScenarioError("the scenario needs the key v.", "v")
    if "particles" in data and "forces" in data:
        raise ScenarioError("the scenario gives both particles and forces; give one of them (a rod struck by "
                            "particles, or a rod driven by forces at its ends).", "forces")
    if "particles" not in data and "forces" not in data:
        raise ScenarioError("the scenario needs the key particles (a rod struck by particles) or forces (a rod "
                            "driven by forces at its ends).", "particles")
    forces = _forces(data["forces"]) if "forces" in data else None
    particles_data = data.get("particles", {})
    particles = []
    for name in PARTICLE_NAMES:
        if name not in particles_data:
            continue
        fields = dict(particles_data[name] or {})
        if "timed_with" in fields:
            timing = dict(fields["timed_with"] or {})
            key = f"particles.{name}.timed_with"
            if "particle" not in timing:
                raise ScenarioError(f"{key} needs the key particle (the other particle, A or B).", key)
            fields["timed_with"] = Timing(**timing, key=key)
        particles.append(Particle(name=name, **fields))
    for key in ("name", "description", "title"):
        if key in data and not isinstance(data[key], str):
            value = data[key]
            raise ScenarioError(f"{key} must be text, got {described(value) if isinstance(value, (list, dict)) else repr(value)}.", key)
    if "sound_speed" in data:
        _check_sound_speed(data["sound_speed"])
    return Scenario(name=data.get("name", default_name), description=data.get("description", ""),
                    v=data["v"], L=data.get("L", 1.0), particles=tuple(particles), title=data.get("title", ""),
                    rod=data.get("rod", "rigid"), sound_speed=data.get("sound_speed"), forces=forces)


def _forces(data: dict[str, Any]) -> Forces:
    """The forces at the ends: a profile for left, right or both (physics/forces.py checks each)."""
    profiles = {end: profile_from(data[end], f"forces.{end}") for end in ENDS if end in data}
    return Forces(**profiles)


def check_sound_speed_rod(scenario: Scenario) -> None:
    """sound_speed: 1 is the causal rod's: a run of the rigid rod (the file's rod, or the one the command line
    chose) with it is refused in one sentence (a rigid rod carries a push across at once: no sound speed)."""
    if scenario.sound_speed is not None and scenario.rod != "causal":
        raise ScenarioError("sound_speed: 1 is the causal rod's: give rod: causal with it, or --rod causal (the "
                            "rigid rod, the default, moves as a whole at once, as if its sound were infinitely "
                            "fast).", "sound_speed")


def _check_sound_speed(value: Any) -> None:
    """sound_speed: 1 (c) is the causal rod; slower sound steepens compressions into shocks, which heat the rod,
    and faster is faster than light: both refused in one sentence."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or value != 1:
        raise ScenarioError(f"sound_speed must be 1 (c, the causal rod: rod: causal), got {described(value)}; a "
                            f"slower sound steepens compressions into shocks, which heat the rod and are not "
                            f"modelled, and a faster one outruns light.", "sound_speed")


# --- built-in scenarios and files ----------------------------------------------------------

@lru_cache(maxsize=1)
def configs_folder() -> Path:
    """Where the built-in scenarios are: the repository's configs/ (installed as rodparadox.configs); looked up once
    per process (`importlib.util.find_spec` takes 0.07 ms, and every load of a built-in and `list` ask)."""
    spec = importlib.util.find_spec("rodparadox.configs")
    if spec is not None and spec.submodule_search_locations:
        return Path(list(spec.submodule_search_locations)[0])
    return Path(__file__).resolve().parents[2] / "configs"  # a checkout: rodparadox/io/ -> configs/


def builtin_names() -> list[str]:
    return sorted(p.stem for p in configs_folder().glob("*.yaml"))


def stem_of(name_or_path: str) -> str:
    """The name of a scenario the user gave, for file names: `fig2` for `fig2`, `my` for `dir/my.YAML`.

    A YAML extension (.yaml, .yml, in any case) is dropped; any other part of the file name is kept.
    """
    name = Path(name_or_path).name
    return name[:-len(Path(name).suffix)] if Path(name).suffix.lower() in YAML_SUFFIXES else name


def _is_path(name_or_path: str) -> bool:
    """Whether SCENARIO names a file: it has a YAML extension or a folder part, or a file of that name exists.

    A file in the current folder wins over a built-in scenario of the same name (docs/commands.md, "Commands"); a folder
    does not (`outputs/fig2/` beside the figures is common).
    """
    path = Path(name_or_path)
    return path.suffix.lower() in YAML_SUFFIXES or len(path.parts) != 1 or (path.exists() and not path.is_dir())


def load(name_or_path: str) -> Scenario:
    """A scenario file by path (`configs/my.yaml`, or `fig2` if such a file exists) or a built-in by name (`fig2`)."""
    if not name_or_path:
        raise ScenarioError("SCENARIO is empty; give a built-in name (see 'sears-paradox list') or a YAML file.")
    path = Path(name_or_path)
    if not _is_path(name_or_path):
        builtin = configs_folder() / f"{name_or_path}.yaml"
        if not builtin.is_file():
            raise ScenarioError(f"there is no built-in scenario {name_or_path!r} and no file of that name; "
                                f"built-in: {', '.join(builtin_names())} (see 'sears-paradox list').")
        return parse(builtin.read_text(encoding="utf-8"), name_or_path, name_or_path)
    if path.is_dir():
        raise ScenarioError(f"scenario file {name_or_path!r} is a folder; give a .yaml file.")
    if path.exists() and not path.is_file():
        raise ScenarioError(f"scenario file {name_or_path!r} is not a regular file; give a .yaml file.")
    try:
        if path.stat().st_size > MAX_FILE_BYTES:
            raise ScenarioError(f"scenario file {name_or_path!r} is larger than {MAX_FILE_BYTES:,} bytes; "
                                f"a scenario is a few lines of YAML.")
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise ScenarioError(f"scenario file {name_or_path!r} does not exist; check the path, "
                            f"or give a built-in name ({', '.join(builtin_names())}).") from None
    except UnicodeDecodeError:
        raise ScenarioError(f"scenario file {name_or_path!r} is not UTF-8 text.") from None
    except OSError as e:
        raise ScenarioError(f"cannot read scenario file {name_or_path!r}: {(e.strerror or str(e)).lower()}.") from None
    return parse(text, name_or_path, stem_of(name_or_path))


def describe(name: str) -> str:
    """One line about a built-in scenario, for `sears-paradox list`."""
    try:
        description = load(name).description.strip()
    except ScenarioError as e:
        return f"(cannot be read: {e})"
    return description.splitlines()[0] if description else ""
