"""The rod's own view in a handout (`handout --frame both,rod`): a figure after each section's diagram, and its
caption, generated from the histories (docs/plot.md, "The rod's own view"). Pure: no matplotlib, except
`refuse_views_too_wide`, which measures the page as the PDF or LaTeX writer sets it.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Sequence

from rodparadox.handout.document import DiagramBlock, Handout, Heading, RodViewBlock
from rodparadox.numbers import impact_name, shown
from rodparadox.physics.rod_view import chart_of

#: the heading of a section's worked answers in a worksheet's key, before which the key shows the rod's own view
ANSWERED = "Questions and answers"
ROD_VIEW = "The rod\u2019s own view"


def rod_view_caption(histories: Sequence, tell: bool = True) -> str:
    """What the figure shows, for a reader who has not seen the code: the chart's two axes, then each model; with
    `tell` (not in a worksheet, which may ask them) how long each turn lasts."""
    parts = ["The rod's own view: across, each material point's label X (its distance from the left end when "
             "unstressed), so the rod is the fixed strip 0 \N{LESS-THAN OR EQUAL TO} X \N{LESS-THAN OR EQUAL TO} L; "
             "up, the rod's own time T. Every level line is one \"now\" of the rod, and the ticks on each material "
             "line are its own clock."]
    for h in histories:
        chart = chart_of(h)
        if h.turning is not None:
            turns = [f"about {impact_name(_pivot_label(h, t))}, {shown((b - a) / h.scenario.L, 4)} L long"
                     for t, (a, b, _) in zip(h.turns, chart.turns)]
            parts.append("Rigid rod: between turns T is the time of its rest frame. During a turn about an impact, T "
                         "grows by L for each unit of rapidity the rod's lines turn through, and a point at distance d "
                         "from the pivot keeps its X while its clock runs at d/L of T's rate: the pivot's clock stops, "
                         "and the far end's runs on, as if it knew of the impact at once. "
                         + (f"Turns: {', '.join(turns)}. " if turns and tell else "")
                         + ("" if turns else "No turns: the rod never moves. ")
                         + ("Hatched: beyond the pivot during its turn, where the rod's own time places an event "
                            "twice, once on a line of the rest frame before the turn and once on one after it."
                            if turns else ""))
        elif h.fronts is not None:
            parts.append("Causal rod: the chart in which every material point stands still and every light ray runs "
                         "at 45\N{DEGREE SIGN}, so each front that carries a push or a pull crosses the rod in a time "
                         "L; a clock runs slow where the rod is compressed (d\N{GREEK SMALL LETTER TAU} = dT/"
                         "\N{GREEK SMALL LETTER LAMDA})."
                         + (" A particle in contact rides the end (a band); outside the rod the chart is carried out "
                            "along light rays from its ends, so the particles' approach and departure are drawn where "
                            "those rays place them." if h.driving is None else ""))
        else:  # a rigid rod driven by forces: its lines of simultaneity turn smoothly, no turn about a pivot
            parts.append("Rigid rod: each level line is one of the rod's own lines of simultaneity, on which all its "
                         "points are at rest together at that instant; T is the proper time of its left end (the time "
                         "of S while the rod rests in S before the forces), and X the distance from the left end "
                         "along that line. While the rod accelerates its lines turn, and a point at X keeps its X "
                         "while its clock runs at 1 + \N{GREEK SMALL LETTER ALPHA}X/c\N{SUPERSCRIPT TWO} of T's rate, "
                         "\N{GREEK SMALL LETTER ALPHA} the left end's proper acceleration (positive towards the right "
                         "end).")
    if any(h.driving is not None for h in histories):
        parts.append("Each force is drawn as a band beside the end it acts on, as wide as the force at each instant; "
                     "on and off mark where it starts and ends.")
    return " ".join(parts)


def _pivot_label(history, turn) -> str:
    return next(i.label for i in history.impacts if i.event == turn.pivot)


def with_rod_views(handout: Handout, views: dict[str, tuple]) -> Handout:
    """The handout with the rod's own view after the first diagram of each section named in `views` (section
    name -> its histories, the rigid rod first). A worksheet's go to its answer key, before each section's
    questions and answers: the rod's lines of simultaneity tell which impacts it takes together, which they ask."""
    if handout.worksheet:
        key = list(handout.answer_key)
        told = [k for k, b in enumerate(key) if isinstance(b, Heading) and b.text == ANSWERED]
        scenarios = [s for s in handout.sections if s.name != "introduction"]
        for at, section in reversed(list(zip(told, scenarios))):
            histories = views.get(section.name)
            if histories:
                key.insert(at, RodViewBlock(f"{section.name}_rod_view", tuple(histories), rod_view_caption(histories)))
                key.insert(at, Heading(ROD_VIEW, 2))
        return replace(handout, answer_key=tuple(key))
    sections = []
    for section in handout.sections:
        histories = views.get(section.name)
        blocks = list(section.blocks)
        if histories:
            at = next((k for k, b in enumerate(blocks) if isinstance(b, DiagramBlock)), len(blocks) - 1)
            caption = rod_view_caption(histories, tell=not handout.worksheet)
            blocks.insert(at + 1, RodViewBlock("rod_view", tuple(histories), caption))
        sections.append(replace(section, blocks=tuple(blocks)))
    return replace(handout, sections=tuple(sections))


def refuse_views_too_wide(views: dict[str, tuple], fmt: str, paper: str, style: str) -> None:
    """Refuse (OptionError) the rods' own views side by side where the page's text is too narrow for them, as
    setting the page would refuse them, but before the document is built (seconds for a driven rod: `handout sears
    --frame both,rod --rod both --style slides` took 1.5 s before refusing). `views`: each section's histories, as
    `with_rod_views` takes them; `fmt` "pdf" (the text width of `handout.pdf`) or "tex" (that of `handout.tex`).
    Imports matplotlib: call it once every other input has been checked."""
    count = max((len(histories) for histories in views.values()), default=0)
    if count < 2:
        return
    from rodparadox.render.rod_panel import check_side_by_side

    if fmt == "pdf":
        from rodparadox.handout.pdf_text import text_width

        width = text_width(paper)
    else:
        from rodparadox.handout.tex import text_width_in

        width = text_width_in(paper) * 72
    check_side_by_side(count, style, width)
