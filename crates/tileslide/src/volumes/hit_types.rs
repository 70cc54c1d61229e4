//! Hit types: what an attack deals and what a vulnerability accepts, as a bit set.

use std::fmt;
use std::ops::{BitAnd, BitOr, BitOrAssign};

/// A set of hit types. An attack volume deals the types of its set and a vulnerability
/// volume accepts the types of its own; they match when the sets share a type. The game
/// defines its types as bits ([`HitTypes::from_bits`]); Replica Island's six are provided
/// as constants, and [`HitTypes::ANY`] (every bit) matches everything, on either side.
///
/// ```
/// use tileslide::HitTypes;
/// // A game's own type, beside the provided ones.
/// const FREEZE: HitTypes = HitTypes::from_bits(1 << 8);
/// let coin = HitTypes::COLLECT;
/// assert!(HitTypes::COLLECT.matches(coin));
/// assert!(!HitTypes::HIT.matches(coin));
/// assert!(HitTypes::ANY.matches(FREEZE) && FREEZE.matches(HitTypes::ANY));
/// assert_eq!(HitTypes::ANY & coin, coin); // what a hit of "any" on a coin deals
/// ```
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "serde", serde(transparent))]
pub struct HitTypes(u32);

impl HitTypes {
    /// No type: a volume with it never hits and is never hit.
    pub const NONE: Self = Self(0);
    /// Every type.
    pub const ANY: Self = Self(u32::MAX);
    /// Replica Island's `HIT`: damage.
    pub const HIT: Self = Self(1 << 0);
    /// Replica Island's `DEATH`: kills outright.
    pub const DEATH: Self = Self(1 << 1);
    /// Replica Island's `COLLECT`: picks up a coin or a gem.
    pub const COLLECT: Self = Self(1 << 2);
    /// Replica Island's `POSSESS`: takes control of a robot.
    pub const POSSESS: Self = Self(1 << 3);
    /// Replica Island's `DEPRESS`: presses a button.
    pub const DEPRESS: Self = Self(1 << 4);
    /// Replica Island's `LAUNCH`: throws the victim (a spring, a cannon).
    pub const LAUNCH: Self = Self(1 << 5);

    /// The set of the given bits (bits 6 and up are free for the game's own types).
    #[must_use]
    pub const fn from_bits(bits: u32) -> Self {
        Self(bits)
    }

    /// The bits.
    #[must_use]
    pub const fn bits(self) -> u32 {
        self.0
    }

    /// True when the sets share a type: an attack of `self` hits a vulnerability of
    /// `other` (or the reverse).
    #[must_use]
    pub const fn matches(self, other: Self) -> bool {
        self.0 & other.0 != 0
    }

    /// True for the empty set.
    #[must_use]
    pub const fn is_empty(self) -> bool {
        self.0 == 0
    }
}

impl BitAnd for HitTypes {
    type Output = Self;
    fn bitand(self, rhs: Self) -> Self {
        Self(self.0 & rhs.0)
    }
}

impl BitOr for HitTypes {
    type Output = Self;
    fn bitor(self, rhs: Self) -> Self {
        Self(self.0 | rhs.0)
    }
}

impl BitOrAssign for HitTypes {
    fn bitor_assign(&mut self, rhs: Self) {
        self.0 |= rhs.0;
    }
}

impl fmt::Debug for HitTypes {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        const NAMES: [&str; 6] = ["HIT", "DEATH", "COLLECT", "POSSESS", "DEPRESS", "LAUNCH"];
        if *self == Self::ANY {
            return f.write_str("HitTypes(ANY)");
        }
        let mut list = f.debug_set();
        for bit in 0..32 {
            if self.0 & (1 << bit) != 0 {
                match NAMES.get(bit) {
                    Some(name) => list.entry(&format_args!("{name}")),
                    None => list.entry(&format_args!("bit {bit}")),
                };
            }
        }
        list.finish()
    }
}
