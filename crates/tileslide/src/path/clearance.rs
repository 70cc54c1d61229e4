//! Clearance: for every move of the lattice, how wide a circle can make it.
//!
//! A move's clearance is the least distance from the straight move (a segment between two
//! nodes) to anything that stops a circle: the map's active segments with a blocking flag,
//! solid tile interiors (a move with an end inside a tile outline has clearance 0) and the
//! map's border. A circle of radius `r` can make the move iff its clearance is at least
//! `r` plus a small margin; then the whole swept circle stays clear of every wall, so the
//! moves of a found path are safe by construction, ramps and partial tiles included, and
//! diagonal moves never cut a corner.
//!
//! One-way platforms (segments with the `ONE_WAY` flag) make moves directed: a circle
//! crosses one only from behind, moving the way its normal points, as the resolver lets it
//! (see [`one_way_distance_squared`]). So each move has two clearances, one each way.
//!
//! One table serves every radius up to the navigation grid's `max_radius`: clearances are
//! computed exactly up to that (plus the margin) and stored, rounded down, in steps of
//! 1/2048 of the shorter cell side (two bytes a move each way, four moves a node).

use std::cmp::Ordering;

use glam::Vec2;

use super::lattice::{Lattice, MOVES};
use crate::geometry::{Aabb, Segment};
use crate::tiles::{Cell, SegmentFlags, TileMap};

/// Clearance steps per shorter cell side.
const QUANTA_PER_CELL: f32 = 2048.0;

/// Extra clearance a circle needs beyond its radius, per shorter cell side: found paths
/// keep this far from walls, so a body following one never touches them.
pub(crate) const MARGIN_PER_CELL: f32 = 1e-3;

/// A move whose clearance changed in an update: from `node`, move `dir` (any of the eight),
/// and its clearance before and after, in steps.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct ChangedMove {
    pub node: u32,
    pub dir: u8,
    pub before: u16,
    pub after: u16,
}

/// Steepest lean of a move along a one-way platform's normal (the sine of its angle to the
/// platform) that still counts as moving along it, not through it: the resolver stops a
/// circle in front of the face that leans into it by a rounding error, and a body that slid
/// round a wall by the resolver's gap aims at its next corner off the run by about that.
const ALONG_PLATFORM: f32 = 1e-2;

/// Share of the margin a point may lie behind a one-way platform's line and still count as
/// in front of it (positions and segment ends round differently).
const FRONT_TOLERANCE: f32 = 0.25;

/// [`Clearance::node_flags`]: the node is inside a solid tile outline.
const NODE_SOLID: u8 = 1;
/// [`Clearance::node_flags`]: a one-way segment in the mask is within reach of the node's
/// moves.
const NODE_NEAR_ONE_WAY: u8 = 2;

/// A one-way platform as moves see it: its segment and the unit normal of its front.
#[derive(Clone, Copy, Debug)]
pub(crate) struct OneWay {
    pub segment: Segment,
    pub normal: Vec2,
}

/// What blocks moves near a place: segments that block from both sides, and one-way ones.
#[derive(Clone, Debug, Default)]
pub(crate) struct Walls {
    pub two_way: Vec<Segment>,
    pub one_way: Vec<OneWay>,
}

impl Walls {
    fn clear(&mut self) {
        self.two_way.clear();
        self.one_way.clear();
    }
}

/// Per node, whether it is inside a solid tile, and its moves' clearances each way.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Clearance {
    pub lattice: Lattice,
    /// Map units per clearance step.
    pub quantum: f32,
    /// The margin every radius gets (map units).
    pub margin: f32,
    /// Clearances are exact up to this (map units); larger ones are stored as this.
    pub cap: f32,
    /// Segment flags that block.
    pub mask: SegmentFlags,
    /// Per node, [`NODE_SOLID`] and [`NODE_NEAR_ONE_WAY`].
    pub node_flags: Vec<u8>,
    /// Nodes with [`NODE_NEAR_ONE_WAY`]: while there are none, runs need no one-way checks.
    pub one_way_nodes: usize,
    /// Per node, in steps (0 off the lattice): the clearance of moves 0..4 from it, then
    /// of their reverses (slot `4 + d`: the move from the neighbour `d` reaches back to
    /// this node). The two differ only near one-way platforms.
    pub moves: Vec<[u16; 8]>,
}

impl Clearance {
    /// The clearance table of `map` for radii up to `max_radius`.
    pub fn build(map: &TileMap, max_radius: f32, mask: SegmentFlags) -> Self {
        let cell = map.cell_size();
        let lattice = Lattice::new(map.origin(), cell, map.width(), map.height());
        let quantum = cell.min_element() / QUANTA_PER_CELL;
        let margin = cell.min_element() * MARGIN_PER_CELL;
        let nodes = lattice.len();
        let mut table = Self {
            lattice,
            quantum,
            margin,
            cap: max_radius + 2.0 * margin,
            mask,
            node_flags: vec![0; nodes],
            one_way_nodes: 0,
            moves: vec![[0; 8]; nodes],
        };
        let (nx, ny) = (table.lattice.nx, table.lattice.ny);
        table.recompute(map, 0, 0, nx - 1, ny - 1, &mut Vec::new());
        table
    }

    /// The steps of clearance a circle of `radius` needs for a move.
    pub fn need(&self, radius: f32) -> u16 {
        ((radius + self.margin) / self.quantum)
            .ceil()
            .clamp(1.0, f32::from(u16::MAX)) as u16
    }

    /// Clearance in steps of move `d` (any of the eight) from node `index` at (`i`, `j`):
    /// moves 0..4 are stored at the node, the others (the reverses of the neighbour's moves
    /// 0..4) at the neighbour they reach.
    #[inline]
    pub fn move_clearance(&self, index: usize, i: u32, j: u32, d: usize) -> u16 {
        if d < 4 {
            self.moves[index][d]
        } else {
            match self.lattice.neighbour(i, j, d) {
                Some((ni, nj)) => self.moves[self.lattice.index(ni, nj)][d],
                None => 0,
            }
        }
    }

    /// True when a one-way segment in the mask is near some node: then runs between
    /// lattice nodes need [`Clearance::segment_clearance`]'s one-way checks.
    pub fn has_one_way(&self) -> bool {
        self.one_way_nodes > 0
    }

    /// Recomputes every node in the (inclusive) lattice rectangle, appending the moves whose
    /// clearance changed to `changed`.
    fn recompute(
        &mut self,
        map: &TileMap,
        i0: u32,
        j0: u32,
        i1: u32,
        j1: u32,
        changed: &mut Vec<ChangedMove>,
    ) {
        for j in j0..=j1 {
            for i in i0..=i1 {
                let index = self.lattice.index(i, j);
                let solid = map.is_point_solid(self.lattice.position(i, j));
                self.node_flags[index] =
                    self.node_flags[index] & !NODE_SOLID | if solid { NODE_SOLID } else { 0 };
            }
        }
        let mut walls = Walls::default();
        let solid = |table: &Self, i: u32, j: u32| {
            table.node_flags[table.lattice.index(i, j)] & NODE_SOLID != 0
        };
        for j in j0..=j1 {
            for i in i0..=i1 {
                let index = self.lattice.index(i, j);
                let p = self.lattice.position(i, j);
                let region = Aabb::from_center(p, self.lattice.step + Vec2::splat(self.cap));
                walls.clear();
                blocking_walls(map, &region, self.mask, &mut walls);
                let was_near = self.node_flags[index] & NODE_NEAR_ONE_WAY != 0;
                let near = !walls.one_way.is_empty();
                if near != was_near {
                    self.node_flags[index] ^= NODE_NEAR_ONE_WAY;
                    if near {
                        self.one_way_nodes += 1;
                    } else {
                        self.one_way_nodes -= 1;
                    }
                }
                let mut moves = [0u16; 8];
                for d in 0..4 {
                    let Some((ni, nj)) = self.lattice.neighbour(i, j, d) else {
                        continue;
                    };
                    if solid(self, i, j) || solid(self, ni, nj) {
                        continue;
                    }
                    let q = self.lattice.position(ni, nj);
                    let steps = |clear: f32| {
                        ((clear / self.quantum).floor()).min(f32::from(u16::MAX)) as u16
                    };
                    let both = two_way_squared(map, &walls.two_way, p, q, self.cap);
                    let tolerance = self.margin * FRONT_TOLERANCE;
                    let way = |a: Vec2, b: Vec2| {
                        steps(one_way_squared(both, &walls.one_way, a, b, tolerance).sqrt())
                    };
                    moves[d] = way(p, q);
                    moves[d + 4] = way(q, p);
                }
                for (slot, (&before, &after)) in self.moves[index].iter().zip(&moves).enumerate() {
                    if before == after {
                        continue;
                    }
                    // Slot 4 + d is the move from neighbour d back to this node.
                    let (node, dir) = if slot < 4 {
                        (index, slot)
                    } else {
                        let (ni, nj) = self.lattice.neighbour(i, j, slot - 4).unwrap_or((i, j));
                        (self.lattice.index(ni, nj), slot)
                    };
                    changed.push(ChangedMove {
                        node: node as u32,
                        dir: dir as u8,
                        before,
                        after,
                    });
                }
                self.moves[index] = moves;
            }
        }
    }

    /// Brings the table up to date after the tile of `cell` changed: recomputes only the
    /// nodes whose moves can see a segment the edit may have changed (those of the cell's
    /// 3 × 3 block: seam culling changes the cell and its four neighbours). Returns the moves
    /// whose clearance changed.
    pub fn update_cell(&mut self, map: &TileMap, cell: Cell) -> Vec<ChangedMove> {
        let (i0, j0, i1, j1) = self.cell_nodes(map, cell);
        let mut changed = Vec::new();
        self.recompute(map, i0, j0, i1, j1, &mut changed);
        changed
    }

    /// The (inclusive) lattice rectangle of the nodes whose stored moves an edit of `cell`
    /// may change: what [`update_cell`](Self::update_cell) recomputes.
    pub fn cell_nodes(&self, map: &TileMap, cell: Cell) -> (u32, u32, u32, u32) {
        let cell_size = map.cell_size();
        let lo = map.cell_corner(cell) - cell_size;
        let hi = lo + 3.0 * cell_size;
        let reach = self.lattice.step + Vec2::splat(self.cap);
        let a = self.lattice.local(lo - reach).floor().max(Vec2::ZERO);
        let b = self.lattice.local(hi + reach).ceil();
        (
            a.x as u32,
            a.y as u32,
            (b.x as u32).min(self.lattice.nx - 1),
            (b.y as u32).min(self.lattice.ny - 1),
        )
    }

    /// The clearance (map units, at most the cap) of a straight move from `a` to `b`
    /// anywhere on the map, one-way platforms counted the way it goes: what joins a query's
    /// end points to the lattice. With `a == b`, how clear the point is of everything but
    /// one-way platforms (which a circle standing still never runs into).
    pub fn segment_clearance(&self, map: &TileMap, a: Vec2, b: Vec2) -> f32 {
        if map.is_point_solid(a) || map.is_point_solid(b) {
            return 0.0;
        }
        let region = Aabb::from_corners(a, b).expand(self.cap);
        let mut walls = Walls::default();
        blocking_walls(map, &region, self.mask, &mut walls);
        move_clearance(map, &walls, a, b, self.cap, self.margin * FRONT_TOLERANCE)
    }

    /// The clearance (map units, at most the cap) of a straight move from `a` to `b` from
    /// the one-way platforms in the mask only, counted the way it goes.
    pub fn one_way_clearance(&self, map: &TileMap, a: Vec2, b: Vec2) -> f32 {
        let region = Aabb::from_corners(a, b).expand(self.cap);
        let mut walls = Walls::default();
        blocking_walls(map, &region, self.mask & SegmentFlags::ONE_WAY, &mut walls);
        let tolerance = self.margin * FRONT_TOLERANCE;
        one_way_squared(self.cap * self.cap, &walls.one_way, a, b, tolerance).sqrt()
    }
}

/// The active segments of the cells `region` touches that have one of `mask`'s flags: those
/// with the `ONE_WAY` flag as one-way platforms, the others as blocking from both sides.
fn blocking_walls(map: &TileMap, region: &Aabb, mask: SegmentFlags, out: &mut Walls) {
    let Some((c0, r0, c1, r1)) = map.cell_range(region) else {
        return;
    };
    let width = map.width() as usize;
    for row in r0 as usize..=r1 as usize {
        for col in c0 as usize..=c1 as usize {
            for s in map.store.cell(row * width + col) {
                if !s.flags.intersects(mask) {
                    continue;
                }
                let segment = Segment::new(s.a, s.b());
                if s.flags.contains(SegmentFlags::ONE_WAY) {
                    out.one_way.push(OneWay {
                        segment,
                        normal: s.normal,
                    });
                } else {
                    out.two_way.push(segment);
                }
            }
        }
    }
}

/// The least distance from the move from `a` to `b` to the two-way `walls` and the map's
/// border, and to the one-way ones the way it goes (see [`one_way_distance_squared`],
/// with `tolerance`), at most `cap`.
fn move_clearance(map: &TileMap, walls: &Walls, a: Vec2, b: Vec2, cap: f32, tolerance: f32) -> f32 {
    let both = two_way_squared(map, &walls.two_way, a, b, cap);
    one_way_squared(both, &walls.one_way, a, b, tolerance).sqrt()
}

/// The least squared distance from the move from `a` to `b` to `walls` and to the map's
/// border, at most `cap` squared: the same both ways.
fn two_way_squared(map: &TileMap, walls: &[Segment], a: Vec2, b: Vec2, cap: f32) -> f32 {
    let lo = map.origin();
    let hi = lo + map.cell_size() * Vec2::new(map.width() as f32, map.height() as f32);
    // The map is a box, so the border is nearest at an end point.
    let border = |p: Vec2| (p - lo).min(hi - p).min_element();
    let mut least = (cap * cap).min(border(a).max(0.0).powi(2));
    least = least.min(border(b).max(0.0).powi(2));
    let path = Segment::new(a, b);
    for wall in walls {
        least = least.min(path.distance_squared_to_segment(wall));
    }
    least
}

/// `least`, lowered to the squared distance of the move from `a` to `b` to each of the
/// one-way `walls`, the way it goes.
fn one_way_squared(least: f32, walls: &[OneWay], a: Vec2, b: Vec2, tolerance: f32) -> f32 {
    walls.iter().fold(least, |least, w| {
        least.min(one_way_distance_squared(w, a, b, tolerance))
    })
}

/// The squared distance at which a circle moving from `p` to `q` can meet the front of the
/// one-way platform `w`: a circle of a smaller radius (and the resolver's gap) does not,
/// whatever steps the resolver moves it by. Infinite when it never can.
///
/// The resolver stops a circle at a one-way segment only on the front: on the flat side
/// when its centre is in front of the line and moving towards it, at a rounded end (every
/// end of a one-way segment has one) when its centre is in front and closing in on the end.
/// So:
/// - moving with the normal (by more than [`ALONG_PLATFORM`]), only the ends count, and
///   only while the centre is in front of the line (or behind it by half the `tolerance`)
///   and still closing in: the distance at the closest approach, if it closes in by more
///   than `tolerance` meanwhile (less only grazes: the resolver slides the circle round
///   the end, never stops it, as a move with the normal never meets an end head-on from
///   the front; a move straight through a platform's end point closes in by half the
///   tolerance);
/// - moving against it or along it, the part of the move in front of the line (or behind
///   it by at most `tolerance`) counts whole: its distance to the segment.
///
/// A move that stays behind the line, or crosses it from behind moving with the normal
/// (straight through the platform), has no distance to it at all; one that stands still
/// runs into nothing.
pub(crate) fn one_way_distance_squared(w: &OneWay, p: Vec2, q: Vec2, tolerance: f32) -> f32 {
    let m = q - p;
    let len2 = m.length_squared();
    if len2 == 0.0 {
        return f32::INFINITY;
    }
    let n = w.normal;
    let h0 = (p - w.segment.a).dot(n);
    let mn = m.dot(n);
    if mn > ALONG_PLATFORM * len2.sqrt() {
        let mut least = f32::INFINITY;
        // In front of the line (or behind it by half the tolerance) from `front` on.
        let front = ((-0.5 * tolerance - h0) / mn).max(0.0);
        for end in [w.segment.a, w.segment.b] {
            // Closing in on the end until `t`.
            let t = ((end - p).dot(m) / len2).min(1.0);
            if t <= front {
                continue;
            }
            let closest = (p + m * t).distance(end);
            // Closing in by no more than the tolerance only grazes the end: the resolver
            // stops the circle there and slides it on round the end, off the run by that.
            // (A circle just through a platform is in reach of both its ends, and only
            // moves straight on along the normal close in on neither.)
            if (p + m * front).distance(end) - closest > tolerance {
                least = least.min(closest * closest);
            }
        }
        return least;
    }
    // The times the centre is in front of the line (less the tolerance).
    let (t0, t1) = if mn < 0.0 {
        (0.0, ((h0 + tolerance) / -mn).min(1.0))
    } else if mn > 0.0 {
        (((-tolerance - h0) / mn).max(0.0), 1.0)
    } else if h0 >= -tolerance {
        (0.0, 1.0)
    } else {
        return f32::INFINITY;
    };
    match t0.partial_cmp(&t1) {
        // Never in front.
        Some(Ordering::Greater) => f32::INFINITY,
        Some(_) => Segment::new(p + m * t0, p + m * t1).distance_squared_to_segment(&w.segment),
        // Not a number (no input in range gives one): taken as touching.
        None => 0.0,
    }
}

/// Which moves of the eight (bits in [`MOVES`] order) a circle needing `need` steps can make
/// from node `index` at (`i`, `j`).
pub(crate) fn open_moves(table: &Clearance, index: usize, i: u32, j: u32, need: u16) -> u8 {
    let mut bits = 0u8;
    for d in 0..MOVES.len() {
        if table.move_clearance(index, i, j, d) >= need {
            bits |= 1 << d;
        }
    }
    bits
}

/// Which moves into node `index` at (`i`, `j`) a circle needing `need` steps can make: bit
/// `d` when the move from neighbour `d` (of [`MOVES`]) to this node is open. The moves a
/// flow field's distances run along, from the goal outwards.
pub(crate) fn incoming_moves(table: &Clearance, index: usize, i: u32, j: u32, need: u16) -> u8 {
    let mut bits = 0u8;
    for d in 0..MOVES.len() {
        let clearance = if d < 4 {
            table.moves[index][d + 4]
        } else {
            match table.lattice.neighbour(i, j, d) {
                Some((ni, nj)) => table.moves[table.lattice.index(ni, nj)][d - 4],
                None => 0,
            }
        };
        if clearance >= need {
            bits |= 1 << d;
        }
    }
    bits
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::ascii;

    fn map(text: &str) -> TileMap {
        ascii::parse(text, "test.txt", 1.0).unwrap()
    }

    #[test]
    fn a_two_wide_corridor_passes_a_wide_circle_only_along_its_middle() {
        let m = map("######\n#....#\n#....#\n######");
        let table = Clearance::build(&m, 1.0, SegmentFlags::SOLID);
        let l = &table.lattice;
        // The corridor is y in [1, 3]; its middle line y = 2 is lattice row 4.
        let middle = table.moves[l.index(4, 4)][0];
        assert!(middle >= table.need(0.99), "{middle}");
        assert!(
            middle < table.need(1.0),
            "the walls are exactly 1 away: {middle}"
        );
        // A row off the middle (y = 1.5) is 0.5 from the wall.
        let off = table.moves[l.index(4, 3)][0];
        assert!(off >= table.need(0.49) && off < table.need(0.5));
        // Moves into the walls have no clearance.
        assert_eq!(table.moves[l.index(4, 2)][2], 0, "(2, 1) is on the wall");
    }

    #[test]
    fn a_diagonal_past_a_corner_has_the_corner_distance() {
        let m = map("####\n#..#\n#.##\n####");
        let table = Clearance::build(&m, 1.0, SegmentFlags::SOLID);
        let l = &table.lattice;
        // From (1.5, 1.5) to (2.0, 2.0): it ends on the corner of the solid cell (2, 2).
        let d = table.moves[l.index(3, 3)][1];
        assert_eq!(d, 0);
        // From (1.5, 1.5) to (1.0, 2.0) ends on the left wall.
        assert_eq!(table.moves[l.index(3, 3)][3], 0);
    }

    #[test]
    fn an_update_equals_a_rebuild() {
        let mut m = map("#######\n#.....#\n#.###.#\n#.....#\n#######");
        let mut table = Clearance::build(&m, 0.8, SegmentFlags::SOLID);
        m.clear_tile(Cell::new(3, 2)).unwrap();
        let changed = table.update_cell(&m, Cell::new(3, 2));
        assert!(!changed.is_empty());
        assert_eq!(table, Clearance::build(&m, 0.8, SegmentFlags::SOLID));
    }

    /// A platform laid and then dug out again: the moves near it become directed, and the
    /// nodes near a one-way segment are counted, exactly as a rebuild finds them.
    #[test]
    fn an_update_laying_or_digging_a_platform_equals_a_rebuild() {
        let mask = SegmentFlags::SOLID | SegmentFlags::ONE_WAY;
        let mut m = map("#######\n#.....#\n#.....#\n#.....#\n#######");
        let mut table = Clearance::build(&m, 0.8, mask);
        assert!(!table.has_one_way());
        let cell = Cell::new(3, 2);
        m.set_tile(cell, Some(ascii::ONE_WAY)).unwrap();
        let changed = table.update_cell(&m, cell);
        assert!(
            changed.iter().any(|c| c.dir >= 4),
            "reverse moves changed too"
        );
        assert_eq!(table, Clearance::build(&m, 0.8, mask));
        assert!(table.has_one_way());
        // Up through the platform (along its normal, (0, -1)) from (3.5, 2.5) to (3.5, 2)
        // and on to (3.5, 1.5) is open; down the same way is not.
        let l = &table.lattice;
        let below = l.index(7, 5);
        assert!(table.move_clearance(below, 7, 5, 6) >= table.need(0.3));
        assert_eq!(table.move_clearance(l.index(7, 3), 7, 3, 2), 0);
        m.clear_tile(cell).unwrap();
        table.update_cell(&m, cell);
        assert_eq!(table, Clearance::build(&m, 0.8, mask));
        assert!(!table.has_one_way());
    }
}
