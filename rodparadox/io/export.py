"""Machine-readable world-lines and events: the JSON contract and the CSV table (docs/json.md, "The JSON contract"). Pure.

Numbers are written with Python's shortest round-trip repr, so parsing them
back gives the same floats (never -0: a zero is 0.0); keys come in a fixed
order, so the same scenario gives the same bytes.
"""

from __future__ import annotations

import csv
import io
import json
import textwrap
from typing import Any

from rodparadox.io import export_forces
from rodparadox.physics.history import RodHistory
from rodparadox.physics.frames import (check_below_c, Frame, frame_heading, FrameView, sampling_tolerance, time_order,
                                      view)
from rodparadox.numbers import coordinate_format, exact, exact_signed, velocity_format
from rodparadox.physics.kinematics import ChartCurve, HyperbolicArc, Line, Segment

FORMAT = "sears-paradox/1"


def _point(e) -> list[float]:
    return [e.x, e.t]


def _segment(s: Segment) -> dict[str, Any]:
    if isinstance(s, Line):
        return {"kind": "line", "start": _point(s.start), "end": _point(s.end)}
    if isinstance(s, ChartCurve):  # the causal rod's: exact only through its chart, so a polyline is the data
        return {"kind": "chart", "start": _point(s.start), "end": _point(s.end), "material_label": s.X}
    assert isinstance(s, HyperbolicArc)
    return {"kind": "arc", "start": _point(s.start), "end": _point(s.end), "centre": _point(s.centre),
            "radius": s.radius, "side": s.side, "rapidity_start": s.phi_start, "rapidity_end": s.phi_end}


#: the causal rod's material points exported, at sigma = k L / MATERIAL_POINTS for k = 0 .. MATERIAL_POINTS
MATERIAL_POINTS = 8


def frame_document(fv: FrameView, tolerance: float, history=None) -> dict[str, Any]:
    check_below_c(fv)
    out = {
        "velocity": fv.frame.velocity,
        "rod_velocity_before": fv.frame.rod_velocity(),
        "t_range": list(fv.t_range),
        "events": [
            {"label": e.impact.label, "particle": e.impact.particle, "end": e.impact.end, "x": e.x, "t": e.t,
             "particle_velocity_before": e.particle_velocity_before,
             "particle_velocity_after": e.particle_velocity_after,
             "rod_velocity_before": e.rod_velocity_before, "rod_velocity_after": e.rod_velocity_after,
             "simultaneous_with": e.impact.simultaneous_with, "while_turning": e.impact.while_turning,
             "kind": e.impact.kind}
            for e in fv.events
        ],
        "worldlines": {name: points.tolist() for name, points in fv.worldline_points(tolerance).items()},
        "segments": {name: [_segment(s) for s in pieces] for name, pieces in fv.segments},
    }
    if history is not None and history.turning is None:
        L, eta = history.scenario.L, fv.frame.rapidity
        out["material_worldlines"] = [
            {"sigma": k * L / MATERIAL_POINTS,
             "points": history.material_worldline(k * L / MATERIAL_POINTS).seen_from(eta).sample(*fv.t_range, tolerance).tolist()}
            for k in range(MATERIAL_POINTS + 1)]
    return out


def document(history: RodHistory, frames: tuple[Frame, ...]) -> dict[str, Any]:
    s = history.scenario
    starts = dict(history.starts)
    tolerance = sampling_tolerance(history)
    return {
        "format": FORMAT,
        "rod": history.model,
        "scenario": {
            "name": s.name, "description": s.description, "v": s.v, "L": s.L,
            "particles": {p.name: {"mass": p.mass, "speed": s.speed(p), "start": _point(starts[p.name])}
                          for p in s.particles},
        },
        "sampling_tolerance": tolerance,
        "frames": {f.name: frame_document(view(history, f), tolerance, history) for f in frames},
    }


def to_json(history: RodHistory, frames: tuple[Frame, ...]) -> str:
    if history.driving is not None:  # a rod driven by forces (`export_forces`)
        return json.dumps(_without_negative_zeros(export_forces.document(history, frames, FORMAT)), indent=1,
                          allow_nan=False) + "\n"
    return json.dumps(_without_negative_zeros(document(history, frames)), indent=1, allow_nan=False) + "\n"


def _without_negative_zeros(value: Any) -> Any:
    """The same document with every -0.0 written as 0.0 (x + 0.0 is x, except that -0.0 + 0.0 is 0.0)."""
    if isinstance(value, float):
        return value + 0.0
    if isinstance(value, dict):
        return {k: _without_negative_zeros(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_without_negative_zeros(v) for v in value]
    return value


CSV_COLUMNS = ("frame", "kind", "name", "particle", "end", "index", "x", "t")


def to_csv(history: RodHistory, frames: tuple[Frame, ...]) -> str:
    """One row per event and per world-line point: frame,kind,name,particle,end,index,x,t."""
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(CSV_COLUMNS)
    _write_rows(writer, history, frames)
    return out.getvalue()


def _write_rows(writer, history: RodHistory, frames: tuple[Frame, ...], *first: str) -> None:
    """`to_csv`'s rows, each after the cells `first` (the rod's name, where several rods share a table)."""
    if history.driving is not None:  # a rod driven by forces (`export_forces`)
        export_forces.write_rows(writer, history, frames, *first)
        return
    tolerance = sampling_tolerance(history)
    for f in frames:
        fv = view(history, f)
        for k, e in enumerate(fv.events):
            writer.writerow([*first, f.name, "event", e.impact.label, e.impact.particle, e.impact.end, k,
                             repr(e.x + 0.0), repr(e.t + 0.0)])  # + 0.0: never -0.0
        for name, points in fv.worldline_points(tolerance).items():
            for k, (x, t) in enumerate(points.tolist()):
                writer.writerow([*first, f.name, "worldline", name, "", "", k, repr(x + 0.0), repr(t + 0.0)])


def rods_to_json(histories, frames: tuple[Frame, ...]) -> str:
    """Several rods struck by the same particles (or driven by the same forces): one object, each rod's document
    (`document`, `export_forces.document`) under "rods"."""
    return json.dumps({"format": FORMAT, "rods": {
        h.model: _without_negative_zeros(document(h, frames) if h.driving is None
                                         else export_forces.document(h, frames, FORMAT))
        for h in histories}}, indent=1, allow_nan=False) + "\n"


def rods_to_csv(histories, frames: tuple[Frame, ...]) -> str:
    """Several rods in one table: `to_csv`'s rows after a first column naming the rod."""
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(("rod", *CSV_COLUMNS))
    for h in histories:
        _write_rows(writer, h, frames, h.model)
    return out.getvalue()


def rods_to_table(histories, frames: tuple[Frame, ...], note: str = "") -> str:
    """Several rods' events tables, one after the other, each headed by its rod, after a `note` (the particles
    they share, where their first impacts fall)."""
    head = "\n".join(textwrap.wrap(note, 110)) + "\n\n" if note else ""
    return head + "\n".join(f"The {h.model} rod\n\n" + to_table(h, frames) for h in histories)


# --- the events table ---------------------------------------------------------------------------------

def to_table(history: RodHistory, frames: tuple[Frame, ...]) -> str:
    """A readable table of the impacts in each frame, for `sears-paradox events`.

    x and t are in the unit L is given in (with L = 2 the right end is at x = 1), with the digits their
    magnitude needs; columns are as wide as their widest number. A rod driven by forces: its force events
    (`export_forces.table`).
    """
    if history.driving is not None:
        return export_forces.table(history, frames)
    s = history.scenario
    views = [view(history, f) for f in frames]
    for fv in views:
        check_below_c(fv)
    ordered = [[fv.events[k] for k in time_order([e.t for e in fv.events],
                                                   s.L + max((abs(e.t) for e in fv.events), default=0.0))]
               for fv in views]  # each frame's time order (the rod's own order at one instant), as the handout's
    events = [e for frame_events in ordered for e in frame_events]
    # x and t: a column's decimals in each frame's part (as each frame's table of `events --format markdown`)
    texts = {id(e): (x_text(e.x), t_text(e.t)) for frame_events in ordered
             for x_text, t_text in [(coordinate_format([e.x for e in frame_events]),
                                     coordinate_format([e.t for e in frame_events]))] for e in frame_events}
    velocity = velocity_format([u for e in events for u in (e.particle_velocity_before, e.particle_velocity_after,
                                                               e.rod_velocity_before, e.rod_velocity_after)])
    speeds = [[velocity(u) for u in (e.particle_velocity_before, e.particle_velocity_after, e.rod_velocity_before,
                                      e.rod_velocity_after)] for e in events]
    wide = max((len(u) for us in speeds for u in us), default=0)  # left-aligned: the decimal points line up
    rows = [(e.impact.label, e.impact.end, *texts[id(e)],
             f"{us[0]:<{wide}} -> {us[1]:<{wide}}", f"{us[2]:<{wide}} -> {us[3]:<{wide}}")
            for e, us in zip(events, speeds)]
    heads = ("impact", "end", "x", "t", "particle velocity", "rod velocity")
    widths = [max([len(h)] + [len(r[k]) for r in rows]) for k, h in enumerate(heads)]
    widths[0], widths[1] = max(widths[0], 6), max(widths[1], 5)

    def line(cells) -> str:
        label, end, x, t, particle, rod = cells
        return (f"  {label:<{widths[0]}} {end:<{widths[1]}}  {x:>{widths[2]}} {t:>{widths[3]}}   "
                f"{particle:<{widths[4]}}   {rod}").rstrip()

    lines = [f"{s.name}: v = {exact(s.v)}, L = {exact(s.L)}   (c = 1; x and t in the unit L is given in)"]
    row = iter(rows)
    for f, frame_events in zip(frames, ordered):
        lines += ["", frame_heading(f) + f": velocity {exact_signed(f.velocity)} relative to S; the rod first moves at "
                  f"{exact_signed(f.rod_velocity())}",
                  line(heads)]
        for e in frame_events:
            note = f"  simultaneous with {e.impact.simultaneous_with}" if e.impact.simultaneous_with else ""
            note += "  (rod still turning)" if e.impact.while_turning else ""
            lines.append(line(next(row)) + note)
    return "\n".join(lines) + "\n"

