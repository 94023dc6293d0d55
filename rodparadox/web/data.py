"""What the html page embeds: every number it shows, computed here by the engine (the docs, "One page to explore:
`sears-paradox html`"). Pure: no matplotlib, no file.

The page never solves the physics. Per scenario, per speed v of a grid (the scenario's own v included), per rod
model (`MODELS`: the rigid rod, then the causal rod, whose part `causal_data` gives), this gives:

* the impacts in S, every digit (`repr`), with their rapidities: boosting an event is exact, so the page places
  them in any frame;
* the world-lines of the particles and the rod's ends in S, as points on the exact curves (arcs sampled so that
  the polyline stays within `LINE_TOLERANCE` L of the curve in every frame |u| <= 0.95) with each point's rapidity:
  boosted point by point, they stay on the curves; before the first point and after the last each is straight at
  its rapidity `before`/`after`;
* the same for `MATERIAL_POINTS` material points of the rod, for the strip under the diagram (coarser: it is drawn
  small), and the colour scale's half-range in rapidity, which is the same in every frame;
* the events tables of S and S' as `sears-paradox events` writes them, with their fractions (`tables.build`);
* the ledger (each body's kinetic (E, p), the hidden part and the total, with the rows' names) on a grid of frames
  (`LEDGER_FRAMES`, and S') and of instants (`LEDGER_INSTANTS` evenly over each frame's time window): the rod's
  kinetic part and the hidden part on a slice are not one four-vector, so they cannot be boosted; the page shows
  the slice nearest its frame and instant and says which;
* the time window of every frame the page can show (each position of the frame slider, and S'; `windows`), the
  tables' format rules (`numbers.coordinate_format`, `velocity_format`: their parameters, for the frames the
  page boosts itself) and the nice multiples its tick steps are chosen from (the choice depends on the pixels);
* for a rod driven by forces (`forces_data`): each force's band, its start, peak and end, their tables as
  `events` prints them, and the ledger of `ledger` (what each agent delivered, the rod's parts, the check).
"""

from __future__ import annotations

import math
import re
from types import SimpleNamespace
from typing import Any, Sequence

import numpy as np

from rodparadox.errors import RodParadoxError
from rodparadox.numbers import MINUS, impact_name
from rodparadox.physics.types import WORLDLINE_NAMES
from rodparadox.physics.models import run_rod
from rodparadox.physics.frames import check_below_c, Frame, frame_of_velocity, moving_frame, rest_frame
from rodparadox.physics.kinematics import HyperbolicArc, WorldLine
from rodparadox.physics.model import Scenario
from rodparadox.tables.build import events_table
from rodparadox.tolerances import ONE_INSTANT, SAMPLING_TOLERANCE
from rodparadox.web import forces_data, windows
from rodparadox.web.windows import slider_steps, slider_velocities

FORMAT = "sears-paradox-html/1"
#: the speeds every page offers (v = 0.05, 0.10, ... 0.95), besides the scenario's own
SPEED_STEPS = 19
#: the fastest frame the frame slider reaches (both ways); S' beyond it widens the slider
FRAME_REACH = 0.95
#: the sampled world-lines stay within SAMPLING_TOLERANCE L of the exact curve in every frame up to FRAME_REACH:
#: a boost of rapidity eta stretches distances by at most e^|eta| (6.2 at 0.95)
LINE_TOLERANCE = SAMPLING_TOLERANCE / math.exp(math.atanh(FRAME_REACH))
#: the strip's material points, their tolerance (units of L, in S) and digits: the strip is drawn a few hundred
#: pixels wide, about a hundredth of L to a pixel
MATERIAL_POINTS = 33
MATERIAL_TOLERANCE = 1e-3
#: the causal rod's ends and particles: within 1e-3 L of the curve in every frame up to FRAME_REACH (a fifth of a
#: pixel on a projector; its curves bend at every contact and ring for ever, and 1e-4 would double the page)
CAUSAL_LINE_TOLERANCE = 1e-3 / math.exp(math.atanh(FRAME_REACH))
#: its material lines (three, drawn thin) within 2e-3 L in S; its points with 6 significant digits (a millionth of
#: the panel, far below a pixel)
CAUSAL_MATERIAL_TOLERANCE = 2e-3
CAUSAL_DIGITS = 6
#: the rod models every page embeds, in the switch's order
MODELS = ("rigid", "causal")
#: the causal rod's runs the page only offers (other speeds, a rod it does not open on) are bounded: windows of
#: chart time L and steps of its contacts (`causal.budget.Budget`; every preset takes at most 150 at every speed of
#: the grid, about a millisecond each), or the speed is left out: a page never waits on a run it was not asked for
OFFERED_WORK = 1000
#: the ledger's frames (velocities relative to S) besides S', and its instants per frame's time window
LEDGER_FRAMES = (-0.9, -0.6, -0.3, 0.3, 0.6, 0.9)
#: the causal rod's (its matter and stress are integrated across each slice: half the frames, half the cost)
CAUSAL_LEDGER_FRAMES = (-0.6, 0.6)
LEDGER_INSTANTS = 41
#: a rod driven by forces: its ledger's frames besides S and S' and its instants (a slice of the rigid rod costs
#: milliseconds: its stress integrated across it)
FORCES_LEDGER_FRAMES = (-0.6, 0.6)
FORCES_LEDGER_INSTANTS = 21
#: decimals of the time windows (units of L; a pixel is about 1e-2 L, the diagram about 1e2 pixels per L)
WINDOW_DECIMALS = 3
#: decimals of the ledger's numbers, as the page prints them (and as the ledger's table, `tables.build`): the
#: numbers are embedded rounded to them, so that the page's cells are their shortest text
LEDGER_DECIMALS = 4
#: significant digits of the drawn points and the ledger's numbers (a pixel is 1e-3 of a panel; the ledger prints 4
#: decimals); the impacts keep every digit
DRAWN_DIGITS = 7


def speeds(scenario: Scenario, extra: Sequence[float] = ()) -> tuple[float, ...]:
    """The grid of speeds a page offers, in order: 0.05 to 0.95 in steps of 0.05, the scenario's own v and `extra`."""
    grid = {round(0.05 * (k + 1), 2) for k in range(SPEED_STEPS)}
    return tuple(sorted(grid | {scenario.v, *extra}))


MATERIAL_DIGITS = 5


def drawn(value: float, digits: int = DRAWN_DIGITS) -> float:
    """A drawn number with `digits` significant digits, never -0: the same text in every run."""
    return float(f"{value:.{digits}g}") + 0.0


def fixed(value: float) -> float:
    """A ledger number with LEDGER_DECIMALS decimals, never -0."""
    return round(value, LEDGER_DECIMALS) + 0.0


def ledger_cell(value: float) -> str:
    """A ledger cell as the page prints it: LEDGER_DECIMALS decimals, a real minus, no sign on a zero or a positive."""
    text = f"{value + 0.0:.{LEDGER_DECIMALS}f}"
    return (text.lstrip("-") if float(text) == 0 else text).replace("-", MINUS)


def sampled(worldline: WorldLine, L: float, tolerance: float, digits: int = DRAWN_DIGITS) -> dict[str, Any]:
    """The world-line's exact segments as points (x, t in units of L, and the rapidity phi there; the polyline within
    `tolerance` L of the curve in S), a kink given twice with the rapidity before and after it, and its rapidity
    before the first point and after the last."""
    x, t, phi = [], [], []
    first = worldline.first
    x.append(first.x), t.append(first.t), phi.append(worldline.rapidity_before)
    for segment in worldline.segments:
        points = segment.sample(tolerance * L)
        if isinstance(segment, HyperbolicArc) and segment.radius > 0:
            angles = [segment.phi_start, *(segment.phi_at_time(p[1]) for p in points[1:-1]), segment.phi_end]
        else:
            angles = [segment.rapidity_at_start] * len(points)
        for (px, pt), a in zip(points, angles):
            x.append(px), t.append(pt), phi.append(a)
    last = worldline.last
    x.append(last.x), t.append(last.t), phi.append(worldline.rapidity_after)
    return {"x": [drawn(v / L, digits) for v in x], "t": [drawn(v / L, digits) for v in t],
            "phi": [drawn(v, digits) for v in phi],
            "before": worldline.rapidity_before + 0.0, "after": worldline.rapidity_after + 0.0}


#: the heading's paragraph where the page holds several scenarios: true where the chooser sits beside the diagram
#: (a laptop) and where it sits under it (a phone)
ABOUT_SEVERAL = "This page holds several scenarios: choose one with the scenario menu."
#: how the shared tables name the unit (`tables.build`); the page says it as a textbook does
TABLE_UNITS = "in the unit L is given in"
#: an apostrophe between letters, as the shared tables and the scenarios write it (rod's): the page sets rod’s
APOSTROPHE = re.compile(r"(?<=\w)'(?=\w)")


def typographic(text: str) -> str:
    """The text with each apostrophe set as print sets it (the paper’s), as the handouts and figures do."""
    return APOSTROPHE.sub("\N{RIGHT SINGLE QUOTATION MARK}", text)


def table_rows(history, frame: Frame) -> dict[str, Any]:
    """The events table of one frame as `events` writes it (digits and fractions), cells as text."""
    table = events_table(history, frame)
    return {"caption": typographic(table.caption), "header": list(table.header),
            "rows": [[cell.text for cell in row] for row in table.rows],
            "notes": [typographic(note.replace(TABLE_UNITS, "in units of L")) for note in table.notes]}


#: the ledger's row labels (the names `Slice.bodies` gives, then the hidden part and the total)
ROW_NAMES = {"rod": "rod (kinetic)", "hidden": "hidden (stress)", "matter": "rod, matter", "stress": "rod, stress"}


def row_name(body: str) -> str:
    """How the page's ledger names a body: the rod's parts by ROW_NAMES, a particle as `particle A`."""
    return ROW_NAMES.get(body, body if body not in ("A", "B") else f"particle {body}")


def ledger(history, frames: Sequence[Frame], window) -> list[dict[str, Any]]:
    """Each frame's ledger on LEDGER_INSTANTS slices evenly over its time window (`window(rapidities)`): per
    slice, each body's (E, p), the hidden part and their total, in the order of `rows`."""
    out = []
    spans = window([frame.rapidity for frame in frames])
    for frame, (lo, hi) in zip(frames, spans):
        slices = []
        for k in range(LEDGER_INSTANTS):
            t = lo + (hi - lo) * k / (LEDGER_INSTANTS - 1)
            s = history.energy_momentum(frame.rapidity, t)
            bodies = [*s.bodies, ("hidden", s.hidden)]
            total = s.kinetic + s.hidden
            slices.append([fixed(number) for em in [*(em for _, em in bodies), total] for number in (em.E, em.p)])
        names = [row_name(name) for name, _ in history.energy_momentum(frames[0].rapidity, 0.0).bodies]
        out.append({"u": frame.velocity + 0.0, "rows": names + [row_name("hidden"), "total"], "slices": slices,
                    "window": [lo / history.scenario.L, hi / history.scenario.L]})
    return out


def forces_ledger(history, frames: Sequence[Frame], window) -> list[dict[str, Any]]:
    """The ledger of a rod driven by forces (`forces_data.ledger_slice`), each frame's slices evenly over its
    window (FORCES_LEDGER_INSTANTS of them)."""
    out = []
    spans = window([frame.rapidity for frame in frames])
    rows = list(forces_data.ledger_rows(history))
    for frame, (lo, hi) in zip(frames, spans):
        times = [lo + (hi - lo) * k / (FORCES_LEDGER_INSTANTS - 1) for k in range(FORCES_LEDGER_INSTANTS)]
        slices = [[fixed(n) for n in forces_data.ledger_slice(history, frame.rapidity, t)] for t in times]
        out.append({"u": frame.velocity + 0.0, "rows": rows, "slices": slices,
                    "window": [lo / history.scenario.L, hi / history.scenario.L]})
    return out


def windows_data(window, v: float, steps: int, L: float) -> dict[str, Any]:
    """The time window (units of L) of every frame the page can show: the frame slider's (`windows.slider_velocities`,
    in its order) and S'."""
    velocities = slider_velocities(steps)
    spans = window(np.concatenate([np.arctanh(velocities), [math.atanh(-v)]])) / L
    near = lambda value: round(float(value), WINDOW_DECIMALS) + 0.0  # noqa: E731
    return {"lo": [near(a) for a in spans[:-1, 0]], "hi": [near(b) for b in spans[:-1, 1]],
            "moving": [near(spans[-1, 0]), near(spans[-1, 1])]}


def model_data(history, v: float, steps: int = 95) -> dict[str, Any]:
    """One rod model's run at one speed: what the page draws and prints (the module's docstring); `steps`: the frame
    slider's reach in hundredths of c (`windows.slider_steps`)."""
    s = history.scenario
    L = s.L
    frames = (rest_frame(), moving_frame(v), *(frame_of_velocity(u) for u in LEDGER_FRAMES if u != -v))
    for frame in frames:  # the check reads the frame and the impacts only: no need to sample a view
        check_below_c(SimpleNamespace(frame=frame, events=[SimpleNamespace(impact=i) for i in history.impacts]))
    window = windows.changes(history).windows
    if history.fronts is not None:
        from rodparadox.web import causal_data

        ledger_frames = (frames[1], frames[0], *(frame_of_velocity(u) for u in CAUSAL_LEDGER_FRAMES if u != -v))
        out = causal_data.model_data(history, v, ledger_frames, FRAME_REACH, window,
                                     CAUSAL_LINE_TOLERANCE, CAUSAL_MATERIAL_TOLERANCE, CAUSAL_DIGITS, MATERIAL_DIGITS,
                                     LEDGER_INSTANTS, table_rows, fixed)
    else:
        out = rigid_data(history, v, frames, window)
    out["windows"] = windows_data(window, v, steps, L)
    end_events = out.pop("end_events", None) or _end_events(history)
    if history.driving is not None:
        out["forces"] = {"scale": forces_data.scale(history), "events": forces_data.events(history),
                         "bands": forces_data.bands(history, end_events, DRAWN_DIGITS),
                         "arrows": forces_data.arrows(history, end_events, DRAWN_DIGITS)}
        out["tables"] = forces_data.tables(history, frames[:2])
        out["final"] = history.final_rapidity
        out["ledger_note"] = typographic(forces_data.ledger_note(history))
    return out


def _end_events(history):
    """Where an end is in S (units of L) when the frame of rapidity f reads the times (units of L) there: on its
    exact world-line (a causal rod's from its tables instead, `causal_data.end_events`)."""
    L = history.scenario.L

    def at(end: str, f: float, times):
        seen = history.worldline(f"rod_{end}").seen_from(f)
        events = [seen.event_at_time(t * L).seen_from(-f) for t in times]
        return [e.x / L for e in events], [e.t / L for e in events]
    return at


def rigid_data(history, v: float, frames, window) -> dict[str, Any]:
    """The rigid rod (struck by particles or driven by forces) at one speed."""
    L = history.scenario.L
    worldlines = {name: history.worldline(name) for name in WORLDLINE_NAMES if history.worldline(name) is not None}
    impacts = [{"label": i.label, "name": impact_name(i.label), "particle": i.particle, "end": i.end,
                "x": i.event.x / L, "t": i.event.t / L, "particle_before": i.particle_rapidity_before,
                "particle_after": i.particle_rapidity_after, "rod_before": i.rod_rapidity_before,
                "rod_after": i.rod_rapidity_after, "simultaneous_with": i.simultaneous_with}
               for i in history.impacts]
    exact = [history.material_worldline(L * k / (MATERIAL_POINTS - 1)) for k in range(MATERIAL_POINTS)]
    material = [sampled(w, L, MATERIAL_TOLERANCE, MATERIAL_DIGITS) for w in exact]
    # the colour scale's half-range: a point's rapidity is monotonic on each segment, so its extremes are ends
    bound = max(abs(r) for w in exact for r in (w.rapidity_before, w.rapidity_after,
                                                 *(s.rapidity_at_start for s in w.segments),
                                                 *(s.rapidity_at_end for s in w.segments)))
    ledger_frames = frames[1:2] + frames[:1] + frames[2:]
    if history.driving is not None:  # the ledger of forces: dearer per slice, fewer frames
        ledger_frames = ledger_frames[:2] + tuple(frame_of_velocity(u) for u in FORCES_LEDGER_FRAMES if u != -v)
    return {
        "model": history.model,
        "impacts": impacts,
        "worldlines": {name: sampled(w, L, LINE_TOLERANCE) for name, w in worldlines.items()},
        "material": material,
        "colour_bound": bound,
        "tables": {"rest": table_rows(history, frames[0]), "moving": table_rows(history, frames[1])},
        "ledger": (ledger if history.driving is None else forces_ledger)(history, ledger_frames, window),
    }


def scenario_data(name: str, scenario: Scenario, extra: Sequence[float] = (), shown: str | None = None,
                  models: Sequence[str] | None = None) -> dict[str, Any]:
    """One scenario at every speed of its grid that the engine runs, in each rod model of `models`. `shown`: the
    rod the page opens on (rigid, causal or both; by default the scenario's own).

    The page opens on its own speeds (the scenario's v and `extra`) in the rods it is asked for: those run as every
    command runs them, and their refusal is the page's. Every other run (another speed, a rod only offered by the
    switch) is bounded (`OFFERED_WORK`, the causal rod's bounds on what it draws): a speed a model refuses, or
    would not finish within those bounds, or at which some body would move at c in double precision in a frame of
    the page, is left out of that model and named in `left_out`, which the page says."""
    models = MODELS if models is None else models
    opened = {"both": ("rigid", "causal")}.get(shown or scenario.rod, (shown or scenario.rod,))
    entries, left_out = [], {model: [] for model in models}
    grid = speeds(scenario, extra)
    steps = slider_steps(max(FRAME_REACH, *grid))  # the frame slider reaches every speed's S'
    own = [v for v in grid if v == scenario.v or v in extra]
    for v in own + [v for v in grid if v not in own]:  # a refusal of the page's own speeds first, at once
        ran = []
        for model in models:
            asked = v in own and model in opened
            try:
                history = run_rod(scenario.with_overrides(v=v, rod=model), budget=None if asked else OFFERED_WORK)
                ran.append(model_data(history, v, steps))
            except RodParadoxError:
                if asked:
                    raise
                left_out[model].append(v)
        if ran:
            entries.append({"v": v, "models": ran})
    entries.sort(key=lambda e: e["v"])
    left_out = {model: sorted(vs) for model, vs in left_out.items()}
    return {"name": name, "title": typographic(scenario.title or name),
            "description": typographic(scenario.description.strip()),
            "v": scenario.v, "L": scenario.L, "speeds": entries, "left_out": left_out, "rod": shown or scenario.rod,
            "one_instant": ONE_INSTANT, "frame_steps": steps}


def page_data(scenarios: Sequence[tuple[str, Scenario]], style: str, shown: str | None = None) -> dict[str, Any]:
    """Everything a page embeds: its scenarios (name, scenario with --v and --L) and the styles' inks; `shown`:
    the rod the page opens on (rigid, causal or both; by default each scenario's own)."""
    from rodparadox.web.inks import force_inks, inks

    from rodparadox.render.shading import SHADES

    from rodparadox.numbers import NICE_MULTIPLES, SCIENTIFIC_BELOW, TABLE_DIGITS
    from rodparadox.tolerances import PRINTED_ZERO

    out = {"format": FORMAT, "style": style, "styles": inks(), "about_several": ABOUT_SEVERAL, "shades": SHADES,
           "formats": {"digits": TABLE_DIGITS, "printed_zero": PRINTED_ZERO, "ledger_decimals": LEDGER_DECIMALS,
                       "scientific_below": SCIENTIFIC_BELOW},
           "tick_multiples": [*NICE_MULTIPLES, 10], "scenarios": [scenario_data(name, s, shown=shown) for name, s in scenarios]}
    if any(s.forces is not None for _, s in scenarios):  # the bands' inks, in a page that draws forces
        out["force_inks"] = force_inks()
    return out
