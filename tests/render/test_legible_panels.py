"""Figures legible at every speed (issue 14 item 4, issue 15 item 14): legends told apart in grey, material lines
thinned to what a panel can hold, the magnified inset of a thin world-sheet, `--equal-scales`.

Every figure here is drawn once (cached) and checked several ways; the thresholds are recomputed from the drawn
world-lines and the axes' own transforms, never read back from the code under test.
"""

from __future__ import annotations

import itertools
import logging
import re

import numpy as np
import pytest
from matplotlib.legend_handler import HandlerTuple  # noqa: F401  (the rod's entry is a tuple of handles)
from matplotlib.lines import Line2D
from matplotlib.colors import to_rgb
from matplotlib.patches import Patch

import drawn as shared
from helpers import history
from rodparadox import render
from rodparadox.physics import rod
from rodparadox.physics.frames import paper_frames, view
from rodparadox.render.layers import legend_entries
from rodparadox.render.styles import STYLE_NAMES, STYLES

EVERYTHING = render.Options(other_axes=True, light_cones=True, hyperbolae=True, grid=False, rod_lines=3, rod_now=True,
                            proper_time=True)
MM = 72 / 25.4  # points per millimetre


def diagram(name: str, v: float, style: str = "default", options: render.Options = render.Options()):
    """The diagram of S and S', drawn once per process for every test of tests/render that draws it (`drawn`)."""
    return shared.diagram(name, v, style, options)


# --- legends in grey --------------------------------------------------------------------------------------

def _grey_look(handle) -> tuple:
    """What a legend handle shows without colour: its line's dash pattern and width, its marker, a shaded patch."""
    parts = handle if isinstance(handle, tuple) else (handle,)
    lines = [p for p in parts if isinstance(p, Line2D)]
    patch = any(isinstance(p, Patch) for p in parts)
    line = lines[0]
    pattern = line._unscaled_dash_pattern[1]  # the style's dashes in units of the width (no public getter)
    marker = line.get_marker() if line.get_marker() not in (None, "None", "none", "") else None
    if marker:  # a filled dot and a hollow ring differ in grey: the face's lightness says which
        marker = (marker, round(float(np.dot(to_rgb(line.get_markerfacecolor()), (0.299, 0.587, 0.114))), 1))
    width = line.get_linewidth() if line.get_linestyle() not in ("None", "none", "") else 0.0
    return tuple(pattern) if pattern else None, width, marker, patch


def _told_apart(one: tuple, other: tuple) -> bool:
    """In grey: another dash pattern, another marker, a shaded patch, or a width at least 1.5 times the other's."""
    (d1, w1, m1, p1), (d2, w2, m2, p2) = one, other
    if d1 != d2 or m1 != m2 or p1 != p2:
        return True
    return min(w1, w2) > 0 and max(w1, w2) / min(w1, w2) >= 1.5


@pytest.mark.parametrize("style", STYLE_NAMES)
def test_every_legend_entry_differs_from_every_other_without_colour(style):
    """Issue 14.4: in grey the default legend's particles A and B were one dashed line; the hyperbolae and the
    material lines two thin solid ones. Every pair of entries must differ in dashes, width, marker or patch."""
    h = history("fig2", 0.6)
    handles, texts = legend_entries(STYLES[style], h, EVERYTHING, 1.0)
    assert len(texts) == 12  # every layer's entry is there
    looks = {text: _grey_look(handle) for handle, text in zip(handles, texts)}
    same = [(a, b) for (a, la), (b, lb) in itertools.combinations(looks.items(), 2) if not _told_apart(la, lb)]
    assert same == []
    # the pairs the issue named, by name
    assert looks["particle A"][0] != looks["particle B"][0]
    assert looks["material points inside the rod"][0] != looks["the rod’s own lines of simultaneity"][0]


def test_the_grey_test_sees_a_planted_twin():
    """The check above has power: two entries that differ only in colour are caught."""
    a = Line2D([], [], color="#D55E00", linewidth=1.3, linestyle=(0, (5.0, 2.5)))
    b = Line2D([], [], color="#009E73", linewidth=1.3, linestyle=(0, (5.0, 2.5)))
    assert not _told_apart(_grey_look(a), _grey_look(b))
    assert _told_apart(_grey_look(a), _grey_look(Line2D([], [], linewidth=1.3, linestyle=(0, (8.0, 2.0, 3.0, 2.0)))))


# --- measuring what is drawn, independently of render.legibility --------------------------------------------

def _dense(points: np.ndarray, step: float) -> np.ndarray:
    """The polyline (display points) resampled at most `step` apart: distances between two such sets are the
    polylines' own within `step`."""
    out = [points[:1]]
    for a, b in zip(points[:-1], points[1:]):
        n = max(1, int(np.ceil(np.hypot(*(b - a)) / step)))
        out.append(a + (b - a) * (np.arange(1, n + 1) / n)[:, None])
    return np.concatenate(out)


def _least_distance(a: np.ndarray, b: np.ndarray, step: float = 0.3) -> float:
    """Brute force: the least distance between two polylines given in display points, within step / 2.

    Every pair of the resampled points is a candidate, but only pairs less than an upper bound apart in y can be the
    closest: `bound` is the distance of an actual pair (each point of a to the point of b nearest it in y), and each
    point of a is compared with the points of b within `bound` of it in y. The closest pair is among those, so the
    least distance is the very float the whole product gives (which took 1.2 s of the suite)."""
    a, b = _dense(a, step), _dense(b, step)
    b = b[np.argsort(b[:, 1], kind="stable")]
    k = np.clip(np.searchsorted(b[:, 1], a[:, 1]), 0, len(b) - 1)
    bound = float(np.sqrt(((a - b[k]) ** 2).sum(1)).min())
    lo = np.searchsorted(b[:, 1], a[:, 1] - bound, side="left")
    hi = np.searchsorted(b[:, 1], a[:, 1] + bound, side="right")
    width = int((hi - lo).max())
    index = lo[:, None] + np.arange(max(width, 1))[None, :]
    inside = index < hi[:, None]
    near = b[np.minimum(index, len(b) - 1)]
    d2 = np.where(inside, ((a[:, None, :] - near) ** 2).sum(2), np.inf)
    return min(bound, float(np.sqrt(d2.min())))


def _on_page(ax, points: np.ndarray) -> np.ndarray:
    """Data (units of L) -> points on the page (the figures are drawn at 72 dpi: a display unit is a point)."""
    assert ax.get_figure(root=True).dpi == 72
    return ax.transData.transform(points)


def _sheet_width_on_page(h, frame, ax) -> float:
    """The world-sheet's least width on the page, from the history's own end world-lines, sampled finely."""
    L = h.scenario.L
    ends = view(h, frame).worldline_points(1e-6 * L)
    return _least_distance(_on_page(ax, ends["rod_left"] / L), _on_page(ax, ends["rod_right"] / L))


def _inset(ax):
    found = [child for child in ax.child_axes if (child.get_gid() or "").endswith("-inset")]
    assert len(found) <= 1
    return found[0] if found else None


# --- the inset -----------------------------------------------------------------------------------------------

THRESHOLD = 3.0 * MM  # the inset's rule, as the README states it: a world-sheet drawn thinner than 3 mm
INSET_CASES = (("while_turning", 0.97, "print"), ("fig2", 0.6, "default"), ("fig2", 0.9, "default"),
               ("fig2", 0.99, "print"), ("single", 0.95, "default"), ("off_timing", 0.85, "print"))


@pytest.mark.parametrize("name, v, style", INSET_CASES)
def test_an_inset_appears_exactly_where_the_sheet_is_thinner_than_3_mm_and_hides_no_label_or_impact(name, v, style):
    """Issue 14.4: `plot while_turning --v 0.97 --style print` drew panel (b) as one thick line. The inset is there
    exactly when the sheet, measured from the world-lines through the axes' transform, is under 3 mm; its
    magnification is the one its note states; it lies inside its panel and covers no label, leader or impact."""
    # laid out as Agg draws it (every extent as rendered), once per process with test_render's label checks
    d, renderer = shared.measured(name, v, style)
    h = history(name, v)
    insets = 0
    for info in d.panels:
        ax = info.axes
        width = _sheet_width_on_page(h, info.frame, ax)
        assert abs(width - THRESHOLD) > 0.3, "too near the threshold to tell"
        inset = _inset(ax)
        assert (inset is not None) == (width < THRESHOLD), (info.letter, width / MM)
        if inset is None:
            continue
        insets += 1
        # its magnification: points per L in the inset over points per L in the panel, both from the axes
        def per_L(axes):
            box = axes.get_window_extent(renderer)
            (x0, x1), (t0, t1) = axes.get_xlim(), axes.get_ylim()
            assert box.width / (x1 - x0) == pytest.approx(box.height / (t1 - t0), rel=1e-6)  # equal scales
            return box.width / (x1 - x0)
        [note] = [t for t in inset.texts if t.get_gid() == f"{info.letter}-inset-note"]
        stated = float(re.fullmatch(r"\$\\times([0-9.]+)\$( at .*)?", note.get_text())[1])
        assert per_L(inset) / per_L(ax) == pytest.approx(stated, rel=1e-6)
        assert stated > 1
        box = inset.get_window_extent(renderer)
        panel = ax.get_window_extent(renderer)
        assert panel.x0 <= box.x0 and box.x1 <= panel.x1 and panel.y0 <= box.y0 and box.y1 <= panel.y1
        assert note.get_window_extent(renderer).fully_overlaps(box) or box.contains(
            *note.get_window_extent(renderer).p0) and box.contains(*note.get_window_extent(renderer).p1)
        for text in ax.texts:
            assert not text.get_window_extent(renderer).overlaps(box), text.get_gid()
        for line in ax.lines:
            gid = line.get_gid() or ""
            if "-impact-" in gid or "-leader-" in gid:
                corners = line.get_transform().transform(np.column_stack([line.get_xdata(), line.get_ydata()]))
                r = render.styles.STYLES[style].impact_size / 2 if "-impact-" in gid else 0.0
                for x, y in corners:
                    assert not (box.x0 - r < x < box.x1 + r and box.y0 - r < y < box.y1 + r), gid
        # the inset's own sheet is wider than the panel's: it shows what the panel could not
        L = h.scenario.L
        ends = view(h, info.frame).worldline_points(1e-6 * L)
        inside = [e[(e[:, 0] / L > inset.get_xlim()[0]) & (e[:, 0] / L < inset.get_xlim()[1])
                    & (e[:, 1] / L > inset.get_ylim()[0]) & (e[:, 1] / L < inset.get_ylim()[1])] / L
                  for e in (ends["rod_left"], ends["rod_right"])]
        if all(len(e) > 1 for e in inside):
            assert _least_distance(*(inset.transData.transform(e) for e in inside)) > width
    assert insets == sum(1 for info in d.panels if _inset(info.axes) is not None)


def test_insets_can_be_turned_off_and_equal_scales_draw_one_length_of_L_alike_in_every_panel():
    h = history("while_turning", 0.97)
    d = render.draw(h, paper_frames(h.scenario.v), "default", render.Options(insets=False, equal_scales=True))
    assert all(_inset(info.axes) is None for info in d.panels)
    fig = d.figure
    scales = []
    for info in d.panels:
        box = info.axes.get_window_extent()
        (x0, x1), (t0, t1) = info.axes.get_xlim(), info.axes.get_ylim()
        scales += [box.width / (x1 - x0), box.height / (t1 - t0)]
    assert max(scales) == pytest.approx(min(scales), rel=1e-6)
    # without the option the fast panel (b) is drawn at a smaller scale than (a): the option changed something
    a, b = diagram("while_turning", 0.97).panels
    assert a.axes.get_window_extent().width / np.ptp(a.axes.get_xlim()) > 1.5 * (
        b.axes.get_window_extent().width / np.ptp(b.axes.get_xlim()))
    assert fig is not None


# --- material lines -------------------------------------------------------------------------------------------

def test_material_lines_are_thinned_to_1_mm_apart_and_the_legend_says_how_many():
    """Issue 14.4: `plot fig2 --v 0.81 --rod-lines 8 --rod-now --proper-time` drew panel (b) as a solid band. Every
    two neighbouring lines (the ends included) are at least 1 mm apart on the page; one line more would have put
    two closer; the legend names the panels drawn with fewer; the ends' clock ticks stay apart (no comb)."""
    asked = 8
    options = render.Options(rod_lines=asked, rod_now=True, proper_time=True)
    d = diagram("fig2", 0.81, "default", options)
    h = history("fig2", 0.81)
    L = h.scenario.L
    drawn = {}
    for info in d.panels:
        ax = info.axes
        lines = sorted(d.artists["rod-lines"][info.letter], key=lambda line: line.get_xdata()[0])
        drawn[info.letter] = len(lines)
        ends = [artist for artist in d.artists["rod"][info.letter]]
        chain = [ends[0], *lines, ends[1]]
        gaps = [_least_distance(*(_on_page(ax, np.column_stack([l.get_xdata(), l.get_ydata()]).astype(float))
                                  for l in pair)) for pair in zip(chain, chain[1:])]
        assert min(gaps) >= MM - 0.2, (info.letter, min(gaps) / MM)
        if len(lines) < asked:  # one more, evenly spaced as the option spaces them, would crowd
            fv = view(h, info.frame)
            more = rod.material_lines(h, info.frame.rapidity, len(lines) + 1, *fv.t_range, 1e-5 * L)
            chain = [np.column_stack([ends[0].get_xdata(), ends[0].get_ydata()]).astype(float),
                     *(p / L for _, p in more), np.column_stack([ends[1].get_xdata(), ends[1].get_ydata()]).astype(float)]
            assert min(_least_distance(_on_page(ax, a), _on_page(ax, b)) for a, b in zip(chain, chain[1:])) < MM + 0.2
        for name in ("rod_left", "rod_right"):  # clock ticks on the ends: each at least its diameter from the next
            [clock] = [a for a in d.artists["clocks"][info.letter] if a.get_gid() == f"{info.letter}-clock-{name}"]
            ticks = _on_page(ax, np.column_stack([clock.get_xdata(), clock.get_ydata()]).astype(float))
            if len(ticks) > 1:
                assert np.hypot(*np.diff(ticks, axis=0).T).min() >= render.styles.STYLES["default"].clock_size
    assert drawn["a"] > drawn["b"]  # (b)'s sheet is thinner on the page
    legend = [t.get_text() for t in d.figure.legends[0].get_texts()]
    [entry] = [t for t in legend if t.startswith("material points")]
    for letter, n in drawn.items():
        if n < asked:
            assert (f"{n} in ({letter})" if n else f"none in ({letter})") in entry
    assert entry.startswith(f"material points inside the rod ({asked}; ") and entry.endswith("to stay 1 mm apart)")


def test_material_lines_that_fit_are_all_drawn():
    d = diagram("fig2", 0.3, "default", render.Options(rod_lines=3))
    assert {info.letter: len(d.artists["rod-lines"][info.letter]) for info in d.panels} == {"a": 3, "b": 3}
    assert "material points inside the rod" in [t.get_text() for t in d.figure.legends[0].get_texts()]


# --- issue 15.14: no missing glyph anywhere at v = 0.9999999 ------------------------------------------------------

@pytest.mark.slow  # about 8 s: a handout and two animations
def test_plot_handout_and_animate_at_0_9999999_warn_of_nothing(tmp_path, caplog):
    """`handout` at v = 0.9999999 printed five "missing glyph" warnings. With warnings as errors, every command that
    draws writes its files and prints nothing on stderr (where matplotlib logs a missing glyph): plot in both
    families of fonts (insets with ×1×10⁶ included), the handout, both animations."""
    from click.testing import CliRunner

    from sears_paradox_cli.main import main

    # the print style's fonts (STIX) and the default's (DejaVu, as slides'); fig1 at 0.9999999 put ×1×10⁶ in an inset
    commands = [["plot", "fig1", "fig2", "while_turning", "--style", "print"], ["plot", "fig2", "unequal_masses"]]
    # a frame u's clock is mathtext ($t_u$): its strips read 5×10⁶ L there (a missing-glyph box, fixed)
    commands += [["handout", "fig1", "--frame", "both,0.9999999"], ["animate", "fig2", "--fps", "2", "--seconds", "1", "--format", "png"],
                 ["animate", "while_turning", "--mode", "boost", "--fps", "2", "--seconds", "1", "--format", "png",
                  "--style", "print"]]
    import warnings
    for k, command in enumerate(commands):
        out = tmp_path / str(k)
        out.mkdir()
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            result = CliRunner().invoke(main, [*command, "--v", "0.9999999", "-o", str(out)], catch_exceptions=True)
        assert result.exit_code == 0 and result.exception is None and result.stderr == "", (command, result.output)
        # matplotlib logs a missing glyph (to stderr in a shell; under pytest, to its log capture)
        assert [r.getMessage() for r in caplog.records if r.levelno >= logging.WARNING] == [], command
        assert any(out.iterdir())
    # the causal rod's PDF: fontTools warned twice of cmsy10.ttf's timestamps while subsetting it
    result = CliRunner().invoke(main, ["plot", "fig2", "--rod", "causal", "--format", "pdf", "-o", str(tmp_path / "c.pdf")])
    assert result.exit_code == 0 and result.stderr == ""
    assert [r.getMessage() for r in caplog.records if r.levelno >= logging.WARNING] == []


def test_plot_equal_scales_names_its_file_and_draws_one_scale(tmp_path):
    from click.testing import CliRunner

    from sears_paradox_cli.main import main

    result = CliRunner().invoke(main, ["plot", "while_turning", "--v", "0.97", "--equal-scales", "-o", str(tmp_path)])
    assert result.exit_code == 0, result.output
    assert result.output.strip() == str(tmp_path / "while_turning_v0.97_samescale.svg")
    # the option reaches the drawing (its one scale is checked on the Options above)
    svg = (tmp_path / "while_turning_v0.97_samescale.svg").read_text()
    assert 'id="a-axes"' in svg and 'id="b-axes"' in svg


def test_a_clock_in_mathtext_reads_its_powers_of_ten_in_mathtext():
    """`t_u = 5×10⁶ L`: mathtext's fonts lack the superscript digits, so a powers-of-ten reading is mathtext; the
    clock's t (t′, t_u) and L are math italics (issue 14.6), the number upright."""
    from rodparadox.physics.frames import Frame
    from rodparadox.render.strip import clock_reading

    rest, moving, other = Frame("rest", 0.0), Frame("moving", -0.6), Frame("u=0.3", 0.3)
    assert clock_reading(other, 5e6) == "$t_u$ = $5{\\times}10^{6}$ $L$"
    assert clock_reading(rest, -0.5) == "$t$ = \N{MINUS SIGN}0.5 $L$"
    assert clock_reading(moving, 1.25) == "$t$\N{PRIME} = 1.25 $L$"


def test_a_deep_inset_samples_only_what_it_shows():
    """Issue 27: masses 1e9 squeeze the causal rod to a sliver a billionth of L wide; its inset (x5e8) sampled the
    whole world-lines a thousandth of its window apart, 6e6 points, and `handout --rod both` took 49 s. Sampled
    within the inset's window only (its side either way), the inset's lines hold a bounded number of points, every
    one of them near the window, and the sheet is still drawn across it."""
    from rodparadox.physics.model import Particle, Scenario
    from rodparadox.physics.models import run_rods

    scenario = Scenario("heavy9", 0.6, (Particle("A", 1e9, gap=0.5), Particle("B", 1e9, gap=0.5)), 1.0, rod="causal")
    fig = render.draw(run_rods(scenario)[0], paper_frames(0.6)).figure
    [inset] = fig.axes[0].child_axes
    assert inset.get_gid() == "a-inset"
    (x0, x1), (t0, t1) = inset.get_xlim(), inset.get_ylim()
    lines = [line for line in inset.lines if len(line.get_xdata()) > 2]
    assert lines and all(len(line.get_xdata()) <= 20_000 for line in lines)
    for line in lines:
        t = np.asarray(line.get_ydata(), float)
        t = t[np.isfinite(t)]
        assert t.min() >= t0 - 1.01 * (t1 - t0) and t.max() <= t1 + 1.01 * (t1 - t0)
    assert [p for p in inset.patches if (p.get_gid() or "").endswith("inset-sheet")]


def test_a_worksheets_inset_names_no_impacts_an_instant_groups():
    """Issue 24: fig2's worksheet at 0.95 (no lines of simultaneity: it asks whether B₁ and A₁ are simultaneous in
    S′) had in panel (b) an inset noted "×5 at B₁, A₁": the inset is centred on the impacts of the frame's first
    instant, so its note told the answer. A worksheet's note is then its factor alone; a handout's names them."""
    frames = paper_frames(0.95)[1:]
    for simultaneity, note in ((False, "$\\times5$"), (True, "$\\times5$ at $B_{1}$, $A_{1}$")):
        drawn = render.draw(history("fig2", 0.95), frames, "print", render.Options(simultaneity=simultaneity))
        [inset] = [c for c in drawn.panels[0].axes.child_axes if c.get_gid() == "a-inset"]
        assert [t.get_text() for t in inset.texts if t.get_gid() == "a-inset-note"] == [note]
