//! Attack and vulnerability volumes: circles, axis-aligned rectangles and capsules in an
//! object's local coordinates, with the hit types they deal or accept, and the way an
//! object faces. Where a volume lands in the world and how placed volumes meet is
//! `placed.rs`.

use glam::Vec2;
use thiserror::Error;

use super::HitTypes;
#[cfg(feature = "aim")]
use crate::geometry::Segment;
use crate::geometry::{Aabb, Circle, MAX_COORD, in_range};

/// A volume's shape in object-local coordinates.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum VolumeShape {
    /// A disc (radius ≥ 0).
    Circle(Circle),
    /// An axis-aligned rectangle (`min ≤ max`); turned with its object's
    /// [`aim`](super::HitObject::aim) when it is an attack volume.
    Rect(Aabb),
    /// The points within `radius` (≥ 0) of `segment`: a blade, a beam, a swept fist
    /// (with the `aim` feature).
    #[cfg(feature = "aim")]
    Capsule {
        /// The middle line, from one cap's centre to the other's.
        segment: Segment,
        /// Its radius.
        radius: f32,
    },
}

/// An attack or vulnerability volume: a shape and the hit types it deals or accepts.
///
/// ```
/// use tileslide::{HitTypes, Vec2, Volume};
/// let fist = Volume::circle(Vec2::new(1.5, 1.0), 0.25, HitTypes::HIT)?;
/// // 1 wide and 2 tall, from the object's position: centre (0.5, 1), half extents (0.5, 1).
/// let body = Volume::rect(Vec2::new(0.5, 1.0), Vec2::new(0.5, 1.0), HitTypes::ANY)?;
/// // A blade 1.5 long, 0.1 thick on each side, from the hilt at (1, 1) pointing right
/// // (capsules come with the `aim` feature, on by default).
/// # #[cfg(feature = "aim")]
/// let blade = Volume::capsule(Vec2::new(1.0, 1.0), Vec2::new(2.5, 1.0), 0.1, HitTypes::HIT)?;
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

/// A volume or a hit object that cannot be used.
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
        /// Which value: a volume's `"center"`, `"radius"`, `"half extents"`, `"min"`,
        /// `"max"`, or a capsule's `"a"` or `"b"`; or a hit object's `"position"`,
        /// `"start"` (its position less its motion) or `"size"`.
        what: &'static str,
        /// The value (a radius has `y = 0`).
        x: f32,
        /// The value's second coordinate.
        y: f32,
    },
    /// A circle or a capsule with a negative radius.
    #[error("volume has a negative radius {0}")]
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
    /// A hit object's [`aim`](super::HitObject::aim) is the zero vector: it points nowhere.
    #[error("hit object's aim is (0, 0): an aim needs a direction")]
    ZeroAim,
    /// A hit object has an [`aim`](super::HitObject::aim), and tileslide was built without
    /// its `aim` feature, which turns attack volumes.
    #[error("hit object has an aim, and tileslide was built without its `aim` feature")]
    AimUnsupported,
    /// More of something than a [`HitWorld`](super::HitWorld) takes (see
    /// [`limits`](crate::limits)).
    #[error("too many {what}: {count}, at most {max}")]
    TooMany {
        /// What: `"attack volumes"` or `"vulnerable volumes"` of one object, `"hit objects
        /// this frame"`, or `"attack volumes this frame"` or `"vulnerable volumes this
        /// frame"`.
        what: &'static str,
        /// How many there would be.
        count: usize,
        /// The most allowed.
        max: usize,
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

/// A capsule's ends and radius (out of line: [`Volume::check`] is on the registering hot
/// path, where circles and rectangles are the common case).
#[cfg(feature = "aim")]
#[inline(never)]
fn check_capsule(segment: &Segment, radius: f32) -> Result<(), VolumeError> {
    check_range("a", segment.a)?;
    check_range("b", segment.b)?;
    check_radius(radius)
}

/// `radius`: finite, within [`MAX_COORD`] and not negative.
fn check_radius(radius: f32) -> Result<(), VolumeError> {
    check_range("radius", Vec2::new(radius, 0.0))?;
    if radius < 0.0 {
        return Err(VolumeError::NegativeRadius(radius));
    }
    Ok(())
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

    /// The capsule whose middle line runs from `a` to `b` (object-local), of `radius` ≥ 0:
    /// every point within `radius` of the segment. With `a == b`, a disc.
    ///
    /// # Errors
    /// [`VolumeError::NonFinite`], [`VolumeError::OutOfRange`] (an end or the radius beyond
    /// [`MAX_COORD`]) or [`VolumeError::NegativeRadius`].
    #[cfg(feature = "aim")]
    pub fn capsule(a: Vec2, b: Vec2, radius: f32, hit: HitTypes) -> Result<Self, VolumeError> {
        let volume = Self {
            shape: VolumeShape::Capsule {
                segment: Segment::new(a, b),
                radius,
            },
            hit,
        };
        volume.check()?;
        Ok(volume)
    }

    /// Whether the volume can be used: what [`circle`](Self::circle),
    /// [`rect`](Self::rect) and [`capsule`](Self::capsule) check, for a volume built from
    /// its public fields. [`HitWorld::register`](super::HitWorld::register) refuses an
    /// object with a volume this refuses.
    ///
    /// # Errors
    /// As [`circle`](Self::circle), [`rect`](Self::rect) and [`capsule`](Self::capsule).
    #[cfg_attr(feature = "aim", inline)]
    pub fn check(&self) -> Result<(), VolumeError> {
        match self.shape {
            VolumeShape::Circle(Circle { center, radius }) => {
                check_range("center", center)?;
                check_radius(radius)?;
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
            #[cfg(feature = "aim")]
            VolumeShape::Capsule { segment, radius } => check_capsule(&segment, radius)?,
        }
        Ok(())
    }
}

/// Which way an object faces: a volume is mirrored about the middle of the object's size on
/// each flipped axis (Replica Island: `x → width − x` when facing left). A game that aims
/// in any direction turns its attack volumes with [`HitObject::aim`](super::HitObject::aim)
/// as well.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Facing {
    /// Mirror x (facing left, for a game whose volumes are drawn facing right).
    pub flip_x: bool,
    /// Mirror y (facing down).
    pub flip_y: bool,
}

#[cfg(test)]
mod tests {
    use super::*;

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
        #[cfg(feature = "aim")]
        {
            assert_eq!(
                Volume::capsule(Vec2::ZERO, Vec2::X, -0.5, HitTypes::HIT),
                Err(VolumeError::NegativeRadius(-0.5))
            );
            assert!(matches!(
                Volume::capsule(
                    Vec2::ZERO,
                    Vec2::new(f32::INFINITY, 0.0),
                    0.5,
                    HitTypes::HIT
                ),
                Err(VolumeError::NonFinite { what: "b", .. })
            ));
            assert!(matches!(
                Volume::capsule(Vec2::new(-1e30, 0.0), Vec2::ZERO, 0.5, HitTypes::HIT),
                Err(VolumeError::OutOfRange { what: "a", .. })
            ));
        }
        // A rectangle built inside out from the public fields: tests/volumes.rs.
    }
}
