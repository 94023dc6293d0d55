"""The physics, pure (no drawing, no files): kinematics, collisions, the scenario model, the rigid engine, the
rod's interior, frames and the energy-momentum ledger (README, "The model").

  kinematics  events, boosts, exact lines and hyperbolic arcs, world-lines, proper time
  collision   the elastic rule (README, "The model", rules 2 and 5)
  model       the scenario as frozen, validated data; what the frame names mean (`frame_velocity`: S' = -v)
  engine      runs a scenario: impacts, the rigid response (turns), the order of impacts -> `History`
  rod         inside the rod: material points, the rod on a slice, its own lines of simultaneity
  frames      frames (named, or by velocity, bounded by FASTEST_FRAME; velocity addition) and a history seen
              from one
  snapshot    one frame's space at one instant: the rod's material points, the particles, the impacts then
  ledger      each body's energy and momentum on a slice of any frame, the hidden part

Imports only `rodparadox.errors`, `rodparadox.numbers` and `rodparadox.tolerances` from outside.
"""
