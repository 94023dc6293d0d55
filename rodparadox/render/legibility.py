"""What keeps a panel legible when the rod is thin on the page (docs/plot.md, "Drawing the figures"): material lines thinned
to what the world-sheet can hold, and a magnified inset of a world-sheet thinner than a few millimetres.

Both measure the world-sheet as it is drawn: the least distance on the page between the world-lines of the rod's
two ends (for a rod moving at u in the panel's frame, its length L/gamma across the slant of its world-lines).
"""

from __future__ import annotations

import math
from typing import NamedTuple, Sequence

import numpy as np

from rodparadox.numbers import SCIENTIFIC_ABOVE, impact_name, nice_number, shown
from rodparadox.physics import rod
from rodparadox.physics.history import RodHistory
from rodparadox.physics.kinematics import Event
from rodparadox.physics.frames import FrameView, moving_frame, relative_velocity, rest_frame, sampling_tolerance
from rodparadox.render.labels import boxes_hit_segments
from rodparadox.render.layer_base import clip_line, impact_marker, line_kwargs
from rodparadox.render.styles import Style
from rodparadox.render.text import approximate_size
from rodparadox.tolerances import SAME_LINE

#: points in a millimetre
MM = 72 / 25.4
#: neighbouring material lines (and the rod's ends) stay at least this far apart on the page, points
MATERIAL_LINE_GAP = 1.0 * MM
#: a panel whose world-sheet is drawn thinner than this (points) gets a magnified inset of the rod's first impacts
INSET_BELOW = 3.0 * MM
#: in the inset the world-sheet is drawn at least this wide (points), unless the first impacts would not fit
INSET_SHEET = 6.0 * MM
#: the inset's side, as a fraction of the panel's shorter side: tried largest first
INSET_SIDES = (0.42, 0.36, 0.3)
#: room between the inset and the panel's frame, and around each label and marker it must not hide, points
INSET_MARGIN = 4.0


def polyline_gap(a: np.ndarray, b: np.ndarray) -> float:
    """The least distance between two polylines (n x 2) that do not cross: it is reached at a vertex of one of them."""
    return min(_vertices_to_segments(a, b), _vertices_to_segments(b, a))


def _vertices_to_segments(points: np.ndarray, polyline: np.ndarray) -> float:
    # x and t apart: each sum of two products is the one a sum over the last axis makes, without 3-d temporaries
    (x0, t0), (dx, dt) = polyline[:-1].T, (polyline[1:] - polyline[:-1]).T
    length2 = np.maximum(dx * dx + dt * dt, 1e-300)
    best = math.inf
    for chunk in np.array_split(points, max(1, len(points) * len(x0) // 200_000 + 1)):  # bounded memory
        if not (len(chunk) and len(x0)):
            continue
        rx, rt = chunk[:, 0, None] - x0[None, :], chunk[:, 1, None] - t0[None, :]
        s = np.clip((rx * dx + rt * dt) / length2, 0.0, 1.0)
        gx, gt = rx - s * dx, rt - s * dt
        best = min(best, float(np.sqrt((gx * gx + gt * gt).min())))
    return best


def sheet_width(worldlines: dict[str, np.ndarray], points_per_L: float) -> float:
    """The world-sheet's least width on the page, points: the least distance between its ends' world-lines."""
    return polyline_gap(worldlines["rod_left"], worldlines["rod_right"]) * points_per_L


# --- material lines -------------------------------------------------------------------------------------------

def material_lines_that_fit(history: RodHistory, fv: FrameView, worldlines: dict[str, np.ndarray], points_per_L: float,
                            asked: int) -> int:
    """How many of `asked` evenly spaced material lines fit in the panel with MATERIAL_LINE_GAP between neighbours
    (the ends included): a first guess from the world-sheet's least width, checked on the lines themselves."""
    if asked <= 0 or "rod_left" not in worldlines:
        return 0
    count = min(asked, max(0, math.floor(sheet_width(worldlines, points_per_L) / MATERIAL_LINE_GAP) - 1))
    L, (t_lo, t_hi) = history.scenario.L, fv.t_range
    tolerance = max(sampling_tolerance(history), 0.02 / points_per_L * L)  # a fiftieth of a point: enough to measure
    while count > 0:
        lines = [points / L for _, points in rod.material_lines(history, fv.frame.rapidity, count, t_lo, t_hi,
                                                                  tolerance)]
        chain = [worldlines["rod_left"], *lines, worldlines["rod_right"]]
        least = min(polyline_gap(a, b) for a, b in zip(chain, chain[1:])) * points_per_L
        if least >= MATERIAL_LINE_GAP:
            return count
        # the gaps shrink as 1/(count + 1): jump to the count whose least gap would be about the rule's
        count = min(count - 1, math.floor((count + 1) * least / MATERIAL_LINE_GAP) - 1)
    return 0


def material_lines_text(asked: int, drawn: dict[str, int]) -> str:
    """The legend's entry for the material lines: how many, and in which panels fewer (to keep them apart)."""
    fewer = [f"{n} in ({letter})" if n else f"none in ({letter})" for letter, n in sorted(drawn.items()) if n < asked]
    if not fewer:
        return "material points inside the rod"
    return f"material points inside the rod ({asked}; {', '.join(fewer)} to stay 1 mm apart)"


# --- the inset ------------------------------------------------------------------------------------------------

class Mark(NamedTuple):
    """An event the inset is centred on and marks: an impact, or a force's start or end on a rod driven by forces."""

    label: str  # for the artists' gids: B1, or left-start
    x: float  # where and when in the panel's frame, units of L
    t: float
    about: str  # what the inset's note says it is magnified at: $B_{1}$, or "the left force's start"


#: how the inset's note names a force's start or end
FORCE_MOMENTS = {"start": "starts", "end": "ends"}


def marks(history: RodHistory, fv: FrameView) -> list[Mark]:
    """The events of the panel the inset is centred on and marks: every impact; on a rod driven by forces (the
    capability `driving`), each force's start and end."""
    L = history.scenario.L
    out = [Mark(e.impact.label, e.x / L, e.t / L, impact_name(e.impact.label, math_text=True)) for e in fv.events]
    if history.driving is not None:
        for e in history.driving.force_events():
            if e.moment in FORCE_MOMENTS:
                seen = e.event.seen_from(fv.frame.rapidity)
                out.append(Mark(f"{e.end}-{e.moment}", seen.x / L, seen.t / L, f"the {e.end} force {FORCE_MOMENTS[e.moment]}"))
    return out


def _about(marks_: Sequence[Mark]) -> str:
    """The inset's note after its factor: at A₁, B₁ (impacts), where the left force starts, where both forces start."""
    if not marks_:
        return ""
    if all("-" not in m.label for m in marks_):  # impacts: B1, A1s
        return " at " + ", ".join(m.about for m in marks_)
    moments = {m.label.split("-")[1] for m in marks_}
    if len(marks_) == 2 and len(moments) == 1:  # both ends' forces at one instant
        return f" where both forces {FORCE_MOMENTS[moments.pop()][:-1]}"
    return " where " + " and ".join(m.about for m in marks_)


class InsetPlan(NamedTuple):
    """Where the inset goes in the panel (points from the axes' lower left: x, y, side), what it shows (the window
    x0, x1, t0, t1 in units of L) and its magnification against the panel."""

    rect: tuple[float, float, float]
    window: tuple[float, float, float, float]
    magnification: float
    about: tuple[Mark, ...]  # the events (impacts, or a force's start or end) it is centred on
    free: bool = False  # a driven rod's small motion: each end's world-line without the forces drawn too, dashed
    legend: bool = False  # the dashed lines named by the legend (`draws_motion_inset`), not by the inset's note


def inset_plan(fv: FrameView, L: float, worldlines: dict[str, np.ndarray], box: Sequence[float], width: float, height: float,
               keep_clear: list[tuple[float, float, float, float]], lines: list[np.ndarray],
               events: Sequence[Mark], hidden: Sequence[np.ndarray] = ()) -> InsetPlan | None:
    """The inset of a panel whose world-sheet is thinner than INSET_BELOW, or None.

    It is centred on the frame's first `events` (`marks`: impacts, or a driven rod's force starts; those at its
    earliest instant) and the rod at that instant,
    magnified a nice factor (1, 2, 2.5 or 5 times a power of ten) that draws the sheet at least INSET_SHEET wide
    while those stay inside; where that leaves less than 2 (the rod already at rest and long there), it shows the
    sheet where it is thinnest, nearest that instant, at the factor that draws it INSET_SHEET wide. It is
    placed in a corner of the panel where it hides none of `keep_clear` (boxes in points: labels, markers) and,
    where any of its sizes can, none of the world-lines `hidden` (units of L), crossing as few of `lines` as it
    can; None when no corner is free.
    """
    x0, x1, t0, t1 = box
    scale = width / (x1 - x0)  # points per L
    if "rod_left" not in worldlines or not events:
        return None
    thin = sheet_width(worldlines, scale)
    if thin >= INSET_BELOW:
        return None
    first_t = min(e.t for e in events)
    reach = max(abs(e.t) for e in events) + 1.0
    first = [e for e in events if abs(e.t - first_t) <= SAME_LINE * reach]  # one instant: Fig. 2's B1 and A1 in S'
    xs, ts = [e.x for e in first], [e.t for e in first]
    # and the whole rod at that instant: a turn is the rod's, from one end to the other
    xs += [float(np.interp(first_t, worldlines[end][:, 1], worldlines[end][:, 0])) for end in ("rod_left", "rod_right")]
    cx, ct = (min(xs) + max(xs)) / 2, (min(ts) + max(ts)) / 2
    spread = max(max(xs) - min(xs), max(ts) - min(ts))  # the first impacts' extent, units of L
    segments, never = _segments_pt(lines, box, scale), _segments_pt(list(hidden), box, scale)
    for fraction, strict in [(f, True) for f in INSET_SIDES] + [(f, False) for f in INSET_SIDES]:
        side = fraction * min(width, height)
        wanted = nice_number(INSET_SHEET / max(thin, 1e-300), "at_least")
        # the first impacts and the rod, and a margin of a fifth of the inset on each side, stay inside
        most = side * 0.6 / (max(spread, 1e-300) * scale)
        magnification = wanted if wanted <= most else nice_number(most, "at_most")
        about = tuple(first)
        centre = (cx, ct)
        if magnification < 2:  # the rod at its first impacts is too wide to magnify: the sheet where it is thinnest
            magnification, about, centre = wanted, (), _thinnest_near(worldlines, first_t)
        half = side / 2 / (scale * magnification)
        window = (centre[0] - half, centre[0] + half, centre[1] - half, centre[1] + half)
        spot = place_inset(side, width, height, keep_clear, segments, never if strict else ())
        if spot is not None:
            return InsetPlan((*spot, side), window, magnification, about)
    return None


#: a driven rod whose ends stray from their world-lines without the forces by less than this on the page (points:
#: less than the rod's ends are wide), but by more than MOTION_LEAST of L, gets an inset of where they stray most
MOTION_BELOW = 0.5 * MM
MOTION_LEAST = 1e-9


def free_line(history, fv: FrameView, end: str) -> tuple[np.ndarray, np.ndarray]:
    """A point (units of L) and the direction of the end's world-line in the panel's frame had no force acted: at
    rest in S at x = -L/2 or L/2 (where every driven rod starts)."""
    f, L = fv.frame.rapidity, history.scenario.L
    start = Event(-0.5 * L if end == "rod_left" else 0.5 * L, 0.0).seen_from(f)
    return np.array([start.x / L, start.t / L]), np.array([-math.sinh(f), math.cosh(f)])  # (dx, dt): at -tanh f


def straying(history, fv: FrameView, worldlines: dict[str, np.ndarray], events: Sequence[Mark]
             ) -> tuple[float, np.ndarray | None]:
    """How far (units of L) a driven rod's end strays most from its world-line without the forces while they act
    (in the panel's time, between the first force's start and the last one's end), and where; (0, None) if never."""
    if history.driving is None or "rod_left" not in worldlines or not events:
        return 0.0, None
    lo, hi = min(e.t for e in events), max(e.t for e in events)
    most, where = 0.0, None
    for end in ("rod_left", "rod_right"):
        points = worldlines[end]
        acting = points[(points[:, 1] >= lo) & (points[:, 1] <= hi)]
        if not len(acting):
            continue
        origin, along = free_line(history, fv, end)
        rel = acting - origin
        gap = np.abs(rel[:, 0] * along[1] - rel[:, 1] * along[0]) / math.hypot(*along)
        k = int(gap.argmax())
        if gap[k] > most:
            most, where = float(gap[k]), acting[k]
    return most, where


#: the room made for the inset of a driven rod's small motion: for an inset of INSET_SIDES[0] of the widened panel,
#: with a margin of this part of its height
INSET_ROOM_MARGIN = 0.06


def draws_motion_inset(history, fv: FrameView, worldlines: dict[str, np.ndarray], box: Sequence[float],
                       width: float, height: float) -> bool:
    """Whether a laid-out panel (`box` in units of L, `width` x `height` points) of a driven rod draws the inset of
    its small motion (`motion_inset_plan`'s rule; not a thin sheet's, `inset_plan`): its legend then names the
    inset's dashed lines, which the inset's note, in the ticks' type, has no room to."""
    if history.driving is None or "rod_left" not in worldlines:
        return False
    scale = width / (box[1] - box[0])
    if sheet_width(worldlines, scale) < INSET_BELOW:
        return False
    most, where = straying(history, fv, worldlines, marks(history, fv))
    return where is not None and MOTION_LEAST < most < MOTION_BELOW / scale


def needs_room(worldlines: dict[str, np.ndarray], box: Sequence[float], width: float, height: float) -> bool:
    """Whether no corner of a laid-out panel holds even the smallest inset without hiding a world-line (the rod at
    rest in S, as wide as its narrow panel: sears_moving at 0.95)."""
    scale = width / (box[1] - box[0])
    never = _segments_pt(list(worldlines.values()), box, scale)
    return place_inset(INSET_SIDES[-1] * min(width, height), width, height, [], np.empty((0, 4)), never) is None


def inset_room(worldlines: dict[str, np.ndarray], box: list[float]) -> None:
    """Widen a data box (x0, x1, t0, t1, units of L) on the left with a column beside the world-lines for the inset
    of the rod's small motion (`needs_room`): f from the world-lines' left edge to the box's, f = INSET_ROOM_MARGIN
    h + INSET_SIDES[0] w′ with w′ the widened width (at most the height h)."""
    x0, x1, t0, t1 = box
    h = t1 - t0
    left = float(min(points[:, 0].min() for points in worldlines.values()))
    side = INSET_SIDES[0]
    column = min((side * (max(x1, left) - left) + INSET_ROOM_MARGIN * h) / (1.0 - side), (side + INSET_ROOM_MARGIN) * h)
    box[0] = min(x0, left - column)


def motion_inset_plan(history, fv: FrameView, worldlines: dict[str, np.ndarray], box: Sequence[float], width: float,
                      height: float, keep_clear, lines, events: Sequence[Mark],
                      hidden: Sequence[np.ndarray] = (), named: bool = False) -> InsetPlan | None:
    """The inset of a driven rod's small motion, or None: where an end strays from its world-line without the
    forces by less than MOTION_BELOW on the page but more than MOTION_LEAST L (or, where the legend names its
    dashed lines, `named`, by any amount), centred where it strays most while its forces act (`straying`),
    magnified a nice factor that draws that straying INSET_BELOW wide; placed as `inset_plan` places its inset."""
    x0, x1, t0, t1 = box
    scale = width / (x1 - x0)
    most, where = straying(history, fv, worldlines, events)
    if where is None or not MOTION_LEAST < most or not (named or most < MOTION_BELOW / scale):
        return None
    magnification = nice_number(INSET_BELOW / (most * scale), "at_least")
    segments, never = _segments_pt(lines, box, scale), _segments_pt(list(hidden), box, scale)
    for strict in (True, False):  # hiding no world-line where any size can; else as few lines as it can
        for fraction in INSET_SIDES:
            side = fraction * min(width, height)
            half = side / 2 / (scale * magnification)
            window = (where[0] - half, where[0] + half, where[1] - half, where[1] + half)
            spot = place_inset(side, width, height, keep_clear, segments, never if strict else ())
            if spot is not None:
                return InsetPlan((*spot, side), window, magnification, (), free=True, legend=named)
    return None


def place_inset(side: float, width: float, height: float, keep_clear, segments, never=()) -> tuple[float, float] | None:
    """The corner of the panel for an inset `side` points wide that hides none of `keep_clear`, crosses none of
    `never` (segments in points: the world-lines, where the caller asks) and the fewest `segments`, or None."""
    corners = [(width - side - INSET_MARGIN, INSET_MARGIN), (INSET_MARGIN, height - side - INSET_MARGIN),
               (width - side - INSET_MARGIN, height - side - INSET_MARGIN), (INSET_MARGIN, INSET_MARGIN)]
    free = []
    for k, (x, y) in enumerate(corners):
        rect = (x - INSET_MARGIN, y - INSET_MARGIN, x + side + INSET_MARGIN, y + side + INSET_MARGIN)
        if any(rect[0] < b[2] and b[0] < rect[2] and rect[1] < b[3] and b[1] < rect[3] for b in keep_clear):
            continue
        if len(never) and boxes_hit_segments(np.array([rect]), never)[0] or _holds(rect, never):
            continue
        crossed = int(boxes_hit_segments(np.array([rect]), segments)[0]) if len(segments) else 0
        free.append((crossed, k, (x, y)))
    return min(free)[2] if free else None


def _holds(rect, segments) -> bool:
    """Whether a segment lies wholly inside the rectangle (it crosses none of its sides, yet is hidden)."""
    if not len(segments):
        return False
    inside = ((segments[:, 0] > rect[0]) & (segments[:, 0] < rect[2]) & (segments[:, 1] > rect[1])
              & (segments[:, 1] < rect[3]))
    return bool(inside.any())


def _thinnest_near(worldlines: dict[str, np.ndarray], t: float) -> tuple[float, float]:
    """Of the places where the world-sheet is within 5 % of its least width, the one nearest the time t: the
    midpoint of a vertex of one end's world-line and the nearest point of the other's (units of L)."""
    places = []
    for one, other in (("rod_left", "rod_right"), ("rod_right", "rod_left")):
        points, line = worldlines[one], worldlines[other]
        p0, d = line[:-1], line[1:] - line[:-1]
        rel = points[:, None, :] - p0[None]
        s = np.clip((rel * d[None]).sum(2) / np.maximum((d * d).sum(1), 1e-300)[None], 0.0, 1.0)
        nearest = p0[None] + s[:, :, None] * d[None]
        gaps = np.hypot(*(points[:, None, :] - nearest).transpose(2, 0, 1))
        k = gaps.argmin(1)
        places.append(np.column_stack([gaps[np.arange(len(points)), k],
                                       (points + nearest[np.arange(len(points)), k]) / 2]))
    places = np.concatenate(places)
    thin = places[places[:, 0] <= 1.05 * places[:, 0].min()]
    x, t_ = thin[np.abs(thin[:, 2] - t).argmin(), 1:]
    return float(x), float(t_)


def _segments_pt(lines: list[np.ndarray], box: Sequence[float], scale: float) -> np.ndarray:
    parts = [np.column_stack([q[:-1], q[1:]]) for q in
             (np.column_stack([(p[:, 0] - box[0]) * scale, (p[:, 1] - box[2]) * scale]) for p in lines) if len(q) > 1]
    return np.concatenate(parts) if parts else np.empty((0, 4))


def label_boxes(ax, box: Sequence[float], scale: float, pad: float) -> list[tuple[float, float, float, float]]:
    """The boxes (points from the axes' lower left, padded) of the texts already placed in the axes, and of their
    leader lines."""
    out = []
    for text in ax.texts:
        w, h, _ = approximate_size(text.get_text(), text.get_fontsize())
        x, y = text.get_position()
        px, py = (x - box[0]) * scale, (y - box[2]) * scale
        left = px - {"left": 0.0, "center": w / 2, "right": w}[text.get_ha()]
        bottom = py - {"bottom": 0.0, "baseline": 0.0, "center": h / 2, "center_baseline": h / 2, "top": h}[text.get_va()]
        out.append((left - pad, bottom - pad, left + w + pad, bottom + h + pad))
    for line in ax.lines:
        if "-leader-" in (line.get_gid() or ""):
            xs, ys = (np.asarray(line.get_xdata(), float) - box[0]) * scale, (np.asarray(line.get_ydata(), float) - box[2]) * scale
            out.append((xs.min() - pad, ys.min() - pad, xs.max() + pad, ys.max() + pad))
    return out


def draw_inset(ax, plan: InsetPlan, history: RodHistory, fv: FrameView, style: Style, letter: str, font_size: float,
               width: float, height: float, events: Sequence[Mark], simultaneity: bool = True) -> tuple:
    """The inset as a child Axes of the panel: the world-sheet, the rod's ends, the particles, the lines of
    simultaneity through the impacts (where the panel draws them: `simultaneity`; a worksheet asks them) and the
    impacts, at equal scales, framed, its magnification written in it."""
    x, y, side = plan.rect
    inset = ax.inset_axes((x / width, y / height, side / width, side / height), zorder=9)
    inset.set_gid(f"{letter}-inset")
    wx0, wx1, wt0, wt1 = plan.window
    inset.set_xlim(wx0, wx1)
    inset.set_ylim(wt0, wt1)
    inset.set_xticks([])
    inset.set_yticks([])
    inset.set_facecolor("white")
    for spine in inset.spines.values():
        spine.set_linewidth(0.8)
    L = history.scenario.L
    # sampled finely enough for the magnified window: a thousandth of its side
    tolerance = min(sampling_tolerance(history), (wx1 - wx0) * L * 1e-3)
    window = (wx0 - (wx1 - wx0), wx1 + (wx1 - wx0), wt0 - (wt1 - wt0), wt1 + (wt1 - wt0))
    if tolerance < 1e-2 * sampling_tolerance(history):  # a deep magnification: only what the inset shows is sampled
        # that finely (masses 1e9 at v = 0.6: the whole causal world-lines at 1e-9 L, 6e6 points, took minutes)
        points = {name: p / L for name, p in fv.worldline_points(tolerance, (window[2] * L, window[3] * L)).items()}
    else:
        points = {name: p / L for name, p in fv.worldline_points(tolerance).items()}
    ends = [_runs(points[end], window) for end in ("rod_left", "rod_right")]
    artists = []
    from matplotlib.patches import Polygon  # noqa: PLC0415  (matplotlib is loaded by now: the panel is drawn)
    left, right = points["rod_left"], points["rod_right"]
    if len(left) and len(right):  # the whole sheet, as in the panel: the inset's frame clips it
        artists.append(inset.add_artist(Polygon(np.concatenate([left, right[::-1]]), closed=True,
                                                facecolor=style.sheet, edgecolor="none", zorder=1,
                                                gid=f"{letter}-inset-sheet")))
    for name, ink, z in (("A", style.particles["A"], 5), ("B", style.particles["B"], 5)):
        if name in points:
            for k, run in enumerate(_runs(points[name], window)):
                artists += inset.plot(run[:, 0], run[:, 1], **line_kwargs(ink), zorder=z, gid=f"{letter}-inset-{name}-{k}")
    if plan.free:  # each end without the forces: the small motion is the gap between the two
        for end in ("rod_left", "rod_right"):
            origin, along = free_line(history, fv, end)
            segment = clip_line(origin[0], origin[1], along[0], along[1], plan.window)
            if segment is not None:
                artists += inset.plot(segment[:, 0], segment[:, 1], color=style.rod.colour, linewidth=0.8,
                                      linestyle=(0, (4.0, 2.0)), zorder=3, gid=f"{letter}-inset-free-{end}")
    for end, runs in zip(("rod_left", "rod_right"), ends):
        for k, run in enumerate(runs):
            artists += inset.plot(run[:, 0], run[:, 1], **line_kwargs(style.rod), zorder=4,
                                  gid=f"{letter}-inset-{end}-{k}")
    v = history.scenario.v
    for family, ink, frame in (("rest", style.rest_simultaneity, rest_frame()),
                               ("moving", style.moving_simultaneity, moving_frame(v)))[:2 if simultaneity else 0]:
        slope = relative_velocity(frame.velocity, fv.frame.velocity)
        for e in events:
            segment = clip_line(e.x, e.t, 1.0, slope, plan.window)
            if segment is not None:
                artists += inset.plot(segment[:, 0], segment[:, 1], **line_kwargs(ink), zorder=2,
                                      gid=f"{letter}-inset-simultaneity-{family}-{e.label}")
    for e in events:
        if wx0 <= e.x <= wx1 and wt0 <= e.t <= wt1:
            artists += inset.plot([e.x], [e.t], **impact_marker(style), zorder=7,
                                  gid=f"{letter}-inset-impact-{e.label}")
    # a worksheet's (`simultaneity` off: it asks which impacts share an instant) names no impacts an instant groups:
    # "×5 at B₁, A₁" in S′ told fig2's worksheet that B₁ and A₁ are simultaneous there
    about = _about(plan.about) if simultaneity or len(plan.about) < 2 else ""
    m = plan.magnification  # 1000 in digits (shown would write 1e+03); from 10⁶ on, 2.5×10⁶ as the ticks write it
    # in mathtext, as the impacts' names are: mathtext's fonts lack the superscript digits plain text would use
    factor = f"$\\times{f'{m:.10g}' if m < SCIENTIFIC_ABOVE else shown(m, 3, math_text=True)}$"
    pad = 3.0
    # the note inside the inset: without the impacts' names if they make it too wide, in smaller type if need be
    candidates = ([factor + about] if about else []) + [factor]
    if plan.free:  # the dashed lines named (by the legend, where the diagram knew of the inset: `draws_motion_inset`)
        candidates = [factor] if plan.legend else [factor + "; dashed: no force"]
    for text in candidates:
        w, h, _ = approximate_size(text, font_size)
        if w <= side - 2 * pad:
            break
    else:
        font_size *= (side - 2 * pad) / w
        w, h, _ = approximate_size(text, font_size)
    # in the corner of the inset whose note crosses the fewest of its lines and markers
    scale = side / (wx1 - wx0)
    drawn = [np.column_stack([line.get_xdata(), line.get_ydata()]).astype(float) for line in inset.lines]
    segments = _segments_pt([d for d in drawn if len(d) > 1], plan.window, scale)
    dots = [((d[0, 0] - wx0) * scale, (d[0, 1] - wt0) * scale) for d in drawn if len(d) == 1]
    corners = [(pad, side - pad - h, "left", "top"), (side - pad - w, side - pad - h, "right", "top"),
               (pad, pad, "left", "bottom"), (side - pad - w, pad, "right", "bottom")]

    def crossed(corner) -> int:
        x0_, y0_ = corner[:2]
        hit = int(boxes_hit_segments(np.array([(x0_, y0_, x0_ + w, y0_ + h)]), segments)[0]) if len(segments) else 0
        return hit + sum(x0_ - 4 <= dx <= x0_ + w + 4 and y0_ - 4 <= dy <= y0_ + h + 4 for dx, dy in dots) * 10

    x_, y_, ha, va = min(corners, key=crossed)
    note = inset.text((x_ if ha == "left" else x_ + w) / side, (y_ + h if va == "top" else y_) / side, text,
                      transform=inset.transAxes, ha=ha, va=va, fontsize=font_size, zorder=8, gid=f"{letter}-inset-note",
                      bbox=dict(boxstyle="square,pad=0.15", facecolor="white", edgecolor="none"))
    return (inset, *artists, note)


def _runs(points: np.ndarray, window) -> list[np.ndarray]:
    """The polyline's runs of segments whose bounding boxes meet `window` (x0, x1, t0, t1): what the inset draws."""
    x0, x1, t0, t1 = window
    a, b = points[:-1], points[1:]
    meets = ((np.maximum(a[:, 0], b[:, 0]) >= x0) & (np.minimum(a[:, 0], b[:, 0]) <= x1)
             & (np.maximum(a[:, 1], b[:, 1]) >= t0) & (np.minimum(a[:, 1], b[:, 1]) <= t1))
    runs, start = [], None
    for k, hit in enumerate(list(meets) + [False]):
        if hit and start is None:
            start = k
        elif not hit and start is not None:
            runs.append(points[start:k + 1])
            start = None
    return runs
