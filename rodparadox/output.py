"""Deterministic, atomic writes (STYLE.md `output`): a file is replaced whole or not at all.

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

from .errors import OutputError


def write_atomic(path: str | os.PathLike, data: bytes) -> bool:
    """Write `data` to `path`; return False if the file already held exactly these bytes."""
    shown = Path(path)
    path = Path(os.path.realpath(path))  # through symbolic links: replace the target, keep the link
    folder = path.parent
    if not folder.is_dir():
        what = "is not a folder" if folder.exists() else "does not exist; create it first"
        raise OutputError(f"cannot write {shown}: the folder {shown.parent} {what}.")
    try:
        old = path.stat()
    except FileNotFoundError:
        old = None
    except OSError as e:
        raise OutputError(f"cannot write {shown}: {(e.strerror or str(e)).lower()}.") from None
    if old is not None and stat.S_ISDIR(old.st_mode):
        raise OutputError(f"cannot write {shown}: it is a folder.")
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
        raise OutputError(f"cannot write {shown}: {(e.strerror or str(e)).lower()} in the folder {shown.parent}.") from None
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
            raise OutputError(f"cannot write {shown}: {(e.strerror or str(e)).lower()}.") from None
        raise
    return True


def _write_stream(path: Path, data: bytes) -> bool:
    """A device or pipe (/dev/null, /dev/stdout, a FIFO): written in place, never replaced by a file."""
    try:
        with open(path, "wb") as f:
            f.write(data)
    except OSError as e:
        raise OutputError(f"cannot write {path}: {(e.strerror or str(e)).lower()}.") from None
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
