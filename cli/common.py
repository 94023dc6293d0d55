"""What every command shares: the error that exits 2, loading and running a scenario, the common options.

Imported by `main` and `plot` (never the other way round), so neither imports
the other's module. Only click and `rodparadox.errors` at module top: `--help`
must not load numpy or matplotlib.
"""

from __future__ import annotations

import functools
import math

import click

from rodparadox.errors import RodParadoxError


class BadInput(click.ClickException):
    """A scenario, option or path the user must fix: one sentence, exit status 2."""

    exit_code = 2


def reports_errors(command):
    """The CLI edge: any library error (`RodParadoxError`) becomes its one sentence and exit status 2, no traceback."""
    @functools.wraps(command)
    def wrapper(*args, **kwargs):
        try:
            return command(*args, **kwargs)
        except RodParadoxError as e:
            raise BadInput(str(e)) from None
    return wrapper


def load_scenario(name: str, v: float | None, L: float | None):
    """A built-in scenario or YAML file, with the command line's --v and --L."""
    from rodparadox.scenario import load

    return load(name).with_overrides(v=v, L=L)


def run_scenario(scenario, source: str):
    """Run a scenario; `source` is the name or path the user gave, to start any error sentence."""
    from rodparadox.engine import run
    from rodparadox.errors import ScenarioError

    try:
        return run(scenario)
    except ScenarioError as e:  # the engine's sentence does not say which scenario: say it here
        raise BadInput(f"{source}: {e}") from None


def checked_frame_velocity(u: float | None) -> float | None:
    """--frame-velocity, checked here so the message names the option."""
    if u is not None and not (math.isfinite(u) and -1.0 < u < 1.0):
        raise BadInput(f"option --frame-velocity must be a velocity u with -1 < u < 1 (units of c), got {u:g}.")
    return u


scenario_argument = click.argument("scenario", metavar="SCENARIO")
v_option = click.option("--v", "v", type=float, metavar="V",
                        help="Speed of the moving frame S' and default particle speed, 0 < V < 1 (overrides the scenario).")
L_option = click.option("--L", "L", type=float, metavar="L", help="The rod's proper length, L > 0 (overrides the scenario).")
frame_velocity_option = click.option("--frame-velocity", "frame_velocity", type=float, metavar="U",
                                     help="Also show the frame of velocity U relative to S, -1 < U < 1.")
