"""Machine-readable world-lines and events: the JSON contract and the CSV table (README, "JSON contract"). Pure.

Numbers are written with Python's shortest round-trip repr, so parsing them
back gives the same floats; keys come in a fixed order, so the same scenario
gives the same bytes.
"""

from __future__ import annotations

import csv
import io
import json
from typing import Any

from .frames import Frame, FrameView, sampling_tolerance, view
from .engine import History
from .kinematics import HyperbolicArc, Line, Segment

FORMAT = "sears-paradox/1"


def _point(e) -> list[float]:
    return [e.x, e.t]


def _segment(s: Segment) -> dict[str, Any]:
    if isinstance(s, Line):
        return {"kind": "line", "start": _point(s.start), "end": _point(s.end)}
    assert isinstance(s, HyperbolicArc)
    return {"kind": "arc", "start": _point(s.start), "end": _point(s.end), "centre": _point(s.centre),
            "radius": s.radius, "side": s.side, "rapidity_start": s.phi_start, "rapidity_end": s.phi_end}


def frame_document(fv: FrameView, tolerance: float) -> dict[str, Any]:
    return {
        "velocity": fv.frame.velocity,
        "rod_velocity_before": fv.frame.rod_velocity(),
        "t_range": list(fv.t_range),
        "events": [
            {"label": e.impact.label, "particle": e.impact.particle, "end": e.impact.end, "x": e.x, "t": e.t,
             "particle_velocity_before": e.particle_velocity_before,
             "particle_velocity_after": e.particle_velocity_after,
             "rod_velocity_before": e.rod_velocity_before, "rod_velocity_after": e.rod_velocity_after,
             "simultaneous_with": e.impact.simultaneous_with, "while_turning": e.impact.while_turning}
            for e in fv.events
        ],
        "worldlines": {name: points.tolist() for name, points in fv.worldline_points(tolerance).items()},
        "segments": {name: [_segment(s) for s in pieces] for name, pieces in fv.segments},
    }


def document(history: History, frames: tuple[Frame, ...]) -> dict[str, Any]:
    s = history.scenario
    starts = dict(history.starts)
    tolerance = sampling_tolerance(history)
    return {
        "format": FORMAT,
        "scenario": {
            "name": s.name, "description": s.description, "v": s.v, "L": s.L,
            "particles": {p.name: {"mass": p.mass, "speed": s.speed(p), "start": _point(starts[p.name])}
                          for p in s.particles},
        },
        "sampling_tolerance": tolerance,
        "frames": {f.name: frame_document(view(history, f), tolerance) for f in frames},
    }


def to_json(history: History, frames: tuple[Frame, ...]) -> str:
    return json.dumps(document(history, frames), indent=1, allow_nan=False) + "\n"


CSV_COLUMNS = ("frame", "kind", "name", "particle", "end", "index", "x", "t")


def to_csv(history: History, frames: tuple[Frame, ...]) -> str:
    """One row per event and per world-line point: frame,kind,name,particle,end,index,x,t."""
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(CSV_COLUMNS)
    tolerance = sampling_tolerance(history)
    for f in frames:
        fv = view(history, f)
        for k, e in enumerate(fv.events):
            writer.writerow([f.name, "event", e.impact.label, e.impact.particle, e.impact.end, k, repr(e.x), repr(e.t)])
        for name, points in fv.worldline_points(tolerance).items():
            for k, (x, t) in enumerate(points.tolist()):
                writer.writerow([f.name, "worldline", name, "", "", k, repr(x), repr(t)])
    return out.getvalue()


def _velocity(u: float) -> str:
    """+0.600000; with more digits where six would round a speed below 1 up to 1; never -0."""
    digits = 6 if abs(u) < 0.9999995 else 10
    return f"{u + 0.0:+.{digits}f}"


def to_table(history: History, frames: tuple[Frame, ...]) -> str:
    """A readable table of the impacts in each frame, for `sears-paradox events`."""
    s = history.scenario
    lines = [f"{s.name}: v = {s.v:.10g}, L = {s.L:.10g}   (c = 1; x and t in the unit of L)"]
    header = f"  {'impact':<7}{'end':<7}{'x':>11} {'t':>11}   {'particle velocity':<23}   {'rod velocity'}"
    for f in frames:
        fv = view(history, f)
        title = {"rest": "S, the rod's rest frame", "moving": "S', where the rod first moves at +v"}.get(f.name, "")
        lines += ["", f"frame {f.name}" + (f" ({title})" if title else "") +
                  f": velocity {f.velocity + 0.0:+.10g} relative to S; the rod first moves at {f.rod_velocity() + 0.0:+.10g}",
                  header]
        for e in fv.events:
            note = f"  simultaneous with {e.impact.simultaneous_with}" if e.impact.simultaneous_with else ""
            note += "  (rod still turning)" if e.impact.while_turning else ""
            lines.append(f"  {e.impact.label:<7}{e.impact.end:<7}{e.x + 0.0:>+11.6f} {e.t + 0.0:>+11.6f}   "
                         f"{_velocity(e.particle_velocity_before)} -> {_velocity(e.particle_velocity_after)}   "
                         f"{_velocity(e.rod_velocity_before)} -> {_velocity(e.rod_velocity_after)}{note}")
    return "\n".join(lines) + "\n"
