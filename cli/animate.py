"""`sears-paradox animate`: the paradox in motion, as a GIF, an MP4 or numbered PNG stills.

Thin: parse the options, plan and check through `sears_paradox_cli.planning`, `rodparadox.animate.timeline` and
`rodparadox.animate.encoders`, then draw (matplotlib only from here on) and stream the images to the file.
"""

from __future__ import annotations

import itertools
import sys
from pathlib import Path

import click

from rodparadox.errors import OptionError

from . import words
from .edge import before_matplotlib, report, reports_errors
from .options import (NUMBER, Whole, format_option, frame_option, output_option, quiet_option, rod_asked, run_scenario,
                      scenario_options, style_option)

#: the defaults: 6 seconds at 25 frames per second, a rate a GIF stores exactly (4 hundredths of a second)
DEFAULT_FPS = 25
DEFAULT_SECONDS = 6.0
#: what `animate` writes: a GIF or MP4 file, or a folder of numbered PNG stills
ANIMATION_FORMATS = ("gif", "mp4", "png")


@click.command()
@scenario_options(rods=("rigid", "causal"))
@frame_option("now: the panels, as plot's --frame (e.g. both,0.3, or rest,rod: the rod's own view too); boost: "
              "the frames to boost between, A..B, each rest, moving or a velocity U (both is rest..moving).",
              metavar="rest|moving|both|U|rod|A..B")
@click.option("--mode", "mode", type=click.Choice(("now", "boost")), default="now", show_default=True,
              help="now: each frame's line of simultaneity sweeps up, with its space below; boost: the frame "
                   "velocity runs smoothly from A to B.")
@format_option("gif, mp4 (needs ffmpeg) or png (numbered stills in a folder). [default: the extension of -o, "
               "else gif]", default=None, metavar="gif|mp4|png")
@click.option("--fps", "fps", type=Whole(), default=DEFAULT_FPS, show_default=True, metavar="N",
              help="Frames per second; for a GIF one of 1, 2, 4, 5, 10, 20, 25, 50 (it stores hundredths of a "
                   "second).")
@click.option("--seconds", "seconds", type=NUMBER, default=DEFAULT_SECONDS, show_default=True, metavar="S",
              help="The animation's length, above 0 and at most 120 seconds: round(S * N) frames.")
@click.option("--allow-long", "allow_long", is_flag=True,
              help="Draw an animation of more than 400 million pixels in all (frames x width x height: about 350 "
                   "frames of the default size), which is refused otherwise: it takes minutes.")
@output_option("gif, mp4: a folder (it must exist) or a file name; png: the folder of the stills. "
               "[default: outputs/, created if missing]")
@style_option()
@quiet_option
@reports_errors
def animate(scenario: str, v: float | None, L: float | None, frame: str, mode: str, fmt: str | None, fps: int,
            seconds: float, allow_long: bool, output: str | None, style: str, quiet: bool) -> None:
    """Animate SCENARIO: both frames' "now" sweeping in lock-step, or a continuous boost, as GIF, MP4 or stills.

    Writes OUTPUT/NAME.gif (or .mp4, or the folder OUTPUT/NAME/ of NAME_0000.png
    ...), NAME being the scenario's name, the mode (_now, _boost), then every
    non-default option as plot names them (fig2_now.gif, fig2_boost_v0.8.mp4),
    and prints its path, `PATH (unchanged)` when the bytes would not change.
    The same command gives the same bytes.

    Example: sears-paradox animate fig2 --fps 10 --seconds 2
    """
    from sears_paradox_cli import planning as planned
    from rodparadox.animate.timeline import boost_ends, check_cost, image_count, timeline
    from rodparadox.animate.encoders import check_fps, check_stills, require_ffmpeg

    described = planned.Outputs(formats=ANIMATION_FORMATS, default="gif", kind=mode, folders={"png": "the stills"},
                                check=_check_output, frames=planned.frames_with_rod if mode == "now" else boost_ends)
    [job] = planned.plan([scenario], described, v=v, L=L, frame=frame, fmt=fmt, output=output, style=style,
                         extras=(["causal"] if rod_asked() == "causal" else []) + list(length_names(fps, seconds)))
    check_fps(job.fmt, fps)
    count = image_count(seconds, fps)
    if job.fmt == "mp4":
        require_ffmpeg()
    frames = planned.lorentz_frames(job.frames[0]) if mode == "now" else job.frames[0]
    rod_view = None if frames == job.frames[0] else ("first" if job.frames[0][0] not in frames else "last")
    history = run_scenario(job.scenario, job.name, frames)
    if rod_view is not None:
        from rodparadox.physics.rod_view import refuse_thin_view

        refuse_thin_view(history)
    planned.prepare([job], described, output)
    if job.fmt == "png":
        check_stills(job.path, job.stem, count)  # a clash with any still is said before the first is drawn
    line = timeline(history, frames, mode, count)

    before_matplotlib()
    from rodparadox.animate.scenes import images_of  # matplotlib: only now, after every input has been checked
    from rodparadox.animate.encoders import write_images

    drawn = images_of(history, frames, mode, style, line, rod_view)
    try:
        first = next(drawn)  # the scene laid out and its first image drawn: the size is known, nothing is written yet
        check_cost(count, first.shape[1], first.shape[0], seconds, fps, allow_long)
        with progress(itertools.chain([first], drawn), count, str(job.path), quiet) as bar:
            written = write_images(job.path, job.fmt, fps, bar, name=job.stem)
    finally:
        drawn.close()  # a refused or failed run leaves no scene waiting for the collector
    report([(f"{job.path}/" if job.fmt == "png" else job.path, written)], quiet)


def length_names(fps: int, seconds: float) -> list[str]:
    """The rate and length in the file name when they are not the defaults (`fps10`, `seconds3`), named as plot
    names its options, so that runs of other lengths never overwrite each other."""
    from rodparadox.numbers import exact

    return ([f"fps{fps}"] if fps != DEFAULT_FPS else []) + \
        ([f"seconds{exact(float(seconds))}"] if seconds != DEFAULT_SECONDS else [])


def progress(images, count: int, label: str, quiet: bool, stream=None):
    """The progress bar over the images, on standard error when it is a terminal and -q is not given (never
    otherwise): the frames drawn of all, the percentage, and the time left as soon as it can be estimated
    (click measures it after the first second)."""
    stream = sys.stderr if stream is None else stream
    holder = []

    def time_left(_image):
        bar = holder[0] if holder else None
        if bar is None or bar.finished:
            return None
        return f"{bar.format_eta()} left" if bar.eta_known else "estimating the time left"

    bar = click.progressbar(images, length=count, label=label, file=stream, hidden=quiet or not _is_terminal(stream),
                            show_eta=False, show_pos=True, show_percent=True, item_show_func=time_left)
    holder.append(bar)
    return bar


def _check_output(output: str, fmt: str, suffix: str) -> None:
    """-o against the format: a file's extension must agree with it, and png stills go into a folder (an
    existing folder named so is that folder)."""
    if Path(output).is_dir():
        return
    if suffix in ANIMATION_FORMATS and suffix != fmt:
        raise words.output_disagrees(output, fmt)
    if fmt == "png" and suffix == "png":
        raise OptionError("output", output, template="{what}: png writes numbered stills into a folder; name the "
                                                     "folder, not {value!r}.")


def _is_terminal(stream) -> bool:
    try:
        return stream.isatty()
    except (AttributeError, ValueError):
        return False
