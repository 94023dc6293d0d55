"""What every command shares before its own work: the options (each declared once), the numbers they take, and
a scenario loaded with them and run in the rods --rod asks for (`physics.models`). Only click at module top:
`--help` must not load numpy or matplotlib.
"""

from __future__ import annotations

import click

from . import words
from .edge import BadInput
from .words import option

def checked_output(output: str | None) -> str | None:
    """-o: an empty name is refused here, as every empty value is (it would mean the current folder)."""
    if output is not None and not output.strip():
        raise words.empty_output(output)
    return output


def load_scenario(name: str, v: float | None, L: float | None):
    """A built-in scenario or YAML file, with the command line's --v, --L and --rod (`with_options`)."""
    from rodparadox.io.scenario import load

    return with_options(load(name), v, L)


def with_options(scenario, v: float | None, L: float | None):
    """The scenario with the command line's --v, --L and --rod; a bad value is said as its option's."""
    from rodparadox.errors import ScenarioError

    try:
        scenario = scenario.with_overrides(v=v, L=L)
    except ScenarioError as e:
        raise words.scenario_option_error(e, [k for k, value in (("v", v), ("L", L)) if value is not None]) from None
    return _with_rod(scenario)


def _with_rod(scenario):
    """The scenario with --rod (kept in the click context by `scenario_options`), if the command takes that rod."""
    context = click.get_current_context(silent=True)
    meta = context.meta if context is not None else {}
    rod, rods = meta.get(ROD_META) or scenario.rod, meta.get(RODS_META, ("rigid", "causal"))
    if rod not in rods:
        raise BadInput(words.rod_not_here(rod, context.info_name if context is not None else "this command", rods))
    if rod != "both":  # both: asked for by name, beside the causal rod the file's sound_speed describes
        from rodparadox.io.scenario import check_sound_speed_rod

        check_sound_speed_rod(scenario.with_overrides(rod=rod))
    if scenario.forces is not None:
        _check_forces(scenario, rod)
    return scenario if rod == "both" else scenario.with_overrides(rod=rod)  # both: the file's rod places particles


def _check_forces(scenario, rod: str) -> None:
    """A scenario with forces (every command shows them): refused, in one sentence, where a rod asked for cannot
    carry them (the pull limits, `physics.models.check_forces`)."""
    from rodparadox.errors import ScenarioError
    from rodparadox.physics.models import check_forces, models_of

    for model in models_of(rod, scenario):
        try:
            check_forces(scenario.with_overrides(rod=model))
        except ScenarioError as e:
            raise BadInput(f"{scenario.name}: {e}") from None


def rod_asked() -> str | None:
    """--rod as given on the command line (rigid, causal or both), or None."""
    context = click.get_current_context(silent=True)
    return context.meta.get(ROD_META) if context is not None else None


def run_rods(scenario, source: str, frames=(), rods: str | None = None) -> tuple:
    """The scenario run in the rods --rod asks for (or `rods`: a handout compares both whenever the causal rod is
    asked for) (`physics.models.run_rods`: with both, the two rods struck by the same particles), each checked as
    `run_scenario` checks one."""
    from rodparadox.physics.models import run_rods as run

    return _checked(lambda: run(scenario, rods or rod_asked()), source, frames)


def run_scenario(scenario, source: str, frames=()):
    """Run a scenario in its own rod; `source` is the name or path the user gave, to start any error sentence.

    The one verdict every command gives a scenario: it runs, and in every frame the command shows (`frames`)
    every velocity is below c in double precision (`frames.check_below_c`), so `plot`, `animate` and `ledger`
    refuse what `events`, `export` and `handout` refuse. A boost's frames in between need no check: a body's
    speed is largest at one of its ends."""
    from rodparadox.physics.models import run_rod

    return _checked(lambda: (run_rod(scenario),), source, frames)[0]


def _checked(run, source: str, frames) -> tuple:
    from rodparadox.errors import ScenarioError
    from rodparadox.physics.frames import check_below_c, view

    try:
        histories = run()
    except ScenarioError as e:  # the engine's sentence does not say which scenario: say it here
        raise BadInput(f"{source}: {e}") from None
    for history in histories:
        for frame in frames:
            check_below_c(view(history, frame))
    return histories


def checked_frame_velocity(u: float | None) -> float | None:
    """--frame-velocity, checked by the library's one rule (`frames.check_velocity`); the message names the option."""
    from rodparadox.errors import FrameError
    from rodparadox.physics.frames import check_velocity

    try:
        return None if u is None else check_velocity(u)
    except FrameError as e:
        raise words.frame_error(e, "frame_velocity", u) from None


# --- numbers: one rule for every number on the command line ------------------------------------------
# Decimal digits, an optional point and exponent (`rodparadox.numbers.decimal`), as in a scenario file: Python's
# `1_000` is refused as `0x10` is, with the same sentence.

def _not_decimal(value, kind: str) -> str:
    if isinstance(value, str) and ("_" in value or value.strip().lower().lstrip("+-").startswith(("0x", "0b", "0o"))):
        examples = "1000, 0.6, 1e-6" if kind == "float" else "1000"
        return f"{value!r} is not a valid {kind}: write it in plain decimal digits (e.g. {examples})."
    return f"{value!r} is not a valid {kind}."


class Decimal(click.types.FloatParamType):
    """A float written in decimal (`numbers.decimal`): click's float without Python's underscores."""

    def convert(self, value, param, ctx):
        from rodparadox.numbers import decimal

        if isinstance(value, float):
            return value
        try:
            return decimal(value)
        except ValueError:
            self.fail(_not_decimal(value, "float"), param, ctx)


class Whole(click.IntRange):
    """A whole number written in decimal digits (`numbers.whole`), within optional bounds: click's int (or
    IntRange) without Python's underscores."""

    def convert(self, value, param, ctx):
        from rodparadox.numbers import whole

        if not isinstance(value, int):
            try:
                value = whole(value)
            except ValueError:
                self.fail(_not_decimal(value, "integer"), param, ctx)
        return super().convert(value, param, ctx)

    def _describe_range(self) -> str:
        """The bounds as help shows them, or nothing for a whole number without bounds (click wrote "x<=None")."""
        return "" if self.min is None and self.max is None else super()._describe_range()


NUMBER = Decimal()


class FrameVelocity(Decimal):
    """--frame-velocity of events and export: a number; the word rod (the rod's own view, a drawing's) is refused
    in a sentence of its own."""

    def convert(self, value, param, ctx):
        if isinstance(value, str) and value.strip() == "rod":
            self.fail("rod (the rod's own view) is drawn by plot, animate and handout only; these tables need a "
                      "Lorentz frame: give a velocity U relative to S.", param, ctx)
        return super().convert(value, param, ctx)



# --- the options the commands share ----------------------------------------------------------------
# Each declared once, named as `words` names it in messages; where commands word an option differently, the
# command gives its own help (and metavar).

scenario_argument = click.argument("scenario", metavar="SCENARIO")
scenarios_argument = click.argument("scenarios", nargs=-1, required=True, metavar="SCENARIO...")
v_option = click.option(option("v"), "v", type=NUMBER, metavar="V",
                        help="Speed of the moving frame S' and default particle speed, 0 < V < 1 (overrides the scenario).")
L_option = click.option(option("L"), "L", type=NUMBER, metavar="L", help="The rod's proper length, L > 0 (overrides the scenario).")
frame_velocity_option = click.option(option("frame_velocity"), "frame_velocity", type=FrameVelocity(), metavar="U",
                                     help="Also show the frame of velocity U relative to S, |U| <= 0.9999999.")
quiet_option = click.option("-q", "--quiet", is_flag=True,
                            help="Print nothing on success (the paths written are printed otherwise).")


#: where `scenario_options` leaves --rod and the rod models a command draws, for `load_scenario`
ROD_META, RODS_META = "sears_paradox.rod", "sears_paradox.rods"
ROD_WORDS = ("rigid", "causal", "both")


def scenario_options(several: bool = False, rods: tuple[str, ...] = ("rigid", "causal")):
    """SCENARIO (or SCENARIO... with `several`), then --v, --L and --rod: how every command begins. `rods`: the
    rod models the command takes; --rod (or a scenario's rod:) naming another is refused in one sentence."""
    def keep_rod(context: click.Context, parameter, value):
        context.meta[ROD_META], context.meta[RODS_META] = value, rods
        return value

    both = "both" in rods
    rod_option = click.option(option("rod"), "rod", type=click.Choice(ROD_WORDS), default=None, expose_value=False,
                              is_eager=True, callback=keep_rod, metavar="|".join(rods),
                              help="The rod: rigid (the paper's) or causal (sound at c, docs \"The causal rod\")"
                                   + ("; both: the two side by side, struck by the same particles" if both else "")
                                   + "; overrides the scenario's rod:.")

    def decorate(command):
        for declare in (rod_option, L_option, v_option, scenarios_argument if several else scenario_argument):
            command = declare(command)
        return command
    return decorate


def frame_option(help: str, metavar: str = "rest|moving|both|U"):
    """--frame: the frames (panels) to show, read by `planning.frames_of` (or by the command's own reader)."""
    return click.option(option("frame"), "frame", default="both", show_default=True, metavar=metavar, help=help)


def format_option(help: str, **kind):
    """--format, as `fmt`: a command's own list of formats (`kind`: a click type, a default, a metavar)."""
    return click.option(option("format"), "fmt", help=help, **kind)


def output_option(help: str, metavar: str = "PATH", default: str | None = None):
    """-o/--output: where the command writes (`None`: the planner's default folder; "-": standard output)."""
    return click.option(option("output"), "--output", "output", metavar=metavar, default=default,
                        show_default=default is not None, help=help)


def style_option(names: tuple[str, ...] | None = None, default: str = "default",
                 help: str = "default: colour, colour-blind safe; print: black and white, serif; slides: large type."):
    """--style, as every drawing command takes it (the names come from `rodparadox.render.styles`, which imports
    nothing); a command that prints by default (handout) gives its own order, default and help."""
    if names is None:
        from rodparadox.render.styles import STYLE_NAMES as names

    return click.option("--style", "style", type=click.Choice(names), default=default, show_default=True, help=help)
