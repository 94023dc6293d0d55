"""`sears-paradox handout`: a printable handout or worksheet (PDF), or its LaTeX pieces for authors.

Thin: parse the options, plan and check through `sears_paradox_cli.planning`, build the document's blocks with
`rodparadox.handout.build`, set them with `rodparadox.handout.pdf` or `rodparadox.handout.tex`, write.
"""

from __future__ import annotations

from pathlib import Path

import click

from rodparadox.errors import OptionError

from .edge import BadInput, before_matplotlib, report, reports_errors
from .options import (format_option, frame_option, output_option, quiet_option, rod_asked, run_rods, run_scenario,
                      scenario_options, style_option)

#: what `handout` writes: one PDF, or a folder of LaTeX pieces (handout.tex, figures, table fragments, .dat files)
HANDOUT_FORMATS = ("pdf", "tex")
#: how a file name says which rods a handout compares: --rod causal and --rod both give the same document
ROD_WORDS = {"causal": "compared", "both": "compared"}
#: handouts are photocopied in black and white
HANDOUT_STYLE = "print"
PAPER_NAMES = ("a4", "letter")
HANDOUT_PAPER = "a4"


@click.command()
@scenario_options(several=True, rods=("rigid", "causal", "both"))
@frame_option("The frames shown, as plot's --frame (e.g. both,0.3); rod beside them (both,rod) adds the rod's own "
              "view after each diagram.", metavar="rest|moving|both|U|rod")
@click.option("--paper", "paper", type=click.Choice(PAPER_NAMES, case_sensitive=False), default=HANDOUT_PAPER,
              show_default=True, help="The paper size.")
@click.option("--worksheet", is_flag=True,
              help="A worksheet: the tables' numbers left blank to fill in, questions, and an answer key at the end.")
@click.option("--questions", "chosen", default=None, metavar="1,3,5",
              help="With --worksheet: which questions to ask, by their numbers in the full set, comma-separated; "
                   "numbered from 1 again, the same in the worksheet and its key.")
@click.option("--compare-v", "compare_v", type=float, default=None,
              help="With --worksheet: the speed the 'another speed' question compares with (0 < v < 1, not the "
                   "scenario's). [default: one of 0.8, 0.5, 0.9, 0.3 at least 0.15 from v]")
@click.option("--key", "key", type=click.Choice(("inline", "separate"), case_sensitive=False), default="inline",
              show_default=True,
              help="With --worksheet: inline, the answer key at the end; separate, the key as its own PDF, "
                   "NAME_worksheet_key.pdf beside the worksheet.")
@click.option("--sections", "parts", default=None, metavar="paradox,diagrams,...",
              help="The parts each document holds, comma-separated: paradox (the paradox and its resolution), "
                   "diagrams (each diagram and what it shows), strips (the rod at successive instants), tables (the "
                   "impacts), ledger (energy and momentum), comparison (the causal rod beside the rigid one, with "
                   "--rod both or causal), rod (the rod's own view, as --frame both,rod). A worksheet keeps its "
                   "diagrams and tables, which its questions read. [default: all]")
@click.option("--equal-scales", is_flag=True, help="Draw the diagram's panels to one scale (the same length of L on "
                                                    "the page), not each filling its panel, as plot's --equal-scales.")
@format_option("pdf: one document to print; tex: a folder with handout.tex (pdflatex), the figures as PDF, the "
               "tables as .tex fragments and the world-lines as .dat files for pgfplots.",
               type=click.Choice(HANDOUT_FORMATS, case_sensitive=False), default="pdf", show_default=True)
@style_option(("print", "default", "slides"), HANDOUT_STYLE,
              "print: black and white, for photocopies; default: colour; slides: large type.")
@output_option("pdf: a folder (it must exist) or a file name .pdf; tex: the folder of the pieces (created if "
               "missing). [default: outputs/, created if missing]")
@quiet_option
@reports_errors
def handout(scenarios: tuple[str, ...], v: float | None, L: float | None, frame: str, paper: str, worksheet: bool,
            chosen: str | None, compare_v: float | None, key: str, parts: str | None, equal_scales: bool, fmt: str,
            style: str, output: str | None, quiet: bool) -> None:
    """Write a teaching handout (or --worksheet) of each SCENARIO, one section each, computed at the speed given.

    Each section holds the setup, the two-frame diagram with an explanation
    generated from the computed history, the rod at successive instants in each
    frame, and the events and energy-momentum tables; with --rod both (or
    causal) it ends comparing the rigid rod with the causal rod. Writes
    OUTPUT/NAME_handout.pdf (NAME_worksheet.pdf), named as plot names figures,
    or with --format tex the folder OUTPUT/NAME_handout/; prints each path
    written, `PATH (unchanged)` for one left alone. The same command gives the
    same bytes.

    Example: sears-paradox handout fig2 --worksheet --key separate
    """
    from sears_paradox_cli import planning as planned

    paper = paper.lower()
    key = key.lower()
    numbers = _worksheet_options(worksheet, chosen, compare_v, key, fmt.lower())
    sections = _sections(parts, worksheet)
    described = planned.Outputs(formats=HANDOUT_FORMATS, default="pdf", kind="worksheet" if worksheet else "handout",
                                folders={"tex": "the LaTeX pieces"}, check=_check_output,
                                together=True, default_style=HANDOUT_STYLE, frames=planned.frames_with_rod)
    rod = rod_asked()
    # the rods compared, named once (fig2_handout_compared.pdf; `both` beside --frame both,rod read twice)
    extras = ([ROD_WORDS[rod]] if rod in ROD_WORDS else []) + ([paper] if paper != HANDOUT_PAPER else [])
    [job] = planned.plan(scenarios, described, v=v, L=L, frame=frame, fmt=fmt.lower(), output=output, style=style,
                         extras=extras + (["samescale"] if equal_scales else []))
    from rodparadox.handout.build import Item

    items, views = [], {}
    for s, name, shown_frames, stem in zip(job.scenarios, job.names, job.frames, job.stems):
        frames = planned.lorentz_frames(shown_frames)
        if not frames:
            raise BadInput("--frame rod needs a frame beside it in a handout, whose tables are read in frames: give "
                           "e.g. both,rod.")
        # the rigid rod's sections always (the diagrams draw it); the causal rod beside it, struck by the same
        # particles (placed once, by the scenario's own rod: `physics.models.run_rods`), when compared
        compared = (rod in ("causal", "both") or s.rod == "causal") and "comparison" in sections
        if compared:
            rigid, causal = run_rods(s, name, frames, rods="both")
        else:
            rigid, causal = run_scenario(s.with_overrides(rod="rigid"), name, frames), None
        items.append(Item(stem, rigid, frames, causal))
        # the rod's own view (--frame both,rod, or rod among --sections): of the rigid rod, and of the causal rod when
        # compared
        if "rod" in sections and (frames != shown_frames or parts is not None):
            views[stem] = (items[-1].history,) + ((causal,) if causal is not None else ())
    from rodparadox.physics.rod_view import refuse_thin_view

    for history in (h for histories in views.values() for h in histories):
        refuse_thin_view(history)
    planned.prepare([job], described, output)

    before_matplotlib()
    from rodparadox.handout.build import build
    from rodparadox.handout.own_view import refuse_views_too_wide, with_rod_views
    from rodparadox.io.output import write_atomic, write_folder

    refuse_views_too_wide(views, job.fmt, paper, style)

    document = build(items, worksheet=worksheet, compare_v=compare_v, chosen=numbers, equal_scales=equal_scales,
                     sections=sections)
    if views:
        document = with_rod_views(document, views)
    if job.fmt == "pdf":
        from rodparadox.handout.pdf import to_pdf  # matplotlib: only now, after every input has been checked

        if key == "separate":
            import dataclasses

            from rodparadox.handout.document import Handout

            sheet = dataclasses.replace(document, answer_key=())
            answers = Handout(document.title + ": answer key", (), False, document.answer_key)
            key_path = Path(job.path).with_name(Path(job.path).stem + "_key.pdf")
            sheet_bytes, key_bytes = to_pdf(sheet, paper, style), to_pdf(answers, paper, style)
            report([(job.path, write_atomic(job.path, sheet_bytes)), (key_path, write_atomic(key_path, key_bytes))],
                   quiet)
            return
        report([(job.path, write_atomic(job.path, to_pdf(document, paper, style)))], quiet)
    else:
        from rodparadox.handout.tex import tex_files

        report(write_folder(job.path, tex_files(document, paper, style)), quiet)


def _check_output(output: str, fmt: str, suffix: str) -> None:
    """-o against the format: tex writes a folder, which a name ending in .pdf cannot be."""
    if fmt == "tex" and suffix == "pdf" and not Path(output).is_dir():
        raise OptionError("output", output, template="{what} names {value!r} but {format} is tex, which writes a "
                                                     "folder; name the folder.")


#: the parts of a handout (`handout.build.SECTIONS`: named here, so that --help needs no import of the library)
SECTIONS = ("paradox", "diagrams", "strips", "tables", "ledger", "comparison", "rod")


def _sections(parts: str | None, worksheet: bool) -> tuple[str, ...]:
    """--sections: the parts asked for, checked before anything is computed (all of them when not given)."""
    if parts is None:
        return SECTIONS
    asked = tuple(dict.fromkeys(p.strip().lower() for p in parts.split(",")))
    unknown = [p for p in asked if p not in SECTIONS]
    if unknown or not asked:
        raise OptionError("sections", parts, f"parts among {', '.join(SECTIONS)}, comma-separated")
    missing = [p for p in ("diagrams", "tables") if p not in asked]
    if worksheet and missing:
        raise OptionError("sections", parts, template="{what} leaves out " + " and ".join(missing)
                          + ", which a worksheet's questions read; add them.")
    return asked


def _worksheet_options(worksheet: bool, chosen: str | None, compare_v: float | None, key: str,
                       fmt: str) -> tuple[int, ...] | None:
    """--questions, --compare-v and --key: worksheet options, checked before anything is computed; the question
    numbers asked (None: all)."""
    for name, given in (("questions", chosen is not None), ("compare_v", compare_v is not None),
                        ("key", key != "inline")):
        if given and not worksheet:
            raise OptionError(name, {"questions": chosen, "compare_v": compare_v, "key": key}[name],
                              template="{what} is for a worksheet; add --worksheet.")
    if key == "separate" and fmt != "pdf":
        raise OptionError("key", key, template="{what} {value} writes a second PDF; with --format tex the key is in "
                                               "handout.tex.")
    if compare_v is not None and not 0.0 < compare_v < 1.0:
        raise OptionError("compare_v", compare_v, "a speed with 0 < v < 1 (units of c)")
    if chosen is None:
        return None
    try:
        numbers = tuple(int(part) for part in chosen.split(","))
    except ValueError:
        numbers = ()
    if not numbers or any(n < 1 or n > 8 for n in numbers) or len(set(numbers)) != len(numbers):
        raise OptionError("questions", chosen, "question numbers from 1 to 8, comma-separated, each once (1,3,5)")
    return numbers
