"""The command line's words: each choice's option, and the sentences that name options.

The library's errors keep their facts (which choice, what value, what would do: `rodparadox.errors.OptionError`)
and call a choice by its parameter's name; here, and only here, a choice gets the name of its option
(`OPTIONS`), and the refusals the command line makes itself are built on the same facts. Only
`rodparadox.errors` is imported: `--help` loads nothing more.
"""

from __future__ import annotations

from typing import Sequence

from rodparadox.errors import ChoiceError, FrameError, OptionError, ScenarioError

#: every choice the library or the command line names, by its option
OPTIONS = {"v": "--v", "L": "--L", "frame": "--frame", "frame_velocity": "--frame-velocity", "output": "-o",
           "format": "--format", "fps": "--fps", "seconds": "--seconds", "mode": "--mode", "paper": "--paper",
           "at": "--at", "questions": "--questions", "compare_v": "--compare-v", "key": "--key",
           "sections": "--sections", "allow_long": "--allow-long", "rod": "--rod", "other_axes": "--other-axes", "light_cones": "--light-cones",
           "hyperbolae": "--hyperbolae", "grid": "--grid", "rod_lines": "--rod-lines", "rod_now": "--rod-now",
           "proper_time": "--proper-time", "equal_scales": "--equal-scales",
           "style": "--style"}


def option(choice: str) -> str:
    """The option that sets a choice: `--fps` for fps, `-o` for output."""
    return OPTIONS[choice]


def subject(choice: str) -> str:
    """A choice as the subject of a sentence: `option --fps`."""
    return f"option {OPTIONS[choice]}"


def worded(error: Exception) -> str:
    """A library error as the command line says it: a choice's facts in the options' names, else its own sentence."""
    if isinstance(error, ChoiceError):
        return error.sentence(option, subject)
    return str(error)


def scenario_option_error(error: ScenarioError, given: Sequence[str]) -> ScenarioError:
    """A scenario's error about a value the command line gave (`given`: v, L), located at its option."""
    return error.located(subject(error.key), None) if error.key in given else error


def frame_error(error: FrameError, choice: str, value) -> OptionError:
    """A frame the library refused (`frames.parse_frames`, `check_velocity`), as the option `choice` that gave it."""
    return OptionError(choice, value, template="{what}: {reason}", reason=str(error))


# --- what the command line itself refuses ----------------------------------------------------------

def empty_output(output: str) -> OptionError:
    """-o '': an empty name would mean the current folder; refused, as every empty value is."""
    return OptionError("output", output, template="{what} must name a file or folder, got {value!r}.")


def output_disagrees(output: str, fmt: str) -> OptionError:
    """-o names a file of one format, --format asks for another."""
    return OptionError("output", output, template="{what} names {value!r} but {format} is {fmt}; make them agree.",
                       fmt=fmt)


def unknown_extension(output: str, extensions: str) -> OptionError:
    """-o's extension names no format the command writes, and --format is not given."""
    return OptionError("output", output, template="{what}: cannot tell the format of {value!r} from its extension; "
                                                  "name it {extensions} or give {format}.", extensions=extensions)


def format_not_one_of(fmt: str, allowed: Sequence[str]) -> OptionError:
    """--format names none of the command's formats."""
    return OptionError("format", fmt, tuple(allowed))


def rod_not_here(rod: str, command: str, rods) -> str:
    """A rod model a command does not take (from --rod or a scenario's rod:), in one sentence."""
    takes = " or ".join(rods)
    if rod == "both":
        return (f"{command} shows one rod at a time, so it does not take --rod both; run it once with --rod rigid "
                f"and once with --rod causal.")
    return f"{command} does not take the {rod} rod yet (from option --rod or the scenario's rod:); it takes {takes}."
