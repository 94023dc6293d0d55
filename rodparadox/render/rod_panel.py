"""The rod's own view as a panel (`--frame rod`, README "The rod's own view"): the rod a fixed vertical strip.

`draw_rod_panel(ax, history, style)` draws the chart of `physics.rod_view` into a caller's Axes and returns its
artists by name: the strip (shaded by compression for the causal rod), the light fronts at 45 degrees, material
lines with their clocks (ticks every `clock_step` of each point's own proper time), each contact as a band on
the end it rides, the particles (through the chart's extension outside the rod), the impacts, and for the rigid
rod each turn (horizontal lines where it starts and ends: the rod's own "now" is every horizontal line) and the
region beyond its pivot's horizon, hatched. `draw_rod_view` adds the panels to a drawn diagram (`plot --frame
rest,rod`) or makes a figure of them alone (`--frame rod`). Sampling is for drawing only: every point is an exact
chart map of an exact world-line.
"""

from __future__ import annotations

import math
from typing import Sequence

import numpy as np
from matplotlib.collections import LineCollection, PolyCollection
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch, Rectangle
from matplotlib.ticker import FixedLocator, FuncFormatter

from rodparadox.physics.rod_view import chart_of, chart_polyline, densified
from rodparadox.physics.rod import clock_step as nice_clock_step
from rodparadox.render.causal_layers import (FRONT_JUMP, HANDLER_MAP, Compression, cells_in_rod,
                                             compression_colour_map, compression_norm, is_causal)
from rodparadox.render.labels import Area, Label, place
from rodparadox.render.layer_base import widest_line
from rodparadox.render.layout import font_sizes, tick_step
from rodparadox.render.styles import STYLES, Style
from rodparadox.numbers import impact_name
from rodparadox.render.text import impact_text_size, suptitle, tick_text, ticks_at

#: the chart's X from this far left of the rod to as far right of it (units of L)
X_MARGIN = 0.75
#: cells of the compression shading, as a fraction of L (cut also at every front: the jumps stay sharp)
CELL = 1.0 / 32
#: interior material lines drawn with their clocks (the ends carry clocks too)
MATERIAL_LINES = 3
#: the width of the panel's key, on its right, in units of the tick labels' size
KEY_WIDTH = 14.0
#: the grid the horizon's hatching is found on, per L
HORIZON_GRID = 32
#: the ground a pivot's dots are drawn on, where the end's solid line is blanked
PIVOT_GROUND = "white"


def rod_box(history, chart=None) -> tuple[float, float, float, float]:
    """(X0, X1, T0, T1) in units of L: the rod with X_MARGIN either side, in time from a lead before the first
    impact (as the frames' panels: the time from the start, at least L/2 and at most 2L) to 1.5 L after the last
    event (a turn's end, or a separation)."""
    chart = chart or chart_of(history)
    L = history.scenario.L
    times = [chart.to_chart(i.event)[0] / L for i in history.impacts]
    if history.turning is not None:
        times += [T1 / L for _, T1, _ in chart.turns]
    first = min(times)
    return -X_MARGIN, 1 + X_MARGIN, first - min(2.0, max(0.5, first)), max(times) + 1.5


def draw_rod_panel(ax, history, style: Style | str = "default", letter: str = "r", title: str | None = None,
                   clock_step: float | None = None, box=None) -> dict[str, tuple]:
    """Draw the rod's own view of a history into `ax`; returns the artists by name."""
    st = STYLES[style] if isinstance(style, str) else style
    fs = font_sizes(st)
    chart = chart_of(history)
    L = history.scenario.L
    X0, X1, T0, T1 = box or rod_box(history, chart)
    step = clock_step or nice_clock_step(T1 - T0, 12)
    drawn: dict[str, list] = {}
    _axes(ax, (X0, X1, T0, T1), st, fs, title or _title(history, letter))
    drawn["strip"] = _strip(ax, history, chart, st, (X0, X1, T0, T1), letter)
    if history.fronts is not None:
        drawn["fronts"] = _fronts(ax, chart, st, T0 * L, T1 * L, letter)
        drawn["contacts"] = _contacts(ax, history, chart, st, letter)
    else:
        drawn["turns"] = _turns(ax, chart, st, (X0, X1), letter, fs)
        drawn["horizon"] = _horizon(ax, chart, st, (X0, X1, T0, T1), letter)
        drawn["light"] = _light(ax, history, chart, st, letter)
    drawn["clocks"] = _clocks(ax, chart, st, step, T0 * L, T1 * L, letter)
    drawn["particles"] = _particles(ax, history, chart, st, (X0, X1, T0, T1), letter, fs)
    drawn["impacts"] = _impacts(ax, history, chart, st, letter, fs)
    drawn["particles"] += _particle_labels(ax, st, (X0, X1, T0, T1), letter, fs, drawn["impacts"])
    drawn["key"] = [_key(ax, history, chart, st, fs, step)]
    return {name: tuple(artists) for name, artists in drawn.items()}


def _title(history, letter: str) -> str:
    model = "causal" if is_causal(history) else "rigid"
    return f"({letter}) the {model} rod's own view"


def _axes(ax, box, st: Style, fs, title: str) -> None:
    X0, X1, T0, T1 = box
    step = tick_step(box)
    ax.set_xlim(X0, X1)
    ax.set_ylim(T0, T1)
    ax.set_aspect("equal", adjustable="box")
    # across, the rod's ends only: the panel is narrow
    for axis, ticks, tick in ((ax.xaxis, [0.0, 1.0], 1.0), (ax.yaxis, ticks_at(T0, T1, step), step)):
        axis.set_major_locator(FixedLocator(ticks))
        axis.set_major_formatter(FuncFormatter(lambda value, _pos, tick=tick: tick_text(value, tick)))
    ax.tick_params(labelsize=fs["tick"], length=st.tick_length)
    ax.set_xlabel("X/L  (material label)", fontsize=fs["label"], fontstyle="italic")
    ax.set_ylabel("T/L  (the rod's own time)", fontsize=fs["label"], fontstyle="italic")
    ax.set_title(title, fontsize=fs["title"])


def _strip(ax, history, chart, st: Style, box, letter: str) -> list:
    """The rod: a fixed strip, its ends solid; the causal rod's shaded by compression lam in light-line cells."""
    X0, X1, T0, T1 = box
    L = history.scenario.L
    out = []
    if history.fronts is not None:
        out += _compression(ax, history, chart, st, T0 * L, T1 * L, letter)
    else:
        out.append(ax.add_patch(Rectangle((0, T0), 1, T1 - T0, facecolor=st.sheet, edgecolor="none", zorder=1,
                                          gid=f"{letter}-rod-sheet")))
    for X, name in ((0.0, "left"), (1.0, "right")):
        line, = ax.plot([X, X], [T0, T1], color=st.rod.colour, linewidth=st.rod.width, zorder=3,
                        gid=f"{letter}-rod-{name}")
        out.append(line)
    return out


def _compression(ax, history, chart, st: Style, T_lo: float, T_hi: float, letter: str) -> list:
    """Diamond cells between light lines u = T + X and w = T - X, each filled with lam at its centre."""
    L, sol = history.scenario.L, chart.solution

    def edges(invariant, lo, hi):
        cuts = sorted({lo, hi, *invariant.breaks(lo, hi), *np.arange(math.ceil(lo / (CELL * L)),
                                                                       math.floor(hi / (CELL * L)) + 1) * CELL * L})
        return np.array([c for c in cuts if lo <= c <= hi])

    us, ws = edges(sol.plus, T_lo, T_hi + L), edges(sol.minus, T_lo - L, T_hi)
    i, j, ln_lam, _ = cells_in_rod(sol, us, ws, L)
    corners = [(us[i], ws[j]), (us[i + 1], ws[j]), (us[i + 1], ws[j + 1]), (us[i], ws[j + 1])]
    polygons = np.stack([np.column_stack([(u - w) / 2, (u + w) / 2]) for u, w in corners], axis=1) / L
    colours = compression_colour_map(st)(compression_norm(history)(ln_lam))
    mesh = PolyCollection(polygons, facecolors=colours, edgecolors=colours, linewidths=0.25, antialiaseds=False,
                          rasterized=True, zorder=1, gid=f"{letter}-compression")
    ax.add_collection(mesh, autolim=False)
    mesh.set_clip_path(Rectangle((0, T_lo / L), 1, (T_hi - T_lo) / L, transform=ax.transData))
    return [mesh]


def _fronts(ax, chart, st: Style, T_lo: float, T_hi: float, letter: str) -> list:
    """Each light front across the rod, where lam or the velocity jumps: a 45-degree line from end to end."""
    L, sol = chart.L, chart.solution
    us, ws = chart.fronts(T_lo, T_hi)
    out = []
    for family, values, invariant in (("+", us, sol.plus), ("-", ws, sol.minus)):
        for s in values:
            if abs(invariant.r(s) - invariant.r(np.nextafter(s, -math.inf))) <= FRONT_JUMP:
                continue  # a kink, no jump
            X = np.array([0.0, L])
            T = s - X if family == "+" else s + X
            line, = ax.plot(X / L, T / L, color=st.front.colour, linewidth=st.front.width, linestyle=st.front.dashes,
                            zorder=2, gid=f"{letter}-front-{len(out)}")
            out.append(line)
    return out


def _contacts(ax, history, chart, st: Style, letter: str) -> list:
    """Each contact: a broad band in the particle's colour on the end it rides, from contact to separation."""
    out = []
    L = history.scenario.L
    for contact in (i for i in history.impacts if i.kind == "contact"):
        separation = next(i for i in history.impacts if i.kind == "separation" and i.particle == contact.particle
                          and i.label == contact.label + "s")
        (T_a, X), (T_b, _) = chart.to_chart(contact.event), chart.to_chart(separation.event)
        X = 0.0 if contact.end == "left" else 1.0
        ink = st.particles[contact.particle]
        band, = ax.plot([X, X], [T_a / L, T_b / L], color=ink.colour, alpha=0.35, linewidth=st.rod.width * 3.2,
                        solid_capstyle="butt", zorder=3.8, gid=f"{letter}-contact-{contact.label}")
        out.append(band)
    return out


def _turns(ax, chart, st: Style, xs, letter: str, fs) -> list:
    """Each turn of the rigid rod: its start and end as lines of the rod's own "now" (horizontal), and its pivot
    (one event for the whole turn: its clock stands still) marked along the end it strikes."""
    out = []
    L = chart.L
    for k, (T_a, T_b, end) in enumerate(chart.turns):
        for T in (T_a, T_b):
            line, = ax.plot([0, 1], [T / L, T / L], color=st.rod_now.colour, linewidth=st.rod_now.width,
                            linestyle=st.rod_now.dashes, zorder=2.5, gid=f"{letter}-turn-{k}-{'ab'[T == T_b]}")
            out.append(line)
        X = 0.0 if end == "left" else 1.0
        # the end's solid line is blanked along the turn, so the pivot's dots read in every style (black on black
        # would draw them solid, against the key)
        gap, = ax.plot([X, X], [T_a / L, T_b / L], color=PIVOT_GROUND, linewidth=st.rod.width + 1.0,
                       solid_capstyle="butt", zorder=3.4, gid=f"{letter}-pivot-{k}-ground")
        pivot, = ax.plot([X, X], [T_a / L, T_b / L], zorder=3.5, gid=f"{letter}-pivot-{k}", **_pivot_ink(st))
        out += [gap, pivot]
    return out


def _pivot_ink(st: Style) -> dict:
    """How a pivot's stretch of an end is drawn, on the panel and in its key: dots as broad as the end."""
    return {"color": st.impact_colour, "linewidth": st.rod.width, "linestyle": (0, (1.0, 1.5))}


def _light(ax, history, chart, st: Style, letter: str) -> list:
    """The light from each impact into the rigid rod, through the chart: the rod turns at once (a level line)
    while the light still crosses it."""
    L = history.scenario.L
    out = []
    for impact in (i for i in history.impacts if i.kind == "contact"):
        inward = 1.0 if impact.end == "left" else -1.0
        ray = densified(np.array([[impact.event.x, impact.event.t],
                                  [impact.event.x + inward * 6 * L, impact.event.t + 6 * L]]), 0.02 * L)
        drawn = chart_polyline(chart, ray) / L
        inside = (drawn[:, 0] >= -1e-9) & (drawn[:, 0] <= 1 + 1e-9)  # NaN (beyond a horizon) is not inside
        if inside.sum() < 2:
            continue
        segment = np.where(inside[:, None], drawn, np.nan)  # across the rod only; a break where the chart has none
        line, = ax.plot(segment[:, 0], segment[:, 1], color=st.light_cone.colour,
                        linewidth=1.5 * st.light_cone.width, linestyle=st.light_cone.dashes, zorder=2.6, gid=f"{letter}-light-{impact.label}")
        out.append(line)
    return out


def _horizon(ax, chart, st: Style, box, letter: str) -> list:
    """Hatch the chart where it holds no event, or an event the rod's time gives two places: beyond a pivot's
    horizon during its turn (`RigidChart.to_event` is None there)."""
    X0, X1, T0, T1 = box
    L = chart.L
    if not chart.turns:
        return []
    xs = np.linspace(X0, X1, max(2, round((X1 - X0) * HORIZON_GRID)) + 1)
    # rows only where a turn, or the wedges beside it, can be: the turns' times with a margin of L either side
    spans = [(a / L - 1.0, b / L + 1.0) for a, b, _ in chart.turns]
    ts = np.linspace(T0, T1, max(2, round((T1 - T0) * HORIZON_GRID)) + 1)
    mask = np.zeros((len(ts), len(xs)))
    for r, T in enumerate(ts):
        if any(a <= T <= b for a, b in spans):
            for c, X in enumerate(xs):
                if X < 0 or X > 1:  # inside the rod the chart always holds an event
                    mask[r, c] = chart.to_event(T * L, X * L) is None
    if not mask.any():
        return []
    filled = ax.contourf(xs, ts, mask, levels=[0.5, 1.5], colors="none", hatches=["////"], zorder=1.5)
    filled.set_edgecolor(st.other_axes.colour)
    filled.set_linewidth(0.0)
    filled.set_gid(f"{letter}-horizon")
    return [filled]


def _clocks(ax, chart, st: Style, step: float, T_lo: float, T_hi: float, letter: str) -> list:
    """Material lines (the ends and MATERIAL_LINES inside), each with a tick every `step` of its proper time."""
    L = chart.L
    out = []
    for k in range(MATERIAL_LINES + 2):
        X = k / (MATERIAL_LINES + 1)
        if 0 < k < MATERIAL_LINES + 1:
            line, = ax.plot([X, X], [T_lo / L, T_hi / L], color=st.rod_interior.colour,
                            linewidth=st.rod_interior.width, zorder=2.2, gid=f"{letter}-material-{k}")
            out.append(line)
        ticks = chart.clock_ticks(X * L, step * L, T_lo, T_hi)
        if ticks:
            T = np.array([T for _, T in ticks]) / L
            half = 0.06
            segments = np.stack([np.column_stack([np.full_like(T, X - half), T]),
                                 np.column_stack([np.full_like(T, X + half), T])], axis=1)
            marks = LineCollection(segments, colors=st.rod.colour if k in (0, MATERIAL_LINES + 1) else
                                   st.rod_interior.colour, linewidths=max(1.0, st.rod_interior.width * 2.2),
                                   zorder=3.2, gid=f"{letter}-clock-{k}")
            ax.add_collection(marks, autolim=False)
            out.append(marks)
    return out


def _particles(ax, history, chart, st: Style, box, letter: str, fs) -> list:
    """Each particle's world-line through the chart (outside the rod the causal chart is extended along light
    rays from its ends; the rigid chart breaks where a world-line passes beyond a pivot's horizon)."""
    X0, X1, T0, T1 = box
    L = history.scenario.L
    out = []
    for name in sorted(st.particles):
        line = history.worldline(name)
        if line is None:
            continue
        t_lo = min(e.t for e in _corners(chart, box, L, T0)) - L
        t_hi = max(e.t for e in _corners(chart, box, L, T1)) + L
        points = densified(line.sample(t_lo, t_hi, 1e-4 * L), 0.04 * L)
        drawn = chart_polyline(chart, points) / L
        ink = st.particles[name]
        artist, = ax.plot(drawn[:, 0], drawn[:, 1], color=ink.colour, linewidth=ink.width, linestyle=ink.dashes,
                          zorder=4, gid=f"{letter}-particle-{name}")
        out.append(artist)
    return out


def _particle_labels(ax, st: Style, box, letter: str, fs, impacts) -> list:
    """Each particle's letter beside its world-line where it crosses no line, impact or impact's name, placed as
    on the frames' panels (`labels.place`); its anchors along the part drawn in the panel, the first part first."""
    X0, X1, T0, T1 = box
    ax.apply_aspect()  # the drawn box (equal scales); its size in points
    width, height = np.array(ax.bbox.size) * 72 / ax.get_figure(root=True).dpi
    scale, labels, lines = width / (X1 - X0), [], [a.get_xydata() for a in ax.lines]
    lines += [q for c in ax.collections if isinstance(c, LineCollection) for q in c.get_segments()]
    for a in impacts:  # each marker and impact name as the outline of its box
        (x, y), half = a.get_xydata()[0] if a in ax.lines else a.get_position(), st.impact_size / 2 / scale
        if a not in ax.lines:
            w, h, _ = impact_text_size(a.get_gid().rsplit("-", 1)[1], fs["impact"])
            x, half = x + (w / 2 if a.get_ha() == "left" else -w / 2) / scale, max(w, h) / 2 / scale
        lines.append(np.array([[x - half, y - half], [x + half, y - half], [x + half, y + half], [x - half, y + half],
                               [x - half, y - half]]))
    for artist in (a for a in ax.lines if str(a.get_gid()).startswith(f"{letter}-particle-")):
        name, points = artist.get_gid().rsplit("-", 1)[1], artist.get_xydata()
        seen = points[(points[:, 0] >= X0) & (points[:, 0] <= X1) & (points[:, 1] >= T0) & (points[:, 1] <= T1)]
        if len(seen):
            anchors = tuple(tuple(seen[round(f * (len(seen) - 1))]) for f in (0.1, 0.35, 0.65, 0.9))
            labels.append(Label(f"{letter}-label-{name}", name, anchors, 180.0 if name == "A" else 0.0,
                                artist.get_color(), fs["particle"], italic=True))
    return [a for placed in place(ax, Area(tuple(box), width, height), labels, lines, [], widest_line(st),
                                  fs["impact"], st.font_size) for a in placed]


def _corners(chart, box, L, T):
    """The events at the box's corners and middle at chart time T (those the chart holds; the rod's middle always)."""
    X0, X1, _, _ = box
    events = [chart.to_event(T * L, X * L) for X in (X0, X1)]
    return [e for e in events if e is not None] + [chart.to_event(T * L, 0.5 * L)]


def _impacts(ax, history, chart, st: Style, letter: str, fs) -> list:
    """Every impact where the chart places it (a rigid turn's pivot at the turn's start, hollow at its end)."""
    L = history.scenario.L
    out = []
    for impact in history.impacts:
        if getattr(chart, "placed", None):
            places = chart.placed(impact.event)
        else:
            places = [chart.to_chart(impact.event)]
        for k, (T, X, *_) in enumerate(places):
            hollow = k > 0 or impact.kind == "separation"
            marker, = ax.plot([X / L], [T / L], marker="o", markersize=st.impact_size * (0.8 if hollow else 1.0),
                              markerfacecolor="white" if hollow else st.impact_colour,
                              markeredgecolor=st.impact_colour, linestyle="none", zorder=5,
                              gid=f"{letter}-impact-{impact.label}-{k}")
            out.append(marker)
        if places and impact.kind != "separation":  # a separation: hollow, named in the legend (A'1)
            T, X = places[0][0], places[0][1]
            side = -1 if X < 0.5 * L else 1
            out.append(ax.text(X / L + side * 0.09, T / L, impact_name(impact.label, math_text=True), fontsize=fs["impact"],
                               va="center", ha="right" if side < 0 else "left", zorder=6, gid=f"{letter}-impact-label-{impact.label}"))
    return out


def _key(ax, history, chart, st: Style, fs, step: float):
    """What the panel shows, in a small key at its top: a teacher reads the picture without the code."""
    handles = [Line2D([], [], color=st.rod_interior.colour, linewidth=st.rod_interior.width, marker="_",
                      markersize=6, markeredgewidth=1.2)]
    labels = [f"material point: a tick\nevery {tick_text(step, step)} L of its\nown (proper) time"]
    if history.fronts is not None:
        handles.append(Line2D([], [], color=st.front.colour, linewidth=st.front.width, linestyle=st.front.dashes))
        labels.append("light front: always\nat 45\N{DEGREE SIGN} here")
        handles.append(Line2D([], [], color="#777777", alpha=0.35, linewidth=st.rod.width * 3.2))
        labels.append("contact: particle\nrides the end")
        ramp, text = Compression().legend_entry(st, history, None)
        handles.append(ramp)
        labels.append(text.replace(": ", ":\n", 1).replace(", 1 unstressed", "\n(1 unstressed)"))
        handles.append(Line2D([], [], linestyle="none"))
        labels.append("outside the rod: the\nchart carried out along\nlight rays from its ends")
    else:
        if not chart.turns:
            handles.append(Line2D([], [], linestyle="none"))
            labels.append("no turn: the chart is\nS throughout, every\nlevel line the rod's \"now\"")
        else:
            handles.append(Line2D([], [], color=st.rod_now.colour, linewidth=st.rod_now.width,
                                  linestyle=st.rod_now.dashes))
            labels.append("a turn starts or ends;\nevery level line is\nthe rod's own \"now\"")
            handles.append(Line2D([], [], color=st.light_cone.colour, linewidth=1.5 * st.light_cone.width,
                                  linestyle=st.light_cone.dashes))
            labels.append("light from an impact:\nthe rod turns before\nit has crossed")
            handles.append(Line2D([], [], **_pivot_ink(st)))
            labels.append("pivot: one event all\nturn, its clock stopped")
            handles.append(Patch(facecolor="none", edgecolor=st.other_axes.colour, hatch="////", linewidth=0))
            labels.append("beyond the pivot's\nhorizon: placed twice,\nbefore and after the turn")
    legend = ax.legend(handles, labels, loc="upper left", bbox_to_anchor=(1.04, 1.0), borderaxespad=0.0,
                       fontsize=fs["tick"] * 0.85, handlelength=2.0, borderpad=0.0, labelspacing=0.6,
                       frameon=False, handler_map=HANDLER_MAP)
    legend.set_zorder(7)
    return legend


# --- the panels with a diagram, or alone --------------------------------------------------------------------------

def draw_rod_view(histories: Sequence, style: str, diagram=None, first: bool = False) -> Figure:
    """The rod's own view of each history (one per row: rigid above causal with --rod both): beside the panels of
    a drawn diagram (on its left when `first`, the figure widened), or, without one, in a figure of its own. Drawn
    in the style's rcParams (its fonts), as the diagram is."""
    from rodparadox.render.diagram import style_context

    with style_context(style):
        return _rod_view(histories, style, diagram, first)


def _rod_view(histories: Sequence, style: str, diagram, first: bool) -> Figure:
    st = STYLES[style]
    fs = font_sizes(st)
    boxes = [_union([rod_box(h) for h in histories])] * len(histories)  # the two models on the same scales
    if diagram is None:
        title_band = 2.2 * fs["suptitle"]
        width, height = rod_view_size(histories, style, st.max_width * 72)
        figure = Figure(figsize=(width / 72, (height + title_band) / 72), dpi=72)
        _into(figure, histories, st, boxes[0], (0.0, 0.0, width, height), width, height + title_band)
        figure.text(0.5, 1 - 6 / (height + title_band), suptitle(histories[0].scenario, width, fs["suptitle"]),
                    ha="center", va="top", fontsize=fs["suptitle"], gid="title")
        return figure
    figure = diagram.figure
    W0, H = figure.get_size_inches() * 72
    per_row = len(diagram.panels) // len(histories)
    for info in diagram.panels:
        info.axes.apply_aspect()  # the drawn box (equal scales), not the one the axes were given
    rows = [diagram.panels[k * per_row].axes.get_position() for k in range(len(histories))]
    width_ax = [r.height * H * (b[1] - b[0]) / (b[3] - b[2]) for r, b in zip(rows, boxes)]
    margin_l, margin_r = _margins(st)[:2]
    extra = margin_l + max(width_ax) + margin_r
    W = W0 + extra
    given = [(ax, ax.get_position(original=True)) for ax in figure.axes]  # read before the figure widens
    figure.set_size_inches(W / 72, H / 72)
    shift = extra if first else 0.0
    for ax, p in given:
        ax.set_position((p.x0 * W0 / W + shift / W, p.y0, p.width * W0 / W, p.height))
    x = margin_l if first else W0 + margin_l
    letters = _relettered(diagram, len(histories), first)
    for k, (h, box, r, w) in enumerate(zip(histories, boxes, rows, width_ax)):
        ax = figure.add_axes((x / W, r.y0, w / W, r.height))
        ax.set_gid(f"rod{k}-view")
        draw_rod_panel(ax, h, st, letter=letters[k], box=box)
    return figure


def _margins(st: Style) -> tuple[float, float, float, float]:
    """(left, key, bottom, top) around one panel of the rod's own view, in points: tick labels and the axis name,
    the key on its right, the x axis's ticks and name, the title."""
    fs = font_sizes(st)
    return 5.2 * fs["tick"], KEY_WIDTH * fs["tick"], 4.5 * fs["tick"], 2.6 * fs["title"]


def rod_view_size(histories: Sequence, style: str, width: float) -> tuple[float, float]:
    """(width, height) in points of the rod's own view of each history, side by side, at most `width` wide and its
    panels at most the style's panel height."""
    st = STYLES[style]
    left, key, bottom, top = _margins(st)
    X0, X1, T0, T1 = _union([rod_box(h) for h in histories])
    aspect = (X1 - X0) / (T1 - T0)
    h_ax = min(st.panel_height * 72, (width / len(histories) - left - key) / aspect)
    return len(histories) * (left + h_ax * aspect + key), h_ax + bottom + top


def _union(boxes):
    return (min(b[0] for b in boxes), max(b[1] for b in boxes), min(b[2] for b in boxes), max(b[3] for b in boxes))


def draw_rod_view_into(target, histories: Sequence, style: str) -> None:
    """The rod's own view of each history, side by side, into a Figure or SubFigure the caller has sized (a
    handout's text width), centred in it, in the style's rcParams."""
    from rodparadox.render.diagram import style_context

    with style_context(style):
        _rod_view_into(target, histories, style)


def _rod_view_into(target, histories: Sequence, style: str) -> None:
    st = STYLES[style]
    root = target.get_figure(root=True) if hasattr(target, "get_figure") else target
    dpi = root.dpi
    W, H = target.bbox.width * 72 / dpi, target.bbox.height * 72 / dpi
    width, height = rod_view_size(histories, style, W)
    if height > H:  # the target is lower than the natural size: the panels shrink to fit it
        left, key, bottom, top = _margins(st)
        X0, X1, T0, T1 = _union([rod_box(h) for h in histories])
        h_ax = H - bottom - top
        width, height = len(histories) * (left + h_ax * (X1 - X0) / (T1 - T0) + key), H
    _into(target, histories, st, _union([rod_box(h) for h in histories]),
          ((W - width) / 2, (H - height) / 2, width, height), W, H)


def _into(target, histories, st: Style, box, area, W: float, H: float) -> None:
    """The panels side by side in `area` (x, y, width, height in points from the target's lower left)."""
    left, key, bottom, top = _margins(st)
    x, y, width, height = area
    h_ax = height - bottom - top
    w_ax = h_ax * (box[1] - box[0]) / (box[3] - box[2])
    for k, h in enumerate(histories):
        x0 = x + k * (left + w_ax + key) + left
        ax = target.add_axes(((x0) / W, (y + bottom) / H, w_ax / W, h_ax / H))
        ax.set_gid(f"rod{k}-view")
        draw_rod_panel(ax, h, st, letter="abcdefgh"[k], box=box)


def _relettered(diagram, rows: int, first: bool) -> list[str]:
    """Letter the panels again in reading order, row by row, now that each row has the rod's own view at its start
    (`first`) or end; returns the letters of the rod's panels, one per row."""
    from rodparadox.physics.frames import PANEL_LETTERS

    letters = iter(PANEL_LETTERS + "ijklmnopqrstuvwxyz")
    per_row = len(diagram.panels) // rows
    mine = []
    for r in range(rows):
        if first:
            mine.append(next(letters))
        for info in diagram.panels[r * per_row:(r + 1) * per_row]:
            title = info.axes.title.get_text()
            if title.startswith("("):
                info.axes.title.set_text(f"({next(letters)})" + title[title.index(")") + 1:])
        if not first:
            mine.append(next(letters))
    return mine
