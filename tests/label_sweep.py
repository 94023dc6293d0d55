"""Run on demand (not by pytest): the impact labels of both rods (`plot --rod both`, and the handout's compared
diagram at 6.3 x 7.6 in) of every preset with particles at v = 0.05, 0.15, ..., 0.95, measured on the renderer's
boxes (tests/render/test_render.py): labels overlapping, a label on a marker, a leader through a label or across a
marker, two leaders crossing.

    .venv/bin/python tests/label_sweep.py [STYLE [SPEEDS [plot|handout]]]

prints each case with a fault and the total (issue 24, print style: 42 at the handout's size and 7 at the plot's
before; 0 now).
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [HERE, os.path.join(HERE, "render")]

from matplotlib.figure import Figure  # noqa: E402

from helpers import causal_history, history, particle_presets  # noqa: E402
from rodparadox import render  # noqa: E402
from rodparadox.physics.frames import paper_frames  # noqa: E402
from test_render import _collisions, _labels_on_sheet, _leader_faults, _renderer  # noqa: E402


def faults(fig, style) -> list:
    renderer = _renderer(fig, style)
    impact = [c for c in _collisions(fig, style, renderer)
              if "-impact-label-" in str(c[0]) and ("-impact-label-" in str(c[1]) or "-impact-leader-" in str(c[1]))]
    return _leader_faults(fig, style, renderer) + impact + _labels_on_sheet(fig, renderer)


if __name__ == "__main__":
    style = sys.argv[1] if len(sys.argv) > 1 else "print"
    speeds = [float(s) for s in sys.argv[2].split(",")] if len(sys.argv) > 2 else [round(0.05 + 0.1 * k, 2)
                                                                                   for k in range(10)]
    size = sys.argv[3] if len(sys.argv) > 3 else "plot"
    total = 0
    for name in particle_presets():
        for v in speeds:
            rigid, causal = history(name, v), causal_history(name, v)
            if size == "plot":
                fig = render.draw_both(rigid, causal, paper_frames(v), style).figure
            else:
                fig = Figure(figsize=(6.3, 7.6), dpi=72)
                render.draw_into(fig, (rigid, causal), paper_frames(v), style)
            found = faults(fig, style)
            total += len(found)
            if found:
                print(name, v, len(found), found[:6], flush=True)
    print("total", total)
