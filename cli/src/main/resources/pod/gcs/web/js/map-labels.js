// Pod ground station: where each vehicle's label goes on the map so that none hides another.
// The simulator parks a fleet 5 m apart and a real one takes off side by side, so the obvious spot
// (right of the marker) is often taken: each label, in priority order, takes the first free spot
// of a fixed list around its marker, then of rings farther out (drawn with a leader line); a label
// with no free spot is hidden and counted, so the page can say "zoom in".
//
// Occupied boxes live in a spatial hash of CELL-pixel cells: each check looks at a few cells, so
// laying out 250 labels costs a few thousand box tests, not 250².

const CELL = 48;
const PAD = 4; // the label's white halo (a 3 px stroke) and a hair of air
const MARKER_HALF = 10; // a marker's box is 20 × 20 px around its centre
const GAP = 12; // between a marker's centre and its label
const MAX_RING = 2; // farther out, leader lines criss-cross a dense fleet more than they help
const LINE = 16; // a label's box height in pixels: 11 px text, its descent and halo
export const BASELINE = 12; // from the box's top to the text's baseline
export const INSET = PAD / 2; // from the box's left to the text's start

let measure = null;

/**
 * A label's width in pixels for its text in the map's label font (`font`, a CSS font shorthand):
 * measured on a canvas, which costs no layout, unlike measuring the SVG text itself.
 */
export function labelWidth(text, font) {
  if (!measure) measure = document.createElement("canvas").getContext("2d");
  if (measure.font !== font) measure.font = font;
  return Math.ceil(measure.measureText(text).width) + PAD;
}

/**
 * Places labels: `items` [{key, x, y, width}] (marker centre in pixels), highest priority first.
 * Returns key → {x, y, leader} (the label box's top-left corner; leader: it sits away from its
 * marker and needs a line to it) or null when no spot is free.
 */
export function placeLabels(items) {
  const hash = new Map();
  for (const it of items) occupy(hash, { x: it.x - MARKER_HALF, y: it.y - MARKER_HALF, w: 2 * MARKER_HALF, h: 2 * MARKER_HALF, key: it.key, marker: true });
  const out = new Map();
  for (const it of items) {
    let placed = null;
    for (const c of candidates(it.width)) {
      const box = { x: it.x + c.dx, y: it.y + c.dy, w: it.width, h: LINE, key: it.key };
      if (!collides(hash, box)) { placed = { x: box.x, y: box.y, leader: c.ring > 0 }; occupy(hash, box); break; }
    }
    out.set(it.key, placed);
  }
  return out;
}

/** Offsets of a label's top-left corner from its marker's centre: beside it first, then rings farther out. */
function candidates(w) {
  const list = [
    { dx: GAP, dy: -LINE - 4, ring: 0 }, { dx: GAP, dy: 4, ring: 0 },
    { dx: -GAP - w, dy: -LINE - 4, ring: 0 }, { dx: -GAP - w, dy: 4, ring: 0 },
    { dx: -w / 2, dy: -LINE - GAP - 4, ring: 0 }, { dx: -w / 2, dy: GAP + 4, ring: 0 },
  ];
  for (let ring = 1; ring <= MAX_RING; ring++) {
    const up = -LINE - 4 - ring * (LINE + 4), down = 4 + ring * (LINE + 4), out = GAP + ring * 14;
    list.push({ dx: out, dy: up, ring }, { dx: out, dy: down, ring }, { dx: -out - w, dy: up, ring }, { dx: -out - w, dy: down, ring });
  }
  return list;
}

// Cells are numbered cx * SPAN + cy (numbers, not strings: no garbage per test).
const SPAN = 1 << 16;

function occupy(hash, box) {
  for (let cx = Math.floor(box.x / CELL); cx <= Math.floor((box.x + box.w) / CELL); cx++) {
    for (let cy = Math.floor(box.y / CELL); cy <= Math.floor((box.y + box.h) / CELL); cy++) {
      const k = cx * SPAN + cy;
      const cell = hash.get(k);
      if (cell) cell.push(box); else hash.set(k, [box]);
    }
  }
}

/** Whether `box` overlaps a label placed before or another vehicle's marker (its own marker is not in its way). */
function collides(hash, box) {
  for (let cx = Math.floor(box.x / CELL); cx <= Math.floor((box.x + box.w) / CELL); cx++) {
    for (let cy = Math.floor(box.y / CELL); cy <= Math.floor((box.y + box.h) / CELL); cy++) {
      const cell = hash.get(cx * SPAN + cy);
      if (!cell) continue;
      for (const o of cell) {
        if (o.marker && o.key === box.key) continue;
        if (box.x < o.x + o.w && o.x < box.x + box.w && box.y < o.y + o.h && o.y < box.y + box.h) return true;
      }
    }
  }
  return false;
}
