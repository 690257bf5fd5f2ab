// Pod ground station: one event of the log as a line an operator reads: {text, level, vehicles}.
// level is "bad" (failures, a lost vehicle, an autopilot's error), "warn" (warnings, cancellations,
// a hold not confirmed), "good" (done, regained) or "" ; vehicles are the system ids it concerns
// (for the "selected vehicle only" filter). Kinds it does not know are shown as their JSON.
import { severityClass } from "./fleet.js";

/** The vehicles of each task that started (id → [sysid]), so its end is filed under them too. */
const taskVehicles = new Map();
const TASKS_KEPT = 5000;

const list = (ids) => (ids && ids.length ? ids.join(", ") : "none");
const seconds = (ms) => `${(ms / 1000).toFixed(1)} s`;

function entry(e) {
  if (!e) return "–";
  const p = e.element && e.element.pattern;
  return `#${e.id} ${p ? p.type.replace("_", " ") : "?"}`;
}

function task(e) { return `task ${e.id} “${e.task}”`; }

function rememberTask(e) {
  taskVehicles.set(e.id, e.vehicles || []);
  if (taskVehicles.size > TASKS_KEPT) taskVehicles.delete(taskVehicles.keys().next().value);
}

function mission(e) {
  switch (e.what) {
    case "uploaded": return `mission uploaded (${e.steps} steps)`;
    case "prepared": return `mission prepared${e.changes && e.changes.length ? `: ${e.changes.join("; ")}` : ""}`;
    case "step_done": return `mission step ${e.step} done`;
    case "loitering": return `mission loitering at step ${e.step}`;
    default: return `mission ${e.what.replace("_", " ")}`;
  }
}

const FORMATS = {
  found: (e) => ({ text: `found: ${e.type.toLowerCase()} ${e.autopilot.toLowerCase()}`, vehicles: [e.sysid] }),
  lost: (e) => ({ text: `LOST${e.silence_ms ? ` (silent ${seconds(e.silence_ms)})` : ""}: last position kept on the map`, level: "bad", vehicles: [e.sysid] }),
  regained: (e) => ({ text: "regained: heard again", level: "good", vehicles: [e.sysid] }),
  vehicle_text: (e) => ({ text: `says [${e.severity}] ${e.text}`, level: severityClass(e.severity), vehicles: [e.sysid] }),
  task_started: (e) => { rememberTask(e); return { text: `${task(e)} started with vehicles ${list(e.vehicles)}`, vehicles: e.vehicles }; },
  task_done: (e) => ({ text: `${task(e)} done`, level: "good", vehicles: taskVehicles.get(e.id) }),
  task_failed: (e) => ({ text: `${task(e)} FAILED: ${e.error}`, level: "bad", vehicles: taskVehicles.get(e.id) }),
  task_cancelled: (e) => ({ text: `${task(e)} cancelled`, level: "warn", vehicles: taskVehicles.get(e.id) }),
  flying: (e) => ({ text: `flies “${e.mission}” (${e.steps} steps) for task ${e.task}`, vehicles: [e.vehicle] }),
  mission: (e) => ({ text: mission(e), level: e.what === "completed" ? "good" : "", vehicles: [e.vehicle] }),
  made_safe: (e) => ({ text: `made safe: ${e.state.toLowerCase()}${e.confirmed ? "" : " (not confirmed)"}`, level: "warn", vehicles: [e.vehicle] }),
  picked: (e) => ({ text: `picked vehicles ${list(e.vehicles)}`, vehicles: e.vehicles }),
  released: (e) => ({ text: `released vehicles ${list(e.vehicles)}`, vehicles: e.vehicles }),
  message: (e) => ({ text: e.text }),
  warning: (e) => ({ text: e.message, level: "warn" }),
  error: (e) => ({ text: e.message, level: "bad" }),
  queue_serving: (e) => ({ text: `queue served (mode ${e.mode || "?"})`, vehicles: [e.sysid] }),
  queue_started: (e) => ({ text: `queue: ${entry(e.entry)} started`, vehicles: [e.sysid] }),
  queue_ended: (e) => ({ text: `queue: ${entry(e.entry)} ended (${e.reason})`, level: e.reason === "cleared" || e.reason === "replaced" ? "warn" : "", vehicles: [e.sysid] }),
  queue_emptied: (e) => ({ text: "queue empty: holding", vehicles: [e.sysid] }),
  queue_done: (e) => ({ text: `queue ${e.action}${e.entry ? `: ${entry(e.entry)}` : ""}`, vehicles: [e.sysid] }),
  // What the pages did (every page sees every operator's actions) and what came of it.
  page_action: (e) => ({
    text: `page: ${e.action}: ${e.outcome}${e.detail ? ` (${e.detail})` : ""}`,
    level: e.outcome === "failed" ? "bad" : e.outcome === "ok" ? "good" : "",
    vehicles: [e.sysid],
  }),
  plan_transfer: (e) => ({
    text: `plan ${e.action} ${e.file}: ${e.ok ? `ok (${Object.entries(e.items || {}).map(([k, n]) => `${n} ${k}`).join(", ") || "nothing"})` : `FAILED: ${e.error}`}`,
    level: e.ok ? "good" : "bad",
    vehicles: [e.sysid],
  }),
  survey_command: (e) => ({
    text: `survey: operator ${e.command} (event ${e.event_id})${e.accepted ? "" : ` refused: ${e.reason}`}`,
    level: e.accepted ? "" : "warn",
    vehicles: [e.sysid],
  }),
  survey_report: (e) => ({
    text: `survey: vehicle reports ${e.report}${e.pass ? ` ${e.pass} pass` : ""}${e.waypoint != null ? `, waypoint ${e.waypoint}` : ""}${e.reason ? `: ${e.reason}` : ""} (event ${e.event_id}${e.counted ? "" : ", older than the last command: ignored"})`,
    level: e.report === "aborted" ? "bad" : e.report === "finished" ? "good" : "",
    vehicles: [e.sysid],
  }),
  survey_photo: (e) => ({
    text: `survey photo at waypoint ${e.waypoint}${e.taken ? "" : " NOT taken"}${e.objects.length ? `: detected ${list(e.objects)}` : ""}`,
    level: e.taken ? "" : "warn",
    vehicles: [e.sysid],
  }),
};

/** Kinds that are states (the latest replaces the last), not happenings: never a log line. */
const STATES = new Set([
  "telemetry", "home", "radio", "reply", "gcs_hello", "gcs_batch",
  // The panels' own states: the queue's flight, a plan transfer's progress, what is on board, a survey's path and backward route.
  "queue_flight", "plan_progress", "on_board", "survey_path", "survey_backward",
]);

/** Whether an event of `kind` is a state rather than a happening: the kinds above and any `…_status` or `…_state` (a panel's own). */
export function notLogged(kind) {
  return STATES.has(kind) || kind.endsWith("_status") || kind.endsWith("_state");
}

/** The first system id an unknown event names (sysid, vehicle, vehicles), for the filter. */
function vehiclesOf(e) {
  if (Number.isInteger(e.sysid)) return [e.sysid];
  if (Number.isInteger(e.vehicle)) return [e.vehicle];
  return Array.isArray(e.vehicles) ? e.vehicles : [];
}

/** The line for event e: {kind, text, level, vehicles}. */
export function format(e) {
  const known = FORMATS[e.event];
  if (known) {
    const line = known(e);
    return { kind: e.event, text: line.text, level: line.level || "", vehicles: line.vehicles || [] };
  }
  const { event, ...rest } = e;
  const text = `${event.replace(/_/g, " ")}: ${JSON.stringify(rest)}`;
  const level = /fail|error|abort/.test(event) ? "bad" : /warn|cancel|paus/.test(event) ? "warn" : "";
  return { kind: event, text: text.length > 300 ? `${text.slice(0, 299)}…` : text, level, vehicles: vehiclesOf(e) };
}
