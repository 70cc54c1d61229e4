// What every page of the playground has around its canvas: the site's header with its
// navigation, the legend of colours, and the status line drawn over the canvas.

/** The pages, in the navigation's order. */
const PAGES = [
  ["sandbox", "Sandbox"],
  ["dungeon", "Dungeon Builder"],
  ["platformer", "Platformer"],
];

/** Fills the page's `<header>` with the site's title and navigation, `current` marked. */
export function siteHeader(current) {
  const links = PAGES.map(
    ([file, name]) =>
      `<a href="./${file}.html"${file === current ? ' aria-current="page"' : ""}>${name}</a>`,
  ).join("\n");
  document.querySelector("header").innerHTML = `<h1><a href="./index.html">tileslide playground</a></h1><nav>${links}</nav>`;
}

/** Fills `#legend` with a dot of each colour and its name: `entries` is [name, colour]. */
export function showLegend(entries) {
  document.getElementById("legend").innerHTML = entries
    .map(([name, color]) => `<div><span style="background:${color}"></span>${name}</div>`)
    .join("");
}

/** Draws `text` in a dark box at the canvas's top left (the HUD's one line). */
export function drawStatusLine(view, text) {
  const ctx = view.ctx;
  view.toScreenPixels();
  ctx.font = "bold 15px system-ui, sans-serif";
  ctx.textAlign = "left";
  ctx.textBaseline = "top";
  ctx.fillStyle = "rgba(0, 0, 0, 0.6)";
  ctx.fillRect(6, 6, ctx.measureText(text).width + 12, 24);
  ctx.fillStyle = "#fff";
  ctx.fillText(text, 12, 10);
  view.toWorldUnits();
}
