//! Loading [`TileMapAsset`]s with Bevy's asset server: one match arm per file format, each
//! calling the core's loader.

use std::collections::BTreeMap;
use std::path::{Component, Path, PathBuf};

use bevy::asset::io::Reader;
use bevy::asset::{AssetLoader, LoadContext, ReadAssetBytesError};
use bevy::prelude::*;
use serde::{Deserialize, Serialize};
use thiserror::Error;
use tileslide::io::ldtk::{LdtkMap, LdtkOptions, LdtkProject};
use tileslide::io::tiled::{TiledMap, TiledOptions};
use tileslide::io::{LoadError, LoadErrorKind, ascii, baked, tiled};
use tileslide::{HitTypes, TileId};

use crate::map::TileMapAsset;

/// Most external files (a Tiled map's tile sets and templates, an LDtk level's file) one
/// map may name.
pub const MAX_EXTERNAL_FILES: usize = 256;

/// How a map file is read, per file: Bevy keeps these in the file's `.meta`, or a game
/// gives them when it loads the file
/// (`asset_server.load_builder().with_settings(|s: &mut TileMapSettings| …).load(path)`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TileMapSettings {
    /// The side of an ASCII map's cells, in map units (default 1).
    pub cell_size: f32,
    /// The tile layer that collides, for the formats with layers (a Tiled layer's name,
    /// `NAME#N` or `#N`; an LDtk layer's identifier); `None`: the format's default (see
    /// `tileslide::io::tiled` and `tileslide::io::ldtk`).
    pub layer: Option<String>,
    /// The level of an LDtk project (its identifier); `None`: its first level.
    #[serde(default)]
    pub level: Option<String>,
    /// Most cells the map may have, checked before anything is allocated; `None`: the core's
    /// limit (`tileslide::limits::MAX_CELLS`).
    pub max_cells: Option<u64>,
}

impl Default for TileMapSettings {
    fn default() -> Self {
        Self {
            cell_size: 1.0,
            layer: None,
            level: None,
            max_cells: None,
        }
    }
}

/// Why a map file did not load. Each names the file (its asset path).
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum MapLoadError {
    /// The file could not be read.
    #[error("{path}: could not read the map: {source}")]
    Read {
        /// The map's asset path.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// The core's loader refused the file; its error names the file, the position and the
    /// cause.
    #[error(transparent)]
    Load(#[from] LoadError),
    /// A file the map names (a tile set, a template, a level file) could not be read.
    #[error("{path}: could not read `{file}`, which it names: {source}")]
    External {
        /// The map's asset path.
        path: PathBuf,
        /// The file it names, as an asset path.
        file: String,
        /// Why.
        source: ReadAssetBytesError,
    },
    /// The map names more external files than [`MAX_EXTERNAL_FILES`].
    #[error("{path}: names more than {max} external files")]
    TooManyFiles {
        /// The map's asset path.
        path: PathBuf,
        /// The limit.
        max: usize,
    },
    /// The file's extension is none this loader reads.
    #[error("{path}: not a map this loader reads (expected .txt, .tmx, .tmj, .ldtk or .tsm)")]
    UnknownFormat {
        /// The map's asset path.
        path: PathBuf,
    },
}

/// The file formats the loader reads, told by the extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum MapFormat {
    Ascii,
    Tmx,
    Tmj,
    Ldtk,
    Baked,
}

impl MapFormat {
    fn of(path: &Path) -> Option<Self> {
        let extension = path.extension()?.to_str()?.to_ascii_lowercase();
        Some(match extension.as_str() {
            "txt" => Self::Ascii,
            "tmx" => Self::Tmx,
            "tmj" => Self::Tmj,
            "ldtk" => Self::Ldtk,
            "tsm" => Self::Baked,
            _ => return None,
        })
    }
}

/// Loads [`TileMapAsset`]s from `.txt`, `.tmx`, `.tmj`, `.ldtk` and `.tsm` files through the
/// core's loaders (`tileslide::io`). A Tiled map's external tile sets and templates, and an
/// LDtk level's `.ldtkl` file, are read through Bevy's asset sources too (never from outside
/// the map's folder), so they reload the map when they change.
#[derive(Clone, Copy, Debug, Default, TypePath)]
pub struct TileMapLoader;

impl AssetLoader for TileMapLoader {
    type Asset = TileMapAsset;
    type Settings = TileMapSettings;
    type Error = MapLoadError;

    async fn load(
        &self,
        reader: &mut dyn Reader,
        settings: &TileMapSettings,
        load_context: &mut LoadContext<'_>,
    ) -> Result<TileMapAsset, MapLoadError> {
        let path = load_context.path().path().to_path_buf();
        let mut bytes = Vec::new();
        reader
            .read_to_end(&mut bytes)
            .await
            .map_err(|source| MapLoadError::Read {
                path: path.clone(),
                source,
            })?;
        let Some(format) = MapFormat::of(&path) else {
            return Err(MapLoadError::UnknownFormat { path });
        };
        match format {
            MapFormat::Ascii => {
                let text = text_of(&bytes, &path)?;
                let map = ascii::parse(text, &path, settings.cell_size)?;
                Ok(TileMapAsset::new(map))
            }
            MapFormat::Baked => Ok(TileMapAsset::new(baked::parse(&bytes, &path)?)),
            MapFormat::Tmx | MapFormat::Tmj => {
                let text = text_of(&bytes, &path)?;
                let level = load_tiled(text, format, settings, &path, load_context).await?;
                Ok(tiled_asset(level))
            }
            MapFormat::Ldtk => {
                let text = text_of(&bytes, &path)?;
                let level = load_ldtk(text, settings, &path, load_context).await?;
                Ok(ldtk_asset(level))
            }
        }
    }

    fn extensions(&self) -> &[&str] {
        &["txt", "tmx", "tmj", "ldtk", "tsm"]
    }
}

/// The file's text, or the core's error naming the first byte that is not UTF-8.
fn text_of<'a>(bytes: &'a [u8], path: &Path) -> Result<&'a str, LoadError> {
    std::str::from_utf8(bytes).map_err(|e| {
        LoadError::new(
            path,
            tileslide::io::Location::Byte(e.valid_up_to() as u64),
            LoadErrorKind::NotText,
        )
    })
}

/// A name no file can have (paths hold no NUL byte): given in memory, it tells the core's
/// Tiled and LDtk loaders to take every external file from memory, never from the disk, and
/// to report the first one they lack, which is then read through Bevy and given.
const NO_FILE: &str = "\0";

/// Parses a Tiled map, reading each external file it names through `load_context` as the
/// parse asks for it.
async fn load_tiled(
    text: &str,
    format: MapFormat,
    settings: &TileMapSettings,
    path: &Path,
    load_context: &mut LoadContext<'_>,
) -> Result<TiledMap, MapLoadError> {
    let mut options = TiledOptions::default();
    if let Some(layer) = &settings.layer {
        options = options.with_layer(layer.clone());
    }
    if let Some(cells) = settings.max_cells {
        options = options.with_max_cells(cells);
    }
    with_files(path, load_context, |files| {
        let options = TiledOptions {
            files: files.clone(),
            ..options.clone()
        };
        match format {
            MapFormat::Tmx => tiled::parse_tmx(text, path, &options),
            _ => tiled::parse_tmj(text, path, &options),
        }
    })
    .await
}

/// Parses an LDtk project and builds the level the settings choose, reading its level file
/// (if it has one) through `load_context`. The core refuses a level file outside the
/// project's folder before it is asked for.
async fn load_ldtk(
    text: &str,
    settings: &TileMapSettings,
    path: &Path,
    load_context: &mut LoadContext<'_>,
) -> Result<LdtkMap, MapLoadError> {
    let project = LdtkProject::parse(text, path)?;
    let mut options = LdtkOptions::default();
    if let Some(level) = &settings.level {
        options = options.with_level(level.clone());
    }
    if let Some(layer) = &settings.layer {
        options = options.with_layer(layer.clone());
    }
    if let Some(cells) = settings.max_cells {
        options = options.with_max_cells(cells);
    }
    with_files(path, load_context, |files| {
        project.build(&LdtkOptions {
            files: files.clone(),
            ..options.clone()
        })
    })
    .await
}

/// Runs `parse` with the external files read so far (given in memory, so that the core's
/// loader never reads the disk), reading each one it reports missing through
/// `load_context` and running it again, until it succeeds or fails otherwise.
async fn with_files<T>(
    path: &Path,
    load_context: &mut LoadContext<'_>,
    mut parse: impl FnMut(&BTreeMap<String, Vec<u8>>) -> Result<T, LoadError>,
) -> Result<T, MapLoadError> {
    let mut files = BTreeMap::from([(NO_FILE.to_owned(), Vec::new())]);
    let dir = path.parent().unwrap_or(Path::new(""));
    loop {
        let error = match parse(&files) {
            Ok(parsed) => return Ok(parsed),
            Err(e) => e,
        };
        // A file the parse asked for and was not given: read it and parse again.
        let Some(name) = missing_file(&error, dir).filter(|n| !files.contains_key(n)) else {
            return Err(error.into());
        };
        if files.len() > MAX_EXTERNAL_FILES {
            return Err(MapLoadError::TooManyFiles {
                path: path.to_path_buf(),
                max: MAX_EXTERNAL_FILES,
            });
        }
        let asset_path = load_context
            .path()
            .resolve_embed_str(&name)
            .map_err(|_| MapLoadError::Load(error))?;
        let bytes = load_context
            .read_asset_bytes(asset_path.clone())
            .await
            .map_err(|source| MapLoadError::External {
                path: path.to_path_buf(),
                file: asset_path.to_string(),
                source,
            })?;
        files.insert(name, bytes);
    }
}

/// The name (relative to the map's folder `dir`, `/`-separated, as the loader looks files
/// up) of the external file whose absence `error` reports, if it reports one.
fn missing_file(error: &LoadError, dir: &Path) -> Option<String> {
    let LoadErrorKind::Io {
        referenced: Some(file),
        source,
    } = &error.kind
    else {
        return None;
    };
    if source.kind() != std::io::ErrorKind::NotFound {
        return None;
    }
    let relative = file.strip_prefix(dir).unwrap_or(file);
    let mut parts: Vec<String> = Vec::new();
    for c in relative.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir if parts.last().is_some_and(|p| p != "..") => {
                parts.pop();
            }
            other => parts.push(other.as_os_str().to_string_lossy().into_owned()),
        }
    }
    Some(parts.join("/"))
}

/// The asset of a loaded Tiled map: its collision layer, its tiles' hit types and its object
/// layers.
fn tiled_asset(level: TiledMap) -> TileMapAsset {
    let tile_hits: BTreeMap<TileId, HitTypes> = level
        .map
        .tile_set()
        .iter()
        .filter_map(|(id, _)| {
            let hits = level.tile_info(id)?.hit_types;
            (!hits.is_empty()).then_some((id, hits))
        })
        .collect();
    let TiledMap {
        map, object_layers, ..
    } = level;
    TileMapAsset {
        tile_hits,
        object_layers,
        ..TileMapAsset::new(map)
    }
}

/// The asset of a loaded LDtk level: its collision layer, its entity layers and the
/// project's levels.
fn ldtk_asset(level: LdtkMap) -> TileMapAsset {
    let level_index = level.level_index;
    let LdtkMap {
        map,
        entity_layers,
        mut levels,
        ..
    } = level;
    TileMapAsset {
        entity_layers,
        level: (level_index < levels.len()).then(|| levels.swap_remove(level_index)),
        ..TileMapAsset::new(map)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats_are_told_by_the_extension_in_any_case() {
        assert_eq!(MapFormat::of(Path::new("a/b.TXT")), Some(MapFormat::Ascii));
        assert_eq!(MapFormat::of(Path::new("b.tmx")), Some(MapFormat::Tmx));
        assert_eq!(MapFormat::of(Path::new("b.tmj")), Some(MapFormat::Tmj));
        assert_eq!(MapFormat::of(Path::new("b.LDtk")), Some(MapFormat::Ldtk));
        assert_eq!(MapFormat::of(Path::new("b.tsm")), Some(MapFormat::Baked));
        assert_eq!(MapFormat::of(Path::new("b.json")), None);
        assert_eq!(MapFormat::of(Path::new("b")), None);
    }

    #[test]
    fn a_missing_file_is_named_relative_to_the_map() {
        let error = |file: &str, kind| {
            LoadError::new(
                "maps/level.tmj",
                tileslide::io::Location::File,
                LoadErrorKind::Io {
                    referenced: Some(PathBuf::from(file)),
                    source: std::io::Error::from(kind),
                },
            )
        };
        let dir = Path::new("maps");
        let not_found = std::io::ErrorKind::NotFound;
        assert_eq!(
            missing_file(&error("maps/tiles.tsj", not_found), dir).as_deref(),
            Some("tiles.tsj")
        );
        assert_eq!(
            missing_file(&error("maps/./sets/../x.tsx", not_found), dir).as_deref(),
            Some("x.tsx")
        );
        assert_eq!(
            missing_file(&error("maps/../shared/x.tsx", not_found), dir).as_deref(),
            Some("../shared/x.tsx")
        );
        let denied = std::io::ErrorKind::PermissionDenied;
        assert_eq!(missing_file(&error("maps/tiles.tsj", denied), dir), None);
    }
}
