"""`sears-paradox handout`: a printable handout or worksheet (PDF), or its LaTeX pieces for authors.

Thin: parse the options, plan and check through `sears_paradox_cli.planning`, build the document's blocks with
`rodparadox.handout.build`, set them with `rodparadox.handout.pdf` or `rodparadox.handout.tex`, write.
"""

from __future__ import annotations

import click

from .common import L_option, emit, quiet_option, reports_errors, run_scenario, v_option


@click.command()
@click.argument("scenarios", nargs=-1, required=True, metavar="SCENARIO...")
@v_option
@L_option
@click.option("--frame", "frame", default="both", show_default=True, metavar="rest|moving|both|U",
              help="The frames shown, as plot's --frame (e.g. both,0.3).")
@click.option("--paper", "paper", type=click.Choice(("a4", "letter"), case_sensitive=False), default="a4",
              show_default=True, help="The paper size.")
@click.option("--worksheet", is_flag=True,
              help="A worksheet: the tables' numbers left blank to fill in, questions, and an answer key at the end.")
@click.option("--format", "fmt", type=click.Choice(("pdf", "tex"), case_sensitive=False), default="pdf",
              show_default=True,
              help="pdf: one document to print; tex: a folder with handout.tex (pdflatex), the figures as PDF, the "
                   "tables as .tex fragments and the world-lines as .dat files for pgfplots.")
@click.option("--style", "style", type=click.Choice(("print", "default", "slides")), default="print",
              show_default=True, help="print: black and white, for photocopies; default: colour; slides: large type.")
@click.option("-o", "--output", "output", metavar="PATH", default=None,
              help="pdf: a folder (it must exist) or a file name .pdf; tex: the folder of the pieces (created if "
                   "missing). [default: outputs/, created if missing]")
@quiet_option
@reports_errors
def handout(scenarios: tuple[str, ...], v: float | None, L: float | None, frame: str, paper: str, worksheet: bool,
            fmt: str, style: str, output: str | None, quiet: bool) -> None:
    """Write a teaching handout (or --worksheet) of each SCENARIO, one section each, computed at the speed given.

    Each section holds the setup, the two-frame diagram with an explanation
    generated from the computed history, the rod at successive instants in each
    frame, and the events and energy-momentum tables. Writes
    OUTPUT/NAME_handout.pdf (NAME_worksheet.pdf), named as plot names figures,
    or with --format tex the folder OUTPUT/NAME_handout/; prints each path
    written, `PATH (unchanged)` for one left alone. The same command gives the
    same bytes.

    Example: sears-paradox handout fig2 --v 0.6 --worksheet
    """
    from sears_paradox_cli import planning as planned

    job = planned.plan_handout(scenarios, v=v, L=L, frame=frame, fmt=fmt.lower(), output=output, style=style,
                               paper=paper.lower(), worksheet=worksheet)
    histories = [run_scenario(s, name) for s, name in zip(job.scenarios, job.names)]
    planned.prepare_handout(job, output)

    from rodparadox.handout.build import build
    from rodparadox.io.output import write_atomic, write_folder

    document = build(list(zip(job.stems, histories, job.frames)), worksheet=worksheet)
    if job.fmt == "pdf":
        from rodparadox.handout.pdf import to_pdf  # matplotlib: only now, after every input has been checked

        written = [(job.path, write_atomic(job.path, to_pdf(document, paper.lower(), style)))]
    else:
        from rodparadox.handout.tex import tex_files

        written = write_folder(job.path, tex_files(document, paper.lower(), style))
    if not quiet:
        for path, changed in written:
            emit(str(path) if changed else f"{path} (unchanged)")
