"""Generated scenarios for the property tests (hypothesis strategies: one particle, two, equal and unequal
masses, simultaneous impacts, timings in any frame, impacts while the rod turns), the explicit examples every
property also sees, and a counter that keeps a property from passing vacuously. Shared by tests/physics and
tests/handout; imported as `generated` (tests/ is on pytest's `pythonpath`).
"""

from __future__ import annotations

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


@st.composite
def one_particle(draw):
    name = draw(st.sampled_from("AB"))
    return Scenario("one", draw(velocities), (Particle(name, draw(masses), draw(speeds), draw(gaps)),), draw(lengths))


@st.composite
def two_gaps(draw):
    m_a = draw(masses)
    m_b = draw(st.one_of(st.just(m_a), masses))
    return Scenario("two", draw(velocities), (Particle("A", m_a, draw(speeds), draw(gaps)),
                                               Particle("B", m_b, draw(speeds), draw(gaps))), draw(lengths))


@st.composite
def simultaneous(draw):
    """Both particles at the same speed and gap: the impacts are simultaneous in S (rule 5), masses equal or not."""
    m_a = draw(masses)
    m_b = draw(st.one_of(st.just(m_a), masses))
    speed, gap = draw(speeds), draw(gaps)
    return Scenario("simultaneous", draw(velocities), (Particle("A", m_a, speed, gap), Particle("B", m_b, speed, gap)),
                    draw(lengths))


@st.composite
def timed(draw):
    """One particle placed by a gap, the other timed against it in S, S' or any frame."""
    first = draw(st.sampled_from("AB"))
    second = "B" if first == "A" else "A"
    m_1 = draw(masses)
    m_2 = draw(st.one_of(st.just(m_1), masses))
    timing = Timing(first, draw(frames), draw(delays))
    return Scenario("timed", draw(velocities), (Particle(first, m_1, draw(speeds), draw(gaps)),
                                                 Particle(second, m_2, draw(speeds), timed_with=timing)),
                    draw(lengths))


@st.composite
def while_turning(draw):
    """A timed a little before B in S' (or a little after in S): A strikes while the rod still turns from B1 (rule 6)."""
    m_b = draw(masses)
    m_a = draw(st.one_of(st.just(m_b), masses))
    timing = draw(st.one_of(st.builds(Timing, st.just("B"), st.just("moving"), st.floats(-0.6, 0.0)),
                            st.builds(Timing, st.just("B"), st.just("rest"), st.floats(0.0, 0.6))))
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


@st.composite
def force_profiles(draw, end: str, least: float):
    """A generated profile for one end: step, sine2 or points (2 to 5 corners), timed in S, S' or a frame u; its
    force never below `least` (a pull the model carries with room: rigid -0.9, causal -0.45)."""
    from rodparadox.physics.forces import ForceProfile

    shape = draw(st.sampled_from(["step", "sine2", "points"]))
    frame = draw(force_frames)
    if shape == "points":
        n = draw(st.integers(2, 5))
        times = sorted(draw(st.lists(st.floats(-1.0, 3.0), min_size=n, max_size=n, unique=True)))
        spread = all(b - a > 1e-3 for a, b in zip(times, times[1:]))
        forces = draw(st.lists(st.floats(least, 1.0), min_size=n, max_size=n))
        if not spread or all(f == 0 for f in forces):
            forces[0], times = 0.3, [k * 0.5 for k in range(n)]
        return ForceProfile("points", points=tuple(zip(times, forces)), frame=frame, key=f"forces.{end}")
    peak = draw(st.floats(least, 2.0).filter(lambda p: abs(p) > 1e-3))
    return ForceProfile(shape, peak=peak, start=draw(st.floats(-1.0, 2.0)), duration=draw(st.floats(0.05, 2.0)),
                        frame=frame, key=f"forces.{end}")
