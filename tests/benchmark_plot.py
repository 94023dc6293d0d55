"""Benchmark of `sears-paradox plot` (run on demand, not collected by pytest):

    python tests/benchmark_plot.py [--repeat 9] [--batch-repeat 3]

1. One figure: `sears-paradox plot fig2` as a whole process, against a bare
   matplotlib script (a separate process) that draws the same figure from
   numbers saved beforehand: the same lines with the same points, the same
   markers, fill, texts, titles and legend, into one SVG; no scenario, no
   engine, no layout. Also against a barer script with the lines and markers only.
2. Twenty figures (fig2 at twenty speeds, as YAML files): one `plot` call
   against twenty separate `plot` processes.
3. The ledger figure: `sears-paradox ledger fig2 --format svg` as a whole
   process against `sears-paradox plot fig2` (target <= 1.2), interleaved.
4. The handout: `sears-paradox handout fig2` (the PDF) and `handout fig2
   --worksheet` as whole processes against `sears-paradox plot fig2`
   (target <= 3), interleaved.
It prints the ratios of median wall-clock times (the targets), of the best
(minimum) wall-clock times and of median CPU times (user + system, which other
jobs on the machine disturb least), and the size of fig2.svg.

Every process runs with Python's bytecode cache on (PYTHONDONTWRITEBYTECODE
removed from the environment), as in an ordinary installation: matplotlib's
modules come precompiled from their wheel, so the tool's own must not be
compiled afresh on every run either. The warm-up run fills the cache.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

BARE_SCRIPT = r'''
import json, sys
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

data = json.load(open(sys.argv[1]))
full = sys.argv[3] == "full"
fig = Figure(figsize=data["size"], dpi=72)
for a in data["axes"]:
    ax = fig.add_axes(a["position"])
    ax.set_xlim(a["xlim"]); ax.set_ylim(a["ylim"])
    for f in a["fills"]:
        ax.fill(f["x"], f["y"], facecolor=f["colour"], edgecolor="none")
    for l in a["lines"]:
        ax.plot(l["x"], l["y"], color=l["colour"], linewidth=l["width"],
                linestyle=tuple(l["dashes"]) if isinstance(l["dashes"], list) else l["dashes"],
                marker=l["marker"], markersize=l["markersize"])
    if full:
        ax.set_xticks(a["xticks"], a["xticklabels"]); ax.set_yticks(a["yticks"], a["yticklabels"])
        ax.set_xlabel(a["xlabel"]); ax.set_ylabel(a["ylabel"]); ax.set_title(a["title"])
        for t in a["texts"]:
            ax.text(t["x"], t["y"], t["text"], fontsize=t["size"], color=t["colour"], ha=t["ha"], va=t["va"])
if full:
    fig.text(0.5, 0.98, data["title"], ha="center", va="top")
    fig.legend([Line2D([], [], color="k")] * len(data["legend"]), data["legend"], loc="lower center",
               ncol=2, frameon=False)
fig.savefig(sys.argv[2], format="svg", metadata={"Date": None})
'''


def command() -> list[str]:
    """The installed console script next to this Python, else the same entry point through -c."""
    script = Path(sys.executable).parent / "sears-paradox"
    if script.exists():
        return [str(script)]
    return [sys.executable, "-c", "from sears_paradox_cli.main import main; main()"]


def figure_data(path: Path) -> None:
    """Save what the tool draws for fig2 (every line's points, texts, layout) for the bare script."""
    from matplotlib.colors import to_hex
    from matplotlib.patches import Polygon

    from rodparadox import render
    from rodparadox.physics.rigid import run
    from rodparadox.physics.frames import paper_frames
    from rodparadox.io.scenario import load

    scenario = load("fig2")
    figure = render.draw(run(scenario), paper_frames(scenario.v)).figure
    data = {"size": list(figure.get_size_inches()), "axes": [],
            "title": figure.texts[0].get_text() if figure.texts else "",
            "legend": [t.get_text() for t in figure.legends[0].get_texts()]}
    for ax in figure.axes:
        lines = []
        for line in ax.lines:
            style = line.get_linestyle()
            dashes = [0, list(line._unscaled_dash_pattern[1])] if line._unscaled_dash_pattern[1] else style
            lines.append({"x": list(map(float, line.get_xdata())), "y": list(map(float, line.get_ydata())),
                          "colour": to_hex(line.get_color()), "width": line.get_linewidth(),
                          "dashes": dashes if style not in ("None", "none") else "none",
                          "marker": line.get_marker() if line.get_marker() not in (None, "None") else "",
                          "markersize": line.get_markersize()})
        fills = [{"x": list(map(float, p.get_xy()[:, 0])), "y": list(map(float, p.get_xy()[:, 1])),
                  "colour": to_hex(p.get_facecolor())} for p in (*ax.patches, *ax.artists) if isinstance(p, Polygon)]
        texts = [{"x": float(t.get_position()[0]), "y": float(t.get_position()[1]), "text": t.get_text(),
                  "size": t.get_fontsize(), "colour": to_hex(t.get_color()), "ha": t.get_ha(), "va": t.get_va()}
                 for t in ax.texts]
        data["axes"].append({
            "position": list(ax.get_position().bounds), "xlim": list(ax.get_xlim()), "ylim": list(ax.get_ylim()),
            "lines": lines, "fills": fills, "texts": texts, "title": ax.get_title(),
            "xlabel": ax.get_xlabel(), "ylabel": ax.get_ylabel(),
            "xticks": list(map(float, ax.get_xticks())), "yticks": list(map(float, ax.get_yticks())),
            "xticklabels": [t.get_text() for t in ax.get_xticklabels()],
            "yticklabels": [t.get_text() for t in ax.get_yticklabels()],
        })
    path.write_text(json.dumps(data))


ENVIRONMENT = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}


def _cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def timed(args: list[str], cwd: Path) -> tuple[float, float]:
    """(wall-clock, CPU) seconds of one process."""
    start, cpu = time.perf_counter(), _cpu()
    subprocess.run(args, cwd=cwd, check=True, stdout=subprocess.DEVNULL, env=ENVIRONMENT)
    return time.perf_counter() - start, _cpu() - cpu


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=9, help="runs of each single-figure command (median kept)")
    parser.add_argument("--batch-repeat", type=int, default=3, help="runs of each twenty-figure variant")
    args = parser.parse_args()
    plot = command() + ["plot"]

    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        (work / "out").mkdir()
        figure_data(work / "fig2.json")
        (work / "bare.py").write_text(BARE_SCRIPT)
        bare = [sys.executable, str(work / "bare.py"), str(work / "fig2.json"), str(work / "out" / "bare.svg")]

        # warm the caches (font cache, files) once, outside the timings
        timed(plot + ["fig2", "-o", "out"], work)
        timed(bare + ["full"], work)

        ledger = command() + ["ledger", "fig2", "--format", "svg", "-o", "out"]
        timed(ledger, work)
        handout = command() + ["handout", "fig2", "-o", "out"]
        worksheet = handout + ["--worksheet"]
        timed(handout, work)
        single = {"tool": [], "bare": [], "bare_lines": [], "ledger": [], "handout": [], "worksheet": []}
        for _ in range(args.repeat):  # interleaved, so drifts in machine load hit all alike
            (work / "out" / "fig2.svg").unlink(missing_ok=True)
            (work / "out" / "fig2_ledger.svg").unlink(missing_ok=True)
            (work / "out" / "fig2_handout.pdf").unlink(missing_ok=True)
            (work / "out" / "fig2_worksheet.pdf").unlink(missing_ok=True)
            single["tool"].append(timed(plot + ["fig2", "-o", "out"], work))
            single["bare"].append(timed(bare + ["full"], work))
            single["bare_lines"].append(timed(bare + ["lines"], work))
            single["ledger"].append(timed(ledger, work))
            single["handout"].append(timed(handout, work))
            single["worksheet"].append(timed(worksheet, work))
        size = (work / "out" / "fig2.svg").stat().st_size

        configs = []
        fig2 = Path(__file__).resolve().parent.parent / "configs" / "fig2.yaml"
        text = fig2.read_text()
        for k in range(20):
            path = work / f"speed{k:02d}.yaml"
            path.write_text(text.replace("v: 0.6", f"v: {0.3 + 0.03 * k:.2f}"))
            configs.append(path.name)
        batch = {"one_call": [], "twenty_processes": []}
        for _ in range(args.batch_repeat):
            shutil.rmtree(work / "out")
            (work / "out").mkdir()
            batch["one_call"].append(timed(plot + configs + ["-o", "out"], work))
            shutil.rmtree(work / "out")
            (work / "out").mkdir()
            times = [timed(plot + [config, "-o", "out"], work) for config in configs]
            batch["twenty_processes"].append((sum(t[0] for t in times), sum(t[1] for t in times)))
        assert len(os.listdir(work / "out")) == 20

    runs = {**single, **batch}
    wall = {k: statistics.median(t[0] for t in v) for k, v in runs.items()}
    best = {k: min(t[0] for t in v) for k, v in runs.items()}
    cpu = {k: statistics.median(t[1] for t in v) for k, v in runs.items()}

    def line(a: str, b: str) -> str:
        return (f"median wall {wall[a]:.3f} s / {wall[b]:.3f} s = {wall[a] / wall[b]:.2f}; "
                f"best wall {best[a] / best[b]:.2f}; median CPU {cpu[a]:.3f} s / {cpu[b]:.3f} s = {cpu[a] / cpu[b]:.2f}")

    print("one figure, sears-paradox plot fig2 against a bare matplotlib script with the same lines, markers and "
          "texts (target <= 1.10):")
    print("    " + line("tool", "bare"))
    print("  against a bare script with the lines and markers only:")
    print("    " + line("tool", "bare_lines"))
    print("twenty figures, one plot call against twenty plot processes (target <= 0.25):")
    print("    " + line("one_call", "twenty_processes"))
    print("the ledger figure, sears-paradox ledger fig2 --format svg against sears-paradox plot fig2 (target <= 1.2):")
    print("    " + line("ledger", "tool"))
    print("the handout, sears-paradox handout fig2 (PDF) against sears-paradox plot fig2 (target <= 3):")
    print("    " + line("handout", "tool"))
    print("  and the worksheet, handout fig2 --worksheet:")
    print("    " + line("worksheet", "tool"))
    print(f"fig2.svg     : {size} bytes ({size / 1024:.0f} KiB)")
    print(f"(medians of {args.repeat} and {args.batch_repeat} runs; Python {sys.version.split()[0]}, "
          f"{os.cpu_count()} CPUs)")


if __name__ == "__main__":
    main()
