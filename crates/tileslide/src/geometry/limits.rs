//! The range of coordinates the library promises to handle.

use glam::Vec2;

/// The largest magnitude a coordinate passed to tileslide may have, in map units: 2²⁴.
///
/// Positions, moves' end points, radii and half extents beyond it are refused at the entry
/// point that takes them, with an error naming the value (a call that cannot fail answers as
/// its docs say). Up to 2²⁴ an `f32` holds every integer exactly, so every cell corner of a
/// unit-cell map is exact, and squared lengths and products of two coordinates stay far from
/// `f32::MAX` (about 3.4·10³⁸): within this range no arithmetic inside the library
/// overflows, so no finite input can turn a result into NaN or carry a body through a wall.
pub const MAX_COORD: f32 = 16_777_216.0;

/// True when both coordinates are finite and at most [`MAX_COORD`] in magnitude.
#[must_use]
pub(crate) fn in_range(v: Vec2) -> bool {
    v.x.abs() <= MAX_COORD && v.y.abs() <= MAX_COORD
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn in_range_refuses_nan_infinite_and_far() {
        assert!(in_range(Vec2::new(MAX_COORD, -MAX_COORD)));
        assert!(!in_range(Vec2::new(f32::NAN, 0.0)));
        assert!(!in_range(Vec2::new(0.0, f32::INFINITY)));
        assert!(!in_range(Vec2::new(MAX_COORD * 1.000_001, 0.0)));
        assert!(!in_range(Vec2::new(0.0, -3.0e38)));
    }
}
