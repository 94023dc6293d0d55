"""`sears-paradox html`: one self-contained HTML page to explore speed, frame and time (the docs, "One page to
explore: `sears-paradox html`").

Thin: parse the options, plan and check through `sears_paradox_cli.planning` (named as `plot` names figures), build
the page with `rodparadox.web.page`, write it atomically. Never imports matplotlib.
"""

from __future__ import annotations

import click

from .edge import report, reports_errors
from .options import output_option, quiet_option, rod_asked, run_scenario, scenario_options, style_option

#: what `html` writes: one page
HTML_FORMATS = ("html",)


@click.command()
@scenario_options(several=True, rods=("rigid", "causal", "both"))
@output_option("A folder to write into (it must exist), or a file name .html. [default: outputs/, created if "
               "missing]", metavar="PATH_OR_DIR")
@style_option(help="The style the page opens in (it has a switch for the others): default: colour; print: black "
                   "and white, serif; slides: large type.")
@quiet_option
@reports_errors
def html(scenarios: tuple[str, ...], v: float | None, L: float | None, output: str | None, style: str,
         quiet: bool) -> None:
    """Write one offline HTML page to explore the SCENARIOs: drag the speed, the frame and the time.

    Every number is computed here and embedded (speeds 0.05 to 0.95 and the
    scenario's own, the rigid rod and the causal rod); the page needs no network
    and opens from file://. --rod (or the scenario's rod:) picks the rod it opens
    on, both side by side with --rod both. Several scenarios give one page with a
    chooser. Writes OUTPUT/NAME.html, named as
    plot names figures, and prints its path, `PATH (unchanged)` when the file
    already held these bytes.

    Example: sears-paradox html fig2 --v 0.6
    """
    from sears_paradox_cli import planning as planned

    described = planned.Outputs(formats=HTML_FORMATS, default="html", together=True)
    rod = rod_asked()
    named = [rod] if rod in ("causal", "both") else []  # fig2_causal.html beside fig2.html, as plot names them
    [job] = planned.plan(scenarios, described, v=v, L=L, frame="both", fmt=None, output=output, style=style,
                         extras=named)
    for s, name, frames in zip(job.scenarios, job.names, job.frames):
        # the one verdict at the scenario's own v, in the rod it opens on, before any other speed is run
        for model in (("rigid", "causal") if rod == "both" else (s.rod,)):
            run_scenario(s.with_overrides(rod=model), name, frames)
    planned.prepare([job], described, output)

    from rodparadox.io.output import write_atomic
    from rodparadox.web.page import page

    text = page(list(zip(job.stems, job.scenarios)), style, shown=rod)
    report([(job.path, write_atomic(job.path, text.encode("utf-8")))], quiet)
