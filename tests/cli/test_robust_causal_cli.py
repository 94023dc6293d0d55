"""What a new user broke in the causal rod, the rod's own view and the ledger figures (issue 27): each case in
process (click's runner), fast; `tests/robustness_check.py` runs them and their variants as real processes under a
memory limit and a timeout."""

from __future__ import annotations

import pytest

from helpers import error_of, run




@pytest.mark.parametrize("args, panels", [
    (("plot", "fig2", "--rod", "both", "--frame", "0,0.1,0.2,0.3,0.4"), 10),
    (("plot", "fig2", "--frame", "rest,moving,0.1,0.2,0.3,0.4,0.5,0.6,rod"), 9),
    (("animate", "fig2", "--frame", "rod,rest,moving,0.1,0.2,0.3,0.4,0.5,0.6"), 9),
    (("plot", "fig1", "--rod", "both", "--frame", "both,0.3,0.5,rod"), 9),
])
def test_at_most_eight_panels(args, panels, tmp_path):
    """Issue 27, item 9: 8 panels at most, the rod's own view counted and each frame twice with --rod both (a
    traceback from the drawing, or 9 panels accepted, before)."""
    message = error_of(*args, "-o", tmp_path)
    assert f"asks for {panels} panels" in message and "at most 8" in message
    assert not list(tmp_path.iterdir())


def test_sound_speed_is_checked_against_the_rod_being_run(tmp_path):
    """Issue 27, item 10: sound_speed: 1 without rod: and --rod causal on the command line is the causal rod, run;
    without --rod causal (or with --rod rigid) it is refused in one sentence naming both ways to fix it."""
    path = tmp_path / "ss.yaml"
    path.write_text("name: ss\nv: 0.6\nsound_speed: 1\nparticles:\n  A:\n    gap: 0.5\n")
    assert "A1s" in run("events", path, "--rod", "causal").output
    for extra in ((), ("--rod", "rigid")):
        message = error_of("events", path, *extra)
        assert "give rod: causal with it, or --rod causal" in message



def test_causal_boost_to_near_c_is_refused(tmp_path):
    """Issue 27, item 4: animate --rod causal --mode boost --frame rest..0.9999999 tried to allocate 286 GiB (its
    window, every frame's, spans thousands of L where the rod rings): refused in one sentence naming the frames."""
    message = error_of("animate", "fig2", "--rod", "causal", "--mode", "boost", "--frame", "rest..0.9999999",
                       "--fps", "4", "--seconds", "1", "-o", tmp_path)
    assert "boost between slower frames" in message and "--mode now" in message
    assert not list(tmp_path.iterdir())
