"""What every layer of the rod's own view shares (`rod_layers`, `rod_forces`): the panel as its layers see it, and
the layer's interface."""

from __future__ import annotations

from typing import NamedTuple

from rodparadox.render.styles import Style


class RodPanel(NamedTuple):
    """One panel of the rod's own view as its layers see it: the run, its chart, the style, the type sizes, the
    panel's letter, its box (X0, X1, T0, T1) in units of L and the proper time between two clock ticks (units of L)."""

    history: object
    chart: object
    style: Style
    fs: dict
    letter: str
    box: tuple[float, float, float, float]
    step: float

    @property
    def L(self) -> float:
        return self.history.scenario.L


class RodLayer:
    """One element of the rod's own view: `draw` gives its artists, `key` its (handle, text) lines of the key."""

    name = ""

    def applies(self, history) -> bool:
        """Whether the run has what this layer draws."""
        return True

    def chart_times(self, history, chart) -> list[float]:
        """Chart times (units of L) the panel's box must reach to show what this layer draws, beyond the impacts."""
        return []

    def draw(self, ax, panel: RodPanel) -> list:
        raise NotImplementedError

    def key(self, panel: RodPanel) -> list[tuple]:
        return []
