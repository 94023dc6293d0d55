"""The SHA-256 of every output of every command over a grid of presets, speeds, styles and formats.

A refactoring that should change nothing a user sees is checked by running this before and after it and
comparing the two lists (`diff`). It drives the installed CLI in one process (click's test runner), which
gives the same bytes as separate processes (the determinism tests check that).

    python tests/output_hashes.py > before.txt      # on the old tree
    python tests/output_hashes.py > after.txt       # on the new one
    diff before.txt after.txt

`--quick` hashes a smaller grid (one speed, no animations of every style). `--models` adds the causal rod, both
rods, the rod's own view and the html page at the presets' own speeds (with `--quick`, their grid alone).
`--forces` adds the rods driven by forces (push, sears, sears_moving) in every command (with `--quick`, their
grid alone).
"""

from __future__ import annotations

import hashlib
import sys
import tempfile
from pathlib import Path

from click.testing import CliRunner

from sears_paradox_cli.main import main

PRESETS = ("fig1", "fig2", "single", "off_timing", "unequal_masses", "while_turning")
STYLES = ("default", "print", "slides")


def _digest(path: Path) -> list[str]:
    if path.is_dir():
        return [line for child in sorted(path.rglob("*")) if child.is_file() for line in _digest_file(child, path)]
    return _digest_file(path, path.parent)


def _digest_file(path: Path, root: Path) -> list[str]:
    return [f"{hashlib.sha256(path.read_bytes()).hexdigest()[:16]}  {path.relative_to(root)}"]


def _run(runner: CliRunner, args: list[str], out: Path) -> list[str]:
    result = runner.invoke(main, args, catch_exceptions=True)
    head = f"$ sears-paradox {' '.join(args)}  -> {result.exit_code}"
    stdout = result.stdout_bytes.replace(str(out).encode(), b"OUT")
    stderr = result.stderr_bytes.replace(str(out).encode(), b"OUT")
    lines = [head, f"  stdout {hashlib.sha256(stdout).hexdigest()[:16]}  stderr {hashlib.sha256(stderr).hexdigest()[:16]}"]
    for path in sorted(out.iterdir()) if out.is_dir() else []:
        lines += ["  " + line for line in _digest(path)]
    return lines


def commands(quick: bool) -> list[list[str]]:
    speeds = (None,) if quick else (None, "0.3", "0.95")
    grid: list[list[str]] = []
    for name in PRESETS:
        for v in speeds:
            vv = [] if v is None else ["--v", v]
            for fmt in ("text", "markdown", "latex"):
                grid.append(["events", name, *vv, "--format", fmt])
            grid.append(["events", name, *vv, "--frame-velocity", "0.3"])
            for fmt in ("json", "csv"):
                grid.append(["export", name, *vv, "--format", fmt])
            for style in STYLES:
                grid.append(["plot", name, *vv, "--style", style, "--format", "svg,pdf,png", "-o", "{out}"])
            grid.append(["plot", name, *vv, "--frame", "rest,moving,0.3", "--other-axes", "--light-cones",
                         "--hyperbolae", "--grid", "--rod-lines", "5", "--rod-now", "--proper-time", "-o", "{out}"])
            for fmt in ("text", "json", "csv", "markdown", "latex"):
                grid.append(["ledger", name, *vv, "--format", fmt, "--at", "0.5,1,1.5"])
            grid.append(["ledger", name, *vv, "--format", "json"])
            for style in STYLES:
                grid.append(["ledger", name, *vv, "--style", style, "--format", "svg,pdf,png", "-o", "{out}"])
        for style in STYLES if not quick else ("default",):
            for mode in ("now", "boost"):
                grid.append(["animate", name, "--mode", mode, "--style", style, "--fps", "5", "--seconds", "1.2",
                             "-o", "{out}"])
            grid.append(["animate", name, "--format", "png", "--style", style, "--fps", "4", "--seconds", "1",
                         "-o", "{out}/stills"])
        for fmt in ("pdf", "tex"):
            for extra in ([], ["--worksheet"], ["--paper", "letter", "--style", "slides"]):
                grid.append(["handout", name, "--format", fmt, *extra, "-o", "{out}" if fmt == "pdf" else "{out}/tex"])
    grid.append(["handout", "fig1", "fig2", "--frame", "both,0.3", "-o", "{out}"])
    return grid


def model_commands() -> list[list[str]]:
    """The causal rod, both rods, the rod's own view and the html page, each preset at its own speed."""
    grid: list[list[str]] = []
    for name in PRESETS:
        for rod in ("causal", "both"):
            grid.append(["events", name, "--rod", rod] if rod == "causal" else ["events", name, "--rod", "causal",
                                                                                   "--format", "markdown"])
            grid.append(["plot", name, "--rod", rod, "--frame", "both,rod", "--format", "svg,pdf", "-o", "{out}"])
            grid.append(["ledger", name, "--rod", rod, "--format", "json"])
            grid.append(["ledger", name, "--rod", rod, "--format", "text"])
            grid.append(["ledger", name, "--rod", rod, "--format", "svg", "-o", "{out}"])
            grid.append(["handout", name, "--rod", rod, "-o", "{out}"])
            grid.append(["html", name, "--rod", rod, "-o", "{out}"])
        grid.append(["export", name, "--rod", "causal", "--format", "json"])
        grid.append(["plot", name, "--frame", "rod,rest", "--format", "svg", "-o", "{out}"])
        grid.append(["animate", name, "--rod", "causal", "--fps", "4", "--seconds", "1", "-o", "{out}"])
        grid.append(["html", name, "-o", "{out}"])
    return grid


FORCES = ("push", "sears", "sears_moving")


def forces_commands() -> list[list[str]]:
    """The rods driven by forces at the ends: every command, both rods, at the presets' own speeds and one other."""
    grid: list[list[str]] = []
    for name in FORCES:
        for vv in ([], ["--v", "0.3"]):
            for rod in ("rigid", "causal", "both"):
                grid.append(["events", name, *vv, "--rod", rod])
                grid.append(["export", name, *vv, "--rod", rod, "--format", "json"])
                grid.append(["plot", name, *vv, "--rod", rod, "--format", "svg,pdf", "-o", "{out}"])
                grid.append(["ledger", name, *vv, "--rod", rod, "--format", "json"])
                grid.append(["ledger", name, *vv, "--rod", rod, "--format", "svg", "-o", "{out}"])
                grid.append(["handout", name, *vv, "--rod", rod, "-o", "{out}"])
            grid.append(["plot", name, *vv, "--frame", "both,rod", "--style", "print", "--format", "pdf", "-o", "{out}"])
            grid.append(["handout", name, *vv, "--worksheet", "-o", "{out}"])
        grid.append(["export", name, "--format", "csv"])
        grid.append(["ledger", name, "--format", "text"])
        grid.append(["animate", name, "--fps", "4", "--seconds", "1", "-o", "{out}"])
        grid.append(["animate", name, "--rod", "causal", "--mode", "boost", "--fps", "4", "--seconds", "1", "-o", "{out}"])
        grid.append(["html", name, "--rod", "both", "-o", "{out}"])
    return grid


def main_(argv: list[str]) -> int:
    quick = "--quick" in argv
    runner = CliRunner(mix_stderr=False) if 'mix_stderr' in CliRunner.__init__.__code__.co_varnames else CliRunner()
    with tempfile.TemporaryDirectory() as tmp:
        extra = (model_commands() if "--models" in argv else []) + (forces_commands() if "--forces" in argv else [])
        grid = commands(quick) if not (quick and extra) else []
        for k, args in enumerate(grid + extra):
            out = Path(tmp) / f"run{k}"
            out.mkdir()
            args = [a.replace("{out}", str(out)) for a in args]
            for line in _run(runner, args, out):
                print(line.replace(str(out), "OUT"), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main_(sys.argv[1:]))
