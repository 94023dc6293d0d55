// The page's script, part 3 of 5 (page.py joins the parts into one <script>): a rod driven by forces at its ends,
// drawn as the figures draw it (`render.force_layers`): each force as a band along its end, its start and end
// marked (on, off), an arrow on the strip.
  // What carries a dot and a label: the impacts, and a driven rod's force starts and ends ("on", "off": plain type).
  function marks(g) {
    if (!g.forceEvents) return g.impacts;
    return g.impacts.concat(g.forceEvents.filter((e) => e.moment !== "peak").map((e) => Object.assign(e, {plain: true})));
  }

  // Each force as a band along its end, outside it, horizontal in the frame: as wide as the type for the force
  // `scale`, filled, its outer edge in the force's ink, a pull's band hatched; arrows into the rod where it presses,
  // out of it where it pulls (as the figures').
  function drawBands(ctx, place, g, size) {
    const fi = DATA.force_inks[state.style], per = size / g.model.forces.scale;
    for (const b of g.bands) {
      const side = b.end === "left" ? -1 : 1;
      for (const sense of [1, -1]) {  // the pushes, then the pulls
        const part = b.F.map((F) => (sense * F > 0 ? Math.abs(F) : 0));
        if (!part.some((F) => F > 0)) continue;
        const inner = b.X.map((x, k) => [place.column(x), place.row(b.T[k])]);
        const outer = inner.map(([px, py], k) => [px + side * per * part[k], py]);
        const band = new Path2D();
        inner.forEach(([px, py]) => band.lineTo(px, py));
        for (let k = outer.length - 1; k >= 0; k--) band.lineTo(...outer[k]);
        band.closePath();
        ctx.fillStyle = fi.force_fill; ctx.fill(band);
        if (sense < 0) { ctx.save(); ctx.clip(band); hatch(ctx, place, fi.force.colour); ctx.restore(); }
        setInk(ctx, fi.force, 1);
        ctx.beginPath();
        outer.forEach(([px, py], k) => { if (part[k] > 0) ctx.lineTo(px, py); else ctx.moveTo(px, py); });
        ctx.stroke();
      }
    }
    ctx.setLineDash([]);
    for (const [end, x, t, F] of g.arrows) {
      const px = place.column(x), py = place.row(t), tip = px + (end === "left" ? -1 : 1) * per * Math.abs(F);
      arrow(ctx, F > 0 ? tip : px, F > 0 ? px : tip, py, 0.55 * size, fi.force);
    }
  }
  function hatch(ctx, place, colour) {
    ctx.strokeStyle = colour; ctx.lineWidth = 0.6; ctx.setLineDash([]);
    ctx.beginPath();
    for (let d = -place.height; d < place.width + place.height; d += 6) { ctx.moveTo(d, place.height); ctx.lineTo(d + place.height, 0); }
    ctx.stroke();
  }
  function arrow(ctx, from, to, y, head, ink) {  // horizontal, its head at `to`
    const dir = Math.sign(to - from) || 1;
    ctx.strokeStyle = ink.colour; ctx.fillStyle = ink.colour; ctx.lineWidth = ink.width * pt;
    ctx.beginPath(); ctx.moveTo(from, y); ctx.lineTo(to - dir * 0.8 * head, y); ctx.stroke();
    ctx.beginPath(); ctx.moveTo(to, y); ctx.lineTo(to - dir * head, y - 0.38 * head); ctx.lineTo(to - dir * head, y + 0.38 * head);
    ctx.closePath(); ctx.fill();
  }

  // A driven end on the strip: an arrow as long as the force at the now-line's instant (twice the diagram's band).
  function drawStripForces(ctx, g, t, ends, y, size) {
    const fi = DATA.force_inks[state.style], per = 2 * size / g.model.forces.scale;
    for (const b of g.bands) {
      const n = b.T.length;
      if (!(t >= b.T[0] && t <= b.T[n - 1])) continue;
      let k = 0;
      while (k + 2 < n && b.T[k + 1] <= t) k += 1;
      const f = b.T[k + 1] > b.T[k] ? (t - b.T[k]) / (b.T[k + 1] - b.T[k]) : 1, F = b.F[k] + f * (b.F[k + 1] - b.F[k]);
      if (Math.abs(F) < 1e-9) continue;
      const px = b.end === "left" ? ends[0] : ends[1], tip = px + (b.end === "left" ? -1 : 1) * per * Math.abs(F);
      arrow(ctx, F > 0 ? tip : px, F > 0 ? px : tip, y, 0.7 * size, {colour: fi.force.colour, width: 1.5 * fi.force.width});
    }
  }
