//! Lines, discs and boxes in pixel coordinates, anti-aliased, onto a pixmap.
//!
//! Every call takes pixel positions that [`View`](crate::view::View) has already checked
//! are finite. tiny-skia's rasteriser works in fixed point and fails an internal assertion
//! on coordinates around 10⁹ and beyond, so nothing far outside the image reaches it: lines
//! are clipped to the image plus a margin (Liang & Barsky 1984), boxes are intersected with
//! it, a disc wholly outside is dropped and one covering all of it becomes a box. The one
//! shape left out is a disc more than [`SAFE_EXTENT`] pixels across whose edge crosses the
//! image (a world-sized circle seen from close up).

use tileslide::Vec2;
use tiny_skia::{
    FillRule, LineCap, LineJoin, Paint, Path, PathBuilder, Pixmap, Rect, Stroke, Transform,
};

use crate::Rgba;

/// Largest radius handed to tiny-skia, in pixels: well inside what it rasterises (tested
/// to 10⁸ on images 10⁵ pixels wide) and larger than any image's side ([`MAX_PIXELS`]).
///
/// [`MAX_PIXELS`]: crate::MAX_PIXELS
const SAFE_EXTENT: f32 = 5e7;

/// How far outside the image shapes are kept, in pixels: more than any line width or
/// marker, so clipped ends never show.
const MARGIN: f32 = 64.0;

/// Draws onto one pixmap.
pub(crate) struct Pen<'a> {
    pixmap: &'a mut Pixmap,
    /// The image plus [`MARGIN`]: everything drawn is clipped to it.
    window: (Vec2, Vec2),
}

impl<'a> Pen<'a> {
    /// A pen for `pixmap`.
    pub fn new(pixmap: &'a mut Pixmap) -> Self {
        let size = Vec2::new(pixmap.width() as f32, pixmap.height() as f32);
        let window = (Vec2::splat(-MARGIN), size + MARGIN);
        Self { pixmap, window }
    }

    /// Fills `path` with the even-odd rule.
    pub fn fill(&mut self, path: &Path, color: Rgba) {
        self.pixmap.fill_path(
            path,
            &paint(color),
            FillRule::EvenOdd,
            Transform::identity(),
            None,
        );
    }

    /// Strokes `path` `width` pixels wide with round ends and joins.
    pub fn stroke(&mut self, path: &Path, color: Rgba, width: f32) {
        let stroke = Stroke {
            width,
            line_cap: LineCap::Round,
            line_join: LineJoin::Round,
            ..Stroke::default()
        };
        self.pixmap
            .stroke_path(path, &paint(color), &stroke, Transform::identity(), None);
    }

    /// A straight line from `a` to `b`.
    pub fn line(&mut self, a: Vec2, b: Vec2, color: Rgba, width: f32) {
        self.polyline([a, b], color, width);
    }

    /// Lines through `points` in order, clipped to the window.
    pub fn polyline(&mut self, points: impl IntoIterator<Item = Vec2>, color: Rgba, width: f32) {
        let mut builder = PathBuilder::new();
        let mut points = points.into_iter();
        let Some(mut previous) = points.next() else {
            return;
        };
        // Where the path's pen is, to continue a line without lifting it.
        let mut at: Option<Vec2> = None;
        for p in points {
            if let Some((a, b)) = self.clip(previous, p) {
                if at != Some(a) {
                    builder.move_to(a.x, a.y);
                }
                builder.line_to(b.x, b.y);
                at = Some(b);
            }
            previous = p;
        }
        if let Some(path) = builder.finish() {
            self.stroke(&path, color, width);
        }
    }

    /// Separate lines, each from the first point of a pair to the second, clipped to the
    /// window and stroked as one path.
    pub fn lines(&mut self, ends: impl IntoIterator<Item = (Vec2, Vec2)>, color: Rgba, width: f32) {
        let mut builder = PathBuilder::new();
        for (a, b) in ends {
            if let Some((a, b)) = self.clip(a, b) {
                builder.move_to(a.x, a.y);
                builder.line_to(b.x, b.y);
            }
        }
        if let Some(path) = builder.finish() {
            self.stroke(&path, color, width);
        }
    }

    /// A filled disc with an outline `width` pixels wide (none if zero).
    pub fn disc(&mut self, center: Vec2, radius: f32, fill: Rgba, outline: Rgba, width: f32) {
        let (lo, hi) = self.window;
        let nearest = center.clamp(lo, hi);
        if nearest.distance(center) > radius {
            return; // Wholly outside.
        }
        let farthest = Vec2::new(
            if center.x < (lo.x + hi.x) * 0.5 {
                hi.x
            } else {
                lo.x
            },
            if center.y < (lo.y + hi.y) * 0.5 {
                hi.y
            } else {
                lo.y
            },
        );
        if farthest.distance(center) <= radius {
            // Covers the whole window: its outline is out of sight.
            if let Some(rect) = Rect::from_ltrb(lo.x, lo.y, hi.x, hi.y) {
                self.fill(&PathBuilder::from_rect(rect), fill);
            }
            return;
        }
        if radius > SAFE_EXTENT {
            return;
        }
        if let Some(path) = PathBuilder::from_circle(center.x, center.y, radius) {
            self.fill(&path, fill);
            if width > 0.0 {
                self.stroke(&path, outline, width);
            }
        }
    }

    /// A filled box (corners in any order) with an outline, cut to the window.
    pub fn rect(&mut self, a: Vec2, b: Vec2, fill: Rgba, outline: Rgba, width: f32) {
        let (lo, hi) = self.window;
        let (min, max) = (a.min(b).max(lo), a.max(b).min(hi));
        if let Some(rect) = Rect::from_ltrb(min.x, min.y, max.x, max.y) {
            let path = PathBuilder::from_rect(rect);
            self.fill(&path, fill);
            self.stroke(&path, outline, width);
        }
    }

    /// An × of half-size `size` at `center`.
    pub fn cross(&mut self, center: Vec2, size: f32, color: Rgba, width: f32) {
        let (d, e) = (Vec2::splat(size), Vec2::new(size, -size));
        self.line(center - d, center + d, color, width);
        self.line(center - e, center + e, color, width);
    }

    /// The part of the line `a`–`b` inside the window, or `None` (Liang & Barsky 1984: the
    /// line is `a + t·(b − a)`; each of the four window edges bounds `t` from one side). In
    /// f64, so that `b − a` cannot overflow for points near `f32::MAX`.
    fn clip(&self, a: Vec2, b: Vec2) -> Option<(Vec2, Vec2)> {
        let (lo, hi) = self.window;
        let (ax, ay) = (f64::from(a.x), f64::from(a.y));
        let (dx, dy) = (f64::from(b.x) - ax, f64::from(b.y) - ay);
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        for (p, q) in [
            (-dx, ax - f64::from(lo.x)),
            (dx, f64::from(hi.x) - ax),
            (-dy, ay - f64::from(lo.y)),
            (dy, f64::from(hi.y) - ay),
        ] {
            if p == 0.0 {
                if q < 0.0 {
                    return None; // Parallel to this edge and outside it.
                }
            } else if p < 0.0 {
                t0 = t0.max(q / p);
            } else {
                t1 = t1.min(q / p);
            }
        }
        if t0 > t1 {
            return None;
        }
        let at = |t: f64| Vec2::new((ax + dx * t) as f32, (ay + dy * t) as f32);
        let start = if t0 > 0.0 { at(t0) } else { a };
        let end = if t1 < 1.0 { at(t1) } else { b };
        // Rounding can leave a line that only grazes a corner with an end far outside
        // (t0 = t1 = 1 for a line 10³⁰ long): clamp, at worst drawing a dot in the margin.
        Some((start.clamp(lo, hi), end.clamp(lo, hi)))
    }
}

fn paint(color: Rgba) -> Paint<'static> {
    let mut paint = Paint::default();
    paint.set_color(color.to_skia());
    paint.anti_alias = true;
    paint
}
