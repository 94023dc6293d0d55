"""The paper's rigid rod (docs, "The model"): every impact turns the rod's lines of simultaneity about a pivot
(rule 3), instantly. Pure.

  engine   runs a scenario: impacts, the turns, the order of impacts -> `History` (the rod interface)
  turns    a turn, the material points' world-lines through the turns, the rod's own lines of simultaneity
  ledger   the rod's kinetic (E, p) on a slice in closed form, and the hidden part
  chart    the rod's own chart (its rest frames and each turn's Rindler chart)
  driven   the rod driven by forces at its ends: the equation of motion, its stages and exact pieces
  driven_history  that run as the rod interface, with the capability `driving`
"""

from rodparadox.physics.rigid.engine import History, particle_starts, run

__all__ = ["History", "particle_starts", "run", "run_forces"]


def run_forces(scenario):
    """The rod driven by the scenario's forces (`driven_history.DrivenHistory`), its solver imported only when a
    scenario with forces asks for it (a rigid plot of particles never loads numpy.polynomial)."""
    from rodparadox.physics.rigid.driven_history import run_forces as run_driven

    return run_driven(scenario)
