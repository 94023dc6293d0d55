"""The project's errors: one base class, each concrete error also a builtin (as pint's are); the command line says
each in one sentence naming what to fix (docs/commands.md, "Commands")."""

from __future__ import annotations

from typing import Any, Callable


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


class BeyondBounds(ScenarioError):
    """A computation would need more than its bound (pieces of a table, stretches of a sum, ...): `what` names it;
    a caller that only offers the result (the html page's other speeds) leaves it out."""

    def __init__(self, what: str):
        self.what = what
        super().__init__(f"the causal rod would need more than {what} here; choose a lower v.")


class OutputError(OSError, RodParadoxError):
    """A file that cannot be written; says which and why."""


class WriteFailed(OutputError):
    """Bytes the system refused part-way (a full disk, a failing device): the environment, not the input, so
    the command line exits 1 rather than 2."""


class FrameError(ValueError, RodParadoxError):
    """A frame velocity outside the bounds double precision can place events in (frames.check_velocity)."""


class ChoiceError(RodParadoxError):
    """An error about one of the caller's choices (a frame rate, a format ...), kept as facts and told in one sentence.

    `what` is the choice, by the name of the library's parameter (fps, seconds, frame, mode, format); `value`
    the value given; `allowed` what would do (words, or a tuple of the choices); `facts` any other value the
    sentence needs. `template` is the sentence: its fields are these facts (`{allowed}` reads "one of a, b" for
    a tuple, `{choices}` "a, b"), `{what}` the choice as the sentence's subject, and any other field a choice
    named inside it (`{fps}`). str() calls every choice by its parameter's name; a caller with names of its own
    (the command line's options) words the same facts with `sentence`.
    """

    MUST_BE = "{what} must be {allowed}, got {value!r}."

    def _keep(self, what: str, value: Any, allowed: Any, template: str, facts: dict[str, Any]) -> None:
        self.what, self.value, self.allowed, self.template, self.facts = what, value, allowed, template, facts

    def sentence(self, name: Callable[[str], str] = str, subject: Callable[[str], str] | None = None) -> str:
        """The sentence, each choice called `name(choice)`, the subject `subject(what)` (default: `name`)."""
        choices = ", ".join(map(str, self.allowed)) if isinstance(self.allowed, tuple) else None
        fields = _Named(name, what=(subject or name)(self.what), value=self.value, choices=choices,
                        allowed=f"one of {choices}" if choices is not None else self.allowed, **self.facts)
        return self.template.format_map(fields)

    def __str__(self) -> str:
        return self.sentence()


class _Named(dict):
    """A template's fields: the facts, and any other field the name of a choice."""

    def __init__(self, name: Callable[[str], str], **facts: Any):
        super().__init__(facts)
        self.name = name

    def __missing__(self, choice: str) -> str:
        return self.name(choice)


class OptionError(ChoiceError, ValueError):
    """A choice the caller made that cannot be used as given (a format, a frame rate, the frames of a boost): keeps
    which choice, its value and what is allowed (`ChoiceError`)."""

    def __init__(self, what: str, value: Any, allowed: Any = None, template: str = ChoiceError.MUST_BE,
                 **facts: Any):
        self._keep(what, value, allowed, template, facts)
        super().__init__(str(self))


class ToolMissing(ChoiceError, RuntimeError):
    """A program the caller's choice needs (ffmpeg for MP4) is not installed: the environment, not the input, so
    the command line exits 1. Keeps the program (`tool`), the choice that needs it and its value
    (`ChoiceError`), and says how to install it."""

    def __init__(self, tool: str, what: str, value: Any, template: str, **facts: Any):
        self.tool = tool
        self._keep(what, value, None, template, dict(facts, tool=tool))
        super().__init__(str(self))
