//! What to draw over the map in one picture: bodies, rays, paths, volumes, hit events.

use tileslide::{
    Aabb, Bodies, Cell, Circle, DebugKinds, DebugLines, HitEvent, HitWorld, NavPath, Ray, RayHit,
    SegmentFlags, TemporarySegment, TileMap, Vec2, VolumeShape,
};

use crate::lines::{draw_body, draw_boxes, draw_circles, draw_points, draw_segments};
use crate::pen::Pen;
use crate::view::{NORMAL_WIDTH, View};
use crate::{Rgba, Style};

/// Which side of a hit a volume is on: it picks the colour.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VolumeKind {
    /// A volume that deals hits ([`Style::attack`], red by default).
    Attack,
    /// A volume that takes hits ([`Style::vulnerability`], blue by default).
    Vulnerability,
}

/// One thing to draw, in world coordinates, checked finite when added.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Overlay {
    Body {
        circle: Circle,
        color: Option<Rgba>,
    },
    Ray {
        from: Vec2,
        to: Vec2,
        /// The hit point and normal.
        hit: Option<(Vec2, Vec2)>,
    },
    /// Points `start..end` of the picture's shared point list.
    Polyline {
        start: usize,
        end: usize,
    },
    Volume {
        shape: VolumeShape,
        kind: VolumeKind,
    },
    HitMarker {
        point: Vec2,
        accepted: bool,
    },
    Temporary {
        a: Vec2,
        b: Vec2,
        normal: Vec2,
    },
    /// A filled box with no outline.
    Area {
        min: Vec2,
        max: Vec2,
        color: Rgba,
    },
    /// An active segment drawn as the canvas draws the map's.
    Wall {
        a: Vec2,
        b: Vec2,
        normal: Vec2,
        one_way: bool,
    },
    /// Debug lines: these ranges of the picture's own buffer.
    Lines(LineRanges),
}

/// Where one batch of debug lines lies in a picture's buffer: `(start, end)` of each list.
#[derive(Clone, Copy, Debug, PartialEq)]
struct LineRanges {
    segments: (usize, usize),
    circles: (usize, usize),
    points: (usize, usize),
    boxes: (usize, usize),
}

impl LineRanges {
    /// The lengths of `lines`' lists: where a batch added next starts (and so far ends).
    fn at_end_of(lines: &DebugLines) -> Self {
        let end = |n: usize| (n, n);
        Self {
            segments: end(lines.segments().len()),
            circles: end(lines.circles().len()),
            points: end(lines.points().len()),
            boxes: end(lines.boxes().len()),
        }
    }

    /// These ranges ending where `lines`' lists end now.
    fn up_to_end_of(self, lines: &DebugLines) -> Self {
        let to = |(start, _): (usize, usize), n: usize| (start, n);
        Self {
            segments: to(self.segments, lines.segments().len()),
            circles: to(self.circles, lines.circles().len()),
            points: to(self.points, lines.points().len()),
            boxes: to(self.boxes, lines.boxes().len()),
        }
    }
}

/// The things to draw over a map in one picture (one frame of an animation), in world
/// coordinates, drawn in the order they were added by [`Canvas::render`](crate::Canvas::render)
/// or an [`Animation`](crate::Animation).
///
/// Input with a NaN or infinite coordinate, a radius that is not positive, or a box whose
/// minimum exceeds its maximum is **skipped** — the rest of the picture is still drawn — and
/// counted by [`skipped`](Self::skipped). Nothing here panics or fails.
///
/// ```
/// use tileslide::io::ascii;
/// use tileslide::{Circle, Ray, QueryFilter, Vec2};
/// use tileslide_render::{Canvas, Picture, RenderOptions};
///
/// let map = ascii::parse("\
/// ######
/// #....#
/// #..=.#
/// ######", "room.txt", 1.0)?;
/// let canvas = Canvas::new(&map, &RenderOptions::default())?; // 16 pixels per cell
///
/// let ray = Ray::between(Vec2::new(1.5, 1.5), Vec2::new(1.5, 3.5));
/// let hit = map.cast_ray(ray, &QueryFilter::default());
/// let mut picture = Picture::new();
/// picture
///     .body(Circle::new(Vec2::new(4.0, 1.5), 0.4))
///     .ray(ray, hit.as_ref())
///     .polyline(&[Vec2::new(1.5, 1.5), Vec2::new(4.5, 1.5)])
///     .body(Circle::new(Vec2::new(f32::NAN, 1.0), 0.5)); // skipped, not drawn
/// assert_eq!(picture.skipped(), 1);
///
/// let image = canvas.render(&picture);
/// assert_eq!((image.width(), image.height()), (96, 64));
/// let png = image.to_png()?; // or image.save_png("room.png")?
/// assert!(png.starts_with(b"\x89PNG"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Picture {
    overlays: Vec<Overlay>,
    points: Vec<Vec2>,
    /// Every batch of debug lines added, one after the other.
    lines: DebugLines,
    skipped: usize,
}

impl Picture {
    /// An empty picture: the map alone.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// Removes everything, keeping the memory for the next frame.
    pub fn clear(&mut self) {
        self.overlays.clear();
        self.points.clear();
        self.lines.clear();
        self.skipped = 0;
    }

    /// How many things will be drawn.
    #[must_use]
    pub fn len(&self) -> usize {
        self.overlays.len()
    }

    /// True when nothing will be drawn over the map.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.overlays.is_empty()
    }

    /// How many things were skipped for a non-finite coordinate or an impossible size.
    #[must_use]
    pub fn skipped(&self) -> usize {
        self.skipped
    }

    /// A body: a disc in [`Style::body`] with an outline. Skipped unless the centre is
    /// finite and the radius positive and finite.
    pub fn body(&mut self, circle: Circle) -> &mut Self {
        self.push_body(circle, None)
    }

    /// A body in a colour of its own (to tell bodies apart).
    pub fn body_with_color(&mut self, circle: Circle, color: Rgba) -> &mut Self {
        self.push_body(circle, Some(color))
    }

    /// A ray with what it hit: the line from its origin to the hit (or to its end when it
    /// hits nothing), the rest of it fainter, a dot at the hit point and a tick along the
    /// hit normal. Skipped if the ray or the hit is not finite.
    pub fn ray(&mut self, ray: Ray, hit: Option<&RayHit>) -> &mut Self {
        let overlay = Overlay::Ray {
            from: ray.origin,
            to: ray.origin + ray.delta,
            hit: hit.map(|h| (h.point, h.normal)),
        };
        let finite = ray.origin.is_finite()
            && ray.delta.is_finite()
            && hit.is_none_or(|h| h.point.is_finite() && h.normal.is_finite());
        self.push(overlay, finite)
    }

    /// A path found by [`NavGrid`](tileslide::NavGrid): its corners joined by lines.
    pub fn path(&mut self, path: &NavPath) -> &mut Self {
        self.polyline(path.points())
    }

    /// Lines through `points` in order (a single point is drawn as a dot). Skipped if empty
    /// or if any point is not finite.
    pub fn polyline(&mut self, points: &[Vec2]) -> &mut Self {
        let finite = !points.is_empty() && points.iter().all(|p| p.is_finite());
        let start = self.points.len();
        if finite {
            self.points.extend_from_slice(points);
        }
        let end = self.points.len();
        self.push(Overlay::Polyline { start, end }, finite)
    }

    /// An attack or vulnerability volume in **world** coordinates (place an object's local
    /// volume at its position first): filled translucent, outlined. Skipped if not finite,
    /// if a circle's radius is negative, if a rect's minimum exceeds its maximum, or if the
    /// shape is one this version does not draw.
    pub fn volume(&mut self, shape: VolumeShape, kind: VolumeKind) -> &mut Self {
        let usable = match shape {
            VolumeShape::Circle(c) => {
                c.center.is_finite() && c.radius.is_finite() && c.radius >= 0.0
            }
            VolumeShape::Rect(b) => {
                b.min.is_finite() && b.max.is_finite() && b.min.cmple(b.max).all()
            }
            // A shape added to tileslide after this version: skipped, as unusable.
            _ => false,
        };
        self.push(Overlay::Volume { shape, kind }, usable)
    }

    /// A hit marker (an ×) at `point`: [`Style::hit`] if the hit was accepted, else
    /// [`Style::hit_refused`].
    pub fn hit_marker(&mut self, point: Vec2, accepted: bool) -> &mut Self {
        self.push(Overlay::HitMarker { point, accepted }, point.is_finite())
    }

    /// A hit event of `world`'s current frame, marked at the middle of the victim (its
    /// position plus half its size). Skipped if the victim is not registered in `world`.
    pub fn hit_event(&mut self, world: &HitWorld, event: &HitEvent) -> &mut Self {
        match world.object(event.victim) {
            Some(victim) => self.hit_marker(victim.position + victim.size * 0.5, event.accepted),
            None => {
                self.skipped += 1;
                self
            }
        }
    }

    /// A temporary segment (moving platform, door) with its normal tick, in
    /// [`Style::temporary`].
    pub fn temporary(&mut self, segment: &TemporarySegment) -> &mut Self {
        let overlay = Overlay::Temporary {
            a: segment.segment.a,
            b: segment.segment.b,
            normal: segment.normal,
        };
        let finite = segment.segment.a.is_finite()
            && segment.segment.b.is_finite()
            && segment.normal.is_finite();
        self.push(overlay, finite)
    }

    /// Every temporary segment `map` holds now.
    pub fn temporaries(&mut self, map: &TileMap) -> &mut Self {
        for t in map.temporaries() {
            self.temporary(t);
        }
        self
    }

    /// A box filled with `color` and no outline: floor, ground, a zone. Drawn in order
    /// with the rest, so add areas first to keep them under bodies.
    pub fn area(&mut self, area: Aabb, color: Rgba) -> &mut Self {
        let usable = area.min.is_finite() && area.max.is_finite() && area.min.cmple(area.max).all();
        self.push(
            Overlay::Area {
                min: area.min,
                max: area.max,
                color,
            },
            usable,
        )
    }

    /// The active segments of `cells` of `map` as they are now, drawn as the canvas draws
    /// the map's (solid and one-way colours, normal ticks): for a map edited since its
    /// [`Canvas`](crate::Canvas) was drawn (an animation keeps one canvas), cover the edited
    /// cells with [`area`](Self::area)s and redraw their walls and their neighbours'.
    /// Cells outside the map are skipped and counted.
    pub fn cell_walls(
        &mut self,
        map: &TileMap,
        cells: impl IntoIterator<Item = Cell>,
    ) -> &mut Self {
        for cell in cells {
            if cell.col >= map.width() || cell.row >= map.height() {
                self.skipped += 1;
                continue;
            }
            for s in map.active_segments(cell) {
                let overlay = Overlay::Wall {
                    a: s.segment.a,
                    b: s.segment.b,
                    normal: s.normal,
                    one_way: s.flags.contains(SegmentFlags::ONE_WAY),
                };
                self.push(overlay, true);
            }
        }
        self
    }

    /// Everything in `lines`, drawn in its kinds' colours (see
    /// [`Style::color_of`]) when the canvas's [layers](crate::RenderOptions::layers) hold
    /// the kind: segments first (one stroke per kind), then boxes, circles and points.
    /// The shapes `lines` skipped count in [`skipped`](Self::skipped).
    ///
    /// ```
    /// use tileslide::{io::ascii, DebugKind, DebugLines, Owner, QueryFilter, Ray, Vec2};
    /// use tileslide_render::{Canvas, Picture, RenderOptions};
    ///
    /// let map = ascii::parse("#...#", "hall.txt", 1.0)?;
    /// // Lines 3 pixels wide at 40 pixels a cell: the pixel under the ray is fully covered.
    /// let canvas = Canvas::new(&map, &RenderOptions::default().with_pixels_per_cell(40.0))?;
    /// let mut lines = DebugLines::new();
    /// let ray = Ray::between(Vec2::new(1.5, 0.5), Vec2::new(4.5, 0.5));
    /// lines.push_ray(ray, map.cast_ray(ray, &QueryFilter::default()).as_ref(), 0.25, Owner(0));
    /// let mut picture = Picture::new();
    /// picture.debug_lines(&lines);
    /// let image = canvas.render(&picture);
    /// let style = RenderOptions::default().style;
    /// let on_the_ray = canvas.to_pixel(Vec2::new(2.5, 0.5)).unwrap();
    /// assert_eq!(image.pixel(on_the_ray.x as u32, on_the_ray.y as u32), Some(style.ray));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn debug_lines(&mut self, lines: &DebugLines) -> &mut Self {
        let start = (LineRanges::at_end_of(&self.lines), self.lines.skipped());
        for s in lines.segments() {
            self.lines.push_segment(s.kind, s.segment, s.owner);
        }
        for c in lines.circles() {
            self.lines.push_circle(c.kind, c.circle, c.owner);
        }
        for p in lines.points() {
            self.lines.push_point(p.kind, p.point, p.owner);
        }
        for b in lines.boxes() {
            self.lines.push_box(b.kind, b.aabb, b.owner);
        }
        // What the buffer itself left out counts as skipped here too.
        self.skipped += lines.skipped();
        self.push_lines(start)
    }

    /// Every body of `bodies` where it is now, from [`Bodies::debug_lines`]: each circle
    /// as [`body`](Self::body) draws one, and (when the canvas's layers hold
    /// [`BroadphaseBox`](tileslide::DebugKind::BroadphaseBox), which they do by default) the
    /// box the broadphase filed it under.
    pub fn bodies(&mut self, bodies: &Bodies) -> &mut Self {
        let start = (LineRanges::at_end_of(&self.lines), self.lines.skipped());
        bodies.debug_lines(&mut self.lines);
        self.push_lines(start)
    }

    /// Records the lines added to the buffer since `start` (its ranges and its count of
    /// skipped shapes then) as one overlay.
    fn push_lines(&mut self, (start, skipped): (LineRanges, usize)) -> &mut Self {
        self.skipped += self.lines.skipped() - skipped;
        let ranges = start.up_to_end_of(&self.lines);
        self.push(Overlay::Lines(ranges), true)
    }

    fn push_body(&mut self, circle: Circle, color: Option<Rgba>) -> &mut Self {
        let usable = circle.center.is_finite() && circle.radius.is_finite() && circle.radius > 0.0;
        self.push(Overlay::Body { circle, color }, usable)
    }

    fn push(&mut self, overlay: Overlay, usable: bool) -> &mut Self {
        if usable {
            self.overlays.push(overlay);
        } else {
            self.skipped += 1;
        }
        self
    }

    /// Draws everything, in order. A shape whose pixel coordinates overflow is left out.
    pub(crate) fn draw(&self, pen: &mut Pen<'_>, view: &View, style: &Style, layers: DebugKinds) {
        let line = view.line_width();
        for overlay in &self.overlays {
            match *overlay {
                Overlay::Body { circle, color } => {
                    let fill = color.unwrap_or(style.body);
                    draw_body(pen, view, style, circle.center, circle.radius, fill);
                }
                Overlay::Lines(r) => {
                    let l = &self.lines;
                    let range = |(start, end): (usize, usize)| start..end;
                    draw_segments(pen, view, style, layers, &l.segments()[range(r.segments)]);
                    draw_boxes(pen, view, style, layers, &l.boxes()[range(r.boxes)]);
                    draw_circles(pen, view, style, layers, &l.circles()[range(r.circles)]);
                    draw_points(pen, view, style, layers, &l.points()[range(r.points)]);
                }
                Overlay::Ray { from, to, hit } => draw_ray(pen, view, style, from, to, hit),
                Overlay::Polyline { start, end } => {
                    let points = self.points[start..end]
                        .iter()
                        .filter_map(|&p| view.pixel_of(p));
                    if end - start == 1 {
                        if let Some(p) = points.clone().next() {
                            pen.disc(p, line, style.path, style.path, 0.0);
                        }
                    } else {
                        pen.polyline(points, style.path, line);
                    }
                }
                Overlay::Volume { shape, kind } => draw_volume(pen, view, style, shape, kind),
                Overlay::HitMarker { point, accepted } => {
                    if let Some(p) = view.pixel_of(point) {
                        let color = if accepted {
                            style.hit
                        } else {
                            style.hit_refused
                        };
                        pen.cross(p, view.tick_length(), color, line * 1.5);
                    }
                }
                Overlay::Temporary { a, b, normal } => {
                    draw_segment(pen, view, style, (a, b, normal), style.temporary);
                }
                Overlay::Wall {
                    a,
                    b,
                    normal,
                    one_way,
                } => {
                    let color = if one_way { style.one_way } else { style.solid };
                    draw_segment(pen, view, style, (a, b, normal), color);
                }
                Overlay::Area { min, max, color } => {
                    if let (Some(a), Some(b)) = (view.pixel_of(min), view.pixel_of(max)) {
                        pen.rect(a, b, color, Rgba::new(0, 0, 0, 0), 0.0);
                    }
                }
            }
        }
    }
}

/// A segment `(a, b, normal)` in `color` with its normal tick, as the canvas draws walls.
fn draw_segment(
    pen: &mut Pen<'_>,
    view: &View,
    style: &Style,
    (a, b, normal): (Vec2, Vec2, Vec2),
    color: Rgba,
) {
    if let (Some(a), Some(b)) = (view.pixel_of(a), view.pixel_of(b)) {
        let line = view.line_width();
        if let Some((from, to)) = view.normal_tick(a, b, normal) {
            pen.line(from, to, style.normal, line * NORMAL_WIDTH);
        }
        pen.line(a, b, color, line);
    }
}

fn draw_ray(
    pen: &mut Pen<'_>,
    view: &View,
    style: &Style,
    from: Vec2,
    to: Vec2,
    hit: Option<(Vec2, Vec2)>,
) {
    let (Some(from), Some(to)) = (view.pixel_of(from), view.pixel_of(to)) else {
        return;
    };
    let Some((point, normal)) = hit else {
        pen.line(from, to, style.ray, view.line_width());
        return;
    };
    let Some(point) = view.pixel_of(point) else {
        return;
    };
    let line = view.line_width();
    pen.line(point, to, style.ray.with_alpha(style.ray.a / 3), line);
    pen.line(from, point, style.ray, line);
    if let Some(n) = view.pixel_direction(normal) {
        pen.line(point, point + n * view.tick_length(), style.normal, line);
    }
    pen.disc(point, line * 1.5 + 1.0, style.ray_hit, style.ray_hit, 0.0);
}

fn draw_volume(
    pen: &mut Pen<'_>,
    view: &View,
    style: &Style,
    shape: VolumeShape,
    kind: VolumeKind,
) {
    let color = match kind {
        VolumeKind::Attack => style.attack,
        VolumeKind::Vulnerability => style.vulnerability,
    };
    let fill = color.with_alpha(color.a / 4);
    let line = view.line_width();
    match shape {
        VolumeShape::Circle(c) => {
            if let Some(center) = view.pixel_of(c.center) {
                pen.disc(center, view.pixel_length(c.radius), fill, color, line);
            }
        }
        VolumeShape::Rect(b) => {
            if let (Some(a), Some(b)) = (view.pixel_of(b.min), view.pixel_of(b.max)) {
                pen.rect(a, b, fill, color, line);
            }
        }
        // Not reached: `volume` skips the shapes it does not know.
        _ => {}
    }
}
