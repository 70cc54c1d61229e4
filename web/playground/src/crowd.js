// The Sandbox's circles: bodies of the package that flow to one goal (the mouse) along a
// flow field for their radius, sliding around each other and along the walls. One
// `Bodies` holds them all; one `FlowField` a radius leads them.
import { Bodies, FlowField, NavGrid } from "../../playground-pkg/tileslide.js";

/** How far a circle moves a step, in cells (the crowd scene's 0.05: 3 cells a second). */
const SPEED = 0.05;
/** The widest circle the navigation grid serves, in cells. */
export const MAX_RADIUS = 0.9;
/** The most circles whose direction a step asks the flow field for with `directions`,
 * which looks ahead along the way for the farthest point in a clear straight line (tens of
 * microseconds a point). A larger crowd (the "10,000 bodies") asks `latticeDirections`
 * instead, a few array reads a point that steer along the lattice's moves and leave the
 * corners to the resolver: every circle gets a new direction every step either way. */
const LOOKAHEAD_CROWD = 256;
/** The "10,000 bodies" button's count, radius and lattice spacing. */
const MANY = { count: 10_000, radius: 0.08, spacing: 0.2 };

/** Circles flowing to a goal over one map. */
export class Crowd {
  /** @param {import("../../playground-pkg/tileslide.js").TileMap} map */
  constructor(map) {
    this.map = map;
    this.bodies = new Bodies();
    this.nav = new NavGrid(map, { maxRadius: MAX_RADIUS });
    this.fields = new Map(); // radius → FlowField
    this.radii = new Map(); // handle → radius
    this.goal = null; // [x, y] on the navigation lattice
    this.moves = new Float32Array(0); // each body's move this step
    this.groups = null; // radius → {indices, points}, made again when bodies come or go
    this.blocked = null; // why the circles of some radius cannot follow the goal
    this.tracing = false; // whether the steps are traced for `storyOf`
  }

  /** Traces the steps from now on (`on`), for `storyOf`, or stops. The trace records every
   * body's passes and contacts, so the sandbox asks for it only while its explain tool is
   * chosen. */
  trace(on) {
    this.tracing = on;
    this.bodies.traceNextSteps(on);
  }

  /** The last traced step of body `handle` in words, or null (not traced, or the body came
   * after the step). */
  storyOf(handle) {
    return this.bodies.contains(handle) ? this.bodies.storyOf(handle) : null;
  }

  /** The handle of the body under (`x`, `y`) (the nearest whose circle holds it), or null. */
  bodyAt(x, y) {
    const circles = this.circles();
    const handles = this.bodies.handles();
    let best = null;
    let bestDistance = Infinity;
    for (let i = 0; i < handles.length; i++) {
      const d = Math.hypot(circles[3 * i] - x, circles[3 * i + 1] - y);
      if (d <= circles[3 * i + 2] && d < bestDistance) {
        best = handles[i];
        bestDistance = d;
      }
    }
    return best;
  }

  get count() {
    return this.bodies.count;
  }

  /** Drops a circle of `radius` at (`x`, `y`); false (and nothing added) where it does not
   * fit clear of the walls. */
  drop(x, y, radius) {
    if (!this.nav.fits(this.map, x, y, radius)) return false;
    const handle = this.bodies.addCircle(x, y, radius);
    this.radii.set(handle, radius);
    this.groups = null;
    return true;
  }

  /** Removes every circle. */
  clear() {
    this.bodies.free();
    this.bodies = new Bodies();
    this.bodies.traceNextSteps(this.tracing);
    this.radii.clear();
    this.groups = null;
  }

  /** Fills the map with `MANY.count` small circles, evenly over the lattice points where
   * one fits; returns how many it placed. */
  fill() {
    this.clear();
    const free = [];
    const { width, height } = this.map;
    for (let y = MANY.spacing / 2; y < height; y += MANY.spacing) {
      for (let x = MANY.spacing / 2; x < width; x += MANY.spacing) {
        if (this.nav.fits(this.map, x, y, MANY.radius)) free.push(x, y);
      }
    }
    const n = Math.min(MANY.count, free.length / 2);
    for (let i = 0; i < n; i++) {
      const k = Math.floor((i * free.length) / 2 / n);
      const handle = this.bodies.addCircle(free[2 * k], free[2 * k + 1], MANY.radius);
      this.radii.set(handle, MANY.radius);
    }
    this.groups = null;
    return n;
  }

  /** Leads the circles to (`x`, `y`) from now on. */
  setGoal(x, y) {
    // The lattice has a node every half cell: a new field only when the goal's node moves.
    const goal = [Math.round(x * 2) / 2, Math.round(y * 2) / 2];
    if (this.goal && goal[0] === this.goal[0] && goal[1] === this.goal[1]) return;
    this.goal = goal;
    this.blocked = null;
    for (const field of this.fields.values()) field?.free();
    this.fields.clear();
  }

  /** After a tile edit: the navigation grid and the fields catch up with the map. */
  mapChanged() {
    this.nav.sync(this.map);
    // A field made for a goal in a wall, or whose goal the edit walled in, is made anew.
    for (const field of this.fields.values()) field?.free();
    this.fields.clear();
  }

  /** The field for circles of `radius`, made on first use for the current goal; `null`
   * when the goal is where such a circle cannot be (in a wall): they wait. */
  field(radius) {
    if (!this.fields.has(radius)) {
      let field = null;
      try {
        field = new FlowField(this.nav, this.map, this.goal[0], this.goal[1], radius);
      } catch (error) {
        // The package names why (a goal in a wall for this radius): they wait, and the
        // page shows why.
        this.blocked = error.message;
      }
      this.fields.set(radius, field);
    }
    return this.fields.get(radius);
  }

  /** One step: each circle proposes a move along its field, then all are resolved together
   * against each other and the map. */
  step() {
    const handles = this.bodies.handles();
    if (handles.length === 0) return;
    if (this.moves.length !== 2 * handles.length) this.moves = new Float32Array(2 * handles.length);
    if (this.goal) {
      const positions = this.bodies.positions();
      this.groups ??= this.byRadius(handles);
      const cheap = handles.length > LOOKAHEAD_CROWD;
      for (const [radius, group] of this.groups) {
        const field = this.field(radius);
        if (!field) {
          for (const body of group.indices) this.moves[2 * body] = this.moves[2 * body + 1] = 0;
          continue;
        }
        const points = group.points;
        group.indices.forEach((body, i) => {
          points[2 * i] = positions[2 * body];
          points[2 * i + 1] = positions[2 * body + 1];
        });
        const directions = cheap
          ? field.latticeDirections(this.nav, this.map, points)
          : field.directions(this.nav, this.map, points);
        group.indices.forEach((body, i) => {
          const dx = directions[2 * i];
          const dy = directions[2 * i + 1];
          // NaN: at the goal, or no way there.
          const go = Number.isFinite(dx) && Number.isFinite(dy);
          this.moves[2 * body] = go ? dx * SPEED : 0;
          this.moves[2 * body + 1] = go ? dy * SPEED : 0;
        });
      }
    } else {
      this.moves.fill(0);
    }
    this.bodies.proposeMany(handles, this.moves);
    return this.bodies.step(this.map);
  }

  /** Adds the bodies' debug lines (their circles and, after a step, the broadphase boxes
   * they are filed under; the resolver keeps no contacts between bodies, so there are none)
   * and each flow field's arrows to `out`, of the kinds `out` takes. */
  fillDebugLines(out) {
    this.bodies.fillDebugLines(out);
    for (const field of this.fields.values()) field?.fillDebugLines(this.nav, out);
  }

  /** The indices (into `handles`) of the circles of each radius, with room for their
   * points. */
  byRadius(handles) {
    const groups = new Map();
    for (let i = 0; i < handles.length; i++) {
      const radius = this.radii.get(handles[i]);
      if (!groups.has(radius)) groups.set(radius, []);
      groups.get(radius).push(i);
    }
    return new Map(
      [...groups].map(([radius, indices]) => [radius, { indices, points: new Float32Array(2 * indices.length) }]),
    );
  }

  /** Every circle as x, y, r (3 floats each), for drawing. */
  circles() {
    const handles = this.bodies.handles();
    const positions = this.bodies.positions();
    const out = new Float32Array(3 * handles.length);
    for (let i = 0; i < handles.length; i++) {
      out[3 * i] = positions[2 * i];
      out[3 * i + 1] = positions[2 * i + 1];
      out[3 * i + 2] = this.radii.get(handles[i]);
    }
    return out;
  }
}
