//! The debug-lines buffer: segments, circles, points and boxes, each with a kind and an
//! owner, refilled every frame.

use glam::Vec2;

use super::{DebugKind, DebugKinds};
use crate::geometry::{Aabb, Circle, Segment};
use crate::owner::Owner;

/// A line to draw: a wall, a normal, a ray, a path leg, a contact.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DebugSegment {
    /// The line, in world coordinates.
    pub segment: Segment,
    /// What it shows.
    pub kind: DebugKind,
    /// Whose it is: a temporary segment's or a body's owner; `Owner(0)` for the map.
    pub owner: Owner,
}

/// A circle to draw: a body, a character, a volume.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DebugCircle {
    /// The circle, in world coordinates.
    pub circle: Circle,
    /// What it shows.
    pub kind: DebugKind,
    /// Whose it is (a body's or a hit object's owner).
    pub owner: Owner,
}

/// A point to mark: a ray hit, a hit event.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DebugPoint {
    /// The point, in world coordinates.
    pub point: Vec2,
    /// What it shows.
    pub kind: DebugKind,
    /// Whose it is (the victim's owner for a hit).
    pub owner: Owner,
}

/// A box to draw: a box volume, a box character, a broadphase box.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DebugBox {
    /// The box, in world coordinates.
    pub aabb: Aabb,
    /// What it shows.
    pub kind: DebugKind,
    /// Whose it is.
    pub owner: Owner,
}

/// What the collision world looks like this frame, as plain shapes with a [`DebugKind`]
/// each, for any front end to draw: `tileslide-render`'s PNG and GIF pictures, the browser
/// playground's canvas, a game's own overlay.
///
/// The map, bodies, characters, hit volumes, paths and flow fields each fill it with a
/// `debug_lines` method ([`TileMap::debug_lines`](crate::TileMap::debug_lines),
/// [`Bodies::debug_lines`](crate::Bodies::debug_lines), …); a game adds its own rays and
/// hits with [`push_segment`](Self::push_segment) and the others. A buffer is meant to be
/// kept: [`clear`](Self::clear) it each frame and fill it again, and once its lists have
/// grown to a frame's size it allocates no more.
///
/// Two settings limit what is taken, and cost nothing to fill when they leave things out:
/// the [kinds](Self::with_kinds) (a map asked for no hidden segments does not compute
/// them) and the [view](Self::with_view) (a 256 × 256 map seen through a 20 × 12 window
/// gives only the cells the window overlaps). Shapes with a NaN or infinite coordinate are
/// not taken but [counted](Self::skipped).
///
/// ```
/// use tileslide::{io::ascii, Aabb, DebugKind, DebugLines, Vec2};
///
/// let map = ascii::parse("##\n..", "seam.txt", 1.0)?;
/// let mut lines = DebugLines::new();
/// map.debug_lines(&mut lines);
/// // Two squares: six active edges, and the two halves of their shared seam hidden.
/// assert_eq!(lines.count(DebugKind::ActiveSegment), 6);
/// assert_eq!(lines.count(DebugKind::HiddenSegment), 2);
/// assert_eq!(lines.count(DebugKind::Normal), 6);
///
/// // Next frame, only the top-left corner: the left square's left and top edges.
/// lines.clear();
/// lines.set_view(Some(Aabb::from_corners(Vec2::ZERO, Vec2::new(0.5, 0.5))));
/// map.debug_lines(&mut lines);
/// assert_eq!(lines.count(DebugKind::ActiveSegment), 2);
/// # Ok::<(), tileslide::io::LoadError>(())
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub struct DebugLines {
    segments: Vec<DebugSegment>,
    circles: Vec<DebugCircle>,
    points: Vec<DebugPoint>,
    boxes: Vec<DebugBox>,
    kinds: DebugKinds,
    view: Option<Aabb>,
    skipped: usize,
}

impl DebugLines {
    /// An empty buffer that takes every kind, everywhere.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// This buffer taking only `kinds` from now on.
    ///
    /// ```
    /// # use tileslide::{io::ascii, DebugKind, DebugKinds, DebugLines};
    /// let map = ascii::parse("##", "two.txt", 1.0)?;
    /// let mut walls = DebugLines::new().with_kinds(DebugKinds::NONE.with(DebugKind::ActiveSegment));
    /// map.debug_lines(&mut walls);
    /// assert_eq!(walls.segments().len(), 6);
    /// # Ok::<(), tileslide::io::LoadError>(())
    /// ```
    #[must_use]
    pub fn with_kinds(mut self, kinds: DebugKinds) -> Self {
        self.kinds = kinds;
        self
    }

    /// Takes only `kinds` from now on (what is already in the buffer stays).
    pub fn set_kinds(&mut self, kinds: DebugKinds) {
        self.kinds = kinds;
    }

    /// The kinds the buffer takes.
    #[must_use]
    pub fn kinds(&self) -> DebugKinds {
        self.kinds
    }

    /// True when the buffer takes `kind`: fillers check it before working out shapes of
    /// that kind.
    #[must_use]
    pub fn wants(&self, kind: DebugKind) -> bool {
        self.kinds.contains(kind)
    }

    /// This buffer taking only shapes that touch `view` (world coordinates) from now on.
    ///
    /// ```
    /// # use tileslide::{Aabb, Circle, DebugKind, DebugLines, Owner, Vec2};
    /// let window = Aabb::from_corners(Vec2::ZERO, Vec2::splat(10.0));
    /// let mut lines = DebugLines::new().with_view(window);
    /// lines.push_circle(DebugKind::Body, Circle::new(Vec2::new(5.0, 5.0), 1.0), Owner(1));
    /// lines.push_circle(DebugKind::Body, Circle::new(Vec2::new(50.0, 5.0), 1.0), Owner(2));
    /// assert_eq!(lines.circles().len(), 1);
    /// ```
    #[must_use]
    pub fn with_view(mut self, view: Aabb) -> Self {
        self.view = Some(view);
        self
    }

    /// Takes only shapes that touch `view` from now on, or shapes anywhere for `None`.
    pub fn set_view(&mut self, view: Option<Aabb>) {
        self.view = view;
    }

    /// The view shapes must touch to be taken, if any.
    #[must_use]
    pub fn view(&self) -> Option<Aabb> {
        self.view
    }

    /// True when a shape whose bounding box is `aabb` may be taken: it touches the view
    /// (or there is none). Fillers use it to skip whole cells and objects.
    #[must_use]
    pub fn sees(&self, aabb: &Aabb) -> bool {
        self.view.is_none_or(|v| v.overlaps(aabb))
    }

    /// Empties the buffer, keeping its memory, kinds and view.
    pub fn clear(&mut self) {
        self.segments.clear();
        self.circles.clear();
        self.points.clear();
        self.boxes.clear();
        self.skipped = 0;
    }

    /// The number of shapes held, of every sort.
    #[must_use]
    pub fn len(&self) -> usize {
        self.segments.len() + self.circles.len() + self.points.len() + self.boxes.len()
    }

    /// True when the buffer holds nothing.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The number of shapes of `kind` held, of every sort.
    ///
    /// ```
    /// # use tileslide::{DebugKind, DebugLines, Owner, Vec2};
    /// let mut lines = DebugLines::new();
    /// lines.push_point(DebugKind::RayHit, Vec2::ONE, Owner(0));
    /// assert_eq!(lines.count(DebugKind::RayHit), 1);
    /// assert_eq!(lines.count(DebugKind::Hit), 0);
    /// ```
    #[must_use]
    pub fn count(&self, kind: DebugKind) -> usize {
        self.segments.iter().filter(|s| s.kind == kind).count()
            + self.circles.iter().filter(|c| c.kind == kind).count()
            + self.points.iter().filter(|p| p.kind == kind).count()
            + self.boxes.iter().filter(|b| b.kind == kind).count()
    }

    /// How many shapes were not taken since the last [`clear`](Self::clear) because a
    /// coordinate or size was NaN or infinite (shapes outside the view or of a kind not
    /// taken are not counted).
    #[must_use]
    pub fn skipped(&self) -> usize {
        self.skipped
    }

    /// The segments, in the order they were added.
    #[must_use]
    pub fn segments(&self) -> &[DebugSegment] {
        &self.segments
    }

    /// The circles, in the order they were added.
    #[must_use]
    pub fn circles(&self) -> &[DebugCircle] {
        &self.circles
    }

    /// The points, in the order they were added.
    #[must_use]
    pub fn points(&self) -> &[DebugPoint] {
        &self.points
    }

    /// The boxes, in the order they were added.
    #[must_use]
    pub fn boxes(&self) -> &[DebugBox] {
        &self.boxes
    }

    /// Adds the line `segment` of `kind`, unless the buffer does not take the kind, the
    /// line misses the view, or a coordinate is not finite (then it is counted as
    /// skipped).
    ///
    /// ```
    /// # use tileslide::{DebugKind, DebugLines, Owner, Segment, Vec2};
    /// let mut lines = DebugLines::new();
    /// lines.push_segment(DebugKind::Ray, Segment::new(Vec2::ZERO, Vec2::X), Owner(0));
    /// lines.push_segment(DebugKind::Ray, Segment::new(Vec2::ZERO, Vec2::NAN), Owner(0));
    /// assert_eq!((lines.segments().len(), lines.skipped()), (1, 1));
    /// ```
    pub fn push_segment(&mut self, kind: DebugKind, segment: Segment, owner: Owner) {
        if !self.wants(kind) {
            return;
        }
        if !segment.is_finite() {
            self.skipped += 1;
        } else if self.sees(&segment.aabb()) {
            self.segments.push(DebugSegment {
                segment,
                kind,
                owner,
            });
        }
    }

    /// Adds `circle` of `kind`, as [`push_segment`](Self::push_segment) does; a negative
    /// radius is skipped too.
    pub fn push_circle(&mut self, kind: DebugKind, circle: Circle, owner: Owner) {
        if !self.wants(kind) {
            return;
        }
        if !(circle.center.is_finite() && circle.radius.is_finite() && circle.radius >= 0.0) {
            self.skipped += 1;
        } else if self.sees(&circle.aabb()) {
            self.circles.push(DebugCircle {
                circle,
                kind,
                owner,
            });
        }
    }

    /// Adds `point` of `kind`, as [`push_segment`](Self::push_segment) does.
    pub fn push_point(&mut self, kind: DebugKind, point: Vec2, owner: Owner) {
        if !self.wants(kind) {
            return;
        }
        if !point.is_finite() {
            self.skipped += 1;
        } else if self.view.is_none_or(|v| v.contains_point(point)) {
            self.points.push(DebugPoint { point, kind, owner });
        }
    }

    /// Adds the box `aabb` of `kind`, as [`push_segment`](Self::push_segment) does; a box
    /// whose minimum exceeds its maximum is skipped too.
    pub fn push_box(&mut self, kind: DebugKind, aabb: Aabb, owner: Owner) {
        if !self.wants(kind) {
            return;
        }
        if !(aabb.min.is_finite() && aabb.max.is_finite() && aabb.min.cmple(aabb.max).all()) {
            self.skipped += 1;
        } else if self.sees(&aabb) {
            self.boxes.push(DebugBox { aabb, kind, owner });
        }
    }

    /// Adds a segment of `kind` and its normal: the normal as a
    /// [`Normal`](DebugKind::Normal) line from the segment's middle, `tick` long. A normal
    /// belongs to its segment: it is taken only when both kinds are.
    pub fn push_with_normal(
        &mut self,
        kind: DebugKind,
        segment: Segment,
        normal: Vec2,
        tick: f32,
        owner: Owner,
    ) {
        if !self.wants(kind) {
            return;
        }
        self.push_segment(kind, segment, owner);
        if self.wants(DebugKind::Normal) {
            let mid = (segment.a + segment.b) * 0.5;
            let tip = mid + normal * tick;
            self.push_segment(DebugKind::Normal, Segment::new(mid, tip), owner);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn filled() -> DebugLines {
        let mut lines = DebugLines::new();
        lines.push_segment(
            DebugKind::Ray,
            Segment::new(Vec2::ZERO, Vec2::ONE),
            Owner(1),
        );
        lines.push_circle(DebugKind::Body, Circle::new(Vec2::ONE, 0.5), Owner(2));
        lines.push_point(DebugKind::RayHit, Vec2::ONE, Owner(3));
        lines.push_box(
            DebugKind::BroadphaseBox,
            Aabb::from_corners(Vec2::ZERO, Vec2::ONE),
            Owner(4),
        );
        lines
    }

    #[test]
    fn a_cleared_buffer_is_empty_and_keeps_its_memory() {
        let mut lines = filled();
        lines.push_point(DebugKind::Hit, Vec2::NAN, Owner(0));
        assert_eq!((lines.len(), lines.skipped()), (4, 1));
        let capacity = lines.segments.capacity();
        lines.clear();
        assert!(lines.is_empty());
        assert_eq!(lines.len(), 0);
        assert_eq!(lines.skipped(), 0);
        assert!(lines.segments().is_empty() && lines.circles().is_empty());
        assert!(lines.points().is_empty() && lines.boxes().is_empty());
        assert_eq!(lines.segments.capacity(), capacity);
    }

    #[test]
    fn refilling_after_warm_up_does_not_grow_the_lists() {
        let mut lines = filled();
        let capacities = |l: &DebugLines| {
            (
                l.segments.capacity(),
                l.circles.capacity(),
                l.points.capacity(),
                l.boxes.capacity(),
            )
        };
        let before = capacities(&lines);
        for _ in 0..100 {
            lines.clear();
            lines.push_segment(
                DebugKind::Ray,
                Segment::new(Vec2::ZERO, Vec2::ONE),
                Owner(1),
            );
            lines.push_circle(DebugKind::Body, Circle::new(Vec2::ONE, 0.5), Owner(2));
            lines.push_point(DebugKind::RayHit, Vec2::ONE, Owner(3));
            let cell = Aabb::from_corners(Vec2::ZERO, Vec2::ONE);
            lines.push_box(DebugKind::BroadphaseBox, cell, Owner(4));
        }
        assert_eq!(capacities(&lines), before);
        assert_eq!(lines.len(), 4);
    }

    #[test]
    fn kinds_not_taken_are_left_out_and_not_counted() {
        let mut lines = DebugLines::new().with_kinds(DebugKinds::NONE.with(DebugKind::Body));
        lines.push_segment(
            DebugKind::Ray,
            Segment::new(Vec2::ZERO, Vec2::NAN),
            Owner(0),
        );
        lines.push_circle(DebugKind::Body, Circle::new(Vec2::ONE, 0.5), Owner(2));
        lines.push_with_normal(
            DebugKind::ActiveSegment,
            Segment::new(Vec2::ZERO, Vec2::X),
            Vec2::Y,
            0.25,
            Owner(0),
        );
        assert_eq!(lines.len(), 1);
        assert_eq!(lines.skipped(), 0);
        assert_eq!(lines.circles()[0].owner, Owner(2));
    }

    #[test]
    fn the_view_keeps_what_touches_it() {
        let view = Aabb::from_corners(Vec2::ZERO, Vec2::splat(2.0));
        let mut lines = DebugLines::new().with_view(view);
        let far = Vec2::splat(10.0);
        lines.push_segment(
            DebugKind::Path,
            Segment::new(Vec2::splat(-1.0), far),
            Owner(0),
        );
        lines.push_segment(DebugKind::Path, Segment::new(far, far + 1.0), Owner(0));
        lines.push_circle(
            DebugKind::Body,
            Circle::new(Vec2::splat(3.0), 1.5),
            Owner(0),
        );
        lines.push_circle(DebugKind::Body, Circle::new(far, 1.5), Owner(0));
        lines.push_point(DebugKind::Hit, Vec2::splat(2.0), Owner(0));
        lines.push_point(DebugKind::Hit, Vec2::splat(2.5), Owner(0));
        lines.push_box(
            DebugKind::Character,
            Aabb::from_corners(Vec2::ONE, far),
            Owner(0),
        );
        lines.push_box(
            DebugKind::Character,
            Aabb::from_corners(far, far + 1.0),
            Owner(0),
        );
        assert_eq!(
            (
                lines.segments().len(),
                lines.circles().len(),
                lines.points().len(),
                lines.boxes().len()
            ),
            (1, 1, 1, 1)
        );
        lines.set_view(None);
        lines.push_point(DebugKind::Hit, far, Owner(0));
        assert_eq!(lines.points().len(), 2);
    }

    #[test]
    fn impossible_sizes_are_skipped() {
        let mut lines = DebugLines::new();
        lines.push_circle(DebugKind::Body, Circle::new(Vec2::ONE, -1.0), Owner(0));
        lines.push_circle(
            DebugKind::Body,
            Circle::new(Vec2::ONE, f32::INFINITY),
            Owner(0),
        );
        lines.push_box(
            DebugKind::AttackVolume,
            Aabb {
                min: Vec2::ONE,
                max: Vec2::ZERO,
            },
            Owner(0),
        );
        assert!(lines.is_empty());
        assert_eq!(lines.skipped(), 3);
    }

    #[test]
    fn a_normal_starts_at_the_middle_of_its_segment() {
        let mut lines = DebugLines::new();
        lines.push_with_normal(
            DebugKind::TemporarySegment,
            Segment::new(Vec2::ZERO, Vec2::new(2.0, 0.0)),
            Vec2::NEG_Y,
            0.5,
            Owner(9),
        );
        let normal = lines.segments()[1];
        assert_eq!(normal.kind, DebugKind::Normal);
        assert_eq!(normal.segment, Segment::new(Vec2::X, Vec2::new(1.0, -0.5)));
        assert_eq!(normal.owner, Owner(9));
    }
}
