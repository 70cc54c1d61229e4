//! `.tmj` maps and `.tsj` tile sets (Tiled's JSON formats) through serde. A `.tmj` map may
//! also name `.tsx` tile sets, which the `tiled` crate reads.
//!
//! Errors in the JSON itself name the line and column (serde_json's); errors in values name
//! the field, as `layers[1].chunks[0].data`.

use std::collections::BTreeMap;
use std::path::Path;

use glam::Vec2;
use serde::de;

use super::document::{Chunk, Document, LayerCells, TileDoc, TileLayerDoc, TileSetDoc};
use super::files::{TiledFiles, read_external};
use super::objects::ObjectLayer;
use super::tile_data::{self, Encoding, count_error};
use super::tmj_schema::{JsonData, JsonKind, JsonLayer, JsonMap, JsonTileSet, object, properties};
use super::{Flip, tmx};
use crate::io::json_text::json_error;
use crate::io::{LoadError, LoadErrorKind, Location, NotTiled, Unsupported};

/// The error `kind` in `path`, a JSON file whose errors (past its syntax) name the field.
fn fail(path: &Path, kind: impl Into<LoadErrorKind>) -> LoadError {
    LoadError::new(path, Location::File, kind.into())
}

/// The error for `owner` without `field`.
fn missing(path: &Path, owner: &str, field: &str) -> LoadError {
    fail(
        path,
        LoadErrorKind::Missing {
            owner: owner.to_owned(),
            field: field.to_owned(),
        },
    )
}

/// Parses a `.tmj` map's text; `path` names it and locates its external tile sets.
pub(super) fn parse(
    text: &str,
    path: &Path,
    max_cells: u64,
    files: &TiledFiles,
) -> Result<Document, LoadError> {
    let json: JsonMap = match serde_json::from_str(text) {
        Ok(json) => json,
        // Valid JSON that fails as a map is most likely some other JSON: say so rather
        // than name the first field it lacks.
        Err(e) => {
            return Err(match not_a_map(text) {
                Some(why) => fail(path, why),
                None => json_error(text, path, e),
            });
        }
    };
    if let Some(why) = kind_mismatch(json.kind.as_deref(), json.orientation.is_some()) {
        return Err(fail(path, why));
    }
    match json.orientation.as_deref() {
        Some("orthogonal") => {}
        Some(other) => return Err(fail(path, Unsupported::Orientation(other.into()))),
        None => return Err(missing(path, "the map", "orientation")),
    }
    for (field, value) in [
        ("tilewidth", json.tilewidth),
        ("tileheight", json.tileheight),
    ] {
        if value == 0 {
            return Err(bad_size(path, field, 0, "must be at least 1".into()));
        }
    }
    if !json.infinite {
        check_grid(path, "map", json.width, json.height, max_cells)?;
    }
    let mut tile_sets = Vec::with_capacity(json.tilesets.len());
    for (i, set) in json.tilesets.iter().enumerate() {
        tile_sets.push(tile_set(set, path, &format!("tilesets[{i}]"), files)?);
    }
    let mut walk = LayerWalk {
        path,
        infinite: json.infinite,
        max_cells,
        tile_layers: Vec::new(),
        object_layers: Vec::new(),
    };
    walk.layers(&json.layers, "layers", Vec2::ZERO)?;
    Ok(Document {
        tile_size: (json.tilewidth, json.tileheight),
        tile_sets,
        tile_layers: walk.tile_layers,
        object_layers: walk.object_layers,
        properties: properties(&json.properties).map_err(|e| fail(path, e.of("the map")))?,
    })
}

/// Why valid JSON `text` is not a Tiled map, or `None` if it may be one (or is not valid
/// JSON, which the map parser names at its line and column).
fn not_a_map(text: &str) -> Option<NotTiled> {
    match serde_json::from_str::<JsonKind>(text) {
        Ok(probe) => kind_mismatch(probe.kind.as_deref(), probe.orientation.is_some()),
        Err(_) => serde_json::from_str::<de::IgnoredAny>(text)
            .ok()
            .map(|_| NotTiled::NotAnObject),
    }
}

/// Why a JSON object whose `type` is `kind` is not a Tiled map: Tiled writes `"type": "map"`
/// (since 1.2; older maps have no `type` but have an `orientation`).
fn kind_mismatch(kind: Option<&str>, has_orientation: bool) -> Option<NotTiled> {
    match kind {
        Some("map") => None,
        Some("tileset") => Some(NotTiled::TileSet),
        Some(other) => Some(NotTiled::JsonType(other.into())),
        None if has_orientation => None,
        None => Some(NotTiled::UntypedJson),
    }
}

fn bad_size(path: &Path, field: &'static str, value: i64, reason: String) -> LoadError {
    LoadError::new(
        path,
        Location::File,
        LoadErrorKind::BadSize {
            field,
            value,
            reason,
        },
    )
}

/// `width` and `height` present, at least 1, and at most `max_cells` cells together.
fn check_grid(
    path: &Path,
    what: &str,
    width: Option<u32>,
    height: Option<u32>,
    max_cells: u64,
) -> Result<(u32, u32), LoadError> {
    let Some(width) = width else {
        return Err(missing(path, what, "width"));
    };
    let Some(height) = height else {
        return Err(missing(path, what, "height"));
    };
    for (field, value) in [("width", width), ("height", height)] {
        if value == 0 {
            return Err(bad_size(
                path,
                field,
                0,
                format!("{what}: must be at least 1"),
            ));
        }
    }
    let cells = u64::from(width) * u64::from(height);
    if cells > max_cells {
        return Err(bad_size(
            path,
            "width × height",
            cells as i64,
            format!(
                "{what}: {width}×{height} is more than {}",
                super::cell_limit(max_cells)
            ),
        ));
    }
    Ok((width, height))
}

/// A map's tile set entry: embedded, or loaded from its `.tsj`/`.tsx` file.
fn tile_set(
    set: &JsonTileSet,
    map_path: &Path,
    field: &str,
    files: &TiledFiles,
) -> Result<TileSetDoc, LoadError> {
    let Some(first_gid) = set.firstgid else {
        return Err(missing(map_path, field, "firstgid"));
    };
    if !(1..=Flip::GID_MASK).contains(&first_gid) {
        return Err(bad_size(
            map_path,
            "firstgid",
            first_gid.into(),
            format!("{field}: must be from 1 to {}", Flip::GID_MASK),
        ));
    }
    let Some(source) = &set.source else {
        return tile_set_doc(set, first_gid, map_path, field);
    };
    let file = map_path.parent().unwrap_or(Path::new("")).join(source);
    let extension = file
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    if extension.as_deref() == Some("tsx") {
        return tmx::load_tile_set(&file, map_path, Location::File, first_gid, files);
    }
    let bytes = read_external(&file, map_path, files).map_err(|source| {
        let kind = LoadErrorKind::Io {
            referenced: Some(file.clone()),
            source,
        };
        fail(map_path, kind)
    })?;
    let text = std::str::from_utf8(&bytes).map_err(|e| {
        LoadError::new(
            &file,
            Location::Byte(e.valid_up_to() as u64),
            LoadErrorKind::NotText,
        )
    })?;
    let external: JsonTileSet =
        serde_json::from_str(text).map_err(|e| json_error(text, &file, e))?;
    tile_set_doc(&external, first_gid, &file, "tile set")
}

fn tile_set_doc(
    set: &JsonTileSet,
    first_gid: u32,
    file: &Path,
    field: &str,
) -> Result<TileSetDoc, LoadError> {
    let owner = format!("{field} {:?}", set.name);
    let [Some(width), Some(height), Some(count)] = [set.tilewidth, set.tileheight, set.tilecount]
    else {
        let absent = [
            ("tilewidth", set.tilewidth),
            ("tileheight", set.tileheight),
            ("tilecount", set.tilecount),
        ]
        .into_iter()
        .find_map(|(name, v)| v.is_none().then_some(name))
        .unwrap_or("tilecount");
        return Err(missing(file, &owner, absent));
    };
    for (name, value) in [("tilewidth", width), ("tileheight", height)] {
        if value == 0 {
            return Err(bad_size(
                file,
                name,
                0,
                format!("{owner}: must be at least 1"),
            ));
        }
    }
    let mut tiles = BTreeMap::new();
    for (i, tile) in set.tiles.iter().enumerate() {
        let field = format!("{owner}, tiles[{i}] (tile {})", tile.id);
        let collision = match &tile.objectgroup {
            Some(group) => group
                .objects
                .iter()
                .map(|o| object(o, Vec2::ZERO).map_err(|kind| fail(file, kind)))
                .collect::<Result<Vec<_>, _>>()?,
            None => Vec::new(),
        };
        let doc = TileDoc {
            class: tile
                .class
                .clone()
                .or_else(|| tile.kind.clone())
                .unwrap_or_default(),
            properties: properties(&tile.properties).map_err(|e| fail(file, e.of(&field)))?,
            collision,
        };
        tiles.insert(tile.id, doc);
    }
    Ok(TileSetDoc {
        first_gid,
        name: set.name.clone(),
        file: file.to_path_buf(),
        tile_size: (width, height),
        tile_count: count,
        tiles,
    })
}

struct LayerWalk<'a> {
    path: &'a Path,
    infinite: bool,
    /// Most cells a layer (or an infinite layer's chunks together) may hold.
    max_cells: u64,
    tile_layers: Vec<TileLayerDoc>,
    object_layers: Vec<ObjectLayer>,
}

impl LayerWalk<'_> {
    fn layers(&mut self, layers: &[JsonLayer], field: &str, offset: Vec2) -> Result<(), LoadError> {
        for (i, layer) in layers.iter().enumerate() {
            let field = format!("{field}[{i}]");
            let label = format!("{field} ({:?})", layer.name);
            let property = |e: super::properties::PropertyFault| fail(self.path, e.of(&label));
            let offset = offset + Vec2::new(layer.offsetx, layer.offsety);
            match layer.kind.as_str() {
                "tilelayer" => {
                    let cells = self.cells(layer, &label)?;
                    self.tile_layers.push(TileLayerDoc {
                        name: layer.name.clone(),
                        properties: properties(&layer.properties).map_err(property)?,
                        offset,
                        cells,
                        location: Location::File,
                        label,
                    });
                }
                "objectgroup" => {
                    let objects = layer
                        .objects
                        .iter()
                        .map(|o| object(o, offset).map_err(|kind| fail(self.path, kind)))
                        .collect::<Result<Vec<_>, _>>()?;
                    self.object_layers.push(ObjectLayer {
                        name: layer.name.clone(),
                        class: layer.class.clone(),
                        properties: properties(&layer.properties).map_err(property)?,
                        objects,
                    });
                }
                "group" => self.layers(&layer.layers, &format!("{field}.layers"), offset)?,
                _ => {}
            }
        }
        Ok(())
    }

    fn cells(&self, layer: &JsonLayer, label: &str) -> Result<LayerCells, LoadError> {
        let compression = layer.compression.as_deref().filter(|c| !c.is_empty());
        if !self.infinite {
            let (width, height) =
                check_grid(self.path, label, layer.width, layer.height, self.max_cells)?;
            let data = layer
                .data
                .as_ref()
                .ok_or_else(|| missing(self.path, label, "data"))?;
            let gids = gids(
                data,
                layer.encoding.as_deref(),
                compression,
                (width, height),
                label,
            )
            .map_err(|kind| fail(self.path, kind))?;
            return Ok(LayerCells::Finite {
                width,
                height,
                gids,
            });
        }
        let chunks = layer.chunks.as_deref().unwrap_or_default();
        let mut out = Vec::with_capacity(chunks.len());
        let mut total = 0u64;
        for (j, chunk) in chunks.iter().enumerate() {
            let what = format!("{label}.chunks[{j}]");
            const FAR: i32 = 1 << 30;
            if !((-FAR..=FAR).contains(&chunk.x) && (-FAR..=FAR).contains(&chunk.y)) {
                return Err(bad_size(
                    self.path,
                    "x, y",
                    chunk.x.max(chunk.y).into(),
                    format!("{what}: chunks must lie within ±{FAR} cells"),
                ));
            }
            let (width, height) = check_grid(
                self.path,
                &what,
                Some(chunk.width),
                Some(chunk.height),
                self.max_cells,
            )?;
            total += u64::from(width) * u64::from(height);
            if total > self.max_cells {
                return Err(bad_size(
                    self.path,
                    "width × height",
                    total as i64,
                    format!(
                        "{label}: the layer's chunks hold more than {}",
                        super::cell_limit(self.max_cells)
                    ),
                ));
            }
            let gids = gids(
                &chunk.data,
                layer.encoding.as_deref(),
                compression,
                (width, height),
                &what,
            )
            .map_err(|kind| fail(self.path, kind))?;
            out.push(Chunk {
                x: chunk.x,
                y: chunk.y,
                width,
                height,
                gids,
            });
        }
        Ok(LayerCells::Chunks(out))
    }
}

/// The gids of `owner`'s `data` for a `width × height` grid (already within the limits).
fn gids(
    data: &JsonData,
    encoding: Option<&str>,
    compression: Option<&str>,
    (width, height): (u32, u32),
    owner: &str,
) -> Result<Vec<u32>, LoadErrorKind> {
    let cells = width as usize * height as usize;
    let bad_value = |field, found, expected| LoadErrorKind::BadValue {
        owner: owner.to_owned(),
        field,
        found,
        expected,
    };
    match data {
        JsonData::Gids(gids) => {
            if !matches!(encoding, None | Some("csv")) || compression.is_some() {
                return Err(bad_value(
                    "data",
                    format!(
                        "an array of gids with encoding {:?} and compression {:?}",
                        encoding.unwrap_or("csv"),
                        compression.unwrap_or("none")
                    ),
                    "a base64 string",
                ));
            }
            if gids.len() != cells {
                return Err(count_error(owner, gids.len(), false, cells));
            }
            Ok(gids.clone())
        }
        JsonData::Text(text) => {
            let encoding =
                Encoding::from_attributes(Some(encoding.unwrap_or("csv")), compression, owner)?;
            if encoding == Encoding::Csv {
                return Err(bad_value(
                    "encoding",
                    "\"csv\" for a string of data".into(),
                    "\"base64\"",
                ));
            }
            tile_data::decode(text, encoding, cells, owner).map_err(|e| e.kind)
        }
    }
}
