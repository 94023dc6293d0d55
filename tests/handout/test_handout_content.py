"""What a handout and a worksheet say (`rodparadox.handout`: build, narrative, strips, worksheet), checked against
hand derivations, never against the code's own output: Fig. 2 and Fig. 1 at v = 0.6 in closed form (the numbers are
derived in the comments), the worksheet's answers against an independent numpy computation from the events, and the
shape of the document."""

from __future__ import annotations

from dataclasses import replace

import functools
import math
import re
import subprocess
import sys

import numpy as np
import pytest

from rodparadox.handout.build import build
from rodparadox.handout.narrative import explanation, setup_text
from rodparadox.handout.strips import strip_times, strips_caption
from rodparadox.handout.worksheet import questions
from rodparadox.tables import build as tables
from rodparadox.handout.document import DiagramBlock, Handout, Heading, Paragraph, Question, Strips, Table
from rodparadox.physics.rigid import run
from rodparadox.physics.frames import frame_of_velocity, moving_frame, paper_frames, rest_frame, time_window
from rodparadox.physics.rod import rod_slice
from rodparadox.io.scenario import load, parse

from helpers import particle_presets


@functools.lru_cache(maxsize=None)
def history(name: str, v: float | None = None):
    """The preset's rigid rod at v (None: its own), run once per process: a history is immutable, and what it works
    out when first asked (its world-lines, their pieces) is then worked out once for every test that reads it."""
    scenario = load(name)
    return run(scenario.with_overrides(v=v) if v is not None else scenario)


# --- the shared tables: the rod's own order at one instant of a frame -----------------------------------

def test_tables_list_impacts_at_one_instant_in_the_rods_own_order():
    # Fig. 2 at v = 0.6: B1 and A1 share t' = 17/12 in S', but the rod takes B1 first (B1 comes first in S,
    # the rod's rest frame until then); the events and ledger tables must list B1, then A1, then B2
    h = history("fig2", 0.6)
    moving = paper_frames(0.6)[1]
    assert [row[0].text for row in tables.events_table(h, moving).rows] == ["B₁", "A₁", "B₂"]
    assert [row[0].text for row in tables.ledger_table(h, moving).rows if row[0].text] == ["B₁ and A₁", "B₂"]
    # and the rod's (dynamical) E runs 1.25 -> 1 at B1 (+0.6 to rest in S'), then 1 -> 17/8 at A1 (rest to 15/17:
    # gamma = 17/8)
    # at one instant of S' they are one row group: the rod's dynamical E goes 1.25 -> 2.125 across both
    rod = [row for row in tables.ledger_table(h, moving).rows if row[2].text == tables.ROD_DYNAMICAL]
    assert (rod[0][3].text, rod[0][5].text) == ("1.2500", "2.1250")


# --- the handout ------------------------------------------------------------------------------------------------

SPEEDS = (0.3, 0.6, 0.95)


def section_blocks(doc: Handout, kind) -> list:
    return [b for s in doc.sections for b in s.blocks if isinstance(b, kind)]


def explanation_text(name: str, v: float) -> str:
    return " ".join(p.text for p in explanation(history(name, v), paper_frames(v)))


def sentences(text: str) -> list[str]:
    return re.split(r"(?<=\.) (?=[A-Z])", text)


def test_fig2_explanation_says_b1_and_a1_share_t_prime_17_12_and_not_t():
    # Fig. 2 at v = 0.6, g = 1.25. B starts L/2 right of the right end: t_B1 = (L/2)/v = 5/6 L at x = L/2.
    # A is timed to strike at the same t' = g(t + v x) as B1: t'_B1 = 1.25 (5/6 + 0.3) = 17/12 L.
    # In S the rod turns about B1 and its left end, on the hyperbola of radius L, meets A at t_A1 = t_B1 + g v L
    # = 5/6 + 3/4 = 19/12 L (x = -3/4 L): t'_A1 = 1.25 (19/12 - 0.45) = 17/12 L, the same.
    text = explanation_text("fig2", 0.6)
    shared = [s for s in sentences(text) if "B₁ and A₁ lie on one line of simultaneity of S′" in s]
    assert len(shared) == 1 and "17/12 L" in shared[0] and "own" in shared[0]  # not on the rod's own line
    apart = next(s for s in sentences(text) if s.startswith("They are not simultaneous in S,"))
    assert "5/6 L" in apart and "19/12 L" in apart and "0.75 L later" in apart
    # S' order: B1 and A1 together, then B2 at t' = g(7/3 + 0.6 * 0.5) = 79/24 L
    # each time said once (issue 24): the order does not repeat the times the sentences before it gave
    assert "in S B₁, then A₁, then B₂ (t = 7/3 L); in S′ B₁ and A₁ together, then B₂ (t′ = 79/24 L)" in text
    told = " ".join(b.text for b in explanation(history("fig2", 0.6), paper_frames(0.6))[:2])
    assert told.count("17/12 L") == 1 and told.count("19/12 L") == 1 and told.count("79/24 L") == 1


def test_fig2_explanation_gives_the_rods_velocity_after_a1_in_s_prime_as_15_17():
    # after A1 the rod moves at +v = +0.6 in S; in S' (velocity -0.6 relative to S) that is
    # (0.6 + 0.6)/(1 + 0.36) = 1.2/1.36 = 15/17
    text = explanation_text("fig2", 0.6)
    in_s_prime = next(s for s in sentences(text) if s.startswith("In S′, in the rod's own order"))
    assert "+15/17 c after A₁" in in_s_prime
    assert "0 after B₁;" in in_s_prime  # B, at rest in S', takes all of the rod's +0.6 (equal masses)
    in_s = next(s for s in sentences(text) if s.startswith("In S, in the rod's own order"))
    assert "−0.6 c after B₁; +0.6 c after A₁; 0 after B₂" in in_s
    # the turn B1 starts ends on A1's line, t' = 17/12: there the whole rod is at rest in S', at full length
    assert "In S′ the whole rod is at rest at the instant t′ = 17/12 L, at its full length L" in text
    # check it on the rod itself: on the slice t' = 17/12 of S' every material point inside the rod has velocity 0
    # in S' (its ends are at the kinks of B1 and A1 just then), and the ends are L apart; a little before and
    # after, some points move
    h = history("fig2", 0.6)
    eta = math.atanh(-0.6)
    sigma = np.linspace(0.0, 1.0, 41)
    now = rod_slice(h, eta, 17 / 12, sigma)  # rapidities in S'
    assert np.allclose(now.rapidity[1:-1], 0.0, atol=1e-9) and now.x[-1] - now.x[0] == pytest.approx(1.0, abs=1e-9)
    for t in (17 / 12 - 0.05, 17 / 12 + 0.05):
        assert np.ptp(rod_slice(h, eta, t, sigma).rapidity[1:-1]) > 1e-3


def test_fig1_explanation_simultaneous_in_s_not_in_s_prime_and_the_rod_keeps_plus_v():
    # Fig. 1 at v = 0.6: both particles L/2 from their ends, both at 0.6: t_A1 = t_B1 = 5/6 L at x = -/+ 1/2 L.
    # In S': t'_A1 = 1.25 (5/6 - 0.3) = 2/3 L, t'_B1 = 1.25 (5/6 + 0.3) = 17/12 L, 3/4 L apart.
    # The rod takes both on one line of its own simultaneity (constant t: it is at rest in S), and equal and
    # opposite impulses cancel: its velocity stays 0 in S and +0.6 in S'.
    text = explanation_text("fig1", 0.6)
    assert "A₁ and B₁ lie on one line of simultaneity of S (t = 5/6 L)" in text
    assert "They are not simultaneous in S′, where A₁ comes at t′ = 2/3 L and B₁ at 17/12 L, 0.75 L later" in text
    assert "It never changes: it is 0 in S and +0.6 c in S′ before, between and after the impacts" in text
    # between them in S' A has stopped (0 in S') and B is not yet struck; the rod moves on at +0.6 (p = g v M =
    # 0.75 M c), so the hidden momentum is A's momentum before: m g' u' with u' = 15/17, g' = 17/8: 15/8 M c,
    # a decimal that ends, so written 1.875
    assert "the momentum A gave up, 1.875 M c, is carried by the stress in the rod" in text


def test_the_explanation_differs_between_fig1_and_fig2():
    assert explanation_text("fig1", 0.6) != explanation_text("fig2", 0.6)


def rod_velocities_in_s(h) -> list[float]:
    """The rod's velocity in S before the first impact and after each, from the impacts' rapidities."""
    out = [0.0]
    for i in h.impacts:
        u = math.tanh(i.rod_rapidity_after)
        if abs(u - out[-1]) > 1e-12:
            out.append(u)
    return out


def changes_direction_more_than_once(velocities: list[float]) -> bool:
    """Its velocity changes direction more than once (down, up, down), or comes back to a value it had."""
    steps = [b - a for a, b in zip(velocities, velocities[1:])]
    reversals = sum(1 for a, b in zip(steps, steps[1:]) if a * b < 0)
    back = any(abs(velocities[j] - velocities[i]) < 1e-12 for i in range(len(velocities))
               for j in range(i + 2, len(velocities)))
    return reversals > 1 or back


@pytest.mark.parametrize("v", SPEEDS)
@pytest.mark.parametrize("name", particle_presets())
def test_a_zig_zag_is_mentioned_only_where_the_rods_velocity_in_s_goes_back_and_forth(name, v):
    h = history(name, v)
    text = explanation_text(name, v)
    assert ("zig-zag" in text) == changes_direction_more_than_once(rod_velocities_in_s(h))


def test_the_built_in_scenarios_zig_zag_as_the_readme_says():
    # fig2, off_timing and while_turning: 0 -> -v -> +v -> 0 in S; fig1, single, unequal_masses do not
    assert {n for n in particle_presets() if "zig-zag" in explanation_text(n, 0.6)} == {"fig2", "off_timing",
                                                                                  "while_turning"}


@pytest.mark.parametrize("name", particle_presets())
def test_the_setup_paragraph_names_each_particles_mass_speed_end_and_start(name):
    h = history(name)
    text = setup_text(h)
    s = h.scenario
    assert f"L = {s.L:g}" in text and f"v = {s.v:g}" in text and "at rest in S" in text and "S′" in text
    for p in s.particles:
        mass = "mass M" if p.mass == 1 else f"mass {p.mass:g} M"
        direction = "right" if p.name == "A" else "left"
        end = "left" if p.name == "A" else "right"
        assert f"Particle {p.name}, of {mass}, moves {direction} at {s.speed(p):g} c in S towards the rod's {end} end" \
            in text
        if p.gap is not None:
            assert f"starting {p.gap:g} L from it at t = 0" in text
        else:
            frame = {"rest": "S", "moving": "S′"}[p.timed_with.frame]
            assert (f"{p.timed_with.delay:g} L after" in text if p.timed_with.delay else "at the same instant" in text)
            assert frame in text


def test_the_setup_paragraph_of_fig2_places_a_as_the_paper_does():
    # the paper's (12): x_A = -g L (1 + v^2) + v t, so at t = 0 A is at -1.25 * 1.36 = -1.7 L: 1.2 L from the
    # left end at -L/2
    assert "so at t = 0 it is 1.2 L from that end" in setup_text(history("fig2", 0.6))


# --- strips ---------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("v", SPEEDS)
@pytest.mark.parametrize("name", particle_presets())
def test_strips_show_six_to_eight_instants_in_the_window_earliest_first(name, v):
    h = history(name, v)
    for f in paper_frames(v):
        times = strip_times(h, f)
        lo, hi = time_window(h, f)
        assert 6 <= len(times) <= 8
        assert list(times) == sorted(times) and len(set(times)) == len(times)
        assert all(lo <= t <= hi for t in times)
        impacts = [i.event.time_in(f.rapidity) for i in h.impacts]
        assert min(times) < min(impacts) and max(times) > max(impacts)  # before the first and after the last
        for t in impacts:  # each impact's instant is shown (to the page's resolution)
            assert min(abs(t - s) for s in times) <= 0.02 * (hi - lo)


def test_the_strips_caption_of_fig2_says_the_left_end_moves_first_in_s_prime():
    # in S' the rod's line of simultaneity through B1 (t = 5/6 in S) reaches the left end (x = -1/2) at
    # t' = 1.25 (5/6 - 0.3) = 2/3 L, before B1 at 17/12 L; it slows from +0.6 to 0 until 17/12 L
    h = history("fig2", 0.6)
    moving = paper_frames(0.6)[1]
    caption = strips_caption(h, moving, strip_times(h, moving))
    assert "The left end moves first, at t′ = 2/3 L: before B₁ strikes the right end (at 17/12 L)" in caption
    assert "from +0.6 c to rest by t′ = 17/12 L" in caption
    rest = paper_frames(0.6)[0]
    caption = strips_caption(h, rest, strip_times(h, rest))
    assert "Both ends start to change velocity at t = 5/6 L" in caption
    assert "the right end is struck by B₁ and starts moving left at 0.6 c at once" in caption


# --- the document -------------------------------------------------------------------------------------------

def test_a_handout_has_a_section_per_scenario_in_order_and_a_title_naming_them():
    items = [(n, history(n, 0.6)) for n in ("fig1", "fig2", "single")]
    doc = build(items)
    # issue 14: the title names no internal stems; a first section states the paradox
    assert doc.title == "The Sears paradox, at v = 0.6"
    assert [s.name for s in doc.sections] == ["introduction", "fig1", "fig2", "single"]
    assert not doc.worksheet and doc.answer_key == ()
    assert not any(isinstance(b, Question) for b in doc.blocks())
    assert build([("fig2", history("fig2", 0.6))]).title == "The Sears paradox, at v = 0.6"
    several = build([("a", history("fig1", 0.6)), ("b", history("fig2", 0.8))])
    assert several.title == "The Sears paradox"
    assert [s.blocks[0].text for s in several.sections[1:]] == [
        "Impacts simultaneous in the rod's rest frame (the paper's Fig. 1), at v = 0.6",
        "Impacts simultaneous in the moving frame (the paper's Fig. 2), at v = 0.8"]


def test_a_section_holds_its_blocks_in_the_order_of_the_issue():
    h = history("fig2", 0.6)
    section = build([("fig2", h)]).sections[1]
    kinds = [type(b) for b in section.blocks]
    assert kinds[:3] == [Heading, Paragraph, DiagramBlock]
    assert section.blocks[0].text == "Impacts simultaneous in the moving frame (the paper's Fig. 2)"
    diagram = section.blocks[2]
    assert diagram.name == "fig2_diagram" and diagram.frames == paper_frames(0.6) and diagram.history == h
    assert "B₁ and A₁ share one dash-dotted line, of S′." in diagram.caption  # when: the explanation says
    strips = [b for b in section.blocks if isinstance(b, Strips)]
    assert [s.name for s in strips] == ["fig2_strips_rest", "fig2_strips_moving"]
    tables_ = [b.name for b in section.blocks if isinstance(b, Table)]
    assert tables_ == ["events_rest", "ledger_rest", "hidden_rest", "events_moving", "ledger_moving", "hidden_moving"]
    # each table is preceded by the sentence that says how to read it
    for k, b in enumerate(section.blocks):
        if isinstance(b, Table):
            assert isinstance(section.blocks[k - 1], Paragraph)
    # explanation paragraphs between the diagram and the strips: one to three
    first_strip = kinds.index(Strips)
    explanation = [b for b in section.blocks[3:first_strip] if isinstance(b, Paragraph)]
    assert 1 <= len(explanation) <= 3


def test_where_the_hidden_part_is_zero_in_a_frame_a_sentence_says_so():
    # Fig. 1 in S: both impulses at once on the rod's own line (constant t), no turn: nothing is ever hidden
    section = build([("fig1", history("fig1", 0.6))]).sections[1]
    names = [b.name for b in section.blocks if isinstance(b, Table)]
    assert "hidden_rest" not in names and "hidden_moving" in names
    assert any(isinstance(b, Paragraph) and b.text.startswith("In S the hidden part is zero on every slice")
               for b in section.blocks)


def numeric(cell_text: str) -> bool:
    return bool(re.search(r"\d", cell_text)) and not re.fullmatch(r"[A-Z][₀-₉]+", cell_text)


@pytest.mark.parametrize("name", particle_presets())
def test_a_worksheet_leaves_every_number_blank_and_its_answer_key_fills_them(name):
    h = history(name, 0.6)
    doc = build([(name, h)], worksheet=True)
    assert doc.worksheet
    in_section = section_blocks(doc, Table)
    assert in_section
    v = h.scenario.v
    for table in in_section:
        seen = set()
        for k, row in enumerate(table.rows):
            for column, cell in zip(table.header, row):
                slice_time = table.name.startswith("hidden") and cell is row[0]  # where the values are taken
                # what the set-up gives stays filled: the rod's velocity before its first impact (0 in S, +v in
                # S′) and, in S, each particle's before its first impact (A at +v, B at −v)
                given = ((k == 0 and column == "rod before") or
                         (table.name == "events_rest" and column == "particle before" and row[0].text[0] not in seen))
                if numeric(cell.text) and not slice_time and not given:
                    assert cell.blank, (table.name, cell.text)  # every value to fill in is blank
                if given:
                    expected = (0.0 if table.name == "events_rest" else v) if column == "rod before" else \
                        (v if row[0].text[0] == "A" else -v)
                    assert not cell.blank and float(cell.text.split()[0].replace("−", "-")) == pytest.approx(
                        expected, abs=1e-6), (table.name, column, cell.text)
                if cell.text in ("left", "right", "particle A", "particle B", "rod", "hidden"):
                    assert not cell.blank  # labels stay
            seen.add(row[0].text[0])
    key = doc.answer_key
    assert isinstance(key[0], Heading) and key[0].text == "Answer key"
    # the worksheet asks for the events in the rod's own order; its key prints the handout's tables, filled
    assert [t.name for t in in_section] == [f"events_{w}" for w in ("rest", "moving")]
    key_tables = [b for b in key if isinstance(b, Table)]
    assert [replace(t, name=f"{name}_{t.name}_key") for t in section_blocks(build([(name, h)]), Table)] == key_tables
    asked = [b for b in section_blocks(doc, Question)]
    assert 5 <= len(asked) <= 8
    assert [b for b in key if isinstance(b, Question)] == asked
    assert all(q.answer for q in asked)


def test_the_handout_tables_are_the_same_numbers_filled():
    h = history("fig2", 0.6)
    plain = [t for t in section_blocks(build([("fig2", h)]), Table) if t.name.startswith("events")]
    sheet = section_blocks(build([("fig2", h)], worksheet=True), Table)
    assert [t.name for t in plain] == [t.name for t in sheet]
    for table, asked in zip(plain, sheet):
        # the same rows, in the rod's own order (B1, A1, B2), with no notes (which impacts it takes together)
        assert [row[0].text for row in asked.rows] == ["B₁", "A₁", "B₂"] and asked.notes == ()
        assert sorted(asked.filled().rows, key=str) == sorted(table.rows, key=str)
    assert not any(t.has_blanks for t in plain)


def test_questions_are_numbered_from_one_and_the_same_on_every_build():
    h = history("fig2", 0.6)
    asked = questions(h, paper_frames(0.6))
    assert [q.number for q in asked] == list(range(1, len(asked) + 1))
    again = history.__wrapped__("fig2", 0.6)  # a run of its own, not the kept one
    assert again is not h
    assert asked == questions(again, paper_frames(0.6))
    assert build([("fig2", h)], worksheet=True) == build([("fig2", again)], worksheet=True)


def test_items_may_carry_their_own_frames_and_moving_means_each_scenarios_own_s_prime():
    a, b = history("fig1", 0.6), history("fig2", 0.8)
    doc = build([("a", a), ("b", b)], frames=(rest_frame(), moving_frame(0.6)))
    diagrams = section_blocks(doc, DiagramBlock)
    assert [d.frames[1].velocity for d in diagrams] == [-0.6, -0.8]
    doc = build([("a", a, (rest_frame(), moving_frame(0.6), frame_of_velocity(0.3)))])
    assert [s.name for s in section_blocks(doc, Strips)] == ["a_strips_rest", "a_strips_moving", "a_strips_u0.3"]


def test_the_module_is_pure():
    code = "import sys, rodparadox.handout.build; assert 'matplotlib' not in sys.modules, 'matplotlib imported'"
    subprocess.run([sys.executable, "-c", code], check=True)


# --- worked answers against an independent computation from the events ------------------------------------------

_SUPERSCRIPTS = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")
_NUMBER = re.compile(r"(?<![\d./])(\d+)/(\d+)(?![\d.])|(?<![\d.])(\d+(?:\.\d+)?)(?:×10([⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+))?")


def quoted_numbers(text: str) -> list[float]:
    """Every number written in a text, as its size: 17/12, 1.416667, 2.5×10⁻⁶ (a minus may be an operator, so sizes
    are compared; the signs are checked by the tests of particular answers)."""
    out = []
    for m in _NUMBER.finditer(text):
        if m.group(1):
            out.append(int(m.group(1)) / int(m.group(2)))
        else:
            exponent = int(m.group(4).translate(_SUPERSCRIPTS)) if m.group(4) else 0
            out.append(float(m.group(3)) * 10.0 ** exponent)
    return out


def boost_to_moving(x, t, v):
    """S′ moves at −v relative to S, so (by hand from the boost x' = g(x − u t), t' = g(t − u x) with u = −v)
    x′ = g(x + v t), t′ = g(t + v x)."""
    g = 1.0 / np.sqrt(1.0 - v * v)
    return g * (x + v * t), g * (t + v * x)


def add_moving(u, v):
    """A velocity u in S seen from S′ (velocity −v relative to S): (u + v)/(1 + u v)."""
    return (u + v) / (1.0 + u * v)


def momentum(m, u):
    return m * u / np.sqrt(1.0 - u * u)


def energy(m, u):
    return m / np.sqrt(1.0 - u * u)


class Independent:
    """The numbers a worked answer may quote, computed here with numpy from the impacts' coordinates and velocities
    in S (and, for the hidden part on a slice, a trapezoid sum over the rod's material points, not the ledger's
    closed form)."""

    def __init__(self):
        self.values: list[tuple[float, float]] = []  # (value, absolute tolerance beyond rounding)

    def add(self, *values, slack: float = 0.0):
        for value in values:
            self.values.append((abs(float(value)), slack))

    def holds(self, quoted: float) -> bool:
        # 7 significant digits: within 5e-7 relative, with a little room for the last digit of a difference
        return any(abs(quoted - value) <= 1e-6 * max(value, quoted) + slack + 1e-12 for value, slack in self.values)

    def scenario(self, h, v):
        s = h.scenario
        g = 1.0 / np.sqrt(1.0 - v * v)
        self.add(0, 1, 2, v, g, 1 / g, s.L, *(p.mass for p in s.particles))
        x = np.array([i.event.x for i in h.impacts])
        t = np.array([i.event.t for i in h.impacts])
        xp, tp = boost_to_moving(x, t, v)
        self.add(*x, *t, *xp, *tp, *(t + v * x), *(x + v * t), *(t * t - x * x))
        for a in range(len(x)):
            for b in range(len(x)):
                dx, dt = x[b] - x[a], t[b] - t[a]
                self.add(dx, dt, tp[b] - tp[a], dx * dx - dt * dt)
                if dx:
                    self.add(dt / dx)
        velocities = []  # the events table's velocities in S
        for i in h.impacts:
            m = s.particle(i.particle).mass
            for u, mass in ((np.tanh(i.particle_rapidity_before), m), (np.tanh(i.particle_rapidity_after), m),
                            (np.tanh(i.rod_rapidity_before), 1.0), (np.tanh(i.rod_rapidity_after), 1.0)):
                velocities.append((u, mass))
        for u, mass in velocities:
            gu = 1 / np.sqrt(1 - u * u)
            self.add(u, add_moving(u, v), u + v, 1 + u * v, momentum(mass, u), momentum(mass, add_moving(u, v)),
                     gu, gu * u, gu * u * u, 1 / gu)
        # momentum before and after each collision, in S
        by_collision = {}
        for i in h.impacts:
            by_collision.setdefault(i.collision, []).append(i)
        for c in by_collision.values():
            masses = [s.particle(i.particle).mass for i in c]
            before = sum(momentum(m, np.tanh(i.particle_rapidity_before)) for m, i in zip(masses, c))
            after = sum(momentum(m, np.tanh(i.particle_rapidity_after)) for m, i in zip(masses, c))
            self.add(before + momentum(1, np.tanh(c[0].rod_rapidity_before)),
                     after + momentum(1, np.tanh(c[-1].rod_rapidity_after)))
        return self

    def slice_of_moving(self, h, v, t_slice):
        """Each body's momentum and energy on the slice t′ = t_slice of S′, their sums, the total before the first
        impact, and the hidden part: from the events (the particles) and a trapezoid sum over the rod."""
        s = h.scenario
        starts = {p.name: (1 if p.name == "A" else -1) * s.speed(p) for p in s.particles}
        total_p = momentum(1, v) + sum(momentum(p.mass, add_moving(starts[p.name], v)) for p in s.particles)
        total_E = energy(1, v) + sum(energy(p.mass, add_moving(starts[p.name], v)) for p in s.particles)
        kinetic_p = kinetic_E = 0.0
        for p in s.particles:
            u = starts[p.name]
            for i in h.impacts:  # the particle's velocity after its last impact before the slice
                _, ti = boost_to_moving(i.event.x, i.event.t, v)
                if i.particle == p.name and ti < t_slice:
                    u = np.tanh(i.particle_rapidity_after)
            u = add_moving(u, v)
            self.add(u, momentum(p.mass, u))
            kinetic_p, kinetic_E = kinetic_p + momentum(p.mass, u), kinetic_E + energy(p.mass, u)
        sigma = np.linspace(0.0, s.L, 3201)
        rapidity = rod_slice(h, math.atanh(-v), t_slice, sigma).rapidity
        rod_p = np.trapezoid(np.sinh(rapidity), sigma) / s.L
        rod_E = np.trapezoid(np.cosh(rapidity), sigma) / s.L
        slack = 1e-6  # the trapezoid sum's error, about 3e-8 at 3201 points (measured against quadrature)
        self.add(rod_p, kinetic_p + rod_p, total_p - kinetic_p - rod_p, total_E - kinetic_E - rod_E, slack=slack)
        self.add(total_p, total_E)
        return self


@pytest.mark.parametrize("v", SPEEDS)
@pytest.mark.parametrize("name", particle_presets())
def test_every_number_in_a_worked_answer_is_an_independent_computation(name, v):
    h = history(name, v)
    asked = questions(h, paper_frames(v))
    assert 5 <= len(asked) <= 8
    allowed = Independent().scenario(h, v)
    for q in asked:
        sliced = re.search(r"On the slice t′ = ([\d./]+) L of S′", q.text)
        if sliced:
            allowed.slice_of_moving(h, v, quoted_numbers(sliced.group(1))[0] if "/" not in sliced.group(1)
                                    else eval(sliced.group(1)))
        other = re.search(r"Now take v = ([\d.]+) instead", q.text)
        if other:
            allowed.scenario(history(name, float(other.group(1))), float(other.group(1)))
    for q in asked:
        for paragraph in q.answer:
            for number in quoted_numbers(paragraph):
                assert allowed.holds(number), (q.number, number, paragraph)


def answer_of(asked, starts: str) -> str:
    return " ".join(next(q for q in asked if q.text.startswith(starts)).answer)


def test_fig2_worked_answers_against_the_hand_derivation():
    asked = questions(history("fig2", 0.6), paper_frames(0.6))
    # the Lorentz transformation: g = 1.25, t' = g(t + 0.6 x): B1 1.25 (5/6 + 0.3) = 17/12, A1 1.25 (19/12 - 0.45)
    # = 17/12; simultaneous in S', 3/4 L apart in S
    lorentz = answer_of(asked, "In S, take the x and t of B₁ and of A₁ from your table of S")
    assert lorentz.startswith("In S, B₁ strikes at x = 0.5 L, t = 5/6 L; A₁ strikes at x = −0.75 L, t = 19/12 L.")
    assert "γ = 1/√(1 − w²) = 1/√(1 − 0.6²) = 1.25" in lorentz and "t′ = γ(t − w x) = γ(t + 0.6 x)" in lorentz
    assert "B₁: t′ = 1.25 × (5/6 + 0.6 × 0.5) L = 1.25 × 17/15 L = 17/12 L" in lorentz
    assert "A₁: t′ = 1.25 × (19/12 + 0.6 × (−0.75)) L = 1.25 × 17/15 L = 17/12 L" in lorentz
    assert "simultaneous in S′, while in S they are 0.75 L apart" in lorentz
    # velocity addition: (0.6 + 0.6)/(1 + 0.36) = 15/17 ≈ 0.8823529
    addition = answer_of(asked, "Take the rod's velocity after A₁ in S from your table of S")
    assert addition.startswith("After A₁ the rod moves at +0.6 c in S.")
    assert "= 1.2/1.36 = +15/17 c ≈ +0.8823529 c" in addition
    # at rest in S' at the instant t' = 17/12, full length L, contracted to L/g = 0.8 L before
    rest = answer_of(asked, "Is the whole rod ever at rest in S′")
    assert "at the one instant t′ = 17/12 L" in rest and "= 0.8 L" in rest
    # v = 0.8: A1 - B1 = g v L = (5/3)(0.8) = 4/3 L in S, and 0 in S' (A is timed so); the rod ends at rest
    other = answer_of(asked, "Now take v = 0.8 instead of 0.6")
    assert "At v = 0.8: A₁ comes 4/3 L after B₁ in S; B₁ and A₁ are " \
           "simultaneous in S′; the rod ends at rest in S" in other


def test_fig1_worked_answers_against_the_hand_derivation():
    asked = questions(history("fig1", 0.6), paper_frames(0.6))
    lorentz = answer_of(asked, "In S, take the x and t of A₁ and of B₁ from your table of S")
    assert lorentz.startswith("In S, A₁ strikes at x = −0.5 L, t = 5/6 L; B₁ strikes at x = 0.5 L, t = 5/6 L.")
    # t'_A1 = 1.25 (5/6 - 0.3) = 2/3, t'_B1 = 17/12: 3/4 L apart
    assert "= 2/3 L" in lorentz and "= 17/12 L" in lorentz and "in S′ B₁ comes 0.75 L after A₁" in lorentz
    # the hidden momentum between A1 and B1 in S': total 2.625 (A 15/8, B 0, rod 0.75) less the rod's 0.75 = 15/8
    hidden = answer_of(asked, "On the slice t′ = 25/24 L of S′,")
    assert "Hidden: 2.625 − 0.75 = 1.875 M c" in hidden
    together = answer_of(asked, "What is the rod's velocity in S′ from before A₁ and B₁")  # asked without their order
    assert together.startswith("+0.6 c, as before and after") and "0.75 M c and −0.75 M c, which cancel" in together


def test_a_stopped_turns_answer_is_the_far_ends_velocity_from_the_two_events():
    # while_turning at v = 0.6: B1 at (1/2, 5/6), A1 0.3 L later in S at the left end, on the hyperbola about B1
    # of radius L: dt = 0.3, dx = -sqrt(1 + 0.09) = -1.044031, velocity dt/dx = -0.2873479 (not -0.6)
    asked = questions(history("while_turning", 0.6), paper_frames(0.6))
    answer = answer_of(asked, "A₁ strikes the left end while the rod is still turning from B₁")
    dx = -math.sqrt(1.09)
    assert f"0.3/({dx:.7g}) = {0.3 / dx:.7g} c in S".replace("-", "−") in answer


def test_a_single_particles_answer_is_g_v_l():
    # single at v = 0.6: the left end follows on the hyperbola about B1 and reaches -0.6 after t - t_P = g v L
    # = 0.75 L, while the struck end moves 0.6 * 0.75 = 0.45 L to the left
    asked = questions(history("single", 0.6), paper_frames(0.6))
    answer = answer_of(asked, "B₁ gives the rod's momentum its velocity after B₁ (your table of S)")
    assert "takes 0.75 L of S's time" in answer and "moves 0.45 L to the left" in answer


# --- scenarios beyond the built-ins -----------------------------------------------------------------------------

HEAVY_B = """
name: heavy
v: 0.6
L: 2
particles:
  B: {mass: 5, gap: 0.5}
  A: {mass: 0.3, speed: 0.9, timed_with: {particle: B, frame: 0.3, delay: 0.4}}
"""


def test_a_re_strike_on_one_rod_line_is_told_as_such_and_turns_keep_their_own_cause():
    h = run(parse(HEAVY_B, "heavy.yaml", "heavy"))
    # the engine: A1 stops B1's turn; B, five times the rod's mass, sits at the pivot and strikes again at once
    # on A1's line (rule 7): B2 at B1's event, on one line of the rod's simultaneity with A1
    assert [i.label for i in h.impacts] == ["B1", "A1", "B2"] and h.impacts[1].simultaneous_with == "B2"
    assert (h.impacts[0].event.x, h.impacts[0].event.t) == (h.impacts[2].event.x, h.impacts[2].event.t)
    text = explanation_text_of(h, paper_frames(0.6))
    assert "no two lie on one line of its own simultaneity" not in text
    assert "A₁ and B₂ lie on one line of the rod's own simultaneity" in text
    assert "B₁ and B₂ happen at one event" in text
    assert "still turning from B₁:" in text  # the turn B1 started, not B2, which came after it
    # L = 2: the text gives multiples of L, the tables the unit of length in which L is given
    assert "the tables give them in the unit of length in which L = 2" in setup_text(h)
    # the timing frame given as a velocity
    assert "in the time of the frame of velocity +0.3 c relative to S" in setup_text(h)


def explanation_text_of(h, frames) -> str:
    return " ".join(p.text for p in explanation(h, frames))


def test_a_third_frame_is_named_the_frame_u_in_running_text():
    frames = paper_frames(0.6) + (frame_of_velocity(0.3),)
    h = history("single", 0.6)
    text = explanation_text_of(h, frames)
    assert "in the frame u = 0.3" in text and "In u = 0.3" not in text
    doc = build([("single", h, frames)])
    caption = next(b for b in section_blocks(doc, DiagramBlock)).caption
    assert "(c) in the frame u = 0.3, moving at +0.3 c relative to S" in caption


# --- issue 14, item 6: textbook form -------------------------------------------------------------------------------

@pytest.mark.parametrize("name", particle_presets())
def test_headings_are_the_scenarios_titles_without_internal_names(name):
    doc = build([(name, history(name, 0.6))])
    headings = [b.text for b in doc.blocks() if isinstance(b, Heading)]
    assert load(name).title and load(name).title in headings
    for text in headings + [doc.title]:
        assert name not in text and " — " not in text and "for v above" not in text, text
    caption = next(b for b in doc.blocks() if isinstance(b, DiagramBlock)).caption
    assert not caption.startswith(name)


def test_the_first_section_states_the_paradox_cites_franklin_and_calls_the_rod_an_idealisation():
    first = build([("fig2", history("fig2", 0.6))]).sections[0]
    text = " ".join(b.text for b in first.blocks if isinstance(b, Paragraph))
    # the paper's own title (The `Sears paradox'), author and affiliation, in full; no journal the copy does not give
    assert "Jerrold Franklin, “The ‘Sears paradox’” (Department of Physics, Temple University, Philadelphia)" in text
    assert "F. W. Sears" in text and "hidden momentum" in text
    assert "idealisation" in text and "before light from the impact could reach it" in text
