"""The one factory of rod models: a scenario's `rod` picks the rigid engine or the causal rod (README, "The
model" and "The causal rod"). Every command runs a scenario through `run_rod`. Pure.
"""

from __future__ import annotations

from rodparadox.physics.model import Scenario


def run_rod(scenario: Scenario, budget: int | None = None):
    """The history of the scenario in its rod model: `engine.History` (rigid) or `causal.CausalHistory`; both
    implement `history.RodHistory`. The causal rod's modules are imported only when asked for. `budget`: a bound on
    the causal rod's work (windows of chart time L and steps of its contacts), refused past it; None: the solver's
    own bounds. The rigid rod's run is a short list of impacts, unbounded by it."""
    if scenario.rod == "causal":
        from rodparadox.physics.causal import run

        return run(scenario, budget)
    from rodparadox.physics.engine import run

    return run(scenario)
