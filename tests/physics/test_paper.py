"""The paper's Appendix (Figs. 1a, 1b, 2a, 2b) derived by hand, checked against the engine; and each printed misprint.

Every expected number here comes from the closed forms below, derived from
the model's rules (README, "The model"), never from the code under test. c = 1, g = 1/sqrt(1 - v^2),
w = 2v/(1 + v^2) (the velocity v' of A in S'). S' moves at -v relative to S:
x' = g(x + v t), t' = g(t + v x).

Fig. 1 (S). A at -L + vt, B at L - vt strike the ends at t = L/(2v), on one
line of the rod's simultaneity; equal and opposite, so the rod stays and the
particles reverse: x_A = -vt, x_B = vt afterwards.
Fig. 1 (S'). The rod's ends are -+L/(2g) + vt'. A moves at w on
x' = -L/(g(1 + v^2)) + w t' and strikes at (0, L/(2gv)), then rests at x' = 0;
B rests at x' = gL, is struck at (gL, t'_B), t'_B = gL(1 + v^2)/(2v), then moves
on x' = w t'.

Fig. 2 (S). t_B = L/(2v): B stops at L/2, the right end takes -v, the rod's
simultaneity turns about E_B = (L/2, t_B) from S to S' (which moves at -v);
the left end, at d = L, follows X_L = L/2 - sqrt(L^2 + (t - t_B)^2) and reaches
-v after g v L, at t_A = t_B + gvL, x = L/2 - gL, which lies on t' = t'_B: A is
timed to strike there, so A starts at x_A = -gL(1 + v^2) + vt. In S' the rod is
at rest at E_A and A arrives at w: they exchange, A rests in S' (-v in S,
x_A = L(1 - 1/g) - vt), the left end takes w in S' (+v in S). The turn about E_A
from S' to +v puts the right end, from E_B on, on X_R = L/2 - gL + sqrt(L^2 +
(t - t_A)^2) (velocity -v at t_B, 0 at t_A), reaching +v at t_B2 = t_B + 2gvL,
x = L/2, where B waits: B2 is on the last line of that turn. There the rod
(+v) and B (0) exchange: the rod stops, B moves on at v (x_B = v t - 2gv^2 L).
The turn about E_B2 from +v to 0 puts the left end, from E_A on, on
X_L = L/2 - sqrt(L^2 + (t - t_B2)^2), at rest at -L/2 at t_B2.
Fig. 2 (S'). Boosting the same hyperbolas (a boost keeps d and moves the
centre): the left end leaves -L/(2g) + vt' at t'_B - gvL, follows
gL - sqrt(L^2 + (t' - t'_B)^2) to (gL - L, t'_B), where the rod rests at full
length L; then x'_B2 - sqrt(L^2 + (t' - t'_B2)^2), x'_B2 = gL + 2g^2 v^2 L,
t'_B2 = t'_B + 2g^2 v L, back on -L/(2g) + vt' at t'_B + (2g^2 - g)vL. The right
end: L/(2g) + vt', then gL - L + sqrt(L^2 + (t' - t'_B)^2) from t'_B to t'_B2,
then L/(2g) + vt' again. A: -L + w t', then rests at gL - L. B: rests at gL,
then L/(2g) + vt' until t'_B2, then w (t' - vL).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import Callable

import pytest

from rodparadox.physics.rigid import engine
from rodparadox.io import scenario
from rodparadox.physics.frames import Frame, view
from rodparadox.physics.kinematics import HyperbolicArc

VS = (0.1, 0.3, 0.6, 0.8, 0.95, 0.99)
LS = (0.5, 1.0, 3.7)
CASES = [(v, L) for v in VS for L in LS]
REL = 1e-12  # the closed forms and the engine must agree to this, relative to the magnitudes involved
FRACTIONS = (0.001, 0.05, 0.25, 0.5, 0.75, 0.95, 0.999)  # where inside each validity range to compare


# ---------------------------------------------------------------- the closed forms (hand-derived)

def lorentz_g(v: float) -> float:
    return 1.0 / math.sqrt(1.0 - v * v)


def v_prime(v: float) -> float:
    """A's velocity in S' (and the rod's after A1 there): v' = 2v/(1 + v^2)."""
    return 2.0 * v / (1.0 + v * v)


@dataclass(frozen=True)
class Piece:
    """One closed form of a world-line, x(t) with velocity u(t), valid for lo < t < hi in one frame."""

    lo: float
    hi: float
    x: Callable[[float], float]
    u: Callable[[float], float]


def line(x0: float, u: float, lo: float = -math.inf, hi: float = math.inf) -> Piece:
    """x = x0 + u t."""
    return Piece(lo, hi, lambda t: x0 + u * t, lambda t: u)


def hyperbola(xc: float, tc: float, d: float, side: int, lo: float, hi: float) -> Piece:
    """x = xc + side sqrt(d^2 + (t - tc)^2): the rigid-response hyperbola centred on (xc, tc)."""
    return Piece(lo, hi, lambda t: xc + side * math.hypot(d, t - tc),
                 lambda t: side * (t - tc) / math.hypot(d, t - tc))


@dataclass(frozen=True)
class Expected:
    """One impact: who, where, when, and the velocities of particle and rod (rest frame) before -> after."""

    particle: str
    end: str
    x: float
    t: float
    particle_before: float
    particle_after: float
    rod_before: float
    rod_after: float


@dataclass(frozen=True)
class ClosedForms:
    events: dict[str, Expected]  # in the rod's own order of impacts
    worldlines: dict[str, tuple[Piece, ...]]


def fig1_rest(v: float, L: float) -> ClosedForms:
    """Fig. 1a: Eqs. (1)-(3)."""
    t1 = L / (2 * v)
    return ClosedForms(
        {"A1": Expected("A", "left", -L / 2, t1, v, -v, 0.0, 0.0),
         "B1": Expected("B", "right", L / 2, t1, -v, v, 0.0, 0.0)},
        {"rod_left": (line(-L / 2, 0.0),),
         "rod_right": (line(L / 2, 0.0),),
         "A": (line(-L, v, hi=t1), line(0.0, -v, lo=t1)),
         "B": (line(L, -v, hi=t1), line(0.0, v, lo=t1))})


def fig1_moving(v: float, L: float) -> ClosedForms:
    """Fig. 1b: the same world-lines in S'."""
    g, w = lorentz_g(v), v_prime(v)
    tA, tB = L / (2 * g * v), g * L * (1 + v * v) / (2 * v)
    return ClosedForms(
        {"A1": Expected("A", "left", 0.0, tA, w, 0.0, v, v),
         "B1": Expected("B", "right", g * L, tB, 0.0, w, v, v)},
        {"rod_left": (line(-L / (2 * g), v),),
         "rod_right": (line(L / (2 * g), v),),
         "A": (line(-L / (g * (1 + v * v)), w, hi=tA), line(0.0, 0.0, lo=tA)),
         "B": (line(g * L, 0.0, hi=tB), line(0.0, w, lo=tB))})


def fig2_times(v: float, L: float) -> dict[str, float]:
    g = lorentz_g(v)
    tB = L / (2 * v)
    tpB = g * L * (1 + v * v) / (2 * v)
    return {"t_B": tB, "t_A": tB + g * v * L, "t_B2": tB + 2 * g * v * L,
            "tp_B": tpB,                                   # t'_B = t'_A
            "tp_left_starts": tpB - g * v * L,             # the left end leaves -L/(2g) + vt'
            "tp_left_back": tpB + (2 * g * g - g) * v * L,  # the left end is back on -L/(2g) + vt'
            "tp_B2": tpB + 2 * g * g * v * L}


def fig2_rest(v: float, L: float) -> ClosedForms:
    """Fig. 2a, corrected."""
    g = lorentz_g(v)
    T = fig2_times(v, L)
    tB, tA, tB2 = T["t_B"], T["t_A"], T["t_B2"]
    return ClosedForms(
        {"B1": Expected("B", "right", L / 2, tB, -v, 0.0, 0.0, -v),
         "A1": Expected("A", "left", L / 2 - g * L, tA, v, -v, -v, v),
         "B2": Expected("B", "right", L / 2, tB2, 0.0, v, v, 0.0)},
        {"rod_right": (line(L / 2, 0.0, hi=tB),
                       hyperbola(L / 2 - g * L, tA, L, +1, tB, tB2),  # Eq. XR, valid to t_B + 2gvL
                       line(L / 2, 0.0, lo=tB2)),
         "rod_left": (line(-L / 2, 0.0, hi=tB),
                      hyperbola(L / 2, tB, L, -1, tB, tA),             # Eq. XL
                      hyperbola(L / 2, tB2, L, -1, tA, tB2),           # Eq. XL2, corrected
                      line(-L / 2, 0.0, lo=tB2)),
         "A": (line(-g * L * (1 + v * v), v, hi=tA), line(L * (1 - 1 / g), -v, lo=tA)),
         "B": (line(L, -v, hi=tB), line(L / 2, 0.0, lo=tB, hi=tB2), line(-2 * g * v * v * L, v, lo=tB2))})


def fig2_moving(v: float, L: float) -> ClosedForms:
    """Fig. 2b, corrected."""
    g, w = lorentz_g(v), v_prime(v)
    T = fig2_times(v, L)
    tB, tB2, ts, te = T["tp_B"], T["tp_B2"], T["tp_left_starts"], T["tp_left_back"]
    xB2 = g * L + 2 * g * g * v * v * L
    return ClosedForms(
        {"B1": Expected("B", "right", g * L, tB, 0.0, v, v, 0.0),
         "A1": Expected("A", "left", g * L - L, tB, w, 0.0, 0.0, w),
         "B2": Expected("B", "right", xB2, tB2, v, w, w, v)},
        {"rod_right": (line(L / (2 * g), v, hi=tB),
                       hyperbola(g * L - L, tB, L, +1, tB, tB2),
                       line(L / (2 * g), v, lo=tB2)),
         "rod_left": (line(-L / (2 * g), v, hi=ts),
                      hyperbola(g * L, tB, L, -1, ts, tB),             # Eq. XpL2, corrected
                      hyperbola(xB2, tB2, L, -1, tB, te),
                      line(-L / (2 * g), v, lo=te)),
         "A": (line(-L, w, hi=tB), line(g * L - L, 0.0, lo=tB)),
         "B": (line(g * L, 0.0, hi=tB), line(L / (2 * g), v, lo=tB, hi=tB2), line(-w * v * L, w, lo=tB2))})


CLOSED_FORMS = {("fig1", "rest"): fig1_rest, ("fig1", "moving"): fig1_moving,
                ("fig2", "rest"): fig2_rest, ("fig2", "moving"): fig2_moving}


def closed_position(pieces: tuple[Piece, ...], t: float) -> float:
    return next(p for p in pieces if p.lo <= t <= p.hi).x(t)


def sample_times(piece: Piece, L: float) -> list[float]:
    """Times strictly inside the piece's validity range (several L out for an unbounded end)."""
    lo, hi = piece.lo, piece.hi
    if math.isinf(lo) and math.isinf(hi):
        return [k * L for k in (-3.0, -0.4, 0.0, 0.7, 2.0, 9.0)]
    if math.isinf(lo):
        return [hi - k * L for k in (0.001, 0.3, 1.0, 4.0)]
    if math.isinf(hi):
        return [lo + k * L for k in (0.001, 0.3, 1.0, 4.0)]
    return [lo + f * (hi - lo) for f in FRACTIONS]


# ---------------------------------------------------------------- the engine, read through its public API

@functools.lru_cache(maxsize=None)
def history(fig: str, v: float, L: float) -> engine.History:
    return engine.run(scenario.load(fig).with_overrides(v=v, L=L))


def frame_of(name: str, v: float) -> Frame:
    return Frame("rest", 0.0) if name == "rest" else Frame("moving", -v)


def engine_worldline(fig: str, frame: str, name: str, v: float, L: float):
    return history(fig, v, L).worldline(name).seen_from(frame_of(frame, v).rapidity)


def engine_x(fig: str, frame: str, name: str, v: float, L: float, t: float) -> float:
    return engine_worldline(fig, frame, name, v, L).event_at_time(t).x


def engine_velocity(fig: str, frame: str, name: str, v: float, L: float, t: float) -> float:
    """The engine's exact velocity at time t (t not at a kink): the slope of its line or tanh of its arc's angle."""
    wl = engine_worldline(fig, frame, name, v, L)
    if t <= wl.first.t:
        return math.tanh(wl.rapidity_before)
    if t >= wl.last.t:
        return math.tanh(wl.rapidity_after)
    for s in wl.segments:
        if s.start.t <= t <= s.end.t:
            return math.tanh(s.phi_at_time(t) if isinstance(s, HyperbolicArc) else s.rapidity_at_start)
    raise AssertionError("no segment at this time")


def agrees(actual: float, expected: float, scale: float) -> bool:
    """Equal to REL of the magnitudes involved (scale: the size of the coordinates at hand)."""
    return abs(actual - expected) <= REL * max(abs(expected), scale)


def differs(actual: float, expected: float, scale: float) -> bool:
    """Clearly different: far beyond any rounding (1e-6 of the magnitudes involved)."""
    return abs(actual - expected) > 1e-6 * max(abs(expected), scale)


def boost_to_moving(x: float, t: float, v: float) -> tuple[float, float]:
    """S -> S' by hand: x' = g(x + vt), t' = g(t + vx)."""
    g = lorentz_g(v)
    return g * (x + v * t), g * (t + v * x)


# ---------------------------------------------------------------- the derivation is self-consistent

@pytest.mark.parametrize("fig", ["fig1", "fig2"])
@pytest.mark.parametrize("v,L", [(0.3, 1.0), (0.6, 3.7), (0.95, 0.5)])
def test_closed_forms_in_S_prime_are_the_boosted_closed_forms_in_S(fig, v, L):
    """No engine here: my S' forms are the Lorentz transforms of my S forms, event by event and point by point."""
    rest, moving = CLOSED_FORMS[fig, "rest"](v, L), CLOSED_FORMS[fig, "moving"](v, L)
    assert list(rest.events) == list(moving.events) or fig == "fig1"
    for label, e in rest.events.items():
        xp, tp = boost_to_moving(e.x, e.t, v)
        m = moving.events[label]
        assert math.isclose(xp, m.x, rel_tol=1e-12, abs_tol=1e-12 * L)
        assert math.isclose(tp, m.t, rel_tol=1e-12)
        for u, up in ((e.particle_before, m.particle_before), (e.particle_after, m.particle_after),
                      (e.rod_before, m.rod_before), (e.rod_after, m.rod_after)):
            assert math.isclose((u + v) / (1 + u * v), up, rel_tol=1e-12, abs_tol=1e-12)
    for name, pieces in rest.worldlines.items():
        for piece in pieces:
            for t in sample_times(piece, L):
                xp, tp = boost_to_moving(piece.x(t), t, v)
                assert math.isclose(closed_position(moving.worldlines[name], tp), xp, rel_tol=1e-12,
                                    abs_tol=1e-12 * (L + abs(tp)))


# ---------------------------------------------------------------- the engine against the closed forms

@pytest.mark.parametrize("fig", ["fig1", "fig2"])
@pytest.mark.parametrize("v,L", CASES)
def test_impacts_match_closed_forms_in_both_frames(fig, v, L):
    h = history(fig, v, L)
    for frame in ("rest", "moving"):
        expected = CLOSED_FORMS[fig, frame](v, L).events
        events = view(h, frame_of(frame, v)).events
        assert sorted(e.impact.label for e in events) == sorted(expected)
        if fig == "fig2":  # the rod's own order: B1, A1, B2
            assert [e.impact.label for e in events] == ["B1", "A1", "B2"]
        for e in events:
            want = expected[e.impact.label]
            scale = max(abs(want.x), abs(want.t), L)
            assert (e.impact.particle, e.impact.end) == (want.particle, want.end)
            assert agrees(e.x, want.x, scale), (frame, e.impact.label, "x", e.x, want.x)
            assert agrees(e.t, want.t, scale), (frame, e.impact.label, "t", e.t, want.t)
            # the same event boosted by hand from the engine's S coordinates
            direct = e.impact.event.seen_from(math.atanh(frame_of(frame, v).velocity))
            assert agrees(direct.x, want.x, scale) and agrees(direct.t, want.t, scale)
            for got, exp in ((e.particle_velocity_before, want.particle_before),
                             (e.particle_velocity_after, want.particle_after),
                             (e.rod_velocity_before, want.rod_before),
                             (e.rod_velocity_after, want.rod_after)):
                assert abs(got - exp) <= REL, (frame, e.impact.label, got, exp)


@pytest.mark.parametrize("frame", ["rest", "moving"])
@pytest.mark.parametrize("fig", ["fig1", "fig2"])
@pytest.mark.parametrize("v,L", CASES)
def test_worldlines_match_closed_forms_inside_every_validity_range(fig, frame, v, L):
    forms = CLOSED_FORMS[fig, frame](v, L)
    for name, pieces in forms.worldlines.items():
        for piece in pieces:
            for t in sample_times(piece, L):
                scale = max(abs(t), L)
                x = engine_x(fig, frame, name, v, L, t)
                assert agrees(x, piece.x(t), scale), (name, t, x, piece.x(t))
                u = engine_velocity(fig, frame, name, v, L, t)
                assert abs(u - piece.u(t)) <= REL * scale / L, (name, t, u, piece.u(t))


@pytest.mark.parametrize("v,L", CASES)
def test_starting_positions(v, L):
    """At t = 0 in S: Fig. 1 both particles L/2 from their ends; Fig. 2 A at -gL(1 + v^2), B at L."""
    g = lorentz_g(v)
    for fig, xA in (("fig1", -L), ("fig2", -g * L * (1 + v * v))):
        starts = dict(history(fig, v, L).starts)
        assert starts["A"].t == 0.0 and starts["B"].t == 0.0
        assert agrees(starts["A"].x, xA, L) and agrees(starts["B"].x, L, L)


# ---------------------------------------------------------------- the paper's claims

@pytest.mark.parametrize("v,L", CASES)
def test_fig1_rod_never_moves_in_S_and_keeps_v_in_S_prime(v, L):
    g = lorentz_g(v)
    for t in (-L, 0.0, L / (2 * v), 10 * L):
        assert engine_x("fig1", "rest", "rod_left", v, L, t) == pytest.approx(-L / 2, rel=REL)
        assert engine_x("fig1", "rest", "rod_right", v, L, t) == pytest.approx(L / 2, rel=REL)
        for name, sign in (("rod_left", -1), ("rod_right", 1)):
            assert engine_velocity("fig1", "rest", name, v, L, t) == 0.0
            assert agrees(engine_x("fig1", "moving", name, v, L, t), sign * L / (2 * g) + v * t, max(abs(t), L))
            assert engine_velocity("fig1", "moving", name, v, L, t) == pytest.approx(v, rel=REL)


@pytest.mark.parametrize("v,L", CASES)
def test_fig1_impacts_simultaneous_in_S_and_A_strikes_first_in_S_prime(v, L):
    h = history("fig1", v, L)
    by_label = {i.label: i for i in h.impacts}
    assert by_label["A1"].simultaneous_with == "B1"
    assert by_label["A1"].event.t == pytest.approx(by_label["B1"].event.t, rel=REL)
    moving = {e.impact.label: e for e in view(h, Frame("moving", -v)).events}
    assert moving["A1"].t < moving["B1"].t
    # A strikes first in S' by t'_B - t'_A = g v L, to rounding
    assert moving["B1"].t - moving["A1"].t == pytest.approx(lorentz_g(v) * v * L, rel=1e-10)


@pytest.mark.parametrize("v,L", CASES)
def test_fig2_three_impacts_B1_A1_B2_in_the_rod_s_order_and_rod_ends_where_it_began(v, L):
    h = history("fig2", v, L)
    assert [(i.label, i.particle, i.end) for i in h.impacts] == [
        ("B1", "B", "right"), ("A1", "A", "left"), ("B2", "B", "right")]
    times = [i.event.t for i in h.impacts]
    assert times == sorted(times)
    assert h.impacts[-1].rod_rapidity_after == pytest.approx(0.0, abs=REL)
    t_late = fig2_times(v, L)["t_B2"] + 5 * L
    assert agrees(engine_x("fig2", "rest", "rod_left", v, L, t_late), -L / 2, t_late)
    assert agrees(engine_x("fig2", "rest", "rod_right", v, L, t_late), L / 2, t_late)
    assert abs(engine_velocity("fig2", "rest", "rod_left", v, L, t_late)) <= REL
    assert abs(engine_velocity("fig2", "rest", "rod_right", v, L, t_late)) <= REL


@pytest.mark.parametrize("v,L", CASES)
def test_fig2_in_S_prime_rod_stops_at_full_length_when_A_and_B_strike_together(v, L):
    g = lorentz_g(v)
    tpB = fig2_times(v, L)["tp_B"]
    moving = {e.impact.label: e for e in view(history("fig2", v, L), Frame("moving", -v)).events}
    assert agrees(moving["A1"].t, moving["B1"].t, tpB)  # simultaneous in S'
    # at t'_B the right end is where B1 happens and the left end where A1 happens
    right, left = moving["B1"].x, moving["A1"].x
    assert agrees(right, g * L, tpB) and agrees(left, g * L - L, tpB)
    assert agrees(right - left, L, tpB)  # rest length L, not L/g
    # the world-lines themselves, read at t'_B
    assert abs(engine_x("fig2", "moving", "rod_right", v, L, tpB)
               - engine_x("fig2", "moving", "rod_left", v, L, tpB) - L) <= 1e-11 * tpB
    assert moving["B1"].rod_velocity_after == pytest.approx(0.0, abs=REL)
    assert moving["A1"].rod_velocity_before == pytest.approx(0.0, abs=REL)
    # the left end slows to rest just as t'_B arrives (velocity ~ (t'_B - t')/L there)
    assert abs(engine_velocity("fig2", "moving", "rod_left", v, L, tpB - 1e-9 * L)) <= 2e-9


@pytest.mark.parametrize("v,L", CASES)
def test_fig2_in_S_prime_A_arrives_at_v_prime_rod_reaches_v_prime_then_moves_on_at_v(v, L):
    w = v_prime(v)
    T = fig2_times(v, L)
    moving = {e.impact.label: e for e in view(history("fig2", v, L), Frame("moving", -v)).events}
    assert moving["A1"].particle_velocity_before == pytest.approx(w, rel=REL)
    assert moving["A1"].rod_velocity_after == pytest.approx(w, rel=REL)
    assert moving["B2"].rod_velocity_before == pytest.approx(w, rel=REL)
    assert moving["B2"].rod_velocity_after == pytest.approx(v, rel=REL)
    # the right end arrives at B2 moving at v' (the last line of the turn about A1)
    tp = T["tp_B2"] - 1e-9 * L
    assert engine_velocity("fig2", "moving", "rod_right", v, L, tp) == pytest.approx(w, abs=1e-8)
    for name in ("rod_left", "rod_right"):
        assert engine_velocity("fig2", "moving", name, v, L, T["tp_B2"] + 3 * L) == pytest.approx(v, rel=REL)


@pytest.mark.parametrize("v,L", CASES)
def test_fig2_particles_final_velocities_interchanged(v, L):
    for frame in ("rest", "moving"):
        T = fig2_times(v, L)
        early, late = -L, (T["tp_B2"] if frame == "moving" else T["t_B2"]) + 3 * L
        u = {(n, when): engine_velocity("fig2", frame, n, v, L, t)
             for n in ("A", "B") for when, t in (("first", early), ("last", late))}
        assert u["A", "last"] == pytest.approx(u["B", "first"], abs=REL)
        assert u["B", "last"] == pytest.approx(u["A", "first"], abs=REL)


# ---------------------------------------------------------------- the misprints: printed form vs engine vs corrected form

@pytest.mark.parametrize("v,L", CASES)
def test_misprint_eq_LT_sign(v, L):
    """Eq. (LT) prints t' = g[t - v x(t)]; S' moves at -v, so t' = g[t + v x(t)]."""
    g = lorentz_g(v)
    moving = {e.impact.label: e for e in view(history("fig1", v, L), Frame("moving", -v)).events}
    printed, corrected = {}, {}
    for label, e in moving.items():
        x, t = e.impact.event.x, e.impact.event.t
        printed[label], corrected[label] = g * (t - v * x), g * (t + v * x)
        assert differs(e.t, printed[label], L) and agrees(e.t, corrected[label], max(abs(e.t), L))
    # the printed sign would have B strike first in S', contrary to the paper's "particle A is the first"
    assert printed["B1"] < printed["A1"] and corrected["A1"] < corrected["B1"]
    # with Eq. (LTx) the printed pair is no Lorentz transformation: it changes the interval t^2 - x^2 of an impact
    for e in moving.values():
        x, t = e.impact.event.x, e.impact.event.t
        xp = g * (x + v * t)
        assert differs(printed[e.impact.label] ** 2 - xp ** 2, t * t - x * x, L * L)
        assert abs(e.t ** 2 - e.x ** 2 - (t * t - x * x)) <= 1e-11 * (e.t ** 2 + L * L)


@pytest.mark.parametrize("v,L", CASES)
def test_misprint_eq_XR_validity_range(v, L):
    """Eq. (XR) holds for t_B < t < t_B + 2gvL, not only to t_A: the right end is still turning at t_A."""
    g = lorentz_g(v)
    T = fig2_times(v, L)
    XR = lambda t: math.sqrt(L * L + (t - T["t_A"]) ** 2) + L / 2 - g * L  # as printed
    for f in FRACTIONS:  # beyond the printed range, up to B2, the engine still follows Eq. (XR)
        t = T["t_A"] + f * (T["t_B2"] - T["t_A"])
        assert agrees(engine_x("fig2", "rest", "rod_right", v, L, t), XR(t), max(t, L))
    # at the printed end t_A the right end is at rest mid-swing, L/2 + L - gL, not yet back at L/2 with velocity +v
    assert abs(engine_velocity("fig2", "rest", "rod_right", v, L, T["t_A"])) <= REL * T["t_A"] / L
    assert differs(engine_x("fig2", "rest", "rod_right", v, L, T["t_A"]), L / 2, L)
    assert engine_velocity("fig2", "rest", "rod_right", v, L, T["t_B2"] - 1e-9 * L) == pytest.approx(v, abs=1e-8)


@pytest.mark.parametrize("v,L", CASES)
def test_misprint_eq_XL2_form(v, L):
    """Eq. (XL2) prints X_L = -2L + sqrt(L^2 + (t - t_R)^2), t_R undefined; it is L/2 - sqrt(L^2 + (t - t_B - 2gvL)^2)."""
    T = fig2_times(v, L)
    corrected = lambda t: L / 2 - math.sqrt(L * L + (t - T["t_B2"]) ** 2)
    for t_R in (T["t_B"], T["t_A"], T["t_B2"]):  # every reading of the undefined t_R
        printed = lambda t: -2 * L + math.sqrt(L * L + (t - t_R) ** 2)
        assert any(differs(engine_x("fig2", "rest", "rod_left", v, L, t), printed(t), L)
                   for t in (T["t_A"] + f * (T["t_B2"] - T["t_A"]) for f in FRACTIONS))
    for f in FRACTIONS:
        t = T["t_A"] + f * (T["t_B2"] - T["t_A"])
        assert agrees(engine_x("fig2", "rest", "rod_left", v, L, t), corrected(t), max(t, L))
    # the printed curve bends the wrong way: the left end decelerates (moving right, slowing to rest), x'' < 0
    t, h = T["t_A"] + 0.5 * (T["t_B2"] - T["t_A"]), 1e-3 * L
    second = sum(c * engine_x("fig2", "rest", "rod_left", v, L, t + k * h) for c, k in ((1, -1), (-2, 0), (1, 1)))
    assert second < 0  # while every curve -2L + sqrt(L^2 + (t - t_R)^2) has x'' > 0


@pytest.mark.parametrize("v,L", [(v, L) for v in VS for L in (0.5, 3.7)])
def test_misprint_eq_XL2_validity_range(v, L):
    """Eq. (XL2) prints t_B < t < t_B + 2gv; it holds for t_A < t < t_B + 2gvL (a length L is missing)."""
    T = fig2_times(v, L)
    g = lorentz_g(v)
    corrected = lambda t: L / 2 - math.sqrt(L * L + (t - T["t_B2"]) ** 2)
    # lower end: on t_B < t < t_A the left end follows Eq. (XL), not Eq. (XL2)
    t = 0.5 * (T["t_B"] + T["t_A"])
    assert differs(engine_x("fig2", "rest", "rod_left", v, L, t), corrected(t), L)
    # upper end: the printed t_B + 2gv is not where the left end comes to rest at -L/2 (unless L = 1)
    printed_end = T["t_B"] + 2 * g * v
    between = 0.5 * (printed_end + T["t_B2"])
    x = engine_x("fig2", "rest", "rod_left", v, L, between)
    if printed_end > T["t_B2"]:  # already at rest at -L/2, off the continued curve
        assert agrees(x, -L / 2, between) and differs(x, corrected(between), L)
    else:  # still moving
        assert differs(x, -L / 2, L) and agrees(x, corrected(between), between)


@pytest.mark.parametrize("v,L", CASES)
def test_misprint_tpB_missing_factor_1_over_v(v, L):
    """t'_B is printed (gL/2)(1 + v^2); it is (gL/2v)(1 + v^2)."""
    g = lorentz_g(v)
    moving = {e.impact.label: e for e in view(history("fig2", v, L), Frame("moving", -v)).events}
    printed, corrected = (g * L / 2) * (1 + v * v), (g * L / (2 * v)) * (1 + v * v)
    for label in ("B1", "A1"):
        assert differs(moving[label].t, printed, L) and agrees(moving[label].t, corrected, corrected)


@pytest.mark.parametrize("v,L", CASES)
def test_misprint_eq_XpL2(v, L):
    """Eq. (XpL2) prints X'_L = L/2g - L + sqrt(L^2 + (t - t'_B)^2); it is gL - sqrt(L^2 + (t' - t'_B)^2)."""
    g = lorentz_g(v)
    T = fig2_times(v, L)
    tpB = T["tp_B"]
    printed = lambda tp: L / (2 * g) - L + math.sqrt(L * L + (tp - tpB) ** 2)
    corrected = lambda tp: g * L - math.sqrt(L * L + (tp - tpB) ** 2)
    for f in FRACTIONS:
        tp = T["tp_left_starts"] + f * (tpB - T["tp_left_starts"])
        x = engine_x("fig2", "moving", "rod_left", v, L, tp)
        assert differs(x, printed(tp), L) and agrees(x, corrected(tp), max(tp, L))
    # at t'_B the printed curve ends at L/(2g), not at gL - L where the paper's own x'_A puts A's impact
    assert differs(printed(tpB), g * L - L, L) and corrected(tpB) == pytest.approx(g * L - L, rel=REL)


@pytest.mark.parametrize("v,L", CASES)
def test_misprint_trajectories_end_time_fig2b(v, L):
    """'These trajectories end at t' = t'_B + 2gvL': the right end at t'_B + 2g^2vL, the left at t'_B + (2g^2 - g)vL."""
    g = lorentz_g(v)
    T = fig2_times(v, L)
    printed_end = T["tp_B"] + 2 * g * v * L
    for name, sign, corrected_end in (("rod_right", 1, T["tp_B2"]), ("rod_left", -1, T["tp_left_back"])):
        original = lambda tp: sign * L / (2 * g) + v * tp
        on_original = lambda tp: agrees(engine_x("fig2", "moving", name, v, L, tp), original(tp), max(tp, L))
        # the engine: off the original world-line just before the corrected end, on it just after
        assert not on_original(corrected_end - 1e-3 * L) and on_original(corrected_end + 1e-3 * L)
        # between the printed and the corrected end, the printed claim and the engine disagree
        between = 0.5 * (printed_end + corrected_end)
        assert on_original(between) == (between > corrected_end) != (between > printed_end)


@pytest.mark.parametrize("v,L", CASES)
def test_misprint_xpB_validity_range(v, L):
    """x'_B = L/2g + vt' is printed for t'_B < t' < t'_B + 2gvL; it holds to t'_B + 2g^2vL (B's second impact)."""
    g = lorentz_g(v)
    T = fig2_times(v, L)
    printed_end = T["tp_B"] + 2 * g * v * L
    b2 = next(e for e in view(history("fig2", v, L), Frame("moving", -v)).events if e.impact.label == "B2")
    assert differs(b2.t, printed_end, L) and agrees(b2.t, T["tp_B2"], b2.t)
    tp = 0.5 * (printed_end + T["tp_B2"])  # after the printed range, B has not yet been struck again
    assert agrees(engine_x("fig2", "moving", "B", v, L, tp), L / (2 * g) + v * tp, tp)


@pytest.mark.parametrize("v,L", CASES)
def test_misprint_xpB_after_second_impact(v, L):
    """After B2 x'_B is printed L/2g + 2vt'/(1 + v^2); it is (2v/(1 + v^2))(t' - vL)."""
    g, w = lorentz_g(v), v_prime(v)
    T = fig2_times(v, L)
    for k in (0.01, 0.5, 2.0, 10.0):
        tp = T["tp_B2"] + k * L
        x = engine_x("fig2", "moving", "B", v, L, tp)
        assert differs(x, L / (2 * g) + w * tp, L) and agrees(x, w * (tp - v * L), tp)


@pytest.mark.parametrize("v,L", CASES)
def test_misprint_notation_right_end(v, L):
    """'X'_L(t') and X'_B(t') of the ends of the rod': the right end is X'_R; x'_B is particle B, another world-line."""
    g = lorentz_g(v)
    tpB = fig2_times(v, L)["tp_B"]
    for fig in ("fig1", "fig2"):
        for tp in (0.0, 0.5 * tpB):  # before B1 the right end and B are apart: L/(2g) + vt' against gL
            right, b = engine_x(fig, "moving", "rod_right", v, L, tp), engine_x(fig, "moving", "B", v, L, tp)
            assert agrees(right, L / (2 * g) + v * tp, max(tp, L)) and agrees(b, g * L, g * L)
            assert differs(right, b, L)


@pytest.mark.parametrize("v,L", CASES)
def test_misprint_fig2b_source_equations(v, L):
    """After A1 the ends follow the transforms of Eqs. (XR) and (XL2); the printed '(XL) and (XR)' cites the wrong left end."""
    T = fig2_times(v, L)
    XL = lambda t: L / 2 - math.sqrt(L * L + (t - T["t_B"]) ** 2)      # Eq. (XL), continued past t_A
    XL2 = lambda t: L / 2 - math.sqrt(L * L + (t - T["t_B2"]) ** 2)    # Eq. (XL2), corrected
    # within its own range t_B < t < t_A, Eq. (XL) only reaches t' = t'_B: it is all before A1 in S'
    assert agrees(boost_to_moving(XL(T["t_A"]), T["t_A"], v)[1], T["tp_B"], T["tp_B"])
    for f in (0.1, 0.5, 0.9):
        t = T["t_A"] + f * (T["t_B2"] - T["t_A"])
        xp_XL, tp_XL = boost_to_moving(XL(t), t, v)
        xp_XL2, tp_XL2 = boost_to_moving(XL2(t), t, v)
        assert tp_XL > T["tp_B"] and tp_XL2 > T["tp_B"]
        assert differs(engine_x("fig2", "moving", "rod_left", v, L, tp_XL), xp_XL, L)
        assert agrees(engine_x("fig2", "moving", "rod_left", v, L, tp_XL2), xp_XL2, max(tp_XL2, L))


@pytest.mark.parametrize("v,L", CASES)
def test_misprint_fig2a_A_does_not_follow_eq_xLR(v, L):
    """'particles A and B will follow Eq. (xLR) until t_B': B does; A starts further left, x_A = -gL(1 + v^2) + vt."""
    g = lorentz_g(v)
    for t in (0.0, 0.5 * fig2_times(v, L)["t_B"]):
        xA = engine_x("fig2", "rest", "A", v, L, t)
        assert differs(xA, -L + v * t, L) and agrees(xA, -g * L * (1 + v * v) + v * t, max(t, L))
        assert agrees(engine_x("fig2", "rest", "B", v, L, t), L - v * t, max(t, L))


@pytest.mark.parametrize("v,L", CASES)
def test_misprint_prose_momentary_stop_at_t_A_is_the_right_end(v, L):
    """'Because the left end of the rod is momentarily stopped by particle A at t_A': in S the left end goes -v -> +v;
    it is the right end that is momentarily at rest at t_A (why Eq. (XR) is centred on t_A)."""
    a1 = next(e for e in view(history("fig2", v, L), Frame("rest", 0.0)).events if e.impact.label == "A1")
    assert a1.rod_velocity_before == pytest.approx(-v, rel=REL) and a1.rod_velocity_after == pytest.approx(v, rel=REL)
    t_A = fig2_times(v, L)["t_A"]
    assert abs(engine_velocity("fig2", "rest", "rod_right", v, L, t_A)) <= REL * t_A / L
    assert differs(engine_velocity("fig2", "rest", "rod_left", v, L, t_A - 1e-6 * L), 0.0, 1.0)


# ---------------------------------------------------------------- reading world-lines exactly at impact times

def test_engine_worldlines_readable_at_every_impact_time_in_both_frames():
    """Every world-line has one event at each impact's time, in S and S' (once broken by a rounding gap
    between consecutive boosted arcs at t'_B, v = 0.8); the struck ones pass through the impact."""
    for fig in ("fig1", "fig2"):
        for v, L in CASES:
            h = history(fig, v, L)
            for frame in ("rest", "moving"):
                eta = frame_of(frame, v).rapidity
                for impact in h.impacts:
                    e = impact.event.seen_from(eta)
                    for name, _ in h.worldlines:
                        read = engine_worldline(fig, frame, name, v, L).event_at_time(e.t)
                        assert abs(read.t - e.t) <= 1e-12 * (L + abs(e.t))
                        if name in (impact.particle, f"rod_{impact.end}"):
                            assert abs(read.x - e.x) <= 1e-12 * (L + abs(e.x) + abs(e.t))
