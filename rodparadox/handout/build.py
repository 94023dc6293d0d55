"""What a handout and a worksheet say, as `document` blocks (docs/handout.md, "Teaching handouts"): `build`. Pure: no
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

Conventions (docs/model.md, "The model"): c = 1; x and t are quoted as multiples of L
(17/12 L), so they hold for any L; speeds as fractions of c; masses in M,
energies in M c², momenta in M c. S′ moves at −v relative to S, so
t′ = γ(t + v x) (derived in the answers from `Event.seen_from`, never copied from
the paper's appendix, which misprints the sign).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, replace
from typing import Sequence

from rodparadox.handout import forces
from rodparadox.handout.causal_compare import comparison
from rodparadox.handout.causal_reading import compare
from rodparadox.handout.document import Block, Cell, DiagramBlock, Handout, Heading, Paragraph, Section, Strips, Table
from rodparadox.handout.narrative import diagram_caption, explanation, setup_text
from rodparadox.handout.strips import strip_times, strips_caption
from rodparadox.handout.words import in_l, time_name, with_primes
from rodparadox.handout.worksheet import questions
from rodparadox.handout.worksheet_causal import causal_questions
from rodparadox.numbers import exact, impact_name
from rodparadox.physics.history import RodHistory
from rodparadox.physics.types import Impact
from rodparadox.physics.frames import Frame, frame_name, frame_word, moving_frame, paper_frames
from rodparadox.tables import build as tables
from rodparadox.tables.build import coordinates
from rodparadox.tolerances import ONE_INSTANT


# --- the title and the headings ---------------------------------------------------------------------------------

def _speed(history: RodHistory) -> str:
    """v = 0.6, or v = 0.6, L = 2."""
    s = history.scenario
    return f"v = {exact(s.v)}" + (f", L = {exact(s.L)}" if s.L != 1.0 else "")


def title(items: Sequence[tuple[str, RodHistory]]) -> str:
    """The Sears paradox, at v = 0.6 (one speed for every scenario), or The Sears paradox (several speeds, each
    section's heading then names its own)."""
    speeds = {_speed(item[1]) for item in items}
    return f"The Sears paradox, at {speeds.pop()}" if len(speeds) == 1 else "The Sears paradox"


def heading(history: RodHistory, with_speed: bool = False) -> str:
    """The scenario's title (the YAML key `title`), else the first sentence of its description without
    parenthesised asides, else its name; with the speed when the sections differ in it."""
    s = history.scenario
    text = s.title
    if not text and s.description:
        first = s.description.split(": ")[-1] if s.description.startswith("The paper's") else s.description
        first = re.sub(r" \([^)]*\)", "", first.split(". ")[0].split("; ")[0]).rstrip(".")
        text = first[:1].upper() + first[1:]
    text = with_primes(text) if text else s.name
    return f"{text}, at {_speed(history)}" if with_speed else text


def neutral_heading(history: RodHistory, with_speed: bool = False) -> str:
    """A worksheet's heading: who strikes the rod, never what follows (a preset's title may say "simultaneous in
    the moving frame", which a worksheet asks)."""
    particles = history.scenario.particles
    if len(particles) == 1:
        text = f"One particle, {particles[0].name}, strikes a rod"
    else:
        masses = "equal" if len({p.mass for p in particles}) == 1 else "unequal"
        text = f"{len(particles)} particles of {masses} mass strike a rod".replace("2 particles", "Two particles")
    return f"{text}, at {_speed(history)}" if with_speed else text


# --- the first section: the paradox and its resolution -----------------------------------------------------------

#: the paper the handout follows, in full as its own text gives it (author, title, affiliation); the copy seen carries
#: no journal, year or arXiv number, so none is cited, nor Sears's own paper, which it cites without details
FRANKLIN = ("Jerrold Franklin, \u201cThe \u2018Sears paradox\u2019\u201d (Department of Physics, Temple University, "
            "Philadelphia)")

PARADOX = (
    "F. W. Sears proposed a paradox about forces on a rigid body in special relativity. A rigid rod at rest in a "
    "frame S is struck at each end at the same instant of S by equal and opposite impulses: the net force is zero "
    "and the rod stays at rest in S. In a frame S′ moving at −v relative to S the rod moves at +v; by the relativity "
    "of simultaneity the two impulses now act at different instants of S′, yet the rod\u2019s velocity does not "
    "change. How can it stay constant in S′, where the forces are no longer equal and opposite at one instant? "
    "Sears answered with \u2018hidden momentum\u2019 that the rod takes in without changing its velocity.")

RESOLUTION = (
    f"{FRANKLIN} resolves it: the usual laws of mechanics apply to a rigid body only in its rest frame. The "
    "impulses that act at different instants of S′ are simultaneous in the rod\u2019s own rest frame, where they "
    "cancel; what the rod does is decided by its own lines of simultaneity, and the time order seen in S′ is, in "
    "Franklin\u2019s words, an illusion caused by the Lorentz transformation. The sections below compute each "
    "scenario from that rule and show it in both frames.")

IDEALISATION = (
    "The rigid rod is an idealisation. When one end is struck, the far end starts to move along the rod\u2019s "
    "line of simultaneity through the impact, that is, before light from the impact could reach it: no real "
    "material transmits a push faster than light, and a real rod would carry it as a wave of compression, far "
    "slower. The rigid rod is the limit the paper uses to make the paradox sharp.")


WORKSHEET_PARADOX = (
    "F. W. Sears proposed a paradox about forces on a rigid body in special relativity. A rigid rod at rest in a "
    "frame S is struck at its two ends by equal and opposite impulses, and stays at rest in S. What happens in a "
    "frame S′ moving at −v relative to S, where the rod moves at +v? Work it out for each scenario below, from the "
    "diagram, the Lorentz transformation and the rod’s own lines of simultaneity; the answer key gives the "
    f"resolution of {FRANKLIN}.")


#: where a document has rods driven by forces: Sears's own statement (forces that act for a while, not impulses), and
#: in a handout what its sections show (a worksheet's says only the first: where the momentum is, is asked)
FORCES_INTRO = ("Sears's own statement has forces that act for a while at the two ends, not impulses; the "
                "scenarios below with forces apply such forces, given as functions of time.")
FORCES_RESOLUTION = (" While they act at different instants of S′, the momentum they deliver changes, yet the "
                     "rigid rod’s velocity does not: those sections follow the momentum slice by slice, into the "
                     "rod’s stress, which carries momentum when the rod moves (von Laue).")


def worksheet_introduction(forces: bool = False) -> Section:
    """A worksheet's first section: the paradox as a question; the whole introduction opens the answer key (its
    resolution tells what the questions ask: the impulses act at different instants of S′). `forces`: some scenario
    is driven by forces (Sears's own statement said, not where the momentum goes)."""
    extra = (Paragraph(FORCES_INTRO.replace("'", "’")),) if forces else ()
    return Section("introduction", "The paradox", (Heading("The paradox"), Paragraph(WORKSHEET_PARADOX), *extra))


def far_end_and_light(histories: Sequence[RodHistory]) -> tuple[RodHistory, Impact, str, float, float] | None:
    """The numbers of the idealisation: in the first scenario whose rod turns from rest in S, the impact at the
    turn's pivot, the far end, when that end starts to move in S and when light from the impact reaches it.

    A turn from rest turns the rod's lines of simultaneity about the pivot P from those of S: the far end starts on
    its hyperbola at P's instant of S (rule 3), while light from P crosses the rod's length L, at rest, only by
    t_P + L."""
    for h in histories:
        if h.turning is None:  # a rod driven by forces: no turn
            continue
        turn = next(iter(h.turning.turns), None)
        if turn is None or turn.rapidity_from != 0.0:
            continue
        impact = next(i for i in h.impacts if math.hypot(i.event.x - turn.pivot.x, i.event.t - turn.pivot.t)
                      <= ONE_INSTANT * (h.scenario.L + abs(i.event.t)))
        far = "left" if turn.pivot_end == "right" else "right"
        return h, impact, far, turn.pivot.t / h.scenario.L, turn.pivot.t / h.scenario.L + 1.0
    return None


def introduction(histories: Sequence[RodHistory] = ()) -> Section:
    """The first section: Sears's paradox, the paper's resolution, and the rigid rod as an idealisation (with the
    numbers of the first scenario whose rod turns: when its far end moves, when light could reach it)."""
    idealisation = IDEALISATION
    numbers = far_end_and_light(histories)
    if numbers is not None:
        h, impact, far, moves, light = numbers
        idealisation += (f" In the scenario \u201c{heading(h)}\u201d, {impact_name(impact.label)} strikes the rod\u2019s "
                         f"{impact.end} end at t = {in_l(moves)} in S, and the {far} end starts to move at that same "
                         f"instant of S, while light from {impact_name(impact.label)} reaches it only at t = "
                         f"{in_l(light)}.")
    forces = (Paragraph(FORCES_INTRO.replace("'", "\u2019") + FORCES_RESOLUTION),) \
        if any(h.driving is not None for h in histories) else ()
    return Section("introduction", "The paradox", (Heading("The paradox and its resolution"), Paragraph(PARADOX),
                                                   Paragraph(RESOLUTION), Paragraph(idealisation), *forces))


#: the parts of a handout a teacher may choose (`build`'s `sections`), in the order they come: the paradox and its
#: resolution, each scenario's diagram and its explanation, the rod at successive instants, the events tables, the
#: ledger and hidden tables, the comparison with the causal rod (where its history is given), the rod's own view
#: (where the frames ask for it: `own_view`)
SECTIONS = ("paradox", "diagrams", "strips", "tables", "ledger", "comparison", "rod")


# --- the numbers -----------------------------------------------------------------------------------------------

def _table_unit(L: float) -> str:
    """How the tables give x and t: in units of L, or, for L other than 1, in the unit of length in which L is given."""
    return "in units of L" if L == 1.0 else f"in the unit of length in which L = {exact(L)}"


def _in_rods_order(history: RodHistory, table: Table, frame: Frame) -> Table:
    """A worksheet's events table: its rows in the rod's own order, without notes (the frame's order, and which
    impacts the rod takes together, are what the questions ask), and the velocities the set-up gives filled in:
    the rod's before its first impact (at rest in S, +v in S′), and in S each particle's before its first impact."""
    order = {impact_name(i.label): k for k, i in enumerate(history.impacts)}
    rows = sorted(table.rows, key=lambda row: order[row[0].text])
    particle, rod = table.header.index("particle before"), table.header.index("rod before")
    given = {(0, rod)} if frame.name in ("rest", "moving") else set()
    if frame.name == "rest":
        firsts = {}
        for k, row in enumerate(rows):
            firsts.setdefault(row[0].text[0], k)
        given |= {(k, particle) for k in firsts.values()}
    rows = [tuple(Cell(c.text) if (k, j) in given else c for j, c in enumerate(row)) for k, row in enumerate(rows)]
    return replace(table, caption=f"{table.caption}, in the rod's own order", notes=(), rows=tuple(rows))


def _worksheet_tables(history: RodHistory, frame: Frame, parts: frozenset[str] = frozenset(),
                      earlier: tuple[Frame, ...] = ()) -> tuple[list[Block], list[Block]]:
    """A worksheet's blank events table of the frame, and the filled tables its answer key prints (`_tables`): the
    ledger and hidden tables wait for the key, since a ledger's row of one instant ("B₁ and A₁") tells which impacts
    are simultaneous in the frame, and its slices' times tell when the impacts come. `earlier`: the section's frames
    before this one (`_tables`)."""
    symbol, time = frame_name(frame), time_name(frame)
    x = coordinates(frame)[0]
    unit = _table_unit(history.scenario.L)
    asked: list[Block] = [
        Paragraph(f"The impacts in {symbol}, in the rod's own order: fill in where and when each strikes ({x} and "
                  f"{time} {unit}), and the velocities (in units of c) of the particle and of the rod just before and "
                  f"just after it; those the set-up gives are filled in." if not earlier else
                  f"Fill in the impacts in {symbol} the same way, in the rod's own order ({x} and {time} {unit})."),
        _in_rods_order(history, tables.events_table(history, frame, blank=True), frame)]
    return asked, _tables(history, frame, blank=False, parts=parts or frozenset(SECTIONS), earlier=earlier)


def _tables(history: RodHistory, frame: Frame, blank: bool, parts: frozenset[str] = frozenset(SECTIONS),
            earlier: tuple[Frame, ...] = ()) -> list[Block]:
    """The frame's events, ledger and hidden tables (`tables.build`), each after the sentence that says how to read it;
    `blank`: a worksheet's copies, their numbers left to fill in; `parts`: the events tables with `tables`, the
    ledger and hidden ones with `ledger`; `earlier`: the section's frames before this one. A sentence says in full how
    to read a kind of table the first time the section prints one, and in short after (a teacher found the same
    paragraph twice on a page, for S and S′)."""
    return ((_events(history, frame, blank, earlier) if "tables" in parts else [])
            + (_ledger(history, frame, blank, earlier) if "ledger" in parts else []))


def _events(history: RodHistory, frame: Frame, blank: bool, earlier: tuple[Frame, ...] = ()) -> list[Block]:
    symbol, time = frame_name(frame), time_name(frame)
    x = coordinates(frame)[0]
    unit = _table_unit(history.scenario.L)
    return [
        Paragraph(f"The impacts in {symbol}, in the order of its time: where and when each strikes ({x} and {time} "
                  f"{unit}), and the velocities (in units of c) of the particle and of the rod just before and just "
                  f"after it." if not earlier else
                  f"The impacts in {symbol}, in the order of its time, in the same columns ({x} and {time} {unit})."),
        tables.events_table(history, frame, blank)]


def _ledger(history: RodHistory, frame: Frame, blank: bool, earlier: tuple[Frame, ...] = ()) -> list[Block]:
    symbol, time = frame_name(frame), time_name(frame)
    blocks: list[Block] = [
        Paragraph(f"The ledger in {symbol}: at each instant of {symbol} at which the rod is struck (impacts at one "
                  f"instant taken together), the energy E and momentum p just before and just after of each "
                  f"particle, of the rod's motion (its kinetic part, the sum over its material points on the slice "
                  f"{time} = constant) and the hidden part (what the rod's stress carries); the note under the table "
                  f"says how they add up, and what the rod's dynamical row, shown apart, is." if not earlier else
                  f"The ledger in {symbol}, read the same way, the rod's kinetic part summed on the slice "
                  f"{time} = constant."),
        tables.ledger_table(history, frame, blank),
    ]
    hidden = tables.hidden_table(history, frame, blank)
    if hidden is None:
        blocks.append(Paragraph(f"In {symbol} the hidden part is zero on every slice between impacts: at every "
                                f"instant of {symbol} the bodies' own motion carries all the energy and momentum."))
    else:
        blocks += [Paragraph(f"The hidden part in {symbol} on a slice halfway between each two consecutive changes "
                             f"(impacts, the start or end of a turn), where it is not zero: energy and momentum that "
                             f"no body's motion shows, held by the stress in the rod."
                             if all(tables.hidden_table(history, f, blank) is None for f in earlier) else
                             f"The hidden part in {symbol}, where it is not zero, on a slice halfway between each two "
                             f"consecutive changes."), hidden]
    return blocks


# --- the document ----------------------------------------------------------------------------------------------

def _section(stem: str, history: RodHistory, frames: tuple[Frame, ...], worksheet: bool,
             with_speed: bool = False, compare_v: float | None = None,
             chosen: Sequence[int] | None = None, equal_scales: bool = False,
             causal=None, parts: frozenset[str] = frozenset(SECTIONS)) -> tuple[Section, list[Block]]:
    """One scenario's section, and for a worksheet its part of the answer key (a heading, the filled tables and
    the questions again). A worksheet asks and never tells before its key: the explanation, the caption's sentences
    on which impacts share a line, and the strips (their row labels and colour bars give velocities) move to the
    key; the tables are left blank. With the `causal` rod's history, the section ends with the comparison of the
    two rods (`causal_compare`), and a worksheet with its questions (`worksheet_causal`)."""
    if history.driving is not None:  # a rod driven by forces: Sears's own paradox (`forces`)
        return _forces_section(stem, history, frames, worksheet, with_speed, equal_scales, causal, parts, chosen)
    caption = diagram_caption(history, frames, tell=not worksheet)
    if equal_scales and len(frames) > 1:
        caption += " The panels are drawn to one scale: a length of L is as long on the page in each."
    diagram = DiagramBlock(f"{stem}_diagram", history, frames, caption, tell=not worksheet, equal_scales=equal_scales)
    title = neutral_heading if worksheet else heading
    blocks: list[Block] = [Heading(title(history, with_speed)), Paragraph(setup_text(history, tell=not worksheet))]
    told: list[Block] = []
    if "diagrams" in parts:
        blocks.append(diagram)
        told += [Heading("What the diagram shows", 2), *explanation(history, frames)]
    for f in frames if "strips" in parts else ():  # each frame's strips under a heading naming it, so a block
        times = strip_times(history, f)            # that starts a page says its frame
        told.append(Heading(f"The rod at successive instants of {frame_name(f)}", 2))
        told.append(Strips(f"{stem}_strips_{frame_word(f)}", history, f, times, strips_caption(history, f, times)))
    if not worksheet:
        blocks += told
    if parts & {"tables", "ledger"}:
        blocks.append(Heading("The numbers", 2))
    filled: list[Block] = []
    for f in frames:
        if worksheet:
            asked_tables, key_tables = _worksheet_tables(history, f, parts, earlier=frames[:frames.index(f)])
            blocks += asked_tables
            # the key's tables named after the section (their LaTeX files fig2_ledger_rest_key.tex, one per scenario)
            filled += [replace(b, name=f"{stem}_{b.name}_key") if isinstance(b, Table) else b for b in key_tables]
        else:
            blocks += _tables(history, f, blank=False, parts=parts, earlier=frames[:frames.index(f)])
    section_title = title(history, with_speed=True)
    key: list[Block] = []
    compared: tuple[list[Block], list[Block]] = ([], [])
    numbers = compare(history, causal, frames) if causal is not None and "comparison" in parts else None
    if numbers is not None:
        compared = comparison(numbers, history, causal, frames, stem, worksheet, equal_scales)
        if not worksheet:
            blocks += compared[0]
    if worksheet:
        asked = questions(history, frames, compare_v, chosen)
        blocks.append(Heading("Questions", 2))
        blocks += asked
        if numbers is not None:
            more = causal_questions(numbers, len(asked) + 1, tabled=any(f.name == "rest" for f in frames))
            blocks += compared[0] + [Heading("Questions on the causal rod", 2), *more]
            asked += more
            compared = ([], [replace(b, name=f"{stem}_{b.name}_key") if isinstance(b, Table) else b
                             for b in compared[1]])
        # the key: the scenario's own title and set-up (which may say what the questions asked), the numbers
        key += [Heading(heading(history, with_speed=True), 2), Paragraph(setup_text(history)),
                *([Heading("The numbers", 2), *filled] if filled else []), Heading("Questions and answers", 2)]
        key += asked
        key += told
        key += compared[1]
    return Section(stem, section_title, tuple(blocks)), key


def _forces_section(stem: str, history: RodHistory, frames: tuple[Frame, ...], worksheet: bool, with_speed: bool,
                    equal_scales: bool, causal, parts: frozenset[str],
                    chosen: Sequence[int] | None = None) -> tuple[Section, list[Block]]:
    """A rod driven by forces: its section (`forces.section_blocks`), and for a worksheet its part of the key."""
    causal = causal if "comparison" in parts else None
    if worksheet:
        blocks, key = forces.worksheet_blocks(stem, history, frames, causal, parts, heading(history, with_speed),
                                              heading(history, with_speed=True), chosen, equal_scales)
        return Section(stem, heading(history, with_speed=True), tuple(blocks)), key
    blocks = forces.section_blocks(stem, history, frames, causal, parts, heading(history, with_speed), worksheet,
                                   equal_scales)
    return Section(stem, heading(history, with_speed=True), tuple(blocks)), []


@dataclass(frozen=True)
class Item:
    """One scenario of a handout: its file stem (fig2), its rigid rod's history, the frames its section shows (None:
    S and S′ of its own v, or `build`'s), and its causal rod's history to compare with (None: no comparison)."""

    stem: str
    history: RodHistory
    frames: tuple[Frame, ...] | None = None
    causal: object = None


def build(items: Sequence[Item | tuple], frames: Sequence[Frame] | None = None, worksheet: bool = False,
          compare_v: float | None = None, chosen: Sequence[int] | None = None, equal_scales: bool = False,
          sections: Sequence[str] = SECTIONS) -> Handout:
    """The handout (or, with `worksheet`, the worksheet and its answer key) of each (stem, history) item, one
    section each, in order. `frames` defaults to S and S′ of each scenario; a frame named `moving` is S′ of each
    scenario's own v. An item may also be (stem, history, frames), its own frames overriding `frames` (None: not),
    or (stem, history, frames, causal), the causal rod's history of the same scenario: the section then compares
    the two rods (docs/handout.md, "Teaching handouts").
    `equal_scales`: each diagram's panels drawn to one scale (`render.Options.equal_scales`)."""
    parts = frozenset(sections)
    unknown = parts - set(SECTIONS)
    if unknown:
        raise ValueError(f"unknown handout sections {sorted(unknown)}; the sections are {', '.join(SECTIONS)}")
    entries = []
    for item in items:
        item = item if isinstance(item, Item) else Item(*item)
        if item.frames is not None:
            shown_frames = tuple(item.frames)
        elif frames is None:
            shown_frames = paper_frames(item.history.scenario.v)
        else:
            shown_frames = tuple(moving_frame(item.history.scenario.v) if f.name == "moving" else f for f in frames)
        entries.append(replace(item, frames=shown_frames))
    first = introduction([e.history for e in entries])
    driven = any(e.history.driving is not None for e in entries)
    opening = [worksheet_introduction(driven) if worksheet else first] if "paradox" in parts else []
    key: list[Block] = []
    several_speeds = len({_speed(e.history) for e in entries}) > 1
    body = []
    for e in entries:
        section, answers = _section(e.stem, e.history, e.frames, worksheet, several_speeds, compare_v, chosen,
                                    equal_scales, e.causal, parts)
        body.append(section)
        key += answers
    resolution = first.blocks[1:] if "paradox" in parts else ()  # the paradox, its resolution and the idealisation
    answer_key = ((Heading("Answer key"), *((Heading("The paradox and its resolution", 2),) if resolution else ()),
                   *resolution, *key) if worksheet else ())
    return Handout(title([(e.stem, e.history) for e in entries]), tuple(opening + body), worksheet,
                   tuple(answer_key))
