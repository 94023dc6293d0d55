"""A GIF's one palette for a whole animation: at most 256 colours chosen from every image's colour counts by a
greedy variance cut (`palette_of`), and each colour's nearest entry (`nearest_entries`); colours packed as
integers 0xRRGGBB (`pack`, `unpack`). Pure numpy, deterministic; `encoders.GifSink` uses it."""

from __future__ import annotations

import numpy as np

#: the colours of a GIF's one palette
GIF_COLOURS = 256


def pack(image: np.ndarray) -> np.ndarray:
    """Each pixel's colour as one integer 0xRRGGBB, in the image's shape (H, W)."""
    f = image.astype(np.uint32)
    return (f[..., 0] << 16) | (f[..., 1] << 8) | f[..., 2]


def unpack(colours: np.ndarray) -> np.ndarray:
    """(n, 3) uint8 colours from integers 0xRRGGBB."""
    c = np.asarray(colours, dtype=np.uint32)
    return np.stack([(c >> 16) & 255, (c >> 8) & 255, c & 255], axis=-1).astype(np.uint8)


def palette_of(colours: np.ndarray, counts: np.ndarray, size: int = GIF_COLOURS) -> np.ndarray:
    """At most `size` colours for pixels of the given colours (sorted 0xRRGGBB integers) and counts.

    Every colour, exactly, when there are no more than `size`. Otherwise a greedy variance cut: start with
    one box of all colours and split, `size` - 1 times, the box with the largest count-weighted squared
    error about its mean, across its widest axis at the cut that leaves the least error. Each box gives its
    count-weighted mean, rounded. A colour that covers many pixels (the page, a line's ink) ends alone in a
    box, so it is kept exactly; anti-aliased edges share the rest. Deterministic: no randomness, ties broken
    by order.
    """
    rgb = unpack(colours).astype(np.float64)
    if len(rgb) <= size:
        return rgb.astype(np.uint8)
    w = counts.astype(np.float64)

    def error(idx: np.ndarray) -> float:
        ww = w[idx]
        mean = (rgb[idx] * ww[:, None]).sum(0) / ww.sum()
        return float((ww * ((rgb[idx] - mean) ** 2).sum(1)).sum())

    boxes = [(error(np.arange(len(rgb))), np.arange(len(rgb)))]
    while len(boxes) < size:
        k = max(range(len(boxes)), key=lambda j: boxes[j][0])
        err, idx = boxes[k]
        if err <= 0:
            break
        points, ww = rgb[idx], w[idx]
        mean = (points * ww[:, None]).sum(0) / ww.sum()
        axis = int(np.argmax((ww[:, None] * (points - mean) ** 2).sum(0)))
        order = np.argsort(points[:, axis], kind="stable")
        idx, points, ww = idx[order], points[order], ww[order]
        # the cut between two distinct values along the axis that minimises the two halves' squared error
        cw = np.cumsum(ww)
        cs = np.cumsum(points * ww[:, None], axis=0)
        cq = np.cumsum((points ** 2).sum(1) * ww)
        left_err = cq[:-1] - (cs[:-1] ** 2).sum(1) / cw[:-1]
        rw, rs, rq = cw[-1] - cw[:-1], cs[-1] - cs[:-1], cq[-1] - cq[:-1]
        right_err = rq - (rs ** 2).sum(1) / rw
        valid = points[1:, axis] != points[:-1, axis]
        total = np.where(valid, left_err + right_err, np.inf)
        if not np.isfinite(total).any():
            boxes[k] = (0.0, idx)
            continue
        cut = int(np.argmin(total)) + 1
        boxes[k:k + 1] = [(error(idx[:cut]), idx[:cut]), (error(idx[cut:]), idx[cut:])]
    out = np.array([(rgb[idx] * w[idx, None]).sum(0) / w[idx].sum() for _, idx in boxes])
    return np.clip(np.rint(out), 0, 255).astype(np.uint8)


def nearest_entries(colours: np.ndarray, palette: np.ndarray) -> np.ndarray:
    """For each colour (0xRRGGBB integers), the index of the nearest palette entry (squared RGB distance; the
    first of equals)."""
    # |c - p|^2 = |c|^2 - 2 c.p + |p|^2, and |c|^2 is the same for every entry: the nearest entry minimises
    # |p|^2 - 2 c.p, whole numbers below 2^19 (exact in int32): the same order, and the same first of equals, as
    # the distances themselves, from two-dimensional sums instead of a (colours, entries, 3) array of
    # differences (measured: 18 against 170-200 CPU-ms for 20,000 colours and 256 entries). No matrix product:
    # OpenBLAS's threads would spin beside the test workers.
    rgb = unpack(colours).astype(np.int32)
    pal = palette.astype(np.int32)
    norms = (pal ** 2).sum(1)
    r, g, b = (2 * pal[:, i] for i in range(3))
    out = np.empty(len(rgb), dtype=np.int64)
    for start in range(0, len(rgb), 4096):
        chunk = rgb[start:start + 4096]
        d = norms - chunk[:, 0:1] * r
        d -= chunk[:, 1:2] * g
        d -= chunk[:, 2:3] * b
        out[start:start + 4096] = np.argmin(d, axis=1)
    return out
