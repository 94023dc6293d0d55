"""Which files a command writes, and under what names (docs/plot.md, "Drawing the figures": file names). Pure.

One planner for every command that writes files (`plot`, `ledger`'s figures, `animate`, `handout`), driven
by the command's own description of its outputs (`Outputs`: its formats, which of them fill a folder, the
kind in its file names ...). Every name follows one rule: OUTPUT/NAME.FORMAT, NAME the scenario's name, then
the kind (`_ledger`, `_now`, `_handout`; none for `plot`), then every option that is not the default, in a
fixed order: `_v0.8`, `_L2`, the frames (`_rest`, `_u0.3`, ...), the style, the extras. No matplotlib here:
the CLI plans and checks every job before anything is drawn.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, NamedTuple, Sequence

from rodparadox.errors import FrameError, OptionError
from rodparadox.physics.frames import Frame, frame_word, parse_frames
from rodparadox.physics.model import Scenario
from rodparadox.physics.rod_view import ROD_VIEW, ROD_WORD
from rodparadox.numbers import exact
from rodparadox.io.output import check_folder, check_target, is_stream
from rodparadox.io.scenario import load, stem_of

from . import words
from .edge import BadInput
from .options import with_options

#: where outputs go when -o is not given; the only output folder a command creates itself
DEFAULT_FOLDER = "outputs"


def frame_suffix(frames: Sequence[Frame]) -> str:
    """The frames' part of a file name: empty for S then S' (`both`), else e.g. `_rest`, `_both_u0.3`, `_moving_rest`,
    `_rest_rod` (the rod's own view, `RodView`, named by its word)."""
    name = "_".join(frame_word(f) if isinstance(f, Frame) else f.name for f in frames)
    name = name.replace("rest_moving", "both")  # each frame appears once, so at most one `both`
    return "" if name == "both" else f"_{name}"


def output_name(stem: str, scenario: Scenario, v: float | None, L: float | None, frames: Sequence[Frame],
                style: str, extras: Sequence[str] = (), kind: str = "", default_style: str = "default") -> str:
    """The file name (without extension) of an output: the scenario's name, its kind, then every non-default choice.

    `fig2` for the defaults; `fig2_v0.8`, `fig2_v0.8_L2`, `fig2_rest`, `fig2_print`, `fig2_grid`,
    `fig2_ledger_v0.8` ... otherwise, so an output with other options never overwrites the default one, and
    the same output asked for in other words (`--frame rest,moving`, `--v` equal to the scenario's) gets the
    same name. `extras` are the short names of the options that are on, in the command's own order; the style
    is named when it is not the command's default (`default_style`).
    """
    name = stem + (f"_{kind}" if kind else "")
    if v is not None and v != scenario.v:
        name += f"_v{exact(v)}"
    if L is not None and L != scenario.L:
        name += f"_L{exact(L)}"
    name += frame_suffix(frames)
    if style != default_style:
        name += f"_{style}"
    return name + "".join(f"_{short}" for short in extras)


def frames_of(spec: str, v: float) -> tuple[Frame, ...]:
    """--frame, parsed by `frames.parse_frames`, its error named as the option's."""
    try:
        return parse_frames(spec, v)
    except FrameError as e:
        raise words.frame_error(e, "frame", spec) from None


def frames_with_rod(spec: str, v: float) -> tuple:
    """--frame of the commands that draw the rod's own view too (`plot`, `animate`, `handout`): the word `rod`
    (`rod_view.ROD_VIEW`, once, where it first appears in the list) beside the frames `frames_of` reads."""
    items = [item.strip() for item in spec.split(",")]
    try:
        if ROD_WORD not in items:
            return parse_frames(spec, v)
        at = items.index(ROD_WORD)
        others = [item for item in items if item != ROD_WORD]
        frames = parse_frames(",".join(others), v) if others else ()
        before = len(parse_frames(",".join(items[:at]), v)) if at else 0
    except FrameError as e:  # the library's sentence, with the word it does not know of
        said = str(e).replace("rest, moving, both or", f"rest, moving, both, {ROD_WORD} (the rod's own view) or")
        raise words.frame_error(FrameError(said), "frame", spec) from None
    check_panels(len(frames), True, False)
    return (*frames[:before], ROD_VIEW, *frames[before:])


def check_panels(frames: int, rod_view: bool, both: bool) -> None:
    """At most MAX_PANELS panels in one figure, the rod's own view counted, each frame twice with --rod both."""
    from rodparadox.physics.frames import MAX_PANELS

    panels = frames * (2 if both else 1) + rod_view
    if panels > MAX_PANELS:
        said = f"{frames} frames" + (" for each of the two rods" if both else "") + (" and the rod's own view"
                                                                                      if rod_view else "")
        raise BadInput(f"--frame asks for {panels} panels ({said}); at most {MAX_PANELS} fit in one figure, so give "
                       f"fewer frames.")


def lorentz_frames(frames: Sequence) -> tuple[Frame, ...]:
    """The Lorentz frames of a list that may name the rod's own view (`frames_with_rod`)."""
    return tuple(f for f in frames if isinstance(f, Frame))


def refuse_rod_view(spec: str, command: str) -> None:
    """A command whose tables need Lorentz frames (`ledger`) refuses `--frame rod` in one sentence."""
    if ROD_WORD in (item.strip() for item in spec.split(",")):
        raise BadInput(f"--frame rod (the rod's own view) is drawn by plot, animate and handout only; {command} "
                       f"reads slices of Lorentz frames: give rest, moving, both or a velocity U.")


# --- what a command writes ---------------------------------------------------------------------------

@dataclass(frozen=True)
class Outputs:
    """What a command writes, as the planner reads it.

    `formats` in the order messages list them, `default` the format when neither --format nor -o says one;
    `kind` the word after the scenario's name (`ledger`, `now`, `handout`; none for `plot`). `folders` names
    the formats written as a folder of files, each with what the folder holds (`png`: "the stills"); a
    command with one reads the format before -o, since the format says whether -o names a file or a folder
    (`check`: the command's own rules on the two); -o names that folder, whether or not it exists yet. Without
    folder formats -o is read first and --format may list several formats, one file each. `together`: every
    scenario in one output (a handout's sections), else one output each. `frames` reads --frame for a scenario's
    v; `default_style` is the style not named.
    """

    formats: tuple[str, ...]
    default: str
    kind: str = ""
    folders: dict[str, str] = field(default_factory=dict)
    check: Callable[[str | None, str, str], None] | None = None
    together: bool = False
    frames: Callable[[str, float], tuple[Frame, ...]] = frames_of
    default_style: str = "default"


class Job(NamedTuple):
    """One output: its scenarios (one; a handout's several) as the user named them and with --v and --L, the
    frames of each, its name, and its files (format -> path: a file, or the folder a folder format fills)."""

    names: tuple[str, ...]
    scenarios: tuple[Scenario, ...]
    frames: tuple[tuple[Frame, ...], ...]
    stem: str
    paths: dict  # format -> Path

    @property
    def name(self) -> str:
        return self.names[0]

    @property
    def scenario(self) -> Scenario:
        return self.scenarios[0]

    @property
    def stems(self) -> tuple[str, ...]:
        """Each scenario's own name for file names (`stem_of`)."""
        return tuple(stem_of(name) for name in self.names)

    @property
    def fmt(self) -> str:
        """The format of a job that writes one (animate, handout)."""
        return next(iter(self.paths))

    @property
    def path(self) -> Path:
        """The file or folder of a job that writes one (animate, handout)."""
        return next(iter(self.paths.values()))


def plan(names: Sequence[str], outputs: Outputs, *, v: float | None, L: float | None, frame: str, fmt: str | None,
         output: str | None, style: str, extras: Sequence[str] = ()) -> list[Job]:
    """Every output a command will write, its files named, every input checked, nothing drawn or written yet.

    The same output asked for twice (`plot fig2 fig2`) is written once; two scenarios that would write one
    file are refused.
    """
    if output is not None and not output.strip():
        raise words.empty_output(output)
    count = 1 if outputs.together else len(set(names))
    if outputs.folders:  # the format says whether -o names a file or a folder: read it first
        formats, place = [_one_format(outputs, fmt, output)], None
    else:  # -o says whether it names a file; the format from --format, else from the file's extension
        place = destination(output, count, outputs.formats)
        formats = formats_of(fmt, place[1], outputs.formats, outputs.default)
    jobs: list[Job] = []
    for names_, bases, scenarios, frames in _read(names, outputs, v=v, L=L, frame=frame):
        stem = output_name("_".join(stem_of(name) for name in names_), bases[0], v, L, frames[0], style, extras,
                           outputs.kind, outputs.default_style)
        paths = {f: _path(outputs, f, stem, output, place, count) for f in formats}
        job = Job(names_, scenarios, frames, stem, paths)
        if any(job[1:] == other[1:] for other in jobs):
            continue
        for other in jobs:
            clash = next((path for path in job.paths.values() if path in other.paths.values()), None)
            if clash is not None:
                raise BadInput(f"{other.name} and {job.name} would both be written to {clash}; rename one of the "
                               f"files.")
        jobs.append(job)
    return jobs


def _read(names: Sequence[str], outputs: Outputs, *, v, L, frame: str):
    """(names, their scenarios as read, with --v and --L, their frames) of each output, one at a time (a later
    scenario is read after an earlier one is planned). Together (a handout), a scenario given twice is refused
    (a section twice over is a slip for another scenario), and every file is read before any option is
    applied."""
    if not outputs.together:
        for name in names:
            base = load(name)
            s = with_options(base, v, L)
            yield (name,), (base,), (s,), (tuple(outputs.frames(frame, s.v)),)
        return
    twice = next((name for k, name in enumerate(names) if name in names[:k]), None)
    if twice is not None:
        raise BadInput(f"{twice} is given twice; a {outputs.kind or 'page'} has one section per scenario, so give each "
                       f"once.")
    bases = tuple(load(name) for name in names)
    scenarios = tuple(with_options(base, v, L) for base in bases)
    frames = tuple(tuple(outputs.frames(frame, s.v)) for s in scenarios)
    stems = [stem_of(name) for name in names]
    if len(set(stems)) < len(stems):
        same = next(s for s in stems if stems.count(s) > 1)
        raise BadInput(f"two scenarios are both named {same}; rename one of the files.")
    yield names, bases, scenarios, frames


def _one_format(outputs: Outputs, fmt: str | None, output: str | None) -> str:
    """--format, else the extension of -o if it names a file format, else the default; checked against -o."""
    suffix = Path(output).suffix.lstrip(".").lower() if output is not None else ""
    if fmt is None:
        files = [f for f in outputs.formats if f not in outputs.folders]
        fmt = suffix if suffix in files else outputs.default
    fmt = fmt.strip().lower()
    if fmt not in outputs.formats:
        raise words.format_not_one_of(fmt, outputs.formats)
    if outputs.check is not None and output is not None:
        outputs.check(output, fmt, suffix)
    return fmt


def _path(outputs: Outputs, fmt: str, stem: str, output: str | None, place, count: int) -> Path:
    """The file (or folder) an output of `fmt` named `stem` goes to."""
    if place is None and fmt in outputs.folders:
        if output is None:
            return Path(DEFAULT_FOLDER) / stem
        return Path(output)  # the folder itself, every time: not a folder inside it once it exists
    folder, file = place if place is not None else destination(output, count, (fmt,))
    return file if file is not None else folder / f"{stem}.{fmt}"


def formats_of(spec: str | None, file: Path | None, allowed: Sequence[str], default: str) -> list[str]:
    """--format: one or more of `allowed`, comma-separated (an empty item is refused), or the extension of -o FILE."""
    if file is not None and spec is None:
        spec = file.suffix.lstrip(".").lower()
        if spec not in allowed:
            raise words.unknown_extension(str(file), f".{', .'.join(allowed)}")
    spec = default if spec is None else spec
    formats = [part.strip().lower() for part in spec.split(",")]
    if any(f not in allowed for f in formats):
        raise OptionError("format", spec, f"one or more of {', '.join(allowed)}, comma-separated")
    formats = list(dict.fromkeys(formats))
    if file is not None:
        if len(formats) > 1:
            raise OptionError("output", str(file), template="{what} names one file, {value!r}, but {format} asks for "
                                                            "{count} formats; give a folder instead.",
                              count=len(formats))
        if file.suffix.lstrip(".").lower() != formats[0] and not is_stream(file):
            raise words.output_disagrees(str(file), formats[0])
    return formats


def destination(output: str | None, count: int, allowed: Sequence[str]) -> tuple[Path | None, Path | None]:
    """(folder, None) or (None, file) for -o; a file only for one output. Says what is wrong in one sentence."""
    if output is None:
        return Path(DEFAULT_FOLDER), None
    if not output.strip():
        raise words.empty_output(output)
    path = Path(output)
    if path.is_dir():
        return path, None
    looks_like_file = (path.suffix.lstrip(".").lower() in allowed and not output.endswith(("/", os.sep))
                       or is_stream(path))  # /dev/stdout, a FIFO: one file, its format from --format
    if not looks_like_file:
        if path.exists():
            raise OptionError("output", output, tuple(allowed), "{what}: {value} is a file, not a folder; give a "
                                                                "folder or a name ending in .{extensions}.",
                              extensions=", .".join(allowed))
        if path.is_symlink():
            raise BadInput(f"the output folder {output} is a symbolic link to {os.readlink(path)}, which does "
                           f"not exist; create it first.")
        raise BadInput(f"the output folder {output} does not exist; create it first.")
    if count > 1:
        raise OptionError("output", output, template="{what} names one file, {value!r}, but {count} scenarios were "
                                                     "given; give a folder instead.", count=count)
    check_target(path)  # the folder exists and is one, a symbolic link leads somewhere
    return None, path


def prepare(jobs: Sequence[Job], outputs: Outputs, output: str | None) -> None:
    """Before anything is drawn: create the default folder (only it), and check every file or folder can be written."""
    if output is None:
        try:
            os.makedirs(DEFAULT_FOLDER, exist_ok=True)
        except OSError as e:
            raise BadInput(f"cannot create the output folder {DEFAULT_FOLDER}: "
                           f"{(e.strerror or str(e)).lower()}.") from None
    for job in jobs:  # a missing folder, a dangling link, a locked folder (root passes)
        for fmt, path in job.paths.items():
            if fmt in outputs.folders:
                check_folder(path, outputs.folders[fmt])
            else:
                check_target(path)
