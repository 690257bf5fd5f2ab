// Pod ground station: the commands panel. Buttons act on the selected vehicle through the server's
// vehicle_* requests (Pod's VehicleActions); each shows the vehicle's answer beside it: ok, or the
// refusal with the autopilot's reason. A button is disabled while its answer is awaited. The
// destructive ones (disarm, take off, land, RTL) ask again in place: the first click turns the
// button into "confirm …?" for a few seconds, the second sends it. "Go to" waits for a click on
// the map. Answers are kept per vehicle, so switching vehicles shows each one's own.
import * as map from "./map.js";
import { h, text } from "./dom.js";

const CONFIRM_MS = 4000;
const TOOL = "commands:goto";
const EMPTY = "Select a vehicle in the fleet table or on the map.";

/** { name, label, op, confirm } in the order they appear, two to a row (the mode row is whole). */
const COMMANDS = [
  { name: "arm", label: "Arm", op: "vehicle_arm" },
  { name: "disarm", label: "Disarm", op: "vehicle_disarm", confirm: "disarm" },
  { name: "takeoff", label: "Take off", op: "vehicle_takeoff", confirm: "take off" },
  { name: "land", label: "Land", op: "vehicle_land", confirm: "land" },
  { name: "goto", label: "Go to", op: "vehicle_goto" },
  { name: "rtl", label: "RTL", op: "vehicle_rtl", confirm: "return to launch" },
  { name: "pause", label: "Pause", op: "vehicle_pause" },
  { name: "resume", label: "Resume", op: "vehicle_resume" },
  { name: "mode", label: "Set mode", op: "vehicle_mode" },
];

let app = null;
const ui = {}; // name → { button, answer, input? }
const answers = new Map(); // sysid → Map(name → { text, cls })
const waiting = new Set(); // `${sysid}:${name}` awaiting the vehicle's answer
const modes = new Map(); // sysid → [names]
let header = null;
let confirming = null; // { name, timer }
let gotoArmed = false;
let gotoMarker = null;

function build(section) {
  header = h("div", { class: "cmd-target" }, section);
  const grid = h("div", { class: "cmd-grid" }, section);
  for (const c of COMMANDS) {
    const cell = h("div", { class: "cmd", "data-command": c.name }, grid);
    const button = h("button", { type: "button", "data-command": c.name }, cell, c.label);
    const entry = { button, answer: null };
    if (c.name === "takeoff" || c.name === "goto") {
      h("span", { class: "cmd-unit" }, cell, c.name === "takeoff" ? "to" : "at");
      entry.input = h("input", { type: "number", min: "1", max: "10000", step: "1", "data-field": `${c.name}-alt`, "aria-label": `${c.label} altitude above home, m` }, cell);
      entry.input.value = c.name === "takeoff" ? "20" : "";
      entry.input.addEventListener("input", () => { entry.input.dataset.edited = "1"; });
      h("span", { class: "cmd-unit" }, cell, "m");
    }
    if (c.name === "mode") {
      entry.input = h("select", { "data-field": "mode", "aria-label": "flight mode" }, cell);
      entry.input.addEventListener("change", () => { entry.input.dataset.edited = "1"; });
      cell.insertBefore(entry.input, button);
    }
    entry.answer = h("div", { class: "answer", "data-answer": c.name }, cell);
    button.addEventListener("click", () => clicked(c));
    ui[c.name] = entry;
  }
}

function clicked(c) {
  const sysid = app.selected;
  if (sysid == null) return;
  if (c.name === "goto") { toggleGoto(); return; }
  if (c.confirm && !(confirming && confirming.name === c.name)) { askConfirm(c); return; }
  endConfirm();
  const fields = fieldsOf(c);
  if (fields === null) return;
  send(sysid, c, fields);
}

/** The request's fields beyond sysid, or null (with the reason shown) when an input is not valid. */
function fieldsOf(c) {
  if (c.name === "takeoff") {
    const alt = Number(ui.takeoff.input.value);
    if (!(alt > 0 && alt <= 10000)) { show(app.selected, c.name, "give an altitude above 0 m and at most 10000 m", "bad"); return null; }
    return { alt_m: alt };
  }
  if (c.name === "mode") {
    const mode = ui.mode.input.value;
    if (!mode) { show(app.selected, c.name, "choose a mode", "bad"); return null; }
    return { mode };
  }
  return {};
}

function askConfirm(c) {
  endConfirm();
  ui[c.name].button.textContent = `confirm ${c.confirm}?`;
  ui[c.name].button.classList.add("confirming");
  confirming = { name: c.name, timer: setTimeout(endConfirm, CONFIRM_MS) };
}

function endConfirm() {
  if (!confirming) return;
  clearTimeout(confirming.timer);
  const c = COMMANDS.find((x) => x.name === confirming.name);
  ui[c.name].button.textContent = c.label;
  ui[c.name].button.classList.remove("confirming");
  confirming = null;
}

async function send(sysid, c, fields) {
  const key = `${sysid}:${c.name}`;
  waiting.add(key);
  show(sysid, c.name, "waiting for the vehicle…", "waiting");
  refresh();
  const reply = await app.request(c.op, { sysid, ...fields });
  waiting.delete(key);
  if (reply.ok) show(sysid, c.name, `ok${reply.detail ? `: ${reply.detail}` : ""}`, "good");
  else show(sysid, c.name, `refused: ${reply.error}`, "bad");
  if (c.name === "mode") ui.mode.input.dataset.edited = "";
  refresh();
  return reply;
}

function show(sysid, name, words, cls) {
  if (!answers.has(sysid)) answers.set(sysid, new Map());
  answers.get(sysid).set(name, { text: words, cls });
  refresh();
}

function toggleGoto() {
  if (gotoArmed) { cancelGoto(); return; }
  const v = app.vehicles.get(app.selected);
  const alt = v && v.telemetry && v.telemetry.alt_rel;
  if (!ui.goto.input.dataset.edited && alt != null) ui.goto.input.value = String(Math.max(1, Math.round(alt)));
  gotoArmed = true;
  ui.goto.button.textContent = "click the map…";
  ui.goto.button.classList.add("active");
  window.dispatchEvent(new CustomEvent("pod-tool", { detail: TOOL }));
}

function cancelGoto() {
  gotoArmed = false;
  ui.goto.button.textContent = "Go to";
  ui.goto.button.classList.remove("active");
}

function mapClicked({ lat, lon }) {
  if (!gotoArmed || app.selected == null) return;
  cancelGoto();
  const alt = Number(ui.goto.input.value);
  if (!(alt > 0 && alt <= 10000)) { show(app.selected, "goto", "give an altitude above 0 m and at most 10000 m", "bad"); return; }
  drawTarget(lat, lon);
  send(app.selected, COMMANDS.find((c) => c.name === "goto"), { lat, lon, alt_m: alt });
}

/** A cross where the last goto was sent, in world metres (it pans and zooms with the map). */
function drawTarget(lat, lon) {
  const g = map.layer("goto");
  if (!gotoMarker) gotoMarker = map.el("path", { class: "goto-target" }, g);
  gotoMarker.dataset.lat = lat;
  gotoMarker.dataset.lon = lon;
  sizeTarget();
}

function sizeTarget() {
  if (!gotoMarker) return;
  const w = map.world(Number(gotoMarker.dataset.lat), Number(gotoMarker.dataset.lon));
  const s = 7 / map.pixelsPerMetre();
  gotoMarker.setAttribute("d", `M${w.x - s},${w.y - s}L${w.x + s},${w.y + s}M${w.x - s},${w.y + s}L${w.x + s},${w.y - s}`);
}

async function loadModes(sysid) {
  if (sysid == null || modes.has(sysid)) { fillModes(); return; }
  const reply = await app.request("vehicle_modes", { sysid });
  if (reply.ok) { modes.set(sysid, JSON.parse(reply.detail)); fillModes(); }
}

/** Fills the mode choice with the selected vehicle's modes; it shows the current mode until the operator picks one. */
function fillModes() {
  const select = ui.mode.input;
  const names = modes.get(app.selected) || [];
  if (select.dataset.sysid !== String(app.selected) || select.options.length !== names.length) {
    select.replaceChildren(...names.map((n) => h("option", { value: n }, null, n)));
    select.dataset.sysid = String(app.selected);
  }
  const v = app.vehicles.get(app.selected);
  const current = v && v.telemetry && v.telemetry.mode;
  if (!select.dataset.edited && current && names.includes(current) && select.value !== current) select.value = current;
}

/** Redraws the panel for the selected vehicle: its name and state, the buttons' states, its answers. */
function refresh() {
  const sysid = app.selected;
  const v = sysid == null ? null : app.vehicles.get(sysid);
  if (!v) {
    text(header, EMPTY);
  } else {
    const t = v.telemetry || {};
    const alt = t.alt_rel == null ? "–" : `${t.alt_rel.toFixed(1)} m`;
    const line = `Vehicle ${sysid}${v.lost ? " (LOST)" : ""}: ${t.mode || "?"}, ${t.armed ? "armed" : "disarmed"}, ${alt}`;
    text(header, line);
  }
  const mine = answers.get(sysid) || new Map();
  for (const c of COMMANDS) {
    const { button, answer } = ui[c.name];
    button.disabled = !v || waiting.has(`${sysid}:${c.name}`);
    const a = mine.get(c.name);
    text(answer, a ? a.text : "");
    answer.className = `answer ${a ? a.cls : ""}`;
  }
}

/** Called once at start with the page's app (see app.js). */
export function init(appRef) {
  app = appRef;
  build(document.getElementById("commands-panel"));
  app.onSelect((sysid) => {
    endConfirm(); cancelGoto();
    ui.goto.input.dataset.edited = ""; ui.mode.input.dataset.edited = "";
    loadModes(sysid); refresh();
  });
  app.afterBatch(() => { refresh(); fillModes(); });
  map.onClick(mapClicked);
  map.onRedraw(sizeTarget);
  window.addEventListener("pod-tool", (e) => { if (e.detail !== TOOL) cancelGoto(); });
  refresh();
}
