"""The physics, pure (no drawing, no files): kinematics, collisions, the scenario model, the rod models and the
interface every consumer reads them through, frames and the energy-momentum ledger (docs, "The model").

  types       the value types every rod model shares: Impact, EnergyMomentum, Slice (a leaf beside kinematics)
  kinematics  events, boosts, exact lines and hyperbolic arcs, chart curves, world-lines, proper time
  collision   the elastic rule (rules 2 and 5)
  model       the scenario as frozen, validated data; what the frame names mean (`frame_velocity`: S' = -v)
  history     the rod interface `RodHistory` and its optional capabilities (`Turning`, `Fronts`)
  models      the one door: `run_rod`, `run_rods(scenario, "both")` (both rods struck by the same particles)
  rigid/      the paper's rigid rod: impacts, turns, its kinetic ledger in closed form, its own chart
  causal/     the causal rod (sound at c): invariants, contacts and separations, matter and stress, its chart
  rod         any rod on a slice, its material lines
  frames      frames (named, or by velocity, bounded by FASTEST_FRAME; velocity addition) and a history seen
              from one
  snapshot    one frame's space at one instant: the rod's material points, the particles, the impacts then
  ledger      each body's energy and momentum on a slice of any frame, before and after each impact
  rod_view    the rod's own view: what every rod's own chart shares

Imports only `rodparadox.errors`, `rodparadox.numbers` and `rodparadox.tolerances` from outside; only `models`
imports a model's package, and the models never import each other (tests/test_layers.py).
"""
