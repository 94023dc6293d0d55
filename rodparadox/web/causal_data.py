"""What the html page embeds for the causal rod (docs/html.md, "One page to explore" and "The causal rod"). Pure.

The page needs thousands of points per speed: it reads the engine's invariants from their tables
(`physics.causal.tables.ChartTables`, Chebyshev pieces to `tables.TABLE_TOLERANCE` L), evaluated for whole
arrays at once.

From the tables, in S (units of L): the world-lines of the ends, the particles and the material points, sampled
adaptively to a tolerance as the rigid rod's are, each point with its rapidity; the light fronts as their two end
points (a front is a light line: boosting its ends is exact); the world-sheet's cells of compression, bounded by
light lines u, w = const (`render.shading`, as the figures'), given by their edges' chart coordinates and a(u),
b(w) there (a boost of rapidity f scales t + x by e^-f and t - x by e^f: the page scales the edges, exact) with r+
and r- at each cell's centre (lam = exp(-(r+ + r-)/2)); and the ledger on a grid of frames and instants: each
particle's (E, p), the rod's matter and stress parts (`Fronts.rod_parts_on_slices`, the ledger's and the ledger
figure's integral), every slice of a speed at once.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from rodparadox.errors import BeyondBounds, ScenarioError
from rodparadox.render.shading import FRONT_JUMP, SHADES, cell_edges

#: the page's bound on the cells of compression of one family (every preset needs a tenth); the tables', lines'
#: and sums' bounds are `causal.tables`' and `causal.parts`'. A speed that would need more is left out of the page
#: (`TooCostly`), so that a page's cost is bounded whatever v, L and the masses
MAX_EDGES = 6000


class TooCostly(BeyondBounds):
    """The causal rod at one speed would need more than the page's bounds (`tables.MAX_PIECES`, ...,
    `MAX_EDGES`) to draw."""

    def __init__(self, what: str, v: float | None = None):
        at = "" if v is None else f" at v = {v:.10g}"
        ScenarioError.__init__(self, f"the page would need more than {what} to show the causal rod{at}; choose a "
                                     f"lower v, or --rod rigid.")
        self.what = what


# --- the page's data ----------------------------------------------------------------------------------------------

def drawn(value: float, digits: int) -> float:
    """As `data.drawn`: `digits` significant digits, never -0."""
    return float(f"{value:.{digits}g}") + 0.0


def line(tables, X: float, T0: float, T_hi: float, tolerance: float, digits: int) -> dict[str, Any]:
    """Points of material line X in S (units of L) from chart time T0 on, to T_hi: after the last separation the
    line repeats, each period 2L of chart time advancing every point by the same (dx, dt) (`period`), so only one
    period is given, from the point `repeat_from`, and `repeats` copies of it reach T_hi (the page translates
    them: exact for points). No rapidities: the page colours the causal rod from its cells."""
    sol, L = tables.history.solution, tables.L
    T_star = max(sol.plus.tail_start - X, sol.minus.tail_start + X, T0)
    period = sol.plus.period
    head = tables.sample(X, T0, T_star, tolerance) if T_star > T0 else None
    tail = tables.sample(X, T_star, T_star + period, tolerance)
    x = np.concatenate([head[1][:-1], tail[1]]) if head is not None else tail[1]
    t = np.concatenate([head[2][:-1], tail[2]]) if head is not None else tail[2]
    advance = period_advance(tables)
    return {"x": [drawn(v / L, digits) for v in x], "t": [drawn(v / L, digits) for v in t],
            "repeat_from": len(x) - len(tail[1]), "repeats": max(0, math.ceil((T_hi - T_star) / period) - 1),
            "period": [drawn(advance[0] / L, 15), drawn(advance[1] / L, 15)], "before": 0.0, "after": 0.0}


def period_advance(tables) -> tuple[float, float]:
    """(dx, dt) of every material point over one period of chart time after the last separation."""
    g_plus, g_minus = tables.plus.gain, tables.minus.gain
    return 0.5 * (g_plus - g_minus), 0.5 * (g_plus + g_minus)


def worldlines(history, tables, T_hi: float, tolerance: float, digits: int) -> dict[str, Any]:
    """The ends and the particles in S: at rest, then each on its chart curves (a particle free between them)."""
    L, out = history.scenario.L, {}
    for name in ("rod_left", "rod_right"):
        X = 0.0 if name == "rod_left" else L
        out[name] = line(tables, X, history.worldline(name).segments[0].T_start, T_hi, tolerance, digits)
    for name in ("A", "B"):
        w = history.worldline(name)
        if w is None:
            continue
        xs, ts = [w.first.x / L], [w.first.t / L]
        for segment in w.segments:
            if hasattr(segment, "chart"):
                _, x, t, _ = tables.sample(segment.X, segment.T_start, segment.T_end, tolerance)
                xs, ts = xs + list(x[1:] / L), ts + list(t[1:] / L)
            else:
                xs.append(segment.end.x / L), ts.append(segment.end.t / L)
        out[name] = {"x": [drawn(v, digits) for v in xs], "t": [drawn(v, digits) for v in ts],
                     "before": w.rapidity_before + 0.0, "after": w.rapidity_after + 0.0}
    return out


def fronts(history, tables, lo: float, hi: float) -> list[list[float]]:
    """Each light front in chart times [lo, hi] as [x, t] of its ends on the left and right end, in S (units of L)."""
    sol, L = history.solution, history.scenario.L
    out = []
    for family, invariant in (("+", sol.plus), ("-", sol.minus)):
        for s in invariant.breaks(lo, hi + L):
            if abs(invariant.r(s) - invariant.r(np.nextafter(s, -math.inf))) <= FRONT_JUMP:
                continue
            T_right = s - L if family == "+" else s + L  # r+ jumps along u = T + X, r- along w = T - X
            xl, tl, _ = tables.point(0.0, np.array([s]))
            xr, tr, _ = tables.point(L, np.array([T_right]))
            out.append([drawn(v / L, 7) for v in (xl[0], tl[0], xr[0], tr[0])])
    return out


def _edges(table, lo: float, hi: float, L: float, step: float) -> np.ndarray:
    """The cells' edges on [lo, hi]: every break, and inside a piece where r varies cells no longer than CELL L
    and short enough that r changes by about `step` from one to the next (as the figures' shading)."""
    edges = cell_edges(table.r, [s for s in table.breaks if lo < s < hi], lo, hi, L, step, MAX_EDGES, vectorised=True)
    if edges is None:
        raise TooCostly(f"{MAX_EDGES} cells of compression along a light line")
    return edges


def cells(history, tables, lo: float, hi: float, compression: tuple[float, float]) -> dict[str, Any]:
    """The world-sheet's cells of compression between chart times lo and hi: edges u_i (w_j) with a(u_i) (b(w_j)),
    and r+ (r-) at each cell's middle; cell (i, j) is in the rod where 0 < u - w < 2L."""
    L = history.scenario.L
    step = 2 * (compression[1] - compression[0]) / SHADES
    us, ws = _edges(tables.plus, lo, hi + 2 * L, L, step), _edges(tables.minus, lo - 2 * L, hi, L, step)
    return {"u": [drawn(v / L, 6) for v in us], "a": [drawn(v / L, 6) for v in tables.plus.m(us)],
            "r_plus": [drawn(v, 3) for v in tables.plus.r(0.5 * (us[1:] + us[:-1]))],
            "w": [drawn(v / L, 6) for v in ws], "b": [drawn(v / L, 6) for v in tables.minus.m(ws)],
            "r_minus": [drawn(v, 3) for v in tables.minus.r(0.5 * (ws[1:] + ws[:-1]))],
            "ln_lam": [compression[0], compression[1]]}


def ledger_sums(history, tables, f: np.ndarray, t: np.ndarray) -> dict[str, np.ndarray]:
    """On each slice (f[k], t[k]): each particle's (E, p), the rod's matter and stress (E, p) (arrays, M = 1):
    `Fronts.rod_parts_on_slices`."""
    L = history.scenario.L
    T_L, T_R = tables.end_chart_times(0.0, f, t), tables.end_chart_times(L, f, t)
    matter, stress = history.fronts.rod_parts_on_slices(f, t)
    sums = {"matter_E": matter[:, 0], "matter_p": matter[:, 1], "stress_E": stress[:, 0], "stress_p": stress[:, 1]}
    sums.update(particles(history, tables, f, t, T_L, T_R))
    return sums


def particles(history, tables, f: np.ndarray, t: np.ndarray, T_L, T_R) -> dict[str, np.ndarray]:
    """Each particle's (E, p) on the slices: free at its rapidity between contacts; in contact, the end's."""
    L, out = history.scenario.L, {}
    for name in ("A", "B"):
        w = history.worldline(name)
        if w is None:
            continue
        mass = history.scenario.particle(name).mass
        mine = [i for i in history.impacts if i.particle == name]
        theta = np.full_like(t, w.rapidity_before) - f
        for contact, separation in zip(mine[::2], mine[1::2]):
            t0 = np.cosh(f) * contact.event.t - np.sinh(f) * contact.event.x
            t1 = np.cosh(f) * separation.event.t - np.sinh(f) * separation.event.x
            X, T = (0.0, T_L) if contact.end == "left" else (L, T_R)
            riding = (t >= t0) & (t < t1)
            theta = np.where(riding, tables.point(X, T, 0.0)[2] - f, theta)
            theta = np.where(t >= t1, separation.particle_rapidity_after - f, theta)
        out[f"{name}_E"], out[f"{name}_p"] = mass * np.cosh(theta), mass * np.sinh(theta)
    return out


# --- one speed --------------------------------------------------------------------------------------------------

#: the causal rod's material lines drawn in the diagram (the ends besides): at X = L/4, L/2, 3L/4
MATERIAL_LINES = 4


def model_data(history, v: float, frames, reach: float, window, tolerance: float, material_tolerance: float,
               digits: int, material_digits: int, instants: int, table_rows, fixed) -> dict[str, Any]:
    """The causal rod at one speed: what the page draws and prints (the module's docstring). `frames`: the
    ledger's frames in the rigid rod's order (S', S, the others); `window(rapidities)`: each frame's time window
    (`windows.Changes.windows`). Raises `TooCostly` past the page's bounds."""
    try:
        return _model_data(history, v, frames, reach, window, tolerance, material_tolerance, digits, material_digits,
                           instants, table_rows, fixed)
    except BeyondBounds as e:
        raise TooCostly(e.what, v) from None


def _model_data(history, v: float, frames, reach: float, window, tolerance: float, material_tolerance: float,
                digits: int, material_digits: int, instants: int, table_rows, fixed) -> dict[str, Any]:
    from rodparadox.numbers import impact_name
    from rodparadox.tables.causal_ledger import event_name

    s, L = history.scenario, history.scenario.L
    sol = history.solution
    impacts = [{"label": i.label, "name": event_name(i.label), "row": impact_name(i.label), "kind": i.kind,
                "particle": i.particle, "end": i.end, "x": i.event.x / L, "t": i.event.t / L,
                "particle_before": i.particle_rapidity_before, "particle_after": i.particle_rapidity_after,
                "rod_before": i.rod_rapidity_before, "rod_after": i.rod_rapidity_after, "simultaneous_with": None}
               for i in history.impacts]
    # the chart times every frame of the page reaches: tables over all of them (the ringing tail costs nothing)
    T_first = min(sol.plus.starts[0], sol.minus.starts[0])
    top = max(sol.plus.tail_start, sol.minus.tail_start)
    tables = history.fronts.chart_tables(T_first - 2 * L, top + 60 * L)
    speeds_ = np.concatenate([np.linspace(-reach, reach, 21), [-v]])
    f = np.arctanh(speeds_)
    spans = window(f)
    ends = [tables.end_chart_times(X, np.concatenate([f, f]), np.concatenate([spans[:, 0], spans[:, 1]]))
            for X in (0.0, L)]
    T_lo, T_hi = min(e.min() for e in ends) - 0.5 * L, max(e.max() for e in ends) + 0.5 * L
    lines = worldlines(history, tables, T_hi, tolerance, digits)
    material = []
    for k in range(1, MATERIAL_LINES):
        X = L * k / MATERIAL_LINES
        T0 = history.material_worldline(X).segments[0].T_start
        material.append(line(tables, X, T0, T_hi, material_tolerance, material_digits))
    compression = history.fronts.compression_range()
    bound = max(abs(r) for r in history.rapidity_range())
    # the ledger: every frame's instants at once
    rapidities = np.array([fr.rapidity for fr in frames])
    spans = window(rapidities)
    fraction = np.linspace(0.0, 1.0, instants)
    ff = np.repeat(rapidities, instants)
    tt = (spans[:, 0][:, None] + (spans[:, 1] - spans[:, 0])[:, None] * fraction[None, :]).ravel()
    ledger = []
    if history.driving is not None:  # what each agent delivered, the rod's two parts, their sum, the check
        from rodparadox.physics.types import EnergyMomentum
        from rodparadox.web import forces_data

        matter, stress = history.fronts.rod_parts_on_slices(ff, tt)
        d, T_L, T_R = history.driving, tables.end_chart_times(0.0, ff, tt), tables.end_chart_times(L, ff, tt)
        rows = [forces_data.ledger_slice(history, f_, t_, (EnergyMomentum(0.0, *m), EnergyMomentum(0.0, *p)),
                                         (d.delivered_at("left", f_, TL), d.delivered_at("right", f_, TR)))
                for f_, t_, m, p, TL, TR in zip(ff, tt, matter, stress, T_L, T_R)]
        names = list(forces_data.ledger_rows(history))
    else:
        sums = ledger_sums(history, tables, ff, tt)
        bodies = [n for n in ("A", "B") if f"{n}_E" in sums] + ["matter", "stress"]
        rows = [[sums[f"{name}_{part}"][k] for name in bodies for part in ("E", "p")] for k in range(len(tt))]
        rows = [row + [math.fsum(row[0::2]), math.fsum(row[1::2])] for row in rows]
        names = [f"particle {n}" if n in ("A", "B") else f"rod, {n}" for n in bodies] + ["total"]
    for j, frame in enumerate(frames):
        # the slices evenly spread over the window: the page reads slice k's time from the window, as it is built
        ledger.append({"u": frame.velocity + 0.0, "rows": names,
                       "slices": [[fixed(n) for n in row] for row in rows[j * instants:(j + 1) * instants]],
                       "window": [spans[j, 0] / L, spans[j, 1] / L]})
    return {
        "model": "causal", "impacts": impacts, "worldlines": lines, "material": material,
        "colour_bound": bound,
        "tables": {"rest": table_rows(history, frames[1]), "moving": table_rows(history, frames[0])},
        "ledger": ledger, "fronts": fronts(history, tables, T_lo, T_hi),
        "cells": cells(history, tables, T_lo, T_hi, compression),
        "final": history.final_rapidity,
        "end_events": lambda end, f, times: end_events(tables, end, f, times),  # the page's bands, if driven
    }


def end_events(tables, end: str, f: float, times) -> tuple[np.ndarray, np.ndarray]:
    """Where an end is in S (units of L) when the frame of rapidity f reads the times (units of L) there."""
    L, X = tables.L, 0.0 if end == "left" else tables.L
    T = tables.end_chart_times(X, np.full(len(times), f), np.asarray(times) * L)
    x, t, _ = tables.point(X, T)
    return x / L, t / L
