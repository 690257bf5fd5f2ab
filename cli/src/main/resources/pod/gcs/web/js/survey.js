// Pod ground station: the survey panel, the I-Seed operator's app for the selected vehicle. Draw a
// polygon on the map (click its corners, close it; drag a corner to move it; clear), choose the
// height and the track spacing or a camera, and the planned path is shown at once (`survey_plan`);
// then build, start, pause, resume or abort (asked again in the page). The app's state (phase, pass,
// waypoint, event id) and the event ids of the commands and the flight's reports show live, the
// photos that detected something as markers, and the backward route as planned and flown.
//
// For tests and tools: `app.survey` = { surveys: Map sysid → {state, history (the states shown, in
// order), path, photos, backward, log (commands and reports)}, draft: {corners, closed},
// screenOf(lat, lon) → map pixels, centreOn(lat, lon, pixelsPerMetre) }.
import * as map from "./map.js";
import * as drawing from "./survey-map.js";

const LOG_MAX = 200;
const CAMERA_1_INCH = { sensor_width_mm: 13.2, sensor_height_mm: 8.8, focal_length_mm: 8.8, image_width: 5472, image_height: 3648 };

const surveys = new Map();
const draft = { corners: [], closed: false, drawing: false, built: false };
let app = null;
let ui = null;
let planSeq = 0;
let dirty = true; // the map drawings are redrawn only after something they show changed
let rendered = null; // the vehicle whose survey is drawn

function survey(sysid) {
  let s = surveys.get(sysid);
  if (!s) {
    s = { state: null, path: null, photos: [], run: 0, backward: null, log: [], logged: 0, history: [] };
    surveys.set(sysid, s);
  }
  return s;
}

function markup(panel) {
  const div = document.createElement("div");
  div.className = "survey";
  div.innerHTML = `
    <div class="survey-head"><span id="survey-vehicle">select a vehicle</span>
      <span id="survey-phase" class="survey-phase" data-phase="">–</span></div>
    <div class="survey-row">
      <button id="survey-draw" title="click the corners on the map">Draw</button>
      <button id="survey-close" disabled>Close</button>
      <button id="survey-undo" disabled>Undo corner</button>
      <button id="survey-clear" disabled>Clear</button>
      <span id="survey-corners" class="muted">no polygon</span></div>
    <div class="survey-row">
      <label>height <input id="survey-height" type="number" min="2" max="300" step="1" value="20"> m</label>
      <label>angle <input id="survey-angle" type="number" min="0" max="359" step="5" value="0">°</label>
      <select id="survey-kind"><option value="spacing">spacing</option><option value="camera">camera</option></select>
      <label id="survey-spacing-label">spacing <input id="survey-spacing" type="number" min="1" max="1000" step="1" value="20"> m</label></div>
    <div class="survey-row" id="survey-camera" hidden>
      <label>sensor <input id="survey-sw" type="number" step="0.1" value="13.2">×<input id="survey-sh" type="number" step="0.1" value="8.8"> mm</label>
      <label>focal <input id="survey-fl" type="number" step="0.1" value="8.8"> mm</label>
      <label>overlap <input id="survey-front" type="number" min="0" max="0.95" step="0.05" value="0.7"> /
        <input id="survey-side" type="number" min="0" max="0.95" step="0.05" value="0.6"></label></div>
    <div id="survey-summary" class="muted"></div>
    <div class="survey-row survey-actions">
      <button id="survey-build" disabled>Build</button>
      <button id="survey-cancel" disabled>Cancel path</button>
      <button id="survey-start" disabled>Start</button>
      <button id="survey-pause" disabled>Pause</button>
      <button id="survey-resume" disabled>Resume</button>
      <button id="survey-abort" class="danger" disabled>Abort</button></div>
    <div id="survey-confirm" class="survey-confirm" hidden>Abort the survey? The vehicle holds, then returns home.
      <button id="survey-abort-yes" class="danger">Abort</button> <button id="survey-abort-no">Keep flying</button></div>
    <div id="survey-error" class="bad"></div>
    <div class="survey-lists">
      <div><h3>Events</h3><ol id="survey-log"></ol></div>
      <div><h3>Detections</h3><ol id="survey-photos"></ol><div id="survey-backward" class="muted"></div></div></div>`;
  panel.appendChild(div);
  const $ = (id) => div.querySelector(`#${id}`);
  return new Proxy({}, { get: (_, id) => $(`survey-${id}`) });
}

/** What the operator chose, as `survey_plan` and `survey_build` take it. */
function area() {
  const a = { polygon: draft.corners.map(([lat, lon]) => ({ lat, lon })), height: Number(ui.height.value), track_angle: Number(ui.angle.value) };
  if (ui.kind.value === "camera") {
    a.camera = { ...CAMERA_1_INCH, sensor_width_mm: Number(ui.sw.value), sensor_height_mm: Number(ui.sh.value), focal_length_mm: Number(ui.fl.value),
      front_overlap: Number(ui.front.value), side_overlap: Number(ui.side.value) };
  } else {
    a.spacing = Number(ui.spacing.value);
  }
  return a;
}

function error(text) { ui.error.textContent = text || ""; }

/** Plans the closed polygon for the selected vehicle and shows the path before anything is built. */
async function preview() {
  if (!draft.closed || app.selected == null) { drawing.drawPath("preview", null); return; }
  const seq = ++planSeq;
  const reply = await app.request("survey_plan", { sysid: app.selected, area: area() });
  if (seq !== planSeq) return; // a later edit asked again
  if (!reply.ok) { error(reply.error); drawing.drawPath("preview", null); ui.summary.textContent = ""; return; }
  error("");
  const path = JSON.parse(reply.detail);
  draft.built = false;
  drawing.drawPath("preview", path.waypoints);
  ui.summary.textContent = summary(path, "planned");
  redraw();
}

function summary(path, what) {
  const photos = path.waypoints.filter((w) => w.photo).length;
  return `${what}: ${path.tracks} tracks ${path.spacing_m.toFixed(1)} m apart, ${photos} photos, ${path.length_m.toFixed(0)} m, ` +
    `${Math.round(path.area_m2)} m² at ${path.height_m} m`;
}

async function send(op, fields = {}) {
  if (app.selected == null) return;
  const reply = await app.request(op, { sysid: app.selected, ...fields });
  error(reply.ok ? "" : reply.error);
  if (op === "survey_build" && reply.ok) { draft.built = true; drawing.drawPath("preview", null); }
  redraw();
}

function phaseText(st) {
  if (!st) return "no survey";
  const where = st.pass ? ` · ${st.pass} pass${st.waypoint != null ? ` · waypoint ${st.waypoint}` : ""}` : "";
  const why = st.reason ? `: ${st.reason}` : "";
  return `${st.phase.replace("_", " ")}${where}${why} · event ${st.event_id}`;
}

function logLine(e) {
  if (e.event === "survey_command") return `#${e.event_id} ${e.command} ${e.accepted ? "accepted" : `refused: ${e.reason}`}`;
  const where = e.pass ? ` ${e.pass}${e.waypoint != null ? ` wp ${e.waypoint}` : ""}` : "";
  const extra = e.report === "vehicle" ? (e.ready ? " ready" : " not ready") : e.reason ? `: ${e.reason}` : "";
  return `#${e.event_id} report ${e.report}${where}${extra}${e.counted ? "" : " (older than the last command: not shown)"}`;
}

/** Shows the selected vehicle's survey: state, buttons, lists, and its drawings on the map. */
function render() {
  if (app.selected !== rendered) { rendered = app.selected; dirty = true; }
  const sysid = app.selected;
  ui.vehicle.textContent = sysid == null ? "select a vehicle (map or table)" : `vehicle ${sysid}`;
  const s = sysid == null ? null : surveys.get(sysid);
  const st = s && s.state;
  const phase = st ? st.phase : "";
  ui.phase.textContent = phaseText(st);
  ui.phase.dataset.phase = phase;
  ui.phase.dataset.eventId = st ? st.event_id : "";
  ui.corners.textContent = draft.corners.length ? `${draft.corners.length} corners${draft.closed ? ", closed" : draft.drawing ? ": click the next" : ""}` : "no polygon";
  ui.draw.disabled = draft.drawing;
  ui.draw.textContent = draft.corners.length ? "Redraw" : "Draw";
  ui.close.disabled = !(draft.drawing && draft.corners.length >= 3);
  ui.undo.disabled = !(draft.drawing && draft.corners.length);
  ui.clear.disabled = !draft.corners.length;
  const flying = phase === "executing" || phase === "paused";
  ui.build.disabled = sysid == null || !draft.closed || flying;
  ui.cancel.disabled = phase !== "path_built";
  ui.start.disabled = phase !== "path_built";
  ui.pause.disabled = phase !== "executing";
  ui.resume.disabled = phase !== "paused";
  ui.abort.disabled = !flying;
  if (!flying) ui.confirm.hidden = true;
  // Lists are rebuilt only when they change, so an element a reader holds stays in the page.
  const logKey = `${sysid}:${s ? s.logged : 0}`;
  if (ui.log.dataset.key !== logKey) {
    ui.log.dataset.key = logKey;
    ui.log.replaceChildren(...(s ? s.log : []).slice(-40).reverse().map((e) => {
      const li = document.createElement("li");
      li.textContent = logLine(e);
      li.dataset.kind = e.event === "survey_command" ? e.command : `report_${e.report}`;
      li.dataset.eventId = e.event_id;
      return li;
    }));
  }
  const detected = s ? s.photos.filter((p) => p.objects.length) : [];
  const photoKey = `${sysid}:${s ? s.run : 0}:${detected.length}`;
  if (ui.photos.dataset.key !== photoKey) {
    ui.photos.dataset.key = photoKey;
    ui.photos.replaceChildren(...detected.map((p) => {
      const li = document.createElement("li");
      li.textContent = `waypoint ${p.waypoint}: object${p.objects.length > 1 ? "s" : ""} ${p.objects.join(", ")}`;
      li.dataset.waypoint = p.waypoint;
      return li;
    }));
  }
  const b = s && s.backward;
  ui.backward.textContent = b ? `backward: ${b.order.join(" → ") || "nothing flagged"} (${b.measured.length} of ${b.order.length} measured)` : "";
  if (s && s.path && draft.built) ui.summary.textContent = summary(s.path, `built (event ${s.path.event_id})`);
  if (!dirty) return;
  dirty = false;
  drawing.drawPolygon(draft.corners, draft.closed, draft.drawing);
  drawing.drawPath("built", s && s.path ? s.path.waypoints : null);
  drawing.drawPhotos(s ? s.photos : []);
  drawing.drawBackward(s && s.path ? s.path.waypoints : null, b);
}

function redraw() { dirty = true; render(); }

function take(e) {
  const s = survey(e.sysid);
  if (e.event !== "survey_state" && e.event !== "survey_report" && e.event !== "survey_command") dirty = true;
  switch (e.event) {
    case "survey_state":
      if (e.run !== s.run) { s.run = e.run; s.photos = s.photos.filter((p) => p.run === e.run); }
      if (!s.state || ["phase", "pass", "waypoint", "event_id"].some((k) => s.state[k] !== e[k])) {
        s.history.push({ phase: e.phase, pass: e.pass, waypoint: e.waypoint, event_id: e.event_id });
        if (s.history.length > LOG_MAX) s.history.shift();
      }
      s.state = e;
      break;
    case "survey_path":
      s.path = e;
      if (e.sysid === app.selected && !draft.corners.length) {
        draft.corners = e.polygon.map((p) => [p.lat, p.lon]); draft.closed = true; draft.built = true;
      }
      break;
    case "survey_photo":
      if (e.run !== s.run) { s.run = e.run; s.photos = []; }
      s.photos.push(e);
      break;
    case "survey_backward": s.backward = e; break;
    case "survey_command":
    case "survey_report":
      s.log.push(e);
      s.logged++;
      if (s.log.length > LOG_MAX) s.log.shift();
      break;
  }
}

export function init(appRef) {
  app = appRef;
  ui = markup(document.getElementById("survey-panel"));
  drawing.init();
  for (const kind of ["survey_state", "survey_path", "survey_photo", "survey_backward", "survey_command", "survey_report"]) app.on(kind, take);
  app.afterBatch(render);
  app.onSelect(() => { draft.built = false; preview(); });
  app.survey = { surveys, draft, screenOf: (lat, lon) => map.screen(lat, lon), centreOn: map.centreOn };

  map.onClick(({ lat, lon }) => {
    if (!draft.drawing) return;
    draft.corners.push([lat, lon]);
    redraw();
  });
  drawing.onCornerDrag((i, p, done) => {
    draft.corners[i] = [p.lat, p.lon];
    redraw();
    if (done && draft.closed) preview();
  });
  ui.draw.onclick = () => { Object.assign(draft, { corners: [], closed: false, drawing: true, built: false }); preview(); redraw(); };
  ui.close.onclick = () => { draft.drawing = false; draft.closed = true; preview(); redraw(); };
  ui.undo.onclick = () => { draft.corners.pop(); redraw(); };
  ui.clear.onclick = () => { Object.assign(draft, { corners: [], closed: false, drawing: false, built: false }); error(""); ui.summary.textContent = ""; preview(); redraw(); };
  for (const input of [ui.height, ui.angle, ui.spacing, ui.sw, ui.sh, ui.fl, ui.front, ui.side]) input.addEventListener("change", preview);
  ui.kind.addEventListener("change", () => {
    ui.camera.hidden = ui.kind.value !== "camera";
    ui["spacing-label"].hidden = ui.kind.value === "camera";
    preview();
  });
  ui.build.onclick = () => send("survey_build", { area: area() });
  ui.cancel.onclick = () => send("survey_command", { command: "cancel_path" });
  ui.start.onclick = () => send("survey_command", { command: "start" });
  ui.pause.onclick = () => send("survey_command", { command: "pause" });
  ui.resume.onclick = () => send("survey_command", { command: "resume" });
  ui.abort.onclick = () => { ui.confirm.hidden = false; };
  ui["abort-no"].onclick = () => { ui.confirm.hidden = true; };
  ui["abort-yes"].onclick = () => { ui.confirm.hidden = true; send("survey_command", { command: "abort" }); };
  redraw();
}
