"""What a comparison of rods says first: where each particle started, and where each rod's first impacts fall
(docs, "The causal rod": like for like). Every table, figure and paragraph that puts two rods side by side states
it, so a reader never compares rods struck by different particles. Pure.
"""

from __future__ import annotations

from typing import Sequence

from rodparadox.numbers import impact_name, shown
from rodparadox.physics.frames import Frame, frame_name

#: two first impacts closer in a frame's time than this (in units of L) are simultaneous there
SIMULTANEOUS = 1e-9


def particle_starts_text(history) -> str:
    """Where each particle is at t = 0 in S and how fast it moves (units of L, c = 1)."""
    s = history.scenario
    L = s.L
    starts = dict(history.starts)
    parts = [f"{p.name} from x = {shown(starts[p.name].x / L, 4)} L at speed {shown(s.speed(p), 4)} c"
             for p in sorted(s.particles, key=lambda p: p.name) if p.name in starts]
    return " and ".join(parts)


def first_impacts(history) -> list:
    """Each particle's first impact on the rod (its first contact), A's before B's."""
    firsts = {}
    for i in history.impacts:
        if not i.is_separation:
            firsts.setdefault(i.particle, i)
    return [firsts[name] for name in sorted(firsts)]


def first_impact_times(history, frames: Sequence[Frame]) -> list[tuple[Frame, list[float], bool]]:
    """For each frame: the first impacts' times there (units of L, in `first_impacts`' order) and whether they
    are simultaneous there."""
    L = history.scenario.L
    out = []
    for f in frames:
        times = [i.event.time_in(f.rapidity) / L for i in first_impacts(history)]
        out.append((f, times, len(times) > 1 and abs(times[0] - times[1]) <= SIMULTANEOUS * (1 + max(map(abs, times)))))
    return out


def first_impacts_text(history, frames: Sequence[Frame]) -> str:
    """In which of `frames` the first impacts of the two particles are simultaneous, with their times there."""
    firsts = first_impacts(history)
    L = history.scenario.L
    names = " and ".join(impact_name(i.label) for i in firsts)
    if len(firsts) < 2:
        i = firsts[0]
        return f"its first impact {impact_name(i.label)} at t = {shown(i.event.t / L, 4)} L in S"
    same, apart = [], []
    for f, times, simultaneous in first_impact_times(history, frames):
        symbol = frame_name(f)
        if simultaneous:
            same.append(f"{symbol} (at {shown(times[0], 4)} L)")
        else:
            at = ", ".join(f"{impact_name(i.label)} at {shown(t, 4)} L" for i, t in zip(firsts, times))
            apart.append(f"{symbol} ({at})")
    said = []
    if same:
        said.append(f"{names} are simultaneous in {' and '.join(same)}")
    if apart:
        said.append(f"{'not' if same else names + ' are not simultaneous'} in {' or '.join(apart)}")
    return ", ".join(said)


def _timed_in(frame) -> str:
    """The frame a profile is timed in, as its times read: t in S, t′ in S′, or a velocity's frame."""
    if frame == "rest":
        return "in S"
    if frame == "moving":
        return "in S′"
    return f"in the frame moving at {shown(frame, 4)} c"


def force_text(profile) -> str:
    """One force in words: its shape, size (units of M c²/L) and when it acts (units of L), in
    the frame its profile is timed in."""
    lo, hi = profile.support()
    t = "t\N{PRIME}" if profile.frame == "moving" else "t"
    # no-break spaces: a figure's note never tears a number from its unit
    nb = "\N{NO-BREAK SPACE}"
    when = f"from {t} = {shown(lo, 4)}{nb}L to {shown(hi, 4)}{nb}L {_timed_in(profile.frame)}"
    units = "\N{NO-BREAK SPACE}M\N{NO-BREAK SPACE}c\N{SUPERSCRIPT TWO}/L"
    if profile.shape == "points":
        least, greatest = profile.least(), profile.greatest()
        size = (f"between {shown(least, 4)} and {shown(greatest, 4)}{units}" if least < 0 < greatest
                else f"up to {shown(greatest if greatest > 0 else least, 4)}{units}")
        kind = "push" if least == 0 else "pull" if greatest == 0 else "force"
        return f"a {kind} through {len(profile.points)} points, {size}, {when}"
    kind = "push" if profile.peak > 0 else "pull"
    if profile.shape == "step":
        return f"a constant {kind} of {shown(abs(profile.peak), 4)}{units} {when}"
    return f"a sine² {kind} peaking at {shown(abs(profile.peak), 4)}{units} {when}"


def forces_text(history) -> str:
    """The forces on a rod's ends in words: each end's, or one sentence for both where they are the same."""
    profiles = dict(history.driving.profiles())
    if len(profiles) == 2 and force_text(profiles["left"]) == force_text(profiles["right"]):
        return f"on each end {force_text(profiles['left'])}"
    said = [f"on the {end} end {force_text(p)}" for end, p in profiles.items()]
    said += [f"none on the {end} end" for end in ("left", "right") if end not in profiles]
    return "; ".join(said)


def comparison_note(histories, frames: Sequence[Frame]) -> str:
    """One paragraph: the particles every rod is struck by, and for each rod where its first impacts fall (for rods
    driven by forces, the forces that drive them all: no particles strike them)."""
    if not histories[0].scenario.particles:
        every = "Both rods are" if len(histories) == 2 else "Every rod is"
        return f"{every} driven by the same forces at their ends: " \
               f"{forces_text(histories[0])}."
    starts = [particle_starts_text(h) for h in histories]
    if len(set(starts)) == 1:
        every = "Both rods are" if len(histories) == 2 else "Every rod is"
        lines = [f"{every} struck by the same particles: {starts[0]}, at t = 0 in S."]
    else:  # histories run apart (a library caller's): say so, never "the same particles"
        lines = ["The rods are struck by particles that start apart: "
                 + "; ".join(f"the {h.model} rod’s {text}" for h, text in zip(histories, starts)) + ", at t = 0 in S."]
    lines += [f"The {h.model} rod: {first_impacts_text(h, frames)}." for h in histories]
    return " ".join(lines)
