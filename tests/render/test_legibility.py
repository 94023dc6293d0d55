"""Legible at every speed (issue 14, item 4): colour bars whose tick labels never overlap and whose colours are
even in rapidity, a print ramp that starts light, a uniform bar drawn without seams, subscripted readouts."""

import math

import numpy as np
import pytest
from matplotlib.figure import Figure

from rodparadox.physics.rigid import run
from rodparadox.physics.frames import Frame
from rodparadox.physics.snapshot import Strip, strip_at
from rodparadox.io.scenario import load
from rodparadox.render.colour_scale import colour_scale
from rodparadox.render.strip import colour_bar_ticks, colour_map, colour_norm, draw_strip, readout_text
from rodparadox.render.text import approximate_size


def history(name="fig2", v=0.6):
    return run(load(name).with_overrides(v=v, L=None))


@pytest.mark.parametrize("v", [0.01, 0.3, 0.6, 0.9, 0.95, 0.97, 0.99, 0.9999999])  # issue 15.14: 0.9999999
@pytest.mark.parametrize("name", ["fig2", "while_turning", "unequal_masses"])
def test_colour_bar_tick_labels_never_overlap(name, v):
    h = history(name, v)
    for frame in (Frame("rest", 0.0), Frame("moving", -v)):
        scale = colour_scale(h, frame)
        for width, size in ((150.0, 8.0), (90.0, 7.0)):
            ticks, labels = colour_bar_ticks(scale, width, size)
            assert len(ticks) >= 1 and len(set(labels)) == len(labels)
            lo, hi = (math.atanh(u) for u in scale.ends)
            # the bar is even in rapidity: a tick sits at (atanh u - atanh lo) / (atanh hi - atanh lo) of its width
            spans = [((math.atanh(u) - lo) / (hi - lo) * width - approximate_size(t, size)[0] / 2,
                      (math.atanh(u) - lo) / (hi - lo) * width + approximate_size(t, size)[0] / 2)
                     for u, t in zip(ticks, labels)]
            assert all(a[1] < b[0] for a, b in zip(spans, spans[1:]))


def test_at_097_the_velocities_after_the_impacts_spread_over_the_scale():
    """fig2, v = 0.97, S′: the rod goes +v -> 0 -> 2v/(1+v²) = 0.99955 -> +v. In velocity the last three sit in the
    scale's top 3 %; in rapidity 0.97 is at the middle (atanh 0.97 of 2 atanh 0.97)."""
    v = 0.97
    h = history("fig2", v)
    scale = colour_scale(h, Frame("moving", -v))
    norm = colour_norm(scale, "default")
    assert float(norm(v)) == pytest.approx(0.5, abs=1e-9)
    assert float(norm(0.0)) == pytest.approx(0.0, abs=1e-9)
    assert float(norm(2 * v / (1 + v * v))) == pytest.approx(1.0, abs=1e-9)
    ticks, labels = colour_bar_ticks(scale, 150.0, 8.0)
    assert labels == ["0", "0.97", "0.9995"]


def test_the_print_ramp_is_light_at_the_velocity_before_the_impacts():
    """unequal_masses at 0.37: the rod, at rest in S, only ever moves forward; in print 0 is the ramp's light end."""
    h = history("unequal_masses", 0.37)
    scale = colour_scale(h, Frame("rest", 0.0))
    assert scale.ends[0] == 0.0
    assert float(colour_norm(scale, "print")(0.0)) == 0.0
    lightest = colour_map("print")(0.0)
    assert min(lightest[:3]) > 0.85  # pale grey, not mid-grey


def test_a_rod_at_rest_is_one_segment_without_seams():
    h = history("while_turning", 0.6)
    frame = Frame("rest", 0.0)
    figure = Figure(figsize=(5, 1), dpi=72)
    ax = figure.add_axes((0.1, 0.3, 0.8, 0.4))
    ax.set_xlim(-1, 1)
    artists = draw_strip(ax, strip_at(h, frame, 0.0, 0.0), "print", colour_scale(h, frame), frame)
    segments = artists.bar.get_segments()
    assert len(segments) == 1
    assert segments[0][0][0] == pytest.approx(-0.5) and segments[0][-1][0] == pytest.approx(0.5)


def test_readouts_write_impacts_with_subscripts():
    strip = Strip(t=1.0, sigma=np.array([0.0, 1.0]), x=np.array([0.0, 1.0]), velocity=np.zeros(2), particles=(),
                  flashing=("A1", "B12"))
    # mathtext subscripts: the readout holds the math-italic clock, and mathtext's fonts lack A₁'s subscript digits
    assert readout_text(strip, Frame("rest", 0.0), 1.0) == "$t$ = 1 $L$ in S   $A_{1}$, $B_{12}$!"


@pytest.mark.parametrize("v", [0.6, 0.97])
def test_a_lens_shows_the_rod_at_least_a_third_of_its_width_at_every_instant(v):
    """fig2 at 0.97 in S′: the rod is 0.24 L long before the impacts, L/γ(0.9995) = 0.03 L between them."""
    from rodparadox import render
    from rodparadox.animate.now_scene import NowScene
    from rodparadox.animate.timeline import timeline
    from rodparadox.physics.frames import paper_frames

    h = history("fig2", v)
    line = timeline(h, paper_frames(v), "now", 13)
    with render.style_context("default"):
        scene = NowScene(h, line, "default")
    lenses = [m for m in scene.panels if m.lens is not None]
    assert lenses
    for k in range(13):
        scene.update(k)
        for motion in lenses:
            ax = motion.lens.bar.axes
            segments = motion.lens.bar.get_segments()
            length = segments[-1][-1][0] - segments[0][0][0]
            width = ax.get_xlim()[1] - ax.get_xlim()[0]
            assert 1 / 3 <= length / width <= 1.0


def test_two_particles_closer_than_a_letter_have_their_letters_apart():
    """Issue 15.14: at v = 0.9999999 seen from u = 0.9999999, A and B end 2 L apart on an axis 10⁷ L wide and
    their letters overprinted. Each letter now sits on its own side of its dot: the two boxes do not overlap,
    A's (the left particle's) ends left of B's start, and a letter of particles far apart stays centred."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from rodparadox import render

    history = run(load("fig2").with_overrides(v=0.9999999))
    frame = Frame("u=0.9999999", 0.9999999)
    times = [-1.0, 1e7]
    for style in ("print", "default"):
        figure = Figure(figsize=(6.0, 4.0), dpi=72)
        with render.style_context(style):
            rows = render.draw_strips_into(figure, history, frame, times, style)
            renderer = FigureCanvasAgg(figure).get_renderer()
            # the rod drifts 10⁷ L: each row follows it (`render.strip_windows`); a particle beyond a row's edge is
            # an arrowhead there with its letter, its own letter hidden
            far, near = ({t.get_text(): t for t in row.texts if "-particle-" in str(t.get_gid()) and t.get_visible()}
                         for row in rows)
            a, b = (near[n].get_window_extent(renderer) for n in "AB")
            assert a.x1 <= b.x0 and not a.overlaps(b), style
            assert far["B"].get_horizontalalignment() == "center" and "A" not in far
            assert [t.get_text() for t in rows[0].texts if "-beyond-" in str(t.get_gid())] == ["A"]


def test_a_note_never_breaks_between_a_number_and_its_unit():
    """Found looking at every page: a comparison's note under a figure broke 'B₁ at 3.207 / L)'."""
    from rodparadox.render.text import approximate_size, note_lines

    note = ("The rigid rod: A₁ and B₁ are not simultaneous in S (A₁ at 0.7763 L, B₁ at 0.5263 L) or S′ (A₁ at "
            "0.8713 L, B₁ at 3.207 L), the particles carrying 0.5 M c² of kinetic energy at 0.95 c.")
    for width in range(80, 400, 7):
        lines = note_lines(note, width, 9.0)
        assert " ".join(lines) == note  # nothing lost or added
        assert not any(line.split(" ")[0] in ("L", "L)", "L),", "L,", "c", "c.", "c²", "M") for line in lines[1:])
        assert all(approximate_size(line, 9.0)[0] <= width / 1.08 for line in lines if " " in line)
