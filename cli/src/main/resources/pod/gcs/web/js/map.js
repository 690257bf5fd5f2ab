// Pod ground station: the map. An SVG in local metres around the first position the page hears
// (east right, north up), with pan (drag), zoom (wheel), a metric grid, a scale bar and a north
// arrow; every vehicle as a marker pointing along its heading, labelled, with its track.
//
// Panels draw on it through the exported API: `world(lat, lon)` gives metres, `layer(name)` an SVG
// group drawn in metres (it pans and zooms with the map; strokes keep their width), `screen(lat, lon)`
// pixels for things that keep their size, `onRedraw(fn)` after each pan or zoom, `onClick(fn)` with
// the clicked {lat, lon}.
const SVG = "http://www.w3.org/2000/svg";
const EARTH_RADIUS = 6378137;
const TRACK_POINTS = 3000;

let svg, worldGroup, gridGroup, screenGroup, vehicleGroup;
let origin = null; // {lat, lon, cos}
const view = { cx: 0, cy: 0, scale: 1.5 }; // centre in world metres, pixels per metre
const layers = new Map();
const redrawListeners = [];
const clickListeners = [];
const markers = new Map(); // sysid → {g, track: [[x,y]...], line}
let appRef = null;

export function el(name, attrs = {}, parent = null) {
  const node = document.createElementNS(SVG, name);
  for (const [k, v] of Object.entries(attrs)) node.setAttribute(k, v);
  if (parent) parent.appendChild(node);
  return node;
}

/** World metres {x: east, y: south} of a position (y grows down, as SVG's does). */
export function world(lat, lon) {
  if (!origin) setOrigin(lat, lon);
  const k = (Math.PI / 180) * EARTH_RADIUS;
  return { x: (lon - origin.lon) * k * origin.cos, y: -(lat - origin.lat) * k };
}

/** The position at world metres (x, y). */
export function position(x, y) {
  const k = (Math.PI / 180) * EARTH_RADIUS;
  return { lat: origin.lat - y / k, lon: origin.lon + x / (k * origin.cos) };
}

/** Pixels on the SVG of a position. */
export function screen(lat, lon) {
  const w = world(lat, lon);
  return toScreen(w.x, w.y);
}

function toScreen(x, y) {
  const r = svg.getBoundingClientRect();
  return { x: (x - view.cx) * view.scale + r.width / 2, y: (y - view.cy) * view.scale + r.height / 2 };
}

function toWorld(px, py) {
  const r = svg.getBoundingClientRect();
  return { x: (px - r.width / 2) / view.scale + view.cx, y: (py - r.height / 2) / view.scale + view.cy };
}

/** An SVG group drawn in world metres, under the vehicles; created on first use, in call order. */
export function layer(name) {
  if (!layers.has(name)) layers.set(name, el("g", { class: `layer ${name}` }, worldGroup));
  return layers.get(name);
}

/** Pixels per metre now (to size things drawn in metres that should keep a size on screen). */
export function pixelsPerMetre() { return view.scale; }

export function onRedraw(fn) { redrawListeners.push(fn); }
export function onClick(fn) { clickListeners.push(fn); }

/** Centres the map on a position, optionally at `scale` pixels per metre. */
export function centreOn(lat, lon, scale) {
  const w = world(lat, lon);
  view.cx = w.x; view.cy = w.y;
  if (scale) view.scale = scale;
  redraw();
}

function setOrigin(lat, lon) {
  origin = { lat, lon, cos: Math.cos((lat * Math.PI) / 180) };
}

function redraw() {
  if (!origin) return;
  const r = svg.getBoundingClientRect();
  worldGroup.setAttribute("transform", `translate(${r.width / 2} ${r.height / 2}) scale(${view.scale}) translate(${-view.cx} ${-view.cy})`);
  drawGrid(r);
  drawVehicles();
  redrawListeners.forEach((fn) => fn());
}

/** Grid lines every 1, 2 or 5 × 10^n metres, about 80 px apart; the scale bar one step long. */
function drawGrid(r) {
  gridGroup.replaceChildren();
  const step = niceStep(80 / view.scale);
  const a = toWorld(0, 0), b = toWorld(r.width, r.height);
  for (let x = Math.floor(a.x / step) * step; x <= b.x; x += step) {
    const p = toScreen(x, 0).x;
    el("line", { x1: p, y1: 0, x2: p, y2: r.height, class: x === 0 ? "grid origin" : "grid" }, gridGroup);
  }
  for (let y = Math.floor(a.y / step) * step; y <= b.y; y += step) {
    const p = toScreen(0, y).y;
    el("line", { x1: 0, y1: p, x2: r.width, y2: p, class: y === 0 ? "grid origin" : "grid" }, gridGroup);
  }
  const bar = el("g", { class: "scale-bar", transform: `translate(16 ${r.height - 20})` }, gridGroup);
  el("line", { x1: 0, y1: 0, x2: step * view.scale, y2: 0 }, bar);
  el("text", { x: 0, y: -5 }, bar).textContent = step >= 1000 ? `${step / 1000} km` : `${step} m`;
  const north = el("g", { class: "north", transform: `translate(${r.width - 24} 34)` }, gridGroup);
  el("path", { d: "M0,-16 L7,8 L0,3 L-7,8 Z" }, north);
  el("text", { x: 0, y: -20 }, north).textContent = "N";
}

function niceStep(metres) {
  const p = Math.pow(10, Math.floor(Math.log10(metres)));
  for (const m of [1, 2, 5, 10]) if (m * p >= metres) return m * p;
  return 10 * p;
}

function marker(sysid) {
  let m = markers.get(sysid);
  if (!m) {
    const g = el("g", { class: "vehicle", "data-sysid": sysid }, vehicleGroup);
    el("path", { class: "body", d: "M0,-11 L7,8 L0,4 L-7,8 Z" }, g);
    const label = el("text", { class: "label", x: 10, y: -6 }, vehicleGroup);
    const line = el("polyline", { class: "track", "data-sysid": sysid }, layer("tracks"));
    g.addEventListener("click", (event) => { event.stopPropagation(); appRef.select(sysid); });
    m = { g, label, line, track: [] };
    markers.set(sysid, m);
  }
  return m;
}

function drawVehicles() {
  for (const v of appRef.vehicles.values()) {
    const t = v.telemetry;
    if (!t || t.lat == null || t.lon == null) continue;
    const m = marker(v.sysid);
    const w = world(t.lat, t.lon);
    const last = m.track[m.track.length - 1];
    if (!last || Math.hypot(last[0] - w.x, last[1] - w.y) > 0.5) {
      m.track.push([w.x, w.y]);
      // Appended to the polyline's own point list: rewriting its `points` text cost O(track) per
      // vehicle per batch, the page's whole frame budget at 250 vehicles (BENCHMARKS.md, issue 28).
      const p = svg.createSVGPoint();
      p.x = w.x; p.y = w.y;
      m.line.points.appendItem(p);
      if (m.track.length > TRACK_POINTS) { m.track.shift(); m.line.points.removeItem(0); }
    }
    const s = toScreen(w.x, w.y);
    m.g.setAttribute("transform", `translate(${s.x.toFixed(1)} ${s.y.toFixed(1)}) rotate(${(t.heading || 0).toFixed(0)})`);
    m.g.setAttribute("data-lat", t.lat);
    m.g.setAttribute("data-lon", t.lon);
    m.g.classList.toggle("lost", v.lost);
    m.g.classList.toggle("selected", appRef.selected === v.sysid);
    const alt = t.alt_rel == null ? "–" : `${t.alt_rel.toFixed(1)} m`;
    const battery = t.battery == null ? "" : ` ${Math.round(t.battery * 100)}%`;
    m.label.setAttribute("x", (s.x + 10).toFixed(1));
    m.label.setAttribute("y", (s.y - 6).toFixed(1));
    m.label.textContent = `${v.sysid} ${t.mode || "?"} ${alt}${battery}`;
  }
}

export function init(app) {
  appRef = app;
  svg = document.getElementById("map");
  gridGroup = el("g", { class: "grid-layer" }, svg);
  worldGroup = el("g", { class: "world" }, svg);
  screenGroup = el("g", { class: "screen" }, svg);
  vehicleGroup = el("g", { class: "vehicles" }, screenGroup);
  let centred = false;
  app.afterBatch(() => {
    if (!centred) {
      const first = [...app.vehicles.values()].find((v) => v.telemetry && v.telemetry.lat != null);
      if (first) { centred = true; centreOn(first.telemetry.lat, first.telemetry.lon); return; }
    }
    if (origin) drawVehicles();
  });
  let drag = null;
  svg.addEventListener("pointerdown", (e) => { drag = { x: e.clientX, y: e.clientY, moved: false }; });
  svg.addEventListener("pointermove", (e) => {
    if (!drag) return;
    const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
    if (!drag.moved && Math.hypot(dx, dy) < 4) return;
    drag.moved = true;
    view.cx -= dx / view.scale; view.cy -= dy / view.scale;
    drag.x = e.clientX; drag.y = e.clientY;
    redraw();
  });
  svg.addEventListener("pointerup", (e) => {
    const wasClick = drag && !drag.moved;
    drag = null;
    if (!wasClick || !origin) return;
    const r = svg.getBoundingClientRect();
    const w = toWorld(e.clientX - r.left, e.clientY - r.top);
    const p = position(w.x, w.y);
    clickListeners.forEach((fn) => fn({ lat: p.lat, lon: p.lon, event: e }));
  });
  svg.addEventListener("wheel", (e) => {
    e.preventDefault();
    if (!origin) return;
    const r = svg.getBoundingClientRect();
    const before = toWorld(e.clientX - r.left, e.clientY - r.top);
    view.scale = Math.min(200, Math.max(0.005, view.scale * Math.exp(-e.deltaY * 0.0015)));
    const after = toWorld(e.clientX - r.left, e.clientY - r.top);
    view.cx += before.x - after.x; view.cy += before.y - after.y;
    redraw();
  }, { passive: false });
  window.addEventListener("resize", redraw);
}
