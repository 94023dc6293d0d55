"""The gallery's pictures: every built-in scenario in configs/, both rods (the rigid rod's row above the causal
rod's, as `sears-paradox plot NAME --rod both` draws them), in each style; and the gallery page that shows them.

    python docs/gallery.py            draw the pictures that are missing or out of date, write docs/gallery.md
    python docs/gallery.py --all      draw every picture again

`make gallery` (and so `make docs`) runs it. Each picture is the figure `plot --rod both --style STYLE` draws, saved
as a PNG of modest size (about 800 pixels wide) in 256 colours, so that the gallery stays small in the repository.
`docs/gallery/made-from.txt` records, for each picture, the sha256 of the scenario file and of the package's
sources it was drawn from, and the matplotlib that drew it: a picture is out of date when either changed.
tests/test_docs.py checks the page and that record, and draws a few pictures again to compare them byte for byte.
"""

from __future__ import annotations

import hashlib
import io
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
CONFIGS = ROOT / "configs"
GALLERY = ROOT / "docs" / "gallery"
PAGE = ROOT / "docs" / "gallery.md"
STYLES = ("default", "print", "slides")
#: pixels across a picture: about 800 (slides are wider pages of larger type, so fewer dots an inch)
WIDTH_PIXELS = 800


def scenarios() -> list[str]:
    """Every built-in scenario, struck by particles or driven by forces at its ends."""
    return sorted(p.stem for p in CONFIGS.glob("*.yaml"))


def picture_name(name: str, style: str) -> str:
    return f"{name}_{style}.png"


def sources_digest() -> str:
    """One sha256 over the package's sources (rodparadox/, cli/), in a fixed order: what draws the pictures."""
    digest = hashlib.sha256()
    for path in sorted([*ROOT.glob("rodparadox/**/*.py"), *ROOT.glob("cli/*.py")]):
        digest.update(str(path.relative_to(ROOT)).encode() + b"\0" + path.read_bytes() + b"\0")
    return digest.hexdigest()


def record(name: str, sources: str) -> str:
    """The line of made-from.txt for one scenario's pictures."""
    import matplotlib

    config = hashlib.sha256((CONFIGS / f"{name}.yaml").read_bytes()).hexdigest()
    return f"{name} config={config} sources={sources} matplotlib={matplotlib.__version__}"


def draw(name: str, style: str) -> bytes:
    """The PNG of `sears-paradox plot configs/NAME.yaml --rod both --style STYLE`'s figure."""
    from PIL import Image

    from rodparadox import render
    from rodparadox.io.scenario import load
    from rodparadox.physics.frames import paper_frames
    from rodparadox.physics.models import run_rods

    scenario = load(str(CONFIGS / f"{name}.yaml"))
    rigid, causal = run_rods(scenario, "both")  # on the same particles (or forces), as plot --rod both runs them
    diagram = render.draw_both(rigid, causal, paper_frames(scenario.v), style)
    width_inches = diagram.figure.get_figwidth()
    buffer = io.BytesIO()
    diagram.savefig(buffer, format="png", dpi=WIDTH_PIXELS / width_inches)
    image = Image.open(buffer).convert("RGB").quantize(256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE)
    out = io.BytesIO()
    image.save(out, format="png", optimize=True)
    return out.getvalue()


def page() -> str:
    """docs/gallery.md: a section per scenario, its description, and its picture in each style."""
    from rodparadox.io.scenario import load

    lines = ["# Gallery", "",
             "Every built-in scenario (the files in `configs/`), drawn by the tool with both rods: in each picture the",
             "paper's rigid rod is the upper row and the causal rod, whose sound travels at c, the lower row, each",
             "in the rod's rest frame S (left) and in S′ (right). Each is shown in the three styles: `default`",
             "(screen and colour print), `print` (black and white, for journals and photocopies) and `slides`",
             "(projection). The same figure in full resolution, as SVG, PDF or PNG, is",
             "`sears-paradox plot NAME --rod both --style STYLE`; `make gallery` draws these pictures again.", ""]
    for name in scenarios():
        scenario = load(str(CONFIGS / f"{name}.yaml"))
        description = " ".join(scenario.description.split())
        lines += [f"## `{name}`", "", f"{description} (v = {scenario.v:g})", ""]
        for style in STYLES:
            lines += [f"![{name}, both rods, style {style}](gallery/{picture_name(name, style)})", ""]
    return "\n".join(lines).rstrip("\n") + "\n"


def main(argv: list[str]) -> int:
    import matplotlib

    matplotlib.use("Agg")
    GALLERY.mkdir(exist_ok=True)
    made_from = GALLERY / "made-from.txt"
    old = dict(line.split(" ", 1) for line in made_from.read_text().splitlines()) if made_from.exists() else {}
    sources = sources_digest()
    new = {}
    for name in scenarios():
        line = record(name, sources)
        new[name] = line.split(" ", 1)[1]
        fresh = old.get(name) == new[name] and all((GALLERY / picture_name(name, s)).exists() for s in STYLES)
        if fresh and "--all" not in argv:
            continue
        for style in STYLES:
            path = GALLERY / picture_name(name, style)
            data = draw(name, style)
            if not path.exists() or path.read_bytes() != data:
                path.write_bytes(data)
                print(path.relative_to(ROOT))
    wanted = {picture_name(n, s) for n in scenarios() for s in STYLES}
    for stale in GALLERY.glob("*.png"):
        if stale.name not in wanted:
            stale.unlink()
    made_from.write_text("".join(f"{name} {new[name]}\n" for name in sorted(new)))
    PAGE.write_text(page())
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
