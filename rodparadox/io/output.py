"""Deterministic, atomic writes (docs/plot.md, "Drawing the figures": reproducible, safe for make): a file is replaced whole
or not at all.

A file whose bytes would not change is left untouched, so make and git see
no change; a new file is written to a temporary name in the same folder and
renamed over the old one, so an interrupted run never leaves half a file.
A symbolic link is followed (its target is replaced, the link kept); a
device or pipe (/dev/null, /dev/stdout, a FIFO) is written in place, never
replaced by a file; a replaced file keeps its permissions.
"""

from __future__ import annotations

import os
import stat
import tempfile
from pathlib import Path

from rodparadox.errors import OutputError, WriteFailed


def _reason(e: OSError) -> str:
    return (e.strerror or str(e)).lower()


def check_target(path: str | os.PathLike) -> Path:
    """Say in one sentence why `path` cannot be written, before anything is computed; return the file to write.

    A symbolic link is followed: its target is the file written (a dangling link's target is created).
    """
    shown = Path(path)
    if is_stream(shown):  # /dev/stdout into a pipe: its link leads to no path (pipe:[...]), it is written in place
        return shown
    real = Path(os.path.realpath(path))  # through symbolic links: replace the target, keep the link
    folder = real.parent
    if not folder.is_dir():
        what = "is a file, not a folder" if folder.exists() else "does not exist"
        if os.path.islink(shown) and real != shown.absolute():
            raise OutputError(f"cannot write {shown}: it is a symbolic link to {os.readlink(shown)}, whose folder "
                              f"{folder} {what}.")
        if folder.exists():
            raise OutputError(f"cannot write {shown}: {shown.parent} is a file, not a folder.")
        raise OutputError(f"cannot write {shown}: the folder {shown.parent} does not exist; create it first.")
    try:
        old = real.stat()
    except FileNotFoundError:
        old = None
    except OSError as e:
        raise OutputError(f"cannot write {shown}: {_reason(e)}.") from None
    if old is not None and stat.S_ISDIR(old.st_mode):
        raise OutputError(f"cannot write {shown}: it is a folder.")
    if old is None or stat.S_ISREG(old.st_mode):
        # a new file goes in beside the old one and is renamed: the folder must take a new file
        refused = _refuses_new_files(folder)
        if refused:
            raise OutputError(f"cannot write {shown}: {refused} in the folder {shown.parent}.")
    return real


def _refuses_new_files(folder: Path) -> str | None:
    """Why no new file can be made in `folder` (None if one can), found before anything is computed: the mode
    bits first, then by making and removing an empty file there, since root passes the mode bits of folders it
    still cannot write into (/sys, a read-only mount)."""
    if not os.access(folder, os.W_OK | os.X_OK):
        return "permission denied"
    try:
        handle, name = tempfile.mkstemp(dir=folder, prefix=".sears-paradox-", suffix=".part")
    except OSError as e:
        return _reason(e)
    os.close(handle)
    os.unlink(name)
    return None


def is_stream(path: str | os.PathLike) -> bool:
    """Whether `path` is, through any links, a device or a pipe (/dev/null, /dev/stdout, a FIFO): written in
    place, never replaced by a file."""
    try:
        mode = os.stat(path).st_mode
    except (OSError, ValueError):
        return False
    return not (stat.S_ISREG(mode) or stat.S_ISDIR(mode))


def write_atomic(path: str | os.PathLike, data: bytes) -> bool:
    """Write `data` to `path`; return False if the file already held exactly these bytes.

    Refuses an impossible target with `OutputError` (`check_target`); a write the system fails part-way
    (a full disk) raises `WriteFailed` and leaves the old file, if any, as it was.
    """
    shown = Path(path)
    path = check_target(path)
    folder = path.parent
    try:
        old = path.stat()
    except FileNotFoundError:
        old = None
    except OSError as e:
        raise OutputError(f"cannot write {shown}: {_reason(e)}.") from None
    if old is not None and not stat.S_ISREG(old.st_mode):
        return _write_stream(shown, data)
    try:
        if old is not None and old.st_size == len(data) and path.read_bytes() == data:
            return False
    except OSError:
        pass  # unreadable: try to replace it, and report that if it fails
    try:
        fd, temporary = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".part", dir=folder)
    except OSError as e:
        raise OutputError(f"cannot write {shown}: {_reason(e)} in the folder {shown.parent}.") from None
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
            f.flush()
            os.fsync(f.fileno())
        os.chmod(temporary, stat.S_IMODE(old.st_mode) if old is not None else 0o666 & ~_umask())
        os.replace(temporary, path)
    except BaseException as e:
        try:
            os.unlink(temporary)
        except OSError:
            pass
        if isinstance(e, OSError):
            raise WriteFailed(f"cannot write {shown}: {_reason(e)}.") from None
        raise
    return True


def _write_stream(path: Path, data: bytes) -> bool:
    """A device or pipe (/dev/null, /dev/stdout, a FIFO): written in place, never replaced by a file."""
    try:
        f = open(path, "wb", buffering=0)
    except OSError as e:
        raise OutputError(f"cannot write {path}: {_reason(e)}.") from None
    try:
        with f:
            view = memoryview(data)
            while view:  # a pipe may take part of a write: write the rest, or hear that its reader went away
                view = view[f.write(view) or 0:]
    except BrokenPipeError:
        raise  # the reader of a pipe went away: the caller ends quietly, as for standard output
    except OSError as e:
        raise WriteFailed(f"cannot write {path}: {_reason(e)}.") from None
    return True


def _umask() -> int:
    """The process's umask, read without changing it (Linux); 0o022 where it cannot be read."""
    try:
        with open("/proc/self/status") as f:
            for line in f:
                if line.startswith("Umask:"):
                    return int(line.split()[1], 8)
    except OSError:
        pass
    return 0o022


def check_folder(folder: str | os.PathLike, what: str) -> Path:
    """A folder to write `what` into: an existing folder that can be written, or a new one whose parent exists
    and can be written (the caller creates it, `make_folder`)."""
    folder = Path(folder)
    if folder.is_dir():
        refused = _refuses_new_files(folder)
        if refused:
            raise OutputError(f"cannot write {what} into {folder}: {refused}.")
        return folder
    if folder.exists():
        raise OutputError(f"cannot write {what} into {folder}: it is a file, not a folder.")
    parent = folder.absolute().parent
    if not parent.is_dir():
        raise OutputError(f"cannot create the folder {folder} for {what}: the folder {folder.parent} does not "
                          f"exist; create it first.")
    refused = _refuses_new_files(parent)
    if refused:
        raise OutputError(f"cannot create the folder {folder} for {what}: {refused} in the folder "
                          f"{folder.parent}.")
    return folder


def write_folder(folder: str | os.PathLike, files: dict[str, bytes]) -> list[tuple[Path, bool]]:
    """Write every file of `files` (name -> bytes) into `folder`, creating it if missing; each file atomically,
    an unchanged one left alone. Returns (path, written) in the order given."""
    folder = Path(folder)
    try:
        folder.mkdir(exist_ok=True)
    except OSError as e:
        raise OutputError(f"cannot create the folder {folder}: {_reason(e)}.") from None
    return [(folder / name, write_atomic(folder / name, data)) for name, data in files.items()]
