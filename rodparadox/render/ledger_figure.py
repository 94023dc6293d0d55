"""The ledger as a figure: momentum and energy against each frame's time (the docs, "Energy and
momentum"). Never pyplot, never files.

One column per frame: momentum above, energy below, against that frame's
own time. Each body's kinetic part (particles dashed, the rod solid), the
kinetic total (thick), the system's total before the first impact (thin,
constant) and between the two the hidden part, shaded. Every impact is a
thin vertical line labelled as in `plot` (B₁, A₁, ...). Same styles,
determinism and gids as `render`.

The causal rod (docs/model.md, "The causal rod") has nothing hidden: its (E, p) is split into its matter part (a solid
line, as the rigid rod's kinetic part) and its stress part, shaded between the particles plus matter and the
total: its pressure's share (von Laue's momentum of a stressed body), drawn where the rigid figure shades the hidden
part, though the two are not the same quantity. Its events are contacts and separations (B₁, A′₁), labelled above the panel on two tiers where close.
With two histories (`draw_both`) the rigid rod's rows sit above the causal rod's, each frame's panels on one
time axis and one scale of E and of p.
"""

from __future__ import annotations

from typing import Sequence

import numpy as np
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch
from matplotlib.ticker import FuncFormatter

from rodparadox.physics.history import RodHistory
from rodparadox.physics.frames import Frame, PANEL_LETTERS, time_window
from rodparadox.physics.types import ZERO
from rodparadox.physics.ledger import impact_entries
from rodparadox.io.ledger_report import slice_times
from rodparadox.tables.causal_ledger import event_name, instants
from rodparadox.numbers import impact_name, shown
from rodparadox.render import axis_label, coordinate_names, frame_symbol, style_context
from rodparadox.render.styles import Style
from rodparadox.render.text import note_lines, suptitle
from rodparadox.tables.comparison import comparison_note
from rodparadox.tolerances import SAME_INSTANT


def _series(history: RodHistory, frame: Frame, window: tuple[float, float] | None = None):
    """Times and values of every curve, with each impact's instant twice (just before, then just after), so the
    curves jump where a particle is struck instead of sloping across the instant; over `window` if given (the
    frame's own window: `slice_times`)."""
    eta = frame.rapidity
    names = sorted(p.name for p in history.scenario.particles)
    entries = impact_entries(history, eta)
    scale = history.scenario.L
    times, rows = [], []
    dense = slice_times(history, frame)
    if window is not None:  # the same sampling, stretched over the window (the turns' ends and impacts kept)
        lo, hi = time_window(history, frame)
        dense = sorted({*(t for t in dense if lo < t < hi), *np.linspace(*window, len(dense))})
    for t in dense:
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


#: slices of a frame's window the causal rod's curves are drawn through (each event's instant added)
CAUSAL_SLICES = 200


def causal_series(history, frame: Frame, window: tuple[float, float] | None = None):
    """The causal rod's curves: times (the window's slices and every contact's and separation's instant), and for
    E and p each particle's, the rod's matter and stress parts (`Fronts.rod_parts_on_slices`), and
    the particles plus matter; with the events (label, kind, t) in the frame's time order."""

    lo, hi = window or time_window(history, frame)
    events = [(label, kind, t) for label, kind, t, _ in instants(history, frame)]
    times = np.unique(np.concatenate([np.linspace(lo, hi, CAUSAL_SLICES), [t for *_, t in events]]))
    eta = frame.rapidity
    names = sorted(p.name for p in history.scenario.particles)
    matter, stress = history.fronts.rod_parts_on_slices(eta, times)
    particles = {n: [history.particle_energy_momentum(n, eta, t) for t in times] for n in names}
    values = {}
    for k, q in enumerate(("E", "p")):
        curves = {n: np.array([getattr(em, q) for em in particles[n]]) for n in names}
        curves["rod_matter"], curves["rod_stress"] = matter[:, k], stress[:, k]
        curves["matter_total"] = sum(curves[n] for n in names) + matter[:, k]
        values[q] = curves
    return times, values, events


def draw(history: RodHistory, frames: Sequence[Frame], style: str = "default") -> Figure:
    """The ledger figure: one column per frame (at most eight), momentum above energy; the causal rod's with its
    matter and stress parts."""
    if not 1 <= len(frames) <= len(PANEL_LETTERS):
        raise ValueError(f"the ledger figure takes 1 to {len(PANEL_LETTERS)} frames, got {len(frames)}")
    with style_context(style) as st:
        if history.fronts is not None:
            return _draw_rods((history,), tuple(frames), st)
        return _draw(history, tuple(frames), st)


def draw_both(rigid: RodHistory, causal, frames: Sequence[Frame], style: str = "default") -> Figure:
    """The two rods' ledgers in one figure (`ledger --rod both`): the rigid rod's rows above the causal rod's, each
    frame's panels over one time window (the union of the two) and on one scale of E and of p."""
    if not 1 <= len(frames) <= len(PANEL_LETTERS) // 2:
        raise ValueError(f"the ledger figure of both rods takes 1 to {len(PANEL_LETTERS) // 2} frames, "
                         f"got {len(frames)}")
    with style_context(style) as st:
        return _draw_rods((rigid, causal), tuple(frames), st)


def _draw(history: RodHistory, frames: tuple[Frame, ...], st: Style) -> Figure:
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
    figure.text(0.5, 1 - 4 / height, suptitle(s, width, fs * 1.25, ": energy and momentum"), ha="center", va="top",
                fontsize=fs * 1.25, gid="title")
    L = s.L
    names = sorted(p.name for p in s.particles)
    particle_inks = dict(st.ledger_particles)
    hidden, total_line, kinetic_line = hidden_fill(st), total_ink(st), kinetic_ink(st)
    for k, frame in enumerate(frames):
        letter = PANEL_LETTERS[k]
        r, c = divmod(k, per_row)
        times, values, entries = _series(history, frame)
        total = history.initial_total(frame.rapidity)
        t = times / L
        x0 = gutter + c * (column_w + gutter + 14)
        y_top = height - suptitle_h - r * row_h - title_h
        for q, ax in pair_axes(figure, letter, x0, y_top, column_w, panel_h, pair_gap):
            level = total.p if q == "p" else total.E
            _rigid_curves(ax, q, letter, t, values, level, entries, L, st)
            ax.set_xlim(t[0], t[-1])
            axis_words(ax, q, frame, fs)
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
    handles = [Line2D([], [], color=particle_inks[n].colour, linewidth=particle_inks[n].width,
                      linestyle=particle_inks[n].dashes) for n in names]
    labels = [f"particle {n}" for n in names]
    handles += [Line2D([], [], color=st.rod.colour, linewidth=st.rod.width), Line2D([], [], **kinetic_line),
                Line2D([], [], **total_line), Patch(**hidden)]
    labels += ["rod (kinetic)", "kinetic total", "total before the first impact", "hidden = total − kinetic"]
    legend = figure.legend(handles, labels, loc="lower center", bbox_to_anchor=(0.5, 4 / height), ncol=3,
                           fontsize=fs, handlelength=2.8, columnspacing=1.4, borderaxespad=0.0)
    legend.set_gid("legend")
    return figure


def pair_axes(figure: Figure, letter: str, x0: float, y_top: float, width: float, panel_h: float, gap: float):
    """One frame's p panel above its E panel, on one time axis, `width` x `panel_h` points each from (x0, y_top)
    down: (q, axes) each in turn, the next made only when the caller has drawn into the last."""
    W, H = figure.get_size_inches() * 72
    top = None
    for q, row in (("p", 0), ("E", 1)):
        y0 = y_top - (row + 1) * panel_h - row * gap
        ax = figure.add_axes((x0 / W, y0 / H, width / W, panel_h / H), sharex=top)
        top = top or ax
        ax.set_gid(f"{letter}-{q}-axes")
        yield q, ax


def axis_words(ax, q: str, frame, fs: float) -> None:
    """A ledger panel's numbers (as every figure writes them: no offsets, no 1e-06) and its axes' names: p above,
    E below with the frame's time under it."""
    for axis in (ax.xaxis, ax.yaxis):
        axis.set_major_formatter(FuncFormatter(lambda value, _pos: shown(value, 6)))
    ax.tick_params(labelsize=fs)
    ax.set_ylabel("p / M c" if q == "p" else "E / M c²", fontsize=fs * 1.05)
    if q != "p":
        ax.set_xlabel(f"{axis_label(coordinate_names(frame)[1])}", fontsize=fs * 1.05)


def hidden_fill(st: Style) -> dict:
    return {"facecolor": st.sheet, "edgecolor": st.hidden_edge, "hatch": st.hidden_hatch, "linewidth": 0.0}


def total_ink(st: Style) -> dict:
    return {"color": "#000000", "linewidth": 0.7 * st.rod.width / 1.7, "linestyle": (0, (1.0, 1.5))}


def kinetic_ink(st: Style) -> dict:
    return {"color": "#000000", "linewidth": st.rod.width * 1.3}


def _rigid_curves(ax, q: str, letter: str, t: np.ndarray, values, level: float, entries, L: float, st: Style) -> None:
    """The rigid rod's curves in one panel: the hidden part shaded, the total, each body's kinetic part, the
    kinetic total, the impacts."""
    kinetic = values[q]["kinetic"]
    ax.fill_between(t, kinetic, np.full_like(kinetic, level), gid=f"{letter}-{q}-hidden", zorder=1, **hidden_fill(st))
    ax.axhline(level, gid=f"{letter}-{q}-total", zorder=2, **total_ink(st))
    for n in sorted(c for c in values[q] if c not in ("rod", "kinetic")):
        ink = st.ledger_particles[n]
        ax.plot(t, values[q][n], color=ink.colour, linewidth=ink.width, linestyle=ink.dashes,
                gid=f"{letter}-{q}-{n}", zorder=3)
    ax.plot(t, values[q]["rod"], color=st.rod.colour, linewidth=st.rod.width, gid=f"{letter}-{q}-rod", zorder=3)
    ax.plot(t, kinetic, gid=f"{letter}-{q}-kinetic", zorder=4, **kinetic_ink(st))
    for e in entries:
        ax.axvline(e.t / L, color="#9a9a9a", linewidth=0.6, zorder=0, gid=f"{letter}-{q}-impact-{e.impact.label}")


# --- the causal rod, alone or below the rigid one -----------------------------------------------------------------

#: the causal rod's stress part: hatched the other way from the rigid rod's hidden part, over a light tint
STRESS_HATCH = "\\\\\\\\"


def stress_fill(st: Style) -> dict:
    edge = st.hidden_edge if st.hidden_edge != "none" else st.rod.colour
    return {"facecolor": st.sheet, "edgecolor": edge, "hatch": STRESS_HATCH, "linewidth": 0.0}


def _causal_curves(ax, q: str, letter: str, t: np.ndarray, values, level: float, events, L: float, st: Style) -> None:
    """The causal rod's curves in one panel: its stress part shaded above the particles plus its matter, the
    total, each particle, the matter part, the particles plus matter, the contacts and separations."""
    below = values[q]["matter_total"]
    ax.fill_between(t, below, below + values[q]["rod_stress"], gid=f"{letter}-{q}-stress", zorder=1, **stress_fill(st))
    ax.axhline(level, gid=f"{letter}-{q}-total", zorder=2, **total_ink(st))
    for n in sorted(c for c in values[q] if not c.startswith(("rod_", "matter_"))):
        ink = st.ledger_particles[n]
        ax.plot(t, values[q][n], color=ink.colour, linewidth=ink.width, linestyle=ink.dashes,
                gid=f"{letter}-{q}-{n}", zorder=3)
    ax.plot(t, values[q]["rod_matter"], color=st.rod.colour, linewidth=st.rod.width, gid=f"{letter}-{q}-rod_matter",
            zorder=3)
    ax.plot(t, below, gid=f"{letter}-{q}-matter_total", zorder=4, **kinetic_ink(st))
    for label, _, te in events:
        ax.axvline(te / L, color="#9a9a9a", linewidth=0.6, zorder=0, gid=f"{letter}-{q}-event-{label}")


def event_labels(ax, events, L: float, fs: float, points_per_unit: float, letter: str) -> None:
    """The contacts' and separations' names above the panel, each over its line or as near as the names before
    it allow, on the lower tier or, where that would push a name farther, the upper one."""
    ends = [-np.inf, -np.inf]  # where each tier's last name ends, points from the panel's left
    for label, _, t in events:
        name = event_name(label)
        w = len(name) * fs * 0.62 + 2
        want = t / L * points_per_unit
        at = [max(want, end + w / 2) for end in ends]
        tier = 0 if at[0] - want <= max(at[1] - want, 0.0) + 0.5 else 1
        ends[tier] = at[tier] + w / 2
        # a name pushed off its line (by more than a point) is tied to the line's top by a thin leader, so it is
        # never read as an event where it stands; leaders under the names, each name on a white ground, so a leader
        # passes behind a name it crosses
        offset = (at[tier] - want, 2 + tier * fs * 1.3)
        if at[tier] - want > 1.0:
            ax.annotate("", (t / L, 1.0), xycoords=("data", "axes fraction"), xytext=offset, textcoords="offset points",
                        arrowprops={"arrowstyle": "-", "linewidth": 0.5, "color": "0.35", "shrinkA": 0.0, "shrinkB": 0.0},
                        zorder=5, gid=f"{letter}-leader-{label}")
        ax.annotate(name, (t / L, 1.0), xycoords=("data", "axes fraction"), xytext=offset, textcoords="offset points",
                    ha="center", va="bottom", fontsize=fs, gid=f"{letter}-label-{label}", zorder=6, style="italic",
                    bbox={"facecolor": "white", "edgecolor": "none", "pad": 0.6})


def _draw_rods(histories: tuple, frames: tuple[Frame, ...], st: Style) -> Figure:
    """The causal rod's ledger figure, or (two histories) the rigid rod's rows above the causal rod's."""
    both = len(histories) == 2

    def panel(history, frame, window):
        causal = history.fronts is not None
        window = window if both else None
        if causal:
            times, values, events = causal_series(history, frame, window)
            entries = ()
        else:
            times, values, entries = _series(history, frame, window)
            events = [(e.impact.label, "impact", e.t) for e in entries]
        total = history.initial_total(frame.rapidity)
        L = history.scenario.L

        def curves(ax, q: str, letter: str, t: np.ndarray) -> None:
            level = total.p if q == "p" else total.E
            if causal:
                _causal_curves(ax, q, letter, t, values, level, events, L, st)
            else:
                _rigid_curves(ax, q, letter, t, values, level, entries, L, st)
        return times, events, curves

    return rod_rows(histories, frames, st, _rods_legend(histories, st), panel)


def rod_rows(histories: tuple, frames: tuple[Frame, ...], st: Style, legend: tuple[list, list[str]], panel) -> Figure:
    """The ledger figure of one rod or (two histories) the rigid rod's rows above the causal rod's, laid out in
    points from the type size: per frame a p panel above an E panel, the events named above them, each frame's
    panels of both rods on one scale, the legend (`legend`: handles and labels) and, for two rods, the comparison's
    note. `panel(history, frame, window)` gives a panel pair's times, its events ((name, kind, t)) and a function
    `curves(ax, q, letter, t)` that draws its curves (t in units of L); `window`: the frame's time window over
    every rod shown."""
    fs = st.font_size
    per_row = min(len(frames), 3 if st.max_width >= 10 else 2)
    rows = -(-len(frames) // per_row)
    gutter = fs * 1.05 * 1.4 + 3.4 * fs + 12
    suptitle_h, pair_gap = fs * 1.25 * 1.6, 6.0
    title_h = fs * 1.1 * 1.6 + fs * 1.5 + 4 + fs * 1.3  # a second tier of event names
    x_axis_h = 3.5 + 3.5 + fs * 1.25 + fs * 1.05 * 1.35 + 4
    both = len(histories) == 2
    handles, labels = legend
    columns = 2
    legend_h = (-(-len(labels) // columns) + 1) * fs * 1.8 + 8  # a row more: the stress's words take two lines
    width = st.max_width * 72
    column_w = (width - 10 - per_row * gutter - (per_row - 1) * 14) / per_row
    panel_h = st.panel_height * 72 * 0.6
    row_h = title_h + 2 * panel_h + pair_gap + x_axis_h
    # a comparison says first what both rods are struck by, and where their first impacts fall
    note = note_lines(comparison_note(histories, frames), width - 20, fs) if both else []
    note_h = len(note) * 1.2 * fs + 10 if note else 0.0
    height = suptitle_h + len(histories) * rows * row_h + legend_h + note_h
    figure = Figure(figsize=(width / 72, height / 72), dpi=72)
    if note:
        figure.text(10 / width, (note_h - 4) / height, "\n".join(note), ha="left", va="top", fontsize=fs,
                    linespacing=1.2, gid="comparison-note")
    s = histories[-1].scenario
    figure.text(0.5, 1 - 4 / height, suptitle(s, width, fs * 1.25, ": energy and momentum"), ha="center",
                va="top", fontsize=fs * 1.25, gid="title")
    L = s.L
    windows = [(min(time_window(h, f)[0] for h in histories), max(time_window(h, f)[1] for h in histories))
               for f in frames]
    shared: dict = {}  # (frame, q) -> the panels that share a scale
    for b, history in enumerate(histories):
        for k, frame in enumerate(frames):
            letter = PANEL_LETTERS[b * len(frames) + k]
            r, c = divmod(k, per_row)
            r += b * rows
            times, events, curves = panel(history, frame, windows[k])
            t = times / L
            x0 = gutter + c * (column_w + gutter + 14)
            y_top = height - suptitle_h - r * row_h - title_h
            for q, ax in pair_axes(figure, letter, x0, y_top, column_w, panel_h, pair_gap):
                curves(ax, q, letter, t)
                ax.set_xlim(t[0], t[-1])
                shared.setdefault((k, q), []).append(ax)
                axis_words(ax, q, frame, fs)
                if q == "p":
                    model = f"{history.model} rod, " if both else ""
                    ax.set_title(f"({letter}) {model}frame {frame_symbol(frame)}", fontsize=fs * 1.1,
                                 pad=fs * 2.8 + 4)
                    ax.tick_params(labelbottom=False)
                    event_labels(ax, events, L, fs, column_w / (t[-1] - t[0]), letter)
    for axes in shared.values():  # the two rods' panels of one frame on one scale
        lo, hi = min(ax.get_ylim()[0] for ax in axes), max(ax.get_ylim()[1] for ax in axes)
        for ax in axes:
            ax.set_ylim(lo, hi)
    legend = figure.legend(handles, labels, loc="lower center", bbox_to_anchor=(0.5, (note_h + 4) / height),
                           ncol=columns, fontsize=fs, handlelength=2.8, columnspacing=1.4, borderaxespad=0.0)
    legend.set_gid("legend")
    return figure


#: the legend's words for the causal rod's stress part (docs/model.md, "The causal rod")
STRESS_TEXT = "rod, stress (hatched): its pressure’s share\nof the rod’s energy and momentum"


def _rods_legend(histories: tuple, st: Style) -> tuple[list, list[str]]:
    names = sorted(p.name for p in histories[-1].scenario.particles)
    inks = st.ledger_particles
    handles = [Line2D([], [], color=inks[n].colour, linewidth=inks[n].width, linestyle=inks[n].dashes) for n in names]
    labels = [f"particle {n}" for n in names]
    rod, thick, total = (Line2D([], [], color=st.rod.colour, linewidth=st.rod.width), Line2D([], [], **kinetic_ink(st)),
                         Line2D([], [], **total_ink(st)))
    if len(histories) == 2:
        handles += [rod, thick, total, Patch(**hidden_fill(st)), Patch(**stress_fill(st))]
        labels += ["rod: kinetic (rigid), matter (causal)", "kinetic total (rigid),\nparticles + matter (causal)",
                   "total before the first impact", "rigid rod: hidden = total − kinetic", STRESS_TEXT]
    else:
        handles += [rod, thick, total, Patch(**stress_fill(st))]
        labels += ["rod, matter (its rest-frame energy moving with it)", "particles + matter",
                   "total before the first contact", STRESS_TEXT]
    return handles, labels
