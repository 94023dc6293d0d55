"""The styles' inks as the page draws them (docs/plot.md, "Drawing the figures": the elements and their inks): the same
colours, widths (points) and dash patterns (in units of the line width) as the SVG figures, read from
`render.styles`, which imports no matplotlib. Pure."""

from __future__ import annotations

from typing import Any

from rodparadox.render.styles import SOLID, STYLES, Ink

#: the strip's colours without matplotlib, evenly spaced along the colour maps `render.strip` uses (tests compare
#: them with matplotlib's): the default's RdBu_r, eleven stops
RDBU_R = ("#053061", "#2065ab", "#4393c3", "#90c4dd", "#d1e5f0", "#f7f6f6", "#fddbc7", "#f3a481", "#d6604d",
          "#b1182b", "#67001f")
#: the print ramp (`render.strip`: matplotlib's Greys from 0.12 to 0.88), light for slower, dark for faster
PRINT_GREYS = ("#f1f1f1", "#dddddd", "#c5c5c5", "#a7a7a7", "#878787", "#696969", "#4a4a4a", "#232323")


def ink(value: Ink) -> dict[str, Any]:
    dashes = [] if value.dashes == SOLID else list(value.dashes[1])
    return {"colour": value.colour, "width": value.width, "dashes": dashes}


def inks() -> dict[str, Any]:
    """Every style's inks and sizes, by style name."""
    out = {}
    for name, style in STYLES.items():
        out[name] = {
            "about": style.about, "font_size": style.font_size, "serif": name == "print",
            "rod": ink(style.rod), "sheet": style.sheet,
            "particles": {p: ink(i) for p, i in style.particles.items()},
            "impact_colour": style.impact_colour, "impact_size": style.impact_size,
            "rest": ink(style.rest_simultaneity), "moving": ink(style.moving_simultaneity),
            "light_cone": ink(style.light_cone), "grid": ink(style.grid), "flash": style.flash_colour,
            "colours": list(PRINT_GREYS if style.velocity_colour_map == "print-greys" else RDBU_R),
            # the causal rod (`render.causal_layers`): its light fronts, material lines and compression scale
            "front": ink(style.front), "rod_interior": ink(style.rod_interior),
            "compression": [style.compression_ends[0], style.sheet, style.compression_ends[1]],
        }
    return out


def force_inks() -> dict[str, Any]:
    """Every style's inks of the forces on the ends (`render.force_layers`: the band's edge and arrows, its fill),
    by style name: embedded only in a page that draws forces."""
    return {name: {"force": ink(style.force), "force_fill": style.force_fill} for name, style in STYLES.items()}
