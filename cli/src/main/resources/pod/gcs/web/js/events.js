// Pod ground station: the event log. Every event the page gets that is a happening rather than a
// state (the program's tasks and missions, queues, vehicles found / lost / regained, their
// STATUSTEXTs, whatever a panel's action logs) becomes a line: time, vehicle, what, coloured by
// level. Newest at the bottom; the panel follows new lines unless the operator scrolled up to read;
// at most MAX_LINES are kept. "Selected vehicle only" hides the lines about other vehicles.
//
// The server replays its recent log when a page connects: those lines come in the first batch and
// are marked "before" (their time is not known here), followed by a "live" separator.
import { format, notLogged } from "./events-format.js";

const MAX_LINES = 1000;
const BOTTOM_SLACK_PX = 24; // this close to the bottom counts as "at the bottom": keep following

let list, panel, onlySelected, appRef;
let following = true;
let replaying = false;
let replayed = 0;

function clock(date) {
  return date.toTimeString().slice(0, 8);
}

function shown(li) {
  if (!onlySelected.checked) return true;
  return appRef.selected != null && li.dataset.vehicles.split(" ").includes(String(appRef.selected));
}

function add(e) {
  if (notLogged(e.event)) return;
  const line = format(e);
  const li = document.createElement("li");
  li.className = `ev ev-${line.kind}${line.level ? ` ${line.level}` : ""}${replaying ? " before" : ""}`;
  li.dataset.kind = line.kind;
  li.dataset.vehicles = line.vehicles.join(" ");
  const time = document.createElement("time");
  time.textContent = replaying ? "before" : clock(new Date());
  const who = document.createElement("span");
  who.className = "who";
  who.textContent = line.vehicles.length ? line.vehicles.map((v) => `V${v}`).join(",") : "–";
  const what = document.createElement("span");
  what.className = "what";
  what.textContent = line.text;
  li.append(time, who, what);
  li.hidden = !shown(li);
  list.appendChild(li);
  if (replaying) replayed++;
  while (list.children.length > MAX_LINES) list.firstElementChild.remove();
}

function separator(text) {
  const li = document.createElement("li");
  li.className = "separator";
  li.dataset.vehicles = "";
  li.textContent = text;
  list.appendChild(li);
}

function refilter() {
  for (const li of list.children) {
    if (li.classList.contains("separator")) li.hidden = onlySelected.checked;
    else li.hidden = !shown(li);
  }
  if (following) panel.scrollTop = panel.scrollHeight;
}

function toolbar() {
  const bar = document.createElement("div");
  bar.id = "events-tools";
  const label = document.createElement("label");
  onlySelected = document.createElement("input");
  onlySelected.type = "checkbox";
  onlySelected.id = "events-selected-only";
  onlySelected.addEventListener("change", refilter);
  label.append(onlySelected, " selected vehicle only");
  const count = document.createElement("span");
  count.id = "events-count";
  bar.append(label, count);
  panel.querySelector("h2").after(bar);
  return count;
}

export function init(app) {
  appRef = app;
  panel = document.getElementById("events-panel");
  list = document.getElementById("events");
  const count = toolbar();
  panel.addEventListener("scroll", () => {
    following = panel.scrollTop + panel.clientHeight >= panel.scrollHeight - BOTTOM_SLACK_PX;
  });
  // A new connection replays the server's log: start afresh rather than show it twice.
  app.on("gcs_hello", () => { list.replaceChildren(); replaying = true; replayed = 0; following = true; });
  app.on("*", add);
  app.afterBatch(() => {
    if (replaying) {
      replaying = false;
      if (replayed) separator("page opened: live from here");
    }
    count.textContent = `${list.childElementCount} lines`;
    if (following) panel.scrollTop = panel.scrollHeight;
  });
  app.onSelect(() => { if (onlySelected.checked) refilter(); });
}
