"""The causal rod drawn (issue 16, item 5): its world-sheet shaded by compression, its light fronts, its contacts
as stretches where a particle rides with an end, separations told from contacts; `--rod both` as a rigid row
above a causal row on the same scales. Checked against the history read independently (material world-lines,
finite differences), never against the drawing code's own numbers.

Histories and figures are built once per process (`causal`, `drawn`) and checked many ways.
"""

from __future__ import annotations

import math
import sys
from functools import lru_cache
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner
from matplotlib.colors import to_rgb

from helpers import history, particle_presets
from rodparadox import render
from rodparadox.io.scenario import load
from rodparadox.physics.frames import Frame, paper_frames, time_window
from rodparadox.physics.kinematics import ChartCurve
from rodparadox.physics.models import run_rod
from rodparadox.render.causal_layers import compression_cells, compression_colour_map, compression_norm
from rodparadox.render.styles import STYLE_NAMES, STYLES
from sears_paradox_cli.main import main

sys.path.insert(0, str(Path(__file__).resolve().parent))
from test_render import (_collisions, _distance_to_polyline, _far_labels, _labels_on_sheet, _leader_faults, _renderer, artist, gids,  # noqa: E402
                         xy)


@lru_cache(maxsize=None)
def causal(name: str, v: float | None = None):
    return run_rod(load(name).with_overrides(v=v, rod="causal"))


def frames(h, *extra: float) -> list[Frame]:
    return [*paper_frames(h.scenario.v), *(Frame(f"u={u}", u) for u in extra)]


def drawn(name: str, v: float, style: str = "default", extra: tuple = ()):
    """The causal rod's figure, once per process (`drawn("fig2", 0.6)` and `drawn("fig2", 0.6, "default")` alike)."""
    return _drawn(name, v, style, tuple(extra))


@lru_cache(maxsize=None)
def _drawn(name: str, v: float, style: str, extra: tuple):
    h = causal(name, v)
    return render.draw(h, frames(h, *extra), style)


@lru_cache(maxsize=None)
def both(name: str, v: float | None, style: str, specs: tuple = ("rest", "moving")):
    rigid, h = history(name, v), causal(name, v)
    chosen = [f for f in paper_frames(h.scenario.v) if f.name in specs]
    return render.draw_both(rigid, h, chosen, style)


# --- the fronts ---------------------------------------------------------------------------------------------

def _sigma_at(h, x: float, t: float, f: float) -> float:
    """The material point at (x, t) of the frame of rapidity f, by bisection on the material world-lines."""
    lo, hi = 0.0, h.scenario.L
    for _ in range(40):
        mid = 0.5 * (lo + hi)
        if h.material_worldline(mid).seen_from(f).event_at_time(t).x < x:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


@pytest.mark.parametrize("name, v", [("fig2", 0.6), ("single", 0.95)])
def test_fronts_are_light_lines_in_every_frame_and_the_material_velocity_jumps_across_each(name, v):
    h = causal(name, v)
    diagram = drawn(name, v, extra=(0.9,))
    assert len(diagram.panels) == 3
    for info in diagram.panels:
        f = info.frame.rapidity
        front_ids = gids(diagram.figure, f"{info.letter}-front-\\d+")
        assert len(front_ids) >= 2
        for gid in front_ids[::3]:  # a third of them, of both families: each costs two bisections
            (x0, t0), (x1, t1) = xy(artist(diagram.figure, gid))
            assert abs(abs(x1 - x0) - abs(t1 - t0)) <= 1e-9 * (1 + abs(t1 - t0))  # 45 degrees: a light line
        if info.letter != "a":
            continue
        # every front of the S panel: the material just either side of its middle moves at different velocities
        L = h.scenario.L
        for gid in front_ids[::3]:  # a third of them, of both families: each costs two bisections
            (x0, t0), (x1, t1) = xy(artist(diagram.figure, gid))
            xm, tm = 0.5 * (x0 + x1) * L, 0.5 * (t0 + t1) * L
            sigma = _sigma_at(h, xm, tm, f)
            jump = abs(h.material_velocity(min(sigma + 1e-6 * L, L), f, tm)
                       - h.material_velocity(max(sigma - 1e-6 * L, 0.0), f, tm))
            assert jump > 1e-4, gid


# --- the shading --------------------------------------------------------------------------------------------

def _lam_by_differences(h, u: float, w: float) -> float:
    """lam at the chart point (u, w) from the material world-lines: the rest length 2 delta of a short piece of
    material over its length in its own rest frame."""
    X, T = 0.5 * (u - w), 0.5 * (u + w)
    P = ChartCurve(h.solution, X, T, T).point(T)
    th = h.material_worldline(X).rapidity_at_time(P.t)
    t_rest = P.seen_from(th).t
    delta = 1e-6 * h.scenario.L
    ends = [h.material_worldline(X + s * delta).seen_from(th).event_at_time(t_rest).x for s in (-1, 1)]
    return 2 * delta / (ends[1] - ends[0])


@pytest.mark.parametrize("name, v, f", [("fig2", 0.6, 0.0), ("fig2", 0.6, -math.atanh(0.6)), ("fig1", 0.95, 0.4)])
def test_the_shadings_lam_at_sampled_cells_is_the_historys_lam_there(name, v, f):
    h, L = causal(name, v), causal(name, v).scenario.L
    t_lo, t_hi = -0.5 * L, 4.0 * L
    polygons, ln_lam, centres = compression_cells(h, f, t_lo, t_hi)
    inside = [k for k, (u, w) in enumerate(centres) if 0.01 * L < 0.5 * (u - w) < 0.99 * L]
    cmap, norm = compression_colour_map(STYLES["default"]), compression_norm(h)
    for k in inside[:: max(1, len(inside) // 25)]:
        lam = _lam_by_differences(h, *centres[k])
        assert math.exp(ln_lam[k]) == pytest.approx(lam, rel=1e-4)
        assert np.allclose(cmap(norm(ln_lam[k])), cmap(norm(math.log(lam))), atol=2 / 255)
    assert max(ln_lam) > 0.1  # compressed somewhere: the test sees a scale, not a flat sheet


def test_the_drawn_cells_are_the_cells_and_their_colours_mean_their_lam():
    h = causal("fig2", 0.6)
    diagram = drawn("fig2", 0.6)
    for info in diagram.panels:
        mesh = artist(diagram.figure, f"{info.letter}-compression")
        colours = mesh.get_facecolors()
        assert len(colours) == len(mesh.get_paths()) > 20
        # lightness falls as lam grows: the darkest cell is the most compressed
        light = colours[:, :3] @ np.array([0.299, 0.587, 0.114])
        polygons, ln_lam, _ = compression_cells(h, info.frame.rapidity, *time_window(h, info.frame))
        assert len(polygons) == len(colours)
        assert np.argmin(light) == np.argmax(ln_lam)


@pytest.mark.parametrize("style", STYLE_NAMES)
def test_the_compression_scale_is_greyscale_safe_lightness_falling_from_stretched_to_compressed(style):
    cmap = compression_colour_map(STYLES[style])
    grey = [np.dot(to_rgb(cmap(x)), (0.299, 0.587, 0.114)) for x in np.linspace(0, 1, 41)]
    assert all(b < a for a, b in zip(grey, grey[1:]))
    assert grey[0] - grey[-1] > 0.45  # a ramp a printer keeps
    assert np.allclose(to_rgb(cmap(0.5)), to_rgb(STYLES[style].sheet), atol=1 / 255)  # unstressed: the plain sheet


# --- contacts and separations -------------------------------------------------------------------------------

def test_each_contact_is_drawn_on_the_particles_and_the_ends_world_lines():
    diagram = drawn("fig2", 0.6)
    h = causal("fig2", 0.6)
    contacts = [i for i in h.impacts if i.kind == "contact"]
    for info in diagram.panels:
        bands = gids(diagram.figure, f"{info.letter}-contact-.*")
        assert len(bands) == len(contacts)  # every contact lies inside the window
        for gid in bands:
            particle = gid.split("-")[2]
            end = next(i.end for i in contacts if i.particle == particle)
            points = xy(artist(diagram.figure, gid))
            for line in (f"{info.letter}-{particle}", f"{info.letter}-rod_{end}"):
                assert _distance_to_polyline(points, xy(artist(diagram.figure, line))).max() <= 2e-4


def test_separations_are_hollow_and_labelled_with_a_prime_contacts_filled_and_the_legend_says_which():
    fig = drawn("fig2", 0.6).figure
    h = causal("fig2", 0.6)
    for i in h.impacts:
        marker = artist(fig, f"a-impact-{i.label}")
        label = artist(fig, f"a-impact-label-{i.label}").get_text()
        if i.kind == "separation":
            assert marker.get_markerfacecolor() == "white" and label == f"${i.particle}$\N{PRIME}$_{{{i.label[1:-1]}}}$"
        else:
            assert marker.get_markerfacecolor() != "white" and label == f"${i.particle}_{{{i.label[1:]}}}$"
    texts = [t.get_text() for t in fig.legends[0].get_texts()]
    # named by fig2's first contact, B₁, and first separation, A′₁
    assert "contact (B\N{SUBSCRIPT ONE})" in texts and "separation (A\N{PRIME}\N{SUBSCRIPT ONE})" in texts
    assert any(t.startswith("compression \N{GREEK SMALL LETTER LAMDA}: 0.3") for t in texts)
    assert any(t.startswith("light front") for t in texts)
    # lines of simultaneity only through each particle's first contact
    assert gids(fig, "a-simultaneity-rest-.*") == ["a-simultaneity-rest-A1", "a-simultaneity-rest-B1"]


def test_the_titles_give_the_ringing_rods_centre_of_momentum_velocity():
    h = causal("fig2", 0.6)
    titles = [info.axes.get_title().replace("\n", " ").replace("\N{MINUS SIGN}", "-") for info in drawn("fig2", 0.6).panels]
    assert titles[0].endswith(f"finally at {math.tanh(h.final_rapidity):+.3f}, ringing")
    assert math.tanh(h.final_rapidity) == pytest.approx(-0.125, abs=5e-4)


# --- labels, every preset, every style, speeds -------------------------------------------------------------

def _label_problems(fig, style) -> list:
    renderer = _renderer(fig, style)
    # a front is a line like any other: no label sits on one (over the shading it may)
    return _collisions(fig, style, renderer) + _far_labels(fig, style, renderer) + _leader_faults(fig, style, renderer)


@pytest.mark.slow
@pytest.mark.parametrize("style", ["default", "print"])
@pytest.mark.parametrize("v", [0.3, 0.6, 0.95])
@pytest.mark.parametrize("name", ["fig1", "fig2"])
def test_labels_touch_nothing_and_sit_by_their_markers(name, v, style):
    assert _label_problems(drawn(name, v, style).figure, style) == []


def test_labels_touch_nothing_in_slides():
    """fig2 at 0.6 in slides collided every way: labels on fronts, across leaders, S' squeezed to a third by S's
    long title (every preset at 0.01 to 0.99 in every style was checked by hand; this is the worst of them)."""
    assert _label_problems(drawn("fig2", 0.6, "slides").figure, "slides") == []


def test_labels_of_both_rods_sit_on_no_front():
    """fig1 at 0.95 with both rods, frame S: the causal row's A′₂ sat on a light front (fronts were guides then)."""
    assert _label_problems(both("fig1", 0.95, "default", ("rest",)).figure, "default") == []


def test_no_particle_s_letter_sits_on_a_world_sheet():
    """Issue 24: B sat on the causal rod's shaded world-sheet (fig1 at 0.95 with both rods, frame S: the figure of
    the test above), read as the rod's; a particle's letter now costs as a line crossed there. The handout-sized
    and plot-sized figures of every preset at 0.3, 0.6 and 0.95: tests/label_sweep.py (4 found before, 0 now)."""
    fig = both("fig1", 0.95, "default", ("rest",)).figure
    assert _labels_on_sheet(fig, _renderer(fig, "default")) == []


@pytest.mark.parametrize("name, v, size", [
    ("fig2", 0.6, (6.3, 7.6)),  # the handout's page with panel (d): A′₂, B′₂, B′₁, B₂, A₂ crowded, leaders crossed
    ("fig2", 0.65, None),  # plot --rod both: B′₁'s leader crossed A₃'s and A′₃'s
])  # two figures (the test budget): tests/label_sweep.py draws the rest
def test_no_label_of_both_rods_sits_on_a_marker_or_a_label_and_no_leaders_cross(name, v, size):
    """Issue 24: the causal rod's labels crowd where contacts and separations follow each other at one end; a label
    placed early took the room a later one needed, whose leader then crossed others or ran across a marker. Now a
    label on a marker, a label or a leader, or a leader across any of them, is chosen only where nothing else is
    left, and a panel where one is left is arranged again with those labels first. Measured on the renderer's boxes;
    the handout's size (6.3 x 7.6 in) and the plot's. A sweep of every preset at v = 0.05 ... 0.95 in both sizes:
    tests/label_sweep.py (no fault left; 42 at the handout's size and 7 at the plot's before)."""
    from matplotlib.figure import Figure

    rigid, h = history(name, v), causal(name, v)
    if size is None:
        fig = render.draw_both(rigid, h, paper_frames(v), "print").figure
    else:
        fig = Figure(figsize=size, dpi=72)
        render.draw_into(fig, (rigid, h), paper_frames(v), "print")
    renderer = _renderer(fig, "print")
    assert _leader_faults(fig, "print", renderer) == []
    assert [c for c in _collisions(fig, "print", renderer) if "-impact-label-" in c[0] and "-impact-label-" in c[1]] == []


@pytest.mark.slow
@pytest.mark.parametrize("style", STYLE_NAMES)
def test_every_preset_draws_with_both_rods_rigid_row_above_causal_on_the_same_scales(style):
    for name in particle_presets():
        diagram = both(name, None, style, ("rest",))
        a, b = diagram.panels
        assert a.letter == "a" and b.letter == "b"
        assert a.axes.get_position().y0 > b.axes.get_position().y1  # rigid above
        # one data box and one scale (points per L), drawn alike: a longer title widens both panels of its frame
        # (review: the causal row's "..., ringing" widened its panel alone, fig2's x from -4.8 against -3.7)
        assert a.data_box == b.data_box and a.axes.get_ylim() == b.axes.get_ylim()
        assert a.axes.get_xlim() == pytest.approx(b.axes.get_xlim(), abs=1e-12)
        scale = [ax.get_position().width * diagram.figure.get_figwidth() / np.ptp(ax.get_xlim())
                 for ax in (a.axes, b.axes)]
        assert scale[0] == pytest.approx(scale[1], rel=1e-9)
        assert "rigid rod" in a.axes.get_title() and "causal rod" in b.axes.get_title()
        assert gids(diagram.figure, "a-compression") == [] and gids(diagram.figure, "b-compression") == ["b-compression"]


@pytest.mark.parametrize("v", [0.01, 0.99])
def test_the_extreme_speeds_draw_and_keep_their_labels_apart(v):
    fig = drawn("fig2", v).figure
    assert gids(fig, "a-compression") == ["a-compression"]
    legend = " ".join(t.get_text() for t in fig.legends[0].get_texts())
    assert "e+" not in legend and "e-" not in legend
    assert _collisions(fig, "default") == []


# --- the command line -----------------------------------------------------------------------------------------

def test_plot_names_the_rod_in_the_file_and_refuses_proper_time_for_the_causal_rod(tmp_path):
    runner = CliRunner()
    for rod in ("causal", "both"):
        result = runner.invoke(main, ["plot", "single", "--rod", rod, "-o", str(tmp_path), "--format", "svg"])
        assert result.exit_code == 0, result.output
        assert result.output == f"{tmp_path / f'single_{rod}.svg'}\n"
    result = runner.invoke(main, ["plot", "single", "--rod", "causal", "--proper-time", "-o", str(tmp_path / "x.svg")])
    assert result.exit_code == 2 and result.output.count(".") <= 2 and "Traceback" not in result.output
    assert "--proper-time" in result.output and not (tmp_path / "x.svg").exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["single_both.svg", "single_causal.svg"]


# --- the ledger ---------------------------------------------------------------------------------------------

LEDGER_ROWS = ("particle A", "particle B", "rod, matter", "rod, stress")


def ledger_out(fmt: str) -> str:
    """fig1's causal ledger in S and the frame u = 0.9, with a slice at t = 1.5: every format from one history, so
    each slice's split (0.3 s) is integrated once (`causal_ledger` keeps it)."""
    from rodparadox.tables import causal_ledger

    h = causal("fig1", None)
    writer = {"text": causal_ledger.to_text, "json": causal_ledger.to_json, "csv": causal_ledger.to_csv,
              "markdown": causal_ledger.to_markdown, "latex": causal_ledger.to_latex}[fmt]
    return writer(h, [paper_frames(0.6)[0], Frame("u=0.9", 0.9)], (1.5,))


def _number(text: str) -> float:
    return float(text.replace("\N{MINUS SIGN}", "-"))


def test_the_json_ledgers_summands_add_up_to_the_initial_total_at_every_event_and_slice():
    import json

    doc = json.loads(ledger_out("json"))
    assert doc["rod"] == "causal" and set(doc["frames"]) == {"rest", "u=0.9"}
    for frame in doc["frames"].values():
        total = frame["total"]
        assert len(frame["events"]) == 4 and {e["kind"] for e in frame["events"]} == {"contact", "separation"}
        for row in frame["events"] + frame["slices"]:
            bodies = row["bodies"]
            for q in ("E", "p"):
                parts = sum(bodies[b][q] for b in ("A", "B", "rod_matter", "rod_stress"))
                assert parts == pytest.approx(total[q], abs=1e-9) and bodies["total"][q] == pytest.approx(parts, abs=1e-12)
    # the stress part is no rounding: seen moving, the squeezed rod's stress carries momentum (in S, by fig1's
    # symmetry, none)
    assert max(abs(e["bodies"]["rod_stress"]["p"]) for e in doc["frames"]["u=0.9"]["events"]) > 0.01


def test_the_csv_ledger_adds_up_as_the_json_does():
    rows = [line.split(",") for line in ledger_out("csv").splitlines()[1:]]
    groups: dict = {}
    for frame, kind, label, t, body, E, p in rows:
        groups.setdefault((frame, kind, label, t), {})[body] = (float(E), float(p))
    assert len(groups) == 2 * 5
    for bodies in groups.values():
        for k in (0, 1):
            parts = sum(bodies[b][k] for b in ("A", "B", "rod_matter", "rod_stress"))
            assert parts == pytest.approx(bodies["total"][k], abs=1e-9)


@pytest.mark.parametrize("fmt", ["text", "markdown", "latex"])
def test_the_printed_ledgers_rows_add_up_to_their_total_within_the_printed_rounding(fmt):
    out = ledger_out(fmt)
    cells = {"text": lambda line: line.split("  "), "markdown": lambda line: line.split("|"),
             "latex": lambda line: line.replace("\\\\", "").split("&")}[fmt]
    groups, current = [], None
    for line in out.splitlines():
        parts = [c.strip() for c in cells(line) if c.strip()]
        names = [p for p in parts if p in (*LEDGER_ROWS, "total") or p.startswith("rod, stress")]
        if not names:
            continue
        name, numbers = names[0], [_number(p) for p in parts[parts.index(names[0]) + 1:]][:2]
        if name == "particle A":
            current = {}
            groups.append(current)
        current["stress" if name.startswith("rod, stress") else name] = numbers
    assert len(groups) == 2 * 5
    for g in groups:
        for k in (0, 1):
            parts = g["particle A"][k] + g["particle B"][k] + g["rod, matter"][k] + g["stress"][k]
            assert abs(parts - g["total"][k]) <= 4 * 0.5e-4 + 1e-12  # four numbers rounded to four decimals
    assert "not to the stress part alone" in out.replace("\n  ", " ").replace("\n", " ")


def test_ledger_both_gives_the_rigid_ledger_then_the_causal_one_and_the_figure_is_drawn(tmp_path):
    result = CliRunner().invoke(main, ["ledger", "single", "--rod", "both", "--frame", "rest"])
    assert result.exit_code == 0, result.output
    out = result.output
    assert out.index("hidden") < out.index("the causal rod") and "rod, stress" in out
    # the figure is no longer refused (test_causal_look checks what it draws); named after its rod, as plot's
    result = CliRunner().invoke(main, ["ledger", "single", "--rod", "causal", "--frame", "rest", "--format", "svg",
                                       "-o", str(tmp_path)])
    assert result.exit_code == 0, result.output
    assert result.output == f"{tmp_path / 'single_ledger_rest_causal.svg'}\n"


@pytest.mark.parametrize("lam, text", [(114.63, "115"), (6.49, "6.5"), (1.0, "1.0"), (0.381, "0.38"),
                                       (0.00862, "0.0086"), (1.0004, "1.0004"), (0.99951, "0.9995"),
                                       (1.04, "1.04"), (2030345398.0, "2\N{MULTIPLICATION SIGN}10\N{SUPERSCRIPT NINE}"),
                                       (2.2e-7, "2.2\N{MULTIPLICATION SIGN}10\N{SUPERSCRIPT MINUS}\N{SUPERSCRIPT SEVEN}")])
def test_the_compression_scale_is_written_in_plain_decimals(lam, text):
    """Two significant digits, but never 1.0 for a stressed rod (review: off_timing at v = 0.01 read "0.98 to 1.0")."""
    from rodparadox.render.causal_layers import lam_text

    assert lam_text(lam) == text


def test_the_causal_strip_read_off_the_chart_is_the_material_world_lines_at_that_instant():
    from rodparadox.physics.snapshot import strip_at, STRIP_POINTS

    h = causal("fig2", 0.6)
    for frame in paper_frames(0.6):
        for t in (0.5, 1.7, 2.9, 6.0):
            strip = strip_at(h, frame, t, 0.0)
            for k in range(0, STRIP_POINTS, 19):
                line = h.material_worldline(float(strip.sigma[k])).seen_from(frame.rapidity)
                assert strip.x[k] == pytest.approx(line.event_at_time(t).x, abs=1e-12)
                assert strip.velocity[k] == pytest.approx(math.tanh(line.rapidity_at_time(t)), abs=1e-9)


@pytest.mark.parametrize("mode", ["now", "boost"])
def test_animate_draws_the_causal_rod_in_both_modes(mode, tmp_path):
    result = CliRunner().invoke(main, ["animate", "single", "--rod", "causal", "--mode", mode, "--fps", "1",
                                       "--seconds", "2", "--format", "png", "-o", str(tmp_path)])
    assert result.exit_code == 0, result.output
    assert sorted(p.name for p in tmp_path.iterdir()) == [f"single_{mode}_causal_fps1_seconds2_000{k}.png"
                                                           for k in (0, 1)]


# --- the comparison's note ------------------------------------------------------------------------------------

@lru_cache(maxsize=None)
def like_for_like(name: str, v: float):
    """Both rods struck by the same particles, as `plot --rod both` runs them (`physics.models.run_rods`)."""
    from rodparadox.physics.models import run_rods

    return run_rods(load(name).with_overrides(v=v), "both")


@lru_cache(maxsize=None)
def compared(name: str, v: float):
    """`plot NAME --v V --rod both --rod-now`, drawn once for the note's test and the rod's-now test."""
    return render.draw_both(*like_for_like(name, v), paper_frames(v), options=render.Options(rod_now=True)).figure


def test_a_comparison_figure_says_what_particles_strike_both_rods_and_where_their_first_impacts_fall():
    """Issue 23, item 3: `plot --rod both` states where each particle started and, for each rod, whether its first
    impacts are simultaneous in the figure's frames. fig2 at v = 0.6 (like for like, `run_rods`): A is placed by
    the rigid rod's timing rule so that A1 and B1 share t' = 17/12 L (hand: B1 at t = L/2v = 5/6, x = L/2, so
    t' = g (t + v x) = 5/4 (5/6 + 0.3) = 17/12); B starts at its gap, x = L/2 + 0.5 = 1; the causal rod's A1 is
    later than its B1 in S' (its far end moves before light from B1 could tell a rigid rod's would)."""
    from rodparadox.tables.comparison import comparison_note

    rigid, causal_rod = like_for_like("fig2", 0.6)
    fig = compared("fig2", 0.6)
    note = " ".join(artist(fig, "comparison-note").get_text().split("\n"))
    assert note.startswith("Both rods are struck by the same particles: A from x = ")
    assert "B from x = 1 L at speed 0.6 c" in note
    assert "The rigid rod: A\N{SUBSCRIPT ONE} and B\N{SUBSCRIPT ONE} are simultaneous in S\N{PRIME} (at 1.417 L)" in note
    assert "The causal rod: A\N{SUBSCRIPT ONE} and B\N{SUBSCRIPT ONE} are not simultaneous in S (" in note
    a_start = dict(rigid.starts)["A"]
    assert f"A from x = \N{MINUS SIGN}{abs(a_start.x):.4g} L" in note
    # inside the figure, clear of the legend and of every other text
    assert _collisions(fig, "default") == []
    # a library caller's histories run apart are never said to share their particles
    apart = comparison_note((history("fig2", 0.6), causal("fig2", 0.6)), paper_frames(0.6))
    assert "start apart" in apart and "the same particles" not in apart


def test_the_rods_own_now_is_in_the_legend_only_where_a_rod_draws_it(tmp_path):
    """Issue 24: `plot fig2 --rod causal --rod-now` showed "the rod's own lines of simultaneity" in the legend
    and drew none (the causal rod has no rod-wide now). Alone it is refused; beside the rigid rod the legend
    keeps the entry for the lines the rigid row draws, and the causal row draws none."""
    from rodparadox.render.layers import legend_entries

    fig = compared("fig2", 0.6)
    labels = [t.get_text() for t in fig.legends[0].get_texts()]
    assert "the rod’s own lines of simultaneity" in labels
    assert gids(fig, r"a-rod-now-\d+") and gids(fig, r"[cd]-rod-now-\d+") == []
    causal_rod = like_for_like("fig2", 0.6)[1]
    _, alone = legend_entries(STYLES["default"], causal_rod, render.Options(rod_now=True), 1.0)
    assert "the rod’s own lines of simultaneity" not in alone
    result = CliRunner().invoke(main, ["plot", "fig2", "--rod", "causal", "--rod-now", "-o", str(tmp_path)])
    assert result.exit_code == 2 and "the causal rod has none" in result.output and not list(tmp_path.iterdir())
