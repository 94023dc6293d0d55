"""The one factory of rod models: a scenario's `rod` picks the rigid engine or the causal rod (README, "The
model" and "The causal rod"). Every command runs a scenario through `run_rod`. Pure.
"""

from __future__ import annotations

from rodparadox.physics.model import Scenario


def run_rod(scenario: Scenario):
    """The history of the scenario in its rod model: `engine.History` (rigid) or `causal.CausalHistory`; both
    implement `history.RodHistory`. The causal rod's modules are imported only when asked for."""
    if scenario.rod == "causal":
        from rodparadox.physics.causal import run

        return run(scenario)
    from rodparadox.physics.engine import run

    return run(scenario)
