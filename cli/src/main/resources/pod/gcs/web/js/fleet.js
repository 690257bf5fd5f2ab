// Pod ground station: the fleet table, one row per vehicle sorted by system id; click a row to
// select its vehicle. Each cell is a text and a colour class (bad / warn / good / none); a batch
// touches only the cells whose text or class changed, so 250 rows at ten batches a second cost a
// few string compares per cell and no layout.
// [header, data-column, what the header means]: short headers keep ten columns beside the map.
const COLUMNS = [
  ["ID", "sysid", "system id"], ["LINK", "link", "connected, or LOST when its heartbeat stopped"], ["MODE", "mode", "flight mode"],
  ["ARM", "armed", "armed or not"], ["ALT", "alt", "height above home"], ["BATT", "battery", "battery remaining"],
  ["GPS", "gps", "GPS fix and satellites"], ["LQ", "link-q", "link quality: the fraction of its frames that arrived"],
  ["WAITING", "awaiting", "what Pod is waiting for from it"], ["LAST TEXT", "last-text", "its last STATUSTEXT (hover: severity)"],
];
const NUMERIC = new Set([0, 4, 5, 7]);
const AWAITING_COLUMN = 8;
const TEXT_COLUMN = 9;
const rows = new Map(); // sysid → <tr>

// Colour thresholds for an operator's glance; the autopilot's own failsafes act on its parameters.
const BATTERY_BAD = 0.2, BATTERY_WARN = 0.3;
const LINK_BAD = 0.6, LINK_WARN = 0.9;
const SATELLITES_WARN = 6;
const BAD_SEVERITIES = new Set(["EMERGENCY", "ALERT", "CRITICAL", "ERROR"]);

/** The colour class of a STATUSTEXT severity (MAVLink's name): failures red, warnings amber. */
export function severityClass(severity) {
  if (BAD_SEVERITIES.has(severity)) return "bad";
  return severity === "WARNING" ? "warn" : "";
}

function gps(t) {
  if (!t.gps_fix) return ["–", "bad"];
  const fix = t.gps_fix.replace("FIX_", "");
  const text = `${fix} ${t.satellites ?? ""}`.trim();
  if (t.gps_fix === "NO_GPS" || t.gps_fix === "NO_FIX") return [text, "bad"];
  return [text, t.gps_fix === "FIX_2D" || (t.satellites != null && t.satellites < SATELLITES_WARN) ? "warn" : ""];
}

function level(value, bad, warn) {
  if (value == null) return "";
  return value < bad ? "bad" : value < warn ? "warn" : "";
}

/** [text, class] for each column of vehicle v. */
function cells(v) {
  const t = v.telemetry || {};
  const s = v.status || {};
  return [
    [String(v.sysid), ""],
    v.lost ? ["LOST", "bad"] : ["ok", "good"],
    [t.mode || "–", ""],
    t.armed ? ["ARMED", "warn"] : ["no", "muted"],
    [t.alt_rel == null ? "–" : `${t.alt_rel.toFixed(1)} m`, ""],
    [t.battery == null ? "–" : `${Math.round(t.battery * 100)}%`, level(t.battery, BATTERY_BAD, BATTERY_WARN)],
    v.telemetry ? gps(t) : ["–", ""],
    [t.link == null ? "–" : `${Math.round(t.link * 100)}%`, level(t.link, LINK_BAD, LINK_WARN)],
    [s.awaiting || "", "warn"],
    [s.text || "", severityClass(s.severity)],
  ];
}

function newRow(app, sysid) {
  const row = document.createElement("tr");
  row.dataset.sysid = sysid;
  COLUMNS.forEach(([, column], c) => {
    const td = row.insertCell();
    td.dataset.column = column;
    td.dataset.cls = "";
    if (NUMERIC.has(c)) td.classList.add("num");
  });
  row.addEventListener("click", () => app.select(sysid));
  return row;
}

function update(app, row, v) {
  const selected = app.selected === v.sysid;
  if (row.classList.contains("selected") !== selected) row.classList.toggle("selected", selected);
  // The page replaces a vehicle's telemetry and status objects only when they change: same objects, same cells.
  if (row.shown && row.shown.telemetry === v.telemetry && row.shown.status === v.status && row.shown.lost === v.lost) return;
  row.shown = { telemetry: v.telemetry, status: v.status, lost: v.lost };
  cells(v).forEach(([text, cls], c) => {
    const td = row.cells[c];
    if (td.textContent !== text) {
      td.textContent = text;
      if (c === TEXT_COLUMN) td.title = v.status && v.status.severity ? `${v.status.severity}: ${text}` : text;
      if (c === AWAITING_COLUMN) td.title = text;
    }
    if (td.dataset.cls !== cls) {
      if (td.dataset.cls) td.classList.remove(td.dataset.cls);
      if (cls) td.classList.add(cls);
      td.dataset.cls = cls;
    }
  });
  if (row.classList.contains("lost") !== v.lost) row.classList.toggle("lost", v.lost);
}

export function init(app) {
  const table = document.getElementById("fleet");
  const head = table.tHead.insertRow();
  COLUMNS.forEach(([name, , meaning]) => {
    const th = document.createElement("th");
    th.textContent = name;
    th.title = meaning;
    head.appendChild(th);
  });
  const body = table.tBodies[0];
  app.afterBatch(() => {
    const sorted = [...app.vehicles.values()].sort((a, b) => a.sysid - b.sysid);
    sorted.forEach((v, i) => {
      let row = rows.get(v.sysid);
      if (!row) { row = newRow(app, v.sysid); rows.set(v.sysid, row); }
      if (body.rows[i] !== row) body.insertBefore(row, body.rows[i] || null);
      update(app, row, v);
    });
  });
  app.onSelect((sysid) => { if (rows.has(sysid)) rows.get(sysid).scrollIntoView({ block: "nearest" }); });
}
