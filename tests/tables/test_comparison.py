"""A comparison of the two rods says first where the particles started and where each rod's first impacts fall,
and every `--rod both` output is of two rods struck by the same particles (docs, "The causal rod")."""

from __future__ import annotations

import json
import re

import pytest
from click.testing import CliRunner

from rodparadox.io.scenario import load
from rodparadox.physics.frames import paper_frames
from rodparadox.physics.models import run_rods
from rodparadox.tables.comparison import comparison_note
from sears_paradox_cli.main import main


@pytest.fixture(scope="module")
def fig2_note() -> str:
    s = load("fig2")
    return comparison_note(run_rods(s, "both"), paper_frames(s.v))


def test_fig2s_note_against_the_paper_and_a_hand_computation(fig2_note):
    # A placed for the rigid rod: A1 at (-3/4, 19/12) in S (the paper), so A starts at -3/4 - 0.6 * 19/12 = -1.7
    assert "A from x = \N{MINUS SIGN}1.7 L at speed 0.6 c and B from x = 1 L at speed 0.6 c" in fig2_note
    # the rigid rod: B1 (t = 5/6) and A1 (t = 19/12) simultaneous in S' at t' = 17/12 (the paper's Fig. 2)
    assert ("The rigid rod: B\N{SUBSCRIPT ONE} and A\N{SUBSCRIPT ONE} are simultaneous in S\N{PRIME} (at 1.417 L), "
            "not in S (B\N{SUBSCRIPT ONE} at 0.8333 L, A\N{SUBSCRIPT ONE} at 1.583 L)") in fig2_note
    # the causal rod: B1 is the same event (B meets the resting right end at t = 0.5/0.6); A1 comes after the
    # front from B1 reaches the left end (t = 5/6 + 1) and before A would reach the resting end (t = 1.2/0.6 = 2)
    causal = fig2_note[fig2_note.index("The causal rod"):]
    assert "not simultaneous in S (B\N{SUBSCRIPT ONE} at 0.8333 L" in causal
    t_A1 = float(re.search(r"in S \(B₁ at 0\.8333 L, A₁ at ([0-9.]+) L\)", causal).group(1))
    assert 11 / 6 < t_A1 < 2.0


def test_a_single_particle_has_one_first_impact():
    s = load("single")
    note = comparison_note(run_rods(s, "both"), paper_frames(s.v))
    assert "its first impact B\N{SUBSCRIPT ONE} at t = 0.8333 L in S" in note  # 0.5 L at 0.6 c


def invoke(*args: str) -> str:
    result = CliRunner().invoke(main, list(args))
    assert result.exit_code == 0, result.output
    return result.output


@pytest.mark.parametrize("name", ["fig2", "off_timing", "unequal_masses"])
def test_every_both_rods_export_shares_the_particles_initial_world_lines(name):
    doc = json.loads(invoke("export", name, "--rod", "both", "--format", "json"))
    rigid, causal = doc["rods"]["rigid"], doc["rods"]["causal"]
    assert (rigid["rod"], causal["rod"]) == ("rigid", "causal")
    for p, a in rigid["scenario"]["particles"].items():
        b = causal["scenario"]["particles"][p]
        assert a["speed"] == b["speed"]
        assert a["start"] == pytest.approx(b["start"], abs=1e-12)
    rows = invoke("export", name, "--rod", "both", "--format", "csv").splitlines()
    assert rows[0].startswith("rod,frame,kind") and {r.split(",")[0] for r in rows[1:]} == {"rigid", "causal"}


@pytest.mark.parametrize("command", [("events",), ("events", "--format", "markdown"), ("events", "--format", "latex"),
                                     ("ledger",), ("ledger", "--format", "markdown"), ("ledger", "--format", "latex")])
def test_every_both_rods_table_states_the_shared_particles_first(command):
    out = invoke(command[0], "fig2", "--rod", "both", *command[1:])
    head = out[:400].replace("\n% ", " ").replace("\n", " ")
    assert "Both rods are struck by the same particles: A from x = \N{MINUS SIGN}1.7 L" in head
    assert out.count("rigid rod") >= 1 and out.count("causal rod") >= 1
