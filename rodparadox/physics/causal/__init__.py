"""The causal rod (docs, "The causal rod"): the stiffest rod relativity allows, its sound at c. Pure.

  history   runs a scenario -> `CausalHistory` (the rod interface, with the capability `fronts`)
  solve     the invariants r+(u), r-(w) along the characteristics, contacts and separations
  ode       the contact equation by Chebyshev collocation, to 1e-12
  driven    an end driven by a force (docs, "Forces at the ends"): its boundary equation, the same way
  forced    runs a scenario with forces -> `DrivenHistory` (capabilities `fronts` and `driving`)
  arrays    the invariants and the chart map for whole arrays at once, exactly (the engine's pieces, vectorised)
  parts     the rod's (E, p) on slices split into matter and stress, and its rest mass in motion: the one integral
            across the rod (the ledger's, the ledger figure's, the page's, the handout's)
  tables    tables of the invariants, read for whole arrays (the page's world-lines, fronts and cells)
  extremes  its fields' extremes over the whole history (colour scales)
  chart     its material chart (the rod's own view)
"""

from rodparadox.physics.causal.forced import DrivenHistory, run_forces
from rodparadox.physics.causal.history import CausalHistory, particle_starts
from rodparadox.physics.causal.history import run as run_struck


def run(scenario, starts=None, budget: int | None = None):
    """The causal rod's history of the scenario: struck by its particles (`history.run`, from `starts`), or
    driven by its forces (`forced.run_forces`); `budget` bounds the work of either."""
    if scenario.forces is not None:
        return run_forces(scenario, budget)
    return run_struck(scenario, starts, budget)


__all__ = ["CausalHistory", "DrivenHistory", "particle_starts", "run", "run_forces", "run_struck"]
