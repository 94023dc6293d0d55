"""One self-contained HTML page to explore a scenario: speed, frame and time (README, "One page to explore:
`sears-paradox html`").

  inks   the styles' inks as the page draws them (from `render.styles`, no matplotlib)
  data   what the page embeds, computed by the engine: world-lines, impacts, tables, the ledger, per speed and model
  causal_data  the causal rod's part of it: its invariants tabulated per speed, its lines, cells of compression,
               fronts and ledger (matter and stress) computed for whole arrays at once
  page   the page itself: inline CSS, the data as inline JSON, the script `page.js` (plain JavaScript, no build)

No matplotlib anywhere here: `sears-paradox html` never imports it.
"""
