"""The ledger as text, JSON and CSV, for `sears-paradox ledger` (docs/ledger.md, "Energy and momentum"). Pure.

JSON numbers are written with Python's shortest round-trip repr and keys in a
fixed order, so the same command gives the same bytes; text tables print
seven significant digits and never -0.
"""

from __future__ import annotations

import csv
import io
import json
from typing import Any, Sequence

from rodparadox.physics.history import RodHistory
from rodparadox.physics.frames import Frame, frame_heading, time_window
from rodparadox.physics.types import EnergyMomentum, Slice
from rodparadox.physics.ledger import impact_entries, ImpactEntry, instant_entries, rounding_zero
from rodparadox.numbers import number_text

FORMAT = "sears-paradox-ledger/1"
#: slices drawn between the ends of a frame's time window when no times are given (plus every turn's start and
#: end and every impact): enough for a smooth curve at print size
DENSE_SLICES = 240


def slice_times(history: RodHistory, frame: Frame, at: Sequence[float] | None = None) -> tuple[float, ...]:
    """The times `at` as given, or a dense sampling of the frame's time window with every turn's start and end and
    every impact's instant."""
    if at is not None:
        return tuple(at)
    lo, hi = time_window(history, frame)
    eta = frame.rapidity
    times = {lo + (hi - lo) * k / (DENSE_SLICES - 1) for k in range(DENSE_SLICES)}
    times.update(t for t in history.turning.turn_times(eta) if lo <= t <= hi)
    times.update(i.event.time_in(eta) for i in history.impacts)
    return tuple(sorted(times))


def _em(em: EnergyMomentum) -> dict[str, float]:
    return {"E": em.E + 0.0, "p": em.p + 0.0}


def _impact(entry: ImpactEntry) -> dict[str, Any]:
    i = entry.impact
    return {"label": i.label, "particle": i.particle, "end": i.end, "t": entry.t + 0.0,
            "particle_before": _em(entry.particle_before), "particle_after": _em(entry.particle_after),
            "impulse": _em(entry.impulse), "rod_kinetic": _em(entry.rod_kinetic),
            "rod_dynamical_before": _em(entry.rod_dynamical_before),
            "rod_dynamical_after": _em(entry.rod_dynamical_after),
            "kinetic_before": _em(entry.kinetic_before), "kinetic_after": _em(entry.kinetic_after),
            "hidden_before": _em(entry.hidden_before), "hidden_after": _em(entry.hidden_after)}


def _slice(s: Slice) -> dict[str, Any]:
    return {"t": s.t + 0.0, "bodies": {name: _em(em) for name, em in s.bodies}, "kinetic": _em(s.kinetic),
            "hidden": _em(s.hidden)}


def document(history: RodHistory, frames: Sequence[Frame], at: Sequence[float] | None = None) -> dict[str, Any]:
    s = history.scenario
    out_frames = {}
    for f in frames:
        eta = f.rapidity
        out_frames[f.name] = {
            "velocity": f.velocity + 0.0,
            "total": _em(history.initial_total(eta)),
            "turns": [{"pivot": turn.pivot_end, "start": lo + 0.0, "end": hi + 0.0}
                      for turn in history.turning.turns for lo, hi in [turn.interval(eta)]],
            "impacts": [_impact(e) for e in impact_entries(history, eta)],
            "slices": [_slice(history.energy_momentum(eta, t)) for t in slice_times(history, f, at)],
        }
    return {"format": FORMAT,
            "scenario": {"name": s.name, "v": s.v, "L": s.L,
                         "masses": {"rod": 1.0, **{p.name: p.mass for p in s.particles}}},
            "units": {"E": "M c^2", "p": "M c", "t": "the unit L is given in"},
            "frames": out_frames}


def to_json(history: RodHistory, frames: Sequence[Frame], at: Sequence[float] | None = None) -> str:
    return json.dumps(document(history, frames, at), indent=1, allow_nan=False) + "\n"


CSV_COLUMNS = ("frame", "kind", "label", "t", "body", "E", "p")


def to_csv(history: RodHistory, frames: Sequence[Frame], at: Sequence[float] | None = None) -> str:
    """Rows frame,kind,label,t,body,E,p: kind is `before`/`after` (an impact's instant), `impulse` or `slice`."""
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(CSV_COLUMNS)
    writer.writerows(csv_rows(history, frames, at))
    return out.getvalue()


def csv_rows(history: RodHistory, frames: Sequence[Frame], at: Sequence[float] | None = None) -> list[list[str]]:
    """`to_csv`'s rows, without its header (CSV_COLUMNS)."""
    rows: list[list[str]] = []
    for f in frames:
        eta = f.rapidity
        names = sorted(p.name for p in history.scenario.particles)
        for e in impact_entries(history, eta):
            t, label = repr(e.t + 0.0), e.impact.label
            for kind, particle, kinetic, hidden, rod in (
                    ("before", e.particle_before, e.kinetic_before, e.hidden_before, e.rod_dynamical_before),
                    ("after", e.particle_after, e.kinetic_after, e.hidden_after, e.rod_dynamical_after)):
                bodies = [(e.impact.particle, particle), ("rod", e.rod_kinetic), ("rod_dynamical", rod),
                          ("kinetic", kinetic), ("hidden", hidden)]
                for body, em in bodies:
                    rows.append([f.name, kind, label, t, body, repr(em.E + 0.0), repr(em.p + 0.0)])
            rows.append([f.name, "impulse", label, t, e.impact.particle, repr(e.impulse.E + 0.0),
                         repr(e.impulse.p + 0.0)])
        for t in slice_times(history, f, at):
            s = history.energy_momentum(eta, t)
            for body, em in (*s.bodies, ("kinetic", s.kinetic), ("hidden", s.hidden)):
                if body in names or body in ("rod", "kinetic", "hidden"):
                    rows.append([f.name, "slice", "", repr(t + 0.0), body, repr(em.E + 0.0), repr(em.p + 0.0)])
    return rows


def fixed(value: float, zero: float = 0.0) -> str:
    """A ledger number: 4 decimals (one format for every number of a column), never -0."""
    text = f"{0.0 if abs(value) <= zero else value:.4f}"
    return text.lstrip("-") if float(text) == 0.0 else text


def _frame_title(f: Frame) -> str:
    return frame_heading(f) + f": velocity {number_text(f.velocity)} relative to S"


def _table(rows: list[list[str]], left: int = 1) -> list[str]:
    """Rows of cells as aligned text: the first `left` columns flush left, the rest flush right, two spaces between;
    each column as wide as its widest cell, and at least as wide as seven digits with a sign and a point, so the
    tables of one frame line up."""
    widths = [max(max(len(row[k]) for row in rows), 14 if k < left else 10) for k in range(len(rows[0]))]
    return ["  " + "  ".join(cell.ljust(w) if k < left else cell.rjust(w) for k, (cell, w) in enumerate(zip(row, widths))).rstrip()
            for row in rows]


def to_text(history: RodHistory, frames: Sequence[Frame], at: Sequence[float] | None = None) -> str:
    """For each frame: every impact with each body's (E, p) just before and after, the impulse, and the totals;
    then each slice at the times asked for."""
    s = history.scenario
    names = sorted(p.name for p in s.particles)
    lines = [f"{s.name}: v = {s.v:.10g}, L = {s.L:.10g}; E in M c^2, p in M c (M the rod's mass, c = 1), "
             f"t in the unit L is given in"]
    for f in frames:
        eta = f.rapidity
        total = history.initial_total(eta)
        zero = rounding_zero(total)

        def num(x: float) -> str:
            return number_text(x, zero)

        lines += ["", _frame_title(f),
                  f"  all bodies before the first impact: E = {number_text(total.E)}, p = {num(total.p)}"]
        for entry in instant_entries(history, eta):  # impacts at one instant of the frame: one table
            labels = " and ".join(i.label for i in entry.impacts)
            ends = ", ".join(f"{i.end} end" + (", rod still turning" if i.while_turning else "") for i in entry.impacts)
            rows = [["", "E before", "p before", "E after", "p after"]]
            for (body, b), (_, a) in zip(entry.before, entry.after):
                label = {"rod": "rod, kinetic", "hidden": "hidden"}.get(body, body)
                # a body's E is at least its rest energy, never rounding: only differences (hidden, p) may be
                e_zero = zero if body == "hidden" else 0.0
                rows.append([label, fixed(b.E, e_zero), fixed(b.p, zero), fixed(a.E, e_zero), fixed(a.p, zero)])
            rows.append(["total"] + [fixed(x, zero) for x in (total.E, total.p, total.E, total.p)])
            d_b, d_a = entry.rod_dynamical_before, entry.rod_dynamical_after
            table = _table(rows)
            lines += ["", f"  impact {labels} ({ends}) at t = {number_text(entry.t)}", *table,
                      f"  rod, dynamical (its momentum's; not a summand): E {fixed(d_b.E)} -> "
                      f"{fixed(d_a.E)}, p {fixed(d_b.p, zero)} -> {fixed(d_a.p, zero)}"]
            for i in entry.impacts:
                e = next(e for e in impact_entries(history, eta) if e.impact is i)
                lines.append(f"  impulse of {i.label} to the rod: E {fixed(e.impulse.E, zero)}, "
                             f"p {fixed(e.impulse.p, zero)}")
        if at:
            rows = [["t"] + [f"{name} {q}" for name in names + ["rod", "kinetic", "hidden"] for q in ("E", "p")]]
            for t in at:
                sl = history.energy_momentum(eta, t)
                values = [em for _, em in sl.bodies] + [sl.kinetic, sl.hidden]
                rows.append([number_text(t)] + [text for k, em in enumerate(values) for text in
                                                (number_text(em.E) if k < len(values) - 1 else num(em.E), num(em.p))])
            lines += ["", "  slices (each body's kinetic (E, p) at the frame's time t)", *_table(rows, left=0)]
    return "\n".join(lines) + "\n"
