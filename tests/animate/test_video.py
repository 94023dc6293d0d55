"""Writing images: GIF (Pillow), MP4 (ffmpeg), numbered PNG stills. Read back with Pillow or ffmpeg; the images
are made here, so every expected pixel is known."""

import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from rodparadox.animate import encoders as video
from rodparadox.animate import palette
from rodparadox.errors import OptionError, OutputError, ToolMissing


def images(count=6, width=41, height=23):
    """A small animation of a few flat colours (a red box moving over white, a fixed green band): 5 colours."""
    out = []
    for k in range(count):
        f = np.full((height, width, 3), 255, np.uint8)
        f[2:8, 3 * k:3 * k + 6] = (213, 94, 0)
        f[12:16, :] = (0, 158, 115)
        f[18, k] = (0, 0, 0)
        out.append(f)
    return out


def gradient_images(count=4, width=64, height=48):
    """Many colours (a smooth gradient with a moving dot): more than a GIF's 256."""
    y, x = np.mgrid[0:height, 0:width]
    out = []
    for k in range(count):
        f = np.stack([x * 4, y * 5, (x + y + 7 * k) % 256], axis=-1).astype(np.uint8)
        f[10:14, 5 + 3 * k:9 + 3 * k] = (255, 255, 255)
        out.append(f)
    return out


def gif_images(path):
    im = Image.open(path)
    out = []
    for k in range(im.n_frames):
        im.seek(k)
        out.append((np.asarray(im.convert("RGB")), im.info.get("duration")))
    return out, im.info.get("loop")


@pytest.mark.parametrize("fps", video.GIF_FPS)
def test_gif_holds_every_image_exactly_with_its_duration_and_loops(tmp_path, fps):
    made = images()
    assert video.write_images(tmp_path / "a.gif", "gif", fps, made) is True
    read, loop = gif_images(tmp_path / "a.gif")
    assert loop == 0 and len(read) == len(made)
    for (pixels, duration), want in zip(read, made):
        assert duration == 1000 // fps and 1000 % fps == 0
        assert np.array_equal(pixels, want)


def test_gif_keeps_identical_images_as_images(tmp_path):
    made = images(3)
    made = [made[0], made[0], made[1], made[1], made[1]]
    video.write_images(tmp_path / "a.gif", "gif", 10, made)
    read, _ = gif_images(tmp_path / "a.gif")
    assert len(read) == 5 and all(np.array_equal(p, m) for (p, _), m in zip(read, made))


def test_gif_with_many_colours_is_as_close_as_a_median_cut_of_all_images_and_keeps_large_areas_exact(tmp_path):
    """The yardstick: Pillow's own median cut of all the images at once, without dithering (thousands of colours
    in a smooth ramp: the worst case for 256)."""
    made = gradient_images()
    video.write_images(tmp_path / "g.gif", "gif", 25, made)
    read, _ = gif_images(tmp_path / "g.gif")
    assert len({tuple(c) for p, _ in read for c in p.reshape(-1, 3)}) <= 256
    everything = np.concatenate(made)
    median_cut = Image.fromarray(everything).quantize(256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE)
    yardstick = np.abs(np.asarray(median_cut.convert("RGB")).astype(int) - everything).mean()
    error = np.abs(np.concatenate([p for p, _ in read]).astype(int) - everything)
    assert error.mean() <= 1.05 * yardstick
    for (pixels, _), want in zip(read, made):
        assert np.array_equal(pixels[10:14, 5:9][want[10:14, 5:9] == 255], want[10:14, 5:9][want[10:14, 5:9] == 255])


def test_the_gif_counts_every_pixel_of_every_image_though_it_looks_only_at_what_changed():
    """The palette is chosen from the colour counts of all images; the sink counts the first image whole and then
    only the pixels that changed. The counts must equal a plain count of every pixel of every image."""
    made = gradient_images(5) + [gradient_images(5)[-1]] + images(3, 64, 48) + gradient_images(2)
    sink = video.GifSink(Path("unused.gif"), 25)
    for image in made:
        sink.add(image)
    colours, counts = np.unique(np.concatenate([palette.pack(f).ravel() for f in made]), return_counts=True)
    assert np.array_equal(sink._colours, colours)
    assert np.array_equal(sink._counts, counts)
    sink.abort()


@pytest.mark.parametrize("fps", [0, 3, 30, 60, -5])
def test_gif_refuses_a_rate_it_cannot_store(fps):
    with pytest.raises(OptionError) as e:
        video.check_fps("gif", fps)
    assert (e.value.what, e.value.value) == ("fps", fps)  # the command line's sentence: test_animate_cli
    if fps <= 0:
        assert str(e.value) == f"fps must be a whole number of frames per second above 0, got {fps}."
    else:
        assert str(e.value) == (f"fps: a GIF stores frame durations in hundredths of a second, so only "
                                f"1, 2, 4, 5, 10, 20, 25, 50 frames per second are exact, got {fps}; choose one of "
                                f"them or format mp4.")


def test_gif_and_png_are_byte_identical_twice_and_an_unchanged_file_is_left_alone(tmp_path):
    made = gradient_images()
    first, second = tmp_path / "1.gif", tmp_path / "2.gif"
    assert video.write_images(first, "gif", 25, made) and video.write_images(second, "gif", 25, made)
    assert first.read_bytes() == second.read_bytes()
    before = os.stat(first)
    assert video.write_images(first, "gif", 25, made) is False
    after = os.stat(first)
    assert (after.st_ino, after.st_mtime_ns) == (before.st_ino, before.st_mtime_ns)

    assert video.write_images(tmp_path / "s1", "png", 25, made, name="x") is True
    assert video.write_images(tmp_path / "s2", "png", 25, made, name="x") is True
    names = sorted(p.name for p in (tmp_path / "s1").iterdir())
    assert names == ["x_0000.png", "x_0001.png", "x_0002.png", "x_0003.png"]
    assert all((tmp_path / "s1" / n).read_bytes() == (tmp_path / "s2" / n).read_bytes() for n in names)
    stamps = {n: os.stat(tmp_path / "s1" / n).st_mtime_ns for n in names}
    assert video.write_images(tmp_path / "s1", "png", 25, made, name="x") is False
    assert stamps == {n: os.stat(tmp_path / "s1" / n).st_mtime_ns for n in names}


def test_png_stills_hold_the_images_and_no_time_chunk(tmp_path):
    made = images(3)
    video.write_images(tmp_path / "s", "png", 5, made, name="fig2_now")
    for k, want in enumerate(made):
        data = (tmp_path / "s" / f"fig2_now_{k:04d}.png").read_bytes()
        assert b"tIME" not in data and b"tEXt" not in data
        assert np.array_equal(np.asarray(Image.open(tmp_path / "s" / f"fig2_now_{k:04d}.png").convert("RGB")), want)


def test_png_removes_the_stills_an_earlier_longer_run_left_and_nothing_else(tmp_path):
    video.write_images(tmp_path / "s", "png", 5, images(5), name="a")
    (tmp_path / "s" / "other_0009.png").write_bytes(b"keep")
    (tmp_path / "s" / "notes.txt").write_text("keep")
    assert video.write_images(tmp_path / "s", "png", 5, images(2), name="a") is True
    assert sorted(p.name for p in (tmp_path / "s").iterdir()) == ["a_0000.png", "a_0001.png", "notes.txt",
                                                                   "other_0009.png"]


def test_png_refuses_a_file_as_its_folder_and_a_missing_parent(tmp_path):
    (tmp_path / "f").write_text("x")
    with pytest.raises(OutputError) as e:
        video.open_sink(tmp_path / "f", "png", 5)
    assert str(e.value) == f"cannot write the stills into {tmp_path / 'f'}: it is a file, not a folder."
    with pytest.raises(OutputError) as e:
        video.open_sink(tmp_path / "no" / "s", "png", 5)
    assert str(e.value) == (f"cannot create the folder {tmp_path / 'no' / 's'} for the stills: the folder "
                            f"{tmp_path / 'no'} does not exist; create it first.")


def failing(made, at, error):
    for k, f in enumerate(made):
        if k == at:
            raise error
        yield f


@pytest.mark.parametrize("error", [RuntimeError("drawing failed"), KeyboardInterrupt()])
def test_an_exception_mid_way_leaves_no_gif_and_no_temporary(tmp_path, error):
    with pytest.raises(type(error)):
        video.write_images(tmp_path / "a.gif", "gif", 25, failing(images(), 3, error))
    assert list(tmp_path.iterdir()) == []
    (tmp_path / "a.gif").write_bytes(b"old")
    with pytest.raises(type(error)):
        video.write_images(tmp_path / "a.gif", "gif", 25, failing(images(), 3, error))
    assert [p.name for p in tmp_path.iterdir()] == ["a.gif"] and (tmp_path / "a.gif").read_bytes() == b"old"


def test_images_of_another_size_are_refused(tmp_path):
    made = images(2) + images(1, width=40)
    with pytest.raises(ValueError, match="image 2 is 40x23, the animation 41x23"):
        video.write_images(tmp_path / "a.gif", "gif", 25, made)
    assert list(tmp_path.iterdir()) == []


# --- mp4 -------------------------------------------------------------------------------------------

def ffmpegs():
    """Every ffmpeg this machine has: on the PATH, and from imageio-ffmpeg."""
    out = []
    if shutil.which("ffmpeg"):
        out.append(pytest.param(shutil.which("ffmpeg"), id="path"))
    try:
        import imageio_ffmpeg

        out.append(pytest.param(imageio_ffmpeg.get_ffmpeg_exe(), id="imageio-ffmpeg"))
    except (ImportError, RuntimeError):
        pass
    return out or [pytest.param(None, marks=pytest.mark.skip(reason="no ffmpeg: neither on the PATH nor from "
                                                                     "imageio-ffmpeg"))]


def decoded(exe, path, width, height):
    """The MP4's images decoded back to RGB by ffmpeg."""
    raw = subprocess.run([exe, "-v", "error", "-i", str(path), "-f", "rawvideo", "-pix_fmt", "rgb24", "-"],
                         capture_output=True, check=True).stdout
    return np.frombuffer(raw, np.uint8).reshape(-1, height, width, 3)


@pytest.mark.parametrize("exe", ffmpegs())
def test_mp4_holds_every_image_padded_to_even_and_is_byte_identical_twice(tmp_path, exe, monkeypatch):
    monkeypatch.setattr(video, "find_ffmpeg", lambda: exe)
    made = [np.repeat(np.repeat(f, 4, 0), 4, 1) for f in images(8)]  # 164 x 92: x264 needs some size
    made = [f[:, :-1] for f in made]  # 163 wide: odd, padded to 164
    assert video.write_images(tmp_path / "a.mp4", "mp4", 10, made) is True
    assert video.write_images(tmp_path / "b.mp4", "mp4", 10, made) is True
    assert (tmp_path / "a.mp4").read_bytes() == (tmp_path / "b.mp4").read_bytes()
    data = (tmp_path / "a.mp4").read_bytes()
    assert b"Lavf" not in data  # bitexact: no muxer version string
    back = decoded(exe, tmp_path / "a.mp4", 164, 92)
    assert len(back) == 8
    for got, want in zip(back, made):
        assert np.abs(got[:, :163].astype(int) - want.astype(int)).mean() < 6  # lossy, but the picture
        white = want[:, -1].min(1) == 255  # rows whose last column is white: no colour bleeds into the padding
        assert got[white, 163].min() > 240  # the padding is white
    before = os.stat(tmp_path / "a.mp4")
    assert video.write_images(tmp_path / "a.mp4", "mp4", 10, made) is False
    assert os.stat(tmp_path / "a.mp4").st_mtime_ns == before.st_mtime_ns
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.mp4", "b.mp4"]


@pytest.mark.parametrize("exe", ffmpegs())
def test_an_exception_mid_way_leaves_no_mp4_and_no_ffmpeg(tmp_path, exe, monkeypatch):
    monkeypatch.setattr(video, "find_ffmpeg", lambda: exe)
    made = [np.repeat(np.repeat(f, 4, 0), 4, 1) for f in images(6)]
    with pytest.raises(RuntimeError):
        video.write_images(tmp_path / "a.mp4", "mp4", 10, failing(made, 4, RuntimeError("drawing failed")))
    assert list(tmp_path.iterdir()) == []


def test_mp4_without_any_ffmpeg_is_one_sentence_naming_both_ways(tmp_path, monkeypatch):
    monkeypatch.setattr(shutil, "which", lambda name: None)
    monkeypatch.setitem(sys.modules, "imageio_ffmpeg", None)  # import fails as if not installed
    assert video.find_ffmpeg() is None
    with pytest.raises(ToolMissing) as e:
        video.open_sink(tmp_path / "a.mp4", "mp4", 25)
    assert (e.value.tool, e.value.what, e.value.value) == ("ffmpeg", "format", "mp4")  # worded: test_animate_cli
    assert str(e.value) == ("format mp4 needs ffmpeg, which was found neither on the PATH nor in the "
                            "imageio-ffmpeg package; install one of them: apt-get install ffmpeg, or pip install "
                            "'sears-paradox[video]'.")
    assert list(tmp_path.iterdir()) == []
