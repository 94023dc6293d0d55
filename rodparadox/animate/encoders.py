"""Writing an animation's images to files: GIF, MP4 or numbered PNG stills (the docs, "The paradox in
motion"). No matplotlib.

An image is an RGB uint8 numpy array of shape (H, W, 3); every image of one
animation has the same size. `open_sink(path, fmt, fps)` gives a sink:
`sink.add(image)` for each image, then `sink.close()`, which returns True if
the file (or any still) was written and False if it already held exactly
these bytes and was left untouched; `sink.abort()` (or leaving a `with` block
by an exception) throws away what was made, leaving no file behind.
`write_images(path, fmt, fps, images)` does all three for an iterable.

Every format is deterministic: the same images give the same bytes (GIF and
PNG on any machine, MP4 with the same ffmpeg). Files are written atomically
through `output.write_atomic`; stills are written one by one as they come,
each atomically.
"""

from __future__ import annotations

import io
import os
import re
import shutil
import subprocess
import tempfile
import zlib
from pathlib import Path
from typing import Iterable

import numpy as np

from rodparadox.errors import OptionError, ToolMissing, WriteFailed
from rodparadox.io.output import check_folder as check_output_folder, check_target, write_atomic
from rodparadox.animate.palette import GIF_COLOURS, nearest_entries, pack, palette_of

FORMATS = ("gif", "mp4", "png")
#: rates (images per second) a GIF stores exactly: it keeps each image's duration in hundredths of a second
GIF_FPS = (1, 2, 4, 5, 10, 20, 25, 50)
#: the fastest rate for MP4 and stills: a screen shows at most about 60 images a second, and more only costs time
MAX_FPS = 60
#: zlib level for images a GIF holds between its two passes: fast, and a diagram still shrinks 20-fold or more
_HOLD_LEVEL = 1


def check_fps(fmt: str, fps: int) -> int:
    """The rate, in images per second, for a format: a positive integer; for a GIF one whose 100/fps is an integer,
    for MP4 and stills at most MAX_FPS."""
    if isinstance(fps, bool) or not isinstance(fps, int) or fps <= 0:
        raise OptionError("fps", fps, "a whole number of frames per second above 0")
    if fmt != "gif" and fps > MAX_FPS:
        raise OptionError("fps", fps, MAX_FPS, "{what}: {value} frames per second is faster than a screen shows; "
                          "give at most {allowed}.")
    if fmt == "gif" and fps not in GIF_FPS:
        raise OptionError("fps", fps, GIF_FPS, "{what}: a GIF stores frame durations in hundredths of a second, so "
                          "only {choices} frames per second are exact, got {value}; choose one of them or {format} "
                          "mp4.")
    return fps


# --- ffmpeg ----------------------------------------------------------------------------------------

def find_ffmpeg() -> str | None:
    """ffmpeg on the PATH, else the one the optional `imageio-ffmpeg` package ships, else None."""
    found = shutil.which("ffmpeg")
    if found:
        return found
    try:
        import imageio_ffmpeg
    except ImportError:
        return None
    try:
        return imageio_ffmpeg.get_ffmpeg_exe()
    except (RuntimeError, OSError):  # the package without its binary
        return None


def require_ffmpeg() -> str:
    """ffmpeg's path, or one sentence naming both ways to get it."""
    exe = find_ffmpeg()
    if exe is None:
        raise ToolMissing("ffmpeg", "format", "mp4", "{format} {value} needs {tool}, which was found neither on the "
                          "PATH nor in the imageio-ffmpeg package; install one of them: apt-get install ffmpeg, or "
                          "pip install 'sears-paradox[video]'.")
    return exe


def ffmpeg_command(exe: str, width: int, height: int, fps: int, target: str) -> list[str]:
    """Raw RGB images on standard input to H.264 (yuv420p, sizes padded to even with white) in an MP4 at `target`.

    One thread and the bitexact flags, no metadata: the same images give the same bytes with the same ffmpeg.
    """
    return [exe, "-nostdin", "-hide_banner", "-loglevel", "error", "-y",
            "-f", "rawvideo", "-pix_fmt", "rgb24", "-s", f"{width}x{height}", "-r", str(fps), "-i", "-",
            "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2:0:0:white",
            "-c:v", "libx264", "-pix_fmt", "yuv420p", "-threads", "1", "-preset", "medium", "-crf", "18",
            "-flags", "+bitexact", "-fflags", "+bitexact", "-map_metadata", "-1", "-movflags", "+faststart",
            "-f", "mp4", target]


# --- sinks -----------------------------------------------------------------------------------------

class _Sink:
    """What every sink shares: the image size, checked on every image; `with` aborts on an exception."""

    def __init__(self, path: Path, fps: int, size: tuple[int, int] | None):
        self.path, self.fps, self.size, self.count = Path(path), fps, size, 0
        self._done = False

    def _check(self, image: np.ndarray) -> np.ndarray:
        image = np.asarray(image)
        if image.dtype != np.uint8 or image.ndim != 3 or image.shape[2] != 3:
            raise ValueError(f"an image must be an (H, W, 3) uint8 array, got {image.dtype} of shape {image.shape}")
        if self.size is None:
            self.size = (image.shape[1], image.shape[0])
        elif (image.shape[1], image.shape[0]) != tuple(self.size):
            raise ValueError(f"image {self.count} is {image.shape[1]}x{image.shape[0]}, the animation "
                             f"{self.size[0]}x{self.size[1]}")
        return image

    def add(self, image: np.ndarray) -> None:
        raise NotImplementedError

    def close(self) -> bool:
        raise NotImplementedError

    def abort(self) -> None:
        self._done = True

    def __enter__(self):
        return self

    def __exit__(self, kind, value, trace) -> None:
        if not self._done:
            self.abort()


class GifSink(_Sink):
    """A looping GIF, every image 100/fps hundredths of a second, one palette for the whole animation.

    Two passes, so that one palette fits every image and no colour flickers: of each image only the
    rectangle that changed since the image before is held, zlib-compressed, while the colours of all images
    are counted (the first image's every pixel, then each image's changed pixels: the counts of the image
    before, less the colours that left, plus those that came); `close` chooses the palette (`palette_of`),
    maps each image to it (nearest colour, no dither) and writes only the rectangle whose palette entries
    changed since the image before. Memory: the compressed rectangles, the colour counts, and two images
    at a time.
    """

    def __init__(self, path: Path, fps: int, size: tuple[int, int] | None = None):
        check_fps("gif", fps)
        super().__init__(path, fps, size)
        self._held: list[tuple[tuple[int, int, int, int], bytes]] = []
        self._colours = np.empty(0, dtype=np.uint32)  # every colour seen, sorted
        self._counts = np.empty(0, dtype=np.int64)  # its pixels over every image so far
        self._current = np.empty(0, dtype=np.int64)  # its pixels in the last image
        self._previous: np.ndarray | None = None  # the last image, packed

    def add(self, image: np.ndarray) -> None:
        image = self._check(image)
        packed = pack(image)
        if self._previous is None:
            self._count(packed.ravel(), +1)
            box = (0, 0, packed.shape[1], packed.shape[0])
        else:
            changed = packed != self._previous
            rows, cols = np.flatnonzero(changed.any(1)), np.flatnonzero(changed.any(0))
            if len(rows):
                self._count(self._previous[changed], -1)
                self._count(packed[changed], +1)
                box = (int(cols[0]), int(rows[0]), int(cols[-1]) + 1, int(rows[-1]) + 1)
            else:
                box = (0, 0, 0, 0)
        self._counts += self._current
        x0, y0, x1, y1 = box
        self._held.append((box, zlib.compress(np.ascontiguousarray(image[y0:y1, x0:x1]).tobytes(), _HOLD_LEVEL)))
        self._previous = packed
        self.count += 1

    def _count(self, pixels: np.ndarray, sign: int) -> None:
        """Add (sign +1) or remove (-1) these pixels (packed colours) from the last image's colour counts."""
        colours, counts = np.unique(pixels, return_counts=True)
        new = np.setdiff1d(colours, self._colours, assume_unique=True)
        if len(new):
            merged = np.union1d(self._colours, new)
            where = np.searchsorted(merged, self._colours)
            for name in ("_counts", "_current"):
                grown = np.zeros(len(merged), dtype=np.int64)
                grown[where] = getattr(self, name)
                setattr(self, name, grown)
            self._colours = merged
        self._current[np.searchsorted(self._colours, colours)] += sign * counts

    def encode(self) -> bytes:
        """The GIF's bytes (after every image was added)."""
        from PIL import GifImagePlugin, Image

        if not self._held:
            raise ValueError("an animation needs at least one image")
        width, height = self.size
        palette = palette_of(self._colours, self._counts)
        lookup = np.zeros(1 << 24, dtype=np.uint8)  # 0xRRGGBB -> palette index: 16 MiB, a gather per image
        lookup[self._colours] = nearest_entries(self._colours, palette)
        table = np.zeros((GIF_COLOURS, 3), dtype=np.uint8)
        table[:len(palette)] = palette
        out = io.BytesIO()
        out.write(b"GIF89a" + _u16(width) + _u16(height) + bytes([0xF7, 0, 0]) + table.tobytes())
        out.write(b"!\xff\x0bNETSCAPE2.0\x03\x01" + _u16(0) + b"\x00")  # loop forever
        previous = None
        index = np.zeros((height, width), dtype=np.uint8)
        for (x0, y0, x1, y1), held in self._held:
            if x1 > x0:
                crop = np.frombuffer(zlib.decompress(held), dtype=np.uint8).reshape(y1 - y0, x1 - x0, 3)
                index = index.copy()  # `previous` keeps the image before
                index[y0:y1, x0:x1] = lookup[pack(crop)]
            box = _changed_box(previous, index)
            previous = index
            x0, y0, x1, y1 = box
            crop = Image.frombytes("P", (x1 - x0, y1 - y0), np.ascontiguousarray(index[y0:y1, x0:x1]).tobytes())
            crop.putpalette(table.tobytes())
            # disposal 1: keep the image, the next one paints only what changed
            for chunk in GifImagePlugin.getdata(crop, (x0, y0), duration=1000 // self.fps, disposal=1):
                out.write(chunk)
        out.write(b";")
        return out.getvalue()

    def close(self) -> bool:
        data = self.encode()
        self._held, self._previous = [], None
        self._done = True
        return write_atomic(self.path, data)

    def abort(self) -> None:
        self._held = []
        self._previous = None
        super().abort()


class Mp4Sink(_Sink):
    """H.264 in an MP4 through ffmpeg: images streamed to its standard input, written to a temporary folder,
    then moved into place by `write_atomic` (so an unchanged file is left alone)."""

    def __init__(self, path: Path, fps: int, size: tuple[int, int] | None = None, ffmpeg: str | None = None):
        check_fps("mp4", fps)
        super().__init__(path, fps, size)
        self._exe = ffmpeg or require_ffmpeg()
        self._folder: tempfile.TemporaryDirectory | None = None
        self._process: subprocess.Popen | None = None
        self._errors = None

    def _start(self) -> None:
        self._folder = tempfile.TemporaryDirectory(prefix="sears-paradox-")
        self._target = os.path.join(self._folder.name, "video.mp4")
        self._errors = tempfile.TemporaryFile()
        width, height = self.size
        self._process = subprocess.Popen(ffmpeg_command(self._exe, width, height, self.fps, self._target),
                                         stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=self._errors)

    def add(self, image: np.ndarray) -> None:
        image = self._check(image)
        if self._process is None:
            self._start()
        try:
            self._process.stdin.write(np.ascontiguousarray(image).tobytes())
        except BrokenPipeError:
            self._fail()
        self.count += 1

    def _fail(self) -> None:
        status = self._process.wait()
        self._errors.seek(0)
        said = self._errors.read().decode("utf-8", "replace").strip().splitlines()
        self.abort()
        raise WriteFailed(f"cannot write {self.path}: ffmpeg failed with status {status}"
                          + (f": {said[-1]}" if said else "") + ".")

    def close(self) -> bool:
        if self._process is None:
            raise ValueError("an animation needs at least one image")
        try:
            self._process.stdin.close()
        except BrokenPipeError:
            pass
        if self._process.wait() != 0:
            self._fail()
        try:
            data = Path(self._target).read_bytes()
        finally:
            self.abort()
        self._done = True
        return write_atomic(self.path, data)

    def abort(self) -> None:
        if self._process is not None:
            if self._process.poll() is None:
                self._process.kill()
            self._process.wait()
            if self._process.stdin and not self._process.stdin.closed:
                try:
                    self._process.stdin.close()
                except OSError:
                    pass
            self._process = None
        if self._errors is not None:
            self._errors.close()
            self._errors = None
        if self._folder is not None:
            self._folder.cleanup()
            self._folder = None
        super().abort()


class PngSink(_Sink):
    """Numbered stills FOLDER/NAME_0000.png, NAME_0001.png, ..., each written atomically as it comes.

    `path` is the folder; it is created if missing (its parent must exist). A still that already holds
    the same bytes is left untouched. At `close`, stills of this NAME numbered beyond the last image (left by
    an earlier, longer run) are removed, so the folder holds exactly this animation. An interrupted run
    leaves the stills written so far, each whole.
    """

    def __init__(self, path: Path, fps: int, size: tuple[int, int] | None = None, name: str | None = None):
        check_fps("png", fps)
        super().__init__(path, fps, size)
        self.name = name or self.path.name
        self.changed = False
        check_folder(self.path)

    def still(self, k: int) -> Path:
        return self.path / f"{self.name}_{k:04d}.png"

    def add(self, image: np.ndarray) -> None:
        image = self._check(image)
        if self.count == 0:
            self.path.mkdir(exist_ok=True)
        self.changed |= write_atomic(self.still(self.count), png_bytes(image))
        self.count += 1

    def close(self) -> bool:
        if self.count == 0:
            raise ValueError("an animation needs at least one image")
        pattern = re.compile(re.escape(self.name) + r"_(\d{4,})\.png")
        for old in sorted(self.path.iterdir()):
            match = pattern.fullmatch(old.name)
            if match and int(match.group(1)) >= self.count and old.is_file():
                old.unlink()
                self.changed = True
        self._done = True
        return self.changed


def check_folder(folder: str | os.PathLike) -> Path:
    """The folder of the stills: an existing folder, or a new one whose parent exists and can be written."""
    return check_output_folder(folder, "the stills")


def check_stills(folder: str | os.PathLike, name: str, count: int) -> None:
    """Before any still is drawn: each of the `count` stills NAME_0000.png ... can be written into `folder` (none
    is a folder, a dangling link into a missing folder ...), so a clash is said before anything is overwritten."""
    folder = check_folder(folder)
    if folder.is_dir():
        for k in range(count):
            still = folder / f"{name}_{k:04d}.png"
            if os.path.lexists(still):
                check_target(still)


def png_bytes(image: np.ndarray) -> bytes:
    """One still: a PNG with no time or text chunk, compressed at a fixed level, so the same pixels give the
    same bytes."""
    from PIL import Image

    out = io.BytesIO()
    Image.fromarray(np.ascontiguousarray(image), "RGB").save(out, "PNG", optimize=False, compress_level=6)
    return out.getvalue()


def open_sink(path: str | os.PathLike, fmt: str, fps: int, size: tuple[int, int] | None = None, *,
              name: str | None = None):
    """A sink for `fmt` (gif, mp4: a file; png: a folder of stills NAME_0000.png ...); `size` (W, H) or taken
    from the first image."""
    if fmt == "gif":
        return GifSink(Path(path), fps, size)
    if fmt == "mp4":
        return Mp4Sink(Path(path), fps, size)
    if fmt == "png":
        return PngSink(Path(path), fps, size, name=name)
    raise OptionError("format", fmt, FORMATS)


def write_images(path: str | os.PathLike, fmt: str, fps: int, images: Iterable[np.ndarray], *,
                 name: str | None = None) -> bool:
    """Every image into one sink; True if written, False if unchanged. Leaves no file on any exception."""
    sink = open_sink(path, fmt, fps, name=name)
    with sink:
        for image in images:
            sink.add(image)
        return sink.close()


def _changed_box(previous: np.ndarray | None, index: np.ndarray) -> tuple[int, int, int, int]:
    """(x0, y0, x1, y1): the rectangle where `index` differs from `previous`; the whole image for the first, one
    pixel for an identical image (a GIF image cannot be empty, and each image must be there to keep its time)."""
    if previous is None:
        return 0, 0, index.shape[1], index.shape[0]
    changed = previous != index
    rows, cols = np.flatnonzero(changed.any(1)), np.flatnonzero(changed.any(0))
    if len(rows) == 0:
        return 0, 0, 1, 1
    return int(cols[0]), int(rows[0]), int(cols[-1]) + 1, int(rows[-1]) + 1


def _u16(n: int) -> bytes:
    return int(n).to_bytes(2, "little")
