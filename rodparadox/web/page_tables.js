// The page's script, part 4 of 5 (page.py joins the parts into one <script>): the tables and the legend.
  // --- the tables ------------------------------------------------------------------------------------------
  function fillTable(table, caption, header, rows, notes) {
    $(table.id + "-caption").textContent = caption;  // above the table, wrapped to the window: only the cells scroll
    const head = table.tHead.rows[0] || table.tHead.insertRow();
    head.innerHTML = "";
    for (const h of header) { const th = document.createElement("th"); th.scope = "col"; th.textContent = h; head.appendChild(th); }
    const body = table.tBodies[0];
    body.innerHTML = "";
    for (const row of rows) {
      const tr = body.insertRow();
      row.forEach((text, k) => {
        const cell = k === 0 ? document.createElement("th") : document.createElement("td");
        if (k === 0) cell.scope = "row";
        cell.textContent = text; tr.appendChild(cell);
      });
    }
    $(table.id + "-notes").textContent = notes.join(" ");
  }

  function drawEvents(panel, g) {
    const m = g.model, name = frameName(state.u), L = scenario().L, causal = m.model === "causal";
    const rod = causal ? ", the causal rod: each contact and its separation" : ", the rigid rod";
    if (name !== "u") {
      const t = m.tables[name];
      fillTable(panel.events, `${t.caption} (v = ${shown(v(), 10)}${rod}): ` +
                (m.forces ? "as the events are printed" : "every digit, with the exact fractions"),
                t.header, t.rows, t.notes);
      return;
    }
    if (g.forceEvents) {  // a driven rod: each force's start, peak and end, boosted
      const events = g.forceEvents.slice().sort((a, b) => a.T - b.T);
      const xText = coordinateFormat(events.map((e) => e.X * L)), tText = coordinateFormat(events.map((e) => e.T * L));
      const force = coordinateFormat(events.map((e) => e.force).concat(m.forces.bands.flatMap((b) => b.F)));
      const velocity = velocityFormat(events.map((e) => Math.tanh(e.rapidity - g.eta)));
      const rows = events.map((e) => [e.moment, e.end, xText(e.X * L), tText(e.T * L), force(e.force),
                                      velocity(Math.tanh(e.rapidity - g.eta))]);
      const names = coordinateNames(state.u);
      fillTable(panel.events, `Each force\u2019s start, peak and end in the frame ${frameSymbol(state.u)} (v = ${shown(v(), 10)}${rod}): ` +
                "decimals boosted from the exact events (choose S or S\u2032 for the table as the events are printed)",
                ["force", "end", names[0], names[1], "F", "end velocity"], rows, m.tables.rest.notes);
      return;
    }
    const scale = 1 + Math.max(...g.impacts.map((i) => Math.abs(i.T)));
    const order = g.impacts.map((i, k) => k).sort((a, b) => g.impacts[a].T - g.impacts[b].T);
    const instant = {}; let n = -1, first = null;
    for (const k of order) {
      if (first === null || g.impacts[k].T - first > scenario().one_instant * scale) { n += 1; first = g.impacts[k].T; }
      instant[k] = n;
    }
    order.sort((a, b) => instant[a] - instant[b] || a - b);
    const speeds = (i) => [i.particle_before, i.particle_after, i.rod_before, i.rod_after].map((r) => Math.tanh(r - g.eta));
    const xText = coordinateFormat(g.impacts.map((i) => i.X * L)), tText = coordinateFormat(g.impacts.map((i) => i.T * L));
    const velocity = velocityFormat(g.impacts.flatMap(speeds));
    const rows = order.map((k) => {
      const i = g.impacts[k];
      return [i.row || i.name, i.end, xText(i.X * L), tText(i.T * L), ...speeds(i).map(velocity)];
    });
    const names = coordinateNames(state.u);
    fillTable(panel.events, `The impacts in the frame ${frameSymbol(state.u)} (v = ${shown(v(), 10)}${rod}): decimals boosted ` +
              "from the exact events (choose S or S\u2032 for the table with exact fractions)",
              ["impact", "end", names[0], names[1], "particle before", "particle after", "rod before", "rod after"], rows, []);
  }

  function drawLedger(panel, g, view) {
    const m = g.model;
    let best = m.ledger[0];
    // slice k's time: the window's slices are spread evenly over it
    const timeOf = (f, k) => f.window[0] + (f.window[1] - f.window[0]) * k / (f.slices.length - 1);
    for (const f of m.ledger) if (Math.abs(Math.atanh(f.u) - g.eta) < Math.abs(Math.atanh(best.u) - g.eta)) best = f;
    // in its own frame the slice nearest the now-line; in another, the same fraction of that frame's window
    let k = Math.round(state.time * (best.slices.length - 1));
    if (Math.abs(Math.atanh(best.u) - g.eta) < 1e-12) {
      const now = nowTime(view);
      best.slices.forEach((row, n) => { if (Math.abs(timeOf(best, n) - now) < Math.abs(timeOf(best, k) - now)) k = n; });
    }
    const slice = best.slices[k];
    const rows = best.rows.map((name, b) => [name, ledgerCell(slice[2 * b]), ledgerCell(slice[2 * b + 1])]);
    const frameU = best.u === 0 ? "S" : best.u === -v() ? "S\u2032" : "u = " + shown(best.u, 4);
    const clock = best.u === 0 ? "t" : best.u === -v() ? "t\u2032" : "t\u1d64";
    const exact = Math.abs(Math.atanh(best.u) - g.eta) < 1e-12;
    const causal = m.model === "causal";
    const others = m.ledger.slice(2).map((f) => shown(f.u, 4)).join(", ");
    fillTable(panel.ledger, `Energy and momentum of the ${m.model} rod on the slice ${clock} = ${shown(timeOf(best, k), 4)} L of ${frameU}` +
              (exact ? " (of the tabulated slices, the nearest the now-line)" :
               ` (the ledger is tabulated in S\u2032, S and u = ${others}: ` +
               "this is the nearest frame, at the same fraction of its time window)"),
              ["body", "E (M c\u00b2)", "p (M c)"], rows,
              m.ledger_note ? [m.ledger_note + ` Computed before the page was made, on ${best.slices.length} slices of each ` +
                               "tabulated frame (to 10\u207b\u2074 M c\u00b2)."]
              : causal ? ["The rod\u2019s (E, p) is split into its matter part (its rest-frame energy density moving with it, " +
                        "elastic energy included) and its stress part (its pressure\u2019s p (u u \u2212 \u03b7) across the " +
                        "slice), each a density along the slice: nothing is hidden. Computed before the page was made, on " +
                        "41 slices of each tabulated frame (to 10\u207b\u2074 M c\u00b2)."] : []);
  }

  // --- the legend: the same elements and inks as the SVG figures --------------------------------------------
  function swatch(ink, extra) {
    const w = ink.width * pt, dash = ink.dashes.map((d) => d * w).join(" ");
    return `<svg width="44" height="14" aria-hidden="true">${extra || ""}<line x1="2" y1="7" x2="42" y2="7" ` +
      `stroke="${ink.colour}" stroke-width="${w}" stroke-dasharray="${dash || "none"}"/></svg>`;
  }
  let legendShown = null;
  function drawLegend(gs) {
    const st = inks(), items = [], causal = gs.find((g) => g.model.model === "causal");
    items.push([swatch(st.rod, `<rect x="2" y="1" width="40" height="12" fill="${st.sheet}"/>`), "rod: its ends (solid), world-sheet shaded"]);
    if (causal) {
      const [lo, hi] = causal.model.cells.ln_lam, ramp = [];
      for (let k = 0; k < 7; k++) {
        const f = k / 6, lnLam = f < 0.5 ? lo * (1 - 2 * f) : hi * (2 * f - 1);
        const g = lnLam < 0 ? 0.5 * (lnLam - Math.min(lo, -1e-3)) / -Math.min(lo, -1e-3) : 0.5 + 0.5 * lnLam / Math.max(hi, 1e-3);
        ramp.push(`<rect x="${2 + 40 * k / 7}" y="1" width="${40 / 7 + 0.3}" height="12" fill="${shadeColour(st.compression, g)}"/>`);
      }
      const lam = (x) => x.toFixed(Math.max(0, 1 - Math.floor(Math.log10(x))));
      items.push([`<svg width="44" height="14" aria-hidden="true">${ramp.join("")}</svg>`,
                  `causal rod\u2019s compression \u03bb: ${lam(Math.exp(lo))} to ${lam(Math.exp(hi))}, 1 unstressed`]);
      items.push([swatch(st.rod_interior), "causal rod\u2019s material lines (L/4, L/2, 3L/4)"]);
      items.push([swatch(st.front), "light front (a jump in \u03bb)"]);
    }
    const driven = gs.find((g) => g.model.forces);
    if (driven) {
      const fi = DATA.force_inks[state.style], scale = driven.model.forces.scale, w = fontSize();
      const pulls = gs.some((g) => g.bands.some((b) => b.F.some((F) => F < 0)));
      items.push([`<svg width="44" height="14" aria-hidden="true"><rect x="${38 - w}" y="1" width="${w}" height="12" fill="${fi.force_fill}" ` +
                  `stroke="${fi.force.colour}" stroke-width="${fi.force.width * pt}"/><line x1="38" y1="0" x2="38" y2="14" stroke="${st.rod.colour}" ` +
                  `stroke-width="${st.rod.width * pt}"/></svg>`,
                  `force on an end: this wide at ${shown(scale, 4)} M c\u00b2/L` + (pulls ? "; hatched: a pull" : "")]);
      items.push([`<svg width="44" height="14" aria-hidden="true"><circle cx="22" cy="7" r="${st.impact_size * pt / 2}" fill="${st.impact_colour}" stroke="white"/></svg>`,
                  "a force starts (on) or ends (off)"]);
    }
    for (const p of ["A", "B"]) if (gs[0].model.worldlines[p]) items.push([swatch(st.particles[p]), "particle " + p]);
    if (!driven) items.push([`<svg width="44" height="14" aria-hidden="true"><circle cx="22" cy="7" r="${st.impact_size * pt / 2}" fill="${st.impact_colour}" stroke="white"/></svg>`,
                causal ? "impact; for the causal rod a contact (B\u2081)" : "impact"]);
    if (causal && !driven) {
      items.push([`<svg width="44" height="14" aria-hidden="true"><circle cx="22" cy="7" r="${st.impact_size * pt / 2}" fill="white" stroke="${st.impact_colour}" stroke-width="1.3"/></svg>`,
                  "separation (B\u2032\u2081)"]);
      items.push([`<svg width="44" height="14" aria-hidden="true"><line x1="2" y1="7" x2="42" y2="7" stroke="#777777" stroke-opacity="0.35" stroke-width="${st.rod.width * 3.2 * pt}"/></svg>`,
                  "contact: particle rides with end"]);
    }
    items.push([swatch(st.rest), "line of simultaneity of S"]);
    items.push([swatch(st.moving), "line of simultaneity of S\u2032"]);
    if (state.cones) items.push([swatch(st.light_cone), "light cone of an impact"]);
    items.push([swatch({colour: st.flash, width: 2 * st.rod.width / 1.7, dashes: []}), "now: the frame\u2019s instant under the scrubber"]);
    const html = items.map(([svg, text]) => `<li>${svg}<span>${text}</span></li>`).join("");
    if (legendShown !== html) { legendShown = html; $("legend").innerHTML = html; }
  }
