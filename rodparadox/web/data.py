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
* the ledger (each body's kinetic (E, p) and the hidden part) on a grid of frames (`LEDGER_FRAMES`, and S') and of
  instants (`LEDGER_INSTANTS` over each frame's time window): the rod's kinetic part and the hidden part on a
  slice are not one four-vector, so they cannot be boosted; the page shows the slice nearest its frame and instant
  and says which.
"""

from __future__ import annotations

import math
from types import SimpleNamespace
from typing import Any, Sequence

from rodparadox.errors import RodParadoxError
from rodparadox.numbers import impact_name
from rodparadox.physics.types import WORLDLINE_NAMES
from rodparadox.physics.models import run_rod
from rodparadox.physics.frames import check_below_c, Frame, frame_of_velocity, moving_frame, rest_frame, time_window
from rodparadox.physics.kinematics import HyperbolicArc, WorldLine
from rodparadox.physics.model import Scenario
from rodparadox.tables.build import events_table
from rodparadox.tolerances import ONE_INSTANT, SAMPLING_TOLERANCE

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
#: decimals of the ledger's numbers (the ledger prints 4)
LEDGER_DECIMALS = 5
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


def table_rows(history, frame: Frame) -> dict[str, Any]:
    """The events table of one frame as `events` writes it (digits and fractions), cells as text."""
    table = events_table(history, frame)
    return {"caption": table.caption, "header": list(table.header),
            "rows": [[cell.text for cell in row] for row in table.rows],
            "notes": [note.replace(TABLE_UNITS, "in units of L") for note in table.notes]}


def ledger(history, frames: Sequence[Frame]) -> list[dict[str, Any]]:
    """Each frame's ledger on LEDGER_INSTANTS slices over its time window: per slice, each body's (E, p), the rod's
    kinetic part and the hidden part, in the body order of `ledger_slice`."""
    out = []
    for frame in frames:
        lo, hi = time_window(history, frame)
        slices = []
        for k in range(LEDGER_INSTANTS):
            t = lo + (hi - lo) * k / (LEDGER_INSTANTS - 1)
            s = history.energy_momentum(frame.rapidity, t)
            bodies = [*s.bodies, ("hidden", s.hidden)]
            slices.append([drawn(t)] + [fixed(number) for _, em in bodies for number in (em.E, em.p)])
        names = [name for name, _ in history.energy_momentum(frames[0].rapidity, 0.0).bodies] + ["hidden"]
        out.append({"u": frame.velocity + 0.0, "bodies": names, "slices": slices})
    return out


def model_data(history, v: float) -> dict[str, Any]:
    """One rod model's run at one speed: what the page draws and prints (the module's docstring)."""
    s = history.scenario
    L = s.L
    frames = (rest_frame(), moving_frame(v), *(frame_of_velocity(u) for u in LEDGER_FRAMES if u != -v))
    for frame in frames:  # the check reads the frame and the impacts only: no need to sample a view
        check_below_c(SimpleNamespace(frame=frame, events=[SimpleNamespace(impact=i) for i in history.impacts]))
    if history.fronts is not None:
        from rodparadox.web import causal_data

        ledger_frames = (frames[1], frames[0], *(frame_of_velocity(u) for u in CAUSAL_LEDGER_FRAMES if u != -v))
        return causal_data.model_data(history, v, ledger_frames, FRAME_REACH,
                                      CAUSAL_LINE_TOLERANCE, CAUSAL_MATERIAL_TOLERANCE, CAUSAL_DIGITS, MATERIAL_DIGITS,
                                      LEDGER_INSTANTS, table_rows, fixed)
    worldlines = {name: history.worldline(name) for name in WORLDLINE_NAMES if history.worldline(name) is not None}
    impacts = [{"label": i.label, "name": impact_name(i.label), "particle": i.particle, "end": i.end,
                "x": i.event.x / L, "t": i.event.t / L, "particle_before": i.particle_rapidity_before,
                "particle_after": i.particle_rapidity_after, "rod_before": i.rod_rapidity_before,
                "rod_after": i.rod_rapidity_after, "simultaneous_with": i.simultaneous_with}
               for i in history.impacts]
    changes = [(i.event.x, i.event.t) for i in history.impacts]
    for w in worldlines.values():
        changes += [(e.x, e.t) for seg in w.segments for e in (seg.start, seg.end)]
    starts = [(e.x, e.t) for _, e in history.starts] + [(-L / 2, 0.0), (L / 2, 0.0)]
    exact = [history.material_worldline(L * k / (MATERIAL_POINTS - 1)) for k in range(MATERIAL_POINTS)]
    material = [sampled(w, L, MATERIAL_TOLERANCE, MATERIAL_DIGITS) for w in exact]
    # the colour scale's half-range: a point's rapidity is monotonic on each segment, so its extremes are ends
    bound = max(abs(r) for w in exact for r in (w.rapidity_before, w.rapidity_after,
                                                 *(s.rapidity_at_start for s in w.segments),
                                                 *(s.rapidity_at_end for s in w.segments)))
    return {
        "model": history.model,
        "impacts": impacts,
        "worldlines": {name: sampled(w, L, LINE_TOLERANCE) for name, w in worldlines.items()},
        "material": material,
        "colour_bound": bound,
        "changes": [[drawn(x / L), drawn(t / L)] for x, t in changes],
        "starts": [[x / L, t / L] for x, t in starts],
        "tables": {"rest": table_rows(history, frames[0]), "moving": table_rows(history, frames[1])},
        "ledger": ledger(history, frames[1:2] + frames[:1] + frames[2:]),
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
    own = [v for v in grid if v == scenario.v or v in extra]
    for v in own + [v for v in grid if v not in own]:  # a refusal of the page's own speeds first, at once
        ran = []
        for model in models:
            asked = v in own and model in opened
            try:
                history = run_rod(scenario.with_overrides(v=v, rod=model), budget=None if asked else OFFERED_WORK)
                ran.append(model_data(history, v))
            except RodParadoxError:
                if asked:
                    raise
                left_out[model].append(v)
        if ran:
            entries.append({"v": v, "models": ran})
    entries.sort(key=lambda e: e["v"])
    left_out = {model: sorted(vs) for model, vs in left_out.items()}
    return {"name": name, "title": scenario.title or name, "description": scenario.description.strip(),
            "v": scenario.v, "L": scenario.L, "speeds": entries, "left_out": left_out, "rod": shown or scenario.rod,
            "one_instant": ONE_INSTANT, "frame_reach": FRAME_REACH}


def page_data(scenarios: Sequence[tuple[str, Scenario]], style: str, shown: str | None = None) -> dict[str, Any]:
    """Everything a page embeds: its scenarios (name, scenario with --v and --L) and the styles' inks; `shown`:
    the rod the page opens on (rigid, causal or both; by default each scenario's own)."""
    from rodparadox.web.inks import inks

    from rodparadox.render.shading import SHADES

    return {"format": FORMAT, "style": style, "styles": inks(), "about_several": ABOUT_SEVERAL, "shades": SHADES,
            "scenarios": [scenario_data(name, s, shown=shown) for name, s in scenarios]}
