"""The scenario as frozen, validated data: a rod, one or two particles, the speed v. Pure, no YAML.

Lengths and times are in units of the rod's proper length L, masses in units
of the rod's mass M, speeds in units of c. `scenario` reads these from YAML;
`engine` runs them.
"""

from __future__ import annotations

import math
import unicodedata
from dataclasses import dataclass, field, replace
from typing import Any

from rodparadox.errors import ScenarioError

PARTICLE_NAMES = ("A", "B")
#: speeds the engine computes to about 1e-9 relative in double precision: slower, the impacts lie so far
#: in the future that t has no digits left for the rod's zig-zag; faster, g exceeds 2000. FASTEST also bounds
#: every frame velocity a user gives (a timing frame here, a frame to see: `frames.FASTEST_FRAME`)
SLOWEST, FASTEST = 1e-6, 0.9999999
#: the largest gap or timing delay, in units of L
MAX_SPAN = 1e6
#: the frames named by a word: S, where the rod is at rest before any impact, and the paper's S'
FRAME_NAMES = ("rest", "moving")
#: the longest scenario name: it starts every figure title and file name
MAX_NAME_LENGTH = 200
#: the rod models: the paper's rigid rod, and the causal rod whose sound speed is c (docs/model.md, "The causal rod")
ROD_MODELS = ("rigid", "causal")


def frame_velocity(frame: str | float, v: float) -> float:
    """Velocity relative to S of a frame: `rest` is S (0); `moving` is the paper's S', of velocity -v, in which
    the rod first moves at +v (the one place this convention is written); a number is the velocity itself."""
    if frame == "rest":
        return 0.0
    if frame == "moving":
        return -v
    return float(frame)


def _check_number(value: Any, key: str, *, low: float | None = None, high: float | None = None,
                  low_open: bool = True, high_open: bool = True, allowed: str, hint: str = "") -> float:
    """Return `value` as a float, or raise a ScenarioError naming `key` and what is allowed."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ScenarioError(f"{key} must be {allowed}, got {described(value)}.", key)
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


#: `_check_number` for the other scenario modules (`forces`): a float, or one sentence naming the key
check_number = _check_number


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
            raise ScenarioError(f"{self.key}.particle must be A or B, got {described(self.particle)}.", f"{self.key}.particle")
        key, allowed = f"{self.key}.frame", f"rest, moving or a velocity u with {-FASTEST!r} <= u <= {FASTEST!r}"
        if isinstance(self.frame, str):
            if self.frame not in FRAME_NAMES:
                raise ScenarioError(f"{key} must be {allowed}, got {self.frame!r}.", key)
        elif abs(_check_number(self.frame, key, allowed=allowed)) > FASTEST:
            raise ScenarioError(f"{key} must be {allowed}, got {self.frame!r}.", key)
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
    """A rod of proper length L at rest in S, centre at x = 0, and one or two particles, or forces at its ends.

    `v` is the speed of the paper's frame S' (the rod moves at +v there) and
    the particles' speed wherever a particle does not give its own. A scenario has `particles` or `forces`
    (`physics.forces.Forces`), never both.
    """

    name: str
    v: float
    particles: tuple[Particle, ...]
    L: float = 1.0
    description: str = ""
    #: a heading for documents (a handout's section), in words: "Impacts simultaneous in the moving frame"
    title: str = ""
    #: which rod: "rigid" (the paper's) or "causal" (sound at c)
    rod: str = "rigid"
    #: the file's sound_speed (1, the causal rod's), or None: the rod being run must then be the causal one
    #: (`--rod causal` may choose it after the file is read, so it is checked where the rod is chosen)
    sound_speed: float | None = field(default=None, compare=False, repr=False)
    #: the forces at the ends (a `physics.forces.Forces`, which imports this module's checks), or None (a rod struck
    #: by particles): a scenario has one or the other
    forces: Any = None

    def __post_init__(self) -> None:
        _check_text(self.name, "name", newlines=False)
        _check_text(self.title, "title", newlines=False)
        _check_text(self.description, "description", newlines=True)
        if len(self.name) > MAX_NAME_LENGTH:
            raise ScenarioError(f"name must be at most {MAX_NAME_LENGTH} characters, got {len(self.name)}; "
                                f"say more in description.", "name")
        _check_number(self.v, "v", low=0, high=1, allowed="a number with 0 < v < 1 (units of c)")
        _check_computable(self.v, "v")
        _check_number(self.L, "L", low=0, allowed="a positive length (the rod's proper length)")
        _check_number(self.L, "L", low=1e-100, high=1e100, low_open=False, high_open=False,
                      allowed="between 1e-100 and 1e+100 (choose the unit of length to suit)")
        if self.rod not in ROD_MODELS:
            raise ScenarioError(f"rod must be rigid or causal, got {described(self.rod)}.", "rod")
        names = [p.name for p in self.particles]
        if names and self.forces is not None:
            raise ScenarioError("the scenario gives both particles and forces; give one of them (a rod struck by "
                                "particles, or a rod driven by forces at its ends).", "forces")
        if not names and self.forces is None:
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

    @property
    def drive(self) -> str:
        """What moves the rod: "particles" or "forces"."""
        return "particles" if self.forces is None else "forces"

    def particle(self, name: str) -> Particle | None:
        return next((p for p in self.particles if p.name == name), None)

    def speed(self, particle: Particle) -> float:
        return self.v if particle.speed is None else particle.speed

    def frame_velocity(self, frame: str | float) -> float:
        """Velocity relative to S of a frame of this scenario: rest, moving (S', -v) or a velocity (`frame_velocity`)."""
        return frame_velocity(frame, self.v)

    def with_overrides(self, *, v: float | None = None, L: float | None = None, rod: str | None = None) -> "Scenario":
        """The same scenario with other values of v, L and rod (None keeps the scenario's); a bad value's error has
        its key, v, L or rod, so that a caller can say where the value came from."""
        return replace(self, **{k: val for k, val in (("v", v), ("L", L), ("rod", rod)) if val is not None})


def described(value: Any) -> str:
    """A YAML value as the user wrote it, for an error message."""
    if isinstance(value, bool):
        return ("yes/true" if value else "no/false") + " (a boolean)"
    if value is None:
        return "nothing (an empty value)"
    if isinstance(value, str):
        return repr(value)
    if isinstance(value, (list, dict)):
        return "a list" if isinstance(value, list) else "a mapping"
    kind = {"int": "a whole number", "float": "a number"}.get(type(value).__name__, f"a {type(value).__name__}")
    return f"{value} ({kind})"


def _check_text(value: Any, key: str, *, newlines: bool) -> None:
    """Text that is drawn and printed: no control characters (tab, NUL, escape, ...), nor newlines in a name."""
    if not isinstance(value, str):
        raise ScenarioError(f"{key} must be text, got {described(value)}.", key)
    bad = next((c for c in value if unicodedata.category(c) == "Cc" and not (newlines and c == "\n")), None)
    if bad is not None:
        what = {"\t": "a tab", "\n": "a line break", "\r": "a carriage return", "\0": "a NUL"}.get(bad, "a control character")
        allowed = "; only line breaks are allowed" if newlines else ""
        raise ScenarioError(f"{key} must be printable text, but it contains {what} (U+{ord(bad):04X}){allowed}.", key)


def _check_computable(speed: float, key: str) -> None:
    if not SLOWEST <= speed <= FASTEST:
        raise ScenarioError(f"{key} must be between {SLOWEST:g} and {FASTEST!r} for double precision to place the "
                            f"impacts, got {speed!r}.", key)


def _finite_at_most_zero(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value) and value <= 0
