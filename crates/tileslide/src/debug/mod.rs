//! Debug lines: what the collision world looks like, as kinded segments, circles, points
//! and boxes that any front end draws (see [`DebugLines`] and `docs/debug-lines.md`).

mod kind;
mod lines;

pub use kind::{DebugKind, DebugKinds};
pub use lines::{DebugBox, DebugCircle, DebugLines, DebugPoint, DebugSegment};
