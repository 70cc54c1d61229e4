//! A uniform grid of buckets over the map, so that a moving circle is only tested against the
//! circles near it: the simple broad phase a hand-rolled parry2d crowd would write.

use parry2d::math::Vector;

/// Square buckets over `[0, width] × [0, height]`, rebuilt from all positions by counting sort
/// once per step. A position outside the map goes to the nearest edge bucket, which keeps every
/// query correct (only slower) whatever the circles do.
///
/// The buckets are `size` wide, `size` being at least the largest centre distance at which two
/// circles can interact during a step (`2r` plus the moves of both, plus the contact skin), so
/// the 3×3 buckets around a circle hold every circle it can meet. Positions may change during
/// the step after the rebuild (the slide loop moves circles one by one): the bucket side is
/// chosen with the moves of both circles included, so a circle's bucket is never more than one
/// step's move stale.
#[derive(Clone, Debug)]
pub struct NeighbourGrid {
    /// Bucket side, in cells.
    size: f32,
    /// Buckets along x.
    cols: usize,
    /// Buckets along y.
    rows: usize,
    /// Prefix sums of the bucket counts (`cols * rows + 1` entries).
    start: Vec<u32>,
    /// Circle indices grouped by bucket.
    order: Vec<u32>,
    /// Scratch: each circle's bucket, kept between rebuilds to avoid reallocating.
    keys: Vec<u32>,
}

impl NeighbourGrid {
    /// Buckets at least `reach` cells wide over a `width` × `height` map.
    pub fn new(width: usize, height: usize, reach: f32) -> Self {
        let size = reach.max(1e-3);
        let cols = ((width as f32 / size).ceil() as usize).max(1);
        let rows = ((height as f32 / size).ceil() as usize).max(1);
        Self {
            size,
            cols,
            rows,
            start: vec![0; cols * rows + 1],
            order: Vec::new(),
            keys: Vec::new(),
        }
    }

    /// The bucket `(column, row)` holding `p`, clamped into the grid.
    #[inline]
    fn bucket_of(&self, p: Vector) -> (usize, usize) {
        // `as usize` saturates: negative and NaN coordinates go to bucket 0.
        let bx = ((p.x / self.size) as usize).min(self.cols - 1);
        let by = ((p.y / self.size) as usize).min(self.rows - 1);
        (bx, by)
    }

    /// Re-sorts all circles into their buckets (no allocation once the buffers have grown).
    pub fn rebuild(&mut self, positions: &[Vector]) {
        self.start.fill(0);
        self.keys.clear();
        for &p in positions {
            let (bx, by) = self.bucket_of(p);
            let key = by * self.cols + bx;
            self.keys.push(key as u32);
            self.start[key + 1] += 1;
        }
        for k in 0..self.cols * self.rows {
            self.start[k + 1] += self.start[k];
        }
        self.order.resize(positions.len(), 0);
        // Fill each bucket from its end, so `start` is restored to the bucket starts when done.
        for (i, &key) in self.keys.iter().enumerate().rev() {
            let slot = &mut self.start[key as usize + 1];
            *slot -= 1;
            self.order[*slot as usize] = i as u32;
        }
        // After the loop, start[k + 1] holds the start of bucket k: shift back by one.
        self.start.rotate_left(1);
        let last = self.cols * self.rows;
        self.start[last] = positions.len() as u32;
    }

    /// Calls `visit(j)` for every circle in the 3×3 buckets around `p` (the circle at `p`
    /// itself included).
    #[inline]
    pub fn for_each_near(&self, p: Vector, mut visit: impl FnMut(usize)) {
        let (bx, by) = self.bucket_of(p);
        let (x0, x1) = (bx.saturating_sub(1), (bx + 1).min(self.cols - 1));
        for y in by.saturating_sub(1)..=(by + 1).min(self.rows - 1) {
            // The buckets of one row are contiguous in `order`.
            let from = self.start[y * self.cols + x0] as usize;
            let to = self.start[y * self.cols + x1 + 1] as usize;
            for &j in &self.order[from..to] {
                visit(j as usize);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use tileslide_scenes::SplitMix64;

    #[test]
    fn finds_every_circle_within_reach_on_random_positions() {
        let mut rng = SplitMix64::new(0x0E16_4B00_0000_0001);
        let mut grid = NeighbourGrid::new(20, 12, 0.7);
        for _ in 0..20 {
            // Some positions outside the map, where they are clamped to the edge buckets.
            let positions: Vec<Vector> = (0..300)
                .map(|_| Vector::new(24.0 * rng.f32() - 2.0, 16.0 * rng.f32() - 2.0))
                .collect();
            grid.rebuild(&positions);
            for (i, &p) in positions.iter().enumerate() {
                let mut near = Vec::new();
                grid.for_each_near(p, |j| near.push(j));
                assert!(near.contains(&i));
                let mut sorted = near.clone();
                sorted.sort_unstable();
                sorted.dedup();
                assert_eq!(sorted.len(), near.len(), "a circle was visited twice");
                for (j, &q) in positions.iter().enumerate() {
                    if p.distance(q) <= 0.7 {
                        assert!(near.contains(&j), "{i} at {p} misses {j} at {q}");
                    }
                }
            }
        }
    }

    #[test]
    fn rebuilding_with_fewer_circles_forgets_the_old_ones() {
        let mut grid = NeighbourGrid::new(4, 4, 1.0);
        grid.rebuild(&[Vector::new(1.5, 1.5), Vector::new(1.6, 1.5)]);
        grid.rebuild(&[Vector::new(1.5, 1.5)]);
        let mut near = Vec::new();
        grid.for_each_near(Vector::new(1.5, 1.5), |j| near.push(j));
        assert_eq!(near, vec![0]);
    }
}
