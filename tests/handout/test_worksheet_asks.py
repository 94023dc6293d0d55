"""A worksheet asks and never tells before its key (issue 14, item 1): for every preset at several speeds, no block
before the answer key states what the questions ask (the rod's velocities after each collision, which impacts
share an instant, the explanation, the strips' labelled velocities); the teacher's choices --questions,
--compare-v and --key separate."""

from __future__ import annotations

import math

import pytest
from click.testing import CliRunner

from rodparadox.handout.build import build
from rodparadox.handout.document import DiagramBlock, Heading, Paragraph, Question, Strips, Table
from rodparadox.handout.words import in_c
from rodparadox.io.scenario import load

from helpers import particle_presets
from rodparadox.physics.rigid import run
from rodparadox.physics.frames import paper_frames

SPEEDS = (0.3, 0.6, 0.95)


def _pre_key_text(doc) -> str:
    out = []
    for s in doc.sections[1:]:  # the first section states the paradox in general
        for b in s.blocks:
            if isinstance(b, (Heading, Paragraph)):
                out.append(b.text)
            elif isinstance(b, DiagramBlock):
                out.append(b.caption)
            elif isinstance(b, Table):
                out += [c.text for row in b.rows for c in row if not c.blank]
            elif isinstance(b, Question):
                pass  # a question may quote what it gives
    return "\n".join(out)


@pytest.mark.parametrize("v", SPEEDS)
@pytest.mark.parametrize("name", particle_presets())
def test_nothing_before_the_key_tells_what_the_questions_ask(name, v):
    h = run(load(name).with_overrides(v=v))
    doc = build([(name, h)], worksheet=True)
    blocks = [b for s in doc.sections for b in s.blocks]
    assert not any(isinstance(b, Strips) for b in blocks)  # their row labels and colour bars give velocities
    assert "What the diagram shows" not in [b.text for b in blocks if isinstance(b, Heading)]
    text = _pre_key_text(doc)
    assert "share one" not in text and "lie on one line of simultaneity" not in text
    # the rod's velocity after each collision in S' (independent: tanh of the rapidity after, less S's), in every
    # printed form but the scenario's own v (which the set-up gives)
    eta = paper_frames(v)[1].rapidity
    for i in h.impacts:
        u = math.tanh(i.rod_rapidity_after - eta)
        if abs(abs(u) - v) < 1e-9 or abs(u) < 1e-9:
            continue
        for form in (in_c(u), f"{u:+.4f}", f"{u:.3f}"):
            assert form not in text, (name, v, i.label, form)
    # the key tells all of it, and numbers its questions as the worksheet does
    key_questions = [b for b in doc.answer_key if isinstance(b, Question)]
    assert [q.number for q in key_questions] == [b.number for b in blocks if isinstance(b, Question)]
    assert any(isinstance(b, Strips) for b in doc.answer_key)


def test_questions_chosen_are_renumbered_alike_in_worksheet_and_key():
    h = run(load("fig2"))
    full = [b for b in build([("fig2", h)], worksheet=True).sections[1].blocks if isinstance(b, Question)]
    doc = build([("fig2", h)], worksheet=True, chosen=(1, 3, 5))
    asked = [b for b in doc.sections[1].blocks if isinstance(b, Question)]
    assert [q.number for q in asked] == [1, 2, 3]
    assert [q.text for q in asked] == [full[0].text, full[2].text, full[4].text]
    assert [q.number for q in doc.answer_key if isinstance(q, Question)] == [1, 2, 3]


def _other_speed_question(doc) -> str:
    return next(b.text for b in doc.blocks() if isinstance(b, Question) and b.text.startswith("Now take v ="))


def test_the_other_speed_differs_meaningfully_by_default_and_is_the_teachers_when_given():
    h = run(load("fig2").with_overrides(v=0.81))
    assert not _other_speed_question(build([("fig2", h)], worksheet=True)).startswith("Now take v = 0.8 ")
    assert _other_speed_question(build([("fig2", h)], worksheet=True, compare_v=0.4)).startswith(
        "Now take v = 0.4 instead of 0.81")


def test_key_separate_writes_the_key_as_its_own_pdf(tmp_path):
    from sears_paradox_cli.main import main as cli
    result = CliRunner().invoke(cli, ["handout", "single", "--worksheet", "--key", "separate", "-o", str(tmp_path)])
    assert result.exit_code == 0, result.output
    assert sorted(p.name for p in tmp_path.iterdir()) == ["single_worksheet.pdf", "single_worksheet_key.pdf"]


@pytest.mark.parametrize("args, message", [
    (["--questions", "1,3"], "Error: option --questions is for a worksheet; add --worksheet.\n"),
    (["--worksheet", "--questions", "0,3"],
     "Error: option --questions must be question numbers from 1 to 8, comma-separated, each once (1,3,5), "
     "got '0,3'.\n"),
    (["--worksheet", "--compare-v", "1"], "Error: option --compare-v must be a speed with 0 < v < 1 (units of c), "
                                          "got 1.0.\n"),
    (["--worksheet", "--key", "separate", "--format", "tex"],
     "Error: option --key separate writes a second PDF; with --format tex the key is in handout.tex.\n"),
])
def test_bad_worksheet_options_are_one_sentence_and_exit_2(tmp_path, args, message):
    from sears_paradox_cli.main import main as cli
    result = CliRunner().invoke(cli, ["handout", "single", "-o", str(tmp_path), *args])
    assert (result.exit_code, result.output) == (2, message)
    assert list(tmp_path.iterdir()) == []
