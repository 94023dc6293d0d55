"""`sears-paradox plot`: draw the paper's Minkowski diagrams into SVG, PDF or PNG files.

Thin: parse the options, call `rodparadox.render` and `rodparadox.io.output`,
print the paths written. matplotlib is imported inside the command, so
`--help` never loads it.
"""

from __future__ import annotations

import click

from rodparadox.render.styles import FORMATS

from .edge import BadInput, before_matplotlib, report, reports_errors
from .options import (Whole, format_option, frame_option, output_option, quiet_option, rod_asked, run_rods,
                      scenario_options, style_option)

_EXTRAS = (("other_axes", "axes"), ("light_cones", "cones"), ("hyperbolae", "hyperbolae"), ("grid", "grid"),
           ("rod_now", "now"), ("proper_time", "clocks"), ("equal_scales", "samescale"))


@click.command()
@scenario_options(several=True, rods=("rigid", "causal", "both"))
@frame_option("Panels, left to right: S, S', both, the frame of velocity U relative to S, or rod (the rod's own "
              "view: it a fixed strip); a comma-separated list gives several (e.g. both,0.3 or rest,rod).",
              metavar="rest|moving|both|U|rod")
@format_option("One or more formats, comma-separated. [default: svg, or the extension of -o FILE]", default=None,
               metavar="svg,pdf,png")
@output_option("A folder to write into (it must exist), or a file name for one scenario in one format. "
               "[default: outputs/, created if missing]", metavar="PATH_OR_DIR")
@style_option()
@click.option("--other-axes", is_flag=True, help="Draw the other frame's x and t axes, tilted, on each panel.")
@click.option("--light-cones", is_flag=True, help="Draw the light cone of every impact.")
@click.option("--hyperbolae", is_flag=True, help="Draw calibration hyperbolae t^2 - x^2 = +-k^2 about the origin.")
@click.option("--grid", is_flag=True, help="Draw a grid at the ticks.")
@click.option("--rod-lines", "rod_lines", type=Whole(0, 50), default=0, metavar="N",
              help="Draw N material world-lines inside the rod (0 to 50), so the rigid response is seen flowing "
                   "through it.")
@click.option("--rod-now", is_flag=True, help="Draw the rod's own lines of simultaneity: each turn's fan through "
                                               "its pivot, and lines between turns.")
@click.option("--proper-time", is_flag=True, help="Draw clock ticks of equal proper time along every particle and "
                                                   "rod end.")
@click.option("--equal-scales", is_flag=True, help="Draw every panel to one scale (the same length of L on the page), "
                                                    "not each filling its panel.")
@quiet_option
@click.option("--verbose", is_flag=True, hidden=True, help="Accepted and ignored: every path is printed anyway.")
@reports_errors
def plot(scenarios: tuple[str, ...], v: float | None, L: float | None, frame: str, fmt: str | None,
         output: str | None, style: str, other_axes: bool, light_cones: bool, hyperbolae: bool, grid: bool,
         rod_lines: int, rod_now: bool, proper_time: bool, equal_scales: bool, quiet: bool, verbose: bool) -> None:
    """Draw Minkowski diagrams of each SCENARIO: both frames side by side (the paper's Figs. 1 and 2).

    Writes OUTPUT/NAME.FORMAT, NAME being the scenario's name followed by every
    non-default option (fig2.svg, fig2_v0.8.svg, fig2_rest_print.pdf, ...), and
    prints the path of each file, `PATH (unchanged)` for one whose bytes would
    not change and which is left alone. SCENARIO is a file if one of that name
    exists, else a built-in name.

    Example: sears-paradox plot fig2 --v 0.6
    """
    from sears_paradox_cli import planning as planned
    from sears_paradox_cli.planning import lorentz_frames

    extras = {"other_axes": other_axes, "light_cones": light_cones, "hyperbolae": hyperbolae, "grid": grid,
              "rod_now": rod_now, "proper_time": proper_time, "equal_scales": equal_scales}
    described = planned.Outputs(formats=FORMATS, default="svg", frames=planned.frames_with_rod)  # a figure each
    rod = rod_asked()
    named = [short for key, short in _EXTRAS if extras[key]] + ([f"lines{rod_lines}"] if rod_lines else [])
    named = ([rod] if rod in ("causal", "both") else []) + named  # fig1_causal.svg beside fig1.svg
    jobs = planned.plan(scenarios, described, v=v, L=L, frame=frame, fmt=fmt, output=output, style=style, extras=named)
    from rodparadox.physics.rod_view import refuse_frame_extras, refuse_thin_view
    for job in jobs:  # every panel the rod's own view: the extras have nothing to draw on
        refuse_frame_extras(job.frames[0], **extras, rod_lines=rod_lines)
        lorentz = lorentz_frames(job.frames[0])
        planned.check_panels(len(lorentz), len(lorentz) < len(job.frames[0]), rod == "both")
    histories = [run_rods(job.scenario, job.name, lorentz_frames(job.frames[0])) for job in jobs]
    for run, job in zip(histories, jobs):
        if len(lorentz_frames(job.frames[0])) < len(job.frames[0]):  # the rod's own view is among the panels
            for h in run:
                refuse_thin_view(h)
    if proper_time and any(h.fronts is not None for run in histories for h in run):
        raise BadInput("--proper-time draws the rigid rod's clocks only for now; leave it out for the causal rod.")
    if rod_now and not any(h.turning is not None or (h.driving is not None and h.driving.now_lines())
                           for run in histories for h in run):  # the rod's own lines: a rigid rod's, or none
        raise BadInput("--rod-now draws the rigid rod's own lines of simultaneity, and the causal rod has none (its "
                       "parts share no rest frame): leave it out, or add the rigid rod with --rod both.")
    planned.prepare(jobs, described, output)

    before_matplotlib()
    from rodparadox import render  # matplotlib: only now, after every input has been checked
    from rodparadox.io.output import write_atomic

    options = render.Options(**extras, rod_lines=rod_lines)
    # every figure laid out before any file is written: one that cannot be drawn leaves no file behind
    figures = [_figure(run, job.frames[0], style, options) for run, job in zip(histories, jobs)]
    report(((path, write_atomic(path, render.figure_bytes(figure, f, style)))
            for figure, job in zip(figures, jobs) for f, path in job.paths.items()), quiet)


def _figure(run: tuple, frames: tuple, style: str, options):
    """The figure of one scenario: the frames' panels, and the rod's own view (`--frame rod`) beside them (on
    their left when it comes first in the list) or alone."""
    from rodparadox import render
    from sears_paradox_cli.planning import lorentz_frames

    lorentz = lorentz_frames(frames)
    diagram = None
    if lorentz:
        diagram = (render.draw_both(*run, lorentz, style, options) if len(run) == 2
                   else render.draw(run[0], lorentz, style, options))
    if len(lorentz) == len(frames):
        return diagram.figure
    return render.draw_rod_view(run, style, diagram, first=frames[0] not in lorentz)
