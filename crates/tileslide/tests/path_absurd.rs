//! Absurd but finite input to the navigation grid (points of 1e20 or 3e38, radii of
//! `f32::MAX`, maps far from the origin) is refused with an error naming the value, never a
//! panic or a wrong answer; points within `MAX_COORD` but far off the map are simply not
//! reached.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::sync::Arc;

use tileslide::io::ascii;
use tileslide::{Cell, FlowField, NavConfig, NavError, NavGrid, TileMap, Vec2, limits::MAX_COORD};

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

const ROOM: &str = "\
########
#......#
#..=...#
#......#
########";

fn room() -> TileMap {
    ascii::parse(ROOM, "room.txt", 1.0).unwrap()
}

/// Finite points past `MAX_COORD`: lattice coordinates of these overflow integers.
const FAR: [Vec2; 5] = [
    Vec2::new(1e20, 1.5),
    Vec2::new(1.5, 3e38),
    Vec2::new(-3e38, -3e38),
    Vec2::new(f32::MAX, f32::MAX),
    Vec2::new(MAX_COORD * 2.0, 0.0),
];

/// True when `result` is the out-of-range error naming `what` and the point `bad`, and
/// says so in its message.
fn names_out_of_range<T>(result: Result<T, NavError>, what: &str, bad: Vec2) -> bool {
    match result {
        Err(e @ NavError::OutOfRange { what: w, point }) => {
            w == what && point == bad && e.to_string().contains("MAX_COORD")
        }
        _ => false,
    }
}

#[test]
fn points_beyond_max_coord_are_refused_naming_the_point() {
    let map = room();
    let nav = NavGrid::new(&map, NavConfig::default()).unwrap();
    let ok = v(1.5, 1.5);
    let field = FlowField::new(&nav, &map, ok, 0.3).unwrap();
    for bad in FAR {
        assert!(
            names_out_of_range(nav.find_path(&map, bad, ok, 0.3), "from", bad),
            "{bad}"
        );
        assert!(
            names_out_of_range(nav.find_path(&map, ok, bad, 0.3), "to", bad),
            "{bad}"
        );
        assert!(
            names_out_of_range(FlowField::new(&nav, &map, bad, 0.3), "goal", bad),
            "{bad}"
        );
        assert!(
            names_out_of_range(nav.fits(&map, bad, 0.3), "p", bad),
            "{bad}"
        );
        assert!(
            names_out_of_range(field.direction(&nav, &map, bad), "p", bad),
            "{bad}"
        );
        assert!(
            names_out_of_range(field.distance(&nav, &map, bad), "p", bad),
            "{bad}"
        );
    }
}

/// At the edge of the range, far off the map, nothing overflows: no path, no fit, no
/// direction, and a field whose goal is there reaches no point of the map.
#[test]
fn points_at_max_coord_far_off_the_map_are_not_reached() {
    let map = room();
    let nav = NavGrid::new(&map, NavConfig::default()).unwrap();
    let ok = v(1.5, 1.5);
    for far in [
        v(MAX_COORD, -MAX_COORD),
        v(-MAX_COORD, MAX_COORD),
        v(MAX_COORD, 1.5),
    ] {
        assert_eq!(nav.find_path(&map, far, ok, 0.3), Ok(None), "{far}");
        assert_eq!(nav.find_path(&map, ok, far, 0.3), Ok(None), "{far}");
        assert_eq!(nav.fits(&map, far, 0.3), Ok(false), "{far}");
        let field = FlowField::new(&nav, &map, far, 0.3).unwrap();
        assert_eq!(field.distance(&nav, &map, ok), Ok(None), "{far}");
        assert_eq!(field.direction(&nav, &map, ok), Ok(None), "{far}");
        let home = FlowField::new(&nav, &map, ok, 0.3).unwrap();
        assert_eq!(home.direction(&nav, &map, far), Ok(None), "{far}");
    }
    // The grid still answers on the map.
    assert!(nav.find_path(&map, ok, v(6.5, 3.5), 0.3).unwrap().is_some());
}

#[test]
fn radii_of_f32_max_or_nan_are_refused_naming_the_radius() {
    let map = room();
    let nav = NavGrid::new(&map, NavConfig::default()).unwrap();
    let ok = v(1.5, 1.5);
    for radius in [f32::MAX, -f32::MAX, 1e20, f32::NAN] {
        let named = |e: NavError| {
            matches!(e, NavError::BadRadius { radius: r, max_radius: 1.0 }
                if r.to_bits() == radius.to_bits())
        };
        assert!(
            named(nav.find_path(&map, ok, ok, radius).unwrap_err()),
            "{radius}"
        );
        assert!(named(nav.fits(&map, ok, radius).unwrap_err()), "{radius}");
        assert!(
            named(nav.open_moves(&map, 2, 2, radius).unwrap_err()),
            "{radius}"
        );
        assert!(
            named(FlowField::new(&nav, &map, ok, radius).unwrap_err()),
            "{radius}"
        );
    }
    // The smallest positive radius is served.
    let path = nav
        .find_path(&map, ok, v(6.5, 3.5), f32::MIN_POSITIVE)
        .unwrap();
    assert!(path.is_some());
}

/// A room of unit cells whose origin is `origin`.
fn room_at(origin: Vec2) -> Result<TileMap, tileslide::MapError> {
    let set = Arc::new(ascii::tile_set(1.0).unwrap());
    let mut map = TileMap::new(set, 8, 5, origin)?;
    for col in 0..8 {
        for row in [0, 4] {
            map.set_tile(Cell::new(col, row), Some(ascii::SOLID))?;
        }
    }
    Ok(map)
}

/// Far from (0, 0), `f32` coordinates are farther apart than the grid's margin (1/1000 of
/// a cell): the clearances of moves there cannot be told from touching a wall, so the grid
/// refuses such a map, naming its far corner, instead of answering wrongly.
#[test]
fn a_map_whose_coordinates_are_coarser_than_the_margin_is_refused() {
    // At 2^13 = 8192 the spacing of f32 is 2^-10 < 1e-3: accepted; at 2^14, 2^-9: not.
    assert!(NavGrid::new(&room_at(v(8000.0, 0.0)).unwrap(), NavConfig::default()).is_ok());
    for origin in [v(16400.0, 0.0), v(0.0, -1e6), v(-1.6e7, 1.6e7)] {
        let map = room_at(origin).unwrap();
        let err = NavGrid::new(&map, NavConfig::default()).unwrap_err();
        let NavError::TooFar {
            corner,
            spacing,
            margin,
        } = err
        else {
            panic!("{origin}: {err:?}");
        };
        assert!(
            spacing > margin && margin == 1e-3,
            "{origin}: {spacing} {margin}"
        );
        let b = map.bounds();
        assert!(corner.x == b.min.x || corner.x == b.max.x, "{corner}");
        assert!(
            corner.abs().max_element() >= origin.abs().max_element(),
            "{corner}"
        );
        assert!(err.to_string().contains("origin"), "{err}");
    }
}
