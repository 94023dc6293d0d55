"""The events, ledger and hidden tables a handout prints (rodparadox.tables.build), against hand derivations at v = 0.6
(g = 5/4), and numbers.fraction."""

from __future__ import annotations

import math

import pytest

from rodparadox.handout.document import Cell, Table
from rodparadox.physics.rigid import run
from rodparadox.physics.frames import moving_frame, rest_frame
from rodparadox.numbers import MINUS, fraction, fraction_text, impact_name
from rodparadox.io.scenario import load
from rodparadox.tables.build import events_table, hidden_table, ledger_table, with_fraction


def history(name: str, v: float = 0.6):
    return run(load(name).with_overrides(v=v))


def number(text: str) -> float:
    """The decimal of a cell (`+1.416667 (17/12)` -> 1.416667)."""
    return float(text.split(" (")[0].replace(MINUS, "-"))


def rows_by_label(table: Table) -> dict[str, list[str]]:
    return {row[0].text: [c.text for c in row] for row in table.rows if row[0].text}


@pytest.mark.parametrize("value, expected", [(17 / 12, (17, 12)), (-1 / 3, (-1, 3)), (15 / 17, (15, 17)),
                                             (1.25, None), (0.73, None), (math.sqrt(2), None), (0.0, None),
                                             (3.0, None), (1 / 101, None), (float("nan"), None)])
def test_fraction_only_where_the_decimal_never_ends_and_the_denominator_is_small(value, expected):
    assert fraction(value) == expected


def test_fraction_text_has_a_real_minus_and_needs_a_match_to_1e12():
    assert fraction_text(-17 / 12) == f"{MINUS}17/12"
    assert fraction_text(17 / 12 + 1e-9) is None
    assert fraction_text(17 / 12 * (1 + 1e-14)) == "17/12"


def test_events_in_s_prime_at_v_06_are_the_papers_fractions():
    # Fig. 2 in S': both first impacts at t' = 17/12 L; the rod's velocity after A1 is 2v/(1+v^2) = 15/17
    table = events_table(history("fig2"), moving_frame(0.6))
    rows = rows_by_label(table)
    assert set(rows) == {"A₁", "B₁", "B₂"}
    for label in ("A₁", "B₁"):
        assert rows[label][3].endswith("(17/12)")
        assert number(rows[label][3]) == pytest.approx(17 / 12, abs=1e-6)
    assert rows["A₁"][7] == "+0.882353 (15/17)"
    assert table.header[2:4] == ("x′", "t′")
    assert [row[0].text for row in table.rows][:2] == ["B₁", "A₁"]  # one instant of S′: the rod takes B₁ first


def test_events_in_s_at_v_06():
    # S: B1 at t = 5/6 (B at 0.6 from x = 1 to x = 0.5), A1 at t = 19/12 and B2 at t = 7/3 (paper, Fig. 2)
    rows = rows_by_label(events_table(history("fig2"), rest_frame()))
    assert number(rows["B₁"][3]) == pytest.approx(5 / 6, abs=1e-6) and rows["B₁"][3].endswith("(5/6)")
    assert number(rows["A₁"][3]) == pytest.approx(19 / 12, abs=1e-6)
    assert number(rows["B₂"][3]) == pytest.approx(7 / 3, abs=1e-6)
    assert number(rows["A₁"][2]) == pytest.approx(-0.75, abs=1e-7) and "(" not in rows["A₁"][2]


def test_a_worksheet_table_leaves_every_number_blank_and_keeps_the_labels():
    h = history("fig2")
    blank = events_table(h, rest_frame(), blank=True)
    full = events_table(h, rest_frame())
    assert blank.has_blanks and not full.has_blanks
    assert all(not c.blank for row in blank.rows for c in row[:2])
    assert all(c.blank for row in blank.rows for c in row[2:])
    assert blank.filled() == full


def test_ledger_per_impact_in_s_prime_by_hand():
    # S', fig2 at v = 0.6: A at 2v/(1+v^2) = 15/17 has gamma = 17/8 and gamma*u = 15/8, so (E, p) = (2.125, 1.875)
    # before A1 and (1, 0) after (A stops); B at rest before B1 and at +0.6 after: (1.25, 0.75)
    rows = [[c.text for c in row] for row in ledger_table(history("fig2"), moving_frame(0.6)).rows]
    # B1 and A1 share t' = 17/12: one row group, just before both and just after both
    first = rows.index(next(r for r in rows if r[0] == "B₁ and A₁"))
    assert rows[first][2:] == ["particle A", "2.1250", "1.8750", "1.0000", "0.0000"]
    assert rows[first + 1][2:] == ["particle B", "1.0000", "0.0000", "1.2500", "0.7500"]
    assert [r[2] for r in rows[first + 2:first + 6]] == ["rod, kinetic", "hidden", "total", "rod, dynamical (not a summand)"]


def test_hidden_part_of_fig1_zero_in_s_and_m_2g2v2_2g2v_in_s_prime():
    h = history("fig1")
    assert hidden_table(h, rest_frame()) is None
    table = hidden_table(h, moving_frame(0.6))
    # between the impacts, M (2 g^2 v^2, 2 g^2 v) = (1.125, 1.875) at v = 0.6 (README, "The ledger")
    assert [[number(c.text) for c in row[1:]] for row in table.rows] == [[1.125, 1.875]]


def test_impact_names_and_with_fraction():
    assert impact_name("B12") == "B₁₂" and impact_name("rod") == "rod"
    assert with_fraction("+1.416667", 17 / 12) == "+1.416667 (17/12)"
    assert with_fraction("+0", 0.0) == "+0"


def test_a_table_with_a_row_of_the_wrong_length_is_refused():
    with pytest.raises(ValueError, match="2 cells for 3 columns"):
        Table("t", "c", ("a", "b", "c"), ((Cell("1"), Cell("2")),), "lnn")
    with pytest.raises(ValueError, match="align"):
        Table("t", "c", ("a",), (), "x")


@pytest.mark.parametrize("v", [0.3, 0.6, 0.95])
def test_every_number_column_of_the_events_tables_shares_its_decimals(v):
    """Issue 24: the tables printed "+0" beside "+1.048285" and "+0.2500000" under "+1.250000", the times with
    six decimals under a time with seven: every number column of every events table (the rigid rod's and the causal
    rod's, in S and S′, every preset with particles) now writes each of its numbers with one number of decimals,
    the largest with seven significant digits."""
    import helpers

    from rodparadox.handout import causal_compare

    checked = 0
    for name in helpers.particle_presets():
        for rod, table_of in (("rigid", events_table), ("causal", causal_compare.events_table)):
            h = helpers.history(name, v) if rod == "rigid" else helpers.causal_history(name, v)
            for frame in (rest_frame(), moving_frame(v)):
                table = table_of(h, frame)
                for k, kind in enumerate(table.align):
                    texts = [row[k].text.split(" (")[0] for row in table.rows if kind == "n" and row[k].text]
                    if not texts or any("e" in t for t in texts):
                        continue
                    decimals = {len(t.split(".")[1]) if "." in t else 0 for t in texts}
                    assert len(decimals) == 1, (name, rod, frame.name, table.header[k], texts)
                    if table.header[k] in ("x", "t", "x\N{PRIME}", "t\N{PRIME}"):
                        largest = max(texts, key=lambda t: abs(number(t)))
                        assert len(largest.lstrip("+" + MINUS).replace(".", "").lstrip("0")) == 7, (name, texts)
                    checked += 1
    assert checked >= 6 * 2 * 2 * 6
