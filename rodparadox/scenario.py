"""Scenarios: YAML -> validated frozen dataclasses. The only module that knows YAML.

Lengths and times in a scenario are in units of the rod's proper length L,
masses in units of the rod's mass M, speeds in units of c. The schema is
documented in the README ("Scenario files").
"""

from __future__ import annotations

import difflib
import re
import importlib.util
import math
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import yaml

from .errors import ScenarioError

PARTICLE_NAMES = ("A", "B")
#: speeds the engine computes to about 1e-9 relative in double precision: slower, the impacts lie so far
#: in the future that t has no digits left for the rod's zig-zag; faster, g exceeds 2000
SLOWEST, FASTEST = 1e-6, 0.9999999
#: the largest gap or timing delay, in units of L
MAX_SPAN = 1e6
#: the largest scenario file read
MAX_FILE_BYTES = 1_000_000
FRAME_NAMES = ("rest", "moving")


def _check_number(value: Any, key: str, *, low: float | None = None, high: float | None = None,
                  low_open: bool = True, high_open: bool = True, allowed: str, hint: str = "") -> float:
    """Return `value` as a float, or raise a ScenarioError naming `key` and what is allowed."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ScenarioError(f"{key} must be {allowed}, got {_shown(value)}.", key)
    try:
        value = float(value)
    except OverflowError:
        raise ScenarioError(f"{key} must be {allowed}, got an integer of {len(str(value))} digits.", key) from None
    bad = not math.isfinite(value)
    if low is not None:
        bad = bad or (value <= low if low_open else value < low)
    if high is not None:
        bad = bad or (value >= high if high_open else value > high)
    if bad:
        raise ScenarioError(f"{key} must be {allowed}, got {value:g}{hint}.", key)
    return value


@dataclass(frozen=True)
class Timing:
    """Place a particle so that its first impact comes `delay` (units of L) after
    the other particle's first impact, in the time of frame `frame`."""

    particle: str
    frame: str | float = "moving"
    delay: float = 0.0
    key: str = field(default="timed_with", compare=False, repr=False)

    def __post_init__(self) -> None:
        if self.particle not in PARTICLE_NAMES:
            raise ScenarioError(f"{self.key}.particle must be A or B, got {self.particle!r}.", f"{self.key}.particle")
        if isinstance(self.frame, str):
            if self.frame not in FRAME_NAMES:
                raise ScenarioError(
                    f"{self.key}.frame must be rest, moving or a velocity u with -1 < u < 1, got {self.frame!r}.",
                    f"{self.key}.frame")
        else:
            _check_number(self.frame, f"{self.key}.frame", low=-1, high=1,
                          allowed="rest, moving or a velocity u with -1 < u < 1")
        _check_number(self.delay, f"{self.key}.delay", low=-MAX_SPAN, high=MAX_SPAN, low_open=False, high_open=False,
                      allowed=f"a number between {-MAX_SPAN:g} and {MAX_SPAN:g} (units of L)")


@dataclass(frozen=True)
class Particle:
    """A point particle: A starts left of the rod and moves right, B starts right and moves left."""

    name: str
    mass: float = 1.0
    speed: float | None = None
    gap: float | None = None
    timed_with: Timing | None = None

    def __post_init__(self) -> None:
        key = f"particles.{self.name}"
        _check_number(self.mass, f"{key}.mass", low=0, allowed="a positive number (units of the rod's mass M)")
        _check_number(self.mass, f"{key}.mass", low=1e-9, high=1e9, low_open=False, high_open=False,
                      allowed="between 1e-09 and 1e+09 (units of the rod's mass M)")
        if self.speed is not None:
            _check_number(self.speed, f"{key}.speed", low=0, high=1,
                          allowed="a number with 0 < speed < 1 (towards the rod, units of c)",
                          hint="; a particle that is at rest or moves away never reaches the rod" if _finite_at_most_zero(self.speed) else "")
            _check_computable(self.speed, f"{key}.speed")
        if (self.gap is None) == (self.timed_with is None):
            raise ScenarioError(f"{key} needs exactly one of gap (its distance from the rod at t = 0) "
                                f"or timed_with (its impact timed against the other particle's).", key)
        if self.gap is not None:
            _check_number(self.gap, f"{key}.gap", low=0, low_open=False,
                          allowed="a number >= 0 (distance from its end of the rod at t = 0, units of L)",
                          hint="; a negative gap puts the particle inside the rod")
            _check_number(self.gap, f"{key}.gap", high=MAX_SPAN, high_open=False,
                          allowed=f"at most {MAX_SPAN:g} (units of L), so that the rod stays visible beside it")
        if self.timed_with is not None and self.timed_with.particle == self.name:
            raise ScenarioError(f"{key}.timed_with.particle must name the other particle, not {self.name} itself.",
                                f"{key}.timed_with.particle")

    @property
    def end(self) -> str:
        """The end of the rod this particle strikes."""
        return "left" if self.name == "A" else "right"


@dataclass(frozen=True)
class Scenario:
    """A rod of proper length L at rest in S, centre at x = 0, and one or two particles.

    `v` is the speed of the paper's frame S' (the rod moves at +v there) and
    the particles' speed wherever a particle does not give its own.
    """

    name: str
    v: float
    particles: tuple[Particle, ...]
    L: float = 1.0
    description: str = ""

    def __post_init__(self) -> None:
        _check_number(self.v, "v", low=0, high=1, allowed="a number with 0 < v < 1 (units of c)")
        _check_computable(self.v, "v")
        _check_number(self.L, "L", low=0, allowed="a positive length (the rod's proper length)")
        _check_number(self.L, "L", low=1e-100, high=1e100, low_open=False, high_open=False,
                      allowed="between 1e-100 and 1e+100 (choose the unit of length to suit)")
        names = [p.name for p in self.particles]
        if not names:
            raise ScenarioError("particles must name at least one of A and B.", "particles")
        if len(set(names)) != len(names):
            raise ScenarioError("particles names a particle twice.", "particles")
        for p in self.particles:
            if p.timed_with is not None:
                other = self.particle(p.timed_with.particle)
                key = f"particles.{p.name}.timed_with.particle"
                if other is None:
                    raise ScenarioError(f"{key} is {p.timed_with.particle}, but the scenario has no particle "
                                        f"{p.timed_with.particle}.", key)
                if other.gap is None:
                    raise ScenarioError(f"{key}: {p.name} and {other.name} cannot both be timed against each "
                                        f"other; give {other.name} a gap.", key)

    def particle(self, name: str) -> Particle | None:
        return next((p for p in self.particles if p.name == name), None)

    def speed(self, particle: Particle) -> float:
        return self.v if particle.speed is None else particle.speed

    def frame_velocity(self, frame: str | float) -> float:
        """Velocity relative to S of a named frame: rest = S, moving = S' (velocity -v)."""
        if frame == "rest":
            return 0.0
        if frame == "moving":
            return -self.v
        return float(frame)

    def with_overrides(self, *, v: float | None = None, L: float | None = None) -> "Scenario":
        """The same scenario with command-line values; a bad value names its option."""
        changes = {k: val for k, val in (("v", v), ("L", L)) if val is not None}
        try:
            return replace(self, **changes)
        except ScenarioError as e:
            bad = e.key if e.key in changes else None
            raise e.located(f"option --{bad}", None) if bad else e


def _shown(value: Any) -> str:
    """A YAML value as the user wrote it, for an error message."""
    if isinstance(value, bool):
        return ("yes/true" if value else "no/false") + " (a boolean)"
    if value is None:
        return "nothing (an empty value)"
    if isinstance(value, str):
        return repr(value)
    if isinstance(value, (list, dict)):
        return "a list" if isinstance(value, list) else "a mapping"
    return f"{value} (a {type(value).__name__})"


def _check_computable(speed: float, key: str) -> None:
    if not SLOWEST <= speed <= FASTEST:
        raise ScenarioError(f"{key} must be between {SLOWEST:g} and {FASTEST!r} for double precision to place the "
                            f"impacts, got {speed!r}.", key)


def _finite_at_most_zero(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value) and value <= 0


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
