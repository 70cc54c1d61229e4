// The camera of a page: which part of the world the canvas shows, and the conversions
// between world units (the map's, y down), canvas pixels and the page's client pixels that
// mouse events and the browser tests use.

/** A canvas looking at a world rectangle, scaled to fit and centred. */
export class View {
  /**
   * @param {HTMLCanvasElement} canvas
   * @param {number} aspect the canvas's width over its height, kept whatever the page width
   */
  constructor(canvas, aspect) {
    this.canvas = canvas;
    this.ctx = canvas.getContext("2d");
    this.aspect = aspect;
    this.world = { x0: 0, y0: 0, x1: 1, y1: 1 };
    this.scale = 1; // device pixels per world unit
    this.ox = 0; // device pixels of world x = 0
    this.oy = 0;
    this.dpr = 1;
    this.sy = 1; // -1 when the world's y axis points up (a Replica Island level)
    /** Called after a resize has cleared the canvas, to draw it again at once. */
    this.onResize = null;
    new ResizeObserver(() => this.resize()).observe(canvas);
    this.resize();
  }

  /** Shows the world rectangle (x0, y0)–(x1, y1), with `margin` world units around it;
   * `yUp`: the world's y axis points up, so y1 is at the top. */
  frame(x0, y0, x1, y1, margin = 0, yUp = false) {
    this.world = { x0: x0 - margin, y0: y0 - margin, x1: x1 + margin, y1: y1 + margin };
    this.sy = yUp ? -1 : 1;
    this.fit();
  }

  /** Matches the canvas's pixels to its size on the page. Setting a canvas's size clears
   * it, even to the size it has, so the size is set only when it changes, and `onResize`
   * draws the canvas again before the browser shows it: otherwise it would stay empty
   * until the next animation frame. */
  resize() {
    this.dpr = window.devicePixelRatio || 1;
    const cssWidth = this.canvas.clientWidth || 800;
    const cssHeight = Math.round(cssWidth / this.aspect);
    const width = Math.round(cssWidth * this.dpr);
    const height = Math.round(cssHeight * this.dpr);
    if (this.canvas.style.height !== `${cssHeight}px`) this.canvas.style.height = `${cssHeight}px`;
    if (width === this.canvas.width && height === this.canvas.height) return;
    this.canvas.width = width;
    this.canvas.height = height;
    this.fit();
    this.onResize?.();
  }

  fit() {
    const { x0, y0, x1, y1 } = this.world;
    const w = this.canvas.width;
    const h = this.canvas.height;
    this.scale = Math.min(w / (x1 - x0), h / (y1 - y0));
    this.ox = (w - (x1 - x0) * this.scale) / 2 - x0 * this.scale;
    const top = (h - (y1 - y0) * this.scale) / 2;
    this.oy = this.sy > 0 ? top - y0 * this.scale : top + y1 * this.scale;
  }

  /** Clears the canvas to `color` and sets the transform to world units. */
  begin(color) {
    const ctx = this.ctx;
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.fillStyle = color;
    ctx.fillRect(0, 0, this.canvas.width, this.canvas.height);
    this.toWorldUnits();
  }

  /** Draws in world units from here on. */
  toWorldUnits() {
    this.ctx.setTransform(this.scale, 0, 0, this.sy * this.scale, this.ox, this.oy);
  }

  /** Draws in CSS pixels of the canvas from here on (text, the HUD). */
  toScreenPixels() {
    this.ctx.setTransform(this.dpr, 0, 0, this.dpr, 0, 0);
  }

  /** World units a line `pixels` CSS pixels wide takes. */
  px(pixels) {
    return (pixels * this.dpr) / this.scale;
  }

  /** The canvas's CSS pixel of a world point, for text drawn after `toScreenPixels()`. */
  cssAt(x, y) {
    return [(x * this.scale + this.ox) / this.dpr, (this.sy * y * this.scale + this.oy) / this.dpr];
  }

  /** CSS pixels a world unit takes. */
  get cssPerUnit() {
    return this.scale / this.dpr;
  }

  /** The world point under a mouse event (or any client coordinates). */
  worldAt(clientX, clientY) {
    const r = this.canvas.getBoundingClientRect();
    const dx = ((clientX - r.left) / r.width) * this.canvas.width;
    const dy = ((clientY - r.top) / r.height) * this.canvas.height;
    return [(dx - this.ox) / this.scale, (dy - this.oy) / (this.sy * this.scale)];
  }

  /** The client coordinates of a world point: where a test clicks to hit it. */
  clientAt(x, y) {
    const r = this.canvas.getBoundingClientRect();
    return {
      x: r.left + ((x * this.scale + this.ox) / this.canvas.width) * r.width,
      y: r.top + ((this.sy * y * this.scale + this.oy) / this.canvas.height) * r.height,
    };
  }

  /** The canvas pixel (device pixels) of a world point: where a test reads the colour. */
  pixelAt(x, y) {
    return {
      x: Math.floor(x * this.scale + this.ox),
      y: Math.floor(this.sy * y * this.scale + this.oy),
    };
  }
}
