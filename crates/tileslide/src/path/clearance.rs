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
//! One table serves every radius up to the navigation grid's `max_radius`: clearances are
//! computed exactly up to that (plus the margin) and stored, rounded down, in steps of
//! 1/2048 of the shorter cell side (two bytes a move, four forward moves a node).

use glam::Vec2;

use super::lattice::{Lattice, MOVES};
use crate::geometry::{Aabb, Segment};
use crate::tiles::{Cell, SegmentFlags, TileMap};

/// Clearance steps per shorter cell side.
const QUANTA_PER_CELL: f32 = 2048.0;

/// Extra clearance a circle needs beyond its radius, per shorter cell side: found paths
/// keep this far from walls, so a body following one never touches them.
pub(crate) const MARGIN_PER_CELL: f32 = 1e-3;

/// A forward move whose clearance changed in an update: `node`, move `dir` (0..4), and its
/// clearance before and after, in steps.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct ChangedMove {
    pub node: u32,
    pub dir: u8,
    pub before: u16,
    pub after: u16,
}

/// Per node, whether it is inside a solid tile, and its four forward moves' clearances.
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
    /// Per node, inside a solid tile outline.
    pub solid: Vec<bool>,
    /// Per node, clearance of moves 0..4 in steps (0 off the lattice).
    pub moves: Vec<[u16; 4]>,
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
            solid: vec![false; nodes],
            moves: vec![[0; 4]; nodes],
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
    /// the forward ones are stored at the node, the others at the neighbour they reach.
    #[inline]
    pub fn move_clearance(&self, index: usize, i: u32, j: u32, d: usize) -> u16 {
        if d < 4 {
            self.moves[index][d]
        } else {
            match self.lattice.neighbour(i, j, d) {
                Some((ni, nj)) => self.moves[self.lattice.index(ni, nj)][d - 4],
                None => 0,
            }
        }
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
                self.solid[index] = map.is_point_solid(self.lattice.position(i, j));
            }
        }
        let mut walls = Vec::new();
        for j in j0..=j1 {
            for i in i0..=i1 {
                let index = self.lattice.index(i, j);
                let p = self.lattice.position(i, j);
                let region = Aabb::from_center(p, self.lattice.step + Vec2::splat(self.cap));
                walls.clear();
                blocking_walls(map, &region, self.mask, &mut walls);
                let mut moves = [0u16; 4];
                for (d, slot) in moves.iter_mut().enumerate() {
                    let Some((ni, nj)) = self.lattice.neighbour(i, j, d) else {
                        continue;
                    };
                    if self.solid[index] || self.solid[self.lattice.index(ni, nj)] {
                        continue;
                    }
                    let q = self.lattice.position(ni, nj);
                    let clear = move_clearance(map, &walls, Segment::new(p, q), self.cap);
                    *slot = ((clear / self.quantum).floor()).min(f32::from(u16::MAX)) as u16;
                }
                for (d, (&before, &after)) in self.moves[index].iter().zip(&moves).enumerate() {
                    if before != after {
                        changed.push(ChangedMove {
                            node: index as u32,
                            dir: d as u8,
                            before,
                            after,
                        });
                    }
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
        let cell_size = map.cell_size();
        let lo = map.cell_corner(cell) - cell_size;
        let hi = lo + 3.0 * cell_size;
        let reach = self.lattice.step + Vec2::splat(self.cap);
        let a = self.lattice.local(lo - reach).floor().max(Vec2::ZERO);
        let b = self.lattice.local(hi + reach).ceil();
        let (i1, j1) = (
            (b.x as u32).min(self.lattice.nx - 1),
            (b.y as u32).min(self.lattice.ny - 1),
        );
        let mut changed = Vec::new();
        self.recompute(map, a.x as u32, a.y as u32, i1, j1, &mut changed);
        changed
    }

    /// The clearance (map units, at most the cap) of a straight move from `a` to `b`
    /// anywhere on the map: what joins a query's end points to the lattice.
    pub fn segment_clearance(&self, map: &TileMap, a: Vec2, b: Vec2) -> f32 {
        if map.is_point_solid(a) || map.is_point_solid(b) {
            return 0.0;
        }
        let region = Aabb::from_corners(a, b).expand(self.cap);
        let mut walls = Vec::new();
        blocking_walls(map, &region, self.mask, &mut walls);
        move_clearance(map, &walls, Segment::new(a, b), self.cap)
    }
}

/// The active segments of the cells `region` touches that have one of `mask`'s flags.
fn blocking_walls(map: &TileMap, region: &Aabb, mask: SegmentFlags, out: &mut Vec<Segment>) {
    let Some((c0, r0, c1, r1)) = map.cell_range(region) else {
        return;
    };
    let width = map.width() as usize;
    for row in r0 as usize..=r1 as usize {
        for col in c0 as usize..=c1 as usize {
            for s in map.store.cell(row * width + col) {
                if s.flags.intersects(mask) {
                    out.push(Segment::new(s.a, s.b()));
                }
            }
        }
    }
}

/// The least distance from `path` to `walls` and to the map's border, at most `cap`.
fn move_clearance(map: &TileMap, walls: &[Segment], path: Segment, cap: f32) -> f32 {
    let lo = map.origin();
    let hi = lo + map.cell_size() * Vec2::new(map.width() as f32, map.height() as f32);
    // The map is a box, so the border is nearest at an end point.
    let border = |p: Vec2| (p - lo).min(hi - p).min_element();
    let mut least = (cap * cap).min(border(path.a).max(0.0).powi(2));
    least = least.min(border(path.b).max(0.0).powi(2));
    for wall in walls {
        least = least.min(path.distance_squared_to_segment(wall));
    }
    least.sqrt()
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
}
