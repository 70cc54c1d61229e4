//! Proves that local tile edits (`set_tile`, `clear_tile`) leave a map in exactly the state
//! `TileMap::from_tiles` builds from the final tiles: the same active segments in every cell
//! (end points, normal, flags, tile, source) with the same `continues` links, the same
//! counts, and the same ray-cast answers; and that refused edits change nothing.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::sync::Arc;

use proptest::prelude::*;
use tileslide::io::ascii;
use tileslide::{Cell, MapError, QueryFilter, Ray, TileId, TileMap, TileSet, TileShape, Vec2};

/// The ASCII tiles plus a half-height block (partial seams) and a nub on the left edge
/// (a seam split in two), all scaled to `cell`.
fn tile_set(cell: f32) -> Arc<TileSet> {
    let mut set = ascii::tile_set(cell).unwrap();
    let p = |x: f32, y: f32| Vec2::new(x, y) * cell;
    set.insert(
        TileId(10),
        TileShape::polygon(&[p(0.0, 0.5), p(1.0, 0.5), p(1.0, 1.0), p(0.0, 1.0)]).unwrap(),
    )
    .unwrap();
    set.insert(
        TileId(11),
        TileShape::polygon(&[p(0.0, 0.25), p(0.5, 0.25), p(0.5, 0.75), p(0.0, 0.75)]).unwrap(),
    )
    .unwrap();
    Arc::new(set)
}

const TILES: [Option<TileId>; 7] = [
    None,
    Some(ascii::SOLID),
    Some(ascii::RAMP_UP_RIGHT),
    Some(ascii::RAMP_DOWN_RIGHT),
    Some(ascii::ONE_WAY),
    Some(TileId(10)),
    Some(TileId(11)),
];

fn tile() -> impl Strategy<Value = Option<TileId>> {
    prop_oneof![3 => Just(None), 3 => Just(TILES[1]), 4 => (2usize..7).prop_map(|i| TILES[i])]
}

#[derive(Clone, Debug)]
struct Scenario {
    width: u32,
    height: u32,
    cell: f32,
    origin: Vec2,
    initial: Vec<Option<TileId>>,
    /// (col, row, tile); `None` is applied with `clear_tile`.
    edits: Vec<(u32, u32, Option<TileId>)>,
}

fn scenario() -> impl Strategy<Value = Scenario> {
    (
        1u32..=10,
        1u32..=10,
        prop_oneof![Just(1.0f32), Just(0.5), Just(32.0)],
        prop_oneof![
            Just(Vec2::ZERO),
            Just(Vec2::new(-3.5, 12.25)),
            Just(Vec2::new(0.1, -7.3))
        ],
        any::<bool>(),
    )
        .prop_flat_map(|(width, height, cell, origin, start_empty)| {
            let n = (width * height) as usize;
            let initial = if start_empty {
                Just(vec![None; n]).boxed()
            } else {
                proptest::collection::vec(tile(), n).boxed()
            };
            let edits = proptest::collection::vec((0..width, 0..height, tile()), 0..60);
            (Just((width, height, cell, origin)), initial, edits)
        })
        .prop_map(|((width, height, cell, origin), initial, edits)| Scenario {
            width,
            height,
            cell,
            origin,
            initial,
            edits,
        })
}

/// Asserts that two maps have the same tiles, active segments, links and counts.
fn assert_same_state(edited: &TileMap, rebuilt: &TileMap) -> Result<(), TestCaseError> {
    prop_assert_eq!(
        edited.placed_segment_count(),
        rebuilt.placed_segment_count()
    );
    prop_assert_eq!(
        edited.active_segment_count(),
        rebuilt.active_segment_count()
    );
    prop_assert_eq!(edited.tile_counts(), rebuilt.tile_counts());
    for row in 0..rebuilt.height() {
        for col in 0..rebuilt.width() {
            let cell = Cell::new(col, row);
            prop_assert_eq!(edited.tile(cell), rebuilt.tile(cell), "tile of {}", cell);
            let a: Vec<_> = edited.active_segments(cell).collect();
            let b: Vec<_> = rebuilt.active_segments(cell).collect();
            // `ActiveSegment` equality covers segment, normal, flags, tile, source and the
            // `continues` links; the links are `SegmentRef`s (cell, index within the cell),
            // and both maps compute each cell's segments in the same order, so the indices
            // must agree too. Compare the geometry they lead to as well, for a clear message.
            for (x, y) in a.iter().zip(&b) {
                for end in 0..2 {
                    let gx = x.continues[end].map(|r| edited.active_segment(r).map(|s| s.segment));
                    let gy = y.continues[end].map(|r| rebuilt.active_segment(r).map(|s| s.segment));
                    prop_assert_eq!(gx, gy, "link {} of {:?} in {}", end, x.segment, cell);
                }
            }
            prop_assert_eq!(&a, &b, "active segments of {}", cell);
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    #[test]
    fn random_edits_give_the_same_state_as_rebuilding_from_the_final_tiles(s in scenario()) {
        let set = tile_set(s.cell);
        let mut edited =
            TileMap::from_tiles(set.clone(), s.width, s.height, s.origin, &s.initial).unwrap();
        let mut tiles = s.initial.clone();
        for &(col, row, id) in &s.edits {
            let cell = Cell::new(col, row);
            match id {
                Some(_) => edited.set_tile(cell, id).unwrap(),
                None => edited.clear_tile(cell).unwrap(),
            }
            tiles[(row * s.width + col) as usize] = id;
        }
        let rebuilt = TileMap::from_tiles(set, s.width, s.height, s.origin, &tiles).unwrap();
        assert_same_state(&edited, &rebuilt)?;

        // The queries read the segment store directly: they must agree too.
        let size = Vec2::new(s.width as f32, s.height as f32) * s.cell;
        for i in 0..16 {
            let f = i as f32 / 16.0;
            let p0 = s.origin + Vec2::new(f * size.x + 0.1 * s.cell, -0.5 * s.cell);
            let p1 = s.origin + Vec2::new((1.0 - f) * size.x, size.y + 0.5 * s.cell);
            for filter in [QueryFilter::default(), QueryFilter::both_sides()] {
                for r in [Ray::between(p0, p1), Ray::between(p1, p0)] {
                    prop_assert_eq!(edited.cast_ray(r, &filter), rebuilt.cast_ray(r, &filter));
                    prop_assert_eq!(edited.cast_ray_all(r, &filter), rebuilt.cast_ray_all(r, &filter));
                }
            }
        }
    }

    #[test]
    fn an_edit_and_its_undo_restore_the_exact_state(
        s in scenario(),
        at in (0u32..10, 0u32..10),
        id in tile(),
    ) {
        let set = tile_set(s.cell);
        let original =
            TileMap::from_tiles(set, s.width, s.height, s.origin, &s.initial).unwrap();
        let cell = Cell::new(at.0 % s.width, at.1 % s.height);
        let before = original.tile(cell);
        let mut map = original.clone();
        map.set_tile(cell, id).unwrap();
        map.set_tile(cell, before).unwrap();
        assert_same_state(&map, &original)?;
    }
}

#[test]
fn building_a_map_tile_by_tile_equals_building_it_at_once() {
    let text = [
        r"#########",
        r"#..=....#",
        r"#.../\..#",
        r"#../##\.#",
        r"#########",
    ];
    let at_once = ascii::parse(&text.join("\n"), "m.txt", 1.0).unwrap();
    let mut by_tile = TileMap::new(at_once.tile_set().clone(), 9, 5, Vec2::ZERO).unwrap();
    // In an order that keeps revisiting neighbours: columns from the right, rows from the top.
    for col in (0..9).rev() {
        for row in 0..5 {
            let cell = Cell::new(col, row);
            by_tile.set_tile(cell, at_once.tile(cell)).unwrap();
        }
    }
    assert_same_state(&by_tile, &at_once).unwrap();
}

#[test]
fn digging_a_cell_out_of_a_solid_block_exposes_exactly_its_four_faces() {
    let mut m = ascii::parse("#####\n#####\n#####", "m.txt", 1.0).unwrap();
    let outline = m.active_segment_count();
    assert_eq!(outline, 16);
    m.clear_tile(Cell::new(2, 1)).unwrap();
    assert_eq!(m.active_segment_count(), outline + 4);
    assert_eq!(m.active_segments(Cell::new(2, 1)).count(), 0);
    // The four neighbours each gained the face towards the hole.
    for (col, row) in [(1, 1), (3, 1), (2, 0), (2, 2)] {
        let faces: Vec<_> = m.active_segments(Cell::new(col, row)).collect();
        assert!(
            faces.iter().any(|s| {
                let mid = (s.segment.a + s.segment.b) * 0.5;
                (mid - Vec2::new(2.5, 1.5)).length() == 0.5
            }),
            "({col}, {row}): {faces:?}"
        );
    }
    m.set_tile(Cell::new(2, 1), Some(ascii::SOLID)).unwrap();
    assert_eq!(m.active_segment_count(), outline);
}

#[test]
fn refused_edits_are_named_and_change_nothing() {
    let mut m = ascii::parse("#.\n.#", "m.txt", 1.0).unwrap();
    let before = m.clone();
    assert_eq!(
        m.set_tile(Cell::new(2, 0), Some(ascii::SOLID)),
        Err(MapError::CellOutOfBounds {
            cell: Cell::new(2, 0),
            width: 2,
            height: 2
        })
    );
    assert_eq!(
        m.clear_tile(Cell::new(0, 7)),
        Err(MapError::CellOutOfBounds {
            cell: Cell::new(0, 7),
            width: 2,
            height: 2
        })
    );
    assert_eq!(
        m.set_tile(Cell::new(1, 0), Some(TileId(99))),
        Err(MapError::UnknownTile { id: TileId(99) })
    );
    assert_same_state(&m, &before).unwrap();
}

#[test]
fn setting_the_tile_a_cell_already_has_changes_nothing() {
    let mut m = ascii::parse("#/\n=#", "m.txt", 1.0).unwrap();
    let before = m.clone();
    for row in 0..2 {
        for col in 0..2 {
            let cell = Cell::new(col, row);
            m.set_tile(cell, m.tile(cell)).unwrap();
        }
    }
    assert_same_state(&m, &before).unwrap();
}
