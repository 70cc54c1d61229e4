//! Geometry: segments, rays, circles and axis-aligned boxes, and the exact primitive tests
//! between them.
//!
//! Everything is `f32` with [`glam::Vec2`]. Degenerate and parallel cases have defined
//! results, documented on each function, rather than whatever the arithmetic happens to give.

mod aabb;
mod circle;
mod end_caps;
mod limits;
mod normal;
pub(crate) mod ray;
mod segment;
mod sweep;
mod sweep_box;

pub use aabb::Aabb;
pub use circle::Circle;
pub use end_caps::EndCaps;
pub use limits::MAX_COORD;
pub(crate) use limits::in_range;
pub(crate) use normal::unit_normal;
pub use ray::{PARALLEL_TOLERANCE, Ray, RaySegmentHit, cast_ray_segment};
pub use segment::Segment;
pub use sweep::{SweepHit, sweep_circle_circle, sweep_circle_segment};
pub(crate) use sweep::{circle_circle, circle_segment};
pub use sweep_box::sweep_box_segment;
