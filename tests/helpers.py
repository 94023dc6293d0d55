"""What several test files share, imported as `helpers` (tests/ is on pytest's `pythonpath`): histories run once
per process, several command lines run in one interpreter, and a renderer that measures figures without drawing.
"""

import functools

from rodparadox.io.scenario import builtin_names, load
from rodparadox.physics.models import run_rod
from rodparadox.physics.rigid import History


@functools.lru_cache(maxsize=None)
def particle_presets() -> tuple[str, ...]:
    """The built-in scenarios whose rod is struck by particles (the presets with forces, `sears`, `sears_moving`,
    `push`, are tested by tests/physics/test_forces*.py and the commands that show them)."""
    return tuple(n for n in builtin_names() if load(n).forces is None)


@functools.lru_cache(maxsize=None)
def history(name: str, v: float | None = None, L: float | None = None) -> History:
    """A built-in scenario's history at v and L (None: the scenario's own), run once per process; it is immutable."""
    return run_rod(load(name).with_overrides(v=v, L=L, rod="rigid"))


@functools.lru_cache(maxsize=None)
def causal_history(name: str, v: float | None = None, L: float | None = None):
    """A built-in scenario's causal rod (README, "The causal rod") at v and L, run once per process (fig2: ~0.3 s)."""
    return run_rod(load(name).with_overrides(v=v, L=L, rod="causal"))


# --- one command in this process: its result, or the one-sentence error it must give ---------------------------

def run(*args, expect=0):
    """Invoke the command line in this process; it must exit with `expect`."""
    from click.testing import CliRunner

    from sears_paradox_cli.main import main

    result = CliRunner().invoke(main, [str(a) for a in args])
    assert result.exit_code == expect, (result.output, result.exception)
    return result


def error_of(*args) -> str:
    """The one-sentence error a bad call prints; it must exit 2 and print no traceback."""
    result = run(*args, expect=2)
    assert isinstance(result.exception, SystemExit), result.exception
    lines = [line for line in result.output.splitlines() if line.startswith("Error: ")]
    assert len(lines) == 1, result.output
    return lines[0][len("Error: "):]


# --- stand-ins for a drawing, where a command-line test checks names, folders or messages, not the figure -------

def tex_figures_stood_in(monkeypatch) -> None:
    """`handout --format tex` writes each figure's PDF as a few bytes naming its block, paper and style (the
    figures are drawn and read in tests/handout and test_determinism)."""
    import rodparadox.handout.tex

    monkeypatch.setattr(rodparadox.handout.tex, "figure_pdf",
                        lambda block, paper, style: repr((type(block).__name__, paper, style)).encode())


def blank_figure(*args):
    """An empty 2 x 2 inch figure, whatever it stands for: written by the real writers (`render.figure_bytes`)."""
    from matplotlib.figure import Figure

    return Figure(figsize=(2, 2))


# --- shared by test_cli.py, test_animate_cli.py, test_robust_cli.py  ---------------------------------

#: runs several command lines one after another in one interpreter (argv[1]: JSON list of argvs, argv[2]: the
#: file the results go to, argv[3]: a file to point standard output at before each command, or ""). Before each
#: command a marker is written to standard output and error, so that each command's output can be told apart;
#: after it, both streams are flushed (data a fresh process would have left for its last flush is a failure) and
#: the drawing and integrating packages imported so far are recorded: the first command after which one is
#: there is the one that imported it.
_IN_ONE_PROCESS = """
import json, os, sys
from sears_paradox_cli.main import main
argvs, results, stdout_path = json.loads(sys.argv[1]), sys.argv[2], sys.argv[3]
MARK = b"\\n--- sears-paradox command %d ---\\n"
found = []
for k, argv in enumerate(argvs):
    if stdout_path:  # the command's standard output, afresh (a failed write points it at /dev/null)
        fd = os.open(stdout_path, os.O_WRONLY)
        os.dup2(fd, 1)
        os.close(fd)
    else:
        os.write(1, MARK % k)
    os.write(2, MARK % k)
    code, left = 0, None
    try:
        main(argv)
    except SystemExit as e:
        code = e.code if isinstance(e.code, int) else (0 if e.code is None else 1)
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except OSError as e:
            left = repr(e)
    found.append({"argv": argv, "code": code, "left_unflushed": left,
                  "modules": sorted({m.split(".")[0] for m in sys.modules} & {"matplotlib", "scipy", "numpy"})})
with open(results, "w") as f:
    json.dump(found, f)
"""


def commands_in_one_process(argvs, tmp_path, stdout_path: str = "") -> list[dict]:
    """Run `argvs` one after another in one fresh interpreter (a subprocess, its output in pipes; with
    `stdout_path`, standard output pointed at that file before each command). Returns, for each command, a dict:
    argv, code (exit status), stdout and stderr (its own part of each stream), left_unflushed (None, or the error a
    last flush raised) and modules (which of matplotlib, scipy, numpy were imported by then)."""
    import json
    import subprocess
    import sys

    results = tmp_path / "commands_in_one_process.json"
    process = subprocess.run([sys.executable, "-c", _IN_ONE_PROCESS, json.dumps(argvs), str(results), stdout_path],
                             capture_output=True, timeout=300)
    assert process.returncode == 0, process.stderr.decode()[-2000:]
    found = json.loads(results.read_text())
    assert [r["argv"] for r in found] == [list(a) for a in argvs]

    def parts(data: bytes) -> list[bytes]:
        pieces = data.split(b"\n--- sears-paradox command ")
        assert pieces[0] == b"", pieces[0]
        return [piece.split(b" ---\n", 1)[1] for piece in pieces[1:]]

    errs = parts(process.stderr)
    outs = parts(process.stdout) if not stdout_path else [b""] * len(argvs)
    assert len(errs) == len(outs) == len(argvs)
    for result, out, err in zip(found, outs, errs):
        result.update(stdout=out, stderr=err)
    return found


# --- shared by test_render.py, test_causal_draw.py, test_legible_panels.py  ---

#: one Agg renderer per dpi for every measuring draw: a text's extent depends only on its font and the dpi, and
#: matplotlib caches text metrics per renderer, so a new renderer for each figure measured every tick label again
_MEASURING_RENDERERS: dict = {}
#: the shared renderers' size in pixels; a larger figure gets its own renderer, as Agg would give it
_MEASURING_SIZE = 3000


def measuring_renderer(fig):
    """Lay out `fig` as Agg draws it, without rasterising (Figure.draw_without_rendering), and return the renderer
    that measured it: every text's extent and every tick is what a rendered PNG has. Call it inside the figure's
    style_context. The renderer is shared by every figure of the same dpi that fits it. The figure's own canvas is
    put back once it is measured: a PNG saved through the measuring canvas would be the shared renderer's."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg, RendererAgg

    class MeasuringCanvas(FigureCanvasAgg):
        def get_renderer(self):
            w, h = self.figure.bbox.size
            if max(w, h) > _MEASURING_SIZE:
                return super().get_renderer()
            dpi = self.figure.dpi
            if dpi not in _MEASURING_RENDERERS:
                _MEASURING_RENDERERS[dpi] = RendererAgg(_MEASURING_SIZE, _MEASURING_SIZE, dpi)
            return _MEASURING_RENDERERS[dpi]

    own = fig.canvas
    canvas = MeasuringCanvas(fig)
    try:
        # Figure.draw_without_rendering, without its way to the renderer: it found it by starting a PNG print,
        # whose FigureCanvasAgg.draw cleared the shared renderer's 3000 x 3000 pixels (36 MB, 3.6 ms a figure)
        # before the draw it cut short; the draw below is the one it then makes, every draw call disabled
        renderer = canvas.get_renderer()
        with renderer._draw_disabled():
            fig.draw(renderer)
        return renderer
    finally:
        fig.set_canvas(own)


# --- one fresh interpreter for the command-line tests of several files (test_cli, test_animate_cli, test_robust_cli)

#: part -> (rank, argvs): the command lines each of those tests runs in a fresh interpreter, registered when its
#: module is imported (pytest imports every test module before running any test). They run in one interpreter,
#: rank 0 first (the commands that must find matplotlib and scipy not yet imported), then rank 1 (those that draw),
#: by name within a rank. Each of those tests is marked xdist_group(SHARED_PROCESS_GROUP), so that one worker runs
#: them all and the interpreter is started once (five before: 4.7 CPU-s measured).
_SHARED_PROCESS_PARTS: dict[str, tuple[int, tuple[tuple[str, ...], ...]]] = {}
SHARED_PROCESS_GROUP = "shared-process"


def register_shared_process(part: str, argvs, draws: bool) -> None:
    """Add `argvs` (lists of words) under `part` to the commands the shared interpreter runs; `draws`: whether
    they may import matplotlib (then they run after every part that must not find it imported)."""
    assert _shared_process_results.cache_info().currsize == 0, f"{part} registered after the interpreter ran"
    _SHARED_PROCESS_PARTS[part] = (int(draws), tuple(tuple(str(w) for w in argv) for argv in argvs))


@functools.lru_cache(maxsize=None)
def _shared_process_results() -> tuple[dict[str, list[dict]], str]:
    import os
    import pathlib
    import tempfile

    folder = tempfile.TemporaryDirectory(prefix="shared-process-")
    _SHARED_PROCESS_FOLDERS.append(folder)  # removed when the worker exits
    order = sorted(_SHARED_PROCESS_PARTS, key=lambda part: (_SHARED_PROCESS_PARTS[part][0], part))
    argvs = [list(argv) for part in order for argv in _SHARED_PROCESS_PARTS[part][1]]
    before = os.getcwd()
    os.chdir(folder.name)  # its relative outputs land in an empty folder of its own (contextlib.chdir: Python 3.11)
    try:
        found = commands_in_one_process(argvs, pathlib.Path(folder.name))
    finally:
        os.chdir(before)
    for before, result in zip([{"modules": []}, *found], found):  # what the earlier commands had imported
        result["modules_before"] = before["modules"]
    results, k = {}, 0
    for part in order:
        n = len(_SHARED_PROCESS_PARTS[part][1])
        results[part], k = found[k:k + n], k + n
    return results, folder.name


_SHARED_PROCESS_FOLDERS: list = []


def shared_process(part: str) -> tuple[list[dict], str]:
    """The results (commands_in_one_process's dicts, copies) of `part`'s commands in the shared interpreter, and
    the folder it ran in (each command's relative outputs are there). Each result also has modules_before: which
    of matplotlib, scipy, numpy the commands before it had imported (a test that a command imports none of them
    checks its part's first has none before it: else an earlier command, not this one, imported it)."""
    import copy

    results, folder = _shared_process_results()
    return copy.deepcopy(results[part]), folder
