"""A whole diagram: panels laid out in points, each drawn from the layers, a suptitle and a legend.

`draw` makes a Figure of the size the layout chooses (the style's page bounds it); `draw_into` draws into a Figure
or SubFigure the caller has sized, fitting the panels into it, and hands back the panels and the artists by layer,
so a caller (an animation) can update artists with `set_data` instead of drawing again.
"""

from __future__ import annotations

import io
import logging
from contextlib import contextmanager, nullcontext
from dataclasses import dataclass
from types import MappingProxyType
from typing import Iterator, Mapping, Sequence

import matplotlib
from matplotlib.figure import Figure, SubFigure
from matplotlib.legend_handler import HandlerTuple

from rodparadox.physics import rod
from rodparadox.physics.history import RodHistory
from rodparadox.physics.frames import Frame, PANEL_LETTERS, time_window
from rodparadox.render.styles import FORMATS, STYLES, Style
from rodparadox.render.layer_base import has_fronts
from rodparadox.render.layers import Options, legend_entries
from rodparadox.render.layout import Layout, Page, Panel, font_sizes, lay_out, one_scale, panel_of, tick_step
from rodparadox.render.legibility import draws_motion_inset, inset_room, material_lines_that_fit, needs_room
from rodparadox.render.panel import draw_panel
from rodparadox.tolerances import FIT_SLACK


def _not_a_low_font_timestamp(record: logging.LogRecord) -> bool:
    return "timestamp seems very low" not in str(record.msg)


# matplotlib's Computer Modern symbol font (cmsy10.ttf, which mathtext reaches for some symbols) has head-table
# timestamps of 0; fontTools says so, as a warning on standard error, each time the PDF backend subsets it for a
# PDF (`plot --rod causal --format pdf` printed it twice). Nothing is wrong with the file written: that notice is dropped.
logging.getLogger("fontTools.ttLib.tables._h_e_a_d").addFilter(_not_a_low_font_timestamp)

# metadata that would make two runs differ (dates, versions) is left out
FIGURE_METADATA = {
    "svg": {"Date": None, "Creator": None},
    "pdf": {"Creator": None, "Producer": None, "CreationDate": None, "ModDate": None},
    "png": {"Software": None},
}


#: the resolution of a vector file's rasterised parts (the causal rod's compression shading, thousands of cells);
#: the vector parts do not depend on it (the rigid figures' bytes are the same at any value)
RASTER_DPI = 300


@contextmanager
def style_context(style: Style | str) -> Iterator[Style]:
    """Apply a style's rcParams while drawing or saving; restore them afterwards."""
    style = STYLES[style] if isinstance(style, str) else style
    with matplotlib.rc_context(style.rc):
        yield style


@dataclass(frozen=True)
class PanelInfo:
    """One drawn panel: its frame, its letter, its data box (the world-lines with their margin) and the axes'
    limits `box` (x0, x1, t0, t1, units of L), and its axes."""

    frame: Frame
    letter: str
    data_box: tuple[float, float, float, float]
    box: tuple[float, float, float, float]
    axes: object


@dataclass(frozen=True)
class Diagram:
    """A drawn diagram: the figure (or subfigure) it is in, its panels in order, and every enabled layer's
    artists by layer name (`rod`, `particle-A`, `impacts`, ...; `layers.LAYERS`) and panel letter."""

    figure: Figure | SubFigure
    panels: tuple[PanelInfo, ...]
    artists: Mapping[str, Mapping[str, tuple]]
    style: str = "default"  #: the style it was drawn in, whose fonts saving it needs

    def savefig(self, fname, **kwargs) -> None:
        """Save the figure as `Figure.savefig` does (the format from the file name or `format=`), in the diagram's
        style and without dates or versions in the file: `render.draw(...).savefig("fig2.pdf")`."""
        fmt = kwargs.get("format") or str(fname).rpartition(".")[2].lower()
        kwargs.setdefault("metadata", FIGURE_METADATA.get(fmt))
        with style_context(self.style) as st:
            kwargs.setdefault("dpi", st.png_dpi if fmt == "png" else RASTER_DPI)
            self.figure.savefig(fname, **kwargs)

    def _repr_png_(self) -> bytes:
        """What Jupyter shows for a diagram: a PNG at 100 dpi. (Not SVG: two inline SVGs in one notebook share
        their element ids, `a-rod_left` and matplotlib's clip paths, so a browser would mix up their parts.)"""
        buffer = io.BytesIO()
        with style_context(self.style):
            self.figure.savefig(buffer, format="png", dpi=100, metadata=FIGURE_METADATA["png"])
        return buffer.getvalue()


#: the legend's entry for the dashed lines of a driven rod's small-motion inset (`_Builder._make_inset_room`)
INSET_ENTRY = "magnified inset: each end without the forces"


def _checked(frames: Sequence[Frame]) -> tuple[Frame, ...]:
    if not 1 <= len(frames) <= len(PANEL_LETTERS):
        raise ValueError(f"draw takes 1 to {len(PANEL_LETTERS)} frames (panels (a) to (h)), got {len(frames)}")
    return tuple(frames)


def draw(history: RodHistory, frames: Sequence[Frame], style: str = "default", options: Options = Options()) -> Diagram:
    """The diagram of a scenario's history: one panel per frame, side by side, in the given order, in a new Figure
    sized by the layout (`Diagram.figure`), with its panels and every layer's artists."""
    frames = _checked(frames)
    with style_context(style) as st:
        builder = _Builder(history, frames, st, options)
        layout = builder.lay_out(Page.of_style(st))
        figure = Figure(figsize=(layout.width / 72, layout.height / 72), dpi=72)
        return builder.render(figure, layout, layout.width, layout.height)


def draw_both(rigid: RodHistory, causal, frames: Sequence[Frame], style: str = "default",
              options: Options = Options()) -> Diagram:
    """The two rod models of one scenario in one figure (`plot --rod both`): a row of panels for the rigid rod
    above a row for the causal rod, one panel per frame, each frame's two panels on the same scales (their data
    boxes joined), one legend for both."""
    frames = _checked(tuple(frames) * 2)[:len(frames)]
    with style_context(style) as st:
        builder = _Builder((rigid, causal), frames, st, options)
        layout = builder.lay_out(Page.of_style(st))
        figure = Figure(figsize=(layout.width / 72, layout.height / 72), dpi=72)
        return builder.render(figure, layout, layout.width, layout.height)


def draw_panel_into(ax, history: RodHistory, frame: Frame, style: str = "default", options: Options = Options(),
                    letter: str = "a") -> Mapping[str, tuple]:
    """Draw one frame's panel of a history into a caller's Axes (as mplhep's functions do); returns its artists by
    layer name (`layers.LAYERS`: `rod`, `particle-A`, `impacts`, ...), labels included.

    The panel is the one `draw` makes for that frame: equal scales, ticks, axis names and title, every enabled
    layer, labels placed clear of the lines. Its layout is computed for the Axes' size on its figure, which the
    caller keeps; the legend and the figure's title are the caller's (`legend_entries` gives the handles). Draw
    inside `style_context(style)` and save inside it too to get the style's fonts.
    """
    dpi = ax.get_figure(root=True).dpi
    width, height = ax.bbox.width * 72 / dpi, ax.bbox.height * 72 / dpi  # the Axes' size in points
    with style_context(style) as st:
        builder = _Builder(history, (frame,), st, options)
        metrics = builder.lay_out(Page(4 * width, 4 * height, height)).metrics  # type sizes and tick lengths
        [p] = builder.panels
        # the Axes is the panel: the data box padded to the Axes' shape (equal scales), ticks at one nice step
        p.width, p.height = width, height
        x0, x1, t0, t1 = p.data_box
        spare = (width / height) * (t1 - t0) - (x1 - x0)
        p.box = [x0 - spare / 2, x1 + spare / 2, t0, t1] if spare >= 0 else \
            [x0, x1, t0 + spare * height / width / 2, t1 - spare * height / width / 2]
        p.title_lines = metrics.wrap(p.title, width)
        step = tick_step(p.box)
        ax.set_gid(f"{letter}-axes")
        return MappingProxyType(draw_panel(ax, p, (step, step), metrics, history, st, options, builder.clock_step))


def natural_size(history: RodHistory, frames: Sequence[Frame], width: float, height: float, style: str = "default",
                 options: Options = Options()) -> tuple[float, float]:
    """The (width, height) in points `draw` would give the diagram on a page `width` x `height` points (its panels
    no taller than the style's): the size of a target `draw_into` fills exactly, e.g. a handout's full text width."""
    frames = _checked(frames)
    with style_context(style) as st:
        layout = _Builder(history, frames, st, options).lay_out(Page(width, height, st.panel_height * 72))
    return layout.width, layout.height


def draw_into(target: Figure | SubFigure, history: RodHistory, frames: Sequence[Frame], style: str = "default",
              options: Options = Options()) -> Diagram:
    """Draw the diagram into a Figure or SubFigure the caller has sized; returns its panels and artists.

    The layout is the one `draw` makes, with the target's size (in points) as the page: the panels are as tall
    as the target lets them be, and the whole is centred in the target. A target too small for panels with room
    for their tick labels is refused (ValueError, naming the size needed). The target's style is the caller's:
    save it inside `style_context(style)` (as `figure_bytes` does) to get the style's fonts.
    """
    frames = _checked(frames)
    dpi = (target.get_figure(root=True) if isinstance(target, SubFigure) else target).dpi
    width, height = target.bbox.width * 72 / dpi, target.bbox.height * 72 / dpi  # points
    with style_context(style) as st:
        builder = _Builder(history, frames, st, options)
        layout = builder.lay_out(Page(width, height, height))
        if layout.width > width + FIT_SLACK or layout.height > height + FIT_SLACK:
            raise ValueError(f"the diagram needs at least {layout.width / 72:.2f} x {layout.height / 72:.2f} in; "
                             f"the target is {width / 72:.2f} x {height / 72:.2f} in.")
        return builder.render(target, layout, width, height)


def figure_bytes(figure: Figure, fmt: str, style: str = "default") -> bytes:
    """The figure as SVG, PDF or PNG bytes; the same figure always gives the same bytes."""
    if fmt not in FORMATS:
        raise ValueError(f"unknown format {fmt!r}; use one of {', '.join(FORMATS)}")
    if fmt == "pdf":  # fontTools and the PDF backend: imported only for a PDF (0.09 CPU-s of a process's start)
        from rodparadox.render.pdf_fonts import kept_subsets

        keeping = kept_subsets()
    else:  # SVG and PNG embed no font subsets
        keeping = nullcontext()
    with style_context(style) as st, keeping:  # a PDF's font subsets: each made once per process
        buffer = io.BytesIO()
        figure.savefig(buffer, format=fmt, metadata=FIGURE_METADATA[fmt], dpi=st.png_dpi if fmt == "png" else RASTER_DPI)
        return buffer.getvalue()


def _same_scales(panels: list[Panel], per_row: int) -> None:
    """Each frame's panels, one per rod model, get one data box (the union of theirs) and say their model."""
    for k in range(per_row):
        same = panels[k::per_row]
        box = (min(p.data_box[0] for p in same), max(p.data_box[1] for p in same),
               min(p.data_box[2] for p in same), max(p.data_box[3] for p in same))
        for p in same:
            p.data_box, p.box = box, list(box)
            p.title = p.title.replace(") frame ", f") {p.history.model} rod, frame ", 1)
            p.title_lines = [p.title]


def _causal_handlers(history) -> dict:
    """The legend handlers of the causal rod's entries (its compression scale), where one is drawn: a rigid figure
    never imports `causal_layers`. (`tuple` beside them: the rod's entry, strip and line in one.)"""
    if not any(has_fronts(h) for h in (history if isinstance(history, tuple) else (history,))):
        return {}
    from rodparadox.render.causal_layers import HANDLER_MAP

    return HANDLER_MAP


def _force_handlers(history) -> dict:
    """The legend handler of the force bands' entry (its scale), where a rod is driven by forces."""
    if not any(h.driving is not None for h in (history if isinstance(history, tuple) else (history,))):
        return {}
    from rodparadox.render.force_layers import HANDLER_MAP

    return HANDLER_MAP


class _Builder:
    """One diagram's panels, laid out and then drawn into a target."""

    def __init__(self, history: RodHistory | tuple, frames: tuple[Frame, ...], style: Style, options: Options):
        histories = history if isinstance(history, tuple) else (history,)  # two: the rigid row, the causal row
        self.history, self.style, self.options = histories[0], style, options
        self.fs = font_sizes(style)
        letters = iter(PANEL_LETTERS)
        windows = [None] * len(frames)
        if len(histories) > 1:  # each frame's panels over one time window: the union of the models' own
            spans = [[time_window(h, frame) for h in histories] for frame in frames]
            windows = [(min(lo for lo, _ in s), max(hi for _, hi in s)) for s in spans]
        self.panels: list[Panel] = [panel_of(h, next(letters), frame, window) for h in histories
                                    for frame, window in zip(frames, windows)]
        self.per_row = len(frames) if len(histories) > 1 else None
        if options.equal_scales:
            one_scale(self.panels)
        elif self.per_row:
            _same_scales(self.panels, len(frames))
        # one clock step for every panel (proper time is the same in every frame), from the longest time span
        self.clock_step = rod.clock_step(max(p.view.t_range[1] - p.view.t_range[0] for p in self.panels))
        self.histories = history
        self.legend = self._with_inset_entry(legend_entries(style, history, options, self.clock_step))
        self.rod_lines = {p.letter: options.rod_lines for p in self.panels}  # material lines drawn in each panel
        # a comparison says first what every rod is struck by, and where each rod's first impacts fall
        self.note = ""
        if len(histories) > 1:  # imported only here: a figure of one rod loads no comparison
            from rodparadox.tables.comparison import comparison_note

            self.note = comparison_note(histories, frames)

    def lay_out(self, page: Page) -> Layout:
        """The layout; with material lines, laid out again while the legend's count of them changes: the count
        follows each panel's width, and only falls, so this ends."""
        while True:
            layout = lay_out(self.history, self.panels, self.style, self.fs, self.legend[1], page, self.options.titled,
                             self.per_row, self.note)
            if self._make_inset_room():  # a small-motion inset's legend entry, or room for it: laid out again
                continue
            if not self.options.rod_lines:
                return layout
            fits = {p.letter: min(self.rod_lines[p.letter], material_lines_that_fit(
                p.history if p.history is not None else self.history, p.view, p.worldlines,
                p.width / (p.box[1] - p.box[0]), self.options.rod_lines))
                for p in self.panels}
            if fits == self.rod_lines:
                return layout
            self.rod_lines = fits
            self.legend = self._with_inset_entry(legend_entries(self.style, self.histories, self.options,
                                                                self.clock_step, fits))

    def _make_inset_room(self) -> bool:
        """After a layout: mark each panel of a driven rod that draws the inset of its small motion
        (`legibility.draws_motion_inset`; the legend then names the inset's dashed lines), and widen, once, each
        whose inset no corner holds without hiding a world-line (`needs_room`, `inset_room`: sears_moving at 0.95
        in S, the rod at rest as wide as the panel); each frame's panels keep one box. True if anything changed
        (the layout is then made again; a mark or a widening is never undone, so this ends)."""
        if not self.options.insets:
            return False
        changed = widened = False
        for p in self.panels:
            history = p.history if p.history is not None else self.history
            if p.motion_inset or not draws_motion_inset(history, p.view, p.worldlines, p.box, p.width, p.height):
                continue
            p.motion_inset = changed = True
            if not p.inset_room and needs_room(p.worldlines, p.box, p.width, p.height):
                box = list(p.data_box)
                inset_room(p.worldlines, box)
                p.data_box, p.box, p.inset_room = tuple(box), list(box), True
                widened = True
        if widened:
            if self.options.equal_scales:
                one_scale(self.panels)
            elif self.per_row:
                _same_scales(self.panels, self.per_row)
        if changed:
            self.legend = self._with_inset_entry(self.legend)
        return changed

    def _with_inset_entry(self, legend: tuple[list, list[str]]) -> tuple[list, list[str]]:
        """The legend, with the dashed lines of a driven rod's small-motion inset where a panel has room for it
        (`legibility.draws_motion_inset`: its note is then only its factor, in the ticks' type)."""
        if not any(p.motion_inset for p in self.panels) or INSET_ENTRY in legend[1]:
            return legend
        from matplotlib.lines import Line2D

        rod = self.style.rod
        handle = Line2D([], [], color=rod.colour, linewidth=0.8, linestyle=(0, (4.0, 2.0)))
        return [*legend[0], handle], [*legend[1], INSET_ENTRY]

    def render(self, target: Figure | SubFigure, layout: Layout, width: float, height: float) -> Diagram:
        """Draw the laid-out diagram into a target `width` x `height` points, centred in it."""
        m, fs = layout.metrics, self.fs
        ox, oy = (width - layout.width) / 2, (height - layout.height) / 2  # 0 when the target is the layout's size
        infos, artists = [], {}
        y = layout.height - layout.top
        for row, block in zip(layout.rows, layout.blocks):
            y -= block
            x = (layout.width - m.row_width(row)) / 2
            for p in row:
                step = layout.steps[p.letter]
                x += m.gutter(p, step)
                ax = target.add_axes(((ox + x) / width, (oy + y + m.bottom_axis) / height, p.width / width,
                                      p.height / height))
                x += p.width + m.gap
                ax.set_gid(f"{p.letter}-axes")
                drawn = draw_panel(ax, p, step, m, self.history, self.style, self.options, self.clock_step,
                                   self.rod_lines[p.letter], crowded=self.per_row is not None)
                for name, layer_artists in drawn.items():
                    artists.setdefault(name, {})[p.letter] = layer_artists
                infos.append(PanelInfo(p.view.frame, p.letter, tuple(p.data_box), tuple(p.box), ax))
            y -= m.row_gap
        top_spare = height - oy - layout.height  # above the layout, in the target
        target.text(0.5, 1 - (top_spare + 7) / height, layout.suptitle, ha="center", va="top", fontsize=fs["suptitle"],
                    gid="title")
        handles, labels = self.legend
        if layout.note_lines:  # below the legend, as wide as the figure, from its left margin
            target.text((ox + m.right) / width, (oy + layout.note_height - 4) / height, "\n".join(layout.note_lines),
                        ha="left", va="top", fontsize=fs["legend"], linespacing=1.2, gid="comparison-note")
        legend = target.legend(handles, labels, loc="upper center",
                               bbox_to_anchor=(0.5, (oy + layout.note_height + layout.legend_height - 2) / height),
                               ncol=layout.legend_columns, fontsize=fs["legend"], handlelength=3.2, handletextpad=0.6,
                               columnspacing=1.6, borderaxespad=0.0, borderpad=0.0, labelspacing=0.5,
                               handler_map={tuple: HandlerTuple(ndivide=1), **_causal_handlers(self.histories),
                                            **_force_handlers(self.histories)})
        legend.set_gid("legend")
        infos.sort(key=lambda info: info.letter)
        return Diagram(target, tuple(infos),
                       MappingProxyType({name: MappingProxyType(by_panel) for name, by_panel in artists.items()}),
                       self.style.name)
