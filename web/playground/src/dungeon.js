// Dungeon Builder, played in the browser: the simulation of `tileslide demo dungeon`
// (crates/tileslide-dungeon through the games package), with the keeper's orders coming
// from the mouse and keyboard, or from the keeper's script. The explain tool tells a
// fighter's last step in words, as `tileslide explain --body` does.
import init, { DungeonGame } from "../../games-pkg/tileslide_games.js";

import { COLORS } from "./colors.js";
import { runFrames } from "./frames.js";
import { publishHook, showError } from "./hook.js";
import { drawStatusLine, showLegend, siteHeader } from "./page.js";
import { View } from "./view.js";

/** The seed of `tileslide demo dungeon` (its default). */
const SEED = 1;
/** The game's fixed steps a second (tileslide_dungeon::STEPS_PER_SECOND). */
const STEPS_PER_SECOND = 30;
/** The speeds the + and − keys step through. */
const SPEEDS = [0.5, 1, 2, 4, 8];

/** What `squares()` codes mean, and their colours. */
const SQUARE_COLORS = [COLORS.floor, COLORS.unexplored, COLORS.earth, COLORS.earth, COLORS.rock];
const SQUARE = { seen: 0, unexplored: 1, diggable: 2, earth: 3, rock: 4 };
/** The fighters' colours by kind code (0 hero, 1 skeleton, 2 imp). */
const FIGHTER_COLORS = [COLORS.hero, COLORS.skeleton, COLORS.imp];
/** Floats a fighter takes in `creatures()`. */
const FIGHTER = 7;

siteHeader("dungeon");
const canvas = document.getElementById("canvas");
const view = new View(canvas, 4 / 3);
// chosen: the fighter the explain tool clicked (its id), story: its last step in words
const state = { tool: "dig", paused: false, speed: 1, message: "", chosen: null, story: null };
let game = null;
let frames = null;
let squares = null; // this frame's square codes
let box = null; // the part of the map the view shows

const hook = publishHook("dungeon", {
  state: () =>
    game && {
      ...game.state,
      tool: state.tool,
      paused: state.paused,
      speed: state.speed,
      message: state.message,
      chosen: state.chosen,
      story: state.story,
      hash: game.stateHash(),
      width: game.width,
      height: game.height,
      frame: frames && frames.summary(),
    },
  square: (col, row) => game.squares()[row * game.width + col],
  diggable: () => Array.from(game.diggable()),
  treasure: () => game.treasure,
  /** The fighters, `creatures()`'s 7 floats each. */
  fighters: () => Array.from(game.creatures()),
  clientAt: (x, y) => view.clientAt(x, y),
  pixelAt: (x, y) => view.pixelAt(x, y),
});

function newGame(scripted) {
  game?.free();
  game = new DungeonGame(SEED, { scripted });
  squares = game.squares();
  game.traceCreatures(state.tool === "explain");
  state.chosen = null;
  box = null;
  reframe();
  say(scripted ? `the keeper's script plays (seed ${SEED})` : "dig out your dungeon before the heroes come");
  frames?.reset();
}

/** Squares of earth the view shows around the dungeon and the squares that can be dug. */
const FRAME_MARGIN = 4;

/** The part of the map to show: the open squares and those that can be dug, with
 * FRAME_MARGIN squares around them, inside the map; it grows as the dungeon does. */
function frameOf(codes, width, height) {
  let x0 = width;
  let y0 = height;
  let x1 = 0;
  let y1 = 0;
  for (let i = 0; i < codes.length; i++) {
    if (codes[i] > SQUARE.diggable) continue;
    const col = i % width;
    const row = Math.floor(i / width);
    x0 = Math.min(x0, col);
    y0 = Math.min(y0, row);
    x1 = Math.max(x1, col + 1);
    y1 = Math.max(y1, row + 1);
  }
  if (x0 >= x1) return { x0: 0, y0: 0, x1: width, y1: height };
  return {
    x0: Math.max(0, x0 - FRAME_MARGIN),
    y0: Math.max(0, y0 - FRAME_MARGIN),
    x1: Math.min(width, x1 + FRAME_MARGIN),
    y1: Math.min(height, y1 + FRAME_MARGIN),
  };
}

/** Frames the dungeon again when it has grown. */
function reframe() {
  const next = frameOf(squares, game.width, game.height);
  if (box && next.x0 === box.x0 && next.y0 === box.y0 && next.x1 === box.x1 && next.y1 === box.y1) return;
  box = next;
  view.frame(box.x0, box.y0, box.x1, box.y1, 0.5);
}

function say(message) {
  state.message = message;
  document.getElementById("message").textContent = message;
}

// ---- input -----------------------------------------------------------------------------

canvas.addEventListener("pointerdown", (event) => {
  if (event.button !== 0 || !game) return;
  canvas.focus();
  const [x, y] = view.worldAt(event.clientX, event.clientY);
  const col = Math.floor(x);
  const row = Math.floor(y);
  // The game refuses what it cannot do (rock, no gold, no room, the script plays) with an
  // Error naming why: shown to the player, not a failure of the page.
  if (state.tool === "explain") {
    state.chosen = game.creatureAt(x, y);
    tellStory();
    return;
  }
  try {
    if (state.tool === "dig") {
      game.dig(col, row);
      say(`dug square (${col}, ${row})`);
    } else {
      game.summon(state.tool, x, y);
      say(`summoned ${state.tool === "imp" ? "an imp" : "a skeleton"}`);
    }
  } catch (error) {
    say(error.message);
  }
  squares = game.squares();
});

/** Shows the chosen fighter's last step (asked again each frame: it follows the steps). */
function tellStory() {
  const story = state.chosen === null ? null : game.storyOf(state.chosen);
  if (story === state.story && story !== null) return;
  state.story = story;
  let text = "choose the explain tool (E) and click a fighter";
  if (state.tool === "explain") {
    text = state.chosen === null ? "click a fighter for its last step" : story ?? `fighter ${state.chosen}: gone`;
  }
  document.getElementById("story").textContent = text;
}

function chooseTool(tool) {
  if (game) game.traceCreatures(tool === "explain");
  if (tool !== "explain") state.chosen = null;
  state.tool = tool;
  if (game) tellStory();
  for (const button of document.querySelectorAll("#tools button")) {
    button.setAttribute("aria-pressed", String(button.dataset.tool === tool));
  }
}

function setPaused(paused) {
  state.paused = paused;
  const button = document.getElementById("pause");
  button.setAttribute("aria-pressed", String(paused));
  button.textContent = paused ? "resume" : "pause";
}

function changeSpeed(by) {
  const i = Math.min(SPEEDS.length - 1, Math.max(0, SPEEDS.indexOf(state.speed) + by));
  state.speed = SPEEDS[i];
  document.getElementById("speed").textContent = `${state.speed}×`;
}

for (const button of document.querySelectorAll("#tools button")) {
  button.addEventListener("click", () => chooseTool(button.dataset.tool));
}
document.getElementById("pause").addEventListener("click", () => setPaused(!state.paused));
document.getElementById("slower").addEventListener("click", () => changeSpeed(-1));
document.getElementById("faster").addEventListener("click", () => changeSpeed(1));
document.getElementById("new-game").addEventListener("click", () => newGame(false));
document.getElementById("scripted").addEventListener("click", () => newGame(true));

window.addEventListener("keydown", (event) => {
  if (event.target instanceof HTMLInputElement || event.target instanceof HTMLSelectElement) return;
  const key = event.key.toLowerCase();
  if (key === "d") chooseTool("dig");
  else if (key === "i") chooseTool("imp");
  else if (key === "s") chooseTool("skeleton");
  else if (key === "e") chooseTool("explain");
  else if (key === " ") setPaused(!state.paused);
  else if (key === "+" || key === "=") changeSpeed(1);
  else if (key === "-") changeSpeed(-1);
  else return;
  event.preventDefault();
});

// ---- drawing -----------------------------------------------------------------------------

showLegend([
  ["hero", COLORS.hero],
  ["imp", COLORS.imp],
  ["skeleton", COLORS.skeleton],
  ["fireball", COLORS.fireball],
  ["treasure", COLORS.treasure],
  ["not explored by heroes", COLORS.unexplored],
  ["floor", COLORS.floor],
  ["earth (50: can be dug)", COLORS.earth],
  ["rock", COLORS.rock],
  ["entrance and exit", COLORS.entrance],
]);

function draw() {
  const ctx = view.ctx;
  const width = game.width;
  squares = game.squares();
  reframe();
  view.begin(COLORS.rock);
  for (let code = 0; code < SQUARE_COLORS.length; code++) {
    ctx.beginPath();
    for (let i = 0; i < squares.length; i++) {
      if (squares[i] === code) ctx.rect(i % width, Math.floor(i / width), 1, 1);
    }
    ctx.fillStyle = SQUARE_COLORS[code];
    ctx.fill();
  }
  // The walls: the map's active segments.
  const segments = game.segments();
  ctx.beginPath();
  for (let i = 0; i < segments.length; i += 7) {
    ctx.moveTo(segments[i], segments[i + 1]);
    ctx.lineTo(segments[i + 2], segments[i + 3]);
  }
  ctx.strokeStyle = COLORS.rock;
  ctx.lineWidth = view.px(2);
  ctx.stroke();
  const [ex, ey] = game.exit;
  ctx.fillStyle = COLORS.entrance;
  ctx.fillRect(ex - 0.35, ey - 0.35, 0.7, 0.7);
  const s = game.state;
  const [tx, ty] = game.treasure;
  if (s.treasureLeft > 0) {
    ctx.beginPath();
    ctx.arc(tx, ty, 0.25 + 0.06 * s.treasureLeft, 0, Math.PI * 2);
    ctx.fillStyle = COLORS.treasure;
    ctx.fill();
  }
  drawFighters(ctx, game.creatures());
  if (state.tool === "explain") tellStory();
  const fireballs = game.fireballs();
  ctx.beginPath();
  for (let i = 0; i < fireballs.length; i += 3) {
    ctx.moveTo(fireballs[i] + fireballs[i + 2], fireballs[i + 1]);
    ctx.arc(fireballs[i], fireballs[i + 1], fireballs[i + 2], 0, Math.PI * 2);
  }
  ctx.fillStyle = COLORS.fireball;
  ctx.fill();
  drawText(ctx, squares, width, s);
  showHud(s);
}

function drawFighters(ctx, fighters) {
  for (let kind = 0; kind < FIGHTER_COLORS.length; kind++) {
    ctx.beginPath();
    for (let i = 0; i < fighters.length; i += FIGHTER) {
      if (fighters[i + 3] !== kind) continue;
      ctx.moveTo(fighters[i] + fighters[i + 2], fighters[i + 1]);
      ctx.arc(fighters[i], fighters[i + 1], fighters[i + 2], 0, Math.PI * 2);
    }
    ctx.fillStyle = FIGHTER_COLORS[kind];
    ctx.fill();
  }
  for (let i = 0; i < fighters.length; i += FIGHTER) {
    const [x, y, r] = [fighters[i], fighters[i + 1], fighters[i + 2]];
    if (fighters[i + 6] > 0) {
      ctx.beginPath();
      ctx.arc(x, y, r * 0.45, 0, Math.PI * 2);
      ctx.fillStyle = COLORS.treasure;
      ctx.fill();
    }
    // Health bar above the fighter.
    const hp = fighters[i + 5];
    ctx.fillStyle = "#000";
    ctx.fillRect(x - r, y - r - 0.22, 2 * r, 0.12);
    ctx.fillStyle = hp > 0.5 ? "#5fd35f" : hp > 0.25 ? "#e0b341" : "#ff4d4d";
    ctx.fillRect(x - r, y - r - 0.22, 2 * r * hp, 0.12);
  }
}

/** The dig costs on the squares that can be dug, and the HUD's first line, in CSS pixels. */
function drawText(ctx, codes, width, s) {
  view.toScreenPixels();
  const size = Math.max(8, Math.min(14, view.cssPerUnit * 0.45));
  ctx.font = `${size}px system-ui, sans-serif`;
  ctx.textAlign = "center";
  ctx.textBaseline = "middle";
  ctx.fillStyle = "rgba(255, 235, 200, 0.75)";
  if (!s.scripted && !s.over) {
    for (let i = 0; i < codes.length; i++) {
      if (codes[i] !== SQUARE.diggable) continue;
      const [x, y] = view.cssAt((i % width) + 0.5, Math.floor(i / width) + 0.5);
      ctx.fillText("50", x, y);
    }
  }
  view.toWorldUnits();
  drawStatusLine(
    view,
    `${clock(s.time)}   wave ${s.wave}   gold ${s.gold}   heroes ${s.heroesAlive}   ` +
      `creatures ${s.creaturesAlive}   treasure ${s.treasureLeft}` +
      (s.over ? `   — ${s.outcome === "won" ? "the dungeon holds" : "the treasure is gone"}` : "") +
      (state.paused ? "   (paused)" : ""),
  );
}

function clock(seconds) {
  const m = Math.floor(seconds / 60);
  const sec = Math.floor(seconds % 60);
  return `${m}:${String(sec).padStart(2, "0")}`;
}

function showHud(s) {
  const next = s.nextWaveIn === null ? "none" : `${Math.ceil(s.nextWaveIn)} s`;
  document.getElementById("hud").textContent = [
    `time      ${clock(s.time)}  (${state.speed}×)`,
    `gold      ${s.gold}`,
    `wave      ${s.wave}, next in ${next}`,
    `heroes    ${s.heroesAlive} alive, ${s.heroesLost} slain, ${s.heroesEscaped} escaped`,
    `creatures ${s.creaturesAlive} alive, ${s.creaturesLost} lost`,
    `treasure  ${s.treasureLeft} left, ${s.treasureStolen} stolen`,
    `dug       ${s.squaresDug} squares`,
    `outcome   ${s.outcome}${s.scripted ? " (scripted keeper)" : ""}`,
    `hash      ${game.stateHash()}`,
  ].join("\n");
}

// ---- start -------------------------------------------------------------------------------

async function start() {
  await init();
  newGame(false);
  chooseTool("dig");
  frames = runFrames({
    step: () => {
      if (!game.state.over) game.step();
    },
    draw,
    view,
    stepsPerSecond: STEPS_PER_SECOND,
    paused: () => state.paused,
    speed: () => state.speed,
    onError: showError,
  });
  hook.ready = true;
}

start().catch(showError);
