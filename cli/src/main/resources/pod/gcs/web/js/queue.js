// Pod ground station: the mission-queue panel for the selected vehicle. Elements are added by
// clicking the map: a goto (one click), a circle (press on the centre, drag out the radius,
// release; direction and optional turns or duration from the fields) or a path (clicks, then
// Finish), at the height in the altitude field (blank: keep the vehicle's), inserted as the
// "insert" choice says. The server flies the queue (queue_* requests); its status comes back
// live as queue_status and queue_flight events and is listed here and drawn on the map (layer
// "queue": the current element solid, the pending ones dashed).
import * as map from "./map.js";
import { h, text } from "./dom.js";
import { describe, drawQueue } from "./queue-draw.js";

const MODES = [["append", "append"], ["prepend", "prepend"], ["replace_current", "replace current"], ["replace_all", "replace all"]];
const HINTS = {
  goto: "click the map where to go",
  circle: "press on the centre and drag out the radius",
  path: "click the points in order, then Finish",
};

let app = null;
const f = {}; // the panel's controls by name
const statuses = new Map(); // sysid → queue_status event
const flights = new Map(); // sysid → queue_flight event
let tool = null; // "goto" | "circle" | "path" | null
let draft = null; // circle: {centre:{x,y}, radius}; path: [{lat, lon}]
let dragging = false;
let drawnFor = null; // the selection the queue layer was last drawn for

function build(section) {
  f.target = h("div", { class: "queue-target" }, section);
  f.name = h("span", {}, f.target);
  f.flight = h("span", { class: "flight" }, f.target);
  const insert = h("div", { class: "queue-row" }, section);
  h("span", { class: "muted" }, insert, "insert");
  f.mode = h("select", { "data-field": "queue-mode", "aria-label": "where to insert" }, insert);
  for (const [value, label] of MODES) h("option", { value }, f.mode, label);
  h("span", { class: "muted" }, insert, "at");
  f.alt = h("input", { type: "number", min: "1", max: "10000", step: "1", placeholder: "keep", "data-field": "queue-alt", "aria-label": "altitude above home, m" }, insert);
  h("span", { class: "muted" }, insert, "m");
  const tools = h("div", { class: "queue-row" }, section);
  for (const name of ["goto", "circle", "path"]) {
    f[name] = h("button", { type: "button", "data-queue-tool": name }, tools, { goto: "Go to", circle: "Circle", path: "Path" }[name]);
    f[name].addEventListener("click", () => (tool === name ? stopTool() : startTool(name)));
  }
  f.finish = h("button", { type: "button", "data-queue": "finish" }, tools, "Finish path");
  f.finish.addEventListener("click", finishPath);
  const circle = h("div", { class: "queue-row" }, section);
  h("span", { class: "muted" }, circle, "circle");
  f.direction = h("select", { "data-field": "queue-direction", "aria-label": "circle direction" }, circle);
  h("option", { value: "cw" }, f.direction, "clockwise");
  h("option", { value: "ccw" }, f.direction, "counter-clockwise");
  f.turns = h("input", { type: "number", min: "0", step: "0.5", placeholder: "turns", "data-field": "queue-turns", "aria-label": "turns" }, circle);
  h("span", { class: "muted" }, circle, "or");
  f.duration = h("input", { type: "number", min: "0", step: "1", placeholder: "time", "data-field": "queue-duration", "aria-label": "duration, s" }, circle);
  h("span", { class: "muted" }, circle, "s");
  f.hint = h("div", { class: "queue-hint" }, section);
  const actions = h("div", { class: "queue-row" }, section);
  f.next = h("button", { type: "button", "data-queue": "next" }, actions, "Next");
  f.clear = h("button", { type: "button", "data-queue": "clear" }, actions, "Clear");
  f.next.addEventListener("click", () => act("queue_next", {}));
  f.clear.addEventListener("click", () => act("queue_clear", {}));
  f.answer = h("div", { class: "answer", "data-answer": "queue" }, section);
  f.status = h("div", { class: "queue-status" }, section);
  f.current = h("div", { class: "current" }, f.status);
  f.then = h("div", { class: "muted" }, f.status, "then:");
  f.pending = h("ol", { class: "pending" }, f.status);
}

function startTool(name) {
  stopTool();
  if (app.selected == null) { answer("select a vehicle first", "bad"); return; }
  tool = name;
  draft = name === "path" ? [] : null;
  f[name].classList.add("active");
  f.hint.textContent = HINTS[name];
  window.dispatchEvent(new CustomEvent("pod-tool", { detail: `queue:${name}` }));
  refresh();
}

function stopTool() {
  if (tool) f[tool].classList.remove("active");
  tool = null; draft = null; dragging = false;
  f.hint.textContent = "";
  map.layer("queue-draft").replaceChildren();
  refresh();
}

/** The element's common part: altitude and duration from the fields. */
function element(pattern) {
  const e = { pattern };
  const alt = f.alt.value.trim();
  if (alt !== "") e.alt_m = Number(alt);
  return e;
}

async function insert(pattern, extra = {}) {
  const sysid = app.selected;
  const e = element(pattern);
  if (extra.duration_s != null) e.duration_s = extra.duration_s;
  const fields = { sysid, mode: f.mode.value, element: e };
  if (extra.turns != null) fields.turns = extra.turns;
  return act("queue_insert", fields, sysid);
}

async function act(op, fields, sysid = app.selected) {
  if (sysid == null) { answer("select a vehicle first", "bad"); return null; }
  const buttons = [f.next, f.clear, f.finish];
  buttons.forEach((b) => { b.disabled = true; });
  answer("waiting…", "waiting");
  const reply = await app.request(op, { sysid, ...fields });
  buttons.forEach((b) => { b.disabled = false; });
  const ended = op === "queue_next" && reply.detail && reply.detail.startsWith("{") ? "ended " : "";
  if (reply.ok) answer(`ok${reply.detail ? `: ${ended}${summary(reply.detail)}` : ""}`, "good");
  else answer(`refused: ${reply.error}`, "bad");
  return reply;
}

/** A reply's detail for people: an entry's description when it is one. */
function summary(detail) {
  try { const entry = JSON.parse(detail); return entry && entry.element ? describe(entry) : detail; } catch { return detail; }
}

function answer(text, cls) {
  f.answer.textContent = text;
  f.answer.className = `answer ${cls}`;
}

function point(lat, lon) { return { type: "global", lat, lon }; }

function mapClicked({ lat, lon }) {
  if (tool === "goto") {
    stopTool();
    insert({ type: "goto", point: point(lat, lon) });
  } else if (tool === "path") {
    draft.push({ lat, lon });
    drawDraft();
    f.hint.textContent = `${draft.length} point${draft.length === 1 ? "" : "s"}: click more, then Finish`;
  }
}

function finishPath() {
  if (tool !== "path" || !draft || draft.length === 0) { answer("draw a path first: press Path, then click its points", "bad"); return; }
  const points = draft.map((p) => point(p.lat, p.lon));
  stopTool();
  insert({ type: "path", points });
}

/** World metres under a pointer event, from the map's own projection (the origin's screen position and the scale). */
function worldAt(event) {
  const r = document.getElementById("map").getBoundingClientRect();
  const o = map.position(0, 0);
  const s = map.screen(o.lat, o.lon);
  const k = map.pixelsPerMetre();
  return { x: (event.clientX - r.left - s.x) / k, y: (event.clientY - r.top - s.y) / k };
}

// The circle is drawn by pressing and dragging, which the map would take as a pan: while the circle
// tool is on, the panel takes the pointer first (capture on the map's section) and keeps it.
function pointer(event) {
  if (tool !== "circle" || event.button > 0) return;
  event.stopPropagation();
  event.preventDefault();
  if (event.type === "pointerdown") {
    dragging = true;
    draft = { centre: worldAt(event), radius: 0 };
  } else if (event.type === "pointermove" && dragging) {
    const w = worldAt(event);
    draft.radius = Math.hypot(w.x - draft.centre.x, w.y - draft.centre.y);
    f.hint.textContent = `radius ${draft.radius.toFixed(0)} m: release to add`;
  } else if (event.type === "pointerup" && dragging) {
    dragging = false;
    finishCircle();
  }
  drawDraft();
}

function finishCircle() {
  const { centre, radius } = draft;
  if (!(radius >= 1)) { f.hint.textContent = "drag out a radius of at least 1 m"; draft = null; return; }
  const turns = f.turns.value.trim() === "" ? null : Number(f.turns.value);
  const duration = f.duration.value.trim() === "" ? null : Number(f.duration.value);
  const c = map.position(centre.x, centre.y);
  const signed = Math.round(radius) * (f.direction.value === "ccw" ? -1 : 1);
  stopTool();
  insert({ type: "circle", center: point(c.lat, c.lon), radius: signed }, { turns, duration_s: duration });
}

function drawDraft() {
  const g = map.layer("queue-draft");
  g.replaceChildren();
  if (tool === "circle" && draft) {
    map.el("circle", { cx: draft.centre.x, cy: draft.centre.y, r: Math.max(draft.radius, 0.1) }, g);
  } else if (tool === "path" && draft && draft.length) {
    const pts = draft.map((p) => map.world(p.lat, p.lon));
    map.el("polyline", { points: pts.map((p) => `${p.x},${p.y}`).join(" ") }, g);
    const r = 4 / map.pixelsPerMetre();
    pts.forEach((p) => map.el("circle", { class: "point", cx: p.x, cy: p.y, r }, g));
  }
}

function refresh() {
  const sysid = app.selected;
  const v = sysid == null ? null : app.vehicles.get(sysid);
  const fl = flights.get(sysid);
  text(f.name, v ? `Vehicle ${sysid}` : "Select a vehicle in the fleet table or on the map.");
  const state = !v ? "" : fl && fl.flying ? "flying" : (fl && fl.error ? "error" : "idle");
  f.flight.dataset.queueFlight = state;
  text(f.flight, { "": "", flying: "flying its queue", error: `flight ended: ${fl && fl.error}`, idle: "queue not flown" }[state]);
  f.flight.className = `flight ${{ flying: "good", error: "bad", idle: "muted" }[state] || ""}`;
  for (const b of [f.goto, f.circle, f.path, f.next, f.clear]) b.disabled = !v && b !== f[tool];
  f.finish.hidden = tool !== "path";
  const s = v ? statuses.get(sysid) : null;
  f.status.hidden = !v;
  f.current.dataset.queueCurrent = s && s.current ? s.current.id : "";
  text(f.current, s && s.current
    ? `now: ${describe(s.current)}${s.remaining_s == null ? "" : `, ${Math.ceil(s.remaining_s)} s left`}`
    : "now: nothing (the queue is empty)");
  const pending = s ? s.pending : [];
  const key = pending.map((e) => e.id).join(",");
  f.then.hidden = pending.length === 0;
  if (f.pending.dataset.key !== key) {
    f.pending.dataset.key = key;
    f.pending.replaceChildren(...pending.map((e) => h("li", { "data-queue-entry": e.id }, null, describe(e))));
  }
}

/** Called once at start with the page's app (see app.js). */
export function init(appRef) {
  app = appRef;
  build(document.getElementById("queue-panel"));
  let changed = false;
  app.on("queue_status", (e) => { statuses.set(e.sysid, e); changed = true; });
  app.on("queue_flight", (e) => { flights.set(e.sysid, e); });
  app.onSelect(() => { stopTool(); f.answer.textContent = ""; });
  app.afterBatch(() => {
    refresh();
    if (changed || app.selected !== drawnFor) { drawQueue(app, statuses); changed = false; drawnFor = app.selected; }
  });
  map.onClick(mapClicked);
  map.onRedraw(() => { drawQueue(app, statuses); drawDraft(); });
  const panel = document.getElementById("map-panel");
  for (const type of ["pointerdown", "pointermove", "pointerup"]) panel.addEventListener(type, pointer, { capture: true });
  window.addEventListener("pod-tool", (e) => { if (tool && e.detail !== `queue:${tool}`) stopTool(); });
  refresh();
}
