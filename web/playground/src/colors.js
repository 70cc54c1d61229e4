// Colours, shared by the pages. The games take the look of the Dungeon Builder write-up:
// heroes cyan, imps pink, skeletons blue, fireballs red, squares the heroes have not
// explored yellow, the treasure gold, earth in browns (dark where it cannot be dug).

export const COLORS = {
  background: "#0d0b09",
  grid: "rgba(255, 255, 255, 0.05)",
  // The map.
  solidFill: "#4a3b2c",
  oneWayFill: "#7a6a4f",
  activeSegment: "#f2e6cf",
  oneWaySegment: "#e0b341",
  normal: "#8fd18f",
  hiddenSegment: "rgba(255, 120, 120, 0.35)",
  temporarySegment: "#f29e4c",
  // Queries and bodies.
  ray: "#ffffff",
  rayHit: "#ff4d4d",
  refusedHit: "#8a8a8a",
  body: "#6fb7ff",
  contact: "#ffe14d",
  broadphase: "rgba(120, 200, 255, 0.25)",
  flow: "rgba(255, 255, 255, 0.18)",
  path: "#b48cff",
  cellHit: "rgba(255, 77, 77, 0.25)",
  // Dungeon Builder.
  earth: "#6b4a2b",
  rock: "#2e1f12",
  floor: "#b08a5e",
  unexplored: "#e6d84a",
  hero: "#35e0e0",
  imp: "#ff6fb5",
  skeleton: "#3d6bff",
  fireball: "#ff3030",
  treasure: "#ffc400",
  entrance: "#7de37d",
  // Platformer.
  player: "#35e0e0",
  coin: "#ffc400",
  enemy: "#ff6fb5",
  goal: "#7de37d",
  platform: "#f29e4c",
};
