// The test hook: `window.__tileslide` tells a browser test what the page is doing (its game
// state, its frame time) and where things are on the canvas, so that a test can play with
// real mouse and keyboard input and check what happened. Pages use nothing in it.

/**
 * Publishes the page's hook. `api` holds functions of the page (state(), clientAt(), …);
 * `ready` turns true once the package is loaded and the first frame is drawn, and `error`
 * holds the message of an error that stopped the page.
 */
export function publishHook(page, api) {
  window.__tileslide = { page, ready: false, error: null, ...api };
  return window.__tileslide;
}

/** Shows an error that stopped the page, on the page and in the hook, and rethrows it to the
 * console (where the browser tests see it). */
export function showError(error) {
  const box = document.getElementById("error");
  if (box) box.textContent = String(error && error.stack ? error.stack : error);
  if (window.__tileslide) window.__tileslide.error = String(error);
  console.error(error);
}
