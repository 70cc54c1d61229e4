//! The walls near each circle, kept from one step to the next.
//!
//! A circle sweeps only against the walls its reach disc (everywhere it can be during the
//! step: its circle grown by its move and the gap) touches. Gathering them reads a few
//! cells' kind bytes, segment indices and segments, scattered over the map: about a fifth
//! of a crowd step when done for every moving circle every step. But a circle moves a
//! fraction of a cell per step, so the walls are gathered once for its reach disc grown by
//! a margin ([`MARGIN`]) and kept while the reach disc stays inside that larger disc and
//! the map does not change near it (see `map_watch`), the same bargain as Verlet neighbour
//! lists (Verlet 1967) make for particle pairs.
//!
//! The kept list gives exactly the contacts the exact list would: it holds, in the same
//! relative order (temporary segments, then cells row by row), every wall touching the
//! larger disc, so every wall the reach disc touches; and a wall outside the reach disc is
//! farther from the circle's start than its radius, its move and the gap, so farther from
//! wherever the circle is during the step than its contact radius and what is left of its
//! move, which the resolver's reach test skips before any sweep. Walls are kept only if they
//! touch the larger disc itself, not merely a cell its box touches: discs rather than
//! boxes, because every pass tests every kept wall, and a box's corners hold walls a
//! circle never reaches.

use super::map_watch::{MapChange, MapWatch};
use crate::geometry::Circle;
use crate::query::Capsule;
use crate::tiles::{SegmentFlags, TileMap};

/// How far the box walls are gathered for reaches past a circle's reach box, in cells: a
/// circle moving 0.05 cells a step gathers again about every third step. Measured on the
/// crowd scene (10k, interleaved runs): 0.175 cells 2.07 ms a step, 0.25 2.10, 0.375 2.23
/// (a wider box lists more walls, and every pass tests them all).
const MARGIN: f32 = 0.175;

/// What is known about the walls near one circle.
#[derive(Clone, Copy, Debug, Default)]
enum Near {
    /// Nothing.
    #[default]
    Unknown,
    /// The walls with one of `mask`'s flags that touch `area`, at `start..end` of the pool
    /// (until the map changes near `area`: see [`NearWalls::begin`]).
    Listed {
        area: Circle,
        mask: SegmentFlags,
        start: u32,
        end: u32,
    },
}

/// The walls near every circle, in one pool.
#[derive(Clone, Debug, Default)]
pub(super) struct NearWalls {
    near: Vec<Near>,
    pool: Vec<Capsule>,
    /// Capsules of the pool some circle lists (the lists' lengths summed), kept as lists
    /// change so that `begin` need not count them.
    live: usize,
}

impl NearWalls {
    /// Makes room for `n` circles, forgets the lists the map's `change` since the last
    /// resolve may have made wrong (the lists of areas that touch a changed region), and
    /// drops the pool's unlisted capsules once they outnumber the listed ones. Call before a
    /// resolve.
    pub fn begin(&mut self, n: usize, change: MapChange, watch: &MapWatch) {
        if self.near.len() > n {
            let dropped: usize = self.near[n..].iter().map(|&near| length(near)).sum();
            self.live -= dropped;
        }
        self.near.resize(n, Near::Unknown);
        match change {
            MapChange::Unchanged => {}
            MapChange::Local => {
                for near in &mut self.near {
                    if let Near::Listed { area, .. } = near
                        && watch.touches(&area.aabb())
                    {
                        self.live -= length(*near);
                        *near = Near::Unknown;
                    }
                }
            }
            MapChange::Everything => {
                self.near.fill(Near::Unknown);
                self.live = 0;
            }
        }
        let live = self.live;
        debug_assert_eq!(
            live,
            self.near.iter().map(|&near| length(near)).sum::<usize>()
        );
        if self.pool.len() > 2 * live + 4096 {
            let mut pool = Vec::with_capacity(2 * live + 4096);
            for near in &mut self.near {
                if let Near::Listed { start, end, .. } = near {
                    let from = pool.len() as u32;
                    pool.extend_from_slice(&self.pool[*start as usize..*end as usize]);
                    (*start, *end) = (from, pool.len() as u32);
                }
            }
            self.pool = pool;
        }
    }

    /// The walls with one of `mask`'s flags near circle `c`, whose reach disc is `reach`:
    /// a superset of the walls `reach` touches, in the same order (see the module doc), as
    /// a range of [`Self::walls`]. `slack` is how far inside its larger disc a reach disc
    /// must stay for a kept list to serve (the resolver's gap: room for rounding).
    pub fn around(
        &mut self,
        c: usize,
        reach: &Circle,
        mask: SegmentFlags,
        slack: f32,
        map: &TileMap,
    ) -> (u32, u32) {
        if mask.is_empty() {
            return (0, 0);
        }
        if let Some(range) = serves(self.near[c], reach, mask, slack) {
            return range;
        }
        let list = gather(reach, mask, map, &mut self.pool);
        self.list(c, list);
        listed(list)
    }

    /// Makes `list` circle `c`'s list.
    #[inline]
    fn list(&mut self, c: usize, list: Near) {
        self.live = self.live + length(list) - length(self.near[c]);
        self.near[c] = list;
    }

    /// [`around`](Self::around) for every circle `c` for which `mask_of(c)` gives a mask,
    /// its range into `ranges[c]` (`(0, 0)` for the others); the lists to gather anew are
    /// gathered on the threads of the rayon pool the call runs in. The pool's order then
    /// differs from one thread count to another, but every list holds the same walls in the
    /// same order.
    #[cfg(feature = "parallel")]
    pub fn around_all(
        &mut self,
        reach: &[Circle],
        mask_of: impl Fn(usize) -> Option<SegmentFlags> + Sync,
        slack: f32,
        map: &TileMap,
        ranges: &mut Vec<(u32, u32)>,
    ) {
        use rayon::prelude::*;
        let wanted = |c: usize| mask_of(c).filter(|mask| !mask.is_empty());
        let near = &self.near;
        // Each task gathers into a pool of its own (the circles listed anew, and their
        // walls), merged below.
        type Gathered = (Vec<(u32, Near)>, Vec<Capsule>);
        let fresh: Vec<Gathered> = (0..reach.len())
            .into_par_iter()
            .with_min_len(256)
            .fold(
                || (Vec::new(), Vec::new()),
                |(mut lists, mut pool), c| {
                    if let Some(mask) = wanted(c)
                        && serves(near[c], &reach[c], mask, slack).is_none()
                    {
                        lists.push((c as u32, gather(&reach[c], mask, map, &mut pool)));
                    }
                    (lists, pool)
                },
            )
            .collect();
        for (lists, pool) in fresh {
            let offset = self.pool.len() as u32;
            self.pool.extend_from_slice(&pool);
            for (c, mut list) in lists {
                if let Near::Listed { start, end, .. } = &mut list {
                    (*start, *end) = (*start + offset, *end + offset);
                }
                self.list(c as usize, list);
            }
        }
        ranges.clear();
        let near = &self.near;
        ranges.par_extend((0..reach.len()).into_par_iter().with_min_len(4096).map(
            |c| match wanted(c) {
                Some(_) => listed(near[c]),
                None => (0, 0),
            },
        ));
    }

    /// Asks the processor to bring the walls of `range` into its caches (see
    /// [`prefetch`](crate::prefetch)).
    #[cfg(feature = "parallel")]
    pub fn prefetch(&self, (start, end): (u32, u32)) {
        let per_line = (64 / std::mem::size_of::<Capsule>()).max(1);
        for k in (start as usize..end as usize).step_by(per_line) {
            crate::prefetch::prefetch(&self.pool, k);
        }
    }

    /// The walls at a range [`Self::around`] returned.
    #[inline]
    pub fn walls(&self, (start, end): (u32, u32)) -> &[Capsule] {
        &self.pool[start as usize..end as usize]
    }

    /// The wall at `index` of the pool (a range's start plus its place in the range).
    pub fn wall(&self, index: u32) -> &Capsule {
        &self.pool[index as usize]
    }
}

/// The range of a kept list, if it holds the walls with one of `mask`'s flags near the reach
/// disc `reach` (see [`NearWalls::around`]).
#[inline]
fn serves(near: Near, reach: &Circle, mask: SegmentFlags, slack: f32) -> Option<(u32, u32)> {
    match near {
        Near::Listed {
            area,
            mask: kept,
            start,
            end,
        } if kept == mask && inside(reach, slack, &area) => Some((start, end)),
        _ => None,
    }
}

/// How many capsules a list holds.
fn length(near: Near) -> usize {
    let (start, end) = listed(near);
    (end - start) as usize
}

/// The range of a list (`(0, 0)` for none).
fn listed(near: Near) -> (u32, u32) {
    match near {
        Near::Listed { start, end, .. } => (start, end),
        Near::Unknown => (0, 0),
    }
}

/// Gathers into `pool` the walls with one of `mask`'s flags that touch the reach disc
/// `reach` grown by the margin, in the map's order: the new list.
fn gather(reach: &Circle, mask: SegmentFlags, map: &TileMap, pool: &mut Vec<Capsule>) -> Near {
    let area = Circle::new(
        reach.center,
        reach.radius + MARGIN * map.cell_size().min_element(),
    );
    let start = pool.len();
    map.capsules_in(&area.aabb(), mask, pool);
    // Only the walls that touch the area itself (a cell its box touches may reach beyond).
    let mut kept = start;
    for k in start..pool.len() {
        if area.overlaps_segment(&pool[k].segment) {
            pool[kept] = pool[k];
            kept += 1;
        }
    }
    pool.truncate(kept);
    Near::Listed {
        area,
        mask,
        start: start as u32,
        end: kept as u32,
    }
}

/// Whether disc `reach` grown by `slack` lies inside disc `area`.
#[inline]
fn inside(reach: &Circle, slack: f32, area: &Circle) -> bool {
    let room = area.radius - reach.radius - slack;
    room >= 0.0 && reach.center.distance_squared(area.center) <= room * room
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::ascii;
    use glam::Vec2;

    /// A 40 × 40 room with a pillar in every other cell of every fourth row.
    fn pillars() -> TileMap {
        let text: Vec<String> = (0..40)
            .map(|y| {
                (0..40)
                    .map(|x| {
                        let border = x == 0 || y == 0 || x == 39 || y == 39;
                        if border || (y % 4 == 2 && x % 2 == 0) {
                            '#'
                        } else {
                            '.'
                        }
                    })
                    .collect()
            })
            .collect();
        ascii::parse(&text.join("\n"), "pillars.txt", 1.0).unwrap_or_else(|e| panic!("{e}"))
    }

    /// What a fresh gather lists for `reach`: every wall of `mask` touching the disc grown
    /// by the margin, in the map's order.
    fn fresh(map: &TileMap, reach: &Circle, mask: SegmentFlags) -> Vec<Capsule> {
        let mut near = NearWalls::default();
        near.begin(1, MapChange::Everything, &MapWatch::default());
        let range = near.around(0, reach, mask, 0.0, map);
        near.walls(range).to_vec()
    }

    #[test]
    fn kept_lists_hold_every_wall_a_reach_disc_touches_through_compactions() {
        let map = pillars();
        let mask = SegmentFlags::SOLID;
        let n = 1500;
        let mut near = NearWalls::default();
        let mut watch = MapWatch::default();
        let mut compacted = false;
        for round in 0..40 {
            let before = near.pool.len();
            near.begin(n, watch.update(&map), &watch);
            compacted |= near.pool.len() < before;
            for c in 0..n {
                // Circles drift a little each round, so lists are both kept and renewed.
                let x = 1.5 + (c % 37) as f32 + 0.07 * round as f32 * ((c % 3) as f32 - 1.0);
                let y = 1.5 + (c / 37) as f32 * 0.9 + 0.05 * round as f32;
                let reach = Circle::new(Vec2::new(x, y % 37.0 + 1.0), 0.4);
                let range = near.around(c, &reach, mask, 0.0, &map);
                let kept = near.walls(range);
                // Everything the reach disc touches is there, in the map's order.
                let wanted: Vec<Capsule> = fresh(&map, &reach, mask)
                    .into_iter()
                    .filter(|w| reach.overlaps_segment(&w.segment))
                    .collect();
                let mut it = kept.iter();
                for w in &wanted {
                    assert!(
                        it.any(|k| k == w),
                        "round {round}, circle {c}: {w:?} missing"
                    );
                }
            }
        }
        assert!(compacted, "the pool was never compacted");
    }

    #[test]
    fn an_edit_near_or_another_mask_renews_the_list_and_an_edit_far_keeps_it() {
        let mut map = pillars();
        let mut near = NearWalls::default();
        let mut watch = MapWatch::default();
        let solid = ascii::tile_for_char('#').unwrap_or_else(|e| panic!("{e}: no tile for '#'"));
        near.begin(1, watch.update(&map), &watch);
        let reach = Circle::new(Vec2::new(3.5, 4.5), 0.4);
        let first = near.around(0, &reach, SegmentFlags::SOLID, 0.0, &map);
        assert!(near.walls(first).is_empty(), "rows 3 to 5 are open floor");
        // A block far away (the list's area reaches x 4.08, the edit's region x 5.75):
        // the list is kept, not gathered again.
        map.set_tile(crate::Cell::new(8, 4), solid)
            .unwrap_or_else(|e| panic!("{e}"));
        near.begin(1, watch.update(&map), &watch);
        assert_eq!(
            near.around(0, &reach, SegmentFlags::SOLID, 0.0, &map),
            first
        );
        // A block next to it: gathered again, with the new block's face.
        map.set_tile(crate::Cell::new(4, 4), solid)
            .unwrap_or_else(|e| panic!("{e}"));
        near.begin(1, watch.update(&map), &watch);
        let after = near.around(0, &reach, SegmentFlags::SOLID, 0.0, &map);
        assert!(
            !near.walls(after).is_empty(),
            "the new block's face is within reach"
        );
        let other = near.around(0, &reach, SegmentFlags::ONE_WAY, 0.0, &map);
        assert!(near.walls(other).is_empty(), "no one-way segments here");
    }
}
