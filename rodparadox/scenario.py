"""Scenarios: YAML -> the validated frozen dataclasses of `model`. The only module that knows YAML.

The schema is documented in the README ("Scenario files"); every error names
the file, the key path and the line.
"""

from __future__ import annotations

import difflib
import importlib.util
import re
from pathlib import Path
from typing import Any

import yaml

from .errors import ScenarioError
from .model import PARTICLE_NAMES, Particle, Scenario, Timing

#: the largest scenario file read
MAX_FILE_BYTES = 1_000_000

__all__ = ["Particle", "Scenario", "Timing", "builtin_names", "configs_folder", "describe", "load", "parse"]

# --- YAML --------------------------------------------------------------------------------

_SCHEMA = {
    "name": None,
    "description": None,
    "v": None,
    "L": None,
    "particles": {
        "A": {"mass": None, "speed": None, "gap": None, "timed_with": {"particle": None, "frame": None, "delay": None}},
        "B": {"mass": None, "speed": None, "gap": None, "timed_with": {"particle": None, "frame": None, "delay": None}},
    },
}


class _Loader(yaml.SafeLoader):
    """PyYAML's safe loader, also reading exponent floats without a dot (1e-6, 2E9) as numbers, as YAML 1.2 does."""


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
            self.data = None if node is None else self._value(loader, node, "", _SCHEMA)
        finally:
            loader.dispose()

    def _value(self, loader: _Loader, node: yaml.Node, path: str, schema: Any) -> Any:
        self.lines[path] = node.start_mark.line + 1
        if isinstance(node, yaml.MappingNode) and isinstance(schema, dict):
            loader.flatten_mapping(node)
            out: dict[str, Any] = {}
            for key_node, value_node in node.value:
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
        if isinstance(schema, dict):
            shown = "a list" if isinstance(node, yaml.SequenceNode) else repr(loader.construct_object(node, deep=True))
            raise ScenarioError(f"{path or 'the scenario'} must be a mapping of keys ({', '.join(schema)}), "
                                f"got {shown}.", path, node.start_mark.line + 1 if path else None)
        value = loader.construct_object(node, deep=True)
        return value


def parse(text: str, source: str, default_name: str) -> Scenario:
    """Read a scenario from YAML text; every error names `source`, the key path and its line."""
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
    for required in ("v", "particles"):
        if required not in data:
            raise ScenarioError(f"the scenario needs the key {required}.", required)
    particles_data = data["particles"]
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
    for key in ("name", "description"):
        if key in data and not isinstance(data[key], str):
            raise ScenarioError(f"{key} must be text, got {data[key]!r}.", key)
    return Scenario(name=data.get("name", default_name), description=data.get("description", ""),
                    v=data["v"], L=data.get("L", 1.0), particles=tuple(particles))


# --- built-in scenarios and files ----------------------------------------------------------

def configs_folder() -> Path:
    """Where the built-in scenarios are: the repository's configs/ (installed as rodparadox.configs)."""
    spec = importlib.util.find_spec("rodparadox.configs")
    if spec is not None and spec.submodule_search_locations:
        return Path(list(spec.submodule_search_locations)[0])
    return Path(__file__).resolve().parent.parent / "configs"


def builtin_names() -> list[str]:
    return sorted(p.stem for p in configs_folder().glob("*.yaml"))


def load(name_or_path: str) -> Scenario:
    """A built-in scenario by name (`fig2`) or a scenario file by path (`configs/my.yaml`)."""
    path = Path(name_or_path)
    looks_like_path = path.suffix in (".yaml", ".yml") or len(path.parts) > 1
    if not looks_like_path:
        builtin = configs_folder() / f"{name_or_path}.yaml"
        if builtin.is_file():
            return parse(builtin.read_text(encoding="utf-8"), name_or_path, name_or_path)
        if not path.is_file():
            raise ScenarioError(f"there is no built-in scenario {name_or_path!r} and no file of that name; "
                                f"built-in: {', '.join(builtin_names())} (see 'sears-paradox list').")
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
        raise ScenarioError(f"cannot read scenario file {name_or_path!r}: {e.strerror}.") from None
    return parse(text, name_or_path, path.stem)


def describe(name: str) -> str:
    """One line about a built-in scenario, for `sears-paradox list`."""
    try:
        description = load(name).description.strip()
    except ScenarioError as e:
        return f"(cannot be read: {e})"
    return description.splitlines()[0] if description else ""
