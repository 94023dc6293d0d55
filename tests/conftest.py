"""Fixtures shared by the test files, hypothesis's profile, and how the suite spreads over processes (the
helpers the test files import are in tests/helpers.py, on the path through pyproject's `pythonpath`).

`python -m pytest` runs on two worker processes (pytest-xdist, `-n auto` capped at 2 in pyproject.toml and
below) with `--dist loadgroup`: tests are handed out one by one, except those of a file marked
`xdist_group(name)` (html's browser, the worksheet search, the page rules, the causal histories), which run on
one worker so that their session and module fixtures are built once. Every other cache below and in the test
files (histories, drawn figures) is filled by each worker for itself.
"""

import compileall
import gc
import os
import sys
from pathlib import Path

import pytest


# Bytecode: where PYTHONDONTWRITEBYTECODE is set (this machine's image sets it), every process the tests start
# (hundreds of `sears-paradox` runs) compiled the package from source again, and every worker rewrote and compiled
# every test module again: measured 0.42 against 0.29 user CPU-s for one `sears-paradox events fig2`. The package
# is compiled once here (written next to the sources in __pycache__, which git ignores), and pytest may cache its
# rewritten test modules; a user's own setting for their other programs is left as it is.
# hypothesis is imported below, not above: pytest rewrites the asserts of every module of a package that ships a
# pytest plugin (all of hypothesis), and keeps the rewritten code only where bytecode may be written. Imported
# before this line, each of the three processes (the controller, two workers) rewrote hypothesis's modules again:
# a process's collection took 3.6 user CPU-s, 2.1 with them kept (the controller, which starts first, writes them).
sys.dont_write_bytecode = False
_ROOT = Path(__file__).resolve().parent.parent
compileall.compile_dir(_ROOT / "rodparadox", quiet=2)
compileall.compile_dir(_ROOT / "cli", quiet=2)

from hypothesis import settings  # noqa: E402 (after dont_write_bytecode: see above)

# CI (CI=true) runs the same generated examples every time, so a landing never hangs on a lucky draw;
# a developer's run draws new ones and finds what CI would not
# and no deadline: a shared CI machine may run an example several times slower than a developer's, which is not an error
settings.register_profile("ci", derandomize=True, database=None, deadline=None)
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
# and those moves are the only passes of the collector: its own would walk the young objects of every test again and
# again (generations 0 and 1: about 10,000 passes a worker) and everything not yet frozen (generation 2). What is
# garbage waits for the next move, and most of a test's garbage is freed as soon as it is dropped (no cycles).
# Measured over the whole suite with 2 workers: the collector took 12.7 CPU-s with its own young passes, 8.9 without
# them; a worker's peak memory 0.76-0.82 -> 0.82-0.92 GB.
gc.disable()


def pytest_collection_modifyitems(items):
    """The long tests (marked `slow`) first, the rest in their files' order: the two workers take tests in this
    order, so that the run ends with short tests on both rather than with one worker building the documentation
    site or running the notebook while the other has nothing left (measured: one worker ended 3.5 to 4.5 s before
    the other). `--dist loadgroup` still hands out each group (its tests together) before any single test."""
    items.sort(key=lambda item: item.get_closest_marker("slow") is None)  # stable: the files' order kept within


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


@pytest.fixture
def here(tmp_path, monkeypatch):
    """An empty folder to run a command in (its default `outputs/` lands there)."""
    monkeypatch.chdir(tmp_path)
    return tmp_path
