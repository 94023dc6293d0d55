"""The documentation's "From Python" example (docs/python.md) runs as printed, and the panel it draws into a pyplot
Axes is the exact one."""

from __future__ import annotations

import contextlib
import io
import math
import os
import re
from pathlib import Path

import matplotlib
import numpy as np
import pytest

#: one worker runs this file: its module fixture is built once, not once per worker
pytestmark = pytest.mark.xdist_group("docs_python")

PAGE = (Path(__file__).resolve().parent.parent / "docs" / "python.md").read_text()


def _example() -> str:
    return re.findall(r"```python\n(.*?)```", PAGE, re.S)[0]  # the first: a panel beside the user's own plot


@pytest.fixture(scope="module")
def ran(tmp_path_factory):
    matplotlib.use("Agg")  # no screen: pyplot draws off-screen
    folder = tmp_path_factory.mktemp("python")
    namespace: dict = {}
    printed = io.StringIO()
    here = os.getcwd()
    os.chdir(folder)  # contextlib.chdir is Python 3.11's; the project supports 3.10
    try:
        with contextlib.redirect_stdout(printed):
            exec(compile(_example(), "docs/python.md (From Python)", "exec"), namespace)
    finally:
        os.chdir(here)
    import matplotlib.pyplot as plt

    yield folder, namespace, printed.getvalue().splitlines()
    plt.close("all")


def test_the_example_runs_writes_its_picture_and_prints_what_it_says(ran):
    folder, ns, printed = ran
    assert (folder / "fig2_beside_mine.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert printed[0].startswith("['impacts', 'particle-A', 'particle-B', 'rod', 'sheet', 'simultaneity-moving'")
    # the rod rests in S' at t' = 17/12 (B1 and A1): the paper's Fig. 2
    assert printed[1] == "True"


def test_the_panel_is_drawn_beside_the_users_own_plot_with_the_exact_world_lines(ran):
    _, ns, _ = ran
    panel, mine, history, moving = ns["panel"], ns["mine"], ns["history"], ns["moving"]
    assert [line.get_label() for line in mine.get_lines()] == ["my own plot"]  # the user's Axes untouched
    assert panel.get_gid() == "a-axes" and panel.get_xlabel() and panel.get_ylabel()
    (x0, x1), (t0, t1) = panel.get_xlim(), panel.get_ylim()
    box = panel.get_window_extent()
    assert box.width / (x1 - x0) == pytest.approx(box.height / (t1 - t0), rel=1e-3)  # equal scales
    rod = {a.get_gid(): a for a in ns["artists"]["rod"] if a.get_gid()}
    right = rod["a-rod_right"]
    exact = history.worldline("rod_right").seen_from(moving.rapidity)
    for x, t in zip(right.get_xdata()[::7], right.get_ydata()[::7]):
        assert x == pytest.approx(exact.event_at_time(float(t)).x, abs=1e-4)  # drawn within the sampling tolerance
    # B1 and A1 share t' = 17/12 in S': their markers sit at one height
    impacts = {a.get_gid(): a for a in ns["artists"]["impacts"] if a.get_gid()}
    heights = [float(np.ravel(impacts[f"a-impact-{k}"].get_ydata())[0]) for k in ("A1", "B1")]
    assert heights == pytest.approx([17 / 12] * 2, abs=1e-12)
    assert math.isclose(moving.rapidity, math.atanh(-0.6))
