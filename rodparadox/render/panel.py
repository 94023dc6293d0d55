"""One panel: a frame's axes (limits, ticks, axis names, title), then every enabled layer, then the labels."""

from __future__ import annotations

import numpy as np
from matplotlib.ticker import FixedLocator, FuncFormatter

from rodparadox.physics.history import RodHistory
from rodparadox.render.styles import Style
from rodparadox.render.labels import Area, place
from rodparadox.render.layers import Options, PanelContext, contacts_last, drawing_order, widest_line
from rodparadox.render.layout import Metrics, Panel
from rodparadox.render.legibility import (draw_inset, inset_plan, label_boxes, marks, material_lines_that_fit,
                                          motion_inset_plan)
from rodparadox.render.text import axis_label, coordinate_names, tick_text, ticks_at


def draw_panel(ax, p: Panel, steps: tuple[float, float], m: Metrics, history: RodHistory, style: Style,
               options: Options, clock_step: float, rod_lines: int | None = None,
               crowded: bool = False) -> dict[str, tuple]:
    """Draw a laid-out panel into `ax`; returns the artists of every enabled layer, its labels' included, by name,
    and the magnified inset's (`inset`) when the world-sheet is thin on the page (`legibility.inset_plan`).
    `rod_lines`: the material lines to draw (the diagram thins them to what the panel holds); None: as asked.
    `crowded`: labels placed as for the causal rod's crowded ends (`labels.place`), as the causal rod's own panels
    always are (a figure of both rods: its rigid rows too, drawn small beside them)."""
    _axes(ax, p, steps, m)
    history = p.history if p.history is not None else history
    if rod_lines is None and options.rod_lines:
        rod_lines = material_lines_that_fit(history, p.view, p.worldlines, p.width / (p.box[1] - p.box[0]),
                                            options.rod_lines)
    panel = PanelContext(history, style, options, m.fs, p.letter, p.view, p.worldlines, tuple(p.box), steps,
                         clock_step, rod_lines, p.width / (p.box[1] - p.box[0]))
    drawn: dict[str, list] = {}
    obstacles, guides, labels = [], [], []
    for layer in drawing_order(history):
        if not (layer.enabled(options) and layer.applies(history)):
            continue
        out = layer.draw(ax, panel)
        drawn[layer.name] = list(out.artists)
        obstacles += out.obstacles
        guides += out.guides
        labels += [(layer.label_rank, layer.name, label) for label in out.labels]
    labels.sort(key=lambda entry: entry[0])  # stable: within a rank, in drawing order
    ends = [p.worldlines[end] for end in ("rod_left", "rod_right") if end in p.worldlines]
    sheet = np.concatenate([ends[0], ends[1][::-1]]) if len(ends) == 2 else None  # the shaded world-sheet
    placed = place(ax, Area(tuple(p.box), p.width, p.height), [label for *_, label in labels], obstacles, guides,
                   widest_line(style), m.fs["impact"], style.font_size, crowded=crowded or contacts_last(history),
                   sheet=sheet)
    for (_, name, _), artists in zip(labels, placed):
        drawn[name] += artists
    if options.insets:
        scale = p.width / (p.box[1] - p.box[0])  # points per L
        keep_clear = label_boxes(ax, p.box, scale, 2.0)
        events = marks(history, p.view)  # impacts, or a driven rod's force starts and ends
        keep_clear += [((e.x - p.box[0]) * scale - style.impact_size, (e.t - p.box[2]) * scale - style.impact_size,
                        (e.x - p.box[0]) * scale + style.impact_size, (e.t - p.box[2]) * scale + style.impact_size)
                       for e in events]
        worldlines = list(p.worldlines.values())  # an inset hides none of them where it can
        plan = inset_plan(p.view, history.scenario.L, p.worldlines, p.box, p.width, p.height, keep_clear, obstacles,
                          events, worldlines)
        if plan is None:  # a driven rod whose small motion would not be seen
            plan = motion_inset_plan(history, p.view, p.worldlines, p.box, p.width, p.height, keep_clear, obstacles,
                                     events, worldlines, p.motion_inset)
        if plan is not None:
            drawn["inset"] = list(draw_inset(ax, plan, history, p.view, style, p.letter, m.fs["tick"], p.width,
                                             p.height, events, options.simultaneity))
    return {name: tuple(artists) for name, artists in drawn.items()}


def _axes(ax, p: Panel, steps: tuple[float, float], m: Metrics) -> None:
    """Limits (equal scales), fixed ticks with their labels, the axes' names and the panel's title."""
    fs = m.fs
    x0, x1, t0, t1 = p.box
    x_step, step = steps
    xt, tt = ticks_at(x0, x1, x_step), ticks_at(t0, t1, step)
    xname, tname = coordinate_names(p.view.frame)
    ax.set_xlim(x0, x1)
    ax.set_ylim(t0, t1)
    ax.set_aspect("equal", adjustable="box")
    ax.xaxis.set_major_locator(FixedLocator(xt))
    ax.yaxis.set_major_locator(FixedLocator(tt))
    ax.xaxis.set_major_formatter(FuncFormatter(lambda value, _pos: tick_text(value, x_step)))
    ax.yaxis.set_major_formatter(FuncFormatter(lambda value, _pos: tick_text(value, step)))
    ax.tick_params(labelsize=fs["tick"], length=m.tick_len, pad=m.tick_pad)
    italic = "normal" if "$" in xname else "italic"
    ax.set_xlabel(axis_label(xname), fontsize=fs["label"], fontstyle=italic, labelpad=m.label_pad)
    ax.set_ylabel(axis_label(tname), fontsize=fs["label"], fontstyle=italic, labelpad=m.label_pad)
    ax.set_title("\n".join(p.title_lines), fontsize=fs["title"], y=1.0)  # y given: no search for tick labels above the axes
