"""Fixtures and helpers shared by the test files, hypothesis's profile, and how the suite spreads over processes.

`python -m pytest` runs on two worker processes (pytest-xdist, `-n auto` capped at 2 in pyproject.toml and
below) with `--dist loadgroup`: tests are handed out one by one, except those of a file marked
`xdist_group(name)` (html's browser, the worksheet search, the page rules, the causal histories), which run on
one worker so that their session and module fixtures are built once. Every other cache below and in the test
files (histories, drawn figures) is filled by each worker for itself.
"""

import functools
import os
from pathlib import Path

import pytest
from hypothesis import settings

from rodparadox.io.scenario import load
from rodparadox.physics.engine import History, run

# CI (CI=true) runs the same generated examples every time, so a landing never hangs on a lucky draw;
# a developer's run draws new ones and finds what CI would not
settings.register_profile("ci", derandomize=True, database=None)
if os.environ.get("CI"):
    settings.load_profile("ci")

#: at most this many worker processes for `-n auto`: each imports matplotlib and collects the suite (a few
#: seconds), and a container's CPU quota is not seen by the CPU count
MAX_WORKERS = 2


def pytest_xdist_auto_num_workers(config):
    try:
        cores = len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        cores = os.cpu_count() or 1
    return max(1, min(cores, MAX_WORKERS))


@functools.lru_cache(maxsize=None)
def history(name: str, v: float | None = None, L: float | None = None) -> History:
    """A built-in scenario's history at v and L (None: the scenario's own), run once per process; it is immutable."""
    return run(load(name).with_overrides(v=v, L=L))


@functools.lru_cache(maxsize=None)
def causal_history(name: str, v: float | None = None, L: float | None = None):
    """A built-in scenario's causal rod (README, "The causal rod") at v and L, run once per process (fig2: ~0.3 s)."""
    from rodparadox.physics.causal import run as run_causal

    return run_causal(load(name).with_overrides(v=v, L=L, rod="causal"))


@pytest.fixture
def unwritable_folder(tmp_path):
    """A folder no new file can be written into: /sys for root (who writes through mode bits), else a locked one."""
    if os.geteuid() == 0:
        yield Path("/sys")
        return
    folder = tmp_path / "locked"
    folder.mkdir()
    folder.chmod(0o500)
    try:
        yield folder
    finally:
        folder.chmod(0o700)


# --- shared by test_render.py, test_causal_draw.py, test_legible_panels.py (t13render) ---

#: one Agg renderer per dpi for every measuring draw: a text's extent depends only on its font and the dpi, and
#: matplotlib caches text metrics per renderer, so a new renderer for each figure measured every tick label again
_MEASURING_RENDERERS: dict = {}
#: the shared renderers' size in pixels; a larger figure gets its own renderer, as Agg would give it
_MEASURING_SIZE = 3000


def measuring_renderer(fig):
    """Lay out `fig` as Agg draws it, without rasterising (Figure.draw_without_rendering), and return the renderer
    that measured it: every text's extent and every tick is what a rendered PNG has. Call it inside the figure's
    style_context. The renderer is shared by every figure of the same dpi that fits it."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg, RendererAgg

    class MeasuringCanvas(FigureCanvasAgg):
        def get_renderer(self):
            w, h = self.figure.bbox.size
            if max(w, h) > _MEASURING_SIZE:
                return super().get_renderer()
            dpi = self.figure.dpi
            if dpi not in _MEASURING_RENDERERS:
                _MEASURING_RENDERERS[dpi] = RendererAgg(_MEASURING_SIZE, _MEASURING_SIZE, dpi)
            return _MEASURING_RENDERERS[dpi]

    canvas = MeasuringCanvas(fig)
    fig.draw_without_rendering()
    return canvas.get_renderer()
