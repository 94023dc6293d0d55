"""The ledger of a rod driven by forces at its ends (docs/model.md, "Forces at the ends"): on slices of each frame,
what each agent delivered up to the slice's end events, the rod's kinetic and stress parts, their sum, the rod's
(E, p) before the forces plus what was delivered (the same, to rounding: the conservation law with forces), and the
rod's centre of energy with its velocity beside p / E (von Laue's point: they differ while forces act). Pure.

Slices: the times given (`--at`), else the window's ends, each force's start, peak and end in that frame (events
simultaneous in the frame, to rounding, give one slice), and the midpoints between them.
"""

from __future__ import annotations

import csv
import io
import json
from typing import Any, Sequence

from rodparadox.numbers import exact
from rodparadox.physics.frames import Frame, frame_heading, time_window
from rodparadox.physics.types import EnergyMomentum
from rodparadox.tolerances import SAME_INSTANT

FORMAT = "sears-paradox-ledger/1"
UNITS = "E in M c^2, p in M c, M the rod's mass; t and x in the unit L is given in"
#: the parts of each slice, in order: what each agent delivered, the rod's parts, their sum, and the check
PARTS = ("delivered left", "delivered right", "rod kinetic", "rod stress", "rod", "initial + delivered")
#: what both notes say of the parts' sum and of the centre of energy
_SUM = ("Their sum equals the rod's (E, p) before the forces plus what the two agents delivered up to the slice's end "
        "events. x_E is the centre of energy, v_E its velocity; for a closed system v_E = p/E, with forces they differ.")
NOTE = ("The rod's (E, p) on a slice is its kinetic part, (M/L) int (cosh psi, sinh psi) d sigma, plus its stress "
        "part, int p tanh psi (sinh psi, cosh psi) d sigma (von Laue's momentum of a stressed body: zero on the "
        "rod's own lines of simultaneity). " + _SUM)
#: the same for a rod whose signals run at c (the capability `fronts`: the causal rod), split as its own ledger is
FRONTS_PARTS = ("delivered left", "delivered right", "rod matter", "rod stress", "rod", "initial + delivered")
FRONTS_NOTE = ("The rod's (E, p) on a slice is its matter part, rho u u (rho its rest-frame energy density, elastic "
               "energy included), plus its stress part, p (u u - eta) (von Laue's momentum of a stressed body). " + _SUM)


def parts_of(history) -> tuple[tuple[str, ...], str]:
    """The names of the parts and the note for the history's rod: matter and stress where it has fronts."""
    return (PARTS, NOTE) if history.fronts is None else (FRONTS_PARTS, FRONTS_NOTE)


def slice_times(history, frame: Frame, at: Sequence[float] | None = None) -> tuple[float, ...]:
    if at is not None:
        return tuple(at)
    lo, hi = time_window(history, frame)
    marks = []
    for t in sorted({lo, hi, *(e.event.time_in(frame.rapidity) for e in history.driving.force_events())}):
        if not marks or t - marks[-1] > SAME_INSTANT * (history.scenario.L + abs(t)):
            marks.append(t)  # events simultaneous in the frame (boosted apart by rounding) give one slice
    out = []
    for a, b in zip(marks, marks[1:]):
        out += [a, 0.5 * (a + b)]
    return tuple(out + [marks[-1]])


def slice_row(history, frame: Frame, t: float) -> dict[str, Any]:
    d, f = history.driving, frame.rapidity
    kinetic, stress = history.rod_parts(f, t)
    left, right = d.delivered("left", f, t), d.delivered("right", f, t)
    rod = kinetic + stress
    x_E, _ = d.centre_of_energy(f, t)
    parts = dict(zip(parts_of(history)[0], (left, right, kinetic, stress, rod, d.total(f, t))))
    return {"t": t, "parts": parts, "x_E": x_E, "v_E": d.centre_velocity(f, t), "p_over_E": rod.p / rod.E}


def _em(em: EnergyMomentum) -> dict[str, float]:
    return {"E": em.E, "p": em.p}


def document(history, frames: Sequence[Frame], at: Sequence[float] | None = None) -> dict[str, Any]:
    s = history.scenario
    out = {"format": FORMAT, "rod": history.model, "drive": "forces", "units": UNITS,
           "scenario": {"name": s.name, "v": s.v, "L": s.L}, "frames": {}}
    for frame in frames:
        rows = [slice_row(history, frame, t) for t in slice_times(history, frame, at)]
        out["frames"][frame.name] = {
            "velocity": frame.velocity,
            "slices": [{"t": r["t"], **{name.replace(" + ", "_plus_").replace(" ", "_"): _em(em)
                                        for name, em in r["parts"].items()},
                        "x_E": r["x_E"], "v_E": r["v_E"], "p_over_E": r["p_over_E"]} for r in rows]}
    return out


def to_json(history, frames: Sequence[Frame], at: Sequence[float] | None = None) -> str:
    return json.dumps(_positive_zeros(document(history, frames, at)), indent=1, allow_nan=False) + "\n"


def _positive_zeros(value: Any) -> Any:
    if isinstance(value, float):
        return value + 0.0
    if isinstance(value, dict):
        return {k: _positive_zeros(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_positive_zeros(v) for v in value]
    return value


CSV_COLUMNS = ("frame", "t", "part", "E", "p")


def csv_rows(history, frames: Sequence[Frame], at: Sequence[float] | None = None) -> list[list[str]]:
    rows = []
    for frame in frames:
        for t in slice_times(history, frame, at):
            r = slice_row(history, frame, t)
            rows += [[frame.name, repr(t + 0.0), name, repr(em.E + 0.0), repr(em.p + 0.0)]
                     for name, em in r["parts"].items()]
            rows.append([frame.name, repr(t + 0.0), "centre of energy x_E, v_E", repr(r["x_E"] + 0.0),
                         repr(r["v_E"] + 0.0)])
    return rows


def to_csv(history, frames: Sequence[Frame], at: Sequence[float] | None = None) -> str:
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(CSV_COLUMNS)
    writer.writerows(csv_rows(history, frames, at))
    return out.getvalue()


def _number(value: float) -> str:
    text = f"{value:+.9f}"
    return " 0.000000000" if float(text) == 0.0 else text  # no -0, aligned with the signed numbers


def to_text(history, frames: Sequence[Frame], at: Sequence[float] | None = None) -> str:
    """Per frame, per slice: a line per part (E, p), then the centre of energy, its velocity and p/E."""
    s = history.scenario
    lines = [f"{s.name}: v = {exact(s.v)}, L = {exact(s.L)}, the {history.model} rod driven by forces", f"({UNITS})",
             ""]
    names, note = parts_of(history)
    width = max(len(name) for name in names)
    for frame in frames:
        lines.append(frame_heading(frame) + f": velocity {exact(frame.velocity)} relative to S")
        for t in slice_times(history, frame, at):
            r = slice_row(history, frame, t)
            lines.append(f"  t = {_number(t)}")
            lines += [f"    {name:<{width}}  E {_number(em.E)}  p {_number(em.p)}" for name, em in r["parts"].items()]
            lines.append(f"    {'centre of energy':<{width}}  x_E {_number(r['x_E'])}  v_E {_number(r['v_E'])}  "
                         f"p/E {_number(r['p_over_E'])}")
        lines.append("")
    return "\n".join(lines + [note, ""])
