#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]
//! Shared by the `replica_*` and `loader_*` tests: where the Replica Island data lives (and
//! what to do when it is missing), and a tiny independent reader of the raw files so that
//! tests compute their expectations from the bytes, not from the loader under test.

// Each test crate uses a different part of this module.
#![allow(dead_code)]

use std::path::{Path, PathBuf};

/// The shared data directory: `../shared/data/replica-island/` beside the repository root.
/// Never copied into the repository.
pub const DATA_DIR: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../../shared/data/replica-island"
);

/// Side of a Replica Island tile in pixels.
pub const TILE: f32 = 32.0;

/// Decides what a test does about the data directory `dir`: `Ok(Some(dir))` when present,
/// `Ok(None)` (skip) when absent outside CI, `Err(message naming the path)` when absent in CI.
pub fn resolve_data_dir(dir: &Path, in_ci: bool) -> Result<Option<PathBuf>, String> {
    if dir.is_dir() {
        return Ok(Some(dir.to_path_buf()));
    }
    let message = format!(
        "Replica Island data directory {} is missing (expected ../shared/data/replica-island \
         beside the repository root)",
        dir.display()
    );
    if in_ci { Err(message) } else { Ok(None) }
}

/// The data directory, or `None` after printing a skip message to stderr. Panics, naming
/// the path, when the data is missing and the `CI` environment variable is set.
pub fn data_dir() -> Option<PathBuf> {
    let in_ci = std::env::var_os("CI").is_some();
    match resolve_data_dir(Path::new(DATA_DIR), in_ci) {
        Ok(Some(dir)) => Some(dir),
        Ok(None) => {
            eprintln!(
                "SKIPPED: Replica Island data not found at {DATA_DIR}; set it up at \
                 ../shared/data/replica-island beside the repository root to run this test"
            );
            None
        }
        Err(message) => panic!("{message} (CI is set, so a missing data set is a failure)"),
    }
}

/// Reads a data file, panicking with its path if it cannot be read.
pub fn read(dir: &Path, name: &str) -> Vec<u8> {
    let path = dir.join(name);
    std::fs::read(&path).unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()))
}

fn le_i32(d: &[u8], at: usize) -> i32 {
    i32::from_le_bytes([d[at], d[at + 1], d[at + 2], d[at + 3]])
}

fn le_f32(d: &[u8], at: usize) -> f32 {
    f32::from_le_bytes([d[at], d[at + 1], d[at + 2], d[at + 3]])
}

/// One raw segment of `collision.bin`: start, end, normal, exactly as stored.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RawSegment {
    pub start: [f32; 2],
    pub end: [f32; 2],
    pub normal: [f32; 2],
}

/// A raw tile of `collision.bin`.
#[derive(Clone, Debug, PartialEq)]
pub struct RawTile {
    pub id: u8,
    pub segments: Vec<RawSegment>,
}

/// Reads `collision.bin` the simplest possible way (FORMAT.md), trusting the bytes.
pub fn raw_tile_set(d: &[u8]) -> Vec<RawTile> {
    assert_eq!(d[0], 52, "tile set signature");
    let mut tiles = Vec::new();
    let mut p = 2;
    for _ in 0..d[1] {
        let (id, count) = (d[p], d[p + 1]);
        p += 2;
        let mut segments = Vec::new();
        for _ in 0..count {
            let f = |i: usize| le_f32(d, p + 4 * i);
            segments.push(RawSegment {
                start: [f(0), f(1)],
                end: [f(2), f(3)],
                normal: [f(4), f(5)],
            });
            p += 24;
        }
        tiles.push(RawTile { id, segments });
    }
    assert_eq!(p, d.len(), "collision.bin has no trailing bytes");
    tiles
}

/// One layer header of a level file as read from the raw bytes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RawLayer {
    pub kind: i8,
    pub width: i32,
    pub height: i32,
    /// Byte offset of the first cell.
    pub cells_at: usize,
}

/// A level's headers: the layers, and the file length the headers claim.
#[derive(Clone, Debug, PartialEq)]
pub struct RawLevel {
    pub layer_count: i8,
    pub layers: Vec<RawLayer>,
    /// Offset just after the last layer's cells, computed from the headers alone (for a
    /// truncated file the headers of the missing layers are assumed to be there).
    pub claimed_len: usize,
}

/// Reads a level's layer headers. Stops reading headers (but keeps counting) once the file
/// ends: a truncated final layer still contributes its claimed size if its header is there.
pub fn raw_level(d: &[u8]) -> RawLevel {
    assert_eq!(d[0] as i8, 96, "level signature");
    let layer_count = d[1] as i8;
    let mut layers = Vec::new();
    let mut p = 3;
    for _ in 0..layer_count {
        assert!(p + 15 <= d.len(), "layer header inside the file");
        assert_eq!(d[p + 6], 42, "tile map signature");
        let layer = RawLayer {
            kind: d[p] as i8,
            width: le_i32(d, p + 7),
            height: le_i32(d, p + 11),
            cells_at: p + 15,
        };
        p = layer.cells_at + (layer.width * layer.height) as usize;
        layers.push(layer);
    }
    RawLevel {
        layer_count,
        layers,
        claimed_len: p,
    }
}

/// The collision layer of a level as a grid of raw ids, indexed in **world** rows (row 0 at
/// the bottom, y up).
pub struct RawGrid {
    pub width: u32,
    pub height: u32,
    ids: Vec<i8>,
}

impl RawGrid {
    /// The collision layer of level bytes `d`.
    pub fn from_level(d: &[u8]) -> Self {
        let level = raw_level(d);
        let layer = level
            .layers
            .iter()
            .find(|l| l.kind == 1)
            .copied()
            .unwrap_or_else(|| panic!("no collision layer"));
        let n = (layer.width * layer.height) as usize;
        let ids = d[layer.cells_at..layer.cells_at + n]
            .iter()
            .map(|&b| b as i8)
            .collect();
        Self {
            width: layer.width as u32,
            height: layer.height as u32,
            ids,
        }
    }

    /// The raw id at world (col, row); file row = height − 1 − row.
    pub fn id(&self, col: u32, row: u32) -> i8 {
        let file_row = self.height - 1 - row;
        self.ids[(file_row * self.width + col) as usize]
    }

    /// The tile at world (col, row): `None` for a negative id or one the tile set lacks.
    pub fn tile(&self, col: u32, row: u32, tiles: &[RawTile]) -> Option<u8> {
        let id = self.id(col, row);
        (id >= 0 && tiles.iter().any(|t| t.id == id as u8)).then_some(id as u8)
    }

    /// Every world cell (col, row), bottom row first.
    pub fn cells(&self) -> impl Iterator<Item = (u32, u32)> + use<> {
        let (w, h) = (self.width, self.height);
        (0..h).flat_map(move |r| (0..w).map(move |c| (c, r)))
    }
}

/// Names of every `level_*.bin` in `dir`, sorted.
pub fn level_names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("cannot list {}: {e}", dir.display()))
        .map(|entry| {
            entry
                .unwrap_or_else(|e| panic!("cannot list {}: {e}", dir.display()))
                .file_name()
                .to_string_lossy()
                .into_owned()
        })
        .filter(|name| name.starts_with("level_") && name.ends_with(".bin"))
        .collect();
    names.sort();
    names
}
