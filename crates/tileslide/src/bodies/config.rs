//! How `resolve` works (the slide rule, the number of passes, the broadphase and the contact
//! gap), and what it reports.

use super::error::BodyError;
use crate::broadphase::PairMethod;
use crate::geometry::MAX_COORD;

/// What happens to the blocked part of a move.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum SlideMode {
    /// The write-up's rule: the blocked remainder keeps its full length and is redirected
    /// along the contact tangent, to the side its projection points. The default.
    #[default]
    FullLength,
    /// Keep only the remainder's component along the tangent (the usual "slide" of
    /// character controllers: hitting a wall at a steep angle slides slowly).
    Tangential,
    /// No slide: the body stops at the contact.
    Stop,
}

/// Settings of [`Bodies::resolve`](crate::Bodies::resolve). Distances are in map units;
/// the defaults suit maps with cells of size 1 (scale them with the cell size, e.g. ×32 for
/// a map in pixels with 32-pixel cells).
///
/// ```
/// # use tileslide::{BodyError, ResolveConfig, SlideMode};
/// let config = ResolveConfig { slide: SlideMode::Tangential, ..ResolveConfig::default() };
/// assert_eq!(config.passes, 4);
/// // A map in pixels, with 32-pixel cells: the same gap, a thousandth of a cell.
/// let pixels = ResolveConfig { gap: 1e-3 * 32.0, ..ResolveConfig::default() };
/// assert_eq!(pixels.validate(), Ok(()));
/// let negative = ResolveConfig { gap: -1.0, ..pixels };
/// assert_eq!(negative.validate(), Err(BodyError::BadConfig { field: "gap", value: -1.0 }));
/// ```
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ResolveConfig {
    /// Slide rule.
    pub slide: SlideMode,
    /// Passes of detect-and-slide; the slides of one pass are checked by the next. After
    /// the last, any move still in conflict is cut short (never left overlapping). At most
    /// [`Self::MAX_PASSES`].
    pub passes: u32,
    /// Pair finding.
    pub broadphase: PairMethod,
    /// Separation that moving bodies keep from each other and from walls, in map units.
    /// Bodies stop between one half and one times this far from contact, so rounding never
    /// leaves them overlapping. Default `1e-3`, a thousandth of a cell of side 1: scale it
    /// with the cell size, keeping it well below a cell's side (a body keeps its gap from
    /// every wall, so with a gap of a cell no body fits a one-cell corridor) and above the
    /// spacing of `f32` values at the map's coordinates (safe steps shorter than an eighth
    /// of it are not taken, so that rounding cannot creep a body into another). From 0 to
    /// [`Self::MAX_GAP`].
    pub gap: f32,
}

impl ResolveConfig {
    /// The largest [`gap`](Self::gap), a distance like every coordinate: [`MAX_COORD`].
    /// Bounded so, the gap adds to the radii and moves the resolver squares without
    /// overflow.
    pub const MAX_GAP: f32 = MAX_COORD;

    /// The most [`passes`](Self::passes): every pass of a blocked body costs a sweep against
    /// everything near it, and after a few the remainder is spent or cut anyway (the
    /// default is 4).
    pub const MAX_PASSES: u32 = 64;

    /// Whether the settings can be used: every field in its range (see each field).
    /// [`Bodies::with_config`](crate::Bodies::with_config) and
    /// [`Bodies::set_config`](crate::Bodies::set_config) refuse what this refuses.
    ///
    /// # Errors
    /// [`BodyError::BadConfig`] naming the first field out of its range and its value (a
    /// NaN gap included).
    pub fn validate(&self) -> Result<(), BodyError> {
        let bad = |field, value| Err(BodyError::BadConfig { field, value });
        // Written so that NaN fails: it is refused, not read as 0.
        if !(self.gap >= 0.0 && self.gap <= Self::MAX_GAP) {
            return bad("gap", self.gap);
        }
        if self.passes > Self::MAX_PASSES {
            return bad("passes", self.passes as f32);
        }
        Ok(())
    }
}

impl Default for ResolveConfig {
    fn default() -> Self {
        Self {
            slide: SlideMode::FullLength,
            passes: 4,
            broadphase: PairMethod::UniformGrid,
            gap: 1e-3,
        }
    }
}

/// What a [`resolve`](crate::Bodies::resolve) did.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ResolveReport {
    /// Bodies with a non-zero proposed move.
    pub moving: usize,
    /// How many contacts were met (each sweep that stopped at something counts once).
    pub contact_count: usize,
    /// Bodies whose remainder was still blocked after the last pass, and was cut at its
    /// first contact.
    pub cut_short: usize,
}
