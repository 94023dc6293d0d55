"""The strip: one frame's space at one instant (docs/animate.md, "The paradox in motion"), for animations and handouts.

The rod is a bar from its left end to its right end, coloured along its length by the velocity of its
material points (a diverging scale centred on the frame's rod velocity before any impact,
`render.colour_scale`); the particles are labelled dots; an impact at (or, in an animation, near) the
instant is a star. Positions are the frame's x in units of L, on the caller's x scale.

Two ways in:

* `draw_strip(ax, strip, style, scale, frame, L=...)` draws one strip into an axes and hands back its
  artists (`StripArtists`); `update_strip(artists, strip, frame, L)` moves them to another instant
  (an animation blits them over a saved background);
* `draw_strips_into(target, history, frame, times, style)` draws, for one frame, a block of strips at
  several instants of that frame's time, stacked top to bottom (earliest on top) on one shared x axis, with
  one colour bar: "the rod at successive instants", for a printed page.

Never pyplot; matplotlib is imported by the caller's choice of this module.
"""

from __future__ import annotations

from functools import lru_cache
from typing import NamedTuple, Sequence

import math

import numpy as np
from matplotlib.axes import Axes
from matplotlib.collections import LineCollection
from matplotlib.colorbar import Colorbar
from matplotlib.colors import FuncNorm
from matplotlib.figure import Figure, SubFigure
from matplotlib.lines import Line2D
from matplotlib.text import Text
from matplotlib.ticker import NullLocator

from rodparadox.physics.history import RodHistory
from rodparadox.physics.frames import Frame, frame_name
from rodparadox.physics.snapshot import Strip, strip_at
from rodparadox.numbers import impact_name, shown
from rodparadox.render.colour_scale import ColourScale, colour_scale
from rodparadox.render.strip_windows import follows_rod, outside, row_ranges, shared_range
from rodparadox.render.styles import STYLES, Style
from rodparadox.render.text import coordinate_names
from rodparadox.tolerances import ONE_INSTANT, STEP_ROUNDING

#: the print style's colour map (`Style.velocity_colour_map`): a grey ramp, light (slower) to dark (faster), whose
#: lightness runs one way only, so the bar reads in black and white (a diverging map, as the other styles' blue-
#: white-red, turns both of its ends dark in grey, and its centre white)
PRINT_GREYS = "print-greys"
#: the print ramp: matplotlib's Greys from 0.12 (light grey, L* about 91) to 0.88 (dark grey, L* about 22)
PRINT_RAMP = (0.12, 0.88)
#: what the colour bar says
COLOUR_BAR_LABEL = "velocity of the rod's material points"
#: the strip's axes run from -1 to 1 vertically; the bar lies on 0, a particle's letter starts here (animations)
LETTER_Y = 0.45
#: in a block of stills the bar is this fraction of a row's height, and a letter starts just above it
STILL_BAR = 0.3
STILL_LETTER_Y = STILL_BAR + 0.05


class StripArtists(NamedTuple):
    """A drawn strip's artists (and where its letters go, in the axes' y from -1 to 1): the bar (one segment between
    neighbouring material points, each coloured by their mean velocity) and its outline (in the rod's ink, so a
    bar at the centre of the colour scale, near white, still shows where the rod is), the particles' dots and
    letters, the impacts' stars, the readout (which frame, which instant, which impacts; None when the caller
    labels the strip), and the colour bar (None when another strip's bar serves)."""

    bar: LineCollection
    outline: Line2D
    dots: Line2D
    names: tuple[Text, ...]
    flash: Line2D
    readout: Text | None
    colour_bar: Colorbar | None
    letter_y: float = LETTER_Y
    half_bar: float = 0.5  # the bar's half thickness, in the axes' y
    arrows: tuple = ()  # a rod driven by forces: an arrow at each driven end, as long as the force (`draw_strip`)
    per_force: float = 0.0  # the arrows' length per unit of force, in the axes' x (units of L)

    @property
    def moving(self) -> tuple:
        """What changes from one instant to the next, in the order an animation draws it."""
        return tuple(a for a in (self.bar, self.outline, self.dots, self.flash, self.readout, *self.names,
                                 *self.arrows)
                     if a is not None)


def _style(style: Style | str) -> Style:
    return STYLES[style] if isinstance(style, str) else style


def colour_map(style: Style | str):
    """The bar's colour map in a style (`Style.velocity_colour_map`, centred on the frame's initial rod velocity):
    a matplotlib Colormap."""
    import matplotlib
    from matplotlib.colors import ListedColormap

    name = _style(style).velocity_colour_map
    if name == PRINT_GREYS:
        return ListedColormap(matplotlib.colormaps["Greys"](np.linspace(*PRINT_RAMP, 256)), name=PRINT_GREYS)
    return matplotlib.colormaps[name]


def colour_norm(scale: ColourScale, style: Style | str) -> FuncNorm:
    """Velocity -> 0..1 for the colour map, linear in rapidity (`ColourScale`). On screen over the scale's
    limits, so its centre, the rod before any impact, is the diverging map's white; in print over the
    velocities the rod takes, slowest light to fastest dark, so a rod that only speeds up (or only slows
    down) from its first velocity starts light, at the ramp's pale end, not at mid-grey."""
    lo, hi = scale.ends if _style(style).name == "print" else scale.limits
    return FuncNorm((np.arctanh, np.tanh), vmin=lo, vmax=hi)


def readout_text(strip: Strip, frame: Frame, L: float) -> str:
    """`t′ = 2.111 L in S′` (t, t′ and L in math italics; `t_u = ... in the frame u = 0.3` for another frame), then
    the impacts flashing now: `   A₁, B₂!`."""
    lit = f"   {', '.join(impact_name(name, math_text=True) for name in strip.flashing)}!" if strip.flashing else ""
    return f"{clock_reading(frame, strip.t / L)} in {frame_name(frame)}{lit}"


#: a frame's clock in math italics: the prime after the mathtext t, as mathtext's own t' sets it too high in STIX
CLOCKS = {"rest": "$t$", "moving": "$t$\N{PRIME}"}


def clock_reading(frame: Frame, t: float) -> str:
    """`t′ = 2.111 L`, the variables t, t′ (t_u in a frame u) and L in math italics, the number upright. A
    powers-of-ten number is mathtext too: outside $...$ its superscripts would be set in mathtext's fonts, which
    lack them (`t_u = 5×10⁶ L` drew a missing-glyph box)."""
    number = shown(t, 4)
    if "\N{MULTIPLICATION SIGN}" in number:
        number = f"${shown(t, 4, math_text=True)}$"
    return f"{CLOCKS.get(frame.name, '$t_u$')} = {number} $L$"


#: room between two colour-bar tick labels, in multiples of the font size
TICK_GAP = 0.8


def colour_bar_ticks(scale: ColourScale, width: float, size: float) -> tuple[list[float], list[str]]:
    """The ticks of a colour bar `width` points wide with labels of `size` points: the scale's two ends and its
    centre (the frame's rod velocity before any impact), placed on the bar's rapidity scale; the centre is left
    out when its label would touch an end's (near c: 0.97 beside 0.9995), and one end when the two would."""
    from rodparadox.render.text import approximate_size

    lo, hi = scale.ends
    # the centre only strictly inside: one that is an end up to rounding (single's causal rod from S′ at v = 0.3
    # reaches +0.30000000000000004 against the centre 0.3) would be told apart from it with 17 digits
    inside = all(abs(math.atanh(scale.centre) - math.atanh(end)) > STEP_ROUNDING * max(1.0, abs(math.atanh(end)))
                 for end in (lo, hi))
    wanted = [lo, hi] + ([scale.centre] if lo < scale.centre < hi and inside else [])  # ends first: kept first
    # centre - bound is often zero up to rounding (S' of fig2: 0.6 - 0.6 = 1.1e-16): it is written 0
    for digits in range(3, 18):  # more digits until no two ticks read alike (0.9999999 and 0.99999994 near c)
        label = {x: shown(0.0 if abs(x) <= STEP_ROUNDING * max(abs(lo), abs(hi)) else x, digits) for x in wanted}
        if len(set(label.values())) == len(wanted):
            break
    a, b = math.atanh(lo), math.atanh(hi)
    place = {x: (0.5 if b == a else (math.atanh(x) - a) / (b - a)) * width for x in wanted}
    half = {x: approximate_size(label[x], size)[0] / 2 for x in wanted}
    kept: list[float] = []
    for x in wanted:
        if all(abs(place[x] - place[y]) >= half[x] + half[y] + TICK_GAP * size for y in kept):
            kept.append(x)
    kept.sort()
    return kept, [label[x] for x in kept]


def label_colour_bar(colour_bar: Colorbar, scale: ColourScale, size: float) -> None:
    """Ticks that never overlap (`colour_bar_ticks`) and the bar's name."""
    lo, hi = scale.ends
    ax = colour_bar.ax
    width = ax.bbox.width * 72 / ax.get_figure(root=True).dpi
    ticks, labels = colour_bar_ticks(scale, width, size)
    colour_bar.set_ticks(ticks, labels=labels)
    colour_bar.ax.xaxis.set_minor_locator(NullLocator())
    colour_bar.ax.set_xlim(lo, hi)  # the velocities the rod takes (in print the norm's own ends)
    colour_bar.ax.tick_params(labelsize=size, length=2, pad=1)
    colour_bar.set_label(COLOUR_BAR_LABEL, fontsize=size, labelpad=1)


def draw_strip(ax: Axes, strip: Strip, style: Style | str, scale: ColourScale, frame: Frame, *, L: float = 1.0,
               colour_ax: Axes | None = None, bar_width: float | None = None, animated: bool = False,
               font_size: float | None = None, letter_y: float = LETTER_Y, readout: bool = True,
               gid: str | None = None, force_scale: float | None = None) -> StripArtists:
    """Draw the strip of `frame` at the instant of `strip` into `ax` (its x limits are the caller's).

    `bar_width`: the bar's thickness in points (default: half the axes' height); `colour_ax`: where the colour
    bar goes (none without it); `animated`: the artists are left out of the canvas's own draw, for blitting;
    `font_size`: of the letters and the readout (default: the style's); `force_scale`: for a rod driven by forces
    (`Strip.forces`), the force an arrow as long as the style's type size shows (as plot's bands, `force_layers`).
    """
    st = _style(style)
    fs = st.font_size if font_size is None else font_size
    ax.set_ylim(-1.0, 1.0)
    ax.set_yticks([])
    ax.tick_params(labelsize=0.8 * fs, length=2.5, pad=2)
    if bar_width is None:
        bar_width = ax.bbox.height * 72 / ax.get_figure(root=True).dpi * 0.5
    bar = LineCollection([], cmap=colour_map(st), norm=colour_norm(scale, st), linewidths=bar_width,
                         capstyle="butt", animated=animated, antialiaseds=False)  # no seams between neighbours
    ax.add_collection(bar)
    half_bar = bar_width / 2 / (ax.bbox.height * 72 / ax.get_figure(root=True).dpi / 2)  # points -> axes' y
    outline = ax.plot([], [], color=st.rod.colour, linewidth=max(0.6, 0.45 * st.rod.width), solid_joinstyle="miter",
                      solid_capstyle="butt", animated=animated)[0]
    colour_bar = None
    if colour_ax is not None:
        colour_bar = ax.get_figure(root=False).colorbar(bar, cax=colour_ax, orientation="horizontal")
        label_colour_bar(colour_bar, scale, 0.8 * fs)
    dots = ax.plot([], [], "o", color="black", markersize=0.5 * st.impact_size + 2, animated=animated)[0]
    names = tuple(ax.text(0.0, letter_y, name, ha="center", va="bottom", fontsize=fs, style="italic",
                          color=st.particles[name].colour, animated=animated) for name, _ in strip.particles)
    flash = ax.plot([], [], "*", color=st.flash_colour, markersize=2.2 * st.impact_size,
                    animated=animated)[0]
    said = None
    if readout:
        said = ax.set_title("", fontsize=fs, loc="left", pad=3)
        said.set_animated(animated)
    arrows, per_force = (), 0.0
    if strip.forces:
        from rodparadox.render.force_layers import band_points, strip_arrow

        per_force = band_points(st) / force_scale * (ax.get_xlim()[1] - ax.get_xlim()[0]) / (
            ax.bbox.width * 72 / ax.get_figure(root=True).dpi)  # units of L per unit of force
        arrows = tuple(strip_arrow(ax, st, end, animated) for end, _ in strip.forces)
    artists = StripArtists(bar, outline, dots, names, flash, said, colour_bar, letter_y, half_bar, arrows, per_force)
    gid = gid or ax.get_gid() or "strip"
    for artist, name in ((bar, "bar"), (outline, "outline"), (dots, "particles"), (flash, "impacts"), (said, "readout"),
                         *((text, f"particle-{text.get_text()}") for text in names),
                         *((arrow, f"force-{end}") for arrow, (end, _) in zip(arrows, strip.forces))):
        if artist is not None:
            artist.set_gid(f"{gid}-{name}")
    if not animated:
        update_strip(artists, strip, frame, L)
    return artists


def update_strip(artists: StripArtists, strip: Strip, frame: Frame, L: float = 1.0) -> tuple:
    """Move a drawn strip to the instant of `strip`; returns the artists that changed (`StripArtists.moving`)."""
    x = strip.x / L
    mid = 0.5 * (strip.velocity[1:] + strip.velocity[:-1])
    # neighbours of one colour are one segment: butt-capped neighbours antialiased apart show a seam between them
    # (a rod at rest in print: a pale line every 0.1 L)
    starts = np.flatnonzero(np.concatenate([[True], mid[1:] != mid[:-1]]))
    ends = np.concatenate([starts[1:], [len(mid)]])
    artists.bar.set_segments([[(x[a], 0.0), (x[b], 0.0)] for a, b in zip(starts, ends)])
    artists.bar.set_array(mid[starts])
    h = artists.half_bar
    artists.outline.set_data([x[0], x[-1], x[-1], x[0], x[0]], [-h, -h, h, h, -h])
    artists.dots.set_data([xp / L for _, xp in strip.particles], [0.0] * len(strip.particles))
    ax = artists.bar.axes
    lo, hi = sorted(ax.get_xlim())
    for text, (_, xp) in zip(artists.names, strip.particles):
        text.set_position((xp / L, artists.letter_y))
        text.set_horizontalalignment("center")
        text.set_visible(bool(lo <= xp / L <= hi))  # a letter is not clipped (it may reach above the axes): hide it
    _set_letters_apart(artists, strip, L)
    artists.flash.set_data([xf / L for xf in strip.flash_x], [0.0] * len(strip.flash_x))
    for arrow, (end, force) in zip(artists.arrows, strip.forces):  # pressing: into the rod; pulling: out of it
        at, out = (x[0], -1.0) if end == "left" else (x[-1], 1.0)
        tip_out = at + out * artists.per_force * abs(force)
        arrow.set_positions(*(((tip_out, 0.0), (at, 0.0)) if force > 0 else ((at, 0.0), (tip_out, 0.0))))
        arrow.set_visible(force != 0.0)
    if artists.readout is not None:
        artists.readout.set_text(readout_text(strip, frame, L))
    return artists.moving


def _set_letters_apart(artists: StripArtists, strip: Strip, L: float) -> None:
    """Two particles closer on the page than a letter's width (A and B 2 L apart on an axis 10⁷ L wide): each
    letter goes to its own side of its dot, a fifth of the type size away, so they never overprint."""
    if len(artists.names) != 2:
        return
    ax = artists.bar.axes
    (left, (_, xl)), (right, (_, xr)) = sorted(zip(artists.names, strip.particles), key=lambda n: n[1][1])
    per_L = abs(ax.transData.transform((1.0, 0.0))[0] - ax.transData.transform((0.0, 0.0))[0])  # pixels per L
    size = left.get_fontsize() * ax.figure.dpi / 72.0  # pixels
    if per_L == 0.0 or (xr - xl) / L * per_L >= size:
        return
    nudge = 0.2 * size / per_L
    left.set_horizontalalignment("right")
    left.set_x(xl / L - nudge)
    right.set_horizontalalignment("left")
    right.set_x(xr / L + nudge)


# --- a block of stills: the rod at successive instants ---------------------------------------------------


def draw_strips_into(target: Figure | SubFigure, history: RodHistory, frame: Frame, times: Sequence[float],
                     style: str, span: Sequence[float] | None = None) -> tuple[Axes, ...]:
    """For one frame, the rod and the particles in that frame's space at each of `times` (the frame's own
    time, in the unit L is given in), stacked top to bottom, earliest on top, on one shared x axis (units
    of L, named with the frame's coordinate, e.g. x′/L); each row is labelled with its time (t′ = 1.25 L)
    and marks the impacts at that instant (within ONE_INSTANT * L: rounding of the times passed); one colour bar under the block serves every row (the
    scale of the whole history, `render.colour_scale`, so a colour is the same velocity in every row and
    in the animation). Fills the target (a Figure or SubFigure the caller has sized).

    `span`: the instants whose rod and particles the x axis spans, and whose labels its room is made for (default
    `times`): the parts of one block set on two pages pass the whole block's, so they share one x axis and one tick
    step.

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
        scale = colour_scale(history, frame)
        strips = strips_at(history, frame, tuple(times), ONE_INSTANT * L)
        xname, _ = coordinate_names(frame)
        contacts = _contacts_last(history)
        labels, notes = _stills_labels(strips, frame, L, contacts)
        spanned = strips if span is None else strips_at(history, frame, tuple(float(t) for t in span), ONE_INSTANT * L)
        # the room for the whole block's labels: the parts of a block split between pages keep one axes width, and
        # so one tick step
        # a colour bar only where the rod's velocity varies (fig1's rod never changes: no bar of ±0.0997)
        bar = scale.shown is not None
        # each row following the rod where one shared range would shrink it to a blob (`render.strip_windows`)
        windows = row_ranges(strips, L, None if span is None else spanned)
        room = _stills_room(*((labels, notes) if span is None else _stills_labels(spanned, frame, L, contacts)), fs, bar,
                            follow=windows is not None)
        gutter, right, below, top, row_gap = room.gutter, room.right, room.below, room.top, room.row_gap
        tick_h, label_h, small, bar_h = room.tick_h, room.label_h, room.small, room.bar_h
        row_h = (height - top - below - row_gap * (len(times) - 1)) / len(times)
        axes_w = width - gutter - right
        if row_h < room.least_row or axes_w < room.least_axes:
            need_w, need_h = room.size(len(times))
            raise ValueError(f"{len(times)} strips need at least {need_w / 72:.2f} x {need_h / 72:.2f} in; the "
                             f"target is {width / 72:.2f} x {height / 72:.2f} in.")
        # the x range: every rod end and particle at these instants, with a margin; or each row's, as wide
        lo, hi = shared_range(spanned, L) if windows is None else windows[0]
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
                       letter_y=STILL_LETTER_Y, readout=False)
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


def _stills_labels(strips: Sequence[Strip], frame: Frame, L: float, contacts: bool = False
                   ) -> tuple[list[str], list[str]]:
    """Each row's time (t′ = 1.25 L) and the events at that instant (mathtext), or an empty note: impacts of a rod
    whose impacts are instantaneous; of a rod whose `contacts` last (the causal rod's), contacts and separations,
    each named as what it is (a particle leaving an end is no impact)."""
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
    return labels, [note(s.flashing) for s in strips]


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


@lru_cache(maxsize=64)
def strips_at(history: RodHistory, frame: Frame, times: tuple[float, ...], flash: float) -> tuple[Strip, ...]:
    """The strips (`physics.snapshot.strip_at`) of these instants, kept: a handout measures a block of strips for
    every row count it tries, then draws it. Their arrays are made read-only, as they are shared."""
    strips = tuple(strip_at(history, frame, t, flash) for t in times)
    for strip in strips:
        for array in (strip.sigma, strip.x, strip.velocity):
            array.flags.writeable = False
    return strips


def strips_size(history: RodHistory, frame: Frame, times: Sequence[float], style: str,
                row_scale: float = 1.0, span: Sequence[float] | None = None) -> tuple[float, float]:
    """The least (width, height) in points of a target `draw_strips_into` accepts for these instants, with rows
    `row_scale` times the least row's height: what a page must leave for the block. `span`: as `draw_strips_into`'s
    (the whole block's instants, of which these are a part)."""
    from rodparadox.render.diagram import style_context
    from rodparadox.render.layout import font_sizes

    if not times:
        raise ValueError("draw_strips_into needs at least one time")
    L = history.scenario.L
    with style_context(style) as st:
        strips = strips_at(history, frame, tuple(sorted(float(t) for t in times)), ONE_INSTANT * L)
        whole = strips if span is None else strips_at(history, frame, tuple(float(t) for t in span), ONE_INSTANT * L)
        return _stills_room(*_stills_labels(strips, frame, L, _contacts_last(history)), font_sizes(st),
                            colour_scale(history, frame).shown is not None, follows_rod(whole, L)).size(len(strips), row_scale)


class _Ticks:
    """A tick formatter: tick_text with the block's step (a class, not a lambda: figures may be pickled)."""

    def __init__(self, step: float):
        self.step = step

    def __call__(self, value, _pos=None) -> str:
        from rodparadox.render.text import tick_text

        return tick_text(value, self.step)
