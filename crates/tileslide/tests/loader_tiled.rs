#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
//! Proves the Tiled loader: every path (.tmx and .tmj, embedded and external .tsx/.tsj tile
//! sets, several tile sets, finite and infinite maps, CSV and base64 with zlib or gzip,
//! groups), the shapes of collision objects with hand-computed segments and normals, the
//! flip bits (a ramp flipped every way), properties, object layers, and that every error
//! names the file and where. Fixtures: `tests/tiled/` and the examples in `examples/maps/`.
#![cfg(feature = "tiled")]

use std::path::{Path, PathBuf};

use tileslide::io::tiled::{
    self, ELLIPSE_SEGMENTS, Flip, MAX_TILE_COUNT, ObjectShape, PropertyValue, TiledMap,
    TiledOptions,
};
use tileslide::io::{LoadError, LoadErrorKind, Location, NotTiled, Unsupported};
use tileslide::{
    Cell, HitTypes, QueryFilter, Ray, SegmentFlags, TileId, TileMap, TileSegment, Vec2,
    limits::MAX_CELLS,
};

const H: u32 = Flip::HORIZONTAL_BIT;
const V: u32 = Flip::VERTICAL_BIT;
const D: u32 = Flip::DIAGONAL_BIT;

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/tiled")
        .join(name)
}

fn example(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/maps")
        .join(name)
}

fn load(path: &Path) -> TiledMap {
    tiled::load(path, &TiledOptions::default()).unwrap_or_else(|e| panic!("{e}"))
}

fn load_err(path: &Path) -> LoadError {
    match tiled::load(path, &TiledOptions::default()) {
        Ok(_) => panic!("{} loaded", path.display()),
        Err(e) => e,
    }
}

fn tmx_err(text: &str) -> LoadError {
    match tiled::parse_tmx(text, fixture("inline.tmx"), &TiledOptions::default()) {
        Ok(_) => panic!("the map loaded"),
        Err(e) => e,
    }
}

fn tmj_err(text: &str) -> LoadError {
    match tiled::parse_tmj(text, fixture("inline.tmj"), &TiledOptions::default()) {
        Ok(_) => panic!("the map loaded"),
        Err(e) => e,
    }
}

fn line_col(line: u32, column: u32) -> Location {
    Location::LineColumn { line, column }
}

/// The line:column just past the end of `text`.
fn end_of(text: &str) -> Location {
    let line = text.matches('\n').count() as u32 + 1;
    let last = text.rsplit('\n').next().unwrap_or("");
    line_col(line, last.chars().count() as u32 + 1)
}

/// A scratch file under Cargo's per-target temporary directory, beside copies of the kit.
fn scratch(name: &str, contents: &[u8]) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("loader_tiled");
    std::fs::create_dir_all(&dir).unwrap();
    // Tests run in parallel: each copy is written aside and renamed into place, so a test
    // never reads a half-written kit.
    for kit in ["kit.tsx", "kit.tsj"] {
        let aside = dir.join(format!("{kit}.{name}.part"));
        std::fs::copy(fixture(kit), &aside).unwrap();
        std::fs::rename(&aside, dir.join(kit)).unwrap();
    }
    let path = dir.join(name);
    std::fs::write(&path, contents).unwrap();
    path
}

/// Asserts two maps are the same map: size, cells, tiles, shapes and every cell's active
/// segments.
fn assert_same_map(a: &TileMap, b: &TileMap) {
    assert_eq!((a.width(), a.height()), (b.width(), b.height()));
    assert_eq!(a.origin(), b.origin());
    assert_eq!(a.cell_size(), b.cell_size());
    assert_eq!(a.tile_set(), b.tile_set(), "tile shapes differ");
    for row in 0..a.height() {
        for col in 0..a.width() {
            let cell = Cell::new(col, row);
            assert_eq!(a.tile(cell), b.tile(cell), "tile of {cell}");
            let sa: Vec<_> = a.active_segments(cell).collect();
            let sb: Vec<_> = b.active_segments(cell).collect();
            assert_eq!(sa, sb, "active segments of {cell}");
        }
    }
    assert_eq!(a.active_segment_count(), b.active_segment_count());
}

fn assert_same_tiled(a: &TiledMap, b: &TiledMap) {
    assert_same_map(&a.map, &b.map);
    assert_eq!(a.collision_layer, b.collision_layer);
    assert_eq!(a.tile_layers, b.tile_layers);
    assert_eq!(a.object_layers, b.object_layers);
    assert_eq!(a.properties, b.properties);
    for (id, _) in a.map.tile_set().iter() {
        assert_eq!(a.tile_info(id), b.tile_info(id), "tile info of {id}");
    }
}

/// A shape's segments as (a, b, normal) with a before b, sorted: order-independent.
fn outline(map: &TileMap, id: TileId) -> Vec<(Vec2, Vec2, Vec2, SegmentFlags)> {
    let shape = map
        .tile_set()
        .shape(id)
        .unwrap_or_else(|| panic!("no tile {id}"));
    let mut out: Vec<_> = shape
        .segments()
        .iter()
        .map(|s| {
            let (a, b) = if (s.a.x, s.a.y) <= (s.b.x, s.b.y) {
                (s.a, s.b)
            } else {
                (s.b, s.a)
            };
            (a, b, s.normal, s.flags)
        })
        .collect();
    out.sort_by(|x, y| format!("{x:?}").cmp(&format!("{y:?}")));
    out
}

fn solid(list: &[(Vec2, Vec2, Vec2)]) -> Vec<(Vec2, Vec2, Vec2, SegmentFlags)> {
    let mut out: Vec<_> = list
        .iter()
        .map(|&(a, b, n)| {
            let (a, b) = if (a.x, a.y) <= (b.x, b.y) {
                (a, b)
            } else {
                (b, a)
            };
            (a, b, n, SegmentFlags::SOLID)
        })
        .collect();
    out.sort_by(|x, y| format!("{x:?}").cmp(&format!("{y:?}")));
    out
}

/// Every normal of a closed shape points out of it.
fn assert_normals_point_out(map: &TileMap, id: TileId) {
    let shape = map.tile_set().shape(id).unwrap();
    for s in shape.segments() {
        let mid = (s.a + s.b) * 0.5;
        assert!(!shape.contains_point(mid + s.normal * 0.25), "{id}: {s:?}");
        assert!(shape.contains_point(mid - s.normal * 0.25), "{id}: {s:?}");
    }
}

// ------------------------------------------------------------------ both formats

#[test]
fn the_cave_in_tmx_and_tmj_is_the_same_map() {
    let tmx = load(&example("cave.tmx"));
    let tmj = load(&example("cave.tmj"));
    assert_same_tiled(&tmx, &tmj);
    assert_eq!((tmx.map.width(), tmx.map.height()), (30, 16));
    assert_eq!(tmx.map.cell_size(), Vec2::splat(16.0));
    assert_eq!(tmx.map.origin(), Vec2::ZERO);
    assert_eq!(tmx.tile_layers, ["background", "walls"]);
    assert_eq!(
        tmx.properties["title"],
        PropertyValue::String("The cave".into())
    );
    assert_eq!(tmx.properties["gravity"], PropertyValue::Float(9.8));
}

#[test]
fn external_tile_sets_given_in_memory_load_as_from_disk() {
    // A game in the browser has no disk: the map's text and its tile set's bytes.
    for (map, set) in [("cave.tmj", "tiles.tsj"), ("cave.tmx", "tiles.tsx")] {
        let text = std::fs::read_to_string(example(map)).unwrap();
        let options = TiledOptions::default().with_file(set, std::fs::read(example(set)).unwrap());
        let from_memory = if map.ends_with(".tmj") {
            tiled::parse_tmj(&text, map, &options)
        } else {
            tiled::parse_tmx(&text, map, &options)
        }
        .unwrap();
        assert_same_tiled(&from_memory, &load(&example(map)));
        // Once files are given, a file they lack is an error naming both.
        let other = TiledOptions::default().with_file("walls.tsj", b"{}".to_vec());
        let e = if map.ends_with(".tmj") {
            tiled::parse_tmj(&text, map, &other)
        } else {
            tiled::parse_tmx(&text, map, &other)
        }
        .unwrap_err();
        assert_eq!(e.io_error_kind(), Some(std::io::ErrorKind::NotFound), "{e}");
        assert!(
            e.to_string().contains(set) && e.to_string().contains("walls.tsj"),
            "{e}"
        );
    }
}

#[test]
fn the_dungeon_in_tmx_and_tmj_is_the_same_map() {
    // Infinite, chunks in base64+zlib (.tmx) and base64+gzip (.tmj), an external tile set
    // and an embedded one, the layers inside a group.
    let tmx = load(&example("dungeon.tmx"));
    let tmj = load(&example("dungeon.tmj"));
    assert_same_tiled(&tmx, &tmj);
    assert_eq!(tmx.tile_layers, ["floor", "walls"]);
    assert_eq!(tmx.collision_layer, "walls");
}

#[test]
fn flips_in_tmx_tmj_and_tmj_with_a_tsx_tile_set_are_the_same_map() {
    let tmx = load(&fixture("flips.tmx"));
    let tmj = load(&fixture("flips.tmj"));
    let mixed = load(&fixture("flips_tsx.tmj"));
    assert_same_tiled(&tmx, &tmj);
    assert_same_tiled(&tmx, &mixed);
}

// ------------------------------------------------------------------ grids

#[test]
fn an_infinite_map_covers_its_chunks_and_keeps_tileds_pixels() {
    let dungeon = load(&example("dungeon.tmx"));
    let map = &dungeon.map;
    // Chunks from Tiled cell (-16, -16) to (32, 16): 48 × 32 cells, origin at the top-left
    // chunk's corner in pixels.
    assert_eq!((map.width(), map.height()), (48, 32));
    assert_eq!(map.origin(), v(-256.0, -256.0));
    // Tiled cell (-16, -16) is the top-left wall: map cell (0, 0), at pixel (-256, -256).
    assert_eq!(map.tile(Cell::new(0, 0)), Some(TileId(1)));
    assert!(map.is_point_solid(v(-250.0, -250.0)));
    assert!(!map.is_point_solid(v(-230.0, -230.0)));
    // The door in the middle wall (Tiled cell (16, -11)) is the embedded tile set's tile 0,
    // gid 9; the rotated ones are gid 9 with D+H.
    assert_eq!(map.tile(Cell::new(32, 5)), Some(TileId(9)));
    let door = dungeon.tile_info(TileId(9)).unwrap();
    assert_eq!((door.tile_set.as_str(), door.local_id), ("doors", 0));
    assert_eq!(map.tile(Cell::new(24, 3)), Some(TileId(9 | D | H)));
    // A vertical door: a 4-pixel slab across the cell at x = 6..10 of its cell, flag1 set.
    // Cell (32, 5) spans x = 256..272, y = -176..-160 in pixels.
    let ray = Ray::between(v(200.0, -168.0), v(300.0, -168.0));
    let hit = map.cast_ray(ray, &QueryFilter::default()).unwrap();
    assert_eq!(hit.tile(), Some(TileId(9)));
    assert_eq!((hit.point, hit.normal), (v(262.0, -168.0), v(-1.0, 0.0)));
    assert_eq!(
        hit.flags,
        SegmentFlags::SOLID | SegmentFlags::user(1).unwrap()
    );
}

#[test]
fn the_collision_layer_is_named_or_flagged_or_the_first() {
    // `walls` has collision = true; `background` comes first.
    let cave = load(&example("cave.tmx"));
    assert_eq!(cave.collision_layer, "walls");
    let back = tiled::load(
        example("cave.tmx"),
        &TiledOptions::default().with_layer("background"),
    )
    .unwrap();
    assert_eq!(back.collision_layer, "background");
    // Moss only: tiles are placed but have no segments.
    assert_eq!(back.map.tile(Cell::new(3, 2)), Some(TileId(7)));
    assert_eq!(back.map.placed_segment_count(), 0);
    // Without the property, the first tile layer.
    let flips = load(&fixture("flips.tmx"));
    assert_eq!(flips.collision_layer, "tiles");
    // An unknown name lists the layers.
    let e = tiled::load(
        example("cave.tmj"),
        &TiledOptions::default().with_layer("lava"),
    )
    .unwrap_err();
    assert_eq!(
        e.to_string(),
        format!(
            "{}: the map has no tile layer named \"lava\" (its tile layers: \"background\", \"walls\")",
            example("cave.tmj").display()
        )
    );
}

#[test]
fn layers_that_share_a_name_are_chosen_by_number() {
    // Two tile layers named "l" (the ramp at cell 0, then the half block at cell 1), a
    // third named "a#1" (a name that looks like a choice), and a fourth.
    let text = r#"<map version="1.10" orientation="orthogonal" width="2" height="1" tilewidth="16" tileheight="16">
 <tileset firstgid="1" source="kit.tsx"/>
 <layer name="l" width="2" height="1"><data encoding="csv">1,0</data></layer>
 <layer name="l" width="2" height="1"><data encoding="csv">0,2</data></layer>
 <layer name="a#1" width="2" height="1"><data encoding="csv">2,2</data></layer>
 <layer name="a" width="2" height="1"><data encoding="csv">1,1</data></layer>
</map>"#;
    let path = scratch("same_names.tmx", text.as_bytes());
    let with = |layer: &str| tiled::load(&path, &TiledOptions::default().with_layer(layer));
    let tiles = |layer: &str| {
        let m = with(layer).unwrap_or_else(|e| panic!("{layer}: {e}"));
        (
            m.collision_layer_index,
            m.map.tile(Cell::new(0, 0)),
            m.map.tile(Cell::new(1, 0)),
        )
    };
    assert_eq!(tiles("l"), (0, Some(TileId(1)), None));
    assert_eq!(tiles("l#1"), (0, Some(TileId(1)), None));
    assert_eq!(tiles("l#2"), (1, None, Some(TileId(2))));
    // A name that exists is that layer, even if it looks like a choice.
    assert_eq!(tiles("a#1"), (2, Some(TileId(2)), Some(TileId(2))));
    // `#N` alone: the N-th tile layer of the file.
    assert_eq!(tiles("#4"), (3, Some(TileId(1)), Some(TileId(1))));
    let message = |layer: &str| match with(layer) {
        Ok(_) => panic!("{layer} loaded"),
        Err(e) => e.to_string(),
    };
    assert_eq!(
        message("l#3"),
        format!(
            "{}: the map has 2 tile layers named \"l\", so no \"l#3\" (its tile layers: \"l\", \"l#2\", \"a#1\", \"a\")",
            path.display()
        )
    );
    assert!(message("#5").contains("the map has 4 tile layers, so no \"#5\""));
    assert!(message("l#0").contains("no tile layer named \"l#0\""));
    // A program offering the player another layer gets the request and every layer's name.
    let Err(e) = with("lava") else {
        panic!("lava loaded");
    };
    let LoadErrorKind::UnknownLayer { requested, layers } = &e.kind else {
        panic!("not an unknown layer: {e}");
    };
    assert_eq!(requested, "lava");
    assert_eq!(layers, &["l", "l", "a#1", "a"]);
}

/// A one-layer `.tmj` map of `cells` (a CSV of gids, one row) on a `grid`-pixel grid, with
/// one embedded tile set of `tile`-pixel tiles whose tile 0 has the collision `objects` (a
/// JSON list).
fn one_tile_map(grid: (u32, u32), tile: (u32, u32), objects: &str, cells: &str) -> String {
    let width = cells.split(',').count();
    format!(
        r#"{{"type": "map", "orientation": "orthogonal", "width": {width}, "height": 1,
  "tilewidth": {}, "tileheight": {},
  "tilesets": [{{"firstgid": 1, "name": "big", "tilewidth": {}, "tileheight": {},
    "tilecount": 1, "tiles": [{{"id": 0, "objectgroup": {{"objects": {objects}}}}}]}}],
  "layers": [{{"type": "tilelayer", "name": "l", "width": {width}, "height": 1,
    "data": [{cells}]}}]}}"#,
        grid.0, grid.1, tile.0, tile.1
    )
}

fn parse_one_tile_map(text: &str) -> Result<TiledMap, LoadError> {
    tiled::parse_tmj(text, fixture("inline.tmj"), &TiledOptions::default())
}

#[test]
fn a_collision_vertex_just_outside_its_tile_snaps_onto_the_edge() {
    // A real map's hand-drawn triangle on a 128-pixel tile: one vertex 0.4 px past the right
    // edge. It loads, with the vertex on the edge.
    let triangle = |x: f32| {
        format!(
            r#"[{{"id": 3, "x": 0, "y": 0, "polygon": [{{"x": 0, "y": 0}}, {{"x": {x}, "y": 0}},
                {{"x": 0, "y": 128}}]}}]"#
        )
    };
    let map = parse_one_tile_map(&one_tile_map(
        (128, 128),
        (128, 128),
        &triangle(128.39629),
        "1",
    ))
    .unwrap_or_else(|e| panic!("{e}"));
    let mut ends: Vec<Vec2> = map
        .map
        .tile_set()
        .shape(TileId(1))
        .unwrap()
        .segments()
        .iter()
        .map(|s| s.a)
        .collect();
    ends.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    assert_eq!(ends, [v(0.0, 0.0), v(0.0, 128.0), v(128.0, 0.0)]);
    // A ray across the tile meets the slope where it is drawn.
    let ray = Ray::between(v(120.0, 64.0), v(0.0, 64.0));
    let hit = map.map.cast_ray(ray, &QueryFilter::default()).unwrap();
    assert_eq!(hit.point, v(64.0, 64.0));
    // Up to 2 px (1/64 of 128) snaps; past it the map is refused, naming layer, cell, tile.
    assert!(
        parse_one_tile_map(&one_tile_map(
            (128, 128),
            (128, 128),
            &triangle(129.99),
            "1"
        ))
        .is_ok()
    );
    let e = parse_one_tile_map(&one_tile_map(
        (128, 128),
        (128, 128),
        &triangle(130.25),
        "1",
    ))
    .unwrap_err();
    assert_eq!(
        e.to_string(),
        format!(
            "{}: layer \"l\": cell (0, 0), gid 0x1: tile set \"big\", tile 0: collision \
             object 3: it reaches (130.25, 0), 2.25 px outside the tile's 128×128 pixels; only \
             vertices within 2 px of the edge are moved onto it",
            fixture("inline.tmj").display()
        )
    );
    // On 16-pixel tiles the tolerance is one pixel: 0.9 px out snaps, 1.1 px is refused.
    let rect = |x: f32| format!(r#"[{{"id": 1, "x": {x}, "y": 0, "width": 16, "height": 8}}]"#);
    let snapped = parse_one_tile_map(&one_tile_map((16, 16), (16, 16), &rect(-0.9), "1")).unwrap();
    let shape = snapped.map.tile_set().shape(TileId(1)).unwrap();
    assert!(
        shape
            .segments()
            .iter()
            .all(|s| s.a.x >= 0.0 && s.a.x <= 16.0)
    );
    // Only the vertex outside moved: the box now starts at the edge and still ends at 15.1.
    let solid_at = |x: f32| snapped.map.is_point_solid(v(x, 4.0));
    assert!(solid_at(0.05) && solid_at(15.0) && !solid_at(15.2));
    let e = parse_one_tile_map(&one_tile_map((16, 16), (16, 16), &rect(-1.1), "1")).unwrap_err();
    assert!(
        e.to_string()
            .contains("it reaches (-1.1, 0), 1.1 px outside the tile's 16×16 pixels"),
        "{e}"
    );
}

#[test]
fn tiles_of_another_size_than_the_grid_are_placed_from_their_cells_bottom_left() {
    // A 160 × 160 decoration on a 16-pixel grid, without collision: placed, blocking nothing.
    let map = parse_one_tile_map(&one_tile_map((16, 16), (160, 160), "[]", "0,1"))
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(map.map.tile(Cell::new(1, 0)), Some(TileId(1)));
    assert_eq!(map.map.placed_segment_count(), 0);
    // Flips do not matter to a tile without collision, even D on a tile that is not square.
    let tall = one_tile_map((16, 16), (16, 48), "[]", &format!("{},{}", 1 | D, 1 | H));
    assert!(parse_one_tile_map(&tall).is_ok());
    // A 32 × 32 tile whose collision is its bottom-left 16 × 16 quarter (Tiled draws it from
    // the cell's bottom-left corner, so that quarter covers the cell).
    let quarter = r#"[{"id": 1, "x": 0, "y": 16, "width": 16, "height": 16}]"#;
    let map = parse_one_tile_map(&one_tile_map((16, 16), (32, 32), quarter, "1")).unwrap();
    assert!(map.map.is_point_solid(v(8.0, 8.0)));
    assert_eq!(
        outline(&map.map, TileId(1)),
        solid(&[
            (v(0.0, 0.0), v(16.0, 0.0), v(0.0, -1.0)),
            (v(16.0, 0.0), v(16.0, 16.0), v(1.0, 0.0)),
            (v(16.0, 16.0), v(0.0, 16.0), v(0.0, 1.0)),
            (v(0.0, 16.0), v(0.0, 0.0), v(-1.0, 0.0)),
        ])
    );
    // Flipped horizontally, the quarter is the tile's bottom-right: outside its cell.
    let e = parse_one_tile_map(&one_tile_map(
        (16, 16),
        (32, 32),
        quarter,
        &(1 | H).to_string(),
    ))
    .unwrap_err();
    assert!(
        e.to_string().contains(
            "layer \"l\": cell (0, 0), gid 0x80000001: tile set \"big\", tile 0: collision \
             object 1: it reaches (0, 16), 16 px outside the 16×16 grid cell its 32×32 tile is \
             placed in (from the cell's bottom-left corner)"
        ),
        "{e}"
    );
    // An 8 × 8 tile sits in its cell's bottom-left quarter.
    let full = r#"[{"id": 1, "x": 0, "y": 0, "width": 8, "height": 8}]"#;
    let map = parse_one_tile_map(&one_tile_map((16, 16), (8, 8), full, "1")).unwrap();
    assert!(map.map.is_point_solid(v(4.0, 12.0)) && !map.map.is_point_solid(v(4.0, 4.0)));
    // D on a tile that is not square and has collision is refused, naming where.
    let e = parse_one_tile_map(&one_tile_map(
        (16, 16),
        (16, 32),
        quarter,
        &(1 | D).to_string(),
    ))
    .unwrap_err();
    assert!(e.to_string().contains("cell (0, 0), gid 0x20000001: tile set \"big\", tile 0: its tile is 16×32 and has collision objects, so it cannot be flipped diagonally"), "{e}");
}

// ------------------------------------------------------------------ shapes

#[test]
fn the_caves_tiles_have_hand_computed_segments() {
    let cave = load(&example("cave.tmx"));
    let map = &cave.map;
    let (n, e, s, w) = (v(0.0, -1.0), v(1.0, 0.0), v(0.0, 1.0), v(-1.0, 0.0));
    // gid 1, the block: the tile's square.
    assert_eq!(
        outline(map, TileId(1)),
        solid(&[
            (v(0.0, 0.0), v(16.0, 0.0), n),
            (v(16.0, 0.0), v(16.0, 16.0), e),
            (v(0.0, 16.0), v(16.0, 16.0), s),
            (v(0.0, 0.0), v(0.0, 16.0), w),
        ])
    );
    // gid 3, the ledge: a 16×4 box with one_way on the tile keeps only its top, one-way.
    assert_eq!(
        outline(map, TileId(3)),
        [(v(0.0, 0.0), v(16.0, 0.0), n, SegmentFlags::ONE_WAY)]
    );
    // In the world: the ledge at cells (14..18, 4) is at y = 64, facing up.
    let ledge: Vec<_> = map.active_segments(Cell::new(14, 4)).collect();
    assert_eq!(ledge.len(), 1);
    assert_eq!(ledge[0].normal, n);
    assert_eq!(ledge[0].segment.a.y, 64.0);
    assert_eq!(ledge[0].flags, SegmentFlags::ONE_WAY);
    // gid 4, the half block: the bottom half.
    assert_eq!(
        outline(map, TileId(4)),
        solid(&[
            (v(0.0, 8.0), v(16.0, 8.0), n),
            (v(16.0, 8.0), v(16.0, 16.0), e),
            (v(0.0, 16.0), v(16.0, 16.0), s),
            (v(0.0, 8.0), v(0.0, 16.0), w),
        ])
    );
    // gid 5, spikes: a zigzag polygon with user bit 0, and DEATH as the tile's hit type.
    let spikes = map.tile_set().shape(TileId(5)).unwrap();
    assert_eq!(spikes.segments().len(), 5);
    let hazard = SegmentFlags::SOLID | SegmentFlags::user(0).unwrap();
    assert!(spikes.segments().iter().all(|s| s.flags == hazard));
    let info = cave.tile_info(TileId(5)).unwrap();
    assert_eq!(info.hit_types, HitTypes::DEATH);
    assert_eq!(info.class, "hazard");
    assert_eq!(
        info.properties["name"],
        PropertyValue::String("spikes".into())
    );
    assert_normals_point_out(map, TileId(5));
    // gid 6, the boulder: an ellipse of ELLIPSE_SEGMENTS corners on the inscribed circle.
    let boulder = map.tile_set().shape(TileId(6)).unwrap();
    assert_eq!(boulder.segments().len(), ELLIPSE_SEGMENTS);
    assert_eq!(boulder.segments()[0].a, v(16.0, 8.0));
    for seg in boulder.segments() {
        assert!((seg.a.distance(v(8.0, 8.0)) - 8.0).abs() < 1e-4);
    }
    assert_normals_point_out(map, TileId(6));
    // gid 8, the fence: a polyline down the middle is two solid segments back to back.
    assert_eq!(
        outline(map, TileId(8)),
        solid(&[
            (v(8.0, 0.0), v(8.0, 16.0), e),
            (v(8.0, 0.0), v(8.0, 16.0), w),
        ])
    );
}

#[test]
fn the_kits_shapes_have_hand_computed_segments() {
    let kit = load(&fixture("flips.tmx"));
    let map = &kit.map;
    // gid 3: a one-way roof polyline (0,8)-(8,4)-(16,8): both edges face up.
    let roof = map.tile_set().shape(TileId(3)).unwrap().segments().to_vec();
    let k = 1.0 / 5f32.sqrt();
    assert_eq!(roof.len(), 2);
    assert_eq!((roof[0].a, roof[0].b), (v(0.0, 8.0), v(8.0, 4.0)));
    assert!(roof[0].normal.distance(v(-k, -2.0 * k)) < 1e-6);
    assert_eq!((roof[1].a, roof[1].b), (v(8.0, 4.0), v(16.0, 8.0)));
    assert!(roof[1].normal.distance(v(k, -2.0 * k)) < 1e-6);
    assert!(roof.iter().all(|s| s.flags == SegmentFlags::ONE_WAY));
    // gid 4: a one-way wall facing left (one_way_side on the tile).
    assert_eq!(
        map.tile_set().shape(TileId(4)).unwrap().segments(),
        [TileSegment::new(
            v(4.0, 0.0),
            v(4.0, 16.0),
            v(-1.0, 0.0),
            SegmentFlags::ONE_WAY
        )]
    );
    // gid 5: an 8×4 box at (8,0) turned 90° clockwise about its corner: (4,0)-(8,8).
    let (n, e, s, w) = (v(0.0, -1.0), v(1.0, 0.0), v(0.0, 1.0), v(-1.0, 0.0));
    assert_eq!(
        outline(map, TileId(5)),
        solid(&[
            (v(4.0, 0.0), v(8.0, 0.0), n),
            (v(8.0, 0.0), v(8.0, 8.0), e),
            (v(4.0, 8.0), v(8.0, 8.0), s),
            (v(4.0, 0.0), v(4.0, 8.0), w),
        ])
    );
    // gid 6: a 16×8 capsule at (0,4): two half circles of ELLIPSE_SEGMENTS / 2 segments
    // and two straight sides, all inside its box.
    let capsule = map.tile_set().shape(TileId(6)).unwrap();
    assert_eq!(capsule.segments().len(), ELLIPSE_SEGMENTS + 2);
    assert!(capsule.contains_point(v(8.0, 8.0)) && !capsule.contains_point(v(8.0, 2.0)));
    assert_normals_point_out(map, TileId(6));
    // gid 7: user bits from the tile (flag2, flag5), the right object turning flag5 off.
    let crate_tile = map.tile_set().shape(TileId(7)).unwrap();
    let (u2, u5) = (
        SegmentFlags::user(2).unwrap(),
        SegmentFlags::user(5).unwrap(),
    );
    let left = &crate_tile.segments()[..4];
    let right = &crate_tile.segments()[4..];
    assert!(
        left.iter()
            .all(|s| s.flags == SegmentFlags::SOLID | u2 | u5)
    );
    assert!(right.iter().all(|s| s.flags == SegmentFlags::SOLID | u2));
    assert_eq!(kit.tile_info(TileId(7)).unwrap().class, "crate");
    // gid 8: no segments, but its properties and hit types.
    let coin = kit.tile_info(TileId(8)).unwrap();
    assert!(
        map.tile_set()
            .shape(TileId(8))
            .unwrap()
            .segments()
            .is_empty()
    );
    assert_eq!(coin.hit_types, HitTypes::COLLECT);
    assert_eq!(coin.properties["value"], PropertyValue::Int(5));
}

#[test]
fn a_ramp_flipped_every_way() {
    // The ramp: solid below the diagonal from (16,0) to (0,16); its slope faces up-left.
    //
    //   none        H           V           H+V
    //   . . /|      |\ . .      |‾‾‾‾/      \‾‾‾‾|
    //   . / #|      |# \ .      |# /          \ #|
    //   /####|      |####\      |/              \|
    //
    // The diagonal flip swaps x and y, which leaves this triangle as it is, so D, D+H (90°
    // clockwise), D+V (90° anticlockwise) and D+H+V give the four outlines again.
    let flips = load(&fixture("flips.tmx"));
    let map = &flips.map;
    let k = std::f32::consts::FRAC_1_SQRT_2;
    let (n, e, s, w) = (v(0.0, -1.0), v(1.0, 0.0), v(0.0, 1.0), v(-1.0, 0.0));
    let (tl, tr, bl, br) = (v(0.0, 0.0), v(16.0, 0.0), v(0.0, 16.0), v(16.0, 16.0));
    let plain = solid(&[(bl, br, s), (tr, br, e), (bl, tr, v(-k, -k))]);
    let h = solid(&[(bl, br, s), (tl, bl, w), (tl, br, v(k, -k))]);
    let vert = solid(&[(tl, tr, n), (tr, br, e), (tl, br, v(-k, k))]);
    let hv = solid(&[(tl, tr, n), (tl, bl, w), (bl, tr, v(k, k))]);
    for (col, bits, want) in [
        (0, 0, &plain),
        (1, H, &h),
        (2, V, &vert),
        (3, H | V, &hv),
        (4, D, &plain),
        (5, D | H, &h),
        (6, D | V, &vert),
        (7, D | H | V, &hv),
    ] {
        let id = TileId(1 | bits);
        assert_eq!(map.tile(Cell::new(col, 0)), Some(id), "column {col}");
        assert_eq!(&outline(map, id), want, "ramp with bits {bits:#x}");
        assert_normals_point_out(map, id);
        let info = flips.tile_info(id).unwrap();
        assert_eq!((info.local_id, info.flip), (0, Flip::from_gid(bits)));
    }
    // A shape the diagonal flip does change: the bottom half block.
    //   none: bottom half; D: right half; D+H (90° cw): left half; D+V (90° ccw): right half.
    let half = |x0: f32, y0: f32, x1: f32, y1: f32| {
        solid(&[
            (v(x0, y0), v(x1, y0), n),
            (v(x1, y0), v(x1, y1), e),
            (v(x0, y1), v(x1, y1), s),
            (v(x0, y0), v(x0, y1), w),
        ])
    };
    assert_eq!(outline(map, TileId(2)), half(0.0, 8.0, 16.0, 16.0));
    assert_eq!(outline(map, TileId(2 | D)), half(8.0, 0.0, 16.0, 16.0));
    assert_eq!(outline(map, TileId(2 | D | H)), half(0.0, 0.0, 8.0, 16.0));
    assert_eq!(outline(map, TileId(2 | D | V)), half(8.0, 0.0, 16.0, 16.0));
}

#[test]
fn a_ray_meets_a_flipped_ramps_slope_from_its_open_side_only() {
    let flips = load(&fixture("flips.tmx"));
    // Cell (1, 0): the ramp flipped H, its slope from (16,0) to (32,16) facing up-right.
    let down = Ray::between(v(28.0, -10.0), v(28.0, 30.0));
    let hit = flips.map.cast_ray(down, &QueryFilter::default()).unwrap();
    assert_eq!(hit.point, v(28.0, 12.0));
    let k = std::f32::consts::FRAC_1_SQRT_2;
    assert!(hit.normal.distance(v(k, -k)) < 1e-6);
}

// ------------------------------------------------------------------ objects

#[test]
fn object_layers_come_with_shapes_properties_and_hit_types() {
    let cave = load(&example("cave.tmx"));
    let spawns = cave.object_layer("spawns").unwrap();
    let player = spawns.object("player").unwrap();
    assert_eq!((player.id, player.class.as_str()), (1, "spawn"));
    assert_eq!(
        (player.position, &player.shape),
        (v(40.0, 200.0), &ObjectShape::Point)
    );
    assert_eq!(spawns.object("bat").unwrap().hit_types, HitTypes::HIT);
    let boulder = spawns.object("boulder").unwrap();
    assert_eq!(boulder.gid, Some(6));
    assert_eq!(
        (boulder.position, boulder.size),
        (v(304.0, 224.0), v(16.0, 16.0))
    );
    let regions = cave.object_layer("regions").unwrap();
    let exit = regions.object("exit").unwrap();
    assert_eq!(
        (exit.shape.clone(), exit.size),
        (ObjectShape::Rectangle, v(16.0, 48.0))
    );
    assert_eq!(
        exit.properties["target"],
        PropertyValue::String("dungeon.tmx".into())
    );
    assert_eq!(regions.object("pool").unwrap().shape, ObjectShape::Ellipse);
    let danger = regions.object("danger").unwrap();
    assert_eq!(danger.hit_types, HitTypes::DEATH | HitTypes::HIT);
    assert_eq!(
        danger.shape,
        ObjectShape::Polygon(vec![
            v(0.0, 0.0),
            v(32.0, 0.0),
            v(40.0, 24.0),
            v(-8.0, 24.0)
        ])
    );
    assert!(matches!(
        &regions.object("bat_path").unwrap().shape,
        ObjectShape::Polyline(p) if p.len() == 3
    ));
    // The dungeon's: a tile object of the embedded tile set keeps its gid.
    let dungeon = load(&example("dungeon.tmj"));
    let actors = dungeon.object_layer("actors").unwrap();
    assert_eq!(actors.object("chest").unwrap().gid, Some(10));
    assert_eq!(actors.object("chest").unwrap().hit_types, HitTypes::COLLECT);
    assert_eq!(
        actors.object("ghost").unwrap().hit_types,
        HitTypes::HIT | HitTypes::POSSESS
    );
    assert_eq!(
        actors.object("skeleton").unwrap().properties["speed"],
        PropertyValue::Float(1.5)
    );
}

// ------------------------------------------------------------------ queries on the cave

#[test]
fn rays_and_circles_behave_in_the_example_cave() {
    let cave = load(&example("cave.tmj"));
    let map = &cave.map;
    let filter = QueryFilter::default();
    // Down onto the one-way ledge (cells 14..18, row 4): stops on its top at y = 64.
    let hit = map
        .cast_ray(Ray::between(v(232.0, 20.0), v(232.0, 200.0)), &filter)
        .unwrap();
    assert_eq!((hit.point.y, hit.normal), (64.0, v(0.0, -1.0)));
    assert!(hit.flags.contains(SegmentFlags::ONE_WAY));
    // Up through it from below: the ledge does not block; the ceiling does, at y = 16.
    let hit = map
        .cast_ray(Ray::between(v(232.0, 100.0), v(232.0, 0.0)), &filter)
        .unwrap();
    assert_eq!((hit.point.y, hit.normal), (16.0, v(0.0, 1.0)));
    // Down onto the hill's left ramp at (11, 12): its slope faces up-left.
    let hit = map
        .cast_ray(Ray::between(v(184.0, 150.0), v(184.0, 230.0)), &filter)
        .unwrap();
    assert_eq!(hit.point, v(184.0, 200.0));
    assert!(hit.normal.x < 0.0 && hit.normal.y < 0.0);
    // Across the fence at x = 120 (rows 6-8), from either side.
    for (from, to, x) in [(60.0, 200.0, 120.0), (200.0, 60.0, 120.0)] {
        let hit = map
            .cast_ray(Ray::between(v(from, 120.0), v(to, 120.0)), &filter)
            .unwrap();
        assert_eq!(hit.point.x, x);
    }
    // A circle of radius 6 dropped at x = 40 lands on the floor (y = 224) at y = 218.
    let hit = map
        .cast_circle(v(40.0, 40.0), 6.0, v(0.0, 300.0), &filter)
        .unwrap()
        .unwrap();
    assert!((hit.center.y - 218.0).abs() < 1e-3, "{hit:?}");
    // Points: inside the floor and a block, not in the air.
    assert!(map.is_point_solid(v(100.0, 230.0)));
    assert!(!map.is_point_solid(v(100.0, 100.0)));
}

// ------------------------------------------------------------------ encodings

const TWO_CELLS: &str = r#"<map version="1.10" orientation="orthogonal" width="2" height="1" tilewidth="16" tileheight="16">
 <tileset firstgid="1" source="kit.tsx"/>
 <layer name="l" width="2" height="1">
  DATA
 </layer>
</map>"#;

fn two_cells(data: &str) -> String {
    TWO_CELLS.replace("DATA", data)
}

#[test]
fn base64_layers_plain_zlib_and_gzip_decode_alike() {
    // gids [2, 0x80000001]: the half block, and the ramp flipped H.
    let datas = [
        r#"<data encoding="csv">2,2147483649</data>"#,
        r#"<data encoding="base64">AgAAAAEAAIA=</data>"#,
        r#"<data encoding="base64" compression="zlib">eJxjYmBgYGRgaAAAAJwAhA==</data>"#,
        r#"<data encoding="base64" compression="gzip">H4sIAAAAAAACA2NiYGBgZGBoAABRPANyCAAAAA==</data>"#,
    ];
    let path = scratch("encodings.tmx", b"");
    for data in datas {
        let map = tiled::parse_tmx(&two_cells(data), &path, &TiledOptions::default())
            .unwrap_or_else(|e| panic!("{data}: {e}"));
        assert_eq!(map.map.tile(Cell::new(0, 0)), Some(TileId(2)), "{data}");
        assert_eq!(map.map.tile(Cell::new(1, 0)), Some(TileId(1 | H)), "{data}");
    }
}

#[cfg(not(feature = "tiled-zstd"))]
#[test]
fn zstd_without_its_feature_is_a_clear_error() {
    let path = scratch("zstd.tmx", b"");
    let text = two_cells(r#"<data encoding="base64" compression="zstd">AAAA</data>"#);
    let e = tiled::parse_tmx(&text, &path, &TiledOptions::default()).unwrap_err();
    assert_eq!(e.location, line_col(4, 3));
    assert!(e.to_string().contains("`tiled-zstd` cargo feature"), "{e}");
}

// ------------------------------------------------------------------ errors

#[test]
fn truncated_xml_names_the_end_and_the_open_element() {
    let text = std::fs::read_to_string(example("cave.tmx")).unwrap();
    let cut = &text[..text.find("<objectgroup").unwrap() + 40];
    let e = tmx_err(cut);
    assert_eq!(e.location, end_of(cut));
    assert!(
        e.to_string().contains("truncated") || e.to_string().contains("malformed"),
        "{e}"
    );
    // Cut between elements: the open element is named with where it was opened.
    let cut = &text[..text.find("</layer>").unwrap()];
    let e = tmx_err(cut);
    assert_eq!(e.location, end_of(cut));
    assert!(
        e.to_string()
            .contains("the file ends inside <layer> (opened at 8:2): truncated XML"),
        "{e}"
    );
    // A program can tell a file cut short (still being written, say) from a broken one.
    assert!(
        matches!(
            e.kind,
            LoadErrorKind::Syntax {
                format: "XML",
                truncated: true,
                ..
            }
        ),
        "{e}"
    );
    assert!(
        e.to_string()
            .starts_with(&format!("{}:", fixture("inline.tmx").display()))
    );
}

#[test]
fn malformed_xml_is_named_at_its_line_and_column() {
    let e = tmx_err(&two_cells(r#"<data encoding="csv">1,2</date>"#));
    assert!(
        matches!(e.location, Location::LineColumn { line: 4, .. }),
        "{e}"
    );
    assert!(e.to_string().contains("malformed XML"), "{e}");
    // quick-xml's own error is the source.
    assert!(
        matches!(
            e.kind,
            LoadErrorKind::Syntax {
                format: "XML",
                truncated: false,
                ..
            }
        ),
        "{e}"
    );
    assert!(std::error::Error::source(&e).is_some(), "{e}");
}

#[test]
fn truncated_and_malformed_json_name_line_and_column() {
    let text = std::fs::read_to_string(example("cave.tmj")).unwrap();
    let cut = &text[..text.len() / 2];
    let e = tmj_err(cut);
    assert_eq!(e.location, end_of(cut));
    assert!(e.to_string().contains("truncated JSON"), "{e}");
    let e = tmj_err("{\n  \"orientation\": \"orthogonal\",\n  \"tilewidth\": 16 16\n}");
    assert_eq!(e.location, line_col(3, 19));
    assert!(e.to_string().contains("malformed JSON"), "{e}");
    let source = std::error::Error::source(&e).expect("serde_json's error is the source");
    assert!(source.is::<serde_json::Error>(), "{source}");
    // A value of the wrong type is named with the field and position.
    let e = tmj_err("{\"orientation\": \"orthogonal\", \"tilewidth\": \"16\", \"tileheight\": 16}");
    assert!(
        e.to_string().contains("tilewidth") || e.to_string().contains("u32"),
        "{e}"
    );
}

#[test]
fn a_missing_external_tile_set_is_named_with_its_path() {
    let text = two_cells(r#"<data encoding="csv">1,1</data>"#).replace("kit.tsx", "missing.tsx");
    let e = tmx_err(&text);
    let missing = fixture("missing.tsx");
    assert_eq!(e.path, fixture("inline.tmx"));
    assert_eq!(e.location, line_col(2, 2));
    // The map names it at its <tileset>; the error keeps the file and the I/O error's kind.
    let LoadErrorKind::Io {
        referenced: Some(file),
        source,
    } = &e.kind
    else {
        panic!("not an I/O error about another file: {e}");
    };
    assert_eq!(
        (file, source.kind()),
        (&missing, std::io::ErrorKind::NotFound)
    );
    assert_eq!(e.io_error_kind(), Some(std::io::ErrorKind::NotFound));
    assert!(
        e.to_string().contains(&format!(
            "cannot read the external file {}",
            missing.display()
        )),
        "{e}"
    );
    let tmj = std::fs::read_to_string(fixture("flips.tmj"))
        .unwrap()
        .replace("kit.tsj", "missing.tsj");
    let e = tmj_err(&tmj);
    assert!(
        matches!(&e.kind, LoadErrorKind::Io { referenced: Some(file), .. }
            if *file == fixture("missing.tsj")),
        "{e}"
    );
    assert_eq!(e.path, fixture("inline.tmj"));
    // A .tsx named by a .tmj: the same message.
    let e = tmj_err(&tmj.replace("missing.tsj", "missing.tsx"));
    assert!(e.to_string().contains("missing.tsx"), "{e}");
}

#[test]
fn a_broken_external_tile_set_is_named_at_its_own_line() {
    let kit = std::fs::read_to_string(fixture("kit.tsx")).unwrap();
    let cut = &kit[..kit.find("<tile id=\"3\"").unwrap()];
    let tsx = scratch("broken.tsx", cut.as_bytes());
    let map = two_cells(r#"<data encoding="csv">1,1</data>"#).replace("kit.tsx", "broken.tsx");
    let path = scratch("uses_broken.tmx", map.as_bytes());
    let e = load_err(&path);
    assert_eq!(e.path, tsx);
    assert_eq!(e.location, end_of(cut));
    assert!(e.to_string().contains("truncated XML"), "{e}");
    // An absurd tilecount is refused before the tiled crate reserves room for it.
    let huge = kit.replace("tilecount=\"8\"", "tilecount=\"4000000000\"");
    scratch("huge.tsx", huge.as_bytes());
    let map = two_cells(r#"<data encoding="csv">1,1</data>"#).replace("kit.tsx", "huge.tsx");
    let e = load_err(&scratch("uses_huge.tmx", map.as_bytes()));
    assert!(
        matches!(
            e.kind,
            LoadErrorKind::BadSize {
                field: "tilecount",
                value: 4_000_000_000,
                ..
            }
        ),
        "{e}"
    );
    assert_eq!(e.location, line_col(3, 1));
    assert!(
        e.to_string()
            .contains(&format!("more than {MAX_TILE_COUNT} tiles"))
    );
}

#[test]
fn an_unknown_encoding_is_named_at_its_data_element() {
    let e = tmx_err(&two_cells(r#"<data encoding="base32">AAAA</data>"#));
    assert_eq!(e.location, line_col(4, 3));
    assert!(
        e.to_string()
            .contains("unknown tile data encoding: encoding \"base32\""),
        "{e}"
    );
    let e = tmx_err(&two_cells(
        r#"<data encoding="base64" compression="lzma">AAAA</data>"#,
    ));
    assert!(e.to_string().contains("compression \"lzma\""), "{e}");
    // The deprecated XML <tile> elements.
    let e = tmx_err(&two_cells(r#"<data><tile gid="1"/><tile gid="1"/></data>"#));
    assert!(e.to_string().contains("XML <tile> elements"), "{e}");
    let tmj = std::fs::read_to_string(fixture("flips.tmj")).unwrap();
    let tmj = tmj.replace(
        "\"type\": \"tilelayer\",",
        "\"type\": \"tilelayer\", \"encoding\": \"base64\", \"compression\": \"lzma\",",
    );
    let tmj = tmj.replacen("\"data\": [", "\"data\": \"AAAA\", \"unused\": [", 1);
    let e = tmj_err(&tmj);
    assert!(
        e.to_string()
            .contains("layers[0] (\"tiles\"): unknown tile data encoding"),
        "{e}"
    );
    let LoadErrorKind::Unsupported(Unsupported::Encoding {
        layer, compression, ..
    }) = &e.kind
    else {
        panic!("not an unsupported encoding: {e}");
    };
    assert_eq!(
        (layer.as_str(), compression.as_deref()),
        ("layers[0] (\"tiles\")", Some("lzma"))
    );
}

#[test]
fn absurd_sizes_are_refused_before_allocating() {
    let big = r#"<map version="1.10" orientation="orthogonal" width="100000" height="100000" tilewidth="16" tileheight="16">
</map>"#;
    let e = tmx_err(big);
    assert_eq!(e.location, line_col(1, 1));
    assert!(
        matches!(
            e.kind,
            LoadErrorKind::BadSize {
                field: "width × height",
                value: 10_000_000_000,
                ..
            }
        ),
        "{e}"
    );
    // A layer that says it is huge but holds two gids.
    let text = TWO_CELLS
        .replace("DATA", r#"<data encoding="csv">1,1</data>"#)
        .replace(
            "<layer name=\"l\" width=\"2\"",
            "<layer name=\"l\" width=\"4000000000\"",
        );
    let e = tmx_err(&text);
    assert_eq!(e.location, line_col(3, 2));
    assert!(matches!(e.kind, LoadErrorKind::BadSize { .. }), "{e}");
    // Layer data that does not match its size is refused (not read past its end).
    let e = tmx_err(&two_cells(r#"<data encoding="csv">1</data>"#));
    assert!(e.to_string().contains("holds 1 gids, expected 2"), "{e}");
    // Infinite chunks spread over more than MAX_CELLS cells.
    let chunks = r#"<map version="1.10" orientation="orthogonal" width="1" height="1" tilewidth="16" tileheight="16" infinite="1">
 <tileset firstgid="1" source="kit.tsx"/>
 <layer name="l" width="1" height="1"><data encoding="csv">
  <chunk x="-100000" y="0" width="1" height="1">1</chunk>
  <chunk x="100000" y="100000" width="1" height="1">1</chunk>
 </data></layer>
</map>"#;
    let e = tmx_err(chunks);
    assert!(
        matches!(e.kind, LoadErrorKind::BadSize { ref reason, .. } if reason.contains(&MAX_CELLS.to_string())),
        "{e}"
    );
    assert_eq!(e.location, line_col(3, 2));
    // The same in JSON.
    let e = tmj_err(
        r#"{"orientation": "orthogonal", "width": 100000, "height": 100000,
            "tilewidth": 16, "tileheight": 16}"#,
    );
    assert!(
        matches!(
            e.kind,
            LoadErrorKind::BadSize {
                field: "width × height",
                ..
            }
        ),
        "{e}"
    );
}

#[test]
fn the_hexagonal_rotation_bit_is_ignored_on_orthogonal_maps() {
    // Tiled uses gid bit 0x10000000 on hexagonal maps only: on an orthogonal map the tile
    // is placed as if the bit were clear, with the same tile id and shape.
    let parse = |data: &str| {
        let path = scratch(&format!("hex_{}.tmx", data.len()), b"");
        tiled::parse_tmx(&two_cells(data), &path, &TiledOptions::default())
            .unwrap_or_else(|e| panic!("{e}"))
    };
    let plain = parse(r#"<data encoding="csv">1,2147483650</data>"#);
    let hex = parse(r#"<data encoding="csv">268435457,2415919106</data>"#);
    assert_same_tiled(&hex, &plain);
    assert_eq!(hex.map.tile(Cell::new(0, 0)), Some(TileId(1)));
    assert_eq!(hex.map.tile(Cell::new(1, 0)), Some(TileId(H | 2)));
    assert_eq!(hex.tile_info(TileId(H | 2)).unwrap().gid, H | 2);
    // The same in JSON.
    let tmj = std::fs::read_to_string(fixture("flips.tmj")).unwrap();
    let data = tmj.find("\"data\": [").unwrap();
    let first = data + tmj[data..].find('1').unwrap();
    let hex_tmj = format!("{}268435457{}", &tmj[..first], &tmj[first + 1..]);
    let parse_tmj = |text: &str| {
        tiled::parse_tmj(text, fixture("inline.tmj"), &TiledOptions::default())
            .unwrap_or_else(|e| panic!("{e}"))
    };
    assert_same_tiled(&parse_tmj(&hex_tmj), &parse_tmj(&tmj));
}

#[test]
fn other_orientations_are_refused() {
    for orientation in ["isometric", "staggered", "hexagonal"] {
        let e = tmx_err(
            &TWO_CELLS
                .replace("orthogonal", orientation)
                .replace("DATA", r#"<data encoding="csv">1,1</data>"#),
        );
        assert_eq!(e.location, line_col(1, 1));
        assert!(
            e.to_string().contains(&format!(
                "orientation \"{orientation}\" is not supported: tileslide loads orthogonal maps only"
            )),
            "{e}"
        );
    }
    let tmj = std::fs::read_to_string(fixture("flips.tmj"))
        .unwrap()
        .replace("orthogonal", "isometric");
    let e = tmj_err(&tmj);
    assert!(
        e.to_string().contains("\"isometric\" is not supported"),
        "{e}"
    );
    assert!(
        matches!(&e.kind, LoadErrorKind::Unsupported(Unsupported::Orientation(o)) if o == "isometric"),
        "{e}"
    );
}

#[test]
fn gids_outside_every_tile_set_are_named() {
    let e = tmx_err(&two_cells(r#"<data encoding="csv">1,99</data>"#));
    assert!(
        e.to_string()
            .contains("cell (1, 0), gid 0x63: tile set \"kit\" has 8 tiles, so it has no tile 98"),
        "{e}"
    );
    let LoadErrorKind::TileNotInSet {
        at,
        tile_set,
        tile_count,
        tile,
    } = &e.kind
    else {
        panic!("not a tile outside its tile set: {e}");
    };
    assert_eq!((at.layer.as_str(), at.x, at.y, at.gid), ("l", 1, 0, 0x63));
    assert_eq!((tile_set.as_str(), *tile_count, *tile), ("kit", 8, 98));
    let text =
        two_cells(r#"<data encoding="csv">1,1</data>"#).replace("firstgid=\"1\"", "firstgid=\"5\"");
    let e = tmx_err(&text);
    assert!(e.to_string().contains("below every first gid"), "{e}");
}

#[test]
fn tsj_tile_sets_are_refused_in_tmx_maps_and_templates_in_tmj_maps() {
    let e = tmx_err(&two_cells(r#"<data encoding="csv">1,1</data>"#).replace("kit.tsx", "kit.tsj"));
    assert_eq!(e.location, line_col(2, 2));
    assert!(e.to_string().contains("must be .tsx"), "{e}");
    let tmj = std::fs::read_to_string(example("cave.tmj"))
        .unwrap()
        .replacen(
            "\"name\": \"player\",",
            "\"name\": \"player\", \"template\": \"spawn.tx\",",
            1,
        );
    let e = tiled::parse_tmj(&tmj, example("inline.tmj"), &TiledOptions::default()).unwrap_err();
    assert!(
        e.to_string()
            .contains("templates are supported in .tmx maps only"),
        "{e}"
    );
}

#[test]
fn bad_properties_and_shapes_are_named_with_their_tile() {
    // A user bit past flag23, on the kit's coin tile.
    let kit = std::fs::read_to_string(fixture("kit.tsx"))
        .unwrap()
        .replace(
            "name=\"value\" type=\"int\" value=\"5\"",
            "name=\"flag30\" type=\"bool\" value=\"true\"",
        );
    scratch("flag30.tsx", kit.as_bytes());
    let map = two_cells(r#"<data encoding="csv">8,8</data>"#).replace("kit.tsx", "flag30.tsx");
    let e = load_err(&scratch("uses_flag30.tmx", map.as_bytes()));
    assert!(
        e.to_string().contains(
            "tile set \"kit\", tile 7: property `flag30`: the user bits are `flag0` to `flag23`"
        ),
        "{e}"
    );
    // A collision object reaching outside its tile.
    let kit = std::fs::read_to_string(fixture("kit.tsx"))
        .unwrap()
        .replace(
            "x=\"0\" y=\"8\" width=\"16\" height=\"8\"",
            "x=\"0\" y=\"8\" width=\"16\" height=\"12\"",
        );
    scratch("outside.tsx", kit.as_bytes());
    let map = two_cells(r#"<data encoding="csv">2,2</data>"#).replace("kit.tsx", "outside.tsx");
    let uses = scratch("uses_outside.tmx", map.as_bytes());
    let e = load_err(&uses);
    // Named where it is placed: the map, its layer and cell, then the tile and object.
    assert_eq!(
        (e.path.as_path(), e.location),
        (uses.as_path(), line_col(3, 2))
    );
    assert!(
        e.to_string().contains("layer \"l\": cell (0, 0), gid 0x2: tile set \"kit\", tile 1: collision object 1: it reaches (16, 20), 4 px outside the tile's 16×16 pixels"),
        "{e}"
    );
    // The tile and where it is placed, as a program reads them.
    let LoadErrorKind::BadTile {
        placed: Some(at),
        tile_set,
        tile,
        ..
    } = &e.kind
    else {
        panic!("not a tile that cannot go where it is placed: {e}");
    };
    assert_eq!((at.layer.as_str(), at.x, at.y, at.gid), ("l", 0, 0, 2));
    assert_eq!((tile_set.as_str(), *tile), ("kit", 1));
    // A bad hit type on an object.
    let tmj = std::fs::read_to_string(example("cave.tmj"))
        .unwrap()
        .replace("\"DEATH,HIT\"", "\"DEATH,BURN\"");
    let e = tiled::parse_tmj(&tmj, example("inline.tmj"), &TiledOptions::default()).unwrap_err();
    assert!(
        e.to_string().contains(
            "object layer \"regions\", object 6: property `hit_types`: unknown hit type \"BURN\""
        ),
        "{e}"
    );
    assert!(
        matches!(&e.kind, LoadErrorKind::BadProperty { property, .. } if property == "hit_types"),
        "{e}"
    );
}

#[test]
fn files_that_are_not_tiled_maps_are_named() {
    let e = load_err(&example("cave.txt"));
    assert!(
        e.to_string()
            .contains("expected a .tmx, .tmj or .json file"),
        "{e}"
    );
    let e = load_err(&scratch("latin1.tmx", b"<map name=\"caf\xe9\"/>"));
    assert!(matches!(e.kind, LoadErrorKind::NotText), "{e}");
    assert_eq!(e.location, Location::Byte(14));
    let e = tmx_err("<tileset name=\"x\" tilewidth=\"16\" tileheight=\"16\" tilecount=\"1\"/>");
    assert!(e.to_string().contains("root element is <tileset>"), "{e}");
    assert!(
        matches!(&e.kind, LoadErrorKind::NotATiledMap(NotTiled::RootElement(root)) if root == "tileset"),
        "{e}"
    );
    let e = load_err(&fixture("nowhere.tmx"));
    assert_eq!(e.io_error_kind(), Some(std::io::ErrorKind::NotFound), "{e}");
}

#[test]
fn json_that_is_not_a_tiled_map_says_what_it_is() {
    let tsj = std::fs::read_to_string(fixture("kit.tsj")).unwrap();
    assert!(tsj.contains("\"type\": \"tileset\""));
    assert_eq!(
        tmj_err(&tsj).to_string(),
        format!(
            "{}: a Tiled tile set (\"type\": \"tileset\"), not a map",
            fixture("inline.tmj").display()
        )
    );
    assert!(matches!(
        tmj_err(&tsj).kind,
        LoadErrorKind::NotATiledMap(NotTiled::TileSet)
    ));
    let e = tmj_err(r#"{"map": "cave.txt", "bodies": []}"#);
    assert!(e.to_string().contains("not a Tiled JSON map"), "{e}");
    assert!(
        matches!(e.kind, LoadErrorKind::NotATiledMap(NotTiled::UntypedJson)),
        "{e}"
    );
    let e = tmj_err("[1, 2]");
    assert!(e.to_string().contains("JSON but not an object"), "{e}");
    assert!(
        matches!(e.kind, LoadErrorKind::NotATiledMap(NotTiled::NotAnObject)),
        "{e}"
    );
    let e = tmj_err(r#"{"type": "world", "maps": []}"#);
    assert!(e.to_string().contains("its `type` is \"world\""), "{e}");
    assert!(
        matches!(&e.kind, LoadErrorKind::NotATiledMap(NotTiled::JsonType(t)) if t == "world"),
        "{e}"
    );
    // A map saved before Tiled 1.2 has no `type`: its `orientation` tells it is a map.
    let old = std::fs::read_to_string(fixture("flips.tmj"))
        .unwrap()
        .replace("\"type\": \"map\",", "");
    assert!(!old.contains("\"type\": \"map\""));
    tiled::parse_tmj(&old, fixture("old.tmj"), &TiledOptions::default()).unwrap();
    // A map file named `.json` loads by the same rules as `.tmj`.
    let json = scratch(
        "flips_tsx.json",
        &std::fs::read(fixture("flips_tsx.tmj")).unwrap(),
    );
    assert_same_tiled(&load(&json), &load(&fixture("flips_tsx.tmj")));
}

/// A 16-pixel infinite `.tmj` map (a few hundred bytes) of two one-cell chunks, at Tiled
/// cells (0, 0) and (`far`, `far`): its bounding box is (far + 1)² cells, all but two empty.
fn far_flung(far: i32) -> String {
    format!(
        r#"{{"type": "map", "orientation": "orthogonal", "infinite": true, "width": 1,
  "height": 1, "tilewidth": 16, "tileheight": 16,
  "tilesets": [{{"firstgid": 1, "name": "t", "tilewidth": 16, "tileheight": 16,
    "tilecount": 1}}],
  "layers": [{{"type": "tilelayer", "name": "l", "width": 1, "height": 1, "chunks": [
    {{"x": 0, "y": 0, "width": 1, "height": 1, "data": [1]}},
    {{"x": {far}, "y": {far}, "width": 1, "height": 1, "data": [1]}}]}}]}}"#
    )
}

#[test]
fn an_infinite_map_of_chunks_far_apart_is_refused_unless_allowed() {
    let parse =
        |text: &str, options: &TiledOptions| tiled::parse_tmj(text, fixture("far.tmj"), options);
    // (Not `unwrap_err`: a map that loads by mistake would print its million cells.)
    let refused = |text: &str, options: &TiledOptions| match parse(text, options) {
        Ok(m) => panic!("a {}×{} map loaded", m.map.width(), m.map.height()),
        Err(e) => e,
    };
    // 1025² cells, two of them in chunks: past the 2²⁰ cells any spread may take, and far
    // more than 64 times what the chunks hold.
    let far = far_flung(1024);
    assert!(far.len() < 600);
    let e = refused(&far, &TiledOptions::default());
    assert_eq!(
        e.to_string(),
        format!(
            "{}: `width × height` = 1050625 is out of range: layers[0] (\"l\"): the infinite \
             layer's chunks hold 2 cells spread over 1025×1025 = 1050625 cells, more than 64 \
             times as many (`TiledOptions::max_chunk_spread`, for maps over 1048576 cells): \
             nearly all of it empty, and each empty cell costs memory; raise \
             `max_chunk_spread` to load it",
            fixture("far.tmj").display()
        )
    );
    // Raised, it loads: the two chunks' cells at the corners of the box.
    let map = parse(
        &far,
        &TiledOptions::default().with_max_chunk_spread(1 << 20),
    )
    .unwrap();
    assert_eq!((map.map.width(), map.map.height()), (1025, 1025));
    assert_eq!(map.map.tile(Cell::new(1024, 1024)), Some(TileId(1)));
    // Up to 2²⁰ cells, any spread loads: 1024² here.
    let near = parse(&far_flung(1023), &TiledOptions::default()).unwrap();
    assert_eq!((near.map.width(), near.map.height()), (1024, 1024));
    // `max_cells` bounds the bounding box too, and says how to raise it.
    let e = refused(
        &far_flung(1023),
        &TiledOptions::default().with_max_cells(1000),
    );
    assert!(
        e.to_string().contains(
            "the layer spans 1024×1024 cells, more than 1000 cells (`TiledOptions::max_cells`; \
             raise it to load this map)"
        ),
        "{e}"
    );
}

#[test]
fn max_cells_bounds_every_layer_before_it_is_read() {
    let small = TiledOptions::default().with_max_cells(1);
    let tmx = two_cells(r#"<data encoding="csv">1,1</data>"#);
    let e = tiled::parse_tmx(&tmx, scratch("max_cells.tmx", b""), &small).unwrap_err();
    assert_eq!(e.location, line_col(1, 1));
    assert!(
        matches!(&e.kind, LoadErrorKind::BadSize { field: "width × height", value: 2, reason }
            if reason.contains("2×1 is more than 1 cells (`TiledOptions::max_cells`")),
        "{e}"
    );
    let tmj = std::fs::read_to_string(fixture("flips.tmj")).unwrap();
    let e = tiled::parse_tmj(&tmj, fixture("inline.tmj"), &small).unwrap_err();
    assert!(e.to_string().contains("`TiledOptions::max_cells`"), "{e}");
    // Above MAX_CELLS is taken as MAX_CELLS.
    let huge = TiledOptions::default().with_max_cells(u64::MAX);
    let e = tiled::parse_tmx(
        r#"<map version="1.10" orientation="orthogonal" width="100000" height="100000" tilewidth="16" tileheight="16">
</map>"#,
        fixture("inline.tmx"),
        &huge,
    )
    .unwrap_err();
    assert!(
        e.to_string()
            .contains(&format!("is more than {MAX_CELLS} cells")),
        "{e}"
    );
}
