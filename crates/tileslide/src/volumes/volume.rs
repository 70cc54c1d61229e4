//! Attack and vulnerability volumes: circles and axis-aligned boxes in an object's local
//! coordinates, mirrored when the object faces the other way, and the exact tests of one
//! placed volume against another, still or moving during the frame.
//!
//! Touching counts: volumes are closed sets, so two volumes that share only a boundary
//! point overlap (Replica Island's tests are strict, so touching never hit there). The same
//! rule as the broadphase's, so a pair the exact test accepts is never culled before it.

use glam::Vec2;
use thiserror::Error;

use super::HitTypes;
use crate::geometry::{Aabb, Circle, MAX_COORD, Segment, in_range};

/// A volume's shape in object-local coordinates.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum VolumeShape {
    /// A disc (radius ≥ 0).
    Circle(Circle),
    /// An axis-aligned rectangle (`min ≤ max`).
    Rect(Aabb),
}

/// An attack or vulnerability volume: a shape and the hit types it deals or accepts.
///
/// ```
/// use tileslide::{HitTypes, Vec2, Volume};
/// let fist = Volume::circle(Vec2::new(1.5, 1.0), 0.25, HitTypes::HIT)?;
/// // 1 wide and 2 tall, from the object's position: centre (0.5, 1), half extents (0.5, 1).
/// let body = Volume::rect(Vec2::new(0.5, 1.0), Vec2::new(0.5, 1.0), HitTypes::ANY)?;
/// # Ok::<(), tileslide::VolumeError>(())
/// ```
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Volume {
    /// The shape, in object-local coordinates.
    pub shape: VolumeShape,
    /// What the volume deals (attack) or accepts (vulnerability).
    pub hit: HitTypes,
}

/// A volume that cannot be used.
#[derive(Clone, Copy, Debug, Error, PartialEq)]
#[non_exhaustive]
pub enum VolumeError {
    /// A coordinate or radius is NaN or infinite.
    #[error("volume has a non-finite {what}: ({x}, {y})")]
    NonFinite {
        /// Which value.
        what: &'static str,
        /// The value (a radius has `y = 0`).
        x: f32,
        /// The value's second coordinate.
        y: f32,
    },
    /// A coordinate or radius beyond [`MAX_COORD`].
    #[error("{what} ({x}, {y}) is out of range: each coordinate must be at most {max} in magnitude", max = MAX_COORD)]
    OutOfRange {
        /// Which value: a volume's `"center"`, `"radius"`, `"half extents"`, `"min"` or
        /// `"max"`, or a hit object's `"position"`, `"start"` (its position less its motion)
        /// or `"size"`.
        what: &'static str,
        /// The value (a radius has `y = 0`).
        x: f32,
        /// The value's second coordinate.
        y: f32,
    },
    /// A circle with a negative radius.
    #[error("volume circle has a negative radius {0}")]
    NegativeRadius(f32),
    /// A rectangle with a negative half extent.
    #[error("volume rect has negative half extents ({x}, {y})")]
    NegativeHalfExtents {
        /// Half the width.
        x: f32,
        /// Half the height.
        y: f32,
    },
    /// A rectangle whose `min` is not below its `max` on both axes.
    #[error("volume rect has min ({min_x}, {min_y}) above max ({max_x}, {max_y})")]
    InvertedRect {
        /// `min.x`.
        min_x: f32,
        /// `min.y`.
        min_y: f32,
        /// `max.x`.
        max_x: f32,
        /// `max.y`.
        max_y: f32,
    },
}

/// `v`, named `what`: finite and within [`MAX_COORD`].
pub(crate) fn check_range(what: &'static str, v: Vec2) -> Result<(), VolumeError> {
    let (x, y) = (v.x, v.y);
    if !v.is_finite() {
        Err(VolumeError::NonFinite { what, x, y })
    } else if !in_range(v) {
        Err(VolumeError::OutOfRange { what, x, y })
    } else {
        Ok(())
    }
}

impl Volume {
    /// A disc at `center` (object-local) of `radius` ≥ 0.
    ///
    /// # Errors
    /// [`VolumeError::NonFinite`], [`VolumeError::OutOfRange`] (beyond [`MAX_COORD`]) or
    /// [`VolumeError::NegativeRadius`].
    pub fn circle(center: Vec2, radius: f32, hit: HitTypes) -> Result<Self, VolumeError> {
        let volume = Self {
            shape: VolumeShape::Circle(Circle::new(center, radius)),
            hit,
        };
        volume.check()?;
        Ok(volume)
    }

    /// The rectangle centred at `center` (object-local) with half extents `half` ≥ 0 (half
    /// the width, half the height), as [`CharacterShape::rect`](crate::CharacterShape::rect)
    /// takes them. A caller holding corners can build
    /// `VolumeShape::Rect(Aabb { min, max })` and [`check`](Self::check) it.
    ///
    /// # Errors
    /// [`VolumeError::NonFinite`], [`VolumeError::OutOfRange`] (a centre, half extents or
    /// corner beyond [`MAX_COORD`]) or [`VolumeError::NegativeHalfExtents`].
    pub fn rect(center: Vec2, half: Vec2, hit: HitTypes) -> Result<Self, VolumeError> {
        check_range("center", center)?;
        check_range("half extents", half)?;
        if !half.cmpge(Vec2::ZERO).all() {
            return Err(VolumeError::NegativeHalfExtents {
                x: half.x,
                y: half.y,
            });
        }
        let volume = Self {
            shape: VolumeShape::Rect(Aabb {
                min: center - half,
                max: center + half,
            }),
            hit,
        };
        volume.check()?;
        Ok(volume)
    }

    /// Whether the volume can be used: what [`circle`](Self::circle) and
    /// [`rect`](Self::rect) check, for a volume built from its public fields.
    /// [`HitWorld::register`](super::HitWorld::register) drops the volumes of an object with
    /// a volume this refuses.
    ///
    /// # Errors
    /// As [`circle`](Self::circle) and [`rect`](Self::rect).
    pub fn check(&self) -> Result<(), VolumeError> {
        match self.shape {
            VolumeShape::Circle(Circle { center, radius }) => {
                check_range("center", center)?;
                check_range("radius", Vec2::new(radius, 0.0))?;
                if radius < 0.0 {
                    return Err(VolumeError::NegativeRadius(radius));
                }
            }
            VolumeShape::Rect(Aabb { min, max }) => {
                check_range("min", min)?;
                check_range("max", max)?;
                if !min.cmple(max).all() {
                    return Err(VolumeError::InvertedRect {
                        min_x: min.x,
                        min_y: min.y,
                        max_x: max.x,
                        max_y: max.y,
                    });
                }
            }
        }
        Ok(())
    }
}

/// Which way an object faces: a volume is mirrored about the middle of the object's size on
/// each flipped axis (Replica Island: `x → width − x` when facing left).
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Facing {
    /// Mirror x (facing left, for a game whose volumes are drawn facing right).
    pub flip_x: bool,
    /// Mirror y (facing down).
    pub flip_y: bool,
}

/// A volume's shape in world coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Placed {
    Circle { center: Vec2, radius: f32 },
    Rect(Aabb),
}

impl Placed {
    /// `shape` of an object at `position` of `size`, facing `facing`.
    pub fn new(shape: &VolumeShape, position: Vec2, size: Vec2, facing: Facing) -> Self {
        let mirror = |v: f32, extent: f32, flip: bool| if flip { extent - v } else { v };
        match *shape {
            VolumeShape::Circle(c) => Placed::Circle {
                center: position
                    + Vec2::new(
                        mirror(c.center.x, size.x, facing.flip_x),
                        mirror(c.center.y, size.y, facing.flip_y),
                    ),
                radius: c.radius,
            },
            VolumeShape::Rect(b) => {
                let (x0, x1) = if facing.flip_x {
                    (size.x - b.max.x, size.x - b.min.x)
                } else {
                    (b.min.x, b.max.x)
                };
                let (y0, y1) = if facing.flip_y {
                    (size.y - b.max.y, size.y - b.min.y)
                } else {
                    (b.min.y, b.max.y)
                };
                Placed::Rect(Aabb {
                    min: position + Vec2::new(x0, y0),
                    max: position + Vec2::new(x1, y1),
                })
            }
        }
    }

    /// The smallest box holding it.
    pub fn aabb(&self) -> Aabb {
        match *self {
            Placed::Circle { center, radius } => Aabb {
                min: center - Vec2::splat(radius),
                max: center + Vec2::splat(radius),
            },
            Placed::Rect(b) => b,
        }
    }

    /// Its farthest point from `p`, as a distance.
    pub fn reach_from(&self, p: Vec2) -> f32 {
        match *self {
            Placed::Circle { center, radius } => center.distance(p) + radius,
            Placed::Rect(b) => (b.min - p).abs().max((b.max - p).abs()).length(),
        }
    }

    /// True when `self`, moving by `motion` over the frame relative to `other`, shares a
    /// point with `other` at some time of the frame (start and end included). With zero
    /// motion, a plain overlap test. Exact, closed sets.
    pub fn meets(&self, motion: Vec2, other: &Placed) -> bool {
        match (*self, *other) {
            (
                Placed::Circle { center, radius },
                Placed::Circle {
                    center: c,
                    radius: r,
                },
            ) => {
                // The centre's path against the disc of the summed radius.
                let reach = radius + r;
                Segment::new(center, center + motion).distance_squared_to(c) <= reach * reach
            }
            (Placed::Circle { center, radius }, Placed::Rect(b)) => {
                circle_path_meets_box(center, motion, radius, &b)
            }
            (Placed::Rect(b), Placed::Circle { center, radius }) => {
                // In the box's frame the circle moves the other way.
                circle_path_meets_box(center, -motion, radius, &b)
            }
            (Placed::Rect(a), Placed::Rect(b)) => {
                // Minkowski difference: the centre of `a` against `b` grown by `a`'s half
                // size; its path as a slab test.
                let half = (a.max - a.min) * 0.5;
                let grown = Aabb {
                    min: b.min - half,
                    max: b.max + half,
                };
                segment_meets_box((a.min + a.max) * 0.5, motion, &grown)
            }
        }
    }
}

/// True when the disc of `radius` whose centre moves from `center` by `motion` touches the
/// closed box. The path is a segment; disjoint convex sets are nearest at an end point of
/// one of them, so the distance is the least of the segment's ends to the box and the box's
/// corners to the segment (zero if the segment crosses the box).
fn circle_path_meets_box(center: Vec2, motion: Vec2, radius: f32, b: &Aabb) -> bool {
    if segment_meets_box(center, motion, b) {
        return true;
    }
    let r2 = radius * radius;
    let to_box = |p: Vec2| p.clamp(b.min, b.max).distance_squared(p);
    if to_box(center) <= r2 || to_box(center + motion) <= r2 {
        return true;
    }
    let path = Segment::new(center, center + motion);
    [
        b.min,
        Vec2::new(b.max.x, b.min.y),
        b.max,
        Vec2::new(b.min.x, b.max.y),
    ]
    .into_iter()
    .any(|corner| path.distance_squared_to(corner) <= r2)
}

/// True when the segment from `p` by `d` shares a point with the closed box (slab test;
/// Kay–Kajiya, as in Ericson, *Real-Time Collision Detection*, 5.3.3).
fn segment_meets_box(p: Vec2, d: Vec2, b: &Aabb) -> bool {
    let (mut t0, mut t1) = (0.0f32, 1.0f32);
    for axis in 0..2 {
        let (o, v, lo, hi) = (p[axis], d[axis], b.min[axis], b.max[axis]);
        if v == 0.0 {
            if o < lo || o > hi {
                return false;
            }
        } else {
            let (a, c) = ((lo - o) / v, (hi - o) / v);
            t0 = t0.max(a.min(c));
            t1 = t1.min(a.max(c));
            if t0 > t1 {
                return false;
            }
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    fn circle(x: f32, y: f32, r: f32) -> Placed {
        Placed::Circle {
            center: Vec2::new(x, y),
            radius: r,
        }
    }

    fn rect(x0: f32, y0: f32, x1: f32, y1: f32) -> Placed {
        Placed::Rect(Aabb {
            min: Vec2::new(x0, y0),
            max: Vec2::new(x1, y1),
        })
    }

    #[test]
    fn touching_counts_and_a_hair_apart_does_not() {
        // Exactly representable distances, so "touching" is exact.
        assert!(circle(0.0, 0.0, 0.5).meets(Vec2::ZERO, &circle(1.0, 0.0, 0.5)));
        assert!(!circle(0.0, 0.0, 0.5).meets(Vec2::ZERO, &circle(1.0, 0.0, 0.499)));
        assert!(rect(0.0, 0.0, 1.0, 1.0).meets(Vec2::ZERO, &rect(1.0, 0.25, 2.0, 2.0)));
        assert!(!rect(0.0, 0.0, 1.0, 1.0).meets(Vec2::ZERO, &rect(1.001, 0.25, 2.0, 2.0)));
        assert!(circle(0.0, 0.0, 0.5).meets(Vec2::ZERO, &rect(0.5, -1.0, 1.0, 1.0)));
        assert!(!circle(0.0, 0.0, 0.5).meets(Vec2::ZERO, &rect(0.501, -1.0, 1.0, 1.0)));
    }

    #[test]
    fn a_circle_near_a_box_corner_is_tested_against_the_rounded_corner() {
        // Inside the box grown by the radius, but outside its rounded corner.
        let b = rect(0.0, 0.0, 1.0, 1.0);
        assert!(!circle(1.4, 1.4, 0.5).meets(Vec2::ZERO, &b));
        assert!(circle(1.3, 1.3, 0.5).meets(Vec2::ZERO, &b));
        assert!(b.meets(Vec2::ZERO, &circle(1.3, 1.3, 0.5)));
    }

    #[test]
    fn a_fast_volume_meets_what_it_passes_between_frames() {
        // A bullet ten times its size per frame, starting and ending clear of the target.
        let bullet = circle(-5.0, 0.0, 0.1);
        assert!(bullet.meets(Vec2::new(10.0, 0.0), &circle(0.0, 0.0, 0.5)));
        assert!(bullet.meets(Vec2::new(10.0, 0.0), &rect(-0.5, -0.5, 0.5, 0.5)));
        assert!(rect(-5.1, -0.1, -4.9, 0.1).meets(Vec2::new(10.0, 0.0), &rect(0.0, 0.0, 1.0, 1.0)));
        // Missing by a little above.
        assert!(!bullet.meets(Vec2::new(10.0, 0.0), &circle(0.0, 0.7, 0.5)));
        // The box moving into a still circle, seen from the circle.
        assert!(rect(-0.5, -0.5, 0.5, 0.5).meets(Vec2::new(-10.0, 0.0), &circle(-5.0, 0.0, 0.1)));
    }

    #[test]
    fn volumes_mirror_about_the_object_size() {
        let size = Vec2::new(2.0, 4.0);
        let at = Vec2::new(10.0, 20.0);
        let left = Facing {
            flip_x: true,
            flip_y: false,
        };
        let fist = VolumeShape::Circle(Circle::new(Vec2::new(1.75, 1.0), 0.25));
        assert_eq!(
            Placed::new(&fist, at, size, left),
            circle(10.25, 21.0, 0.25)
        );
        let blade = VolumeShape::Rect(Aabb {
            min: Vec2::new(1.5, 0.5),
            max: Vec2::new(2.5, 1.0),
        });
        let down = Facing {
            flip_x: false,
            flip_y: true,
        };
        assert_eq!(
            Placed::new(&blade, at, size, left),
            rect(9.5, 20.5, 10.5, 21.0)
        );
        assert_eq!(
            Placed::new(&blade, at, size, down),
            rect(11.5, 23.0, 12.5, 23.5)
        );
    }

    #[test]
    fn bad_volumes_are_errors() {
        assert_eq!(
            Volume::circle(Vec2::ZERO, -1.0, HitTypes::HIT),
            Err(VolumeError::NegativeRadius(-1.0))
        );
        assert!(matches!(
            Volume::circle(Vec2::NAN, 1.0, HitTypes::HIT),
            Err(VolumeError::NonFinite { what: "center", .. })
        ));
        assert!(matches!(
            Volume::rect(Vec2::ONE, Vec2::new(0.5, -0.5), HitTypes::HIT),
            Err(VolumeError::NegativeHalfExtents { .. })
        ));
        assert!(matches!(
            Volume::rect(Vec2::ONE, Vec2::NAN, HitTypes::HIT),
            Err(VolumeError::NonFinite {
                what: "half extents",
                ..
            })
        ));
        // A rectangle built inside out from the public fields: tests/volumes.rs.
    }
}
