"""Which files a drawing command writes, and under what names (README, "Drawing the figures": file names). Pure.

Shared by `plot`, `ledger` and every later drawing command, so their names
follow one rule: OUTPUT/NAME.FORMAT, NAME the scenario's name, then the kind
of figure (`_ledger`; none for `plot`), then every option that is not the
default, in a fixed order: `_v0.8`, `_L2`, the frames (`_rest`, `_u0.3`, ...),
the style, the extras. No matplotlib here: the CLI plans and checks every
job before anything is drawn.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import NamedTuple, Sequence

from rodparadox.errors import FrameError, OptionError
from rodparadox.physics.frames import Frame, frame_word, parse_frames
from rodparadox.physics.model import Scenario
from rodparadox.numbers import exact
from rodparadox.io.output import check_target
from rodparadox.io.scenario import load, stem_of

#: where figures go when -o is not given; the only output folder a command creates itself
DEFAULT_FOLDER = "outputs"


def frame_suffix(frames: Sequence[Frame]) -> str:
    """The frames' part of a file name: empty for S then S' (`both`), else e.g. `_rest`, `_both_u0.3`, `_moving_rest`."""
    words = [frame_word(f) for f in frames]
    name = "_".join(words).replace("rest_moving", "both")  # each frame appears once, so at most one `both`
    return "" if name == "both" else f"_{name}"


def output_name(stem: str, scenario: Scenario, v: float | None, L: float | None, frames: Sequence[Frame],
                style: str, extras: Sequence[str] = (), kind: str = "") -> str:
    """The file name (without extension) of a figure: the scenario's name, its kind, then every non-default choice.

    `fig2` for the defaults; `fig2_v0.8`, `fig2_v0.8_L2`, `fig2_rest`, `fig2_print`, `fig2_grid`,
    `fig2_ledger_v0.8` ... otherwise, so a figure with other options never overwrites the default one, and
    the same figure asked for in other words (`--frame rest,moving`, `--v` equal to the scenario's) gets the
    same name. `extras` are the short names of the options that are on, in the command's own order.
    """
    name = stem + (f"_{kind}" if kind else "")
    if v is not None and v != scenario.v:
        name += f"_v{exact(v)}"
    if L is not None and L != scenario.L:
        name += f"_L{exact(L)}"
    name += frame_suffix(frames)
    if style != "default":
        name += f"_{style}"
    return name + "".join(f"_{short}" for short in extras)


def formats_of(spec: str | None, file: Path | None, allowed: Sequence[str], default: str) -> list[str]:
    """--format: one or more of `allowed`, comma-separated (an empty item is refused), or the extension of -o FILE."""
    if file is not None and spec is None:
        spec = file.suffix.lstrip(".").lower()
        if spec not in allowed:
            raise OptionError(f"option -o: cannot tell the format of {str(file)!r} from its extension; "
                              f"name it .{', .'.join(allowed)} or give --format.")
    spec = default if spec is None else spec
    formats = [part.strip().lower() for part in spec.split(",")]
    if any(f not in allowed for f in formats):
        raise OptionError(f"option --format must be one or more of {', '.join(allowed)}, comma-separated, "
                          f"got {spec!r}.")
    formats = list(dict.fromkeys(formats))
    if file is not None:
        if len(formats) > 1:
            raise OptionError(f"option -o names one file, {str(file)!r}, but --format asks for {len(formats)} "
                              f"formats; give a folder instead.")
        if file.suffix.lstrip(".").lower() != formats[0]:
            raise OptionError(f"option -o names {str(file)!r} but --format is {formats[0]}; make them agree.")
    return formats


def destination(output: str | None, count: int, allowed: Sequence[str]) -> tuple[Path | None, Path | None]:
    """(folder, None) or (None, file) for -o; a file only for one scenario. Says what is wrong in one sentence."""
    if output is None:
        return Path(DEFAULT_FOLDER), None
    if not output.strip():
        raise OptionError(f"option -o must name a file or folder, got {output!r}.")
    path = Path(output)
    if path.is_dir():
        return path, None
    looks_like_file = path.suffix.lstrip(".").lower() in allowed and not output.endswith(("/", os.sep))
    if not looks_like_file:
        if path.exists():
            raise OptionError(f"option -o: {output} is a file, not a folder; give a folder or a name ending in "
                              f".{', .'.join(allowed)}.")
        if path.is_symlink():
            raise OptionError(f"the output folder {output} is a symbolic link to {os.readlink(path)}, which does "
                              f"not exist; create it first.")
        raise OptionError(f"the output folder {output} does not exist; create it first.")
    if count > 1:
        raise OptionError(f"option -o names one file, {output!r}, but {count} scenarios were given; give a folder "
                          f"instead.")
    check_target(path)  # the folder exists and is one, a symbolic link leads somewhere
    return None, path


def named(name: str, *, v: float | None, L: float | None, frames, style: str, extras: Sequence[str] = (),
          kind: str = "") -> tuple[Scenario, tuple[Frame, ...], str]:
    """What every drawing command does first: the scenario `name` with --v and --L, its frames (`frames(v)`, the
    command's own reading of --frame, which names its errors), and the file name it writes (`output_name`)."""
    base = load(name)
    s = base.with_overrides(v=v, L=L)
    chosen = tuple(frames(s.v))
    return s, chosen, output_name(stem_of(name), base, v, L, chosen, style, extras, kind)


class Job(NamedTuple):
    """One figure to draw: the name the user gave, the scenario with --v and --L, its frames and its files."""

    name: str
    scenario: Scenario
    frames: tuple[Frame, ...]
    paths: dict  # format -> Path


def plan(names: Sequence[str], *, v: float | None, L: float | None, frame: str, fmt: str | None,
         output: str | None, style: str, extras: Sequence[str] = (), kind: str = "",
         allowed: Sequence[str], default_format: str) -> list[Job]:
    """Every figure a command will write, its files named, every input checked, nothing drawn or written yet.

    The same figure asked for twice (`plot fig2 fig2`) is drawn once; two scenarios that would write one
    file are refused.
    """
    folder, file = destination(output, len(set(names)), allowed)
    formats = formats_of(fmt, file, allowed, default_format)
    jobs: list[Job] = []
    for name in names:
        s, frames, stem = named(name, v=v, L=L, frames=lambda v_: frames_of(frame, v_), style=style, extras=extras,
                                kind=kind)
        job = Job(name, s, frames, {f: file if file is not None else folder / f"{stem}.{f}" for f in formats})
        if any(job[1:] == other[1:] for other in jobs):
            continue
        for other in jobs:
            clash = next((path for path in job.paths.values() if path in other.paths.values()), None)
            if clash is not None:
                raise OptionError(f"{other.name} and {name} would both be written to {clash}; rename one of the "
                                  f"files.")
        jobs.append(job)
    return jobs


def _make_default_folder() -> None:
    """The default output folder, the only one a command creates itself."""
    try:
        os.makedirs(DEFAULT_FOLDER, exist_ok=True)
    except OSError as e:
        raise OptionError(f"cannot create the output folder {DEFAULT_FOLDER}: {(e.strerror or str(e)).lower()}.") from None


def frames_of(spec: str, v: float) -> tuple[Frame, ...]:
    """--frame, parsed by `frames.parse_frames`, its error named as the option's."""
    try:
        return parse_frames(spec, v)
    except FrameError as e:
        raise OptionError(f"option --frame: {e}") from None


def prepare(jobs: Sequence[Job], output: str | None) -> None:
    """Before anything is drawn: create the default folder (only it), and check every file can be written."""
    if output is None:
        _make_default_folder()
    for job in jobs:  # a missing folder, a dangling link, a locked folder (root passes)
        for path in job.paths.values():
            check_target(path)


# --- animations (`sears-paradox animate`) -----------------------------------------------------------

#: what `animate` writes: a GIF or MP4 file, or a folder of numbered PNG stills
ANIMATION_FORMATS = ("gif", "mp4", "png")


class AnimationJob(NamedTuple):
    """One animation: the scenario with --v and --L, its frames (now: the panels; boost: the two ends), its
    format, and where it goes: the file (gif, mp4) or the folder of stills (png), whose stills are STEM_0000.png."""

    name: str
    scenario: Scenario
    frames: tuple[Frame, ...]
    fmt: str
    path: Path
    stem: str


def plan_animation(name: str, *, v: float | None, L: float | None, frame: str, mode: str, fmt: str | None,
                   output: str | None, style: str) -> AnimationJob:
    """The animation `animate` will write, named as `plot` names figures with the mode as the kind
    (`fig2_now.gif`, `fig2_boost_v0.8.mp4`, the folder `fig2_now/` of `fig2_now_0000.png` ...), every input
    checked, nothing drawn or written yet.

    The format is --format, else the extension of -o (.gif, .mp4), else gif. For gif and mp4, -o is a folder
    that exists or a file name; for png it names the folder of the stills (created if missing, in a folder
    that exists); without -o, everything goes in `outputs/`.
    """
    from rodparadox.animate.timeline import MODES, boost_ends

    if output is not None and not output.strip():
        raise OptionError(f"option -o must name a file or folder, got {output!r}.")
    if mode not in MODES:
        raise OptionError(f"option --mode must be one of {', '.join(MODES)}, got {mode!r}.")
    suffix = Path(output).suffix.lstrip(".").lower() if output is not None else ""
    if fmt is None:
        fmt = suffix if suffix in ("gif", "mp4") else "gif"
    fmt = fmt.strip().lower()
    if fmt not in ANIMATION_FORMATS:
        raise OptionError(f"option --format must be one of {', '.join(ANIMATION_FORMATS)}, got {fmt!r}.")
    if suffix in ANIMATION_FORMATS and suffix != fmt and not Path(output).is_dir():
        raise OptionError(f"option -o names {output!r} but --format is {fmt}; make them agree.")
    if fmt == "png" and suffix == "png" and not Path(output).is_dir():
        raise OptionError(f"option -o: png writes numbered stills into a folder; name the folder, not "
                          f"{output!r}.")
    s, frames, stem = named(name, v=v, L=L, style=style, kind=mode,
                            frames=lambda v_: frames_of(frame, v_) if mode == "now" else boost_ends(frame, v_))
    if fmt == "png":
        path = Path(output) if output is not None else Path(DEFAULT_FOLDER) / stem
    else:
        folder, file = destination(output, 1, (fmt,))
        path = file if file is not None else folder / f"{stem}.{fmt}"
    return AnimationJob(name, s, frames, fmt, path, stem)


def prepare_animation(job: AnimationJob, output: str | None) -> None:
    """Before anything is drawn: create the default folder (only it), check the file or the stills' folder."""
    from rodparadox.animate.encoders import check_folder

    if output is None:
        _make_default_folder()
    if job.fmt == "png":
        check_folder(job.path)
    else:
        check_target(job.path)


# --- handouts (`sears-paradox handout`) -------------------------------------------------------------

#: what `handout` writes: one PDF, or a folder of LaTeX pieces (handout.tex, figures, table fragments, .dat files)
HANDOUT_FORMATS = ("pdf", "tex")
#: handouts are photocopied in black and white
HANDOUT_STYLE = "print"
PAPER_NAMES = ("a4", "letter")
HANDOUT_PAPER = "a4"


class HandoutJob(NamedTuple):
    """One document: every scenario (the names given, each with --v and --L), the frames of each, and where it
    goes: the PDF file, or the folder of the LaTeX pieces."""

    names: tuple[str, ...]
    scenarios: tuple[Scenario, ...]
    frames: tuple[tuple[Frame, ...], ...]
    stems: tuple[str, ...]
    fmt: str
    path: Path


def plan_handout(names: Sequence[str], *, v: float | None, L: float | None, frame: str, fmt: str | None,
                 output: str | None, style: str, paper: str, worksheet: bool) -> HandoutJob:
    """The document `handout` will write, every input checked, nothing computed or written yet.

    Named as `plot` names figures, with the kind `handout` or `worksheet` and the scenarios' names joined
    (`fig2_handout.pdf`, `fig1_fig2_worksheet_v0.8_letter.pdf`); the style is named only if not print, the
    paper only if not A4. pdf: -o is a folder that exists or a file name .pdf; tex: -o names the folder of the
    pieces (created if missing, in a folder that exists); without -o, everything goes in `outputs/`.
    """
    if output is not None and not output.strip():
        raise OptionError(f"option -o must name a file or folder, got {output!r}.")
    if paper not in PAPER_NAMES:
        raise OptionError(f"option --paper must be one of {', '.join(PAPER_NAMES)}, got {paper!r}.")
    suffix = Path(output).suffix.lstrip(".").lower() if output is not None else ""
    if fmt is None:
        fmt = "pdf"
    fmt = fmt.strip().lower()
    if fmt not in HANDOUT_FORMATS:
        raise OptionError(f"option --format must be one of {', '.join(HANDOUT_FORMATS)}, got {fmt!r}.")
    if fmt == "tex" and suffix == "pdf" and not Path(output).is_dir():
        raise OptionError(f"option -o names {output!r} but --format is tex, which writes a folder; name the "
                          f"folder.")
    names = tuple(dict.fromkeys(names))  # a scenario given twice is one section
    bases = [load(name) for name in names]
    scenarios = tuple(base.with_overrides(v=v, L=L) for base in bases)
    frames = tuple(frames_of(frame, s.v) for s in scenarios)
    stems = tuple(stem_of(name) for name in names)
    if len(set(stems)) < len(stems):
        same = next(s for s in stems if stems.count(s) > 1)
        raise OptionError(f"two scenarios are both named {same}; rename one of the files.")
    kind = "worksheet" if worksheet else "handout"
    stem = output_name("_".join(stems), bases[0], v, L, frames[0], "default", (), kind)
    if style != HANDOUT_STYLE:
        stem += f"_{style}"
    if paper != HANDOUT_PAPER:
        stem += f"_{paper}"
    if fmt == "tex":
        path = Path(output) if output is not None and not Path(output).is_dir() else \
            Path(output if output is not None else DEFAULT_FOLDER) / stem
    else:
        folder, file = destination(output, 1, ("pdf",))
        path = file if file is not None else folder / f"{stem}.pdf"
    return HandoutJob(names, scenarios, frames, stems, fmt, path)


def prepare_handout(job: HandoutJob, output: str | None) -> None:
    """Before anything is computed: create the default folder (only it), check the file or the pieces' folder."""
    from rodparadox.io.output import check_folder

    if output is None:
        _make_default_folder()
    if job.fmt == "tex":
        check_folder(job.path, "the LaTeX pieces")
    else:
        check_target(job.path)
