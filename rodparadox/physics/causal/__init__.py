"""The causal rod (docs, "The causal rod"): the stiffest rod relativity allows, its sound at c. Pure.

  history   runs a scenario -> `CausalHistory` (the rod interface, with the capability `fronts`)
  solve     the invariants r+(u), r-(w) along the characteristics, contacts and separations
  ode       the contact equation by Chebyshev collocation, to 1e-12
  arrays    the invariants and the chart map for whole arrays at once, exactly (the engine's pieces, vectorised)
  parts     the rod's (E, p) on slices split into matter and stress, and its rest mass in motion: the one integral
            across the rod (the ledger's, the ledger figure's, the page's, the handout's)
  tables    tables of the invariants, read for whole arrays (the page's world-lines, fronts and cells)
  extremes  its fields' extremes over the whole history (colour scales)
  chart     its material chart (the rod's own view)
"""

from rodparadox.physics.causal.history import CausalHistory, particle_starts, run

__all__ = ["CausalHistory", "particle_starts", "run"]
