//! Free-moving bodies: circles and compounds of circles that slide around each other and
//! along walls, never overlapping.
//!
//! A step is the three loops of "Simple sphere-based collision detection and response"
//! (the Dungeon Builder write-up): the caller [proposes](Bodies::propose) a move per body;
//! [`resolve`](Bodies::resolve) finds each move's exact time of impact against the walls
//! and the other bodies and slides the blocked remainder along the contact tangent; then
//! [`integrate`](Bodies::integrate) applies the resolved moves. See `resolve` for the
//! guarantees and `docs/resolver.md` for the design.

mod body;
mod config;
mod map_watch;
mod near_walls;
mod neighbours;
mod resolve;
mod set;
mod settled;

pub use body::{BodyDesc, BodyFilter, BodyShape};
pub use config::{ResolveConfig, SlideMode, TimeOfImpact};
pub use resolve::ResolveReport;
pub use set::{Bodies, Body, BodyError, BodyHandle};
