"""The `sears-paradox` command line: parse, call the library, report. No physics, no drawing.

Library modules are imported inside the commands so that `--help` stays fast
and never loads numpy or matplotlib.
"""

from __future__ import annotations

import sys

import click

from rodparadox import __version__

from .common import (L_option, checked_frame_velocity, frame_velocity_option, load_scenario, reports_errors,
                     run_scenario, scenario_argument, v_option)
from .plot import plot  # the drawing command; it imports matplotlib only when it runs


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, "--version", prog_name="sears-paradox")
def main() -> None:
    """Minkowski diagrams of a rigid rod struck by particles, in two frames at once.

    SCENARIO is a built-in name (see `sears-paradox list`) or a YAML file.

    Example: sears-paradox events fig2 --v 0.6
    """


@main.command("list")
@reports_errors
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
@frame_velocity_option
@reports_errors
def events(scenario: str, v: float | None, L: float | None, frame_velocity: float | None) -> None:
    """Print the impacts in the rest frame S and the moving frame S' (and U if given).

    Example: sears-paradox events fig2 --v 0.8 --frame-velocity 0.3
    """
    from rodparadox.export import to_table
    from rodparadox.frames import paper_frames

    s = load_scenario(scenario, v, L)
    frames = paper_frames(s.v, checked_frame_velocity(frame_velocity))
    click.echo(to_table(run_scenario(s, scenario), frames), nl=False)


@main.command()
@scenario_argument
@v_option
@L_option
@frame_velocity_option
@click.option("--format", "fmt", type=click.Choice(["json", "csv"]), default="json", show_default=True,
              help="json: the documented contract (README); csv: one row per event and world-line point.")
@click.option("-o", "--output", "output", metavar="PATH", default="-", show_default=True,
              help="File to write ('-' for standard output); written atomically, left untouched if unchanged.")
@reports_errors
def export(scenario: str, v: float | None, L: float | None, frame_velocity: float | None, fmt: str, output: str) -> None:
    """Write the world-lines and impacts of both frames as JSON or CSV.

    Example: sears-paradox export fig2 --v 0.6 -o fig2.json
    """
    from rodparadox.export import to_csv, to_json
    from rodparadox.frames import paper_frames
    from rodparadox.output import write_atomic

    s = load_scenario(scenario, v, L)
    frames = paper_frames(s.v, checked_frame_velocity(frame_velocity))
    text = (to_json if fmt == "json" else to_csv)(run_scenario(s, scenario), frames)
    if output == "-":
        sys.stdout.write(text)
        return
    write_atomic(output, text.encode("utf-8"))
    click.echo(output)


main.add_command(plot)
