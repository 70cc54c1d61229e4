//! The collision audit, computed from body positions alone, independently of the
//! resolver: pairs of bodies that overlap, and bodies that reach into a solid cell.

use tileslide::{Bodies, Cell, TileMap, Vec2};

/// How deep an overlap must be to count (rounding allowance).
const TOLERANCE: f32 = 1e-4;

/// Overlapping pairs and wall penetrations.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Audit {
    /// Pairs of bodies closer than the sum of their radii.
    pub overlapping_pairs: u64,
    /// Bodies reaching into a solid cell.
    pub wall_penetrations: u64,
}

impl Audit {
    /// The audit of the bodies' current positions (every pair: O(n²), fine for a few
    /// dozen bodies), against the map's tiles (every tile of this game is a full square).
    #[must_use]
    pub fn of(bodies: &Bodies, map: &TileMap) -> Self {
        let circles: Vec<(Vec2, f32)> = bodies
            .iter()
            .map(|(_, b)| (b.position(), b.shape().bounding_radius()))
            .collect();
        let mut audit = Self::default();
        for (i, &(p, r)) in circles.iter().enumerate() {
            for &(q, s) in &circles[i + 1..] {
                if p.distance(q) < r + s - TOLERANCE {
                    audit.overlapping_pairs += 1;
                }
            }
            if penetrates(map, p, r) {
                audit.wall_penetrations += 1;
            }
        }
        audit
    }

    /// Both counts added.
    pub fn add(&mut self, other: Audit) {
        self.overlapping_pairs += other.overlapping_pairs;
        self.wall_penetrations += other.wall_penetrations;
    }
}

/// True when the circle reaches into a solid cell (or off the map).
fn penetrates(map: &TileMap, p: Vec2, r: f32) -> bool {
    let (lo, hi) = ((p - r).floor(), (p + r).floor());
    for row in lo.y as i64..=hi.y as i64 {
        for col in lo.x as i64..=hi.x as i64 {
            if col < 0 || row < 0 || col >= i64::from(map.width()) || row >= i64::from(map.height())
            {
                return true;
            }
            let cell = Cell {
                col: col as u32,
                row: row as u32,
            };
            if map.tile(cell).is_some() {
                let rect = map.cell_rect(cell);
                let nearest = p.clamp(rect.min, rect.max);
                if nearest.distance(p) < r - TOLERANCE {
                    return true;
                }
            }
        }
    }
    false
}
