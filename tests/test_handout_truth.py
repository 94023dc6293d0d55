"""Every generated sentence is true (issue 14, item 2): the claims of a handout's explanation checked against an
independent computation, the rod's material velocities read from `History.material_velocity` over a grid of
material points and instants, for every preset at v = 0.3, 0.6, 0.95; and the three sentences the issue found
wrong, as regression tests."""

from __future__ import annotations

import re

import numpy as np
import pytest

from rodparadox.handout.narrative import explanation
from rodparadox.io.scenario import builtin_names, load
from rodparadox.numbers import MINUS
from rodparadox.physics.engine import run
from rodparadox.physics.frames import paper_frames

SPEEDS = (0.3, 0.6, 0.95)
#: a number as the text writes it: 5/6, 1.2, −0.75
NUMBER = r"[+−]?[0-9]+(?:\.[0-9]+)?(?:/[0-9]+)?"


def _text(name: str, v: float) -> str:
    return " ".join(p.text for p in explanation(run(load(name).with_overrides(v=v)), paper_frames(v)))


def _number(text: str) -> float:
    text = text.replace(MINUS, "-").replace("+", "")
    if "/" in text:
        a, b = text.split("/")
        return float(a) / float(b)
    return float(text)


def _material_range(h, frame_rapidity: float, n: int = 17) -> tuple[float, float]:
    """The least and greatest velocity in the frame of any material point, over a grid of the frame's time that
    spans every impact and well beyond (an independent reading: the world-lines, not the turns' bookkeeping)."""
    times = [i.event.time_in(frame_rapidity) for i in h.impacts]
    L = h.scenario.L
    grid = np.concatenate([np.linspace(min(times) - 2 * L, max(times) + 4 * L, 241), times])
    us = [h.material_velocity(sigma, frame_rapidity, t) for sigma in np.linspace(0, L, n) for t in grid]
    return min(us), max(us)


# --- the three wrong sentences of the issue ------------------------------------------------------------------------

def test_fig2_next_turn_after_the_rest_in_s_prime_is_a1s():
    text = _text("fig2", 0.6)
    assert "A₁ starts the next one at that same instant" in text
    assert "B₂ starts the next one" not in text


def test_fig2_does_not_deny_what_it_says_next():
    # B1 and A1 both lie on the rod's line t' = 17/12 at the end of B1's turn: never say they are "not on one of
    # the rod's own lines"
    assert "not on one of the rod's own lines" not in _text("fig2", 0.6)


def test_while_turning_081_never_stops_in_s_prime_and_is_never_driven_at_081_in_s():
    h = run(load("while_turning").with_overrides(v=0.81))
    text = _text("while_turning", 0.81)
    s_prime = paper_frames(0.81)[1].rapidity
    low, high = _material_range(h, s_prime)
    assert low > 0.6  # independent: the material never stands still in S' (+0.68..+0.89)
    assert "in S′ it stops" not in text
    assert "driven at +0.81 c in S" not in text
    low_s, high_s = _material_range(h, 0.0)
    assert high_s < 0.3 and low_s > -0.3


# --- every preset, every speed: each kind of claim against the grid ------------------------------------------------

@pytest.mark.parametrize("v", SPEEDS)
@pytest.mark.parametrize("name", builtin_names())
def test_claims_about_the_material_hold(name, v):
    h = run(load(name).with_overrides(v=v))
    text = _text(name, v)
    frames = {"S": 0.0, "S′": paper_frames(v)[1].rapidity}
    ranges = {symbol: _material_range(h, rapidity) for symbol, rapidity in frames.items()}
    number = r"([+−]?[0-9./]+) c"
    # "the rod's material only ever moves at velocities from X to Y in F"
    for low, high, symbol in re.findall(rf"from {number} to {number} in (S′|S)(?!′)", text):
        lo, hi = ranges[symbol]
        assert abs(_number(low) - lo) < 2e-3 and abs(_number(high) - hi) < 2e-3, (symbol, low, high, lo, hi)
    # "in F it ... stops (X)": the whole rod stands still in F at some instant (a grid of instants near each impact
    # is too coarse, so: the material's velocities in F reach 0)
    for symbol, steps in re.findall(r"[Ii]n (S′|S)(?!′) it ([^;.]*)", text):
        if "stops" in steps:
            lo, hi = ranges[symbol]
            assert lo <= 1e-6 and hi >= -1e-6, (name, v, symbol, steps, lo, hi)
        if "never moving backwards" in steps:
            lo, hi = ranges[symbol]
            assert lo >= -1e-9 or hi <= 1e-9, (name, v, symbol, lo, hi)
    # "the rod's X end moved at U in S": that end's velocity just before the impact, read from its world-line
    for end, u in re.findall(rf"the rod's (left|right) end moved at {number} in S", text):
        sigma = 0.0 if end == "left" else h.scenario.L
        again = [i for i in h.impacts if i.end == end][-1]
        measured = h.material_velocity(sigma, 0.0, again.event.t - 1e-6)
        assert abs(_number(u) - measured) < 2e-3, (name, v, end, u, measured)
    # "stops" never claimed where the range in that frame excludes 0
    for symbol, (lo, hi) in ranges.items():
        if lo > 1e-6 or hi < -1e-6:
            assert not re.search(rf"[Ii]n {re.escape(symbol)} it [^;.]*stops", text), (name, v, symbol)


# --- the rigid rod as an idealisation: its far end moves before light from the impact could reach it --------------

@pytest.mark.parametrize("v", SPEEDS)
@pytest.mark.parametrize("name", builtin_names())
def test_the_far_end_moves_before_light_from_the_impact_reaches_it(name, v):
    from rodparadox.handout.build import introduction
    from rodparadox.numbers import impact_name

    h = run(load(name).with_overrides(v=v))
    text = introduction([h]).blocks[-1].text
    found = re.search(rf"(\S+) strikes the rod’s (left|right) end at t = ({NUMBER}) L in S, and the (left|right) end "
                      rf"starts to move at that same instant of S, while light from \1 reaches it only at t = "
                      rf"({NUMBER}) L\.", text)
    if not any(t.rapidity_from == 0.0 for t in h.rigid.turns[:1]):
        assert found is None and "In the scenario" not in text  # fig1: the rod never turns
        return
    assert found, text
    label, end, moves, far, light = found.groups()
    impact = next(i for i in h.impacts if impact_name(i.label) == label)
    L = h.scenario.L
    assert impact.end == end and far != end and abs(_number(moves) - impact.event.t / L) < 1e-6
    # independent: the far end's material velocity in S, read from its world-line, is 0 before the impact's instant
    # and not after it; light from the impact crosses to the far end's place at rest (x = ∓L/2)
    sigma = 0.0 if far == "left" else L
    eps = 1e-6 * L
    assert h.material_velocity(sigma, 0.0, impact.event.t - eps) == pytest.approx(0.0, abs=1e-9)
    assert abs(h.material_velocity(sigma, 0.0, impact.event.t + eps)) > 0.0
    x_far = -L / 2 if far == "left" else L / 2
    assert abs(_number(light) - (impact.event.t + abs(x_far - impact.event.x)) / L) < 1e-6
    assert _number(light) > _number(moves)
