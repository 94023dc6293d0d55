"""Generated scenarios for the property tests (hypothesis strategies: one particle, two, equal and unequal
masses, simultaneous impacts, timings in any frame, impacts while the rod turns), the explicit examples every
property also sees, and a counter that keeps a property from passing vacuously. Shared by tests/physics and
tests/handout; imported as `generated` (tests/ is on pytest's `pythonpath`).
"""

from __future__ import annotations

import functools
from collections import Counter

from hypothesis import HealthCheck, assume, example, note, settings
from hypothesis import strategies as st

from rodparadox.errors import ScenarioError
from rodparadox.io.scenario import Particle, Scenario, Timing
from rodparadox.physics.rigid import History, run

#: the properties' settings: enough examples to find the rare cases, no deadline (a run takes milliseconds to a second)
SETTINGS = settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])

RUNS: Counter = Counter()


def history_of(scenario: Scenario) -> History:
    """Run a generated scenario; a timing that contradicts itself is rejected (and counted)."""
    note(repr(scenario))
    try:
        history = run(scenario)
    except ScenarioError as e:
        RUNS["rejected"] += 1
        note(f"rejected: {e}")
        assume(False)
    RUNS["ran"] += 1
    return history


def runs_enough(prop, minimum: int, counted: str = "ran") -> None:
    """Run a hypothesis property and check that `minimum` generated scenarios ran (or were `counted`, for a property
    that sets some aside after running them): it cannot pass vacuously."""
    RUNS.clear()
    prop()
    assert RUNS[counted] >= minimum, f"only {RUNS[counted]} generated scenarios {counted} ({dict(RUNS)})"
    # about 1 in 10 generated scenarios times its particles inconsistently; far more means the engine refuses runnable ones
    assert RUNS["rejected"] <= RUNS["ran"], f"{RUNS['rejected']} generated scenarios refused, {RUNS['ran']} ran"


velocities = st.floats(0.02, 0.99)
speeds = st.one_of(st.none(), st.floats(0.02, 0.99))
masses = st.floats(0.1, 10.0)
gaps = st.floats(0.0, 3.0)
lengths = st.floats(0.1, 10.0)
delays = st.floats(-1.5, 1.5)
frames = st.one_of(st.sampled_from(["rest", "moving"]), st.floats(-0.99, 0.99))


#: "the same mass" or another: `st.one_of(st.just(m), masses)` drawn as one strategy built once (a strategy built
#: inside a draw is validated again at every draw: a quarter of the time hypothesis spent drawing a scenario); the
#: same choices, so the same draws (checked: every test case of every property drawing from here, before and after)
_SAME = object()
_same_or_other_mass = st.one_of(st.just(_SAME), masses)


def _same_or_other(draw, mass: float) -> float:
    """`draw(st.one_of(st.just(mass), masses))`."""
    other = draw(_same_or_other_mass)
    return mass if other is _SAME else other


@st.composite
def one_particle(draw):
    name = draw(st.sampled_from("AB"))
    return Scenario("one", draw(velocities), (Particle(name, draw(masses), draw(speeds), draw(gaps)),), draw(lengths))


@st.composite
def two_gaps(draw):
    m_a = draw(masses)
    m_b = _same_or_other(draw, m_a)
    return Scenario("two", draw(velocities), (Particle("A", m_a, draw(speeds), draw(gaps)),
                                               Particle("B", m_b, draw(speeds), draw(gaps))), draw(lengths))


@st.composite
def simultaneous(draw):
    """Both particles at the same speed and gap: the impacts are simultaneous in S (rule 5), masses equal or not."""
    m_a = draw(masses)
    m_b = _same_or_other(draw, m_a)
    speed, gap = draw(speeds), draw(gaps)
    return Scenario("simultaneous", draw(velocities), (Particle("A", m_a, speed, gap), Particle("B", m_b, speed, gap)),
                    draw(lengths))


@st.composite
def timed(draw):
    """One particle placed by a gap, the other timed against it in S, S' or any frame."""
    first = draw(st.sampled_from("AB"))
    second = "B" if first == "A" else "A"
    m_1 = draw(masses)
    m_2 = _same_or_other(draw, m_1)
    timing = Timing(first, draw(frames), draw(delays))
    return Scenario("timed", draw(velocities), (Particle(first, m_1, draw(speeds), draw(gaps)),
                                                 Particle(second, m_2, draw(speeds), timed_with=timing)),
                    draw(lengths))


#: while_turning's timings, built once: a strategy built inside a draw is validated again at every draw (half of
#: the time hypothesis spent drawing a while_turning scenario; the same draws either way)
_TIMINGS_WHILE_TURNING = st.one_of(st.builds(Timing, st.just("B"), st.just("moving"), st.floats(-0.6, 0.0)),
                                   st.builds(Timing, st.just("B"), st.just("rest"), st.floats(0.0, 0.6)))


@st.composite
def while_turning(draw):
    """A timed a little before B in S' (or a little after in S): A strikes while the rod still turns from B1 (rule 6)."""
    m_b = draw(masses)
    m_a = _same_or_other(draw, m_b)
    timing = draw(_TIMINGS_WHILE_TURNING)
    return Scenario("while_turning", draw(velocities), (Particle("B", m_b, draw(speeds), draw(gaps)),
                                                         Particle("A", m_a, draw(speeds), timed_with=timing)),
                    draw(lengths))


scenarios = st.one_of(one_particle(), two_gaps(), simultaneous(), timed(), while_turning())

# explicit examples every property sees, whatever hypothesis draws: the presets' kinds at awkward values
WHILE_TURNING = Scenario("wt", 0.8, (Particle("B", 1.0, None, 0.2),
                                     Particle("A", 1.0, None, timed_with=Timing("B", "moving", -0.3))), 2.5)
UNEQUAL_SIMULTANEOUS = Scenario("us", 0.9, (Particle("A", 0.3, 0.5, 1.0), Particle("B", 7.0, 0.5, 1.0)), 0.4)
ZIGZAG = Scenario("zz", 0.95, (Particle("B", 1.0, None, 0.0),
                               Particle("A", 1.0, None, timed_with=Timing("B", "moving", 0.0))), 7.0)


#: found by hypothesis: B2 struck at cosh^2 r = 32, where a Line's rapidity (atanh of its slope) carries 32 times
#: its slope's rounding
STEEP_B2 = Scenario("while_turning", 0.984375, (Particle("B", 5.6875, 0.046875, 2.0),
                                               Particle("A", 9.0, None, timed_with=Timing("B", "moving", 0.0))), 1.0)


def with_examples(*extra):
    """Decorator: the property also runs on these scenarios (with `extra` for its other arguments)."""
    def decorate(test):
        for s in (WHILE_TURNING, UNEQUAL_SIMULTANEOUS, ZIGZAG):
            test = example(s, *extra)(test)
        return test
    return decorate


# --- force profiles (a rod driven at its ends) -----------------------------------------------------------------

force_frames = st.one_of(st.just("rest"), st.just("moving"), st.floats(-0.8, 0.8))


@functools.lru_cache(maxsize=None)
def _profile_parts(least: float) -> dict:
    """force_profiles' strategies for a least force, built once (a strategy built inside a draw is validated again
    at every draw); drawn exactly as they were written inline before, so the same draws."""
    return {"shape": st.sampled_from(["step", "sine2", "points"]), "n": st.integers(2, 5),
            "times": {n: st.lists(st.floats(-1.0, 3.0), min_size=n, max_size=n, unique=True) for n in range(2, 6)},
            "forces": {n: st.lists(st.floats(least, 1.0), min_size=n, max_size=n) for n in range(2, 6)},
            "peak": st.floats(least, 2.0).filter(lambda p: abs(p) > 1e-3),
            "start": st.floats(-1.0, 2.0), "duration": st.floats(0.05, 2.0)}


@st.composite
def force_profiles(draw, end: str, least: float):
    """A generated profile for one end: step, sine2 or points (2 to 5 corners), timed in S, S' or a frame u; its
    force never below `least` (a pull the model carries with room: rigid -0.9, causal -0.45)."""
    from rodparadox.physics.forces import ForceProfile

    parts = _profile_parts(least)
    shape = draw(parts["shape"])
    frame = draw(force_frames)
    if shape == "points":
        n = draw(parts["n"])
        times = sorted(draw(parts["times"][n]))
        spread = all(b - a > 1e-3 for a, b in zip(times, times[1:]))
        forces = draw(parts["forces"][n])
        if not spread or all(f == 0 for f in forces):
            forces[0], times = 0.3, [k * 0.5 for k in range(n)]
        return ForceProfile("points", points=tuple(zip(times, forces)), frame=frame, key=f"forces.{end}")
    peak = draw(parts["peak"])
    return ForceProfile(shape, peak=peak, start=draw(parts["start"]), duration=draw(parts["duration"]),
                        frame=frame, key=f"forces.{end}")
