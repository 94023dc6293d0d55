"""What the two scenes share: drawing their images by blitting on one Agg canvas (their resolution is the style's
`animation_dpi`).

An image is one instant of an animation: an (H, W, 3) uint8 RGB array; every image of one animation has the same
size. A scene draws its figure once, saves it as the background, and for each instant draws only what moved over
it (`blitted`), so the same figure gives the same pixels every run.
"""

from __future__ import annotations

from typing import Callable, Iterable, Iterator, Sequence

import numpy as np

def in_style(style: str, draw: Callable[[], Iterator[np.ndarray]]) -> Iterator[np.ndarray]:
    """The images `draw()` gives, each drawn inside `render.style_context(style)`, which is left before each image
    is handed on. A generator that yielded inside the style's context would keep the style's rcParams on the whole
    process while it waits, and until it is collected when its caller stops early (`animate` refusing a long run
    after the first image; an error): every figure made meanwhile outside a style (a handout's LaTeX figures take
    the process's figure.dpi) was laid out at the style's 72 dpi instead of matplotlib's 100, so its bytes depended
    on when the collector ran. Here nothing is changed between images."""
    from rodparadox import render

    images = None
    while True:
        with render.style_context(style):
            if images is None:
                images = draw()
            try:
                image = next(images)
            except StopIteration:
                return
        yield image


def image_of(canvas) -> np.ndarray:
    """The canvas's pixels as an image: RGB, a copy (the canvas draws the next instant over them)."""
    return np.asarray(canvas.buffer_rgba())[..., :3].copy()


def blitted(canvas, moved: Iterable[Sequence]) -> Iterator[np.ndarray]:
    """Draw the canvas's figure once and keep it as the background; then, for each instant, the artists `moved`
    gives (already moved to it, in drawing order) over the background: one image per instant. `moved` is read
    lazily, one instant at a time, after the background is drawn."""
    canvas.draw()
    background = canvas.copy_from_bbox(canvas.figure.bbox)
    for artists in moved:
        canvas.restore_region(background)
        for artist in artists:
            artist.axes.draw_artist(artist)
        yield image_of(canvas)
