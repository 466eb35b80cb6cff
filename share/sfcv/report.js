// sfcv HTML report: plays a counterexample on the chart. Plain JavaScript, no framework.
// Data: <script id="sfcv-data"> holds {result: <sfcv check --json>, nodes: {steps, transitions,
// situations}} where nodes map observable and transition names to the ids of the chart's SVG
// nodes, and a Grafcet step situation (its step names sorted, joined by ",") to its node on the
// situation graph.
// URL hash "#trace=I&cycle=K" selects a trace and a cycle (bookmarks, the browser test).
(function () {
  "use strict";
  const data = JSON.parse(document.getElementById("sfcv-data").textContent);
  // "&test" in the hash asks for the layout probe the browser tests read (html_page.cpp): kept
  // when the player rewrites the hash.
  const testing = /(^#|&)test(&|=|$)/.test(location.hash) ? "&test" : "";
  const traces = data.result.properties
    .map((p, i) => ({ property: p, index: i }))
    .filter((x) => x.property.trace && x.property.trace.steps.length > 0);
  const player = document.getElementById("player");
  // The pictures' zoom (fitted, or natural size when the fitted text would be too small) is the
  // shared script of every page (html_page.cpp, html_pictures_script).
  const situations = document.getElementById("situations-svg");
  if (traces.length === 0) return;
  player.hidden = false;

  const $ = (id) => document.getElementById(id);
  const select = $("trace-select");
  const svgNS = "http://www.w3.org/2000/svg";
  let current = 0; // index into traces
  let cycle = 0;

  traces.forEach((t, i) => {
    const o = document.createElement("option");
    o.value = String(i);
    o.textContent = t.property.name + " (" + t.property.verdict + ", " + t.property.trace.kind + ")";
    select.appendChild(o);
  });

  function trace() { return traces[current].property.trace; }
  function text(el, s) { el.textContent = s; return el; }
  function make(tag, cls, content) {
    const el = document.createElement(tag);
    if (cls) el.className = cls;
    if (content !== undefined) el.textContent = content;
    return el;
  }
  function show(v) { return v === true ? "1" : v === false ? "0" : String(v); }

  // Highlighting on the chart: steps active in this cycle, transitions fired to get here.
  function highlight(step) {
    document.querySelectorAll("#chart-svg g.active, #chart-svg g.fired").forEach((g) => {
      g.classList.remove("active", "fired");
    });
    const mark = (names, map, cls) => names.forEach((n) => {
      const g = map[n] && document.getElementById(map[n]);
      if (g) g.classList.add(cls);
    });
    mark(step.active_steps, data.nodes.steps, "active");
    mark(step.fired, data.nodes.transitions, "fired");
    const first = document.querySelector("#chart-svg g.active, #chart-svg g.fired");
    if (first) follow($("chart-svg"), first);
    // Grafcet: the cycle's step situation on the situation graph.
    document.querySelectorAll("#situations-svg g.active").forEach((g) => g.classList.remove("active"));
    const situation = (data.nodes.situations || {})[step.active_steps.slice().sort().join(",")];
    const node = situation && document.getElementById(situation);
    if (node) {
      node.classList.add("active");
      follow(situations, node);
    }
  }
  // Scroll a picture's own box (not the page) to a node out of its view.
  function follow(box, node) {
    if (!box || box.classList.contains("fit")) return;
    const r = node.getBoundingClientRect(), b = box.getBoundingClientRect();
    if (r.left < b.left || r.right > b.right) box.scrollLeft += r.left - b.left - (b.width - r.width) / 2;
    if (r.top < b.top || r.bottom > b.bottom) box.scrollTop += r.top - b.top - (b.height - r.height) / 2;
  }

  // A qualified name ("Plant.V2") whose short form ("V2", the property's atom) is also a value
  // is the same signal: show it once.
  // An input is shown with the inputs, not again among the values (a Grafcet state holds them).
  function shownValues(values, inputs) {
    return Object.keys(values).filter((n) => {
      const dot = n.lastIndexOf(".");
      return !(n in inputs) && (dot < 0 || !(n.slice(dot + 1) in values));
    });
  }
  function pick(obj, names) {
    const out = {};
    names.forEach((n) => { out[n] = obj[n]; });
    return out;
  }
  function signals(t) {
    const s0 = t.steps[0];
    return Object.keys(s0.inputs).map((n) => ({ name: n, kind: "input" }))
      .concat(shownValues(s0.values, s0.inputs).map((n) => ({ name: n, kind: "value" })));
  }
  function valueOf(step, sig) { return sig.kind === "input" ? step.inputs[sig.name] : step.values[sig.name]; }

  // The cycle's panel: inputs (changed ones marked), fired transitions, active steps, values.
  function panel(t, k) {
    const step = t.steps[k];
    const marked = new Set(t.marked);
    text($("cycle-label"), "cycle " + k + " of " + (t.steps.length - 1) +
      (t.loop_start !== null && k === t.steps.length - 1 ? " (back to cycle " + t.loop_start + ")" : ""));
    text($("fired"), step.fired.length ? step.fired.join(", ") : "none");
    text($("active-steps"), step.active_steps.join(" "));
    const fill = (id, obj, changed) => {
      const box = $(id);
      box.replaceChildren();
      Object.keys(obj).forEach((n) => {
        const cls = "sig" + (changed && changed.includes(n) ? " changed" : "") +
          (marked.has(n) ? " marked" : "") + (obj[n] === true || (obj[n] !== false && obj[n] !== 0) ? " on" : "");
        const chip = make("span", cls, n + "=" + show(obj[n]));
        chip.dataset.name = n;
        chip.dataset.value = show(obj[n]);
        box.appendChild(chip);
      });
    };
    fill("inputs", step.inputs, k > 0 ? step.changed : null);
    const values = pick(step.values, shownValues(step.values, step.inputs));
    fill("values", values, null);
    const on = Object.keys(values).filter((n) => values[n] === true);
    $("values").dataset.on = on.join(" ");
  }

  // The waveform of every input and value over the whole trace, with a cursor on the cycle.
  const W = 34, H = 20, LABEL = 150;
  function waveform(t) {
    const sigs = signals(t);
    const n = t.steps.length;
    const svg = document.createElementNS(svgNS, "svg");
    svg.setAttribute("width", LABEL + n * W + 10);
    svg.setAttribute("height", (sigs.length + 1) * H + 6);
    // Scales when printed (report.css); on screen the box scrolls instead.
    svg.setAttribute("viewBox", "0 0 " + (LABEL + n * W + 10) + " " + ((sigs.length + 1) * H + 6));
    svg.id = "waveform-svg";
    const add = (tag, attrs, content) => {
      const el = document.createElementNS(svgNS, tag);
      Object.keys(attrs).forEach((a) => el.setAttribute(a, attrs[a]));
      if (content !== undefined) el.textContent = content;
      svg.appendChild(el);
      return el;
    };
    for (let k = 0; k < n; k++) {
      add("text", { x: LABEL + k * W + W / 2, y: 14, class: "tick" }, String(k));
      const hit = add("rect", { x: LABEL + k * W, y: 0, width: W, height: (sigs.length + 1) * H, class: "hit" });
      hit.addEventListener("click", () => go(k));
    }
    add("rect", { id: "cursor", x: LABEL, y: 2, width: W, height: (sigs.length + 1) * H, class: "cursor" });
    sigs.forEach((sig, r) => {
      const y0 = (r + 1) * H + 4;
      add("text", { x: 4, y: y0 + 13, class: "name " + sig.kind + (t.marked.includes(sig.name) ? " marked" : "") }, sig.name);
      const bool = typeof valueOf(t.steps[0], sig) === "boolean";
      if (bool) {
        let d = "";
        for (let k = 0; k < n; k++) {
          const y = valueOf(t.steps[k], sig) ? y0 + 2 : y0 + H - 4;
          d += (k === 0 ? "M" : "L") + (LABEL + k * W) + " " + y + " L" + (LABEL + (k + 1) * W) + " " + y + " ";
        }
        add("path", { d: d, class: "wave" });
      } else {
        for (let k = 0; k < n; k++) {
          const v = valueOf(t.steps[k], sig);
          if (k > 0 && v === valueOf(t.steps[k - 1], sig)) continue;
          let end = k + 1;
          while (end < n && valueOf(t.steps[end], sig) === v) end++;
          add("rect", { x: LABEL + k * W + 1, y: y0 + 2, width: (end - k) * W - 2, height: H - 6, class: "bus" });
          add("text", { x: LABEL + k * W + 4, y: y0 + 13, class: "busval" }, String(v));
        }
      }
    });
    $("waveform").replaceChildren(svg);
  }

  function go(k) {
    const t = trace();
    cycle = Math.max(0, Math.min(t.steps.length - 1, k));
    panel(t, cycle);
    highlight(t.steps[cycle]);
    const cursor = document.getElementById("cursor");
    if (cursor) cursor.setAttribute("x", LABEL + cycle * W);
    $("prev").disabled = cycle === 0;
    $("first").disabled = cycle === 0;
    $("next").disabled = cycle === t.steps.length - 1;
    $("last").disabled = cycle === t.steps.length - 1;
    history.replaceState(null, "", "#trace=" + current + "&cycle=" + cycle + testing);
  }

  function load(i, k) {
    current = Math.max(0, Math.min(traces.length - 1, i));
    select.value = String(current);
    const p = traces[current].property;
    text($("trace-title"), p.name + (p.formula && p.formula !== p.name ? " \u2014 " + p.formula : ""));
    text($("trace-note"), p.trace.note || "");
    waveform(p.trace);
    go(k);
  }

  select.addEventListener("change", () => load(Number(select.value), 0));
  $("first").addEventListener("click", () => go(0));
  $("prev").addEventListener("click", () => go(cycle - 1));
  $("next").addEventListener("click", () => go(cycle + 1));
  $("last").addEventListener("click", () => go(trace().steps.length - 1));
  document.addEventListener("keydown", (e) => {
    if (e.target === select) return;
    if (e.key === "ArrowRight") go(cycle + 1);
    else if (e.key === "ArrowLeft") go(cycle - 1);
    else if (e.key === "Home") go(0);
    else if (e.key === "End") go(trace().steps.length - 1);
    else return;
    e.preventDefault();
  });
  document.querySelectorAll("a.play").forEach((a) => a.addEventListener("click", (e) => {
    e.preventDefault();
    const i = traces.findIndex((t) => t.index === Number(a.dataset.property));
    if (i >= 0) load(i, 0);
    player.scrollIntoView();
  }));

  const hash = new URLSearchParams(location.hash.slice(1));
  load(Number(hash.get("trace") || 0), Number(hash.get("cycle") || 0));
  // "#press=RRL": key presses (Right, Left, Home, End) replayed through the keyboard handler,
  // so that a headless browser test steps the way a user does.
  const keys = { R: "ArrowRight", L: "ArrowLeft", H: "Home", E: "End" };
  for (const c of hash.get("press") || "")
    if (keys[c]) document.dispatchEvent(new KeyboardEvent("keydown", { key: keys[c], bubbles: true }));
})();
