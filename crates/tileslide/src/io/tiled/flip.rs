//! Tiled's flip bits: how a placed tile is mirrored or turned.

use glam::Vec2;

use crate::tiles::TileSegment;

/// How a placed tile is flipped: the three high bits of a Tiled gid.
///
/// Tiled applies them in a fixed order, and so does [`Flip::apply`]: first the **diagonal**
/// flip, which swaps x and y (the tile's top-right and bottom-left corners trade places), then
/// the **horizontal** flip (x → w − x), then the **vertical** flip (y → h − y), all in the
/// tile's own y-down pixel frame. Turning a tile 90° clockwise in Tiled sets diagonal +
/// horizontal; 180° sets horizontal + vertical; 90° anticlockwise sets diagonal + vertical.
///
/// ```
/// use tileslide::io::tiled::Flip;
/// use tileslide::Vec2;
/// let gid = 5 | Flip::HORIZONTAL_BIT | Flip::DIAGONAL_BIT; // tile 5 turned 90° clockwise
/// let flip = Flip::from_gid(gid);
/// assert!(flip.horizontal && flip.diagonal && !flip.vertical);
/// let size = Vec2::splat(16.0);
/// // The tile's top-left corner goes to its top-right corner.
/// assert_eq!(flip.apply(Vec2::ZERO, size), Vec2::new(16.0, 0.0));
/// assert_eq!(gid & Flip::GID_MASK, 5);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Flip {
    /// Mirrored left to right (gid bit `0x8000_0000`).
    pub horizontal: bool,
    /// Mirrored top to bottom (gid bit `0x4000_0000`).
    pub vertical: bool,
    /// x and y swapped (gid bit `0x2000_0000`), applied before the other two.
    pub diagonal: bool,
}

impl Flip {
    /// The gid bit of a horizontal flip.
    pub const HORIZONTAL_BIT: u32 = 0x8000_0000;
    /// The gid bit of a vertical flip.
    pub const VERTICAL_BIT: u32 = 0x4000_0000;
    /// The gid bit of a diagonal flip (x/y swap).
    pub const DIAGONAL_BIT: u32 = 0x2000_0000;
    /// The gid bit of the 120° rotation of hexagonal maps: ignored on orthogonal maps, as
    /// Tiled ignores it there.
    pub const HEXAGONAL_120_BIT: u32 = 0x1000_0000;
    /// The bits of a gid that number the tile (the others are flags).
    pub const GID_MASK: u32 = 0x0FFF_FFFF;

    /// No flip.
    pub const NONE: Self = Self {
        horizontal: false,
        vertical: false,
        diagonal: false,
    };

    /// The flips a gid's high bits ask for (the hexagonal bit is not one of them).
    #[must_use]
    pub fn from_gid(gid: u32) -> Self {
        Self {
            horizontal: gid & Self::HORIZONTAL_BIT != 0,
            vertical: gid & Self::VERTICAL_BIT != 0,
            diagonal: gid & Self::DIAGONAL_BIT != 0,
        }
    }

    /// The gid bits of these flips.
    #[must_use]
    pub fn bits(self) -> u32 {
        let bit = |on: bool, b: u32| if on { b } else { 0 };
        bit(self.horizontal, Self::HORIZONTAL_BIT)
            | bit(self.vertical, Self::VERTICAL_BIT)
            | bit(self.diagonal, Self::DIAGONAL_BIT)
    }

    /// True when the tile is placed as drawn.
    #[must_use]
    pub fn is_none(self) -> bool {
        self == Self::NONE
    }

    /// True when the flips reverse the winding of outlines (an odd number of mirrorings).
    #[must_use]
    pub fn reverses_winding(self) -> bool {
        self.horizontal ^ self.vertical ^ self.diagonal
    }

    /// Where the tile-local point `p` of a tile of `size` goes. The diagonal flip assumes a
    /// square tile (the loader refuses it on other tiles).
    #[must_use]
    pub fn apply(self, p: Vec2, size: Vec2) -> Vec2 {
        let mut q = if self.diagonal {
            Vec2::new(p.y, p.x)
        } else {
            p
        };
        if self.horizontal {
            q.x = size.x - q.x;
        }
        if self.vertical {
            q.y = size.y - q.y;
        }
        q
    }

    /// Where a direction (a normal) goes: the same flips without the translation.
    #[must_use]
    pub fn apply_direction(self, d: Vec2) -> Vec2 {
        let mut q = if self.diagonal {
            Vec2::new(d.y, d.x)
        } else {
            d
        };
        if self.horizontal {
            q.x = -q.x;
        }
        if self.vertical {
            q.y = -q.y;
        }
        // No `-0.0` components: a flipped shape compares equal to one drawn that way.
        q + Vec2::ZERO
    }

    /// The segment flipped: end points and normal transformed, and the end points swapped
    /// when the flips mirror, so an outline keeps its winding.
    pub(crate) fn apply_segment(self, s: TileSegment, size: Vec2) -> TileSegment {
        let (a, b) = (self.apply(s.a, size), self.apply(s.b, size));
        let (a, b) = if self.reverses_winding() {
            (b, a)
        } else {
            (a, b)
        };
        TileSegment::new(a, b, self.apply_direction(s.normal), s.flags)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const SIZE: Vec2 = Vec2::splat(16.0);

    #[test]
    fn bits_round_trip_and_ignore_the_tile_number() {
        for bits in 0..8u32 {
            let gid = (bits << 29) | 7;
            let flip = Flip::from_gid(gid);
            assert_eq!(flip.bits() | 7, gid);
        }
        assert!(Flip::from_gid(Flip::HEXAGONAL_120_BIT | 3).is_none());
    }

    #[test]
    fn rotations_are_combinations_of_flips() {
        let corner = Vec2::new(0.0, 0.0);
        let cw = Flip {
            diagonal: true,
            horizontal: true,
            vertical: false,
        };
        let half = Flip {
            diagonal: false,
            horizontal: true,
            vertical: true,
        };
        let ccw = Flip {
            diagonal: true,
            horizontal: false,
            vertical: true,
        };
        assert_eq!(cw.apply(corner, SIZE), Vec2::new(16.0, 0.0));
        assert_eq!(half.apply(corner, SIZE), Vec2::new(16.0, 16.0));
        assert_eq!(ccw.apply(corner, SIZE), Vec2::new(0.0, 16.0));
        // Rotations keep the winding, single mirrorings reverse it.
        assert!(!cw.reverses_winding() && !half.reverses_winding() && !ccw.reverses_winding());
        assert!(Flip::from_gid(Flip::DIAGONAL_BIT).reverses_winding());
    }

    #[test]
    fn directions_have_no_negative_zero() {
        let d = Flip::from_gid(Flip::HORIZONTAL_BIT).apply_direction(Vec2::new(0.0, -1.0));
        assert!(d.x.is_sign_positive());
        assert_eq!(d, Vec2::new(0.0, -1.0));
    }
}
