"""What a new user broke in the newer commands (issue 15): the command line and its files at the edges.

Signals and pipes are tried on real processes; everything else in-process (click's runner).
"""

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from click.testing import CliRunner

from helpers import SHARED_PROCESS_GROUP, register_shared_process, shared_process
from helpers import error_of, run, tex_figures_stood_in
from sears_paradox_cli.main import main




def _cli() -> list[str]:
    script = Path(sys.executable).parent / "sears-paradox"
    if script.exists():
        return [str(script)]
    return [sys.executable, "-c", "from sears_paradox_cli.main import main; main()"]


# --- item 8: output lost in a pipe is exit 141, whatever the buffering ------------------------------------

@pytest.mark.parametrize("unbuffered", ["1", ""])
@pytest.mark.parametrize("args", [["ledger", "fig2", "--format", "json"],
                                  ["ledger", "fig2", "--format", "json", "-o", "/dev/stdout"]])
def test_a_reader_that_leaves_after_a_pause_is_exit_141(args, unbuffered):
    """The table (215 kB) is more than a pipe holds (64 kB): a reader that takes 10 bytes a moment later and leaves
    loses the rest, which the README says is status 141. With PYTHONUNBUFFERED the text stream handed the
    system one write and dropped what the pipe did not take, exiting 0."""
    env = dict(os.environ, PYTHONUNBUFFERED=unbuffered)
    process = subprocess.Popen(_cli() + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env)
    _wait_until_full(process)  # the pipe fills and the writer waits
    assert len(process.stdout.read(10)) == 10
    process.stdout.close()
    stderr = process.stderr.read().decode()
    assert (process.wait(timeout=60), stderr) == (141, "")


def _wait_until_full(process) -> None:
    """Until the writer has filled its standard output's pipe and waits (Linux: the pipe holds as many bytes as it
    can take, seen without reading them); elsewhere a second's pause, as this test had everywhere (a second, most
    of it waiting, where the writer fills the pipe in about a third)."""
    try:
        import fcntl
        import termios

        capacity = fcntl.fcntl(process.stdout.fileno(), fcntl.F_GETPIPE_SZ)
        FIONREAD = termios.FIONREAD
    except (ImportError, AttributeError, OSError):
        time.sleep(1.0)
        return
    held = bytearray(4)
    deadline = time.monotonic() + 60
    while True:
        fcntl.ioctl(process.stdout.fileno(), FIONREAD, held)
        if int.from_bytes(held, sys.byteorder) >= capacity:
            return
        assert process.poll() is None and time.monotonic() < deadline, "the writer never filled the pipe"
        time.sleep(0.02)


# --- item 15: -o /dev/stdout into a pipe ----------------------------------------------------------------

#: -o /dev/stdout into a pipe: the command, and how its standard output starts
TO_DEV_STDOUT = [
    (["ledger", "fig2", "--format", "json"], b'{\n "format": "sears-paradox-ledger/1"'),
    (["export", "fig2", "--format", "csv"], b"frame,kind,name"),
    (["plot", "fig2", "--format", "svg"], b"<?xml"),
]
#: a table to -o /dev/stdout without --format
TABLES_TO_DEV_STDOUT = [(["export", "fig2"], b'{\n "format": "sears-paradox/1"'),
                        (["ledger", "fig2"], b"fig2: v = 0.6, L = 1; E in M c^2")]


register_shared_process("to_dev_stdout", [args + ["-o", "/dev/stdout"] for args, _ in TO_DEV_STDOUT + TABLES_TO_DEV_STDOUT],
                        draws=True)


@pytest.mark.xdist_group(SHARED_PROCESS_GROUP)
def test_output_to_dev_stdout_in_a_pipe_is_the_data_alone():
    """/dev/stdout in a pipe leads to `pipe:[...]`, no path: it was "no such file or directory"; now it is written
    in place, and the path written is not printed into the data.

    And a table to /dev/stdout takes the format of standard output: no extension to read the format from, json
    for export and text for ledger, as without -o (test_a_table_to_dev_stdout_takes_the_format_of_standard_output
    before). The five commands (a process each before) run one after another in one interpreter whose standard
    output is a pipe (helpers.shared_process's, with other tests' commands); each has its own status, standard
    output and standard error."""
    calls = TO_DEV_STDOUT + TABLES_TO_DEV_STDOUT
    results, _ = shared_process("to_dev_stdout")
    assert [r["argv"] for r in results] == [args + ["-o", "/dev/stdout"] for args, _ in calls]
    for result, (args, start) in zip(results, calls):
        assert (result["code"], result["stderr"], result["left_unflushed"]) == (0, b"", None), result
        assert result["stdout"].startswith(start), result["stdout"][:200]
        assert b"/dev/stdout" not in result["stdout"]


def test_a_figure_to_dev_stdout_needs_its_format():
    assert error_of("plot", "fig2", "-o", "/dev/null") == ("option -o: cannot tell the format of '/dev/null' from "
                                                          "its extension; name it .svg, .pdf, .png or give --format.")
    run("plot", "fig2", "--frame", "rest", "--format", "pdf", "-o", "/dev/null")  # one panel: less to draw


# --- item 7: ledger's -o and --format contradicting ------------------------------------------------------

@pytest.mark.parametrize("name, fmt", [("x.svg", "json"), ("x.png", "text"), ("x.pdf", "csv"), ("x.tex", "svg"),
                                       ("x.md", "pdf"), ("x.JSON", "png"), ("x.md", "latex"), ("x.csv", "json")])
def test_ledger_refuses_an_extension_that_contradicts_the_format(tmp_path, monkeypatch, name, fmt):
    monkeypatch.chdir(tmp_path)
    assert error_of("ledger", "fig2", "-o", name, "--format", fmt) == (f"option -o names {name!r} but --format is "
                                                                      f"{fmt}; make them agree.")
    assert list(tmp_path.iterdir()) == []


def test_ledger_still_writes_an_agreeing_or_unknown_extension(tmp_path, monkeypatch):
    from rodparadox import render
    from rodparadox.render import ledger_figure

    monkeypatch.chdir(tmp_path)
    run("ledger", "fig2", "-o", "x.TXT", "--format", "text")
    run("ledger", "fig2", "-o", "table.dat", "--format", "json")
    # the figure's name is checked, not the figure (drawn and read in test_ledger_cli): it is stood in for
    monkeypatch.setattr(ledger_figure, "draw", lambda history, frames, style: (frames, style))
    monkeypatch.setattr(render, "figure_bytes", lambda figure, fmt, style="default": repr((figure, fmt)).encode())
    run("ledger", "fig2", "-o", "x.svg", "--format", "svg")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["table.dat", "x.TXT", "x.svg"]
    assert (tmp_path / "table.dat").read_text().startswith('{\n "format": "sears-paradox-ledger/1"')


# --- item 9: handout --format tex -o DIR is DIR every time ------------------------------------------------

def test_handout_tex_writes_into_the_folder_named_every_time(tmp_path, monkeypatch):
    """`single` in the rest frame alone (fig2 in both before): the same -o DIR handling, in fewer pieces. The -o
    DIR handling is checked, not the figures: each stands in as a few bytes (drawn in tests/handout)."""
    tex_figures_stood_in(monkeypatch)
    folder = tmp_path / "pieces"
    first = run("handout", "single", "--frame", "rest", "--format", "tex", "-o", folder, "-q")
    second = run("handout", "single", "--frame", "rest", "--format", "tex", "-o", folder)
    assert first.output == ""
    assert (folder / "handout.tex").is_file() and not (folder / "single_handout_rest").exists()
    printed = second.output.splitlines()
    assert printed and all(line.startswith(f"{folder}/") and line.endswith(" (unchanged)") for line in printed)
    assert {Path(line.split(" ")[0]).name for line in printed} == {p.name for p in folder.iterdir()}


# --- item 11: YAML 1.1's other numbers --------------------------------------------------------------------

@pytest.mark.parametrize("text, meant", [("1:30", "in base 60 as 90"),  # 1*60 + 30
                                         ("-1:30", "in base 60 as -90"),
                                         ("1:30.5", "in base 60 as 90.5"),
                                         ("010", "in octal as 8"),  # 1*8 + 0
                                         ("0x10", "in hexadecimal as 16"),
                                         ("0b11", "in binary as 3"),
                                         ("1_000", "skipping the underscores, as 1000")])
def test_a_number_yaml_reads_otherwise_than_its_digits_is_refused(tmp_path, text, meant):
    scenario = tmp_path / "s.yaml"
    scenario.write_text(f"v: 0.6\nparticles:\n  A: {{gap: 0.5}}\n  B:\n    gap: 1\n    speed: 0.6\nL: {text}\n")
    assert error_of("events", scenario) == (f"{scenario}, line 7: L is {text}, which YAML 1.1 reads {meant}; write "
                                            f"the number in plain decimal digits.")
    scenario.write_text(f"v: 0.6\nparticles:\n  A:\n    gap: {text}\n")
    assert error_of("events", scenario).startswith(f"{scenario}, line 4: particles.A.gap is {text}, which YAML 1.1")


@pytest.mark.parametrize("text, L", [("2.", "2"), (".5", "0.5"), ("1e1", "10"), ("007.5", "7.5"), ("+3", "3"),
                                     ("'2'", None)])
def test_a_decimal_number_in_yaml_is_read_as_written(tmp_path, text, L):
    scenario = tmp_path / "s.yaml"
    scenario.write_text(f"v: 0.6\nL: {text}\nparticles:\n  A: {{gap: 0.5}}\n")
    if L is None:  # a quoted number is text: the scenario's own check says so
        assert "L" in error_of("events", scenario)
        return
    assert run("events", scenario).output.startswith(f"s: v = 0.6, L = {L} ")


# --- item 15: one rule for numbers on the command line: decimal digits, no Python-only underscores -----------

@pytest.mark.parametrize("args, message", [
    (["events", "fig2", "--v", "0_6"], "Invalid value for '--v': '0_6' is not a valid float: write it in plain "
                                       "decimal digits (e.g. 1000, 0.6, 1e-6)."),
    (["events", "fig2", "--v", "0x1"], "Invalid value for '--v': '0x1' is not a valid float: write it in plain "
                                       "decimal digits (e.g. 1000, 0.6, 1e-6)."),
    (["events", "fig2", "--L", "1_0"], "Invalid value for '--L': '1_0' is not a valid float: write it in plain "
                                       "decimal digits (e.g. 1000, 0.6, 1e-6)."),
    (["animate", "fig2", "--fps", "1_0"], "Invalid value for '--fps': '1_0' is not a valid integer: write it in plain "
                                          "decimal digits (e.g. 1000)."),
    (["animate", "fig2", "--seconds", "1_0"], "Invalid value for '--seconds': '1_0' is not a valid float: write it in "
                                              "plain decimal digits (e.g. 1000, 0.6, 1e-6)."),
    (["plot", "fig2", "--rod-lines", "1_0"], "Invalid value for '--rod-lines': '1_0' is not a valid integer: write it "
                                             "in plain decimal digits (e.g. 1000)."),
    (["ledger", "fig2", "--at", "1_000"], "option --at must be one or more times (numbers, in the unit L is given "
                                          "in), comma-separated, got '1_000'."),
    (["ledger", "fig2", "--at", "0x10"], "option --at must be one or more times (numbers, in the unit L is given "
                                         "in), comma-separated, got '0x10'."),
    (["plot", "fig2", "--frame", "both,0_3"], "option --frame: a frame must be rest, moving, both, rod (the rod's own "
                                              "view) or a velocity U with -0.9999999 <= U <= 0.9999999 (or a "
                                              "comma-separated list of these), got '0_3'."),
    (["animate", "fig2", "--mode", "boost", "--frame", "0_1..0.5"],
     "option --frame: each end of A..B must be rest, moving or a velocity U relative to S; not a velocity: '0_1'."),
])
def test_numbers_with_underscores_are_refused_as_hexadecimal_is(args, message):
    assert error_of(*args) == message


def test_decimal_numbers_in_every_spelling_are_read():
    from rodparadox.numbers import decimal, whole

    assert [decimal(t) for t in ("0.6", ".6", "0.60", "+0.6", "6e-1", "6E-1", " 0.6 ", "-0")] == [0.6] * 7 + [0.0]
    assert str(decimal("-0")) == "0.0" and whole("+12") == 12 and whole(" 7") == 7
    for bad in ("1_000", "0x10", "0b1", "1e", "", "1,5", "٣"):
        with pytest.raises(ValueError):
            decimal(bad)
    for bad in ("1_0", "1.0", "0x1", "1e2"):
        with pytest.raises(ValueError):
            whole(bad)


# --- item 15: --at far beyond the history -----------------------------------------------------------------

@pytest.mark.parametrize("t", ["1e308", "-1e308", "1e5"])
def test_a_time_far_outside_the_window_is_refused(t):
    message = error_of("ledger", "fig2", "--at", t)
    assert message.startswith(f"option --at: {float(t):g} lies more than 1000 window lengths outside S's window (")
    assert message.endswith("), where nothing changes; give times near it.")


def test_a_time_well_outside_the_window_gives_the_state_after_the_last_impact():
    """fig2 is settled after its last impact (t = 79/24 in S, README): at t = 1000 every body's (E, p) is the
    one at t = 10."""
    import json

    slices = json.loads(run("ledger", "fig2", "--frame", "rest", "--at", "10,1000", "--format", "json").output)
    late, far = slices["frames"]["rest"]["slices"]
    assert (late["t"], far["t"]) == (10, 1000)
    assert {k: v for k, v in late.items() if k != "t"} == {k: v for k, v in far.items() if k != "t"}


# --- item 15: an unwritable HOME: no matplotlib warnings, nothing left in the temporary folder ---------------

def test_an_unwritable_home_gives_no_matplotlib_warnings(tmp_path):
    temporary = tmp_path / "tmp"
    temporary.mkdir()
    env = {k: v for k, v in os.environ.items() if not k.startswith(("XDG_", "MPL"))}
    env.update(HOME="/proc/version", TMPDIR=str(temporary))  # a file: no folder can be made in it, even by root
    # the fewest drawing (single, one panel; fig2 in two before): matplotlib still loads, and makes its font cache
    # afresh (most of the time here) in the folder of our own that is removed at exit
    result = subprocess.run(_cli() + ["plot", "single", "--frame", "rest", "-o", str(tmp_path / "p.svg")],
                            capture_output=True, text=True, env=env, timeout=120)
    assert (result.returncode, result.stderr, result.stdout) == (0, "", f"{tmp_path / 'p.svg'}\n")
    assert list(temporary.iterdir()) == []


# --- items 4 and 13: a signal ends a command cleanly: one sentence, 128 + the signal, nothing left ------------

def _start_mp4(tmp_path):
    """`animate --format mp4` in a process of its own, its temporary folder in tmp_path/tmp; returns it once the
    MP4's temporary folder exists (ffmpeg is encoding)."""
    temporary = tmp_path / "tmp"
    temporary.mkdir()
    env = dict(os.environ, TMPDIR=str(temporary))
    process = subprocess.Popen(_cli() + ["animate", "fig2", "--format", "mp4", "--fps", "10", "--seconds", "12", "-o",
                                         str(tmp_path / "a.mp4")], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               text=True, env=env)
    deadline = time.monotonic() + 90
    while not any(p.name.startswith("sears-paradox-") for p in temporary.iterdir()):
        assert process.poll() is None and time.monotonic() < deadline, process.communicate()
        time.sleep(0.05)
    return process, temporary


@pytest.mark.skipif(not hasattr(signal, "SIGTERM"), reason="POSIX signals")
@pytest.mark.parametrize("signum, said, status", [(signal.SIGTERM, "SIGTERM", 143), (signal.SIGINT, "Ctrl-C", 130)])
def test_a_signal_during_an_mp4_leaves_nothing(tmp_path, signum, said, status):
    """SIGTERM (kill, timeout) left sears-paradox-*/video.mp4 in the temporary folder; Ctrl-C said click's
    "Aborted!" and exited 1. Now both clean up and say one sentence, with the shell's status for the signal."""
    pytest.importorskip("imageio_ffmpeg")
    process, temporary = _start_mp4(tmp_path)
    process.send_signal(signum)
    stdout, stderr = process.communicate(timeout=60)
    assert (process.returncode, stdout, stderr) == (status, "", f"Error: interrupted by {said}; no file was left "
                                                                f"half-written.\n")
    assert list(temporary.iterdir()) == [] and not (tmp_path / "a.mp4").exists()
    assert [p.name for p in tmp_path.iterdir()] == ["tmp"]


@pytest.mark.parametrize("name, status", [("SIGHUP", 129), ("SIGTERM", 143), ("SIGINT", 130)])
def test_each_stopping_signal_raises_where_the_program_is(name, status):
    from sears_paradox_cli.edge import Stopped, stopped_by_signals

    number = getattr(signal, name)
    inherited = signal.getsignal(number)
    # as a terminal starts it: a test run started in the background inherits SIGINT ignored, which the program
    # rightly keeps ignoring (the next test)
    before = signal.default_int_handler if name == "SIGINT" else signal.SIG_DFL
    signal.signal(number, before)
    cleaned = []
    try:
        with pytest.raises(Stopped) as e:
            with stopped_by_signals():
                try:
                    os.kill(os.getpid(), number)
                    time.sleep(5)  # the handler raises here, at once
                finally:
                    cleaned.append(True)
        assert cleaned == [True] and e.value.exit_code == status and signal.getsignal(number) is before
    finally:
        signal.signal(number, inherited)
    word = "Ctrl-C" if name == "SIGINT" else name
    assert e.value.sentence() == f"interrupted by {word}; no file was left half-written."


def test_a_signal_ignored_when_the_program_starts_stays_ignored():
    """nohup's SIGHUP, a background job's SIGINT: ignored before, ignored while the command runs, as Python does."""
    from sears_paradox_cli.edge import stopped_by_signals

    inherited = signal.getsignal(signal.SIGHUP)
    signal.signal(signal.SIGHUP, signal.SIG_IGN)
    try:
        with stopped_by_signals():
            os.kill(os.getpid(), signal.SIGHUP)  # would raise Stopped were it caught
            assert signal.getsignal(signal.SIGHUP) is signal.SIG_IGN
        assert signal.getsignal(signal.SIGHUP) is signal.SIG_IGN
    finally:
        signal.signal(signal.SIGHUP, inherited)


def test_ctrl_c_in_a_command_is_one_sentence_and_130(monkeypatch):
    import sears_paradox_cli.main as cli_main

    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(cli_main, "run_rods", interrupted)
    result = CliRunner().invoke(main, ["events", "fig2"])
    # click's blank line closes the terminal's ^C, then the one sentence
    assert (result.exit_code, result.output) == (130, "\nError: interrupted by Ctrl-C; no file was left "
                                                      "half-written.\n")


# --- items 5 and 13: the progress bar: a time estimate, never with -q ------------------------------------------

class _Terminal:
    """A stream that says it is a terminal, keeping what is written."""

    def __init__(self):
        self.text = ""

    def isatty(self):
        return True

    def write(self, text):
        self.text += text

    def flush(self):
        pass


def _drawn_with_clock(monkeypatch, quiet: bool) -> str:
    import click._termui_impl as termui

    from sears_paradox_cli.animate import progress

    now = [1000.0]
    monkeypatch.setattr(termui.time, "time", lambda: now[0])
    terminal = _Terminal()
    with progress(iter(range(10)), 10, "outputs/fig2_now.gif", quiet, stream=terminal) as bar:
        for _ in bar:
            now[0] += 2.0  # two seconds an image
    return terminal.text


def test_the_progress_bar_says_the_time_left(monkeypatch):
    shown = _drawn_with_clock(monkeypatch, quiet=False)
    assert "outputs/fig2_now.gif" in shown and "3/10" in shown
    assert "00:00:14 left" in shown  # after 3 images at 2 s each, 7 are left: 14 s


def test_quiet_draws_no_progress_bar_on_a_terminal(monkeypatch):
    assert _drawn_with_clock(monkeypatch, quiet=True) == ""


# --- item 5: long animations: a bound on frames x pixels, --fps bounded, the length in the name -----------------

def test_a_long_animation_is_refused_unless_allowed(tmp_path, monkeypatch):
    import rodparadox.animate.timeline as timeline

    monkeypatch.chdir(tmp_path)
    # 3000 images of the default 1049 x 1101: 3465 million pixels, above the 400 million bound
    assert error_of("animate", "fig2", "--seconds", "120") == (
        "--seconds 120 at --fps 25 gives 3000 frames of 1049 x 1101 pixels, 3,465 million pixels in all, more than "
        "the 400 million drawn without asking (minutes of work); give --allow-long to draw them, or lower --seconds "
        "or --fps.")
    assert list(tmp_path.iterdir()) == [Path("outputs")] or [p.name for p in tmp_path.iterdir()] == ["outputs"]
    assert list((tmp_path / "outputs").iterdir()) == []
    # a bound a short run (2 images, the fewest an animation has) passes only when allowed; the bound and the
    # refusal are what is checked, so its images are stood in for, blank, of the size just refused (the first
    # image's drawing and the message with its size: above)
    import numpy as np

    import rodparadox.animate.scenes as scenes

    monkeypatch.setattr(timeline, "MAX_PIXELS", 1 * 1049 * 1101)
    monkeypatch.setattr(scenes, "images_of", lambda history, frames, mode, style, line, rod_view=None: (
        np.full((1101, 1049, 3), 255, dtype=np.uint8) for _ in range(len(line))))
    assert "give --allow-long" in error_of("animate", "fig2", "--fps", "2", "--seconds", "1")
    assert run("animate", "fig2", "--fps", "2", "--seconds", "1", "--allow-long").output == \
        "outputs/fig2_now_fps2_seconds1.gif\n"


@pytest.mark.parametrize("fmt", ["mp4", "png"])
def test_the_frame_rate_of_mp4_and_stills_is_bounded(tmp_path, monkeypatch, fmt):
    monkeypatch.chdir(tmp_path)
    assert error_of("animate", "fig2", "--format", fmt, "--fps", "1000", "--seconds", "1") == \
        "option --fps: 1000 frames per second is faster than a screen shows; give at most 60."
    assert error_of("animate", "fig2", "--format", fmt, "--fps", "61", "--seconds", "1").endswith("at most 60.")


@pytest.mark.parametrize("args, name", [([], "fig2_now.gif"), (["--fps", "25", "--seconds", "6"], "fig2_now.gif"),
                                        (["--fps", "10"], "fig2_now_fps10.gif"),
                                        (["--seconds", "3"], "fig2_now_seconds3.gif"),
                                        (["--seconds", "2.5", "--fps", "4"], "fig2_now_fps4_seconds2.5.gif"),
                                        (["--mode", "boost", "--v", "0.8", "--fps", "5", "--format", "mp4"],
                                         "fig2_boost_v0.8_fps5.mp4")])
def test_animation_names_carry_a_rate_and_length_other_than_the_defaults(args, name):
    from sears_paradox_cli import planning
    from sears_paradox_cli.animate import ANIMATION_FORMATS, DEFAULT_FPS, DEFAULT_SECONDS, length_names

    options = dict(zip(args[::2], args[1::2]))
    fps, seconds = int(options.get("--fps", DEFAULT_FPS)), float(options.get("--seconds", DEFAULT_SECONDS))
    outputs = planning.Outputs(formats=ANIMATION_FORMATS, default="gif", kind=options.get("--mode", "now"),
                               folders={"png": "the stills"}, frames=planning.frames_of if "--mode" not in options
                               else __import__("rodparadox.animate.timeline", fromlist=["x"]).boost_ends)
    v = float(options["--v"]) if "--v" in options else None
    [job] = planning.plan(["fig2"], outputs, v=v, L=None, frame="both", fmt=options.get("--format"), output=None,
                          style="default", extras=length_names(fps, seconds))
    assert job.path == Path("outputs") / name


# --- item 12: PNG stills: a clash said before anything is drawn; a locked folder without internal names -------

def test_a_still_that_cannot_be_written_is_found_before_any_is_drawn(tmp_path):
    stills = tmp_path / "stills"
    (stills / "fig2_now_fps4_seconds2_0005.png").mkdir(parents=True)
    (stills / "fig2_now_fps4_seconds2_0000.png").write_bytes(b"an older still")
    assert error_of("animate", "fig2", "--format", "png", "--fps", "4", "--seconds", "2", "-o", stills) == \
        f"cannot write {stills}/fig2_now_fps4_seconds2_0005.png: it is a folder."
    assert (stills / "fig2_now_fps4_seconds2_0000.png").read_bytes() == b"an older still"
    assert sorted(p.name for p in stills.iterdir()) == ["fig2_now_fps4_seconds2_0000.png",
                                                       "fig2_now_fps4_seconds2_0005.png"]


def test_a_locked_stills_folder_is_said_without_internal_names(tmp_path, monkeypatch):
    import rodparadox.io.output as output

    stills = tmp_path / "stills"
    stills.mkdir()
    monkeypatch.setattr(output.os, "access", lambda path, mode: Path(path) != stills)  # as for a user, not root
    assert error_of("animate", "fig2", "--format", "png", "--fps", "4", "--seconds", "1", "-o", stills) == \
        f"cannot write the stills into {stills}: permission denied."


# --- handouts: letter slides in LaTeX, a colour scale zero wide, a scenario given twice ---------------------------

@pytest.mark.parametrize("paper", ["letter", "a4"])
def test_a_slides_handout_in_latex_sizes_its_strips_for_the_type(tmp_path, paper):
    """6 strips in slides type need 6.39 in; the LaTeX writer gave them 1.45 + 6 x 0.5 = 4.45 in and died with
    render/strip.py's ValueError. Now the block is as tall as the type needs. Only the moving frame is asked for:
    the strips PDF read is the moving frame's, byte for byte the same as with both frames (checked by hand)."""
    from pypdf import PdfReader

    run("handout", "fig1", "--format", "tex", "--paper", paper, "--style", "slides", "--frame", "moving", "-o",
        tmp_path / "tex", "-q")
    box = PdfReader(tmp_path / "tex" / "fig1_strips_moving.pdf").pages[0].mediabox
    assert float(box.height) / 72 > 4.45 + 1.0  # the larger type needs about 6.4 in


def test_a_rod_that_never_changes_velocity_seen_from_another_frame_draws_no_warning():
    """fig1 from u = 0.3: every material point at -0.30000000000000004, the centre -0.3; the colour bar was zero
    wide, and matplotlib warned "Attempting to set identical low and high xlims" on standard error."""
    import warnings

    from rodparadox.io.scenario import load
    from rodparadox.physics.rigid import run as run_history
    from rodparadox.physics.frames import frame_of_velocity
    from rodparadox.render.colour_scale import STILL_BOUND, colour_scale

    history = run_history(load("fig1"))
    scale = colour_scale(history, frame_of_velocity(0.3))
    assert (scale.centre, scale.bound, scale.shown) == (-0.3, STILL_BOUND, None)  # as fig1 in S: the still scale
    from matplotlib.figure import Figure

    from rodparadox import render

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        render.draw_strips_into(Figure(figsize=(7, 5)), history, frame_of_velocity(0.3), [0.5, 1.0], "print")


def test_a_scenario_given_twice_to_a_handout_is_refused(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert error_of("handout", "fig2", "fig2") == ("fig2 is given twice; a handout has one section per scenario, so "
                                                  "give each once.")
    assert error_of("handout", "fig1", "fig2", "fig1", "--worksheet") == (
        "fig1 is given twice; a worksheet has one section per scenario, so give each once.")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("name", ["sears", "fig2"])
def test_two_rods_own_views_too_wide_for_the_page_are_refused_in_one_sentence(name, tmp_path):
    """In slides type, the two rods' own views side by side (tick labels and keys 326 pt each) need more than an A4
    page's text width: refused naming the styles and the rods that fit, nothing written (it raised a traceback for
    a driven rod, and drew a particle scenario's views off the page)."""
    message = error_of("handout", name, "--frame", "both,rod", "--rod", "both", "--style", "slides", "-o", tmp_path)
    assert message == ("the rods' own views do not fit side by side on this page in the slides style; choose --style "
                       "default or print, or the rigid rod alone (--rod rigid).")
    assert not list(tmp_path.iterdir())
