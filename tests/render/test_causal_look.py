"""The causal rod's ledger figure (issue 16, item 5): its matter and stress parts drawn as the table gives them, the
stress part named as its pressure's share of the rod's energy and momentum, and with both rods the rigid rows
above the causal ones on one scale.

The figure's values are checked against `tables.causal_ledger` (the split on each slice asked for, one slice at a
time) and against the total before the first contact (closed form): the figure reads its curves from many slices
at once (`Fronts.rod_parts_on_slices`, the same integral, `physics.causal.parts`; tests/physics/test_causal_parts.py
checks that against an independent quadrature). One figure per rod model, built once and checked many ways.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np
import pytest
from click.testing import CliRunner

from helpers import causal_history, history
from rodparadox.physics.frames import Frame, paper_frames
from rodparadox.render import ledger_figure
from rodparadox.tables import causal_ledger
from sears_paradox_cli.main import main

pytestmark = pytest.mark.xdist_group("causal_look")

#: `single`: one particle B on the rod at rest, a contact B₁ and its separation B′₁; frame u = 0.5, where the
#: squeezed rod moves and its stress carries momentum
FRAME = Frame("u=0.5", 0.5)


@lru_cache(maxsize=None)
def causal_figure():
    return ledger_figure.draw(causal_history("single"), [FRAME], "default")


@lru_cache(maxsize=None)
def both_figure():
    return ledger_figure.draw_both(history("single"), causal_history("single"), [paper_frames(0.6)[0]], "print")


def _line(fig, gid: str) -> tuple[np.ndarray, np.ndarray]:
    [line] = [a for a in fig.findobj(lambda a: a.get_gid() == gid)]
    return np.asarray(line.get_xdata(), float), np.asarray(line.get_ydata(), float)


def _band(fig, gid: str) -> np.ndarray:
    """The shaded band's outline: (t, lower edge) then (t, upper edge) backwards, as fill_between draws it."""
    [band] = [a for a in fig.findobj(lambda a: a.get_gid() == gid)]
    return band.get_paths()[0].vertices


def test_the_ledger_figure_draws_the_tables_matter_and_stress_parts_at_every_contact_and_separation():
    h, fig = causal_history("single"), causal_figure()
    events = causal_ledger.instants(h, FRAME)
    assert [kind for _, kind, *_ in events] == ["contact", "separation"]
    for label, _, t, impact in events:
        rows = dict(causal_ledger.rows_at(h, FRAME, t, impact))
        for q in ("E", "p"):
            ts, particle = _line(fig, f"a-{q}-B")
            k = int(np.flatnonzero(ts == t / h.scenario.L)[0])  # every event's instant is one of the curves' times
            assert particle[k] == pytest.approx(getattr(rows["particle B"], q), abs=1e-9)
            assert _line(fig, f"a-{q}-rod_matter")[1][k] == pytest.approx(getattr(rows[causal_ledger.MATTER], q), abs=1e-8)
            stress = getattr(rows[causal_ledger.STRESS], q)
            below = _line(fig, f"a-{q}-matter_total")[1][k]
            outline = _band(fig, f"a-{q}-stress")
            at = outline[np.abs(outline[:, 0] - t / h.scenario.L) < 1e-12, 1]
            assert below in at and any(abs(y - below - stress) <= 1e-8 for y in at), (label, q)
    # seen moving, the squeezed rod's stress carries momentum (no rounding): the band is not a line
    assert np.ptp(_band(fig, "a-p-stress")[:, 1]) > 0.05


def test_the_stress_band_closes_the_ledger_on_every_slice():
    """Particles, matter and stress add up to the total before the first contact (closed form) on each of the
    figure's slices: what the shaded band's upper edge must be."""
    h, fig = causal_history("single"), causal_figure()
    total = h.initial_total(FRAME.rapidity)
    for q in ("E", "p"):
        outline = _band(fig, f"a-{q}-stress")
        n = len(_line(fig, f"a-{q}-matter_total")[0])
        upper = outline[n + 1:2 * n + 1, 1]  # after the lower edge and its closing vertex
        assert np.abs(upper - getattr(total, q)).max() <= 1e-8, q
        level = _line(fig, f"a-{q}-total")[1]
        assert np.all(level == getattr(total, q))


def test_the_legend_names_the_stress_part_as_the_real_local_hidden_momentum():
    texts = [t.get_text().replace("\n", " ") for t in causal_figure().legends[0].get_texts()]
    assert "rod, stress (hatched): its pressure’s share of the rod’s energy and momentum" in texts
    assert any(t.startswith("rod, matter") for t in texts) and "total before the first contact" in texts
    names = sorted(a.get_text() for a in causal_figure().findobj(lambda a: str(a.get_gid()).startswith("a-label-")))
    assert names == ["B\N{PRIME}\N{SUBSCRIPT ONE}", "B\N{SUBSCRIPT ONE}"]


def test_both_rods_ledgers_sit_rigid_above_causal_on_one_scale():
    fig = both_figure()
    axes = {ax.get_gid(): ax for ax in fig.axes}
    assert sorted(axes) == ["a-E-axes", "a-p-axes", "b-E-axes", "b-p-axes"]
    assert axes["a-E-axes"].get_position().y0 > axes["b-p-axes"].get_position().y1  # the rigid rod's rows above
    for q in ("E", "p"):
        assert axes[f"a-{q}-axes"].get_ylim() == axes[f"b-{q}-axes"].get_ylim()
        assert axes[f"a-{q}-axes"].get_xlim() == axes[f"b-{q}-axes"].get_xlim()
    assert "rigid rod" in axes["a-p-axes"].get_title() and "causal rod" in axes["b-p-axes"].get_title()
    gids = {a.get_gid() for a in fig.findobj(lambda a: bool(a.get_gid()))}
    assert {"a-p-hidden", "b-p-stress"} <= gids and "b-p-hidden" not in gids and "a-p-stress" not in gids
    # the hidden part and the stress part are told apart without colour: hatched one way and the other
    hatches = {gid: a.get_hatch() for a in fig.findobj(lambda a: a.get_gid() in ("a-p-hidden", "b-p-stress"))
               for gid in [a.get_gid()]}
    assert hatches["a-p-hidden"] != hatches["b-p-stress"] and all(hatches.values())


def test_ledger_figure_of_both_rods_refuses_more_frames_than_four_rows_of_each(tmp_path):
    result = CliRunner().invoke(main, ["ledger", "single", "--rod", "both", "--frame", "both,0.1,0.2,0.3",
                                       "-o", str(tmp_path / "x.svg")])
    assert result.exit_code == 2 and "Traceback" not in result.output and result.output.count(".") <= 2
    assert "at most 4 frames" in result.output and list(tmp_path.iterdir()) == []


def test_an_event_name_pushed_off_its_line_is_tied_to_it():
    """Review: in fig2's S′ panel of both rods A′₃ stood 0.8 L right of its line, untied, read as another event. A name
    whose box is no longer over its event's line gets a leader ending on that line at the panel's top."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.text import Text

    fig = ledger_figure.draw_both(history("fig2", 0.6), causal_history("fig2", 0.6), paper_frames(0.6), "default")
    renderer = FigureCanvasAgg(fig).get_renderer()
    fig.draw_without_rendering()
    tied = 0
    for ax in fig.axes:
        for text in ax.texts:
            if "-label-" not in (text.get_gid() or ""):
                continue
            box = Text.get_window_extent(text, renderer)  # the name alone
            line_x = ax.transData.transform((text.xy[0], 0.0))[0]
            if not box.x0 <= line_x <= box.x1:
                leader = text.get_gid().replace("-label-", "-leader-")
                assert [a for a in ax.texts if a.get_gid() == leader], text.get_text()
                tied += 1
    assert tied >= 2  # A′₂ and A′₃ in S′ (this test fails if names are never pushed: then it checks nothing)
