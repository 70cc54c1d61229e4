//! The SplitMix64 generator that seeds every standard scene.

/// SplitMix64 exactly as BENCHMARKS.md specifies (Steele, Lea & Flood 2014, the
/// `splitmix64` of Vigna's reference code).
///
/// Every standard scene is generated from one of these, so the draw functions
/// must stay bit-for-bit identical to the specification: `f32()` keeps the top
/// 24 bits, `below(n)` uses the top 32 bits with a multiply-shift (no rejection).
///
/// ```
/// use tileslide_scenes::SplitMix64;
/// let mut rng = SplitMix64::new(0);
/// assert_eq!(rng.next_u64(), 0xE220_A839_7B1D_CDAF);
/// let r = rng.f32();
/// assert!((0.0..1.0).contains(&r));
/// assert!(rng.below(10) < 10);
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SplitMix64 {
    state: u64,
}

impl SplitMix64 {
    /// Creates a generator whose state is `seed`.
    #[must_use]
    pub fn new(seed: u64) -> Self {
        Self { state: seed }
    }

    /// Advances the state by the golden-ratio increment and returns the mixed value.
    pub fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A uniform `f32` in `[0, 1)`: the top 24 bits of `next_u64()` divided by 2²⁴.
    pub fn f32(&mut self) -> f32 {
        // The top 24 bits fit the f32 mantissa exactly, so the cast is lossless.
        let top = (self.next_u64() >> 40) as f32;
        top / 16_777_216.0
    }

    /// A uniform integer in `[0, n)` by multiply-shift on the top 32 bits:
    /// `((next_u64() >> 32) * n) >> 32`. Returns 0 when `n` is 0.
    ///
    /// The product is computed in 128 bits so that `n` above 2³² cannot overflow;
    /// for every `n` the specification uses (below 2³²) this equals the 64-bit
    /// formula of BENCHMARKS.md.
    pub fn below(&mut self, n: u64) -> u64 {
        let hi = u128::from(self.next_u64() >> 32);
        // (hi * n) >> 32 < n, so it always fits back into a u64.
        u64::try_from((hi * u128::from(n)) >> 32).unwrap_or(0)
    }

    /// A uniform `f32` from `lo` to `hi`: `lo + (hi − lo) · f32()` (below `hi` but for
    /// rounding).
    ///
    /// ```
    /// # use tileslide_scenes::SplitMix64;
    /// let mut rng = SplitMix64::new(3);
    /// assert!((-2.0..5.0).contains(&rng.range(-2.0, 5.0)));
    /// ```
    pub fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.f32()
    }

    /// One of `items`, drawn uniformly with [`below`](Self::below), or `None` when there is
    /// none.
    ///
    /// ```
    /// # use tileslide_scenes::SplitMix64;
    /// let mut rng = SplitMix64::new(3);
    /// assert!([1, 2, 3].contains(&rng.pick(&[1, 2, 3]).unwrap()));
    /// assert_eq!(rng.pick::<u8>(&[]), None);
    /// ```
    pub fn pick<T: Copy>(&mut self, items: &[T]) -> Option<T> {
        let n = u64::try_from(items.len()).ok()?;
        let i = usize::try_from(self.below(n)).ok()?;
        items.get(i).copied()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matches_reference_splitmix64_outputs_for_seed_zero() {
        // First outputs of Vigna's splitmix64.c seeded with 0.
        let mut rng = SplitMix64::new(0);
        assert_eq!(rng.next_u64(), 0xE220_A839_7B1D_CDAF);
        assert_eq!(rng.next_u64(), 0x6E78_9E6A_A1B9_65F4);
        assert_eq!(rng.next_u64(), 0x06C4_5D18_8009_454F);
    }

    #[test]
    fn f32_is_top_24_bits_over_two_to_the_24() {
        let mut a = SplitMix64::new(42);
        let mut b = SplitMix64::new(42);
        for _ in 0..1000 {
            let r = a.f32();
            let bits = b.next_u64() >> 40;
            assert!((0.0..1.0).contains(&r));
            assert_eq!(r, bits as f32 / 16_777_216.0);
        }
    }

    #[test]
    fn below_matches_the_64_bit_formula_and_stays_in_range() {
        let mut a = SplitMix64::new(7);
        let mut b = SplitMix64::new(7);
        for n in [1_u64, 2, 3, 4, 253, 65_536, 4_000_000_000] {
            for _ in 0..100 {
                let v = a.below(n);
                assert!(v < n);
                assert_eq!(v, ((b.next_u64() >> 32) * n) >> 32);
            }
        }
        assert_eq!(a.below(0), 0);
    }

    #[test]
    fn range_and_pick_are_f32_and_below_scaled() {
        let mut a = SplitMix64::new(11);
        let mut b = SplitMix64::new(11);
        let items = [10, 20, 30, 40, 50];
        for _ in 0..1000 {
            let r = a.range(-3.0, 5.0);
            assert!((-3.0..5.0).contains(&r));
            assert_eq!(r, -3.0 + 8.0 * b.f32());
            let picked = a.pick(&items);
            assert_eq!(picked, Some(items[b.below(5) as usize]));
        }
        assert_eq!(a.pick::<u8>(&[]), None);
    }
}
