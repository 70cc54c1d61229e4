// The platformer, played in the browser: the game of `tileslide demo platformer`
// (crates/tileslide-platformer through the games package) with the player's keys instead
// of its script, on the bundled level or a Replica Island level chosen from disk. A click
// on the player tells its last move in words, as `tileslide explain --character` does.
import init, { PlatformerGame } from "../../games-pkg/tileslide_games.js";

import { COLORS } from "./colors.js";
import { runFrames } from "./frames.js";
import { publishHook, showError } from "./hook.js";
import { drawStatusLine, showLegend, siteHeader } from "./page.js";
import { View } from "./view.js";

/** The game's fixed steps a second (tileslide_platformer::STEPS_PER_SECOND). */
const STEPS_PER_SECOND = 60;
/** The most cells the view shows across; it follows the player through a wider level. */
const VIEW_CELLS = 30;
/** Floats a segment takes in `segments()`: x0, y0, x1, y1, nx, ny, flags. */
const SEGMENT = 7;
/** The one-way bit of a segment's flags. */
const ONE_WAY = 2;

/** Which key codes hold which of the game's keys. */
const KEYS = {
  ArrowLeft: "left",
  KeyA: "left",
  ArrowRight: "right",
  KeyD: "right",
  Space: "jump",
  ArrowUp: "jump",
  KeyW: "jump",
  ArrowDown: "down",
  KeyS: "down",
};

siteHeader("platformer");
const canvas = document.getElementById("canvas");
const view = new View(canvas, 16 / 9);
const held = { left: false, right: false, jump: false, down: false };
// level: null (bundled) or Replica Island bytes; story: the player's move last clicked
const state = { message: "", level: null, story: null };
let game = null;
let frames = null;
let segments = null; // the level's, fixed while it runs

const hook = publishHook("platformer", {
  state: () =>
    game && {
      ...game.state,
      name: game.name,
      up: game.up,
      cellSize: game.cellSize,
      player: Array.from(game.player()),
      platform: Array.from(game.platform()),
      coinsLeft: game.coins().length / 3,
      held: { ...held },
      message: state.message,
      story: state.story,
      frame: frames && frames.summary(),
    },
  clientAt: (x, y) => view.clientAt(x, y),
  pixelAt: (x, y) => view.pixelAt(x, y),
});

function say(message) {
  state.message = message;
  document.getElementById("message").textContent = message;
}

/** Starts the bundled level, or the Replica Island level of `state.level`. */
function restart() {
  const next = state.level
    ? PlatformerGame.fromReplicaIsland(state.level.level, state.level.tileSet)
    : new PlatformerGame();
  game?.free();
  game = next;
  // The player's moves are traced, for a click on it: one character, a few events a move.
  game.tracePlayer(true);
  segments = game.segments();
  tell(null);
  frames?.reset();
}

// ---- input -----------------------------------------------------------------------------

function onKey(event, down) {
  if (event.target instanceof HTMLInputElement) return;
  const key = KEYS[event.code];
  if (key) {
    held[key] = down;
    event.preventDefault();
  } else if (down && event.code === "KeyR") {
    restart();
    event.preventDefault();
  }
}
window.addEventListener("keydown", (event) => onKey(event, true));
window.addEventListener("keyup", (event) => onKey(event, false));
// Keys let go while the page is not looking stay held otherwise.
window.addEventListener("blur", () => Object.keys(held).forEach((k) => (held[k] = false)));

document.getElementById("restart").addEventListener("click", restart);
document.getElementById("bundled").addEventListener("click", () => {
  state.level = null;
  restart();
  say("the bundled level");
});

async function loadReplicaIsland() {
  const tileSet = document.getElementById("tile-set").files[0];
  const level = document.getElementById("level").files[0];
  if (!tileSet || !level) {
    say(`choose ${tileSet ? "a level .bin" : "collision.bin"} too`);
    return;
  }
  const bytes = {
    tileSet: new Uint8Array(await tileSet.arrayBuffer()),
    level: new Uint8Array(await level.arrayBuffer()),
  };
  // A file that is not a level (or not Replica Island's collision.bin) is refused with an
  // Error naming the file, the offset and the cause: shown, and the game goes on.
  try {
    const previous = state.level;
    state.level = bytes;
    try {
      restart();
    } catch (error) {
      state.level = previous;
      throw error;
    }
    say(`${level.name} with ${tileSet.name}`);
  } catch (error) {
    say(error.message);
  }
  canvas.focus();
}
document.getElementById("tile-set").addEventListener("change", () => loadReplicaIsland().catch(showError));
document.getElementById("level").addEventListener("change", () => loadReplicaIsland().catch(showError));

/** Shows `story` (the player's last move in words) in the panel, or the hint for null. */
function tell(story) {
  state.story = story;
  document.getElementById("story").textContent = story ?? "click the player for its last move";
}

canvas.addEventListener("pointerdown", (event) => {
  if (event.button !== 0 || !game) return;
  canvas.focus();
  const [x, y] = view.worldAt(event.clientX, event.clientY);
  const [px, py, hw, hh] = game.player();
  // A few pixels of slack round the box: it is small, and moving.
  const slack = view.px(4);
  const on = Math.abs(x - px) <= hw + slack && Math.abs(y - py) <= hh + slack;
  tell(on ? game.playerStory() : null);
});

// ---- drawing -----------------------------------------------------------------------------

showLegend([
  ["player", COLORS.player],
  ["coin", COLORS.coin],
  ["enemy (stomp it)", COLORS.enemy],
  ["moving platform", COLORS.platform],
  ["one-way platform", COLORS.oneWaySegment],
  ["goal", COLORS.goal],
]);

/** Frames the part of the level around the player: VIEW_CELLS across, inside the level. */
function follow() {
  const [minX, minY, maxX, maxY] = game.bounds();
  const cell = game.cellSize;
  const w = Math.min(maxX - minX, VIEW_CELLS * cell);
  const h = Math.min(maxY - minY, (w * 9) / 16);
  const [px, py] = game.player();
  const x0 = Math.min(Math.max(px - w / 2, minX), maxX - w);
  const y0 = Math.min(Math.max(py - h / 2, minY), maxY - h);
  view.frame(x0, y0, x0 + w, y0 + h, 0, game.up > 0);
}

function draw() {
  follow();
  const ctx = view.ctx;
  view.begin(COLORS.background);
  const [gx0, gy0, gx1, gy1] = game.goal();
  ctx.fillStyle = COLORS.goal;
  ctx.globalAlpha = 0.35;
  ctx.fillRect(gx0, gy0, gx1 - gx0, gy1 - gy0);
  ctx.globalAlpha = 1;
  for (const oneWay of [false, true]) {
    ctx.beginPath();
    for (let i = 0; i < segments.length; i += SEGMENT) {
      if (((segments[i + 6] & ONE_WAY) !== 0) !== oneWay) continue;
      ctx.moveTo(segments[i], segments[i + 1]);
      ctx.lineTo(segments[i + 2], segments[i + 3]);
    }
    ctx.strokeStyle = oneWay ? COLORS.oneWaySegment : COLORS.activeSegment;
    ctx.lineWidth = view.px(oneWay ? 3 : 2);
    ctx.stroke();
  }
  const platform = game.platform();
  if (platform.length) {
    ctx.beginPath();
    ctx.moveTo(platform[0], platform[1]);
    ctx.lineTo(platform[2], platform[3]);
    ctx.strokeStyle = COLORS.platform;
    ctx.lineWidth = view.px(6);
    ctx.stroke();
  }
  const coins = game.coins();
  ctx.beginPath();
  for (let i = 0; i < coins.length; i += 3) {
    ctx.moveTo(coins[i] + coins[i + 2], coins[i + 1]);
    ctx.arc(coins[i], coins[i + 1], coins[i + 2], 0, Math.PI * 2);
  }
  ctx.fillStyle = COLORS.coin;
  ctx.fill();
  const enemies = game.enemies();
  ctx.fillStyle = COLORS.enemy;
  for (let i = 0; i < enemies.length; i += 4) {
    const [x, y, hw, hh] = enemies.subarray(i, i + 4);
    ctx.fillRect(x - hw, y - hh, 2 * hw, 2 * hh);
  }
  const s = game.state;
  const [x, y, hw, hh] = game.player();
  ctx.fillStyle = COLORS.player;
  // Blinks while it cannot be hurt again.
  ctx.globalAlpha = s.invulnerable && Math.floor(s.steps / 6) % 2 ? 0.4 : 1;
  ctx.fillRect(x - hw, y - hh, 2 * hw, 2 * hh);
  ctx.globalAlpha = 1;
  showHud(s);
}

function showHud(s) {
  const status = s.reachedGoal ? "goal reached!" : s.over ? "fell out (R: restart)" : "";
  const line = `${s.time.toFixed(1)} s   coins ${s.coins}/${s.coinsTotal}   enemies ${s.enemiesDefeated}/${s.enemiesTotal}   hits ${s.hitsTaken}   ${status}`;
  drawStatusLine(view, line);
  document.getElementById("hud").textContent = [
    `level    ${game.name}`,
    `time     ${s.time.toFixed(1)} s`,
    `coins    ${s.coins} of ${s.coinsTotal}`,
    `enemies  ${s.enemiesDefeated} of ${s.enemiesTotal} stomped`,
    `hits     ${s.hitsTaken} taken`,
    `jumps    ${s.jumps}`,
    `standing ${s.grounded ? "yes" : "no"}`,
    status && `         ${status}`,
  ]
    .filter(Boolean)
    .join("\n");
}

// ---- start -------------------------------------------------------------------------------

async function start() {
  await init();
  restart();
  frames = runFrames({
    step: () => {
      if (!game.state.over) game.step({ ...held });
    },
    draw,
    view,
    stepsPerSecond: STEPS_PER_SECOND,
    onError: showError,
  });
  hook.ready = true;
  canvas.focus();
}

start().catch(showError);
