"""`sears-paradox animate`: the paradox in motion, as a GIF, an MP4 or numbered PNG stills.

Thin: parse the options, plan and check through `sears_paradox_cli.planning`, `rodparadox.animate.timeline` and
`rodparadox.animate.encoders`, then draw (matplotlib only from here on) and stream the images to the file.
"""

from __future__ import annotations

import sys
from pathlib import Path

import click

from rodparadox.errors import OptionError

from . import words
from .common import (NUMBER, Whole, before_matplotlib, format_option, frame_option, output_option, quiet_option, report,
                     reports_errors, run_scenario, scenario_options, style_option)

#: the defaults: 6 seconds at 25 frames per second, a rate a GIF stores exactly (4 hundredths of a second)
DEFAULT_FPS = 25
DEFAULT_SECONDS = 6.0
#: what `animate` writes: a GIF or MP4 file, or a folder of numbered PNG stills
ANIMATION_FORMATS = ("gif", "mp4", "png")


@click.command()
@scenario_options()
@frame_option("now: the panels, as plot's --frame (e.g. both,0.3); boost: the frames to boost between, "
              "A..B, each rest, moving or a velocity U (both is rest..moving).", metavar="rest|moving|both|U|A..B")
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
@output_option("gif, mp4: a folder (it must exist) or a file name; png: the folder of the stills. "
               "[default: outputs/, created if missing]")
@style_option()
@quiet_option
@reports_errors
def animate(scenario: str, v: float | None, L: float | None, frame: str, mode: str, fmt: str | None, fps: int,
            seconds: float, output: str | None, style: str, quiet: bool) -> None:
    """Animate SCENARIO: both frames' "now" sweeping in lock-step, or a continuous boost, as GIF, MP4 or stills.

    Writes OUTPUT/NAME.gif (or .mp4, or the folder OUTPUT/NAME/ of NAME_0000.png
    ...), NAME being the scenario's name, the mode (_now, _boost), then every
    non-default option as plot names them (fig2_now.gif, fig2_boost_v0.8.mp4),
    and prints its path, `PATH (unchanged)` when the bytes would not change.
    The same command gives the same bytes.

    Example: sears-paradox animate fig2 --fps 10 --seconds 2
    """
    from sears_paradox_cli import planning as planned
    from rodparadox.animate.timeline import boost_ends, image_count, timeline
    from rodparadox.animate.encoders import check_fps, require_ffmpeg

    described = planned.Outputs(formats=ANIMATION_FORMATS, default="gif", kind=mode, folders={"png": "the stills"},
                                check=_check_output, frames=planned.frames_of if mode == "now" else boost_ends)
    [job] = planned.plan([scenario], described, v=v, L=L, frame=frame, fmt=fmt, output=output, style=style)
    check_fps(job.fmt, fps)
    count = image_count(seconds, fps)
    if job.fmt == "mp4":
        require_ffmpeg()
    history = run_scenario(job.scenario, job.name)
    planned.prepare([job], described, output)
    line = timeline(history, job.frames[0], mode, count)

    before_matplotlib()
    from rodparadox.animate.scenes import images_of  # matplotlib: only now, after every input has been checked
    from rodparadox.animate.encoders import write_images

    drawn = images_of(history, job.frames[0], mode, style, line)
    with click.progressbar(drawn, length=count, label=str(job.path), file=sys.stderr,
                           hidden=not _is_terminal(sys.stderr)) as bar:
        written = write_images(job.path, job.fmt, fps, bar, name=job.stem)
    report([(f"{job.path}/" if job.fmt == "png" else job.path, written)], quiet)


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
