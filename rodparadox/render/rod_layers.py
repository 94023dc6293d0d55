"""The rod's own view's layers (`rod_panel`): each draws one element of the panel and gives its own lines of the
panel's key, and says in `applies(history)` whether the run has what it draws (the turns of the rod's lines of
simultaneity, `RodHistory.turning`; the fronts, compression and lasting contacts, `RodHistory.fronts`): a panel
asks each layer, never the model's name.

`DRAW` is the drawing order (with the zorders it fixes the SVG's order of elements), `KEY` the key's order. Every
point drawn is an exact chart map of an exact world-line; sampling is for drawing only.
"""

from __future__ import annotations

import math

import numpy as np
from matplotlib.collections import LineCollection, PolyCollection
from matplotlib.lines import Line2D
from matplotlib.patches import Patch, Rectangle

from rodparadox.numbers import impact_name
from rodparadox.physics.rod_view import chart_polyline, densified
from rodparadox.render.rod_forces import Forces
from rodparadox.render.rod_layer_base import RodLayer, RodPanel
from rodparadox.render.causal_layers import (FRONT_JUMP, Compression as FrameCompression, cells_in_rod,
                                             compression_colour_map, compression_norm)
from rodparadox.render.styles import Style
from rodparadox.render.text import tick_text

#: cells of the compression shading, as a fraction of L (cut also at every front: the jumps stay sharp)
CELL = 1.0 / 32
#: interior material lines drawn with their clocks (the ends carry clocks too)
MATERIAL_LINES = 3
#: the grid the horizon's hatching is found on, per L
HORIZON_GRID = 32
#: at most this many rows of it; a particle's line is sampled to 1e-4 L, densified every 0.04 L, in a window of up
#: to PARTICLE_WINDOW L, in proportion beyond (a gap of 1e6 L: a panel's cost bounded by what it shows)
HORIZON_ROWS, PARTICLE_WINDOW = 2048, 50.0
#: the most points of a particle's world-line carried into the rod's chart
PARTICLE_POINTS = 2000
#: the ground a pivot's dots are drawn on, where the end's solid line is blanked
PIVOT_GROUND = "white"


def _with_fronts(history) -> bool:
    return history.fronts is not None


def _with_turns(history) -> bool:
    return history.turning is not None


class CompressionFill(RodLayer):
    """The causal rod's strip shaded by compression lam: diamond cells between light lines u = T + X and w = T - X,
    each filled with lam at its centre."""

    name = "compression"

    def applies(self, history):
        return _with_fronts(history)

    def draw(self, ax, panel):
        history, chart, letter = panel.history, panel.chart, panel.letter
        T_lo, T_hi = panel.box[2] * panel.L, panel.box[3] * panel.L
        L, sol = history.scenario.L, chart.solution

        def edges(invariant, lo, hi):
            cuts = sorted({lo, hi, *invariant.breaks(lo, hi), *np.arange(math.ceil(lo / (CELL * L)),
                                                                           math.floor(hi / (CELL * L)) + 1) * CELL * L})
            return np.array([c for c in cuts if lo <= c <= hi])

        us, ws = edges(sol.plus, T_lo, T_hi + L), edges(sol.minus, T_lo - L, T_hi)
        i, j, ln_lam, _ = cells_in_rod(sol, us, ws, L)
        corners = [(us[i], ws[j]), (us[i + 1], ws[j]), (us[i + 1], ws[j + 1]), (us[i], ws[j + 1])]
        polygons = np.stack([np.column_stack([(u - w) / 2, (u + w) / 2]) for u, w in corners], axis=1) / L
        colours = compression_colour_map(panel.style)(compression_norm(history)(ln_lam))
        mesh = PolyCollection(polygons, facecolors=colours, edgecolors=colours, linewidths=0.25, antialiaseds=False,
                              rasterized=True, zorder=1, gid=f"{letter}-compression")
        ax.add_collection(mesh, autolim=False)
        mesh.set_clip_path(Rectangle((0, T_lo / L), 1, (T_hi - T_lo) / L, transform=ax.transData))
        return [mesh]

    def key(self, panel):
        ramp, text = FrameCompression().legend_entry(panel.style, panel.history, None)
        return [(ramp, text.replace(": ", ":\n", 1).replace(", 1 unstressed", "\n(1 unstressed)")),
                (Line2D([], [], linestyle="none"), "outside the rod: the\nchart carried out along\nlight rays from its ends")]


class PlainSheet(RodLayer):
    """The rod's strip in the style's plain sheet."""

    name = "sheet"

    def draw(self, ax, panel):
        X0, X1, T0, T1 = panel.box
        return [ax.add_patch(Rectangle((0, T0), 1, T1 - T0, facecolor=panel.style.sheet, edgecolor="none", zorder=1,
                                       gid=f"{panel.letter}-rod-sheet"))]


class Strip(RodLayer):
    """The rod: a fixed strip, its ends solid, filled by the first of `FILLS` that applies (shaded by compression
    where the run has it, else plain)."""

    name = "strip"
    FILLS = (CompressionFill(), PlainSheet())

    def fill(self, history) -> RodLayer:
        return next(fill for fill in self.FILLS if fill.applies(history))

    def draw(self, ax, panel):
        X0, X1, T0, T1 = panel.box
        st = panel.style
        out = list(self.fill(panel.history).draw(ax, panel))
        for X, name in ((0.0, "left"), (1.0, "right")):
            line, = ax.plot([X, X], [T0, T1], color=st.rod.colour, linewidth=st.rod.width, zorder=3,
                            gid=f"{panel.letter}-rod-{name}")
            out.append(line)
        return out

    def key(self, panel):
        return self.fill(panel.history).key(panel)


class Fronts(RodLayer):
    """Each light front across the rod, where lam or the velocity jumps: a 45-degree line from end to end."""

    name = "fronts"

    def applies(self, history):
        return _with_fronts(history)

    @staticmethod
    def _jumps(panel) -> list[tuple[str, float]]:
        """(family, u or w) of each front in the panel's chart times where lam or the velocity jumps."""
        chart = panel.chart
        sol = chart.solution
        us, ws = chart.fronts(panel.box[2] * panel.L, panel.box[3] * panel.L)
        return [(family, s) for family, values, invariant in (("+", us, sol.plus), ("-", ws, sol.minus))
                for s in values if abs(invariant.r(s) - invariant.r(np.nextafter(s, -math.inf))) > FRONT_JUMP]

    def draw(self, ax, panel):
        st, letter, L = panel.style, panel.letter, panel.chart.L
        out = []
        for family, s in self._jumps(panel):  # a kink, no jump, draws nothing
            X = np.array([0.0, L])
            T = s - X if family == "+" else s + X
            line, = ax.plot(X / L, T / L, color=st.front.colour, linewidth=st.front.width,
                            linestyle=st.front.dashes, zorder=2, gid=f"{letter}-front-{len(out)}")
            out.append(line)
        return out

    def key(self, panel):
        st = panel.style
        if panel.history.driving is not None and not self._jumps(panel):  # smooth forces: no front to name
            return []
        return [(Line2D([], [], color=st.front.colour, linewidth=st.front.width, linestyle=st.front.dashes),
                 "light front: always\nat 45\N{DEGREE SIGN} here")]


class Contacts(RodLayer):
    """Each lasting contact: a broad band in the particle's colour on the end it rides, from contact to
    separation."""

    name = "contacts"

    def applies(self, history):
        return _with_fronts(history)

    def draw(self, ax, panel):
        history, chart, st = panel.history, panel.chart, panel.style
        out = []
        L = history.scenario.L
        for contact in (i for i in history.impacts if not i.is_separation):
            separation = next(i for i in history.impacts if i.is_separation and i.particle == contact.particle
                              and i.label == contact.label + "s")
            (T_a, X), (T_b, _) = chart.to_chart(contact.event), chart.to_chart(separation.event)
            X = 0.0 if contact.end == "left" else 1.0
            ink = st.particles[contact.particle]
            band, = ax.plot([X, X], [T_a / L, T_b / L], color=ink.colour, alpha=0.35, linewidth=st.rod.width * 3.2,
                            solid_capstyle="butt", zorder=3.8, gid=f"{panel.letter}-contact-{contact.label}")
            out.append(band)
        return out

    def key(self, panel):
        if not any(not i.is_separation for i in panel.history.impacts):  # driven by forces: no particle rides it
            return []
        return [(Line2D([], [], color="#777777", alpha=0.35, linewidth=panel.style.rod.width * 3.2),
                 "contact: particle\nrides the end")]


class Turns(RodLayer):
    """Each turn of the rigid rod: its start and end as lines of the rod's own "now" (horizontal)."""

    name = "turns"

    def applies(self, history):
        return _with_turns(history)

    def chart_times(self, history, chart):
        return [T1 / history.scenario.L for _, T1, _ in chart.turns]

    def draw(self, ax, panel):
        st, L, out = panel.style, panel.chart.L, []
        for k, (T_a, T_b, end) in enumerate(panel.chart.turns):
            for T in (T_a, T_b):
                line, = ax.plot([0, 1], [T / L, T / L], color=st.rod_now.colour, linewidth=st.rod_now.width,
                                linestyle=st.rod_now.dashes, zorder=2.5,
                                gid=f"{panel.letter}-turn-{k}-{'ab'[T == T_b]}")
                out.append(line)
        return out

    def key(self, panel):
        st = panel.style
        if not panel.chart.turns:
            return [(Line2D([], [], linestyle="none"),
                     "no turn: the chart is\nS throughout, every\nlevel line the rod’s “now”")]
        return [(Line2D([], [], color=st.rod_now.colour, linewidth=st.rod_now.width, linestyle=st.rod_now.dashes),
                 "a turn starts or ends;\nevery level line is\nthe rod’s own “now”")]


def pivot_ink(st: Style) -> dict:
    """How a pivot's stretch of an end is drawn, on the panel and in its key: dots as broad as the end."""
    return {"color": st.impact_colour, "linewidth": st.rod.width, "linestyle": (0, (1.0, 1.5))}


class Pivots(RodLayer):
    """Each turn's pivot (one event for the whole turn: its clock stands still), marked along the end it strikes."""

    name = "pivots"

    def applies(self, history):
        return _with_turns(history)

    def draw(self, ax, panel):
        st, L, out = panel.style, panel.chart.L, []
        for k, (T_a, T_b, end) in enumerate(panel.chart.turns):
            X = 0.0 if end == "left" else 1.0
            # the end's solid line is blanked along the turn, so the pivot's dots read in every style (black on
            # black would draw them solid, against the key)
            gap, = ax.plot([X, X], [T_a / L, T_b / L], color=PIVOT_GROUND, linewidth=st.rod.width + 1.0,
                           solid_capstyle="butt", zorder=3.4, gid=f"{panel.letter}-pivot-{k}-ground")
            pivot, = ax.plot([X, X], [T_a / L, T_b / L], zorder=3.5, gid=f"{panel.letter}-pivot-{k}", **pivot_ink(st))
            out += [gap, pivot]
        return out

    def key(self, panel):
        if not panel.chart.turns:
            return []
        return [(Line2D([], [], **pivot_ink(panel.style)), "pivot: one event all\nturn, its clock stopped")]


class Horizon(RodLayer):
    """Hatch the chart where it holds no event, or an event the rod's time gives two places: beyond a pivot's
    horizon during its turn (`RigidChart.to_event` is None there)."""

    name = "horizon"

    def applies(self, history):
        return _with_turns(history)

    def draw(self, ax, panel):
        chart = panel.chart
        X0, X1, T0, T1 = panel.box
        L = chart.L
        if not chart.turns:
            return []
        xs = np.linspace(X0, X1, max(2, round((X1 - X0) * HORIZON_GRID)) + 1)
        # rows only where a turn, or the wedges beside it, can be: the turns' times with a margin of L either side
        spans = [(a / L - 1.0, b / L + 1.0) for a, b, _ in chart.turns]
        ts = np.linspace(T0, T1, min(HORIZON_ROWS, max(2, round((T1 - T0) * HORIZON_GRID))) + 1)
        mask = np.zeros((len(ts), len(xs)))
        for r, T in enumerate(ts):
            if any(a <= T <= b for a, b in spans):
                for c, X in enumerate(xs):
                    if X < 0 or X > 1:  # inside the rod the chart always holds an event
                        mask[r, c] = chart.to_event(T * L, X * L) is None
        if not mask.any():
            return []
        filled = ax.contourf(xs, ts, mask, levels=[0.5, 1.5], colors="none", hatches=["////"], zorder=1.5)
        filled.set_edgecolor(panel.style.other_axes.colour)
        filled.set_linewidth(0.0)
        filled.set_gid(f"{panel.letter}-horizon")
        return [filled]

    def key(self, panel):
        if not panel.chart.turns:
            return []
        return [(Patch(facecolor="none", edgecolor=panel.style.other_axes.colour, hatch="////", linewidth=0),
                 "beyond the pivot’s\nhorizon: no place in\nthe rod’s chart")]


class Light(RodLayer):
    """The light from each impact into the rigid rod, through the chart: the rod turns at once (a level line)
    while the light still crosses it."""

    name = "light"

    def applies(self, history):
        return _with_turns(history)

    def draw(self, ax, panel):
        history, chart, st = panel.history, panel.chart, panel.style
        L = history.scenario.L
        out = []
        for impact in (i for i in history.impacts if not i.is_separation):
            inward = 1.0 if impact.end == "left" else -1.0
            ray = densified(np.array([[impact.event.x, impact.event.t],
                                      [impact.event.x + inward * 6 * L, impact.event.t + 6 * L]]), 0.02 * L)
            drawn = chart_polyline(chart, ray) / L
            inside = (drawn[:, 0] >= -1e-9) & (drawn[:, 0] <= 1 + 1e-9)  # NaN (beyond a horizon) is not inside
            if inside.sum() < 2:
                continue
            segment = np.where(inside[:, None], drawn, np.nan)  # across the rod only; a break where the chart has none
            line, = ax.plot(segment[:, 0], segment[:, 1], color=st.light_cone.colour,
                            linewidth=1.5 * st.light_cone.width, linestyle=st.light_cone.dashes, zorder=2.6,
                            gid=f"{panel.letter}-light-{impact.label}")
            out.append(line)
        return out

    def key(self, panel):
        st = panel.style
        if not panel.chart.turns:
            return []
        return [(Line2D([], [], color=st.light_cone.colour, linewidth=1.5 * st.light_cone.width,
                        linestyle=st.light_cone.dashes), "light from an impact:\nthe rod turns before\nit has crossed")]


class Clocks(RodLayer):
    """Material lines (the ends and MATERIAL_LINES inside), each with a tick every `step` of its proper time."""

    name = "clocks"

    def draw(self, ax, panel):
        chart, st, letter, step = panel.chart, panel.style, panel.letter, panel.step
        T_lo, T_hi = panel.box[2] * panel.L, panel.box[3] * panel.L
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

    def key(self, panel):
        st, step = panel.style, panel.step
        return [(Line2D([], [], color=st.rod_interior.colour, linewidth=st.rod_interior.width, marker="_",
                        markersize=6, markeredgewidth=1.2),
                 f"material point: a tick\nevery {tick_text(step, step)} L of its\nown (proper) time")]


class Particles(RodLayer):
    """Each particle's world-line through the chart (outside the rod the causal chart is extended along light
    rays from its ends; the rigid chart breaks where a world-line passes beyond a pivot's horizon)."""

    name = "particles"

    def draw(self, ax, panel):
        history, chart, st, box = panel.history, panel.chart, panel.style, panel.box
        X0, X1, T0, T1 = box
        L = history.scenario.L
        out = []
        for name in sorted(st.particles):
            line = history.worldline(name)
            if line is None:
                continue
            t_lo = min(e.t for e in _corners(chart, box, L, T0)) - L
            t_hi = max(e.t for e in _corners(chart, box, L, T1)) + L
            coarse = max(1.0, (T1 - T0) / PARTICLE_WINDOW)
            # at most PARTICLE_POINTS points: a rod driven near c spans thousands of L of S's time in a few L of its
            # own (single at v = 0.9999999, causal: 10^5 points, each found in the chart by Newton, ran minutes)
            spacing = max(0.04 * L * coarse, (t_hi - t_lo) / PARTICLE_POINTS)
            points = densified(line.sample(t_lo, t_hi, 1e-4 * L * coarse), spacing)
            drawn = chart_polyline(chart, points) / L
            ink = st.particles[name]
            artist, = ax.plot(drawn[:, 0], drawn[:, 1], color=ink.colour, linewidth=ink.width, linestyle=ink.dashes,
                              zorder=4, gid=f"{panel.letter}-particle-{name}")
            out.append(artist)
        return out


def _corners(chart, box, L, T):
    """The events at the box's corners and middle at chart time T (those the chart holds; the rod's middle always)."""
    X0, X1, _, _ = box
    events = [chart.to_event(T * L, X * L) for X in (X0, X1)]
    return [e for e in events if e is not None] + [chart.to_event(T * L, 0.5 * L)]


class Impacts(RodLayer):
    """Every impact where the chart places it (a rigid turn's pivot at the turn's start, hollow at its end; a
    separation hollow, named in the legend)."""

    name = "impacts"

    def draw(self, ax, panel):
        history, chart, st, fs, letter = panel.history, panel.chart, panel.style, panel.fs, panel.letter
        L = history.scenario.L
        out = []
        for impact in history.impacts:
            places = chart.placed(impact.event)
            for k, (T, X, *_) in enumerate(places):
                hollow = k > 0 or impact.is_separation
                marker, = ax.plot([X / L], [T / L], marker="o", markersize=st.impact_size * (0.8 if hollow else 1.0),
                                  markerfacecolor="white" if hollow else st.impact_colour,
                                  markeredgecolor=st.impact_colour, linestyle="none", zorder=5,
                                  gid=f"{letter}-impact-{impact.label}-{k}")
                out.append(marker)
            if places and not impact.is_separation:  # a separation: hollow, named in the legend (A'1)
                T, X = places[0][0], places[0][1]
                side = -1 if X < 0.5 * L else 1
                out.append(ax.text(X / L + side * 0.09, T / L, impact_name(impact.label, math_text=True),
                                   fontsize=fs["impact"], va="center", ha="right" if side < 0 else "left", zorder=6,
                                   gid=f"{letter}-impact-label-{impact.label}"))
        return out


STRIP, FRONTS, CONTACTS, TURNS, PIVOTS = Strip(), Fronts(), Contacts(), Turns(), Pivots()
HORIZON, LIGHT, CLOCKS, PARTICLES, IMPACTS = Horizon(), Light(), Clocks(), Particles(), Impacts()
FORCES = Forces()
#: the drawing order (zorders decide what covers what; this order breaks ties)
DRAW: tuple[RodLayer, ...] = (STRIP, FRONTS, CONTACTS, TURNS, PIVOTS, HORIZON, LIGHT, CLOCKS, PARTICLES, IMPACTS,
                              FORCES)
#: the key's order: the material points' clocks, what the run's own model shows, the turns' pieces
KEY: tuple[RodLayer, ...] = (CLOCKS, FRONTS, CONTACTS, STRIP, TURNS, LIGHT, PIVOTS, HORIZON, FORCES)
