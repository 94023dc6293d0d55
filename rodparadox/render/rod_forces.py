"""The rod's own view's layer of a rod driven by forces (`rod_panel`, `rod_layers.DRAW`): each force as a band beside
its end, as wide as F at each instant of the rod's own time, its start and end marked (on, off)."""

from __future__ import annotations

import numpy as np
from matplotlib.lines import Line2D
from matplotlib.patches import Polygon

from rodparadox.render.force_layers import PULL_HATCH, ForceKey, force_scale, profile_samples
from rodparadox.render.rod_layer_base import RodLayer
from rodparadox.render.text import tick_text

#: samples of a force's profile along its end in the rod's own view (its corners and jumps besides)
FORCE_SAMPLES = 96
#: the width, in units of L, of a force's band at the legend's force (`force_layers.force_scale`): no band is wider
FORCE_BAND = 0.3


class Forces(RodLayer):
    """Each force of a rod driven by forces (the capability `driving`) as a band outside its end, as wide as F at
    each instant of the rod's own time (F is the push in the end's rest frame: the same number in every frame and
    chart), with its start and end marked on the end (on, off). The band's points are the exact chart places of the
    end's events where its profile reads each sampled instant."""

    name = "forces"

    def applies(self, history):
        return history.driving is not None

    def chart_times(self, history, chart):
        return [chart.to_chart(e.event)[0] / history.scenario.L for e in history.driving.force_events()]

    @staticmethod
    def _band(history, chart, end: str, profile) -> tuple[np.ndarray, np.ndarray]:
        """Chart times (units of L) and forces along the end, over the profile's support, a jump's instant twice."""
        rapidity = history.driving.frame_rapidity(end)
        line = history.worldline(f"rod_{end}").seen_from(rapidity)  # the end in the profile's own frame
        instants, forces = profile_samples(profile, *profile.support(), FORCE_SAMPLES)
        L = history.scenario.L
        T = [chart.to_chart(line.event_at_time(t).seen_from(-rapidity))[0] / L for t in instants]
        return np.array(T), forces

    def draw(self, ax, panel):
        history, chart, st, fs, letter = panel.history, panel.chart, panel.style, panel.fs, panel.letter
        per_force = FORCE_BAND / force_scale(history)
        out = []
        for end, profile in history.driving.profiles():
            X, side = (0.0, -1.0) if end == "left" else (1.0, 1.0)
            T, forces = self._band(history, chart, end, profile)
            for sense, part in (("press", np.maximum(forces, 0.0)), ("pull", np.minimum(forces, 0.0))):
                if not part.any():
                    continue
                outer = np.column_stack([X + side * per_force * np.abs(part), T])
                inner = np.column_stack([np.full_like(T, X), T])
                out.append(ax.add_patch(Polygon(np.concatenate([inner, outer[::-1]]), closed=True,
                                                     facecolor=st.force_fill, edgecolor="none",
                                                     hatch=PULL_HATCH if sense == "pull" else None, zorder=2.8,
                                                     gid=f"{letter}-force-{end}-{sense}")))
                edge = np.where((part != 0.0)[:, None], outer, np.nan)
                line, = ax.plot(edge[:, 0], edge[:, 1], color=st.force.colour, linewidth=st.force.width,
                                zorder=2.9, gid=f"{letter}-force-edge-{end}-{sense}")
                out.append(line)
        L = history.scenario.L
        for e in history.driving.force_events():
            if e.moment not in ("start", "end"):
                continue
            T, X = chart.to_chart(e.event)
            marker, = ax.plot([X / L], [T / L], marker="o", markersize=st.impact_size, markerfacecolor=st.impact_colour,
                              markeredgecolor=st.impact_colour, linestyle="none", zorder=5,
                              gid=f"{letter}-force-event-{e.end}-{e.moment}")
            side = -1 if e.end == "left" else 1
            word = {"start": "on", "end": "off"}[e.moment]
            # inside the strip, beside its end: outside it the band is
            out += [marker, ax.text(X / L - side * 0.08, T / L, word, fontsize=fs["impact"], va="center",
                                    ha="left" if side < 0 else "right", zorder=6,
                                    gid=f"{letter}-force-event-label-{e.end}-{e.moment}")]
        return out

    def key(self, panel):
        st = panel.style
        pulls = any(p.least() < 0 for _, p in panel.history.driving.profiles())
        scale = tick_text(force_scale(panel.history), force_scale(panel.history))
        return [(ForceKey(st, pulls), f"force on an end: {FORCE_BAND:g} L\nwide at {scale} $Mc^2/L$"
                 + ("; hatched:\na pull" if pulls else "")),
                (Line2D([], [], marker="o", markersize=st.impact_size, markerfacecolor=st.impact_colour,
                        markeredgecolor=st.impact_colour, linestyle="none"), "a force starts (on)\nor ends (off)")]
