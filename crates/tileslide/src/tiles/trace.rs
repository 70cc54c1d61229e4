//! Tile shapes traced from a pixel mask: an image-authored tile gets collision.
//!
//! 1. **Crack following.** Every side between a solid pixel and an empty one (or the
//!    image's border) is a boundary edge, directed so that solid lies on its right on
//!    screen (y down); the edges link into closed loops, clockwise around solid regions and
//!    counter-clockwise around holes. Where two solid pixels touch only at a corner, the
//!    loop turns right, keeping them apart (solid is 4-connected).
//! 2. **Collinear runs** merge into single edges.
//! 3. **Staircases** become slopes: each loop is simplified with Douglas–Peucker (Douglas &
//!    Peucker 1973) to within `tolerance` pixels, so a ramp drawn as 1-pixel steps is one
//!    straight segment. A tolerance of 0 keeps the exact pixel outline; 1 (the usual
//!    choice) turns 45° and 26.6° staircases into slopes and keeps every corner of a shape
//!    whose sides are longer than a pixel or two.
//!
//! Normals point from solid to empty. Coordinates are pixels, tile-local, y down (row 0 is
//! the image's top row), as in Tiled.

use glam::Vec2;

use super::{SegmentFlags, ShapeError, TileSegment, TileShape};

impl TileShape {
    /// The solid shape of a `width × height` pixel mask (`mask[row · width + col]`, row 0 at
    /// the top), its outline simplified to within `tolerance` pixels (see the module's
    /// documentation). An error when the mask's length is not `width × height`, the
    /// tolerance is negative or not finite, or the outline needs more segments than a tile
    /// may have.
    ///
    /// ```
    /// use tileslide::{TileShape, Vec2};
    /// // A 4 × 4 ramp drawn in steps, rising to the right (y down).
    /// let mask: Vec<bool> = (0..16).map(|i| i % 4 + i / 4 >= 3).collect();
    /// let ramp = TileShape::trace(&mask, 4, 4, 1.0)?;
    /// // Three sides: the right side, the bottom, and one slope facing up-left.
    /// assert_eq!(ramp.segments().len(), 3);
    /// let slope = ramp.segments().iter().find(|s| s.normal.x < 0.0 && s.normal.y < 0.0);
    /// assert!(slope.is_some());
    /// assert!(ramp.contains_point(Vec2::new(3.5, 3.5)));
    /// assert!(!ramp.contains_point(Vec2::new(0.5, 0.5)));
    /// # Ok::<(), tileslide::ShapeError>(())
    /// ```
    pub fn trace(
        mask: &[bool],
        width: u32,
        height: u32,
        tolerance: f32,
    ) -> Result<Self, ShapeError> {
        let (w, h) = (width as usize, height as usize);
        if w.checked_mul(h) != Some(mask.len()) {
            return Err(ShapeError::MaskSize {
                width,
                height,
                len: mask.len(),
            });
        }
        if !(tolerance >= 0.0 && tolerance.is_finite()) {
            return Err(ShapeError::BadTolerance { tolerance });
        }
        let mut segments = Vec::new();
        for corners in loops(mask, w, h) {
            let kept = simplify(&corners, tolerance);
            for (k, &a) in kept.iter().enumerate() {
                let b = kept[(k + 1) % kept.len()];
                let d = b - a;
                // Solid on the right of the direction of travel (y down): the normal is on
                // the left.
                let normal = Vec2::new(d.y, -d.x);
                segments.push(TileSegment::new(a, b, normal, SegmentFlags::SOLID));
                if segments.len() > super::MAX_SHAPE_SEGMENTS {
                    return Err(ShapeError::TooManySegments {
                        count: segments.len(),
                    });
                }
            }
        }
        Self::from_segments(segments)
    }
}

/// The four directions of a boundary edge, in the order of a right turn (y down).
const DIRECTIONS: [(i64, i64); 4] = [(1, 0), (0, 1), (-1, 0), (0, -1)];

/// Every boundary loop of the mask, as its corners (collinear runs merged), in order.
fn loops(mask: &[bool], w: usize, h: usize) -> Vec<Vec<Vec2>> {
    let solid = |x: i64, y: i64| {
        x >= 0
            && y >= 0
            && (x as usize) < w
            && (y as usize) < h
            && mask[y as usize * w + x as usize]
    };
    // Boundary edges by start vertex: vertex (x, y) has id y·(w+1) + x, and each holds up to
    // two outgoing edges (two at a vertex where solid pixels touch only at the corner).
    let stride = w + 1;
    let vertex = |x: i64, y: i64| y as usize * stride + x as usize;
    let mut outgoing: Vec<[Option<u8>; 2]> = vec![[None; 2]; stride * (h + 1)];
    let mut add = |x: i64, y: i64, dir: u8| {
        let slot = &mut outgoing[vertex(x, y)];
        if slot[0].is_none() {
            slot[0] = Some(dir);
        } else {
            slot[1] = Some(dir);
        }
    };
    for y in 0..h as i64 {
        for x in 0..w as i64 {
            if !solid(x, y) {
                continue;
            }
            // Solid on the right of each edge: top edge goes right, right edge goes down,
            // bottom edge goes left, left edge goes up.
            if !solid(x, y - 1) {
                add(x, y, 0);
            }
            if !solid(x + 1, y) {
                add(x + 1, y, 1);
            }
            if !solid(x, y + 1) {
                add(x + 1, y + 1, 2);
            }
            if !solid(x - 1, y) {
                add(x, y + 1, 3);
            }
        }
    }
    let mut out = Vec::new();
    for start in 0..outgoing.len() {
        while let Some(first) = take(&mut outgoing[start], None) {
            let (sx, sy) = ((start % stride) as i64, (start / stride) as i64);
            let start_point = Vec2::new(sx as f32, sy as f32);
            let mut corners = Vec::new();
            let (mut x, mut y, mut dir) = (sx, sy, first);
            loop {
                let (dx, dy) = DIRECTIONS[dir as usize];
                (x, y) = (x + dx, y + dy);
                let v = vertex(x, y);
                if v == start {
                    // Back where the loop began: closed if the rule would take its first
                    // edge again here (a saddle start vertex may hold another loop's edge).
                    let mut with_first = outgoing[v];
                    let free = usize::from(with_first[0].is_some());
                    with_first[free] = Some(first);
                    if choose(&with_first, Some(dir)).and_then(|k| with_first[k]) == Some(first) {
                        if dir != first {
                            corners.push(start_point);
                        }
                        break;
                    }
                }
                // (Every boundary vertex has as many edges out as in, so one is left.)
                let Some(next) = take(&mut outgoing[v], Some(dir)) else {
                    break;
                };
                if next != dir {
                    corners.push(Vec2::new(x as f32, y as f32));
                }
                dir = next;
            }
            if corners.len() >= 3 {
                out.push(corners);
            }
        }
    }
    out
}

/// Which of a vertex's outgoing directions to take after arriving going `incoming`: the
/// right turn when there is a choice (keeping pixels that touch only at a corner apart),
/// else the one there is; the first when starting a loop.
fn choose(slot: &[Option<u8>; 2], incoming: Option<u8>) -> Option<usize> {
    match (slot[0], slot[1], incoming) {
        (Some(_), Some(b), Some(inc)) => Some(if b == (inc + 1) % 4 { 1 } else { 0 }),
        (Some(_), _, _) => Some(0),
        (None, Some(_), _) => Some(1),
        (None, None, _) => None,
    }
}

/// Removes and returns the outgoing direction [`choose`] picks.
fn take(slot: &mut [Option<u8>; 2], incoming: Option<u8>) -> Option<u8> {
    let pick = choose(slot, incoming)?;
    let dir = slot[pick].take();
    if pick == 0 {
        slot[0] = slot[1].take();
    }
    dir
}

/// Douglas–Peucker on a closed loop: the corners to keep, in order, so that every dropped
/// corner lies within `tolerance` of the kept outline. A tolerance of 0 keeps every corner.
fn simplify(corners: &[Vec2], tolerance: f32) -> Vec<Vec2> {
    if tolerance == 0.0 || corners.len() <= 3 {
        return corners.to_vec();
    }
    // Split the loop at corner 0 and the corner farthest from it.
    let far = (1..corners.len())
        .max_by(|&i, &j| {
            corners[i]
                .distance_squared(corners[0])
                .total_cmp(&corners[j].distance_squared(corners[0]))
        })
        .unwrap_or(1);
    let mut keep = vec![false; corners.len()];
    keep[0] = true;
    keep[far] = true;
    let n = corners.len();
    mark(corners, 0, far, tolerance, &mut keep);
    mark(corners, far, n, tolerance, &mut keep);
    let kept: Vec<Vec2> = corners
        .iter()
        .zip(&keep)
        .filter(|(_, k)| **k)
        .map(|(c, _)| *c)
        .collect();
    if kept.len() >= 3 {
        kept
    } else {
        // A sliver thinner than the tolerance: keep it exact rather than lose it.
        corners.to_vec()
    }
}

/// Marks the corners to keep between `from` and `to` (indices modulo the loop's length;
/// `to` may equal the length for the loop's closing stretch).
fn mark(corners: &[Vec2], from: usize, to: usize, tolerance: f32, keep: &mut [bool]) {
    if to <= from + 1 {
        return;
    }
    let n = corners.len();
    let (a, b) = (corners[from % n], corners[to % n]);
    let (mut worst, mut at) = (0.0f32, from);
    for i in from + 1..to {
        let d = distance_to_segment(corners[i % n], a, b);
        if d > worst {
            (worst, at) = (d, i);
        }
    }
    if worst > tolerance {
        keep[at % n] = true;
        mark(corners, from, at, tolerance, keep);
        mark(corners, at, to, tolerance, keep);
    }
}

fn distance_to_segment(p: Vec2, a: Vec2, b: Vec2) -> f32 {
    let e = b - a;
    let len2 = e.length_squared();
    let t = if len2 > 0.0 {
        ((p - a).dot(e) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    p.distance(a + e * t)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn mask(rows: &[&str]) -> (Vec<bool>, u32, u32) {
        let h = rows.len() as u32;
        let w = rows[0].len() as u32;
        let m = rows
            .iter()
            .flat_map(|r| r.chars().map(|c| c == '#'))
            .collect();
        (m, w, h)
    }

    #[test]
    fn a_full_mask_is_its_square() {
        let (m, w, h) = mask(&["####", "####", "####"]);
        let s = TileShape::trace(&m, w, h, 1.0).unwrap();
        assert_eq!(s.segments().len(), 4);
        for seg in s.segments() {
            // Every side on the tile's boundary, facing out.
            let mid = (seg.a + seg.b) * 0.5;
            assert!(
                mid.x == 0.0 || mid.x == 4.0 || mid.y == 0.0 || mid.y == 3.0,
                "{seg:?}"
            );
            assert!(s.contains_point(mid - seg.normal * 0.1));
            assert!(!s.contains_point(mid + seg.normal * 0.1));
        }
    }

    #[test]
    fn an_empty_mask_has_no_segments() {
        let (m, w, h) = mask(&["....", "...."]);
        assert!(
            TileShape::trace(&m, w, h, 1.0)
                .unwrap()
                .segments()
                .is_empty()
        );
    }

    #[test]
    fn a_ring_has_an_outer_and_an_inner_outline_both_facing_empty_space() {
        let (m, w, h) = mask(&["#####", "#...#", "#...#", "#####"]);
        let s = TileShape::trace(&m, w, h, 0.0).unwrap();
        assert_eq!(s.segments().len(), 8);
        for seg in s.segments() {
            let mid = (seg.a + seg.b) * 0.5;
            assert!(s.contains_point(mid - seg.normal * 0.25), "{seg:?}");
            assert!(!s.contains_point(mid + seg.normal * 0.25), "{seg:?}");
        }
    }

    #[test]
    fn pixels_touching_at_a_corner_stay_apart() {
        let (m, w, h) = mask(&["#.", ".#"]);
        let s = TileShape::trace(&m, w, h, 0.0).unwrap();
        assert_eq!(s.segments().len(), 8);
        assert!(s.contains_point(Vec2::new(0.5, 0.5)) && s.contains_point(Vec2::new(1.5, 1.5)));
        assert!(!s.contains_point(Vec2::new(1.5, 0.5)));
    }

    #[test]
    fn a_staircase_ramp_becomes_one_slope() {
        // A 32-pixel ramp rising to the right.
        let m: Vec<bool> = (0..32 * 32).map(|i| i % 32 + i / 32 >= 31).collect();
        let s = TileShape::trace(&m, 32, 32, 1.0).unwrap();
        let slopes: Vec<_> = s
            .segments()
            .iter()
            .filter(|seg| seg.normal.x < -0.5 && seg.normal.y < -0.5)
            .collect();
        assert_eq!(slopes.len(), 1, "{:?}", s.segments());
        assert!(slopes[0].segment().length() > 40.0);
        assert!(s.segments().len() <= 5, "{:?}", s.segments());
    }

    #[test]
    fn bad_input_is_an_error() {
        assert!(matches!(
            TileShape::trace(&[true; 5], 2, 2, 1.0),
            Err(ShapeError::MaskSize { .. })
        ));
        assert!(matches!(
            TileShape::trace(&[true; 4], 2, 2, f32::NAN),
            Err(ShapeError::BadTolerance { .. })
        ));
        // A checkerboard of 64 × 64 pixels needs more segments than a tile may have.
        let board: Vec<bool> = (0..64 * 64).map(|i| (i % 64 + i / 64) % 2 == 0).collect();
        assert!(matches!(
            TileShape::trace(&board, 64, 64, 0.0),
            Err(ShapeError::TooManySegments { .. })
        ));
    }

    proptest! {
        /// With no simplification the outline is exact: a pixel centre is inside the shape
        /// exactly when the pixel is solid, and every segment faces empty space.
        #[test]
        fn the_exact_outline_encloses_exactly_the_solid_pixels(
            w in 1u32..9, h in 1u32..9, bits in prop::collection::vec(any::<bool>(), 64),
        ) {
            let m: Vec<bool> = bits[..(w * h) as usize].to_vec();
            let s = TileShape::trace(&m, w, h, 0.0).unwrap();
            for y in 0..h {
                for x in 0..w {
                    let centre = Vec2::new(x as f32 + 0.5, y as f32 + 0.5);
                    prop_assert_eq!(s.contains_point(centre), m[(y * w + x) as usize], "pixel ({}, {})", x, y);
                }
            }
            // Every boundary side appears exactly once: the outline's length equals the
            // number of solid/empty pixel sides.
            let solid = |x: i64, y: i64| x >= 0 && y >= 0 && x < w as i64 && y < h as i64 && m[(y * w as i64 + x) as usize];
            let mut sides = 0;
            for y in 0..h as i64 {
                for x in 0..w as i64 {
                    if solid(x, y) {
                        sides += [(1, 0), (-1, 0), (0, 1), (0, -1)].iter().filter(|(dx, dy)| !solid(x + dx, y + dy)).count();
                    }
                }
            }
            let length: f32 = s.segments().iter().map(|seg| seg.segment().length()).sum();
            prop_assert_eq!(length, sides as f32);
        }
    }
}
