"""The causal rod on the command line (issue 16, items 1 and 4): rod: and --rod, the refusals, events and the JSON
contract's "rod", "kind" and material world-lines. In-process (CliRunner); one causal export shared."""

from __future__ import annotations

import json
import math

import pytest
from click.testing import CliRunner

from sears_paradox_cli.main import main

#: one worker runs this file, so its shared fixtures are built once (`--dist loadgroup`, pyproject.toml)
pytestmark = pytest.mark.xdist_group("causal_cli")


def run(*args, expect=0):
    result = CliRunner().invoke(main, list(args))
    assert result.exit_code == expect, result.output
    return result


@pytest.fixture(scope="module")
def causal_json():
    return json.loads(run("export", "single", "--rod", "causal").output)


def test_export_names_the_rod_and_each_event_kind(causal_json):
    """Single: B strikes the resting rod; contact, then separation at chart time 2L (rest frame: the struck end
    then moved), B leaving at tanh(th_f/2) = tanh(th0/2) exp(-2) (M = m)."""
    assert causal_json["rod"] == "causal"
    for frame in causal_json["frames"].values():
        assert [(e["label"], e["kind"]) for e in frame["events"]] == [("B1", "contact"), ("B1s", "separation")]
    v = causal_json["scenario"]["v"]
    th_f = -2 * math.atanh(math.tanh(math.atanh(v) / 2) * math.exp(-2))
    assert causal_json["frames"]["rest"]["events"][1]["particle_velocity_after"] == pytest.approx(math.tanh(th_f), abs=1e-12)
    rigid = json.loads(run("export", "single").output)
    assert rigid["rod"] == "rigid" and {e["kind"] for f in rigid["frames"].values() for e in f["events"]} == {"contact"}


def test_export_polylines_within_the_sampling_tolerance(causal_json):
    """Ends, particles and nine material points as polylines, every point on its world-line's exact position and
    every polyline time-like; the exact curve between points (the causal history recomputed) within tolerance."""
    from rodparadox.io.scenario import load
    from rodparadox.physics.causal import run as run_causal

    h = run_causal(load("single"))
    tolerance = causal_json["sampling_tolerance"]
    frame = causal_json["frames"]["moving"]
    eta = -math.atanh(causal_json["scenario"]["v"])
    assert set(frame["worldlines"]) == {"B", "rod_left", "rod_right"}
    material = frame["material_worldlines"]
    assert [m["sigma"] for m in material] == pytest.approx([k / 8 for k in range(9)])
    for m in (material[0], material[5]):
        curve = h.material_worldline(m["sigma"]).seen_from(eta)
        pts = m["points"]
        for (x0, t0), (x1, t1) in zip(pts, pts[1:]):
            assert abs(x1 - x0) < t1 - t0
            for q in (0.25, 0.5, 0.75):  # the exact curve at a time between two points, against the chord
                t = t0 + q * (t1 - t0)
                chord_x = x0 + q * (x1 - x0)
                assert abs(curve.event_at_time(t).x - chord_x) <= 2 * tolerance


def test_events_list_contacts_and_separations():
    out = run("events", "fig1", "--rod", "causal").output
    for label in ("A1 ", "B1 ", "A1s", "B1s"):
        assert label in out


def test_rod_key_and_option(tmp_path):
    """rod: causal in a file is run by the causal rod, --rod rigid overrides it; a sound speed below c is refused."""
    path = tmp_path / "s.yaml"
    path.write_text("v: 0.6\nrod: causal\nparticles:\n  A: {gap: 0.5}\n")
    assert "A1s" in run("events", str(path)).output
    assert "A1s" not in run("events", str(path), "--rod", "rigid").output
    path.write_text("v: 0.6\nrod: elastic\nparticles:\n  A: {gap: 0.5}\n")
    assert "rod must be rigid or causal, got 'elastic'." in run("events", str(path), expect=2).output
    path.write_text("v: 0.6\nsound_speed: 0.5\nparticles:\n  A: {gap: 0.5}\n")
    out = run("events", str(path), expect=2).output
    assert "sound_speed must be 1" in out and "shocks" in out and "Traceback" not in out
    # review: sound_speed: 1 beside the rigid rod (the default, or rod: rigid) ran the rigid model without a word
    for rod in ("", "rod: rigid\n"):
        path.write_text(f"v: 0.6\n{rod}sound_speed: 1\nparticles:\n  A: {{gap: 0.5}}\n")
        assert "give rod: causal with it" in run("events", str(path), expect=2).output
    path.write_text("v: 0.6\nrod: causal\nsound_speed: 1\nparticles:\n  A: {gap: 0.5}\n")
    assert "A1s" in run("events", str(path)).output
    path.write_text("v: 0.6\nrod: 1\nparticles:\n  A: {gap: 0.5}\n")
    assert "rod must be rigid or causal, got 1 (a whole number)." in run("events", str(path), expect=2).output


def test_commands_without_both_refuse_it():  # (html takes the causal rod and both now: tests/web/test_html.py)
    out = run("animate", "fig1", "--rod", "both", expect=2).output
    assert "shows one rod at a time, so it does not take --rod both; run it once with --rod rigid and once with --rod causal." in out

