//! What a query refuses.

use thiserror::Error;

/// A circle cast with a radius that describes no circle.
///
/// A radius is a size: it is checked wherever one enters tileslide (a body's
/// [`BodyShape::circle`](crate::BodyShape::circle), a character's
/// [`CharacterShape::circle`](crate::CharacterShape::circle), a hit
/// [`Volume::circle`](crate::Volume::circle), and [`TileMap::cast_circle`]), so a sign
/// error or a NaN from a game's arithmetic surfaces where it happens instead of as a
/// circle that silently hits nothing. Positions and motions are answered as given: a
/// NaN one hits nothing, as it does for a ray.
///
/// [`TileMap::cast_circle`]: crate::TileMap::cast_circle
#[derive(Clone, Copy, Debug, Error, PartialEq)]
#[non_exhaustive]
pub enum CastError {
    /// The radius is zero, negative, NaN or infinite: a circle cast needs a positive,
    /// finite radius.
    #[error("circle cast radius {0} is not a positive, finite number")]
    InvalidRadius(f32),
}
