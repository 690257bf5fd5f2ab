// Pod ground station: the fleet table, one row per vehicle by system id; click a row to select it.
const COLUMNS = ["SYSID", "LINK", "MODE", "ARMED", "ALT", "BATT", "GPS", "LINK Q", "AWAITING", "LAST TEXT"];
const rows = new Map();

function cells(v) {
  const t = v.telemetry || {};
  const s = v.status || {};
  return [
    String(v.sysid),
    v.lost ? "LOST" : "connected",
    t.mode || "–",
    t.armed ? "yes" : "no",
    t.alt_rel == null ? "–" : `${t.alt_rel.toFixed(1)} m`,
    t.battery == null ? "–" : `${Math.round(t.battery * 100)}%`,
    t.gps_fix ? `${t.gps_fix.replace("FIX_", "")} ${t.satellites ?? ""}` : "–",
    t.link == null ? "–" : `${Math.round(t.link * 100)}%`,
    s.awaiting || "",
    s.text || "",
  ];
}

export function init(app) {
  const table = document.getElementById("fleet");
  const head = table.tHead.insertRow();
  COLUMNS.forEach((c) => { const th = document.createElement("th"); th.textContent = c; head.appendChild(th); });
  const body = table.tBodies[0];
  app.afterBatch(() => {
    const sorted = [...app.vehicles.values()].sort((a, b) => a.sysid - b.sysid);
    sorted.forEach((v, i) => {
      let row = rows.get(v.sysid);
      if (!row) {
        row = document.createElement("tr");
        row.dataset.sysid = v.sysid;
        COLUMNS.forEach((_, c) => { const td = row.insertCell(); if ([0, 4, 5, 7].includes(c)) td.className = "num"; });
        row.addEventListener("click", () => app.select(v.sysid));
        rows.set(v.sysid, row);
      }
      if (body.rows[i] !== row) body.insertBefore(row, body.rows[i] || null);
      cells(v).forEach((text, c) => { if (row.cells[c].textContent !== text) row.cells[c].textContent = text; });
      row.classList.toggle("lost", v.lost);
      row.classList.toggle("selected", app.selected === v.sysid);
    });
  });
}
