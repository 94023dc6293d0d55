"""Fixtures shared by the CLI test files."""

import os
from pathlib import Path

import pytest


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
