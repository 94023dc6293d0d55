"""`render.draw_into`: the diagram drawn into a Figure or SubFigure the caller sized, its panels and its artists by
layer handed back, so a caller (an animation) can update them instead of drawing again."""

from __future__ import annotations

import re

import numpy as np
import pytest
from matplotlib.figure import Figure

import drawn as shared
from rodparadox import render
from rodparadox.physics.rigid import run
from rodparadox.physics.frames import paper_frames
from rodparadox.io.scenario import load

EXTRAS = render.Options(other_axes=True, light_cones=True, hyperbolae=True, grid=True, rod_lines=3, rod_now=True,
                        proper_time=True)


def fig2():
    return run(load("fig2"))


def lines_by_gid(fig) -> dict[str, np.ndarray]:
    return {line.get_gid(): np.asarray(line.get_xydata()) for ax in fig.axes for line in ax.get_lines()}


def subfigure_diagram(options=render.Options(), style="default"):
    """The diagram in the right half of a figure twice as wide as a slide."""
    figure = Figure(figsize=(26.0, 8.0), dpi=72)
    left, right = figure.subfigures(1, 2)
    return figure, render.draw_into(right, fig2(), paper_frames(0.6), style, options)


@pytest.mark.parametrize("style", ["default", "slides"])
def test_a_subfigure_holds_the_same_world_lines_as_draw(style):
    figure, diagram = subfigure_diagram(style=style)
    alone = lines_by_gid(shared.diagram("fig2", 0.6, style).figure)  # render.draw's, drawn once per process
    assert [p.letter for p in diagram.panels] == ["a", "b"]
    assert [p.frame.name for p in diagram.panels] == ["rest", "moving"]
    for p in diagram.panels:
        assert p.axes.get_figure(root=False) is diagram.figure and p.axes.get_figure(root=True) is figure
        assert p.box[0] <= p.data_box[0] and p.box[1] >= p.data_box[1]
        assert p.axes.get_xlim() == pytest.approx(p.box[:2]) and p.axes.get_ylim() == pytest.approx(p.box[2:])
        for name in ("rod_left", "rod_right", "A", "B"):
            gid = f"{p.letter}-{name}"
            layer = "rod" if name.startswith("rod_") else f"particle-{name}"
            line = next(a for a in diagram.artists[layer][p.letter] if a.get_gid() == gid)
            np.testing.assert_array_equal(line.get_xydata(), alone[gid])
    # the panels sit inside the right half
    for p in diagram.panels:
        x0, _, w, _ = p.axes.get_position().bounds
        assert 0.0 <= x0 and x0 + w <= 1.0  # subfigure coordinates
        assert p.axes.get_window_extent().x0 >= figure.bbox.width / 2


def test_artists_by_layer_are_the_drawn_objects():
    _, diagram = subfigure_diagram(EXTRAS)
    expected = {"grid": None, "sheet": r"sheet", "rod-lines": r"rod-line-\d", "rod-now": r"rod-now-\d+",
                "clocks": r"clock-(rod_left|rod_right|A|B)", "rod": r"rod_(left|right)",
                "particle-A": r"(A|particle-label-A)", "particle-B": r"(B|particle-label-B)",
                "simultaneity-rest": r"simultaneity-rest-[AB0-9+]+", "simultaneity-moving": r"simultaneity-moving-[AB0-9+]+",
                "other-axes": r"axis-(label-)?(rest|moving)-[xt]", "light-cones": r"light-cone-[AB]\d-(left|right)",
                "hyperbolae": r"hyperbola-\d+", "impacts": r"impact-(label-|leader-)?[AB]\d"}
    # every layer that applies to the rigid rod (the causal rod's own layers do not)
    assert list(diagram.artists) == [layer.name for layer in render.LAYERS if layer.applies(fig2())]
    for name, pattern in expected.items():
        for letter, artists in diagram.artists[name].items():
            axes = next(p.axes for p in diagram.panels if p.letter == letter)
            assert artists, (name, letter)
            for a in artists:
                if pattern is not None:  # grid lines belong to the ticks, not to the axes
                    assert a.axes is axes
                    assert re.fullmatch(f"{letter}-{pattern}", a.get_gid()), (name, a.get_gid())
    impacts = diagram.artists["impacts"]["a"]
    assert {a.get_gid() for a in impacts} >= {"a-impact-B1", "a-impact-A1", "a-impact-label-B1"}
    # every artist drawn in a panel belongs to exactly one layer
    for p in diagram.panels:
        by_layer = [a for layer in diagram.artists.values() for a in layer.get(p.letter, ())]
        assert len(by_layer) == len(set(map(id, by_layer)))
        drawn = [a for a in p.axes.get_lines() + p.axes.texts + p.axes.patches]
        assert {id(a) for a in drawn} <= {id(a) for a in by_layer}


def test_an_updated_artist_changes_the_saved_svg():
    figure, diagram = subfigure_diagram()
    before = render.figure_bytes(figure, "svg")
    (line,) = [a for a in diagram.artists["particle-A"]["a"] if a.get_gid() == "a-A"]
    x, t = line.get_data()
    line.set_data(np.asarray(x)[:2], np.asarray(t)[:2])
    after = render.figure_bytes(figure, "svg")
    assert before != after
    assert before.count(b'id="a-A"') == after.count(b'id="a-A"') == 1
    assert before == render.figure_bytes(subfigure_diagram()[0], "svg")  # drawn afresh: the first bytes again


def test_disabled_layers_are_absent_and_a_small_target_is_refused():
    _, diagram = subfigure_diagram()
    assert "grid" not in diagram.artists and "hyperbolae" not in diagram.artists and "impacts" in diagram.artists
    with pytest.raises(ValueError, match="the diagram needs at least"):
        render.draw_into(Figure(figsize=(1.5, 1.0)), fig2(), paper_frames(0.6))


def test_draw_into_a_figure_of_draws_size_lays_it_out_as_draw_does():
    fig = shared.diagram("fig2", 0.6).figure  # render.draw's, drawn once per process
    target = Figure(figsize=fig.get_size_inches(), dpi=72)
    diagram = render.draw_into(target, fig2(), paper_frames(0.6))
    # the same layout, up to the rounding of the size in inches (the bisection of the panels' height may differ)
    for p, ax in zip(diagram.panels, fig.axes):
        assert p.axes.get_position().bounds == pytest.approx(ax.get_position().bounds, abs=1e-6)
    assert [t.get_text() for t in target.texts] == [t.get_text() for t in fig.texts]
