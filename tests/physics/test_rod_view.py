"""The rod's own view (`--frame rod`, README "The rod's own view"): its charts, checked against hand derivations and
independent computations (issue 16, item 6)."""

import functools
import math

import numpy as np
import pytest

from helpers import causal_history, history
from rodparadox.physics.kinematics import Event
from rodparadox.physics.causal.chart import CausalChart
from rodparadox.physics.rigid.chart import RigidChart
from rodparadox.physics.rod_view import chart_polyline

pytestmark = pytest.mark.xdist_group("causal")  # the causal histories, built once on the worker that has them

LN2 = math.log(2.0)  # the rapidity of v = 0.6


@pytest.fixture(scope="module")
def fig1_chart():
    return CausalChart(causal_history("fig1"))


def test_the_chart_of_a_rod_never_struck_is_s_with_the_left_end_at_zero():
    # no contact: both invariants vanish, a(u) = u - L/2, b(w) = w + L/2, so t = T and x = X - L/2 everywhere
    from types import SimpleNamespace

    from rodparadox.physics.causal.solve import Invariant, Solution

    L = 2.0
    chart = CausalChart(SimpleNamespace(solution=Solution(L, Invariant(), Invariant(), [], {}),
                                        scenario=SimpleNamespace(L=L)))
    for x, t in [(-1.0, 0.0), (0.3, 0.7), (5.0, -2.0), (-4.0, 3.5)]:
        assert chart.to_chart(Event(x, t)) == pytest.approx((t, x + 1.0), abs=1e-12)
    assert chart.proper_time(0.7, 0.0, 3.0) == pytest.approx(3.0, rel=1e-14)  # at rest: tau = T
    assert [T for _, T in chart.clock_ticks(0.7, 0.5, 0.0, 2.0)] == pytest.approx([0.0, 0.5, 1.0, 1.5, 2.0])


def test_causal_chart_before_any_contact_is_s_with_the_left_end_at_zero(fig1_chart):
    # fig1 at v = 0.6: the first contacts are at t = 5/6; events whose light rays meet the ends before then (inside
    # the rod: no front has reached them) are charted as they are in S
    for x, t in [(-0.5, 0.0), (0.1, 0.3), (0.5, -1.0), (-2.0, -1.5), (2.0, -1.5)]:
        T, X = fig1_chart.to_chart(Event(x, t))
        assert (T, X) == pytest.approx((t, x + 0.5), abs=1e-12)
        e = fig1_chart.to_event(t, x + 0.5)
        assert (e.x, e.t) == pytest.approx((x, t), abs=1e-12)


def test_every_light_ray_is_drawn_at_45_degrees(fig1_chart):
    # rays from the first contact (A1 at (-1/2, 5/6)) and from a point inside the ringing rod, both ways, inside
    # and outside the rod: along t - x = const the chart's T - X is constant, along t + x = const its T + X
    h = causal_history("fig1")
    for origin in (h.impacts[0].event, Event(0.1, 3.0), Event(0.6, 2.7)):
        for direction in (+1, -1):
            points = [fig1_chart.to_chart(Event(origin.x + direction * s, origin.t + s)) for s in np.linspace(0, 2, 9)]
            kept = [T - direction * X for T, X in points]
            assert max(kept) - min(kept) <= 1e-12 * (1 + max(abs(k) for k in kept))
            assert points[-1][0] - points[0][0] > 0.5  # the ray did move in the chart


def test_a_material_clock_ticks_its_proper_time_along_the_world_line(fig1_chart):
    # independent: d tau = sqrt(dt^2 - dx^2) summed along the history's world-line of X = 0.3, sampled in S
    X, step = 0.3, 0.5
    line = causal_history("fig1").material_worldline(X)
    ticks = fig1_chart.clock_ticks(X, step, 0.0, 4.0)
    assert [tau for tau, _ in ticks] == pytest.approx([k * step for k in range(len(ticks))], abs=1e-12)
    assert len(ticks) >= 6  # the clock runs slow while compressed: fewer than 9 ticks in 4 L of chart time
    end = fig1_chart.to_event(ticks[-1][1], X)
    points = line.sample(0.0, end.t, 1e-6)
    d = np.diff(points, axis=0)
    cumulative = np.concatenate(([0.0], np.cumsum(np.sqrt(d[:, 1] ** 2 - d[:, 0] ** 2))))
    for tau, T in ticks[1:]:
        t = fig1_chart.to_event(T, X).t
        assert np.interp(t, points[:, 1], cumulative) == pytest.approx(tau, abs=1e-6)
    # and the chart's clock agrees with d tau = dT / lam integrated across the fronts to rounding
    assert fig1_chart.proper_time(X, 0.0, ticks[-1][1]) == pytest.approx(ticks[-1][0], rel=1e-12)


def test_a_contact_rides_the_end_line_of_the_chart():
    h = causal_history("fig1")
    chart = CausalChart(h)
    A = h.worldline("A")
    contact, separation = [i.event for i in h.impacts if i.particle == "A"]
    for t in np.linspace(contact.t, separation.t, 5):
        assert chart.to_chart(A.event_at_time(t))[1] == pytest.approx(0.0, abs=1e-9)


def test_fig2_turns_last_L_times_their_change_of_rapidity():
    # fig2 at v = 0.6 in S: B1 at t = 5/6 turns the rod from 0 to -ln 2 about the right end, A1 from -ln 2 to ln 2,
    # B2 from ln 2 to 0; each turn follows the last with no rest between (A1 and B2 lie on the last line)
    chart = RigidChart(history("fig2"))
    expected = [(5 / 6, 5 / 6 + LN2, "right"), (5 / 6 + LN2, 5 / 6 + 3 * LN2, "left"),
                (5 / 6 + 3 * LN2, 5 / 6 + 4 * LN2, "right")]
    assert len(chart.turns) == 3
    for (T0, T1, end), (a, b, pivot_end) in zip(chart.turns, expected):
        assert (T0, T1, end) == (pytest.approx(a, abs=1e-12), pytest.approx(b, abs=1e-12), pivot_end)


@pytest.mark.parametrize("name", ["fig2", "off_timing"])
def test_a_turn_charts_the_fan_hyperbolae_as_vertical_lines_and_the_rod_as_0_to_L(name):
    h = history(name)
    chart = RigidChart(h)
    for turn, (T0, T1, _) in zip(h.turns, chart.turns):
        for sigma in (0.0, 0.25, 0.5, 1.0):
            d = turn.distance(sigma)
            for f in (0.1, 0.5, 0.9):
                phi = turn.rapidity_from + f * (turn.rapidity_stop - turn.rapidity_from)
                e = turn.pivot.displaced(turn.side * d, phi) if d > 0 else None
                if e is None:
                    continue
                T, X = chart.to_chart(e)
                assert X == pytest.approx(sigma, abs=1e-12)
                assert T == pytest.approx(T0 + f * (T1 - T0), abs=1e-12)
    # between and during turns the ends stay at X = 0 and X = L
    for end, X_end in (("rod_left", 0.0), ("rod_right", 1.0)):
        line = h.worldline(end)
        for t in np.linspace(0.0, 3.0, 31):
            point = chart.to_chart(line.event_at_time(t))
            assert point is not None and point[1] == pytest.approx(X_end, abs=1e-12)


def test_events_beyond_a_pivot_are_reported_not_placed():
    # fig2 in S: during the first turn (about B1 = (1/2, 5/6), rod on its left) the fan's lines run from t = 5/6 to
    # t - 5/6 = -0.6 (x - 1/2); right of B1 between them the rest frames before and after the turn both reach an
    # event: beyond the pivot's horizon
    chart = RigidChart(history("fig2"))
    beyond = Event(0.8, 5 / 6 - 0.05)
    assert chart.beyond_horizon(beyond) and chart.to_chart(beyond) is None
    T0, T1, _ = chart.turns[0]
    assert chart.to_event(0.5 * (T0 + T1), 1.3) is None  # past the pivot during the turn: no event there
    assert not chart.beyond_horizon(Event(-0.2, 0.9))  # inside the rod, mid-turn
    # a world-line through the pivot breaks there and goes on from the turn's end
    # (B arrives at 0.6 and rests after B1; the point after B1 lies in the second turn's chart, beyond the rod)
    drawn = chart_polyline(chart, np.array([[0.5 + 0.6 * 0.1, 5 / 6 - 0.1], [0.5, 5 / 6], [0.5, 5 / 6 + 0.1]]))
    assert np.isnan(drawn).any(axis=1).sum() == 1
    assert drawn[1] == pytest.approx([1.0, T0]) and drawn[3] == pytest.approx([1.0, T1])
    assert drawn[4][0] > 1.0


# --- drawn, and asked for on the command line ------------------------------------------------------------------

def test_the_rigid_panel_shows_the_rod_as_the_strip_and_hatches_only_where_turns_are(tmp_path, monkeypatch):
    from click.testing import CliRunner
    from matplotlib.figure import Figure

    from rodparadox.render.rod_panel import draw_rod_panel
    from sears_paradox_cli.main import main

    monkeypatch.chdir(tmp_path)
    drawn = {}
    for name in ("fig1", "fig2"):
        ax = Figure().add_subplot()
        drawn[name] = draw_rod_panel(ax, history(name, 0.6), "print")
        left, right = (line.get_xdata() for line in drawn[name].strip[-2:])
        assert list(left) == [0.0, 0.0] and list(right) == [1.0, 1.0]
    assert drawn["fig1"].horizon == () and len(drawn["fig2"].horizon) == 1
    assert len(drawn["fig2"].turns) == 6 and len(drawn["fig2"].pivots) == 6  # 3 turns: start and end; pivot, blanked end
    assert drawn["fig1"].fronts == drawn["fig1"].contacts == ()  # a rod without fronts draws none
    assert len(drawn["fig2"].light) == 3  # from each impact
    # fig1 never turns: its chart is S (left end at X = 0), so A1's light (X = 0, T = 5/6) runs X = T - 5/6
    ray = drawn["fig1"].light[0].get_xydata()
    ray = ray[np.isfinite(ray[:, 0])]
    assert ray[:, 1] - ray[:, 0] == pytest.approx(np.full(len(ray), 5 / 6), abs=1e-12)
    assert (ray[0, 0], ray[-1, 0]) == (pytest.approx(0.0, abs=1e-12), pytest.approx(1.0, abs=0.03))
    # (beside a frame's panels: the animation's test below; here the figure of its own, cheaper to draw)
    result = CliRunner().invoke(main, ["plot", "fig1", "--frame", "rod", "-o", "."])
    assert result.exit_code == 0, result.output
    svg = (tmp_path / "fig1_rod.svg").read_text()
    assert 'id="rod0-view"' in svg and 'id="a-axes"' not in svg


@pytest.mark.parametrize("args, message", [
    (["ledger", "fig1", "--frame", "rod"], "--frame rod (the rod's own view) is drawn by plot, animate and handout "
     "only; ledger reads slices of Lorentz frames: give rest, moving, both or a velocity U."),
    (["events", "fig1", "--frame-velocity", "rod"], "rod (the rod's own view) is drawn by plot, animate and handout "
     "only; these tables need a Lorentz frame: give a velocity U relative to S."),
    (["plot", "fig1", "--frame", "rod,sideways"], "a frame must be rest, moving, both, rod (the rod's own view) or"),
])
def test_what_cannot_show_the_rod_view_refuses_it_in_one_sentence(args, message, tmp_path, monkeypatch):
    from click.testing import CliRunner

    from sears_paradox_cli.main import main

    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(main, args)
    assert result.exit_code == 2 and message in " ".join(result.output.split())
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("command", [["plot", "--frame", "rest,rod"], ["animate", "--frame", "rod"],
                                     ["handout", "--frame", "both,rod"]])
def test_a_rod_view_too_thin_to_read_is_refused_in_one_sentence(command, tmp_path, monkeypatch):
    """Issue 27, item 9: with a particle 1e6 L from the rod the rod's own view was a sliver 1.3e6 L tall and 1 L
    wide, every label on the next. Its span of chart time (hand: B1 at t = 1/(2 v) - ... ~ 0, A's impact at its
    gap / v = 1e6 / 0.6 ~ 1.67e6 L later in S, the rod at rest between) is over MAX_VIEW_SPAN: refused, no file."""
    from click.testing import CliRunner

    from sears_paradox_cli.main import main

    monkeypatch.chdir(tmp_path)
    (tmp_path / "far.yaml").write_text("name: far\nv: 0.6\nparticles:\n  A: {gap: 1.0e6}\n  B: {gap: 0.5}\n")
    result = CliRunner().invoke(main, [command[0], "far.yaml", *command[1:]])
    said = " ".join(result.output.split())
    assert result.exit_code == 2 and "the rod's own view would be 1.3\N{MULTIPLICATION SIGN}10\N{SUPERSCRIPT SIX} L" in said
    assert "too thin to read" in said and len(result.output.strip().splitlines()) == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["far.yaml"]


def test_a_handout_shows_the_rod_view_after_the_diagram_with_its_turns_in_the_caption():
    from rodparadox.handout.document import DiagramBlock, Handout, Paragraph, RodViewBlock, Section
    from rodparadox.handout.own_view import with_rod_views
    from rodparadox.physics.frames import paper_frames

    h = history("fig2", 0.6)
    section = Section("fig2", "Fig. 2", (Paragraph("set-up"), DiagramBlock("diagram", h, paper_frames(0.6), "c"),
                                         Paragraph("explanation")))
    out = with_rod_views(Handout("t", (section,)), {"fig2": (h,)})
    blocks = out.sections[0].blocks
    assert [type(b).__name__ for b in blocks] == ["Paragraph", "DiagramBlock", "RodViewBlock", "Paragraph"]
    assert isinstance(blocks[2], RodViewBlock) and blocks[2].histories == (h,)
    # fig2 at v = 0.6: the turns about B1, A1, B2 last L ln 2, 2 L ln 2, L ln 2 (hand: atanh 0.6 = ln 2)
    assert "about B\N{SUBSCRIPT ONE}, 0.6931 L long, about A\N{SUBSCRIPT ONE}, 1.386 L long, about " \
           "B\N{SUBSCRIPT TWO}, 0.6931 L long" in blocks[2].caption
    assert with_rod_views(Handout("t", (section,)), {}).sections[0].blocks == section.blocks
    # a worksheet's goes to its answer key, before the section's explanation: the rod's own lines of simultaneity
    # tell which impacts it takes together, which the questions ask
    from rodparadox.handout.document import Heading
    key = (Heading("Answer key"), Heading("Questions and answers", 2), Paragraph("explanation"))
    worksheet = with_rod_views(Handout("t", (Section("introduction", "i", ()), section), True, key), {"fig2": (h,)})
    assert worksheet.sections[1].blocks == section.blocks
    assert [type(b).__name__ for b in worksheet.answer_key] == ["Heading", "Heading", "RodViewBlock", "Heading",
                                                                "Paragraph"]
    assert worksheet.answer_key[1].text == "The rod\u2019s own view"


def test_the_rod_view_in_an_animation_sweeps_its_own_now_from_bottom_to_top():
    from rodparadox.animate.now_scene import NowScene
    from rodparadox.animate.timeline import timeline
    from rodparadox.physics.frames import parse_frames
    from rodparadox.render.styles import STYLES
    from rodparadox.render.diagram import style_context

    h = history("fig1", 0.6)
    frames = parse_frames("rest", 0.6)
    with style_context("default"):
        scene = NowScene(h, timeline(h, frames, "now", 3), "default", rod_view="first")
    [now] = scene.rod_now
    T0, T1 = now.axes.get_ylim()
    heights = []
    for k in range(3):
        assert now in scene.update(k)
        heights.append(now.get_ydata()[0])
    assert heights == pytest.approx([T0, (T0 + T1) / 2, T1])
    assert now.get_color() == STYLES["default"].flash_colour
    # the rod's panel on the left: its axes start left of the frame's panel
    view = now.axes.get_position().x0
    assert view < min(ax.get_position().x0 for ax in scene.figure.axes if ax.get_gid() == "a-axes")


@functools.cache
def _rasterised(name: str, v: float, style: str):
    """The rigid rod's own view of a preset alone in a small figure, drawn by Agg: (axes, artists, grey levels).
    Drawn once per process (fig2 at 0.6 in the default style serves the pivot's test and the names' test); the
    tests only read it, and the grey levels are read-only."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    from rodparadox.render.rod_panel import draw_rod_panel

    figure = Figure(figsize=(4, 6), dpi=100)
    ax = figure.add_subplot()
    drawn = draw_rod_panel(ax, history(name, v), style)
    canvas = FigureCanvasAgg(figure)
    canvas.draw()
    grey = np.asarray(canvas.buffer_rgba())[:, :, :3].astype(float).mean(axis=2)  # grey level 0..255
    grey.flags.writeable = False
    return ax, drawn, grey


def test_a_pivot_is_drawn_dotted_on_the_end_as_its_key_says_in_every_style():
    # review: in print the black dots lay on the black end, so the pivot was drawn solid while the key said dotted.
    # Rasterised: along the pivot's stretch of the end, ink alternates with paper; below the turn the end is solid.
    from rodparadox.physics.rod_view import chart_of

    h = history("fig2", 0.6)
    [(T_a, T_b, end), *_] = chart_of(h).turns  # the turn about B1, on the right end (X = 1)
    T_a, T_b, X = T_a / h.scenario.L, T_b / h.scenario.L, 1.0 if end == "right" else 0.0
    for style in ("default", "print", "slides"):
        ax, drawn, pixels = _rasterised("fig2", 0.6, style)

        def column(T_lo, T_hi):
            (x, y0), (_, y1) = ax.transData.transform([(X, T_lo), (X, T_hi)])
            rows = np.arange(round(min(y0, y1)), round(max(y0, y1)))
            return pixels[pixels.shape[0] - 1 - rows, round(x)]

        pivot = column(T_a + 0.2 * (T_b - T_a), T_a + 0.8 * (T_b - T_a))
        assert (pivot > 230).mean() > 0.2 and (pivot < 120).mean() > 0.2, style  # dots: paper between ink
        solid = column(T_a - 0.4, T_a - 0.2)  # the end before the turn, clear of clock ticks or not: no paper
        assert (solid > 230).mean() == 0.0, style
        key = {text.get_text().split(":")[0]: handle for text, handle in
               zip(drawn.key[0].get_texts(), drawn.key[0].legend_handles)}["pivot"]
        line = next(a for a in drawn.pivots if a.get_gid() == "r-pivot-0")
        assert (key.get_linestyle(), key.get_linewidth(), key.get_color()) == \
               (line.get_linestyle(), line.get_linewidth(), line.get_color())


@pytest.mark.parametrize("extra", [["--light-cones"], ["--rod-now"], ["--equal-scales"], ["--rod-lines", "3"],
                                   ["--grid"], ["--hyperbolae"], ["--other-axes"], ["--proper-time"]])
def test_an_extra_with_only_the_rod_view_to_draw_on_is_refused_in_one_sentence(extra, tmp_path, monkeypatch):
    # review: each gave exit 0 and a new file name with the same bytes as without it (the rod view ignores them)
    from click.testing import CliRunner

    from sears_paradox_cli.main import main

    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(main, ["plot", "fig2", "--frame", "rod", *extra])
    said = " ".join(result.output.split())
    assert result.exit_code == 2 and said.count(". ") == 0 and "Traceback" not in said, result.output
    assert f"option {extra[0]} draws on the frames' panels" in said and "(--frame rest,rod)" in said
    assert list(tmp_path.iterdir()) == []


def test_the_library_refuses_extras_only_when_every_panel_is_the_rod_view():
    from rodparadox.errors import OptionError
    from rodparadox.physics.frames import parse_frames
    from rodparadox.physics.rod_view import refuse_frame_extras, ROD_VIEW

    with pytest.raises(OptionError) as refused:
        refuse_frame_extras((ROD_VIEW,), grid=False, rod_lines=4, hyperbolae=True)
    assert (refused.value.what, refused.value.value) == ("hyperbolae", True)  # the first in the options' order
    assert "--" not in str(refused.value)  # facts, no option's wording
    refuse_frame_extras((ROD_VIEW,), grid=False, rod_lines=0)  # none asked
    refuse_frame_extras((*parse_frames("rest", 0.6), ROD_VIEW), grid=True, rod_lines=3)  # a frame to draw on


@pytest.mark.parametrize("v", [0.6, 0.95])
def test_the_particles_names_sit_clear_of_every_line_of_the_rod_view(v):
    # review: "A" and "B" sat on their own dashed world-lines. The drawn text's box (Agg's own extent) is met by
    # no point of any line of the panel, each line sampled every half pixel, nor by an impact's marker
    ax, drawn, _ = _rasterised("fig2", v, "default")
    renderer = ax.get_figure(root=True).canvas.get_renderer()
    names = [a for a in drawn.particles if hasattr(a, "get_text")]
    assert sorted(a.get_text() for a in names) == ["A", "B"]
    for text in names:
        box = text.get_window_extent(renderer)
        assert ax.bbox.contains(box.x0, box.y0) and ax.bbox.contains(box.x1, box.y1)  # inside the panel
        for line in ax.lines:
            points = ax.transData.transform(line.get_xydata())
            if len(points) == 1:  # an impact: its marker's disc (markersize is its diameter in points)
                r = line.get_markersize() / 2 * 100 / 72
                (x, y), = points
                assert x + r <= box.x0 or x - r >= box.x1 or y + r <= box.y0 or y - r >= box.y1, line.get_gid()
            for p, q in zip(points[:-1], points[1:]):
                if not (np.isfinite(p).all() and np.isfinite(q).all()):
                    continue
                samples = p + np.linspace(0, 1, int(np.hypot(*(q - p)) * 2) + 2)[:, None] * (q - p)
                inside = ((samples[:, 0] > box.x0) & (samples[:, 0] < box.x1) & (samples[:, 1] > box.y0)
                          & (samples[:, 1] < box.y1))
                assert not inside.any(), (text.get_text(), line.get_gid())
