"""One self-contained HTML page to explore a scenario: speed, frame and time (the docs, "One page to explore:
`sears-paradox html`").

  inks   the styles' inks as the page draws them (from `render.styles`, no matplotlib)
  data   what the page embeds, computed by the engine: world-lines, impacts, tables, the ledger, per speed and model
  causal_data  the causal rod's part of it, from its invariants' tables (`physics.causal.tables`, through the
               rod interface): its lines, cells of compression, fronts and ledger (matter and stress), for whole
               arrays at once, within the page's bounds (a speed beyond them is left out)
  forces_data  a rod driven by forces (the `driving` capability): its bands, force events, tables and ledger
  windows  each frame's time window (`frames.time_window` for whole arrays of frames): the page's and the ledger's
  page   the page itself: inline CSS, the data as inline JSON, the script in five parts by job (`page.js`: data,
         state, numbers and their formats, boosts; `page_draw.js`; `page_forces.js`: bands and force events;
         `page_tables.js`: tables and legend; `page_controls.js`), plain JavaScript joined into one <script>, no
         build

No matplotlib anywhere here: `sears-paradox html` never imports it.
"""
