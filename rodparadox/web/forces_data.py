"""What the html page embeds for a rod driven by forces at its ends (the `driving` capability; docs/model.md,
"Forces at the ends"). Pure: no matplotlib.

* each force as a band along its end's world-line, as `plot` draws it (`render.force_layers`): events of the end in
  S (units of L) at instants of the profile's own time, over its support (evenly spread, its corners, a jump's
  instant twice with the force before and after it), with the force there. An event and the force at it are the
  same in every frame: the page boosts the events and draws the band outside the end, horizontally in its frame,
  `BAND_EMS` of its type size wide for the force `scale` (the least nice number not below the largest |F|);
* each force's start, peak and end (`Driving.force_events`): the event in S with every digit, the end's rapidity
  there, the force and the instant in the profile's frame;
* the ledger's rows (`tables.forces_ledger`): what each agent delivered up to the slice's end events, the rod's
  two parts, their sum and the rod's (E, p) before the forces plus what was delivered.
"""

from __future__ import annotations

from typing import Any, Callable

import numpy as np

from rodparadox.io.export_forces import force_rows
from rodparadox.numbers import MINUS, coordinate_format, nice_number, velocity_format
from rodparadox.tables.forces_ledger import parts_of

#: instants of a profile's own time along its support (its corners and jumps besides): a sine^2 band smooth at the
#: page's size (the figures take 160 for a printed page)
BAND_SAMPLES = 48
#: the width of a band in the page's type size for the force `scale` (as the figures', `render.force_layers`)
BAND_EMS = 1.0


def scale(history) -> float:
    """The force a band BAND_EMS wide shows: the least nice number not below the largest |F| of any profile."""
    greatest = max(max(abs(p.least()), abs(p.greatest())) for _, p in history.driving.profiles())
    return nice_number(greatest, "at_least")


def instants(profile) -> tuple[np.ndarray, np.ndarray]:
    """The instants (units of L, the profile's frame) a band is drawn through, in order, and the force at each: a
    jump's instant twice, with the force before and then after it."""
    lo, hi = profile.support()
    times = np.unique(np.concatenate([np.linspace(lo, hi, BAND_SAMPLES), [b for b in profile.pieces() if lo <= b <= hi]]))
    forces = np.asarray(profile.value(times), dtype=float)  # right-continuous: at a jump, the force after it
    for b in (b for b in profile.jumps() if lo <= b <= hi):
        k = int(np.searchsorted(times, b))
        times = np.insert(times, k, b)
        forces = np.insert(forces, k, profile.piece_value(profile.piece_index(b) - 1, b))
    return times, forces


def bands(history, end_events: Callable[[str, float, np.ndarray], tuple[np.ndarray, np.ndarray]],
          digits: int) -> list[dict[str, Any]]:
    """Each force's band: its end ("left" or "right"), the events of that end in S (x, t, units of L) at the
    profile's instants (`instants`) and the force at each (units of M c^2/L). `end_events(end, f, times)`: where the
    end is, in S (units of L), when the frame of rapidity f reads those times (units of L) there."""
    d, out = history.driving, []
    for end, profile in d.profiles():
        times, forces = instants(profile)
        x, t = end_events(end, d.frame_rapidity(end), times)
        out.append({"end": end, "x": [_drawn(v, digits) for v in x], "t": [_drawn(v, digits) for v in t],
                    "F": [_drawn(v, digits) for v in forces]})
    return out


def events(history) -> list[dict[str, Any]]:
    """Each force's start, peak and end: its end, moment, event in S (units of L, every digit), the end's rapidity
    in S, the force there and the instant in the profile's frame (units of L)."""
    L = history.scenario.L
    return [{"end": e.end, "moment": e.moment, "x": e.event.x / L, "t": e.event.t / L, "rapidity": e.rapidity + 0.0,
             "force": e.force + 0.0, "instant": e.profile_time + 0.0} for e in history.driving.force_events()]


#: the arrows along a band, at the middles of this many equal parts of the support, where the force is at least
#: ARROW_LEAST of the scale (as the figures', `render.force_layers`)
ARROWS = 6
ARROW_LEAST = 0.3


def arrows(history, end_events, digits: int) -> list[list]:
    """Each band's arrows: [end, x, t (in S, units of L), F] at the middles of ARROWS equal parts of its support
    (in the profile's time) where |F| is at least ARROW_LEAST of the scale."""
    d, least, out = history.driving, ARROW_LEAST * scale(history), []
    for end, profile in d.profiles():
        lo, hi = profile.support()
        times = np.array([lo + (k + 0.5) * (hi - lo) / ARROWS for k in range(ARROWS)])
        forces = np.asarray(profile.value(times), dtype=float)
        keep = np.abs(forces) >= least
        if keep.any():
            x, t = end_events(end, d.frame_rapidity(end), times[keep])
            out += [[end, _drawn(a, digits), _drawn(b, digits), _drawn(F, digits)] for a, b, F in zip(x, t, forces[keep])]
    return out


#: how the page names the frames' coordinates in a table's header
COORDINATES = {"rest": ("x", "t"), "moving": ("x\u2032", "t\u2032")}


def tables(history, frames) -> dict[str, Any]:
    """The force events of S and S' (`frames`: rest, moving) as `sears-paradox events` prints them: every start,
    peak and end in the frame's time order, F and the velocities with the digits shared by both frames' rows, x and
    t with each frame's column's decimals."""
    per_frame = [force_rows(history, f) for f in frames]
    rows = [r for rs in per_frame for r in rs]
    # x and t: a column's decimals in each frame (as `events` prints them, `io.export_forces.table`)
    columns = {frame.name: (coordinate_format([r["x"] for r in rs]), coordinate_format([r["t"] for r in rs]))
               for frame, rs in zip(frames, per_frame)}
    velocity = velocity_format([r["end_velocity"] for r in rows])
    force = coordinate_format([r["force"] for r in rows] + [p.greatest() for _, p in history.driving.profiles()])
    out = {}
    for frame, rs in zip(frames, per_frame):
        x, t = COORDINATES[frame.name]
        symbol = "S" if frame.name == "rest" else "S\u2032"
        out[frame.name] = {
            "caption": f"Each force’s start, peak and end in frame {symbol}",
            "header": ["force", "end", x, t, "F", "end velocity"],
            "rows": [[r["moment"], r["end"], *(text.replace("-", MINUS) for text in (
                columns[frame.name][0](r["x"]), columns[frame.name][1](r["t"]), force(r["force"]),
                velocity(r["end_velocity"])))] for r in rs],
            "notes": ["x and t in units of L, F in M c\u00b2/L (a push > 0, a pull < 0), velocities in units of c; "
                      "F at an end: the force just before it stops."]}
    return out


def ledger_rows(history) -> tuple[str, ...]:
    """The names of the ledger's rows for the history's rod (`tables.forces_ledger`), in order."""
    return parts_of(history)[0]


def ledger_note(history) -> str:
    """The ledger's note (`tables.forces_ledger`) up to its centre of energy, which the page does not show (its
    velocity costs several slices a slice)."""
    note = parts_of(history)[1]
    return note[:note.index(" x_E is")]


def ledger_slice(history, f: float, t: float, parts: tuple | None = None, delivered: tuple | None = None) -> list[float]:
    """One slice's row: (E, p) of each of `ledger_rows` in order (units of M c^2, M c; t absolute). `parts`: the
    rod's two parts on the slice, `delivered`: what the left and the right agent delivered, if already computed (a
    causal rod's, for many slices at once); the last row is the rod's (E, p) before the forces plus both
    (`Driving.total`)."""
    d = history.driving
    kinetic, stress = parts if parts is not None else history.rod_parts(f, t)
    left, right = delivered if delivered is not None else (d.delivered("left", f, t), d.delivered("right", f, t))
    return [n for em in (left, right, kinetic, stress, kinetic + stress, history.initial_total(f) + left + right)
            for n in (em.E, em.p)]


def _drawn(value: float, digits: int) -> float:
    return float(f"{value:.{digits}g}") + 0.0
