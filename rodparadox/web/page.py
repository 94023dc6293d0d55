"""The page: one self-contained HTML document (docs/html.md, "One page to explore: `sears-paradox html`"). Pure.

Inline CSS (`page.css`), the data (`data.page_data`) as inline JSON, and the script (plain JavaScript in five files
by job, `SCRIPTS`, joined verbatim into one <script>: no build step): nothing is fetched, so the page opens from
`file://` with no network. The same scenarios, options and package give the same bytes: JSON with sorted keys and
Python's shortest round-trip floats, no date, no version.
"""

from __future__ import annotations

import html
import json
from importlib import resources
from typing import Sequence

from rodparadox.physics.model import Scenario
from rodparadox.render.styles import STYLE_NAMES
from rodparadox.web.data import ABOUT_SEVERAL, page_data


def asset(name: str) -> str:
    """A file of the package beside this module (`page.js`, `page.css`), as text."""
    return resources.files("rodparadox.web").joinpath(name).read_text(encoding="utf-8")


#: the script's parts, by job, joined in this order into the page's one <script> (one scope; no build step)
SCRIPTS = ("page.js", "page_draw.js", "page_forces.js", "page_tables.js", "page_controls.js")


def script() -> str:
    """The page's script: its parts (`SCRIPTS`) one after the other, verbatim."""
    return "".join(asset(name) for name in SCRIPTS)


def data_json(data: dict) -> str:
    """The data as JSON safe inside a <script> element: sorted keys, no spaces, `<` escaped (no `</script>`)."""
    return json.dumps(data, sort_keys=True, separators=(",", ":"), ensure_ascii=False, allow_nan=False).replace(
        "<", "\\u003c")


def page(scenarios: Sequence[tuple[str, Scenario]], style: str = "default", shown: str | None = None) -> str:
    """The whole page for the scenarios (name as the user gave it, scenario with --v and --L applied); `shown`:
    the rod it opens on, rigid, causal or both (by default each scenario's own `rod`)."""
    if style not in STYLE_NAMES:
        raise ValueError(f"style must be one of {', '.join(STYLE_NAMES)}, got {style!r}")
    if shown not in (None, "rigid", "causal", "both"):
        raise ValueError(f"shown must be rigid, causal or both, got {shown!r}")
    data = page_data(scenarios, style, shown)
    first = data["scenarios"][0]
    title = " · ".join(s["title"] for s in data["scenarios"])
    about = first["description"] if len(data["scenarios"]) == 1 else ABOUT_SEVERAL
    styles = "".join(f'<option value="{name}">{name}</option>' for name in STYLE_NAMES)
    return TEMPLATE.format(title=html.escape(title), heading=html.escape(first["title"]),
                           about=html.escape(about), styles=styles, css=asset("page.css"), data=data_json(data),
                           script=script())


TEMPLATE = """<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<meta name="generator" content="sears-paradox html">
<title>{title}</title>
<style>
{css}</style>
</head>
<body>
<header>
<h1 id="heading">{heading}</h1>
<p class="about" id="about">{about}</p>
<noscript><p>This page draws with JavaScript; allow scripts for this file to explore it.</p></noscript>
</header>
<main>
<section aria-label="Minkowski diagrams and the rod at one instant">
<div id="panels">
<div class="panel" id="panel-1"><h2 id="panel-1-heading"></h2>
<canvas id="diagram" role="img" aria-label="Minkowski diagram: the rod’s world-sheet and ends, the particles, the impacts and the lines of simultaneity, in the chosen frame"></canvas>
<canvas id="strip" role="img" aria-label="The rod and the particles at the now-line’s instant, the rod coloured by the velocity of its material points"></canvas>
</div>
<div class="panel" id="panel-2" hidden><h2 id="panel-2-heading"></h2>
<canvas id="diagram-2" role="img" aria-label="Minkowski diagram of the causal rod beside the rigid one: its world-sheet shaded by compression, its light fronts, material lines and contacts, in the chosen frame"></canvas>
<canvas id="strip-2" role="img" aria-label="The causal rod and the particles at the now-line’s instant, coloured by the velocity of its material points"></canvas>
</div>
</div>
<ul id="legend" aria-label="Legend"></ul>
</section>
<section aria-label="Controls and tables">
<fieldset>
<legend class="group">Explore</legend>
<div class="control"><label for="scenario">scenario</label><select id="scenario"></select></div>
<fieldset class="control" id="rod"><legend>rod</legend><label><input type="radio" name="rod" id="rod-rigid" value="rigid"> rigid</label><label><input type="radio" name="rod" id="rod-causal" value="causal"> causal (sound at c)</label><label><input type="radio" name="rod" id="rod-both" value="both"> both, side by side</label></fieldset>
<div id="sliders" role="group" aria-label="speed, frame and time">
<div class="control"><label for="speed">speed v of S′</label><input type="range" id="speed" min="0" max="0" step="1" value="0"><output id="speed-value" for="speed"></output></div>
<div class="control"><label for="frame">frame: velocity u relative to S</label><input type="range" id="frame" min="-95" max="95" step="1" value="0"><output id="frame-value" for="frame"></output></div>
<div class="control"><label for="time">time: the now-line</label><input type="range" id="time" min="0" max="1000" step="1" value="500"><output id="time-value" for="time"></output><button type="button" id="play" aria-pressed="false">Play</button></div>
</div>
<p class="notes" id="left-out" hidden></p>
<div class="control"><span>the paper’s frames</span><button type="button" id="frame-rest" aria-pressed="true">S</button><button type="button" id="frame-moving" aria-pressed="false">S′</button></div>
<div class="control"><label for="cones">light cones</label><input type="checkbox" id="cones"></div>
<div class="control"><label for="style">style</label><select id="style">{styles}</select></div>
</fieldset>
</section>
<section class="tables" aria-label="The impacts and the ledger">
<div class="table-set" id="tables-1">
<div class="table-box"><p class="caption" id="events-caption"></p>
<div class="cells" tabindex="0" role="region" aria-labelledby="events-caption"><table id="events" aria-labelledby="events-caption"><thead><tr></tr></thead><tbody></tbody></table></div>
<p class="notes" id="events-notes"></p></div>
<div class="table-box"><p class="caption" id="ledger-caption"></p>
<div class="cells" tabindex="0" role="region" aria-labelledby="ledger-caption"><table id="ledger" aria-labelledby="ledger-caption"><thead><tr></tr></thead><tbody></tbody></table></div>
<p class="notes" id="ledger-notes"></p></div>
</div>
<div class="table-set" id="tables-2" hidden>
<div class="table-box"><p class="caption" id="events-2-caption"></p>
<div class="cells" tabindex="0" role="region" aria-labelledby="events-2-caption"><table id="events-2" aria-labelledby="events-2-caption"><thead><tr></tr></thead><tbody></tbody></table></div>
<p class="notes" id="events-2-notes"></p></div>
<div class="table-box"><p class="caption" id="ledger-2-caption"></p>
<div class="cells" tabindex="0" role="region" aria-labelledby="ledger-2-caption"><table id="ledger-2" aria-labelledby="ledger-2-caption"><thead><tr></tr></thead><tbody></tbody></table></div>
<p class="notes" id="ledger-2-notes"></p></div>
</div>
</section>
</main>
<script type="application/json" id="page-data">{data}</script>
<script>
{script}</script>
</body>
</html>
"""
