use std::fmt;
use std::ops::{BitAnd, BitOr, BitOrAssign};

/// What a segment is: a bit set. The low bits are tileslide's own; bits 8 to 31 are the
/// game's (hazard, material, …).
///
/// ```
/// # use tileslide::SegmentFlags;
/// let spikes = SegmentFlags::SOLID | SegmentFlags::user(0).unwrap();
/// assert!(spikes.intersects(SegmentFlags::SOLID));
/// assert!(!spikes.intersects(SegmentFlags::ONE_WAY));
/// ```
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "serde", serde(transparent))]
pub struct SegmentFlags(pub u32);

impl SegmentFlags {
    /// No flags. A segment with no flags matches no query mask.
    pub const NONE: Self = Self(0);
    /// The boundary of solid material: hides an opposite-facing neighbour it coincides with
    /// (seam culling) and encloses the area that [`TileMap::is_point_solid`] reports.
    ///
    /// [`TileMap::is_point_solid`]: crate::TileMap::is_point_solid
    pub const SOLID: Self = Self(1);
    /// A one-way platform: blocks only from its front side. It hides nothing behind it.
    pub const ONE_WAY: Self = Self(1 << 1);
    /// Every bit: the default query mask.
    pub const ALL: Self = Self(u32::MAX);
    /// The first bit free for the game.
    pub const FIRST_USER_BIT: u32 = 8;

    /// The game's bit number `n` (0 to 23), or `None` past the last one.
    #[must_use]
    pub fn user(n: u32) -> Option<Self> {
        (n < 32 - Self::FIRST_USER_BIT).then(|| Self(1 << (Self::FIRST_USER_BIT + n)))
    }

    /// True when every bit of `other` is set here.
    #[must_use]
    pub fn contains(self, other: Self) -> bool {
        self.0 & other.0 == other.0
    }

    /// True when at least one bit of `other` is set here.
    #[must_use]
    pub fn intersects(self, other: Self) -> bool {
        self.0 & other.0 != 0
    }

    /// True when no bit is set.
    #[must_use]
    pub fn is_empty(self) -> bool {
        self.0 == 0
    }
}

impl BitOr for SegmentFlags {
    type Output = Self;
    fn bitor(self, rhs: Self) -> Self {
        Self(self.0 | rhs.0)
    }
}

impl BitOrAssign for SegmentFlags {
    fn bitor_assign(&mut self, rhs: Self) {
        self.0 |= rhs.0;
    }
}

impl BitAnd for SegmentFlags {
    type Output = Self;
    fn bitand(self, rhs: Self) -> Self {
        Self(self.0 & rhs.0)
    }
}

impl fmt::Debug for SegmentFlags {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut parts = Vec::new();
        if self.contains(Self::SOLID) {
            parts.push("SOLID".to_string());
        }
        if self.contains(Self::ONE_WAY) {
            parts.push("ONE_WAY".to_string());
        }
        let rest = self.0 & !(Self::SOLID.0 | Self::ONE_WAY.0);
        if rest != 0 {
            parts.push(format!("{rest:#x}"));
        }
        if parts.is_empty() {
            parts.push("NONE".to_string());
        }
        write!(f, "SegmentFlags({})", parts.join(" | "))
    }
}
