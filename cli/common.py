"""What every command shares: the error that exits 2, loading and running a scenario, the common options.

Imported by `main` and `plot` (never the other way round), so neither imports
the other's module. Only click and `rodparadox.errors` at module top: `--help`
must not load numpy or matplotlib.
"""

from __future__ import annotations

import contextlib
import functools

import click

from rodparadox.errors import RodParadoxError

from . import words
from .words import option, worded


class BadInput(click.ClickException):
    """A scenario, option or path the user must fix: one sentence, exit status 2."""

    exit_code = 2


class EnvironmentFailure(click.ClickException):
    """A failure of the system, not of the input (a full disk): one sentence, exit status 1."""

    exit_code = 1


#: the exit status of a process killed by SIGPIPE (128 + 13), as `yes | head -1` leaves `yes`
BROKEN_PIPE_STATUS = 141


class Stopped(BaseException):
    """A signal that ends the command (Ctrl-C's SIGINT, SIGTERM from kill or timeout, SIGHUP from a closed
    terminal), raised where the program is, so that every `with` and `finally` on the way out runs: a temporary
    file or folder (an MP4's, an atomic write's) is removed as for any error. Not an Exception: no `except
    Exception` stops it."""

    def __init__(self, signum: int):
        super().__init__(signum)
        self.signum = signum

    @property
    def exit_code(self) -> int:
        return 128 + self.signum  # as the shell reports a process the signal killed: 130, 143, 129

    def sentence(self) -> str:
        import signal

        said = "by Ctrl-C" if self.signum == signal.SIGINT else f"by {signal.Signals(self.signum).name}"
        return f"interrupted {said}; no file was left half-written."


#: the signals that end a command with its clean-up (`Stopped`)
STOPPING_SIGNALS = ("SIGINT", "SIGTERM", "SIGHUP")


def signal_number(name: str) -> int:
    import signal

    return int(getattr(signal, name))


@contextlib.contextmanager
def stopped_by_signals():
    """While the command runs, each of STOPPING_SIGNALS raises `Stopped` (a second one, during the clean-up, is
    ignored); the handlers before are restored after. Outside the main thread, signals cannot be caught: nothing
    changes."""
    import signal

    def stop(signum, frame):
        for name in STOPPING_SIGNALS:
            try:
                signal.signal(signal_number(name), signal.SIG_IGN)
            except (ValueError, OSError):
                pass
        raise Stopped(signum)

    before = {}
    try:
        for name in STOPPING_SIGNALS:
            if hasattr(signal, name):
                number = signal_number(name)
                if signal.getsignal(number) is signal.SIG_IGN:
                    continue  # nohup's SIGHUP, a background job's SIGINT: keep ignoring it, as Python does
                before[number] = signal.signal(number, stop)
    except ValueError:  # not the main thread
        pass
    try:
        yield
    finally:
        for number, handler in before.items():
            signal.signal(number, handler if handler is not None else signal.SIG_DFL)


def reports_errors(command):
    """The CLI edge: any library error (`RodParadoxError`) becomes its one sentence, in the options' names
    (`words.worded`), and exit status 2 (a failed write or a missing tool such as ffmpeg: 1), no traceback; a
    reader that closed standard output ends the command quietly."""
    @functools.wraps(command)
    def wrapper(*args, **kwargs):
        from rodparadox.errors import ToolMissing, WriteFailed

        try:
            return command(*args, **kwargs)
        except (WriteFailed, ToolMissing) as e:
            raise EnvironmentFailure(worded(e)) from None
        except RodParadoxError as e:
            raise BadInput(worded(e)) from None
        except BrokenPipeError:
            _quiet_exit()
        except RecursionError:  # a safety net: the YAML reader bounds nesting (scenario.MAX_DEPTH) before this
            raise BadInput("the input is nested too deeply to read; write it flat.") from None
    return wrapper


def before_matplotlib() -> None:
    """Call before a command first imports matplotlib: where its default config and cache folders cannot be made
    (an unwritable HOME), point MPLCONFIGDIR at a temporary folder of our own, removed at exit, so that
    matplotlib's warnings about them ("mkdir -p failed", "created a temporary cache directory") never reach
    standard error. matplotlib would make the same folders itself; a MPLCONFIGDIR the user set is left alone."""
    import atexit
    import os
    import shutil
    import sys
    import tempfile
    from pathlib import Path

    if "matplotlib" in sys.modules or os.environ.get("MPLCONFIGDIR") or not sys.platform.startswith("linux"):
        return
    try:
        home = Path.home()
    except RuntimeError:
        home = None
    for variable, default in (("XDG_CONFIG_HOME", ".config"), ("XDG_CACHE_HOME", ".cache")):
        base = os.environ.get(variable) or (home / default if home is not None else None)
        if base is None:
            break
        folder = Path(base, "matplotlib")
        try:
            folder.mkdir(parents=True, exist_ok=True)
        except OSError:
            break
        if not (folder.is_dir() and os.access(folder, os.W_OK)):
            break
    else:
        return
    try:
        folder = tempfile.mkdtemp(prefix="sears-paradox-matplotlib-")
    except OSError:
        return  # matplotlib will say why itself
    atexit.register(shutil.rmtree, folder, True)
    os.environ["MPLCONFIGDIR"] = folder
    # a new folder has no font cache: matplotlib builds one, and says so on standard error when that takes over
    # 5 s (a loaded machine); the building is ours to arrange here, so the notice is dropped
    import logging

    logging.getLogger("matplotlib.font_manager").addFilter(
        lambda record: not str(record.msg).startswith("Matplotlib is building the font cache"))


def report(written, quiet: bool) -> None:
    """Print each path of `written` (path, changed), `PATH (unchanged)` for a file left alone because it already
    held these bytes; nothing with -q. `written` may be lazy (each file written as it is reached): it is read to
    the end either way."""
    for path, changed in written:
        if not quiet and not _is_standard_output(path):  # -o /dev/stdout: the output is the data itself
            emit(str(path) if changed else f"{path} (unchanged)")


def _is_standard_output(path) -> bool:
    """Whether `path` is this process's standard output (/dev/stdout, or what it leads to)."""
    import os
    import sys

    if str(path) in ("/dev/stdout", "/dev/fd/1", "/proc/self/fd/1"):
        return True
    try:
        here, there = os.fstat(sys.stdout.fileno()), os.stat(path)
    except (OSError, ValueError, AttributeError):
        return False
    return (here.st_dev, here.st_ino) == (there.st_dev, there.st_ino) and not os.path.isdir(path)


def emit(text: str, nl: bool = True) -> None:
    """Print to standard output: a failed write (a full disk) is one sentence and exit status 1, a closed pipe
    (`| head -1`) a quiet exit."""
    try:
        _write_all(text + ("\n" if nl else ""))
    except BrokenPipeError:
        _quiet_exit()
    except OSError as e:
        stdout_to_devnull()
        raise EnvironmentFailure(f"cannot write to standard output: {(e.strerror or str(e)).lower()}.") from None


def _write_all(text: str) -> None:
    """Write `text` to standard output whole. A text stream without a buffer in between (`python -u`,
    PYTHONUNBUFFERED) hands the system one write and drops what a pipe did not take; here every short write is
    followed by another, so a reader that went away is always seen (BrokenPipeError), never a cut table."""
    import sys

    stream = sys.stdout
    raw = getattr(stream, "buffer", None)
    if raw is None or stream is None:  # a stream of text only (a test's): it takes everything or raises
        click.echo(text, nl=False)
        return
    stream.flush()
    view = memoryview(text.encode(stream.encoding or "utf-8", stream.errors or "strict"))
    while view:
        written = raw.write(view)
        if written is None:  # a non-blocking stream that is full: wait for it
            import select

            select.select([], [raw], [])
            continue
        view = view[written:]
    raw.flush()


def _quiet_exit():
    stdout_to_devnull()
    raise click.exceptions.Exit(BROKEN_PIPE_STATUS)


def stdout_to_devnull() -> None:
    """Point standard output at /dev/null, so that Python's last flush at exit neither fails nor prints."""
    import os
    import sys

    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)
    except (OSError, ValueError):  # no file descriptor (a test's captured output): nothing is left to flush
        pass


def checked_output(output: str | None) -> str | None:
    """-o: an empty name is refused here, as every empty value is (it would mean the current folder)."""
    if output is not None and not output.strip():
        raise words.empty_output(output)
    return output


def load_scenario(name: str, v: float | None, L: float | None):
    """A built-in scenario or YAML file, with the command line's --v, --L and --rod (`with_options`)."""
    from rodparadox.io.scenario import load

    return with_options(load(name), v, L)


def with_options(scenario, v: float | None, L: float | None):
    """The scenario with the command line's --v, --L and --rod; a bad value is said as its option's."""
    from rodparadox.errors import ScenarioError

    try:
        scenario = scenario.with_overrides(v=v, L=L)
    except ScenarioError as e:
        raise words.scenario_option_error(e, [k for k, value in (("v", v), ("L", L)) if value is not None]) from None
    return _with_rod(scenario)


def _with_rod(scenario):
    """The scenario with --rod (kept in the click context by `scenario_options`), if the command takes that rod."""
    context = click.get_current_context(silent=True)
    meta = context.meta if context is not None else {}
    rod, rods = meta.get(ROD_META) or scenario.rod, meta.get(RODS_META, ("rigid", "causal"))
    if rod not in rods:
        raise BadInput(words.rod_not_here(rod, context.info_name if context is not None else "this command", rods))
    return scenario.with_overrides(rod="rigid" if rod == "both" else rod)  # both: the rigid run, the command adds the other


def rod_asked() -> str | None:
    """--rod as given on the command line (rigid, causal or both), or None."""
    context = click.get_current_context(silent=True)
    return context.meta.get(ROD_META) if context is not None else None


def run_scenario(scenario, source: str, frames=()):
    """Run a scenario; `source` is the name or path the user gave, to start any error sentence.

    The one verdict every command gives a scenario: it runs, and in every frame the command shows (`frames`)
    every velocity is below c in double precision (`frames.check_below_c`), so `plot`, `animate` and `ledger`
    refuse what `events`, `export` and `handout` refuse. A boost's frames in between need no check: a body's
    speed is largest at one of its ends."""
    from rodparadox.physics.rod_models import run_rod
    from rodparadox.physics.frames import check_below_c, view
    from rodparadox.errors import ScenarioError

    try:
        history = run_rod(scenario)
    except ScenarioError as e:  # the engine's sentence does not say which scenario: say it here
        raise BadInput(f"{source}: {e}") from None
    for frame in frames:
        check_below_c(view(history, frame))
    return history


def checked_frame_velocity(u: float | None) -> float | None:
    """--frame-velocity, checked by the library's one rule (`frames.check_velocity`); the message names the option."""
    from rodparadox.errors import FrameError
    from rodparadox.physics.frames import check_velocity

    try:
        return None if u is None else check_velocity(u)
    except FrameError as e:
        raise words.frame_error(e, "frame_velocity", u) from None


# --- numbers: one rule for every number on the command line ------------------------------------------
# Decimal digits, an optional point and exponent (`rodparadox.numbers.decimal`), as in a scenario file: Python's
# `1_000` is refused as `0x10` is, with the same sentence.

def _not_decimal(value, kind: str) -> str:
    if isinstance(value, str) and ("_" in value or value.strip().lower().lstrip("+-").startswith(("0x", "0b", "0o"))):
        examples = "1000, 0.6, 1e-6" if kind == "float" else "1000"
        return f"{value!r} is not a valid {kind}: write it in plain decimal digits (e.g. {examples})."
    return f"{value!r} is not a valid {kind}."


class Decimal(click.types.FloatParamType):
    """A float written in decimal (`numbers.decimal`): click's float without Python's underscores."""

    def convert(self, value, param, ctx):
        from rodparadox.numbers import decimal

        if isinstance(value, float):
            return value
        try:
            return decimal(value)
        except ValueError:
            self.fail(_not_decimal(value, "float"), param, ctx)


class Whole(click.IntRange):
    """A whole number written in decimal digits (`numbers.whole`), within optional bounds: click's int (or
    IntRange) without Python's underscores."""

    def convert(self, value, param, ctx):
        from rodparadox.numbers import whole

        if not isinstance(value, int):
            try:
                value = whole(value)
            except ValueError:
                self.fail(_not_decimal(value, "integer"), param, ctx)
        return super().convert(value, param, ctx)


NUMBER = Decimal()


class FrameVelocity(Decimal):
    """--frame-velocity of events and export: a number; the word rod (the rod's own view, a drawing's) is refused
    in a sentence of its own."""

    def convert(self, value, param, ctx):
        if isinstance(value, str) and value.strip() == "rod":
            self.fail("rod (the rod's own view) is drawn by plot, animate and handout only; these tables need a "
                      "Lorentz frame: give a velocity U relative to S.", param, ctx)
        return super().convert(value, param, ctx)



# --- the options the commands share ----------------------------------------------------------------
# Each declared once, named as `words` names it in messages; where commands word an option differently, the
# command gives its own help (and metavar).

scenario_argument = click.argument("scenario", metavar="SCENARIO")
scenarios_argument = click.argument("scenarios", nargs=-1, required=True, metavar="SCENARIO...")
v_option = click.option(option("v"), "v", type=NUMBER, metavar="V",
                        help="Speed of the moving frame S' and default particle speed, 0 < V < 1 (overrides the scenario).")
L_option = click.option(option("L"), "L", type=NUMBER, metavar="L", help="The rod's proper length, L > 0 (overrides the scenario).")
frame_velocity_option = click.option(option("frame_velocity"), "frame_velocity", type=FrameVelocity(), metavar="U",
                                     help="Also show the frame of velocity U relative to S, |U| <= 0.9999999.")
quiet_option = click.option("-q", "--quiet", is_flag=True,
                            help="Print nothing on success (the paths written are printed otherwise).")


#: where `scenario_options` leaves --rod and the rod models a command draws, for `load_scenario`
ROD_META, RODS_META = "sears_paradox.rod", "sears_paradox.rods"
ROD_WORDS = ("rigid", "causal", "both")


def scenario_options(several: bool = False, rods: tuple[str, ...] = ("rigid", "causal")):
    """SCENARIO (or SCENARIO... with `several`), then --v, --L and --rod: how every command begins. `rods`: the
    rod models the command takes; --rod (or a scenario's rod:) naming another is refused in one sentence."""
    def keep_rod(context: click.Context, parameter, value):
        context.meta[ROD_META], context.meta[RODS_META] = value, rods
        return value

    rod_option = click.option(option("rod"), "rod", type=click.Choice(ROD_WORDS), default=None, expose_value=False,
                              is_eager=True, callback=keep_rod, metavar="rigid|causal",
                              help="The rod: rigid (the paper's) or causal (sound at c: the documentation's "
                                   "\"The model\"); overrides the scenario's rod:.")

    def decorate(command):
        for declare in (rod_option, L_option, v_option, scenarios_argument if several else scenario_argument):
            command = declare(command)
        return command
    return decorate


def frame_option(help: str, metavar: str = "rest|moving|both|U"):
    """--frame: the frames (panels) to show, read by `planning.frames_of` (or by the command's own reader)."""
    return click.option(option("frame"), "frame", default="both", show_default=True, metavar=metavar, help=help)


def format_option(help: str, **kind):
    """--format, as `fmt`: a command's own list of formats (`kind`: a click type, a default, a metavar)."""
    return click.option(option("format"), "fmt", help=help, **kind)


def output_option(help: str, metavar: str = "PATH", default: str | None = None):
    """-o/--output: where the command writes (`None`: the planner's default folder; "-": standard output)."""
    return click.option(option("output"), "--output", "output", metavar=metavar, default=default,
                        show_default=default is not None, help=help)


def style_option(names: tuple[str, ...] | None = None, default: str = "default",
                 help: str = "default: colour, colour-blind safe; print: black and white, serif; slides: large type."):
    """--style, as every drawing command takes it (the names come from `rodparadox.render.styles`, which imports
    nothing); a command that prints by default (handout) gives its own order, default and help."""
    if names is None:
        from rodparadox.render.styles import STYLE_NAMES as names

    return click.option("--style", "style", type=click.Choice(names), default=default, show_default=True, help=help)
