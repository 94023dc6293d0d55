"""`sears-paradox ledger`: each body's energy and momentum in each frame, and the hidden part (the docs,
"Energy and momentum").

Thin: parse the options, call `rodparadox.io.ledger_report` (text, JSON, CSV),
`rodparadox.tables.build` (Markdown, LaTeX) or `rodparadox.render.ledger_figure` (SVG,
PDF, PNG), report what was written.
matplotlib is imported only to draw a figure.
"""

from __future__ import annotations

import math
import textwrap
from pathlib import Path

import click

from rodparadox.render.styles import FORMATS as FIGURE_FORMATS

from rodparadox.errors import OptionError
from rodparadox.numbers import decimal

from . import words
from .edge import BadInput, before_matplotlib, emit, report, reports_errors
from .options import (format_option, frame_option, load_scenario, output_option, quiet_option, rod_asked, run_rods,
                      scenario_options, style_option)

TABLE_FORMATS = ("text", "json", "csv", "markdown", "latex")
_EXTENSIONS = {"txt": "text", "text": "text", "json": "json", "csv": "csv", "md": "markdown", "markdown": "markdown",
               "tex": "latex"}


def _times(spec: str | None) -> tuple[float, ...] | None:
    """--at: comma-separated times of the frame's own clock; every item a finite number."""
    if spec is None:
        return None
    out = []
    for item in (part.strip() for part in spec.split(",")):
        try:
            t = decimal(item)
        except ValueError:
            t = math.nan
        if not math.isfinite(t):
            raise OptionError("at", item, "one or more times (numbers, in the unit L is given in), comma-separated")
        out.append(t)
    return tuple(out)


#: --at: a time farther than this many lengths of a frame's window (docs/ledger.md, "The ledger") outside it is refused:
#: nothing changes outside the window, so such a time is a slip (1e308 for 1e3), not a question
AT_WINDOWS = 1000


def _check_times(history, frames, times) -> None:
    """Every --at time within AT_WINDOWS lengths of each frame's time window (`frames.time_window`)."""
    from rodparadox.numbers import shown
    from rodparadox.physics.frames import frame_symbol, time_window

    for frame in frames:
        lo, hi = time_window(history, frame)
        reach = AT_WINDOWS * (hi - lo)
        for t in times or ():
            if not lo - reach <= t <= hi + reach:
                raise OptionError("at", t, template="{what}: {value:g} lies more than {windows} window lengths "
                                  "outside {frame}'s window ({lo} to {hi}, from before the first impact to after the "
                                  "last), where nothing changes; give times near it.", windows=AT_WINDOWS,
                                  frame=frame_symbol(frame), lo=shown(lo, 4), hi=shown(hi, 4))


def _kind(fmt: str | None, output: str | None) -> str:
    """`table` or `figure`, from --format, else from the extension of -o, else a table (text)."""
    if fmt is not None:
        items = [part.strip().lower() for part in fmt.split(",")]
        if len(items) == 1 and items[0] in TABLE_FORMATS:
            return "table"
        if all(item in FIGURE_FORMATS for item in items):
            return "figure"
        raise OptionError("format", fmt, f"one of {', '.join(TABLE_FORMATS)}, or one or more of "
                                         f"{', '.join(FIGURE_FORMATS)} comma-separated")
    from rodparadox.io.output import is_stream

    if output is None or output == "-" or (is_stream(output) and not Path(output).suffix):
        return "table"  # standard output, or a device or pipe such as /dev/stdout: text unless --format says
    suffix = Path(output).suffix.lstrip(".").lower()
    if suffix in _EXTENSIONS:
        return "table"
    if suffix in FIGURE_FORMATS or Path(output).is_dir():
        return "figure"
    raise words.unknown_extension(output, ".txt, .json, .csv, .md, .tex, .svg, .pdf or .png,")


def _check_agreement(kind: str, fmt: str | None, output: str | None) -> None:
    """-o's extension against --format: a table into a file named as a figure (x.svg with json), or a figure into
    one named as a table (x.tex with svg), is a contradiction, refused as export and plot refuse theirs."""
    if fmt is None or output in (None, "-") or Path(output).is_dir():
        return
    suffix = Path(output).suffix.lstrip(".").lower()
    named = _EXTENSIONS.get(suffix) or (suffix if suffix in FIGURE_FORMATS else None)
    asked = [part.strip().lower() for part in fmt.split(",")]
    if named is not None and (named not in asked or (kind == "table") != (suffix in _EXTENSIONS)):
        raise words.output_disagrees(output, fmt.strip())


@click.command()
@scenario_options(rods=("rigid", "causal", "both"))
@frame_option("The frames: S, S', both, or the frame of velocity U relative to S; a comma-separated list "
              "gives several (e.g. both,0.3).")
@click.option("--at", "at", default=None, metavar="T1,T2,...",
              help="Also give each body's (E, p) at these times of each frame (a table), in the unit L is "
                   "given in. [json and csv without --at: a dense sampling]")
@format_option("A table (text, json, csv; markdown: pipe tables; latex: a booktabs/siunitx fragment) or a figure "
               "(svg, pdf, png). [default: the extension of -o, else text]", default=None,
               metavar="text|json|csv|markdown|latex|svg,pdf,png")
@output_option("Tables: a file ('-' or none: standard output). Figures: a folder (it must exist) or a file name. "
               "[figures: outputs/, created if missing]")
@style_option()
@quiet_option
@reports_errors
def ledger(scenario: str, v: float | None, L: float | None, frame: str, at: str | None, fmt: str | None,
           output: str | None, style: str, quiet: bool) -> None:
    """Energy and momentum of every body, before and after each impact and on slices of each frame's time.

    The rod's kinetic part is integrated over its material points; the hidden
    part (total before the first impact minus the kinetic total) is what the
    rod's stress carries: Sears's "hidden momentum".

    Example: sears-paradox ledger fig1 --frame moving --at 0.5,1,1.5
    """
    from sears_paradox_cli import planning as planned
    from rodparadox.io.output import check_target, write_atomic

    if output is not None and not output.strip():
        raise words.empty_output(output)
    planned.refuse_rod_view(frame, "ledger")
    times = _times(at)
    kind = _kind(fmt, output)
    _check_agreement(kind, fmt, output)
    if kind == "table":
        fmt = (fmt or _EXTENSIONS.get(Path(output or "-").suffix.lstrip(".").lower(), "text")).strip().lower()
        if output not in (None, "-"):
            suffix = Path(output).suffix.lstrip(".").lower()
            if suffix in _EXTENSIONS and _EXTENSIONS[suffix] != fmt:
                raise words.output_disagrees(output, fmt)
            check_target(output)
        s = load_scenario(scenario, v, L)
        if s.forces is not None and fmt not in ("text", "json", "csv"):
            raise BadInput(f"{s.name} drives the rod by forces at its ends, whose ledger is written as text, json or "
                           f"csv only for now; give one of these.")
        frames = planned.frames_of(frame, s.v)

        histories = run_rods(s, scenario, frames)
        for history in histories:
            _check_times(history, frames, times)
        text = _text(fmt, histories, frames, times)
        if output in (None, "-"):
            emit(text, nl=False)
            return
        report([(output, write_atomic(output, text.encode("utf-8")))], quiet)
        return

    if times is not None:
        raise OptionError("at", at, TABLE_FORMATS, "{what} selects the slices of a table ({choices}); a figure shows "
                                                   "every instant.")
    rod = rod_asked()
    described = planned.Outputs(formats=FIGURE_FORMATS, default="svg", kind="ledger")  # as plot's, named _ledger
    jobs = planned.plan([scenario], described, v=v, L=L, frame=frame, fmt=fmt, output=output, style=style,
                        extras=[rod] if rod in ("causal", "both") else [])  # fig1_ledger_causal.svg
    if rod == "both" and any(len(job.frames[0]) > 4 for job in jobs):
        raise OptionError("frame", frame, template="{what}: the ledger figure of both rods takes at most 4 frames "
                                                   "(a row of each rod per frame); give fewer.")
    histories = [run_rods(job.scenario, job.name, job.frames[0]) for job in jobs]
    planned.prepare(jobs, described, output)

    before_matplotlib()
    from rodparadox import render
    from rodparadox.render import ledger_figure  # matplotlib: only now, after every input has been checked

    for run, job in zip(histories, jobs):
        if run[0].driving is not None:  # a rod driven by forces: what each agent delivered, the rod's parts
            from rodparadox.render import forces_ledger_figure

            figure = forces_ledger_figure.draw(run, job.frames[0], style)
        else:
            figure = (ledger_figure.draw_both(*run, job.frames[0], style) if len(run) == 2
                      else ledger_figure.draw(run[0], job.frames[0], style))
        report(((path, write_atomic(path, render.figure_bytes(figure, f, style))) for f, path in job.paths.items()),
               quiet)


def _writers(history) -> dict:
    """The ledger's writers for the history's rod: with fronts (the causal rod), its matter and stress parts
    (`tables.causal_ledger`); with turns (the rigid rod), its kinetic and hidden parts (`io.ledger_report`)."""
    from rodparadox.io import ledger_report
    from rodparadox.tables import build as tables
    from rodparadox.tables import causal_ledger

    if history.driving is not None:
        from rodparadox.tables import forces_ledger

        return {"text": forces_ledger.to_text, "json": forces_ledger.to_json, "csv": forces_ledger.to_csv,
                "document": forces_ledger.document, "rows": forces_ledger.csv_rows}
    if history.fronts is not None:
        return {"text": causal_ledger.to_text, "json": causal_ledger.to_json, "csv": causal_ledger.to_csv,
                "markdown": causal_ledger.to_markdown, "latex": causal_ledger.to_latex,
                "document": causal_ledger.document, "rows": causal_ledger.csv_rows}
    return {"text": ledger_report.to_text, "json": ledger_report.to_json, "csv": ledger_report.to_csv,
            "markdown": tables.ledger_markdown, "latex": tables.ledger_latex,
            "document": ledger_report.document, "rows": ledger_report.csv_rows}


def _text(fmt: str, histories: tuple, frames, times) -> str:
    """The ledger of one rod, or of both rods (the same particles): one after the other as text, tables and LaTeX;
    one JSON object with a member per rod; one CSV table whose first column names the rod."""
    import json

    from rodparadox.io import ledger_report

    if len(histories) == 1:
        return _writers(histories[0])[fmt](histories[0], frames, times)
    if fmt == "json":
        return json.dumps({"format": ledger_report.FORMAT, "rod": "both",
                           **{h.model: _writers(h)["document"](h, frames, times) for h in histories}},
                          indent=1, allow_nan=False) + "\n"
    if fmt == "csv":
        rows = [["rod", *ledger_report.CSV_COLUMNS]]
        rows += [[h.model, *row] for h in histories for row in _writers(h)["rows"](h, frames, times)]
        return "\n".join(",".join(row) for row in rows) + "\n"
    from rodparadox.tables.comparison import comparison_note

    note = textwrap.wrap(comparison_note(histories, frames), 110)
    head = {"latex": "".join(f"% {line}\n" for line in note)}.get(fmt, "\n".join(note) + "\n\n")
    return head + "\n".join(_writers(h)[fmt](h, frames, times) for h in histories)