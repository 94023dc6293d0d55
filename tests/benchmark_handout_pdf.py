"""Benchmark of the handout typesetter (run on demand, not collected by pytest):

    python tests/benchmark_handout_pdf.py [--repeat 7]

In one process, interleaved, the median wall-clock time of
  plot:    render.draw + render.figure_bytes(fig, "pdf") of fig2 at v = 0.6, print style (what `plot fig2` does
           after its imports);
  handout: handout_pdf.to_pdf of a realistic fig2 handout built by hand (tests/handout_samples.py: a diagram,
           two blocks of six strips, events, ledger and hidden tables in S and S', paragraphs, six questions),
           and of the same worksheet (blank tables, ruled answer lines, the answer key);
and the ratios handout / plot. The issue's bound is on whole processes (`handout fig2` at most 3x `plot fig2`,
which is about 0.85 s, most of it imports): with imports of about 0.6 s shared by both, to_pdf must stay under
about 7x draw + figure_bytes for the process to stay under 3x.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from handout_samples import handout  # noqa: E402
from rodparadox import render  # noqa: E402
from rodparadox.physics.rigid import run  # noqa: E402
from rodparadox.physics.frames import paper_frames  # noqa: E402
from rodparadox.handout.pdf import to_pdf  # noqa: E402
from rodparadox.io.scenario import load  # noqa: E402


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeat", type=int, default=7)
    repeat = parser.parse_args().repeat
    history, frames = run(load("fig2")), paper_frames(0.6)
    sheet, notes = handout("fig2"), handout("fig2", worksheet=True)
    jobs = {
        "plot": lambda: render.figure_bytes(render.draw(history, frames, "print").figure, "pdf", "print"),
        "handout": lambda: to_pdf(sheet),
        "worksheet": lambda: to_pdf(notes),
    }
    for job in jobs.values():  # warm-up: font caches, imports done lazily
        job()
    times: dict[str, list[float]] = {name: [] for name in jobs}
    sizes = {}
    for _ in range(repeat):
        for name, job in jobs.items():
            start = time.perf_counter()
            sizes[name] = len(job())
            times[name].append(time.perf_counter() - start)
    plot = statistics.median(times["plot"])
    for name in jobs:
        median = statistics.median(times[name])
        print(f"{name:10s} median {median:6.3f} s  best {min(times[name]):6.3f} s  {median / plot:5.2f}x plot  "
              f"{sizes[name] / 1024:6.0f} KiB")


if __name__ == "__main__":
    main()
