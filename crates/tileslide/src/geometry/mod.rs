//! The exact pair primitives: a ray against a segment, a circle against a circle or a
//! segment's capsule, a box against a segment, each answering the time of impact of one
//! moving shape against one still one. The map's queries, the bodies and the character are
//! built on them; a game calls them directly only for shapes of its own, outside the map.
//!
//! The shapes they take, [`Segment`], [`Ray`],
//! [`Circle`] and [`Aabb`], are at the crate root: the
//! every-frame API takes them too. Everything is `f32` with [`glam::Vec2`]. Degenerate and
//! parallel cases have defined results, documented on each function, rather than whatever
//! the arithmetic happens to give.
//!
//! ```
//! use tileslide::geometry::{EndCaps, sweep_circle_circle, sweep_circle_segment};
//! use tileslide::{Segment, Vec2};
//! // A ball of radius 0.5 falling from y = 3 onto a floor along y = 0 facing up.
//! let floor = Segment::new(Vec2::new(-5.0, 0.0), Vec2::new(5.0, 0.0));
//! let fall = Vec2::new(0.0, -5.0);
//! let hit = sweep_circle_segment(Vec2::new(0.0, 3.0), 0.5, fall, &floor, Vec2::Y, EndCaps::BOTH);
//! assert_eq!(hit.map(|h| h.t), Some(0.5));
//! // Its centre against a point 1 below its path's end: the contact radius is 1.
//! let hit = sweep_circle_circle(Vec2::new(0.0, 3.0), fall, Vec2::new(0.0, -3.0), 1.0);
//! assert_eq!(hit.map(|h| h.t), Some(1.0));
//! ```

// The shapes are `pub(crate)` modules so that the crate root can re-export them by their
// own path: this module's public names are only the primitives.
pub(crate) mod aabb;
pub(crate) mod circle;
mod end_caps;
pub(crate) mod limits;
mod normal;
pub(crate) mod ray;
pub(crate) mod segment;
mod sweep;
mod sweep_box;

pub(crate) use aabb::Aabb;
pub(crate) use circle::Circle;
pub use end_caps::EndCaps;
pub(crate) use limits::{MAX_COORD, in_range};
pub(crate) use normal::unit_normal;
pub(crate) use ray::Ray;
pub use ray::{PARALLEL_TOLERANCE, RaySegmentHit, cast_ray_segment};
pub(crate) use segment::Segment;
pub use sweep::{SweepHit, sweep_circle_circle, sweep_circle_segment};
pub(crate) use sweep::{circle_circle, circle_segment};
pub use sweep_box::sweep_box_segment;
