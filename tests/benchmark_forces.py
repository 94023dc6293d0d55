"""Benchmark of a rod driven by forces in `plot` (issue 26, item 6; run on demand, not collected by pytest):

    python tests/benchmark_forces.py [--repeat 3]

Whole processes, interleaved so drifts in machine load hit all alike: `plot sears` and `plot sears --rod causal`
against `plot fig1` (target <= 1.5 each). It prints the ratios of median wall-clock times, of the best (minimum)
wall-clock times and of median CPU times (user + system, which other jobs on the machine disturb least).
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from benchmark_causal import command, timed  # noqa: E402  (the same process timing)

COMMANDS = {"fig1": ["plot", "fig1"], "sears": ["plot", "sears"], "sears_causal": ["plot", "sears", "--rod", "causal"]}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3, help="runs of each command (median kept)")
    args = parser.parse_args()
    tool = command()
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        (work / "out").mkdir()
        commands = {key: tool + argv + ["-o", "out"] for key, argv in COMMANDS.items()}
        for key, argv in commands.items():  # warm-up: the bytecode cache, and that each succeeds
            assert timed(argv, work)[2] == 0, key
        runs: dict[str, list] = {key: [] for key in commands}
        for _ in range(args.repeat):
            for key, argv in commands.items():
                for stale in (work / "out").iterdir():
                    stale.unlink()
                runs[key].append(timed(argv, work)[:2])
    wall = {k: statistics.median(t[0] for t in v) for k, v in runs.items()}
    best = {k: min(t[0] for t in v) for k, v in runs.items()}
    cpu = {k: statistics.median(t[1] for t in v) for k, v in runs.items()}
    print(f"whole processes, interleaved; medians of {args.repeat} runs (target <= 1.5):")
    for key in ("sears", "sears_causal"):
        print(f"  {' '.join(COMMANDS[key])} against plot fig1: median wall {wall[key]:.3f} s / {wall['fig1']:.3f} s = "
              f"{wall[key] / wall['fig1']:.2f}; best wall {best[key] / best['fig1']:.2f}; median CPU "
              f"{cpu[key]:.3f} s / {cpu['fig1']:.3f} s = {cpu[key] / cpu['fig1']:.2f}")
    print(f"(Python {sys.version.split()[0]}, {os.cpu_count()} CPUs)")


if __name__ == "__main__":
    main()
