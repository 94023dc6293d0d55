"""The animation's images (docs/animate.md, "The paradox in motion"): now mode over `plot`'s diagram, boost mode over fixed axes.

  now_scene    `NowScene`: the diagram with each frame's "now" sweeping up, and a band of strips below
  boost_scene  `BoostScene`: one panel whose frame runs smoothly from one velocity to another
  images       what both share: the images' resolution, blitting on one Agg canvas

matplotlib (Agg) is imported here; import this module only after every input has been checked. The interface
the real drawing keeps:

    images_of(history, frames, mode, style, timeline) -> Iterator[np.ndarray]

* `history`: `engine.History`; `frames`: the panels (now) or the two ends of the boost (boost), as
  `frames.Frame`s; `mode`: "now" or "boost"; `style`: a name of `styles.STYLE_NAMES`;
* `timeline`: `timeline.NowTimeline` (its `times[k, p]`, `windows`, `scales`, and `strip(history, k, p)`)
  or `timeline.BoostTimeline` (its `frames[k]`, `t_window`, `x_window`);
* yields len(timeline) images, each an (H, W, 3) uint8 RGB array, all of one size, drawn the same way
  every run (Agg), by updating artists on one figure rather than building a figure per image.
"""

from __future__ import annotations

from typing import Iterator

import numpy as np

from rodparadox.animate.boost_scene import boost_images
from rodparadox.animate.now_scene import now_images
from rodparadox.animate.timeline import BoostTimeline, NowTimeline
from rodparadox.physics.history import RodHistory
from rodparadox.physics.frames import Frame


def images_of(history: RodHistory, frames: tuple[Frame, ...], mode: str, style: str,
              timeline: NowTimeline | BoostTimeline, rod_view: str | None = None) -> Iterator[np.ndarray]:
    """Each instant of the timeline as an RGB image (see the module's docstring). `rod_view` ("first" or "last",
    now mode): the rod's own view (`--frame rod`) beside the panels, its own "now" (a level line) sweeping up."""
    if mode == "now":
        return now_images(history, timeline, style, rod_view)
    return boost_images(history, timeline, style)
