//! A map file of any format, told by its extension: what bindings to other languages load
//! (`ts_map_load_file` in C, `TileMap.from_file` in Python).

use std::path::Path;
use std::sync::Arc;

use super::{LoadError, LoadErrorKind, Location, ascii, baked, replica};
use crate::TileMap;

/// The extensions [`load_file`] reads, for messages.
const FORMATS: &str = "a .txt ASCII map, a .bin Replica Island level (with its tile set), a \
                       .tsm baked map, a .tmx/.tmj/.json Tiled map or a .ldtk LDtk project";

/// Loads the map at `path`, its format told by its extension, with each loader's defaults:
/// `.txt` an ASCII map of unit cells, `.bin` a Replica Island level with the tile set
/// `tileset` (`collision.bin`; required), `.tsm` a baked map, `.tmx`, `.tmj` and `.json` a
/// Tiled map (feature `tiled`), `.ldtk` an LDtk project's first level (feature `ldtk`).
/// `tileset` is refused for the formats that carry their own.
///
/// # Errors
/// The loader's [`LoadError`] (the file, the position and the cause); an unknown extension,
/// a missing or unwanted tile set, and a format whose feature is off are
/// [`LoadErrorKind::Parameter`] errors naming the file.
///
/// ```
/// let dir = std::env::temp_dir().join("tileslide-load-file-doc");
/// std::fs::create_dir_all(&dir)?;
/// let path = dir.join("room.txt");
/// std::fs::write(&path, "###\n#.#\n###")?;
/// let map = tileslide::io::load_file(&path, None)?;
/// assert_eq!((map.width(), map.height()), (3, 3));
/// let err = tileslide::io::load_file(dir.join("room.png"), None).unwrap_err();
/// assert!(err.to_string().contains("unknown map format"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn load_file(path: impl AsRef<Path>, tileset: Option<&Path>) -> Result<TileMap, LoadError> {
    let path = path.as_ref();
    let refuse = |why: String| LoadError::new(path, Location::File, LoadErrorKind::Parameter(why));
    let extension = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let own_tiles = |format: &str| {
        if tileset.is_some() {
            Err(refuse(format!(
                "{format} carries its own tile set: give no tile set"
            )))
        } else {
            Ok(())
        }
    };
    match extension.as_deref() {
        Some("txt") => {
            own_tiles("an ASCII map")?;
            ascii::load(path, 1.0)
        }
        Some("bin") => {
            let Some(tileset) = tileset else {
                return Err(refuse(
                    "a Replica Island level needs its tile set (collision.bin)".into(),
                ));
            };
            let set = replica::load_tile_set(tileset)?;
            replica::load_level(path, Arc::new(set))
        }
        Some("tsm") => {
            own_tiles("a baked map")?;
            baked::load(path)
        }
        #[cfg(feature = "tiled")]
        Some("tmx" | "tmj" | "json") => {
            own_tiles("a Tiled map")?;
            super::tiled::load(path, &super::tiled::TiledOptions::default()).map(|m| m.map)
        }
        #[cfg(feature = "ldtk")]
        Some("ldtk") => {
            own_tiles("an LDtk project")?;
            super::ldtk::load(path, &super::ldtk::LdtkOptions::default()).map(|m| m.map)
        }
        _ => Err(refuse(format!(
            "unknown map format (expected {FORMATS}; Tiled and LDtk with their features)"
        ))),
    }
}
