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

/// Circles whose lists share a pool. A block of circles keeps its lists in a pool of its
/// own, so the lists gathered on many threads go straight to their place, one task a pool
/// (see [`NearWalls::around_all`]). With one pool for all circles, each task gathered into
/// a buffer of its own and the calling thread copied them over: the walls near the crowd
/// scene's 50,000 circles took 2.3 ms a step on one thread of an EPYC against 1.3 now.
const POOL_CIRCLES: usize = 256;

/// Capsules a pool may hold past twice its listed ones before `begin` compacts it.
const POOL_SLACK: usize = 256;

/// What is known about the walls near one circle.
#[derive(Clone, Copy, Debug, Default)]
enum Near {
    /// Nothing.
    #[default]
    Unknown,
    /// The walls with one of `mask`'s flags that touch `area`, at `start..end` of the
    /// circle's pool (until the map changes near `area`: see [`NearWalls::begin`]).
    Listed {
        area: Circle,
        mask: SegmentFlags,
        start: u32,
        end: u32,
    },
}

/// The walls of the lists of [`POOL_CIRCLES`] circles.
#[derive(Clone, Debug, Default)]
struct Pool {
    capsules: Vec<Capsule>,
    /// Capsules some circle lists (the lists' lengths summed), kept as lists change so
    /// that `begin` need not count them.
    live: usize,
}

impl Pool {
    /// Gathers the walls near `reach` anew as `near`'s list (see [`gather`]); returns its
    /// range.
    fn renew(
        &mut self,
        near: &mut Near,
        reach: &Circle,
        mask: SegmentFlags,
        map: &TileMap,
    ) -> (u32, u32) {
        let list = gather(reach, mask, map, &mut self.capsules);
        self.live = self.live + length(list) - length(*near);
        *near = list;
        listed(list)
    }

    /// Drops the capsules no list of `near` (this pool's circles) holds once they
    /// outnumber the listed ones, moving each list down in place.
    fn compact(&mut self, near: &mut [Near]) {
        if self.capsules.len() <= 2 * self.live + POOL_SLACK {
            return;
        }
        let mut order = [(0u32, 0u32); POOL_CIRCLES];
        let mut count = 0;
        for (i, near) in near.iter().enumerate() {
            if let Near::Listed { start, .. } = near {
                order[count] = (*start, i as u32);
                count += 1;
            }
        }
        let order = &mut order[..count];
        order.sort_unstable();
        let mut to = 0;
        for &(_, i) in order.iter() {
            if let Near::Listed { start, end, .. } = &mut near[i as usize] {
                let len = *end - *start;
                self.capsules
                    .copy_within(*start as usize..*end as usize, to as usize);
                (*start, *end) = (to, to + len);
                to += len;
            }
        }
        self.capsules.truncate(to as usize);
    }
}

/// The walls near every circle, in a pool for each block of [`POOL_CIRCLES`] circles.
#[derive(Clone, Debug, Default)]
pub(super) struct NearWalls {
    near: Vec<Near>,
    pools: Vec<Pool>,
}

impl NearWalls {
    /// Makes room for `n` circles, forgets the lists the map's `change` since the last
    /// resolve may have made wrong (the lists of areas that touch a changed region), and
    /// compacts the pools whose unlisted capsules outnumber the listed ones. Call before a
    /// resolve.
    pub fn begin(&mut self, n: usize, change: MapChange, watch: &MapWatch) {
        let shrinks = n < self.near.len();
        self.near.resize(n, Near::Unknown);
        self.pools
            .resize_with(n.div_ceil(POOL_CIRCLES), Pool::default);
        let last = self.pools.len().saturating_sub(1);
        if shrinks && let Some(pool) = self.pools.get_mut(last) {
            // The last pool lost some of its circles.
            pool.live = self.near[last * POOL_CIRCLES..]
                .iter()
                .map(|&near| length(near))
                .sum();
        }
        match change {
            MapChange::Unchanged => {}
            MapChange::Local => {
                for (c, near) in self.near.iter_mut().enumerate() {
                    if let Near::Listed { area, .. } = near
                        && watch.touches(&area.aabb())
                    {
                        self.pools[c / POOL_CIRCLES].live -= length(*near);
                        *near = Near::Unknown;
                    }
                }
            }
            MapChange::Everything => {
                self.near.fill(Near::Unknown);
                for pool in &mut self.pools {
                    pool.capsules.clear();
                    pool.live = 0;
                }
            }
        }
        for (pool, near) in self
            .pools
            .iter_mut()
            .zip(self.near.chunks_mut(POOL_CIRCLES))
        {
            debug_assert_eq!(
                pool.live,
                near.iter().map(|&near| length(near)).sum::<usize>()
            );
            pool.compact(near);
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
        self.pools[c / POOL_CIRCLES].renew(&mut self.near[c], reach, mask, map)
    }

    /// [`around`](Self::around) for every circle `c` for which `mask_of(c)` gives a mask,
    /// its range into `ranges[c]` (`(0, 0)` for the others), on the threads of the rayon
    /// pool the call runs in: a task a pool, which gathers its circles' lists into it as
    /// `around` would, so every pool is what one thread makes of it.
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
        ranges.resize(reach.len(), (0, 0));
        self.near
            .par_chunks_mut(POOL_CIRCLES)
            .zip(self.pools.par_iter_mut())
            .zip(ranges.par_chunks_mut(POOL_CIRCLES))
            .enumerate()
            .for_each(|(k, ((near, pool), ranges))| {
                let first = k * POOL_CIRCLES;
                for (i, (near, range)) in near.iter_mut().zip(ranges).enumerate() {
                    let c = first + i;
                    *range = match mask_of(c).filter(|mask| !mask.is_empty()) {
                        None => (0, 0),
                        Some(mask) => match serves(*near, &reach[c], mask, slack) {
                            Some(range) => range,
                            None => pool.renew(near, &reach[c], mask, map),
                        },
                    };
                }
            });
    }

    /// Asks the processor to bring the walls of circle `c` at `range` into its caches (see
    /// [`prefetch`](crate::prefetch)).
    #[cfg(feature = "parallel")]
    pub fn prefetch(&self, c: usize, (start, end): (u32, u32)) {
        let pool = &self.pools[c / POOL_CIRCLES].capsules;
        let per_line = (64 / std::mem::size_of::<Capsule>()).max(1);
        for k in (start as usize..end as usize).step_by(per_line) {
            crate::prefetch::prefetch(pool, k);
        }
    }

    /// The walls of circle `c` at a range [`Self::around`] returned for it.
    #[inline]
    pub fn walls(&self, c: usize, (start, end): (u32, u32)) -> &[Capsule] {
        &self.pools[c / POOL_CIRCLES].capsules[start as usize..end as usize]
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
        near.walls(0, range).to_vec()
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
            let before: usize = near.pools.iter().map(|p| p.capsules.len()).sum();
            near.begin(n, watch.update(&map), &watch);
            compacted |= near.pools.iter().map(|p| p.capsules.len()).sum::<usize>() < before;
            for c in 0..n {
                let reach = drifting(c, round);
                let range = near.around(c, &reach, mask, 0.0, &map);
                let kept = near.walls(c, range);
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
        assert!(
            near.walls(0, first).is_empty(),
            "rows 3 to 5 are open floor"
        );
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
            !near.walls(0, after).is_empty(),
            "the new block's face is within reach"
        );
        let other = near.around(0, &reach, SegmentFlags::ONE_WAY, 0.0, &map);
        assert!(near.walls(0, other).is_empty(), "no one-way segments here");
    }

    /// Where circle `c` of `n` reaches in `round`: circles drift a little each round, so
    /// lists are both kept and renewed.
    fn drifting(c: usize, round: usize) -> Circle {
        let x = 1.5 + (c % 37) as f32 + 0.07 * round as f32 * ((c % 3) as f32 - 1.0);
        let y = 1.5 + (c / 37 % 40) as f32 * 0.9 + 0.05 * round as f32;
        Circle::new(Vec2::new(x, y % 37.0 + 1.0), 0.4)
    }

    #[cfg(feature = "parallel")]
    #[test]
    fn every_pool_gathered_side_by_side_lists_what_one_circle_at_a_time_lists() {
        let map = pillars();
        let (mut one, mut all) = (NearWalls::default(), NearWalls::default());
        let (mut watch_one, mut watch_all) = (MapWatch::default(), MapWatch::default());
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(3)
            .build()
            .unwrap_or_else(|e| panic!("{e}"));
        let mut ranges = Vec::new();
        for round in 0..30 {
            // Fewer circles now and then: the last pool loses some, later pools go.
            let n = if round % 10 == 9 { 700 } else { 1500 };
            let reach: Vec<Circle> = (0..n).map(|c| drifting(c, round)).collect();
            // Every seventh circle stays still: no mask, no walls.
            let mask_of = |c: usize| (c % 7 != 3).then_some(SegmentFlags::SOLID);
            one.begin(n, watch_one.update(&map), &watch_one);
            all.begin(n, watch_all.update(&map), &watch_all);
            pool.install(|| all.around_all(&reach, mask_of, 0.01, &map, &mut ranges));
            assert_eq!(ranges.len(), n);
            for (c, reach) in reach.iter().enumerate() {
                let mask = mask_of(c).unwrap_or(SegmentFlags::NONE);
                let range = one.around(c, reach, mask, 0.01, &map);
                assert_eq!(
                    all.walls(c, ranges[c]),
                    one.walls(c, range),
                    "round {round}, circle {c}"
                );
            }
        }
    }
}
