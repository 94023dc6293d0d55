// The page's script, part 1 of 5 (page.py joins page.js, page_draw.js, page_forces.js, page_tables.js and
// page_controls.js, in that order, into one <script>: one scope, no build step): the data, the state, numbers, frames and boosts.
// Plain JavaScript, no network. Every number comes from the data Python embedded: the page only
// Lorentz-transforms embedded points (exact for each point) and interpolates along the sampled lines to draw.
// Two rod models per speed: the rigid rod and the causal rod (README, "The causal rod"), shown alone or side by
// side. The causal rod's cells of compression are bounded by light lines: a boost scales t + x by e^-eta and
// t - x by e^eta, so the page scales their embedded edges (exact), and reads lam = exp(-(r+ + r-)/2) from the
// invariants embedded at each cell's middle; after its last separation the rod rings with a period, each
// period's points the last one's moved by the same (dx, dt), which the page adds (exact for points).
"use strict";
(function () {
  const DATA = JSON.parse(document.getElementById("page-data").textContent);
  const MINUS = "\u2212", PRIME = "\u2032";
  const $ = (id) => document.getElementById(id);
  const controls = {
    scenario: $("scenario"), speed: $("speed"), frame: $("frame"), time: $("time"),
    play: $("play"), rest: $("frame-rest"), moving: $("frame-moving"), cones: $("cones"), style: $("style"),
  };
  const state = {scenario: 0, speed: 0, rod: "rigid", u: 0, time: 0, cones: false, style: DATA.style, playing: false};
  const RODS = ["rigid", "causal", "both"];
  const rodControls = RODS.map((r) => $("rod-" + r));
  // the two panels: the first shows the rigid rod (or the causal rod alone), the second the causal rod beside it
  const PANELS = [1, 2].map((n) => {
    const suffix = n === 1 ? "" : "-" + n;
    return {box: $("panel-" + n), heading: $("panel-" + n + "-heading"), diagram: $("diagram" + suffix),
            strip: $("strip" + suffix), events: $("events" + suffix), ledger: $("ledger" + suffix),
            tables: $("tables-" + n), placed: null};
  });
  // what each drawing took (ms, performance.now()); drawnAt: the first drawing's end, from the page's start
  const timings = {first: null, drawnAt: null, redraws: []};
  const cache = new Map();  // the geometry of each scenario, speed, model and frame drawn lately

  // --- numbers as the tool writes them ------------------------------------------------------------------
  // The tables' rules, Python's (`numbers.coordinate_format`, `velocity_format`; the ledger's fixed decimals), with
  // their parameters embedded (`DATA.formats`): the digits of a double rounded as Python rounds them (ties to
  // even on its exact value), a real minus sign, no sign on a zero.
  const FORMATS = DATA.formats;
  function rounded(a, n) {  // a > 0 to n >= 0 significant digits: [digits (n of them), exponent of the first]
    const [m, e] = a.toExponential(100).split("e"), d = m.replace(".", "");
    let exp = Number(e), head = d.slice(0, n);
    const rest = d.slice(n), last = n ? Number(head[n - 1]) : 0;
    if (rest[0] > "5" || (rest[0] === "5" && (/[1-9]/.test(rest.slice(1)) || last % 2 === 1))) {
      head = n ? (BigInt(head) + 1n).toString() : "1";
      if (head.length > n) { exp += 1; head = head.slice(0, Math.max(n, 1)); if (!n) return ["", exp]; }
    } else if (!n) return ["", -Infinity];
    return [head, exp];
  }
  function pyG(x, p) {  // Python's format(x, "+#.{p}g")
    const sign = x < 0 || Object.is(x, -0) ? "-" : "+", a = Math.abs(x);
    if (a === 0) return sign + "0." + "0".repeat(p - 1);
    const [d, exp] = rounded(a, p);
    if (exp < -4 || exp >= p) return `${sign}${d[0]}.${d.slice(1)}e${exp < 0 ? "-" : "+"}${String(Math.abs(exp)).padStart(2, "0")}`;
    return sign + (exp >= 0 ? d.slice(0, exp + 1) + "." + d.slice(exp + 1) : "0." + "0".repeat(-exp - 1) + d);
  }
  function pyF(x, decimals) {  // Python's format(x, "+.{decimals}f")
    const sign = x < 0 || Object.is(x, -0) ? "-" : "+", a = Math.abs(x);
    const n = a === 0 ? -1 : Number(a.toExponential(100).split("e")[1]) + 1 + decimals;  // digits kept
    const [d, exp] = n < 0 ? ["", -Infinity] : rounded(a, n);
    let units;  // the value as an integer count of 10^-decimals
    if (exp === -Infinity) units = "0";
    else if (!d) units = "1";  // rounded up from below the last decimal
    else units = d + "0".repeat(Math.max(exp + 1 + decimals - d.length, 0));
    units = units.replace(/^0+(?=.)/, "").padStart(decimals + 1, "0");
    const text = decimals ? units.slice(0, -decimals) + "." + units.slice(-decimals) : units;
    return sign + text;
  }
  function withoutZeroSign(text) {  // -0.000 is +0.000: a value that rounds to zero has no sign
    return text[0] === "-" && !/[1-9]/.test(text.split("e")[0]) ? "+" + text.slice(1) : text;
  }
  const minus = (text) => text.replace(/-/g, MINUS);
  function coordinateFormat(values, signed = true) {  // numbers.coordinate_format: one column, one number of decimals
    const largest = values.reduce((m, x) => Math.max(m, Math.abs(x)), 0);
    const scientific = largest > 0 && !(FORMATS.scientific_below <= largest && largest < 10 ** FORMATS.digits);
    const decimals = largest === 0 || scientific ? 0 : Math.max(0, FORMATS.digits - 1 - Math.floor(Math.log10(largest)));
    return (x) => {
      const y = Math.abs(x) <= FORMATS.printed_zero * largest ? 0 : x + 0;
      const text = withoutZeroSign(scientific && y !== 0 ? pyG(y, FORMATS.digits) : pyF(y, decimals));
      return minus(signed ? text : text.replace(/^\+/, ""));
    };
  }
  function velocityFormat(values) {  // numbers.velocity_format: every velocity given with one number of decimals
    const largest = values.reduce((m, x) => Math.max(m, Math.abs(x)), 0);
    const nearC = (u) => (Math.abs(u) > 0.5 ? Math.ceil(-Math.log10(1 - Math.abs(u))) + 1 : 0);
    let decimals = FORMATS.digits - 1;
    if (largest > 0 && largest < 0.1) decimals = FORMATS.digits - 2 - Math.floor(Math.log10(largest));
    decimals = values.reduce((d, u) => Math.max(d, nearC(u)), decimals);
    return (u) => minus(withoutZeroSign(pyF(u + 0, Math.max(decimals, nearC(u)))));
  }
  // a ledger cell: FORMATS.ledger_decimals decimals (the embedded numbers have no more), no sign but a minus
  const ledgerCell = (x) => minus(withoutZeroSign(pyF(x + 0, FORMATS.ledger_decimals))).replace("+", "");
  function shown(x, digits) {  // up to `digits` significant digits, trailing zeros dropped, a real minus sign
    let s = Number(x.toPrecision(digits)).toString();
    if (s === "-0") s = "0";
    return s.replace("-", MINUS);
  }

  function speed(u, digits) {  // a velocity |u| < 1 never written as 1: as many more digits as keep it below
    let d = digits;
    while (d < 17 && Math.abs(Number(u.toPrecision(d))) >= 1 && Math.abs(u) < 1) d += 1;
    return shown(u, d);
  }

  // --- frames and boosts ----------------------------------------------------------------------------------
  const scenario = () => DATA.scenarios[state.scenario];
  const entry = () => scenario().speeds[state.speed];
  function shownModels() {  // the models the switch asks for that ran at this speed (the other if none did)
    const asked = (state.rod === "both" ? ["rigid", "causal"] : [state.rod]).filter((n) => modelNamed(n) !== null);
    return asked.length ? asked : [entry().models[0].model];
  }
  const modelNamed = (name) => entry().models.find((m) => m.model === name) || null;
  const v = () => entry().v;
  function frameName(u) { return u === 0 ? "rest" : (u === -v() ? "moving" : "u"); }
  function frameSymbol(u) { const n = frameName(u); return n === "rest" ? "S" : n === "moving" ? "S" + PRIME : "u = " + speed(u, 4); }
  function coordinateNames(u) {
    const n = frameName(u);
    return n === "rest" ? ["x", "t"] : n === "moving" ? ["x" + PRIME, "t" + PRIME] : ["x\u1d64", "t\u1d64"];
  }
  function boost(x, t, c, s) { return [c * x - s * t, c * t - s * x]; }
  // the labels of a force's start and end beside their markers (as the figures')
  const FORCE_WORDS = {start: "on", end: "off"};

  // A line in S with its periods unrolled: a causal line gives one period from `repeat_from` and how many
  // times it repeats, each copy moved by `period` (dx, dt).
  function unrolled(w) {
    if (!w.repeats) return w;
    if (w.unrolled) return w.unrolled;  // the same in every frame: once per line
    w.unrolled = unrolledOnce(w);
    return w.unrolled;
  }
  function unrolledOnce(w) {
    const x = w.x.slice(), t = w.t.slice(), n = w.x.length;
    for (let r = 1; r <= w.repeats; r++) {
      for (let k = w.repeat_from + 1; k < n; k++) { x.push(w.x[k] + r * w.period[0]); t.push(w.t[k] + r * w.period[1]); }
    }
    return {x, t, before: w.before, after: w.after};
  }

  // The time window of the frame (embedded: Python's frames.time_window for each position of the frame slider
  // and for S').
  function frameWindow(m, u) {
    if (frameName(u) === "moving") return m.windows.moving;
    const k = Math.round(u * 100) + scenario().frame_steps;
    return [m.windows.lo[k], m.windows.hi[k]];
  }

  // A model's geometry in the current frame: every embedded point boosted once, each line extended straight to
  // the window's ends.
  function geometry(name) {
    name = name || shownModels()[0];
    const key = [state.scenario, state.speed, name, state.u].join("/");
    if (cache.has(key)) return cache.get(key);
    if (cache.size > 12) cache.clear();
    const m = modelNamed(name), eta = Math.atanh(state.u), c = Math.cosh(eta), s = Math.sinh(eta);
    if (m === null) return null;
    const [lo, hi] = frameWindow(m, state.u);
    const line = (given) => {
      const X = [], T = [], P = [], w = unrolled(given);
      for (let k = 0; k < w.x.length; k++) {
        const [x, t] = boost(w.x[k], w.t[k], c, s);
        X.push(x); T.push(t); P.push(w.phi ? w.phi[k] - eta : 0);
      }
      return {X, T, P, before: w.before - eta, after: w.after - eta};
    };
    const worldlines = {};
    for (const name of Object.keys(m.worldlines)) worldlines[name] = line(m.worldlines[name]);
    const impacts = m.impacts.map((i) => {
      const [x, t] = boost(i.x, i.t, c, s);
      return Object.assign({}, i, {X: x, T: t});
    });
    let xmin = Infinity, xmax = -Infinity;
    const drawn = {};
    for (const name of Object.keys(worldlines)) {
      drawn[name] = clipped(worldlines[name], lo, hi);
      for (const x of drawn[name][0]) { xmin = Math.min(xmin, x); xmax = Math.max(xmax, x); }
    }
    // room for a driven end's band outside it (a type size wide at most: 0.6 L at the narrowest panels' scale)
    const pad = Math.max(0.08 * (xmax - xmin), m.forces ? 0.6 : 0.25);
    const g = {key, name, model: m, eta, c, s, lo, hi, worldlines, drawn, impacts, material: m.material.map(line),
               box: [xmin - pad, xmax + pad, lo, hi]};
    if (m.forces) {  // a rod driven by forces: its bands, arrows and force events, boosted
      g.bands = m.forces.bands.map((b) => {
        const X = [], T = [];
        b.x.forEach((x, k) => { const [bx, bt] = boost(x, b.t[k], c, s); X.push(bx); T.push(bt); });
        return {end: b.end, X, T, F: b.F};
      });
      g.arrows = m.forces.arrows.map(([end, x, t, F]) => [end, ...boost(x, t, c, s), F]);
      g.forceEvents = m.forces.events.map((e) => {
        const [x, t] = boost(e.x, e.t, c, s);
        return Object.assign({}, e, {X: x, T: t, label: e.end + "-" + e.moment, name: FORCE_WORDS[e.moment] || ""});
      });
    }
    if (m.model === "causal") {
      g.fronts = m.fronts.map(([xl, tl, xr, tr]) => [...boost(xl, tl, c, s), ...boost(xr, tr, c, s)]);
      g.cells = causalCells(m.cells, eta);
    }
    cache.set(key, g);
    return g;
  }

  // What the shown panels share: one time window and one box, so that side by side they read alike.
  function shared() {
    const gs = shownModels().map(geometry).filter((g) => g !== null);
    const box = [Math.min(...gs.map((g) => g.box[0])), Math.max(...gs.map((g) => g.box[1])),
                 Math.min(...gs.map((g) => g.lo)), Math.max(...gs.map((g) => g.hi))];
    return {gs, box, lo: box[2], hi: box[3]};
  }

  // The causal rod's cells of compression in the frame of rapidity eta: each edge u_i (w_j) at t + x = e^-eta a_i
  // (t - x = e^eta b_j); cell (i, j) lies in the rod where 0 < u - w < 2 (X between 0 and L); its shade from
  // ln lam = -(r+_i + r-_j)/2 on the figures' two-sided scale. Which cells and their shades are the same in every
  // frame: found once per model, neighbours along w of one shade joined into one parallelogram (i, j from, j to,
  // shade): its sides are light lines still; a frame only scales the edges.
  const SHADES = DATA.shades;  // as the figures' (`render.shading`)
  function keptCells(cells) {
    if (cells.kept) return cells.kept;
    const [low, high] = [Math.min(cells.ln_lam[0], -1e-3), Math.max(cells.ln_lam[1], 1e-3)], kept = [];
    for (let i = 0; i + 1 < cells.u.length; i++) {
      for (let j = 0; j + 1 < cells.w.length; j++) {
        if (!(cells.u[i + 1] - cells.w[j] > 0 && cells.u[i] - cells.w[j + 1] < 2)) continue;
        const lnLam = -0.5 * (cells.r_plus[i] + cells.r_minus[j]);
        const f = lnLam < 0 ? 0.5 * (lnLam - low) / -low : 0.5 + 0.5 * lnLam / high;
        const shade = Math.max(0, Math.min(SHADES - 1, Math.floor(f * SHADES))), n = kept.length;
        if (n && kept[n - 4] === i && kept[n - 2] === j && kept[n - 1] === shade) kept[n - 2] = j + 1;
        else kept.push(i, j, j + 1, shade);
      }
    }
    cells.kept = Int32Array.from(kept);
    return cells.kept;
  }
  function causalCells(cells, eta) {
    return {U: cells.a.map((a) => Math.exp(-eta) * a), V: cells.b.map((b) => Math.exp(eta) * b), kept: keptCells(cells)};
  }
  // A shade's colour: the compression scale (stretched, unstressed as the sheet, compressed), linear between.
  function shadeColour(stops, f) {
    const k = Math.max(0, Math.min(1, f)) * (stops.length - 1), a = Math.floor(Math.min(k, stops.length - 2)), w = k - a;
    const rgb = (h) => [1, 3, 5].map((i) => parseInt(h.slice(i, i + 2), 16));
    const p = rgb(stops[a]), q = rgb(stops[a + 1]);
    return `rgb(${p.map((v, i) => Math.round(v + w * (q[i] - v))).join(",")})`;
  }

  // A boosted line's points from t = lo to t = hi: straight before its first point and after its last (its
  // points are its changes, which the window holds).
  function clipped(w, lo, hi) {
    const X = [], T = [];
    const n = w.X.length;
    if (lo < w.T[0]) { X.push(w.X[0] + Math.tanh(w.before) * (lo - w.T[0])); T.push(lo); }
    for (let k = 0; k < n; k++) { X.push(w.X[k]); T.push(w.T[k]); }  // every point is within the window
    if (hi > w.T[n - 1]) { X.push(w.X[n - 1] + Math.tanh(w.after) * (hi - w.T[n - 1])); T.push(hi); }
    return [X, T];
  }

  // Where a boosted line is at time t of the frame, and its rapidity there (interpolated between points).
  function at(w, t) {
    const n = w.X.length;
    if (t <= w.T[0]) return [w.X[0] + Math.tanh(w.before) * (t - w.T[0]), w.before];
    if (t >= w.T[n - 1]) return [w.X[n - 1] + Math.tanh(w.after) * (t - w.T[n - 1]), w.after];
    let a = 0, b = n - 1;
    while (b - a > 1) { const mid = (a + b) >> 1; if (w.T[mid] <= t) a = mid; else b = mid; }
    const span = w.T[b] - w.T[a];
    const f = span > 0 ? (t - w.T[a]) / span : 1;
    return [w.X[a] + f * (w.X[b] - w.X[a]), w.P[a] + f * (w.P[b] - w.P[a])];
  }
