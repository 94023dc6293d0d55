"""`sears-paradox plot`: draw the paper's Minkowski diagrams into SVG, PDF or PNG files.

Thin: parse the options, call `rodparadox.render` and `rodparadox.output`,
print the paths written. matplotlib is imported inside the command, so
`--help` never loads it.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import NamedTuple

import click

from rodparadox.styles import FORMATS, STYLE_NAMES

from .common import (BadInput, L_option, checked_output, emit, load_scenario, quiet_option, reports_errors,
                     run_scenario, v_option)

#: where figures go when -o is not given; the only output folder `plot` creates itself
DEFAULT_FOLDER = "outputs"

_EXTRAS = (("other_axes", "axes"), ("light_cones", "cones"), ("hyperbolae", "hyperbolae"), ("grid", "grid"))


def _number(value: float) -> str:
    """A number in a file name: every digit the float holds, as in a frame's name (rodparadox.numbers.exact)."""
    from rodparadox.numbers import exact

    return exact(value)


def parse_frames(spec: str, v: float):
    """--frame: `rodparadox.frames.parse_frames`, its error named as the option's."""
    from rodparadox.errors import FrameError
    from rodparadox.frames import parse_frames as frames_of

    try:
        return frames_of(spec, v)
    except FrameError as e:
        raise BadInput(f"option --frame: {e}") from None


def frame_suffix(frames) -> str:
    """The frames' part of a file name: empty for S then S' (`both`), else e.g. `_rest`, `_both_u0.3`, `_moving_rest`."""
    words = [f.name if f.name in ("rest", "moving") else "u" + _number(f.velocity) for f in frames]
    name = "_".join(words).replace("rest_moving", "both")  # each frame appears once, so at most one `both`
    return "" if name == "both" else f"_{name}"


def output_name(stem: str, scenario, v: float | None, L: float | None, frames, style: str, extras: dict) -> str:
    """The file name (without extension) of a figure: the scenario's name, then every non-default choice.

    `fig2` for the defaults; `fig2_v0.8`, `fig2_v0.8_L2`, `fig2_rest`, `fig2_print`, `fig2_grid`, ...
    otherwise, so a figure with other options never overwrites the default one, and the same figure
    asked for in other words (`--frame rest,moving`, `--v` equal to the scenario's) gets the same name.
    """
    name = stem
    if v is not None and v != scenario.v:
        name += f"_v{_number(v)}"
    if L is not None and L != scenario.L:
        name += f"_L{_number(L)}"
    name += frame_suffix(frames)
    if style != "default":
        name += f"_{style}"
    name += "".join(f"_{short}" for key, short in _EXTRAS if extras[key])
    return name


class _Job(NamedTuple):
    """One scenario to draw: the name the user gave, the scenario with --v and --L, its panels and files."""

    name: str
    scenario: object
    frames: tuple
    paths: dict  # format -> path


def _formats(spec: str) -> list[str]:
    """--format: one or more formats, comma-separated; an empty item (`svg,`, ``) is refused, as --frame's are."""
    formats = [part.strip().lower() for part in spec.split(",")]
    bad = [f for f in formats if f not in FORMATS]
    if bad:
        raise BadInput(f"option --format must be one or more of {', '.join(FORMATS)}, comma-separated, "
                       f"got {spec!r}.")
    return list(dict.fromkeys(formats))


@click.command()
@click.argument("scenarios", nargs=-1, required=True, metavar="SCENARIO...")
@v_option
@L_option
@click.option("--frame", "frame", default="both", show_default=True, metavar="rest|moving|both|U",
              help="Panels, left to right: S, S', both, or the frame of velocity U relative to S; "
                   "a comma-separated list gives several (e.g. both,0.3).")
@click.option("--format", "fmt", default=None, metavar="svg,pdf,png",
              help="One or more formats, comma-separated. [default: svg, or the extension of -o FILE]")
@click.option("-o", "--output", "output", metavar="PATH_OR_DIR", default=None,
              help=f"A folder to write into (it must exist), or a file name for one scenario in one format. "
                   f"[default: {DEFAULT_FOLDER}/, created if missing]")
@click.option("--style", "style", type=click.Choice(STYLE_NAMES), default="default", show_default=True,
              help="default: colour, colour-blind safe; print: black and white, serif; slides: large type.")
@click.option("--other-axes", is_flag=True, help="Draw the other frame's x and t axes, tilted, on each panel.")
@click.option("--light-cones", is_flag=True, help="Draw the light cone of every impact.")
@click.option("--hyperbolae", is_flag=True, help="Draw calibration hyperbolae t^2 - x^2 = +-k^2 about the origin.")
@click.option("--grid", is_flag=True, help="Draw a grid at the ticks.")
@quiet_option
@click.option("--verbose", is_flag=True, hidden=True, help="Accepted and ignored: every path is printed anyway.")
@reports_errors
def plot(scenarios: tuple[str, ...], v: float | None, L: float | None, frame: str, fmt: str | None,
         output: str | None, style: str, other_axes: bool, light_cones: bool, hyperbolae: bool, grid: bool,
         quiet: bool, verbose: bool) -> None:
    """Draw Minkowski diagrams of each SCENARIO: both frames side by side (the paper's Figs. 1 and 2).

    Writes OUTPUT/NAME.FORMAT, NAME being the scenario's name followed by every
    non-default option (fig2.svg, fig2_v0.8.svg, fig2_rest_print.pdf, ...), and
    prints the path of each file, `PATH (unchanged)` for one whose bytes would
    not change and which is left alone. SCENARIO is a file if one of that name
    exists, else a built-in name.

    Example: sears-paradox plot fig2 --v 0.6
    """
    from rodparadox.output import check_target
    from rodparadox.scenario import stem_of

    extras = {"other_axes": other_axes, "light_cones": light_cones, "hyperbolae": hyperbolae, "grid": grid}
    folder, file = _destination(checked_output(output), len(set(scenarios)))
    if file is not None and fmt is None:
        fmt = file.suffix.lstrip(".").lower()
        if fmt not in FORMATS:
            raise BadInput(f"option -o: cannot tell the format of {str(file)!r} from its extension; "
                           f"name it .{', .'.join(FORMATS)} or give --format.")
    formats = _formats("svg" if fmt is None else fmt)
    if file is not None:
        if len(formats) > 1:
            raise BadInput(f"option -o names one file, {str(file)!r}, but --format asks for {len(formats)} formats; "
                           f"give a folder instead.")
        if file.suffix.lstrip(".").lower() != formats[0]:
            raise BadInput(f"option -o names {str(file)!r} but --format is {formats[0]}; make them agree.")

    jobs: list[_Job] = []
    for name in scenarios:
        base = load_scenario(name, None, None)
        s = base.with_overrides(v=v, L=L)
        frames = parse_frames(frame, s.v)
        stem = output_name(stem_of(name), base, v, L, frames, style, extras)
        job = _Job(name, s, frames, {f: file if file is not None else folder / f"{stem}.{f}" for f in formats})
        if any(job[1:] == other[1:] for other in jobs):  # the same figure to the same files (`plot fig2 fig2`): once
            continue
        for other in jobs:
            clash = next((path for path in job.paths.values() if path in other.paths.values()), None)
            if clash is not None:
                raise BadInput(f"{other.name} and {name} would both be written to {clash}; rename one of the files.")
        jobs.append(job)
    histories = [run_scenario(job.scenario, job.name) for job in jobs]

    if folder is not None and output is None:
        try:
            os.makedirs(folder, exist_ok=True)
        except OSError as e:
            raise BadInput(f"cannot create the output folder {folder}: {(e.strerror or str(e)).lower()}.") from None
    for job in jobs:  # before drawing anything: a missing folder, a dangling link, a locked folder (root passes)
        for path in job.paths.values():
            check_target(path)

    from rodparadox import render  # matplotlib: only now, after every input has been checked
    from rodparadox.output import write_atomic

    options = render.Options(**extras)
    # every figure laid out before any file is written: one that cannot be drawn leaves no file behind
    figures = [render.draw(history, job.frames, style, options) for history, job in zip(histories, jobs)]
    for figure, job in zip(figures, jobs):
        for f, path in job.paths.items():
            written = write_atomic(path, render.figure_bytes(figure, f, style))
            if not quiet:
                emit(str(path) if written else f"{path} (unchanged)")


def _destination(output: str | None, count: int) -> tuple[Path | None, Path | None]:
    """(folder, None) or (None, file) for -o; a file only for one scenario. Says what is wrong in one sentence."""
    if output is None:
        return Path(DEFAULT_FOLDER), None
    path = Path(output)
    if path.is_dir():
        return path, None
    looks_like_file = path.suffix.lstrip(".").lower() in FORMATS and not output.endswith(("/", os.sep))
    if not looks_like_file:
        if path.exists():
            raise BadInput(f"option -o: {output} is a file, not a folder; give a folder or a name ending in "
                           f".{', .'.join(FORMATS)}.")
        if path.is_symlink():
            raise BadInput(f"the output folder {output} is a symbolic link to {os.readlink(path)}, which does not "
                           f"exist; create it first.")
        raise BadInput(f"the output folder {output} does not exist; create it first.")
    if count > 1:
        raise BadInput(f"option -o names one file, {output!r}, but {count} scenarios were given; give a folder instead.")
    from rodparadox.output import check_target

    check_target(path)  # the folder exists and is one, a symbolic link leads somewhere
    return None, path
