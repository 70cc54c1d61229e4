// What every browser test shares: the built playground served on a free loopback port
// (Vite's preview server over playground/dist, which `npm run test:browser` builds first),
// Debian's Chromium driven by playwright-core (never a downloaded browser), a page opened
// with every console error and uncaught exception collected, and the page's test hook.
import { existsSync, mkdirSync } from "node:fs";
import { after, before } from "node:test";
import { fileURLToPath } from "node:url";
import { chromium } from "playwright-core";
import { preview } from "vite";

const web = fileURLToPath(new URL("../../", import.meta.url));
const config = `${web}playground/vite.config.js`;
const dist = `${web}playground/dist`;

/** Where the screenshots of the pages go: web/test-results/ (ignored by git), or the
 * committed docs/pictures/ when TILESLIDE_UPDATE_PICTURES=1 asks to update those. */
export const PICTURES = fileURLToPath(
  new URL(process.env.TILESLIDE_UPDATE_PICTURES === "1" ? "../../../docs/pictures/" : "../../test-results/", import.meta.url),
);

/** The Chromium to drive: TILESLIDE_CHROMIUM, else Debian's. */
const CHROMIUM = process.env.TILESLIDE_CHROMIUM || "/usr/bin/chromium";

/** Chromium's flags on a machine with no network and no GPU, run as root: no sandbox, no
 * GPU, and none of the background connections that a closed network refuses. Playwright
 * adds a fresh --user-data-dir of its own for every launch. */
const FLAGS = [
  "--no-sandbox",
  "--disable-gpu",
  "--disable-quic",
  "--no-first-run",
  "--disable-background-networking",
  "--disable-component-update",
  "--disable-sync",
];

/** The size of the browser window, which the screenshots take. */
export const VIEWPORT = { width: 1280, height: 800 };

/**
 * Serves the built playground and starts Chromium; `close()` stops both.
 * @returns {Promise<{url: string, browser: import("playwright-core").Browser, close: () => Promise<void>}>}
 */
export async function startPlayground() {
  if (!existsSync(`${dist}/index.html`)) {
    throw new Error(`${dist} is missing: build the playground first (npm run build:playground)`);
  }
  if (!existsSync(CHROMIUM)) {
    throw new Error(
      `no Chromium at ${CHROMIUM}: install Debian's (apt-get install chromium) or set TILESLIDE_CHROMIUM`,
    );
  }
  const server = await preview({
    configFile: config,
    logLevel: "warn",
    preview: { host: "127.0.0.1", port: 0, strictPort: false, open: false },
  });
  const address = server.httpServer.address();
  const url = `http://127.0.0.1:${address.port}/`;
  const browser = await chromium.launch({ executablePath: CHROMIUM, headless: true, args: FLAGS });
  return {
    url,
    browser,
    async close() {
      await browser.close();
      await server.close();
    },
  };
}

/**
 * Opens page `name` (sandbox, dungeon, platformer) and waits until its hook says it is
 * ready and it has drawn a frame. `errors` collects every console error and uncaught
 * exception of the page: a test asserts it is empty.
 */
export async function openPage(site, name) {
  const page = await site.browser.newPage({ viewport: VIEWPORT });
  const errors = [];
  page.on("console", (message) => {
    if (message.type() === "error") errors.push(`console.error: ${message.text()}`);
  });
  page.on("pageerror", (error) => errors.push(`uncaught: ${error.stack || error}`));
  page.on("response", (response) => {
    if (response.status() >= 400) errors.push(`HTTP ${response.status()}: ${response.url()}`);
  });
  page.on("requestfailed", (request) =>
    errors.push(`request failed: ${request.url()} (${request.failure()?.errorText})`),
  );
  await page.goto(`${site.url}${name}.html`);
  try {
    await page.waitForFunction(
      () => {
        const hook = window.__tileslide;
        return hook && (hook.error || (hook.ready && hook.state().frame?.frames > 0));
      },
      null,
      { timeout: 20_000 },
    );
  } catch (error) {
    throw new Error(`${name} did not start: ${errors.join("\n") || error.message}`);
  }
  return { page, errors };
}

/**
 * The setup of a test file: before its tests, the playground served, Chromium started and
 * page `name` opened; after them, both stopped. The returned object's `page` and `errors`
 * are set once the page is open.
 */
export function usePage(name) {
  const session = { site: null, page: null, errors: null };
  before(async () => {
    session.site = await startPlayground();
    Object.assign(session, await openPage(session.site, name));
  });
  after(async () => {
    await session.site?.close();
  });
  return session;
}

/** The page's state through its hook. */
export function stateOf(page) {
  return page.evaluate(() => window.__tileslide.state());
}

/** The client coordinates of world point (x, y) on the page's canvas. */
export function clientAt(page, x, y) {
  return page.evaluate(([x, y]) => window.__tileslide.clientAt(x, y), [x, y]);
}

/** The RGBA colour of the canvas pixel that shows world point (x, y). */
export function colorAt(page, x, y) {
  return page.evaluate(([x, y]) => {
    const canvas = document.getElementById("canvas");
    const { x: px, y: py } = window.__tileslide.pixelAt(x, y);
    return Array.from(canvas.getContext("2d").getImageData(px, py, 1, 1).data);
  }, [x, y]);
}

/** `#rrggbb` as [r, g, b, 255]. */
export function rgba(hex) {
  const n = parseInt(hex.slice(1), 16);
  return [(n >> 16) & 255, (n >> 8) & 255, n & 255, 255];
}

/** Waits `frames` animation frames of the page. */
export function waitFrames(page, frames) {
  return page.evaluate(
    (n) =>
      new Promise((resolve) => {
        const tick = () => (n-- <= 0 ? resolve() : requestAnimationFrame(tick));
        requestAnimationFrame(tick);
      }),
    frames,
  );
}

/** Saves a screenshot of the page as `file` in `PICTURES`. */
export async function screenshot(page, file) {
  mkdirSync(PICTURES, { recursive: true });
  await page.screenshot({ path: `${PICTURES}${file}` });
}
