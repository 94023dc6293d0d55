"""The rod's own view as a panel (`--frame rod`, docs/plot.md, "The rod's own view"): the rod a fixed vertical strip.

`draw_rod_panel(ax, history, style)` draws the chart of `physics.rod_view` into a caller's Axes from the layers of
`rod_layers` (each draws itself where the run has what it draws, and gives its own lines of the key) and returns
their artists in a `RodPanelArtists`: the strip (shaded by compression where the run has it), the light fronts at
45 degrees, each contact as a band on the end it rides, each turn of the rod's lines of simultaneity (horizontal
lines where it starts and ends: the rod's own "now" is every horizontal line), its pivot, the region beyond the
pivot's horizon, hatched, the light from each impact, material lines with their clocks (ticks every `clock_step`
of each point's own proper time), the particles (through the chart's extension outside the rod), the impacts, and
the key. `draw_rod_view` adds the panels to a drawn diagram (`plot --frame rest,rod`) or makes a figure of them
alone (`--frame rod`). Sampling is for drawing only: every point is an exact chart map of an exact world-line.
"""

from __future__ import annotations

from typing import NamedTuple, Sequence

import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure
from matplotlib.ticker import FixedLocator, FuncFormatter

from rodparadox.physics.rod_view import MAX_VIEW_SPAN, chart_of, thin_view
from rodparadox.physics.rod import clock_step as nice_clock_step
from rodparadox.render.causal_layers import HANDLER_MAP
from rodparadox.render.labels import Area, Label, place
from rodparadox.render.layer_base import widest_line
from rodparadox.render.layout import font_sizes, tick_step
from rodparadox.render.rod_layers import DRAW, KEY, RodPanel
from rodparadox.render.styles import STYLES, Style
from rodparadox.render.text import impact_text_size, suptitle, tick_text, ticks_at

#: the chart's X from this far left of the rod to as far right of it (units of L)
X_MARGIN = 0.75
#: the width of the panel's key, on its right, in units of the tick labels' size
KEY_WIDTH = 14.0
#: points by which a view must be taller than its panels to be held so by its keys (`least_height`), not rounding
KEY_SLACK = 1e-6
#: the least width in points of a panel of the rod's own view beside its key; a page narrower than that for the
#: views side by side is refused (`rod_view_size`)
MIN_PANEL_WIDTH = 36.0


class RodPanelArtists(NamedTuple):
    """What `draw_rod_panel` drew, by layer (`rod_layers`): empty where the run has nothing of that layer (no
    fronts for a rigid rod, no turns for a causal one). `particles` holds their labels too; `key` the legend."""

    strip: tuple = ()
    fronts: tuple = ()
    contacts: tuple = ()
    turns: tuple = ()
    pivots: tuple = ()
    horizon: tuple = ()
    light: tuple = ()
    clocks: tuple = ()
    particles: tuple = ()
    impacts: tuple = ()
    key: tuple = ()
    forces: tuple = ()  # a rod driven by forces: each force's band beside its end, its start and end marked


def rod_box(history, chart=None) -> tuple[float, float, float, float]:
    """(X0, X1, T0, T1) in units of L: the rod with X_MARGIN either side, in time from a lead before the first
    impact (as the frames' panels: the time from the start, at least L/2 and at most 2L) to 1.5 L after the last
    event (a turn's end, or a separation)."""
    chart = chart or chart_of(history)
    L = history.scenario.L
    times = [chart.to_chart(i.event)[0] / L for i in history.impacts]
    times += [T for layer in DRAW if layer.applies(history) for T in layer.chart_times(history, chart)]  # forces too
    first = min(times)
    T0, T1 = first - min(2.0, max(0.5, first)), max(times) + 1.5
    if T1 - T0 > MAX_VIEW_SPAN:
        raise thin_view(T1 - T0)
    return -X_MARGIN, 1 + X_MARGIN, T0, T1


def draw_rod_panel(ax, history, style: Style | str = "default", letter: str = "r", title: str | None = None,
                   clock_step: float | None = None, box=None) -> RodPanelArtists:
    """Draw the rod's own view of a history into `ax`; returns the artists by layer."""
    st = STYLES[style] if isinstance(style, str) else style
    fs = font_sizes(st)
    chart = chart_of(history)
    X0, X1, T0, T1 = box or rod_box(history, chart)
    step = clock_step or nice_clock_step(T1 - T0, 12)
    panel = RodPanel(history, chart, st, fs, letter, (X0, X1, T0, T1), step)
    _axes(ax, panel.box, st, fs, title or f"({letter}) the {history.model} rod’s own view")
    drawn = {layer.name: tuple(layer.draw(ax, panel)) for layer in DRAW if layer.applies(history)}
    drawn["particles"] += tuple(_particle_labels(ax, st, panel.box, letter, fs, drawn["impacts"]))
    drawn["key"] = (_key(ax, panel),)
    return RodPanelArtists(**drawn)


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
    ax.set_ylabel("T/L  (the rod’s own time)", fontsize=fs["label"], fontstyle="italic")
    ax.set_title(title, fontsize=fs["title"])


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


def _key(ax, panel: RodPanel):
    """What the panel shows, in a small key at its top (each layer's own lines, `rod_layers.KEY`): a teacher reads
    the picture without the code."""
    entries = [entry for layer in KEY if layer.applies(panel.history) for entry in layer.key(panel)]
    legend = ax.legend([handle for handle, _ in entries], [text for _, text in entries], loc="upper left",
                       bbox_to_anchor=(1.04, 1.0), borderaxespad=0.0, fontsize=panel.fs["tick"] * 0.85,
                       handlelength=2.0, borderpad=0.0, labelspacing=0.6, frameon=False,
                       handler_map=_handlers(panel.history))
    legend.set_zorder(7)
    return legend


def _handlers(history) -> dict:
    """The key's handlers: the compression ramp's, and the force band's for a rod driven by forces."""
    if history.driving is None:
        return HANDLER_MAP
    from rodparadox.render.force_layers import HANDLER_MAP as FORCE_HANDLERS

    return {**HANDLER_MAP, **FORCE_HANDLERS}


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
        panels = _panels_height(width, len(histories), boxes[0], st)
        _into(figure, histories, st, boxes[0], (0.0, 0.0, width, height), width, height + title_band,
              panels - sum(_margins(st)[2:]) if height > panels + KEY_SLACK else None)
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
    panels at most the style's panel height; at least `least_height` high, so that no key runs below it."""
    st = STYLES[style]
    left, key, bottom, top = _margins(st)
    X0, X1, T0, T1 = _union([rod_box(h) for h in histories])
    aspect = (X1 - X0) / (T1 - T0)
    check_side_by_side(len(histories), style, width)
    h_ax = min(st.panel_height * 72, (width / len(histories) - left - key) / aspect)
    return len(histories) * (left + h_ax * aspect + key), max(h_ax + bottom + top, least_height(histories, style))


def check_side_by_side(count: int, style: str, width: float) -> None:
    """Refuse (OptionError, naming the styles in which they fit) the rods' own views of `count` histories side by
    side in `width` points when the keys and tick labels take the whole width (`rod_view_size` refuses so before
    laying them out; a handout asks before building its document, which takes seconds for a driven rod)."""
    left, key = _margins(STYLES[style])[:2]
    if width / count - left - key < MIN_PANEL_WIDTH:  # the keys and tick labels take the whole width
        from rodparadox.errors import OptionError

        fit = tuple(name for name, other in STYLES.items() if width / count - sum(_margins(other)[:2])
                    >= MIN_PANEL_WIDTH)
        raise OptionError("style", style, " or ".join(fit) or "a wider page",
                          "the rods' own views do not fit side by side on this page in the {value} style; choose "
                          "{style} {allowed}, or the rigid rod alone ({rod} rigid).")


def least_height(histories: Sequence, style: str) -> float:
    """The least height in points of the rod's own view of `histories`: its keys hang from the panels' top on their
    right, so the figure reaches at least the tallest key (and a line of slack) below the panels' top. A short view
    (a rod driven by forces for about L: its panels are as wide as they are tall) has a key taller than its panels;
    measured as the key is drawn, in the style's rcParams."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from rodparadox.render.diagram import style_context

    st = STYLES[style]
    fs = font_sizes(st)
    box = _union([rod_box(h) for h in histories])
    with style_context(style):
        figure = Figure(figsize=(4.0, 4.0), dpi=72)
        renderer = FigureCanvasAgg(figure).get_renderer()
        ax = figure.add_axes((0.0, 0.0, 0.1, 0.1))
        keys = [_key(ax, RodPanel(h, chart_of(h), st, fs, "a", box, nice_clock_step(box[3] - box[2], 12)))
                for h in histories]
        tallest = max(k.get_window_extent(renderer).height for k in keys)
    return _margins(st)[3] + tallest + fs["tick"]


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
    left, key, bottom, top = _margins(st)
    box = _union([rod_box(h) for h in histories])
    h_ax = None
    if height > H:  # the target is lower than the natural size: the panels shrink to fit it
        h_ax = H - bottom - top
        width, height = len(histories) * (left + h_ax * (box[1] - box[0]) / (box[3] - box[2]) + key), H
    elif height > _panels_height(width, len(histories), box, st) + KEY_SLACK:  # the keys are taller than the panels
        h_ax = _panels_height(width, len(histories), box, st) - bottom - top
    _into(target, histories, st, box, ((W - width) / 2, (H - height) / 2, width, height), W, H, h_ax)


def _panels_height(width: float, count: int, box, st: Style) -> float:
    """The height of panels side by side `width` wide, with their margins (`rod_view_size`'s without the keys)."""
    left, key, bottom, top = _margins(st)
    return (width / count - left - key) * (box[3] - box[2]) / (box[1] - box[0]) + bottom + top


def _into(target, histories, st: Style, box, area, W: float, H: float, h_ax: float | None = None) -> None:
    """The panels side by side in `area` (x, y, width, height in points from the target's lower left), their top
    at its top below the titles' margin; `h_ax` their height (None: the area's, less the margins)."""
    left, key, bottom, top = _margins(st)
    x, y, width, height = area
    y_ax = y + bottom
    if h_ax is None:
        h_ax = height - bottom - top
    else:  # lower than the area: at its top, the keys reaching down beside and below them
        y_ax = y + height - top - h_ax
    w_ax = h_ax * (box[1] - box[0]) / (box[3] - box[2])
    for k, h in enumerate(histories):
        x0 = x + k * (left + w_ax + key) + left
        ax = target.add_axes(((x0) / W, y_ax / H, w_ax / W, h_ax / H))
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
