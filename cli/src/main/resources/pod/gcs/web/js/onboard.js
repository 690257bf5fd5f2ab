// Pod ground station: what each vehicle holds on board (the `on_board` events the plans panel asks
// for, and every upload refreshes), drawn on the map's "onboard" layer: the mission's waypoints
// numbered as a planner numbers them and joined in order, fence polygons and circles (inclusion
// green, exclusion red) and rally points. The selected vehicle's lists are drawn over the others.
//
// Shapes are drawn in metres; the markers (a numbered disc, an R, an H) keep their size on screen:
// each is scaled by 1 / pixels-per-metre after every zoom.
import { el, layer, world, onRedraw, pixelsPerMetre } from "./map.js";

const lists = new Map(); // sysid → the latest on_board event
let app = null;
let group = null;
const markers = []; // the <g> of each marker, to rescale on zoom

function pointsOf(coordinates) {
  return coordinates.map((w) => `${w.x.toFixed(1)},${w.y.toFixed(1)}`).join(" ");
}

/** A marker at (lat, lon): a disc with [text], of [kind] (waypoint, roi, rally, home). */
function marker(parent, lat, lon, text, kind, data) {
  const w = world(lat, lon);
  const g = el("g", { class: `marker ${kind}`, "data-lat": lat, "data-lon": lon, ...data }, parent);
  g.dataset.x = w.x;
  g.dataset.y = w.y;
  el("circle", { r: 8 }, g);
  el("text", { y: 3.5 }, g).textContent = text;
  markers.push(g);
  return g;
}

function drawVehicle(e) {
  const g = el("g", { class: "onboard-vehicle", "data-sysid": e.sysid }, group);
  g.classList.toggle("selected", app.selected === e.sysid);
  for (const p of e.polygons) {
    const corners = p.points.map(([lat, lon]) => world(lat, lon));
    el("polygon", { class: `fence ${p.inclusion ? "inclusion" : "exclusion"}`, points: pointsOf(corners) }, g);
  }
  for (const c of e.circles) {
    const w = world(c.lat, c.lon);
    el("circle", { class: `fence ${c.inclusion ? "inclusion" : "exclusion"}`, cx: w.x.toFixed(1), cy: w.y.toFixed(1), r: c.radius }, g);
  }
  // The path a planner draws: from home through each navigation item, in order.
  const path = e.mission.filter((i) => i.nav).map((i) => world(i.lat, i.lon));
  if (e.home && path.length > 0) path.unshift(world(e.home[0], e.home[1]));
  if (path.length > 1) el("polyline", { class: "mission-path", points: pointsOf(path) }, g);
  if (e.home) marker(g, e.home[0], e.home[1], "H", "home-item", {});
  for (const r of e.rally) marker(g, r.lat, r.lon, "R", "rally", {});
  for (const i of e.mission) marker(g, i.lat, i.lon, String(i.n), i.nav ? "waypoint" : "roi", { "data-n": i.n, "data-seq": i.seq, "data-command": i.command });
}

function resize() {
  const k = 1 / pixelsPerMetre();
  for (const g of markers) g.setAttribute("transform", `translate(${g.dataset.x} ${g.dataset.y}) scale(${k})`);
}

function draw() {
  group = group || layer("onboard");
  group.replaceChildren();
  markers.length = 0;
  const order = [...lists.values()].sort((a, b) => (a.sysid === app.selected) - (b.sysid === app.selected) || a.sysid - b.sysid);
  order.forEach(drawVehicle);
  resize();
}

/** Called by the plans panel once at start. */
export function init(appRef) {
  app = appRef;
  app.on("on_board", (e) => { lists.set(e.sysid, e); draw(); });
  app.onSelect(() => { if (lists.size > 0) draw(); });
  onRedraw(resize);
}
