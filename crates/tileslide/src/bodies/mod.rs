//! Free-moving bodies: circles and compounds of circles that slide around each other and
//! along walls, never overlapping.
//!
//! A step is the three loops of "Simple sphere-based collision detection and response"
//! (the Dungeon Builder write-up): the caller [proposes](Bodies::propose) a move per body;
//! [`resolve`](Bodies::resolve) finds each move's exact time of impact against the walls
//! and the other bodies and slides the blocked remainder along the contact tangent; then
//! [`integrate`](Bodies::integrate) applies the resolved moves. See `resolve` for the
//! guarantees and `docs/resolver.md` for the design.
//!
//! The files depend on each other in one direction only: `set` (the [`Bodies`] a caller
//! holds) uses `resolver`, which uses the contact rules (`contact`) and its memories
//! (`neighbours`, `near_walls`, `settled`, `map_watch`); all of them use the plain types
//! (`body`, `config`, `error`, `handle`).

mod body;
mod config;
mod contact;
mod debug_lines;
mod error;
mod handle;
mod map_watch;
mod near_walls;
mod neighbours;
mod resolver;
pub(crate) mod set;
mod settled;
mod trace;

pub use body::{Body, BodyDesc, BodyFilter, BodyShape, MAX_COMPOUND_CIRCLES};
pub use config::{ResolveConfig, ResolveReport, SlideMode};
pub use error::BodyError;
pub use handle::BodyHandle;
pub use set::Bodies;
pub use trace::{
    BodyFate, BodyTrace, ContactPart, ContactSource, ContactTrace, PassTrace, ResolveTrace,
    Response,
};
