"""A block of strips: one frame's space at several instants of its time, stacked top to bottom (earliest on top),
with one colour bar, "the rod at successive instants" for a printed page (`render.strip` draws each strip).

`draw_strips_into(target, history, frame, times, style)` draws the block into a caller's Figure or SubFigure;
`strips_size` is the least target it accepts. Each row shares one x range, or follows the rod where one range
would shrink it to a blob (`render.strip_windows`).

Never pyplot; matplotlib is imported by the caller's choice of this module.
"""

from __future__ import annotations

from typing import NamedTuple, Sequence

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure, SubFigure

from rodparadox.physics.history import RodHistory
from rodparadox.physics.frames import Frame
from rodparadox.physics.snapshot import Strip
from rodparadox.render.colour_scale import colour_scale, shared_scale
from rodparadox.render.force_layers import force_notes
from rodparadox.render.strip import STILL_BAR, STILL_LETTER_Y, clock_reading, draw_strip, label_colour_bar
from rodparadox.render.strip_windows import follows_rod, outside, row_ranges, shared_range, strips_at
from rodparadox.render.styles import Style
from rodparadox.render.text import coordinate_names
from rodparadox.tolerances import ONE_INSTANT


def draw_strips_into(target: Figure | SubFigure, history: RodHistory, frame: Frame, times: Sequence[float],
                     style: str, span: Sequence[float] | None = None,
                     partners: Sequence[tuple[RodHistory, Sequence[float]]] = ()) -> tuple[Axes, ...]:
    """For one frame, the rod and the particles in that frame's space at each of `times` (the frame's own
    time, in the unit L is given in), stacked top to bottom, earliest on top, on one shared x axis (units
    of L, named with the frame's coordinate, e.g. x′/L); each row is labelled with its time (t′ = 1.25 L)
    and marks the impacts at that instant (within ONE_INSTANT * L: rounding of the times passed); one colour bar under the block serves every row (the
    scale of the whole history, `render.colour_scale`, so a colour is the same velocity in every row and
    in the animation). Fills the target (a Figure or SubFigure the caller has sized).

    `span`: the instants whose rod and particles the x axis spans, and whose labels its room is made for (default
    `times`): the parts of one block set on two pages pass the whole block's, so they share one x axis and one tick
    step.

    `partners`: the other rods of a comparison in this frame, each with its block's instants (the causal rod beside
    the rigid one, driven by the same forces): the blocks share one x range (or, following the rod, one row width),
    one room for the rows' labels, so one tick step, and one colour scale (`colour_scale.shared_scale`); a block
    whose own rod never changes velocity still has no colour bar.

    Returns the rows' axes, top to bottom (earliest first); the colour bar's axes has the gid
    `strips-colour-bar` (none where the rod's velocity never changes). A target too small for the rows, their labels and the colour bar is refused
    (ValueError, naming the size needed).
    """
    from rodparadox.render.diagram import style_context
    from rodparadox.numbers import nice_number
    from rodparadox.render.layout import font_sizes
    from rodparadox.render.text import approximate_size, axis_label, ticks_at

    if not times:
        raise ValueError("draw_strips_into needs at least one time")
    times = sorted(float(t) for t in times)
    L = history.scenario.L
    dpi = (target.get_figure(root=True) if isinstance(target, SubFigure) else target).dpi
    width, height = target.bbox.width * 72 / dpi, target.bbox.height * 72 / dpi  # points
    with style_context(style) as st:
        fs = font_sizes(st)
        scale = colour_scale(history, frame) if not partners else shared_scale(
            [history, *(h for h, _ in partners)], frame)
        strips = strips_at(history, frame, tuple(times), ONE_INSTANT * L)
        xname, _ = coordinate_names(frame)
        contacts = _contacts_last(history)
        labels, notes = _stills_labels(strips, frame, L, contacts, history)
        spanned = strips if span is None else strips_at(history, frame, tuple(float(t) for t in span), ONE_INSTANT * L)
        forces = None
        if history.driving is not None:  # a rod driven by forces: an arrow at each end, as long as the force there
            from rodparadox.render.force_layers import band_points, force_scale

            forces = force_scale(history)
        # the room for the whole block's labels: the parts of a block split between pages keep one axes width, and
        # so one tick step
        # a colour bar only where the rod's velocity varies (fig1's rod never changes: no bar of ±0.0997)
        bar = colour_scale(history, frame).shown is not None
        # each row following the rod where one shared range would shrink it to a blob (`render.strip_windows`)
        others = _partner_strips(frame, partners)
        windows = row_ranges(strips, L, None if span is None and not partners else tuple(spanned) + others)
        room_labels = (labels, notes) if span is None else _stills_labels(spanned, frame, L, contacts, history)
        if partners:  # the room for every compared block's labels: one axes width, so one range and tick step
            room_labels = _with_partners_labels(room_labels, frame, partners)
        room = _stills_room(*room_labels, fs, bar, follow=windows is not None)
        gutter, right, below, top, row_gap = room.gutter, room.right, room.below, room.top, room.row_gap
        tick_h, label_h, small, bar_h = room.tick_h, room.label_h, room.small, room.bar_h
        row_h = (height - top - below - row_gap * (len(times) - 1)) / len(times)
        axes_w = width - gutter - right
        if row_h < room.least_row or axes_w < room.least_axes:
            need_w, need_h = room.size(len(times))
            raise ValueError(f"{len(times)} strips need at least {need_w / 72:.2f} x {need_h / 72:.2f} in; the "
                             f"target is {width / 72:.2f} x {height / 72:.2f} in.")
        # the x range: every rod end and particle at these instants, with a margin (with forces, room beyond each
        # end for the longest arrow: band_points at the scale's force); or each row's, as wide
        reach = band_points(st) + 0.5 * fs["tick"] if forces is not None else 0.0
        lo, hi = shared_range(tuple(spanned) + others, L, reach, axes_w) if windows is None else windows[0]
        step = nice_number(10.0 ** np.floor(np.log10((hi - lo) / 10)), "above")
        while (hi - lo) / step > max(2.0, axes_w / (3.0 * approximate_size("−0.00", fs["tick"])[0])):
            step = nice_number(step, "above")
        rows: list[Axes] = []
        y = height - top
        for k, (strip, label, note) in enumerate(zip(strips, labels, notes)):
            y -= row_h
            ax = target.add_axes((gutter / width, y / height, axes_w / width, row_h / height),
                                 sharex=rows[0] if rows and windows is None else None)
            y -= row_gap
            ax.set_gid(f"strips-row-{k}")  # its artists: strips-row-0-bar, strips-row-0-particles, ...
            if windows is not None:
                lo, hi = windows[k]
            ax.set_xlim(lo, hi)
            draw_strip(ax, strip, st, scale, frame, L=L, bar_width=STILL_BAR * row_h / 2, font_size=fs["label"],
                       letter_y=STILL_LETTER_Y, readout=False, force_scale=forces)
            ax.set_xticks(ticks_at(lo, hi, step))
            ax.xaxis.set_major_formatter(_Ticks(step))
            ax.tick_params(labelsize=fs["tick"], length=3.5, pad=3.5,
                           labelbottom=(k == len(times) - 1 or windows is not None))
            if windows is not None:
                _mark_beyond(ax, strip, (lo, hi), L, st, fs["label"], k)
            ax.grid(axis="x", color=st.grid.colour, linewidth=st.grid.width, zorder=0)
            ax.set_axisbelow(True)
            ax.text(-8.0 / axes_w, 0.5 if not note else 0.62, label, transform=ax.transAxes, ha="right",
                    va="center", fontsize=fs["label"], gid=f"strips-time-{k}")
            if note:
                ax.text(-8.0 / axes_w, 0.24, note, transform=ax.transAxes, ha="right", va="center",
                        fontsize=fs["tick"], gid=f"strips-impacts-{k}")
            rows.append(ax)
        rows[-1].set_xlabel(axis_label(xname), fontsize=fs["label"], labelpad=4.0,
                            fontstyle="normal" if "$" in xname else "italic")
        if not bar:
            return tuple(rows)
        bar_y = below - (3.5 + 3.5 + tick_h + 4.0 + label_h) - 10.0 - bar_h
        colour_ax = target.add_axes(((gutter + 0.15 * axes_w) / width, bar_y / height, 0.7 * axes_w / width,
                                     bar_h / height))
        colour_ax.set_gid("strips-colour-bar")
        shown_bar = target.colorbar(rows[0].collections[0], cax=colour_ax, orientation="horizontal")
        # a printed page keeps it vector (matplotlib rasterises a long scale), each cell edged in its own colour so
        # that no seam shows between neighbours when a viewer or printer antialiases them
        shown_bar.solids.set_rasterized(False)
        shown_bar.solids.set_edgecolor("face")
        shown_bar.solids.set_linewidth(0.3)
        label_colour_bar(shown_bar, scale, small)
    return tuple(rows)


def _mark_beyond(ax: Axes, strip: Strip, window: tuple[float, float], L: float, st: Style, size: float, k: int) -> None:
    """A row that follows the rod: each particle beyond its window, an arrowhead at that edge pointing its way, with
    its letter inside the edge (the letter and the dot `draw_strip` drew are out of sight)."""
    lo, hi = window
    inset = 0.012 * (hi - lo)  # the arrowhead just inside the edge
    for name, side in outside(strip, window, L):
        at, marker, align = (lo + inset, "<", "left") if side == "left" else (hi - inset, ">", "right")
        ax.plot([at], [0.0], marker=marker, color="black", markersize=0.5 * st.impact_size + 2, clip_on=False,
                gid=f"strips-row-{k}-beyond-{name}")
        ax.text(at, STILL_LETTER_Y, name, ha=align, va="bottom", fontsize=size, style="italic",
                color=st.particles[name].colour, gid=f"strips-row-{k}-beyond-{name}-letter")


class _StillsRoom(NamedTuple):
    """Room around a block of stills, points: left of the rows for their labels, right, under them for the ticks,
    the x name and the colour bar, above; between rows; the least row (a particle's letter fits above the bar) and
    the least axes width; and the sizes those are made of."""

    gutter: float
    right: float
    below: float
    top: float
    row_gap: float
    least_row: float
    least_axes: float
    tick_h: float
    label_h: float
    small: float
    bar_h: float

    def size(self, rows: int, row_scale: float = 1.0) -> tuple[float, float]:
        """(width, height) of a block of `rows` rows, each `row_scale` times the least row, with the least axes."""
        return (self.gutter + self.right + self.least_axes,
                self.top + self.below + rows * row_scale * self.least_row + self.row_gap * (rows - 1))


def _stills_labels(strips: Sequence[Strip], frame: Frame, L: float, contacts: bool = False, history=None
                   ) -> tuple[list[str], list[str]]:
    """Each row's time (t′ = 1.25 L) and the events at that instant (mathtext), or an empty note: impacts of a rod
    whose impacts are instantaneous; of a rod whose `contacts` last (the causal rod's), contacts and separations,
    each named as what it is (a particle leaving an end is no impact); of a `history` driven by forces, each force
    that starts, peaks or ends then (`force_layers.force_notes`)."""
    from rodparadox.numbers import impact_name

    def named(word: str, events: Sequence[str]) -> str:
        return (f"{word} " if len(events) == 1 else f"{word}s ") + ", ".join(impact_name(f, math_text=True)
                                                                            for f in events)

    def note(flashing: Sequence[str]) -> str:
        if not contacts:
            return named("impact", flashing) if flashing else ""
        touching = [f for f in flashing if not _is_separation(f)]
        leaving = [f for f in flashing if _is_separation(f)]
        return ", ".join(([named("contact", touching)] if touching else []) +
                         ([named("separation", leaving)] if leaving else []))

    labels = [clock_reading(frame, s.t / L) for s in strips]
    if history is not None and history.driving is not None:
        return labels, force_notes(history, frame, [s.t for s in strips], L)
    return labels, [note(s.flashing) for s in strips]



def _partner_strips(frame: Frame, partners: Sequence[tuple[RodHistory, Sequence[float]]]) -> tuple[Strip, ...]:
    """The strips of the compared rods' blocks (`draw_strips_into`'s `partners`)."""
    return tuple(s for h, times in partners
                 for s in strips_at(h, frame, tuple(sorted(float(t) for t in times)), ONE_INSTANT * h.scenario.L))


def _with_partners_labels(labels: tuple[list[str], list[str]], frame: Frame,
                          partners: Sequence[tuple[RodHistory, Sequence[float]]]) -> tuple[list[str], list[str]]:
    """A block's row labels and notes with those of the compared rods' blocks: the room made for all of them."""
    texts, notes = list(labels[0]), list(labels[1])
    for h, times in partners:
        more = _block_labels(h, frame, tuple(sorted(float(t) for t in times)))
        texts += more[0]
        notes += more[1]
    return texts, notes


def _block_labels(history: RodHistory, frame: Frame, times: tuple[float, ...]) -> tuple[list[str], list[str]]:
    """Each row's time and note of a block at these instants (a driven rod's from the instants alone)."""
    L = history.scenario.L
    if history.driving is not None:
        return [clock_reading(frame, t / L) for t in times], force_notes(history, frame, times, L)
    return _stills_labels(strips_at(history, frame, times, ONE_INSTANT * L), frame, L, _contacts_last(history), history)


def _contacts_last(history: RodHistory) -> bool:
    """Whether the rod's contacts last, each ended by a separation (the causal rod's): its stills name contacts and
    separations, not impacts."""
    return any(i.is_separation for i in history.impacts)


def _is_separation(label: str) -> bool:
    """A separation's label (A1s: the particle leaving the end its contact A1 struck), as `numbers.impact_name`
    reads it."""
    from rodparadox.numbers import impact_parts

    return label.endswith("s") and impact_parts(label[:-1])[1] != ""


def _stills_room(labels: Sequence[str], notes: Sequence[str], fs: dict[str, float], bar: bool = True,
                 follow: bool = False) -> _StillsRoom:
    """The room of `draw_strips_into` for rows with these labels, in a style's type sizes; `bar`: with room for the
    colour bar (none where the rod's velocity never changes); `follow`: each row follows the rod, with its own tick
    labels under it (`render.strip_windows`)."""
    from rodparadox.render.text import approximate_size

    # room, in points: left of the rows for their labels; under them for the ticks, the x name, the colour bar
    gutter = 1.05 * max(approximate_size(text, fs["label"])[0] for text in [*labels, *notes]) + 8.0 + 6.0
    tick_h = approximate_size("0123456789", fs["tick"])[1]
    label_h = approximate_size("$x_u/L$", fs["label"])[1]
    small = 0.8 * fs["tick"]
    bar_h = max(5.0, 0.7 * small)
    below = (3.5 + 3.5 + tick_h + 4.0 + label_h) + ((10.0 + bar_h + (2 + 1 + 1.2 * small) * 2) if bar else 0.0) + 4.0
    least_row = 2 * 0.95 * fs["label"] / (1 - STILL_LETTER_Y)  # a particle's letter fits above the bar
    row_gap = 0.25 * fs["tick"] + ((3.5 + 3.5 + tick_h + 4.0) if follow else 0.0)
    return _StillsRoom(gutter, 10.0, below, 4.0, row_gap, least_row, 8 * fs["tick"], tick_h, label_h, small, bar_h)


def strips_size(history: RodHistory, frame: Frame, times: Sequence[float], style: str,
                row_scale: float = 1.0, span: Sequence[float] | None = None,
                partners: Sequence[tuple[RodHistory, Sequence[float]]] = ()) -> tuple[float, float]:
    """The least (width, height) in points of a target `draw_strips_into` accepts for these instants, with rows
    `row_scale` times the least row's height: what a page must leave for the block. `span`, `partners`: as
    `draw_strips_into`'s (the whole block's instants, of which these are a part; the compared rods' blocks)."""
    from rodparadox.render.diagram import style_context
    from rodparadox.render.layout import font_sizes

    if not times:
        raise ValueError("draw_strips_into needs at least one time")
    L = history.scenario.L
    times = tuple(sorted(float(t) for t in times))
    with style_context(style) as st:
        bar = colour_scale(history, frame).shown is not None
        strips = strips_at(history, frame, times, ONE_INSTANT * L)
        whole = strips if span is None else strips_at(history, frame, tuple(float(t) for t in span), ONE_INSTANT * L)
        if history.driving is not None:  # its rows' notes from the instants alone
            labels = ([clock_reading(frame, t / L) for t in times], force_notes(history, frame, times, L))
        else:
            labels = _stills_labels(strips, frame, L, _contacts_last(history), history)
        if partners:
            labels = _with_partners_labels(labels, frame, partners)
            whole = tuple(whole) + _partner_strips(frame, partners)
        return _stills_room(*labels, font_sizes(st), bar, follows_rod(whole, L)).size(len(times), row_scale)


class _Ticks:
    """A tick formatter: tick_text with the block's step (a class, not a lambda: figures may be pickled)."""

    def __init__(self, step: float):
        self.step = step

    def __call__(self, value, _pos=None) -> str:
        from rodparadox.render.text import tick_text

        return tick_text(value, self.step)
