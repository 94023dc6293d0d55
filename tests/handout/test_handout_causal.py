"""The handout's comparison of the rigid rod with the causal rod (issue 16, item 7; README, "Teaching handouts"):
every sentence's numbers against an independent computation: the closed forms of one particle on the rod at rest
(README, "The causal rod"), velocity addition, and conservation of energy and momentum; the worksheet's questions
on it against their worked answers. One causal run per preset per process (`conftest.causal_history`); no PDF but
one, in the command-line test."""

from __future__ import annotations

import math

import pytest
from click.testing import CliRunner

from helpers import causal_history, history
from rodparadox.handout.build import build
from rodparadox.handout.causal_compare import HEADING
from rodparadox.handout.causal_reading import compare
from rodparadox.handout.document import Heading, Paragraph, Question, Table
from rodparadox.handout.words import in_c, in_l, numeral
from rodparadox.physics.frames import paper_frames
from rodparadox.physics.types import EnergyMomentum
from sears_paradox_cli.main import main

#: one worker runs this file: its module fixture is built once, not once per worker
pytestmark = pytest.mark.xdist_group("handout_causal")

V = 0.6


def _single(v: float, mass: float = 1.0):
    """The one-particle closed forms (README, "The causal rod"): B strikes the right end of the rod at rest with
    rapidity th0 = artanh v; tanh(th_f/2) = tanh(th0/2) exp(-2M/m); the far end starts at rapidity 2 th0."""
    th0 = math.atanh(v)
    th_f = 2.0 * math.atanh(math.tanh(th0 / 2.0) * math.exp(-2.0 / mass))
    return th0, th_f


@pytest.fixture(scope="module")
def compared():
    """The comparison's numbers of three presets at v = 0.6: one particle, two at once, two at different times."""
    return {name: compare(history(name, V), causal_history(name, V), paper_frames(V))
            for name in ("single", "fig1", "fig2")}


@pytest.fixture(scope="module")
def sections():
    """The handout's comparison blocks of the same three presets, text joined."""
    doc = build([(name, history(name, V), None, causal_history(name, V)) for name in ("single", "fig1", "fig2")])
    out = {}
    for section in doc.sections[1:]:
        k = next(i for i, b in enumerate(section.blocks) if isinstance(b, Heading) and b.text == HEADING)
        out[section.name] = section.blocks[k:]
    return out


def _text(blocks) -> str:
    return " ".join(b.text for b in blocks if isinstance(b, Paragraph))


def test_the_far_end_starts_when_light_arrives_at_twice_the_rapidity(compared, sections):
    """One particle: the causal rod's far end starts exactly at t = L after the contact, at rapidity 2 th0; the rigid
    rod's at the contact's instant. B at gap L/2, speed v: the contact at t = (L/2)/v = 5/6 L."""
    f = compared["single"].far_end
    th0, _ = _single(V)
    assert f.t_contact == pytest.approx(0.5 / V, rel=1e-12)
    assert f.by_light and f.t_causal == pytest.approx(0.5 / V + 1.0, rel=1e-9)
    assert f.t_rigid == pytest.approx(0.5 / V, rel=1e-12)
    assert f.u_causal == pytest.approx(-math.tanh(2.0 * th0), rel=1e-9) == pytest.approx(-2 * V / (1 + V * V))
    text = _text(sections["single"])
    assert "stays at rest until t = 11/6 L" in text and "at once at −15/17 c" in text
    assert "starts to move at that same instant of S, t = 5/6 L" in text


@pytest.mark.parametrize("v, L", [(0.1, 1.0), (0.9, 2.5)])
def test_the_far_end_at_other_speeds_and_lengths(v, L):
    """The same at another speed and length (t in units of L): light takes L, the far end starts at 2 th0."""
    c = compare(history("single", v, L), causal_history("single", v, L), paper_frames(v))
    assert c.far_end.t_causal - c.far_end.t_contact == pytest.approx(1.0, rel=1e-9)
    assert math.atanh(-c.far_end.u_causal) == pytest.approx(2.0 * math.atanh(v), rel=1e-9)


def test_two_particles_the_far_end_is_struck_before_light_arrives(compared, sections):
    """fig1: both ends struck at t = 5/6 L; fig2: A₁ strikes the left end before light from B₁ gets there."""
    for name in ("fig1", "fig2"):
        f = compared[name].far_end
        assert not f.by_light and f.own.event.t < f.t_light
        assert f.t_causal == pytest.approx(f.own.event.t, abs=1e-12)
    assert "set moving by A₁ itself" in _text(sections["fig2"])
    assert compared["fig1"].far_end.t_rigid is None and compared["fig2"].far_end.t_rigid == pytest.approx(5 / 6)
    # the question asks when the rigid rod's far end starts to move: fig1's equal and opposite impacts at one
    # instant of S leave the rigid rod at rest (its right end's world-line one straight piece, at rest), fig2's at B₁
    from rodparadox.handout.worksheet_causal import question_far_end

    rigid_fig1 = history("fig1", V)
    for sigma in (0.0, rigid_fig1.scenario.L):  # both ends at rest before and long after the impacts
        end = rigid_fig1.material_worldline(sigma)
        assert end.rapidity_at_time(0.0) == end.rapidity_at_time(10.0) == 0.0
    assert compared["fig1"].far_end.t_rigid_moves is None
    assert compared["fig2"].far_end.t_rigid_moves == compared["fig2"].far_end.t_rigid
    fig1 = " ".join(question_far_end(compared["fig1"]).answer)
    assert "The rigid rod’s right end never moves in S: A₁ and B₁, at one instant of S, together leave" in fig1
    assert "B₁ strikes the right end before light from A₁ reaches it" in fig1 and "comes first" not in fig1
    assert "The rigid rod never moves in S: A₁ and B₁ together leave it at rest." in _text(sections["fig1"])
    assert "never moves" not in _text(sections["fig2"])


def test_one_particle_leaves_as_the_closed_form_says_in_both_frames(compared, sections):
    """B leaves the causal rod at -tanh th_f in S (closed form) and, by velocity addition, (u + v)/(1 + u v) in S′;
    it stops dead on the rigid rod (equal masses, elastic): 0 in S, +v in S′."""
    _, th_f = _single(V)
    u = -math.tanh(th_f)
    u_moving = (u + V) / (1 + u * V)
    [b] = compared["single"].leaving
    assert b.causal["rest"] == pytest.approx(u, rel=1e-10) and b.causal["moving"] == pytest.approx(u_moving, rel=1e-10)
    assert b.rigid == {"rest": 0.0, "moving": pytest.approx(V)}
    text = _text(sections["single"])
    assert f"at {in_c(u)} in S ({in_c(u_moving)} in S′)" in text and "rigid rod at 0 in S (+0.6 c in S′)" in text
    # a heavier particle (m = 2M) loses less: mu = 1/2 in the closed form
    _, th_heavy = _single(V, mass=2.0)
    assert th_heavy > th_f


def test_the_ringing_rod_holds_the_missing_energy(compared, sections):
    """Conservation: the rod's (E, p) after the last separation, (M/2L)(Δt, Δx), is the initial total less the
    particles' as they leave (for one particle from the closed form), its rest mass above M; and a material point
    really advances by (Δt, Δx) over 2L of chart time (the chart map, not the period's bookkeeping)."""
    th0, th_f = _single(V)
    r = compared["single"].ringing
    E0, p0 = 1.0 + math.cosh(th0), -math.sinh(th0)
    assert r.E == pytest.approx(E0 - math.cosh(th_f), rel=1e-9) and r.p == pytest.approx(p0 + math.sinh(th_f), rel=1e-9)
    assert r.rest_mass == pytest.approx(math.sqrt(r.E ** 2 - r.p ** 2)) and r.rest_mass > 1.0
    for name in ("fig1", "fig2"):
        c, causal = compared[name], causal_history(name, V)
        total = causal.initial_total(0.0)
        out = [EnergyMomentum.of(causal.scenario.particle(p.particle).mass, math.atanh(p.causal["rest"]))
               for p in c.leaving]
        assert c.ringing.E == pytest.approx(total.E - sum(em.E for em in out), abs=1e-9)
        assert c.ringing.p == pytest.approx(total.p - sum(em.p for em in out), abs=1e-9)
        assert c.ringing.rest_mass > 1.0
        from rodparadox.physics.kinematics import ChartCurve
        T = causal.last_separation + 0.3
        one, two = (ChartCurve(causal.solution, 0.4, T, T).point(T), ChartCurve(causal.solution, 0.4, T + 2, T + 2)
                    .point(T + 2))
        assert (two.t - one.t, two.x - one.x) == (pytest.approx(c.ringing.dt, abs=1e-9),
                                                   pytest.approx(c.ringing.dx, abs=1e-9))
    text = _text(sections["single"])
    assert f"Its rest mass √(E² − p²) = {numeral(r.rest_mass)} M is more than M" in text
    assert f"one period lasts √(Δt² − Δx²) = {in_l(2 * r.rest_mass)}" in text


def test_the_stress_part_is_what_the_ledger_needs(compared, sections):
    """On the slice quoted, the particles, the matter part and the stress part add up to the initial total (the
    rod's stress carries what the rigid ledger calls hidden); the rigid hidden part is the initial total less the
    kinetic sum; before any contact the causal rod carries no stress."""
    for name in ("single", "fig1", "fig2"):
        s = compared[name].stress
        total = s.matter + s.stress
        for em in dict(s.particles).values():
            total = total + em
        assert (total.E, total.p) == (pytest.approx(s.total.E, abs=1e-9), pytest.approx(s.total.p, abs=1e-9))
        rigid = history(name, V).energy_momentum(s.frame.rapidity, s.t)
        assert s.hidden.p == pytest.approx(rigid.hidden.p, abs=1e-12)
        assert abs(s.stress.p) > 1e-3  # a slice the causal rod's stress crosses
    _, stress = causal_history("fig2", V).energy_momentum(0.0, 0.5, split=True).rod_parts
    assert stress[1].p == 0.0 and stress[1].E == 0.0
    assert "The hidden momentum, like with like." in _text(sections["fig2"])


def test_the_contacts_table_lists_every_contact_and_separation(sections):
    """The causal rod's table in each frame: every contact and separation once, B′₁'s particle velocity in S the
    closed form's to its printed digits. (B′₁ is
    B1s, as every table but the ASCII text ones names it.)"""
    tables = [b for b in sections["single"] if isinstance(b, Table)]
    assert [t.name for t in tables] == ["causal_events_rest", "causal_events_moving", "ledger_causal_rest",
                                       "ledger_causal_moving"]
    rows = {row[0].text: row for row in tables[0].rows}
    assert set(rows) == {"B₁", "B′₁"}  # the separation named as the figures name it (was B1s)
    _, th_f = _single(V)
    assert rows["B′₁"][4].text == f"{-math.tanh(th_f):.6f}".replace("-", "−")
    assert [row[0].text for row in tables[0].rows] == [i.label.replace("1s", "′1").replace("1", "₁")
                                                       for i in causal_history("single", V).impacts]
    # the sentence before each table names separations as the table does (it said "A1s, B1s")
    # (the second frame's sentence reads "in the same columns": said once, in full, for the first)
    blocks = sections["single"]
    said = [b.text for b, after in zip(blocks, blocks[1:])
            if isinstance(b, Paragraph) and isinstance(after, Table) and after.name.startswith("causal_events")]
    assert len(said) == 2 and "B′₁" in said[0] and not any("1s" in t for t in said)


def test_the_worksheet_asks_and_the_key_answers():
    """A worksheet keeps the comparison's numbers for its key: its blank table, and three questions whose number facts
    appear in their worked answers (the whole worksheet against its pages: test_worksheet_tells_nothing)."""
    doc = build([("fig2", history("fig2", V), None, causal_history("fig2", V))], worksheet=True)
    blocks = doc.sections[1].blocks
    k = next(i for i, b in enumerate(blocks) if isinstance(b, Heading) and b.text == HEADING)
    assert all(c.blank for t in blocks[k:] if isinstance(t, Table) for row in t.rows for c in row[2:])
    asked = [b for b in blocks[k:] if isinstance(b, Question)]
    assert len(asked) == 3 and [q.number for q in asked] == [8, 9, 10]
    key = {q.number: " ".join(q.answer) for q in doc.answer_key if isinstance(q, Question)}
    for q in asked:
        for fact in q.asks:
            if fact.number and fact.forms:
                assert any(form in key[q.number] for form in fact.forms), (q.number, fact.what)
    # the rest mass asked, from conservation by hand (every particle's first and last velocity in S)
    c = compare(history("fig2", V), causal_history("fig2", V), paper_frames(V))
    E = 1.0 + sum(m / math.sqrt(1 - u * u) for m, u in c.particles.values())
    E -= sum(c.particles[p.particle][0] / math.sqrt(1 - p.causal["rest"] ** 2) for p in c.leaving)
    p = sum(m * u / math.sqrt(1 - u * u) for m, u in c.particles.values())
    p -= sum(c.particles[q.particle][0] * q.causal["rest"] / math.sqrt(1 - q.causal["rest"] ** 2) for q in c.leaving)
    rest_mass = next(f for f in asked[1].asks if "rest mass" in f.what)
    assert f"{math.sqrt(E * E - p * p):.7g}" in rest_mass.forms


def test_handout_takes_both_rods_and_names_the_file(tmp_path, monkeypatch):
    """`handout --rod both` writes outputs/NAME_handout_compared (here its LaTeX: the PDF's pages are drawn in
    test_worksheet_tells_nothing) holding the comparison; `--rod causal` is taken too."""
    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(main, ["handout", "single", "--rod", "both", "--format", "tex"])
    assert result.exit_code == 0, result.output
    folder = tmp_path / "outputs" / "single_handout_compared"
    tex = (folder / "handout.tex").read_text()
    assert HEADING in tex and "single_compared.pdf" in tex  # the two rods' diagram
    assert (folder / "single_causal_events_moving.tex").exists()
    result = CliRunner().invoke(main, ["handout", "single", "--rod", "causal", "--questions", "9", "-o",
                                       str(tmp_path / "x.pdf")])
    assert result.exit_code == 2 and "--worksheet" in result.output  # checked before the causal rod is run


def test_a_scenario_file_of_the_causal_rod_gets_the_comparison(tmp_path):
    """A file with `rod: causal` and no --rod: the rigid sections (the drawings) and the comparison, named as the file
    (no _causal: the name says the options given, as plot's)."""
    path = tmp_path / "one.yaml"
    path.write_text("v: 0.6\nrod: causal\nparticles:\n  A: {gap: 0.5}\n")
    result = CliRunner().invoke(main, ["handout", str(path), "--format", "tex", "-o", str(tmp_path / "out")])
    assert result.exit_code == 0, result.output
    tex = (tmp_path / "out" / "handout.tex").read_text()
    assert HEADING in tex and "one_causal_events_rest" in tex


def test_a_greek_capital_before_a_variable_stays_two_tokens_in_latex():
    """(Δt, Δx) in the ringing paragraph: $\\Delta$ then $t$ merged as $\\Delta t$, not the undefined \\Deltat that
    stopped pdflatex."""
    from rodparadox.handout.tex import prose

    assert prose("(Δt, Δx)") == r"($\Delta t$, $\Delta x$)"
    assert prose("γt′ and −L") == r"$\gamma t'$ and $-L$"


def test_the_comparison_draws_both_rods_in_the_same_frames_and_the_causal_rod_s_strips():
    """Issue 24: the comparison is drawn: the two rods' diagram (the rigid row above the causal row, the section's
    frames, one scale per frame), the causal rod's strips in each frame, then its tables; a worksheet asks first and
    its key draws it."""
    from rodparadox.handout.document import DiagramBlock, Strips

    rigid, causal = history("single", 0.6), causal_history("single", 0.6)
    frames = paper_frames(0.6)
    doc = build([("single", rigid, None, causal)])
    blocks = doc.sections[1].blocks
    [both] = [b for b in blocks if isinstance(b, DiagramBlock) and b.compared is not None]
    assert both.drawn == (rigid, causal) and both.frames == frames
    assert "(a), (b) the rigid rod; (c), (d) the causal rod" in both.caption
    strips = [b for b in blocks if isinstance(b, Strips) and b.history is causal]
    assert [s.frame for s in strips] == list(frames) and all(6 <= len(s.times) <= 8 for s in strips)
    # a part set on the next page is headed "The causal rod at successive instants of S′ (continued)", not "The rod"
    assert {s.subject for s in strips} == {"The causal rod"}
    assert {b.subject for b in blocks if isinstance(b, Strips) and b.history is rigid} <= {"The rod"}
    assert "does not draw" not in " ".join(b.text for b in blocks if isinstance(b, Paragraph))
    sheet = build([("single", rigid, None, causal)], worksheet=True)
    assert not any(getattr(b, "compared", None) for b in sheet.sections[1].blocks)
    assert any(getattr(b, "compared", None) is causal for b in sheet.answer_key)


def test_the_stress_part_is_set_against_a_hidden_part_where_the_rigid_model_has_one():
    """Review: `single`'s comparison used a slice of S′ halfway through the causal contact, where its rigid ledger has
    no hidden part: "set against nothing". The slice is taken in the first frame shown where the rigid ledger has a
    hidden part and the causal rod is stressed (moving frames first): for `single` in S, where the two nearly agree."""
    from rodparadox.handout.causal_reading import stress_slice
    from rodparadox.tables.build import hidden_instants

    rigid, causal = history("single", 0.6), causal_history("single", 0.6)
    frames = paper_frames(0.6)
    # why not S′: where its rigid hidden part is largest no front has reached the causal rod yet (nothing to compare)
    f = frames[1].rapidity
    t_max = max(hidden_instants(rigid, frames[1]), key=lambda t: abs(rigid.energy_momentum(f, t).hidden.p))
    assert dict(causal.energy_momentum(f, t_max, split=True).rod_parts)["stress"].p == pytest.approx(0.0, abs=1e-12)
    s = stress_slice(rigid, causal, frames)
    assert s.frame.name == "rest" and abs(s.hidden.p) > 0.05 * s.total.E
    assert s.stress.p == pytest.approx(s.hidden.p, rel=0.05)  # the local stress momentum, near the rigid hidden one
    # fig2 keeps the paper's S′
    assert stress_slice(history("fig2", 0.6), causal_history("fig2", 0.6), frames).frame.name == "moving"
