"""The causal rod (docs, "The causal rod"): the stiffest rod relativity allows, its sound at c. Pure.

  history   runs a scenario -> `CausalHistory` (the rod interface, with the capability `fronts`)
  solve     the invariants r+(u), r-(w) along the characteristics, contacts and separations
  ode       the contact equation by Chebyshev collocation, to 1e-12
  parts     the rod's (E, p) on a slice split into matter and stress, exactly, slice by slice (the ledger's)
  slices    the same on many slices at once, from tables of the invariants (the ledger figure's, the page's)
  extremes  its fields' extremes over the whole history (colour scales)
  chart     its material chart (the rod's own view)
"""

from rodparadox.physics.causal.history import CausalHistory, particle_starts, run

__all__ = ["CausalHistory", "particle_starts", "run"]
