"""Benchmark of `sears-paradox animate` (run on demand, not collected by pytest):

    python tests/benchmark_animate.py [--repeat 5] [--memory-images 600] [--skip-speed] [--skip-memory]

1. Speed: `sears-paradox animate fig2 --fps 20 --seconds 6` (a GIF of 120 images) as a whole process,
   against a bare matplotlib script (a separate process) that draws the same artists image by image:
   the same figure size and dpi, the diagram's lines, fills, texts, titles, ticks and legend, the two
   strips' axes and colour bars, and per image the same now-lines, bars (a LineCollection with the same
   segments and colours) and their outlines, particle dots and letters, flashes and readouts, and the lens
   (the magnified strip) where the tool draws one, from numbers saved beforehand,
   with `FuncAnimation(...).save(..., writer=PillowWriter(fps=20))`; no scenario, no engine, no layout.
   Interleaved, so drifts in machine load hit both alike. Target: the tool at most 0.5 of the bare
   script's median wall time.
2. Memory: the peak resident set size (ru_maxrss from wait4, which covers the process and the children it
   waited for, such as ffmpeg) of `animate fig2` with 600 images (`--fps 25 --seconds 24`), as a GIF, as PNG
   stills, and as an MP4 when ffmpeg is there. Target: under 1 GiB each.

It prints the ratios of median wall-clock times (the target), of the best (minimum) wall times and of median
CPU times (user + system), and the sizes of the two GIFs. Every process runs with Python's bytecode cache on,
as in an ordinary installation (see benchmark_plot.py).
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

#: the animation measured: fig2, 120 images at 20 per second, a GIF
FPS, SECONDS = 20, 6

BARE_SCRIPT = r'''
import json, sys
import matplotlib
from matplotlib.animation import FuncAnimation, PillowWriter
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.collections import LineCollection
from matplotlib.colors import Normalize
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

data = json.load(open(sys.argv[1]))
matplotlib.rcParams.update(data["rc"])
fig = Figure(figsize=data["size"], dpi=data["dpi"])
FigureCanvasAgg(fig)

def dashes(d):
    return tuple(d) if isinstance(d, list) else d

for a in data["axes"]:
    ax = fig.add_axes(a["position"])
    ax.set_xlim(a["xlim"]); ax.set_ylim(a["ylim"])
    for f in a["fills"]:
        ax.fill(f["x"], f["y"], facecolor=f["colour"], edgecolor="none")
    for l in a["lines"]:
        ax.plot(l["x"], l["y"], color=l["colour"], linewidth=l["width"], linestyle=dashes(l["dashes"]),
                marker=l["marker"], markersize=l["markersize"], markerfacecolor=l["face"], markeredgecolor=l["edge"])
    ax.set_xticks(a["xticks"], a["xticklabels"], fontsize=a["tick_size"])
    ax.set_yticks(a["yticks"], a["yticklabels"], fontsize=a["tick_size"])
    ax.set_xlabel(a["xlabel"], fontsize=a["label_size"]); ax.set_ylabel(a["ylabel"], fontsize=a["label_size"])
    ax.set_title(a["title"], fontsize=a["title_size"])
    if a["left_title"]:
        ax.set_title(a["left_title"], fontsize=a["left_title_size"], loc="left")
    for t in a["texts"]:
        ax.text(t["x"], t["y"], t["text"], fontsize=t["size"], color=t["colour"], ha=t["ha"], va=t["va"])
    a["ax"] = ax
fig.text(0.5, data["title_y"], data["title"], ha="center", va="top", fontsize=data["title_size"])
fig.legend([Line2D([], [], color=c, linestyle=dashes(d)) for c, d in data["legend_handles"]], data["legend"],
           loc="upper center", bbox_to_anchor=data["legend_anchor"], ncol=data["legend_columns"], frameon=False,
           fontsize=data["legend_size"])

nows = [(data["axes"][n["panel"]]["ax"].axhline(0, color=n["colour"], linewidth=n["width"], zorder=8), n["t"])
        for n in data["nows"]]
moving = []
for s in data["strips"]:
    strip = data["axes"][s["strip"]]["ax"]
    bar = LineCollection([], cmap=s["cmap"], norm=Normalize(*s["limits"]), linewidths=s["bar_width"],
                         capstyle="butt")
    strip.add_collection(bar)
    if s["colour"] is not None:
        cax = data["axes"][s["colour"]]["ax"]
        bar_legend = fig.colorbar(bar, cax=cax, orientation="horizontal")
        bar_legend.ax.tick_params(labelsize=s["small"]); bar_legend.set_label(s["bar_label"], fontsize=s["small"])
    outline = strip.plot([], [], color=s["outline_colour"], linewidth=s["outline_width"])[0]
    dots = strip.plot([], [], "o", color="black", markersize=s["dot_size"])[0]
    names = [strip.text(0, s["letter_y"], n, ha="center", va="bottom", fontsize=s["size"], style="italic",
                        color=c) for n, c in s["names"]]
    flash = strip.plot([], [], "*", color=s["flash_colour"], markersize=s["star_size"])[0]
    readout = strip.set_title("", fontsize=s["size"], loc="left") if s["readout"] else None
    moving.append((s, bar, outline, dots, names, flash, readout))

def update(k):
    for now, t in nows:
        now.set_ydata([t[k], t[k]])
    for s, bar, outline, dots, names, flash, readout in moving:
        f = s["images"][k]
        x = f["x"]
        bar.set_segments([[(a, 0.0), (b, 0.0)] for a, b in zip(x[:-1], x[1:])])
        bar.set_array(f["colours"])
        h = s["half_bar"]
        outline.set_data([x[0], x[-1], x[-1], x[0], x[0]], [-h, -h, h, h, -h])
        dots.set_data(f["particles"], [0.0] * len(f["particles"]))
        for text, xp, shown in zip(names, f["particles"], f["shown"]):
            text.set_position((xp, s["letter_y"]))
            text.set_visible(shown)
        flash.set_data(f["flash"], [0.0] * len(f["flash"]))
        if readout is not None:
            readout.set_text(f["readout"])
    return []

FuncAnimation(fig, update, frames=len(data["nows"][0]["t"]), blit=False).save(
    sys.argv[2], writer=PillowWriter(fps=data["fps"]), dpi=data["dpi"])
'''


def command() -> list[str]:
    """The installed console script next to this Python, else the same entry point through -c."""
    script = Path(sys.executable).parent / "sears-paradox"
    if script.exists():
        return [str(script)]
    return [sys.executable, "-c", "from sears_paradox_cli.main import main; main()"]


def scene_data(path: Path) -> None:
    """Save what `animate fig2` draws (the diagram, the strips' axes, and every image's moving artists, with the
    same figure size and dpi) for the bare script."""
    from matplotlib.colors import to_hex
    from matplotlib.patches import Polygon

    from rodparadox import render
    from rodparadox.animate.now_scene import NowScene
    from rodparadox.animate.timeline import image_count, timeline
    from rodparadox.physics.rigid import run
    from rodparadox.physics.frames import paper_frames
    from rodparadox.render.strip import COLOUR_BAR_LABEL
    from rodparadox.io.scenario import load
    from rodparadox.render.styles import STYLES

    scenario = load("fig2")
    history = run(scenario)
    count = image_count(SECONDS, FPS)
    line = timeline(history, paper_frames(scenario.v), "now", count)
    rc = {k: v for k, v in STYLES["default"].rc.items() if isinstance(v, (str, int, float, bool))}
    rc["font.family"] = list(STYLES["default"].rc["font.family"])
    with render.style_context("default"):
        scene = NowScene(history, line, "default")
        figure = scene.figure
        legend = figure.legends[0]
        anchor = legend.get_bbox_to_anchor().transformed(figure.transFigure.inverted())
        handles = []
        for handle in legend.legend_handles:
            handle = handle[-1] if isinstance(handle, tuple) else handle
            colour = to_hex(handle.get_color()) if hasattr(handle, "get_color") else "#000000"
            handles.append((colour, "solid"))
        data = {"size": list(figure.get_size_inches()), "dpi": figure.dpi, "fps": FPS, "rc": rc, "axes": [],
                "title": figure.texts[0].get_text(), "title_y": figure.texts[0].get_position()[1],
                "title_size": figure.texts[0].get_fontsize(),
                "legend": [t.get_text() for t in legend.get_texts()], "legend_handles": handles,
                "legend_anchor": [anchor.x0 + anchor.width / 2, anchor.y0], "legend_columns": legend._ncols,
                "legend_size": legend.get_texts()[0].get_fontsize(), "strips": []}
        index = {}
        for ax in figure.axes:
            lines = []
            for line2d in ax.lines:
                if line2d.get_animated():
                    continue
                style = line2d.get_linestyle()
                pattern = line2d._unscaled_dash_pattern[1]
                dashes = [0, list(pattern)] if pattern else style
                lines.append({"x": list(map(float, line2d.get_xdata())), "y": list(map(float, line2d.get_ydata())),
                              "colour": to_hex(line2d.get_color()), "width": line2d.get_linewidth(),
                              "dashes": dashes if style not in ("None", "none") else "none",
                              "marker": line2d.get_marker() if line2d.get_marker() not in (None, "None") else "",
                              "markersize": line2d.get_markersize(),
                              "face": to_hex(line2d.get_markerfacecolor()),
                              "edge": to_hex(line2d.get_markeredgecolor())})
            fills = [{"x": list(map(float, p.get_xy()[:, 0])), "y": list(map(float, p.get_xy()[:, 1])),
                      "colour": to_hex(p.get_facecolor())} for p in ax.patches if isinstance(p, Polygon)]
            texts = [{"x": float(t.get_position()[0]), "y": float(t.get_position()[1]), "text": t.get_text(),
                      "size": t.get_fontsize(), "colour": to_hex(t.get_color()), "ha": t.get_ha(), "va": t.get_va()}
                     for t in ax.texts if not t.get_animated()]
            ticks = ax.xaxis.get_major_ticks()
            index[ax] = len(data["axes"])
            data["axes"].append({
                "position": list(ax.get_position().bounds), "xlim": list(ax.get_xlim()), "ylim": list(ax.get_ylim()),
                "lines": lines, "fills": fills, "texts": texts, "title": ax.get_title(),
                "title_size": ax.title.get_fontsize(), "left_title": ax.get_title(loc="left"),
                "left_title_size": ax._left_title.get_fontsize(), "xlabel": ax.get_xlabel(), "ylabel": ax.get_ylabel(),
                "label_size": ax.xaxis.label.get_fontsize(),
                "tick_size": ticks[0].label1.get_fontsize() if ticks else 10.0,
                "xticks": list(map(float, ax.get_xticks())), "yticks": list(map(float, ax.get_yticks())),
                "xticklabels": [t.get_text() for t in ax.get_xticklabels()],
                "yticklabels": [t.get_text() for t in ax.get_yticklabels()],
            })
        data["nows"] = [{"panel": index[m.now.axes], "colour": to_hex(m.now.get_color()),
                         "width": m.now.get_linewidth(), "t": []} for m in scene.panels]
        strips = [(m.strip, m.strip.colour_bar) for m in scene.panels]
        strips += [(m.lens, None) for m in scene.panels if m.lens is not None]
        for strip, colour_bar in strips:
            if colour_bar is not None:  # the bare script's colorbar draws the colour bar's own axes: no ticks of ours
                data["axes"][index[colour_bar.ax]].update(xticks=[], yticks=[], xticklabels=[], yticklabels=[],
                                                          xlabel="")
            data["strips"].append({
                "strip": index[strip.bar.axes], "colour": index[colour_bar.ax] if colour_bar is not None else None,
                "cmap": STYLES["default"].velocity_colour_map, "limits": [strip.bar.norm.vmin, strip.bar.norm.vmax],
                "bar_width": float(strip.bar.get_linewidth()[0]), "half_bar": strip.half_bar,
                "outline_colour": to_hex(strip.outline.get_color()), "outline_width": strip.outline.get_linewidth(),
                "bar_label": COLOUR_BAR_LABEL, "small": 0.8 * STYLES["default"].font_size,
                "dot_size": strip.dots.get_markersize(), "star_size": strip.flash.get_markersize(),
                "flash_colour": to_hex(strip.flash.get_color()), "letter_y": strip.letter_y,
                "size": strip.names[0].get_fontsize(), "readout": strip.readout is not None,
                "names": [(t.get_text(), to_hex(t.get_color())) for t in strip.names], "images": []})
        for k in range(count):
            scene.update(k)
            for m, now in zip(scene.panels, data["nows"]):
                now["t"].append(float(m.now.get_ydata()[0]))
            for (strip, _), record in zip(strips, data["strips"]):
                segments = strip.bar.get_segments()
                record["images"].append({
                    "x": [float(s[0][0]) for s in segments] + [float(segments[-1][-1][0])],
                    "colours": list(map(float, strip.bar.get_array())),
                    "particles": list(map(float, strip.dots.get_xdata())),
                    "shown": [t.get_visible() for t in strip.names],
                    "flash": list(map(float, strip.flash.get_xdata())),
                    "readout": strip.readout.get_text() if strip.readout is not None else ""})
    path.write_text(json.dumps(data))


ENVIRONMENT = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}


def measured(args: list[str], cwd: Path) -> tuple[float, float, int]:
    """(wall-clock seconds, CPU seconds, peak resident set size in bytes) of one process and its waited-for
    children (ru_maxrss from wait4: the largest of them)."""
    start = time.perf_counter()
    process = subprocess.Popen(args, cwd=cwd, stdout=subprocess.DEVNULL, env=ENVIRONMENT)
    _, status, usage = os.wait4(process.pid, 0)
    wall = time.perf_counter() - start
    process.returncode = os.waitstatus_to_exitcode(status)
    if process.returncode != 0:
        raise SystemExit(f"{' '.join(args)} failed with status {process.returncode}")
    return wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss * 1024  # Linux: kilobytes


def speed(args, work: Path) -> None:
    tool = command() + ["animate", "fig2", "--fps", str(FPS), "--seconds", str(SECONDS), "-o", "out/tool.gif"]
    scene_data(work / "fig2_animation.json")
    (work / "bare.py").write_text(BARE_SCRIPT)
    bare = [sys.executable, str(work / "bare.py"), str(work / "fig2_animation.json"), "out/bare.gif"]
    measured(tool, work)  # warm the caches (fonts, bytecode, files) once, outside the timings
    measured(bare, work)
    runs = {"tool": [], "bare": []}
    for _ in range(args.repeat):  # interleaved
        (work / "out" / "tool.gif").unlink(missing_ok=True)
        runs["tool"].append(measured(tool, work))
        runs["bare"].append(measured(bare, work))
    wall = {k: statistics.median(t[0] for t in v) for k, v in runs.items()}
    best = {k: min(t[0] for t in v) for k, v in runs.items()}
    cpu = {k: statistics.median(t[1] for t in v) for k, v in runs.items()}
    from PIL import Image

    images = {k: Image.open(work / "out" / f"{k}.gif").n_frames for k in runs}
    sizes = {k: (work / "out" / f"{k}.gif").stat().st_size for k in runs}
    print(f"speed: sears-paradox animate fig2 --fps {FPS} --seconds {SECONDS} (GIF, {images['tool']} images) against a bare matplotlib script "
          f"(FuncAnimation.save with PillowWriter, {images['bare']} images, same size and dpi); target <= 0.50:")
    print(f"    median wall {wall['tool']:.2f} s / {wall['bare']:.2f} s = {wall['tool'] / wall['bare']:.2f}; "
          f"best wall {best['tool']:.2f} s / {best['bare']:.2f} s = {best['tool'] / best['bare']:.2f}; "
          f"median CPU {cpu['tool']:.2f} s / {cpu['bare']:.2f} s = {cpu['tool'] / cpu['bare']:.2f}")
    print(f"    GIF sizes: tool {sizes['tool'] / 1e6:.2f} MB, bare {sizes['bare'] / 1e6:.2f} MB "
          f"(medians of {args.repeat} interleaved runs)")


def memory(args, work: Path) -> None:
    from rodparadox.animate.encoders import find_ffmpeg

    fps = 25
    seconds = args.memory_images / fps
    formats = ["gif", "png"] + (["mp4"] if find_ffmpeg() else [])
    print(f"memory: peak resident set size of animate fig2 --fps {fps} --seconds {seconds:g} "
          f"({args.memory_images} images), whole process (and ffmpeg); target < 1 GiB:")
    for fmt in formats:
        out = f"out/memory_{fmt}" + ("" if fmt == "png" else f".{fmt}")
        wall, _, peak = measured(command() + ["animate", "fig2", "--fps", str(fps), "--seconds", f"{seconds:g}",
                                              "--format", fmt, "-o", out], work)
        print(f"    {fmt}: {peak / 2 ** 20:.0f} MiB, {wall:.1f} s")
    if not find_ffmpeg():
        print("    mp4: no ffmpeg (neither on the PATH nor from imageio-ffmpeg), not measured")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5, help="interleaved runs of each speed variant (median kept)")
    parser.add_argument("--memory-images", type=int, default=600, help="images of the memory measurement")
    parser.add_argument("--skip-speed", action="store_true")
    parser.add_argument("--skip-memory", action="store_true")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        (work / "out").mkdir()
        if not args.skip_speed:
            speed(args, work)
        if not args.skip_memory:
            memory(args, work)
    print(f"(Python {sys.version.split()[0]}, {os.cpu_count()} CPUs)")


if __name__ == "__main__":
    main()
