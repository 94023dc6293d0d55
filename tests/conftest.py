"""Fixtures shared by the test files, and hypothesis's profile."""

import os
from pathlib import Path

import pytest
from hypothesis import settings

# CI (CI=true) runs the same generated examples every time, so a landing never hangs on a lucky draw;
# a developer's run draws new ones and finds what CI would not
settings.register_profile("ci", derandomize=True, database=None)
if os.environ.get("CI"):
    settings.load_profile("ci")


@pytest.fixture
def unwritable_folder(tmp_path):
    """A folder no new file can be written into: /sys for root (who writes through mode bits), else a locked one."""
    if os.geteuid() == 0:
        yield Path("/sys")
        return
    folder = tmp_path / "locked"
    folder.mkdir()
    folder.chmod(0o500)
    try:
        yield folder
    finally:
        folder.chmod(0o700)
