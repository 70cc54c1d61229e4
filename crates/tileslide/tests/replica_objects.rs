#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
//! Proves that `replica::parse_objects` reads the game's real levels as FORMAT.md and the
//! game lay them out: every level loads, every object and hot spot is where an independent
//! reading of the bytes puts it, the player spawns where the level says, and the two files
//! the game ships cut short are reported, not refused.

use crate::replica_support;

use std::path::Path;

use replica_support::{RawLevel, data_dir, level_names, raw_level, read};
use tileslide::Cell;
use tileslide::io::replica::{self, HotSpotKind, LevelObjects, ObjectKind};

/// Every level file of the data: `level_*.bin`, `collisiontest.bin` and the game's test maps.
fn every_level(dir: &Path) -> Vec<String> {
    let mut names = level_names(dir);
    names.push("collisiontest.bin".into());
    let mut tests: Vec<String> = std::fs::read_dir(dir.join("test-levels"))
        .unwrap()
        .map(|e| format!("test-levels/{}", e.unwrap().file_name().to_string_lossy()))
        .filter(|n| n.ends_with(".bin"))
        .collect();
    tests.sort();
    names.extend(tests);
    names
}

/// The raw bytes of the layer of `layer_type`, when the file holds all of them.
fn raw_cells<'a>(d: &'a [u8], raw: &RawLevel, layer_type: i8) -> Option<&'a [u8]> {
    let l = raw.layers.iter().find(|l| l.kind == layer_type)?;
    d.get(l.cells_at..l.cells_at + (l.width * l.height) as usize)
}

fn load(dir: &Path, name: &str) -> LevelObjects {
    replica::parse_objects(&read(dir, name), name).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn every_level_loads_and_each_object_is_where_its_byte_is() {
    let Some(dir) = data_dir() else { return };
    let names = every_level(&dir);
    assert!(names.len() > 55, "{} levels", names.len());
    let mut objects = 0;
    for name in &names {
        let bytes = read(&dir, name);
        let raw = raw_level(&bytes);
        let level = load(&dir, name);
        let collision = raw.layers.iter().find(|l| l.kind == 1).unwrap();
        assert_eq!(
            (level.width as i32, level.height as i32),
            (collision.width, collision.height),
            "{name}"
        );
        // Expected: every non-negative byte of the object layer, top row first, at world
        // row height − 1 − file row.
        let w = collision.width as usize;
        let expected: Vec<(u8, Cell)> = raw_cells(&bytes, &raw, 2)
            .unwrap_or_default()
            .iter()
            .enumerate()
            .filter(|&(_, &b)| (b as i8) >= 0)
            .map(|(i, &b)| {
                let row = level.height - 1 - (i / w) as u32;
                (b, Cell::new((i % w) as u32, row))
            })
            .collect();
        let got: Vec<(u8, Cell)> = level
            .objects
            .iter()
            .map(|o| (o.type_number, o.cell))
            .collect();
        assert_eq!(got, expected, "{name}");
        for o in &level.objects {
            assert_eq!(o.kind, ObjectKind::from_type(o.type_number), "{name}");
            assert_eq!(o.position.x, o.cell.col as f32 * 32.0, "{name}");
            assert_eq!(o.position.y, o.cell.row as f32 * 32.0, "{name}");
        }
        objects += level.objects.len();
    }
    // The data's objects, counted by the independent reading above.
    assert!(objects > 2500, "{objects} objects");
}

#[test]
fn every_object_in_the_games_levels_has_a_kind_the_game_defines() {
    let Some(dir) = data_dir() else { return };
    for name in every_level(&dir) {
        for o in load(&dir, &name).objects {
            assert!(
                o.kind.is_some(),
                "{name}: type {} at {}",
                o.type_number,
                o.cell
            );
        }
    }
}

#[test]
fn every_hot_spot_is_where_its_byte_is() {
    let Some(dir) = data_dir() else { return };
    let mut levels_with_hot_spots = 0;
    for name in every_level(&dir) {
        let bytes = read(&dir, &name);
        let raw = raw_level(&bytes);
        let level = load(&dir, &name);
        let Some(cells) = raw_cells(&bytes, &raw, 3) else {
            assert_eq!(level.hot_spots, None, "{name}");
            continue;
        };
        levels_with_hot_spots += 1;
        let spots = level.hot_spots.as_ref().unwrap();
        let w = level.width as usize;
        for (i, &b) in cells.iter().enumerate() {
            let cell = Cell::new((i % w) as u32, level.height - 1 - (i / w) as u32);
            let code = u8::try_from(b as i8).ok();
            assert_eq!(spots.code(cell), code, "{name} {cell}");
            assert_eq!(
                spots.kind(cell),
                code.and_then(HotSpotKind::from_code),
                "{name}"
            );
        }
        assert_eq!(
            spots.iter().count(),
            cells.iter().filter(|&&b| (b as i8) >= 0).count()
        );
    }
    assert!(levels_with_hot_spots > 40, "{levels_with_hot_spots}");
}

#[test]
fn the_player_spawns_where_each_level_places_it() {
    let Some(dir) = data_dir() else { return };
    // Read by hand from the object layers (world rows, row 0 at the bottom).
    for (name, cell) in [
        ("level_1_1_island.bin", Cell::new(5, 43)),
        ("level_1_4_island.bin", Cell::new(33, 58)),
        ("level_2_4_grass.bin", Cell::new(3, 2)),
        ("level_3_5_sewer.bin", Cell::new(145, 20)),
        ("level_final_boss_lab.bin", Cell::new(44, 5)),
        ("collisiontest.bin", Cell::new(0, 4)),
        ("test-levels/slidetest3.bin", Cell::new(0, 37)),
    ] {
        let level = load(&dir, name);
        let spawn = level.player_spawn().unwrap_or_else(|| panic!("{name}"));
        assert_eq!(spawn.cell, cell, "{name}");
        assert_eq!(spawn.bottom_middle().x, cell.col as f32 * 32.0 + 16.0);
    }
    // Every level the player plays has exactly one spawn; three story levels (the
    // sewer's opening, its repeat and Wanda's) place none: a character walks them alone.
    let mut without = Vec::new();
    for name in level_names(&dir) {
        match load(&dir, &name).of_kind(ObjectKind::Player).count() {
            0 => without.push(name),
            n => assert_eq!(n, 1, "{name}"),
        }
    }
    assert_eq!(
        without,
        [
            "level_0_1_sewer.bin",
            "level_0_1_sewer_repeat.bin",
            "level_0_1_sewer_wanda.bin"
        ]
    );
}

#[test]
fn level_1_1_island_holds_its_coins_rubies_diary_and_enemies() {
    let Some(dir) = data_dir() else { return };
    let level = load(&dir, "level_1_1_island.bin");
    let count = |kind| level.of_kind(kind).count();
    assert_eq!(count(ObjectKind::Coin), 32);
    assert_eq!(count(ObjectKind::Ruby), 3);
    assert_eq!(count(ObjectKind::Diary), 1);
    assert_eq!(count(ObjectKind::Brobot), 4);
    assert_eq!(count(ObjectKind::Karaguin), 2);
    assert_eq!(count(ObjectKind::Wanda), 1);
    assert_eq!(level.objects.len(), 58);
    let spots = level.hot_spots.as_ref().unwrap();
    let turns = spots
        .iter()
        .filter(|&(cell, _)| {
            matches!(
                spots.kind(cell),
                Some(HotSpotKind::GoLeft | HotSpotKind::GoRight)
            )
        })
        .count();
    assert_eq!(turns, 5);
}

#[test]
fn the_two_files_cut_short_load_with_their_cut_layer_read_as_empty() {
    let Some(dir) = data_dir() else { return };
    // level_1_4_island.bin: the hot-spot layer (the last of five) lacks 2,738 bytes.
    let level = load(&dir, "level_1_4_island.bin");
    let cut = level.cut_short.unwrap();
    assert_eq!((cut.index, cut.layer_type, cut.cells), (4, 3, 80 * 80));
    assert_eq!(cut.cells - cut.present, 2738);
    assert_eq!(level.hot_spots, None);
    assert_eq!(level.of_kind(ObjectKind::Coin).count(), 115);
    // test-levels/slidetest.bin: the object layer (the last of four) lacks 8,016 bytes, so
    // it has no objects, and no player to start.
    let level = load(&dir, "test-levels/slidetest.bin");
    let cut = level.cut_short.unwrap();
    assert_eq!((cut.index, cut.layer_type), (3, 2));
    assert_eq!(cut.cells - cut.present, 8016);
    assert!(level.objects.is_empty());
    assert_eq!(level.player_spawn(), None);
    // No other file is cut short.
    for name in every_level(&dir) {
        if !["level_1_4_island.bin", "test-levels/slidetest.bin"].contains(&name.as_str()) {
            assert_eq!(load(&dir, &name).cut_short, None, "{name}");
        }
    }
}

#[test]
fn load_objects_reads_the_file_parse_objects_parses() {
    let Some(dir) = data_dir() else { return };
    let name = "level_3_6_sewer.bin";
    let from_file = replica::load_objects(dir.join(name)).unwrap();
    assert_eq!(from_file, load(&dir, name));
}

#[test]
fn the_notes_table_names_every_kind_by_its_type_number() {
    // docs/replica-island.md lists the kinds as `| type | kind |` cells, three pairs a row.
    let note = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../docs/replica-island.md"
    ))
    .unwrap();
    let mut listed: Vec<(u8, String)> = Vec::new();
    for line in note.lines().filter(|l| l.starts_with("| ")) {
        let cells: Vec<&str> = line.trim_matches('|').split('|').map(str::trim).collect();
        for pair in cells.chunks(2) {
            if let [number, name] = pair
                && let Ok(number) = number.parse::<u8>()
            {
                listed.push((number, name.trim_matches('`').to_owned()));
            }
        }
    }
    listed.sort();
    let kinds: Vec<(u8, String)> = ObjectKind::ALL
        .iter()
        .map(|k| (k.type_number(), k.name().to_owned()))
        .collect();
    assert_eq!(listed, kinds);
}
