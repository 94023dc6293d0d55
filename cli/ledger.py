"""`sears-paradox ledger`: each body's energy and momentum in each frame, and the hidden part (README, "The ledger").

Thin: parse the options, call `rodparadox.io.ledger_report` (text, JSON, CSV),
`rodparadox.tables.build` (Markdown, LaTeX) or `rodparadox.render.ledger_figure` (SVG,
PDF, PNG), report what was written.
matplotlib is imported only to draw a figure.
"""

from __future__ import annotations

import math
from pathlib import Path

import click

from rodparadox.render.styles import FORMATS as FIGURE_FORMATS

from .common import (BadInput, L_option, emit, load_scenario, quiet_option, reports_errors, run_scenario, style_option,
                     v_option)

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
            t = float(item) + 0.0
        except ValueError:
            t = math.nan
        if not math.isfinite(t):
            raise BadInput(f"option --at must be one or more times (numbers, in the unit L is given in), "
                           f"comma-separated, got {item!r}.")
        out.append(t)
    return tuple(out)


def _kind(fmt: str | None, output: str | None) -> str:
    """`table` or `figure`, from --format, else from the extension of -o, else a table (text)."""
    if fmt is not None:
        items = [part.strip().lower() for part in fmt.split(",")]
        if len(items) == 1 and items[0] in TABLE_FORMATS:
            return "table"
        if all(item in FIGURE_FORMATS for item in items):
            return "figure"
        raise BadInput(f"option --format must be one of {', '.join(TABLE_FORMATS)}, or one or more of "
                       f"{', '.join(FIGURE_FORMATS)} comma-separated, got {fmt!r}.")
    if output is None or output == "-":
        return "table"
    suffix = Path(output).suffix.lstrip(".").lower()
    if suffix in _EXTENSIONS:
        return "table"
    if suffix in FIGURE_FORMATS or Path(output).is_dir():
        return "figure"
    raise BadInput(f"option -o: cannot tell the format of {output!r} from its extension; name it "
                   f".txt, .json, .csv, .md, .tex, .svg, .pdf or .png, or give --format.")


@click.command()
@click.argument("scenario", metavar="SCENARIO")
@v_option
@L_option
@click.option("--frame", "frame", default="both", show_default=True, metavar="rest|moving|both|U",
              help="The frames: S, S', both, or the frame of velocity U relative to S; a comma-separated list "
                   "gives several (e.g. both,0.3).")
@click.option("--at", "at", default=None, metavar="T1,T2,...",
              help="Also give each body's (E, p) at these times of each frame (a table), in the unit L is "
                   "given in. [json and csv without --at: a dense sampling]")
@click.option("--format", "fmt", default=None, metavar="text|json|csv|markdown|latex|svg,pdf,png",
              help="A table (text, json, csv; markdown: pipe tables; latex: a booktabs/siunitx fragment) or a figure "
                   "(svg, pdf, png). [default: the extension of -o, else text]")
@click.option("-o", "--output", "output", metavar="PATH", default=None,
              help="Tables: a file ('-' or none: standard output). Figures: a folder (it must exist) or a file name. "
                   "[figures: outputs/, created if missing]")
@style_option
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
        raise BadInput(f"option -o must name a file or folder, got {output!r}.")
    times = _times(at)
    if _kind(fmt, output) == "table":
        fmt = (fmt or _EXTENSIONS.get(Path(output or "-").suffix.lstrip(".").lower(), "text")).strip().lower()
        if output not in (None, "-"):
            suffix = Path(output).suffix.lstrip(".").lower()
            if suffix in _EXTENSIONS and _EXTENSIONS[suffix] != fmt:
                raise BadInput(f"option -o names {output!r} but --format is {fmt}; make them agree.")
            check_target(output)
        s = load_scenario(scenario, v, L)
        frames = planned.frames_of(frame, s.v)
        from rodparadox.io import ledger_report
        from rodparadox.tables import build as tables

        text = {"text": ledger_report.to_text, "json": ledger_report.to_json, "csv": ledger_report.to_csv,
                "markdown": tables.ledger_markdown, "latex": tables.ledger_latex}[fmt](run_scenario(s, scenario),
                                                                                    frames, times)
        if output in (None, "-"):
            emit(text, nl=False)
            return
        written = write_atomic(output, text.encode("utf-8"))
        if not quiet:
            emit(output if written else f"{output} (unchanged)")
        return

    if times is not None:
        raise BadInput(f"option --at selects the slices of a table ({', '.join(TABLE_FORMATS)}); a figure shows every "
                       f"instant.")
    jobs = planned.plan([scenario], v=v, L=L, frame=frame, fmt=fmt, output=output, style=style, kind="ledger",
                        allowed=FIGURE_FORMATS, default_format="svg")
    histories = [run_scenario(job.scenario, job.name) for job in jobs]
    planned.prepare(jobs, output)

    from rodparadox import render
    from rodparadox.render import ledger_figure  # matplotlib: only now, after every input has been checked

    for history, job in zip(histories, jobs):
        figure = ledger_figure.draw(history, job.frames, style)
        for f, path in job.paths.items():
            written = write_atomic(path, render.figure_bytes(figure, f, style))
            if not quiet:
                emit(str(path) if written else f"{path} (unchanged)")
