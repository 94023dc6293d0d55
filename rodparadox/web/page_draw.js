// The page's script, part 2 of 5 (page.py joins the parts, in SCRIPTS' order, into one <script>): drawing the
// diagram, its labels and axes, and the strip.
  // --- drawing ---------------------------------------------------------------------------------------------
  const inks = () => DATA.styles[state.style];
  const pt = 4 / 3;  // CSS pixels per point
  function fontSize() { return parseFloat(getComputedStyle(document.body).fontSize); }
  function fontFamily() { return getComputedStyle(document.body).fontFamily; }
  function setInk(ctx, ink, scale) {
    const w = ink.width * pt * scale;
    ctx.strokeStyle = ink.colour; ctx.lineWidth = w;
    ctx.setLineDash(ink.dashes.map((d) => d * w));
    ctx.lineCap = ink.dashes.length ? "butt" : "round";
  }
  function niceStep(span, pixels, room) {  // the least nice step (embedded multiples x 10^n) `room` pixels apart
    const raw = span * room / pixels, power = Math.pow(10, Math.floor(Math.log10(raw)));
    for (const m of DATA.tick_multiples) if (m * power >= raw) return m * power;
    return 10 * power;
  }

  function canvasSized(canvas, width, height) {
    const ratio = window.devicePixelRatio || 1;
    if (canvas.style.width !== width + "px") canvas.style.width = width + "px";  // a style written is a layout
    if (canvas.style.height !== height + "px") canvas.style.height = height + "px";
    if (canvas.width !== Math.round(width * ratio) || canvas.height !== Math.round(height * ratio)) {
      canvas.width = Math.round(width * ratio); canvas.height = Math.round(height * ratio);
    }
    const ctx = canvas.getContext("2d");
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    ctx.clearRect(0, 0, width, height);
    return ctx;
  }

  // The panel's place on the page: equal scales (light at 45 degrees), as wide as the column allows and no
  // taller than most of the window.
  function layout(panel, box) {
    const size = fontSize();
    const margin = {left: 4.2 * size, right: 1.2 * size, top: 2.4 * size, bottom: 2.8 * size};
    const holder = {clientWidth: panel.width};  // measured before any drawing (`drawPanels`)
    const avail = Math.max(holder.clientWidth - margin.left - margin.right, 120);
    const share = state.style === "slides" ? 0.8 : 0.62;  // on a projector the diagram is the point
    // a phone keeps the sliders at the window's foot (page.css): the diagram fits in what they leave
    const tallest = Math.max((window.innerHeight - (widths ? widths.footer : 0)) * share - margin.top - margin.bottom, 120);
    const [x0, x1, t0, t1] = box;
    const scale = Math.min(avail / (x1 - x0), tallest / (t1 - t0));
    const extra = (avail - scale * (x1 - x0)) / 2;
    return {margin, scale, width: holder.clientWidth, height: margin.top + margin.bottom + scale * (t1 - t0),
            column: (x) => margin.left + extra + (x - x0) * scale, row: (t) => margin.top + (t1 - t) * scale};
  }

  function polyline(ctx, place, X, T) {
    ctx.beginPath();
    for (let k = 0; k < X.length; k++) {
      const px = place.column(X[k]), py = place.row(T[k]);
      if (k === 0) ctx.moveTo(px, py); else ctx.lineTo(px, py);
    }
    ctx.stroke();
  }

  // The infinite line through (x, t) along (dx, dt), clipped to the panel's box.
  function infinite(ctx, place, box, x, t, dx, dt) {
    let lo = -Infinity, hi = Infinity;
    for (const [p, a, b] of [[dx, box[0] - x, box[1] - x], [dt, box[2] - t, box[3] - t]]) {
      if (p === 0) { if (a > 0 || b < 0) return; continue; }
      const s0 = Math.min(a / p, b / p), s1 = Math.max(a / p, b / p);
      lo = Math.max(lo, s0); hi = Math.min(hi, s1);
    }
    if (!(lo < hi)) return;
    polyline(ctx, place, [x + lo * dx, x + hi * dx], [t + lo * dt, t + hi * dt]);
  }

  // The causal rod's shading: its cells, clipped to its world-sheet, one path per shade (kept while only the
  // time moves: the panel's place and the frame are the same).
  function drawCells(ctx, place, g, st, sheet) {
    const sign = [g.key, state.style, place.scale, place.column(0), place.row(0)].join("/");
    if (!g.paths || g.paths.sign !== sign) {
      // in pixels, a point (U, V) is at column(0) + scale (U - V)/2, row(0) - scale (U + V)/2: each edge's share once
      const {U, V, kept} = g.cells, h = place.scale / 2, c0 = place.column(0), r0 = place.row(0);
      const uc = U.map((x) => h * x), vc = V.map((x) => h * x);
      const top = place.row(place.box[3]), bottom = place.row(place.box[2]);
      const paths = Array.from({length: SHADES}, () => null);
      for (let k = 0; k < kept.length; k += 4) {
        const i = kept[k], j = kept[k + 1], J = kept[k + 2];
        // rows fall with U and V: the highest corner is (i + 1, J), the lowest (i, j)
        if (r0 - uc[i + 1] - vc[J] > bottom || r0 - uc[i] - vc[j] < top) continue;  // outside the time window
        const path = paths[kept[k + 3]] || (paths[kept[k + 3]] = new Path2D());
        path.moveTo(c0 + uc[i] - vc[j], r0 - uc[i] - vc[j]); path.lineTo(c0 + uc[i + 1] - vc[j], r0 - uc[i + 1] - vc[j]);
        path.lineTo(c0 + uc[i + 1] - vc[J], r0 - uc[i + 1] - vc[J]); path.lineTo(c0 + uc[i] - vc[J], r0 - uc[i] - vc[J]);
        path.closePath();
      }
      g.paths = {sign, paths: paths.map((path, shade) => path && [shadeColour(st.compression, (shade + 0.5) / SHADES), path])
                                   .filter((p) => p)};
    }
    ctx.save(); ctx.clip(sheet);
    for (const [colour, path] of g.paths.paths) { ctx.fillStyle = colour; ctx.fill(path); }
    ctx.restore();
  }

  // Where a contact's particle rides with its end: the particle's line between its contact and its separation.
  function contactStretches(g, p) {
    const mine = g.impacts.filter((i) => i.particle === p), w = g.worldlines[p], out = [];
    for (let k = 0; k + 1 < mine.length; k += 2) {
      const [a, b] = [mine[k].T, mine[k + 1].T], X = [mine[k].X], T = [a];
      for (let n = 0; n < w.T.length; n++) if (w.T[n] > a && w.T[n] < b) { X.push(w.X[n]); T.push(w.T[n]); }
      X.push(mine[k + 1].X); T.push(b);
      out.push([X, T]);
    }
    return out;
  }

  function drawDiagram(panel, g, view) {
    const st = inks(), place = layout(panel, view.box), size = fontSize();
    place.box = view.box;
    const canvas = panel.diagram, ctx = canvasSized(canvas, place.width, place.height);
    const [x0, x1, t0, t1] = view.box;
    const family = fontFamily(), causal = g.model.model === "causal";
    ctx.save();
    ctx.beginPath();
    ctx.rect(place.column(x0), place.row(t1), (x1 - x0) * place.scale, (t1 - t0) * place.scale);
    ctx.clip();
    // the rod's world-sheet, between its ends (the causal rod's shaded by compression)
    const left = clipped(g.worldlines.rod_left, t0, t1), right = clipped(g.worldlines.rod_right, t0, t1);
    const sheet = new Path2D();
    for (let k = 0; k < left[0].length; k++) sheet.lineTo(place.column(left[0][k]), place.row(left[1][k]));
    for (let k = right[0].length - 1; k >= 0; k--) sheet.lineTo(place.column(right[0][k]), place.row(right[1][k]));
    sheet.closePath();
    ctx.fillStyle = st.sheet; ctx.fill(sheet);
    if (causal) {
      drawCells(ctx, place, g, st, sheet);
      setInk(ctx, st.rod_interior, 1);
      for (const w of g.material) polyline(ctx, place, ...clipped(w, t0, t1));
      setInk(ctx, st.front, 1);
      for (const [xl, tl, xr, tr] of g.fronts) polyline(ctx, place, [xl, xr], [tl, tr]);
    }
    if (g.bands) drawBands(ctx, place, g, size);
    // lines of simultaneity of S and S' through every impact (impacts on one line share it); the causal rod's
    // through each particle's first contact (its later contacts and separations crowd one end); a driven rod's
    // through each force's start and end
    const through = g.forceEvents ? g.forceEvents.filter((e) => e.moment !== "peak")
      : causal ? g.impacts.filter((i) => i.kind === "contact" && /^[AB]1$/.test(i.label)) : g.impacts;
    for (const [which, frameU] of [["rest", 0], ["moving", -v()]]) {
      setInk(ctx, st[which], 1);
      const seen = [];
      for (const i of through) {
        const own = Math.cosh(Math.atanh(frameU)) * (i.t - frameU * i.x);
        if (seen.some((o) => Math.abs(o - own) <= 1e-9 * (1 + Math.abs(own)))) continue;
        seen.push(own);
        const [dx, dt] = boost(1, frameU, g.c, g.s);
        infinite(ctx, place, view.box, i.X, i.T, dx, dt);
      }
    }
    if (state.cones) {  // arms a sixth of the panel's shorter side each way
      setInk(ctx, st.light_cone, 1);
      const arm = Math.min(x1 - x0, t1 - t0) / 6;
      for (const i of marks(g)) for (const d of [[1, 1], [-1, 1]]) {
        polyline(ctx, place, [i.X - d[0] * arm, i.X + d[0] * arm], [i.T - d[1] * arm, i.T + d[1] * arm]);
      }
    }
    if (causal) for (const p of ["A", "B"]) if (g.worldlines[p]) {  // contacts: a broad band under the line
      ctx.strokeStyle = st.particles[p].colour; ctx.globalAlpha = 0.35; ctx.setLineDash([]);
      ctx.lineWidth = st.rod.width * 3.2 * pt; ctx.lineCap = "butt";
      for (const [X, T] of contactStretches(g, p)) polyline(ctx, place, X, T);
      ctx.globalAlpha = 1;
    }
    setInk(ctx, st.rod, 1);
    polyline(ctx, place, ...left); polyline(ctx, place, ...right);
    for (const p of ["A", "B"]) if (g.worldlines[p]) {
      setInk(ctx, st.particles[p], 1); polyline(ctx, place, ...clipped(g.worldlines[p], t0, t1));
    }
    ctx.setLineDash([]);
    // the now-line: the frame's instant under the scrubber
    const now = nowTime(view), nowRow = place.row(now);
    ctx.strokeStyle = st.flash; ctx.lineWidth = 2 * st.rod.width * pt / 1.7;
    ctx.beginPath(); ctx.moveTo(place.column(x0), nowRow); ctx.lineTo(place.column(x1), nowRow); ctx.stroke();
    // impacts: a dot with a white rim, its label beside it on the side of its end
    const dots = [];
    const radius = st.impact_size * pt / 2;
    ctx.font = `italic ${size}px ${family}`;
    for (const i of marks(g)) {  // a separation of the causal rod: hollow
      const px = place.column(i.X), py = place.row(i.T), hollow = i.kind === "separation";
      ctx.fillStyle = hollow ? "white" : st.impact_colour; ctx.strokeStyle = hollow ? st.impact_colour : "white";
      ctx.lineWidth = hollow ? 1.3 : 0.8;
      ctx.beginPath(); ctx.arc(px, py, radius, 0, 2 * Math.PI); ctx.fill(); ctx.stroke();
      dots.push({label: i.label, x: px, y: py});
    }
    const labelSign = [g.key, state.style, size, place.scale, place.column(0), place.row(0)].join("/");
    if (!g.labels || g.labels.sign !== labelSign) g.labels = {sign: labelSign, placed: placeLabels(ctx, g, place, radius, size)};
    const labels = g.labels.placed;  // the same while only the time moves
    ctx.strokeStyle = "black"; ctx.lineWidth = 0.6 * pt * size / 12; ctx.setLineDash([]);
    for (const b of labels) if (b.leader) {
      ctx.beginPath(); ctx.moveTo(...b.leader[0]); ctx.lineTo(...b.leader[1]); ctx.stroke();
    }
    for (const b of labels) label(ctx, b.name, b.x, b.baseline, "left", size, b.plain);
    for (const p of ["A", "B"]) if (g.worldlines[p]) {  // the letter beside the first part of its line
      const [X, T] = clipped(g.worldlines[p], t0, t1);
      const k = Math.min(1, X.length - 1);
      const t = T[0] + 0.12 * (t1 - t0), x = at(g.worldlines[p], t)[0];
      ctx.fillStyle = st.particles[p].colour;
      ctx.font = `italic ${1.1 * size}px ${family}`;
      ctx.textAlign = x < (X[k] + X[0]) / 2 ? "left" : "right";
      ctx.fillText(p, place.column(x) + (ctx.textAlign === "left" ? 0.5 : -0.5) * size, place.row(t));
    }
    ctx.restore();
    axes(ctx, place, g, view.box, size, family);
    panel.placed = place;
    canvas.dataset.impacts = JSON.stringify(dots);
    canvas.dataset.labels = JSON.stringify(labels.map((b) => ({label: b.label, x: b.x, y: b.y, w: b.w, h: b.h,
                                                                leader: b.leader !== null})));
    canvas.dataset.nowRow = String(nowRow);
    canvas.dataset.window = JSON.stringify([view.lo, view.hi]);
    return place;
  }

  // Each impact's label beside its dot on the side of its end; where that would cover a label already placed or
  // another dot (a contact and its separation a few pixels apart, A₃ and A′₃), the nearest free place around the
  // dot, tied to it by a thin leader when it sits farther than half a label's height from the dot (as plot's
  // labels). Boxes in CSS pixels, of the ink (measured), the white halo's 1.5 px kept clear between them.
  function placeLabels(ctx, g, place, radius, size) {
    const items = marks(g), dots = items.map((i) => [place.column(i.X), place.row(i.T)]), placed = [], halo = 1.5;
    const [x0, x1, t0, t1] = place.box, inside = [place.column(x0), place.row(t1), place.column(x1), place.row(t0)];
    const clash = (a, b, pad) => a[0] < b[2] + pad && b[0] < a[2] + pad && a[1] < b[3] + pad && b[1] < a[3] + pad;
    items.forEach((i, k) => {
      const [px, py] = dots[k], [w, ascent, descent] = labelSize(ctx, i.name, size, i.plain), h = ascent + descent;
      const side = i.end === "right" ? 1 : -1, gap = radius + 0.3 * size, base = py - 0.35 * size;
      const candidates = [];
      for (const s of [side, -side]) for (const dx of [0, 0.8 * size, 2 * size]) for (const n of [0, 1, -1, 2, -2, 3, -3, 4, -4]) {
        const x = s > 0 ? px + gap + dx : px - gap - dx - w, y = base - ascent + n * 0.55 * h;
        candidates.push([x, y, s === side ? 0 : size]);
      }
      for (const n of [1, 2]) for (const s of [-1, 1]) {  // above and below the dot
        candidates.push([px - w / 2, s < 0 ? py - radius - n * 0.6 * h - h : py + radius + (n - 1) * 0.6 * h + 2, 0.6 * size]);
      }
      const scored = candidates.map(([x, y, away], order) => {
        const box = [x, y, x + w, y + h];
        const far = Math.hypot(Math.max(box[0] - px, 0, px - box[2]), Math.max(box[1] - py, 0, py - box[3]));
        let hits = placed.filter((b) => clash(box, [b.x, b.y, b.x + b.w, b.y + b.h], 2 * halo)).length;
        hits += dots.filter(([dx, dy], n) => n !== k && clash(box, [dx - radius, dy - radius, dx + radius, dy + radius], 0)).length;
        const out = box[0] < inside[0] || box[2] > inside[2] || box[1] < inside[1] || box[3] > inside[3];
        return {box, far, cost: 1000 * hits + 100 * out + far + away + 1e-3 * order};
      });
      const best = scored.reduce((a, b) => (b.cost < a.cost ? b : a));
      const [x, y] = best.box, reach = radius + 0.3 * size + 0.5 * h;
      let leader = null;
      if (best.far > reach) {  // from the dot's edge to the nearest point of the box
        const qx = Math.max(x, Math.min(px, x + w)), qy = Math.max(y, Math.min(py, y + h)), d = Math.hypot(qx - px, qy - py);
        leader = [[px + (qx - px) * radius / d, py + (qy - py) * radius / d], [qx, qy]];
      }
      placed.push({name: i.name, label: i.label, x, y, w, h, baseline: y + ascent, leader, plain: !!i.plain});
    });
    return placed;
  }
  function labelSize(ctx, name, size, plain) {  // width, ascent and descent of the ink of a label drawn by `label`
    ctx.font = `${plain ? "" : "italic "}${size}px ${fontFamily()}`;
    const a = ctx.measureText(name[0]);
    ctx.font = `${size}px ${fontFamily()}`;
    const b = ctx.measureText(name.slice(1));
    return [a.width + b.width, Math.max(a.actualBoundingBoxAscent, b.actualBoundingBoxAscent),
            Math.max(a.actualBoundingBoxDescent, b.actualBoundingBoxDescent, 0)];
  }

  function label(ctx, name, x, y, align, size, plain) {  // B₁: the letter in italics, the subscript digits upright
    const letter = name[0], digits = name.slice(1), italic = plain ? "" : "italic ";
    ctx.fillStyle = "black"; ctx.textAlign = "left"; ctx.textBaseline = "alphabetic";
    ctx.font = `${italic}${size}px ${fontFamily()}`;
    const w1 = ctx.measureText(letter).width;
    ctx.font = `${size}px ${fontFamily()}`;
    const w2 = ctx.measureText(digits).width;
    const start = align === "left" ? x : x - w1 - w2;
    ctx.lineWidth = 3; ctx.strokeStyle = "rgba(255,255,255,0.85)"; ctx.setLineDash([]);
    ctx.font = `${italic}${size}px ${fontFamily()}`; ctx.strokeText(letter, start, y); ctx.fillText(letter, start, y);
    ctx.font = `${size}px ${fontFamily()}`; ctx.strokeText(digits, start + w1, y); ctx.fillText(digits, start + w1, y);
  }

  function axes(ctx, place, g, box, size, family) {
    const [x0, x1, t0, t1] = box, names = coordinateNames(state.u);
    ctx.strokeStyle = "black"; ctx.lineWidth = 1; ctx.setLineDash([]);
    ctx.strokeRect(place.column(x0), place.row(t1), (x1 - x0) * place.scale, (t1 - t0) * place.scale);
    ctx.fillStyle = "black"; ctx.font = `${0.9 * size}px ${family}`;
    const xs = niceStep(x1 - x0, (x1 - x0) * place.scale, 3.6 * size), ts = niceStep(t1 - t0, (t1 - t0) * place.scale, 2.2 * size);
    ctx.textAlign = "center"; ctx.textBaseline = "top";
    for (let x = Math.ceil(x0 / xs) * xs; x <= x1 + 1e-9; x += xs) {
      const px = place.column(x), py = place.row(t0);
      ctx.beginPath(); ctx.moveTo(px, py); ctx.lineTo(px, py + 4); ctx.stroke();
      ctx.fillText(shown(x, 6), px, py + 6);
    }
    ctx.textAlign = "right"; ctx.textBaseline = "middle";
    for (let t = Math.ceil(t0 / ts) * ts; t <= t1 + 1e-9; t += ts) {
      const px = place.column(x0), py = place.row(t);
      ctx.beginPath(); ctx.moveTo(px, py); ctx.lineTo(px - 4, py); ctx.stroke();
      ctx.fillText(shown(t, 6), px - 6, py);
    }
    ctx.textAlign = "center"; ctx.textBaseline = "alphabetic"; ctx.font = `italic ${size}px ${family}`;
    ctx.fillText(names[0] + "/L", place.column((x0 + x1) / 2), place.row(t0) + 2.5 * size);
    ctx.save(); ctx.translate(place.column(x0) - 3.4 * size, place.row((t0 + t1) / 2)); ctx.rotate(-Math.PI / 2);
    ctx.fillText(names[1] + "/L", 0, 0); ctx.restore();
    ctx.textAlign = "left";
    fitted(ctx, panelTitle(g), place.column(x0), place.row(t1) - 0.7 * size, place.width, size, family);
  }

  // Text from x on, in a smaller type where the panel is too narrow for it (side by side, a phone): never cut.
  function fitted(ctx, text, x, y, width, size, family) {
    const room = width - x - 0.3 * size;
    ctx.font = `${size}px ${family}`;
    const wide = ctx.measureText(text).width;
    if (wide > room) ctx.font = `${Math.max(0.55, room / wide) * size}px ${family}`;
    ctx.fillText(text, x, y);
  }

  function panelTitle(g) {
    const before = -state.u, last = g.impacts[g.impacts.length - 1];
    const after = g.model.final !== undefined ? Math.tanh(g.model.final - g.eta)
      : last ? Math.tanh(last.rod_after - g.eta) : before;
    const phrase = (u) => Math.abs(u) < 5e-13 ? "at rest" : "at " + (u > 0 ? "+" : "") + speed(u, 4);
    const ringing = g.model.model === "causal" ? " on average" : "";  // it rings for ever
    const said = Math.abs(before - after) < 5e-13 ? `rod ${phrase(before)} before and after${ringing}`
      : `rod first ${phrase(before)}, finally ${phrase(after)}${ringing}`;
    return `frame ${frameSymbol(state.u)}: ${said}`;
  }

  function nowTime(view) { return view.lo + state.time * (view.hi - view.lo); }

  // Where the now-line opens (a fraction of the window): the middle, unless an impact lies within OPEN_CLEAR of
  // it (fig1's impacts are at the middle of S's window: the now-line hid their line of simultaneity); then the
  // middle of the widest stretch between impacts, the nearest the middle of those at least twice that wide.
  const OPEN_CLEAR = 0.04;
  function openingTime() {
    const view = shared(), span = view.hi - view.lo;
    const times = view.gs.flatMap((g) => marks(g).map((i) => (i.T - view.lo) / span)).filter((f) => f > 0 && f < 1);
    if (times.every((f) => Math.abs(f - 0.5) > OPEN_CLEAR)) return 0.5;
    const cuts = [0, ...times.sort((a, b) => a - b), 1];
    let best = null;
    for (let k = 0; k + 1 < cuts.length; k++) {
      const mid = 0.5 * (cuts[k] + cuts[k + 1]), wide = cuts[k + 1] - cuts[k] >= 4 * OPEN_CLEAR;
      if (wide && (best === null || Math.abs(mid - 0.5) < Math.abs(best - 0.5))) best = mid;
    }
    return best === null ? 0.5 : Math.round(best * 1000) / 1000;
  }

  // The strip: the frame's space at the now-line's instant, on the panel's x scale: the rod coloured by the
  // velocity of its material points (the colour scale even in rapidity, centred on the rod's first velocity, the
  // same in every frame), the particles, the impacts flashing.
  function colourAt(f) {
    const stops = inks().colours, k = Math.max(0, Math.min(1, f)) * (stops.length - 1);
    const a = Math.floor(Math.min(k, stops.length - 2)), w = k - a;
    const rgb = (h) => [1, 3, 5].map((i) => parseInt(h.slice(i, i + 2), 16));
    const p = rgb(stops[a]), q = rgb(stops[a + 1]);
    return `rgb(${p.map((c, i) => Math.round(c + w * (q[i] - c))).join(",")})`;
  }

  // The causal rod at time t of the frame, piece by piece: where the slice crosses the cells' edges (u-edge i at
  // x = e^-eta a_i - t, w-edge j at x = t - e^eta b_j) it enters another cell, whose material rapidity in S is
  // (r+_i - r-_j)/2. Returns [x from, x to, rapidity in S] between the rod's ends.
  function causalPieces(g, t) {
    const xl = at(g.worldlines.rod_left, t)[0], xr = at(g.worldlines.rod_right, t)[0], cells = g.model.cells;
    const cuts = [xl, xr];
    for (const U of g.cells.U) if (U - t > xl && U - t < xr) cuts.push(U - t);
    for (const V of g.cells.V) if (t - V > xl && t - V < xr) cuts.push(t - V);
    cuts.sort((a, b) => a - b);
    const find = (edges, value) => {  // the last edge at or below value (edges increase)
      let a = 0, b = edges.length - 1;
      if (value < edges[0]) return 0;
      while (b - a > 1) { const mid = (a + b) >> 1; if (edges[mid] <= value) a = mid; else b = mid; }
      return Math.min(a, edges.length - 2);
    };
    const pieces = [];
    for (let k = 0; k + 1 < cuts.length; k++) {
      const xm = 0.5 * (cuts[k] + cuts[k + 1]);
      const i = find(g.cells.U, t + xm), j = find(g.cells.V, t - xm);
      pieces.push([cuts[k], cuts[k + 1], 0.5 * (cells.r_plus[i] - cells.r_minus[j])]);
    }
    return pieces;
  }

  function drawStrip(panel, place, g, view) {
    const st = inks(), size = fontSize(), family = fontFamily(), m = g.model;
    const height = 8.2 * size, canvas = panel.strip, ctx = canvasSized(canvas, place.width, height);
    const t = nowTime(view), bar = 2.4 * size, barH = 0.9 * size, bound = m.colour_bound || 0.1;
    const [x0, x1, t0, t1] = view.box;
    const flash = 0.02 * (t1 - t0);
    const lit = g.impacts.filter((i) => Math.abs(i.T - t) <= flash);
    const clock = coordinateNames(state.u)[1];
    ctx.fillStyle = "black"; ctx.font = `${size}px ${family}`; ctx.textAlign = "left"; ctx.textBaseline = "alphabetic";
    const where = frameName(state.u) === "u" ? "the frame " + frameSymbol(state.u) : frameSymbol(state.u);
    fitted(ctx, `${clock} = ${shown(t, 4)} L in ${where}` + (lit.length ? "   " + lit.map((i) => i.name).join(", ") + "!" : ""),
           place.column(x0), 1.1 * size, place.width, size, family);
    let ends;
    if (m.model === "causal") {
      const pieces = causalPieces(g, t);
      for (const [a, b, phiS] of pieces) {  // phiS: the departure from the first velocity (at rest in S)
        ctx.fillStyle = colourAt(0.5 + 0.5 * phiS / bound);
        ctx.fillRect(place.column(a), bar, place.column(b) - place.column(a) + 0.5, barH);
      }
      ends = [place.column(pieces[0][0]), place.column(pieces[pieces.length - 1][1])];
    } else {
      const points = g.material.map((w) => at(w, t));
      for (let k = 0; k + 1 < points.length; k++) {
        const phiS = 0.5 * (points[k][1] + points[k + 1][1]) + g.eta;  // the departure from the first velocity
        ctx.fillStyle = colourAt(0.5 + 0.5 * phiS / bound);
        const a = place.column(points[k][0]), b = place.column(points[k + 1][0]);
        ctx.fillRect(a, bar, b - a + 0.5, barH);
      }
      ends = [place.column(points[0][0]), place.column(points[points.length - 1][0])];
    }
    setInk(ctx, st.rod, 0.6); ctx.strokeRect(ends[0], bar, ends[1] - ends[0], barH);
    ctx.setLineDash([]);
    for (const p of ["A", "B"]) if (g.worldlines[p]) {
      const x = place.column(at(g.worldlines[p], t)[0]);
      ctx.fillStyle = st.particles[p].colour;
      ctx.beginPath(); ctx.arc(x, bar + barH / 2, 0.28 * size, 0, 2 * Math.PI); ctx.fill();
      ctx.font = `italic ${size}px ${family}`; ctx.textAlign = "center";
      ctx.fillText(p, x, bar - 0.25 * size);
    }
    for (const i of lit) star(ctx, place.column(i.X), bar + barH / 2, 0.6 * size, st.flash);
    if (g.bands) drawStripForces(ctx, g, t, ends, bar + barH / 2, size);
    // the colour bar: its two ends and its centre, in velocity
    const cx0 = place.column(x0), cw = Math.min((x1 - x0) * place.scale, 22 * size), cy = bar + barH + 1.3 * size;
    for (let k = 0; k < cw; k += 2) { ctx.fillStyle = colourAt(k / cw); ctx.fillRect(cx0 + k, cy, 2.5, 0.6 * size); }
    ctx.strokeStyle = "#444"; ctx.lineWidth = 0.8; ctx.strokeRect(cx0, cy, cw, 0.6 * size);
    ctx.fillStyle = "black"; ctx.font = `${0.85 * size}px ${family}`; ctx.textBaseline = "top";
    const centre = -g.eta;
    [[0, "left", centre - bound], [0.5, "center", centre], [1, "right", centre + bound]].forEach(([f, align, r]) => {
      const u = Math.tanh(r);  // a rounding's 1e-16 is 0
      ctx.textAlign = align; ctx.fillText(speed(Math.abs(u) < 1e-12 ? 0 : u, 3), cx0 + f * cw, cy + 0.75 * size);
    });
    ctx.textAlign = "left";
    fitted(ctx, "velocity of the rod\u2019s material points (c = 1)", cx0, cy + 1.9 * size, place.width, 0.85 * size, family);
  }

  function star(ctx, x, y, r, colour) {
    ctx.fillStyle = colour; ctx.beginPath();
    for (let k = 0; k < 10; k++) {
      const a = -Math.PI / 2 + k * Math.PI / 5, rr = k % 2 ? 0.45 * r : r;
      ctx.lineTo(x + rr * Math.cos(a), y + rr * Math.sin(a));
    }
    ctx.closePath(); ctx.fill();
  }
