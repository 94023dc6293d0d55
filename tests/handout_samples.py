"""Handouts built by hand from document blocks, as the handout generator will build them: for the typesetter's
tests and for looking at its pages (`python tests/handout_samples.py OUT_DIR` writes fig1 and fig2 handouts and
worksheets on A4 and Letter). Not collected by pytest (no test_ prefix)."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

from rodparadox.tables import build as tables
from rodparadox.handout.document import DiagramBlock, Handout, Heading, Paragraph, Question, Section, Strips
from rodparadox.physics.rigid import run
from rodparadox.physics.frames import paper_frames, time_window
from rodparadox.io.scenario import load

SETUP = {
    "fig1": ("Particles A and B, each of the rod's mass M, approach a rod of proper length L at rest in S, A "
             "from the left and B from the right, each at speed v = 0.6 and each L/2 from its end at t = 0. They "
             "strike the two ends at the same instant of S."),
    "fig2": ("Particles A and B, each of the rod's mass M, approach a rod of proper length L at rest in S. B, at "
             "rest in S′, starts L/2 from the right end; A moves at 15/17 in S′ and strikes the left end at the "
             "instant t′ = 17/12 L at which B strikes the right end."),
}

QUESTIONS = (
    ("Read the coordinates (x, t) of the impact B₁ off panel (a) and (x′, t′) off panel (b).",
     ("In S, B₁ is at x = +0.5000000 L, t = +0.8333333 L (5/6 L); in S′ at x′ = +1.250000 L, t′ = +1.416667 L "
      "(17/12 L).",)),
    ("Show with a Lorentz transformation that A₁ and B₁ are simultaneous in S′ but not in S.",
     ("With γ = 1.25 and S′ moving at −0.6: t′ = γ (t + v x). For B₁: 1.25 × (5/6 + 0.6 × 0.5) = 17/12. "
      "For A₁: 1.25 × (19/12 − 0.6 × 0.75) = 17/12. The same t′; in S they differ by 3/4 L.",
      "So the two impacts lie on one line of simultaneity of S′ and on two lines of S.")),
    ("What is the rod's velocity in S′ just after A₁?",
     ("+0.882353 (15/17): the velocity addition of +0.6 and +0.6, (0.6 + 0.6)/(1 + 0.36).",)),
    ("Which impact does the rod itself take first, and why does it zig-zag?",
     ("B₁: on the rod's own lines of simultaneity B₁ comes 3/4 L before A₁, so the impulses do not cancel; the "
      "rod turns about its left end, then about its right end.",)),
    ("How large is the hidden momentum in S between the impacts B₁ and A₁?",
     ("−0.2301396 M c at t = 29/24 L, read from the table of the hidden part.",)),
    ("What would change at v = 0.8?",
     ("The impacts move apart in S (γ v L grows from 0.75 L to 1.333 L), and the zig-zag lasts longer.",
      "In S′ the first two impacts are still simultaneous: the scenario times A so.")),
)


def instants(history, frame, count: int = 6) -> tuple[float, ...]:
    t0, t1 = time_window(history, frame)
    return tuple(float(t) for t in np.linspace(t0, t1, count + 2)[1:-1])


def section(name: str, v: float = 0.6, worksheet: bool = False, strips: bool = True) -> tuple[Section, tuple]:
    """A scenario's section and its answer key's blocks (filled tables, questions with worked answers)."""
    history = run(load(name))
    rest, moving = paper_frames(v)
    blocks = [Heading(f"{name}: the paper's Fig. {name[-1]} at v = {v}"), Paragraph(SETUP.get(name, SETUP["fig1"])),
              DiagramBlock(name, history, (rest, moving),
                      f"The history of {name} in S (a) and in S′ (b). Dotted: lines of simultaneity of S; "
                      f"dash-dotted: lines of simultaneity of S′, through every impact."),
              Paragraph("In S′ the first two impacts share t′ = 17/12 L, yet the rod is struck by B first in its "
                        "own time, and zig-zags: read the order of the impacts on the rod's own lines of "
                        "simultaneity, not on any observer's clock.")]
    if strips:
        blocks += [Heading("The rod at successive instants", 2)]
        blocks += [Strips(f"{name}_strips_{f.name}", history, f, instants(history, f),
                          f"The rod and the particles in the space of {('S', 'S′')[k]} at six instants of its "
                          f"time; the rod's shade is the velocity of its material points.")
                   for k, f in enumerate((rest, moving))]
    blocks.append(Heading("The impacts", 2))
    key = []
    made = [tables.events_table(history, f, blank=worksheet) for f in (rest, moving)]
    made += [tables.ledger_table(history, f, blank=worksheet) for f in (rest, moving)]
    made += [t for t in (tables.hidden_table(history, f, blank=worksheet) for f in (rest, moving)) if t]
    blocks += made[:2] + [Heading("Energy and momentum", 2)] + made[2:]
    blocks.append(Heading("Questions", 2))
    questions = [Question(k, q, a) for k, (q, a) in enumerate(QUESTIONS, start=1)]
    blocks += questions
    if worksheet:
        key = [Heading(f"{name}", 2)] + [t.filled() for t in made if t.has_blanks] + questions
    return Section(name, f"{name} at v = {v}", tuple(blocks)), tuple(key)


def handout(*names: str, worksheet: bool = False, strips: bool = True) -> Handout:
    sections, key = [], []
    for name in names:
        s, k = section(name, worksheet=worksheet, strips=strips)
        sections.append(s)
        key += k
    title = f"The Sears paradox: {', '.join(names)} at v = 0.6" + (" (worksheet)" if worksheet else "")
    return Handout(title, tuple(sections), worksheet, (Heading("Answer key"), *key) if worksheet else ())


if __name__ == "__main__":
    from rodparadox.handout.pdf import to_pdf

    out = Path(sys.argv[1] if len(sys.argv) > 1 else "outputs/handout-samples")
    out.mkdir(parents=True, exist_ok=True)
    papers = sys.argv[2].split(",") if len(sys.argv) > 2 else ["a4"]
    for name in ("fig1", "fig2"):
        for worksheet in (False, True):
            for paper in papers:
                path = out / f"{name}_{'worksheet' if worksheet else 'handout'}_{paper}.pdf"
                path.write_bytes(to_pdf(handout(name, worksheet=worksheet), paper))
                print(path)
