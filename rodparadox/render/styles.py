"""The styles of every figure, animation and handout: plain data, no matplotlib import (the CLI's help reads the
names).

Each style says how every element of a diagram is drawn (its colour, line
width and dash pattern), every other value that differs between styles (the
ledger figure's inks, an animation's size and resolution, a handout's type
size), and what rcParams `render` sets while it draws and saves, inside a
context that restores them. Colours are the Okabe-Ito
palette, safe for the common forms of colour blindness; the `print` style is
black and grey only, and every element keeps a line style of its own.
"""

from __future__ import annotations

from types import MappingProxyType
from typing import Any, Mapping, NamedTuple

#: formats `plot` writes, in the order it writes them
FORMATS = ("svg", "pdf", "png")

# Okabe & Ito (2008), "Color Universal Design"
_BLUE, _VERMILLION, _GREEN, _ORANGE, _PURPLE, _SKY, _GREY = (
    "#0072B2", "#D55E00", "#009E73", "#E69F00", "#CC79A7", "#56B4E9", "#6E6E6E")

# dash patterns, in units of the line width (matplotlib's (offset, (on, off, ...)))
SOLID = "solid"
PARTICLE_DASH = (0, (5.0, 2.5))
REST_DOTS = (0, (1.0, 1.8))
MOVING_DASHDOT = (0, (6.0, 2.0, 1.2, 2.0))
AXES_DASHDOTDOT = (0, (7.0, 2.0, 1.2, 2.0, 1.2, 2.0))
CONE_SHORT_DASH = (0, (2.0, 2.0))
#: the rod's own lines of simultaneity (Options.rod_now): long dashes, so that in grey they are not taken for the
#: material lines (thin, solid) they cross
ROD_NOW_DASH = (0, (16.0, 4.0))
#: calibration hyperbolae: thin long dashes, so that in grey they are not taken for the material lines (thin, solid)
HYPERBOLA_DASH = (0, (6.0, 2.0))
#: particle B is long-and-short dashed in every style (not dash-dotted: that is S′'s simultaneity), so that a legend
#: read in grey (a photocopy, the print style) tells A from B without colour
B_DASH = (0, (8.0, 2.0, 3.0, 2.0))
#: the causal rod's light fronts: long thin dashes, told from the dotted lines of simultaneity in grey
FRONT_DASH = (0, (7.0, 3.0))
#: the ledger figure's particle B in print, where both particles are black and no label names the curves
LEDGER_DASHDOT = (0, (6.0, 1.8, 1.5, 1.8))


class Ink(NamedTuple):
    """How one kind of line is drawn."""

    colour: str
    width: float  # points
    dashes: Any = SOLID


class Style(NamedTuple):
    """Everything that differs between the default, print and slides figures, animations and handouts: every
    value that depends on the style is a field here, so no module keeps a table keyed by style name."""

    name: str
    about: str
    font_size: float  # points: tick labels and legend; labels and titles are scaled from it
    panel_height: float  # inches, the largest a panel is drawn
    max_width: float  # inches, the widest a figure is drawn: the page's (or slide's) text width
    max_height: float  # inches, the tallest a figure is drawn: the page's (or slide's) text height
    png_dpi: int
    rod: Ink
    sheet: str  # fill of the rod's world-sheet
    particles: Mapping[str, Ink]
    impact_colour: str
    impact_size: float  # marker diameter, points
    rest_simultaneity: Ink  # lines t = const of S
    moving_simultaneity: Ink  # lines t' = const of S'
    other_axes: Ink
    light_cone: Ink
    hyperbola: Ink
    grid: Ink
    rod_interior: Ink  # Options.rod_lines: material world-lines inside the rod
    rod_now: Ink  # Options.rod_now: the rod's own lines of simultaneity, drawn across the rod only
    clock_size: float  # Options.proper_time: diameter of a clock tick (a hollow circle in the world-line's colour), points
    tick_length: float  # points: the tick marks of a diagram's axes
    ledger_particles: Mapping[str, Ink]  # the particles' curves in the ledger figure, where no label names them
    hidden_edge: str  # the edge of the ledger figure's shaded hidden part ("none": no edge)
    hidden_hatch: str | None  # its hatching (None: a plain fill)
    flash_colour: str  # an impact's flash (a star) in a strip, and an animation's now-line
    velocity_colour_map: str  # a strip's velocity colour bar: a matplotlib colour map, or print-greys (render.strip)
    animation_dpi: int  # pixels per inch of an animation's images
    animation_ticks: tuple[float, float]  # points: the tick length and pad of an animation's strips
    boost_size: tuple[float, float]  # inches: a boost animation's width and its largest height
    handout_body_size: float  # points: a handout's body text
    rc: Mapping[str, Any]  # rcParams set while drawing and saving
    #: the causal rod (docs/model.md, "The causal rod"): its light fronts, thin light lines across the world-sheet, and
    #: the ends of its compression scale (most stretched, most compressed; the unstressed middle is `sheet`)
    front: Ink = Ink("#1a1a1a", 0.45, FRONT_DASH)
    compression_ends: tuple[str, str] = ("#fff4cf", "#08306b")
    force: Ink = Ink(_VERMILLION, 0.8)  # a force on an end: its band's outer edge and its arrows
    force_fill: str = "#f7cdb3"  # the band's fill (a pull's band is hatched as well)


def _frozen(mapping: dict) -> Mapping:
    return MappingProxyType(dict(mapping))


_COMMON_RC = {
    "svg.hashsalt": "sears-paradox",  # fixed ids: the same figure gives the same bytes
    "svg.fonttype": "path",  # glyphs as shared paths: the SVG looks the same without our fonts
    "pdf.fonttype": 42,  # TrueType, as journals ask (no Type 3 fonts)
    "path.simplify": False,  # keep every sampled point: curves stay within 1e-4 L
    "axes.unicode_minus": True,
    "figure.dpi": 72,  # one display unit per point while laying out
    "axes.titlepad": 5.0,
    "xtick.direction": "out",
    "ytick.direction": "out",
    "lines.dash_capstyle": "butt",
    "lines.solid_capstyle": "round",
    "legend.frameon": False,
}

_SANS = {"font.family": ("DejaVu Sans",), "mathtext.fontset": "dejavusans"}
_SERIF = {"font.family": ("STIXGeneral", "DejaVu Serif"), "mathtext.fontset": "stix"}  # DejaVu: the glyphs STIX lacks (italic prime)

_DEFAULT_PARTICLES = {"A": Ink(_VERMILLION, 1.3, PARTICLE_DASH), "B": Ink(_GREEN, 1.3, B_DASH)}
_DEFAULT = Style(
    name="default",
    about="colour (Okabe-Ito, colour-blind safe), sans-serif, 7 in wide: for the screen and colour print",
    font_size=9.0, panel_height=3.4, max_width=7.0, max_height=9.0, png_dpi=200,
    rod=Ink(_BLUE, 1.7), sheet="#d4e6f3",
    particles=_frozen(_DEFAULT_PARTICLES),
    impact_colour="#000000", impact_size=5.0,
    rest_simultaneity=Ink(_ORANGE, 1.3, REST_DOTS),
    moving_simultaneity=Ink(_PURPLE, 1.1, MOVING_DASHDOT),
    other_axes=Ink(_GREY, 0.9, AXES_DASHDOTDOT),
    light_cone=Ink(_SKY, 0.9, CONE_SHORT_DASH),
    hyperbola=Ink("#9a9a9a", 0.6, HYPERBOLA_DASH),
    grid=Ink("#e3e3e3", 0.5),
    rod_interior=Ink(_BLUE, 0.55),
    rod_now=Ink("#3d3d3d", 0.75, ROD_NOW_DASH),
    clock_size=3.2,
    tick_length=3.5,
    ledger_particles=_frozen(_DEFAULT_PARTICLES),
    hidden_edge="none", hidden_hatch=None,
    flash_colour="#CC0033", velocity_colour_map="RdBu_r",
    animation_dpi=150, animation_ticks=(2.5, 2.0), boost_size=(7.0, 6.0),
    handout_body_size=9.5,
    rc=_frozen({**_COMMON_RC, **_SANS}),
)
_PRINT_PARTICLES = {"A": Ink("#000000", 1.0, PARTICLE_DASH), "B": Ink("#000000", 1.0, B_DASH)}
_PRINT = Style(
    name="print",
    about="black and grey only, serif (STIX): every element told apart by its line style; for journals",
    font_size=8.5, panel_height=3.2, max_width=7.0, max_height=9.0, png_dpi=600,
    rod=Ink("#000000", 1.5), sheet="#e4e4e4",
    particles=_frozen(_PRINT_PARTICLES),
    impact_colour="#000000", impact_size=4.5,
    rest_simultaneity=Ink("#000000", 0.9, REST_DOTS),
    moving_simultaneity=Ink("#000000", 0.7, MOVING_DASHDOT),
    other_axes=Ink("#555555", 0.7, AXES_DASHDOTDOT),
    light_cone=Ink("#555555", 0.6, CONE_SHORT_DASH),
    hyperbola=Ink("#8c8c8c", 0.45, HYPERBOLA_DASH),
    grid=Ink("#e6e6e6", 0.4),
    rod_interior=Ink("#9a9a9a", 0.4),  # grey, behind: the rod's own lines of simultaneity are the black ones
    rod_now=Ink("#000000", 0.55, ROD_NOW_DASH),
    clock_size=3.0,
    tick_length=3.5,
    ledger_particles=_frozen({**_PRINT_PARTICLES, "B": _PRINT_PARTICLES["B"]._replace(dashes=LEDGER_DASHDOT)}),
    hidden_edge="#888888", hidden_hatch="////",  # hatched: a light grey fill alone fades in print
    flash_colour="#000000", velocity_colour_map="print-greys",
    animation_dpi=150, animation_ticks=(2.5, 2.0), boost_size=(7.0, 6.0),
    handout_body_size=10.0,
    rc=_frozen({**_COMMON_RC, **_SERIF}),
    front=Ink("#000000", 0.45, FRONT_DASH),
    compression_ends=("#ffffff", "#4d4d4d"),
    force=Ink("#000000", 0.7), force_fill="#b8b8b8",  # darker than the sheet's grey, black arrows
)

# slides: the default's colours and dashes, with large type, thick lines and a 16:9 canvas
_SLIDES_PARTICLES = {name: ink._replace(width=2.6) for name, ink in _DEFAULT_PARTICLES.items()}
_SLIDES = _DEFAULT._replace(
    name="slides",
    about="colour, large type and thick lines on a 13.3 in (16:9) canvas: for projecting",
    font_size=17.0, panel_height=4.7, max_width=13.33, max_height=7.5, png_dpi=150,
    rod=_DEFAULT.rod._replace(width=3.2),
    particles=_frozen(_SLIDES_PARTICLES),
    impact_size=10.0,
    rest_simultaneity=_DEFAULT.rest_simultaneity._replace(width=2.4),
    moving_simultaneity=_DEFAULT.moving_simultaneity._replace(width=2.0),
    other_axes=_DEFAULT.other_axes._replace(width=1.6),
    light_cone=_DEFAULT.light_cone._replace(width=1.6),
    hyperbola=_DEFAULT.hyperbola._replace(width=1.1),
    grid=_DEFAULT.grid._replace(width=0.9),
    rod_interior=_DEFAULT.rod_interior._replace(width=1.1),
    rod_now=_DEFAULT.rod_now._replace(width=1.4),
    clock_size=6.0,
    tick_length=6.0,
    ledger_particles=_frozen(_SLIDES_PARTICLES),
    animation_dpi=100, animation_ticks=(4.0, 2.5), boost_size=(13.33, 7.5),
    handout_body_size=12.0,
    front=Ink("#1a1a1a", 0.9, FRONT_DASH),
    force=_DEFAULT.force._replace(width=1.5),
    rc=_frozen({**_DEFAULT.rc, "axes.linewidth": 1.4, "xtick.major.width": 1.4, "ytick.major.width": 1.4,
                "xtick.major.size": 6.0, "ytick.major.size": 6.0}),
)

#: read-only, like every mapping inside a Style: a caller cannot restyle another caller's figures
STYLES: Mapping[str, Style] = MappingProxyType({s.name: s for s in (_DEFAULT, _PRINT, _SLIDES)})

STYLE_NAMES = tuple(STYLES)
