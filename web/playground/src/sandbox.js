// The Sandbox: the bundled cave map, painted with the mouse, ray casts dragged across it
// with each filter, circles that flow to the mouse, and the explain tool: a circle's last
// step and the segment under the mouse in words (the package's `explain` build).
import init, { DebugLines, TileMap } from "../../playground-pkg/tileslide.js";
import caveText from "../../../examples/maps/cave.txt?raw";

import { COLORS } from "./colors.js";
import { Crowd, MAX_RADIUS } from "./crowd.js";
import { runFrames } from "./frames.js";
import { publishHook, showError } from "./hook.js";
import { KIND, drawLines } from "./lines.js";
import { siteHeader } from "./page.js";
import { TILE_NAMES, tilesOfAscii, traceTile } from "./tiles.js";
import { View } from "./view.js";

/** The ray filters of the Filter menu, as `castRay` options. */
const FILTERS = {
  front: undefined,
  both: { bothSides: true },
  down: { against: [0, 1] },
  up: { against: [0, -1] },
  left: { against: [-1, 0] },
  right: { against: [1, 0] },
};

/** The layers the page can draw, in drawing order, with the debug-line kinds each shows. */
const LAYERS = [
  { key: "tiles", label: "tiles (filled)", on: true, kinds: [] },
  { key: "grid", label: "cell grid", on: false, kinds: [] },
  { key: "active", label: "active segments", on: true, kinds: [KIND.ActiveSegment, KIND.OneWaySegment] },
  { key: "normals", label: "normals", on: true, kinds: [KIND.Normal] },
  { key: "hidden", label: "hidden seam segments (faint)", on: true, kinds: [KIND.HiddenSegment] },
  { key: "ray", label: "ray, hit, normal, cell", on: true, kinds: [] },
  { key: "bodies", label: "bodies", on: true, kinds: [] },
  { key: "broadphase", label: "bodies' broadphase boxes", on: false, kinds: [KIND.BroadphaseBox] },
  { key: "flow", label: "flow arrows (each circle size's field)", on: false, kinds: [KIND.FlowArrow] },
];
/** The kinds the bodies and flow fields add to `crowdLines`, each frame, for the layers on. */
const CROWD_KINDS = [KIND.BroadphaseBox, KIND.FlowArrow];
/** The layer that shows each debug-line kind. */
const LAYER_OF_KIND = new Map(LAYERS.flatMap((layer) => layer.kinds.map((kind) => [kind, layer.key])));

siteHeader("sandbox");
const canvas = document.getElementById("canvas");
const tiles = tilesOfAscii(caveText);
const width = tiles[0].length;
const height = tiles.length;
const view = new View(canvas, width / height);
view.frame(0, 0, width, height, 0.5);

const state = {
  tool: { kind: "paint", tile: 1 },
  filter: "front",
  ray: null, // {x0, y0, x1, y1, hit}
  dragging: false,
  lastCell: null,
  paused: false,
  radius: 0.3,
  message: "",
  layers: Object.fromEntries(LAYERS.map((l) => [l.key, l.on])),
  // The explain tool: the body clicked (a handle) and its story; the cell explained under
  // the mouse (map.explainCell's answer) and the segment of it nearest the mouse.
  explain: { body: null, story: null, cell: null, segment: null },
};
let map = null;
let frames = null;
let mapLines = null; // the map's debug lines, filled again when a tile changes
let mapChanged = true;
let crowdLines = null; // the bodies' and flow fields' debug lines, filled each frame
let crowd = null;

const hook = publishHook("sandbox", {
  state: () => ({
    tool: { ...state.tool },
    filter: state.filter,
    ray: state.ray && { ...state.ray },
    bodies: crowd ? crowd.count : 0,
    goal: crowd && crowd.goal,
    radius: state.radius,
    paused: state.paused,
    message: state.message,
    width,
    height,
    frame: frames && frames.summary(),
  }),
  tileAt: (col, row) => tiles[row][col],
  /** Every body as x, y, r. */
  circles: () => Array.from(crowd.circles()),
  /** The map's debug segments of kind `kind` (a DebugKind number), as [x0, y0, x1, y1]. */
  segments: (kind) => {
    const coords = mapLines.segments;
    const kinds = mapLines.segmentKinds;
    const out = [];
    for (let i = 0; i < kinds.length; i++) {
      if (kinds[i] === kind) out.push(Array.from(coords.subarray(4 * i, 4 * i + 4)));
    }
    return out;
  },
  /** How many shapes of each kind the last frame drew from the bodies and flow fields. */
  crowdLineCounts: () => ({
    boxes: crowdLines.boxKinds.filter((k) => k === KIND.BroadphaseBox).length,
    arrows: crowdLines.segmentKinds.filter((k) => k === KIND.FlowArrow).length,
  }),
  /** The bodies' handles, in the order of `circles`. */
  bodyHandles: () => Array.from(crowd.bodies.handles()),
  /** Proposes the move (`dx`, `dy`) for body `handle` alone and runs one step: a contact
   * on demand, whatever the flow would do. */
  moveBody: (handle, dx, dy) => {
    crowd.bodies.propose(handle, dx, dy);
    crowd.bodies.step(map);
  },
  /** What the explain tool shows: the body clicked and its story, the segment hovered. */
  explain: () => {
    const { body, story, cell, segment } = state.explain;
    return {
      body,
      story,
      cell: cell && cell.cell,
      segment: segment && { index: segment.index, hidden: segment.hidden, state: segment.state, words: segment.words },
      readout: document.getElementById("explain-readout").textContent,
    };
  },
  clientAt: (x, y) => view.clientAt(x, y),
  pixelAt: (x, y) => view.pixelAt(x, y),
});

// ---- input -----------------------------------------------------------------------------

/** The cell (col, row) under a world point, or null outside the map. */
function cellAt(x, y) {
  const col = Math.floor(x);
  const row = Math.floor(y);
  return col >= 0 && row >= 0 && col < width && row < height ? { col, row } : null;
}

/** Paints the current tile (or empties) cell `cell`, leaving the map's outer ring, which
 * keeps bodies inside. */
function paint(cell) {
  const { col, row } = cell;
  if (col === 0 || row === 0 || col === width - 1 || row === height - 1) return;
  const id = state.tool.tile === 0 ? null : state.tool.tile;
  if (tiles[row][col] === id) return;
  map.setTile(col, row, id);
  tiles[row][col] = id;
  mapChanged = true;
  crowd.mapChanged();
  state.explain.cell = state.explain.segment = null;
  castAgain();
}

/** Paints every cell on the grid line from `a` to `b`, so a fast drag leaves no gaps. */
function paintLine(a, b) {
  const steps = Math.max(Math.abs(b.col - a.col), Math.abs(b.row - a.row));
  for (let i = 0; i <= steps; i++) {
    const f = steps === 0 ? 0 : i / steps;
    paint({ col: Math.round(a.col + (b.col - a.col) * f), row: Math.round(a.row + (b.row - a.row) * f) });
  }
}

function castAgain() {
  const ray = state.ray;
  if (!ray) return;
  const moved = ray.x0 !== ray.x1 || ray.y0 !== ray.y1;
  ray.hit = moved ? map.castRay(ray.x0, ray.y0, ray.x1, ray.y1, FILTERS[state.filter]) : null;
  showRay();
}

function showRay() {
  const out = document.getElementById("ray-readout");
  const ray = state.ray;
  if (!ray) {
    out.textContent = "drag on the map with the ray tool";
    return;
  }
  const f = (v) => v.toFixed(3);
  const lines = [`from (${f(ray.x0)}, ${f(ray.y0)})`, `to   (${f(ray.x1)}, ${f(ray.y1)})`];
  const hit = ray.hit;
  if (hit) {
    lines.push(`hit  t = ${f(hit.t)}`, `at   (${f(hit.x)}, ${f(hit.y)})`);
    lines.push(`normal (${f(hit.nx)}, ${f(hit.ny)})`);
    lines.push(hit.cell ? `cell [${hit.cell[0]}, ${hit.cell[1]}]` : "cell: a temporary segment");
    lines.push(`tile ${hit.tile} (${TILE_NAMES[hit.tile] ?? "?"})`);
  } else {
    lines.push("no hit");
  }
  out.textContent = lines.join("\n");
}

canvas.addEventListener("pointerdown", (event) => {
  if (event.button !== 0 || !map) return;
  canvas.focus();
  canvas.setPointerCapture(event.pointerId);
  const [x, y] = view.worldAt(event.clientX, event.clientY);
  state.dragging = true;
  if (state.tool.kind === "paint") {
    const cell = cellAt(x, y);
    if (cell) paint(cell);
    state.lastCell = cell;
  } else if (state.tool.kind === "ray") {
    state.ray = { x0: x, y0: y, x1: x, y1: y, hit: null };
    castAgain();
  } else if (state.tool.kind === "explain") {
    state.explain.body = crowd.bodyAt(x, y);
    tellStory();
  } else if (state.tool.kind === "circles") {
    crowd.setGoal(x, y);
    say(
      crowd.drop(x, y, state.radius)
        ? `dropped a circle of radius ${state.radius.toFixed(2)}`
        : `a circle of radius ${state.radius.toFixed(2)} does not fit there`,
    );
  }
});

canvas.addEventListener("pointermove", (event) => {
  if (!map) return;
  const [x, y] = view.worldAt(event.clientX, event.clientY);
  // The circles flow to the mouse.
  if (x >= 0 && y >= 0 && x < width && y < height) crowd.setGoal(x, y);
  if (state.tool.kind === "explain") explainAt(x, y);
  if (!state.dragging) return;
  if (state.tool.kind === "paint") {
    const cell = cellAt(x, y);
    if (cell && state.lastCell) paintLine(state.lastCell, cell);
    else if (cell) paint(cell);
    state.lastCell = cell;
  } else if (state.tool.kind === "ray" && state.ray) {
    state.ray.x1 = x;
    state.ray.y1 = y;
    castAgain();
  }
});

canvas.addEventListener("pointerup", () => {
  state.dragging = false;
  state.lastCell = null;
});

// ---- explain -----------------------------------------------------------------------------

/** The distance from (`x`, `y`) to the segment from `a` to `b`. */
function distanceToSegment(x, y, [ax, ay], [bx, by]) {
  const [dx, dy] = [bx - ax, by - ay];
  const length2 = dx * dx + dy * dy;
  const f = length2 > 0 ? Math.min(1, Math.max(0, ((x - ax) * dx + (y - ay) * dy) / length2)) : 0;
  return Math.hypot(ax + f * dx - x, ay + f * dy - y);
}

/** Explains the cell under (`x`, `y`) and picks its segment nearest the mouse. */
function explainAt(x, y) {
  const at = cellAt(x, y);
  const e = state.explain;
  if (!at) {
    e.cell = e.segment = null;
  } else {
    const [col, row] = e.cell ? e.cell.cell : [-1, -1];
    if (col !== at.col || row !== at.row) e.cell = map.explainCell(at.col, at.row);
    let best = Infinity;
    e.segment = null;
    for (const segment of e.cell.segments) {
      const d = distanceToSegment(x, y, segment.from, segment.to);
      if (d < best) [best, e.segment] = [d, segment];
    }
  }
  showExplain();
}

/** Asks the story of the body clicked again (after a step, or a click). */
function tellStory() {
  const e = state.explain;
  if (e.body !== null && !crowd.bodies.contains(e.body)) e.body = null;
  const story = e.body === null ? null : crowd.storyOf(e.body);
  if (story === e.story) return;
  e.story = story;
  showExplain();
}

function showExplain() {
  const e = state.explain;
  const lines = [];
  if (state.tool.kind !== "explain") {
    lines.push("choose the explain tool (E)");
  } else {
    if (e.body === null) lines.push("click a circle for its last step");
    else lines.push(e.story ?? `body ${e.body}: no step traced yet`);
    if (e.cell) {
      const [col, row] = e.cell.cell;
      if (e.cell.tile === null) lines.push(`cell (${col}, ${row}): empty`);
      else if (e.segment) {
        lines.push(`cell (${col}, ${row}), tile ${e.cell.tile}: segment ${e.segment.index} ${e.segment.state}`);
        lines.push(e.segment.words.trimEnd());
      }
    }
  }
  document.getElementById("explain-readout").textContent = lines.join("\n");
}

function chooseTool(tool) {
  const explaining = tool.kind === "explain";
  if (crowd && crowd.tracing !== explaining) crowd.trace(explaining);
  if (!explaining) state.explain = { body: null, story: null, cell: null, segment: null };
  state.tool = tool;
  showExplain();
  for (const button of document.querySelectorAll("#tools button")) {
    const same =
      button.dataset.tool === tool.kind &&
      (tool.kind !== "paint" || Number(button.dataset.tile) === tool.tile);
    button.setAttribute("aria-pressed", String(same));
  }
}

for (const button of document.querySelectorAll("#tools button")) {
  button.addEventListener("click", () => {
    const kind = button.dataset.tool;
    chooseTool(kind === "paint" ? { kind, tile: Number(button.dataset.tile) } : { kind });
  });
}

const filterMenu = document.getElementById("filter");
filterMenu.addEventListener("change", () => {
  state.filter = filterMenu.value;
  castAgain();
});

function say(message) {
  state.message = message;
}

const radiusSlider = document.getElementById("radius");
radiusSlider.max = String(MAX_RADIUS);
function setRadius(radius) {
  state.radius = Math.round(Math.min(MAX_RADIUS, Math.max(0.1, radius)) * 100) / 100;
  radiusSlider.value = String(state.radius);
  document.getElementById("radius-value").textContent = state.radius.toFixed(2);
}
radiusSlider.addEventListener("input", () => setRadius(Number(radiusSlider.value)));

function setPaused(paused) {
  state.paused = paused;
  const button = document.getElementById("pause");
  button.setAttribute("aria-pressed", String(paused));
  button.textContent = paused ? "resume" : "pause";
}
document.getElementById("pause").addEventListener("click", () => setPaused(!state.paused));
document.getElementById("clear-bodies").addEventListener("click", () => {
  crowd.clear();
  frames.reset();
  say("no bodies");
});
document.getElementById("ten-thousand").addEventListener("click", () => {
  const n = crowd.fill();
  frames.reset();
  say(`${n.toLocaleString("en")} bodies of radius 0.08`);
});

const layerBox = document.getElementById("layers");
for (const layer of LAYERS) {
  const label = document.createElement("label");
  const box = document.createElement("input");
  box.type = "checkbox";
  box.checked = layer.on;
  box.dataset.layer = layer.key;
  box.addEventListener("change", () => (state.layers[layer.key] = box.checked));
  label.append(box, ` ${layer.label}`);
  layerBox.append(label);
}

window.addEventListener("keydown", (event) => {
  if (event.target instanceof HTMLInputElement || event.target instanceof HTMLSelectElement) return;
  const key = event.key.toLowerCase();
  const tileKeys = { 1: 1, 2: 2, 3: 3, 4: 4, 5: 0 };
  if (key in tileKeys) chooseTool({ kind: "paint", tile: tileKeys[key] });
  else if (key === "r") chooseTool({ kind: "ray" });
  else if (key === "c") chooseTool({ kind: "circles" });
  else if (key === "e") chooseTool({ kind: "explain" });
  else if (key === "[") setRadius(state.radius - 0.05);
  else if (key === "]") setRadius(state.radius + 0.05);
  else if (key === " ") setPaused(!state.paused);
  else if (key === "f") {
    const keys = Object.keys(FILTERS);
    state.filter = keys[(keys.indexOf(state.filter) + 1) % keys.length];
    filterMenu.value = state.filter;
    castAgain();
  } else return;
  event.preventDefault();
});

// ---- drawing -----------------------------------------------------------------------------

function draw() {
  view.begin(COLORS.background);
  const ctx = view.ctx;
  if (state.layers.tiles) {
    ctx.beginPath();
    for (let row = 0; row < height; row++) {
      for (let col = 0; col < width; col++) {
        if (tiles[row][col] !== null) traceTile(ctx, tiles[row][col], col, row, 1);
      }
    }
    ctx.fillStyle = COLORS.solidFill;
    ctx.fill();
  }
  if (state.layers.grid) {
    ctx.beginPath();
    for (let col = 0; col <= width; col++) {
      ctx.moveTo(col, 0);
      ctx.lineTo(col, height);
    }
    for (let row = 0; row <= height; row++) {
      ctx.moveTo(0, row);
      ctx.lineTo(width, row);
    }
    ctx.strokeStyle = COLORS.grid;
    ctx.lineWidth = view.px(1);
    ctx.stroke();
  }
  if (mapChanged) {
    mapLines.clear();
    map.fillDebugLines(mapLines);
    mapChanged = false;
  }
  const shown = (kind) => state.layers[LAYER_OF_KIND.get(kind)];
  drawLines(view, mapLines, shown);
  const crowdKinds = CROWD_KINDS.filter(shown);
  if (crowdKinds.length > 0) {
    crowdLines.clear();
    crowdLines.setKinds(crowdKinds);
    crowd.fillDebugLines(crowdLines);
    drawLines(view, crowdLines, shown);
  }
  if (state.layers.bodies) drawBodies(ctx);
  if (state.layers.ray && state.ray) drawRay(ctx, state.ray);
  if (state.tool.kind === "explain") {
    tellStory();
    drawExplain(ctx);
  }
  showBodies();
}

function drawBodies(ctx) {
  const circles = crowd.circles();
  // A circle a few pixels across is drawn as its square: the same dot, and ten times
  // cheaper to rasterise for a crowd of 10,000 (the canvas has no GPU in the tests).
  const dots = 3 * view.dpr;
  ctx.beginPath();
  for (let i = 0; i < circles.length; i += 3) {
    const [x, y, r] = [circles[i], circles[i + 1], circles[i + 2]];
    if (r * view.scale < dots) {
      ctx.rect(x - r, y - r, 2 * r, 2 * r);
    } else {
      ctx.moveTo(x + r, y);
      ctx.arc(x, y, r, 0, Math.PI * 2);
    }
  }
  ctx.fillStyle = COLORS.body;
  ctx.fill();
  if (crowd.goal) {
    const [gx, gy] = crowd.goal;
    ctx.beginPath();
    ctx.arc(gx, gy, view.px(6), 0, Math.PI * 2);
    ctx.strokeStyle = COLORS.body;
    ctx.lineWidth = view.px(1.5);
    ctx.stroke();
  }
}

function showBodies() {
  const ms = (v) => (Number.isFinite(v) ? `${v.toFixed(2)} ms` : "–");
  document.getElementById("body-readout").textContent = [
    `bodies ${crowd.count.toLocaleString("en")}`,
    `frame  ${ms(frames?.mean)} (mean of 60)`,
    `       a step ${ms(frames?.step)}, drawing ${ms(frames?.draw)}`,
    state.message,
    crowd.blocked ?? "",
  ]
    .filter(Boolean)
    .join("\n");
}

/** The explain tool's highlights: the body clicked ringed, the cell under the mouse framed,
 * its segment nearest the mouse drawn thick (red when hidden), each end of its active
 * pieces dotted (orange: a rounded cap; green: joined). */
function drawExplain(ctx) {
  const e = state.explain;
  if (e.body !== null) {
    const circles = crowd.circles();
    const i = crowd.bodies.handles().indexOf(e.body);
    if (i >= 0) {
      ctx.beginPath();
      ctx.arc(circles[3 * i], circles[3 * i + 1], circles[3 * i + 2] + view.px(4), 0, Math.PI * 2);
      ctx.strokeStyle = COLORS.contact;
      ctx.lineWidth = view.px(2);
      ctx.stroke();
    }
  }
  if (!e.cell) return;
  const [col, row] = e.cell.cell;
  ctx.strokeStyle = COLORS.grid;
  ctx.lineWidth = view.px(1);
  ctx.strokeRect(col, row, 1, 1);
  const segment = e.segment;
  if (!segment) return;
  ctx.beginPath();
  ctx.moveTo(...segment.from);
  ctx.lineTo(...segment.to);
  ctx.strokeStyle = segment.hidden ? COLORS.rayHit : COLORS.contact;
  ctx.lineWidth = view.px(4);
  ctx.stroke();
  for (const end of segment.ends) {
    ctx.beginPath();
    ctx.arc(end.at[0], end.at[1], view.px(5), 0, Math.PI * 2);
    ctx.fillStyle = end.cap ? COLORS.platform : COLORS.entrance;
    ctx.fill();
  }
}

function drawRay(ctx, ray) {
  const hit = ray.hit;
  if (hit && hit.cell) {
    ctx.fillStyle = COLORS.cellHit;
    ctx.fillRect(hit.cell[0], hit.cell[1], 1, 1);
  }
  ctx.beginPath();
  ctx.moveTo(ray.x0, ray.y0);
  ctx.lineTo(hit ? hit.x : ray.x1, hit ? hit.y : ray.y1);
  ctx.strokeStyle = COLORS.ray;
  ctx.lineWidth = view.px(2);
  ctx.stroke();
  if (hit) {
    // The rest of the ray, past the hit, faint.
    ctx.beginPath();
    ctx.moveTo(hit.x, hit.y);
    ctx.lineTo(ray.x1, ray.y1);
    ctx.setLineDash([view.px(4), view.px(4)]);
    ctx.lineWidth = view.px(1);
    ctx.stroke();
    ctx.setLineDash([]);
    ctx.beginPath();
    ctx.moveTo(hit.x, hit.y);
    ctx.lineTo(hit.x + hit.nx * 0.8, hit.y + hit.ny * 0.8);
    ctx.strokeStyle = COLORS.normal;
    ctx.lineWidth = view.px(2);
    ctx.stroke();
    ctx.beginPath();
    ctx.arc(hit.x, hit.y, view.px(5), 0, Math.PI * 2);
    ctx.fillStyle = COLORS.rayHit;
    ctx.fill();
  }
}

// ---- start -------------------------------------------------------------------------------

async function start() {
  await init();
  map = TileMap.fromAscii(caveText);
  mapLines = new DebugLines();
  crowdLines = new DebugLines();
  // Only what the canvas shows: a flow field draws the arrows of the nodes in the map.
  crowdLines.setView([0, 0, width, height]);
  crowd = new Crowd(map);
  setRadius(state.radius);
  chooseTool(state.tool);
  frames = runFrames({
    step: () => crowd.step(),
    draw,
    view,
    // One step a frame, whatever the frame costs: the sandbox has no clock to keep, and a
    // slow frame (10,000 bodies) that ran the steps it owes would only be slower.
    maxSteps: 1,
    paused: () => state.paused,
    onError: showError,
  });
  hook.ready = true;
}

start().catch(showError);
