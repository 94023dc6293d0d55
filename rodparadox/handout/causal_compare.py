"""A handout's comparison of the rigid rod with the causal rod (README, "The causal rod"): `comparison`. Pure.

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
from rodparadox.handout.document import Block, Heading, Paragraph, Table
from rodparadox.handout.words import in_c, in_l, listed, numeral, time_name
from rodparadox.numbers import impact_name
from rodparadox.physics.frames import Frame, frame_name, frame_symbol, frame_word
from rodparadox.physics.types import EnergyMomentum
from rodparadox.tables import build as tables

HEADING = "The causal rod beside the rigid rod"

INTRODUCTION = (
    "The rigid rod above is the paper\u2019s idealisation. The causal rod is the stiffest rod relativity allows: "
    "sound in it travels at c, so the push of an impact spreads through it as a front of compression at the speed "
    "of light, and a particle rides with the end it strikes, pushed by the end\u2019s compression, until that "
    "compression has gone (README, \u201cThe causal rod\u201d). Here the same particles, at the same speeds, strike "
    "a causal rod of the same rest mass M and length L; every number below is computed from its run. The diagrams, "
    "the rod at successive instants and the tables above are of the rigid rod: this handout does not draw the "
    "causal rod yet.")
#: what the introductions say of the causal rod's drawing, and what they say instead where the rod's own view after
#: the diagram draws it (`own_view.with_rod_views`)
NOT_DRAWN = "does not draw the causal rod yet."
DRAWN_IN_OWN_VIEW = "draws the causal rod only in the rod\u2019s own view, after the diagram."
#: a worksheet shows the diagram and blank tables of the rigid rod (the strips wait for the key)
WORKSHEET_INTRODUCTION = INTRODUCTION.replace("The diagrams, the rod at successive instants and the tables above",
                                              "The diagram and the tables above").replace("this handout", "this sheet")


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
                 f"once at {in_c(f.u_causal)}: its rapidity, {numeral(abs(math.atanh(f.u_causal)))}, is twice the "
                 f"struck end\u2019s, {numeral(abs(f.rapidity_struck))}, for the front of compression comes back from "
                 f"the free end as tension.")
        return text
    D = impact_name(f.own.label)
    when = "at that same instant" if f.t_causal == f.t_contact else f"at t = {in_l(f.t_causal)}"
    text += (f"{D} strikes its {f.far} end {when}, before light from {C} could reach it (at t = {in_l(f.t_light)}): "
             f"the causal rod\u2019s {f.far} end is set moving by {D} itself, and the fronts from the two contacts "
             f"cross inside the rod.")
    if f.t_rigid is not None:
        text += (f" The rigid rod\u2019s {f.far} end starts to move already at t = {in_l(f.t_rigid)}, at "
                 f"{C}\u2019s instant of S.")
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
    """Where the energy went: the causal rod rings for ever after the last separation."""
    r = c.ringing
    internal = r.rest_mass - 1.0
    return (f"Where the energy went: after the last separation (t = {in_l(r.t_last)} in S) the causal rod rings for "
            f"ever, its motion repeating every 2L of its chart time (the time its material clocks keep when "
            f"unstressed). Over each period every material point advances by the same (Δt, Δx) = "
            f"({in_l(r.dt)}, {in_l(_zero(r.dx, r.dt))}) in S, so the rod carries (E, p) = (M/2L)(Δt, Δx) = "
            f"({numeral(r.E)} M c², {numeral(_zero(r.p, r.E))} M c). Its rest mass √(E² − p²) = {numeral(r.rest_mass)} M "
            f"is more than M: {numeral(internal)} M c² is internal energy, the energy of its vibration, which a rigid "
            f"rod cannot hold. Its centre moves at Δx/Δt = {in_c(_zero(r.velocity, 1.0))} in S (the rigid rod at "
            f"{in_c(_zero(r.rigid_velocity, 1.0))}), and in its own rest frame one period lasts √(Δt² − Δx²) = "
            f"{in_l(2.0 * r.rest_mass)}, 2L times its rest mass in M.")


def _zero(x: float, scale: float) -> float:
    """Rounding (below 1e-12 of the scale) as 0."""
    return 0.0 if abs(x) <= 1e-12 * max(1.0, abs(scale)) else x


def _pair(em: EnergyMomentum, scale: float) -> str:
    return f"({numeral(_zero(em.E, scale))} M c², {numeral(_zero(em.p, scale))} M c)"


def stress_text(c: Comparison) -> str:
    """The rigid ledger's hidden part against the causal rod's stress part on one slice."""
    s = c.stress
    scale = s.total.E
    where = f"the slice {time_name(s.frame)} = {in_l(s.t)} of {frame_name(s.frame)}"
    hidden = _zero(s.hidden.E, scale) != 0.0 or _zero(s.hidden.p, scale) != 0.0
    rigid = (f"On {where} the rigid ledger\u2019s hidden part is {_pair(s.hidden, scale)}: what the rigid rod\u2019s "
             f"stress carries, known only as what the bodies\u2019 motion is missing." if hidden else
             f"On {where} the rigid ledger has no hidden part.")
    return (f"The hidden momentum made local. {rigid} The causal rod has no hidden part: its ledger adds up on every "
            f"slice. On the same slice its (E, p) is its matter part, {_pair(s.matter, scale)}, plus its stress part, "
            f"{_pair(s.stress, scale)}, which the pressure carries where the rod is compressed (p(uu − η) in its "
            f"stress-energy): the stress part is the real, local version of the rigid model\u2019s hidden momentum.")


def events_table(causal, frame: Frame, blank: bool = False) -> Table:
    """The causal rod's contacts and separations in the frame (`tables.build.events_table`, named apart from the
    rigid rod's)."""
    table = tables.events_table(causal, frame, blank)
    return replace(table, name=f"causal_events_{frame_word(frame)}",
                   caption=f"The causal rod\u2019s contacts and separations in frame {frame_symbol(frame)}")


def table_text(frame: Frame) -> str:
    return (f"The causal rod\u2019s contacts (A₁, B₁ \u2026) and separations (A′₁, B′₁ \u2026, where the particle "
            f"leaves the end) in {frame_name(frame)}: where and when, the particle\u2019s velocity (it changes during a "
            f"contact, not at its ends) and the struck end\u2019s, just before and just after.")


def comparison(c: Comparison, causal, frames: tuple[Frame, ...],
               worksheet: bool = False) -> tuple[list[Block], list[Block]]:
    """The comparison's blocks in the scenario's section, and those a worksheet's answer key prints (the told
    paragraphs and the filled tables: a worksheet keeps only the introduction and blank tables before its key)."""
    told: list[Block] = [Paragraph(far_end_text(c)), Paragraph(leaving_text(c, frames)), Paragraph(ringing_text(c)),
                         Paragraph(stress_text(c))]
    filled: list[Block] = [b for f in frames for b in (Paragraph(table_text(f)), events_table(causal, f))]
    if not worksheet:
        return [Heading(HEADING, 2), Paragraph(INTRODUCTION), *told, *filled], []
    blank = [b for f in frames for b in (Paragraph(table_text(f) + " Fill in the numbers."),
                                         events_table(causal, f, blank=True))]
    return [Heading(HEADING, 2), Paragraph(WORKSHEET_INTRODUCTION), *blank], [Heading(HEADING, 2), *told, *filled]
