"""The paper's rigid rod (docs, "The model"): every impact turns the rod's lines of simultaneity about a pivot
(rule 3), instantly. Pure.

  engine   runs a scenario: impacts, the turns, the order of impacts -> `History` (the rod interface)
  turns    a turn, the material points' world-lines through the turns, the rod's own lines of simultaneity
  ledger   the rod's kinetic (E, p) on a slice in closed form, and the hidden part
  chart    the rod's own chart (its rest frames and each turn's Rindler chart)
  driven   the rod driven by forces at its ends: the equation of motion, its stages and exact pieces
  driven_history  that run as the rod interface, with the capability `driving`
"""

from rodparadox.physics.rigid.driven_history import DrivenHistory, run_forces
from rodparadox.physics.rigid.engine import History, particle_starts, run

__all__ = ["DrivenHistory", "History", "particle_starts", "run", "run_forces"]
