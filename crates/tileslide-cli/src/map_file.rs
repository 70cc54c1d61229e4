//! Loading the MAP argument by its extension.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use anyhow::{Result, bail};
use clap::Args;
use tileslide::TileMap;
use tileslide::io::ldtk::{self, LdtkOptions};
use tileslide::io::tiled::{self, TiledOptions};
use tileslide::io::{LoadErrorKind, ascii, baked, replica};
use tileslide_platformer::{Level, MARKERS};

/// The map arguments shared by every command that reads a map.
#[derive(Args, Debug)]
pub struct MapArgs {
    /// The map: `.txt` ASCII map, `.bin` Replica Island level (needs `--tileset`), `.tsm`
    /// baked map (`tileslide bake`), `.tmx`/`.tmj`/`.json` Tiled map (in Tiled's pixels,
    /// y down), or `.ldtk` LDtk project (in world pixels, y down).
    pub map: PathBuf,
    /// The tile set for maps that need one (Replica Island: `collision.bin`).
    #[arg(long, value_name = "FILE")]
    pub tileset: Option<PathBuf>,
    /// Cell size of an ASCII map (default 1).
    #[arg(long, value_name = "SIZE")]
    pub cell: Option<f32>,
    /// The tile layer that collides in a Tiled map: its name, `NAME#2` for the second layer
    /// of that name, or `#3` for the third tile layer (default: the first tile layer with the
    /// property `collision = true`, else the first tile layer). In an LDtk project: the
    /// IntGrid, auto-layer or tile layer's identifier (default: the first IntGrid layer,
    /// else the first whose tiles name a collision shape).
    #[arg(long, value_name = "NAME")]
    pub layer: Option<String>,
    /// The level of an LDtk project, by its identifier (default: the first).
    #[arg(long, value_name = "NAME")]
    pub level: Option<String>,
    #[command(flatten)]
    pub limits: TiledLimits,
}

/// Bounds on what a Tiled map or an LDtk project may cost to load.
#[derive(Args, Debug, Default)]
pub struct TiledLimits {
    /// Most cells a Tiled map's or an LDtk level's layer may hold (default and most: 2^26).
    #[arg(long, value_name = "CELLS")]
    pub max_cells: Option<u64>,
    /// Most cells an infinite Tiled map may span per cell its chunks hold, once over 2^20
    /// cells (default 64): refuses a few chunks far apart.
    #[arg(long, value_name = "RATIO")]
    pub max_chunk_spread: Option<u64>,
}

/// The kind of map file, from its extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MapFormat {
    Ascii,
    /// An ASCII map with the platformer demo's markers (`examples/maps/platformer.txt`).
    PlatformerLevel,
    ReplicaIsland,
    Baked,
    TiledXml,
    TiledJson,
    Ldtk,
}

impl MapFormat {
    pub fn name(self) -> &'static str {
        match self {
            MapFormat::Ascii => "ascii",
            MapFormat::PlatformerLevel => "ascii-platformer",
            MapFormat::ReplicaIsland => "replica-island",
            MapFormat::Baked => "baked",
            MapFormat::TiledXml => "tiled-tmx",
            MapFormat::TiledJson => "tiled-tmj",
            MapFormat::Ldtk => "ldtk",
        }
    }

    fn of(path: &Path) -> Result<Self> {
        match path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase)
            .as_deref()
        {
            Some("txt") => Ok(MapFormat::Ascii),
            Some("bin") => Ok(MapFormat::ReplicaIsland),
            Some("tsm") => Ok(MapFormat::Baked),
            Some("tmx") => Ok(MapFormat::TiledXml),
            // Tiled saves JSON maps as `.json` as often as `.tmj`; the loader tells a map from
            // a tile set or other JSON by its content, and names what it found.
            Some("tmj" | "json") => Ok(MapFormat::TiledJson),
            Some("ldtk") => Ok(MapFormat::Ldtk),
            _ => bail!(
                "{}: unknown map format (expected a .txt ASCII map, a .bin Replica Island level, a .tsm baked map, a .tmx/.tmj/.json Tiled map or a .ldtk LDtk project)",
                path.display()
            ),
        }
    }
}

/// Loads the map the arguments name.
pub fn load(args: &MapArgs) -> Result<(TileMap, MapFormat)> {
    if args.map.is_dir() {
        bail!(
            "{}: is a folder; give a map file (a .txt ASCII map, a .bin Replica Island level, a .tsm baked map, a .tmx/.tmj/.json Tiled map or a .ldtk LDtk project)",
            args.map.display()
        );
    }
    let mut format = MapFormat::of(&args.map)?;
    let tiled = matches!(format, MapFormat::TiledXml | MapFormat::TiledJson);
    let ldtk = format == MapFormat::Ldtk;
    if args.layer.is_some() && !tiled && !ldtk {
        bail!(
            "{}: --layer chooses the collision layer of a Tiled map (.tmx, .tmj, .json) or an LDtk project (.ldtk); drop it",
            args.map.display()
        );
    }
    if args.level.is_some() && !ldtk {
        bail!(
            "{}: --level chooses the level of an LDtk project (.ldtk); drop it",
            args.map.display()
        );
    }
    if args.limits.max_cells.is_some() && !tiled && !ldtk {
        bail!(
            "{}: --max-cells bounds Tiled maps (.tmx, .tmj, .json) and LDtk projects (.ldtk); drop it",
            args.map.display()
        );
    }
    if args.limits.max_chunk_spread.is_some() && !tiled {
        bail!(
            "{}: --max-chunk-spread bounds infinite Tiled maps (.tmx, .tmj, .json); drop it",
            args.map.display()
        );
    }
    let map = match format {
        MapFormat::Ascii | MapFormat::PlatformerLevel => {
            if args.tileset.is_some() {
                bail!(
                    "{}: an ASCII map uses the built-in tile set; drop --tileset",
                    args.map.display()
                );
            }
            match ascii::load(&args.map, args.cell.unwrap_or(1.0)) {
                Ok(map) => map,
                Err(e) => match e.kind {
                    // The platformer demo's levels are ASCII maps with markers on top.
                    LoadErrorKind::UnknownCharacter(c) if MARKERS.contains(c) => {
                        format = MapFormat::PlatformerLevel;
                        platformer_level(args)?
                    }
                    _ => return Err(e.into()),
                },
            }
        }
        MapFormat::ReplicaIsland => {
            if args.cell.is_some() {
                bail!(
                    "{}: --cell applies to ASCII maps; a Replica Island level's cells are its tiles' 32 pixels",
                    args.map.display()
                );
            }
            let Some(tileset) = &args.tileset else {
                bail!(
                    "{}: a Replica Island level needs its tile set: add --tileset collision.bin",
                    args.map.display()
                );
            };
            let set = replica::load_tile_set(tileset)?;
            replica::load_level(&args.map, Arc::new(set))?
        }
        MapFormat::Baked => {
            if args.tileset.is_some() || args.cell.is_some() {
                bail!(
                    "{}: a baked map carries its own tile set and cell size; drop --tileset and --cell",
                    args.map.display()
                );
            }
            baked::load(&args.map)?
        }
        MapFormat::TiledXml | MapFormat::TiledJson => {
            if args.tileset.is_some() || args.cell.is_some() {
                bail!(
                    "{}: a Tiled map names its own tile sets and cell size; drop --tileset and --cell",
                    args.map.display()
                );
            }
            let defaults = TiledOptions::default();
            let options = TiledOptions {
                layer: args.layer.clone(),
                max_cells: args.limits.max_cells.unwrap_or(defaults.max_cells),
                max_chunk_spread: args
                    .limits
                    .max_chunk_spread
                    .unwrap_or(defaults.max_chunk_spread),
                ..defaults
            };
            tiled::load(&args.map, &options)?.map
        }
        MapFormat::Ldtk => {
            if args.tileset.is_some() || args.cell.is_some() {
                bail!(
                    "{}: an LDtk project names its own tile sets and cell sizes; drop --tileset and --cell",
                    args.map.display()
                );
            }
            let defaults = LdtkOptions::default();
            let options = LdtkOptions {
                level: args.level.clone(),
                layer: args.layer.clone(),
                max_cells: args.limits.max_cells.unwrap_or(defaults.max_cells),
                ..defaults
            };
            ldtk::load(&args.map, &options)?.map
        }
    };
    Ok((map, format))
}

/// The map of a platformer level (an ASCII map with the demo's markers `P`, `G`, `o`, `E`,
/// `M`, each an empty cell), whose cells are of size 1.
fn platformer_level(args: &MapArgs) -> Result<TileMap> {
    if args.cell.is_some_and(|c| c != 1.0) {
        bail!(
            "{}: a platformer level (an ASCII map with the demo's markers {MARKERS}) has cells of size 1; drop --cell",
            args.map.display()
        );
    }
    Ok(Level::load_ascii(&args.map)?.map)
}
