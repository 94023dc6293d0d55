"""The rod driven by forces at successive instants of a frame (a forces handout's strips): which instants show the
forces (`force_strip_times`: before them, each force's start, peak and end, after them) and the caption saying what
the rows show. Pure.
"""

from __future__ import annotations

from typing import NamedTuple, Sequence

import numpy as np

from rodparadox.handout.document import Block, Heading, Strips
from rodparadox.handout.strips import chosen_instants, following_rows
from rodparadox.handout.words import in_c, listed, time_name
from rodparadox.numbers import shown
from rodparadox.physics.frames import Frame, frame_name, frame_word, time_window
from rodparadox.render.colour_scale import colour_scale
from rodparadox.render.strip_windows import follows_rod


def force_strip_times(history, frame: Frame) -> tuple[float, ...]:
    """Six to eight instants of the frame's time, earliest first, within `frames.time_window`: before the first
    force, each force's start and end, each one's peak, after the last force; instants closer than STRIP_SEPARATION
    of the window are one (two forces starting together); fewer than six, the widest gap is halved. Each is rounded
    to 1e-12 L, as the rows' labels and the caption print it."""
    eta = frame.rapidity
    t_lo, t_hi = time_window(history, frame)
    moments = [(e.moment, e.event.time_in(eta)) for e in history.driving.force_events()]
    first, last = min(t for _, t in moments), max(t for _, t in moments)
    # (priority, time): the lower the priority, the surer an instant is kept
    candidates = [(0, 0.5 * (t_lo + first)), (0, 0.5 * (last + t_hi))]
    candidates += [(1, t) for moment, t in moments if moment != "peak"]
    candidates += [(2, t) for moment, t in moments if moment == "peak"]
    times = chosen_instants(candidates, t_lo, t_hi)
    L = history.scenario.L  # rounded to 1e-12 L: a halved gap's 0 is not -2.8e-17, a peak's 1 not 0.9999999999999999
    return tuple(round(min(max(t, t_lo), t_hi) / L, 12) * L + 0.0 for t in times)


def force_strips_caption(history, frame: Frame, times: Sequence[float], model: str = "", follows: bool = False) -> str:
    """What the rows show, for a rod driven by forces: at which instants, the bar's shading, the arrows; `model`:
    the rod's name where two rods are shown ("the rigid rod"); `follows`: each row follows the rod
    (`render.strip_windows`), as the caption then says."""
    L = history.scenario.L
    symbol = frame_name(frame)
    instants = listed([shown(t / L, 4) for t in times])  # as each row's label gives it
    rod = model or "the rod"
    if colour_scale(history, frame).shown is None:  # its velocity never changes in this frame: one shade
        bar = (f"The bar runs from the rod's left end to its right end; its material points keep the rod's first "
               f"velocity in {symbol}, {in_c(frame.rod_velocity())}, throughout, so it has one shade")
    else:
        bar = (f"The bar runs from the rod's left end to its right end, shaded by the velocity in {symbol} of each of "
               f"its material points, which the scale under the rows gives")
    return (f"{rod[0].upper()}{rod[1:]} in {symbol} at {time_name(frame)} = {instants} (in units of L), earliest "
            f"first. {bar}.{' ' + following_rows(frame, particles=False) if follows else ''} An arrow at an end is "
            f"the force acting there, its length in proportion to the force, pointing into the rod where the force presses and out of it where it pulls; no arrow where the force "
            f"is zero (as when a force ends, or a smooth one starts). Beside a row, the forces that start (on), "
            f"peak or end (off) at its instant.")


class _Ends(NamedTuple):
    """A driven rod's two ends at one instant, as `strip_windows.follows_rod` reads a strip (no particles)."""

    x: np.ndarray
    particles: tuple = ()


def _ends_at(history, frame: Frame, t: float) -> _Ends:
    """Where the rod's two ends are at the instant t of the frame (its strip's first and last points)."""
    eta = frame.rapidity
    return _Ends(np.array([history.worldline(f"rod_{end}").seen_from(eta).event_at_time(t).x
                           for end in ("left", "right")]))


def strips_blocks(stem: str, histories: Sequence, frames: Sequence[Frame]) -> list[Block]:
    """Each frame's strips, each rod's block (the rigid rod first) under a heading naming the rod (where two are
    shown) and the frame, with its caption; the blocks of one frame share one x range and one colour scale."""
    blocks: list[Block] = []
    for f in frames:
        chosen = [(h, force_strip_times(h, f)) for h in histories]
        # the rows follow the rod where one range would shrink it (`render.strip_windows`): the compared blocks alike
        follows = follows_rod([_ends_at(h, f, t) for h, times in chosen for t in times], histories[0].scenario.L)
        for k, (h, times) in enumerate(chosen):
            model = f"the {h.model} rod" if len(histories) > 1 else ""
            subject = f"The {h.model} rod" if model else "The rod"
            blocks.append(Heading(f"{subject} at successive instants of {frame_name(f)}", 2))
            # the rods compared share one x range and one colour scale in each frame
            blocks.append(Strips(f"{stem}_strips_{'causal_' if h.fronts is not None else ''}{frame_word(f)}", h, f, times,
                                 force_strips_caption(h, f, times, model, follows), subject=subject,
                                 partners=tuple(other for j, other in enumerate(chosen) if j != k)))
    return blocks
