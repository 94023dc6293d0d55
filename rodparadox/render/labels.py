"""Label placement in points: each label beside its anchor, clear of every line, marker and earlier label."""

from __future__ import annotations

import math
from operator import itemgetter
from typing import NamedTuple

import numpy as np

from rodparadox.render.text import text_size

#: an impact's label sits within this many points of its marker's edge, or a thin leader line ties it to the marker
LABEL_REACH = 12.0
#: the cost of a label on a marker, another label or a leader, or of a leader across one of those (`place`): more
#: than any number of lines crossed, less than no room at all
FAULT = 10 ** 6
#: how many times `place` arranges a panel's labels again, those that found no place free of faults first
REORDERINGS = 6


class Label(NamedTuple):
    """A text to place beside one of its anchors (data units, best first), clear of every line, marker and label."""

    gid: str
    text: str
    anchors: tuple[tuple[float, float], ...]
    preferred: float  # direction, degrees, counter-clockwise from +x
    colour: str
    size: float
    avoid_radius: float = 0.0  # points kept clear around the first anchor (a marker)
    italic: bool = False  # plain text in italics: a single letter needs no mathtext
    guides_block: bool = False  # an axis's name: it must not sit on any line, its own included
    box_size: tuple[float, float] | None = None  # (width, height) in points, if not measured from `text`
    off_sheet: bool = False  # a particle's letter: on the rod's shaded world-sheet only as a last resort, as on a line


class Area(NamedTuple):
    """Where labels go: the axes' limits (x0, x1, t0, t1, units of L) and its size in points."""

    box: tuple[float, float, float, float]
    width: float
    height: float


def boxes_hit_segments(boxes: np.ndarray, segments: np.ndarray) -> np.ndarray:
    """For each box (k, 4: xmin ymin xmax ymax), how many segments (n, 4: x0 y0 x1 y1) cross it (Liang-Barsky)."""
    if len(segments) == 0:
        return np.zeros(len(boxes), dtype=int)
    return np.count_nonzero(_hits(boxes, segments), axis=1)


def _hits(boxes: np.ndarray, segments: np.ndarray) -> np.ndarray:
    """(k, n): whether segment n crosses box k.

    Only the pairs whose extents come within a billionth of the largest coordinate of each other are tested
    (`_liang_barsky`): a segment farther from a box than that, on either axis, is rejected by the test itself
    (an entry past its end, an exit before its start, or parallel and outside), by a margin far above rounding."""
    scale = max(float(np.abs(boxes).max(initial=0.0)), float(np.abs(segments).max(initial=0.0)))
    if not math.isfinite(scale):
        return _liang_barsky(boxes[:, None, :], segments[None, :, :])
    margin = 1e-9 * scale
    near = ((np.maximum(segments[:, 0], segments[:, 2])[None, :] >= boxes[:, 0, None] - margin)
            & (np.minimum(segments[:, 0], segments[:, 2])[None, :] <= boxes[:, 2, None] + margin)
            & (np.maximum(segments[:, 1], segments[:, 3])[None, :] >= boxes[:, 1, None] - margin)
            & (np.minimum(segments[:, 1], segments[:, 3])[None, :] <= boxes[:, 3, None] + margin))
    k, n = np.nonzero(near)
    # each pair's coordinates gathered as rows (4, pairs), contiguous: the test runs on rows, not strided columns
    # (239 place() calls of the label tests: 1.39 s -> 1.34 s with `_crosses`)
    near[k, n] = _crosses(*segments.T[:, n], *boxes.T[:, k])
    return near


def _liang_barsky(boxes: np.ndarray, segments: np.ndarray) -> np.ndarray:
    """Whether each segment (..., 4: x0 y0 x1 y1) crosses its box (..., 4: xmin ymin xmax ymax), element by element.

    Liang-Barsky: the segment's parameters where it enters and leaves each of the box's slabs, lo the latest
    entry (from 0), hi the earliest exit (from 1); a segment parallel to a slab and outside it misses. Per axis,
    the sign of the segment's step there decides which of the two edges it enters by, so each edge's parameter
    is computed once and taken as an entry or an exit."""
    x0, y0, x1, y1 = (segments[..., i] for i in range(4))
    b = [boxes[..., i] for i in range(4)]
    lo, hi = 0.0, 1.0
    ok = True
    with np.errstate(divide="ignore", invalid="ignore"):
        for start, step, low, high in ((x0, x1 - x0, b[0], b[2]), (y0, y1 - y0, b[1], b[3])):
            zero = step == 0
            safe = np.where(zero, 1.0, step)
            at_low, at_high = (start - low) / -safe, (high - start) / safe  # the edges' parameters
            forward, backward = step > 0, step < 0
            lo = np.maximum(lo, np.where(forward, at_low, np.where(backward, at_high, -np.inf)))
            hi = np.minimum(hi, np.where(forward, at_high, np.where(backward, at_low, np.inf)))
            if np.any(zero):
                ok = ok & ~(zero & ((start - low < 0) | (high - start < 0)))
    return ok & (lo <= hi)


def _crosses(x0, y0, x1, y1, x_min, y_min, x_max, y_max) -> np.ndarray:
    """`_liang_barsky` for finite coordinates (`_hits`), given apart, with fewer array operations: a step (finite or
    overflowing to an infinity, never NaN) that is not forward is backward or zero, so its entry is its low edge's
    parameter going forward and its high edge's otherwise, its exit the other one; a zero step (parallel to the slab)
    neither enters nor leaves it (-inf, inf), and misses when outside. The same booleans."""
    lo, hi = 0.0, 1.0
    ok = True
    with np.errstate(divide="ignore", invalid="ignore"):
        for start, step, low, high in ((x0, x1 - x0, x_min, x_max), (y0, y1 - y0, y_min, y_max)):
            zero = step == 0
            any_zero = zero.any()
            safe = np.where(zero, 1.0, step) if any_zero else step
            at_low, at_high = (start - low) / -safe, (high - start) / safe  # the edges' parameters
            forward = step > 0
            entry, leave = np.where(forward, at_low, at_high), np.where(forward, at_high, at_low)
            if any_zero:
                entry[zero], leave[zero] = -np.inf, np.inf
                ok = ok & ~(zero & ((start - low < 0) | (high - start < 0)))
            lo, hi = np.maximum(lo, entry), np.minimum(hi, leave)
    return ok & (lo <= hi)


def place(ax, frame: Area, labels: list[Label], obstacles: list[np.ndarray], guides: list[np.ndarray],
          widest_line: float, impact_size: float, font_size: float, crowded: bool = False,
          sheet: np.ndarray | None = None) -> list[tuple]:
    """Put each label near its anchor where its box crosses no line, marker or earlier label; returns each label's
    artists (its text, and its leader line if it has one), in the order of `labels`.

    Candidates ring the anchor (24 directions, growing distances). The first
    free one wins: nearest ring first, then nearest the preferred direction.
    Crossing a guide (an extra's line) costs as much as three rings outwards,
    and such a label gets a white ground; crossing anything else is a last resort.
    A label marked `off_sheet` (a particle's letter) whose box's centre lies on the rod's world-sheet (`sheet`, the
    polygon of its ends, units of L) costs as a line crossed: read as the rod's, it sits beside the sheet (issue 24:
    B on the causal rod's sheet in unequal_masses at 0.6 and fig1 at 0.95).
    A leader is 0.6 pt wide for a label of `impact_size` in a style of 9 pt type, scaled with both.
    `crowded` (the causal rod: contacts, separations and re-contacts at one end): four more rings.
    A fault -- a label on a marker, on a placed label or on a leader, or the leader it would need across a marker,
    a placed label or another leader -- costs more than any number of lines crossed (FAULT): a label is read through
    a line, not for another. Where some label found no place free of faults and lines, the panel's labels are
    arranged again with those labels first (REORDERINGS times at most; a label placed early takes the room a later
    one needed), and the arrangement with the fewest faults, then the fewest labels on a line, is drawn.
    """
    x0, x1, t0, t1 = frame.box
    sx, st_ = frame.width / (x1 - x0), frame.height / (t1 - t0)  # points per unit of L (equal, up to rounding)

    def to_pt(points: np.ndarray) -> np.ndarray:
        return np.column_stack([(points[:, 0] - x0) * sx, (points[:, 1] - t0) * st_])

    def segments_of(polylines: list[np.ndarray]) -> np.ndarray:
        parts = [np.column_stack([q[:-1], q[1:]]) for q in map(to_pt, polylines) if len(q) > 1]
        return np.concatenate(parts) if parts else np.empty((0, 4))

    def extents(segments: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The segments with their (xmax, ymax, xmin, ymin), found once for every chunk of candidates."""
        return segments, np.stack([np.maximum(segments[:, 0], segments[:, 2]), np.maximum(segments[:, 1], segments[:, 3]),
                                   np.minimum(segments[:, 0], segments[:, 2]), np.minimum(segments[:, 1], segments[:, 3])])

    def crossings(boxes: np.ndarray, segments_and_extents: tuple[np.ndarray, np.ndarray]) -> np.ndarray:
        segments, (x_max, t_max, x_min, t_min) = segments_and_extents
        lo, hi = boxes[:, :2].min(0), boxes[:, 2:].max(0)  # only nearby segments can be hit
        near = (x_max >= lo[0]) & (x_min <= hi[0]) & (t_max >= lo[1]) & (t_min <= hi[1])
        return boxes_hit_segments(boxes, segments[near])

    hard, soft = segments_of(obstacles), segments_of(guides)
    if sheet is not None and len(sheet) > 2:
        from matplotlib.path import Path  # noqa: PLC0415  (loaded by now: the panel is drawn)
        on_sheet = Path(to_pt(sheet)).contains_points
    else:
        on_sheet = None
    hard_extents, soft_extents = extents(hard), extents(soft)
    markers_taken = [_marker_box(to_pt(np.array(l.anchors[:1]))[0], l.avoid_radius) for l in labels if l.avoid_radius]
    pad, edge = 2.0 + widest_line / 2, 2.0  # clear of every line's stroke, and of the frame
    radii = np.array([2.0, 4.0, 7.0, 11.0, 16.0, 22.0, 29.0, 37.0, 46.0] + ([56.0, 67.0, 79.0, 92.0] if crowded else []))
    angles = np.arange(0.0, 360.0, 15.0)
    never = 10 ** 9

    # what a label's candidates are and which lines each crosses depend on the label alone, not on the labels placed
    # before it: found once per label, for every arrangement (`arrange`), each chunk of rings once it is reached
    known: dict[int, tuple] = {}
    known_chunks: dict[tuple[int, int], tuple] = {}

    def candidates(i: int) -> tuple:
        if i not in known:
            known[i] = _candidates(labels[i])
        return known[i]

    def _candidates(label: Label) -> tuple:
        if label.box_size:
            w, h = label.box_size
        else:  # crowded: as tall as a line of its type (a text's drawn box, its ground's too), not as its glyphs
            w, h = text_size(label.text, label.size, label.italic)[:2]
            h = max(h, label.size) if crowded else h
        anchors = to_pt(np.array(label.anchors))
        turn = np.abs((angles - label.preferred + 180) % 360 - 180)
        order = angles[np.lexsort((angles, turn))]
        # candidates ordered by ring, then anchor, then direction: that order breaks ties in cost
        ring = np.repeat(np.arange(len(radii)), len(anchors) * len(order))
        which = np.tile(np.repeat(np.arange(len(anchors)), len(order)), len(radii))
        a = np.radians(np.tile(order, len(radii) * len(anchors)))
        r = radii[ring] + label.avoid_radius
        c, s_ = np.cos(a), np.sin(a)
        px, py = anchors[which, 0] + r * c, anchors[which, 1] + r * s_
        ha = np.where(c > 0.3, 0, np.where(c < -0.3, 2, 1))  # left, center, right
        va = np.where(s_ > 0.3, 0, np.where(s_ < -0.3, 2, 1))  # bottom, center, top
        bx, by = px - ha * w / 2, py - va * h / 2
        boxes = np.column_stack([bx - pad, by - pad, bx + w + pad, by + h + pad])
        inside = ((boxes[:, 0] >= edge) & (boxes[:, 1] >= edge) & (boxes[:, 2] <= frame.width - edge)
                  & (boxes[:, 3] <= frame.height - edge))
        return w, h, anchors, ring, which, px, py, ha, va, bx, by, boxes, inside

    def lines_crossed(i: int, first: int, last: int) -> tuple:
        """The chunk of label i's candidates in rings first to last (inside the panel), their boxes, and how many
        obstacles (the sheet included, for a particle's letter) and guides each crosses."""
        if (i, first) not in known_chunks:
            label, (ring, boxes, inside) = labels[i], itemgetter(3, 11, 12)(candidates(i))
            chunk = np.flatnonzero(inside & (ring >= first) & (ring < last))
            b = boxes[chunk]
            if len(chunk) == 0:
                known_chunks[i, first] = chunk, b, None, None
            else:
                blocked = crossings(b, hard_extents)
                if label.off_sheet and on_sheet is not None:
                    blocked = blocked + on_sheet(np.column_stack([(b[:, 0] + b[:, 2]) / 2, (b[:, 1] + b[:, 3]) / 2]))
                known_chunks[i, first] = chunk, b, blocked, crossings(b, soft_extents)
        return known_chunks[i, first]

    def choose(i: int, taken: list, leaders: list, leader_extents) -> _Placed:
        label = labels[i]
        w, h, anchors, ring, which, px, py, ha, va, bx, by, boxes, inside = candidates(i)
        # what the label and its leader keep clear of: every placed label, and every marker but one whose centre its
        # own marker covers (one blot, B₁ on A₁ at v near c: a label beside it or a leader from it cannot keep off it)
        own = _marker_box(anchors[0], label.avoid_radius - 1.0) if label.avoid_radius else None  # as drawn
        mine = _marker_box(anchors[0], label.avoid_radius) if label.avoid_radius else None  # as kept clear
        clear = [box for j, box in enumerate(taken) if own is None or j >= len(markers_taken) or tuple(box) == tuple(mine)
                 or not _covers(own, box)]
        cost = np.full(len(boxes), never)
        crossed_guides = np.zeros(len(boxes), dtype=int)
        for first, last in ((0, 3), (3, 6), (6, 9), (9, 11), (11, len(radii))):  # nearest rings first; stop once one is free
            if first >= len(radii):
                break
            chunk, b, blocked, guides_crossed = lines_crossed(i, first, last)
            if len(chunk) == 0:
                continue
            # on a marker, on another label or on a leader, or a leader across a marker, a label or another leader:
            # a label read for another, never chosen while any candidate avoids it (a line crossed is read through)
            faults = crossings(b, leader_extents) if leaders else np.zeros(len(chunk), dtype=int)
            if clear:
                other = np.array(clear)
                faults += ((b[:, None, 0] < other[None, :, 2]) & (other[None, :, 0] < b[:, None, 2])
                           & (b[:, None, 1] < other[None, :, 3]) & (other[None, :, 1] < b[:, None, 3])).sum(1)
            crossed_guides[chunk] = guides_crossed
            if label.avoid_radius and clear:  # the leader it would need
                faults += _leaders_blocked(anchors[0], b, pad, label.avoid_radius, clear)
                faults += _leaders_crossing(anchors[0], b, pad, label.avoid_radius, leaders)
            if label.guides_block:
                blocked, crossed_guides[chunk] = blocked + crossed_guides[chunk], 0
            cost[chunk] = FAULT * faults + 1000 * blocked + 3 * crossed_guides[chunk] + ring[chunk] + which[chunk]
            if (faults + blocked + crossed_guides[chunk] == 0).any():
                break
        k = int(np.lexsort((np.arange(len(boxes)), cost))[0])  # cheapest; among equals, the earliest candidate
        if cost[k] == never:  # no room inside the panel at all: centre it on the first anchor
            anchor = anchors[0]
            box = (anchor[0] - w / 2, anchor[1] - h / 2, anchor[0] + w / 2, anchor[1] + h / 2)
            position, alignment, ground = anchor, ("center", "center"), True
        else:
            box = tuple(boxes[k])
            position = (px[k], py[k])
            alignment = (("left", "center", "right")[ha[k]], ("bottom", "center", "top")[va[k]])
            ground = crossed_guides[k] > 0 or cost[k] >= 1000
        leader = None
        if label.avoid_radius and cost[k] != never:
            leader = _leader(anchors[0], (bx[k], by[k], bx[k] + w, by[k] + h), label.avoid_radius - 1.0)
        return _Placed(tuple(position), alignment, tuple(box), bool(ground), leader, float(cost[k]))

    def arrange(order: list[int]) -> tuple[dict[int, _Placed], tuple[int, int]]:
        """Each label placed in this order, and how many of them could not avoid a fault, and a line."""
        taken, leaders = list(markers_taken), []
        leader_extents = extents(np.empty((0, 4)))
        out: dict[int, _Placed] = {}
        for i in order:
            out[i] = placed = choose(i, taken, leaders, leader_extents)
            taken.append(placed.box)
            if placed.leader is not None:
                leaders.append(placed.leader)
                leader_extents = extents(np.array([line.reshape(4) for line in leaders]))
        return out, (sum(FAULT <= p.cost < never for p in out.values()), sum(1000 <= p.cost < never for p in out.values()))

    # greedy, in the labels' order; where a label found no place free of faults and lines, again with those labels
    # first (a label placed early takes the room a later one's leader needed), keeping the arrangement with fewest
    # faults, then fewest labels on a line
    order = list(range(len(labels)))
    best, trouble = arrange(order)
    latest = best
    for _ in range(REORDERINGS):
        if not any(trouble):
            break
        first = [i for i in order if 1000 <= latest[i].cost < never]
        order = first + [i for i in order if i not in first]
        latest, again = arrange(order)
        if again < trouble:
            best, trouble = latest, again
    drawn: list[tuple] = []
    for i, label in enumerate(labels):
        placed = best[i]
        position, alignment = placed.position, placed.alignment
        text = ax.text(x0 + position[0] / sx, t0 + position[1] / st_, label.text, ha=alignment[0], va=alignment[1],
                       fontsize=label.size, fontstyle="italic" if label.italic else "normal", color=label.colour,
                       zorder=8, gid=label.gid,
                       bbox=dict(boxstyle="square,pad=0.1", facecolor="white", edgecolor="none") if placed.ground else None)
        artists = (text,)
        if placed.leader is not None:  # a label that could not sit close is tied to its marker
            leader = placed.leader
            line, = ax.plot(x0 + leader[:, 0] / sx, t0 + leader[:, 1] / st_, color=label.colour,
                            linewidth=0.6 * label.size / impact_size * font_size / 9.0, linestyle="solid", zorder=6.5,
                            gid=label.gid.replace("-label-", "-leader-"))
            artists += (line,)
        drawn.append(artists)
    return drawn


class _Placed(NamedTuple):
    """Where a label goes (points): its text's position and alignment, its padded box, its ground, its leader."""

    position: tuple[float, float]
    alignment: tuple[str, str]
    box: tuple[float, float, float, float]
    ground: bool
    leader: np.ndarray | None
    cost: float


def _candidate_leaders(centre: np.ndarray, padded: np.ndarray, pad: float, radius: float
                       ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """For each candidate box (padded by `pad`), the leader it would need (`_leader`): its start on the marker's
    edge, its end on the box, and whether it needs one at all."""
    boxes = padded + np.array([pad, pad, -pad, -pad])
    nearest = np.column_stack([np.clip(centre[0], boxes[:, 0], boxes[:, 2]), np.clip(centre[1], boxes[:, 1], boxes[:, 3])])
    distance = np.hypot(nearest[:, 0] - centre[0], nearest[:, 1] - centre[1])
    needs = distance - (radius - 1.0) > LABEL_REACH
    start = centre + (nearest - centre) * ((radius - 1.0) / np.where(distance > 0, distance, 1.0))[:, None]
    return start, nearest, needs


def _leaders_crossing(centre: np.ndarray, padded: np.ndarray, pad: float, radius: float, leaders: list) -> np.ndarray:
    """For each candidate box, how many placed leaders (2 x 2 arrays, points) the leader it would need crosses."""
    if not leaders:
        return np.zeros(len(padded), dtype=int)
    start, end, needs = _candidate_leaders(centre, padded, pad, radius)
    if not needs.any():
        return np.zeros(len(padded), dtype=int)
    placed = np.array([leader.reshape(4) for leader in leaders])  # x0 y0 x1 y1

    def side(ax, ay, bx, by, cx, cy):  # the sign of the turn a -> b -> c
        return np.sign((bx - ax) * (cy - ay) - (by - ay) * (cx - ax))
    p, q = start[:, None, :], end[:, None, :]
    r, t = placed[None, :, :2], placed[None, :, 2:]
    cross = ((side(p[..., 0], p[..., 1], q[..., 0], q[..., 1], r[..., 0], r[..., 1])
              * side(p[..., 0], p[..., 1], q[..., 0], q[..., 1], t[..., 0], t[..., 1]) < 0)
             & (side(r[..., 0], r[..., 1], t[..., 0], t[..., 1], p[..., 0], p[..., 1])
                * side(r[..., 0], r[..., 1], t[..., 0], t[..., 1], q[..., 0], q[..., 1]) < 0))
    return np.where(needs, np.count_nonzero(cross, axis=1), 0)


def _leaders_blocked(centre: np.ndarray, padded: np.ndarray, pad: float, radius: float, taken: list) -> np.ndarray:
    """For each candidate box (padded by `pad`), how many taken boxes (other markers, placed labels) the leader
    it would need (`_leader`) crosses; 0 for a candidate close enough to need none."""
    start, nearest, needs = _candidate_leaders(centre, padded, pad, radius)
    if not needs.any():
        return np.zeros(len(padded), dtype=int)
    own = _marker_box(centre, radius)
    others = np.array([box for box in taken if tuple(box) != tuple(own)]).reshape(-1, 4)
    if len(others) == 0:
        return np.zeros(len(padded), dtype=int)
    hits = np.count_nonzero(_hits(others, np.column_stack([start, nearest])), axis=0)
    return np.where(needs, hits, 0)


def _leader(centre: np.ndarray, text_box: tuple[float, float, float, float], radius: float) -> np.ndarray | None:
    """A leader (points, 2 x 2) from the marker's edge to the nearest point of the label's box, if farther than LABEL_REACH."""
    nearest = np.array([min(max(centre[0], text_box[0]), text_box[2]), min(max(centre[1], text_box[1]), text_box[3])])
    distance = float(np.hypot(*(nearest - centre)))
    if distance - radius <= LABEL_REACH:
        return None
    start = centre + (nearest - centre) * (radius / distance)
    return np.array([start, nearest])


def _covers(marker, other) -> bool:
    """Whether a marker's box (xmin, ymin, xmax, ymax) covers the centre of another's."""
    x, y = 0.5 * (other[0] + other[2]), 0.5 * (other[1] + other[3])
    return marker[0] <= x <= marker[2] and marker[1] <= y <= marker[3]


def _marker_box(centre, radius: float):
    return (centre[0] - radius, centre[1] - radius, centre[0] + radius, centre[1] + radius)
