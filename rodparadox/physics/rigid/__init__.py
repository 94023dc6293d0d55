"""The paper's rigid rod (docs, "The model"): every impact turns the rod's lines of simultaneity about a pivot
(rule 3), instantly. Pure.

  engine   runs a scenario: impacts, the turns, the order of impacts -> `History` (the rod interface)
  turns    a turn, the material points' world-lines through the turns, the rod's own lines of simultaneity
  ledger   the rod's kinetic (E, p) on a slice in closed form, and the hidden part
  chart    the rod's own chart (its rest frames and each turn's Rindler chart)
"""

from rodparadox.physics.rigid.engine import History, particle_starts, run

__all__ = ["History", "particle_starts", "run"]
