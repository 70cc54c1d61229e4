//! A placed volume as a convex core rounded by a radius: a point (a circle), a segment (a
//! capsule) or a quadrilateral (a rectangle, turned or not). The volumes that are not plain
//! circles and upright rectangles are tested in this form, with one algorithm for every
//! pair of shapes: the distance between the cores against the sum of the radii.
//!
//! Two convex sets moving along straight lines first touch, or come nearest, at a corner of
//! one against an edge of the other, unless they overlap from the start (Ericson,
//! *Real-Time Collision Detection*, 5.5: a moving convex polygon against another is its
//! corners swept against the other's edges, and the other's against its own). So every
//! test here is a loop over corners and edges: a corner's path (a segment) against an edge
//! for the overlap test, the exact circle sweeps of the `geometry` module for the time of
//! impact.

use glam::Vec2;

use crate::geometry::{
    Aabb, EndCaps, Segment, SweepHit, sweep_circle_circle, sweep_circle_segment,
};

/// A convex core (one, two or four corners) and a radius ≥ 0: the points within the radius
/// of the core.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Rounded {
    /// The corners; the first `len` are used. A quadrilateral's go counterclockwise with y
    /// up (positive area), so each edge's outward normal is on its right.
    corners: [Vec2; 4],
    len: usize,
    radius: f32,
}

impl Rounded {
    /// A disc: the point `center` rounded by `radius`.
    pub fn point(center: Vec2, radius: f32) -> Self {
        Self {
            corners: [center; 4],
            len: 1,
            radius,
        }
    }

    /// A capsule: the segment from `a` to `b` rounded by `radius` (a disc when `a == b`).
    pub fn segment(a: Vec2, b: Vec2, radius: f32) -> Self {
        Self {
            corners: [a, b, b, b],
            len: if a == b { 1 } else { 2 },
            radius,
        }
    }

    /// A quadrilateral with corners counterclockwise (y up) and some area, not rounded.
    pub fn quad(corners: [Vec2; 4]) -> Self {
        Self {
            corners,
            len: 4,
            radius: 0.0,
        }
    }

    fn corners(&self) -> &[Vec2] {
        &self.corners[..self.len]
    }

    /// The core's edges for distances: a point's is the point itself (a segment of length
    /// zero), a segment's the segment, a quadrilateral's its four sides.
    fn edges(&self) -> impl Iterator<Item = Segment> + '_ {
        let count = if self.len == 4 { 4 } else { 1 };
        (0..count).map(|i| Segment::new(self.corners[i], self.corners[(i + 1) % self.len]))
    }

    /// The core's faces for sweeps, each an edge and its outward unit normal: a
    /// quadrilateral's four sides, both sides of a segment, none for a point (its sweeps are
    /// against the other shape's faces, and the caps of those faces).
    fn faces(&self) -> impl Iterator<Item = (Segment, Vec2)> + '_ {
        let (count, sides) = match self.len {
            4 => (4, 1),
            2 => (1, 2),
            _ => (0, 0),
        };
        (0..count).flat_map(move |i| {
            let edge = Segment::new(self.corners[i], self.corners[(i + 1) % self.len]);
            let d = edge.delta();
            let normal = Vec2::new(d.y, -d.x).normalize_or_zero();
            [(edge, normal), (edge, -normal)].into_iter().take(sides)
        })
    }

    /// Whether `p` lies in the quadrilateral (closed); false for a point or a segment, which
    /// have no inside.
    fn contains(&self, p: Vec2) -> bool {
        self.len == 4
            && (0..4).all(|i| {
                let (a, b) = (self.corners[i], self.corners[(i + 1) % 4]);
                (b - a).perp_dot(p - a) >= 0.0
            })
    }

    /// The same shape moved by `offset`.
    pub fn moved(mut self, offset: Vec2) -> Self {
        for c in &mut self.corners {
            *c += offset;
        }
        self
    }

    /// The smallest box holding it: its core's corners' box grown by the radius. (Out of
    /// line, as the other tests here: the hot loops place circles and upright rectangles.)
    #[inline(never)]
    pub fn aabb(&self) -> Aabb {
        let corners = self.corners();
        let (lo, hi) = corners
            .iter()
            .fold((corners[0], corners[0]), |(lo, hi), &c| {
                (lo.min(c), hi.max(c))
            });
        Aabb {
            min: lo - Vec2::splat(self.radius),
            max: hi + Vec2::splat(self.radius),
        }
    }

    /// Its farthest point from `p`, as a distance: a corner's, plus the radius.
    #[inline(never)]
    pub fn reach_from(&self, p: Vec2) -> f32 {
        self.corners()
            .iter()
            .fold(0.0f32, |far, c| far.max(c.distance(p)))
            + self.radius
    }

    /// True when `self`, moving by `motion`, shares a point with `other` at some time of the
    /// frame (start and end included): the cores come within the sum of the radii.
    #[inline(never)]
    pub fn meets(&self, motion: Vec2, other: &Rounded) -> bool {
        let reach = self.radius + other.radius;
        let reach2 = reach * reach;
        // At the start: one core inside the other, or two edges within reach (crossing
        // edges are at distance 0).
        if other.contains(self.corners[0])
            || self.contains(other.corners[0])
            || any_within(self.edges(), other, reach2)
        {
            return true;
        }
        // Along the move: each corner's path against the other's edges, and each of the
        // other's corners against this one's edges, in the frame where this one stands
        // still.
        motion != Vec2::ZERO
            && (any_within(
                self.corners().iter().map(|&p| Segment::new(p, p + motion)),
                other,
                reach2,
            ) || any_within(
                other.corners().iter().map(|&q| Segment::new(q, q - motion)),
                self,
                reach2,
            ))
    }

    /// The squared distance between the two cores: 0 when they overlap (one holds a corner
    /// of the other, or edges cross), else the least between an edge of each.
    pub fn core_distance_squared(&self, other: &Rounded) -> f32 {
        if other.contains(self.corners[0]) || self.contains(other.corners[0]) {
            return 0.0;
        }
        (self.edges())
            .flat_map(|e| {
                other
                    .edges()
                    .map(move |f| e.distance_squared_to_segment(&f))
            })
            .fold(f32::INFINITY, f32::min)
    }

    /// The sum of the two radii.
    pub fn reach(&self, other: &Rounded) -> f32 {
        self.radius + other.radius
    }

    /// The first time in `[0, 1]` at which `self`, moving by `motion`, touches `other`,
    /// from the exact sweeps of each corner of one, rounded by both radii, against each face
    /// of the other and its end caps. `None` when no sweep reports a contact: the shapes
    /// miss, or their paths only graze (the sweeps count a contact only where the shapes
    /// move into each other).
    pub fn time_of_impact(&self, motion: Vec2, other: &Rounded) -> Option<f32> {
        let reach = self.radius + other.radius;
        let mut best: Option<f32> = None;
        let mut keep = |hit: Option<SweepHit>| {
            if let Some(h) = hit {
                best = Some(best.map_or(h.t, |t| t.min(h.t)));
            }
        };
        if self.len == 1 && other.len == 1 {
            keep(sweep_circle_circle(
                self.corners[0],
                motion,
                other.corners[0],
                reach,
            ));
        }
        for &p in self.corners() {
            for (edge, normal) in other.faces() {
                keep(sweep_circle_segment(
                    p,
                    reach,
                    motion,
                    &edge,
                    normal,
                    EndCaps::BOTH,
                ));
            }
        }
        for &q in other.corners() {
            for (edge, normal) in self.faces() {
                keep(sweep_circle_segment(
                    q,
                    reach,
                    -motion,
                    &edge,
                    normal,
                    EndCaps::BOTH,
                ));
            }
        }
        best
    }

    /// A point the two shapes share, for shapes that meet: the middle of the part their
    /// cores share if they overlap; otherwise, on the line between the cores' nearest
    /// points, the middle of the stretch both shapes cover (where they touch, the point of
    /// contact).
    pub fn contact_point(&self, other: &Rounded) -> Vec2 {
        if let Some(p) = self.core_overlap_middle(other) {
            return p;
        }
        let (p, q) = self.nearest_points(other);
        let d = q - p;
        let len = d.length();
        if len <= 0.0 {
            return p;
        }
        let s = ((len + self.radius - other.radius) * 0.5).clamp(0.0, len);
        p + d * (s / len)
    }

    /// The middle of the part the two cores share: the average of its corners (the corners
    /// of each core inside the other and the points where their edges cross). `None` when
    /// the cores do not overlap (or only touch without a corner on the other's side).
    fn core_overlap_middle(&self, other: &Rounded) -> Option<Vec2> {
        let (mut sum, mut count) = (Vec2::ZERO, 0u32);
        let mut add = |p: Vec2| {
            sum += p;
            count += 1;
        };
        for (inner, outer) in [(self, other), (other, self)] {
            for &p in inner.corners() {
                if outer.contains(p) {
                    add(p);
                }
            }
        }
        for e in self.edges() {
            for f in other.edges() {
                if let Some(p) = crossing(&e, &f) {
                    add(p);
                }
            }
        }
        (count > 0).then(|| sum / count as f32)
    }

    /// The nearest points of the two cores (one of them a corner: the nearest points of two
    /// disjoint convex polygons include a corner of one of them).
    fn nearest_points(&self, other: &Rounded) -> (Vec2, Vec2) {
        let mut best = (f32::INFINITY, self.corners[0], other.corners[0]);
        for (from, to, swapped) in [(self, other, false), (other, self, true)] {
            for &p in from.corners() {
                for e in to.edges() {
                    let q = e.closest_point(p);
                    let d = p.distance_squared(q);
                    if d < best.0 {
                        best = if swapped { (d, q, p) } else { (d, p, q) };
                    }
                }
            }
        }
        (best.1, best.2)
    }
}

/// True when one of `paths` comes within `sqrt(reach2)` of an edge of `shape`'s core.
fn any_within(mut paths: impl Iterator<Item = Segment>, shape: &Rounded, reach2: f32) -> bool {
    paths.any(|p| {
        shape
            .edges()
            .any(|e| p.distance_squared_to_segment(&e) <= reach2)
    })
}

/// Where two segments properly cross (each one's ends strictly on opposite sides of the
/// other's line), or `None`.
fn crossing(e: &Segment, f: &Segment) -> Option<Vec2> {
    let side = |s: &Segment, p: Vec2| s.delta().perp_dot(p - s.a);
    let (d1, d2) = (side(e, f.a), side(e, f.b));
    let (d3, d4) = (side(f, e.a), side(f, e.b));
    (d1 * d2 < 0.0 && d3 * d4 < 0.0).then(|| f.a + f.delta() * (d1 / (d1 - d2)))
}
