"""A scenario with forces at the ends in every command, and a rod that cannot carry the forces refused naming why,
in one sentence (no traceback)."""

import json
import math

import pytest

from helpers import error_of, run
from rodparadox.io.scenario import load
from rodparadox.physics.models import run_rod


@pytest.mark.parametrize("mode", ["now", "boost"])
def test_animate_shows_a_rod_driven_by_forces_in_both_modes(mode, tmp_path):
    """Two stills of the causal rod pushed (push), each mode: written, and the same bytes twice."""
    args = ("animate", "push", "--rod", "causal", "--mode", mode, "--format", "png", "--fps", "1", "--seconds", "2")
    run(*args, "-o", tmp_path / "one")
    run(*args, "-o", tmp_path / "two")
    one, two = sorted((tmp_path / "one").rglob("*.png")), sorted((tmp_path / "two").rglob("*.png"))
    assert len(one) == 2 and [p.read_bytes() for p in one] == [p.read_bytes() for p in two]


@pytest.mark.parametrize("args, words", [
    (("events", "sears", "--format", "latex"), "printed as text only for now"),
])
def test_what_events_cannot_do_with_forces_is_refused_in_one_sentence(args, words):
    assert words in error_of(*args)


def test_events_and_export_show_both_rods_driven_by_forces(tmp_path):
    """The causal rod is driven too: Sears's pulses peak at t = 1 of S at both ends, where its pushed end moves at
    tanh(ln(1 + 2F/rho0)/2) = F/(rho0 + F) = 0.2/1.2 (r+ = 0 still: nothing has crossed the rod yet)."""
    text = run("events", "sears", "--rod", "both").stdout
    assert "Both rods are driven by the same forces at their ends" in text and "The causal rod" in text
    assert f"{0.2 / 1.2:+.6f}" in text and f"{-0.2 / 1.2:+.6f}" in text
    path = tmp_path / "both.json"
    run("export", "sears", "--rod", "both", "-o", path)
    rods = json.loads(path.read_text())["rods"]
    assert set(rods) == {"rigid", "causal"} and rods["causal"]["drive"] == "forces"
    assert rods["causal"]["frames"]["rest"]["t_range"] == [-0.5, 2.5]  # L before the first force, L after the last


def test_a_pull_past_the_causal_limit_is_refused_naming_the_limit(tmp_path):
    path = tmp_path / "pull.yaml"
    path.write_text("v: 0.6\nforces:\n  right: {shape: step, peak: -0.5, start: 0, duration: 1}\n")
    message = error_of("events", path, "--rod", "causal")
    assert "forces.right pulls with 0.5 M c^2/L, but the causal rod carries a pull only below M c^2/(2L)" in message


def test_a_pull_past_the_rigid_limit_is_refused_naming_the_limit(tmp_path):
    path = tmp_path / "pull.yaml"
    path.write_text("v: 0.6\nforces:\n  right: {shape: step, peak: -1.0, start: 0, duration: 1}\n")
    message = error_of("events", path)
    assert "forces.right pulls with 1 M c^2/L, but the rigid rod carries a pull only below M c^2/L" in message


def test_events_lists_each_force_start_peak_and_end_in_each_frame():
    text = run("events", "sears_moving", "--frame-velocity", "0.3").output
    for frame in ("frame rest", "frame moving", "frame u=0.3"):
        assert frame in text
    assert text.count("start left") == 3 and text.count("peak  right") == 3 and text.count("end   right") == 3
    # timed in S': both forces start at t' = 0.5 in S'
    moving = text.split("frame moving")[1].split("frame u=0.3")[0]
    # x and t with their column's decimals in the frame (x: 1.27, t: 1.5 the largest: six)
    rows = [" ".join(line.split()) for line in moving.splitlines()]
    assert "start left -0.111644 +0.500000 +0.0000000 +0.556143" in rows
    assert "start right +0.700000 +0.500000 +0.0000000 +0.600000" in rows


def test_export_writes_the_profiles_the_force_events_and_the_world_lines():
    data = json.loads(run("export", "push", "--L", "2").output)
    assert data["drive"] == "forces" and data["scenario"]["forces"]["left"]["area"] == 1.0
    rest = data["frames"]["rest"]
    events = {(e["end"], e["moment"]): e for e in rest["events"]}
    assert all(e["kind"] == "force" for e in rest["events"])
    # the push (0.25 M c^2/L on a rod of L = 2) from t = 1 to 9: the end's velocity F s / sqrt(1 + (F s)^2), F = 0.125
    assert math.isclose(events["left", "end"]["end_velocity"], 1 / math.sqrt(2), rel_tol=1e-12)
    assert math.isclose(events["left", "peak"]["t"], 5.0, rel_tol=1e-12)
    t_lo, t_hi = rest["t_range"]
    assert t_lo <= 1.0 - 2.0 and t_hi >= 9.0 + 2.0  # from L before the first force to L after the last ends
    assert len(rest["material_worldlines"]) == 9
    assert {s["kind"] for s in rest["segments"]["rod_left"]} == {"line", "arc"}
    h = run_rod(load("push").with_overrides(L=2.0))
    for x, t in rest["worldlines"]["rod_right"][::7]:
        assert abs(h.worldline("rod_right").event_at_time(t).x - x) <= 1e-12 * 10


def test_export_csv_has_a_force_row_per_event():
    rows = run("export", "sears", "--format", "csv").output.splitlines()
    assert rows[0] == "frame,kind,name,particle,end,index,x,t"
    assert sum(1 for r in rows if ",force," in r) == 12 and "np." not in "".join(rows)


def test_ledger_writes_delivered_rod_parts_and_the_check_per_slice():
    data = json.loads(run("ledger", "sears", "--frame", "moving", "--format", "json").output)
    assert data["drive"] == "forces"
    slices = data["frames"]["moving"]["slices"]
    assert len(slices) >= 9
    for s in slices:
        for q in ("E", "p"):
            assert abs(s["rod"][q] - s["initial_plus_delivered"][q]) <= 1e-9
            assert abs(s["rod_kinetic"][q] + s["rod_stress"][q] - s["rod"][q]) <= 1e-12
        assert abs(s["rod_kinetic"]["p"] - 0.75) <= 1e-12  # the rod rests in S all along: its kinetic part is g v
    assert max(s["rod_stress"]["p"] for s in slices) > 0.05  # Sears's hidden momentum, a computed row
    text = run("ledger", "sears", "--at", "0.5,1").output
    assert text.count("initial + delivered") == 4 and "centre of energy" in text


@pytest.mark.parametrize("args, words", [
    (("ledger", "sears", "--format", "markdown"), "ledger is written as text, json or csv only for now"),
])
def test_what_ledger_cannot_do_with_forces_is_refused_in_one_sentence(args, words, tmp_path):
    assert words in error_of(*args, "-o", tmp_path / ("x." + args[-1]))


def test_the_ledger_names_each_rods_own_parts():
    """The rigid rod's (E, p) splits into kinetic and stress parts, the causal rod's into matter (elastic energy
    included) and stress, as its ledger with particles does; both add up to initial + delivered."""
    text = run("ledger", "sears", "--rod", "both").stdout
    rigid, causal = text.split("the causal rod driven by forces")
    assert "rod kinetic" in rigid and "rod matter" not in rigid
    assert "rod matter" in causal and "rod kinetic" not in causal and "elastic energy included" in causal


def test_ledger_draws_the_figure_of_a_rod_driven_by_forces(tmp_path):
    """The figure: what each agent delivered, the rod's parts and its whole, the check on the table's slices."""
    path = tmp_path / "push.svg"
    run("ledger", "push", "--rod", "causal", "--frame", "rest", "-o", path)
    svg = path.read_text()
    for gid in ("a-p-left", "a-E-right", "a-p-rod_part", "a-p-stress", "a-p-rod", "a-p-check", "a-label-left on"):
        assert f'id="{gid}"' in svg
