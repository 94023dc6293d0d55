// The page's script, part 5 of 5 (page.py joins the parts into one <script>): the controls and the start.
  // --- the controls ----------------------------------------------------------------------------------------
  function setSpeedControl() {
    const speeds = scenario().speeds;
    controls.speed.max = String(speeds.length - 1);
    controls.speed.value = String(state.speed);
    controls.speed.setAttribute("aria-valuetext", "v = " + shown(v(), 10));
    $("speed-value").textContent = shown(v(), 10);
    controls.frame.min = String(-scenario().frame_steps); controls.frame.max = String(scenario().frame_steps);
    rodControls.forEach((input, k) => {
      input.checked = RODS[k] === state.rod;
      input.disabled = RODS[k] !== "rigid" && !modelNamed("causal") || RODS[k] !== "causal" && !modelNamed("rigid");
    });
  }
  // The speeds a rod is not shown at (its run refused there, or longer than the page allows): said under the slider.
  function setLeftOut() {
    const gone = Object.entries(scenario().left_out || {}).filter(([, vs]) => vs.length);
    const said = gone.map(([model, vs]) => `the ${model} rod at v = ${vs.map((u) => shown(u, 10)).join(", ")}`);
    $("left-out").hidden = !said.length;
    $("left-out").textContent = said.length ? `Not on this page: ${said.join("; ")} (its run there is refused, ` +
      "or would take longer than this page allows)." : "";
  }
  function setFrameControl() {
    controls.frame.value = String(Math.round(state.u * 100));
    const said = frameSymbol(state.u) + (frameName(state.u) === "u" ? "" : ` (u = ${shown(state.u, 10)})`);
    controls.frame.setAttribute("aria-valuetext", said);
    $("frame-value").textContent = said;
    controls.rest.setAttribute("aria-pressed", String(frameName(state.u) === "rest"));
    controls.moving.setAttribute("aria-pressed", String(frameName(state.u) === "moving"));
  }
  function setTimeControl() {
    const t = nowTime(shared()), clock = coordinateNames(state.u)[1];
    controls.time.value = String(Math.round(state.time * 1000));
    controls.time.setAttribute("aria-valuetext", `${clock} = ${shown(t, 4)} L`);
    $("time-value").textContent = `${clock} = ${shown(t, 4)} L`;
  }

  function render() {
    const start = performance.now();
    document.body.className = "style-" + state.style;
    controls.scenario.value = String(state.scenario); controls.style.value = state.style;
    controls.cones.checked = state.cones;
    $("heading").textContent = scenario().title;
    $("about").textContent = DATA.scenarios.length > 1 ? DATA.about_several : scenario().description;
    setSpeedControl(); setLeftOut(); setFrameControl(); setTimeControl();
    drawPanels(true);
    const took = performance.now() - start;
    if (timings.first === null) { timings.first = took; timings.drawnAt = performance.now(); }
    else timings.redraws.push(took);
  }
  // A time step redraws only what moves with time.
  function renderTime() {
    const start = performance.now();
    setTimeControl();
    drawPanels(false);
    timings.redraws.push(performance.now() - start);
  }

  // Each shown panel: its heading, diagram, strip, ledger and (with `all`) its events table; the second panel and
  // its tables hidden when one rod is shown; side by side when the window is wide enough, else one under the other.
  let widths = null;  // the panels' widths, measured again only when the window, the style or the panels change
  function drawPanels(all) {
    const view = shared(), two = view.gs.length === 2;
    $("panels").classList.toggle("two", two);
    PANELS[1].box.hidden = !two; PANELS[1].tables.hidden = !two;
    const sign = [window.innerWidth, window.innerHeight, state.style, two].join("/");
    if (!widths || widths.sign !== sign) {  // a measurement forces a layout of the whole page: once, before any drawing
      const sliders = $("sliders"), fixed = getComputedStyle(sliders).position === "fixed";
      widths = {sign, px: view.gs.map((g, k) => PANELS[k].box.clientWidth), footer: fixed ? sliders.offsetHeight : 0};
    }
    view.gs.forEach((g, k) => { PANELS[k].width = widths.px[k]; });
    view.gs.forEach((g, k) => {
      const panel = PANELS[k];
      panel.heading.textContent = g.model.model === "causal" ? "The causal rod (sound at c)" : "The rigid rod (the paper\u2019s)";
      const place = drawDiagram(panel, g, view);
      drawStrip(panel, place, g, view);
      drawLedger(panel, g, view);
      if (all) drawEvents(panel, g);
    });
    if (all) drawLegend(view.gs);
  }

  let pending = null;
  function soon(what) {  // one drawing per animation frame however fast the events come
    if (pending === null) requestAnimationFrame(() => { const f = pending; pending = null; f(); });
    pending = pending === render || what === render ? render : what;
  }

  controls.scenario.addEventListener("change", () => {
    state.scenario = Number(controls.scenario.value);
    state.speed = scenario().speeds.findIndex((e) => e.v === scenario().v);
    state.rod = scenario().rod; state.u = 0; soon(render);
  });
  rodControls.forEach((input) => input.addEventListener("change", () => {
    if (input.checked) { state.rod = input.value; soon(render); }
  }));
  controls.speed.addEventListener("input", () => {
    const moving = frameName(state.u) === "moving";
    state.speed = Number(controls.speed.value);
    if (moving) state.u = -v();  // S' stays S' at the new speed
    soon(render);
  });
  controls.frame.addEventListener("input", () => { state.u = Number(controls.frame.value) / 100 + 0; soon(render); });
  controls.rest.addEventListener("click", () => { state.u = 0; render(); });
  controls.moving.addEventListener("click", () => { state.u = -v(); render(); });
  controls.time.addEventListener("input", () => { state.time = Number(controls.time.value) / 1000; soon(renderTime); });
  controls.cones.addEventListener("change", () => { state.cones = controls.cones.checked; soon(render); });
  controls.style.addEventListener("change", () => { state.style = controls.style.value; soon(render); });
  let last = null;
  function tick(now) {
    if (!state.playing) { last = null; return; }
    if (last !== null) state.time = (state.time + (now - last) / 8000) % 1;  // eight seconds a sweep
    last = now;
    renderTime();
    requestAnimationFrame(tick);
  }
  controls.play.addEventListener("click", () => {
    state.playing = !state.playing;
    controls.play.textContent = state.playing ? "Pause" : "Play";
    controls.play.setAttribute("aria-pressed", String(state.playing));
    if (state.playing) requestAnimationFrame(tick);
  });
  window.addEventListener("resize", () => soon(render));
  // a panel whose width changes without a resize (a scroll bar comes with the tables): measured again
  new ResizeObserver((seen) => {
    if (widths && seen.some((e) => !widths.px.includes(Math.round(e.target.clientWidth)))) { widths = null; soon(render); }
  }).observe($("panel-1"));

  // --- start -------------------------------------------------------------------------------------------------
  controls.scenario.innerHTML = DATA.scenarios.map((s, k) => `<option value="${k}">${s.title}</option>`).join("");
  controls.scenario.disabled = DATA.scenarios.length < 2;
  controls.style.value = state.style;
  state.speed = scenario().speeds.findIndex((e) => e.v === scenario().v);
  state.rod = scenario().rod;
  state.time = openingTime();
  render();
  // the causal rod's cells of every speed sorted while nobody is dragging yet: one speed a tick
  const unsorted = DATA.scenarios.flatMap((sc) => sc.speeds.flatMap((e) => e.models.filter((m) => m.cells)));
  (function sortSome() { const m = unsorted.shift(); if (m) { keptCells(m.cells); setTimeout(sortSome, 0); } })();
  // for the tests and the benchmark: the state, the drawing's geometry, the times each drawing took; row and
  // column of the first panel, or of panel k (0 or 1)
  window.searsParadox = {state, timings, geometry, render, nowTime: () => nowTime(shared()),
                         formats: {coordinateFormat, velocityFormat, ledgerCell},
                         row: (t, k) => PANELS[k || 0].placed.row(t), column: (x, k) => PANELS[k || 0].placed.column(x)};
})();
