use glam::Vec2;

/// `n` scaled to unit length, or `None` when it has no direction (zero) or a NaN or
/// infinite component. Scaled by its largest component first, so a huge but finite vector
/// such as (3e38, 3e38) normalises instead of overflowing to a zero vector, and a `-0`
/// component comes out as `0` (the same face then has the same bits however it was built).
pub(crate) fn unit_normal(n: Vec2) -> Option<Vec2> {
    if !n.is_finite() {
        return None;
    }
    let largest = n.abs().max_element();
    if largest == 0.0 {
        return None;
    }
    let scaled = n / largest;
    Some(scaled / scaled.length() + Vec2::ZERO)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn huge_tiny_zero_and_non_finite_normals() {
        let huge = unit_normal(Vec2::new(3e38, 3e38)).unwrap();
        assert!((huge.length() - 1.0).abs() < 1e-6);
        let tiny = unit_normal(Vec2::new(1e-40, 0.0)).unwrap();
        assert_eq!(tiny, Vec2::X);
        assert_eq!(unit_normal(Vec2::ZERO), None);
        assert_eq!(unit_normal(Vec2::new(f32::NAN, 1.0)), None);
        assert_eq!(unit_normal(Vec2::new(f32::INFINITY, 1.0)), None);
        assert_eq!(
            unit_normal(Vec2::new(-0.0, -2.0)).unwrap().x.to_bits(),
            0.0f32.to_bits()
        );
    }
}
