"""The events table, JSON and CSV of a rod driven by forces at its ends (`RodHistory.driving`, docs "Forces at the
ends"). Pure. Beside `export`, which writes the rods struck by particles and sends a driven run here.

Each force's start, peak and end at its end (kind `force`), in every frame, with the end's velocity there; the
profiles; the ends' and material points' world-lines sampled to `sampling_tolerance`; `"drive": "forces"`.
"""

from __future__ import annotations

import math
from typing import Any

from rodparadox.numbers import coordinate_format, exact, exact_signed, velocity_format
from rodparadox.physics.frames import Frame, frame_heading, sampling_tolerance, time_order, view
from rodparadox.physics.kinematics import HyperbolicArc, Line

#: the material points exported, at sigma = k L / MATERIAL_POINTS for k = 0 .. MATERIAL_POINTS
MATERIAL_POINTS = 8


def force_rows(history, frame: Frame) -> list[dict[str, Any]]:
    """Each force event seen from the frame, in the frame's time order: end, moment, x, t, the force (units of
    M c^2/L), the end's velocity, the instant in the profile's frame (units of L)."""
    eta = frame.rapidity
    rows = []
    for e in history.driving.force_events():
        seen = e.event.seen_from(eta)
        rows.append({"end": e.end, "moment": e.moment, "x": float(seen.x), "t": float(seen.t), "force": float(e.force),
                     "end_velocity": math.tanh(e.rapidity - eta), "profile_time": float(e.profile_time)})
    order = time_order([r["t"] for r in rows], history.scenario.L + max((abs(r["t"]) for r in rows), default=0.0))
    return [rows[k] for k in order]


def profile_document(profile) -> dict[str, Any]:
    out: dict[str, Any] = {"shape": profile.shape}
    if profile.shape == "points":
        out["points"] = [list(p) for p in profile.points]
    else:
        out.update(peak=profile.peak, start=profile.start, duration=profile.duration)
    out.update(frame=profile.frame, area=profile.area())
    return out


def _segment(s) -> dict[str, Any]:
    """A piece as the JSON contract writes it: a line, an arc, or a piece of a driven stage (exact only through
    the solution, so the sampled world-line is its data)."""
    out = {"start": [s.start.x, s.start.t], "end": [s.end.x, s.end.t]}
    if isinstance(s, Line):
        return {"kind": "line", **out}
    if isinstance(s, HyperbolicArc):
        return {"kind": "arc", **out, "centre": [s.centre.x, s.centre.t], "radius": s.radius, "side": s.side,
                "rapidity_start": s.phi_start, "rapidity_end": s.phi_end}
    return {"kind": "driven", **out}


def frame_document(history, frame: Frame, tolerance: float) -> dict[str, Any]:
    fv = view(history, frame)
    L, eta = history.scenario.L, frame.rapidity
    return {
        "velocity": frame.velocity,
        "rod_velocity_before": frame.rod_velocity(),
        "t_range": list(fv.t_range),
        "events": [{"kind": "force", **row} for row in force_rows(history, frame)],
        "worldlines": {name: points.tolist() for name, points in fv.worldline_points(tolerance).items()},
        "segments": {name: [_segment(s) for s in pieces] for name, pieces in fv.segments},
        "material_worldlines": [
            {"sigma": k * L / MATERIAL_POINTS,
             "points": history.material_worldline(k * L / MATERIAL_POINTS).seen_from(eta).sample(*fv.t_range,
                                                                                                  tolerance).tolist()}
            for k in range(MATERIAL_POINTS + 1)],
    }


def document(history, frames: tuple[Frame, ...], fmt: str) -> dict[str, Any]:
    s = history.scenario
    tolerance = sampling_tolerance(history)
    return {
        "format": fmt,
        "rod": history.model,
        "drive": "forces",
        "scenario": {"name": s.name, "description": s.description, "v": s.v, "L": s.L,
                     "forces": {end: profile_document(p) for end, p in history.driving.profiles()}},
        "sampling_tolerance": tolerance,
        "final_rod_velocity": math.tanh(history.final_rapidity),
        "frames": {f.name: frame_document(history, f, tolerance) for f in frames},
    }


def write_rows(writer, history, frames: tuple[Frame, ...], *first: str) -> None:
    """CSV rows (`export.CSV_COLUMNS`): each force event (kind force, name its moment, end), then each world-line
    point."""
    tolerance = sampling_tolerance(history)
    for f in frames:
        for k, row in enumerate(force_rows(history, f)):
            writer.writerow([*first, f.name, "force", row["moment"], "", row["end"], k, repr(row["x"] + 0.0),
                             repr(row["t"] + 0.0)])
        for name, points in view(history, f).worldline_points(tolerance).items():
            for k, (x, t) in enumerate(points.tolist()):
                writer.writerow([*first, f.name, "worldline", name, "", "", k, repr(x + 0.0), repr(t + 0.0)])


def table(history, frames: tuple[Frame, ...]) -> str:
    """The force events of each frame as a readable table (`sears-paradox events`)."""
    s = history.scenario
    per_frame = [force_rows(history, f) for f in frames]
    rows = [r for rs in per_frame for r in rs]
    # x and t: a column's decimals in each frame's part, as the impacts' table (`export.to_table`)
    texts = {id(r): (x_text(r["x"]), t_text(r["t"])) for rs in per_frame
             for x_text, t_text in [(coordinate_format([r["x"] for r in rs]), coordinate_format([r["t"] for r in rs]))]
             for r in rs}
    velocity = velocity_format([r["end_velocity"] for r in rows])
    force = coordinate_format([r["force"] for r in rows] + [p.greatest() for _, p in history.driving.profiles()])
    heads = ("force", "end", "x", "t", "F", "end velocity")
    cells = [(r["moment"], r["end"], *texts[id(r)], force(r["force"]),
              velocity(r["end_velocity"])) for r in rows]
    widths = [max([len(h)] + [len(c[k]) for c in cells]) for k, h in enumerate(heads)]

    def line(c) -> str:
        return (f"  {c[0]:<{widths[0]}} {c[1]:<{widths[1]}}  {c[2]:>{widths[2]}} {c[3]:>{widths[3]}}  "
                f"{c[4]:>{widths[4]}}   {c[5]}").rstrip()

    lines = [f"{s.name}: v = {exact(s.v)}, L = {exact(s.L)}   (c = 1; x and t in the unit L is given in, F in "
             f"M c^2/L)"]
    for end, p in history.driving.profiles():
        timed = {"rest": "S", "moving": "S'"}[p.frame] if isinstance(p.frame, str) else \
            f"the frame of velocity {exact_signed(p.frame)}"
        lines.append(f"  force on the {end} end: {p.shape}, timed in {timed}, momentum delivered there "
                     f"{exact(round(p.area(), 12))} M c")
    row = iter(cells)
    for f, rs in zip(frames, per_frame):
        lines += ["", frame_heading(f) + f": velocity {exact_signed(f.velocity)} relative to S; the rod first moves "
                  f"at {exact_signed(f.rod_velocity())}", line(heads)]
        for _ in rs:
            lines.append(line(next(row)))
    return "\n".join(lines) + "\n"
