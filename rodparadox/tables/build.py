"""The events and the ledger as `document.Table`s: the numbers a handout prints, built once. Pure.

The events table has the columns `sears-paradox events` prints, with its digits
(`numbers.coordinate_format`, `numbers.velocity_format`); the ledger table has,
per impact, the particle's, the rod's and the hidden (E, p) just before and
after (as `sears-paradox ledger` prints them); the hidden table has the hidden
part on the slices between impacts where it is not zero. A worksheet's copy
leaves every number blank (`blank=True`), the ledger's impact times too (they
are the events table's); labels stay, and so do the hidden table's slice times,
which say where the numbers asked for are taken.
"""

from __future__ import annotations

from typing import Sequence

from rodparadox.tables.table import Cell, Table
from rodparadox.physics.history import RodHistory
from rodparadox.physics.frames import check_below_c, Frame, frame_symbol, frame_word, time_order, view
from rodparadox.physics.ledger import instant_entries, rounding_zero
from rodparadox.numbers import MINUS, coordinate_format, exact, fraction_text, impact_name, number_text, velocity_format
from rodparadox.tables.formats import latex_text, tables_latex, tables_markdown, to_latex, to_markdown  # noqa: F401 (re-exported)
from rodparadox.tolerances import ONE_INSTANT


def coordinates(frame: Frame) -> tuple[str, str]:
    """The frame's (x, t) in plain text: x, t in S; x′, t′ in S′; x_u, t_u otherwise."""
    return {"rest": ("x", "t"), "moving": ("x\N{PRIME}", "t\N{PRIME}")}.get(frame.name, ("xᵤ", "tᵤ"))


def with_fraction(text: str, value: float) -> str:
    """A number's text, followed by its exact fraction where the decimal never ends: `+1.416667 (17/12)`."""
    exact = fraction_text(value)
    return f"{text} ({exact})" if exact and float(text.replace(MINUS, "-")) != 0.0 else text


def events_table(history: RodHistory, frame: Frame, blank: bool = False) -> Table:
    """The impacts in one frame, in the frame's time order: label, end, x, t, and the particle's and the rod's
    velocities just before and after (c = 1; x and t in the unit L is given in)."""
    fv = view(history, frame)
    check_below_c(fv)
    scale = history.scenario.L + max((abs(e.t) for e in fv.events), default=0.0)
    events = [fv.events[k] for k in time_order([e.t for e in fv.events], scale)]  # the rod's order at one instant
    x_text, t_text = coordinate_format([e.x for e in events]), coordinate_format([e.t for e in events])  # a column's decimals
    def velocities(e):
        return e.particle_velocity_before, e.particle_velocity_after, e.rod_velocity_before, e.rod_velocity_after
    velocity = velocity_format([u for e in events for u in velocities(e)])  # one number of decimals for all four
    x, t = coordinates(frame)
    rows = []
    for e in events:
        numbers = [with_fraction(x_text(e.x), e.x), with_fraction(t_text(e.t), e.t)]
        numbers += [with_fraction(velocity(u), u) for u in velocities(e)]
        rows.append((Cell(impact_name(e.impact.label)), Cell(e.impact.end),
                     *(Cell(n.replace("-", MINUS), blank) for n in numbers)))
    notes = []
    for e in events:
        i = e.impact
        if i.simultaneous_with and i.label < i.simultaneous_with:
            notes.append(f"{impact_name(i.label)} and {impact_name(i.simultaneous_with)} lie on one line of the "
                         f"rod's own simultaneity.")
        if i.while_turning:
            notes.append(f"{impact_name(i.label)} strikes while the rod is still turning.")
    return Table(f"events_{frame_word(frame)}", f"The impacts in frame {frame_symbol(frame)}",
                 ("impact", "end", x, t, "particle before", "particle after", "rod before", "rod after"),
                 tuple(rows), "llnnnnnn", tuple(notes))


def _zero_below(history: RodHistory, frame: Frame) -> float:
    """Differences of totals below this are rounding (`ledger.rounding_zero`)."""
    return rounding_zero(history.initial_total(frame.rapidity))


#: decimals of every number in the ledger table: one format per column, so the rows add up to the eye
LEDGER_DECIMALS = 4


def fixed(value: float, zero: float = 0.0) -> str:
    """A number with LEDGER_DECIMALS decimals, − for minus, never −0 (|value| <= zero is 0)."""
    if abs(value) <= zero:
        value = 0.0
    text = f"{value:.{LEDGER_DECIMALS}f}"
    if float(text) == 0.0:
        text = text.lstrip("-")
    return text.replace("-", MINUS)


def _body_name(name: str) -> str:
    return {"rod": "rod, kinetic", "hidden": "hidden"}.get(name, f"particle {name}")


def ledger_table(history: RodHistory, frame: Frame, blank: bool = False) -> Table:
    """Per instant of the frame at which impacts happen (impacts at one instant are one row group: just before all
    of them, just after all of them), in its time order: each particle's (E, p), the rod's kinetic part, the hidden
    part, and their total (the same as before the first impact); then, apart and not a summand, the rod's
    dynamical (E, p). E in M c², p in M c; every number with LEDGER_DECIMALS decimals."""
    zero = _zero_below(history, frame)
    rows = []
    for entry in instant_entries(history, frame.rapidity):
        name = impact_names_text(entry.impacts)
        t = fixed(entry.t)
        for k, ((body, b), (_, a)) in enumerate(zip(entry.before, entry.after)):
            values = (b.E, b.p, a.E, a.p)
            # the impact's time is left blank too: it is the events table's t, which a worksheet asks for
            rows.append((Cell(name if k == 0 else ""), Cell(t if k == 0 else "", blank and k == 0),
                         Cell(_body_name(body)),  # a body's E is at least its rest energy, never a rounding zero
                         *(Cell(fixed(q, zero if (j % 2 or body == "hidden") else 0.0), blank)
                           for j, q in enumerate(values))))
        total = entry.total
        rows.append((Cell(""), Cell(""), Cell("total"), *(Cell(fixed(q, zero), blank)
                                                          for q in (total.E, total.p, total.E, total.p))))
        b, a = entry.rod_dynamical_before, entry.rod_dynamical_after
        rows.append((Cell(""), Cell(""), Cell(ROD_DYNAMICAL), *(Cell(fixed(q, zero if j % 2 else 0.0), blank)
                                                                  for j, q in enumerate((b.E, b.p, a.E, a.p)))))
    _, tn = coordinates(frame)
    total = history.initial_total(frame.rapidity)
    return Table(f"ledger_{frame_word(frame)}", f"Energy and momentum at each impact, frame {frame_symbol(frame)}",
                 ("impact", tn, "body", "E before", "p before", "E after", "p after"), tuple(rows), "lnlnnnn",
                 (f"E in M c², p in M c, M the rod's mass. Particles, the rod's kinetic part and the hidden part add "
                  f"up to the total, the total before the first impact (E = {fixed(total.E, zero)}, p = "
                  f"{fixed(total.p, zero)}); hidden: that total less every body's kinetic (E, p) on the frame's "
                  f"slice. Impacts at one instant of the frame are one row group. {ROD_DYNAMICAL.capitalize()}: E and p of the "
                  f"rod's momentum, which takes each impulse at once; shown apart, it is not a summand.",))


#: the label of the rod's dynamical (E, p) in every ledger table: shown apart from the summands
ROD_DYNAMICAL = "rod, dynamical (not a summand)"


def impact_names_text(impacts) -> str:
    """B₁, or B₁ and A₁ (in the rod's order) for impacts at one instant."""
    names = [impact_name(i.label) for i in impacts]
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


def hidden_instants(history: RodHistory, frame: Frame) -> tuple[float, ...]:
    """The middle of each stretch of the frame's time between consecutive changes (impacts, a turn's start or end)."""
    eta = frame.rapidity
    changes = sorted({i.event.time_in(eta) for i in history.impacts} | set(history.turning.turn_times(eta)))
    scale = history.scenario.L + max((abs(t) for t in changes), default=0.0)
    return tuple(0.5 * (a + b) for a, b in zip(changes, changes[1:]) if b - a > ONE_INSTANT * scale)


def hidden_table(history: RodHistory, frame: Frame, blank: bool = False) -> Table | None:
    """The hidden (E, p) on the slices between impacts where it is not zero, or None where it is zero on all."""
    zero = _zero_below(history, frame)
    rows = []
    for t in hidden_instants(history, frame):
        hidden = history.energy_momentum(frame.rapidity, t).hidden
        if number_text(hidden.E, zero) == "0" and number_text(hidden.p, zero) == "0":
            continue
        rows.append((Cell(fixed(t)), *(Cell(fixed(q, zero), blank) for q in (hidden.E, hidden.p))))
    if not rows:
        return None
    _, tn = coordinates(frame)
    return Table(f"hidden_{frame_word(frame)}", f"The hidden part between impacts, frame {frame_symbol(frame)}",
                 (tn, "hidden E", "hidden p"), tuple(rows), "nnn",
                 ("Each slice lies halfway between two consecutive impacts or ends of a turn.",))


def slices_table(history: RodHistory, frame: Frame, times: Sequence[float], blank: bool = False) -> Table:
    """Each body's kinetic (E, p), the kinetic total and the hidden part on the slices t = `times` of the frame (the
    slices `sears-paradox ledger` is asked for), a row per body, the time on the first row of each slice."""
    zero = _zero_below(history, frame)
    slices = []
    for t in times:
        s = history.energy_momentum(frame.rapidity, t)
        named = [(f"particle {name}" if name != "rod" else "rod, kinetic", em) for name, em in s.bodies]
        named += [("kinetic total", s.kinetic), ("hidden", s.hidden)]
        # a value below `zero` in size is rounding of a difference (the hidden part, a momentum): 0
        slices.append((t, [(body, em.E if body != "hidden" or abs(em.E) >= zero else 0.0,
                            em.p if abs(em.p) >= zero else 0.0) for body, em in named]))
    # each column with one number of decimals (`numbers.coordinate_format`): the times, E, p
    time_text = coordinate_format(list(times), signed=False)
    e_text = coordinate_format([E for _, named in slices for _, E, _ in named], signed=False)
    p_text = coordinate_format([p for _, named in slices for _, _, p in named], signed=False)
    rows = []
    for t, named in slices:
        for k, (body, E, p) in enumerate(named):
            time = with_fraction(time_text(t), t).replace("-", MINUS) if k == 0 else ""
            rows.append((Cell(time), Cell(body), *(Cell(with_fraction(text, value).replace("-", MINUS), blank)
                                                   for text, value in ((e_text(E), E), (p_text(p), p)))))
    _, tn = coordinates(frame)
    return Table(f"slices_{frame_word(frame)}",
                 f"Each body's kinetic energy and momentum at chosen instants, frame {frame_symbol(frame)}",
                 (tn, "body", "E", "p"), tuple(rows), "nlnn",
                 (f"E in M c², p in M c, M the rod's mass, on the slice {tn} = const of the frame; hidden: the total "
                  f"before the first impact less the kinetic total.",))


# --- the tables of a command, as one Markdown or LaTeX text -----------------------------------------------

def events_tables(history: RodHistory, frames: Sequence[Frame]) -> tuple[Table, ...]:
    """`sears-paradox events` as tables: the impacts in each frame."""
    return tuple(events_table(history, f) for f in frames)


def ledger_tables(history: RodHistory, frames: Sequence[Frame], at: Sequence[float] | None = None) -> tuple[Table, ...]:
    """`sears-paradox ledger` as tables: for each frame the ledger per impact, the hidden part between impacts
    where it is not zero, and the slices at `at` if any."""
    out: list[Table] = []
    for f in frames:
        out.append(ledger_table(history, f))
        hidden = hidden_table(history, f)
        if hidden is not None:
            out.append(hidden)
        if at:
            out.append(slices_table(history, f, at))
    return tuple(out)


def heading(history: RodHistory, units: str) -> str:
    """The line above a command's tables: the scenario, its v and L, and the units (`units`, after c = 1)."""
    s = history.scenario
    return f"{s.name}: v = {exact(s.v)}, L = {exact(s.L)} (c = 1; {units})"


#: the units of `events` and of `ledger`, as their text output states them
EVENTS_UNITS = "x and t in the unit L is given in"
LEDGER_UNITS = "E in M c², p in M c, M the rod's mass; t in the unit L is given in"


def events_markdown(history: RodHistory, frames: Sequence[Frame]) -> str:
    return tables_markdown(heading(history, EVENTS_UNITS), events_tables(history, frames))


def events_latex(history: RodHistory, frames: Sequence[Frame]) -> str:
    return tables_latex(heading(history, EVENTS_UNITS), events_tables(history, frames))


def ledger_markdown(history: RodHistory, frames: Sequence[Frame], at: Sequence[float] | None = None) -> str:
    return tables_markdown(heading(history, LEDGER_UNITS), ledger_tables(history, frames, at))


def ledger_latex(history: RodHistory, frames: Sequence[Frame], at: Sequence[float] | None = None) -> str:
    return tables_latex(heading(history, LEDGER_UNITS), ledger_tables(history, frames, at))
