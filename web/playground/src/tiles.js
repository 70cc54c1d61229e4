// The tiles of an ASCII map (the ids `tileslide::io::ascii` gives them) and their filled
// shapes, cell-local with y down, for drawing a map's solid parts under its debug lines.

/** The tile ids of `io::ascii`: `#`, `/`, `\`, `=`. */
export const TILE = { solid: 1, rampUpRight: 2, rampDownRight: 3, oneWay: 4 };

/** Each tile's name, as the pages show it. */
export const TILE_NAMES = {
  [TILE.solid]: "square",
  [TILE.rampUpRight]: "ramp / (rising right)",
  [TILE.rampDownRight]: "ramp \\ (falling right)",
  [TILE.oneWay]: "one-way platform",
};

/** The tile id of an ASCII map character, `null` for empty. */
export function tileOfChar(c) {
  switch (c) {
    case "#":
      return TILE.solid;
    case "/":
      return TILE.rampUpRight;
    case "\\":
      return TILE.rampDownRight;
    case "=":
      return TILE.oneWay;
    default:
      return null;
  }
}

/** The rows of tile ids (or `null`) of an ASCII map, skipping `;` comment lines, padded
 * to the longest row, as `io::ascii` reads it. */
export function tilesOfAscii(text) {
  const lines = text
    .replace(/^\uFEFF/, "")
    .split(/\r?\n/)
    .filter((line) => !line.startsWith(";"));
  while (lines.length && lines[lines.length - 1] === "") lines.pop();
  const width = Math.max(...lines.map((line) => line.length));
  return lines.map((line) => Array.from({ length: width }, (_, col) => tileOfChar(line[col])));
}

/** Traces the filled shape of tile `id` in cell (`col`, `row`) of size `cell`. */
export function traceTile(ctx, id, col, row, cell) {
  const x = col * cell;
  const y = row * cell;
  switch (id) {
    case TILE.solid:
      ctx.rect(x, y, cell, cell);
      break;
    case TILE.rampUpRight:
      ctx.moveTo(x, y + cell);
      ctx.lineTo(x + cell, y + cell);
      ctx.lineTo(x + cell, y);
      ctx.closePath();
      break;
    case TILE.rampDownRight:
      ctx.moveTo(x, y);
      ctx.lineTo(x, y + cell);
      ctx.lineTo(x + cell, y + cell);
      ctx.closePath();
      break;
    case TILE.oneWay:
      ctx.rect(x, y, cell, cell * 0.2);
      break;
    default:
      break;
  }
}
