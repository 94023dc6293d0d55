"""World-lines -> matplotlib Figures: the paper's Minkowski diagrams (docs/plot.md, "Drawing the figures").

Never pyplot, never files: `draw` builds a `matplotlib.figure.Figure`
directly and `figure_bytes` serialises it deterministically; `output` writes.
Each panel is one frame's own coordinates in units of L (t up, x right, equal
scales, so light runs at 45 degrees) and shows, as in the paper's Figs. 1-2:
the rod's two end world-lines (solid) with its world-sheet shaded, the
particles' world-lines (dashed, labelled A and B), every impact (marker and
label, the same in every panel), and through every impact the line of
simultaneity of S and of S'. Every artist carries a gid (`a-rod_left`,
`b-impact-B1`, ...), which is also its id in the SVG.

Importing the package loads no matplotlib: each name below is looked up in its module on first use
(`render.draw`, `from rodparadox.render import draw`), so `render.styles`, which the command line's
help reads, stays light.

The package, its imports running one way (text <- layout, labels <- layers <- panel <- diagram):
  text     what the panels say (frame names, titles, tick labels) and text sizes in points, without a renderer
  mathtext_parses  each mathtext string parsed once per process, not once per renderer (imported by text)
  layout   the layout in points: data boxes, rows of panels, tick steps, title lines, the legend's shape
  labels   label placement: beside an anchor, clear of lines, markers and other labels
  layer_base  what every layer shares: options, the panel context, the Layer class, inks as keywords
  layers   one class per element (world-sheet, rod ends, particles, impacts, lines of simultaneity, extras):
           it draws itself, names what labels must avoid, and gives its own legend entry; ink from the style
  causal_layers  the causal rod's own layers: its sheet shaded by compression, its light fronts, its contacts
  panel    one panel: its axes, then every enabled layer, then the labels
  diagram  `draw` (a Figure the layout sizes), `draw_both` (two rod models, a row each), `draw_into` (a Figure or SubFigure the caller sized), bytes
  styles   the three styles as plain data (inks, dashes, rcParams, sizes): no matplotlib
  ledger_figure  the ledger as a figure (momentum and energy against each frame's time)
  colour_scale  which velocity each colour of a strip means, in one frame (pure: no matplotlib)
  rod_panel  the rod's own view (`--frame rod`): its chart, the rod a fixed strip, as a panel beside a diagram's
  strip    one frame's space at one instant (the rod coloured by its material points' velocities, the
           particles, the impacts): `draw_strip`/`update_strip` for animations
  strip_block  a block of stills, the rod at successive instants (`draw_strips_into`, `strips_size`)
  strip_windows  which stretch of x each still shows: one shared range, or each row following the rod (pure)

The layout is computed in points rather than by matplotlib's layout
engines: the figure's size follows from the data (equal scales), labels are
placed where they cross no line and no other label, and the result does not
depend on a renderer, so it is fast and byte-for-byte reproducible.
"""

import importlib

#: each public name, and the module of this package that defines it
_HOME = {
    "PANEL_LETTERS": "rodparadox.physics.frames", "relative_velocity": "rodparadox.physics.frames",
    **dict.fromkeys(("Diagram", "PanelInfo", "draw", "draw_both", "draw_into", "draw_panel_into", "figure_bytes", "natural_size", "style_context",
                     "FIGURE_METADATA"), "rodparadox.render.diagram"),
    **dict.fromkeys(("StripArtists", "draw_strip", "update_strip"), "rodparadox.render.strip"),
    **dict.fromkeys(("draw_strips_into", "strips_size"), "rodparadox.render.strip_block"),
    "LABEL_REACH": "rodparadox.render.labels",
    **dict.fromkeys(("draw_rod_panel", "draw_rod_view", "draw_rod_view_into", "least_height", "rod_view_size"),
                    "rodparadox.render.rod_panel"),
    **dict.fromkeys(("LAYERS", "LEGEND", "Layer", "LayerArtists", "Options", "PanelContext"), "rodparadox.render.layers"),
    **dict.fromkeys(("approximate_size", "axis_label", "coordinate_names", "frame_symbol",
                     "impact_text_size", "measuring_fonts", "text_size", "text_size_cache_info"),
                    "rodparadox.render.text"),
}

__all__ = sorted(_HOME)


def __getattr__(name: str):
    if name not in _HOME:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(_HOME[name]), name)
    globals()[name] = value
    return value
