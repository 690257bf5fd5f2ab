// Pod ground station: what the survey panel draws on the map, each in a layer of its own drawn in
// metres: the operator's polygon (its corners can be dragged), the planned path (a preview, dashed,
// until built), the forward pass's photos (a marker for each that detected something) and the
// backward route (the flagged waypoints in the order the flight revisits them; the ones measured
// already drawn solid). Marker sizes are in pixels, so they are redrawn after each zoom.
import * as map from "./map.js";

const CORNER_PX = 6;
const PHOTO_PX = 7;
const DOT_PX = 2.5;
const LABEL_PX = 11;

let drawn = { draft: null, path: null, preview: null, photos: [], backward: null };
let onCornerMoved = null;

/** Calls fn(index, {lat, lon}) when the operator drags corner `index` to a new place. */
export function onCornerDrag(fn) { onCornerMoved = fn; }

/** World metres of a position, as the map draws it. */
function xy(lat, lon) { return map.world(lat, lon); }

function px(n) { return n / map.pixelsPerMetre(); }

/** The map position under a pointer event, through the polygon layer's own transform. */
function eventPosition(event, layer) {
  const svg = layer.ownerSVGElement;
  const p = svg.createSVGPoint();
  p.x = event.clientX; p.y = event.clientY;
  const w = p.matrixTransform(layer.getScreenCTM().inverse());
  return map.position(w.x, w.y);
}

/** The operator's polygon: `corners` [[lat, lon]…]; `closed` draws its last edge. */
export function drawPolygon(corners, closed, editing) {
  drawn.draft = { corners, closed, editing };
  const g = map.layer("survey-polygon");
  g.replaceChildren();
  if (!corners.length) return;
  const points = corners.map(([lat, lon]) => xy(lat, lon)).map((p) => `${p.x.toFixed(1)},${p.y.toFixed(1)}`).join(" ");
  map.el(closed ? "polygon" : "polyline", { class: `survey-area${closed ? " closed" : ""}${editing ? " editing" : ""}`, points }, g);
  corners.forEach(([lat, lon], i) => {
    const p = xy(lat, lon);
    const c = map.el("circle", { class: "survey-corner", cx: p.x, cy: p.y, r: px(CORNER_PX), "data-index": i }, g);
    c.addEventListener("pointerdown", (event) => startDrag(event, i, g));
  });
}

function startDrag(event, index, layer) {
  event.stopPropagation();
  event.preventDefault();
  const move = (e) => {
    const p = eventPosition(e, layer);
    if (onCornerMoved) onCornerMoved(index, p, false);
  };
  const up = (e) => {
    window.removeEventListener("pointermove", move);
    window.removeEventListener("pointerup", up);
    const p = eventPosition(e, layer);
    if (onCornerMoved) onCornerMoved(index, p, true);
  };
  window.addEventListener("pointermove", move);
  window.addEventListener("pointerup", up);
}

/** A survey path: `waypoints` [{lat, lon, photo}…]; `kind` is "built" or "preview" (each its own layer). */
export function drawPath(kind, waypoints) {
  drawn[kind === "built" ? "path" : "preview"] = waypoints;
  const g = map.layer(`survey-${kind}`);
  g.replaceChildren();
  if (!waypoints || !waypoints.length) return;
  const pts = waypoints.map((w) => xy(w.lat, w.lon));
  map.el("polyline", { class: `survey-path ${kind}`, points: pts.map((p) => `${p.x.toFixed(1)},${p.y.toFixed(1)}`).join(" "), "data-waypoints": waypoints.length }, g);
  waypoints.forEach((w, i) => {
    if (!w.photo) return;
    map.el("circle", { class: `survey-waypoint ${kind}`, cx: pts[i].x, cy: pts[i].y, r: px(DOT_PX), "data-index": i }, g);
  });
}

/** The forward pass's photos: a marker for each that detected something, numbered by its waypoint. */
export function drawPhotos(photos) {
  drawn.photos = photos;
  const g = map.layer("survey-photos");
  g.replaceChildren();
  for (const photo of photos) {
    const p = xy(photo.lat, photo.lon);
    if (!photo.objects.length) {
      map.el("circle", { class: "survey-photo empty", cx: p.x, cy: p.y, r: px(DOT_PX), "data-waypoint": photo.waypoint }, g);
      continue;
    }
    const c = map.el("circle", {
      class: "survey-photo detected", cx: p.x, cy: p.y, r: px(PHOTO_PX),
      "data-waypoint": photo.waypoint, "data-objects": photo.objects.join(","),
    }, g);
    map.el("title", {}, c).textContent = `waypoint ${photo.waypoint}: object${photo.objects.length > 1 ? "s" : ""} ${photo.objects.join(", ")}`;
    const label = map.el("text", { class: "survey-photo-label", x: p.x + px(PHOTO_PX + 2), y: p.y - px(PHOTO_PX), "font-size": px(LABEL_PX) }, g);
    label.textContent = photo.objects.join(",");
  }
}

/**
 * The backward route over the built path's `waypoints`: `order` (the plan's indices, in flying
 * order) dashed, and the `measured` ones ({waypoint, range_m}) solid with their order number.
 */
export function drawBackward(waypoints, backward) {
  drawn.backward = { waypoints, backward };
  const g = map.layer("survey-backward");
  g.replaceChildren();
  if (!backward || !waypoints) return;
  const at = (i) => xy(waypoints[i].lat, waypoints[i].lon);
  const line = (indices, cls) => map.el("polyline", {
    class: cls, points: indices.map(at).map((p) => `${p.x.toFixed(1)},${p.y.toFixed(1)}`).join(" "), "data-waypoints": indices.join(","),
  }, g);
  line(backward.order, "survey-backward planned");
  line(backward.measured.map((m) => m.waypoint), "survey-backward flown");
  backward.order.forEach((w, n) => {
    const p = at(w);
    const done = backward.measured.find((m) => m.waypoint === w);
    const c = map.el("circle", { class: `survey-revisit${done ? " measured" : ""}`, cx: p.x, cy: p.y, r: px(PHOTO_PX + 3), "data-waypoint": w, "data-order": n }, g);
    map.el("title", {}, c).textContent = `backward ${n + 1}: waypoint ${w}${done && done.range_m != null ? `, range ${done.range_m.toFixed(1)} m` : ""}`;
    const label = map.el("text", { class: "survey-revisit-label", x: p.x - px(PHOTO_PX + 12), y: p.y + px(4), "font-size": px(LABEL_PX) }, g);
    label.textContent = String(n + 1);
  });
}

/** Redraws everything at the new zoom (marker sizes are in pixels). */
export function init() {
  map.onRedraw(() => {
    if (drawn.draft) drawPolygon(drawn.draft.corners, drawn.draft.closed, drawn.draft.editing);
    drawPath("built", drawn.path);
    drawPath("preview", drawn.preview);
    drawPhotos(drawn.photos);
    if (drawn.backward) drawBackward(drawn.backward.waypoints, drawn.backward.backward);
  });
}
