"""The causal rod's own layers (docs/model.md, "The causal rod"): its world-sheet shaded by compression lam, the light
fronts that carry each disturbance, and each contact drawn as the stretch where a particle rides with an end.

Each applies (`CausalLayer.applies`) to a run with fronts (`RodHistory.fronts` not None) alone: the diagram draws
a layer only where it applies, and its legend entry is None elsewhere; the rigid layers that need the rigid part
(the fans of the rod's own lines of simultaneity, `RodHistory.turning`) apply only where it is.

The shading is exact where it matters: the material chart is cut along the light lines u = T + X and w = T - X
at every front (a jump of r+ or r-) and inside every piece where an invariant varies, and each cell, bounded by
two u-lines and two w-lines, is a parallelogram with light-line sides in every frame (t + x = e^-f a(u) is
constant along u), filled with lam = exp(-(r+ + r-)/2) at its centre: so the shading jumps exactly at the fronts
drawn over it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from matplotlib.collections import PolyCollection
from matplotlib.colors import LinearSegmentedColormap, TwoSlopeNorm
from matplotlib.legend_handler import HandlerBase
from matplotlib.lines import Line2D
from matplotlib.patches import Rectangle

from rodparadox.numbers import shown
from rodparadox.physics.frames import sampling_tolerance
from rodparadox.render.layer_base import Layer, LayerArtists, line_handle
from rodparadox.render.shading import FRONT_JUMP, SHADES, cell_edges
from rodparadox.render.styles import Style

#: swatches in the legend's ramp of the compression scale
SWATCHES = 7


# --- the compression scale: pure numbers, shared by the layer, its legend entry and the tests ----------------

def compression_norm(history) -> TwoSlopeNorm:
    """ln lam to [0, 1]: stretched below 0.5, unstressed at 0.5, compressed above (each side its own range)."""
    lo, hi = history.fronts.compression_range()
    return TwoSlopeNorm(0.0, min(lo, -1e-3), max(hi, 1e-3))


def compression_colour_map(style: Style) -> LinearSegmentedColormap:
    """Lightness falls steadily from the most stretched to the most compressed (greyscale-safe): in colour a
    pale warm tint for tension, the plain sheet for an unstressed rod, the rod's blue deepening for compression;
    in print white, the plain sheet's grey, then darker greys."""
    stretched, compressed = style.compression_ends
    return LinearSegmentedColormap.from_list(f"compression-{style.name}", [stretched, style.sheet, compressed])


def compression_at(history, u: float, w: float) -> float:
    """lam at the chart point of light-line coordinates u = T + X, w = T - X (the same in every frame)."""
    sol = history.solution
    return math.exp(-0.5 * (sol.r_plus(u) + sol.r_minus(w)))


# --- cells and fronts in a frame --------------------------------------------------------------------------------

def _frame_chart(history, f: float):
    """(U, V) = (t + x, t - x) in the frame of rapidity f of the light lines u and w."""
    sol = history.solution
    return (lambda u: math.exp(-f) * sol.a(u)), (lambda w: math.exp(f) * sol.b(w))


def chart_window(history, f: float, t_lo: float, t_hi: float) -> tuple[float, float, float, float]:
    """(u_lo, u_hi, w_lo, w_hi): the light-line coordinates the world-sheet spans between t_lo and t_hi."""
    L = history.scenario.L
    T = {(end, t): history.end_chart_time(end, f, t) for end in ("left", "right") for t in (t_lo, t_hi)}
    return T["left", t_lo], T["right", t_hi] + L, T["right", t_lo] - L, T["left", t_hi]


def _cell_edges(invariant, lo: float, hi: float, L: float, step: float) -> np.ndarray:
    """The cuts of [lo, hi] (`shading.cell_edges`) at every piece boundary of the invariant."""
    return cell_edges(invariant.r, invariant.breaks(lo, hi), lo, hi, L, step)


def compression_cells(history, f: float, t_lo: float, t_hi: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The world-sheet's cells between t_lo and t_hi in the frame of rapidity f: (polygons (n, 4, 2) of [x, t],
    their ln lam, their centres (n, 2) as (u, w)). Cells wholly outside the rod (X < 0 or X > L) are left out;
    the rest is clipped to the world-sheet when drawn."""
    sol, L = history.solution, history.scenario.L
    u_lo, u_hi, w_lo, w_hi = chart_window(history, f, t_lo, t_hi)
    U_of, V_of = _frame_chart(history, f)
    low, high = history.fronts.compression_range()
    step = 2 * (high - low) / SHADES  # ln lam is -(r+ + r-)/2: a change of r by this is one shade
    us, ws = _cell_edges(sol.plus, u_lo, u_hi, L, step), _cell_edges(sol.minus, w_lo, w_hi, L, step)
    U, V = np.array([U_of(u) for u in us]), np.array([V_of(w) for w in ws])
    i, j, ln_lam, centres = cells_in_rod(sol, us, ws, L)
    corners = [(U[i], V[j]), (U[i + 1], V[j]), (U[i + 1], V[j + 1]), (U[i], V[j + 1])]
    polygons = np.stack([np.column_stack([(Uc - Vc) / 2, (Uc + Vc) / 2]) for Uc, Vc in corners], axis=1)
    return polygons, ln_lam, centres


def cells_in_rod(sol, us, ws, L: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The diamond cells between consecutive chart edges `us` (u = T + X) and `ws` (w = T - X) that reach into the
    rod (0 < X < L): their edge indices i (into us) and j (into ws), ln lam at each centre, the centres (n, 2) as
    (u, w). Shared by the frames' panels (`compression_cells`) and the rod's own view (rod_panel)."""
    um, wm = 0.5 * (us[1:] + us[:-1]), 0.5 * (ws[1:] + ws[:-1])
    rp, rm = np.array([sol.r_plus(u) for u in um]), np.array([sol.r_minus(w) for w in wm])
    i, j = np.meshgrid(np.arange(len(um)), np.arange(len(wm)), indexing="ij")
    keep = (us[1:][i] - ws[:-1][j] > 0) & (us[:-1][i] - ws[1:][j] < 2 * L)
    i, j = i[keep], j[keep]
    return i, j, -0.5 * (rp[i] + rm[j]), np.column_stack([um[i], wm[j]])


def fronts(history, f: float, t_lo: float, t_hi: float) -> list[tuple[str, float, np.ndarray]]:
    """The light fronts in the frame of rapidity f between t_lo and t_hi: (family, chart coordinate, [[x, t], [x, t]])
    from the left end to the right end, clipped to the window. A front is a jump of an invariant: r+ jumps along a
    line u = const (moving left, t + x constant), r- along w = const (moving right)."""
    sol, L = history.solution, history.scenario.L
    u_lo, u_hi, w_lo, w_hi = chart_window(history, f, t_lo, t_hi)
    out = []
    for family, invariant, lo, hi in (("+", sol.plus, u_lo, u_hi), ("-", sol.minus, w_lo, w_hi)):
        for s in invariant.breaks(lo, hi):
            if abs(invariant.r(s) - invariant.r(np.nextafter(s, -math.inf))) <= FRONT_JUMP:
                continue
            # the front meets the left end (X = 0) at T = s, the right end (X = L) at T = s -+ L
            ends = [_end_point(history, f, 0.0, s), _end_point(history, f, L, s - L if family == "+" else s + L)]
            segment = _clip_t(np.array([[e.x, e.t] for e in ends]), t_lo, t_hi)
            if segment is not None:
                out.append((family, float(s), segment))
    return out


def _end_point(history, f: float, X: float, T: float):
    from rodparadox.physics.kinematics import ChartCurve

    return ChartCurve(history.solution, X, T, T, f).point(T)


def _clip_t(segment: np.ndarray, t_lo: float, t_hi: float) -> np.ndarray | None:
    (x0, t0), (x1, t1) = segment
    if max(t0, t1) <= t_lo or min(t0, t1) >= t_hi or t0 == t1:
        return None
    def at(t):
        return [x0 + (x1 - x0) * (t - t0) / (t1 - t0), t]
    a, b = (at(min(max(t, t_lo), t_hi)) for t in (t0, t1))
    return np.array([a, b])


# --- the layers --------------------------------------------------------------------------------------------------

def sheet_window(panel) -> tuple[float, float]:
    """The frame's times the panel draws the rod's ends over (a boost animation's window is wider than the
    frame's own): the shading and the fronts fill the same stretch of the world-sheet."""
    ends = np.concatenate([panel.worldlines["rod_left"], panel.worldlines["rod_right"]])
    return float(ends[:, 1].min()) * panel.L, float(ends[:, 1].max()) * panel.L


class _Ramp(HandlerBase):
    """A legend handle: the compression scale as a row of swatches, lightest (stretched) to darkest."""

    def create_artists(self, legend, handle, x0, y0, width, height, fontsize, trans):
        colours = handle.get_gid().split(",")
        w = width / len(colours)
        return [Rectangle((x0 + k * w, y0 - 0.15 * height), w, 1.3 * height, facecolor=c, edgecolor="none",
                          transform=trans) for k, c in enumerate(colours)]


class RampHandle(Line2D):
    """The compression scale's legend handle (its colours in its gid: `_Ramp` draws them)."""


HANDLER_MAP = {RampHandle: _Ramp()}


@dataclass(frozen=True)
class CausalLayer(Layer):
    """A layer only a rod with fronts has (the causal rod: its chart, `solution`, is what these layers read)."""

    def applies(self, history):
        return history.fronts is not None


@dataclass(frozen=True)
class Compression(CausalLayer):
    """The causal rod's world-sheet shaded by compression lam (its own scale, greyscale-safe), clipped to the
    sheet (the `sheet` layer's polygon, drawn with no fill for the causal rod)."""

    name = "compression"

    def draw(self, ax, panel):
        history = panel.history
        L, f = panel.L, panel.view.frame.rapidity
        polygons, ln_lam, _ = compression_cells(history, f, *sheet_window(panel))
        cmap, norm = compression_colour_map(panel.style), compression_norm(history)
        colours = cmap(norm(ln_lam))
        # rasterised: thousands of cells would make a vector file megabytes (`diagram.RASTER_DPI`)
        mesh = PolyCollection(polygons / L, facecolors=colours, edgecolors=colours, linewidths=0.25, zorder=1.1,
                              antialiaseds=False, rasterized=True, gid=f"{panel.letter}-compression")
        ax.add_collection(mesh, autolim=False)
        left, right = panel.worldlines["rod_left"], panel.worldlines["rod_right"]
        from matplotlib.patches import Polygon

        clip = Polygon(np.concatenate([left, right[::-1]]), closed=True, transform=ax.transData)
        mesh.set_clip_path(clip)
        return LayerArtists(artists=(mesh,))

    def legend_entry(self, style, history, options, clock_step=None):
        if not self.applies(history):
            return None
        lo, hi = history.fronts.compression_range()
        cmap, norm = compression_colour_map(style), compression_norm(history)
        ramp = np.linspace(lo, hi, SWATCHES)
        handle = RampHandle([], [])
        handle.set_gid(",".join(_hex(cmap(norm(value))) for value in ramp))
        return handle, (f"compression \N{GREEK SMALL LETTER LAMDA}: {lam_text(math.exp(lo))} to "
                        f"{lam_text(math.exp(hi))}, 1 unstressed")


def lam_text(lam: float) -> str:
    """lam to two significant digits in plain decimals (115, 6.5, 0.38, 0.0086): never e-notation; more digits
    where two would read an unstressed 1 for a stressed rod (1.0004 at v = 0.01, not 1.0); beyond a million or
    below 1e-4, a power of ten (2×10⁹: masses 1e9 squeeze the rod so, and "2030345398" is read by no one)."""
    if not 1e-4 <= lam < 1e6:
        return shown(lam, 2)
    decimals = max(0, 1 - math.floor(math.log10(lam)))
    while decimals < 12 and lam != 1.0 and float(f"{lam:.{decimals}f}") == 1.0:
        decimals += 1
    return f"{lam:.{decimals}f}"


def _hex(rgba) -> str:
    return "#" + "".join(f"{round(255 * c):02x}" for c in rgba[:3])


@dataclass(frozen=True)
class Fronts(CausalLayer):
    """The light fronts that carry each disturbance across the causal rod: thin light lines from end to end, which
    no label may cross."""

    name = "fronts"

    def draw(self, ax, panel):
        drawn, segments = [], []
        for k, (family, _s, segment) in enumerate(fronts(panel.history, panel.view.frame.rapidity,
                                                         *sheet_window(panel))):
            segment = segment / panel.L
            drawn.append(panel.plot(ax, segment, panel.style.front, 3.2, f"{panel.letter}-front-{k}"))
            segments.append(segment)
        # obstacles: a label on a front would hide where the signal runs (over the shading it may sit)
        return LayerArtists(artists=tuple(drawn), obstacles=tuple(segments))

    def legend_entry(self, style, history, options, clock_step=None):
        if not self.applies(history):
            return None
        if history.driving is not None and not any(p.jumps() for _, p in history.driving.profiles()):
            return None  # forces without a jump: the compression changes smoothly, no front is drawn
        return line_handle(style.front), "light front (a jump in \N{GREEK SMALL LETTER LAMDA})"


@dataclass(frozen=True)
class Contacts(CausalLayer):
    """Each contact of the causal rod: a broad band in the particle's colour where it rides with the end."""

    name = "contacts"

    def draw(self, ax, panel):
        history = panel.history
        st, L = panel.style, panel.L
        tolerance = sampling_tolerance(history)
        drawn = []
        for name, pieces in panel.view.segments:
            if name not in st.particles:
                continue
            k = 0
            for piece in pieces:
                if not hasattr(piece, "chart"):  # a free flight between contacts: a straight line
                    continue
                points = piece.sample(tolerance) / L
                ink = st.particles[name]
                line, = ax.plot(points[:, 0], points[:, 1], color=ink.colour, alpha=0.35,
                                linewidth=st.rod.width * 3.2, solid_capstyle="butt", zorder=3.8,
                                gid=f"{panel.letter}-contact-{name}-{k}")
                drawn.append(line)
                k += 1
        return LayerArtists(artists=tuple(drawn))

    def legend_entry(self, style, history, options, clock_step=None):
        if not self.applies(history) or not history.impacts:  # no contacts: a rod driven by forces
            return None
        return (Line2D([], [], color="#777777", alpha=0.35, linewidth=style.rod.width * 3.2, solid_capstyle="butt"),
                "contact: particle rides with end")

