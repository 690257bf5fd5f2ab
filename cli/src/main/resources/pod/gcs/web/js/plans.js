// Pod ground station: the plans panel. A QGC .plan or QGC WPL 110 file dropped on the map or on
// this panel (or chosen with the file input) goes to the selected vehicle: mission, fence and rally
// lists, with the transfer's progress and its outcome shown here (an error names the file). "Show on
// board" draws what the vehicle holds (onboard.js); "download plan" saves it as a .plan file.
import * as onboard from "./onboard.js";

// The server reads at most 2 MiB of text (PlanFile.MAX_CHARS): escaped into the request it stays within
// the WebSocket's 4 MiB frame. A real plan is a few hundred KiB.
const MAX_BYTES = 2 * 1024 * 1024;
const PLAN_FILE = /\.(plan|waypoints|txt|mission)$/i;

let app = null;
let status, transfers;
const progress = new Map(); // sysid → the latest plan_progress event
let progressChanged = false;
const rows = new Map(); // sysid → its row in the transfers list

/** Shows [text] as the panel's outcome line; kind: good, bad or busy. */
function say(text, kind) {
  status.textContent = text;
  status.className = `plan-status ${kind}`;
  status.dataset.kind = kind;
}

/** The selected vehicle, or null after saying that one must be selected for [what]. */
function target(what) {
  if (app.selected == null) say(`${what}: select a vehicle first (click it on the map or in the fleet table)`, "bad");
  return app.selected;
}

/** Uploads [file] (a File) to the selected vehicle; resolves once the vehicle answered. */
export async function upload(file) {
  const sysid = target(file.name);
  if (sysid == null) return;
  if (!PLAN_FILE.test(file.name)) {
    say(`${file.name}: not a plan file: drop a QGC .plan file or a QGC WPL 110 file (.waypoints)`, "bad");
    return;
  }
  if (file.size > MAX_BYTES) {
    say(`${file.name} is too large for a plan file (${Math.round(file.size / 1024)} KiB)`, "bad");
    return;
  }
  let text;
  try {
    text = await file.text();
  } catch (e) {
    say(`${file.name}: cannot read it: ${e.message}`, "bad");
    return;
  }
  say(`uploading ${file.name} to vehicle ${sysid}…`, "busy");
  const reply = await app.request("plan_upload", { sysid, name: file.name, text });
  if (reply.ok) say(reply.detail, "good");
  else say(reply.error.startsWith(file.name) ? reply.error : `${file.name}: ${reply.error}`, "bad");
}

async function showOnBoard() {
  const sysid = target("show on board");
  if (sysid == null) return;
  say(`reading what vehicle ${sysid} holds…`, "busy");
  const reply = await app.request("plan_on_board", { sysid });
  say(reply.ok ? reply.detail : `vehicle ${sysid}: ${reply.error}`, reply.ok ? "good" : "bad");
}

/** Fetches the selected vehicle's plan from the server and hands it to the browser as a file. */
async function download() {
  const sysid = target("download plan");
  if (sysid == null) return;
  say(`downloading vehicle ${sysid}'s plan…`, "busy");
  const query = app.token ? `?token=${encodeURIComponent(app.token)}` : "";
  let response, text;
  try {
    response = await fetch(`/api/vehicles/${sysid}/plan${query}`);
    text = await response.text();
  } catch (e) {
    say(`download of vehicle ${sysid}'s plan failed: ${e.message}`, "bad");
    return;
  }
  if (!response.ok) {
    say(`download of vehicle ${sysid}'s plan failed: ${text}`, "bad");
    return;
  }
  const name = `vehicle-${sysid}.plan`;
  const url = URL.createObjectURL(new Blob([text], { type: "application/json" }));
  const link = document.createElement("a");
  link.href = url;
  link.download = name;
  document.body.appendChild(link);
  link.click();
  link.remove();
  setTimeout(() => URL.revokeObjectURL(url), 60_000);
  say(`saved ${name} (${text.length} bytes)`, "good");
}

/** One row per vehicle with a transfer: what moves and how far, or how the last one ended. */
function drawTransfers() {
  if (!progressChanged) return;
  progressChanged = false;
  [...progress.values()].sort((a, b) => a.sysid - b.sysid).forEach((p, i) => {
    let row = rows.get(p.sysid);
    if (!row) {
      row = document.createElement("li");
      row.dataset.sysid = p.sysid;
      row.append(document.createElement("span"), document.createElement("progress"));
      rows.set(p.sysid, row);
    }
    if (transfers.children[i] !== row) transfers.insertBefore(row, transfers.children[i] || null);
    row.className = p.failed ? "failed" : p.finished ? "finished" : "running";
    const what = p.waiting ? `waiting: ${p.waiting}` : `${p.list} ${p.done}/${p.total}`;
    row.firstChild.textContent = `vehicle ${p.sysid}: ${p.action} ${p.file}: ${p.failed ? "failed" : p.finished ? "done" : what}`;
    row.lastChild.max = Math.max(p.total, 1);
    row.lastChild.value = p.finished ? row.lastChild.max : p.done;
  });
}

/** Makes [node] take dropped files: the first one is uploaded. */
function acceptDrops(node) {
  node.addEventListener("dragover", (e) => {
    if (![...e.dataTransfer.types].includes("Files")) return;
    e.preventDefault();
    e.dataTransfer.dropEffect = "copy";
    node.classList.add("plan-drop");
  });
  node.addEventListener("dragleave", () => node.classList.remove("plan-drop"));
  node.addEventListener("drop", (e) => {
    node.classList.remove("plan-drop");
    const files = e.dataTransfer.files;
    if (!files || files.length === 0) return;
    e.preventDefault();
    if (files.length > 1) say(`${files.length} files dropped: uploading only the first, ${files[0].name}`, "busy");
    upload(files[0]);
  });
}

function button(parent, text, action) {
  const b = document.createElement("button");
  b.type = "button";
  b.textContent = text;
  b.addEventListener("click", action);
  parent.appendChild(b);
  return b;
}

/** Called once at start with the page's app (see app.js). */
export function init(appRef) {
  app = appRef;
  const panel = document.getElementById("plans-panel");
  const zone = document.createElement("div");
  zone.id = "plan-drop-zone";
  zone.textContent = "Drop a .plan or .waypoints file here or on the map to upload it to the selected vehicle, or ";
  const input = document.createElement("input");
  input.type = "file";
  input.id = "plan-file";
  input.accept = ".plan,.waypoints,.txt,.mission";
  input.addEventListener("change", () => {
    const file = input.files[0];
    if (file) upload(file).finally(() => { input.value = ""; });
  });
  zone.appendChild(input);
  const tools = document.createElement("div");
  tools.className = "plan-tools";
  button(tools, "show on board", showOnBoard).id = "plan-show";
  button(tools, "download plan", download).id = "plan-download";
  status = document.createElement("div");
  status.id = "plan-status";
  transfers = document.createElement("ul");
  transfers.id = "plan-transfers";
  panel.append(zone, tools, status, transfers);
  say("", "");
  acceptDrops(panel);
  acceptDrops(document.getElementById("map-panel"));
  app.on("plan_progress", (e) => { progress.set(e.sysid, e); progressChanged = true; });
  app.afterBatch(drawTransfers);
  onboard.init(app);
}
