"""`sears-paradox animate`: names, formats, frame counts and durations read back, determinism, and bad input
(one sentence; exit 2, or 1 for a missing ffmpeg). Small: two frames each, so the file runs in seconds."""

import os
import subprocess

import pytest
from click.testing import CliRunner
from PIL import Image

from helpers import SHARED_PROCESS_GROUP, register_shared_process, shared_process
from rodparadox.animate.encoders import check_fps, open_sink
from rodparadox.animate.timeline import boost_ends, image_count, timeline
from sears_paradox_cli.main import main

#: a short animation: 2 frames, the fewest an animation has (4 before; every check here holds for any number of
#: frames: the count and duration read back, names, bytes twice, the stills numbered)
SHORT = ["--fps", "4", "--seconds", "0.5"]


def run(*args, expect=0):
    result = CliRunner().invoke(main, ["animate", *args])
    assert result.exit_code == expect, (result.output, result.exception)
    return result


def error_of(*args, expect=2) -> str:
    result = run(*args, expect=expect)
    assert isinstance(result.exception, SystemExit), result.exception
    lines = [line for line in result.output.splitlines() if line.startswith("Error: ")]
    assert len(lines) == 1 and "Traceback" not in result.output, result.output
    return lines[0][len("Error: "):]


def test_default_is_a_now_gif_in_outputs_with_its_frames_and_duration(here):
    assert run("fig2", *SHORT).output == "outputs/fig2_now_fps4_seconds0.5.gif\n"
    im = Image.open(here / "outputs" / "fig2_now_fps4_seconds0.5.gif")
    assert im.n_frames == 2 and im.info["duration"] == 250 and im.info["loop"] == 0
    first = (here / "outputs" / "fig2_now_fps4_seconds0.5.gif").read_bytes()
    stamp = os.stat(here / "outputs" / "fig2_now_fps4_seconds0.5.gif").st_mtime_ns
    assert run("fig2", *SHORT).output == "outputs/fig2_now_fps4_seconds0.5.gif (unchanged)\n"
    assert os.stat(here / "outputs" / "fig2_now_fps4_seconds0.5.gif").st_mtime_ns == stamp
    (here / "outputs" / "fig2_now_fps4_seconds0.5.gif").unlink()
    assert run("fig2", *SHORT, "-q").output == ""
    # byte-identical, and -q prints nothing
    assert (here / "outputs" / "fig2_now_fps4_seconds0.5.gif").read_bytes() == first


@pytest.mark.parametrize("args, path", [
    (["--mode", "boost"], "outputs/fig2_boost_fps4_seconds0.5.gif"),
    (["--mode", "boost", "--v", "0.8", "--frame", "rest..0.3"],
     "outputs/fig2_boost_v0.8_rest_u0.3_fps4_seconds0.5.gif"),
    (["--frame", "rest", "--style", "print"], "outputs/fig2_now_rest_print_fps4_seconds0.5.gif"),
    (["--frame", "rest,moving", "--v", "0.6"], "outputs/fig2_now_fps4_seconds0.5.gif"),
    (["--L", "2", "--fps", "5"], "outputs/fig2_now_L2_fps5_seconds0.5.gif"),
])
def test_names_follow_plots_rule_with_the_mode_as_the_kind(here, args, path, monkeypatch):
    """The rate and length are named when not the defaults (25 and 6), after the other options (issue 15). The name
    is the planning's, made before anything is drawn: the images are stood in for (`_images_stood_in`), so these
    cases cost what naming and writing cost, not five drawings (the images themselves: tests/animate, and the
    command's real drawings in the other tests here)."""
    _images_stood_in(monkeypatch)
    assert run("fig2", *SHORT, *args).output == f"{path}\n"
    assert (here / path).is_file()


def _images_stood_in(monkeypatch) -> None:
    """`animate` draws stand-ins instead of its scene: as many images as its timeline has instants (the real
    count, checked and written as always), each 8 x 8 pixels of one grey. Everything before the drawing (options,
    planning, the history, the timeline, the checks) and after it (the cost check, the encoder, the file) is the
    command's own."""
    import numpy as np

    import rodparadox.animate.scenes as scenes

    def images_of(history, frames, mode, style, timeline, rod_view=None):
        return (np.full((8, 8, 3), 40 * k, dtype=np.uint8) for k in range(len(timeline)))

    monkeypatch.setattr(scenes, "images_of", images_of)


def test_boost_has_its_frame_count(here):
    run("fig1", "--mode", "boost", "--fps", "5", "--seconds", "1.2")
    assert Image.open(here / "outputs" / "fig1_boost_fps5_seconds1.2.gif").n_frames == 6


def test_png_writes_numbered_stills_into_a_folder_named_like_the_file(here):
    assert run("fig2", *SHORT, "--format", "png").output == "outputs/fig2_now_fps4_seconds0.5/\n"
    names = sorted(p.name for p in (here / "outputs" / "fig2_now_fps4_seconds0.5").iterdir())
    assert names == [f"fig2_now_fps4_seconds0.5_{k:04d}.png" for k in range(2)]
    sizes = {Image.open(here / "outputs" / "fig2_now_fps4_seconds0.5" / n).size for n in names}
    assert len(sizes) == 1
    before = {n: (here / "outputs" / "fig2_now_fps4_seconds0.5" / n).read_bytes() for n in names}
    assert run("fig2", *SHORT, "--format", "png").output == "outputs/fig2_now_fps4_seconds0.5/ (unchanged)\n"
    assert run("fig2", *SHORT, "--format", "png", "-o", "stills").output == "stills/\n"
    assert {n: (here / "stills" / n).read_bytes() for n in names} == before


def test_output_file_and_folder(here, monkeypatch):
    """Where -o puts the file: planned before anything is drawn, so the images are stood in for
    (`_images_stood_in`, as for the names above)."""
    _images_stood_in(monkeypatch)
    (here / "anims").mkdir()
    assert run("fig2", *SHORT, "-o", "anims").output == "anims/fig2_now_fps4_seconds0.5.gif\n"
    assert run("fig2", *SHORT, "-o", "anims/lecture.GIF").output == "anims/lecture.GIF\n"
    assert not (here / "outputs").exists()  # only the default folder is ever created


def test_mp4_has_its_frames(here):
    from rodparadox.animate.encoders import find_ffmpeg

    exe = find_ffmpeg()
    if exe is None:
        pytest.skip("no ffmpeg: neither on the PATH nor from imageio-ffmpeg")
    assert run("fig2", *SHORT, "-o", "a.mp4").output == "a.mp4\n"
    probe = subprocess.run([exe, "-v", "error", "-i", "a.mp4", "-f", "rawvideo", "-pix_fmt", "rgb24", "-"],
                           capture_output=True, check=True).stdout
    assert run("fig2", *SHORT, "--format", "mp4").output == "outputs/fig2_now_fps4_seconds0.5.mp4\n"
    assert (here / "a.mp4").read_bytes() == (here / "outputs" / "fig2_now_fps4_seconds0.5.mp4").read_bytes()
    gif = Image.open(run("fig2", *SHORT).output.strip())
    width, height = (n + n % 2 for n in gif.size)
    assert len(probe) == 2 * width * height * 3


@pytest.mark.parametrize("args, message", [
    (["--fps", "0"], "option --fps must be a whole number of frames per second above 0, got 0."),
    (["--seconds", "-1"], "option --seconds must be a duration above 0 and at most 120 seconds, got -1.0."),
    (["--fps", "30"], "option --fps: a GIF stores frame durations in hundredths of a second, so only 1, 2, 4, 5, "
                      "10, 20, 25, 50 frames per second are exact, got 30; choose one of them or --format mp4."),
    (["--format", "webm"], "option --format must be one of gif, mp4, png, got 'webm'."),
    (["-o", "a.mp4", "--format", "gif"], "option -o names 'a.mp4' but --format is gif; make them agree."),
    (["-o", "a.png", "--format", "png"], "option -o: png writes numbered stills into a folder; name the folder, "
                                          "not 'a.png'."),
    (["-o", "nowhere/a.gif"], "cannot write nowhere/a.gif: the folder nowhere does not exist; create it first."),
    (["-o", "nowhere"], "the output folder nowhere does not exist; create it first."),
    (["-o", ""], "option -o must name a file or folder, got ''."),
    (["--mode", "boost", "--frame", "rest"], "option --frame: in boost mode give the frames to boost between as "
                                             "A..B (each rest, moving or a velocity U relative to S), e.g. "
                                             "rest..moving, got 'rest'."),
    (["--frame", "fast"], "option --frame: a frame must be rest, moving, both, rod (the rod's own view) or a velocity U "
                          "with -0.9999999 <= U <= 0.9999999 (or a comma-separated list of these), got 'fast'."),
    (["--v", "1"], None),
])
def test_bad_input_is_one_sentence_exit_2_and_writes_nothing(here, args, message):
    said = error_of("fig2", *args)
    if message is not None:
        assert said == message
    assert list(here.iterdir()) == []


def _refusal(call):
    from rodparadox.errors import RodParadoxError

    with pytest.raises(RodParadoxError) as e:
        call()
    return e.value


@pytest.mark.parametrize("call, message", [
    (lambda: image_count(6, 0), "option --fps must be a whole number of frames per second above 0, got 0."),
    (lambda: image_count(-1, 25), "option --seconds must be a duration above 0 and at most 120 seconds, got -1."),
    (lambda: image_count(0, 25), "option --seconds must be a duration above 0 and at most 120 seconds, got 0."),
    (lambda: image_count(121, 25), "option --seconds must be a duration above 0 and at most 120 seconds, got 121."),
    (lambda: image_count(float("nan"), 25), "option --seconds must be a duration above 0 and at most 120 seconds, "
                                            "got nan."),
    (lambda: image_count(0.01, 25), "--seconds 0.01 at --fps 25 gives 0 frames; an animation needs at least 2."),
    (lambda: image_count(100, 50), "--seconds 100 at --fps 50 gives 5000 frames; at most 3000 are drawn, so lower "
                                   "one of them."),
    (lambda: boost_ends("rest", 0.6), "option --frame: in boost mode give the frames to boost between as A..B (each "
                                      "rest, moving or a velocity U relative to S), e.g. rest..moving, got 'rest'."),
    (lambda: boost_ends("rest..rest", 0.6), "option --frame: rest..rest boosts from a frame to itself; give two "
                                            "different frames."),
    (lambda: boost_ends("rest..fast", 0.6), "option --frame: each end of A..B must be rest, moving or a velocity U "
                                            "relative to S; not a velocity: 'fast'."),
    (lambda: check_fps("gif", 0), "option --fps must be a whole number of frames per second above 0, got 0."),
    (lambda: check_fps("gif", -5), "option --fps must be a whole number of frames per second above 0, got -5."),
    *[(lambda fps=fps: check_fps("gif", fps),
       f"option --fps: a GIF stores frame durations in hundredths of a second, so only 1, 2, 4, 5, 10, 20, 25, 50 "
       f"frames per second are exact, got {fps}; choose one of them or --format mp4.") for fps in (3, 30, 60)],
    (lambda: timeline(None, (), "sideways", 2), "option --mode must be one of now, boost, got 'sideways'."),
    (lambda: open_sink("a.webm", "webm", 25), "option --format must be one of gif, mp4, png, got 'webm'."),
])
def test_the_librarys_refusals_are_worded_with_the_options_names(call, message):
    """The library keeps the facts (test_animation, test_video); `words` names the options, as the user reads it."""
    from sears_paradox_cli.words import worded

    assert worded(_refusal(call)) == message


def test_a_file_as_the_stills_folder_is_refused(here):
    (here / "stills").write_text("x")
    assert error_of("fig2", *SHORT, "--format", "png", "-o", "stills") == \
        "cannot write the stills into stills: it is a file, not a folder."


def test_an_unwritable_folder_is_refused(here, unwritable_folder):
    said = error_of("fig2", *SHORT, "-o", str(unwritable_folder))
    assert said == (f"cannot write {unwritable_folder}/fig2_now_fps4_seconds0.5.gif: permission denied in the folder "
                    f"{unwritable_folder}.")


def test_mp4_without_ffmpeg_is_one_sentence_and_exit_1(here, monkeypatch):
    import rodparadox.animate.encoders

    monkeypatch.setattr(rodparadox.animate.encoders, "find_ffmpeg", lambda: None)
    assert error_of("fig2", "--format", "mp4", expect=1) == (
        "--format mp4 needs ffmpeg, which was found neither on the PATH nor in the imageio-ffmpeg package; install "
        "one of them: apt-get install ffmpeg, or pip install 'sears-paradox[video]'.")
    assert list(here.iterdir()) == []


#: help and two refused inputs: no matplotlib imported; then an animation whose standard error is a pipe
REFUSED = [["animate", "--help"], ["animate", "fig2", "--fps", "0"], ["animate", "fig2", "--fps", "30"]]
DRAWN = ["animate", "fig2", *SHORT]
register_shared_process("animate_refused", REFUSED, draws=False)
register_shared_process("animate_drawn", [DRAWN], draws=True)


@pytest.mark.xdist_group(SHARED_PROCESS_GROUP)
def test_help_and_refused_input_import_no_matplotlib_and_no_progress_bar_when_stderr_is_not_a_terminal():
    """Four processes before, one now (helpers.shared_process's, shared with other tests' commands): help and two
    refused inputs (test_help_and_refused_input_import_no_matplotlib) run one after another in one interpreter,
    matplotlib looked for after each (the first after which it is there is named; only commands that import no
    matplotlib run before them), then an animation whose standard error is a pipe draws no progress bar
    (test_no_progress_bar_when_stderr_is_not_a_terminal): its own status, standard output and error, and its file
    written in the interpreter's folder, where nothing else writes."""
    probes, folder = shared_process("animate_refused")
    [drawn], _ = shared_process("animate_drawn")
    assert [r["argv"] for r in probes] == REFUSED and drawn["argv"] == DRAWN
    assert "matplotlib" not in probes[0]["modules_before"], "imported by another test's command"
    for result in probes:
        assert "matplotlib" not in result["modules"], result["argv"]
    assert (drawn["code"], drawn["stdout"], drawn["stderr"]) == (0, b"outputs/fig2_now_fps4_seconds0.5.gif\n", b"")
    assert Image.open(os.path.join(folder, "outputs", "fig2_now_fps4_seconds0.5.gif")).n_frames == 2
