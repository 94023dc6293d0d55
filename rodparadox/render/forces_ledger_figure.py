"""The ledger figure of a rod driven by forces at its ends (docs/model.md, "Forces at the ends"). Never pyplot, never
files.

One column per frame, momentum above energy against that frame's own time, as the ledger figure of a struck rod
(`ledger_figure`): what each agent delivered up to the slice's end events (dashed and dash-dotted, in the inks of
particles A and B: the left agent and the right one), the rod's kinetic part (rigid) or matter part (causal) as a solid
line, its stress part shaded between that line and the rod's whole (E, p) (thick): for the rigid rod the hidden part,
hatched the other way for the causal rod, as their ledgers with particles shade them. A thin dotted line is the rod's
(E, p) before any force; open circles on the thick line are the rod's (E, p) before the forces plus what both agents
delivered, on the ledger table's slices (`tables.forces_ledger.slice_times`): where they sit on the thick line, the
conservation law with forces holds. Each force's start and end is a thin vertical line, named above the panel (on,
off; left on, right off where only one end's force starts or ends there). With two histories the rigid rod's rows
sit above the causal rod's, each frame's panels over one time window and on one scale of E and of p.
"""

from __future__ import annotations

from typing import Sequence

import numpy as np
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

from rodparadox.physics.frames import Frame, PANEL_LETTERS, time_window
from rodparadox.render import style_context
from rodparadox.render.ledger_figure import STRESS_TEXT, hidden_fill, kinetic_ink, rod_rows, stress_fill, total_ink
from rodparadox.render.styles import Style
from rodparadox.tables.forces_ledger import slice_times

#: slices of a frame's window the curves are drawn through (each force's start, peak and end added)
SLICES = 160
#: force events closer than this (in units of L + |t|) in a frame's time are one instant there (to rounding)
SAME = 1e-9
#: the inks of the left and the right agent: those of particles A and B, which strike the left and the right end
AGENT_INKS = {"left": "A", "right": "B"}


def series(history, frame: Frame, window: tuple[float, float] | None = None):
    """Times (the window's slices and every force event's instant), and for E and p the curves: what each agent
    delivered ("left", "right"), the rod's two parts ("part": kinetic or matter, "stress"), its whole ("rod"); the
    slices of the ledger table with the rod's (E, p) before the forces plus what was delivered there."""
    f = frame.rapidity
    d = history.driving
    lo, hi = window or time_window(history, frame)
    marks = [e.event.time_in(f) for e in d.force_events()]
    times = np.unique(np.concatenate([np.linspace(lo, hi, SLICES), [t for t in marks if lo <= t <= hi]]))
    if history.fronts is not None:  # every slice at once
        part, stress = history.fronts.rod_parts_on_slices(f, times)
    else:
        pairs = [history.rod_parts(f, t) for t in times]
        part = np.array([[k.E, k.p] for k, _ in pairs])
        stress = np.array([[s.E, s.p] for _, s in pairs])
    delivered = {end: np.array([[em.E, em.p] for em in (d.delivered(end, f, t) for t in times)])
                 for end in ("left", "right")}
    checks = np.array(slice_times(history, frame))
    checks = checks[(checks >= lo) & (checks <= hi)]
    initial = history.initial_total(f)
    check = np.array([[em.E, em.p] for em in (d.total(f, t) for t in checks)])
    values = {}
    for k, q in enumerate(("E", "p")):
        values[q] = {"left": delivered["left"][:, k], "right": delivered["right"][:, k], "part": part[:, k],
                     "stress": stress[:, k], "rod": part[:, k] + stress[:, k],
                     "initial": initial.E if q == "E" else initial.p}
    return times, values, (checks, {"E": check[:, 0], "p": check[:, 1]})


def events(history, frame: Frame) -> list[tuple[str, str, float]]:
    """(name, kind, t) of each instant a force starts or ends in the frame's time, in order: "on" or "off" where both
    ends' forces start or end at it, else "left on", "right off", ... ."""
    L = history.scenario.L
    found = sorted((e.event.time_in(frame.rapidity), e.moment, e.end) for e in history.driving.force_events()
                   if e.moment in ("start", "end"))
    groups: list[list] = []
    for t, moment, end in found:
        if groups and t - groups[-1][0][0] <= SAME * (L + abs(t)) and groups[-1][0][1] == moment:
            groups[-1].append((t, moment, end))
        else:
            groups.append([(t, moment, end)])
    out = []
    for group in groups:
        word = {"start": "on", "end": "off"}[group[0][1]]
        ends = {end for _, _, end in group}
        name = word if len(ends) == 2 else f"{group[0][2]} {word}"
        out.append((name, "force", group[0][0]))
    return out


def draw(histories: Sequence, frames: Sequence[Frame], style: str = "default") -> Figure:
    """The ledger figure of one driven rod, or of two (the rigid rod's rows above the causal rod's)."""
    limit = len(PANEL_LETTERS) // len(histories)
    if not 1 <= len(frames) <= limit:
        raise ValueError(f"the ledger figure takes 1 to {limit} frames, got {len(frames)}")
    with style_context(style) as st:
        return _draw(tuple(histories), tuple(frames), st)


def _curves(ax, q: str, letter: str, t: np.ndarray, values, checks, causal: bool, marks, L: float, st: Style) -> None:
    v = values[q]
    fill = stress_fill(st) if causal else hidden_fill(st)
    ax.fill_between(t, v["part"], v["rod"], gid=f"{letter}-{q}-stress", zorder=1, **fill)
    ax.axhline(v["initial"], gid=f"{letter}-{q}-initial", zorder=2, **total_ink(st))
    for end in ("left", "right"):
        ink = st.ledger_particles[AGENT_INKS[end]]
        ax.plot(t, v[end], color=ink.colour, linewidth=ink.width, linestyle=ink.dashes, gid=f"{letter}-{q}-{end}",
                zorder=3)
    ax.plot(t, v["part"], color=st.rod.colour, linewidth=st.rod.width, gid=f"{letter}-{q}-rod_part", zorder=3)
    ax.plot(t, v["rod"], gid=f"{letter}-{q}-rod", zorder=4, **kinetic_ink(st))
    at, check = checks
    ax.plot(at / L, check[q], linestyle="none", marker="o", markersize=st.font_size * 0.55, markerfacecolor="white",
            markeredgecolor="#000000", markeredgewidth=0.8, gid=f"{letter}-{q}-check", zorder=5)
    for name, _, te in marks:
        ax.axvline(te / L, color="#9a9a9a", linewidth=0.6, zorder=0, gid=f"{letter}-{q}-event-{name.replace(' ', '_')}")


def _draw(histories: tuple, frames: tuple[Frame, ...], st: Style) -> Figure:
    """Laid out as the ledger figure of a struck rod (`ledger_figure.rod_rows`)."""
    def panel(history, frame, window):
        times, values, checks = series(history, frame, window)
        marks = events(history, frame)
        causal, L = history.fronts is not None, history.scenario.L

        def curves(ax, q: str, letter: str, t: np.ndarray) -> None:
            _curves(ax, q, letter, t, values, checks, causal, marks, L, st)
        return times, marks, curves

    return rod_rows(histories, frames, st, _legend(histories, st), panel)


def _legend(histories: tuple, st: Style) -> tuple[list, list[str]]:
    inks = st.ledger_particles
    handles = [Line2D([], [], color=inks[AGENT_INKS[end]].colour, linewidth=inks[AGENT_INKS[end]].width,
                      linestyle=inks[AGENT_INKS[end]].dashes) for end in ("left", "right")]
    labels = ["delivered by the force on the left end", "delivered by the force on the right end"]
    rod = Line2D([], [], color=st.rod.colour, linewidth=st.rod.width)
    whole = Line2D([], [], **kinetic_ink(st))
    before = Line2D([], [], **total_ink(st))
    check = Line2D([], [], linestyle="none", marker="o", markersize=st.font_size * 0.55, markerfacecolor="white",
                   markeredgecolor="#000000", markeredgewidth=0.8)
    causal = [h.fronts is not None for h in histories]
    if len(histories) == 2:
        handles += [rod, whole, Patch(**hidden_fill(st)), Patch(**stress_fill(st))]
        labels += ["rod: kinetic (rigid), matter (causal)", "rod: its whole energy and momentum",
                   "rigid rod: hidden = stress = whole − kinetic", STRESS_TEXT]
    elif causal[0]:
        handles += [rod, whole, Patch(**stress_fill(st))]
        labels += ["rod, matter (its rest-frame energy moving with it)", "rod: its whole energy and momentum",
                   STRESS_TEXT]
    else:
        handles += [rod, whole, Patch(**hidden_fill(st))]
        labels += ["rod (kinetic)", "rod: its whole energy and momentum", "hidden = stress = whole − kinetic"]
    handles += [before, check]
    labels += ["rod before the forces", "before the forces + delivered"]
    return handles, labels
