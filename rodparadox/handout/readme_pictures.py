"""The README's pictures that no command writes: the first page of fig2's handout as a PNG (`make readme-figures`).

    python -m rodparadox.handout.readme_pictures FOLDER
"""

from __future__ import annotations

import sys
from pathlib import Path


def handout_first_page() -> bytes:
    """Page 1 of `sears-paradox handout fig2` (A4, print style) as a PNG."""
    from rodparadox.physics.models import run_rod as run
    from rodparadox.handout.build import build
    from rodparadox.handout.pdf import page_png
    from rodparadox.io.scenario import load

    return page_png(build([("fig2", run(load("fig2")))]))


def main(folder: str) -> None:
    from rodparadox.io.output import write_atomic

    path = Path(folder) / "fig2_handout_page1.png"
    print(path if write_atomic(path, handout_first_page()) else f"{path} (unchanged)")


if __name__ == "__main__":
    main(*sys.argv[1:])
