//! What a cell of an LDtk layer becomes: the collision shapes by name, their tile ids, and
//! their shapes (mirrored as LDtk flips tiles).

use glam::Vec2;

use crate::io::ascii;
use crate::tiles::{SegmentFlags, ShapeError, TileId, TileSegment, TileShape};

/// The collision of a cell: one of the built-in shapes, nothing, or one of the game's own
/// tiles. IntGrid values, tile sets' enum tags and tiles' custom data name them
/// ([`from_name`](Self::from_name)); [`LdtkOptions`](super::LdtkOptions) maps values and
/// names to them.
///
/// Ramps are drawn y down, as LDtk shows them: [`RampUpRight`](Self::RampUpRight) rises to
/// the right at 45°; the gentle ramps rise one cell over two (26.6°), as a low and a high
/// cell side by side.
///
/// ```
/// use tileslide::io::ldtk::Collision;
/// assert_eq!(Collision::from_name("One_Way"), Some(Collision::OneWay));
/// assert_eq!(Collision::from_name("RAMP-UP-RIGHT"), Some(Collision::RampUpRight));
/// assert_eq!(Collision::from_name("lava"), None);
/// assert_eq!(Collision::Solid.tile_id(), Some(tileslide::io::ascii::SOLID));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[non_exhaustive]
pub enum Collision {
    /// Nothing: the cell blocks nothing (names `empty`, `none`).
    Empty,
    /// A solid square (`solid`).
    Solid,
    /// A one-way platform along the cell's top edge, passed from below (`one_way`).
    OneWay,
    /// A solid 45° ramp rising to the right (`ramp_up_right`).
    RampUpRight,
    /// A solid 45° ramp falling to the right (`ramp_down_right`).
    RampDownRight,
    /// The lower cell of a ramp rising one cell over two to the right
    /// (`gentle_ramp_up_right_low`): from the bottom-left corner to half height.
    GentleRampUpRightLow,
    /// The higher cell of a ramp rising one cell over two to the right
    /// (`gentle_ramp_up_right_high`): from half height to the top-right corner.
    GentleRampUpRightHigh,
    /// The higher cell of a ramp falling one cell over two to the right
    /// (`gentle_ramp_down_right_high`): from the top-left corner to half height.
    GentleRampDownRightHigh,
    /// The lower cell of a ramp falling one cell over two to the right
    /// (`gentle_ramp_down_right_low`): from half height to the bottom-right corner.
    GentleRampDownRightLow,
    /// One of the game's own tiles, with the shape
    /// [`LdtkOptions::tile_shapes`](super::LdtkOptions::tile_shapes) gives it (an id below
    /// [`FIRST_FREE_ID`](Self::FIRST_FREE_ID) is refused: those are the built-in
    /// shapes').
    Tile(TileId),
}

/// The flip bits of a tile id taken from a tile or auto-layer: LDtk's `f`, bit 0 (x) and
/// bit 1 (y), moved to the id's top bits.
pub const FLIP_X_BIT: u32 = 1 << 31;
/// See [`FLIP_X_BIT`].
pub const FLIP_Y_BIT: u32 = 1 << 30;

impl Collision {
    /// The names [`from_name`](Self::from_name) knows, in the order of the variants.
    pub const NAMES: [&'static str; 9] = [
        "empty",
        "solid",
        "one_way",
        "ramp_up_right",
        "ramp_down_right",
        "gentle_ramp_up_right_low",
        "gentle_ramp_up_right_high",
        "gentle_ramp_down_right_high",
        "gentle_ramp_down_right_low",
    ];

    /// The smallest id a game's own tile ([`Collision::Tile`]) may have: the ids below are
    /// the built-in shapes'.
    pub const FIRST_FREE_ID: u32 = 16;

    /// The largest id a game's own tile may have: the two bits above it are the flips.
    pub const LAST_FREE_ID: u32 = FLIP_Y_BIT - 2;

    const BUILT_IN: [Collision; 9] = [
        Collision::Empty,
        Collision::Solid,
        Collision::OneWay,
        Collision::RampUpRight,
        Collision::RampDownRight,
        Collision::GentleRampUpRightLow,
        Collision::GentleRampUpRightHigh,
        Collision::GentleRampDownRightHigh,
        Collision::GentleRampDownRightLow,
    ];

    /// The built-in shape a name stands for, ignoring case, `_`, `-` and spaces
    /// (`one_way`, `OneWay` and `ONE-WAY` are the same); `none` is [`Empty`](Self::Empty).
    #[must_use]
    pub fn from_name(name: &str) -> Option<Self> {
        let key: String = name
            .chars()
            .filter(|c| !matches!(c, '_' | '-' | ' '))
            .map(|c| c.to_ascii_lowercase())
            .collect();
        if key == "none" {
            return Some(Collision::Empty);
        }
        Self::NAMES
            .iter()
            .position(|n| n.replace('_', "") == key)
            .and_then(|i| Self::BUILT_IN.get(i).copied())
    }

    /// The tile id of this collision in the maps the loader builds (unflipped): the ids of
    /// [`io::ascii`](crate::io::ascii) for the shapes ASCII maps have (solid 1, ramps 2
    /// and 3, one-way 4), 5 to 8 for the gentle ramps, the game's id for its own tiles;
    /// `None` for [`Empty`](Self::Empty).
    #[must_use]
    pub fn tile_id(self) -> Option<TileId> {
        Some(match self {
            Collision::Empty => return None,
            Collision::Solid => ascii::SOLID,
            Collision::OneWay => ascii::ONE_WAY,
            Collision::RampUpRight => ascii::RAMP_UP_RIGHT,
            Collision::RampDownRight => ascii::RAMP_DOWN_RIGHT,
            Collision::GentleRampUpRightLow => TileId(5),
            Collision::GentleRampUpRightHigh => TileId(6),
            Collision::GentleRampDownRightHigh => TileId(7),
            Collision::GentleRampDownRightLow => TileId(8),
            Collision::Tile(id) => id,
        })
    }

    /// The collision whose tile id is `id` without its flip bits, given the game's own
    /// tiles' ids.
    #[must_use]
    pub fn of_tile_id(id: TileId) -> Self {
        let base = TileId(id.0 & !(FLIP_X_BIT | FLIP_Y_BIT));
        Self::BUILT_IN
            .iter()
            .copied()
            .find(|c| c.tile_id() == Some(base))
            .unwrap_or(Collision::Tile(base))
    }

    /// This collision's shape in a cell of `size` (y down), mirrored by the flip bits `flip`
    /// (1: in x, 2: in y, as LDtk's `f`); a game's own tile takes its shape in a unit cell
    /// from `own`. `None` for [`Empty`](Self::Empty), and for a game's tile without `own`.
    /// This is how the LDtk loader shapes its tiles, for other sources of tile grids (a
    /// tile-map layer in an engine).
    ///
    /// ```
    /// use tileslide::io::ldtk::Collision;
    /// use tileslide::Vec2;
    /// let ramp = Collision::RampUpRight.shape_in_cell(Vec2::new(16.0, 8.0), 1, None);
    /// let mirrored = ramp.unwrap().unwrap();
    /// let down = Collision::RampDownRight.shape_in_cell(Vec2::new(16.0, 8.0), 0, None);
    /// assert_eq!(mirrored.segments().len(), down.unwrap().unwrap().segments().len());
    /// assert!(Collision::Empty.shape_in_cell(Vec2::ONE, 0, None).is_none());
    /// ```
    pub fn shape_in_cell(
        self,
        size: Vec2,
        flip: u32,
        own: Option<&TileShape>,
    ) -> Option<Result<TileShape, ShapeError>> {
        let unit = match self {
            Collision::Tile(_) => own.cloned().map(Ok),
            built_in => built_in.unit_shape(),
        }?;
        Some(unit.and_then(|u| place(&u, size, flip)))
    }

    /// The tile id of this collision mirrored by the flip bits `flip` (1: x, 2: y): its
    /// [`tile_id`](Self::tile_id) with [`FLIP_X_BIT`] and [`FLIP_Y_BIT`] set as `flip` says;
    /// `None` for [`Empty`](Self::Empty).
    #[must_use]
    pub fn flipped_tile_id(self, flip: u32) -> Option<TileId> {
        self.tile_id().map(|id| flipped(id, flip))
    }

    /// The built-in shape in a unit cell (`[0, 1]²`, y down); `None` for
    /// [`Empty`](Self::Empty) and the game's tiles.
    pub(super) fn unit_shape(self) -> Option<Result<TileShape, ShapeError>> {
        let v = Vec2::new;
        let polygon = |points: &[Vec2]| Some(TileShape::polygon(points));
        match self {
            Collision::Empty | Collision::Tile(_) => None,
            Collision::Solid => polygon(&[v(0.0, 0.0), v(1.0, 0.0), v(1.0, 1.0), v(0.0, 1.0)]),
            Collision::OneWay => Some(TileShape::from_segments([TileSegment::new(
                v(0.0, 0.0),
                v(1.0, 0.0),
                v(0.0, -1.0),
                SegmentFlags::ONE_WAY,
            )])),
            Collision::RampUpRight => polygon(&[v(0.0, 1.0), v(1.0, 1.0), v(1.0, 0.0)]),
            Collision::RampDownRight => polygon(&[v(0.0, 0.0), v(0.0, 1.0), v(1.0, 1.0)]),
            Collision::GentleRampUpRightLow => polygon(&[v(0.0, 1.0), v(1.0, 1.0), v(1.0, 0.5)]),
            Collision::GentleRampUpRightHigh => {
                polygon(&[v(0.0, 1.0), v(1.0, 1.0), v(1.0, 0.0), v(0.0, 0.5)])
            }
            Collision::GentleRampDownRightHigh => {
                polygon(&[v(0.0, 0.0), v(0.0, 1.0), v(1.0, 1.0), v(1.0, 0.5)])
            }
            Collision::GentleRampDownRightLow => polygon(&[v(0.0, 0.5), v(0.0, 1.0), v(1.0, 1.0)]),
        }
    }
}

/// `unit`, a shape in a unit cell, scaled to a cell of `size` and mirrored by LDtk's flip
/// bits `f` (1: x, 2: y). Mirroring keeps each segment's normal pointing the same way out of
/// the shape.
pub(super) fn place(unit: &TileShape, size: Vec2, f: u32) -> Result<TileShape, ShapeError> {
    let mirror = |p: Vec2| {
        Vec2::new(
            if f & 1 != 0 { 1.0 - p.x } else { p.x },
            if f & 2 != 0 { 1.0 - p.y } else { p.y },
        ) * size
    };
    let turn = Vec2::new(
        if f & 1 != 0 { -1.0 } else { 1.0 },
        if f & 2 != 0 { -1.0 } else { 1.0 },
    );
    TileShape::from_segments(unit.segments().iter().map(|s| {
        TileSegment::new(
            mirror(s.a),
            mirror(s.b),
            s.normal * turn + Vec2::ZERO,
            s.flags,
        )
    }))
}

/// The tile id of `base` placed with LDtk's flip bits `f`.
pub(super) fn flipped(base: TileId, f: u32) -> TileId {
    let mut id = base.0;
    if f & 1 != 0 {
        id |= FLIP_X_BIT;
    }
    if f & 2 != 0 {
        id |= FLIP_Y_BIT;
    }
    TileId(id)
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;

    #[test]
    fn every_name_reads_back_as_its_collision_and_ids_are_distinct() {
        for (name, c) in Collision::NAMES.iter().zip(Collision::BUILT_IN) {
            assert_eq!(Collision::from_name(name), Some(c), "{name}");
            if let Some(id) = c.tile_id() {
                assert!(id.0 < Collision::FIRST_FREE_ID);
                assert_eq!(Collision::of_tile_id(id), c);
            }
        }
        let ids: std::collections::BTreeSet<_> = Collision::BUILT_IN
            .iter()
            .filter_map(|c| c.tile_id())
            .collect();
        assert_eq!(ids.len(), Collision::BUILT_IN.len() - 1);
        assert_eq!(Collision::from_name("OneWay"), Some(Collision::OneWay));
        assert_eq!(Collision::from_name("None"), Some(Collision::Empty));
        assert_eq!(Collision::from_name("wall"), None);
        assert_eq!(
            Collision::of_tile_id(TileId(40 | FLIP_X_BIT)),
            Collision::Tile(TileId(40))
        );
    }

    #[test]
    fn the_45_degree_ramps_are_the_ascii_maps_ramps() {
        let set = crate::io::ascii::tile_set(16.0).unwrap();
        for c in [
            Collision::Solid,
            Collision::OneWay,
            Collision::RampUpRight,
            Collision::RampDownRight,
        ] {
            let unit = c.unit_shape().unwrap().unwrap();
            let placed = place(&unit, Vec2::splat(16.0), 0).unwrap();
            let ascii = set.shape(c.tile_id().unwrap()).unwrap();
            assert_eq!(placed.segments(), ascii.segments(), "{c:?}");
        }
    }

    #[test]
    fn a_ramp_mirrored_in_x_is_the_other_ramp_and_normals_stay_outward() {
        let up = Collision::RampUpRight.unit_shape().unwrap().unwrap();
        let mirrored = place(&up, Vec2::splat(8.0), 1).unwrap();
        let down = place(
            &Collision::RampDownRight.unit_shape().unwrap().unwrap(),
            Vec2::splat(8.0),
            0,
        )
        .unwrap();
        let key = |s: &TileShape| {
            let mut v: Vec<_> = s
                .segments()
                .iter()
                .map(|s| {
                    let (a, b) = if (s.a.x, s.a.y) < (s.b.x, s.b.y) {
                        (s.a, s.b)
                    } else {
                        (s.b, s.a)
                    };
                    format!("{a} {b} {}", s.normal)
                })
                .collect();
            v.sort();
            v
        };
        assert_eq!(key(&mirrored), key(&down));
        // Every flip keeps the shape closed, with normals pointing out of it.
        for unit in Collision::BUILT_IN.iter().filter_map(|c| c.unit_shape()) {
            let unit = unit.unwrap();
            for f in 0..4 {
                let s = place(&unit, Vec2::ONE, f).unwrap();
                if !s.has_inside() {
                    continue;
                }
                for seg in s.segments() {
                    let mid = (seg.a + seg.b) * 0.5;
                    assert!(!s.contains_point(mid + seg.normal * 0.01), "{f} {seg:?}");
                    assert!(s.contains_point(mid - seg.normal * 0.01), "{f} {seg:?}");
                }
            }
        }
        assert_eq!(flipped(TileId(3), 3), TileId(3 | FLIP_X_BIT | FLIP_Y_BIT));
    }

    #[test]
    fn gentle_ramps_meet_at_half_height() {
        let low = place(
            &Collision::GentleRampUpRightLow
                .unit_shape()
                .unwrap()
                .unwrap(),
            Vec2::splat(16.0),
            0,
        )
        .unwrap();
        let high = place(
            &Collision::GentleRampUpRightHigh
                .unit_shape()
                .unwrap()
                .unwrap(),
            Vec2::splat(16.0),
            0,
        )
        .unwrap();
        // The low cell is solid below y = 8 at its right edge; the high cell at its left.
        assert!(low.contains_point(Vec2::new(15.0, 9.0)));
        assert!(!low.contains_point(Vec2::new(15.0, 7.0)));
        assert!(high.contains_point(Vec2::new(1.0, 9.0)));
        assert!(!high.contains_point(Vec2::new(1.0, 7.0)));
    }

    #[test]
    fn a_shape_in_a_cell_wider_than_tall_spans_the_cell_and_a_flip_sets_the_ids_bits() {
        let size = Vec2::new(16.0, 8.0);
        let ramp = Collision::RampUpRight
            .shape_in_cell(size, 2, None)
            .unwrap()
            .unwrap();
        // Mirrored in y, the ramp rising to the right hangs from the top: solid near the
        // top-right corner, open near the bottom-right one.
        assert!(ramp.contains_point(Vec2::new(15.0, 1.0)));
        assert!(ramp.contains_point(Vec2::new(8.0, 1.0)));
        assert!(!ramp.contains_point(Vec2::new(1.0, 1.0)));
        assert!(!ramp.contains_point(Vec2::new(1.0, 7.0)));
        let xs: Vec<f32> = ramp
            .segments()
            .iter()
            .flat_map(|s| [s.a.x, s.b.x])
            .collect();
        let ys: Vec<f32> = ramp
            .segments()
            .iter()
            .flat_map(|s| [s.a.y, s.b.y])
            .collect();
        assert_eq!(xs.iter().copied().fold(f32::MIN, f32::max), 16.0);
        assert_eq!(ys.iter().copied().fold(f32::MIN, f32::max), 8.0);
        assert_eq!(
            Collision::OneWay.flipped_tile_id(1),
            Some(TileId(4 | FLIP_X_BIT))
        );
        assert_eq!(Collision::Empty.flipped_tile_id(3), None);
        let own = TileShape::polygon(&[Vec2::ZERO, Vec2::X, Vec2::ONE]).unwrap();
        let game = Collision::Tile(TileId(20));
        assert!(game.shape_in_cell(size, 0, None).is_none());
        assert!(game.shape_in_cell(size, 0, Some(&own)).unwrap().is_ok());
    }
}
