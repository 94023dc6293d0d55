"""Atomic writes: whole or nothing, unchanged files untouched, links followed, devices written in place, modes kept."""

import os
import stat

import pytest

from rodparadox.errors import OutputError
from rodparadox.io.output import write_atomic


def test_new_file_then_unchanged_then_changed(tmp_path):
    target = tmp_path / "a.json"
    assert write_atomic(target, b"one") is True and target.read_bytes() == b"one"
    before = target.stat().st_mtime_ns
    assert write_atomic(target, b"one") is False and target.stat().st_mtime_ns == before
    assert write_atomic(target, b"two") is True and target.read_bytes() == b"two"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.json"]  # no temporary left behind


def test_a_symbolic_link_is_followed_and_kept(tmp_path):
    (tmp_path / "real.json").write_bytes(b"old")
    link = tmp_path / "link.json"
    link.symlink_to("real.json")
    write_atomic(link, b"new")
    assert link.is_symlink() and (tmp_path / "real.json").read_bytes() == b"new"


def test_a_replaced_file_keeps_its_permissions(tmp_path):
    target = tmp_path / "private.json"
    target.write_bytes(b"old")
    target.chmod(0o600)
    write_atomic(target, b"new")
    assert stat.S_IMODE(target.stat().st_mode) == 0o600


def test_a_device_is_written_in_place_not_replaced():
    assert write_atomic("/dev/null", b"data") is True
    assert stat.S_ISCHR(os.stat("/dev/null").st_mode)


def test_a_pipe_stays_a_pipe(tmp_path):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    reader = os.open(fifo, os.O_RDONLY | os.O_NONBLOCK)
    try:
        write_atomic(fifo, b"through")
        assert os.read(reader, 100) == b"through" and stat.S_ISFIFO(fifo.stat().st_mode)
    finally:
        os.close(reader)


@pytest.mark.parametrize("make, message", [
    (lambda d: d / "missing" / "x.json", "the folder {d}/missing does not exist; create it first."),
    (lambda d: (d / "file").write_bytes(b"") or d / "file" / "x.json", "{d}/file is a file, not a folder."),
    (lambda d: (d / "sub").mkdir() or d / "sub", "it is a folder."),
])
def test_impossible_targets_are_one_sentence(tmp_path, make, message):
    target = make(tmp_path)
    with pytest.raises(OutputError) as info:
        write_atomic(target, b"x")
    assert str(info.value) == f"cannot write {target}: " + message.format(d=tmp_path)
