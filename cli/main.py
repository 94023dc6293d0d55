"""The `sears-paradox` command line: parse, call the library, report. No physics, no drawing.

Library modules are imported inside the commands so that `--help` stays fast
and never loads numpy or matplotlib.
"""

from __future__ import annotations

import errno
import gc
import sys
import textwrap
from pathlib import Path

import click

from rodparadox import __version__

from . import edge, words
from .edge import BadInput, emit, report, reports_errors
from .options import (checked_frame_velocity, checked_output, format_option, frame_velocity_option, load_scenario,
                      output_option, quiet_option, ROD_WORDS, run_rods, scenario_options)
from .animate import animate  # imports matplotlib only when it runs
from .handout import handout
from .html import html  # never imports matplotlib
from .ledger import ledger
from .plot import plot  # the drawing command; it imports matplotlib only when it runs

#: what `export` writes, each named by its file extension
EXPORT_FORMATS = ("json", "csv")
#: what `events` prints: the aligned text table, a Markdown pipe table, or a LaTeX (booktabs, siunitx) fragment
EVENTS_FORMATS = ("text", "markdown", "latex")


class _Main(click.Group):
    """The group, with one more edge: help and version text that cannot be written (a full disk) is one
    sentence and exit status 1; the commands' own output goes through `edge.emit`."""

    def main(self, args=None, prog_name=None, complete_var=None, standalone_mode=True, **extra):
        try:
            if not standalone_mode:
                return super().main(args, prog_name, complete_var, standalone_mode, **extra)
            try:
                with edge.stopped_by_signals():
                    code = super().main(args, prog_name, complete_var, False, **extra)
            except click.UsageError as e:  # click's own checks (a bad --style, --rod-lines -1): one sentence too
                click.echo(f"Error: {e.format_message()}", err=True)
                sys.exit(e.exit_code)
            except click.ClickException as e:
                e.show()
                sys.exit(e.exit_code)
            except (edge.Stopped, click.exceptions.Abort) as e:
                # Ctrl-C, kill, timeout, a closed terminal: every file and temporary folder was cleaned up on the
                # way out (atomic writes, the encoders' `with` blocks); say so, and exit as the signal would
                stopped = e if isinstance(e, edge.Stopped) else edge.Stopped(edge.signal_number("SIGINT"))
                try:
                    click.echo(f"Error: {stopped.sentence()}", err=True)
                except OSError:  # the terminal went away with SIGHUP
                    pass
                sys.exit(stopped.exit_code)
            sys.exit(code if isinstance(code, int) else 0)
        except OSError as e:
            # only help and version text are written outside the commands' edge (reports_errors, emit)
            if e.errno not in (errno.ENOSPC, errno.EIO, errno.EDQUOT, errno.EFBIG):
                raise
            edge.stdout_to_devnull()
            click.echo(f"Error: cannot write to standard output: {(e.strerror or str(e)).lower()}.", err=True)
            sys.exit(1)


@click.group(cls=_Main, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, "--version", prog_name="sears-paradox")
def main() -> None:
    """Minkowski diagrams of a rod struck by particles or pushed by forces, in two frames at once.

    SCENARIO is a built-in name (see `sears-paradox list`) or a YAML file; a file
    that exists wins over a built-in name of the same name.

    Example: sears-paradox events fig2 --v 0.6
    """


@main.command("list")
@reports_errors
def list_scenarios() -> None:
    """Name the built-in scenarios, each with one line about it.

    Example: sears-paradox list
    """
    from rodparadox.io.scenario import builtin_names, describe

    names = builtin_names()
    width = max(map(len, names), default=0)
    for name in names:
        emit(f"{name:<{width}}  {describe(name)}")


@main.command()
@scenario_options(rods=ROD_WORDS)
@frame_velocity_option
@format_option("text: aligned columns; markdown: a pipe table per frame; latex: a booktabs/siunitx fragment "
               "to \\input.", type=click.Choice(EVENTS_FORMATS, case_sensitive=False), default="text",
               show_default=True)
@reports_errors
def events(scenario: str, v: float | None, L: float | None, frame_velocity: float | None, fmt: str) -> None:
    """Print the impacts in the rest frame S and the moving frame S' (and U if given).

    Example: sears-paradox events fig2 --v 0.8 --frame-velocity 0.3
    """
    from rodparadox.physics.frames import paper_frames

    s = load_scenario(scenario, v, L)
    if s.forces is not None and fmt != "text":
        raise BadInput(f"{s.name} drives the rod by forces at its ends, whose events are printed as text only for "
                       f"now; leave out --format {fmt}.")
    frames = paper_frames(s.v, checked_frame_velocity(frame_velocity))
    histories = run_rods(s, scenario, frames)
    from rodparadox.tables.comparison import comparison_note

    note = comparison_note(histories, frames) if len(histories) > 1 else ""
    if fmt == "text":
        from rodparadox.io.export import rods_to_table, to_table

        emit(to_table(histories[0], frames) if not note else rods_to_table(histories, frames, note), nl=False)
        return
    from rodparadox.tables import build as tables

    write = tables.events_markdown if fmt == "markdown" else tables.events_latex
    if not note:
        emit(write(histories[0], frames), nl=False)
        return
    head = f"{note}\n\n" if fmt == "markdown" else "".join(f"% {line}\n" for line in textwrap.wrap(note, 110))
    title = "**The {} rod**\n\n" if fmt == "markdown" else "% The {} rod\n"
    emit(head + "\n".join(title.format(h.model) + write(h, frames) for h in histories), nl=False)


@main.command()
@scenario_options(rods=ROD_WORDS)
@frame_velocity_option
@format_option("json: the documented contract (the documentation's \"The JSON contract\"); csv: one row per event "
               "and world-line point. [default: the extension of -o FILE, else json]",
               type=click.Choice(EXPORT_FORMATS), default=None)
@output_option("File to write ('-' for standard output); written atomically, left untouched if unchanged.",
               default="-")
@quiet_option
@reports_errors
def export(scenario: str, v: float | None, L: float | None, frame_velocity: float | None, fmt: str | None,
           output: str, quiet: bool) -> None:
    """Write the world-lines and impacts of both frames as JSON or CSV.

    With -o it prints the path written, or `PATH (unchanged)` when the file already held these bytes.

    Example: sears-paradox export fig2 --v 0.6 -o fig2.json
    """
    from rodparadox.io.export import rods_to_csv, rods_to_json, to_csv, to_json
    from rodparadox.physics.frames import paper_frames
    from rodparadox.io.output import check_target, write_atomic

    fmt = export_format(checked_output(output), fmt)
    if output != "-":
        check_target(output)  # before the work: a missing folder is said at once
    s = load_scenario(scenario, v, L)
    frames = paper_frames(s.v, checked_frame_velocity(frame_velocity))
    histories = run_rods(s, scenario, frames)
    if len(histories) == 1:
        text = (to_json if fmt == "json" else to_csv)(histories[0], frames)
    else:
        text = (rods_to_json if fmt == "json" else rods_to_csv)(histories, frames)
    if output == "-":
        emit(text, nl=False)
        return
    report([(output, write_atomic(output, text.encode("utf-8")))], quiet)


def export_format(output: str, fmt: str | None) -> str:
    """The format: --format, else the extension of -o FILE (.json, .csv, any case), else json for standard output
    (and for a device or pipe named by -o, such as /dev/stdout)."""
    from rodparadox.io.output import is_stream

    if output == "-" or (is_stream(output) and not Path(output).suffix):
        return fmt or "json"
    suffix = Path(output).suffix.lstrip(".").lower()
    if fmt is None:
        if suffix not in EXPORT_FORMATS:
            raise words.unknown_extension(output, f".{', .'.join(EXPORT_FORMATS)}")
        return suffix
    if suffix in EXPORT_FORMATS and suffix != fmt:
        raise words.output_disagrees(output, fmt)
    return fmt


main.add_command(plot)
main.add_command(ledger)
main.add_command(animate)
main.add_command(handout)
main.add_command(html)


#: the garbage collector's thresholds in the program's own process (Python's are 700, 10, 10): a command lives for
#: seconds and imports numpy and matplotlib, about half a million objects, over which the collector's full passes ran
#: again and again while they loaded; with the first threshold at 100,000 they run a few times instead. The next two
#: keep Python's ratios, so that garbage in reference cycles (an animation's or a handout's figures) is still freed as
#: it builds up (`handout fig2 --rod both` at its peak: 123 MB with Python's thresholds, 130 MB with these).
GC_THRESHOLDS = (100_000, 10, 10)


def run() -> None:
    """The `sears-paradox` program (pyproject's console script): `main`, with `GC_THRESHOLDS`, and every object
    frozen (`gc.freeze`) once it is done, so that the interpreter's last collection at exit does not walk them all
    again. Measured with tests/benchmark_plot.py (median wall time against a bare matplotlib script drawing as much):
    `plot fig2` took 1.22x with Python's collector and 1.04x with these two changes. The tests call `main` in
    their own process, whose collector is theirs (tests/conftest.py)."""
    gc.set_threshold(*GC_THRESHOLDS)
    try:
        main()
    finally:
        gc.freeze()
