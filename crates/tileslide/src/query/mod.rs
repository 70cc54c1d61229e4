//! Queries against a [`TileMap`](crate::TileMap) and its temporary segments: ray casts by
//! exact grid traversal, circle casts, and overlap and point queries.

mod circle_cast;
mod circle_wide;
mod debug_lines;
mod error;
mod fast_walk;
mod filter;
mod hit;
mod overlap;
mod ray_batch;
mod ray_cast;
mod segment_test;
mod traversal;

pub use circle_cast::CircleHit;
pub(crate) use circle_cast::{Capsule, Wall};
pub use error::CastError;
pub use filter::{Faces, QueryFilter};
pub use hit::{RayHit, SegmentSource};
pub use overlap::SegmentOverlap;
