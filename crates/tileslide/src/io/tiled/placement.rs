//! Where a placed tile's collision goes: a tile of any size, flipped, in its grid cell.
//!
//! Tiled draws a tile layer's tile from its cell's **bottom-left corner**: a tile the size of
//! the grid covers its cell; a 160 × 160 decoration on a 16-pixel grid reaches up and to the
//! right over its neighbours; an 8 × 8 tile sits in the cell's bottom-left quarter. Flips
//! turn the tile within its own rectangle before it is placed. The collision of a tile must
//! lie in the cell it is placed in, because each cell's segments are indexed there; a tile
//! without collision may be any size.
//!
//! **Overhang.** Collision drawn by hand often ends a fraction of a pixel past the tile's
//! edge (Tiled allows it). A vertex at most [`overhang_tolerance`] outside the cell (one
//! pixel, or 1/64 of the cell on cells over 64 pixels) is moved onto the cell's edge; nothing
//! else is clipped. A vertex further out is an error naming the object and how far it
//! reaches.

use glam::Vec2;

use super::Flip;
use crate::tiles::TileSegment;

/// A vertex up to this many pixels outside its cell is moved onto the cell's edge...
const OVERHANG_PIXELS: f32 = 1.0;

/// ... or up to this fraction of the cell, when that is more (cells over 64 pixels).
const OVERHANG_CELL_FRACTION: f32 = 1.0 / 64.0;

/// How far outside its cell (per axis, in pixels) a vertex is moved onto the cell's edge
/// rather than refused: one pixel, or 1/64 of the cell's side when that is more.
///
/// Why both: a slip of the mouse in Tiled's collision editor is a fraction of a screen pixel,
/// which is a fraction of a tile pixel on small tiles (shown magnified) and can be a few tile
/// pixels on large ones (shown at their size or smaller); the overhangs seen in real maps
/// are 0.18–0.40 px on 128-pixel tiles.
pub(super) fn overhang_tolerance(cell: Vec2) -> Vec2 {
    (cell * OVERHANG_CELL_FRACTION).max(Vec2::splat(OVERHANG_PIXELS))
}

/// A tile of size `tile`, flipped by `flip`, placed in a grid cell of size `cell`.
#[derive(Clone, Copy, Debug)]
pub(super) struct Placement {
    /// The tile's size (its tile set's), in pixels.
    pub tile: Vec2,
    /// The grid's cell size, in pixels.
    pub cell: Vec2,
    /// How the tile is flipped.
    pub flip: Flip,
}

impl Placement {
    /// The rectangle of the tile's own pixels (y down, before flips) that lands in its cell.
    pub fn bounds(&self) -> (Vec2, Vec2) {
        // In the flipped tile's frame the cell is [0, cw] × [th − ch, th] (bottom-left
        // anchored); the flips map axis-aligned rectangles to axis-aligned rectangles.
        let a = self.unflip(Vec2::new(0.0, self.tile.y - self.cell.y));
        let b = self.unflip(Vec2::new(self.cell.x, self.tile.y));
        (a.min(b), a.max(b))
    }

    /// `points` (in the tile's own pixels) with every vertex that lies outside
    /// [`bounds`](Self::bounds) by at most the [`overhang_tolerance`] moved onto its edge,
    /// and whether any moved; or, for a vertex further out, why it cannot be placed.
    pub fn snap(&self, points: &mut [Vec2]) -> Result<bool, String> {
        let (lo, hi) = self.bounds();
        let tolerance = overhang_tolerance(self.cell);
        let mut moved = false;
        for p in points.iter_mut() {
            let outside = (lo - *p).max(*p - hi).max(Vec2::ZERO);
            if outside.cmpgt(tolerance).any() {
                return Err(self.overhang_message(*p, outside, tolerance));
            }
            let snapped = p.clamp(lo, hi);
            moved |= snapped != *p;
            *p = snapped;
        }
        Ok(moved)
    }

    fn overhang_message(&self, p: Vec2, outside: Vec2, tolerance: Vec2) -> String {
        let by = outside.max_element();
        let (cw, ch) = (self.cell.x, self.cell.y);
        let place = if self.tile == self.cell {
            format!("outside the tile's {cw}×{ch} pixels")
        } else {
            format!(
                "outside the {cw}×{ch} grid cell its {}×{} tile is placed in (from the \
                 cell's bottom-left corner)",
                self.tile.x, self.tile.y
            )
        };
        let within = if tolerance.x == tolerance.y {
            format!("{} px", tolerance.x)
        } else {
            format!("{}×{} px", tolerance.x, tolerance.y)
        };
        format!(
            "it reaches ({}, {}), {by} px {place}; only vertices within {within} of the edge \
             are moved onto it",
            p.x, p.y
        )
    }

    /// A segment in the tile's own pixels as it lies in its cell: flipped, then moved so the
    /// tile's bottom-left corner is the cell's.
    pub fn place(&self, s: TileSegment) -> TileSegment {
        let s = self.flip.apply_segment(s, self.tile);
        let lift = self.cell.y - self.tile.y;
        if lift == 0.0 {
            // The usual tile the size of the grid: no arithmetic, so its segments are exact.
            return s;
        }
        TileSegment::new(
            s.a + Vec2::new(0.0, lift),
            s.b + Vec2::new(0.0, lift),
            s.normal,
            s.flags,
        )
    }

    /// The tile-local point that [`Flip::apply`] takes to `q`: the flips undone in reverse
    /// order (V, then H, then D).
    fn unflip(&self, q: Vec2) -> Vec2 {
        let mut p = q;
        if self.flip.vertical {
            p.y = self.tile.y - p.y;
        }
        if self.flip.horizontal {
            p.x = self.tile.x - p.x;
        }
        if self.flip.diagonal {
            p = Vec2::new(p.y, p.x);
        }
        p
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn flip(bits: u32) -> Flip {
        Flip::from_gid(bits << 29)
    }

    proptest! {
        /// `unflip` undoes `Flip::apply` for every flip of a square tile, and for the flips
        /// without D of any tile (D needs a square tile).
        #[test]
        fn unflip_undoes_every_flip(
            bits in 0u32..8,
            w in 1u32..200,
            h in 1u32..200,
            x in 0u32..200,
            y in 0u32..200,
        ) {
            let f = flip(bits);
            let h = if f.diagonal { w } else { h };
            let tile = Vec2::new(w as f32, h as f32);
            let p = Vec2::new(x as f32, y as f32);
            let placement = Placement { tile, cell: Vec2::splat(16.0), flip: f };
            prop_assert_eq!(placement.unflip(f.apply(p, tile)), p);
        }

        /// A point of the tile lands in its cell exactly when it lies in `bounds`: checked
        /// against placing it (flip, then the bottom-left lift) for every flip and size.
        #[test]
        fn bounds_are_the_points_that_land_in_the_cell(
            bits in 0u32..8,
            w in 1u32..64,
            h in 1u32..64,
            cw in 1u32..64,
            ch in 1u32..64,
            x in -70i32..140,
            y in -70i32..140,
        ) {
            let f = flip(bits);
            let h = if f.diagonal { w } else { h };
            let placement = Placement {
                tile: Vec2::new(w as f32, h as f32),
                cell: Vec2::new(cw as f32, ch as f32),
                flip: f,
            };
            let p = Vec2::new(x as f32, y as f32);
            let (lo, hi) = placement.bounds();
            let in_bounds = p.cmpge(lo).all() && p.cmple(hi).all();
            let q = f.apply(p, placement.tile) + Vec2::new(0.0, placement.cell.y - placement.tile.y);
            let in_cell = q.cmpge(Vec2::ZERO).all() && q.cmple(placement.cell).all();
            prop_assert_eq!(in_bounds, in_cell);
        }
    }

    #[test]
    fn the_tolerance_is_a_pixel_or_a_64th_of_large_cells() {
        assert_eq!(overhang_tolerance(Vec2::splat(16.0)), Vec2::splat(1.0));
        assert_eq!(overhang_tolerance(Vec2::splat(64.0)), Vec2::splat(1.0));
        assert_eq!(
            overhang_tolerance(Vec2::new(128.0, 32.0)),
            Vec2::new(2.0, 1.0)
        );
    }

    #[test]
    fn vertices_within_the_tolerance_snap_and_others_are_refused() {
        let at = |cell: f32| Placement {
            tile: Vec2::splat(cell),
            cell: Vec2::splat(cell),
            flip: Flip::NONE,
        };
        // 16 px: one pixel.
        let mut points = [
            Vec2::new(-0.9, 3.0),
            Vec2::new(16.9, 16.5),
            Vec2::new(4.0, 5.0),
        ];
        assert_eq!(at(16.0).snap(&mut points), Ok(true));
        assert_eq!(
            points,
            [
                Vec2::new(0.0, 3.0),
                Vec2::new(16.0, 16.0),
                Vec2::new(4.0, 5.0)
            ]
        );
        let mut inside = [Vec2::new(0.0, 16.0), Vec2::new(8.0, 8.0)];
        assert_eq!(at(16.0).snap(&mut inside), Ok(false));
        let e = at(16.0).snap(&mut [Vec2::new(17.25, 3.0)]).unwrap_err();
        assert_eq!(
            e,
            "it reaches (17.25, 3), 1.25 px outside the tile's 16×16 pixels; only vertices \
             within 1 px of the edge are moved onto it"
        );
        // 128 px: two pixels (the real maps' 0.4 px overhang, and more, snap).
        let mut points = [Vec2::new(128.39629, 0.0), Vec2::new(-1.9, 130.0)];
        assert_eq!(at(128.0).snap(&mut points), Ok(true));
        assert_eq!(points, [Vec2::new(128.0, 0.0), Vec2::new(0.0, 128.0)]);
        assert!(at(128.0).snap(&mut [Vec2::new(64.0, -2.1)]).is_err());
    }
}
