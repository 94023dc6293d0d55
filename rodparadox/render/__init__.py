"""World-lines -> matplotlib Figures: the paper's Minkowski diagrams (README, "Drawing the figures").

Never pyplot, never files: `draw` builds a `matplotlib.figure.Figure`
directly and `figure_bytes` serialises it deterministically; `output` writes.
Each panel is one frame's own coordinates in units of L (t up, x right, equal
scales, so light runs at 45 degrees) and shows, as in the paper's Figs. 1-2:
the rod's two end world-lines (solid) with its world-sheet shaded, the
particles' world-lines (dashed, labelled A and B), every impact (marker and
label, the same in every panel), and through every impact the line of
simultaneity of S and of S'. Every artist carries a gid (`a-rod_left`,
`b-impact-B1`, ...), which is also its id in the SVG.

The package, its imports running one way (text <- layout, labels <- layers <- panel <- diagram):
  text     what the panels say (frame names, titles, tick labels) and text sizes in points, without a renderer
  layout   the layout in points: data boxes, rows of panels, tick steps, title lines, the legend's shape
  labels   label placement: beside an anchor, clear of lines, markers and other labels
  layers   one class per element (world-sheet, rod ends, particles, impacts, lines of simultaneity, extras):
           it draws itself, names what labels must avoid, and gives its own legend entry; ink from the style
  panel    one panel: its axes, then every enabled layer, then the labels
  diagram  `draw` (a Figure the layout sizes), `draw_into` (a Figure or SubFigure the caller sized), bytes
  strip    one frame's space at one instant (the rod coloured by its material points' velocities, the
           particles, the impacts): `draw_strip`/`update_strip` for animations, `draw_strips_into` for a
           block of stills, the rod at successive instants

The layout is computed in points rather than by matplotlib's layout
engines: the figure's size follows from the data (equal scales), labels are
placed where they cross no line and no other label, and the result does not
depend on a renderer, so it is fast and byte-for-byte reproducible.
"""

from ..frames import PANEL_LETTERS, relative_velocity
from .diagram import Diagram, PanelInfo, draw, draw_into, figure_bytes, style_context
from .strip import StripArtists, draw_strip, draw_strips_into, update_strip
from .labels import LABEL_REACH
from .layers import LAYERS, LEGEND, Layer, LayerArtists, Options, PanelContext
from .text import (_measured, approximate_size, axis_label, coordinate_names, frame_symbol, impact_text,
                   impact_text_size, text_size)

__all__ = ["PANEL_LETTERS", "LABEL_REACH", "LAYERS", "LEGEND", "Diagram", "Layer", "LayerArtists", "Options",
           "PanelContext", "PanelInfo", "StripArtists", "approximate_size", "axis_label", "coordinate_names", "draw", "draw_into", "draw_strip", "draw_strips_into",
           "figure_bytes", "frame_symbol", "impact_text", "impact_text_size", "relative_velocity", "style_context",
           "text_size", "update_strip"]
