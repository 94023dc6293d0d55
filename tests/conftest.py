"""Fixtures and helpers shared by the test files, hypothesis's profile, and how the suite spreads over processes.

`python -m pytest` runs on two worker processes (pytest-xdist, `-n auto` capped at 2 in pyproject.toml and
below) with `--dist loadgroup`: tests are handed out one by one, except those of a file marked
`xdist_group(name)` (html's browser, the worksheet search, the page rules, the causal histories), which run on
one worker so that their session and module fixtures are built once. Every other cache below and in the test
files (histories, drawn figures) is filled by each worker for itself.
"""

import functools
import gc
import os
from pathlib import Path

import pytest
from hypothesis import settings

from rodparadox.io.scenario import load
from rodparadox.physics.rigid.engine import History
from rodparadox.physics.rigid import run

# CI (CI=true) runs the same generated examples every time, so a landing never hangs on a lucky draw;
# a developer's run draws new ones and finds what CI would not
settings.register_profile("ci", derandomize=True, database=None)
if os.environ.get("CI"):
    settings.load_profile("ci")

#: at most this many worker processes for `-n auto`: each imports matplotlib and collects the suite (a few
#: seconds), and a container's CPU quota is not seen by the CPU count
MAX_WORKERS = 2


def pytest_xdist_auto_num_workers(config):
    try:
        cores = len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        cores = os.cpu_count() or 1
    return max(1, min(cores, MAX_WORKERS))


#: tests between two moves of what a worker keeps (its caches) out of the garbage collector's reach
FREEZE_EVERY = 200
_tests_since_freeze = 0
# and those moves are the only full passes: the collector's own (generation 2) would walk everything not yet frozen
gc.set_threshold(*gc.get_threshold()[:2], 1_000_000)


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_protocol(item, nextitem):
    """Every FREEZE_EVERY tests: collect what is garbage, then freeze what survives (gc.freeze), so that the
    collector's full passes no longer walk the worker's caches (histories, figures, pages: millions of objects)
    again and again. Measured over the whole suite with 2 workers: full passes took 27 s of CPU, 10 s every 50
    tests, 6.5 s every 200 tests with no full pass of the collector's own; in a fresh clone (CI=true) the run took
    154 user CPU-s and 84 s wall with the first, 142 and 78 s with the second; a worker's peak memory 0.5 -> 0.7 GB.
    What a frozen object leaves behind later (a cache entry pushed out) is freed when the worker exits."""
    global _tests_since_freeze
    yield
    _tests_since_freeze += 1
    if _tests_since_freeze >= FREEZE_EVERY:
        gc.collect()
        gc.freeze()
        _tests_since_freeze = 0


@pytest.hookimpl(trylast=True)
def pytest_sessionfinish(session):
    """Nothing is collected once the session is over: a worker's caches (histories, figures, PDFs: millions of
    objects in reference cycles) were freed one cycle at a time as the interpreter shut down, 4 to 5 s of wall time
    after the last test (measured: the run ended 5.5 s after its last test, 0.5 s with this). Fixtures are already
    torn down here; what is left is memory the process returns to the system when it exits."""
    gc.freeze()


@functools.lru_cache(maxsize=None)
def history(name: str, v: float | None = None, L: float | None = None) -> History:
    """A built-in scenario's history at v and L (None: the scenario's own), run once per process; it is immutable."""
    return run(load(name).with_overrides(v=v, L=L))


@functools.lru_cache(maxsize=None)
def causal_history(name: str, v: float | None = None, L: float | None = None):
    """A built-in scenario's causal rod (README, "The causal rod") at v and L, run once per process (fig2: ~0.3 s)."""
    from rodparadox.physics.causal import run as run_causal

    return run_causal(load(name).with_overrides(v=v, L=L, rod="causal"))


@pytest.fixture
def unwritable_folder(tmp_path):
    """A folder no new file can be written into: /sys for root (who writes through mode bits), else a locked one."""
    if os.geteuid() == 0:
        yield Path("/sys")
        return
    folder = tmp_path / "locked"
    folder.mkdir()
    folder.chmod(0o500)
    try:
        yield folder
    finally:
        folder.chmod(0o700)


# --- shared by test_cli.py, test_animate_cli.py, test_robust_cli.py (t13cli) ---------------------------------

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


# --- shared by test_render.py, test_causal_draw.py, test_legible_panels.py (t13render) ---

#: one Agg renderer per dpi for every measuring draw: a text's extent depends only on its font and the dpi, and
#: matplotlib caches text metrics per renderer, so a new renderer for each figure measured every tick label again
_MEASURING_RENDERERS: dict = {}
#: the shared renderers' size in pixels; a larger figure gets its own renderer, as Agg would give it
_MEASURING_SIZE = 3000


def measuring_renderer(fig):
    """Lay out `fig` as Agg draws it, without rasterising (Figure.draw_without_rendering), and return the renderer
    that measured it: every text's extent and every tick is what a rendered PNG has. Call it inside the figure's
    style_context. The renderer is shared by every figure of the same dpi that fits it."""
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

    canvas = MeasuringCanvas(fig)
    fig.draw_without_rendering()
    return canvas.get_renderer()
