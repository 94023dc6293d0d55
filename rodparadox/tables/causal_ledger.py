"""The causal rod's ledger (docs/model.md, "The causal rod"): each body's (E, p) at every contact and separation and on
chosen slices of a frame, the rod's split into its matter part and its stress part. Pure.

The stress part, p (u u - eta) integrated across the slice, is von Laue's momentum of a stressed body. The rigid
ledger's "hidden" row is a total less the bodies (no field carries it); here every part is the rod's own, so the
rows add up to the total before the first contact with nothing hidden. (What corresponds to the rigid hidden part is
the total less the rest mass moving with the rod, not the stress part alone: their near match in fig2 is chance.) The split costs
an integral along the slice (`Fronts.rod_parts`, `physics.causal.parts`), so it is taken at the events and at the
times asked for; a dense sampling (JSON, CSV without times) gives the rod's total only, which is exact and cheap.

One table per frame (`ledger_table`), written as Markdown or LaTeX (`tables.formats`) or as aligned text
(`to_text`); `document` and `to_csv` give the same numbers at full precision.
"""

from __future__ import annotations

import csv
import functools
import io
import json
import textwrap
from typing import Any, Sequence

from rodparadox.numbers import MINUS, coordinate_format, exact, impact_name
from rodparadox.physics.frames import Frame, frame_heading, frame_symbol, frame_word, time_window
from rodparadox.physics.types import EnergyMomentum
from rodparadox.physics.ledger import rounding_zero
from rodparadox.tables.build import coordinates, fixed
from rodparadox.tables.formats import tables_latex, tables_markdown
from rodparadox.tables.table import Cell, Table

FORMAT = "sears-paradox-ledger/1"
#: slices of a frame's window in the dense sampling (JSON and CSV without times): the rod's total only
DENSE_SLICES = 240
#: the rows' labels: the stress row says what it is
MATTER, STRESS = "rod, matter", "rod, stress"
UNITS = "E in M c², p in M c, M the rod's mass; t in the unit L is given in"
NOTE = ("The rod's (E, p) is split into its matter part (its rest-frame energy density moving with it, elastic "
        "energy included) and its stress part (its pressure's p (u u - η), integrated across the slice: von "
        "Laue's momentum of a stressed body). Particles, matter and stress add up to the total before the first "
        "contact; nothing is hidden. The rigid ledger's hidden part corresponds to this rod's total less its rest "
        "mass moving with it, (M/L)∫(cosh ψ, sinh ψ) dσ, not to the stress part alone.")


def event_name(label: str) -> str:
    """A contact as B₁, its separation as B′₁ (the figures' labels, plain text: `numbers.impact_name`)."""
    return impact_name(label)


def instants(history, frame: Frame) -> list[tuple[str, str, float, object]]:
    """(label, kind, t, impact) of every contact and separation in the frame's time order; events at one time (to
    rounding, 1e-9 L: Fig. 2's B₁ and A₁ in S′) in the history's own order, whatever the unit of length."""
    f, L = frame.rapidity, history.scenario.L
    order = {id(i): k for k, i in enumerate(history.impacts)}
    out = sorted(((i.label, i.kind, i.event.time_in(f), i) for i in history.impacts), key=lambda e: e[2])
    for k in range(1, len(out)):  # an insertion pass over ties: rounding must not order simultaneous events
        j = k
        while (j > 0 and abs(out[j][2] - out[j - 1][2]) <= 1e-9 * (L + abs(out[j][2]))
               and order[id(out[j][3])] < order[id(out[j - 1][3])]):
            out[j - 1], out[j] = out[j], out[j - 1]
            j -= 1
    return out


def time_format(times: Sequence[float]):
    """The t column's text: four decimals where they tell every time apart and the largest keeps four significant
    digits (0.1 <= |t| < 1e5), else TABLE_DIGITS significant digits (L = 1e-5 put every event at 0.0000)."""
    largest = max((abs(t) for t in times), default=0.0)
    distinct = []  # the times, those within rounding of each other (simultaneous events) once
    for t in sorted(times):
        if not distinct or t - distinct[-1] > 1e-9 * largest:
            distinct.append(t)
    if 0.1 <= largest < 1e5 and len({fixed(t) for t in distinct}) == len(distinct):
        return fixed
    text = coordinate_format(list(times))
    return lambda t: (lambda x: MINUS + x[1:] if x.startswith("-") else x)(text(t).lstrip("+"))  # as `fixed`


def rows_at(history, frame: Frame, t: float, event=None) -> list[tuple[str, EnergyMomentum]]:
    """The summands on the slice t (through `event`, an Impact, if given): each particle, the rod's matter, its
    stress; then their total."""
    s = _split_slice(history, frame.rapidity, t)
    parts = dict(s.rod_parts)
    rows = [(f"particle {name}", em) for name, em in s.bodies if name != "rod"]
    if event is not None:
        # the event's own particle from the event's exact velocity: the world-line agrees with it to rounding (it is
        # read a hair inside the contact, ChartCurve.phi_at_time), and the event's value keeps a particle at rest
        # at exactly p = 0 in the CSV and JSON
        mass = history.scenario.particle(event.particle).mass
        rows = [(body, EnergyMomentum.of(mass, event.particle_rapidity_after - frame.rapidity)
                 if body == f"particle {event.particle}" else em) for body, em in rows]
    rows += [(MATTER, parts["matter"]), (STRESS, parts["stress"])]
    total = rows[0][1]
    for _, em in rows[1:]:
        total += em
    return rows + [("total", total)]


@functools.lru_cache(maxsize=512)
def _split_slice(history, frame_rapidity: float, t: float):
    """The slice with the rod's parts (an integral across the rod): once per history, frame and time, whatever the
    formats."""
    return history.energy_momentum(frame_rapidity, t, split=True)


def ledger_table(history, frame: Frame, at: Sequence[float] | None = None) -> Table:
    """The frame's ledger: at each contact and separation (then at each time of `at`), a row per summand and
    their total, E in M c², p in M c with four decimals."""
    zero = rounding_zero(history.initial_total(frame.rapidity))
    _, tn = coordinates(frame)
    rows = []
    times = [(event_name(label), t, i) for label, _, t, i in instants(history, frame)]
    times += [("", t, None) for t in at or ()]
    t_text = time_format([t for _, t, _ in times])
    for name, t, event in times:
        for k, (body, em) in enumerate(rows_at(history, frame, t, event)):
            rows.append((Cell(name if k == 0 else ""), Cell(t_text(t) if k == 0 else ""), Cell(body),
                         Cell(fixed(em.E, zero if body == STRESS else 0.0)), Cell(fixed(em.p, zero))))
    total = history.initial_total(frame.rapidity)
    return Table(f"ledger_causal_{frame_word(frame)}",
                 f"Energy and momentum of the causal rod at each contact and separation, frame {frame_symbol(frame)}",
                 ("event", tn, "body", "E", "p"), tuple(rows), "lnlnn",
                 (f"{NOTE} The total before the first contact: E = {fixed(total.E, zero)}, p = {fixed(total.p, zero)}. "
                  f"X′₁ is the separation that ends contact X₁.",))


def heading(history) -> str:
    s = history.scenario
    return f"{s.name}, the causal rod: v = {exact(s.v)}, L = {exact(s.L)} (c = 1; {UNITS})"


def to_markdown(history, frames: Sequence[Frame], at: Sequence[float] | None = None) -> str:
    return tables_markdown(heading(history), [ledger_table(history, f, at) for f in frames])


def to_latex(history, frames: Sequence[Frame], at: Sequence[float] | None = None) -> str:
    return tables_latex(heading(history), [ledger_table(history, f, at) for f in frames])


def to_text(history, frames: Sequence[Frame], at: Sequence[float] | None = None) -> str:
    lines = [heading(history).replace("²", "^2")]
    for f in frames:
        table = ledger_table(history, f, at)
        widths = [max(len(row[k].text) for row in (tuple(map(Cell, table.header)), *table.rows))
                  for k in range(len(table.header))]
        lines += ["", frame_heading(f) + f": {table.caption[0].lower()}{table.caption[1:]}"]
        for row in (tuple(map(Cell, table.header)), *table.rows):
            cells = [c.text.replace(MINUS, "-") for c in row]
            lines.append("  " + "  ".join(c.ljust(w) if a == "l" else c.rjust(w)
                                          for c, w, a in zip(cells, widths, table.align)).rstrip())
        lines += ["", *(line for note in table.notes for line in textwrap.wrap(note.replace("²", "^2"), 110,
                                                                              initial_indent="  ", subsequent_indent="  "))]
    return "\n".join(lines) + "\n"


def _em(em: EnergyMomentum) -> dict[str, float]:
    return {"E": float(em.E) + 0.0, "p": float(em.p) + 0.0}


def _split(history, frame: Frame, t: float, event=None) -> dict[str, Any]:
    named = {"particle A": "A", "particle B": "B", MATTER: "rod_matter", STRESS: "rod_stress", "total": "total"}
    return {named[body]: _em(em) for body, em in rows_at(history, frame, t, event)}


def _dense(history, frame: Frame) -> list[float]:
    lo, hi = time_window(history, frame)
    # the events are listed apart, every summand there: the dense slices keep off their instants
    return [lo + (hi - lo) * k / (DENSE_SLICES - 1) for k in range(DENSE_SLICES)]


def document(history, frames: Sequence[Frame], at: Sequence[float] | None = None) -> dict[str, Any]:
    """Per frame: the total, each contact and separation with every summand there, and the slices (`at` with
    every summand, else a dense sampling with the rod's total)."""
    s = history.scenario
    out = {}
    for f in frames:
        eta = f.rapidity
        events = [{"label": label, "kind": kind, "t": t + 0.0, "bodies": _split(history, f, t, i)}
                  for label, kind, t, i in instants(history, f)]
        if at is not None:
            slices = [{"t": t + 0.0, "bodies": _split(history, f, t)} for t in at]
        else:
            slices = [{"t": t + 0.0, "bodies": {name: _em(em) for name, em in history.energy_momentum(eta, t).bodies}}
                      for t in _dense(history, f)]
        out[f.name] = {"velocity": f.velocity + 0.0, "total": _em(history.initial_total(eta)), "events": events,
                       "slices": slices}
    return {"format": FORMAT, "rod": "causal",
            "scenario": {"name": s.name, "v": s.v, "L": s.L,
                         "masses": {"rod": 1.0, **{p.name: p.mass for p in s.particles}}},
            "units": {"E": "M c^2", "p": "M c", "t": "the unit L is given in"},
            "bodies": {"rod_matter": "the rod's matter part: rest-frame energy density moving with it",
                       "rod_stress": "the rod's stress part: its pressure's p (u u - eta) integrated across the "
                                     "slice (von Laue's momentum of a stressed body)"},
            "frames": out}


def to_json(history, frames: Sequence[Frame], at: Sequence[float] | None = None) -> str:
    return json.dumps(document(history, frames, at), indent=1, allow_nan=False) + "\n"


CSV_COLUMNS = ("frame", "kind", "label", "t", "body", "E", "p")


def to_csv(history, frames: Sequence[Frame], at: Sequence[float] | None = None) -> str:
    """Rows frame,kind,label,t,body,E,p: kind `contact` or `separation` (every summand at the event), `slice`."""
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(CSV_COLUMNS)
    writer.writerows(csv_rows(history, frames, at))
    return out.getvalue()


def csv_rows(history, frames: Sequence[Frame], at: Sequence[float] | None = None) -> list[list[str]]:
    """`to_csv`'s rows, without its header (CSV_COLUMNS)."""
    doc = document(history, frames, at)
    rows = []
    for name, frame in doc["frames"].items():
        for e in frame["events"]:
            for body, em in e["bodies"].items():
                rows.append([name, e["kind"], e["label"], repr(e["t"]), body, repr(em["E"]), repr(em["p"])])
        for s in frame["slices"]:
            for body, em in s["bodies"].items():
                rows.append([name, "slice", "", repr(s["t"]), body, repr(em["E"]), repr(em["p"])])
    return rows
