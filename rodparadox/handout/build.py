"""What a handout and a worksheet say, as `document` blocks (README, "Teaching handouts"): `build`. Pure: no
matplotlib, no LaTeX.

`build` turns scenarios' histories into a `document.Handout`: per scenario a
heading, a set-up paragraph, the diagram with its caption, an explanation, the
rod at successive instants in each frame, the events, ledger and hidden tables,
and for a worksheet 5 to 8 questions whose worked answers the answer key
prints. The parts come from the modules beside this one:

  words             numbers and names as the sentences write them (17/12 L, +0.6 c, B₁, S′)
  reading           `Reading`: a history read once for the text (instants, collisions, turns, velocities)
  narrative         the set-up, the diagram's caption and the explanation
  strips            the rod at successive instants: which instants, and their caption
  worksheet         which questions a worksheet asks (`worksheet_frames`, `worksheet_rod` build them)


Every sentence is generated from the computed history; a question about
another speed runs the engine again. `pdf` and `tex` set the same blocks on
paper and in LaTeX.

Conventions (README, "The model"): c = 1; x and t are quoted as multiples of L
(17/12 L), so they hold for any L; speeds as fractions of c; masses in M,
energies in M c², momenta in M c. S′ moves at −v relative to S, so
t′ = γ(t + v x) (derived in the answers from `Event.seen_from`, never copied from
the paper's appendix, which misprints the sign).
"""

from __future__ import annotations

from typing import Sequence

from rodparadox.handout.document import Block, DiagramBlock, Handout, Heading, Paragraph, Section, Strips
from rodparadox.handout.narrative import diagram_caption, explanation, setup_text
from rodparadox.handout.strips import strip_times, strips_caption
from rodparadox.handout.words import listed, time_name, with_primes
from rodparadox.handout.worksheet import questions
from rodparadox.numbers import exact
from rodparadox.physics.engine import History
from rodparadox.physics.frames import Frame, frame_name, frame_word, moving_frame, paper_frames
from rodparadox.tables import build as tables
from rodparadox.tables.build import coordinates


# --- the title and the headings ---------------------------------------------------------------------------------

def _speed(history: History) -> str:
    """v = 0.6, or v = 0.6, L = 2."""
    s = history.scenario
    return f"v = {exact(s.v)}" + (f", L = {exact(s.L)}" if s.L != 1.0 else "")


def title(items: Sequence[tuple[str, History]]) -> str:
    """The Sears paradox: fig2 at v = 0.6; fig1 and fig2 at v = 0.6; fig1 at v = 0.6 and fig2 at v = 0.8."""
    stems = [item[0] for item in items]
    speeds = [_speed(item[1]) for item in items]
    if len(set(speeds)) == 1:
        return f"The Sears paradox: {listed(stems)} at {speeds[0]}"
    return "The Sears paradox: " + listed([f"{stem} at {sp}" for stem, sp in zip(stems, speeds)])


def heading(history: History) -> str:
    """The scenario's name and description."""
    s = history.scenario
    description = with_primes(s.description)
    return f"{s.name} — {description}" if description else s.name


# --- the numbers -----------------------------------------------------------------------------------------------

def _table_unit(L: float) -> str:
    """How the tables give x and t: in units of L, or, for L other than 1, in the unit L is given in."""
    return "in units of L" if L == 1.0 else f"in the unit L is given in (L = {exact(L)})"


def _tables(history: History, frame: Frame, blank: bool) -> list[Block]:
    """The frame's events, ledger and hidden tables (`tables.build`), each after the sentence that says how to read it;
    `blank`: a worksheet's copies, their numbers left to fill in."""
    symbol, time = frame_name(frame), time_name(frame)
    x = coordinates(frame)[0]
    blocks: list[Block] = [
        Paragraph(f"The impacts in {symbol}, in the order of its time: where and when each strikes ({x} and {time} "
                  f"{_table_unit(history.scenario.L)}), and the velocities (in units of c) of the particle and of the "
                  f"rod just before and just after it."),
        tables.events_table(history, frame, blank),
        Paragraph(f"The ledger in {symbol}: at each impact, the energy E and momentum p of the particle, of the rod "
                  f"(its momentum's, which takes the whole impulse) and the hidden part (what the rod's stress "
                  f"carries: the total before the first impact less every body's kinetic E and p on the slice "
                  f"{time} = constant), just before and just after."),
        tables.ledger_table(history, frame, blank),
    ]
    hidden = tables.hidden_table(history, frame, blank)
    if hidden is None:
        blocks.append(Paragraph(f"In {symbol} the hidden part is zero on every slice between impacts: at every "
                                f"instant of {symbol} the bodies' own motion carries all the energy and momentum."))
    else:
        blocks += [Paragraph(f"The hidden part in {symbol} on a slice halfway between each two consecutive changes "
                             f"(impacts, the start or end of a turn), where it is not zero: energy and momentum that "
                             f"no body's motion shows, held by the stress in the rod."), hidden]
    return blocks


# --- the document ----------------------------------------------------------------------------------------------

def _section(stem: str, history: History, frames: tuple[Frame, ...], worksheet: bool) -> tuple[Section, list[Block]]:
    """One scenario's section, and for a worksheet its part of the answer key (a heading, the filled tables and
    the questions again)."""
    blocks: list[Block] = [Heading(heading(history)), Paragraph(setup_text(history)),
                           DiagramBlock(f"{stem}_diagram", history, frames, diagram_caption(history, frames)),
                           Heading("What the diagram shows", 2)]
    blocks += explanation(history, frames)
    blocks.append(Heading("The rod at successive instants", 2))
    for f in frames:
        times = strip_times(history, f)
        blocks.append(Strips(f"{stem}_strips_{frame_word(f)}", history, f, times, strips_caption(history, f, times)))
    blocks.append(Heading("The numbers", 2))
    for f in frames:
        blocks += _tables(history, f, worksheet)
    section_title = f"{stem} at {_speed(history)}"
    key: list[Block] = []
    if worksheet:
        asked = questions(history, frames)
        blocks.append(Heading("Questions", 2))
        blocks += asked
        key.append(Heading(section_title, 2))
        key += [b.filled() for b in blocks if hasattr(b, "filled")]
        key += asked
    return Section(stem, section_title, tuple(blocks)), key


def build(items: Sequence[tuple], frames: Sequence[Frame] | None = None, worksheet: bool = False) -> Handout:
    """The handout (or, with `worksheet`, the worksheet and its answer key) of each (stem, history) item, one
    section each, in order. `frames` defaults to S and S′ of each scenario; a frame named `moving` is S′ of each
    scenario's own v. An item may also be (stem, history, frames), its own frames overriding `frames`."""
    entries = []
    for item in items:
        stem, history, *own = item
        if own:
            shown_frames = tuple(own[0])
        elif frames is None:
            shown_frames = paper_frames(history.scenario.v)
        else:
            shown_frames = tuple(moving_frame(history.scenario.v) if f.name == "moving" else f for f in frames)
        entries.append((stem, history, shown_frames))
    sections, key = [], []
    for stem, history, shown_frames in entries:
        section, answers = _section(stem, history, shown_frames, worksheet)
        sections.append(section)
        key += answers
    answer_key = (Heading("Answer key"), *key) if worksheet else ()
    return Handout(title([(stem, history) for stem, history, _ in entries]), tuple(sections), worksheet,
                   tuple(answer_key))
