"""The bound on a causal run's work (docs, "The causal rod"): each window of chart time L, each stretch of an end's
window and each step of a contact's integration spends one step; past the bound the run is refused in one
sentence, never left to run for minutes. Pure."""

from __future__ import annotations

from rodparadox.errors import ScenarioError


class Budget:
    """A bound on a run's work that a caller may set (the page's offered speeds): each window, each stretch of an
    end's window (free, in contact, a separation) and each step of a contact's integration spends one; past `limit`
    the run is refused."""

    def __init__(self, limit: int, asked: bool = True):
        self.limit, self.spent, self.asked = limit, 0, asked

    def spend(self) -> None:
        self.spent += 1
        if self.spent > self.limit:
            if self.asked:
                raise ScenarioError(f"the causal rod's run takes more than {self.limit} steps here; this scenario "
                                    f"does not settle within the bound asked for.")
            raise ScenarioError(f"the causal rod's run needs more than {self.limit} steps here (contacts with "
                                f"particles far heavier or lighter than the rod, or at speeds very near c, need "
                                f"ever smaller steps); choose masses nearer the rod's, or a lower speed.")


#: the solver's own bound on a run's work where the caller sets none: the presets spend 25 to 140 steps at any
#: speed, masses from 1e-6 to 1e4 at most 200; masses 1e9 and 1e-9 at v = 0.9999999 spent 23,000 in 8 s without an
#: end in sight (issue 27)
MAX_STEPS = 5_000
