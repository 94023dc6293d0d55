"""The error edge every command goes through: the error that exits 2, signals and a closed pipe, and what a
command prints (`emit`, `report`). Only click and `rodparadox.errors` at module top: `--help` must not load
numpy or matplotlib.
"""

from __future__ import annotations

import contextlib
import functools

import click

from rodparadox.errors import RodParadoxError

from .words import worded


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
