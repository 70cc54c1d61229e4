//! How `resolve` works: the time-of-impact method, the slide rule, the number of passes,
//! the broadphase and the contact gap.

use super::BodyError;
use crate::broadphase::Broadphase;

/// How the time of impact of a move is found.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum TimeOfImpact {
    /// Closed form: swept circle against circle (a quadratic) and against a segment's
    /// capsule. Nothing tunnels, at any speed. The default.
    #[default]
    Exact,
    /// The write-up's bisection: check the end of the move, then halve `halvings` times
    /// (at most [`ResolveConfig::MAX_HALVINGS`]).
    /// Kept for comparison: it only looks at sampled positions, so a move whose end is
    /// clear passes through anything in between, and the stop is up to `2^-halvings` of
    /// the move short of contact. The invariants of [`Bodies::resolve`](crate::Bodies::resolve)
    /// hold only with [`Exact`](Self::Exact).
    Bisection {
        /// Number of halvings (the write-up uses 4).
        halvings: u32,
    },
}

/// What happens to the blocked part of a move.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
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

/// Settings of [`Bodies::resolve`](crate::Bodies::resolve).
///
/// ```
/// # use tileslide::{ResolveConfig, SlideMode};
/// let config = ResolveConfig { slide: SlideMode::Tangential, ..ResolveConfig::default() };
/// assert_eq!(config.passes, 4);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ResolveConfig {
    /// Time-of-impact method.
    pub toi: TimeOfImpact,
    /// Slide rule.
    pub slide: SlideMode,
    /// Passes of detect-and-slide; the slides of one pass are checked by the next. After
    /// the last, any move still in conflict is cut short (never left overlapping). At most
    /// [`Self::MAX_PASSES`].
    pub passes: u32,
    /// Pair finding.
    pub broadphase: Broadphase,
    /// Separation that moving bodies keep from each other and from walls, as a fraction of
    /// the map's smaller cell side. Bodies stop between one half and one times this far
    /// from contact, so rounding never leaves them overlapping. Default `1e-3`; from 0 to
    /// [`Self::MAX_GAP`].
    pub gap: f32,
}

impl ResolveConfig {
    /// The largest [`gap`](Self::gap): one cell. A body keeps its gap from every wall, so a
    /// larger one would keep bodies out of one-cell corridors; and bounded, the gap in map
    /// units is at most a cell's side, which a map keeps within
    /// [`MAX_COORD`](crate::MAX_COORD).
    pub const MAX_GAP: f32 = 1.0;

    /// The most [`passes`](Self::passes): every pass of a blocked body costs a sweep against
    /// everything near it, and after a few the remainder is spent or cut anyway (the
    /// default is 4).
    pub const MAX_PASSES: u32 = 64;

    /// The most halvings of [`TimeOfImpact::Bisection`]: past 32 the probes' spacing is below
    /// an `f32`'s resolution of `t`.
    pub const MAX_HALVINGS: u32 = 32;

    /// An error naming the first field out of its range.
    pub(crate) fn check(&self) -> Result<(), BodyError> {
        let bad = |field, value| Err(BodyError::BadConfig { field, value });
        // Written so that NaN fails: it is refused, not read as 0.
        if !(self.gap >= 0.0 && self.gap <= Self::MAX_GAP) {
            return bad("gap", self.gap);
        }
        if self.passes > Self::MAX_PASSES {
            return bad("passes", self.passes as f32);
        }
        if let TimeOfImpact::Bisection { halvings } = self.toi
            && halvings > Self::MAX_HALVINGS
        {
            return bad("halvings", halvings as f32);
        }
        Ok(())
    }
}

impl Default for ResolveConfig {
    fn default() -> Self {
        Self {
            toi: TimeOfImpact::Exact,
            slide: SlideMode::FullLength,
            passes: 4,
            broadphase: Broadphase::UniformGrid,
            gap: 1e-3,
        }
    }
}
