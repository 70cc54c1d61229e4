//! Where a volume is in the world during a frame, and the exact test of one placed volume
//! moving against another.
//!
//! A volume is placed in three steps, in object-local coordinates and then in the world:
//! mirrored about the middle of the object's size on each axis its [`Facing`] flips, then,
//! for an attack volume of an object with an [`aim`](super::HitObject::aim), turned about
//! that same middle so that the local `+x` points along the aim, then moved to the object's
//! position.
//!
//! Touching counts: volumes are closed sets, so two volumes that share only a boundary
//! point overlap (Replica Island's tests are strict, so touching never hit there). The same
//! rule as the broadphase's, so a pair the exact test accepts is never culled before it.
//! Circles and upright rectangles, the shapes of most games, have exact tests of their own;
//! turned rectangles and capsules are tested as rounded convex cores (`rounded.rs`).
//!
//! With the `aim` feature the shapes' enums have more variants, and LLVM keeps the hot
//! placing and checking functions out of line, at a cost of about a quarter more
//! instructions per `register`; they are marked `inline` for that build only (without it,
//! the web package's build, LLVM inlines them as it judges best for size).

use glam::Vec2;

#[cfg(feature = "aim")]
use super::rounded::Rounded;
use super::volume::{Facing, VolumeShape};
use crate::geometry::{Aabb, Segment};

/// A volume's shape in world coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Placed {
    Circle {
        center: Vec2,
        radius: f32,
    },
    Rect(Aabb),
    /// A rectangle turned by an aim that is not a quarter turn: its centre, the unit
    /// direction its local `x` axis points along, and its half extents.
    #[cfg(feature = "aim")]
    Turned {
        center: Vec2,
        axis: Vec2,
        half: Vec2,
    },
    #[cfg(feature = "aim")]
    Capsule {
        a: Vec2,
        b: Vec2,
        radius: f32,
    },
}

/// `p` (object-local) mirrored about the middle of `size` on each axis `facing` flips.
fn mirrored(p: Vec2, size: Vec2, facing: Facing) -> Vec2 {
    let mirror = |v: f32, extent: f32, flip: bool| if flip { extent - v } else { v };
    Vec2::new(
        mirror(p.x, size.x, facing.flip_x),
        mirror(p.y, size.y, facing.flip_y),
    )
}

/// The rectangle `b` (object-local) of an object at `position` of `size`, mirrored about
/// the middle of the size on each axis `facing` flips.
#[cfg_attr(feature = "aim", inline)]
fn mirrored_rect(b: &Aabb, position: Vec2, size: Vec2, facing: Facing) -> Aabb {
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
    Aabb {
        min: position + Vec2::new(x0, y0),
        max: position + Vec2::new(x1, y1),
    }
}

impl Placed {
    /// `shape` of an object at `position` of `size`, facing `facing`.
    #[cfg_attr(feature = "aim", inline)]
    pub fn new(shape: &VolumeShape, position: Vec2, size: Vec2, facing: Facing) -> Self {
        match *shape {
            VolumeShape::Circle(c) => Placed::Circle {
                center: position + mirrored(c.center, size, facing),
                radius: c.radius,
            },
            VolumeShape::Rect(b) => Placed::Rect(mirrored_rect(&b, position, size, facing)),
            #[cfg(feature = "aim")]
            VolumeShape::Capsule { segment, radius } => Placed::Capsule {
                a: position + mirrored(segment.a, size, facing),
                b: position + mirrored(segment.b, size, facing),
                radius,
            },
        }
    }

    /// The smallest box holding `shape` of an object at `position` of `size`, facing
    /// `facing`: `Placed::new(…).aabb()`, without building the placed shape (registering
    /// computes one per volume).
    #[cfg_attr(feature = "aim", inline)]
    pub fn new_aabb(shape: &VolumeShape, position: Vec2, size: Vec2, facing: Facing) -> Aabb {
        match *shape {
            VolumeShape::Circle(c) => {
                let center = position + mirrored(c.center, size, facing);
                Aabb {
                    min: center - Vec2::splat(c.radius),
                    max: center + Vec2::splat(c.radius),
                }
            }
            VolumeShape::Rect(b) => mirrored_rect(&b, position, size, facing),
            #[cfg(feature = "aim")]
            _ => Placed::new(shape, position, size, facing).aabb(),
        }
    }

    /// As [`new`](Self::new), with the mirrored shape turned by the unit vector `turn` (the
    /// local `+x` onto `turn`) about the middle of the object's size before it is moved to
    /// `position`. (Out of line: the hot loops place upright volumes.)
    #[cfg(feature = "aim")]
    #[inline(never)]
    pub fn turned(
        shape: &VolumeShape,
        position: Vec2,
        size: Vec2,
        facing: Facing,
        turn: Vec2,
    ) -> Self {
        let pivot = size * 0.5;
        let at = |p: Vec2| position + (pivot + turn.rotate(mirrored(p, size, facing) - pivot));
        match *shape {
            VolumeShape::Circle(c) => Placed::Circle {
                center: at(c.center),
                radius: c.radius,
            },
            VolumeShape::Capsule { segment, radius } => Placed::Capsule {
                a: at(segment.a),
                b: at(segment.b),
                radius,
            },
            // A quarter turn (or none) keeps a rectangle upright, exactly: turning by a unit
            // axis vector only swaps and negates coordinates.
            VolumeShape::Rect(b) if turn.x == 0.0 || turn.y == 0.0 => {
                Placed::Rect(Aabb::from_corners(at(b.min), at(b.max)))
            }
            VolumeShape::Rect(b) => Placed::Turned {
                center: at((b.min + b.max) * 0.5),
                axis: turn,
                half: (b.max - b.min) * 0.5,
            },
        }
    }

    /// A box and a radius: the volume is the points within the radius of the box, for a
    /// circle (its centre, its radius) and an upright rectangle (itself, 0). A turned
    /// rectangle or a capsule gives its bounding box and 0, which holds it
    /// ([`contact`](Self::contact) tests those as `Rounded` instead).
    pub fn rounded_box(&self) -> (Aabb, f32) {
        match *self {
            Placed::Circle { center, radius } => (
                Aabb {
                    min: center,
                    max: center,
                },
                radius,
            ),
            Placed::Rect(b) => (b, 0.0),
            #[cfg(feature = "aim")]
            _ => (self.aabb(), 0.0),
        }
    }

    /// True for the shapes [`rounded_box`](Self::rounded_box) gives exactly: circles and
    /// upright rectangles.
    #[cfg(feature = "aim")]
    pub fn is_rounded_box(&self) -> bool {
        matches!(self, Placed::Circle { .. } | Placed::Rect(_))
    }

    /// The shape as a rounded convex core. A rectangle of zero width or height is the
    /// segment between its corners: a quadrilateral without area would hold every point in
    /// the sign test of `Rounded::contains`.
    #[cfg(feature = "aim")]
    pub fn rounded(&self) -> Rounded {
        let (corners, flat) = match *self {
            Placed::Circle { center, radius } => return Rounded::point(center, radius),
            Placed::Capsule { a, b, radius } => return Rounded::segment(a, b, radius),
            Placed::Rect(b) => (
                [
                    b.min,
                    Vec2::new(b.max.x, b.min.y),
                    b.max,
                    Vec2::new(b.min.x, b.max.y),
                ],
                b.min.cmpeq(b.max).any(),
            ),
            Placed::Turned { center, axis, half } => (
                [
                    Vec2::new(-half.x, -half.y),
                    Vec2::new(half.x, -half.y),
                    half,
                    Vec2::new(-half.x, half.y),
                ]
                .map(|corner| center + axis.rotate(corner)),
                half.cmpeq(Vec2::ZERO).any(),
            ),
        };
        if flat {
            Rounded::segment(corners[0], corners[2], 0.0)
        } else {
            Rounded::quad(corners)
        }
    }

    /// The smallest box holding it (for a turned rectangle, its corners as the exact tests
    /// compute them).
    #[cfg_attr(feature = "aim", inline)]
    pub fn aabb(&self) -> Aabb {
        match *self {
            Placed::Circle { center, radius } => Aabb {
                min: center - Vec2::splat(radius),
                max: center + Vec2::splat(radius),
            },
            Placed::Rect(b) => b,
            #[cfg(feature = "aim")]
            _ => self.rounded().aabb(),
        }
    }

    /// Its farthest point from `p`, as a distance.
    pub fn reach_from(&self, p: Vec2) -> f32 {
        match *self {
            Placed::Circle { center, radius } => center.distance(p) + radius,
            Placed::Rect(b) => (b.min - p).abs().max((b.max - p).abs()).length(),
            #[cfg(feature = "aim")]
            _ => self.rounded().reach_from(p),
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
                segment_entry((a.min + a.max) * 0.5, motion, &grown).is_some()
            }
            #[cfg(feature = "aim")]
            _ => self.rounded().meets(motion, &other.rounded()),
        }
    }
}

/// True when the disc of `radius` whose centre moves from `center` by `motion` touches the
/// closed box. The path is a segment; disjoint convex sets are nearest at an end point of
/// one of them, so the distance is the least of the segment's ends to the box and the box's
/// corners to the segment (zero if the segment crosses the box).
fn circle_path_meets_box(center: Vec2, motion: Vec2, radius: f32, b: &Aabb) -> bool {
    if segment_entry(center, motion, b).is_some() {
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

/// The first fraction of the segment from `p` by `d` in the closed box, if any (slab test;
/// Kay–Kajiya, as in Ericson, *Real-Time Collision Detection*, 5.3.3): 0 when `p` is in it.
pub(super) fn segment_entry(p: Vec2, d: Vec2, b: &Aabb) -> Option<f32> {
    let (mut t0, mut t1) = (0.0f32, 1.0f32);
    for axis in 0..2 {
        let (o, v, lo, hi) = (p[axis], d[axis], b.min[axis], b.max[axis]);
        if v == 0.0 {
            if o < lo || o > hi {
                return None;
            }
        } else {
            let (a, c) = ((lo - o) / v, (hi - o) / v);
            t0 = t0.max(a.min(c));
            t1 = t1.min(a.max(c));
            if t0 > t1 {
                return None;
            }
        }
    }
    Some(t0)
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::geometry::Circle;

    /// The circle at (`x`, `y`) of radius `r`.
    pub(in crate::volumes) fn circle(x: f32, y: f32, r: f32) -> Placed {
        Placed::Circle {
            center: Vec2::new(x, y),
            radius: r,
        }
    }

    /// The upright rectangle from (`x0`, `y0`) to (`x1`, `y1`).
    pub(in crate::volumes) fn rect(x0: f32, y0: f32, x1: f32, y1: f32) -> Placed {
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

    #[cfg(feature = "aim")]
    fn right_and_left(flip_x: bool) -> Facing {
        Facing {
            flip_x,
            flip_y: false,
        }
    }

    #[cfg(feature = "aim")]
    #[test]
    fn a_quarter_turn_keeps_a_rect_upright_and_exact() {
        // A blade 1 long and 0.2 thick reaching right of a 2 × 2 object at (10, 20), whose
        // middle is (11, 21); aimed down (+y), it hangs below the middle instead.
        let blade = VolumeShape::Rect(Aabb {
            min: Vec2::new(1.5, 0.9),
            max: Vec2::new(2.5, 1.1),
        });
        let at = Vec2::new(10.0, 20.0);
        let size = Vec2::splat(2.0);
        let down = Placed::turned(&blade, at, size, Facing::default(), Vec2::Y);
        assert_eq!(down, rect(10.9, 21.5, 11.1, 22.5));
        let up = Placed::turned(&blade, at, size, Facing::default(), Vec2::NEG_Y);
        assert_eq!(up, rect(10.9, 19.5, 11.1, 20.5));
        // Aiming right changes nothing; aiming left is mirroring x (and y, about the
        // middle: the blade is symmetric in y here).
        let ahead = Placed::turned(&blade, at, size, Facing::default(), Vec2::X);
        assert_eq!(ahead, Placed::new(&blade, at, size, Facing::default()));
        let back = Placed::turned(&blade, at, size, Facing::default(), Vec2::NEG_X);
        assert_eq!(back, Placed::new(&blade, at, size, right_and_left(true)));
    }

    #[cfg(feature = "aim")]
    #[test]
    fn a_turn_comes_after_mirroring_about_the_same_middle() {
        // A fist at (1.5, 0.5) of a 1 × 1 object: facing left it is at (−0.5, 0.5); then a
        // quarter turn to +y takes the local +x to +y about the middle (0.5, 0.5), so the
        // mirrored fist, left of the middle, ends above it, at (0.5, −0.5).
        let fist = VolumeShape::Circle(Circle::new(Vec2::new(1.5, 0.5), 0.25));
        let turned = Placed::turned(&fist, Vec2::ZERO, Vec2::ONE, right_and_left(true), Vec2::Y);
        assert_eq!(turned, circle(0.5, -0.5, 0.25));
    }

    #[cfg(feature = "aim")]
    #[test]
    fn a_turned_rect_is_tested_as_the_turned_rect() {
        // A 2 × 0.2 blade centred on a point object, turned 45°: its tip reaches about
        // (0.707, 0.707), where the upright blade (which reaches (1, 0)) does not.
        let blade = VolumeShape::Rect(Aabb {
            min: Vec2::new(-1.0, -0.1),
            max: Vec2::new(1.0, 0.1),
        });
        let diagonal = Vec2::ONE.normalize();
        let placed = Placed::turned(&blade, Vec2::ZERO, Vec2::ZERO, Facing::default(), diagonal);
        assert!(matches!(placed, Placed::Turned { .. }));
        assert!(placed.meets(Vec2::ZERO, &circle(0.65, 0.65, 0.01)));
        assert!(!placed.meets(Vec2::ZERO, &circle(0.9, 0.0, 0.05)));
        assert!(!placed.meets(Vec2::ZERO, &circle(0.5, 0.0, 0.1)));
        // Swept across a target that both of its ends miss.
        assert!(placed.meets(Vec2::new(4.0, 0.0), &circle(2.0, 0.0, 0.05)));
        assert!(!placed.meets(Vec2::new(4.0, 0.0), &circle(2.0, 1.0, 0.05)));
        // The box that holds it holds its corners and no more.
        let b = placed.aabb();
        let reach = 1.0 * diagonal.x + 0.1 * diagonal.x;
        assert!(
            (b.max.x - reach).abs() < 1e-6 && (b.min.y + reach).abs() < 1e-6,
            "{b:?}"
        );
    }

    #[cfg(feature = "aim")]
    #[test]
    fn a_capsule_is_mirrored_turned_and_tested_by_its_segment() {
        let sword = VolumeShape::Capsule {
            segment: Segment::new(Vec2::new(1.0, 0.5), Vec2::new(2.0, 0.5)),
            radius: 0.125,
        };
        let left = Placed::new(&sword, Vec2::ZERO, Vec2::ONE, right_and_left(true));
        assert_eq!(
            left,
            Placed::Capsule {
                a: Vec2::new(0.0, 0.5),
                b: Vec2::new(-1.0, 0.5),
                radius: 0.125
            }
        );
        assert!(left.meets(Vec2::ZERO, &circle(-1.05, 0.55, 0.01)));
        assert!(!left.meets(Vec2::ZERO, &circle(-1.05, 0.7, 0.01)));
        // Touching its side counts (0.5 + 0.125 is exact), a hair beyond does not.
        assert!(left.meets(Vec2::ZERO, &rect(-0.6, 0.625, -0.4, 0.9)));
        assert!(!left.meets(Vec2::ZERO, &rect(-0.6, 0.626, -0.4, 0.9)));
        // Two capsules crossing like an X, their ends far apart.
        let other = Placed::Capsule {
            a: Vec2::new(-0.5, 0.0),
            b: Vec2::new(-0.5, 1.0),
            radius: 0.0,
        };
        assert!(left.meets(Vec2::ZERO, &other));
    }
}
