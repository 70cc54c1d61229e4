//! Sweep and prune (Baraff's sort and sweep) along x, in horizontal bands.
//!
//! Boxes are sorted by `(band, min.x)`, where a band is a horizontal strip taller than the
//! largest box: two boxes that overlap then lie in the same band or in neighbouring ones.
//! Each band is swept against itself and against the band above it. The sort order is kept
//! from one call to the next, so when boxes move a little, insertion sort puts it right in
//! close to linear time.
//!
//! Why bands: a single sweep along x tests every box against all boxes whose x extents
//! overlap its own, whatever their y. In a scene spread over a square that is a whole
//! column: on the "broad" scene of BENCHMARKS.md (100,000 boxes in a 254-cell square) about
//! 240 candidates per box and 90 ms per call, against about 3 candidates per box and 6 ms
//! with bands.

use std::ops::Range;

use super::{BLOCK, Candidates, extent, insertion_sort_by, lower, upper};
use crate::geometry::Aabb;

/// Most bands the sort makes buckets for; boxes beyond share the last one.
const MAX_BANDS: u32 = 1 << 21;

/// The most bands per box (plus [`SPARSE_BANDS_MIN`]) for which the boxes are sorted by
/// band with a bucket per band. The buckets cost time in proportion to the span of the
/// bands, not to the boxes: past this the boxes are sorted by comparison, so that one box
/// far from the others cannot cost everyone (one box a million cells away from nine others
/// made every call 1,700 times slower).
const SPARSE_BANDS_PER_BOX: usize = 4;

/// Bands always sorted with buckets, however few the boxes.
const SPARSE_BANDS_MIN: usize = 256;

/// Sweep and prune's buffers, kept between calls.
#[derive(Clone, Debug, Default)]
pub(super) struct SweepPairs {
    /// `(sort key, box)` in sweep order, kept between calls (see [`sort_key`]).
    order: Vec<(u64, u32)>,
    /// Each box's sort key, by box.
    keys: Vec<u64>,
    /// The boxes in sweep order, and the [`x_key`] of each one's `min.x`.
    candidates: Candidates,
    xs: Vec<u32>,
    /// Sorting: the bucket starts and fill cursors of the counting sort, the boxes by
    /// bucket, and the boxes that changed band (one band's, merged).
    starts: Vec<u32>,
    fill: Vec<u32>,
    next: Vec<(u64, u32)>,
    moved: Vec<(u64, u32)>,
    /// The sweep on many threads.
    #[cfg(feature = "parallel")]
    parts: super::Parts,
}

impl SweepPairs {
    /// Appends every overlapping pair of `boxes` to `pairs` (see
    /// [`PairFinder::find`](super::PairFinder::find)).
    pub(super) fn find(&mut self, boxes: &[Aabb], pairs: &mut Vec<(u32, u32)>) {
        let count = boxes.len();
        if self.order.len() != count {
            // Fewer or more boxes than last time (objects come and go between frames): keep
            // the order of the ones still there, the new ones at the end, so the insertion
            // sort still starts from a nearly sorted list.
            let old = self.order.len() as u32;
            self.order.retain(|&(_, i)| (i as usize) < count);
            self.order.extend((old..count as u32).map(|i| (0, i)));
        }
        let Some((lo, hi, largest)) = extent(boxes) else {
            return;
        };
        let per_band = 1.0 / band_height(largest, hi.y - lo.y);
        self.keys.clear();
        self.keys
            .extend(boxes.iter().map(|b| sort_key(b, per_band)));
        // Every band is between these two, but for boxes turned inside out (`min > max`)
        // and NaN coordinates: `sort` files those with the nearest one. The cap bounds the
        // buckets whatever the coordinates (the band height keeps real scenes far below).
        let lowest = band_of(lo.y, per_band);
        let highest = band_of(hi.y, per_band).clamp(lowest, lowest.saturating_add(MAX_BANDS));
        if (highest - lowest) as usize <= SPARSE_BANDS_PER_BOX * count + SPARSE_BANDS_MIN {
            self.sort(lowest, highest);
        } else {
            // Bands spread far apart (one box far from the others): sorting by band costs
            // more than the boxes, so compare instead.
            for entry in &mut self.order {
                entry.0 = self.keys[entry.1 as usize];
            }
            self.order.sort_unstable();
        }
        self.candidates.reset(count);
        self.xs.clear();
        for (slot, &(key, i)) in self.order.iter().enumerate() {
            self.candidates.set(slot, upper(&boxes[i as usize]), i);
            // The low half of the key is the x key.
            self.xs.push(key as u32);
        }
        // Padding, so that a block never reads past the end (see `skip`).
        self.xs.extend([u32::MAX; BLOCK]);
        #[cfg(feature = "parallel")]
        if super::Parts::worth(count) {
            // A run may start at any band's first box.
            let mut parts = std::mem::take(&mut self.parts);
            parts.cut(count, self.band_starts(count));
            parts.scan(pairs, |run, pairs| self.scan(run, pairs));
            self.parts = parts;
            return;
        }
        self.scan(0..count, pairs);
    }

    /// Appends the pairs of the bands at `run` (of the boxes in sweep order; it starts at a
    /// band's first box and ends at one's last) to `pairs`: within each band, and across it
    /// and the band above.
    fn scan(&self, run: Range<usize>, pairs: &mut Vec<(u32, u32)>) {
        let mut n = pairs.len();
        let mut start = run.start;
        while start < run.end {
            let band = self.order[start].0 >> 32;
            let end = start + self.order[start..].partition_point(|&(key, _)| key >> 32 == band);
            self.sweep(start..end, pairs, &mut n);
            let count = self.order.len();
            if end < count && self.order[end].0 >> 32 == band + 1 {
                let above = self.order[end..].partition_point(|&(key, _)| key >> 32 == band + 1);
                self.sweep_across(start..end, end..end + above, pairs, &mut n);
            }
            start = end;
        }
        pairs.truncate(n);
    }

    /// The first box of every band in sweep order, in order.
    #[cfg(feature = "parallel")]
    fn band_starts(&self, count: usize) -> impl Iterator<Item = usize> + '_ {
        let mut start = 0;
        std::iter::from_fn(move || {
            if start >= count {
                return None;
            }
            let at = start;
            let band = self.order[start].0 >> 32;
            start += self.order[start..].partition_point(|&(key, _)| key >> 32 == band);
            Some(at)
        })
    }

    /// How many buckets the last sort by band used.
    #[cfg(test)]
    pub(super) fn buckets(&self) -> usize {
        self.starts.len()
    }

    /// Puts `order` in order of the new `keys`, by (key, box). Bands below `lowest` or
    /// above `highest` share the bucket of the nearest one, which keeps the order right.
    ///
    /// A box that stays in its band keeps nearly its place, but one that changes band moves
    /// a whole band along the list, so insertion sort on the whole list is slow (measured on
    /// the broad scene, where 3 % of the boxes change band per update: 5 ms, against 1.4 ms
    /// for this). So
    /// first a stable counting sort by band and by where a box came from (a lower band,
    /// the same, a higher one), then insertion sort within each of those groups (each
    /// nearly sorted from the last call), then a merge of a band's three groups.
    fn sort(&mut self, lowest: u32, highest: u32) {
        let bands = (highest - lowest) as usize + 1;
        let bucket_of = |old: u64, new: u64| {
            let (old_band, band) = ((old >> 32) as u32, (new >> 32) as u32);
            let from = match old_band.cmp(&band) {
                std::cmp::Ordering::Less => 0,
                std::cmp::Ordering::Equal => 1,
                std::cmp::Ordering::Greater => 2,
            };
            (band.clamp(lowest, highest) - lowest) as usize * 3 + from
        };
        self.starts.clear();
        self.starts.resize(3 * bands + 1, 0);
        for &(old, i) in &self.order {
            self.starts[bucket_of(old, self.keys[i as usize]) + 1] += 1;
        }
        let mut total = 0;
        for start in &mut self.starts {
            total += *start;
            *start = total;
        }
        self.next.clear();
        self.next.resize(self.order.len(), (0, 0));
        self.fill.clear();
        self.fill.extend_from_slice(&self.starts[..3 * bands]);
        for &(old, i) in &self.order {
            let key = self.keys[i as usize];
            let slot = &mut self.fill[bucket_of(old, key)];
            self.next[*slot as usize] = (key, i);
            *slot += 1;
        }
        for group in self.starts.windows(2) {
            insertion_sort_by(
                &mut self.next[group[0] as usize..group[1] as usize],
                |a, b| a < b,
            );
        }
        // Fewer boxes change band than stay: merge the (sorted) newcomers into the band,
        // copying the stretches of stayers between them whole.
        self.order.clear();
        for band in self.starts.windows(4).step_by(3) {
            let [lower, same, higher, end] =
                [band[0], band[1], band[2], band[3]].map(|k| k as usize);
            self.moved.clear();
            merge(
                &self.next[lower..same],
                &self.next[higher..end],
                &mut self.moved,
            );
            let mut stayers = &self.next[same..higher];
            for &entry in &self.moved {
                let before = stayers.partition_point(|&stayer| stayer < entry);
                self.order.extend_from_slice(&stayers[..before]);
                self.order.push(entry);
                stayers = &stayers[before..];
            }
            self.order.extend_from_slice(stayers);
        }
    }

    /// The pairs within one band: each box against the following ones until their `min.x`
    /// passes its `max.x` (the sort puts every later one further right).
    fn sweep(&self, band: Range<usize>, pairs: &mut Vec<(u32, u32)>, n: &mut usize) {
        for k in band.clone() {
            self.emit_from(k, k + 1, band.end, pairs, n);
        }
    }

    /// The pairs of a box of `band` with a box of the band `above` that starts at or right
    /// of it in x, then those of a box of `above` with a box of `band` that starts strictly
    /// right of it: between them, every pair across the two bands once. Each half walks one
    /// band with a cursor into the other that only moves right.
    fn sweep_across(
        &self,
        band: Range<usize>,
        above: Range<usize>,
        pairs: &mut Vec<(u32, u32)>,
        n: &mut usize,
    ) {
        let mut from = above.start;
        for k in band.clone() {
            from = self.skip(from, above.end, |x| x < self.xs[k]);
            self.emit_from(k, from, above.end, pairs, n);
        }
        let mut from = band.start;
        for k in above {
            from = self.skip(from, band.end, |x| x <= self.xs[k]);
            self.emit_from(k, from, band.end, pairs, n);
        }
    }

    /// The first slot from `from` on (at most `end`) whose x key is not `before`, for a
    /// `before` that holds for a prefix of the sorted keys.
    ///
    /// Counted a block at a time without branching on each key: the cursor moves by one
    /// or two slots per box, and a loop that stops after a varying few steps is
    /// mispredicted about every other time.
    #[inline]
    fn skip(&self, mut from: usize, end: usize, before: impl Fn(u32) -> bool) -> usize {
        loop {
            let mut passed = 0;
            for j in from..from + BLOCK {
                passed += usize::from(before(self.xs[j]) & (j < end));
            }
            from += passed;
            if passed < BLOCK {
                return from;
            }
        }
    }

    /// The pairs of box `k` with the boxes at `from..end` (sorted by `min.x`, none starting
    /// left of box `k`'s `min.x`): tested a block at a time until a block ends past box
    /// `k`'s `max.x`. The boxes of a block past `max.x` are tested too (and do not overlap),
    /// which costs less than finding where to stop.
    #[inline]
    fn emit_from(
        &self,
        k: usize,
        from: usize,
        end: usize,
        pairs: &mut Vec<(u32, u32)>,
        n: &mut usize,
    ) {
        let upper = self.candidates.uppers[k];
        let (reach, lower, id) = (x_key(upper.x), lower(upper), self.candidates.ids[k]);
        let mut q = from;
        loop {
            self.candidates.emit_block(lower, id, q, end, pairs, n);
            q += BLOCK;
            if q >= end || self.xs[q - 1] > reach {
                return;
            }
        }
    }
}

/// Appends the sorted lists `a` and `b` to `out`, merged in order.
fn merge<T: Copy + PartialOrd>(a: &[T], b: &[T], out: &mut Vec<T>) {
    let (mut i, mut j) = (0, 0);
    while i < a.len() && j < b.len() {
        if b[j] < a[i] {
            out.push(b[j]);
            j += 1;
        } else {
            out.push(a[i]);
            i += 1;
        }
    }
    out.extend_from_slice(&a[i..]);
    out.extend_from_slice(&b[j..]);
}

/// The band of a box whose `min.y` is `y`: `y · per_band` rounded down, saturated to `i32`,
/// as a `u32` that sorts as the band numbers do.
fn band_of(y: f32, per_band: f32) -> u32 {
    ((y * per_band).floor() as i32 as u32) ^ 0x8000_0000
}

/// The height of the bands: the smallest power of two strictly greater than `largest` (the
/// largest side of any box), and not below a millionth of the boxes' vertical `span`.
///
/// Strictly greater, so that two overlapping boxes are never more than one band apart:
/// a box's height `max.y − min.y` rounds to at most `largest`, so it is exactly less than
/// the band height (rounding is monotone, and a power of two is exact). A power of two, so
/// that `min.y / height` is exact and the bands stay put while box sizes change a little
/// (a new band height re-sorts everything). Infinite (one band, a plain sweep) when the
/// boxes are too large or too far apart for bands.
fn band_height(largest: f32, span: f32) -> f32 {
    let floor = largest.max(span / 1_048_576.0);
    if !floor.is_finite() {
        return f32::INFINITY;
    }
    if floor <= 0.0 {
        return 1.0;
    }
    // Keep only the exponent, and raise it by one: the next power of two above `floor`
    // (infinity past the largest finite one).
    f32::from_bits(((floor.to_bits() >> 23) + 1) << 23)
}

/// A box's place in the sweep: its band (`min.y · per_band`, rounded down, saturated to
/// `i32`) in the high half, the [`x_key`] of its `min.x` in the low half. As plain numbers,
/// the keys sort by band, then by `min.x`.
fn sort_key(b: &Aabb, per_band: f32) -> u64 {
    (u64::from(band_of(b.min.y, per_band)) << 32) | u64::from(x_key(b.min.x))
}

/// `x` as a `u32` that sorts as the float does (−0.0 and 0.0 the same, NaN at the ends):
/// the sign bit flipped on positives, all bits flipped on negatives.
fn x_key(x: f32) -> u32 {
    // `+ 0.0` turns −0.0 into 0.0: a box ending at −0.0 touches one starting at 0.0.
    let bits = (x + 0.0).to_bits();
    if bits >> 31 == 1 {
        !bits
    } else {
        bits | 0x8000_0000
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn band_height_is_the_next_power_of_two_above_the_largest_box() {
        assert_eq!(band_height(0.6, 254.0), 1.0);
        assert_eq!(band_height(1.0, 254.0), 2.0);
        assert_eq!(band_height(0.99, 1.0e9), 1024.0);
        assert_eq!(band_height(0.0, 0.0), 1.0);
        assert_eq!(band_height(f32::MAX, 1.0), f32::INFINITY);
        assert_eq!(band_height(1.0, f32::INFINITY), f32::INFINITY);
        let tiny = f32::from_bits(1); // the smallest subnormal
        assert!(band_height(tiny, 0.0) > tiny);
    }

    #[test]
    fn one_far_box_costs_no_more_than_the_boxes() {
        // Nine boxes together and one a million cells above (then at the far corner of
        // the coordinate range): the sort's buckets stay in proportion to the boxes, not to
        // the distance, and the pairs are still right.
        let unit = |x: f32, y: f32| Aabb {
            min: glam::Vec2::new(x, y),
            max: glam::Vec2::new(x + 0.8, y + 0.8),
        };
        for far in [
            glam::Vec2::new(0.0, 1.0e6),
            glam::Vec2::splat(crate::geometry::MAX_COORD),
        ] {
            let mut boxes: Vec<Aabb> = (0..9)
                .map(|i| unit((i % 3) as f32 * 0.5, (i / 3) as f32 * 0.5))
                .collect();
            boxes.push(unit(far.x, far.y));
            let mut sweep = SweepPairs::default();
            for step in 0..3 {
                // Every box drifts a little, the far one too.
                for b in &mut boxes {
                    *b = unit(b.min.x + 0.1, b.min.y + 0.05 * step as f32);
                }
                let mut pairs = Vec::new();
                sweep.find(&boxes, &mut pairs);
                pairs.sort_unstable();
                let mut expected = Vec::new();
                for i in 0..boxes.len() {
                    for j in i + 1..boxes.len() {
                        if boxes[i].overlaps(&boxes[j]) {
                            expected.push((i as u32, j as u32));
                        }
                    }
                }
                assert_eq!(pairs, expected);
                let most = 3 * (SPARSE_BANDS_PER_BOX * boxes.len() + SPARSE_BANDS_MIN + 1) + 1;
                assert!(
                    sweep.buckets() <= most,
                    "{} buckets for {} boxes",
                    sweep.buckets(),
                    boxes.len()
                );
            }
        }
    }

    #[test]
    fn x_keys_sort_as_the_floats_do() {
        let xs = [
            f32::NEG_INFINITY,
            -3.0e38,
            -1.5,
            -1.0e-40,
            0.0,
            1.0e-40,
            0.6,
            255.0,
            f32::INFINITY,
        ];
        for w in xs.windows(2) {
            assert!(x_key(w[0]) < x_key(w[1]), "{w:?}");
        }
        assert_eq!(x_key(-0.0), x_key(0.0));
    }

    #[test]
    fn keys_sort_by_band_then_x() {
        let at = |x: f32, y: f32| Aabb {
            min: glam::Vec2::new(x, y),
            max: glam::Vec2::new(x + 0.5, y + 0.5),
        };
        let per_band = 1.0;
        assert!(sort_key(&at(9.0, 0.5), per_band) < sort_key(&at(-9.0, 1.0), per_band));
        assert!(sort_key(&at(-9.0, -0.5), per_band) < sort_key(&at(-10.0, 0.0), per_band));
        assert!(sort_key(&at(-2.0, 3.2), per_band) < sort_key(&at(1.0, 3.9), per_band));
    }
}
