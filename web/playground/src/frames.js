// The frame loop of a page: a fixed simulation step (the games' own 60 steps a second),
// drawing once a frame, and the frame time measured as the work done in a frame (steps plus
// drawing, in milliseconds), which is what the pages show and the browser tests report.

/** How many recent frames the average frame time covers. */
const WINDOW = 60;

/** Frame times: the last one and the mean over the last `WINDOW` frames, and the same for
 * the two parts of a frame, a step (each) and the drawing. */
export class FrameTimes {
  constructor() {
    this.times = [];
    this.stepTimes = [];
    this.drawTimes = [];
    this.frames = 0;
  }

  add(ms, stepMs, steps, drawMs) {
    push(this.times, ms);
    if (steps > 0) push(this.stepTimes, stepMs / steps);
    push(this.drawTimes, drawMs);
    this.frames += 1;
  }

  /** The mean time of one step, over the last `WINDOW` frames that stepped. */
  get step() {
    return mean(this.stepTimes);
  }

  /** The mean time of drawing a frame. */
  get draw() {
    return mean(this.drawTimes);
  }

  get last() {
    return this.times.length ? this.times[this.times.length - 1] : NaN;
  }

  get mean() {
    return mean(this.times);
  }

  /** Forgets the frames so far (after the scene changes). */
  reset() {
    this.times = [];
    this.stepTimes = [];
    this.drawTimes = [];
  }

  /** What the hook tells a test. */
  summary() {
    return { last: this.last, mean: this.mean, step: this.step, draw: this.draw, frames: this.frames };
  }
}

function push(times, ms) {
  times.push(ms);
  if (times.length > WINDOW) times.shift();
}

function mean(times) {
  return times.length ? times.reduce((a, b) => a + b, 0) / times.length : NaN;
}

/**
 * Runs `step()` `stepsPerSecond` times a second of page time (at most `maxSteps` a frame, so a
 * slow frame slows the game rather than snowballing) and `draw()` once a frame, from
 * requestAnimationFrame. `paused()` stops the steps, not the drawing; `speed()` multiplies
 * the steps. Errors stop the loop and go to `onError`. With `view`, a resize of its canvas
 * draws at once too (the resize cleared it).
 */
export function runFrames({
  step,
  draw,
  view = null,
  stepsPerSecond = 60,
  maxSteps = 8,
  paused = () => false,
  speed = () => 1,
  onError,
}) {
  const times = new FrameTimes();
  let owed = 0;
  let before = performance.now();
  let stopped = false;
  const fail = (error) => {
    stopped = true;
    onError(error);
  };
  if (view) {
    view.onResize = () => {
      if (stopped) return;
      try {
        draw();
      } catch (error) {
        fail(error);
      }
    };
  }
  function frame(now) {
    try {
      const start = performance.now();
      let steps = 0;
      if (!paused()) {
        // A frame's timestamp can precede the time the loop started: no steps owed then.
        owed += Math.min((Math.max(0, now - before) / 1000) * stepsPerSecond * speed(), maxSteps);
        steps = Math.floor(owed);
        owed -= steps;
        for (let i = 0; i < steps; i++) step();
      }
      before = now;
      const drawStart = performance.now();
      draw();
      const end = performance.now();
      times.add(end - start, drawStart - start, steps, end - drawStart);
      requestAnimationFrame(frame);
    } catch (error) {
      fail(error);
    }
  }
  requestAnimationFrame(frame);
  return times;
}
