"""The force profiles of `physics.forces`: values, exact areas and primitives, supports, pieces and refusals, each
against a hand computation."""

import math

import numpy as np
import pytest

from rodparadox.errors import ScenarioError
from rodparadox.physics.forces import MAX_FORCE, PULL_LIMITS, ForceProfile, Forces, profile_from


def quad(f, a, b, n=200_001):
    """Simpson's rule, for an independent check of the exact areas."""
    x = np.linspace(a, b, n)
    y = f(x)
    h = (b - a) / (n - 1)
    return h / 3 * (y[0] + y[-1] + 4 * y[1:-1:2].sum() + 2 * y[2:-1:2].sum())


def test_step_values_area_support():
    p = ForceProfile("step", peak=0.3, start=0.5, duration=2.0)
    assert p.value(0.4999) == 0 and p.value(0.5) == 0.3 and p.value(2.4999) == 0.3 and p.value(2.5) == 0
    assert p.area() == pytest.approx(0.6, abs=1e-15)
    assert p.support() == (0.5, 2.5) and p.pieces() == (0.5, 2.5) and p.jumps() == (0.5, 2.5)
    assert p.least() == 0 and p.greatest() == 0.3 and p.peak_time() == 1.5
    assert p.primitive(1.0) == pytest.approx(0.15, abs=1e-15) and p.primitive(9) == pytest.approx(0.6, abs=1e-15)


def test_sine2_values_area_primitive():
    p = ForceProfile("sine2", peak=-0.2, start=1.0, duration=1.0)
    assert p.value(1.5) == pytest.approx(-0.2, abs=1e-15)
    assert p.value(1.25) == pytest.approx(-0.1, abs=1e-15)  # sin^2(pi/4) = 1/2
    assert p.value(0.999) == 0 and p.value(2.001) == 0
    assert p.area() == pytest.approx(-0.1, abs=1e-15)  # peak * duration / 2
    assert quad(p.value, 1.0, 2.0) == pytest.approx(p.area(), abs=1e-12)
    for t in (1.1, 1.37, 1.9):
        assert p.primitive(t) == pytest.approx(quad(p.value, 1.0, t), abs=1e-12)
    assert p.least() == -0.2 and p.greatest() == 0 and p.jumps() == () and p.peak_time() == 1.5


def test_points_values_area_support_jumps():
    p = ForceProfile("points", points=((0.0, 0.0), (1.0, 0.0), (2.0, 0.4), (3.0, -0.2)), frame="moving")
    assert p.value(1.5) == pytest.approx(0.2, abs=1e-15) and p.value(2.5) == pytest.approx(0.1, abs=1e-15)
    assert p.value(3.0) == 0 and p.value(-1) == 0  # zero outside [t0, tn): the last value -0.2 is a jump
    assert p.area() == pytest.approx(0.2 + 0.1, abs=1e-15)  # triangles: 1 * 0.4 / 2, then 1 * (0.4 - 0.2) / 2
    assert p.support() == (1.0, 3.0) and p.pieces() == (0.0, 1.0, 2.0, 3.0) and p.jumps() == (3.0,)
    assert p.least() == -0.2 and p.greatest() == 0.4 and p.peak_time() == 2.0
    assert p.primitive(2.5) == pytest.approx(quad(p.value, 0, 2.5), abs=1e-12)
    assert p.frame_velocity(0.6) == -0.6


def test_values_take_arrays():
    p = ForceProfile("sine2", peak=1.0, start=0.0, duration=2.0)
    t = np.array([-1.0, 0.5, 1.0, 3.0])
    assert np.allclose(p.value(t), [0.0, 0.5, 1.0, 0.0], atol=1e-15)


def test_frames():
    assert ForceProfile("step", peak=1, start=0, duration=1).frame_velocity(0.5) == 0.0
    assert ForceProfile("step", peak=1, start=0, duration=1, frame="moving").frame_velocity(0.5) == -0.5
    assert ForceProfile("step", peak=1, start=0, duration=1, frame=0.25).frame_velocity(0.5) == 0.25


def test_scaled_doubles_times_halves_forces():
    p = ForceProfile("sine2", peak=0.2, start=0.5, duration=1.0).scaled(2.0)
    assert p.support() == (1.0, 3.0) and p.value(2.0) == pytest.approx(0.1, abs=1e-15)
    assert quad(p.value, 1.0, 3.0) == pytest.approx(0.1, abs=1e-12)


@pytest.mark.parametrize("fields, key, words", [
    (dict(shape="box", peak=1, start=0, duration=1), "forces.left.shape", "step, sine2 or points"),
    (dict(shape="step", peak=1, start=0, duration=0), "forces.left.duration", "0 < duration"),
    (dict(shape="step", peak=1, start=0, duration=-1), "forces.left.duration", "0 < duration"),
    (dict(shape="step", peak=float("nan"), start=0, duration=1), "forces.left.peak", "between"),
    (dict(shape="step", peak=0, start=0, duration=1), "forces.left.peak", "not be 0"),
    (dict(shape="step", peak=2 * MAX_FORCE, start=0, duration=1), "forces.left.peak", "between"),
    (dict(shape="step", peak=1, start=float("inf"), duration=1), "forces.left.start", "between"),
    (dict(shape="step", peak=1, duration=1), "forces.left.start", "needs the key start"),
    (dict(shape="step", peak=1, start=0, duration=1, frame="sideways"), "forces.left.frame", "rest, moving"),
    (dict(shape="step", peak=1, start=0, duration=1, frame=1.0), "forces.left.frame", "rest, moving"),
    (dict(shape="step", peak=1, start=0, duration=1, frame=True), "forces.left.frame", "rest, moving"),
    (dict(shape="points", points=[[0, 1], [0, 2]]), "forces.left.points", "strictly increasing"),
    (dict(shape="points", points=[[1, 1], [0, 2]]), "forces.left.points", "strictly increasing"),
    (dict(shape="points", points=[[0, 1]]), "forces.left.points", "at least two"),
    (dict(shape="points", points=[[0, 1, 2], [1, 2]]), "forces.left.points", "pair"),
    (dict(shape="points", points=[[0, 0], [1, 0]]), "forces.left.points", "all 0"),
    (dict(shape="points", points=[[0, 0], [1, float("nan")]]), "forces.left.points", "force must be"),
    (dict(shape="points", peak=1, points=[[0, 0], [1, 1]]), "forces.left.peak", "not used"),
    (dict(shape="step", peak=900, start=0, duration=100), "forces.left", "momentum"),
    (dict(peak=1, start=0, duration=1), "forces.left.shape", "needs the key shape"),
])
def test_refusals_name_the_key_in_one_sentence(fields, key, words):
    with pytest.raises(ScenarioError) as e:
        profile_from(fields, "forces.left")
    assert e.value.key.startswith(key) and words in e.value.message
    assert e.value.message.count(". ") == 0 and e.value.message.endswith(".")


def test_forces_need_an_end_and_pull_limits():
    with pytest.raises(ScenarioError, match="left, right or both"):
        Forces(None, None)
    pull = ForceProfile("sine2", peak=-0.6, start=0, duration=1, key="forces.right")
    Forces(right=pull).check_pull("rigid")
    with pytest.raises(ScenarioError, match=r"below M c\^2/\(2L\)") as e:
        Forces(right=pull).check_pull("causal")
    assert e.value.key == "forces.right"
    at_limit = ForceProfile("points", points=((0, 0), (1, -PULL_LIMITS["rigid"]), (2, 0)))
    with pytest.raises(ScenarioError, match=r"below M c\^2/L"):
        Forces(left=at_limit).check_pull("rigid")
    assert Forces(right=pull).items() == (("right", pull),) and Forces(right=pull).at("left") is None


@pytest.mark.parametrize("profile", [
    ForceProfile("step", peak=0.3, start=0.5, duration=2.0),
    ForceProfile("sine2", peak=-0.2, start=1.0, duration=1.0),
    ForceProfile("points", points=((0.0, 0.1), (1.0, 0.1), (2.0, 0.4), (3.0, -0.2))),
])
def test_pieces_continue_their_own_formula(profile):
    """On each piece, piece_value is the profile; past it, the same smooth formula; piece_constant where flat."""
    bounds = (-5.0, *profile.pieces(), 9.0)
    for i, (lo, hi) in enumerate(zip(bounds, bounds[1:])):
        t = np.linspace(lo, hi, 7)[:-1]
        assert np.allclose(profile.piece_value(i, t), profile.value(t), atol=1e-15)
        assert profile.piece_index(float(t[0])) == i
        constant = profile.piece_constant(i)
        if constant is not None:
            assert np.all(profile.value(t) == constant)
    last = len(profile.pieces())
    assert profile.piece_value(last, 100.0) == 0.0 and profile.piece_constant(0) == 0.0
