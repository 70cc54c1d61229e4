//! What each debug line shows, and sets of kinds to ask for.

/// What a debug line, circle, point or box shows: the front end picks its colour and layer
/// by it.
///
/// The numbers are stable (`kind as u8`): the JavaScript package hands them to canvas code
/// as bytes, and a front end may keep a table indexed by them. New kinds take new numbers.
///
/// ```
/// use tileslide::DebugKind;
///
/// assert_eq!(DebugKind::HiddenSegment as u8, 3);
/// assert_eq!(DebugKind::from_u8(3), Some(DebugKind::HiddenSegment));
/// assert_eq!(DebugKind::HiddenSegment.name(), "hidden_segment");
/// assert_eq!(DebugKind::ALL.len(), DebugKind::COUNT);
/// ```
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[repr(u8)]
#[non_exhaustive]
pub enum DebugKind {
    /// An active solid segment of the map, after seam culling (a segment).
    ActiveSegment = 0,
    /// An active one-way platform segment of the map (a segment).
    OneWaySegment = 1,
    /// A segment's outward normal: from the middle of the segment, a quarter of a cell
    /// long (a segment; its start is on the surface).
    Normal = 2,
    /// A piece of a tile's segment that seam culling hides: it lies against an
    /// opposite-facing solid segment of the neighbouring cell, so no query ever meets it
    /// (a segment, running with its normal on the right as active segments do).
    HiddenSegment = 3,
    /// A temporary segment: a moving platform, a door (a segment, with its normal as a
    /// [`Normal`](Self::Normal)).
    TemporarySegment = 4,
    /// A body's circle (a circle; one per circle of a compound).
    Body = 5,
    /// A character's shape (a circle or a box).
    Character = 6,
    /// A surface a character or body touched: from the contact point along the surface's
    /// normal (a segment).
    Contact = 7,
    /// A ray, from its origin to its end or hit (a segment).
    Ray = 8,
    /// Where a ray hit (a point, with the hit normal as a [`Normal`](Self::Normal)).
    RayHit = 9,
    /// An attack volume, placed in the world (a circle or a box).
    AttackVolume = 10,
    /// A vulnerability volume, placed in the world (a circle or a box).
    VulnerabilityVolume = 11,
    /// An accepted hit event, at the middle of the victim's box (a point).
    Hit = 12,
    /// A hit event the victim refused (a point).
    RefusedHit = 13,
    /// A leg of a navigation path (a segment).
    Path = 14,
    /// A flow field's next move out of a lattice node, half of the way to the next node
    /// (a segment, from the node).
    FlowArrow = 15,
    /// A box the broadphase files something under: a body circle's reach grown by the
    /// margin its neighbours were found for (they are found again once it leaves the box),
    /// a hit object's swept reach (a box).
    BroadphaseBox = 16,
}

impl DebugKind {
    /// How many kinds there are.
    pub const COUNT: usize = 17;

    /// Every kind, by number.
    pub const ALL: [DebugKind; Self::COUNT] = [
        Self::ActiveSegment,
        Self::OneWaySegment,
        Self::Normal,
        Self::HiddenSegment,
        Self::TemporarySegment,
        Self::Body,
        Self::Character,
        Self::Contact,
        Self::Ray,
        Self::RayHit,
        Self::AttackVolume,
        Self::VulnerabilityVolume,
        Self::Hit,
        Self::RefusedHit,
        Self::Path,
        Self::FlowArrow,
        Self::BroadphaseBox,
    ];

    /// The kind numbered `n` (`kind as u8`), or `None` for a number no kind has.
    #[must_use]
    pub fn from_u8(n: u8) -> Option<Self> {
        Self::ALL.get(usize::from(n)).copied()
    }

    /// The kind's name in snake case (`"hidden_segment"`), as front ends show it.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::ActiveSegment => "active_segment",
            Self::OneWaySegment => "one_way_segment",
            Self::Normal => "normal",
            Self::HiddenSegment => "hidden_segment",
            Self::TemporarySegment => "temporary_segment",
            Self::Body => "body",
            Self::Character => "character",
            Self::Contact => "contact",
            Self::Ray => "ray",
            Self::RayHit => "ray_hit",
            Self::AttackVolume => "attack_volume",
            Self::VulnerabilityVolume => "vulnerability_volume",
            Self::Hit => "hit",
            Self::RefusedHit => "refused_hit",
            Self::Path => "path",
            Self::FlowArrow => "flow_arrow",
            Self::BroadphaseBox => "broadphase_box",
        }
    }
}

/// A set of [`DebugKind`]s: which ones a [`DebugLines`](crate::DebugLines) buffer takes.
/// Fillers skip the work for kinds left out (the map computes no hidden pieces unless
/// [`HiddenSegment`](DebugKind::HiddenSegment) is in the set).
///
/// ```
/// use tileslide::{DebugKind, DebugKinds};
///
/// let walls = DebugKinds::NONE
///     .with(DebugKind::ActiveSegment)
///     .with(DebugKind::OneWaySegment);
/// assert!(walls.contains(DebugKind::ActiveSegment));
/// assert!(!walls.contains(DebugKind::Normal));
/// assert!(!DebugKinds::ALL.without(DebugKind::Normal).contains(DebugKind::Normal));
/// assert_eq!(DebugKinds::default(), DebugKinds::ALL);
/// ```
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(transparent))]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct DebugKinds(pub u32);

impl DebugKinds {
    /// No kind.
    pub const NONE: Self = Self(0);
    /// Every kind, including those added later.
    pub const ALL: Self = Self(u32::MAX);

    /// This set with `kind` in it.
    #[must_use]
    pub const fn with(self, kind: DebugKind) -> Self {
        Self(self.0 | 1 << kind as u32)
    }

    /// This set without `kind`.
    #[must_use]
    pub const fn without(self, kind: DebugKind) -> Self {
        Self(self.0 & !(1 << kind as u32))
    }

    /// True when `kind` is in the set.
    #[must_use]
    pub const fn contains(self, kind: DebugKind) -> bool {
        self.0 & 1 << kind as u32 != 0
    }
}

impl Default for DebugKinds {
    /// Every kind.
    fn default() -> Self {
        Self::ALL
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_kind_is_numbered_by_its_place_in_all() {
        for (n, kind) in DebugKind::ALL.into_iter().enumerate() {
            assert_eq!(kind as usize, n);
            assert_eq!(DebugKind::from_u8(n as u8), Some(kind));
        }
        assert_eq!(DebugKind::from_u8(DebugKind::COUNT as u8), None);
    }

    #[test]
    fn names_are_distinct_snake_case() {
        let mut names: Vec<&str> = DebugKind::ALL.iter().map(|k| k.name()).collect();
        assert!(
            names
                .iter()
                .all(|n| n.chars().all(|c| c.is_ascii_lowercase() || c == '_'))
        );
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), DebugKind::COUNT);
    }

    #[test]
    fn a_set_holds_what_was_put_in() {
        let set = DebugKinds::NONE.with(DebugKind::Body).with(DebugKind::Path);
        for kind in DebugKind::ALL {
            let expected = matches!(kind, DebugKind::Body | DebugKind::Path);
            assert_eq!(set.contains(kind), expected, "{kind:?}");
        }
        assert_eq!(
            set.without(DebugKind::Body),
            DebugKinds::NONE.with(DebugKind::Path)
        );
    }
}
