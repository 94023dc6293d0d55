"""What several handout test files share, run once per process (each cached value is immutable, or only read):
the histories of driven presets and the causal rods `handout --rod both` runs. Imported as `handout_shared`
(tests/handout is on the path as the test files' folder); not collected (no test_ prefix).

Files that share one of these run in one xdist group (`--dist loadgroup`), so that a worker fills it once:
test_handout_forces with the forces worksheets of test_worksheet_tells_nothing (group `handout_forces`),
test_handout_words with the rest of test_worksheet_tells_nothing (group `worksheet_tells_nothing`)."""

from __future__ import annotations

import functools

from rodparadox.io.scenario import load
from rodparadox.physics.models import models_of, run_rods


@functools.lru_cache(maxsize=None)
def rods(name: str, v: float, which: str = "both") -> tuple:
    """`physics.models.run_rods(load(name).with_overrides(v=v), which)`: a preset's rods at v (`both`: the rigid and
    the causal rod, struck or driven alike, as `handout --rod both` runs them). The histories are read-only, and
    the handout's caches (`handout.forces_reading.read`, the causal ledger's slices) are keyed on them: one run
    here, one reading for every document built of it in the process.

    A driven rod is run one model at a time (`driven`: nothing is placed, so the models' runs are independent), each
    once: `rods(name, v, "rigid")` is the rigid rod of `rods(name, v, "both")`, run and read once."""
    scenario = load(name).with_overrides(v=v)
    if scenario.forces is not None:
        return tuple(driven(name, v, model) for model in models_of(which, scenario))
    return run_rods(scenario, which)


@functools.lru_cache(maxsize=None)
def driven(name: str, v: float, model: str):
    """A driven preset's rod of one model at v: `run_rods(load(name).with_overrides(v=v), model)`, its only rod."""
    [rod] = run_rods(load(name).with_overrides(v=v), model)
    return rod


@functools.lru_cache(maxsize=None)
def causal_alike(name: str, v: float, L: float | None = None):
    """The causal rod of a preset struck by the rigid rod's particles (`physics.models.run_rods`, like for like),
    as `handout --rod both` runs it."""
    return run_rods(load(name).with_overrides(v=v, L=L), "both")[1]
