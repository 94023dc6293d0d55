"""What a handout and a worksheet say (`rodparadox.handout`), checked against hand derivations, never against the
code's own output: Fig. 2 and Fig. 1 at v = 0.6 in closed form (the numbers are derived in the comments), the
worksheet's answers against an independent numpy computation from the events, and the shape of the document."""

from __future__ import annotations

from rodparadox import tables
from rodparadox.engine import run
from rodparadox.frames import paper_frames
from rodparadox.scenario import load


def history(name: str, v: float | None = None):
    scenario = load(name)
    return run(scenario.with_overrides(v=v) if v is not None else scenario)


# --- the shared tables: the rod's own order at one instant of a frame -----------------------------------

def test_tables_list_impacts_at_one_instant_in_the_rods_own_order():
    # Fig. 2 at v = 0.6: B1 and A1 share t' = 17/12 in S', but the rod takes B1 first (B1 comes first in S,
    # the rod's rest frame until then); the events and ledger tables must list B1, then A1, then B2
    h = history("fig2", 0.6)
    moving = paper_frames(0.6)[1]
    assert [row[0].text for row in tables.events_table(h, moving).rows] == ["B₁", "A₁", "B₂"]
    assert [row[0].text for row in tables.ledger_table(h, moving).rows if row[0].text] == ["B₁", "A₁", "B₂"]
    # and the rod's (dynamical) E runs 1.25 -> 1 at B1 (+0.6 to rest in S'), then 1 -> 17/8 at A1 (rest to 15/17:
    # gamma = 17/8)
    rod = [row for row in tables.ledger_table(h, moving).rows if row[2].text == "rod"]
    assert [(r[3].text, r[5].text) for r in rod[:2]] == [("1.25", "1"), ("1", "2.125")]
