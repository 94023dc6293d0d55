"""The elements of a diagram, one layer each: it draws itself into a panel's axes and gives its own legend entry.

A layer is a small frozen object with
  name                                   its key in `Diagram.artists`;
  enabled(options) -> bool               whether the options ask for it;
  draw(ax, panel) -> LayerArtists        its artists in one panel, the polylines labels must avoid (`obstacles`)
                                         or may cross on a white ground (`guides`), and its labels to place;
  legend_entry(style, history, options)  its (handle, text) in the legend, or None.
Every layer's ink comes from the style through `line_kwargs` / `marker_kwargs`, so a style says once how a kind
of line looks. `LAYERS` is the drawing order (with the zorders, it fixes the SVG's order of elements), `LEGEND`
the legend's order (the paper's caption: the bodies, then the impacts, then the lines of simultaneity, then the
extras), and a layer's `label_rank` the order its labels are placed in (markers' labels first: they must sit
beside their marker).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np
from matplotlib.lines import Line2D
from matplotlib.patches import Patch, Polygon

from rodparadox.physics import kinematics
from rodparadox.physics import rod
from rodparadox.physics.types import WORLDLINE_NAMES
from rodparadox.physics.history import RodHistory
from rodparadox.physics.frames import Frame, moving_frame, relative_velocity, rest_frame, sampling_tolerance
from rodparadox.physics.kinematics import Event, HyperbolicArc
from rodparadox.numbers import impact_name, shown
from rodparadox.render.styles import Ink, Style
from rodparadox.render.layer_base import (Layer, LayerArtists, Options, PanelContext, clip_line, clock_marker,  # noqa: F401
                                          contacts_last, impact_marker, has_fronts, line_handle, line_kwargs,
                                          marker_kwargs, own_now_lines, separation_marker, widest_line)
from rodparadox.render.force_layers import ForceBands, ForceMoments
from rodparadox.render.labels import Label
from rodparadox.render.legibility import material_lines_text
from rodparadox.render.text import coordinate_names, frame_symbol, impact_text_size
from rodparadox.tolerances import SAME_LINE

#: calibration hyperbolae are sampled to this fraction of the panel's larger side (a few hundredths of a point on
#: any page), so their cost follows what is drawn, not v or L; never finer than the world-lines' tolerance
HYPERBOLA_SAMPLING = 1e-5
#: length of a light cone's arms (each way, in t) as a fraction of the shorter side of the panel
CONE_REACH = 0.16


# --- the layers ----------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Grid(Layer):
    name = "grid"

    def enabled(self, options):
        return options.grid

    def draw(self, ax, panel):
        ax.grid(True, **line_kwargs(panel.style.grid), zorder=0)
        ax.set_axisbelow(True)
        return LayerArtists(artists=tuple(ax.get_xgridlines()) + tuple(ax.get_ygridlines()))


@dataclass(frozen=True)
class WorldSheet(Layer):
    """The rod's world-sheet, shaded between its ends' world-lines (its legend entry is the rod's)."""

    name = "sheet"

    def draw(self, ax, panel):
        left, right = panel.worldlines["rod_left"], panel.worldlines["rod_right"]
        # add_artist, not fill: the limits are fixed, and fill would walk every vertex to update them
        sheet = ax.add_artist(Polygon(np.concatenate([left, right[::-1]]), closed=True, facecolor=panel.style.sheet,
                                      edgecolor="none", zorder=1, gid=f"{panel.letter}-sheet"))
        return LayerArtists(artists=(sheet,))


@dataclass(frozen=True)
class MaterialLines(Layer):
    """Options.rod_lines: world-lines of material points inside the rod (docs/model.md, "Inside the rod")."""

    name = "rod-lines"

    def enabled(self, options):
        return bool(options.rod_lines)

    def draw(self, ax, panel):
        t_lo, t_hi = panel.view.t_range
        count = panel.options.rod_lines if panel.rod_lines is None else panel.rod_lines
        lines = rod.material_lines(panel.history, panel.view.frame.rapidity, count, t_lo, t_hi,
                                   sampling_tolerance(panel.history))
        drawn, points_drawn = [], []
        for k, (_sigma, points) in enumerate(lines, start=1):
            points = points / panel.L
            drawn.append(panel.plot(ax, points, panel.style.rod_interior, 3, f"{panel.letter}-rod-line-{k}"))
            points_drawn.append(points)
        return LayerArtists(artists=tuple(drawn), guides=tuple(points_drawn))

    def legend_entry(self, style, history, options, clock_step=None):
        return line_handle(style.rod_interior), material_lines_text(options.rod_lines, {})


@dataclass(frozen=True)
class RodNow(Layer):
    """Options.rod_now: the rod's own lines of simultaneity, drawn across the rod only (a rigid rod's: a model
    without them, `history.turning` None, draws none)."""

    name = "rod-now"

    def enabled(self, options):
        return options.rod_now

    def applies(self, history):  # a rigid rod: its turns' lines; a driven one: its lines of each stage
        return history.turning is not None or bool(own_now_lines(history))

    def draw(self, ax, panel):
        eta = panel.view.frame.rapidity
        t_lo, t_hi = panel.view.t_range
        lines = [(a.seen_from(eta), b.seen_from(eta)) for a, b in own_now_lines(panel.history)]
        drawn, segments = [], []
        for k, (a, b) in enumerate((a, b) for a, b in lines if min(a.t, b.t) >= t_lo and max(a.t, b.t) <= t_hi):
            segment = np.array([[a.x, a.t], [b.x, b.t]]) / panel.L
            drawn.append(panel.plot(ax, segment, panel.style.rod_now, 3.5, f"{panel.letter}-rod-now-{k}"))
            segments.append(segment)
        return LayerArtists(artists=tuple(drawn), guides=tuple(segments))

    def legend_entry(self, style, history, options, clock_step=None):
        return line_handle(style.rod_now), "the rod’s own lines of simultaneity"


@dataclass(frozen=True)
class Clocks(Layer):
    """Options.proper_time: ticks of equal proper time on every world-line, the same events in every panel."""

    name = "clocks"

    def enabled(self, options):
        return options.proper_time

    def applies(self, history):
        return history.fronts is None  # a chart curve's proper time is not integrated yet (plot refuses it)

    def draw(self, ax, panel):
        st, L, eta = panel.style, panel.L, panel.view.frame.rapidity
        t_lo, t_hi = panel.view.t_range
        # the same events in every panel: counted in S (tau = 0 at t = 0 there), then boosted
        x0, x1 = (value * L for value in panel.box[:2])
        drawn = []
        named = ((name, panel.history.worldline(name)) for name in WORLDLINE_NAMES)  # the rod interface's names
        for name, worldline in ((name, line) for name, line in named if line is not None):
            ink = st.rod if name.startswith("rod_") else st.particles[name]
            # the times in S at which this world-line enters and leaves the panel's window, a little widened for
            # rounding: only ticks there are sought, so their number is bounded by the window, not by t = 0's distance
            seen = worldline.seen_from(eta)
            s_lo, s_hi = (seen.event_at_time(t).seen_from(-eta).t for t in (t_lo, t_hi))
            slack = 1e-9 * (s_hi - s_lo + L)
            marks = [e.seen_from(eta) for _, e in kinematics.proper_time_events(
                worldline, panel.clock_step, s_lo - slack, s_hi + slack)]
            # within the frame's time window, where the world-lines are drawn
            marks = np.array([[e.x, e.t] for e in marks if t_lo <= e.t <= t_hi and x0 <= e.x <= x1]).reshape(-1, 2) / L
            line, = ax.plot(marks[:, 0], marks[:, 1], **clock_marker(st, ink), zorder=6,
                            gid=f"{panel.letter}-clock-{name}")
            drawn.append(line)
        return LayerArtists(artists=tuple(drawn))

    def legend_entry(self, style, history, options, clock_step=None):
        step = clock_step / history.scenario.L
        return Line2D([], [], **clock_marker(style, style.rod)), f"proper time: a tick every {shown(step, 4)} $L$"


@dataclass(frozen=True)
class RodEnds(Layer):
    """The world-lines of the rod's two ends (solid); the legend shows them over the world-sheet."""

    name = "rod"

    def draw(self, ax, panel):
        drawn = tuple(panel.plot(ax, panel.worldlines[end], panel.style.rod, 4, f"{panel.letter}-{end}")
                      for end in ("rod_left", "rod_right"))
        return LayerArtists(artists=drawn, obstacles=tuple(panel.worldlines[end] for end in ("rod_left", "rod_right")))

    def legend_entry(self, style, history, options, clock_step=None):
        sheet = Patch(facecolor=style.sheet, edgecolor="none")
        return (sheet, line_handle(style.rod)), "rod: its ends (solid), world-sheet shaded"


@dataclass(frozen=True)
class Particle(Layer):
    """A particle's world-line (dashed), its letter beside the first part of it, else further along where there is room."""

    particle: str
    label_rank = 2  # several anchors to choose from: placed last

    @property
    def name(self) -> str:
        return f"particle-{self.particle}"

    def draw(self, ax, panel):
        name = self.particle
        if name not in panel.worldlines:
            return LayerArtists()
        ink, points, box = panel.style.particles[name], panel.worldlines[name], panel.box
        line = panel.plot(ax, points, ink, 5, f"{panel.letter}-{name}")
        first = next((e.t / panel.L for e in panel.view.events if e.impact.particle == name), points[-1, 1])
        span = points[-1, 1] - points[0, 1]
        times = [points[0, 1] + min(0.1 * (box[3] - box[2]), 0.6 * (first - points[0, 1]))]
        times += [points[0, 1] + f * span for f in (0.35, 0.65, 0.9)]
        anchors = tuple((float(np.interp(t, points[:, 1], points[:, 0])), t) for t in times)
        label = Label(f"{panel.letter}-particle-label-{name}", name, anchors, 180.0 if name == "A" else 0.0,
                      ink.colour, panel.fs["particle"], italic=True, off_sheet=True)
        return LayerArtists(artists=(line,), obstacles=(points,), labels=(label,))

    def legend_entry(self, style, history, options, clock_step=None):
        if history.worldline(self.particle) is None:
            return None
        return line_handle(style.particles[self.particle]), f"particle {self.particle}"


@dataclass(frozen=True)
class Simultaneity(Layer):
    """Lines of simultaneity of S (`rest`) or of S' (`moving`) through every impact; one line for impacts on it."""

    family: str  # rest or moving
    zorder: float

    @property
    def name(self) -> str:
        return f"simultaneity-{self.family}"

    def enabled(self, options):
        return options.simultaneity

    def ink(self, style: Style) -> Ink:
        return style.rest_simultaneity if self.family == "rest" else style.moving_simultaneity

    def frame(self, v: float) -> Frame:
        return rest_frame() if self.family == "rest" else moving_frame(v)

    def draw(self, ax, panel):
        slope = relative_velocity(self.frame(panel.v).velocity, panel.view.frame.velocity)  # dt/dx of the line in this panel
        events = [e for e in panel.events() if e[0] in panel.simultaneity_labels]  # a causal rod's first contacts
        events += panel.force_events()  # a rod driven by forces: each force's start and end
        drawn: list[tuple[float, str, list[str]]] = []
        for label, _, x, t in events:
            intercept = t - slope * x
            same = next((d for d in drawn if abs(d[0] - intercept) <= SAME_LINE * (1 + abs(intercept))), None)
            if same is not None:
                same[2].append(label)
            else:
                drawn.append((intercept, label, [label]))
        artists, segments = [], []
        for intercept, label, labels in drawn:
            x, t = next((e[2], e[3]) for e in events if e[0] == label)
            segment = clip_line(x, t, 1.0, slope, panel.box)
            if segment is None:
                continue
            artists.append(panel.plot(ax, segment, self.ink(panel.style), self.zorder,
                                      f"{panel.letter}-simultaneity-{self.family}-{'+'.join(labels)}"))
            segments.append(segment)
        return LayerArtists(artists=tuple(artists), obstacles=tuple(segments))

    def legend_entry(self, style, history, options, clock_step=None):
        return line_handle(self.ink(style)), f"line of simultaneity of {frame_symbol(self.frame(history.scenario.v))}"


@dataclass(frozen=True)
class OtherAxes(Layer):
    """Options.other_axes: the other paper frame's x and t axes through the shared origin, tilted, each named at its end."""

    name = "other-axes"
    label_rank = 1

    def enabled(self, options):
        return options.other_axes

    def draw(self, ax, panel):
        ink, letter, (x0, x1, t0, t1) = panel.style.other_axes, panel.letter, panel.box
        artists, segments, labels = [], [], []
        for other in (rest_frame(), moving_frame(panel.v)):
            if other.name == panel.view.frame.name:
                continue
            u = relative_velocity(other.velocity, panel.view.frame.velocity)
            xn, tn = coordinate_names(other)
            for axis, (dx, dt), name in (("t", (u, 1.0), tn), ("x", (1.0, u), xn)):
                segment = clip_line(0.0, 0.0, dx, dt, panel.box)
                if segment is None:
                    continue
                artists.append(panel.plot(ax, segment, ink, 2, f"{letter}-axis-{other.name}-{axis}"))
                segments.append(segment)
                end = segment[1]
                inward = math.degrees(math.atan2((t0 + t1) / 2 - end[1], (x0 + x1) / 2 - end[0]))
                labels.append(Label(f"{letter}-axis-label-{other.name}-{axis}", name, ((end[0], end[1]),), inward,
                                    ink.colour, panel.fs["impact"], italic=True, guides_block=True))
        return LayerArtists(artists=tuple(artists), guides=tuple(segments), labels=tuple(labels))

    def legend_entry(self, style, history, options, clock_step=None):
        return line_handle(style.other_axes), "axes of the other frame"


@dataclass(frozen=True)
class LightCones(Layer):
    """Options.light_cones: short arms of every impact's light cone."""

    name = "light-cones"

    def enabled(self, options):
        return options.light_cones

    def draw(self, ax, panel):
        x0, x1, t0, t1 = panel.box
        reach = CONE_REACH * min(x1 - x0, t1 - t0)  # short arms: a cone per impact, not a lattice of lines
        artists, segments = [], []
        for label, _, x, t in panel.events():
            for side, slope in (("right", 1.0), ("left", -1.0)):
                segment = clip_line(x, t, 1.0, slope, (x - reach, x + reach, t - reach, t + reach))
                segment = None if segment is None else clip_line(x, t, 1.0, slope, panel.box)
                if segment is not None:
                    segment = np.clip(segment, [[x - reach, t - reach]], [[x + reach, t + reach]])
                    artists.append(panel.plot(ax, segment, panel.style.light_cone, 1.5,
                                              f"{panel.letter}-light-cone-{label}-{side}"))
                    segments.append(segment)
        return LayerArtists(artists=tuple(artists), guides=tuple(segments))

    def legend_entry(self, style, history, options, clock_step=None):
        return line_handle(style.light_cone), "light cone of an impact"


@dataclass(frozen=True)
class Hyperbolae(Layer):
    """Options.hyperbolae: calibration hyperbolae t^2 - x^2 = +-k^2 about the shared origin, k a multiple of the t step."""

    name = "hyperbolae"

    def enabled(self, options):
        return options.hyperbolae

    def draw(self, ax, panel):
        artists, curves = [], []
        for k, points in enumerate(self.curves(panel)):
            artists.append(panel.plot(ax, points, panel.style.hyperbola, 1.2, f"{panel.letter}-hyperbola-{k}"))
            curves.append(points)
        return LayerArtists(artists=tuple(artists), guides=tuple(curves))

    @staticmethod
    def curves(panel: PanelContext) -> list[np.ndarray]:
        """The pieces of the branches inside the panel, sampled within the drawing's tolerance.

        Only the part of each branch inside the box is sampled, to a tolerance
        that is a fixed fraction of the box (never finer than the world-lines'):
        the number of points is then bounded whatever v, L or the gaps make of
        the box (a branch of radius k is within HYPERBOLA_SAMPLING of the
        panel's size with some hundred points).
        """
        x0, x1, t0, t1 = panel.box
        step = panel.steps[1]  # the t step is the finer
        reach = max(abs(x0), abs(x1), abs(t0), abs(t1))
        tolerance = max(sampling_tolerance(panel.history) / panel.L, HYPERBOLA_SAMPLING * max(x1 - x0, t1 - t0))
        out = []
        for m in range(1, 7):
            k = m * step
            if k > reach:
                break
            for swap in (False, True):  # x-branches (space-like), then t-branches (time-like)
                for side in (1, -1):
                    along = (x0, x1) if swap else (t0, t1)  # the coordinate that runs along the branch
                    across = (t0, t1) if swap else (x0, x1)  # the one that is side * k cosh(phi) on it
                    for lo, hi in _branch_in_box(k, side, along, across):
                        arc = HyperbolicArc(Event(0.0, 0.0), k, side, lo, hi)
                        points = arc.sample(tolerance)
                        if swap:
                            points = points[:, ::-1]
                        inside = ((points[:, 0] >= x0) & (points[:, 0] <= x1) & (points[:, 1] >= t0)
                                  & (points[:, 1] <= t1))
                        if inside.any():
                            out.append(points)
        return out

    def legend_entry(self, style, history, options, clock_step=None):
        # the variables in math italics (mathtext), the words upright
        return line_handle(style.hyperbola), r"calibration hyperbolae $t^2 - x^2 = \pm k^2$"


def _branch_in_box(k: float, side: int, along: tuple[float, float], across: tuple[float, float]) -> list[tuple[float, float]]:
    """The ranges of phi (increasing) where the branch side * k (cosh phi, sinh phi) (across, along; sinh runs along
    the branch) lies within the box's two ranges: one range through the vertex, two beside it, or none."""
    a_lo, a_hi = (along if side == 1 else (-along[1], -along[0]))  # side * range: k sinh(phi) lies in it
    c_lo, c_hi = (across if side == 1 else (-across[1], -across[0]))  # and k cosh(phi) in this
    if c_hi < k or a_hi < a_lo:
        return []
    lo = math.asinh(max(min(a_lo / k, 1e6), -1e6))
    hi = math.asinh(max(min(a_hi / k, 1e6), -1e6))
    outer = math.acosh(min(c_hi / k, 1e6))
    inner = math.acosh(c_lo / k) if c_lo > k else 0.0
    ranges = [(-outer, -inner), (inner, outer)] if inner > 0.0 else [(-outer, outer)]
    out = []
    for r_lo, r_hi in ranges:
        a, b = max(lo, r_lo), min(hi, r_hi)
        if a < b:
            out.append((a, b))
    return out


@dataclass(frozen=True)
class Impacts(Layer):
    """Every impact: a marker on top, labelled the same in every panel (B1 -> B₁)."""

    name = "impacts"
    label_rank = 0  # beside its marker, before any other label takes the room

    def draw(self, ax, panel):
        st, fs, letter = panel.style, panel.fs, panel.letter
        markers, labels = [], []
        for label, end, x, t in panel.events():
            contact = label in panel.contact_labels
            marker, = ax.plot([x], [t], **(impact_marker(st) if contact else separation_marker(st)), zorder=7,
                              gid=f"{letter}-impact-{label}")
            markers.append(marker)
            text, size = (impact_name(label, math_text=True), impact_text_size(label, fs["impact"])[:2]) if contact \
                else separation_text(label, fs["impact"])
            labels.append(Label(f"{letter}-impact-label-{label}", text, ((x, t),),
                                0.0 if end == "right" else 180.0, st.impact_colour, fs["impact"],
                                avoid_radius=st.impact_size / 2 + 1.0, box_size=size))
        return LayerArtists(artists=tuple(markers), labels=tuple(labels))

    def legend_entry(self, style, history, options, clock_step=None):
        if not history.impacts:  # a rod driven by forces: nothing strikes it
            return None
        if contacts_last(history):  # named by its first contact, so the legend shows how labels read
            first = next(i for i in history.impacts if not i.is_separation)
            return Line2D([], [], **impact_marker(style)), f"contact ({impact_name(first.label)})"
        return Line2D([], [], **impact_marker(style)), "impact"


@dataclass(frozen=True)
class Separations(Layer):
    """The legend's entry for the causal rod's separations (the `impacts` layer draws their hollow markers)."""

    name = "separations"

    def applies(self, history):
        return contacts_last(history)

    def draw(self, ax, panel):
        return LayerArtists()

    def legend_entry(self, style, history, options, clock_step=None):
        first = next((i for i in history.impacts if i.is_separation), None)
        if first is None:
            return None
        name = impact_name(first.label[:-1])
        return Line2D([], [], **separation_marker(style)), f"separation ({name[0]}\N{PRIME}{name[1:]})"


def separation_text(label: str, size: float) -> tuple[str, tuple[float, float]]:
    """A separation's label, mathtext (A1s -> A′₁, `numbers.impact_name`), and a box at least as large as it draws."""
    contact = label[:-1] if label.endswith("s") else label
    w, h, _ = impact_text_size(contact, size)
    return impact_name(label, math_text=True), (w + 0.35 * size, h)


_SHEET, _ROD_LINES, _ROD_NOW, _CLOCKS, _ROD = WorldSheet(), MaterialLines(), RodNow(), Clocks(), RodEnds()
_A, _B = Particle("A"), Particle("B")
_REST, _MOVING = Simultaneity("rest", 2.2), Simultaneity("moving", 2.1)
_OTHER_AXES, _CONES, _HYPERBOLAE, _IMPACTS = OtherAxes(), LightCones(), Hyperbolae(), Impacts()
_SEPARATIONS = Separations()
_FORCES, _FORCE_EVENTS = ForceBands(), ForceMoments()  # a rod driven by forces: each force, its start and end
#: the causal rod's own layers, by name: `causal_layers` is imported only when one is drawn (`drawing_order`)
_COMPRESSION, _FRONTS, _CONTACTS = "compression", "fronts", "contacts"

#: the drawing order: the grid behind, the world-sheet, the rod's inside, its ends, the particles, the lines of
#: simultaneity, the extras' lines, the impacts on top (zorders decide what covers what; this order breaks ties)
_DRAWING = (Grid(), _SHEET, _COMPRESSION, _ROD_LINES, _FRONTS, _ROD_NOW, _CLOCKS, _CONTACTS, _FORCES, _ROD, _A, _B,
            _REST, _MOVING, _OTHER_AXES, _CONES, _HYPERBOLAE, _IMPACTS, _SEPARATIONS, _FORCE_EVENTS)
#: the legend's order, as the paper's caption reads: bodies, impacts, lines of simultaneity, then the extras
_LEGEND = (_ROD, _COMPRESSION, _FORCES, _A, _B, _IMPACTS, _SEPARATIONS, _CONTACTS, _FORCE_EVENTS, _FRONTS, _REST,
           _MOVING, _OTHER_AXES, _CONES, _ROD_LINES, _ROD_NOW, _CLOCKS, _HYPERBOLAE)
assert set(_LEGEND) <= set(_DRAWING)


@functools.cache
def _ordered(order: tuple, causal: bool) -> tuple[Layer, ...]:
    """`order` with the causal rod's layers in their places (their module imported then), or without them."""
    if not causal:  # they draw nothing, and give no legend entry, for another rod
        return tuple(layer for layer in order if not isinstance(layer, str))
    from rodparadox.render.causal_layers import Compression, Contacts, Fronts

    own = {layer.name: layer for layer in (Compression(), Fronts(), Contacts())}
    return tuple(own[layer] if isinstance(layer, str) else layer for layer in order)


def drawing_order(history, legend: bool = False) -> tuple[Layer, ...]:
    """The layers that may draw for `history` (one or a tuple), in `LAYERS`' order (`legend`: in `LEGEND`'s)."""
    causal = any(has_fronts(h) for h in (history if isinstance(history, tuple) else (history,)))
    return _ordered(_LEGEND if legend else _DRAWING, causal)


def __getattr__(name: str):
    """`LAYERS` (the drawing order) and `LEGEND` (the legend's order): every layer, the causal rod's included."""
    if name in ("LAYERS", "LEGEND"):
        return _ordered(_LEGEND if name == "LEGEND" else _DRAWING, True)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def legend_entries(style: Style, history: RodHistory, options: Options, clock_step: float,
                   rod_lines: dict[str, int] | None = None) -> tuple[list, list[str]]:
    """The legend's handles and texts: every enabled layer's own entry, in LEGEND order (`clock_step`: the proper
    time between clock ticks, chosen by the diagram from its panels' time spans; `rod_lines`: the material lines
    drawn in each panel, when fewer than asked)."""
    # --rod both: each layer's entry for the first rod giving one, a rod whose contacts last first (they're contacts)
    histories = sorted(history, key=lambda h: not contacts_last(h)) if isinstance(history, tuple) else (history,)
    enabled = [layer for layer in drawing_order(history, legend=True) if layer.enabled(options)]
    entries = [next((e for e in (layer.legend_entry(style, h, options, clock_step) for h in histories
                                 if layer.applies(h)) if e is not None), None) for layer in enabled]  # drawn only
    if rod_lines and options.rod_lines:
        thinned = material_lines_text(options.rod_lines, rod_lines)
        entries = [(entry[0], thinned) if layer is _ROD_LINES and entry is not None else entry
                   for layer, entry in zip(enabled, entries)]
    entries = [entry for entry in entries if entry is not None]
    return [h for h, _ in entries], [text for _, text in entries]
