"""Figures the drawing tests share (imported as `drawn`, a sibling of the test files): each drawn once per process
for every test, in every file of tests/render, that draws the same history with the same frames, style and options.

A shared figure is only read by the tests (its artists, their extents); a test that changes a figure, or checks
that two drawings give the same bytes, draws its own.
"""

from __future__ import annotations

from functools import lru_cache

from helpers import history, measuring_renderer
from rodparadox import render
from rodparadox.io.scenario import load
from rodparadox.physics.frames import Frame, paper_frames


def _own_v(name: str, v: float | None) -> float:
    """v as given, or the scenario's own (`history(name)` and `history(name, its v)` are the same history)."""
    return load(name).v if v is None else v


def frames_of(specs: tuple, v: float) -> list[Frame]:
    """Frames by name: "rest" (S), "moving" (S', velocity -v), or a number u (the frame u=...)."""
    named = {"rest": Frame("rest", 0.0), "moving": Frame("moving", -v)}
    return [named[f] if f in named else Frame(f"u={f}", f) for f in specs]


def diagram(name: str, v: float | None = None, style: str = "default", options: render.Options = render.Options(),
            L: float | None = None, specs: tuple = ("rest", "moving")):
    """`render.draw(history(name, v, L), frames, style, options)`, S and S' (the paper's frames) unless `specs`
    names others, drawn once per process."""
    return _diagram(name, _own_v(name, v), style, options, L, tuple(specs))


@lru_cache(maxsize=None)
def _diagram(name, v, style, options, L, specs):
    return render.draw(history(name, v, L), frames_of(specs, v), style, options)


def measured(name: str, v: float | None = None, style: str = "default", specs: tuple = ("rest", "moving")):
    """(the `diagram` of these arguments, with default options; the renderer that laid it out as Agg draws it,
    `measuring_renderer`): drawn and laid out once per process. Read extents with this renderer."""
    return _measured(name, _own_v(name, v), style, tuple(specs))


@lru_cache(maxsize=None)
def _measured(name, v, style, specs):
    # `diagram`'s own figure, its canvas put back once measured: a PNG saved through the measuring canvas would be
    # the shared renderer's (test_render's two renderings of fig2 failed so while the canvas stayed)
    d = diagram(name, v, style, specs=specs)
    canvas = d.figure.canvas
    with render.style_context(style):
        renderer = measuring_renderer(d.figure)
    d.figure.set_canvas(canvas)
    return d, renderer


def svg(name: str, v: float | None = None, style: str = "default") -> bytes:
    """`render.figure_bytes` of the `diagram` of these arguments as SVG (what `plot` writes), once per process."""
    return _svg(name, _own_v(name, v), style)


@lru_cache(maxsize=None)
def _svg(name, v, style):
    return render.figure_bytes(diagram(name, v, style).figure, "svg", style)
