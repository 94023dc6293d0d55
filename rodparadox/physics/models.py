"""The one door to the rod models: which models there are, and a scenario run in the models asked for (docs,
"The model" and "The causal rod"). Every command runs a scenario through `run_rods` (or `run_rod` for one
model). Pure.

Like for like: where several models are run, every particle starts on the same world-line in each. A particle
timed against another (`timed_with`, as in the paper's Fig. 2) is placed once, by the timing rule in the
scenario's own rod (`scenario.rod`: rigid unless the file says `rod: causal`), and the other rods are struck by
the very same particles: their first impacts fall where that rod's response puts them, simultaneous or not.
"""

from __future__ import annotations

from rodparadox.physics.history import RodHistory
from rodparadox.physics.kinematics import Event
from rodparadox.physics.model import ROD_MODELS, Scenario

#: what `--rod` takes: one model, or every model side by side
ROD_CHOICES = (*ROD_MODELS, "both")


def _module(model: str):
    """The model's package, imported only when asked for (a rigid plot never loads the causal rod)."""
    if model == "causal":
        from rodparadox.physics import causal

        return causal
    from rodparadox.physics import rigid

    return rigid


def models_of(rods: str, scenario: Scenario) -> tuple[str, ...]:
    """The models `rods` names: "both" is every model (the rigid rod first), None the scenario's own."""
    if rods in (None, ""):
        return (scenario.rod,)
    return ROD_MODELS if rods == "both" else (rods,)


def particle_starts(scenario: Scenario) -> dict[str, Event]:
    """Each particle's event at t = 0, placed by the rules of the scenario's own rod (a gap, or an impact timed
    against the other particle's first contact)."""
    return _module(scenario.rod).particle_starts(scenario)


def run_rod(scenario: Scenario, starts: dict[str, Event] | None = None, budget: int | None = None) -> RodHistory:
    """The history of the scenario in its own rod model (`scenario.rod`), the particles starting at `starts`
    (default: placed by that model's rules). `budget`: a bound on the causal rod's work (windows of chart time L,
    stretches and steps of its contacts), refused past it; None: the solver's own bounds. The rigid rod's run is a
    short list of impacts, unbounded by it.

    A scenario with forces (`scenario.forces`) runs through the model package's `run_forces`, after the pull
    limit of that model (`Forces.check_pull`)."""
    if scenario.forces is not None:
        return run_forces(scenario, budget)
    if budget is not None and scenario.rod == "causal":
        return _module(scenario.rod).run(scenario, starts, budget)
    return _module(scenario.rod).run(scenario, starts)


def check_forces(scenario: Scenario) -> None:
    """Refuse, in one sentence, forces the scenario's own rod cannot carry (the pull limits, `Forces.check_pull`):
    where the rod is chosen, before any run."""
    if scenario.forces is None:
        return
    scenario.forces.check_pull(scenario.rod)


def run_forces(scenario: Scenario, budget: int | None = None) -> RodHistory:
    """The scenario's rod driven by its forces (`check_forces` first); `budget` bounds the causal rod's work, as
    for particles."""
    check_forces(scenario)
    if budget is not None and scenario.rod == "causal":
        return _module(scenario.rod).run_forces(scenario, budget)
    return _module(scenario.rod).run_forces(scenario)


def run_rods(scenario: Scenario, rods: str | None = None) -> tuple[RodHistory, ...]:
    """The scenario run in each model `rods` names ("rigid", "causal", "both"; None: the scenario's own), every
    particle starting where the scenario's own rod places it, so that the rods are compared like for like."""
    models = models_of(rods, scenario)
    if scenario.forces is not None:  # no particles to place: each rod driven by the same forces
        return tuple(run_forces(scenario.with_overrides(rod=model)) for model in models)
    if len(models) == 1:  # one model: the timing rule resolved in that model
        return (run_rod(scenario.with_overrides(rod=models[0])),)
    starts = particle_starts(scenario)
    return tuple(run_rod(scenario.with_overrides(rod=model), starts) for model in models)
