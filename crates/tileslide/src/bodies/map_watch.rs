//! What changed in the map since the last resolve, for the memories the resolver keeps from
//! one step to the next: the walls kept near each circle and the settled bodies.
//!
//! Both memories are statements about the walls within some disc, and an edit changes walls
//! only near where it happens. So a memory whose disc is far from every change still holds:
//! digging one square of a dungeon, or moving one platform, wakes the bodies near it and
//! renews their wall lists, not everyone's.
//!
//! - **A tile edit** recomputes its cell and the four next to it (seam culling) and relinks
//!   the segment ends within two cells (caps; see `TileMap::set_tile`), so walls change only
//!   inside the cell's box grown by two cells. The map's edit journal
//!   (`TileMap::edits_since`) names the cells.
//! - **A temporary segment** changes walls where it was and where it is. Temporaries are
//!   compared entry by entry in list order, the order every query lists them in (equal
//!   contacts go to the first listed), so an entry that moved, appeared, vanished or holds
//!   another segment than before changes the boxes of both its old and its new segment.
//!   A game that clears and re-submits the same temporaries every frame changes nothing.
//!
//! Anything the journal cannot account for (another map, more edits than it keeps, more
//! changes than [`MAX_REGIONS`]) changes everything.

use glam::Vec2;

use crate::geometry::{Aabb, Segment};
use crate::tiles::{SegmentFlags, TileMap};

/// Most changed boxes tracked one by one; past this, every memory is dropped (each memory
/// is tested against each box).
const MAX_REGIONS: usize = 64;

/// How far past its cell a tile edit changes walls, in cells: two (the relinked ends),
/// plus a quarter for rounding in the segments' corners.
const EDIT_REACH: f32 = 2.25;

/// How the map changed since the last resolve.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum MapChange {
    /// Not at all: every memory holds.
    Unchanged,
    /// Only inside [`MapWatch::regions`]: memories of discs that touch none of them hold.
    Local,
    /// In a way the watch cannot place: no memory holds.
    Everything,
}

/// A temporary segment as a wall: what the resolver sweeps against.
type TemporaryWall = (Segment, Vec2, SegmentFlags);

/// The map as the last resolve saw it.
#[derive(Clone, Debug, Default)]
pub(super) struct MapWatch {
    /// Its tiles and temporaries revisions; `None` before the first resolve.
    seen: Option<(u64, u64)>,
    temporaries: Vec<TemporaryWall>,
    /// The boxes outside which nothing changed, when the change is local.
    regions: Vec<Aabb>,
}

impl MapWatch {
    /// How `map` changed since the last call, which it then remembers.
    pub fn update(&mut self, map: &TileMap) -> MapChange {
        self.regions.clear();
        let now = (map.tiles_revision(), map.temporaries_revision());
        let Some((tiles, temporaries)) = self.seen.replace(now) else {
            self.remember_temporaries(map);
            return MapChange::Everything;
        };
        let mut everything = false;
        if now.0 != tiles {
            match map.edits_since(tiles) {
                Some(cells) => {
                    let reach = map.cell_size() * EDIT_REACH;
                    for cell in cells {
                        let rect = map.cell_rect(cell);
                        self.regions
                            .push(Aabb::from_corners(rect.min - reach, rect.max + reach));
                        if self.regions.len() > MAX_REGIONS {
                            everything = true;
                            break;
                        }
                    }
                }
                None => everything = true,
            }
        }
        if now.1 != temporaries {
            let old = std::mem::take(&mut self.temporaries);
            self.remember_temporaries(map);
            let longest = old.len().max(self.temporaries.len());
            for i in 0..longest {
                let (was, is) = (old.get(i), self.temporaries.get(i));
                if was == is {
                    continue;
                }
                let boxes = [was, is].into_iter().flatten().map(|(s, ..)| s.aabb());
                self.regions.extend(boxes);
                if self.regions.len() > MAX_REGIONS {
                    everything = true;
                    break;
                }
            }
        }
        if everything {
            self.regions.clear();
            MapChange::Everything
        } else if self.regions.is_empty() {
            MapChange::Unchanged
        } else {
            MapChange::Local
        }
    }

    /// The boxes a [`MapChange::Local`] change happened in.
    #[cfg(test)]
    pub fn regions(&self) -> &[Aabb] {
        &self.regions
    }

    /// Whether `area` touches a box a local change happened in.
    pub fn touches(&self, area: &Aabb) -> bool {
        self.regions.iter().any(|r| r.overlaps(area))
    }

    fn remember_temporaries(&mut self, map: &TileMap) {
        self.temporaries.clear();
        self.temporaries.extend(
            map.temporaries()
                .iter()
                .map(|t| (t.segment, t.normal, t.flags)),
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::ascii::{self, TEST_ROOM};
    use crate::{Cell, Owner, TemporarySegment};

    fn room() -> TileMap {
        ascii::parse(TEST_ROOM, "room.txt", 1.0).unwrap_or_else(|e| panic!("{e}"))
    }

    fn platform(x: f32) -> TemporarySegment {
        TemporarySegment {
            segment: Segment::new(Vec2::new(x, 2.0), Vec2::new(x + 1.0, 2.0)),
            normal: Vec2::Y,
            flags: SegmentFlags::SOLID,
            owner: Owner(7),
            velocity: Vec2::ZERO,
        }
    }

    fn dig(map: &mut TileMap, cell: Cell) {
        // (An edit that changes nothing is no edit: the cell must be a wall.)
        let floor = ascii::tile_for_char('.').unwrap_or_else(|()| panic!("no tile for '.'"));
        map.set_tile(cell, floor).unwrap_or_else(|e| panic!("{e}"));
    }

    #[test]
    fn edits_are_placed_within_two_cells_of_their_cell() {
        let mut map = room();
        let mut watch = MapWatch::default();
        assert_eq!(watch.update(&map), MapChange::Everything, "first look");
        assert_eq!(watch.update(&map), MapChange::Unchanged);
        dig(&mut map, Cell::new(0, 3));
        assert_eq!(watch.update(&map), MapChange::Local);
        let [region] = watch.regions() else {
            panic!("one edit, one region: {:?}", watch.regions());
        };
        // Cell (0, 3) spans x 0..1, y 3..4; two and a quarter cells around it.
        assert_eq!(region.min, Vec2::new(-2.25, 0.75));
        assert_eq!(region.max, Vec2::new(3.25, 6.25));
        let near = Aabb::from_corners(Vec2::new(3.0, 5.0), Vec2::new(3.5, 5.5));
        let far = Aabb::from_corners(Vec2::new(3.5, 5.0), Vec2::new(4.0, 5.5));
        assert!(watch.touches(&near) && !watch.touches(&far));
        assert_eq!(watch.update(&map), MapChange::Unchanged, "seen already");
    }

    #[test]
    fn resubmitted_temporaries_change_nothing_and_moved_ones_change_both_places() {
        let mut map = room();
        let mut watch = MapWatch::default();
        map.add_temporary(platform(2.0))
            .unwrap_or_else(|e| panic!("{e}"));
        watch.update(&map);
        // Cleared and submitted again, the same: nothing changed.
        map.clear_temporaries();
        map.add_temporary(platform(2.0))
            .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(watch.update(&map), MapChange::Unchanged);
        // Moved: where it was and where it is.
        map.clear_temporaries();
        map.add_temporary(platform(4.0))
            .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(watch.update(&map), MapChange::Local);
        let boxes: Vec<_> = watch.regions().iter().map(|r| (r.min, r.max)).collect();
        assert_eq!(
            boxes,
            [
                (Vec2::new(2.0, 2.0), Vec2::new(3.0, 2.0)),
                (Vec2::new(4.0, 2.0), Vec2::new(5.0, 2.0))
            ]
        );
        // Gone: where it was.
        map.clear_temporaries();
        assert_eq!(watch.update(&map), MapChange::Local);
        assert_eq!(watch.regions().len(), 1);
    }

    #[test]
    fn another_map_or_too_many_edits_change_everything() {
        let mut map = room();
        let mut watch = MapWatch::default();
        watch.update(&map);
        assert_eq!(watch.update(&room()), MapChange::Everything, "another map");
        watch.update(&map);
        // One more edit than the watch places one by one: a cell filled and dug in turn.
        for k in 0..=MAX_REGIONS {
            let tile = ascii::tile_for_char(if k % 2 == 0 { '#' } else { '.' });
            let tile = tile.unwrap_or_else(|()| panic!("no tile"));
            map.set_tile(Cell::new(3, 2), tile)
                .unwrap_or_else(|e| panic!("{e}"));
        }
        assert_eq!(watch.update(&map), MapChange::Everything);
        assert!(watch.regions().is_empty());
    }
}
