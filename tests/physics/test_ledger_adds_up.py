"""Every ledger table adds up (issue 14, item 3): in each table a handout, a worksheet's key, `ledger --format
markdown` and the text of `ledger` print, the printed particles, the rod's kinetic part and the hidden part sum to
the printed total row, which is the total before the first impact; impacts at one instant of a frame are one row
group; the rod's dynamical (E, p) is labelled apart. Numbers are parsed from the printed text."""

from __future__ import annotations

import re

import pytest

from rodparadox.io.ledger_report import to_text
from rodparadox.io.scenario import load

from helpers import particle_presets
from rodparadox.physics.rigid import run
from rodparadox.physics.frames import paper_frames
from rodparadox.tables import build as tables

SPEEDS = (0.3, 0.6, 0.95)
SUMMANDS = ("particle A", "particle B", "rod, kinetic", "hidden")


def _n(text: str) -> float:
    return float(text.replace("−", "-"))


def _groups(rows):
    out = []
    for row in rows:
        if row[0]:
            out.append([])
        out[-1].append(row)
    return out


@pytest.mark.parametrize("v", SPEEDS)
@pytest.mark.parametrize("name", particle_presets())
def test_every_ledger_table_adds_up_to_the_total_before_the_first_impact(name, v):
    h = run(load(name).with_overrides(v=v))
    for frame in paper_frames(v):
        total = h.initial_total(frame.rapidity)  # independent: the bodies before the first impact
        table = tables.ledger_table(h, frame)
        rows = [[c.text for c in row] for row in table.rows]
        times = [_n(r[1]) for r in rows if r[0]]
        assert len(times) == len(set(times)), "impacts at one instant must be one row group"
        for group in _groups(rows):
            bodies = {r[2]: [_n(x) for x in r[3:]] for r in group}
            assert set(bodies) - set(SUMMANDS) == {"total", tables.ROD_DYNAMICAL}
            summed = [sum(bodies[b][k] for b in SUMMANDS if b in bodies) for k in range(4)]
            for k in range(4):
                assert abs(summed[k] - bodies["total"][k]) <= 3e-4, (name, v, frame.name, group[0][0], k)
            assert bodies["total"] == pytest.approx([total.E, total.p] * 2, abs=1e-4)
            # one format per column: every number of the table has 4 decimals
            assert all(re.fullmatch(r"−?\d+\.\d{4}", x) for r in group for x in r[3:])


@pytest.mark.parametrize("name", particle_presets())
def test_ledger_text_adds_up(name):
    h = run(load(name).with_overrides(v=0.6))
    text = to_text(h, paper_frames(0.6))
    for block in text.split("  impact ")[1:]:
        lines = []
        for line in block.splitlines()[2:]:
            lines.append(line.split())
            if lines[-1][0] == "total":
                break
        values = {" ".join(l[:-4]): [float(x) for x in l[-4:]] for l in lines}
        summed = [sum(vals[k] for body, vals in values.items() if body != "total") for k in range(4)]
        assert summed == pytest.approx(values["total"], abs=3e-4), block
        assert "not a summand" in block


def test_fig2_in_s_prime_b1_and_a1_are_one_row_with_one_hidden_part():
    # S', fig2 at v = 0.6: B1 and A1 share t' = 17/12; just before both, the rod has been turning since t' = 2/3
    # (its left end first) and is at rest on the slice, so the hidden part is the total
    # (4.375, 2.625) less A (17/8, 15/8), B (1, 0) and the rod at rest on the slice (1, 0): (0.25, 0.75)
    h = run(load("fig2"))
    rows = [[c.text for c in r] for r in tables.ledger_table(h, paper_frames(0.6)[1]).rows]
    hidden = [r for r in rows if r[2] == "hidden"]
    assert len(hidden) == 2  # two instants: {B1, A1} and B2
    assert hidden[0][3:5] == ["0.2500", "0.7500"]
