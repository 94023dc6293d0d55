"""The ledger as a figure: momentum and energy against each frame's time (README, "Energy and
momentum"). Never pyplot, never files.

One column per frame: momentum above, energy below, against that frame's
own time. Each body's kinetic part (particles dashed, the rod solid), the
kinetic total (thick), the system's total before the first impact (thin,
constant) and between the two the hidden part, shaded. Every impact is a
thin vertical line labelled as in `plot` (B₁, A₁, ...). Same styles,
determinism and gids as `render`.
"""

from __future__ import annotations

from typing import Sequence

import numpy as np
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch
from matplotlib.ticker import FuncFormatter

from rodparadox.physics.engine import History
from rodparadox.physics.frames import PANEL_LETTERS, Frame
from rodparadox.physics.ledger import ZERO, impact_entries
from rodparadox.io.ledger_report import slice_times
from rodparadox.numbers import impact_name, shown
from rodparadox.render import axis_label, coordinate_names, frame_symbol, style_context
from rodparadox.render.styles import Style
from rodparadox.tolerances import SAME_INSTANT


def _series(history: History, frame: Frame):
    """Times and values of every curve, with each impact's instant twice (just before, then just after), so the
    curves jump where a particle is struck instead of sloping across the instant."""
    eta = frame.rapidity
    names = sorted(p.name for p in history.scenario.particles)
    entries = impact_entries(history, eta)
    scale = history.scenario.L
    times, rows = [], []
    for t in slice_times(history, frame):
        if times and t - times[-1] <= SAME_INSTANT * (scale + abs(t)):
            continue  # one instant, boosted twice (two impacts simultaneous in this frame)
        s = history.energy_momentum(eta, t)
        bodies = dict(s.bodies)
        here = [e for e in entries if abs(e.t - t) <= SAME_INSTANT * (scale + abs(t))]
        if here:
            before = dict(bodies)
            for e in here:  # each struck particle as it was just before (the others are unchanged at this instant)
                before[e.impact.particle] = e.particle_before
            kinetic_before = sum((before[n] for n in names), ZERO) + bodies["rod"]  # the order ledger sums in
            times.append(t)
            rows.append([before[n] for n in names] + [bodies["rod"], kinetic_before])
        times.append(t)
        rows.append([bodies[n] for n in names] + [bodies["rod"], s.kinetic])
    columns = names + ["rod", "kinetic"]
    E = {c: np.array([r[k].E for r in rows]) for k, c in enumerate(columns)}
    p = {c: np.array([r[k].p for r in rows]) for k, c in enumerate(columns)}
    return np.array(times), {"p": p, "E": E}, entries


def draw(history: History, frames: Sequence[Frame], style: str = "default") -> Figure:
    """The ledger figure: one column per frame (at most eight), momentum above energy."""
    if not 1 <= len(frames) <= len(PANEL_LETTERS):
        raise ValueError(f"the ledger figure takes 1 to {len(PANEL_LETTERS)} frames, got {len(frames)}")
    with style_context(style) as st:
        return _draw(history, tuple(frames), st)


def _draw(history: History, frames: tuple[Frame, ...], st: Style) -> Figure:
    """Laid out in points from the type size (no layout engine: fast, and the same bytes on every save)."""
    fs = st.font_size
    per_row = min(len(frames), 3 if st.max_width >= 10 else 2)
    rows = -(-len(frames) // per_row)
    gutter = fs * 1.05 * 1.4 + 3.4 * fs + 12  # y label, tick labels (up to "−0.75"), ticks and pads
    suptitle_h, title_h, pair_gap = fs * 1.25 * 1.6, fs * 1.1 * 1.6 + fs * 1.5 + 4, 6.0
    x_axis_h = 3.5 + 3.5 + fs * 1.25 + fs * 1.05 * 1.35 + 4
    legend_h = 2 * fs * 1.8 + 8
    width = st.max_width * 72
    column_w = (width - 10 - per_row * gutter - (per_row - 1) * 14) / per_row
    panel_h = st.panel_height * 72 * 0.6
    row_h = title_h + 2 * panel_h + pair_gap + x_axis_h
    height = suptitle_h + rows * row_h + legend_h
    figure = Figure(figsize=(width / 72, height / 72), dpi=72)
    s = history.scenario
    figure.text(0.5, 1 - 4 / height, f"{s.name}: energy and momentum, v = {shown(s.v)}", ha="center", va="top",
                fontsize=fs * 1.25, gid="title")
    L = s.L
    names = sorted(p.name for p in s.particles)
    particle_inks = dict(st.ledger_particles)
    hidden_fill = {"facecolor": st.sheet, "edgecolor": st.hidden_edge, "hatch": st.hidden_hatch, "linewidth": 0.0}
    total_ink = {"color": "#000000", "linewidth": 0.7 * st.rod.width / 1.7, "linestyle": (0, (1.0, 1.5))}
    kinetic_ink = {"color": "#000000", "linewidth": st.rod.width * 1.3}
    for k, frame in enumerate(frames):
        letter = PANEL_LETTERS[k]
        r, c = divmod(k, per_row)
        times, values, entries = _series(history, frame)
        total = history.initial_total(frame.rapidity)
        t = times / L
        top = None
        x0 = gutter + c * (column_w + gutter + 14)
        y_top = height - suptitle_h - r * row_h - title_h
        for q, row in (("p", 0), ("E", 1)):
            y0 = y_top - (row + 1) * panel_h - row * pair_gap
            ax = figure.add_axes((x0 / width, y0 / height, column_w / width, panel_h / height), sharex=top)
            top = top or ax
            ax.set_gid(f"{letter}-{q}-axes")
            kinetic = values[q]["kinetic"]
            level = total.p if q == "p" else total.E
            ax.fill_between(t, kinetic, np.full_like(kinetic, level), gid=f"{letter}-{q}-hidden", zorder=1,
                            **hidden_fill)
            ax.axhline(level, gid=f"{letter}-{q}-total", zorder=2, **total_ink)
            for n in names:
                ink = particle_inks[n]
                ax.plot(t, values[q][n], color=ink.colour, linewidth=ink.width, linestyle=ink.dashes,
                        gid=f"{letter}-{q}-{n}", zorder=3)
            ax.plot(t, values[q]["rod"], color=st.rod.colour, linewidth=st.rod.width, gid=f"{letter}-{q}-rod", zorder=3)
            ax.plot(t, kinetic, gid=f"{letter}-{q}-kinetic", zorder=4, **kinetic_ink)
            for e in entries:
                ax.axvline(e.t / L, color="#9a9a9a", linewidth=0.6, zorder=0, gid=f"{letter}-{q}-impact-{e.impact.label}")
            ax.set_xlim(t[0], t[-1])
            for axis in (ax.xaxis, ax.yaxis):  # numbers as every figure writes them: no offsets, no 1e-06
                axis.set_major_formatter(FuncFormatter(lambda value, _pos: shown(value, 6)))
            ax.tick_params(labelsize=fs)
            ax.set_ylabel("p / M c" if q == "p" else "E / M c²", fontsize=fs * 1.05)
            if q == "p":
                ax.set_title(f"({letter}) frame {frame_symbol(frame)}", fontsize=fs * 1.1, pad=fs * 1.5 + 4)
                ax.tick_params(labelbottom=False)
                instants: list[list] = []  # impacts at one instant of this frame, side by side above it
                for e in entries:
                    if instants and abs(e.t - instants[-1][0].t) <= SAME_INSTANT * (L + abs(e.t)):
                        instants[-1].append(e)
                    else:
                        instants.append([e])
                for group in instants:
                    for k, e in enumerate(group):
                        # above the panel, over its frame line: no curve runs there
                        # plain text (subscript digits): mathtext would cost milliseconds per label to lay out
                        ax.annotate(impact_name(e.impact.label), (e.t / L, 1.0), xycoords=("data", "axes fraction"),
                                    xytext=((k - (len(group) - 1) / 2) * fs * 1.6, 2), textcoords="offset points",
                                    ha="center", va="bottom", fontsize=fs, gid=f"{letter}-label-{e.impact.label}",
                                    zorder=5, style="italic")
            else:
                ax.set_xlabel(f"{axis_label(coordinate_names(frame)[1])}", fontsize=fs * 1.05)
    handles = [Line2D([], [], color=particle_inks[n].colour, linewidth=particle_inks[n].width,
                      linestyle=particle_inks[n].dashes) for n in names]
    labels = [f"particle {n}" for n in names]
    handles += [Line2D([], [], color=st.rod.colour, linewidth=st.rod.width), Line2D([], [], **kinetic_ink),
                Line2D([], [], **total_ink), Patch(**hidden_fill)]
    labels += ["rod (kinetic)", "kinetic total", "total before the first impact", "hidden = total − kinetic"]
    legend = figure.legend(handles, labels, loc="lower center", bbox_to_anchor=(0.5, 4 / height), ncol=3,
                           fontsize=fs, handlelength=2.8, columnspacing=1.4, borderaxespad=0.0)
    legend.set_gid("legend")
    return figure
