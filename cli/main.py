"""The `sears-paradox` command line: parse, call the library, report. No physics, no drawing.

Library modules are imported inside the commands so that `--help` stays fast
and never loads numpy or matplotlib.
"""

from __future__ import annotations

import math
import sys

import click

from rodparadox import __version__


class BadInput(click.ClickException):
    """A scenario, option or path the user must fix: one sentence, exit status 2."""

    exit_code = 2


def _scenario(name: str, v: float | None, L: float | None):
    from rodparadox.errors import ScenarioError
    from rodparadox.scenario import load

    try:
        return load(name).with_overrides(v=v, L=L)
    except ScenarioError as e:
        raise BadInput(str(e)) from None


def _history(scenario, source: str):
    """Run a scenario; `source` is the name or path the user gave, to start any error sentence."""
    from rodparadox.engine import run
    from rodparadox.errors import ScenarioError

    try:
        return run(scenario)
    except ScenarioError as e:
        raise BadInput(f"{source}: {e}") from None


def _frame_velocity(u: float | None) -> float | None:
    if u is not None and not (math.isfinite(u) and -1.0 < u < 1.0):
        raise BadInput(f"option --frame-velocity must be a velocity u with -1 < u < 1 (units of c), got {u:g}.")
    return u


scenario_argument = click.argument("scenario", metavar="SCENARIO")
v_option = click.option("--v", "v", type=float, metavar="V",
                        help="Speed of the moving frame S' and default particle speed, 0 < V < 1 (overrides the scenario).")
L_option = click.option("--L", "L", type=float, metavar="L", help="The rod's proper length, L > 0 (overrides the scenario).")
frame_option = click.option("--frame-velocity", "frame_velocity", type=float, metavar="U",
                            help="Also show the frame of velocity U relative to S, -1 < U < 1.")


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, "--version", prog_name="sears-paradox")
def main() -> None:
    """Minkowski diagrams of a rigid rod struck by particles, in two frames at once.

    SCENARIO is a built-in name (see `sears-paradox list`) or a YAML file.

    Example: sears-paradox events fig2 --v 0.6
    """


@main.command("list")
def list_scenarios() -> None:
    """Name the built-in scenarios, each with one line about it.

    Example: sears-paradox list
    """
    from rodparadox.scenario import builtin_names, describe

    names = builtin_names()
    width = max(map(len, names), default=0)
    for name in names:
        click.echo(f"{name:<{width}}  {describe(name)}")


@main.command()
@scenario_argument
@v_option
@L_option
@frame_option
def events(scenario: str, v: float | None, L: float | None, frame_velocity: float | None) -> None:
    """Print the impacts in the rest frame S and the moving frame S' (and U if given).

    Example: sears-paradox events fig2 --v 0.8 --frame-velocity 0.3
    """
    from rodparadox.export import to_table
    from rodparadox.frames import paper_frames

    s = _scenario(scenario, v, L)
    frames = paper_frames(s.v, _frame_velocity(frame_velocity))
    click.echo(to_table(_history(s, scenario), frames), nl=False)


@main.command()
@scenario_argument
@v_option
@L_option
@frame_option
@click.option("--format", "fmt", type=click.Choice(["json", "csv"]), default="json", show_default=True,
              help="json: the documented contract (README); csv: one row per event and world-line point.")
@click.option("-o", "--output", "output", metavar="PATH", default="-", show_default=True,
              help="File to write ('-' for standard output); written atomically, left untouched if unchanged.")
def export(scenario: str, v: float | None, L: float | None, frame_velocity: float | None, fmt: str, output: str) -> None:
    """Write the world-lines and impacts of both frames as JSON or CSV.

    Example: sears-paradox export fig2 --v 0.6 -o outputs/fig2.json
    """
    from rodparadox.errors import OutputError
    from rodparadox.export import to_csv, to_json
    from rodparadox.frames import paper_frames
    from rodparadox.output import write_atomic

    s = _scenario(scenario, v, L)
    frames = paper_frames(s.v, _frame_velocity(frame_velocity))
    text = (to_json if fmt == "json" else to_csv)(_history(s, scenario), frames)
    if output == "-":
        sys.stdout.write(text)
        return
    try:
        write_atomic(output, text.encode("utf-8"))
    except OutputError as e:
        raise BadInput(str(e)) from None
    click.echo(output)


from .plot import plot  # noqa: E402  (the drawing command; it imports matplotlib only when it runs)

main.add_command(plot)
