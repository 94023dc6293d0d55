"""A handout's comparison of the rigid rod with the causal rod (docs/model.md, "The causal rod"): `comparison`. Pure.

Per scenario, after the rigid rod's sections: where the rigid rod's far end moves before light from the impact
could reach it and the causal rod's does not; how fast each particle leaves each rod, in every frame shown; where
the energy went (the causal rod rings: its period, its (Δt, Δx) per period, its rest mass above M); the rigid
ledger's hidden momentum against the causal rod's stress momentum on one slice; and the causal rod's contacts and
separations. Every number comes from `causal_reading.compare`, read off the two runs.
"""

from __future__ import annotations

import math
from dataclasses import replace

from rodparadox.handout.causal_reading import Comparison
from rodparadox.handout.document import Block, Cell, DiagramBlock, Heading, Paragraph, Strips, Table
from rodparadox.handout.strips import STRIP_SEPARATION, STRIPS_FEWEST, STRIPS_MOST, following_rows
from rodparadox.handout.words import in_c, in_l, listed, numeral, signed_numeral, time_name
from rodparadox.numbers import impact_name
from rodparadox.numbers import exact
from rodparadox.tables.comparison import first_impact_times, first_impacts
from rodparadox.physics.frames import PANEL_LETTERS, Frame, frame_name, frame_symbol, frame_word, time_window
from rodparadox.physics.types import EnergyMomentum
from rodparadox.render.strip_windows import strips_follow_rod
from rodparadox.tables import build as tables
from rodparadox.tables import causal_ledger

HEADING = "The causal rod beside the rigid rod"

INTRODUCTION = (
    "The rigid rod above is the paper\u2019s idealisation. The causal rod is the stiffest rod relativity allows: "
    "sound in it travels at c, so the push of an impact spreads through it as a front of compression at the speed "
    "of light, and a particle rides with the end it strikes, pushed by the end\u2019s compression, until that "
    "compression has gone.")
#: what the comparison shows, after the introduction (a worksheet's key shows it; the worksheet asks first)
SHOWN = ("The diagram draws both rods in the same frames, the rigid rod in the upper row and the causal rod in the "
         "lower, each frame\u2019s two panels on one scale; what it shows follows it, then the causal rod at successive "
         "instants, its contacts and separations, and its ledger.")
#: after the particles' starts (`starts_text`), what a worksheet says of the comparison
WORKSHEET_SHOWN = "Its diagram and numbers are in the answer key; the questions below ask what you can work out first."


def comparison_caption(frames: tuple[Frame, ...], v: float, causal=None) -> str:
    """The two rows' caption: which panel is which rod in which frame, and how the causal rod is drawn."""
    n = len(frames)
    letters = PANEL_LETTERS
    upper = ", ".join(f"({letters[k]})" for k in range(n))
    lower = ", ".join(f"({letters[n + k]})" for k in range(n))
    named = listed([frame_name(f) for f in frames])
    return (f"At v = {exact(v)}, in {named}: {upper} the rigid rod; {lower} the causal rod, on the same particles. "
            f"Each frame\u2019s two panels have one scale. The causal rod\u2019s world-sheet is shaded by its "
            f"compression; light-speed fronts cross it; a filled dot is a contact, where a particle starts to ride an "
            f"end, a hollow one its separation{_example(causal)}.")


def _example(causal) -> str:
    """ (B′₁ ends B₁): the first separation of the run and the contact it ends."""
    first = next((i for i in getattr(causal, "impacts", ()) if i.kind == "separation"), None)
    return "" if first is None else f" ({impact_name(first.label)} ends {impact_name(first.label[:-1])})"


def causal_strip_times(causal, frame: Frame) -> tuple[float, ...]:
    """Six to eight instants of the frame's time for the causal rod's strips, earliest first, in its time window:
    before the first contact, at each contact and separation, between them, and after the last."""
    t_lo, t_hi = time_window(causal, frame)
    events = sorted(i.event.time_in(frame.rapidity) for i in causal.impacts)
    events = [t for t in events if t_lo < t < t_hi]
    candidates = [(0, 0.5 * (t_lo + events[0])), (0, 0.5 * (events[-1] + t_hi))] if events else []
    candidates += [(1, t) for t in events] + [(2, 0.5 * (a + b)) for a, b in zip(events, events[1:])]
    close = STRIP_SEPARATION * (t_hi - t_lo)
    chosen: list[float] = []
    for _, t in sorted(candidates):
        if all(abs(t - c) > close for c in chosen) and len(chosen) < STRIPS_MOST:
            chosen.append(t)
    times = sorted(chosen)
    while len(times) < STRIPS_FEWEST:  # halve the widest gap, the window's ends as bounds
        bounds = [t_lo] + times + [t_hi]
        k = max(range(len(bounds) - 1), key=lambda j: bounds[j + 1] - bounds[j])
        times = sorted(times + [0.5 * (bounds[k] + bounds[k + 1])])
    return tuple(times)


def causal_strips_caption(frame: Frame, times: tuple[float, ...], L: float, follows: bool = False) -> str:
    """`follows`: each row follows the rod (`render.strip_windows`), which the caption says."""
    symbol = frame_name(frame)
    instants = listed([numeral(t / L) for t in times])
    return (f"The causal rod and the particles in {symbol} at {time_name(frame)} = {instants} (in units of L), "
            f"earliest first. The bar runs from the rod\u2019s left end to its right end, shaded by the velocity in "
            f"{symbol} of each of its material points: it changes only where a front has passed, so the far end "
            f"stays as it was until the front from an impact reaches it; the dots are the particles."
            + (" " + following_rows(frame) if follows else ""))


def ledger_table(causal, frame: Frame) -> Table:
    """The causal rod's ledger in the frame (`tables.causal_ledger`), its stress row and note in the comparison's
    words: the stress part is what the rod's material points' motion leaves out, not the rigid rod's hidden part."""
    table = causal_ledger.ledger_table(causal, frame)
    rows = tuple(tuple(Cell("rod, stress") if c.text == causal_ledger.STRESS else c for c in row)
                 for row in table.rows)
    total = causal.initial_total(frame.rapidity)
    note = (f"E in M c², p in M c, M the rod\u2019s mass. The rod\u2019s (E, p) is split into its matter part (its "
            f"rest-frame energy density moving with it, elastic energy included) and its stress part (what its "
            f"pressure carries, p(uu − η) in its stress-energy, across the slice). Particles, matter and stress add "
            f"up to the total before the first contact, E = {tables.fixed(total.E)}, p = {tables.fixed(total.p)}: "
            f"nothing is hidden. X′₁ is the separation that ends contact X₁.")
    return replace(table, rows=rows, notes=(note,))


def starts_text(rigid, causal, frames: tuple[Frame, ...], impacts: bool = True) -> str:
    """Where each particle started (at t = 0 in S) for each rod, and (`impacts`; a worksheet asks it) where each
    rod's first impacts fall: at one instant, or how far apart, in each frame shown."""
    L = rigid.scenario.L
    rigid_starts, causal_starts = dict(rigid.starts), dict(causal.starts)
    names = sorted(rigid_starts)
    same = all(abs(rigid_starts[n].x - causal_starts[n].x) <= 1e-12 * L * (1.0 + abs(rigid_starts[n].x / L))
               for n in names)
    where = listed([f"{n} at x = {in_l(rigid_starts[n].x / L)}" for n in names])
    if same:
        text = (f"Here the same particles, on the same world-lines, strike a causal rod of the same rest mass M and "
                f"length L: at t = 0, {where}, at the same velocities.")
    else:
        other = listed([f"{n} at x = {in_l(causal_starts[n].x / L)}" for n in names])
        text = (f"Here particles of the same masses and speeds strike a causal rod of the same rest mass M and length "
                f"L, but not on the same world-lines: at t = 0, {where} for the rigid rod, {other} for the causal rod.")
    if len(names) < 2 or not impacts:
        return text
    parts = []
    for word, history in (("rigid", rigid), ("causal", causal)):
        firsts = first_impacts(history)
        said = [f"simultaneous in {frame_name(f)}" if simultaneous else
                f"{in_l(abs(times[1] - times[0]))} apart in {frame_name(f)}"
                for f, times, simultaneous in first_impact_times(history, frames)]
        parts.append(f"on the {word} rod {listed([impact_name(i.label) for i in firsts])} are {listed(said)}")
    return text + " Each particle\u2019s first impact: " + "; ".join(parts) + "."


def far_end_text(c: Comparison) -> str:
    """When each rod's far end first moves, and when light from the first contact reaches it (in S)."""
    f = c.far_end
    C = impact_name(f.contact.label)
    text = f"{C} strikes the rod\u2019s {f.contact.end} end at t = {in_l(f.t_contact)} in S. "
    if f.by_light:
        if f.t_rigid is not None:
            text += (f"The rigid rod\u2019s {f.far} end starts to move at that same instant of S, t = "
                     f"{in_l(f.t_rigid)}, before light from {C} could reach it. ")
        text += (f"The causal rod\u2019s {f.far} end stays at rest until t = {in_l(f.t_causal)}, when light from {C} "
                 f"arrives (the rod is at rest in S, so light crosses its length L in a time L), and then moves off at "
                 f"once at {in_c(f.u_causal)}: its rapidity in S, {signed_numeral(math.atanh(f.u_causal))}, is twice "
                 f"the struck end\u2019s, {signed_numeral(f.rapidity_struck)}, for the front of compression comes back "
                 f"from the free end as tension.")
        return text
    D = impact_name(f.own.label)
    when = "at that same instant" if f.t_causal == f.t_contact else f"at t = {in_l(f.t_causal)}"
    text += (f"{D} strikes its {f.far} end {when}, before light from {C} could reach it (at t = {in_l(f.t_light)}): "
             f"the causal rod\u2019s {f.far} end is set moving by {D} itself, and the fronts from the two contacts "
             f"cross inside the rod.")
    if f.t_rigid is not None:
        text += (f" The rigid rod\u2019s {f.far} end starts to move already at t = {in_l(f.t_rigid)}, at "
                 f"{C}\u2019s instant of S.")
    elif f.t_rigid_moves is None:
        text += f" The rigid rod never moves in S: {C} and {D} together leave it at rest."  # both ends at rest
    return text


def leaving_text(c: Comparison, frames: tuple[Frame, ...]) -> str:
    """Each particle's velocity as it leaves each rod, in every frame shown, and the particles' kinetic energy."""
    parts = []
    for p in c.leaving:
        def where(velocities: dict) -> str:
            said = [f"{in_c(velocities[f.name])} in {frame_name(f)}" for f in frames]
            return said[0] + (f" ({listed(said[1:])})" if len(said) > 1 else "")
        contacts = "one contact" if p.contacts == 1 else f"{p.contacts} contacts"
        parts.append(f"{p.particle} leaves the rigid rod at {where(p.rigid)}, and the causal rod, after {contacts}, "
                     f"at {where(p.causal)}")
    r = c.ringing
    return (f"{'; '.join(parts)}. In S the particles carry {numeral(r.kinetic_before)} M c² of kinetic energy "
            f"before the first impact, and after the last {_energy(r.kinetic_rigid)} from the rigid rod but "
            f"{_energy(r.kinetic_causal)} from the causal rod.")


def _energy(E: float) -> str:
    text = numeral(E if abs(E) > 1e-12 else 0.0)
    return "none" if text == "0" else f"{text} M c²"


def ringing_text(c: Comparison) -> str:
    """The causal rod after the last separation: it rings for ever, and its rest mass is more than M."""
    r = c.ringing
    return (f"After the last separation (t = {in_l(r.t_last)} in S) the causal rod rings for ever, its motion "
            f"repeating every 2L of its chart time (the time its material clocks keep when unstressed). Over each "
            f"period every material point advances by the same (Δt, Δx) = ({in_l(r.dt)}, {in_l(_zero(r.dx, r.dt))}) "
            f"in S, so the rod carries (E, p) = (M/2L)(Δt, Δx) = ({numeral(r.E)} M c², "
            f"{numeral(_zero(r.p, r.E))} M c). Its rest mass √(E² − p²) = {numeral(r.rest_mass)} M is more than M: the "
            f"energy of its vibration, which a rigid rod cannot hold, counts in it. Its centre moves at Δx/Δt = "
            f"{in_c(_zero(r.velocity, 1.0))} in S (the rigid rod at {in_c(_zero(r.rigid_velocity, 1.0))}), and in its "
            f"own rest frame one period lasts √(Δt² − Δx²) = {in_l(2.0 * r.rest_mass)}, 2L times its rest mass in M.")


def energy_text(c: Comparison) -> str:
    """Where the energy went, frame by frame: what the particles lose = the rise of the causal rod's rest mass
    (internal energy) + the change of its bulk kinetic energy; all bulk kinetic energy for the rigid rod."""
    parts = []
    for e in c.energy:
        lost = _zero(e.lost_causal, 1.0)
        bulk = (f"(from {numeral(_zero(e.bulk_before, 1.0))} to {numeral(_zero(e.bulk_after, 1.0))} M c²)")
        if lost >= 0:
            parts.append(f"in {frame_name(e.frame)} the particles lose {numeral(lost)} M c² = {numeral(e.internal)} M "
                         f"c² of internal energy + {_signed_energy(e.bulk_change)} of bulk kinetic energy {bulk}")
        else:  # they leave with more than they came with (single in S′): the rod gives up bulk kinetic energy
            parts.append(f"in {frame_name(e.frame)} the particles gain {numeral(-lost)} M c² = the "
                         f"{numeral(-e.bulk_change)} M c² of bulk kinetic energy the rod gives up {bulk} \u2212 the "
                         f"{numeral(e.internal)} M c² of internal energy it gains")
    rigid = listed([f"{numeral(x)} M c² lost in {frame_name(e.frame)}" if x >= 0 else
                    f"{numeral(-x)} M c² gained in {frame_name(e.frame)}"
                    for e in c.energy for x in [_zero(e.lost_rigid, 1.0)]])
    text = "; ".join(parts)
    return (f"Where the energy went. From before the first impact to after the last separation, {text}. The rise of "
            f"the rest mass is the same in every frame; the bulk kinetic energy, and so what the particles lose, is "
            f"not. The rigid rod\u2019s rest mass stays M, so what the particles exchange with it, {rigid}, is all "
            f"bulk kinetic energy.")


def _signed_energy(E: float) -> str:
    """A change of energy in a sum: 0.0172 M c², or (−0.0523) M c²."""
    text = numeral(_zero(E, 1.0))
    return f"({text}) M c²" if text.startswith("\u2212") else f"{text} M c²"


def _zero(x: float, scale: float) -> float:
    """Rounding (below 1e-12 of the scale) as 0."""
    return 0.0 if abs(x) <= 1e-12 * max(1.0, abs(scale)) else x


def _pair(em: EnergyMomentum, scale: float) -> str:
    return f"({numeral(_zero(em.E, scale))} M c², {numeral(_zero(em.p, scale))} M c)"


def stress_text(c: Comparison) -> str:
    """Hidden momentum compared like with like on one slice: the rigid ledger's hidden part (the total less every
    body's motion) against the causal rod's total less its material points' rest-mass motion."""
    s = c.stress
    scale = s.total.E
    where = f"the slice {time_name(s.frame)} = {in_l(s.t)} of {frame_name(s.frame)}"
    unshown = EnergyMomentum(0.0, s.unshown[0], s.unshown[1])
    motion = EnergyMomentum(0.0, s.motion[0], s.motion[1])
    hidden = _zero(s.hidden.E, scale) != 0.0 or _zero(s.hidden.p, scale) != 0.0
    rigid = (f"the rigid ledger\u2019s hidden part is {_pair(s.hidden, scale)}: the total less what the particles\u2019 "
             f"and the rod\u2019s material points\u2019 motion carries, each point its share of M at its own "
             f"velocity. It is the rigid rod\u2019s stress, which takes an impulse across the rod at once"
             if hidden else "the rigid ledger has no hidden part")
    return (f"The hidden momentum, like with like. On {where} {rigid}. Made the same way for the causal rod, its "
            f"material points\u2019 rest mass moving at their velocities carries (M/L)∫(cosh ψ, sinh ψ)dσ = "
            f"{_pair(motion, scale)}, ψ the rapidity of the point σ on the slice; the rod as a whole carries "
            f"{_pair(EnergyMomentum(0.0, *s.rod), scale)}, so {_pair(unshown, scale)} is not shown by its material "
            f"points\u2019 motion: the energy of its compression and the momentum its stress carries, where the fronts "
            f"have reached, real and local. The two need not be alike: the rigid rod\u2019s is there at once along the "
            f"whole rod, the causal rod\u2019s only where the fronts have come.")


def events_table(causal, frame: Frame, blank: bool = False) -> Table:
    """The causal rod's contacts and separations in the frame (`tables.build.events_table`, named apart from the
    rigid rod's)."""
    table = tables.events_table(causal, frame, blank)
    # its rows are contacts and separations, and a particle leaving an end is no impact: the first column is the
    # event, as the causal rod's ledger names it
    header = tuple("event" if column == "impact" else column for column in table.header)
    return replace(table, name=f"causal_events_{frame_word(frame)}", header=header,
                   caption=f"The causal rod\u2019s contacts and separations in frame {frame_symbol(frame)}")


def table_text(frame: Frame, first: bool = True) -> str:
    """How to read the causal rod's table of contacts and separations in the frame: in full for the `first` frame,
    in short for the next (the same paragraph twice on a page, for S and S′, said nothing new)."""
    if not first:
        return f"The causal rod\u2019s contacts and separations in {frame_name(frame)}, in the same columns."
    return (f"The causal rod\u2019s contacts (A₁, B₁ \u2026) and separations (A′₁, B′₁ \u2026, where the particle "
            f"leaves the end) in {frame_name(frame)}: where and when, the particle\u2019s velocity (it changes during a "
            f"contact, not at its ends) and the struck end\u2019s, just before and just after.")


def comparison(c: Comparison, rigid, causal, frames: tuple[Frame, ...], stem: str,
               worksheet: bool = False, equal_scales: bool = False) -> tuple[list[Block], list[Block]]:
    """The comparison's blocks in the scenario's section, and those a worksheet's answer key prints: the two rods'
    diagram (same frames, one scale per frame), the causal rod's strips, the told paragraphs, its contacts and
    separations and its ledger. A worksheet keeps only the introduction before its key: the causal rod's numbers
    come from solving its wave equation, which a student cannot do, and its first contacts are the rigid rod's
    first impacts, whose cells the worksheet asks."""
    v = causal.scenario.v
    diagram = DiagramBlock(f"{stem}_compared", rigid, frames, comparison_caption(frames, v, causal),
                           equal_scales=equal_scales,
                           compared=causal)
    drawn: list[Block] = []
    for f in frames:
        times = causal_strip_times(causal, f)
        drawn += [Heading(f"The causal rod at successive instants of {frame_name(f)}", 2),
                  Strips(f"{stem}_causal_strips_{frame_word(f)}", causal, f, times,
                         causal_strips_caption(f, times, causal.scenario.L, strips_follow_rod(causal, f, times)),
                         "The causal rod")]
    told: list[Block] = [Heading("What the comparison shows", 2), Paragraph(far_end_text(c)),
                         Paragraph(leaving_text(c, frames)), Paragraph(ringing_text(c)), Paragraph(energy_text(c)),
                         Paragraph(stress_text(c))]
    filled: list[Block] = [Heading("The causal rod\u2019s numbers", 2)]
    filled += [b for f in frames for b in (Paragraph(table_text(f, f == frames[0])), events_table(causal, f))]
    filled += [b for f in frames for b in (Paragraph(ledger_text(f, f == frames[0])), ledger_table(causal, f))]
    # the diagram, then what it shows (text that may fill a page the diagram misses), the strips, the numbers
    # where each rod's first impacts fall is said once, by the note under the diagram (`tables.comparison`), which
    # a teacher found said twice, here and there, a few lines apart
    shown = [Heading(HEADING, 2),
             Paragraph(INTRODUCTION + " " + starts_text(rigid, causal, frames, impacts=False) + " " + SHOWN),
             diagram, *told, *drawn, *filled]
    if not worksheet:
        return shown, []
    asked = INTRODUCTION + " " + starts_text(rigid, causal, frames, impacts=False) + " " + WORKSHEET_SHOWN
    return [Heading(HEADING, 2), Paragraph(asked)], shown


def ledger_text(frame: Frame, first: bool = True) -> str:
    """How to read the causal rod's ledger in the frame: in full for the `first` frame, in short for the next."""
    symbol, time = frame_name(frame), time_name(frame)
    if not first:
        return f"The causal rod\u2019s ledger in {symbol}, read the same way, on the slice {time} = constant."
    return (f"The causal rod\u2019s ledger in {symbol}: at each contact and separation, on the slice {time} = "
            f"constant through it, the energy E and momentum p of each particle and of the rod\u2019s matter and "
            f"stress; the note under the table says what each part is and how they add up.")
