//! The caller's entity, in the one name every part of the crate uses for it.

/// The caller's id for its entity (for example a Bevy `Entity::to_bits()`): who submitted a
/// temporary segment, whose a body is, which object a hit volume belongs to. tileslide
/// never reads it, except to compare: a query's filter can skip an owner's temporary
/// segments, and "hit once per swing" remembers the owners a swing hit.
///
/// ```
/// use tileslide::{BodyDesc, BodyShape, Owner, Vec2};
/// let hero = Owner(7);
/// let desc = BodyDesc::new(Vec2::new(3.5, 2.5), BodyShape::circle(0.3)?).with_owner(hero);
/// assert_eq!(desc.owner, hero);
/// assert_eq!(Owner::default(), Owner(0));
/// # Ok::<(), tileslide::BodyError>(())
/// ```
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[cfg_attr(feature = "serde", serde(transparent))]
pub struct Owner(pub u64);
