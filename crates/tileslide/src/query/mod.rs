//! Queries against a [`TileMap`](crate::TileMap) and its temporary segments: ray casts by
//! exact grid traversal, and overlap and point queries.

mod fast_walk;
mod filter;
mod hit;
mod overlap;
mod ray_cast;
mod segment_test;
mod traversal;

pub use filter::{Faces, RayFilter};
pub use hit::{RayHit, SegmentSource};
pub use overlap::SegmentOverlap;
