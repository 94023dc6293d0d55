"""The project's errors: one base class, each concrete error also a builtin (STYLE.md, from pint)."""


class RodParadoxError(Exception):
    """Base of every error the tool reports to its user as one sentence."""


class ScenarioError(ValueError, RodParadoxError):
    """A scenario (YAML file or command-line override) that cannot be run; says what to fix.

    `key` is the dotted key path (e.g. ``particles.A.speed``), `line` the YAML
    line where known, `source` the file or option it came from.
    """

    def __init__(self, message: str, key: str | None = None, line: int | None = None, source: str | None = None):
        self.message, self.key, self.line, self.source = message, key, line, source
        super().__init__(str(self))

    def located(self, source: str, line: int | None) -> "ScenarioError":
        return ScenarioError(self.message, self.key, self.line if self.line is not None else line, source)

    def __str__(self) -> str:
        where = self.source or ""
        if self.line is not None:
            where = f"{where}, line {self.line}" if where else f"line {self.line}"
        return f"{where}: {self.message}" if where else self.message


class OutputError(OSError, RodParadoxError):
    """A file that cannot be written; says which and why."""


class WriteFailed(OutputError):
    """Bytes the system refused part-way (a full disk, a failing device): the environment, not the input, so
    the command line exits 1 rather than 2."""


class FrameError(ValueError, RodParadoxError):
    """A frame velocity outside the bounds double precision can place events in (frames.check_velocity)."""


class OptionError(ValueError, RodParadoxError):
    """A command-line option that cannot be used as given (a format, an output path, a frame list): says which."""


class ToolMissing(RuntimeError, RodParadoxError):
    """A program the command needs (ffmpeg for MP4) is not installed: the environment, not the input, so the
    command line exits 1; says how to install it."""
