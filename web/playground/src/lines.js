// Drawing a `DebugLines` buffer of the package on a canvas: its segments, circles, points
// and boxes (typed arrays of coordinates with a `DebugKind` number each), one path and one
// stroke or fill per kind, in the colours of `colors.js`. Which kinds are drawn is the
// page's layers.
import { DebugKind } from "../../playground-pkg/tileslide.js";

import { COLORS } from "./colors.js";

/** How each `DebugKind` is drawn (by name): colour, line width in CSS pixels, dashes, and
 * whether circles are filled. */
const STYLE_LIST = [
  { name: "ActiveSegment", color: COLORS.activeSegment, width: 2 },
  { name: "OneWaySegment", color: COLORS.oneWaySegment, width: 2 },
  { name: "Normal", color: COLORS.normal, width: 1 },
  { name: "HiddenSegment", color: COLORS.hiddenSegment, width: 1, dash: [3, 3] },
  { name: "TemporarySegment", color: COLORS.temporarySegment, width: 3 },
  { name: "Body", color: COLORS.body, width: 1, fill: true },
  { name: "Character", color: COLORS.player, width: 2 },
  { name: "Contact", color: COLORS.contact, width: 2 },
  { name: "Ray", color: COLORS.ray, width: 1 },
  { name: "RayHit", color: COLORS.rayHit, width: 1 },
  { name: "AttackVolume", color: COLORS.fireball, width: 1 },
  { name: "VulnerabilityVolume", color: COLORS.hero, width: 1 },
  { name: "Hit", color: COLORS.rayHit, width: 1 },
  { name: "RefusedHit", color: COLORS.refusedHit, width: 1 },
  { name: "Path", color: COLORS.path, width: 2 },
  { name: "FlowArrow", color: COLORS.flow, width: 1 },
  { name: "BroadphaseBox", color: COLORS.broadphase, width: 1 },
];

/** The styles by kind number (the package's `DebugKind`, the core's numbers). */
const STYLES = [];
for (const style of STYLE_LIST) STYLES[DebugKind[style.name]] = style;

/** The kinds' numbers by name: the package's `DebugKind`. */
export const KIND = DebugKind;

function begin(ctx, view, style) {
  ctx.strokeStyle = style.color;
  ctx.fillStyle = style.color;
  ctx.lineWidth = view.px(style.width);
  ctx.setLineDash(style.dash ? style.dash.map((d) => view.px(d)) : []);
  ctx.beginPath();
}

/**
 * Draws `lines` (a `DebugLines`) on `view`'s canvas in world units, the kinds for which
 * `shown(kind)` is true. The typed arrays are read once (each getter copies out of wasm
 * memory).
 */
export function drawLines(view, lines, shown) {
  const ctx = view.ctx;
  const segments = lines.segments;
  const segmentKinds = lines.segmentKinds;
  const circles = lines.circles;
  const circleKinds = lines.circleKinds;
  const points = lines.points;
  const pointKinds = lines.pointKinds;
  const boxes = lines.boxes;
  const boxKinds = lines.boxKinds;
  for (let kind = 0; kind < STYLES.length; kind++) {
    const style = STYLES[kind];
    if (!style || !shown(kind)) continue;
    begin(ctx, view, style);
    let strokes = false;
    for (let i = 0; i < segmentKinds.length; i++) {
      if (segmentKinds[i] !== kind) continue;
      ctx.moveTo(segments[4 * i], segments[4 * i + 1]);
      ctx.lineTo(segments[4 * i + 2], segments[4 * i + 3]);
      strokes = true;
    }
    for (let i = 0; i < boxKinds.length; i++) {
      if (boxKinds[i] !== kind) continue;
      const x = boxes[4 * i];
      const y = boxes[4 * i + 1];
      ctx.rect(x, y, boxes[4 * i + 2] - x, boxes[4 * i + 3] - y);
      strokes = true;
    }
    if (strokes) ctx.stroke();
    begin(ctx, view, style);
    let shapes = false;
    for (let i = 0; i < circleKinds.length; i++) {
      if (circleKinds[i] !== kind) continue;
      const x = circles[3 * i];
      const y = circles[3 * i + 1];
      ctx.moveTo(x + circles[3 * i + 2], y);
      ctx.arc(x, y, circles[3 * i + 2], 0, Math.PI * 2);
      shapes = true;
    }
    if (shapes) {
      if (style.fill) ctx.fill();
      else ctx.stroke();
    }
    begin(ctx, view, style);
    let marks = false;
    const r = view.px(4);
    for (let i = 0; i < pointKinds.length; i++) {
      if (pointKinds[i] !== kind) continue;
      ctx.moveTo(points[2 * i] + r, points[2 * i + 1]);
      ctx.arc(points[2 * i], points[2 * i + 1], r, 0, Math.PI * 2);
      marks = true;
    }
    if (marks) ctx.fill();
  }
  ctx.setLineDash([]);
}
