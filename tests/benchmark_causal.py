"""Benchmark of the causal rod (issue 16, item 8; run on demand, not collected by pytest):

    python tests/benchmark_causal.py [--repeat 7] [--scenario fig1]

1. Whole processes, interleaved so drifts in machine load hit all alike: each command with `--rod causal`
   against the same command on the rigid rod. `plot fig1 --rod causal` against `plot fig1` (target <= 1.5) where
   plot draws the causal rod; until then (plot refuses it, exit status 2) `events` and `export`, which run it; and
   `handout --rod both` against `handout`.
2. In this process: the causal solve alone (`physics.causal.run`) against the rigid engine's run, the import of
   the causal modules timed apart (a process pays it once), and a profile of the solve: where its time goes.

It prints the ratios of median wall-clock times, of the best (minimum) wall-clock times and of median CPU times
(user + system, which other jobs on the machine disturb least).
"""

from __future__ import annotations

import argparse
import cProfile
import io
import os
import pstats
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ENVIRONMENT = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}


def command() -> list[str]:
    """The installed console script next to this Python, else the same entry point through -c."""
    script = Path(sys.executable).parent / "sears-paradox"
    if script.exists():
        return [str(script)]
    return [sys.executable, "-c", "from sears_paradox_cli.main import main; main()"]


def _cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def timed(args: list[str], cwd: Path) -> tuple[float, float, int]:
    """(wall-clock, CPU) seconds of one process, and its exit status."""
    start, cpu = time.perf_counter(), _cpu()
    done = subprocess.run(args, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=ENVIRONMENT)
    return time.perf_counter() - start, _cpu() - cpu, done.returncode


def in_process(name: str, repeat: int) -> None:
    """The causal solve against the rigid run, in this process, and its profile."""
    from rodparadox.io.scenario import load
    from rodparadox.physics.rigid import run as run_rigid

    t0 = time.perf_counter()
    from rodparadox.physics.causal import run as run_causal  # what the first causal run of a process pays once
    causal_import = time.perf_counter() - t0

    scenario = load(name)
    causal = scenario.with_overrides(rod="causal")

    def best(run, s) -> float:
        times = []
        for _ in range(repeat):
            start = time.perf_counter()
            run(s)
            times.append(time.perf_counter() - start)
        return min(times)

    run_causal(causal)  # warm: every module imported
    rigid_s, causal_s = best(run_rigid, scenario), best(run_causal, causal)
    print(f"in this process, {name}: the causal modules' import {causal_import:.3f} s (once a process); the rigid run "
          f"{rigid_s * 1e3:.1f} ms, the causal solve {causal_s * 1e3:.1f} ms (best of {repeat})")
    profile = cProfile.Profile()
    profile.enable()
    run_causal(causal)
    profile.disable()
    out = io.StringIO()
    pstats.Stats(profile, stream=out).sort_stats("tottime").print_stats(12)
    lines = [line for line in out.getvalue().splitlines() if line.strip()]
    start = next(k for k, line in enumerate(lines) if "ncalls" in line)
    print("  the causal solve's profile, by time in each function itself:")
    for line in lines[start:start + 13]:
        print("    " + line.strip()[:150])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=7, help="runs of each command (median kept)")
    parser.add_argument("--scenario", default="fig1", help="the scenario (a built-in name)")
    args = parser.parse_args()
    tool, name = command(), args.scenario

    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        (work / "out").mkdir()
        pairs = {
            "plot": ["plot", name, "-o", "out"],
            "events": ["events", name],
            "export": ["export", name, "--format", "json"],
            "handout": ["handout", name, "-o", "out"],
        }
        commands = {}
        for key, argv in pairs.items():
            rod = ["--rod", "both"] if key == "handout" else ["--rod", "causal"]
            commands[key] = tool + argv
            commands[key + "_causal"] = tool + argv + rod
        status = {key: timed(argv, work)[2] for key, argv in commands.items()}  # warm-up, and what each does
        runs: dict[str, list] = {key: [] for key, code in status.items() if code == 0}
        for _ in range(args.repeat):
            for key in runs:
                for stale in (work / "out").iterdir():
                    stale.unlink()
                runs[key].append(timed(commands[key], work)[:2])

    wall = {k: statistics.median(t[0] for t in v) for k, v in runs.items()}
    best = {k: min(t[0] for t in v) for k, v in runs.items()}
    cpu = {k: statistics.median(t[1] for t in v) for k, v in runs.items()}

    print(f"whole processes, {name}, interleaved; medians of {args.repeat} runs:")
    for key in pairs:
        rod = "--rod both" if key == "handout" else "--rod causal"
        mine = key + "_causal"
        if mine not in runs:
            print(f"  {key} {name} {rod}: refused (exit status {status[mine]}), not measured")
            continue
        target = " (target <= 1.5)" if key == "plot" else ""
        print(f"  {key} {name} {rod} against {key} {name}{target}:")
        print(f"    median wall {wall[mine]:.3f} s / {wall[key]:.3f} s = {wall[mine] / wall[key]:.2f}; best wall "
              f"{best[mine] / best[key]:.2f}; median CPU {cpu[mine]:.3f} s / {cpu[key]:.3f} s = "
              f"{cpu[mine] / cpu[key]:.2f}")
    in_process(name, args.repeat)
    print(f"(Python {sys.version.split()[0]}, {os.cpu_count()} CPUs)")


if __name__ == "__main__":
    main()
