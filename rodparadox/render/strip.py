"""The strip: one frame's space at one instant (docs/animate.md, "The paradox in motion"), for animations and handouts.

The rod is a bar from its left end to its right end, coloured along its length by the velocity of its
material points (a diverging scale centred on the frame's rod velocity before any impact,
`render.colour_scale`); the particles are labelled dots; an impact at (or, in an animation, near) the
instant is a star. Positions are the frame's x in units of L, on the caller's x scale.

Two ways in:

* `draw_strip(ax, strip, style, scale, frame, L=...)` draws one strip into an axes and hands back its
  artists (`StripArtists`); `update_strip(artists, strip, frame, L)` moves them to another instant
  (an animation blits them over a saved background);
* `render.strip_block.draw_strips_into(target, history, frame, times, style)` draws, for one frame, a block of
  strips at several instants of that frame's time, stacked top to bottom (earliest on top), with one colour bar:
  "the rod at successive instants", for a printed page.

Never pyplot; matplotlib is imported by the caller's choice of this module.
"""

from __future__ import annotations

from typing import NamedTuple

import math

import numpy as np
from matplotlib.axes import Axes
from matplotlib.collections import LineCollection
from matplotlib.colorbar import Colorbar
from matplotlib.colors import FuncNorm
from matplotlib.lines import Line2D
from matplotlib.text import Text
from matplotlib.ticker import NullLocator

from rodparadox.physics.frames import Frame, frame_name
from rodparadox.physics.snapshot import Strip
from rodparadox.numbers import impact_name, shown
from rodparadox.render.colour_scale import ColourScale
from rodparadox.render.styles import STYLES, Style
from rodparadox.tolerances import STEP_ROUNDING

#: the print style's colour map (`Style.velocity_colour_map`): a grey ramp, light (slower) to dark (faster), whose
#: lightness runs one way only, so the bar reads in black and white (a diverging map, as the other styles' blue-
#: white-red, turns both of its ends dark in grey, and its centre white)
PRINT_GREYS = "print-greys"
#: the print ramp: matplotlib's Greys from 0.12 (light grey, L* about 91) to 0.88 (dark grey, L* about 22)
PRINT_RAMP = (0.12, 0.88)
#: what the colour bar says
COLOUR_BAR_LABEL = "velocity of the rod’s material points"
#: the strip's axes run from -1 to 1 vertically; the bar lies on 0, a particle's letter starts here (animations)
LETTER_Y = 0.45
#: in a block of stills the bar is this fraction of a row's height, and a letter starts just above it
STILL_BAR = 0.3
STILL_LETTER_Y = STILL_BAR + 0.05
#: an arrow shorter than this (units of L) is a force zero to rounding (a sine² at its start seen from another
#: frame: 2e-32): none is drawn, since its head alone would show
ARROW_ZERO = 1e-9


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
        arrow.set_visible(abs(force) * artists.per_force > ARROW_ZERO)  # not a head on a force zero to rounding
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
