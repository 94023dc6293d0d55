"""How fast the html page draws in headless Chromium (issue 17: the first drawing under 1 s, each redraw while a
slider is dragged under 16 ms), measured in the browser with performance.now(); run on demand, not by pytest.

    python tests/benchmark_html.py [SCENARIO] [--drags N] [--rod rigid|causal|both]

Builds the page (and says how long that took and its size, and how long the rigid rod's part alone took), opens
it from file:// in /usr/bin/chromium through playwright with every non-file request refused, on the rod asked
for (both, side by side, by default: the dearest to draw), and reports: the first drawing's end from the page's
start (parsing the embedded data included) and the drawing alone; then, for each slider (speed, frame, time), the
mouse dragging it from end to end in N steps, and the median, 95th percentile and largest redraw time.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
from pathlib import Path

ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
        "--disable-component-update", "--no-first-run", "--disable-sync"]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scenario", nargs="?", default="fig2")
    parser.add_argument("--drags", type=int, default=60, help="mouse steps per drag")
    parser.add_argument("--rod", choices=("rigid", "causal", "both"), default="both", help="the rod the page opens on")
    options = parser.parse_args()

    from playwright.sync_api import sync_playwright

    from rodparadox.io.scenario import load
    from rodparadox.web import data
    from rodparadox.web.page import page

    import rodparadox.physics.causal  # noqa: F401  (the causal rod's imports, once, outside the timings)

    scenario = [(options.scenario, load(options.scenario))]
    start = time.perf_counter()
    text = page(scenario, shown=options.rod)
    built = time.perf_counter() - start
    models, data.MODELS = data.MODELS, ("rigid",)
    start = time.perf_counter()
    rigid = page(scenario)
    rigid_built = time.perf_counter() - start
    data.MODELS = models
    print(f"page built in {built:.2f} s: {len(text.encode('utf-8')):,} bytes (the rigid rod alone: {rigid_built:.2f} s, "
          f"{len(rigid.encode('utf-8')):,} bytes)")
    with tempfile.TemporaryDirectory() as folder, sync_playwright() as driver:
        path = Path(folder) / f"{options.scenario}.html"
        path.write_text(text, encoding="utf-8")
        browser = driver.chromium.launch(executable_path="/usr/bin/chromium", args=ARGS)
        context = browser.new_context(viewport={"width": 1280, "height": 860})
        refused = []
        context.route("**/*", lambda route: route.continue_() if route.request.url.startswith("file://")
                      else (refused.append(route.request.url), route.abort()))
        tab = context.new_page()
        tab.goto(path.as_uri())
        tab.wait_for_function("window.searsParadox && window.searsParadox.timings.drawnAt !== null")
        first = tab.evaluate("window.searsParadox.timings")
        print(f"first drawing: done {first['drawnAt']:.0f} ms after the page's start (the drawing itself "
              f"{first['first']:.1f} ms)")
        for slider in ("speed", "frame", "time"):
            tab.evaluate("window.searsParadox.timings.redraws.length = 0")
            box = tab.locator(f"#{slider}").bounding_box()
            y = box["y"] + box["height"] / 2
            tab.mouse.move(box["x"] + 2, y)
            tab.mouse.down()
            for k in range(options.drags + 1):
                tab.mouse.move(box["x"] + 2 + (box["width"] - 4) * k / options.drags, y)
                tab.evaluate("new Promise((done) => requestAnimationFrame(() => done()))")
            tab.mouse.up()
            times = sorted(tab.evaluate("window.searsParadox.timings.redraws"))
            if not times:
                print(f"{slider}: no redraw recorded")
                continue
            p95 = times[min(len(times) - 1, int(0.95 * len(times)))]
            print(f"dragging {slider}: {len(times)} redraws, median {statistics.median(times):.1f} ms, "
                  f"95th percentile {p95:.1f} ms, largest {times[-1]:.1f} ms")
        print(f"requests refused: {len(refused)}")
        browser.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
