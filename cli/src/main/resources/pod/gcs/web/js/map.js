// Pod ground station: the map. An SVG in local metres around the first position the page hears
// (east right, north up), with pan (drag), zoom (wheel), a metric grid, a scale bar, a north arrow
// and a "fit" control; the vehicles, their tracks and homes are drawn by map-vehicles.js, the
// optional tiles under the grid by map-tiles.js.
//
// Panels draw on it through the exported API: `world(lat, lon)` gives metres, `layer(name)` an SVG
// group drawn in metres (it pans and zooms with the map; strokes keep their width), `screen(lat, lon)`
// pixels for things that keep their size, `onRedraw(fn)` after each pan or zoom, `onClick(fn)` with
// the clicked {lat, lon}. Added for the fleet view: `fit(points)`, `underlay(name)`, `screenLayer(name)`,
// `toScreen(x, y)`, `onUserView(fn)`; `app.map` holds the same functions for scripts and tests.
import * as vehicles from "./map-vehicles.js";
import * as tiles from "./map-tiles.js";

const SVG = "http://www.w3.org/2000/svg";
const EARTH_RADIUS = 6378137;
const MIN_SCALE = 0.002; // pixels per metre: ~500 km across a 1000 px map
const MAX_SCALE = 200;
const FIT_MARGIN_PX = 70; // around the fitted points, so labels and markers stay inside
const FIT_MIN_SPAN_M = 40; // a fleet parked 5 m apart is fitted at a readable zoom, not 200 px/m

let svg, underGroup, gridGroup, worldGroup, screenGroup, overlayGroup;
let origin = null; // {lat, lon, cos}
const view = { cx: 0, cy: 0, scale: 1.5, width: 0, height: 0 }; // centre in world metres, pixels per metre, SVG size
const layers = new Map();
const underlays = new Map();
const screenLayers = new Map();
const redrawListeners = [];
const clickListeners = [];
const userViewListeners = [];
let redrawPending = false;

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

/** Pixels on the SVG of world metres (x, y); uses the size measured at the last redraw (no layout read). */
export function toScreen(x, y) {
  return { x: (x - view.cx) * view.scale + view.width / 2, y: (y - view.cy) * view.scale + view.height / 2 };
}

function toWorld(px, py) {
  return { x: (px - view.width / 2) / view.scale + view.cx, y: (py - view.height / 2) / view.scale + view.cy };
}

/** An SVG group drawn in world metres, under the vehicles; created on first use, in call order. */
export function layer(name) {
  if (!layers.has(name)) layers.set(name, el("g", { class: `layer ${name}` }, worldGroup));
  return layers.get(name);
}

/** An SVG group drawn in world metres under the grid (map tiles). */
export function underlay(name) {
  if (!underlays.has(name)) underlays.set(name, el("g", { class: `underlay ${name}` }, underGroup));
  return underlays.get(name);
}

/** An SVG group in screen pixels above the world layers (markers that keep their size), in call order. */
export function screenLayer(name) {
  if (!screenLayers.has(name)) screenLayers.set(name, el("g", { class: `screen-layer ${name}` }, screenGroup));
  return screenLayers.get(name);
}

/** Pixels per metre now (to size things drawn in metres that should keep a size on screen). */
export function pixelsPerMetre() { return view.scale; }

/** The visible area: {west, east, north, south} in degrees, and the scale; null before the first position. */
export function bounds() {
  if (!origin) return null;
  const nw = toWorld(0, 0), se = toWorld(view.width, view.height);
  const a = position(nw.x, nw.y), b = position(se.x, se.y);
  return { north: a.lat, west: a.lon, south: b.lat, east: b.lon, scale: view.scale, width: view.width, height: view.height };
}

export function onRedraw(fn) { redrawListeners.push(fn); }
export function onClick(fn) { clickListeners.push(fn); }
/** Calls fn() when the operator pans or zooms (the map stops fitting the fleet by itself). */
export function onUserView(fn) { userViewListeners.push(fn); }

/** Centres the map on a position, optionally at `scale` pixels per metre. */
export function centreOn(lat, lon, scale) {
  const w = world(lat, lon);
  view.cx = w.x; view.cy = w.y;
  if (scale) view.scale = clampScale(scale);
  redraw();
}

/**
 * Shows every one of `points` ([{lat, lon}]) with a margin, at the closest zoom that holds them
 * (never closer than FIT_MIN_SPAN_M across); vehicles kilometres apart are fitted as well as parked ones.
 */
export function fit(points) {
  if (!points.length) return;
  const ws = points.map((p) => world(p.lat, p.lon));
  const xs = ws.map((p) => p.x), ys = ws.map((p) => p.y);
  const x0 = Math.min(...xs), x1 = Math.max(...xs), y0 = Math.min(...ys), y1 = Math.max(...ys);
  measure();
  const usableW = Math.max(view.width - 2 * FIT_MARGIN_PX, 50), usableH = Math.max(view.height - 2 * FIT_MARGIN_PX, 50);
  const scale = Math.min(usableW / Math.max(x1 - x0, FIT_MIN_SPAN_M), usableH / Math.max(y1 - y0, FIT_MIN_SPAN_M));
  view.cx = (x0 + x1) / 2; view.cy = (y0 + y1) / 2;
  view.scale = clampScale(scale);
  redraw();
}

function clampScale(s) { return Math.min(MAX_SCALE, Math.max(MIN_SCALE, s)); }

function setOrigin(lat, lon) {
  origin = { lat, lon, cos: Math.cos((lat * Math.PI) / 180) };
}

function measure() {
  const r = svg.getBoundingClientRect();
  view.width = r.width; view.height = r.height;
}

/** Redraws now (after a programmatic change); pointer moves use requestRedraw, at most once a frame. */
function redraw() {
  if (!origin) return;
  measure();
  const t = `translate(${view.width / 2} ${view.height / 2}) scale(${view.scale}) translate(${-view.cx} ${-view.cy})`;
  worldGroup.setAttribute("transform", t);
  underGroup.setAttribute("transform", t);
  drawGrid();
  redrawListeners.forEach((fn) => fn());
}

function requestRedraw() {
  if (redrawPending) return;
  redrawPending = true;
  requestAnimationFrame(() => { redrawPending = false; redraw(); });
}

/** Grid lines every 1, 2 or 5 × 10^n metres, about 80 px apart; the scale bar one step long. */
function drawGrid() {
  gridGroup.replaceChildren();
  overlayGroup.replaceChildren();
  const step = niceStep(80 / view.scale);
  const a = toWorld(0, 0), b = toWorld(view.width, view.height);
  for (let x = Math.floor(a.x / step) * step; x <= b.x; x += step) {
    const p = toScreen(x, 0).x;
    el("line", { x1: p, y1: 0, x2: p, y2: view.height, class: x === 0 ? "grid origin" : "grid" }, gridGroup);
  }
  for (let y = Math.floor(a.y / step) * step; y <= b.y; y += step) {
    const p = toScreen(0, y).y;
    el("line", { x1: 0, y1: p, x2: view.width, y2: p, class: y === 0 ? "grid origin" : "grid" }, gridGroup);
  }
  const bar = el("g", { class: "scale-bar", transform: `translate(16 ${view.height - 20})` }, overlayGroup);
  el("line", { x1: 0, y1: 0, x2: step * view.scale, y2: 0, "data-metres": step }, bar);
  el("text", { x: 0, y: -6 }, bar).textContent = step >= 1000 ? `${step / 1000} km` : `${step} m`;
  const north = el("g", { class: "north", transform: `translate(${view.width - 24} 34)` }, overlayGroup);
  el("path", { d: "M0,-16 L7,8 L0,3 L-7,8 Z" }, north);
  el("text", { x: 0, y: -20 }, north).textContent = "N";
}

function niceStep(metres) {
  const p = Math.pow(10, Math.floor(Math.log10(metres)));
  for (const m of [1, 2, 5, 10]) if (m * p >= metres) return m * p;
  return 10 * p;
}

function userMoved() { userViewListeners.forEach((fn) => fn()); }

function listen() {
  let drag = null;
  svg.addEventListener("pointerdown", (e) => { drag = { x: e.clientX, y: e.clientY, moved: false }; });
  svg.addEventListener("pointermove", (e) => {
    if (!drag) return;
    const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
    if (!drag.moved && Math.hypot(dx, dy) < 4) return;
    if (!drag.moved) userMoved();
    drag.moved = true;
    view.cx -= dx / view.scale; view.cy -= dy / view.scale;
    drag.x = e.clientX; drag.y = e.clientY;
    requestRedraw();
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
    userMoved();
    const r = svg.getBoundingClientRect();
    const before = toWorld(e.clientX - r.left, e.clientY - r.top);
    view.scale = clampScale(view.scale * Math.exp(-e.deltaY * 0.0015));
    const after = toWorld(e.clientX - r.left, e.clientY - r.top);
    view.cx += before.x - after.x; view.cy += before.y - after.y;
    requestRedraw();
  }, { passive: false });
  new ResizeObserver(() => requestRedraw()).observe(svg);
}

export function init(app) {
  svg = document.getElementById("map");
  underGroup = el("g", { class: "under" }, svg);
  gridGroup = el("g", { class: "grid-layer" }, svg);
  worldGroup = el("g", { class: "world" }, svg);
  screenGroup = el("g", { class: "screen" }, svg);
  overlayGroup = el("g", { class: "overlay" }, svg);
  app.map = { world, position, screen, toScreen, fit, centreOn, bounds, pixelsPerMetre, fitFleet: () => vehicles.fitFleet() };
  listen();
  vehicles.init(app);
  tiles.init(app);
}
