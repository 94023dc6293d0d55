"""The handout and worksheet of a rod driven by forces (issue 26: "Sears's own paradox"), checked against closed
forms computed here, never read from the engine: a sine² profile's area, the Lorentz transformation of an end at
rest, the momentum a force on an end at rest delivers in another frame, hyperbolic motion under a constant push
(proper acceleration F/M), the causal rod's staircase tanh((2n + 1)κ/2) with κ = ln(1 + 2F/ρ₀), and the rod's total
= initial + delivered on every printed row. One document per preset, built once per module (text only: no PDF)."""

from __future__ import annotations

import functools
import math
import re

import pytest

from rodparadox.handout.build import SECTIONS, build
from rodparadox.handout.document import DiagramBlock, Heading, Paragraph, Question, Table
from rodparadox.physics.frames import frame_name
from rodparadox.handout.forces import PARADOX_TITLE, PUSH_TITLE
from rodparadox.io.scenario import load
from rodparadox.numbers import MINUS
from rodparadox.physics.models import run_rods

from handout_shared import rods as shared_rods

V = 0.6
GAMMA = 1.25  # 1/√(1 − 0.6²)


#: one worker runs this file and the forces worksheets' tests of test_worksheet_tells_nothing, which read the same
#: rods (`handout_shared.rods`, run once per process, and read once: `handout.forces_reading.read` is cached on them)
pytestmark = pytest.mark.xdist_group("handout_forces")


def rods(name: str, v: float = V):
    """The preset's rigid and causal rod at v: `run_rods(load(name).with_overrides(v=v), "both")`, run once."""
    return shared_rods(name, v, "both")


def number(text: str) -> float:
    return float(text.replace(MINUS, "-").split(" ")[0])


def sine2_area(peak: float, start: float, duration: float, t: float) -> float:
    """∫ peak sin²(π (s − start)/duration) ds from start to t (clipped to the support)."""
    s = min(max(t - start, 0.0), duration)
    return peak * (s / 2 - duration * math.sin(2 * math.pi * s / duration) / (4 * math.pi))


@functools.lru_cache(maxsize=None)
def compared(name: str, worksheet: bool = False):
    """The preset's handout (or worksheet) comparing its rigid and causal rods, built once per process (a document is
    frozen: the fixtures below and the page rules' test read the same one)."""
    rigid, causal = rods(name)
    return build([(name, rigid, None, causal)], worksheet=worksheet)


@pytest.fixture(scope="module")
def sears():
    return compared("sears")


@pytest.fixture(scope="module")
def sears_sheet():
    return compared("sears", worksheet=True)


@pytest.fixture(scope="module")
def push():
    return compared("push")


@pytest.fixture(scope="module")
def push_sheet():
    return build([("push", rods("push")[0])], worksheet=True)


def tables(doc, prefix: str) -> list[Table]:
    return [b for b in doc.blocks() if isinstance(b, Table) and b.caption.startswith(prefix)]


def text_of(doc) -> str:
    return "\n".join(b.text for b in doc.blocks() if isinstance(b, (Paragraph, Heading)))


def test_a_forces_handout_has_its_diagram_its_tables_and_sears_s_own_paradox(sears, push):
    blocks = sears.sections[1].blocks
    drawn = [b.drawn for b in blocks if isinstance(b, DiagramBlock)]  # both rods drawn, the rigid rod's row first
    assert [[h.fronts is not None for h in pair] for pair in drawn] == [[False, True]]
    assert Heading(PARADOX_TITLE, 2) in blocks and "\u2019" in PARADOX_TITLE
    assert Heading(PUSH_TITLE, 2) in push.sections[1].blocks
    # nothing of particles: no impacts, no particle's start
    words = text_of(sears)
    assert "impacts in" not in words and "Particle" not in words
    assert len(tables(sears, "The forces in frame")) == 4 and len(tables(sears, "Where the momentum is")) == 4


def test_the_rows_add_up_rod_total_is_initial_plus_delivered(sears, push):
    for doc in (sears, push):
        for table in tables(doc, "Where the momentum is"):
            initial = number(table.rows[0][5].text)  # the first row: a force's start, nothing delivered yet
            assert number(table.rows[0][1].text) == number(table.rows[0][2].text) == 0.0
            for row in table.rows:
                left, right, moving, stress, total = (number(c.text) for c in row[1:6])
                assert total == pytest.approx(initial + left + right, abs=2e-4), (table.caption, row)
                assert total == pytest.approx(moving + stress, abs=2e-4), (table.caption, row)


def test_sears_in_s_balanced_forces_nothing_moves(sears):
    rigid = next(t for t in tables(sears, "Where the momentum is in frame S ") if "rigid" in t.caption)
    for row in rigid.rows:
        left, right, moving, stress, total = (number(c.text) for c in row[1:6])
        assert moving == stress == total == 0.0
        t = number(row[0].text)
        assert left == pytest.approx(sine2_area(0.2, 0.5, 1.0, t), abs=6e-5) and right == pytest.approx(-left)
    assert "Nothing moves" in text_of(sears)
    # the momentum each agent delivers in S, its profile's area: 0.2 × 1 / 2
    assert "the left agent delivers +0.1 M c and the right agent delivers −0.1 M c" in text_of(sears)


def _in_s_prime(t_prime: float) -> tuple[float, float]:
    """The momentum each agent has delivered in S′ by the slice t′ (ends at rest at x = ∓1/2 in S): the slice meets
    the end x at t = t′/γ − v x, where the agent has delivered p = ±area in S and no energy, γ p in S′."""
    left = GAMMA * sine2_area(0.2, 0.5, 1.0, t_prime / GAMMA + V * 0.5)
    right = -GAMMA * sine2_area(0.2, 0.5, 1.0, t_prime / GAMMA - V * 0.5)
    return left, right


def test_sears_in_s_prime_the_momentum_is_in_the_stress(sears):
    rigid = next(t for t in tables(sears, "Where the momentum is in frame S′") if "rigid" in t.caption)
    for row in rigid.rows:
        t = number(row[0].text)
        left, right = _in_s_prime(t)
        cells = [number(c.text) for c in row[1:6]]
        assert cells[0] == pytest.approx(left, abs=6e-5) and cells[1] == pytest.approx(right, abs=6e-5)
        assert cells[2] == 0.75  # the kinetic part: γ M v, unchanged
        assert cells[3] == pytest.approx(left + right, abs=6e-5)  # the stress holds what was delivered
    # the sentence's slice and numbers, from the closed form
    m = re.search(r"The rigid rod in S′: at t′ = ([\d.]+) L the left agent has delivered \+([\d.]+) M c and the right "
                  r"−([\d.]+) M c, together \+([\d.]+) M c", text_of(sears))
    t = float(m.group(1))
    left, right = _in_s_prime(t)
    assert float(m.group(2)) == pytest.approx(left, rel=1e-3) and float(m.group(3)) == pytest.approx(-right, rel=1e-3)
    assert float(m.group(4)) == pytest.approx(left + right, rel=1e-3)
    assert "Yet the rod’s kinetic part is still +0.75 M c" in text_of(sears).replace("'", "’")


def test_the_worksheet_asks_when_the_forces_start_in_s_prime(sears_sheet):
    asked = [b for b in sears_sheet.sections[1].blocks if isinstance(b, Question)]
    assert asked and all(q.asks for q in asked)
    starts = {f.what: f for f in asked[0].asks}
    for end, x in (("left", -0.5), ("right", 0.5)):
        t_prime = GAMMA * (0.5 + V * x)  # t′ = γ(t + v x), S′ moving at −v
        forms = starts[f"the {end} force's start in S′"].forms
        assert not forms or f"{t_prime:.4f}" in forms or f"{t_prime:.4g}" in forms
    assert "the left force starts first" in " ".join(asked[0].asks[-1].forms)
    momentum = asked[1]
    delivered = next(f for f in momentum.asks if f.what.startswith("the momentum delivered"))
    t = float(delivered.what.split("= ")[1])
    assert f"{sum(_in_s_prime(t)):.4f}" in delivered.forms
    # the key answers each question
    answered = [b for b in sears_sheet.answer_key if isinstance(b, Question)]
    assert [q.text for q in answered] == [q.text for q in asked]


def test_push_rigid_hyperbolic_motion_and_causal_staircase(push, push_sheet):
    F, t0, t1 = 0.25, 0.5, 4.5
    a = F  # proper acceleration F/M
    u = a * (t1 - t0) / math.sqrt(1 + (a * (t1 - t0)) ** 2)
    dx = (math.sqrt(1 + (a * (t1 - t0)) ** 2) - 1) / a
    words = text_of(push)
    assert f"constant proper acceleration, {a:g} c²/L = |F|/M" in words
    assert f"it moves at +{u:.4f} c and has gone {dx:.4g} L" in words
    kappa = math.log(1 + 2 * F)  # ρ₀ = M/L = 1
    first = F / (1 + F)
    assert first == pytest.approx(math.tanh(kappa / 2), abs=1e-15)
    m = re.search(r"in steps, (.*?), while the push lasts", words)
    steps = [s.split(" c")[0].lstrip("+") for s in re.split(r", | and ", m.group(1))]
    expected = [math.tanh((2 * n + 1) * kappa / 2) for n in range(len(steps))]
    for said, value in zip(steps, expected):
        said = said.split("/")
        assert (float(said[0]) / float(said[1]) if len(said) == 2 else float(said[0])) == pytest.approx(value, abs=5e-5)
    assert "right end starts to move only at t = 1.5 L" in words  # the first signal at c: t0 + L
    # the worksheet's facts: the velocity, distance and proper time of hyperbolic motion
    asks = {f.what: f for q in push_sheet.sections[1].blocks if isinstance(q, Question) for f in q.asks}
    assert f"{u:.4f}" in asks["the pushed end's velocity when the push ends, in S"].forms
    assert f"{dx:.4f}" in asks["the pushed end's distance"].forms
    assert f"{math.asinh(a * (t1 - t0)) / a:.4f}" in asks["the push's proper duration"].forms
    questions = [q.text for q in push_sheet.sections[1].blocks if isinstance(q, Question)]
    assert questions[0].startswith("The agent pushes the left end with a constant force F = 0.25 M c²/L")  # not "pushs"
    x1, t1p = -0.5 + dx, GAMMA * (t1 + V * (-0.5 + dx))
    assert f"{t1p:.4f}" in asks["the push's end in S′"].forms


def test_sections_leave_out_what_is_not_asked():
    rigid = rods("sears")[0]
    for parts in (("diagrams", "ledger"), ("paradox", "tables")):
        doc = build([("sears", rigid)], sections=parts)
        blocks = [b for s in doc.sections for b in s.blocks]
        assert any(isinstance(b, DiagramBlock) for b in blocks) == ("diagrams" in parts)
        assert any(isinstance(b, Table) and b.caption.startswith("The forces") for b in blocks) == ("tables" in parts)
        assert (Heading(PARADOX_TITLE, 2) in blocks) == ("ledger" in parts)
        assert (doc.sections[0].name == "introduction") == ("paradox" in parts)
    assert set(SECTIONS) >= {"paradox", "diagrams", "tables", "ledger"}


def test_no_caption_says_the_rod_is_struck(sears, push):
    """A rod driven by forces is struck by nothing: S is its rest frame "before the forces act"."""
    for doc in (sears, push):
        captions = [b.caption for b in doc.blocks() if hasattr(b, "caption")]
        assert not [c for c in captions if "struck" in c]
        assert any("S, the rod's rest frame before the forces act" in c for c in captions)


def test_the_words_name_no_software(sears, sears_sheet, push):
    """No software word (`test_handout_words.SOFTWARE`) in any block's words, the answer key's included."""
    from test_handout_words import SOFTWARE

    for doc in (sears, sears_sheet, push):
        words = [b.text for b in doc.blocks() if isinstance(b, (Paragraph, Heading))]
        words += [b.caption for b in doc.blocks() if hasattr(b, "caption")]
        words += [" ".join(b.answer) + b.text for b in doc.blocks() if isinstance(b, Question)]
        words += [n for b in doc.blocks() if isinstance(b, Table) for n in (*b.header, *b.notes)]
        found = [m.group() for text in words for m in SOFTWARE.finditer(text)]
        assert not found, found


def test_the_command_writes_only_the_sections_asked(here):
    """handout sears --frame both,rod --sections paradox,ledger,rod --format tex: the paradox, the momentum tables and
    the rod's own view (once refused for a driven rod), no diagram, no forces' tables."""
    from helpers import run

    run("handout", "sears", "--frame", "both,rod", "--sections", "paradox,ledger,rod", "--format", "tex", "-o", "out")
    files = sorted(p.name for p in (here / "out").iterdir())
    assert "sears_momentum_rest.tex" in files and "sears_momentum_moving.tex" in files
    assert "sears_rod_view.pdf" in files
    assert not [f for f in files if "diagram" in f or "forces_" in f], files
    tex = (here / "out" / "handout.tex").read_text()
    assert "Sears's own paradox" in tex and "The paradox and its resolution" in tex


def test_sears_moving_the_rigid_rod_moves_though_the_forces_balance_in_s_prime():
    """Timed in S′, the forces balance at every instant of S′ but not of the rod's own time (S): the rigid rod's
    kinetic part in S′ changes, and the text says so, never "Nothing moves"."""
    rigid = rods("sears_moving")[0]
    doc = build([("sears_moving", rigid)], sections=("ledger",))
    words = text_of(doc)
    assert "Nothing moves" not in words and "Yet the rod moves" in words
    table = next(t for t in tables(doc, "Where the momentum is in frame S′"))
    assert max(abs(number(row[3].text) - 0.75) for row in table.rows) > 1e-3


# --- scenarios no preset has ---------------------------------------------------------------------------------------

#: (name, v, L, forces): two unlike forces timed in S′ and in the frame u = 0.3; a sine² pull alone; a constant pull
#: alone on a rod of L = 2 (its times and lengths in units of L)
GENERATED = [
    ("gen_two", 0.47, 1.0,
     "left: {shape: points, points: [[0.2, 0], [0.6, 0.3], [1.4, 0.1], [1.8, 0]], frame: moving}\n"
     "  right: {shape: step, peak: 0.15, start: 0.4, duration: 0.8, frame: 0.3}"),
    ("gen_pull", 0.8, 1.0, "right: {shape: sine2, peak: -0.3, start: 0.3, duration: 1.2}"),
    ("gen_step", 0.35, 2.0, "right: {shape: step, peak: -0.2, start: 0.25, duration: 2.5}"),
]
AREAS = {"gen_two": {"left": 0.5 * 0.4 * 0.3 + 0.8 * 0.2 + 0.5 * 0.4 * 0.1, "right": 0.15 * 0.8},
         "gen_pull": {"right": -0.3 * 1.2 / 2}, "gen_step": {"right": -0.2 * 2.5}}


@functools.lru_cache(maxsize=None)
def generated(name: str):
    from rodparadox.io.scenario import parse

    _, v, L, forces = next(g for g in GENERATED if g[0] == name)
    scenario = parse(f"name: {name}\nv: {v}\nL: {L}\nforces:\n  {forces}\n", f"{name}.yaml", name)
    rigid, = run_rods(scenario, "rigid")
    return rigid, build([(name, rigid)]), build([(name, rigid)], worksheet=True)


@pytest.mark.parametrize("name", [pytest.param(g[0], marks=pytest.mark.slow) if g[0] == "gen_two" else g[0]
                                  for g in GENERATED])  # gen_two's 16 slices cost 2 s: in the full run
def test_a_generated_scenario_s_handout_adds_up_and_its_worksheet_tells_nothing(name):
    from test_worksheet_tells_nothing import _latex_of, _questions, found_leaks, model_text

    rigid, doc, sheet = generated(name)
    words = text_of(doc)
    for end, area in AREAS[name].items():  # delivered in its own frame = the profile's area (right: −area)
        said = re.search(rf"the {end} agent delivers ([+−][\d./]+) M c", words).group(1)
        value = number(said) if "/" not in said else float(said[1:].split("/")[0]) / float(said.split("/")[1])
        sign = -1.0 if said.startswith("−") else 1.0
        value = sign * abs(value)
        assert value == pytest.approx(area if end == "left" else -area, rel=1e-3), (end, said, area)
    for table in tables(doc, "Where the momentum is"):
        initial = number(table.rows[0][5].text) - number(table.rows[0][1].text) - number(table.rows[0][2].text)
        for row in table.rows:
            left, right, moving, stress, total = (number(c.text) for c in row[1:6])
            assert total == pytest.approx(initial + left + right, abs=2e-4) == pytest.approx(moving + stress, abs=2e-4)
    section = sheet.sections[1]
    assert _questions(section)
    found = found_leaks(section, [("model", model_text(section)), ("latex", _latex_of(sheet)[1])])
    assert not found, found


def test_a_constant_pull_on_a_longer_rod_is_hyperbolic_in_units_of_l():
    """gen_step: F = −0.2 M c²/L on the right end of a rod of L = 2 for 2.5 L: proper acceleration |F|/M in c²/L,
    u = aΔt/√(1 + (aΔt)²), distance (√(1 + (aΔt)²) − 1)/a in units of L."""
    _, doc, sheet = generated("gen_step")
    a, dt = 0.2, 2.5
    u = a * dt / math.sqrt(1 + (a * dt) ** 2)
    dx = (math.sqrt(1 + (a * dt) ** 2) - 1) / a
    words = text_of(doc)
    assert f"constant proper acceleration, {a:g} c²/L = |F|/M" in words
    assert f"it moves at +{u:.4f} c and has gone {dx:.4g} L" in words  # a pull on the right end: to the right
    asks = {f.what: f for q in sheet.sections[1].blocks if isinstance(q, Question) for f in q.asks}
    assert f"{u:.4f}" in asks["the pushed end's velocity when the push ends, in S"].forms
    assert f"{math.asinh(a * dt) / a:.4f}" in asks["the push's proper duration"].forms


@pytest.mark.parametrize("name", ["sears", pytest.param("sears_moving", marks=pytest.mark.slow), "push"])
def test_the_pages_are_set_like_a_book(name):
    """Both rods' handout and worksheet at 0.6 on A4, read from the page plan (no drawing), under the rules of
    `test_page_rules`: headings and introductions with what follows, short tables whole, no page more than a quarter
    empty but a section's last, nor a third but the last before the key."""
    import test_page_rules as rules
    from rodparadox.handout.pdf import page_plan

    plans = [(f"{name} {kind}", doc, page_plan(doc, "a4"))  # build([(name, rigid, None, causal)], worksheet=...)
             for kind, doc in (("handout", compared(name)), ("worksheet", compared(name, worksheet=True)))]
    rules.test_no_heading_or_introduction_is_left_apart_from_what_follows_it(plans)
    rules.test_a_short_table_is_whole_and_on_its_introduction_s_page(plans)
    rules.test_no_page_is_more_than_a_quarter_empty_but_a_section_s_last(plans)
    rules.test_no_page_is_more_than_a_third_empty_but_the_last_before_the_key_and_the_document_s_last(plans)


def test_the_rod_s_own_view_of_a_driven_rod_says_each_model_s_chart(sears, sears_sheet):
    """handout --frame both,rod of a driven rod, both rods: the view after the diagram (a worksheet's in its key, before
    the questions' answers), its caption true for a driven rod, per model. The rigid rod's chart: its own lines of
    simultaneity, T the left end's proper time, X the distance from it, clocks at 1 + αX (driven_chart's dτ_X =
    (1 + αX) dT); no turn, pivot or impact, which a driven rod has none of. The causal rod's: its material chart, and
    no particle riding an end."""
    from rodparadox.handout.document import RodViewBlock
    from rodparadox.handout.own_view import ANSWERED, with_rod_views

    rigid, causal = rods("sears")
    doc = with_rod_views(sears, {"sears": (rigid, causal)})
    blocks = doc.sections[1].blocks
    at = next(k for k, b in enumerate(blocks) if isinstance(b, RodViewBlock))
    assert isinstance(blocks[at - 1], DiagramBlock) and blocks[at].histories == (rigid, causal)
    caption = " ".join(blocks[at].caption.split())
    rigid_words, causal_words = caption.split("Causal rod:")
    for said in ("Rigid rod: each level line is one of the rod's own lines of simultaneity",
                 "T is the proper time of its left end", "X the distance from the left end along that line",
                 "its clock runs at 1 + \N{GREEK SMALL LETTER ALPHA}X/c\N{SUPERSCRIPT TWO} of T's rate"):
        assert said in rigid_words, said
    assert "every material point stands still and every light ray runs at 45\N{DEGREE SIGN}" in causal_words
    assert caption.count("Each force is drawn as a band beside the end it acts on") == 1
    for unsaid in ("turns:", "a turn", "pivot", "impact", "particle", "hatched", "never moves"):
        assert unsaid not in caption.lower(), unsaid
    alone = with_rod_views(sears, {"sears": (rigid,)})  # the rigid rod alone: no causal rod in its caption
    assert "Causal rod" not in next(b for b in alone.blocks() if isinstance(b, RodViewBlock)).caption
    sheet = with_rod_views(sears_sheet, {"sears": (rigid, causal)})
    key = list(sheet.answer_key)
    answered = next(k for k, b in enumerate(key) if isinstance(b, Heading) and b.text == ANSWERED)
    assert isinstance(key[answered - 1], RodViewBlock) and key[answered - 1].caption == blocks[at].caption
    assert not any(isinstance(b, RodViewBlock) for s in sheet.sections for b in s.blocks)


def test_the_rod_s_own_view_of_a_driven_rod_runs_into_nothing_on_its_page():
    """The view of both driven rods on an A4 page, its caption and a paragraph under it, measured as the PDF draws
    them (`test_handout_pdf.drawn_extents`): no text or axes of the figure meets a line of the page's text, and all
    lies inside the page. Its keys are taller than its panels (sears: about L of the rods' time); they once ran
    into the caption. Squeezed to its least height (`render.least_height`, what a page may shrink it to), the rigid
    rod's view still holds its key."""
    from matplotlib.figure import Figure
    from matplotlib.legend import Legend
    from test_handout_pdf import drawn_extents, page_runs, pdf_renderer, run_box

    from rodparadox import render
    from rodparadox.handout.document import Handout, RodViewBlock, Section
    from rodparadox.handout.own_view import rod_view_caption
    from rodparadox.handout.pdf import page_figures
    from rodparadox.handout.pdf_text import MARGIN
    from rodparadox.handout.tex import text_width_in

    histories = rods("sears")
    block = RodViewBlock("rod_view", histories, rod_view_caption(histories))
    doc = Handout("t", (Section("sears", "s", (block, Paragraph("After the view."))),))
    [page] = page_figures(doc, "a4", "print")
    drawn = drawn_extents(page, "print")  # draws the page as the PDF does; the page's own runs first
    runs = [run_box(r, pdf_renderer(page)) for r in page_runs(page)]
    figure_boxes = [(what, box) for what, box in drawn[len(runs):]]
    assert len(figure_boxes) > 20 and len(runs) > 5
    for what, box in figure_boxes:  # (its axis's name reaches into the left margin, as a struck rod's view's does)
        assert 0.0 <= box.x0 and box.x1 <= page.bbox.width - MARGIN + 0.5, (what, box)
        assert not [r for r in runs if r.overlaps(box)], what
    rigid = histories[:1]
    width = text_width_in("a4") * 72
    least = render.least_height(rigid, "print")
    assert least < render.rod_view_size(rigid, "print", width)[1]  # a page may squeeze this one
    squeezed = Figure(figsize=(width / 72, least / 72), dpi=72)
    render.draw_rod_view_into(squeezed, rigid, "print")
    [key] = squeezed.findobj(Legend)
    assert key.get_window_extent(pdf_renderer(squeezed)).y0 >= 0.0


# --- the rod at successive instants -------------------------------------------------------------------------------

#: sears at v = 0.6 in S′ (hand: t′ = γ (t + v x), γ = 1.25; the left end at x = −1/2, the right at +1/2, each force
#: on at t = 1/2, peak at 1, off at 3/2 of S): the left force on, peak, off at t′ = 1/4, 7/8, 3/2, the right at 1,
#: 13/8, 9/4; with an instant before and one after, the eight rows
SEARS_S_PRIME = {0.25: "left on", 0.875: "left peak", 1.0: "right on", 1.5: "left off", 1.625: "right peak",
                 2.25: "right off"}


def test_the_strips_of_a_driven_rod_show_each_force_s_start_peak_and_end(sears, sears_sheet):
    """Each frame's strips of each rod (rigid first) after the diagram's explanation, a worksheet's in its key; the
    rows at each force's start, peak and end (hand: SEARS_S_PRIME; in S both forces at t = 1/2, 1, 3/2), one before
    and one after, each row's note naming the forces that start, peak or end then; the caption true for forces."""
    from rodparadox.handout.document import Strips
    from rodparadox.physics.frames import moving_frame, rest_frame
    from rodparadox.render.force_layers import force_notes

    rigid, causal = rods("sears")
    blocks = [b for b in sears.blocks() if isinstance(b, Strips)]
    assert [(b.history.model, b.frame.name) for b in blocks] == [("rigid", "rest"), ("causal", "rest"),
                                                                 ("rigid", "moving"), ("causal", "moving")]
    assert not [b for s in sears_sheet.sections for b in s.blocks if isinstance(b, Strips)]
    assert len([b for b in sears_sheet.answer_key if isinstance(b, Strips)]) == 4
    moving = blocks[2]
    inner = moving.times[1:-1]
    assert inner == pytest.approx(sorted(SEARS_S_PRIME), abs=1e-12)
    assert moving.times[0] < 0.25 and moving.times[-1] > 2.25
    assert force_notes(rigid, moving.frame, moving.times, 1.0) == ["", *SEARS_S_PRIME.values(), ""]
    rest = blocks[0]
    assert [t for t in rest.times if 0.25 < t < 1.75] == pytest.approx([0.5, 1.0, 1.5], abs=1e-12)
    assert [n for n in force_notes(rigid, rest.frame, rest.times, 1.0) if n] == [
        "left and right on", "left and right peak", "left and right off"]
    assert rest.caption.startswith("The rigid rod in S at t = ") and "so it has one shade" in rest.caption
    assert blocks[1].caption.startswith("The causal rod in S at t = ") and "shaded by the velocity" in blocks[1].caption
    for b in blocks:
        assert "An arrow at an end is the force acting there" in b.caption
        assert "particle" not in b.caption and "impact" not in b.caption
    # each rod's block under its own heading, which a part set on the next page repeats (the causal rows sat under
    # "The rod at successive instants of S", the rod named only in the caption after them)
    everything = list(sears.blocks())
    for b in blocks:
        heading = everything[everything.index(b) - 1]
        assert heading == Heading(f"The {b.history.model} rod at successive instants of {frame_name(b.frame)}", 2)
        assert b.subject == f"The {b.history.model} rod"


def test_the_two_rods_strips_share_one_x_range_and_one_colour_scale_in_each_frame(sears):
    """Issue 24: the rigid and the causal rod's blocks of one frame were drawn each to its own x range (in S the
    rigid rod's −0.6 to 0.6, the causal's −0.5 to 0.5) and colour scale; now each block names the other
    (`Strips.partners`) and, drawn, both have one x range, one tick step and one colour scale, as a comparison must;
    the rigid rod, which never moves in S, still has no colour bar."""
    from matplotlib.figure import Figure

    from rodparadox.handout.document import Strips
    from rodparadox.render.strip_block import draw_strips_into

    blocks = [b for b in sears.blocks() if isinstance(b, Strips)]
    for b in blocks:
        assert [(h.model, times) for h, times in b.partners] == [
            (o.history.model, o.times) for o in blocks if o.frame == b.frame and o is not b]
    drawn = []
    for b in blocks[:2]:  # S: rigid, causal (each block's strips are the other's partners: computed once)
        figure = Figure(figsize=(6.0, 6.0), dpi=72)
        rows = draw_strips_into(figure, b.history, b.frame, b.times, "print", partners=b.partners)
        norm = rows[0].collections[0].norm
        drawn.append((rows[-1].get_xlim(), list(rows[-1].get_xticks()), (norm.vmin, norm.vmax),
                      [ax.get_gid() for ax in figure.axes if ax.get_gid() == "strips-colour-bar"]))
    (x_rigid, ticks_rigid, norm_rigid, bar_rigid), (x_causal, ticks_causal, norm_causal, bar_causal) = drawn
    assert x_rigid == pytest.approx(x_causal, abs=1e-12) and ticks_rigid == ticks_causal
    assert norm_rigid == pytest.approx(norm_causal, abs=1e-12)
    assert bar_rigid == [] and bar_causal == ["strips-colour-bar"]


def test_no_text_writes_a_subscript_as_code_does(sears, push):
    """Issue 24, found looking at the pages: the momentum tables' last column was headed "v_E", their note and the
    section's paragraph said "v_E", printed as it stands; they now say the centre velocity in words."""
    import re

    for doc in (sears, push):
        text = text_of(doc) + " ".join(" ".join(b.header) + " ".join(b.notes) for b in doc.blocks()
                                       if isinstance(b, Table))
        assert not re.findall(r"[A-Za-z]_[A-Za-z]", text)
        assert "centre velocity" in text


def test_a_driven_rods_strips_say_where_their_rows_follow_the_rod():
    """push at 0.95 in S′: the rod drifts 20 L while 0.3 L long, so each row follows it (`render.strip_windows`), both
    rods' blocks alike; their captions said nothing of it (a particle comparison's do). Now they say so, without
    the particles' arrowheads a driven rod has none of; in S, where one range serves, they do not."""
    from rodparadox.handout.document import Strips
    from rodparadox.handout.forces_strips import strips_blocks
    from rodparadox.physics.frames import paper_frames
    from rodparadox.render.strip_windows import strips_follow_rod

    rigid, causal = rods("push", 0.95)
    blocks = [b for b in strips_blocks("push", (rigid, causal), paper_frames(0.95)) if isinstance(b, Strips)]
    for b in blocks:
        follows = b.frame.name == "moving"
        assert ("so each row follows it" in b.caption) == follows, (b.history.model, b.frame.name)
        assert "particle" not in b.caption
        if b.history.model == "rigid":  # as the drawing decides, from the strips themselves
            assert strips_follow_rod(b.history, b.frame, b.times) == follows


def test_a_strip_s_arrow_is_as_long_as_its_force_and_points_into_the_rod():
    """sears in S′ (v = 0.6), drawn: an arrow only where a force acts (SEARS_S_PRIME: at t′ = 1 the right force
    starts, a sine² at zero, while the left acts), pressing: from outside the rod to its end; at a peak (0.2 M c²/L,
    the scale's force) as long as band_points; inside the axes."""
    from matplotlib.figure import Figure

    from rodparadox.render.force_layers import band_points
    from rodparadox.render.strip_block import draw_strips_into
    from rodparadox.render.styles import STYLES

    from rodparadox.physics.frames import moving_frame

    rigid = rods("sears")[0]
    frame = moving_frame(V)
    times = (0.875, 1.0, 1.625)  # left peak, right on (zero), right peak
    figure = Figure(figsize=(6.0, 3.0), dpi=72)
    rows = draw_strips_into(figure, rigid, frame, times, "print")
    for ax, t in zip(rows, times):
        arrows = {p.get_gid().rsplit("-", 1)[1]: p for p in ax.patches if "force" in str(p.get_gid())}
        shown_ends = {end for end, a in arrows.items() if a.get_visible()}
        assert shown_ends == {0.875: {"left"}, 1.0: {"left"}, 1.625: {"right"}}[t]
        for end in shown_ends:
            (x_tail, _), (x_head, _) = arrows[end]._posA_posB  # as update_strip set them
            rod = [x for line in ax.lines if line.get_gid() and line.get_gid().endswith("outline")
                   for x in line.get_xdata()]
            at = min(rod) if end == "left" else max(rod)
            assert x_head == pytest.approx(at, abs=1e-12)  # the head on the end: pressing
            assert (x_tail < x_head) == (end == "left")  # from outside the rod
            lo, hi = ax.get_xlim()
            assert lo < x_tail < hi
            points = abs(x_head - x_tail) * ax.bbox.width / (hi - lo)
            if t != 1.0:  # a peak: F = 0.2, the scale's force
                assert points == pytest.approx(band_points(STYLES["print"]), rel=1e-6)
            else:  # the left force at t′ = 1 (t = 1.1 at x = −1/2): 0.2 sin²(0.6 π), by hand
                assert points == pytest.approx(band_points(STYLES["print"]) * math.sin(0.6 * math.pi) ** 2, rel=1e-6)


def test_a_momentum_cell_is_nought_four_decimals_or_a_rounding_zero_without_a_minus(sears):
    """Found looking at sears at 0.95: S′'s table printed −0.0000 where the right agent had just begun to pull."""
    from rodparadox.handout.forces import _p

    assert (_p(0.0), _p(-2e-6), _p(3e-5), _p(-0.0003), _p(0.32026)) == ("0", "+0.0000", "+0.0000", "\u22120.0003",
                                                                       "+0.3203")
    cells = [c.text for t in tables(sears, "Where the momentum is") for row in t.rows for c in row[1:]]
    assert cells and not any(c.startswith("\u22120.0000") or c == "-0.0000" for c in cells)
