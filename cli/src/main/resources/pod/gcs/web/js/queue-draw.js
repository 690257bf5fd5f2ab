// Pod ground station: mission-queue entries in words and on the map. Entries are `pod queue`'s JSON
// (EntryJson: {id, element: {pattern, duration_s, alt_m}}); points are global (lat/lon) or local
// (metres north and east of the vehicle's home).
import * as map from "./map.js";

/** "#3 circle r 30 m clockwise at 20 m for 60 s": an entry for people, as `pod queue` prints it. */
export function describe(entry) {
  const e = entry.element;
  let text = `#${entry.id} ${pattern(e.pattern)}`;
  if (e.alt_m != null) text += ` at ${round(e.alt_m)} m`;
  if (e.duration_s != null) text += ` for ${round(e.duration_s)} s`;
  return text;
}

function pattern(p) {
  switch (p.type) {
    case "goto": return `goto ${where(p.point)}`;
    case "circle": return `circle ${where(p.center)} r ${round(Math.abs(p.radius))} m ${p.radius > 0 ? "clockwise" : "counter-clockwise"}`;
    case "segment": return `segment ${where(p.from)} → ${where(p.to)}`;
    case "path": return `path of ${p.points.length} point${p.points.length === 1 ? "" : "s"}`;
    case "survey": return `survey ${round(p.length)} × ${round(p.width)} m`;
    case "return_home": return "return home";
    default: return p.type;
  }
}

function where(pt) {
  return pt.type === "local" ? `(${round(pt.north)} N, ${round(pt.east)} E)` : `(${pt.lat.toFixed(5)}, ${pt.lon.toFixed(5)})`;
}

function round(x) { return Math.abs(x - Math.round(x)) < 0.05 ? String(Math.round(x)) : x.toFixed(1); }

/** World metres of a point for vehicle [v] (its home for local points), or null when it cannot be placed yet. */
function worldOf(v, pt) {
  if (pt.type === "global") return map.world(pt.lat, pt.lon);
  if (!v || !v.home) return null;
  const home = map.world(v.home.lat, v.home.lon);
  return { x: home.x + pt.east, y: home.y - pt.north };
}

/**
 * Draws every vehicle's queue in the map's "queue" layer: the current element solid, the pending
 * ones dashed; the selected vehicle's in full colour, the others faded.
 */
export function drawQueue(app, statuses) {
  const g = map.layer("queue");
  g.replaceChildren();
  for (const [sysid, s] of statuses) {
    const v = app.vehicles.get(sysid);
    const group = map.el("g", { "data-sysid": sysid, class: sysid === app.selected ? "mine" : "other" }, g);
    if (s.current) drawEntry(group, v, s.current, "current");
    s.pending.forEach((e) => drawEntry(group, v, e, "pending"));
  }
}

function drawEntry(group, v, entry, state) {
  const p = entry.element.pattern;
  const attrs = (cls) => ({ class: `element ${cls} ${state}`, "data-entry": entry.id });
  const dot = 4 / map.pixelsPerMetre();
  const spot = (w) => map.el("circle", { ...attrs("point"), cx: w.x, cy: w.y, r: dot }, group);
  if (p.type === "goto") {
    const w = worldOf(v, p.point);
    if (w) spot(w);
  } else if (p.type === "circle") {
    const c = worldOf(v, p.center);
    if (!c) return;
    map.el("circle", { ...attrs("circle"), cx: c.x, cy: c.y, r: Math.abs(p.radius) }, group);
    spot(c);
  } else if (p.type === "path" || p.type === "segment") {
    const pts = (p.type === "path" ? p.points : [p.from, p.to]).map((pt) => worldOf(v, pt)).filter((w) => w);
    if (!pts.length) return;
    map.el("polyline", { ...attrs("path"), points: pts.map((w) => `${w.x},${w.y}`).join(" ") }, group);
    pts.forEach(spot);
  }
}
