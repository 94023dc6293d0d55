"""A rod driven by forces drawn (issue 26, items 4 and 5): the ends' world-lines, each force as a band as wide as F
along its end, its start and end marked with the lines of simultaneity of S and S' through them. Checked against
hand derivations (Sears's sine^2 pulses in their own frame, the Lorentz transformation written out) and the
history's exact world-lines, never against the drawing code's own numbers.

Figures are drawn once per process (`drawn`) and checked many ways.
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np
import pytest

from helpers import error_of
from rodparadox import render
from rodparadox.io.scenario import load
from rodparadox.physics.frames import paper_frames
from rodparadox.physics.models import run_rods

#: a band is this many points wide at the legend's force in the default style (its type size); Sears's presets
#: peak at 0.2 M c^2/L, the push at 0.25, so the legend's force (the least nice number not below the peak) is the
#: peak itself
BAND_POINTS = 9.0


@lru_cache(maxsize=None)
def runs(name: str, v: float = 0.6):
    return run_rods(load(name).with_overrides(v=v), "both")


def drawn(name: str, v: float = 0.6, rod: str = "rigid", style: str = "default"):
    """The figure of S and S', once per process (`drawn("push")` and `drawn("push", 0.6)` alike): only read."""
    return _drawn(name, v, rod, style)


@lru_cache(maxsize=None)
def _drawn(name: str, v: float, rod: str, style: str):
    rigid, causal = runs(name, v)
    frames = paper_frames(v)
    if rod == "both":
        return render.draw_both(rigid, causal, frames, style)
    return render.draw(rigid if rod == "rigid" else causal, frames, style)


def _points_per_L(panel) -> float:
    x0, x1 = panel.box[:2]
    return panel.axes.bbox.width * 72 / panel.axes.get_figure(root=True).dpi / (x1 - x0)


def _line(diagram, layer: str, letter: str, gid: str):
    return next(a for a in diagram.artists[layer][letter] if a.get_gid() == gid)


# --- the ends' world-lines -----------------------------------------------------------------------------------

@pytest.mark.parametrize("name, rod", [("push", "rigid"), ("sears_moving", "rigid"), ("push", "causal")])
def test_the_drawn_ends_lie_on_the_historys_exact_world_lines_in_both_frames(name, rod):
    diagram = drawn(name, 0.6, rod)
    h = runs(name, 0.6)[0 if rod == "rigid" else 1]
    for panel in diagram.panels:
        eta = panel.frame.rapidity
        for end in ("rod_left", "rod_right"):
            x, t = _line(diagram, "rod", panel.letter, f"{panel.letter}-{end}").get_data()
            exact = h.worldline(end).seen_from(eta)
            gap = max(abs(exact.event_at_time(tk).x - xk) for xk, tk in zip(x, t))
            assert gap < 1e-9, (panel.letter, end, gap)  # the vertices are exact; the chords within tolerance
            # the chords: the exact world-line at the middle of each chord is within the sampling tolerance
            mid_t, mid_x = (t[1:] + t[:-1]) / 2, (x[1:] + x[:-1]) / 2
            chord = max(abs(exact.event_at_time(tk).x - xk) for xk, tk in zip(mid_x, mid_t))
            assert chord < 2e-4


def test_the_window_runs_from_before_the_first_force_to_L_after_the_last_in_S_and_its_image():
    """push: the force acts on the left end for t in [0.5, 4.5] of S; every frame's panel shows at least L before
    the first force event and L after the last, in its own time."""
    diagram = drawn("push")
    h = runs("push")[0]
    for panel in diagram.panels:
        eta = panel.frame.rapidity
        times = [e.event.seen_from(eta).t for e in h.driving.force_events()]
        x, t = _line(diagram, "rod", panel.letter, f"{panel.letter}-rod_left").get_data()
        assert t[0] <= min(times) - 1.0 + 1e-12 and t[-1] >= max(times) + 1.0 - 1e-12


# --- the force bands ---------------------------------------------------------------------------------------

def _band_widths(diagram, letter: str, end: str):
    """(t of the end's event, the band's width in points) along the pressing band of `end`."""
    band = next(a for a in diagram.artists["forces"][letter] if a.get_gid() == f"{letter}-force-{end}-press")
    xy = band.get_xy()
    xy = xy[:-1] if len(xy) % 2 else xy  # closed: the first vertex repeated
    n = len(xy) // 2
    inner, outer = xy[:n], xy[n:][::-1]
    np.testing.assert_allclose(inner[:, 1], outer[:, 1], atol=1e-15)  # widths are horizontal
    panel = next(p for p in diagram.panels if p.letter == letter)
    return inner, np.abs(outer[:, 0] - inner[:, 0]) * _points_per_L(panel)


@pytest.mark.parametrize("rod", ["rigid", "causal"])
def test_sears_bands_are_as_wide_as_the_sine2_force_in_S(rod):
    """Sears: F = 0.2 sin^2(pi (t - 0.5)) on [0.5, 1.5] of S at both ends; 0.2 is the legend's force, so the band
    is BAND_POINTS sin^2(pi (t - 0.5)) points wide at the end's event of time t (the rigid rod stays put in S)."""
    diagram = drawn("sears", 0.6, rod)
    for end in ("left", "right"):
        inner, width = _band_widths(diagram, "a", end)
        t = inner[:, 1]
        expected = BAND_POINTS * np.where((t >= 0.5) & (t < 1.5), np.sin(np.pi * (t - 0.5)) ** 2, 0.0)
        np.testing.assert_allclose(width, expected, atol=1e-9)
        assert width.max() == pytest.approx(BAND_POINTS, abs=1e-3)  # the peak at t = 1 is sampled


def test_sears_moving_bands_read_the_force_at_the_events_time_in_S_prime():
    """sears_moving: the same pulses timed in S'. In the panel of S an end's event (x, t) is at t' = g (t + v x)
    (the paper's convention, S' moving at -v), and the band there is BAND_POINTS sin^2(pi (t' - 0.5)) wide; in the
    panel of S' the panel's own time is the profile's."""
    v = 0.6
    g = 1 / math.sqrt(1 - v * v)
    diagram = drawn("sears_moving", v)
    for letter, to_profile in (("a", lambda x, t: g * (t + v * x)), ("b", lambda x, t: t)):
        for end in ("left", "right"):
            inner, width = _band_widths(diagram, letter, end)
            tp = to_profile(inner[:, 0], inner[:, 1])
            expected = BAND_POINTS * np.where((tp >= 0.5) & (tp < 1.5), np.sin(np.pi * (tp - 0.5)) ** 2, 0.0)
            np.testing.assert_allclose(width, expected, atol=1e-7)


def test_a_constant_push_is_one_width_from_on_to_off_and_its_arrows_press_in():
    """push: 0.25 on the left end for t in [0.5, 4.5) of S: the band is BAND_POINTS wide all along, in both frames,
    falling to nothing at the end; its arrows point right, into the rod, and end on the rod's end."""
    diagram = drawn("push")
    for panel in diagram.panels:
        inner, width = _band_widths(diagram, panel.letter, "left")
        # the jumps drawn as jumps: nothing, then BAND_POINTS at the same instant, and back to nothing at the end
        assert width[0] == 0.0 and width[-1] == 0.0 and inner[0, 1] == inner[1, 1] and inner[-1, 1] == inner[-2, 1]
        assert np.all(np.abs(width[1:-1] - BAND_POINTS) < 1e-9)
        arrows = [a for a in diagram.artists["forces"][panel.letter] if "arrow" in (a.get_gid() or "")]
        assert len(arrows) == 6
        for arrow in arrows:
            (x0, t0), (x1, t1) = arrow._posA_posB
            assert x1 > x0 and t0 == t1
            assert abs((x1 - x0) * _points_per_L(panel) - BAND_POINTS) < 1e-9
    assert not any("right" in (a.get_gid() or "") for a in diagram.artists["forces"]["a"])  # no force there


def test_a_pull_is_told_from_a_push_hatched_and_arrows_pointing_out(tmp_path):
    """A pull on the right end: hatched, its arrows pointing right (out of the rod, away from its right end)."""
    path = tmp_path / "pull.yaml"
    path.write_text("name: pull\nv: 0.6\nforces:\n  right: {shape: step, peak: -0.2, start: 0.5, duration: 1.0}\n")
    h = run_rods(load(str(path)), "rigid")[0]
    diagram = render.draw(h, paper_frames(0.6))
    band = [a for a in diagram.artists["forces"]["a"] if a.get_gid() == "a-force-right-pull"]
    assert len(band) == 1 and band[0].get_hatch()
    arrows = [a for a in diagram.artists["forces"]["a"] if "arrow" in (a.get_gid() or "")]
    assert arrows and all(a._posA_posB[1][0] > a._posA_posB[0][0] for a in arrows)
    _, labels = diagram.figure.legends[0].legend_handles, [t.get_text() for t in diagram.figure.legends[0].texts]
    assert any(text.endswith("; hatched: a pull") for text in labels)


# --- the force events and the lines of simultaneity ------------------------------------------------------------

@pytest.mark.parametrize("name", ["sears", "sears_moving", "push"])
def test_lines_of_simultaneity_run_through_each_forces_start_and_end_at_the_frames_slopes(name):
    """In the panel of S the lines of S are flat and those of S' have slope dt/dx = -v (t' = g (t + v x) constant);
    in the panel of S' those of S have slope +v, those of S' are flat. Each goes through the force events it names
    (x, t by the Lorentz transformation written out from the events in S)."""
    v = 0.6
    g = 1 / math.sqrt(1 - v * v)
    diagram = drawn(name, v)
    h = runs(name, v)[0]
    events = {f"{e.end}-{e.moment}": (e.event.x, e.event.t) for e in h.driving.force_events()
              if e.moment in ("start", "end")}
    to_frame = {"a": lambda x, t: (x, t), "b": lambda x, t: (g * (x + v * t), g * (t + v * x))}
    slopes = {("a", "rest"): 0.0, ("a", "moving"): -v, ("b", "rest"): v, ("b", "moving"): 0.0}
    for letter in ("a", "b"):
        marked = {a.get_gid().removeprefix(f"{letter}-force-event-"): a.get_data()
                  for a in diagram.artists["force-events"][letter] if "label" not in a.get_gid() and "leader" not in a.get_gid()}
        assert set(marked) == set(events)
        for family in ("rest", "moving"):
            through = set()
            for line in diagram.artists[f"simultaneity-{family}"][letter]:
                (x0, x1), (t0, t1) = line.get_data()
                assert (t1 - t0) / (x1 - x0) == pytest.approx(slopes[letter, family], abs=1e-12)
                for label in line.get_gid().split(f"simultaneity-{family}-")[1].split("+"):
                    x, t = to_frame[letter](*events[label])
                    assert abs(t0 + slopes[letter, family] * (x - x0) - t) < 1e-9
                    assert marked[label][0][0] == pytest.approx(x, abs=1e-12)
                    through.add(label)
            assert through == set(events)  # every start and end has its line of each frame


def test_the_legend_and_the_note_say_forces_not_particles():
    diagram = drawn("sears_moving", 0.6, "both")
    texts = [t.get_text() for t in diagram.figure.legends[0].texts]
    assert any(text == "force on an end: this wide at 0.2 $Mc^2/L$" for text in texts)
    assert "a force starts (on) or ends (off)" in texts
    assert not any(text in ("impact", "contact: particle rides with end") or "particle" in text for text in texts)
    assert "light front (a jump in λ)" not in texts  # smooth forces: no front
    note = next(t for t in diagram.figure.texts if t.get_gid() == "comparison-note").get_text()
    assert ("Both rods are driven by the same forces at their ends: on each end a sine² "
            "push peaking at 0.2 M c²/L from t′ = 0.5 L to 1.5 L in S′.") == " ".join(note.replace("\xa0", " ").split())
    assert all("\xa0" not in line[:1] + line[-1:] for line in note.split("\n"))  # no unit torn from its number


@pytest.mark.parametrize("name, v, style", [("sears_moving", 0.6, "default"), ("push", 0.95, "print")])
def test_no_label_touches_a_line_a_marker_or_another_label(name, v, style):
    """on and off beside their markers, clear of the bands' edges, the ends, the lines of simultaneity and each
    other; titles, ticks, legend and note clear of each other (the checks of every particle figure)."""
    import sys
    from pathlib import Path

    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from test_render import _collisions, _layout_problems

    figure = drawn(name, v, "both", style).figure
    assert not _collisions(figure, style) and not _layout_problems(figure, style)


def test_titles_say_the_driven_rods_final_velocity():
    """push: F = 0.25 for 4 L of S on a rod of mass M: the rigid rod's momentum is 0.25 x 4 = 1 M c, so sinh phi = 1
    and v = 1/sqrt(2) in S; in S' (moving at -0.6 relative to S) (0.7071 + 0.6)/(1 + 0.6 x 0.7071) = 0.9177."""
    diagram = drawn("push")
    titles = [p.axes.get_title().replace("\n", " ") for p in diagram.panels]
    assert "rod first at rest, finally at +0.7071" in titles[0]
    u = math.sqrt(0.5)
    assert f"rod first at +0.6, finally at +{(u + 0.6) / (1 + 0.6 * u):.4f}" in titles[1]


def test_the_same_figure_gives_the_same_bytes():
    h = runs("sears_moving")[0]
    one = render.figure_bytes(drawn("sears_moving").figure, "svg")  # render.draw(h, paper_frames(0.6)), kept
    two = render.figure_bytes(render.draw(h, paper_frames(0.6)).figure, "svg")  # drawn afresh
    assert one == two and b'id="a-force-left-press"' in one


# --- what plot still refuses for forces -------------------------------------------------------------------

@pytest.mark.parametrize("args, words", [
    (("push", "--rod", "causal", "--rod-now"), "--rod-now draws the rigid rod's own lines of simultaneity, and the "
                                              "causal rod has none"),
    (("push", "--rod", "causal", "--proper-time"), "--proper-time draws the rigid rod's clocks only for now"),
])
def test_what_plot_cannot_draw_for_forces_is_refused_in_one_sentence(args, words, tmp_path):
    message = error_of("plot", *args, "-o", tmp_path)
    assert words in message and message.count("\n") <= 1 and not list(tmp_path.iterdir())


# --- the animations' strips ----------------------------------------------------------------------------------

@pytest.mark.parametrize("t, expected", [(1.0, 0.2), (0.75, 0.1), (1.6, 0.0)])
def test_a_strip_carries_the_force_at_each_end_and_draws_it_as_an_arrow(t, expected):
    """Sears in S: F = 0.2 sin^2(pi (t - 0.5)) at both ends on [0.5, 1.5]: 0.2 at t = 1, 0.1 at t = 0.75, nothing
    at t = 1.6. The strip's arrows are as long as plot's bands (BAND_POINTS at 0.2), pressing into the rod."""
    from matplotlib.figure import Figure

    from rodparadox.physics.frames import rest_frame
    from rodparadox.physics.snapshot import strip_at
    from rodparadox.render.colour_scale import colour_scale
    from rodparadox.render.strip import draw_strip

    h = runs("sears")[0]
    strip = strip_at(h, rest_frame(), t, 0.0)
    assert dict(strip.forces) == pytest.approx({"left": expected, "right": expected}, abs=1e-12)
    figure = Figure(figsize=(4, 1), dpi=72)
    ax = figure.add_axes((0, 0, 1, 1))
    ax.set_xlim(-2, 2)  # 72 points per L
    drawn = draw_strip(ax, strip, "default", colour_scale(h, rest_frame()), rest_frame(), force_scale=0.2)
    for arrow, end in zip(drawn.arrows, ("left", "right")):
        assert arrow.get_visible() == (expected > 0)
        if expected > 0:
            (x0, _), (x1, _) = arrow._posA_posB
            assert x1 == pytest.approx(-0.5 if end == "left" else 0.5, abs=1e-12)  # the head on the end
            assert (x1 - x0) * 72 == pytest.approx(BAND_POINTS * expected / 0.2 * (1 if end == "left" else -1))


def test_a_thin_driven_sheet_gets_the_inset_at_the_first_force_start():
    """As for particles, a panel whose world-sheet is drawn thinner than 3 mm gets a magnified inset, centred on the
    frame's first events: for Sears at v = 0.95, S' only, at the left force's start, x' = -t' = gamma (-0.5 + 0.95 x
    0.5) (the event x = -L/2, t = L/2 of S), with its marker and S's and S''s lines through it."""
    diagram = drawn("sears", 0.95)
    insets = {p.letter: [c for c in p.axes.child_axes if c.get_gid() == f"{p.letter}-inset"] for p in diagram.panels}
    assert not insets["a"] and len(insets["b"]) == 1
    inset = insets["b"][0]
    g = 1 / math.sqrt(1 - 0.95 ** 2)
    x, t = g * (-0.5 + 0.95 * 0.5), g * (0.5 - 0.95 * 0.5)
    (x0, x1), (t0, t1) = inset.get_xlim(), inset.get_ylim()
    assert x0 < x < x1 and t0 < t < t1
    marker = next(line for line in inset.lines if line.get_gid() == "b-inset-impact-left-start")
    assert marker.get_xdata()[0] == pytest.approx(x, abs=1e-12) and marker.get_ydata()[0] == pytest.approx(t, abs=1e-12)
    assert {"b-inset-simultaneity-rest-left-start", "b-inset-simultaneity-moving-left-start"} <= {
        line.get_gid() for line in inset.lines}
    assert next(t for t in inset.texts if t.get_gid() == "b-inset-note").get_text().startswith("$\\times")


def test_an_inset_draws_no_line_of_simultaneity_where_its_panel_draws_none():
    """A worksheet's diagram leaves the lines of simultaneity out (a question asks them): its inset must too (the
    inset drew them whatever the panel drew)."""
    from rodparadox.render.layers import Options

    rigid, _ = runs("sears", 0.95)
    diagram = render.draw(rigid, paper_frames(0.95), "default", Options(simultaneity=False))
    [inset] = [c for p in diagram.panels for c in p.axes.child_axes if c.get_gid() == f"{p.letter}-inset"]
    gids = {line.get_gid() for line in inset.lines}
    assert "b-inset-impact-left-start" in gids and not [g for g in gids if "simultaneity" in g]


# --- the rod's own view ----------------------------------------------------------------------------------------

@pytest.mark.parametrize("rod", ["rigid", "causal"])
def test_the_rods_own_view_draws_the_push_as_a_band_beside_its_end_from_on_to_off(rod):
    """push: F = 0.25 (the legend's force: the band 0.3 L wide) on the left end; on and off on the end (X = 0) at the
    chart times of its start and end. The rigid rod's T is its left end's proper time (T = t of S before the push):
    on at 0.5, off at 0.5 + asinh(F t / M)/(F/M) = 0.5 + 4 asinh(1) (hyperbolic motion for 4 L of S's time)."""
    from matplotlib.figure import Figure

    h = runs("push")[0 if rod == "rigid" else 1]
    ax = Figure().add_subplot()
    drawn = render.draw_rod_panel(ax, h, "default", letter="r")
    gids = {a.get_gid(): a for a in drawn.forces}
    band = gids["r-force-left-press"].get_xy()
    assert band[:, 0].min() == pytest.approx(-0.3, abs=1e-12) and band[:, 0].max() == pytest.approx(0.0, abs=1e-12)
    on, off = (gids[f"r-force-event-left-{m}"].get_xydata()[0] for m in ("start", "end"))
    assert on[0] == pytest.approx(0.0, abs=1e-12) and off[0] == pytest.approx(0.0, abs=1e-12)
    assert on[1] == pytest.approx(0.5, abs=1e-12) and band[:, 1].min() == pytest.approx(on[1], abs=1e-12)
    assert band[:, 1].max() == pytest.approx(off[1], abs=1e-12)
    if rod == "rigid":
        assert off[1] == pytest.approx(0.5 + 4 * math.asinh(1.0), abs=1e-12)
    words = [t.get_text() for t in drawn.key[0].get_texts()]
    assert "a force starts (on)\nor ends (off)" in words and not any("contact" in w for w in words)


def test_a_weak_forces_tiny_motion_gets_an_inset_against_the_unforced_world_line(tmp_path):
    """Sears's pulses timed in S' at a tenth of the preset's peak move the ends by less than half a millimetre on
    the page: the panel of S' gets an inset magnifying where an end strays most, with each end's world-line without
    the forces dashed (the rest at x = -L/2 and L/2 of S, boosted: x' = gamma (x + v t)). At the preset's own peak
    the motion is seen without one. Issue 24 (sears_moving at 0.95 in S: the inset hid the rod's right end, its note
    "×10; dashed: no force" shrunk below the ticks' type): the panel is widened for it, so it hides no world-line,
    its note is its factor in the ticks' type, and the legend names the dashed lines."""
    from rodparadox.io.scenario import load as load_file

    path = tmp_path / "weak.yaml"
    path.write_text("v: 0.6\nforces:\n  left: {shape: sine2, peak: 0.02, start: 0.5, duration: 1, frame: moving}\n"
                    "  right: {shape: sine2, peak: 0.02, start: 0.5, duration: 1, frame: moving}\n")
    weak = run_rods(load_file(str(path)), "rigid")[0]
    diagram = render.draw(weak, paper_frames(0.6)[1:])  # S' alone: its unforced lines the boosted rest
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    renderer = FigureCanvasAgg(diagram.figure).get_renderer()
    for p in diagram.panels:
        inset = next(c for c in p.axes.child_axes if c.get_gid() == f"{p.letter}-inset")
        free = {line.get_gid(): line.get_xydata() for line in inset.lines if "-inset-free-" in line.get_gid()}
        assert free, p.letter
        for gid, xy in free.items():  # on the unforced world-line: x' = gamma (x + v t), t' = gamma (t + v x)
            x = -0.5 if gid.endswith("left") else 0.5
            f = p.frame.rapidity
            assert np.allclose(np.cosh(f) * xy[:, 0] + np.sinh(f) * xy[:, 1], x, atol=1e-12)
        note = next(t for t in inset.texts if t.get_gid() == f"{p.letter}-inset-note")
        assert note.get_text().startswith("$\\times") and note.get_fontsize() >= p.axes.xaxis.get_ticklabels()[0].get_fontsize()
        box = inset.get_window_extent(renderer).padded(2.0)
        for line in p.axes.lines:  # the panel's world-lines, all of them outside it
            if line.get_gid() in (f"{p.letter}-{name}" for name in ("rod_left", "rod_right", "A", "B")):
                path = line.get_transform().transform_path(line.get_path())
                assert not path.intersects_bbox(box, filled=True), line.get_gid()
    legend = next(a for a in diagram.figure.findobj() if getattr(a, "get_gid", lambda: None)() == "legend")
    assert "magnified inset: each end without the forces" in [t.get_text() for t in legend.get_texts()]
    assert not any(c.get_gid().endswith("-inset") for p in drawn("sears_moving").panels for c in p.axes.child_axes)


def test_the_small_motions_inset_of_a_rod_at_rest_hides_no_world_line_and_its_note_reads():
    """Issue 24: `handout sears_moving --v 0.95 --rod both`, page 2: in S the rod at rest is as wide as its narrow
    panel, and the weak-force inset (x10, the unforced world-lines dashed) hid the rod's right end above t = 1.2, its
    note "x10; dashed: no force" shrunk below the ticks' type. Drawn at the handout's size (6.3 x 7.6 in): each
    panel of S is widened on the left (its box no longer symmetric about the rod at rest), its inset hides none of
    the panel's world-lines, its note is its factor in the ticks' type, and the legend names the dashed lines."""
    from matplotlib.figure import Figure
    from matplotlib.transforms import TransformedBbox

    rigid, causal = runs("sears_moving", 0.95)
    figure = Figure(figsize=(6.3, 7.6), dpi=72)
    diagram = render.draw_into(figure, (rigid, causal), paper_frames(0.95), "print")
    for p in diagram.panels:
        if p.frame.name != "rest":
            continue
        x0, x1 = p.axes.get_xlim()
        assert -x0 > x1 + 0.5, (p.letter, x0, x1)  # room on the left, beyond the symmetric -x1
        inset = next(c for c in p.axes.child_axes if c.get_gid() == f"{p.letter}-inset")
        # where its locator puts it (no renderer needed: the bounds are the panel's axes fractions)
        box = TransformedBbox(inset.get_axes_locator()(inset, None), figure.transSubfigure).frozen().padded(2.0)
        for line in p.axes.lines:
            if line.get_gid() in (f"{p.letter}-rod_left", f"{p.letter}-rod_right"):
                assert not line.get_transform().transform_path(line.get_path()).intersects_bbox(box, filled=True)
        note = next(t for t in inset.texts if t.get_gid() == f"{p.letter}-inset-note")
        assert note.get_text() == "$\\times10$"
        assert note.get_fontsize() >= p.axes.xaxis.get_ticklabels()[0].get_fontsize()
    assert "magnified inset: each end without the forces" in [t.get_text() for t in figure.legends[0].get_texts()]
