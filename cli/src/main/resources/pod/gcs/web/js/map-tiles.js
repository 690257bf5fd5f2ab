// Pod ground station: map tiles under the grid, when `pod gcs --tiles URL-template` gave a template
// (`gcs_hello.tiles`); without one the map stays an offline metric grid.
//
// Tiles are the usual XYZ scheme on Web Mercator (OpenStreetMap's "slippy map" numbering: x east
// from the antimeridian, y south from ~85°N, 2^z of each at zoom z). Each tile is drawn as an SVG
// <image> whose corners are projected with the map's own `world()`, so it lines up with the vehicles
// whatever the projection's origin; inside a tile the small difference between Mercator and the
// map's local projection is not corrected (well under a pixel at the zooms a field map uses).
// Only the tiles the view needs are attached, at the zoom whose pixel is closest to the map's, at
// most MAX_TILES of them (fewer, coarser tiles beyond); the last CACHE_SIZE images are kept so
// panning back does not fetch again. Who made the tiles is the user's business: the map shows
// "tiles: host" and leaves attribution to them.
import { el, world, underlay, onRedraw, bounds } from "./map.js";

const MAX_ZOOM = 19;
const MAX_TILES = 48;
const CACHE_SIZE = 200;
const TILE_PX = 256;
const EQUATOR_M_PER_PX_Z0 = (2 * Math.PI * 6378137) / TILE_PX; // 156543.03 m per pixel at zoom 0

let template = null;
let group = null;
let note = null;
let failed = 0;
const cache = new Map(); // "z/x/y" → <image>, least recently used first

/** The tile {x, y} holding a position at zoom z. */
export function tileOf(lat, lon, z) {
  const n = 2 ** z;
  const r = (lat * Math.PI) / 180;
  const x = Math.floor(((lon + 180) / 360) * n);
  const y = Math.floor(((1 - Math.log(Math.tan(r) + 1 / Math.cos(r)) / Math.PI) / 2) * n);
  return { x: clamp(x, 0, n - 1), y: clamp(y, 0, n - 1) };
}

/** The zoom whose tile pixel is closest to `scale` pixels per metre at latitude `lat`. */
export function zoomFor(scale, lat) {
  const z = Math.round(Math.log2(EQUATOR_M_PER_PX_Z0 * Math.cos((lat * Math.PI) / 180) * scale));
  return clamp(z, 0, MAX_ZOOM);
}

function tileLon(x, z) { return (x / 2 ** z) * 360 - 180; }

function tileLat(y, z) {
  const n = Math.PI - (2 * Math.PI * y) / 2 ** z;
  return (180 / Math.PI) * Math.atan(Math.sinh(n));
}

function clamp(v, lo, hi) { return Math.min(hi, Math.max(lo, v)); }

function url(z, x, y) {
  return template.replace("{z}", z).replace("{x}", x).replace("{y}", y).replace("{s}", "abc"[(x + y) % 3]);
}

/** The tiles covering the view: the zoom fitting the scale, coarser while that needs more than MAX_TILES. */
function wanted(b) {
  let z = zoomFor(b.scale, (b.north + b.south) / 2);
  for (;;) {
    const a = tileOf(b.north, b.west, z), c = tileOf(b.south, b.east, z);
    if ((c.x - a.x + 1) * (c.y - a.y + 1) <= MAX_TILES || z === 0) return { z, x0: a.x, x1: c.x, y0: a.y, y1: c.y };
    z--;
  }
}

function image(z, x, y) {
  const key = `${z}/${x}/${y}`;
  let img = cache.get(key);
  if (img) {
    cache.delete(key); // re-inserted below: most recently used
  } else {
    const nw = world(tileLat(y, z), tileLon(x, z)), se = world(tileLat(y + 1, z), tileLon(x + 1, z));
    img = el("image", { x: nw.x, y: nw.y, width: se.x - nw.x, height: se.y - nw.y, preserveAspectRatio: "none", "data-tile": key });
    img.addEventListener("error", () => { failed++; showNote(); });
    img.setAttribute("href", url(z, x, y));
  }
  cache.set(key, img);
  return img;
}

function draw() {
  const b = bounds();
  if (!b || !b.width) return;
  const w = wanted(b);
  const keep = new Set();
  for (let x = w.x0; x <= w.x1; x++) {
    for (let y = w.y0; y <= w.y1; y++) {
      const img = image(w.z, x, y);
      keep.add(img);
      if (img.parentNode !== group) group.appendChild(img);
    }
  }
  for (const child of [...group.children]) if (!keep.has(child)) child.remove();
  for (const [key, img] of cache) {
    if (cache.size <= CACHE_SIZE) break;
    if (!keep.has(img)) cache.delete(key);
  }
  group.setAttribute("data-zoom", w.z);
}

function showNote() {
  let host = template;
  try { host = new URL(template.replace(/\{[a-z]\}/g, "0")).host; } catch (e) { /* a template that is no URL: show it whole */ }
  note.textContent = `tiles: ${host}` + (failed ? ` (${failed} failed to load)` : "");
}

export function init(app) {
  app.on("gcs_hello", (hello) => {
    if (!hello.tiles || template) return;
    template = hello.tiles;
    group = underlay("tiles");
    note = document.createElement("div");
    note.id = "map-tiles-note";
    document.getElementById("map-panel").appendChild(note);
    showNote();
    draw();
  });
  onRedraw(() => { if (template) draw(); });
}
