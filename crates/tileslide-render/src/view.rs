//! The map's world rectangle mapped onto the image's pixels.

use tileslide::{Cell, TileMap, Vec2};

use crate::{Framing, MAX_PIXELS, RenderError, RenderOptions, YAxis};

/// Width of a normal tick, as a fraction of the line width.
pub(crate) const NORMAL_WIDTH: f32 = 0.75;

/// Where world points land in the image: pixel `(0, 0)` is the top-left corner of the
/// top-left pixel, so a pixel `(x, y)` covers `[x, x + 1) × [y, y + 1)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct View {
    /// The map's origin (world position of cell (0, 0)'s corner).
    origin: Vec2,
    /// The map's cell size.
    cell: Vec2,
    /// Pixels per cell along x and y (y in proportion to the cell's shape).
    cell_pixels: Vec2,
    /// Rows in the map, to count rows from the bottom when y is up.
    rows: f32,
    y_axis: YAxis,
    /// Added to every pixel position: zero for a whole map, else what puts a framed
    /// window where it belongs in the image.
    shift: Vec2,
    width: u32,
    height: u32,
}

impl View {
    /// The view of the whole of `map` at the options' scale, or why there is none.
    pub fn new(map: &TileMap, options: &RenderOptions) -> Result<Self, RenderError> {
        let scale = options.pixels_per_cell;
        if !(scale > 0.0 && scale.is_finite()) {
            return Err(RenderError::BadScale(scale));
        }
        let cell = map.cell_size();
        let cell_pixels = Vec2::new(scale, scale * cell.y / cell.x);
        // In f64 so that a huge map or scale is measured, not overflowed, before refusing it.
        let width = (f64::from(map.width()) * f64::from(cell_pixels.x)).round();
        let height = (f64::from(map.height()) * f64::from(cell_pixels.y)).round();
        let (width, height) = (width.max(1.0), height.max(1.0));
        // (Both are finite: the scale and the map's cell size are.)
        let fits = width * height <= MAX_PIXELS as f64;
        if !fits {
            return Err(RenderError::TooLarge {
                width: width as u64,
                height: height as u64,
            });
        }
        Ok(Self {
            origin: map.origin(),
            cell,
            cell_pixels,
            rows: map.height() as f32,
            y_axis: options.y_axis,
            shift: Vec2::ZERO,
            width: width as u32,
            height: height as u32,
        })
    }

    /// The view of `framing`'s window of `map` (see [`Framing`]), or why there is none.
    pub fn framed(
        map: &TileMap,
        options: &RenderOptions,
        framing: &Framing,
    ) -> Result<Self, RenderError> {
        let (width, height) = framing.image;
        let (vw, vh) = framing.viewport;
        let window = framing.window;
        let size = window.max - window.min;
        let usable = window.min.is_finite() && size.is_finite() && size.x > 0.0 && size.y > 0.0;
        if !usable {
            return Err(RenderError::BadFraming(
                "the window must be a finite box wider and taller than zero",
            ));
        }
        if vw == 0 || vh == 0 || vw > width || vh > height {
            return Err(RenderError::BadFraming(
                "the viewport must be at least one pixel and fit in the image",
            ));
        }
        if u64::from(width) * u64::from(height) > MAX_PIXELS {
            return Err(RenderError::TooLarge {
                width: width.into(),
                height: height.into(),
            });
        }
        let cell = map.cell_size();
        // One scale for both axes: the window fits the viewport and is centred in it.
        let per_unit = (vw as f32 / size.x).min(vh as f32 / size.y);
        let cell_pixels = cell * per_unit;
        let mut view = Self {
            origin: map.origin(),
            cell,
            cell_pixels,
            rows: map.height() as f32,
            y_axis: options.y_axis,
            shift: Vec2::ZERO,
            width,
            height,
        };
        let centre = view
            .pixel_of((window.min + window.max) * 0.5)
            .ok_or(RenderError::BadFraming("the window is too far out to draw"))?;
        view.shift = Vec2::new(vw as f32, vh as f32) * 0.5 - centre;
        Ok(view)
    }

    /// Image width in pixels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Image height in pixels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// Pixels per cell along x.
    pub fn pixels_per_cell(&self) -> f32 {
        self.cell_pixels.x
    }

    /// The pixel position of world point `p`, or `None` if it is not finite or too far out
    /// to have a finite pixel position.
    pub fn pixel_of(&self, p: Vec2) -> Option<Vec2> {
        self.grid_to_pixel((p - self.origin) / self.cell)
    }

    /// The pixel position of the tile-local point `local` of `cell`. Computed from the grid
    /// position rather than the world position so that neighbouring cells' shared edges land
    /// on exactly the same pixel coordinates (no hairline seams between filled cells).
    pub fn cell_point(&self, cell: Cell, local: Vec2) -> Option<Vec2> {
        let grid = Vec2::new(cell.col as f32, cell.row as f32) + local / self.cell;
        self.grid_to_pixel(grid)
    }

    /// A direction in the world (a normal) as a unit direction in the image.
    pub fn pixel_direction(&self, d: Vec2) -> Option<Vec2> {
        let d = d / self.cell * self.cell_pixels;
        let d = match self.y_axis {
            YAxis::Down => d,
            YAxis::Up => Vec2::new(d.x, -d.y),
        };
        d.try_normalize()
    }

    /// Width of segment and path lines, in pixels: a tenth of a cell, 1 to 3 pixels.
    pub fn line_width(&self) -> f32 {
        (self.cell_pixels.x * 0.1).clamp(1.0, 3.0)
    }

    /// Length of a normal tick, in pixels: a quarter of a cell, at least 3 pixels.
    pub fn tick_length(&self) -> f32 {
        (self.cell_pixels.x * 0.25).max(3.0)
    }

    /// The normal tick of the segment `a`–`b` (pixels): from its middle, along the normal
    /// (world), [`tick_length`](Self::tick_length) long. `None` for a zero normal.
    pub fn normal_tick(&self, a: Vec2, b: Vec2, normal: Vec2) -> Option<(Vec2, Vec2)> {
        let n = self.pixel_direction(normal)?;
        let mid = (a + b) * 0.5;
        Some((mid, mid + n * self.tick_length()))
    }

    /// A world length along x as pixels (for radii).
    pub fn pixel_length(&self, length: f32) -> f32 {
        length / self.cell.x * self.cell_pixels.x
    }

    /// Position in cells (fractions included) to pixels.
    fn grid_to_pixel(&self, grid: Vec2) -> Option<Vec2> {
        let y = match self.y_axis {
            YAxis::Down => grid.y,
            YAxis::Up => self.rows - grid.y,
        };
        let p = Vec2::new(grid.x, y) * self.cell_pixels + self.shift;
        p.is_finite().then_some(p)
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use tileslide::io::ascii;

    use super::*;

    fn map() -> TileMap {
        ascii::parse("#..\n...", "view.txt", 2.0).unwrap()
    }

    #[test]
    fn y_down_puts_row_zero_at_the_top() {
        let view = View::new(&map(), &RenderOptions::default()).unwrap();
        assert_eq!((view.width(), view.height()), (48, 32));
        assert_eq!(
            view.pixel_of(Vec2::new(2.0, 0.0)),
            Some(Vec2::new(16.0, 0.0))
        );
        assert_eq!(
            view.pixel_direction(Vec2::new(0.0, -1.0)),
            Some(Vec2::new(0.0, -1.0))
        );
    }

    #[test]
    fn y_up_puts_row_zero_at_the_bottom() {
        let options = RenderOptions::default().with_y_axis(YAxis::Up);
        let view = View::new(&map(), &options).unwrap();
        assert_eq!(
            view.pixel_of(Vec2::new(2.0, 0.0)),
            Some(Vec2::new(16.0, 32.0))
        );
        assert_eq!(
            view.pixel_direction(Vec2::new(0.0, 1.0)),
            Some(Vec2::new(0.0, -1.0))
        );
    }

    #[test]
    fn non_finite_points_have_no_pixel() {
        let view = View::new(&map(), &RenderOptions::default()).unwrap();
        assert_eq!(view.pixel_of(Vec2::new(f32::NAN, 0.0)), None);
        assert_eq!(view.pixel_of(Vec2::new(f32::MAX, 0.0)), None);
    }

    #[test]
    fn bad_scales_are_refused() {
        for scale in [0.0, -1.0, f32::NAN, f32::INFINITY] {
            let options = RenderOptions::default().with_pixels_per_cell(scale);
            assert!(matches!(
                View::new(&map(), &options),
                Err(RenderError::BadScale(_))
            ));
        }
    }
}
