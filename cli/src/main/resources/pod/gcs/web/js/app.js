// Pod ground station: the page's link to the server (one WebSocket) and the fleet state every panel
// reads. The server sends a hello, then at most ten batches a second; each batch's events update
// `app.vehicles` first, then go to the panels that asked for their kind, then `afterBatch` listeners
// redraw once. Requests go out as JSON with an id and resolve with the server's reply.
import * as map from "./map.js";
import * as fleet from "./fleet.js";
import * as commands from "./commands.js";
import * as queue from "./queue.js";
import * as survey from "./survey.js";
import * as plans from "./plans.js";
import * as events from "./events.js";

const handlers = new Map();
const batchListeners = [];
const selectListeners = [];
const pending = new Map();
let socket = null;
let nextId = 1;

export const app = {
  /** sysid → { sysid, type, autopilot, lost, telemetry, home, status } */
  vehicles: new Map(),
  selected: null,
  hello: null,
  token: new URLSearchParams(location.search).get("token"),
  stats: { batches: 0, events: 0, lastSeq: 0 },

  /** Calls fn(event) for every event of this kind, after the fleet state took it in ("*": of every kind). */
  on(kind, fn) {
    if (!handlers.has(kind)) handlers.set(kind, []);
    handlers.get(kind).push(fn);
  },
  /** Calls fn() once after each batch (and after a selection changes): the place to redraw. */
  afterBatch(fn) { batchListeners.push(fn); },
  onSelect(fn) { selectListeners.push(fn); },
  select(sysid) {
    app.selected = sysid;
    selectListeners.forEach((fn) => fn(sysid));
    batchListeners.forEach((fn) => fn());
  },
  /** Sends {op, ...fields}; resolves with the reply {id, ok, error, detail}. */
  request(op, fields = {}) {
    const id = nextId++;
    return new Promise((resolve) => {
      if (!socket || socket.readyState !== WebSocket.OPEN) {
        resolve({ id, ok: false, error: "not connected to the ground station" });
        return;
      }
      pending.set(id, resolve);
      socket.send(JSON.stringify({ op, id, ...fields }));
    });
  },
};
window.pod = app;
// The server keeps the token in a cookie now: take it out of the address bar (history, bookmarks, screenshots).
if (app.token) history.replaceState(null, "", location.pathname);

function vehicle(sysid) {
  let v = app.vehicles.get(sysid);
  if (!v) {
    v = { sysid, type: null, autopilot: null, lost: false, telemetry: null, home: null, status: null };
    app.vehicles.set(sysid, v);
  }
  return v;
}

function take(e) {
  switch (e.event) {
    case "found": Object.assign(vehicle(e.sysid), { type: e.type, autopilot: e.autopilot, lost: false }); break;
    case "lost": vehicle(e.sysid).lost = true; break;
    case "regained": vehicle(e.sysid).lost = false; break;
    case "telemetry": vehicle(e.sysid).telemetry = e; break;
    case "home": vehicle(e.sysid).home = e; break;
    case "vehicle_status": vehicle(e.sysid).status = e; break;
    case "reply": {
      const resolve = pending.get(e.id);
      pending.delete(e.id);
      if (resolve) resolve(e);
      break;
    }
  }
  (handlers.get(e.event) || []).forEach((fn) => fn(e));
  (handlers.get("*") || []).forEach((fn) => fn(e));
}

function connect() {
  const scheme = location.protocol === "https:" ? "wss" : "ws";
  const query = app.token ? `?token=${encodeURIComponent(app.token)}` : "";
  socket = new WebSocket(`${scheme}://${location.host}/ws${query}`);
  const state = document.getElementById("connection");
  socket.onopen = () => { state.textContent = "connected"; state.className = "up"; };
  socket.onclose = () => {
    state.textContent = "disconnected: retrying"; state.className = "down";
    pending.forEach((resolve, id) => resolve({ id, ok: false, error: "the connection to the ground station closed" }));
    pending.clear();
    setTimeout(connect, 1000);
  };
  socket.onmessage = (message) => {
    const e = JSON.parse(message.data);
    if (e.event === "gcs_hello") {
      app.hello = e;
      document.getElementById("source").textContent = e.source;
      take(e);
    } else if (e.event === "gcs_batch") {
      app.stats.batches++;
      app.stats.events += e.events.length;
      app.stats.lastSeq = e.seq;
      e.events.forEach(take);
      batchListeners.forEach((fn) => fn());
      // Taken in and drawn: the server sends the next batch only once this page has kept up, so a
      // slow page gets fewer, fresher batches rather than a backlog (PageBatcher).
      socket.send(JSON.stringify({ drawn: e.seq }));
    } else {
      take(e);
    }
  };
}

for (const part of [map, fleet, commands, queue, survey, plans, events]) part.init(app);
connect();
