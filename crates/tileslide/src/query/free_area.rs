//! Free areas: rectangles of cells known to hold no segment, so that a body that stays
//! inside one need not look for walls again.
//!
//! Most bodies of a crowd are nowhere near a wall, and each step asked the map again for
//! the walls around every one of them: a few cells' worth of scattered reads that found
//! nothing, about a tenth of a step. A body's reach box moves by a fraction of a cell per
//! step, so the answer "no segment here" stays true for many steps. [`FreeArea`] keeps it,
//! stamped with the map's revision: any edit of the tiles or the temporary segments gives
//! the map a new revision, and the area stops holding anything.

use glam::Vec2;

use crate::geometry::Aabb;
use crate::tiles::TileMap;

/// A rectangle of whole cells, in grid units, that held no active or temporary segment when
/// the map had revision `revision`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct FreeArea {
    lo: Vec2,
    hi: Vec2,
    revision: u64,
}

impl FreeArea {
    /// Whether the map still has no segment that `aabb` touches, as far as this area knows:
    /// the map is unchanged since, and the box lies strictly inside the area, so every cell
    /// whose closed rectangle it touches is one of the area's (`TileMap::cell_range` puts
    /// cell `c` in when `c ≥ lo − 1` and `c ≤ hi`). False for a box with a NaN coordinate.
    #[inline]
    pub fn holds(&self, map: &TileMap, aabb: &Aabb) -> bool {
        let inv = map.inv_cell_size();
        let lo = (aabb.min - map.origin()) * inv;
        let hi = (aabb.max - map.origin()) * inv;
        map.revision() == self.revision
            && lo.x > self.lo.x
            && lo.y > self.lo.y
            && hi.x < self.hi.x
            && hi.y < self.hi.y
    }
}

impl TileMap {
    /// A free area around `aabb`: the cells it touches and a ring of one cell around them
    /// if none of those holds a segment, else the cells it touches if none of those does,
    /// else `None`. Also `None` while the map has temporary segments (they lie anywhere),
    /// and for a box outside the map or with a non-finite coordinate. Cells beyond the
    /// map's edge hold nothing, so an area reaching the edge extends without bound.
    pub(crate) fn free_area_around(&self, aabb: &Aabb) -> Option<FreeArea> {
        if !self.temporaries().is_empty() {
            return None;
        }
        let (c0, r0, c1, r1) = self.cell_range(aabb)?;
        let (w, h) = (self.width(), self.height());
        let ring = (
            c0.saturating_sub(1),
            r0.saturating_sub(1),
            (c1 + 1).min(w - 1),
            (r1 + 1).min(h - 1),
        );
        let empty = |(c0, r0, c1, r1): (u32, u32, u32, u32)| {
            let kinds = self.store.kinds();
            (r0..=r1).all(|r| (c0..=c1).all(|c| kinds[(r * w + c) as usize] == 0))
        };
        // Bounds in grid units, open past the map's edges.
        let area = |(a0, b0, a1, b1): (u32, u32, u32, u32)| {
            let low = |k: u32| if k == 0 { f32::NEG_INFINITY } else { k as f32 };
            let high = |k: u32, n: u32| {
                if k + 1 == n {
                    f32::INFINITY
                } else {
                    (k + 1) as f32
                }
            };
            FreeArea {
                lo: Vec2::new(low(a0), low(b0)),
                hi: Vec2::new(high(a1, w), high(b1, h)),
                revision: self.revision(),
            }
        };
        if empty(ring) {
            Some(area(ring))
        } else if empty((c0, r0, c1, r1)) {
            Some(area((c0, r0, c1, r1)))
        } else {
            None
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::ascii;

    fn room() -> TileMap {
        ascii::parse(
            "\
#######
#.....#
#.....#
#.....#
#.....#
#.....#
#######",
            "free.txt",
            1.0,
        )
        .unwrap_or_else(|e| panic!("{e}"))
    }

    fn boxed(x: f32, y: f32, half: f32) -> Aabb {
        Aabb::from_center(Vec2::new(x, y), Vec2::splat(half))
    }

    #[test]
    fn an_area_holds_boxes_inside_it_and_nothing_after_an_edit() {
        let mut map = room();
        // Centre of the room: the box touches cell (3, 3) only; the ring (2..=4)² is empty.
        let area = map.free_area_around(&boxed(3.5, 3.5, 0.3));
        let area = area.unwrap_or_else(|| panic!("no area in an empty room"));
        assert!(area.holds(&map, &boxed(3.5, 3.5, 0.3)));
        assert!(area.holds(&map, &boxed(3.2, 3.8, 0.9)));
        // Touching the ring's outer edge (x = 2) would touch cell (1, 3): not held.
        assert!(!area.holds(&map, &boxed(2.5, 3.5, 0.5)));
        assert!(!area.holds(&map, &boxed(f32::NAN, 3.5, 0.3)));
        map.clear_tile(crate::Cell::new(6, 3))
            .unwrap_or_else(|e| panic!("{e}"));
        assert!(
            !area.holds(&map, &boxed(3.5, 3.5, 0.3)),
            "held after an edit"
        );
    }

    #[test]
    fn areas_stop_short_of_walls_and_every_box_they_hold_finds_none() {
        let map = room();
        // Next to the wall at x = 1: the ring holds the wall's cells, the box's own cells
        // do not.
        let near = boxed(2.5, 3.5, 0.3);
        let area = map.free_area_around(&near);
        let area = area.unwrap_or_else(|| panic!("no area next to a wall"));
        assert!(area.holds(&map, &near));
        for k in 0..200 {
            let b = boxed(1.0 + k as f32 * 0.03, 3.5, 0.3);
            if area.holds(&map, &b) {
                assert!(map.segments_overlapping_aabb(&b).is_empty(), "{b:?}");
            }
        }
        // Reaching into the wall's cell (x < 1): no area at all.
        assert_eq!(map.free_area_around(&boxed(1.2, 3.5, 0.3)), None);
    }
}
