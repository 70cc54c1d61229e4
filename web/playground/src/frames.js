// The frame loop of a page: a fixed simulation step (the games' own 60 steps a second),
// drawing once a frame, and the frame time measured as the work done in a frame (steps plus
// drawing, in milliseconds), which is what the pages show and the browser tests report.

/** How many recent frames the average frame time covers. */
const WINDOW = 60;

/** Frame times: the last one and the mean over the last `WINDOW` frames. */
export class FrameTimes {
  constructor() {
    this.times = [];
    this.frames = 0;
  }

  add(ms) {
    this.times.push(ms);
    if (this.times.length > WINDOW) this.times.shift();
    this.frames += 1;
  }

  get last() {
    return this.times.length ? this.times[this.times.length - 1] : NaN;
  }

  get mean() {
    if (!this.times.length) return NaN;
    return this.times.reduce((a, b) => a + b, 0) / this.times.length;
  }

  /** Forgets the frames so far (after the scene changes). */
  reset() {
    this.times = [];
  }
}

/**
 * Runs `step()` `stepsPerSecond` times a second of page time (at most `maxSteps` a frame, so a
 * slow frame slows the game rather than snowballing) and `draw()` once a frame, from
 * requestAnimationFrame. `paused()` stops the steps, not the drawing; `speed()` multiplies
 * the steps. Errors stop the loop and go to `onError`.
 */
export function runFrames({
  step,
  draw,
  stepsPerSecond = 60,
  maxSteps = 8,
  paused = () => false,
  speed = () => 1,
  onError,
}) {
  const times = new FrameTimes();
  let owed = 0;
  let before = performance.now();
  function frame(now) {
    try {
      const start = performance.now();
      if (!paused()) {
        owed += Math.min(((now - before) / 1000) * stepsPerSecond * speed(), maxSteps);
        let steps = Math.floor(owed);
        owed -= steps;
        while (steps-- > 0) step();
      }
      before = now;
      draw();
      times.add(performance.now() - start);
      requestAnimationFrame(frame);
    } catch (error) {
      onError(error);
    }
  }
  requestAnimationFrame(frame);
  return times;
}
