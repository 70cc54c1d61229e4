//! The dungeon256 and open256 maps: random fill, then corridors carved by random walks.

use crate::{SolidGrid, SplitMix64};

/// Side of both standard maps, in cells.
const SIZE: usize = 256;
/// Seed of the map generator, shared by dungeon256 and open256.
const MAP_SEED: u64 = 0x7115_51DE_2026_0001;
/// Probability that an interior cell starts solid.
const FILL: f32 = 0.45;
/// Steps per carving walk.
const WALK_STEPS: usize = 48;
/// Probability that a walk turns before a step.
const TURN: f32 = 0.15;
/// Walk directions, indexed by `d` as in BENCHMARKS.md: +x, +y, −x, −y.
const DIRECTIONS: [(usize, isize); 4] = [(0, 1), (1, 1), (0, -1), (1, -1)];

/// The "dungeon256" map of BENCHMARKS.md: 256×256, carved until at most 30 %
/// of the interior is solid (20,365 solid cells, fingerprint `a36c9fd56f2ba422`).
///
/// ```
/// let grid = tileslide_scenes::dungeon256();
/// assert_eq!(grid.fingerprint_hex(), "a36c9fd56f2ba422");
/// ```
#[must_use]
pub fn dungeon256() -> SolidGrid {
    carved_map(0.30)
}

/// The "open256" variant: the same generator carved down to 10 % interior
/// solid fraction (7,459 solid cells).
///
/// ```
/// assert_eq!(tileslide_scenes::open256().solid_count(), 7_459);
/// ```
#[must_use]
pub fn open256() -> SolidGrid {
    carved_map(0.10)
}

/// Runs the BENCHMARKS.md map generator, carving until the interior solid
/// fraction is no longer above `target`.
fn carved_map(target: f64) -> SolidGrid {
    let mut rng = SplitMix64::new(MAP_SEED);
    let last = SIZE - 1;
    let on_border = |x: usize, y: usize| x == 0 || y == 0 || x == last || y == last;
    let is_interior = |x: usize, y: usize| (1..last).contains(&x) && (1..last).contains(&y);

    // 1. Fill: one draw per cell in row-major order, border cells included.
    let mut solid = Vec::with_capacity(SIZE * SIZE);
    for y in 0..SIZE {
        for x in 0..SIZE {
            let r = rng.f32();
            solid.push(on_border(x, y) || r < FILL);
        }
    }

    // 2. Carve: count interior solids once and keep the count up to date.
    let interior_cells = ((SIZE - 2) * (SIZE - 2)) as f64;
    let mut interior_solid = (1..last)
        .flat_map(|y| (1..last).map(move |x| (x, y)))
        .filter(|&(x, y)| solid[y * SIZE + x])
        .count();
    let span = (SIZE - 3) as u64; // start cells 1..=253
    while interior_solid as f64 / interior_cells > target {
        let mut pos = [
            1 + below_usize(&mut rng, span),
            1 + below_usize(&mut rng, span),
        ];
        let mut d = below_usize(&mut rng, 4);
        for _ in 0..WALK_STEPS {
            for (cx, cy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                let (x, y) = (pos[0] + cx, pos[1] + cy);
                if is_interior(x, y) && solid[y * SIZE + x] {
                    solid[y * SIZE + x] = false;
                    interior_solid -= 1;
                }
            }
            if rng.f32() < TURN {
                d = if rng.below(2) == 0 {
                    (d + 1) % 4
                } else {
                    (d + 3) % 4
                };
            }
            let (axis, delta) = DIRECTIONS[d];
            // The walk stays in 1..254 on both axes (so its 2×2 block stays inside
            // the interior); at the limit it reverses without moving.
            match pos[axis].checked_add_signed(delta) {
                Some(next) if (1..last - 1).contains(&next) => pos[axis] = next,
                _ => d = (d + 2) % 4,
            }
        }
    }
    SolidGrid {
        width: SIZE,
        height: SIZE,
        solid,
    }
}

/// `rng.below(n)` as a `usize` index (values are below `n`, which is small).
fn below_usize(rng: &mut SplitMix64, n: u64) -> usize {
    usize::try_from(rng.below(n)).unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dungeon256_matches_published_solid_count_and_fingerprint() {
        let grid = dungeon256();
        assert_eq!(
            (grid.width, grid.height, grid.solid.len()),
            (256, 256, 65_536)
        );
        assert_eq!(grid.solid_count(), 20_365);
        assert_eq!(grid.fingerprint_hex(), "a36c9fd56f2ba422");
    }

    #[test]
    fn open256_matches_published_solid_count() {
        assert_eq!(open256().solid_count(), 7_459);
    }

    #[test]
    fn border_ring_stays_solid() {
        for grid in [dungeon256(), open256()] {
            for i in 0..256 {
                assert!(grid.is_solid(i, 0) && grid.is_solid(i, 255));
                assert!(grid.is_solid(0, i) && grid.is_solid(255, i));
            }
        }
    }

    #[test]
    fn generation_is_deterministic() {
        assert_eq!(dungeon256(), dungeon256());
        assert_eq!(open256(), open256());
    }
}
