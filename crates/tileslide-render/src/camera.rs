//! Part of a map framed in a picture of a fixed size, and a camera that follows what grows.

use tileslide::{Aabb, TileMap, Vec2};

use crate::view::View;
use crate::{Canvas, RenderError, RenderOptions};

/// Which part of the world a [`Canvas::framed`] canvas shows, and where in its image.
///
/// The window is scaled by one factor for both axes, as large as fits the viewport, and
/// centred in it: along the window's shorter side (relative to the viewport's shape) more
/// of the map shows. The viewport is the image's top-left `viewport.0 × viewport.1`
/// pixels; the rest of the image (on the right or below) is left for a legend or HUD.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Framing {
    /// The part of the world to show, in world coordinates.
    pub window: Aabb,
    /// Width and height of the whole image, in pixels.
    pub image: (u32, u32),
    /// Width and height of the part of the image showing the map, from its top-left.
    pub viewport: (u32, u32),
}

impl Canvas {
    /// Draws the part of `map` that `framing` shows, into an image of `framing.image`
    /// pixels (`options.pixels_per_cell` is not used: the framing sets the scale). The
    /// map is drawn past the viewport's edges too: cover the rest of the image (a panel)
    /// after rendering.
    ///
    /// Refuses an empty or non-finite window or a viewport that does not fit the image
    /// ([`RenderError::BadFraming`]), and an image over [`MAX_PIXELS`](crate::MAX_PIXELS)
    /// ([`RenderError::TooLarge`]).
    ///
    /// ```
    /// use tileslide::io::ascii;
    /// use tileslide::{Aabb, Vec2};
    /// use tileslide_render::{Canvas, Framing, RenderOptions};
    ///
    /// let map = ascii::parse("########\n#......#\n########", "hall.txt", 1.0)?;
    /// let framing = Framing {
    ///     window: Aabb::from_corners(Vec2::new(1.0, 1.0), Vec2::new(3.0, 2.0)),
    ///     image: (300, 100),
    ///     viewport: (200, 100),
    /// };
    /// let canvas = Canvas::framed(&map, &RenderOptions::default(), &framing)?;
    /// assert_eq!((canvas.width(), canvas.height()), (300, 100));
    /// assert_eq!(canvas.pixels_per_cell(), 100.0); // 2 × 1 cells fill 200 × 100 pixels
    /// assert_eq!(canvas.to_pixel(Vec2::new(1.0, 1.0)), Some(Vec2::new(0.0, 0.0)));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn framed(
        map: &TileMap,
        options: &RenderOptions,
        framing: &Framing,
    ) -> Result<Self, RenderError> {
        Self::with_view(map, View::framed(map, options, framing)?, options)
    }
}

/// A window that follows a growing area without jitter: it always holds the area plus a
/// margin, keeps the viewport's shape, and never shrinks or moves back, so a dungeon that
/// grows square by square is seen zooming out smoothly, never swaying.
///
/// ```
/// use tileslide::{Aabb, Vec2};
/// use tileslide_render::Camera;
///
/// let mut camera = Camera::new(1.0, 2.0); // square viewport, 2 units of margin
/// let first = camera.follow(Aabb::from_corners(Vec2::new(10.0, 10.0), Vec2::new(14.0, 12.0)));
/// assert_eq!(first, Aabb::from_corners(Vec2::new(8.0, 7.0), Vec2::new(16.0, 15.0)));
/// // The area grows: the window grows to hold it; it shrinks: the window stays.
/// let grown = camera.follow(Aabb::from_corners(Vec2::new(10.0, 10.0), Vec2::new(20.0, 12.0)));
/// assert!(grown.min.cmple(first.min).all() && grown.max.cmpge(first.max).all());
/// assert_eq!(camera.follow(Aabb::from_corners(Vec2::new(11.0, 11.0), Vec2::splat(12.0))), grown);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// Width over height of the viewport.
    aspect: f32,
    margin: f32,
    window: Option<Aabb>,
}

impl Camera {
    /// A camera for a viewport of `aspect` = width / height, keeping `margin` world units
    /// around what it follows. A non-finite or non-positive aspect is taken as 1, a
    /// negative or non-finite margin as 0.
    #[must_use]
    pub fn new(aspect: f32, margin: f32) -> Self {
        let aspect = if aspect.is_finite() && aspect > 0.0 {
            aspect
        } else {
            1.0
        };
        let margin = if margin.is_finite() {
            margin.max(0.0)
        } else {
            0.0
        };
        Self {
            aspect,
            margin,
            window: None,
        }
    }

    /// The window now: the union of everything followed so far plus the margin, widened
    /// about its centre to the viewport's shape. A target with a non-finite or inside-out
    /// box is ignored (the window stays; before any usable target, a unit box at the origin).
    pub fn follow(&mut self, target: Aabb) -> Aabb {
        let usable =
            target.min.is_finite() && target.max.is_finite() && target.min.cmple(target.max).all();
        if usable {
            let wanted = Aabb::from_corners(target.min - self.margin, target.max + self.margin);
            let grown = match self.window {
                Some(w) => w.union(&wanted),
                None => wanted,
            };
            self.window = Some(self.shaped(grown));
        }
        self.window
            .unwrap_or_else(|| Aabb::from_corners(Vec2::ZERO, Vec2::ONE))
    }

    /// The window now, if the camera has followed anything.
    #[must_use]
    pub fn window(&self) -> Option<Aabb> {
        self.window
    }

    /// `b` widened about its centre along one axis to the viewport's shape (never narrowed).
    fn shaped(&self, b: Aabb) -> Aabb {
        let size = (b.max - b.min).max(Vec2::splat(f32::MIN_POSITIVE));
        let centre = (b.min + b.max) * 0.5;
        let half = if size.x / size.y < self.aspect {
            Vec2::new(size.y * self.aspect, size.y) * 0.5
        } else {
            Vec2::new(size.x, size.x / self.aspect) * 0.5
        };
        // Widening about the centre can round a hair inside the box: keep the box whole.
        Aabb::from_corners(centre - half, centre + half).union(&b)
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use tileslide::io::ascii;

    use super::*;
    use crate::Picture;

    #[test]
    fn the_window_holds_every_target_followed_and_keeps_its_shape() {
        let mut camera = Camera::new(0.75, 1.5);
        let mut area = Aabb::from_corners(Vec2::new(30.0, 20.0), Vec2::new(31.0, 21.0));
        let mut previous: Option<Aabb> = None;
        for k in 0..60 {
            // Grows by one square at a time, in turn right, down and left.
            let step = Vec2::new(1.0, 1.0);
            area = match k % 3 {
                0 => Aabb::from_corners(area.min, area.max + Vec2::X * step),
                1 => Aabb::from_corners(area.min, area.max + Vec2::Y * step),
                _ => Aabb::from_corners(area.min - Vec2::X * step, area.max),
            };
            let w = camera.follow(area);
            assert!(w.min.cmple(area.min - 1.5).all() && w.max.cmpge(area.max + 1.5).all());
            let size = w.max - w.min;
            assert!((size.x / size.y - 0.75).abs() < 1e-3, "{size}");
            if let Some(p) = previous {
                assert!(w.min.cmple(p.min).all() && w.max.cmpge(p.max).all());
                // No jump: one square more grows each side by at most a few units.
                assert!(
                    (w.max - p.max).max_element() <= 2.0 && (p.min - w.min).max_element() <= 2.0
                );
            }
            previous = Some(w);
        }
    }

    #[test]
    fn bad_targets_are_ignored() {
        let mut camera = Camera::new(f32::NAN, -1.0);
        assert_eq!(
            camera.follow(Aabb::from_corners(Vec2::splat(f32::NAN), Vec2::ONE)),
            Aabb::from_corners(Vec2::ZERO, Vec2::ONE)
        );
        assert_eq!(camera.window(), None);
        let w = camera.follow(Aabb::from_corners(Vec2::ZERO, Vec2::new(2.0, 1.0)));
        assert_eq!(
            w,
            Aabb::from_corners(Vec2::new(0.0, -0.5), Vec2::new(2.0, 1.5))
        );
        let inside_out = Aabb {
            min: Vec2::ONE,
            max: Vec2::ZERO,
        };
        assert_eq!(camera.follow(inside_out), w);
    }

    #[test]
    fn a_framed_canvas_puts_the_window_in_the_viewport() {
        let map = ascii::parse("#####\n#...#\n#...#\n#####", "f.txt", 1.0).unwrap();
        let framing = Framing {
            window: Aabb::from_corners(Vec2::new(1.0, 1.0), Vec2::new(4.0, 3.0)),
            image: (200, 100),
            viewport: (150, 100),
        };
        let canvas = Canvas::framed(&map, &crate::RenderOptions::default(), &framing).unwrap();
        assert_eq!(canvas.pixels_per_cell(), 50.0);
        assert_eq!(canvas.to_pixel(Vec2::new(1.0, 1.0)), Some(Vec2::ZERO));
        assert_eq!(
            canvas.to_pixel(Vec2::new(4.0, 3.0)),
            Some(Vec2::new(150.0, 100.0))
        );
        let image = canvas.render(&Picture::new());
        assert_eq!((image.width(), image.height()), (200, 100));
        // Inside the room is background, past the window's left edge is wall.
        let style = crate::Style::default();
        assert_eq!(image.pixel(75, 50), Some(style.background));
        // Y up: the window's top (largest y) is at the top of the viewport.
        let up = crate::RenderOptions::default().with_y_axis(crate::YAxis::Up);
        let canvas = Canvas::framed(&map, &up, &framing).unwrap();
        assert_eq!(canvas.to_pixel(Vec2::new(1.0, 3.0)), Some(Vec2::ZERO));
    }

    #[test]
    fn bad_framings_are_refused() {
        let map = ascii::parse("#.", "f.txt", 1.0).unwrap();
        let options = crate::RenderOptions::default();
        let ok = Framing {
            window: Aabb::from_corners(Vec2::ZERO, Vec2::ONE),
            image: (10, 10),
            viewport: (10, 10),
        };
        let bad = [
            Framing {
                window: Aabb::from_corners(Vec2::ZERO, Vec2::new(0.0, 1.0)),
                ..ok
            },
            Framing {
                window: Aabb::from_corners(Vec2::ZERO, Vec2::new(f32::INFINITY, 1.0)),
                ..ok
            },
            Framing {
                viewport: (11, 10),
                ..ok
            },
            Framing {
                viewport: (0, 10),
                ..ok
            },
        ];
        for framing in bad {
            assert!(
                matches!(
                    Canvas::framed(&map, &options, &framing),
                    Err(RenderError::BadFraming(_))
                ),
                "{framing:?}"
            );
        }
        let huge = Framing {
            image: (1 << 20, 1 << 20),
            ..ok
        };
        assert!(matches!(
            Canvas::framed(&map, &options, &huge),
            Err(RenderError::TooLarge { .. })
        ));
    }
}
