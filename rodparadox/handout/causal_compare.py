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
from rodparadox.handout.words import in_c, in_l, listed, numeral, signed_numeral, summand, time_name
from rodparadox.numbers import impact_name
from rodparadox.physics.frames import Frame, frame_name, frame_symbol, frame_word
from rodparadox.physics.ledger import EnergyMomentum
from rodparadox.tables import build as tables

HEADING = "The causal rod beside the rigid rod"

INTRODUCTION = (
    "The rigid rod above is the paper\u2019s idealisation. The causal rod is the stiffest rod relativity allows: "
    "sound in it travels at c, so the push of an impact spreads through it as a front of compression at the speed "
    "of light, and a particle rides with the end it strikes, pushed by the end\u2019s compression, until that "
    "compression has gone. Here the same particles, at the same speeds, strike "
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
        parts.append(f"in {frame_name(e.frame)} the particles lose {numeral(_zero(e.lost_causal, 1.0))} M c² = "
                     f"{numeral(e.internal)} M c² of internal energy + {_signed_energy(e.bulk_change)} of bulk "
                     f"kinetic energy (from {numeral(_zero(e.bulk_before, 1.0))} to {numeral(_zero(e.bulk_after, 1.0))} "
                     f"M c²)")
    rigid = listed([f"{numeral(_zero(e.lost_rigid, 1.0))} M c² in {frame_name(e.frame)}" for e in c.energy])
    text = "; ".join(parts)
    return (f"Where the energy went. From before the first impact to after the last separation, {text}. The rise of "
            f"the rest mass is the same in every frame; the bulk kinetic energy, and so what the particles lose, is "
            f"not. The rigid rod\u2019s rest mass stays M, so what the particles lose to it, {rigid}, is all bulk "
            f"kinetic energy.")


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
                         Paragraph(energy_text(c)), Paragraph(stress_text(c))]
    filled: list[Block] = [b for f in frames for b in (Paragraph(table_text(f)), events_table(causal, f))]
    if not worksheet:
        return [Heading(HEADING, 2), Paragraph(INTRODUCTION), *told, *filled], []
    # the causal rod's contacts and separations come from solving its wave equation, which a student cannot fill in,
    # and its first contacts are the rigid rod's first impacts, whose cells the worksheet asks: the key prints them
    return [Heading(HEADING, 2), Paragraph(WORKSHEET_INTRODUCTION)], [Heading(HEADING, 2), *told, *filled]
