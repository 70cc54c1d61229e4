#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
//! Proves the ASCII map loader's rules (characters, comments, CRLF, padding, blank lines,
//! cell size) and that each of its errors names the file and the line:column or byte offset.

use std::path::{Path, PathBuf};

use tileslide::io::{LoadError, LoadErrorKind, Location, ascii};
use tileslide::{Cell, QueryFilter, Ray, TileId, TileMap, Vec2};

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

fn parse(text: &str) -> TileMap {
    ascii::parse(text, "maps/test.txt", 1.0).unwrap_or_else(|e| panic!("{e}"))
}

fn parse_err(text: &str) -> LoadError {
    ascii::parse(text, "maps/test.txt", 1.0).unwrap_err()
}

fn row(map: &TileMap, r: u32) -> Vec<Option<TileId>> {
    (0..map.width())
        .map(|c| map.tile(Cell::new(c, r)))
        .collect()
}

fn line_col(line: u32, column: u32) -> Location {
    Location::LineColumn { line, column }
}

/// A scratch file under Cargo's per-target temporary directory.
fn scratch(name: &str, bytes: &[u8]) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("loader_ascii");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, bytes).unwrap();
    path
}

const S: Option<TileId> = Some(ascii::SOLID);
const U: Option<TileId> = Some(ascii::RAMP_UP_RIGHT);
const D: Option<TileId> = Some(ascii::RAMP_DOWN_RIGHT);
const P: Option<TileId> = Some(ascii::ONE_WAY);

#[test]
fn every_tile_character_maps_to_its_tile_and_first_line_is_row_0() {
    let map = parse("#./\\= \n");
    assert_eq!((map.width(), map.height()), (6, 1));
    assert_eq!(row(&map, 0), [S, None, U, D, P, None]);
    let map = parse("#..\n..#\n");
    assert_eq!(row(&map, 0), [S, None, None]);
    assert_eq!(row(&map, 1), [None, None, S]);
}

#[test]
fn unknown_character_is_an_error_at_its_line_and_column() {
    let e = parse_err("####\n#..#\n#.@#\n####");
    assert_eq!(e.location, line_col(3, 3));
    assert!(
        matches!(e.kind, LoadErrorKind::UnknownCharacter('@')),
        "{e}"
    );
    assert!(e.to_string().starts_with("maps/test.txt:3:3: "), "{e}");
}

#[test]
fn unknown_character_line_counts_comment_lines() {
    let e = parse_err("; first\n; second\n#\nX");
    assert_eq!(e.location, line_col(4, 1));
    assert!(
        matches!(e.kind, LoadErrorKind::UnknownCharacter('X')),
        "{e}"
    );
}

#[test]
fn unknown_character_column_counts_characters_not_bytes() {
    // A multi-byte character is one column: 'é' is itself the unknown character at column 3.
    let e = parse_err("#.é#");
    assert_eq!(e.location, line_col(1, 3));
    assert!(
        matches!(e.kind, LoadErrorKind::UnknownCharacter('é')),
        "{e}"
    );
}

#[test]
fn tab_is_an_error_not_whitespace() {
    let e = parse_err("#\t#");
    assert_eq!(e.location, line_col(1, 2));
    assert!(
        matches!(e.kind, LoadErrorKind::UnknownCharacter('\t')),
        "{e}"
    );
    assert!(e.to_string().starts_with("maps/test.txt:1:2: "), "{e}");
}

#[test]
fn semicolon_inside_a_row_is_an_error_not_a_comment() {
    let e = parse_err("#.; not a comment");
    assert_eq!(e.location, line_col(1, 3));
    assert!(
        matches!(e.kind, LoadErrorKind::UnknownCharacter(';')),
        "{e}"
    );
}

#[test]
fn crlf_line_endings_load_like_lf() {
    let lf = parse("#./\n\\=#\n");
    let crlf = parse("#./\r\n\\=#\r\n");
    assert_eq!((crlf.width(), crlf.height()), (3, 2));
    for r in 0..2 {
        assert_eq!(row(&crlf, r), row(&lf, r));
    }
    // Mixed endings, no final newline.
    let mixed = parse("#./\r\n\\=#");
    assert_eq!(row(&mixed, 1), row(&lf, 1));
}

#[test]
fn stray_carriage_return_inside_a_line_is_an_error() {
    let e = parse_err("#\r#\n");
    assert_eq!(e.location, line_col(1, 2));
    assert!(
        matches!(e.kind, LoadErrorKind::UnknownCharacter('\r')),
        "{e}"
    );
}

#[test]
fn comment_lines_are_not_rows() {
    let map = parse("; title\n#.\n; between rows\n.#\n; trailing\n");
    assert_eq!((map.width(), map.height()), (2, 2));
    assert_eq!(row(&map, 0), [S, None]);
    assert_eq!(row(&map, 1), [None, S]);
    // A comment may contain any character, and CRLF.
    let map = parse(";\t@é\r\n#\r\n");
    assert_eq!((map.width(), map.height()), (1, 1));
}

#[test]
fn empty_map_is_an_error_naming_the_file() {
    for text in ["", "\n", "\n\n\r\n", "; only a comment", "; a\n; b\n\n"] {
        let e = parse_err(text);
        assert_eq!(e.location, Location::File, "{text:?}");
        assert!(matches!(e.kind, LoadErrorKind::NoRows), "{text:?}");
        assert_eq!(e.to_string(), "maps/test.txt: the map has no rows");
    }
}

#[test]
fn short_lines_are_padded_with_empty_cells() {
    let map = parse("#\n###\n##\n");
    assert_eq!((map.width(), map.height()), (3, 3));
    assert_eq!(row(&map, 0), [S, None, None]);
    assert_eq!(row(&map, 1), [S, S, S]);
    assert_eq!(row(&map, 2), [S, S, None]);
}

#[test]
fn blank_line_between_rows_is_an_empty_row_and_trailing_blank_lines_are_dropped() {
    let map = parse("#\n\n#\n\n\n");
    assert_eq!((map.width(), map.height()), (1, 3));
    assert_eq!(row(&map, 1), [None]);
    // A leading blank line is a row too.
    let map = parse("\n#");
    assert_eq!(map.height(), 2);
    assert_eq!(row(&map, 0), [None]);
}

#[test]
fn spaces_only_map_is_a_valid_empty_map() {
    let map = parse("   \n   ");
    assert_eq!((map.width(), map.height()), (3, 2));
    assert_eq!(map.active_segment_count(), 0);
}

#[test]
fn cell_size_scales_the_map() {
    let map = ascii::parse("##\n#.\n", "s.txt", 2.5).unwrap();
    assert_eq!(map.cell_size(), Vec2::splat(2.5));
    assert_eq!(map.bounds().max, v(5.0, 5.0));
    let hit = map
        .cast_ray(
            Ray::between(v(3.75, 3.75), v(3.75, 0.5)),
            &QueryFilter::default(),
        )
        .unwrap();
    // Row 0 at the top (y down): the block above has its bottom edge at y = 2.5.
    assert_eq!(hit.point, v(3.75, 2.5));
    assert_eq!(hit.normal, v(0.0, 1.0));
}

#[test]
fn cell_size_nan_zero_negative_or_infinite_is_an_error_naming_the_file() {
    for cell in [f32::NAN, 0.0, -0.0, -1.0, f32::INFINITY, f32::NEG_INFINITY] {
        let e = ascii::parse("#", "maps/cell.txt", cell).unwrap_err();
        assert_eq!(e.location, Location::File, "{cell}");
        assert!(matches!(e.kind, LoadErrorKind::Parameter(_)), "{cell}: {e}");
        let text = e.to_string();
        assert!(text.starts_with("maps/cell.txt: "), "{text}");
        assert!(text.contains("cell size"), "{text}");
    }
}

#[test]
fn cell_size_is_checked_before_the_text() {
    // Both are wrong: the parameter is reported first.
    let e = ascii::parse("@", "m.txt", 0.0).unwrap_err();
    assert!(matches!(e.kind, LoadErrorKind::Parameter(_)), "{e}");
}

#[test]
fn one_way_platform_blocks_from_above_only() {
    let map = parse("...\n.=.\n...");
    let down = Ray::between(v(1.5, 0.5), v(1.5, 2.5));
    let hit = map.cast_ray(down, &QueryFilter::default()).unwrap();
    assert_eq!(hit.point, v(1.5, 1.0));
    assert_eq!(hit.normal, v(0.0, -1.0));
    let up = Ray::between(v(1.5, 2.5), v(1.5, 0.5));
    assert!(map.cast_ray(up, &QueryFilter::default()).is_none());
}

#[test]
fn ramps_face_up_left_and_up_right() {
    // y down: '/' rises to the right, so its surface faces up-left (−x, −y); '\' up-right.
    let map = parse("..\n/\\");
    let h = std::f32::consts::FRAC_1_SQRT_2;
    let on = |x: f32| {
        map.cast_ray(Ray::between(v(x, 0.5), v(x, 2.0)), &QueryFilter::default())
            .unwrap()
    };
    let up = on(0.25);
    assert!((up.point.y - 1.75).abs() < 1e-6, "{}", up.point);
    assert!((up.normal - v(-h, -h)).length() < 1e-6, "{}", up.normal);
    let down = on(1.25);
    assert!((down.point.y - 1.25).abs() < 1e-6, "{}", down.point);
    assert!((down.normal - v(h, -h)).length() < 1e-6, "{}", down.normal);
}

#[test]
fn load_reads_a_file_and_names_it_in_errors() {
    let path = scratch("good.txt", b"; saved\r\n#.#\r\n###\r\n");
    let map = ascii::load(&path, 1.0).unwrap();
    assert_eq!((map.width(), map.height()), (3, 2));

    let path = scratch("bad_char.txt", b"##\n#?\n");
    let e = ascii::load(&path, 1.0).unwrap_err();
    assert_eq!(e.path, path);
    assert_eq!(e.location, line_col(2, 2));
    assert!(
        e.to_string()
            .starts_with(&format!("{}:2:2: ", path.display())),
        "{e}"
    );
}

#[test]
fn non_utf8_file_is_an_error_at_the_first_bad_byte() {
    let path = scratch("latin1.txt", b"##\n#\xe9#\n");
    let e = ascii::load(&path, 1.0).unwrap_err();
    assert_eq!(e.path, path);
    assert_eq!(e.location, Location::Byte(4));
    let text = e.to_string();
    assert!(
        text.starts_with(&format!("{}: byte 4: ", path.display())),
        "{text}"
    );
    assert!(text.contains("UTF-8"), "{text}");
    assert!(matches!(e.kind, LoadErrorKind::NotText), "{e}");
}

#[test]
fn leading_byte_order_mark_is_ignored() {
    let path = scratch("bom.txt", "\u{feff}#.\n.#\n".as_bytes());
    let map = ascii::load(&path, 1.0).unwrap();
    assert_eq!((map.width(), map.height()), (2, 2));
    assert_eq!(map.tile(tileslide::Cell::new(0, 0)), Some(ascii::SOLID));
}

#[test]
fn missing_file_is_an_io_error_naming_it() {
    let path = "/nonexistent-tileslide-dir/map.txt";
    let e = ascii::load(path, 1.0).unwrap_err();
    assert_eq!(e.location, Location::File);
    assert!(
        matches!(
            e.kind,
            LoadErrorKind::Io {
                referenced: None,
                ..
            }
        ),
        "{e}"
    );
    assert!(e.to_string().starts_with(path), "{e}");
}

#[test]
fn a_missing_file_keeps_the_not_found_kind_and_the_io_error_as_its_source() {
    let e = ascii::load("/nonexistent-tileslide-dir/map.txt", 1.0).unwrap_err();
    // A program can tell a missing file from a refused or unreadable one.
    assert_eq!(e.io_error_kind(), Some(std::io::ErrorKind::NotFound));
    let source = std::error::Error::source(&e).expect("the I/O error is the source");
    let io = source
        .downcast_ref::<std::io::Error>()
        .expect("the source is the std::io::Error");
    assert_eq!(io.kind(), std::io::ErrorKind::NotFound);
    assert!(e.to_string().ends_with(&io.to_string()), "{e}");
    // An error that is not about reading a file has no I/O kind.
    assert_eq!(parse_err("@").io_error_kind(), None);
}

#[test]
fn an_unknown_character_is_a_variant_with_its_character_line_and_column() {
    let e = parse_err("####\n#..#\n#.?#\n");
    let (LoadErrorKind::UnknownCharacter(c), Location::LineColumn { line, column }) =
        (&e.kind, e.location)
    else {
        panic!("not an unknown character at a line and column: {e}");
    };
    assert_eq!((*c, line, column), ('?', 3, 3));
    assert_eq!(
        e.to_string(),
        "maps/test.txt:3:3: unknown tile character '?' (expected one of `.`, space, `#`, `/`, \
         `\\`, `=`)"
    );
}

#[test]
fn tile_for_char_agrees_with_the_design_table() {
    assert_eq!(ascii::tile_for_char('.'), Ok(None));
    assert_eq!(ascii::tile_for_char(' '), Ok(None));
    assert_eq!(ascii::tile_for_char('#'), Ok(S));
    assert_eq!(ascii::tile_for_char('/'), Ok(U));
    assert_eq!(ascii::tile_for_char('\\'), Ok(D));
    assert_eq!(ascii::tile_for_char('='), Ok(P));
    for c in ['\t', ';', 'x', '0', '\u{feff}'] {
        assert_eq!(
            ascii::tile_for_char(c),
            Err(ascii::UnknownTileChar(c)),
            "{c:?}"
        );
    }
}

#[test]
fn extreme_but_finite_cell_size_is_a_parameter_error_naming_the_cell_size() {
    // Regression: a positive, finite cell size whose square overflows or underflows f32
    // (the built-in ramp and square shapes cannot be built at that size) was reported as
    // "tile 1: the polygon has zero area", blaming a tile the user never defined.
    for cell in [1e20f32, 1e30, f32::MAX, 1e-30, f32::MIN_POSITIVE, 1e-45] {
        let e = ascii::parse("#/", "maps/huge.txt", cell).unwrap_err();
        assert_eq!(e.location, Location::File, "{cell}");
        assert!(matches!(e.kind, LoadErrorKind::Parameter(_)), "{cell}: {e}");
        let text = e.to_string();
        assert!(text.starts_with("maps/huge.txt: "), "{text}");
        assert!(text.contains(&format!("cell size {cell}")), "{text}");
    }
    // Sizes well inside f32's range work.
    for cell in [1e-10f32, 1e-3, 0.5, 32.0, 1e6] {
        let map = ascii::parse("#/", "ok.txt", cell).unwrap_or_else(|e| panic!("{cell}: {e}"));
        assert_eq!(map.cell_size(), Vec2::splat(cell));
    }
    // A size whose map reaches past MAX_COORD is refused, naming the range.
    let e = ascii::parse("#/", "maps/far.txt", 1e10).unwrap_err();
    assert!(e.to_string().contains("MAX_COORD"), "{e}");
}
