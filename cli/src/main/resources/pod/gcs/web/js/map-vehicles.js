// Pod ground station: the fleet on the map. Each vehicle is a marker pointing along its heading in
// its own colour, labelled "sysid mode altitude battery" (labels laid out by map-labels.js so close
// vehicles stay readable), with its track and its home (the `home` events). A lost vehicle turns
// red, says LOST and stays where it was last heard; the selected one has a ring. Clicking a marker
// selects its vehicle; the Fit button shows the whole fleet, and the map fits it by itself until
// the operator pans or zooms.
//
// Cost per batch with 250 vehicles: only markers whose telemetry, state or screen position changed
// are touched; a track grows by appending to its SVG point list, never by rewriting it.
import { el, world, toScreen, layer, screenLayer, onRedraw, onUserView, fit } from "./map.js";
import { placeLabels, labelWidth, BASELINE, INSET } from "./map-labels.js";

const PALETTE = ["#1f6feb", "#00897b", "#7b1fa2", "#2e7d32", "#5d4037", "#283593", "#ad1457", "#827717"];
const TRACK_POINTS = 3000;
const TRACK_STEP_M = 0.5; // a new track point once the vehicle moved this far

const markers = new Map(); // sysid → marker state (see marker())
let appRef, svgRoot, homeLayer, markerLayer, labelLayer, note;
let autoFit = true;
let fittedCount = 0;
let viewChanged = true;

/** The colour of vehicle `sysid` (marker, track, home): the same on every page. */
export function colour(sysid) { return PALETTE[(sysid - 1 + PALETTE.length) % PALETTE.length]; }

/** Fits the map to every vehicle heard with a position and every home. */
export function fitFleet() {
  const points = [];
  for (const v of appRef.vehicles.values()) {
    if (v.telemetry && v.telemetry.lat != null) points.push({ lat: v.telemetry.lat, lon: v.telemetry.lon });
    if (v.home) points.push({ lat: v.home.lat, lon: v.home.lon });
  }
  fit(points);
}

/** The CSS font of a label (bold when selected or lost), read once per weight: canvas measuring needs it. */
const fonts = new Map();
function labelFont(label) {
  const bold = label.classList.contains("selected") || label.classList.contains("lost");
  if (!fonts.has(bold)) {
    const style = getComputedStyle(label);
    fonts.set(bold, `${style.fontWeight} ${style.fontSize} ${style.fontFamily}`);
  }
  return fonts.get(bold);
}

function labelText(v) {
  const t = v.telemetry;
  const alt = t.alt_rel == null ? "–" : `${t.alt_rel.toFixed(1)} m`;
  const battery = t.battery == null ? "" : ` ${Math.round(t.battery * 100)}%`;
  return `${v.sysid}${v.lost ? " LOST" : ""} ${t.mode || "?"} ${alt}${battery}`;
}

function marker(sysid) {
  let m = markers.get(sysid);
  if (m) return m;
  const style = `--vc: ${colour(sysid)}`;
  const g = el("g", { class: "vehicle", "data-sysid": sysid, style }, markerLayer);
  el("circle", { class: "halo", r: 15 }, g);
  el("path", { class: "body", d: "M0,-11 L7,8 L0,4 L-7,8 Z" }, g);
  const leader = el("line", { class: "leader", style }, labelLayer);
  const label = el("text", { class: "label", "data-sysid": sysid }, labelLayer);
  const line = el("polyline", { class: "track", "data-sysid": sysid, style }, layer("tracks"));
  g.addEventListener("pointerdown", (event) => event.stopPropagation());
  g.addEventListener("click", (event) => { event.stopPropagation(); appRef.select(sysid); });
  m = { g, label, leader, line, telemetry: null, screen: null, text: "", state: "", home: null, homeG: null, track: 0, last: null };
  markers.set(sysid, m);
  return m;
}

/** Appends the vehicle's position to its track when it moved TRACK_STEP_M, dropping the oldest beyond TRACK_POINTS. */
function extendTrack(m, w) {
  if (m.last && Math.hypot(m.last.x - w.x, m.last.y - w.y) < TRACK_STEP_M) return;
  const p = svgRoot.createSVGPoint();
  p.x = Math.round(w.x * 10) / 10; p.y = Math.round(w.y * 10) / 10;
  m.line.points.appendItem(p);
  if (m.line.points.numberOfItems > TRACK_POINTS) m.line.points.removeItem(0);
  m.last = w;
}

function drawHome(v, m) {
  if (!v.home) return;
  if (!m.homeG) {
    m.homeG = el("g", { class: "home", "data-sysid": v.sysid, style: `--vc: ${colour(v.sysid)}` }, homeLayer);
    el("path", { d: "M-7,1 L0,-6 L7,1 L5,1 L5,7 L-5,7 L-5,1 Z" }, m.homeG);
    el("title", {}, m.homeG).textContent = `home of vehicle ${v.sysid}`;
  }
  if (m.home === v.home && !viewChanged) return;
  m.home = v.home;
  const w = world(v.home.lat, v.home.lon), s = toScreen(w.x, w.y);
  m.homeG.setAttribute("transform", `translate(${s.x.toFixed(1)} ${s.y.toFixed(1)})`);
  m.homeG.setAttribute("data-lat", v.home.lat);
  m.homeG.setAttribute("data-lon", v.home.lon);
}

/** Updates one vehicle's marker; returns whether its screen position or label changed. */
function drawVehicle(v) {
  const t = v.telemetry;
  const m = marker(v.sysid);
  drawHome(v, m);
  let moved = false;
  if (t !== m.telemetry || viewChanged) {
    const w = world(t.lat, t.lon);
    if (t !== m.telemetry) extendTrack(m, w);
    const s = toScreen(w.x, w.y);
    const transform = `translate(${s.x.toFixed(1)} ${s.y.toFixed(1)}) rotate(${(t.heading || 0).toFixed(0)})`;
    if (m.g.getAttribute("transform") !== transform) { m.g.setAttribute("transform", transform); moved = true; }
    m.screen = s;
    if (t !== m.telemetry) { m.g.setAttribute("data-lat", t.lat); m.g.setAttribute("data-lon", t.lon); }
    m.telemetry = t;
  }
  const state = `${v.lost ? "lost" : ""} ${appRef.selected === v.sysid ? "selected" : ""}`;
  const restyled = state !== m.state;
  if (restyled) {
    m.state = state;
    for (const node of [m.g, m.label, m.line]) {
      node.classList.toggle("lost", v.lost);
      node.classList.toggle("selected", appRef.selected === v.sysid);
    }
    moved = true;
  }
  const text = labelText(v);
  if (text !== m.text || restyled) {
    m.text = text;
    m.label.textContent = text;
    m.width = labelWidth(text, labelFont(m.label)); // bold when selected or lost: wider
    moved = true;
  }
  return moved;
}

/** Lays the labels out again: the selected vehicle's first, then lost ones, then by sysid. */
function layoutLabels() {
  const items = [...markers.entries()].filter(([, m]) => m.screen)
    .map(([sysid, m]) => ({ key: sysid, x: m.screen.x, y: m.screen.y, width: m.width, m }))
    .sort((a, b) => rank(a.key) - rank(b.key) || a.key - b.key);
  const spots = placeLabels(items);
  let hidden = 0;
  for (const it of items) {
    const spot = spots.get(it.key);
    if (!spot) hidden++;
    placeLabel(it.m, spot, it);
  }
  note.textContent = hidden ? `${hidden} label${hidden > 1 ? "s" : ""} hidden: zoom in` : "";
  note.style.display = hidden ? "" : "none";
}

/** Moves one label (and its leader line) to `spot`, or hides it; writes the DOM only for what changed. */
function placeLabel(m, spot, it) {
  const key = spot ? `${(spot.x + INSET).toFixed(1)} ${(spot.y + BASELINE).toFixed(1)} ${spot.leader ? `${it.x.toFixed(1)} ${it.y.toFixed(1)}` : ""}` : "hidden";
  if (key === m.placed) return;
  m.placed = key;
  m.label.style.display = spot ? "" : "none";
  m.leader.style.display = spot && spot.leader ? "" : "none";
  if (!spot) return;
  m.label.setAttribute("x", (spot.x + INSET).toFixed(1));
  m.label.setAttribute("y", (spot.y + BASELINE).toFixed(1));
  if (spot.leader) {
    const toRight = spot.x > it.x;
    const ends = { x1: it.x, y1: it.y, x2: toRight ? spot.x : spot.x + it.width, y2: spot.y + BASELINE / 2 + 2 };
    for (const [k, val] of Object.entries(ends)) m.leader.setAttribute(k, val.toFixed(1));
  }
}

function rank(sysid) {
  if (appRef.selected === sysid) return 0;
  const v = appRef.vehicles.get(sysid);
  return v && v.lost ? 1 : 2;
}

function draw() {
  let changed = viewChanged;
  let positioned = 0;
  for (const v of appRef.vehicles.values()) {
    if (!v.telemetry || v.telemetry.lat == null || v.telemetry.lon == null) continue;
    positioned++;
    if (drawVehicle(v)) changed = true;
  }
  if (changed) layoutLabels();
  viewChanged = false;
  return positioned;
}

function tools() {
  const bar = document.getElementById("map-tools");
  const fitButton = document.createElement("button");
  fitButton.id = "map-fit";
  fitButton.textContent = "Fit";
  fitButton.title = "zoom to the whole fleet";
  fitButton.addEventListener("click", fitFleet);
  const centre = document.createElement("button");
  centre.id = "map-centre";
  centre.textContent = "Centre";
  centre.title = "centre on the selected vehicle";
  centre.addEventListener("click", () => {
    const v = appRef.vehicles.get(appRef.selected);
    if (v && v.telemetry && v.telemetry.lat != null) appRef.map.centreOn(v.telemetry.lat, v.telemetry.lon);
  });
  bar.append(fitButton, centre);
  note = document.createElement("div");
  note.id = "map-note";
  note.style.display = "none";
  document.getElementById("map-panel").appendChild(note);
}

export function init(app) {
  appRef = app;
  svgRoot = document.getElementById("map");
  homeLayer = screenLayer("homes");
  markerLayer = screenLayer("vehicles");
  labelLayer = screenLayer("labels");
  tools();
  onUserView(() => { autoFit = false; });
  onRedraw(() => { viewChanged = true; draw(); });
  app.afterBatch(() => {
    const positioned = [...app.vehicles.values()].filter((v) => v.telemetry && v.telemetry.lat != null).length;
    // Until the operator moves the map, it keeps the whole fleet in view as vehicles appear.
    if (autoFit && positioned > fittedCount) { fittedCount = positioned; fitFleet(); return; }
    draw();
  });
}
