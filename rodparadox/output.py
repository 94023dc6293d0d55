"""Deterministic, atomic writes (STYLE.md `output`): a file is replaced whole or not at all.

A file whose bytes would not change is left untouched, so make and git see
no change; a new file is written to a temporary name in the same folder and
renamed over the old one, so an interrupted run never leaves half a file.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

from .errors import OutputError


def write_atomic(path: str | os.PathLike, data: bytes) -> bool:
    """Write `data` to `path`; return False if the file already held exactly these bytes."""
    path = Path(path)
    folder = path.parent
    if not folder.is_dir():
        raise OutputError(f"cannot write {path}: the folder {folder} does not exist; create it first.")
    if path.is_dir():
        raise OutputError(f"cannot write {path}: it is a folder.")
    try:
        if path.is_file() and path.stat().st_size == len(data) and path.read_bytes() == data:
            return False
    except OSError:
        pass  # unreadable: try to replace it, and report that if it fails
    try:
        fd, temporary = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".part", dir=folder)
    except OSError as e:
        raise OutputError(f"cannot write {path}: {e.strerror.lower()} in the folder {folder}.") from None
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.chmod(temporary, 0o644)
        os.replace(temporary, path)
    except BaseException as e:
        try:
            os.unlink(temporary)
        except OSError:
            pass
        if isinstance(e, OSError):
            raise OutputError(f"cannot write {path}: {(e.strerror or str(e)).lower()}.") from None
        raise
    return True
