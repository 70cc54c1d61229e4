//! Why a step fails: the library's own errors, passed on (bad input never panics).

use thiserror::Error;
use tileslide::{ControllerError, MapError, VolumeError};

/// Why a step failed (the library's own errors: bad input never panics).
#[derive(Debug, Error)]
pub enum GameError {
    /// The controller refused a move or a shape.
    #[error("controller: {0}")]
    Controller(#[from] ControllerError),
    /// The map refused the platform's segment.
    #[error("moving platform: {0}")]
    Map(#[from] MapError),
    /// The hit volumes refused an object (a position beyond `MAX_COORD`).
    #[error("hit volumes: {0}")]
    Volume(#[from] VolumeError),
}
