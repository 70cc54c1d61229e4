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
use super::objects::ObjectLayer;
use super::tile_data::{self, Encoding, count_message};
use super::tmj_schema::{JsonData, JsonKind, JsonLayer, JsonMap, JsonTileSet, object, properties};
use super::{Flip, invalid, line_column, tmx};
use crate::io::{LoadError, LoadErrorKind, Location};

/// A JSON syntax or shape error at serde_json's line and column (converted to characters).
fn json_error(text: &str, path: &Path, e: &serde_json::Error) -> LoadError {
    let (line, byte_column) = (e.line(), e.column());
    let column = text
        .lines()
        .nth(line.saturating_sub(1))
        .map(|l| {
            let mut end = byte_column.saturating_sub(1).min(l.len());
            while !l.is_char_boundary(end) {
                end -= 1;
            }
            l[..end].chars().count() + 1
        })
        .unwrap_or(byte_column);
    // At the end of a truncated file serde_json points at its last character; the file
    // ends just past it, as XML errors say.
    let location = if e.is_eof() {
        line_column(text, text.len())
    } else if line == 0 {
        Location::File
    } else {
        Location::LineColumn {
            line: line as u32,
            column: column as u32,
        }
    };
    // serde_json appends " at line L column C": the location already says it.
    let message = e.to_string();
    let message = message.split(" at line ").next().unwrap_or(&message);
    let cause = if e.is_eof() {
        format!("truncated JSON: {message}")
    } else {
        format!("malformed JSON: {message}")
    };
    invalid(path, location, cause)
}

/// Parses a `.tmj` map's text; `path` names it and locates its external tile sets.
pub(super) fn parse(text: &str, path: &Path, max_cells: u64) -> Result<Document, LoadError> {
    let error = |message: String| invalid(path, Location::File, message);
    let json: JsonMap = match serde_json::from_str(text) {
        Ok(json) => json,
        // Valid JSON that fails as a map is most likely some other JSON: say so rather
        // than name the first field it lacks.
        Err(e) => return Err(not_a_map(text).map_or_else(|| json_error(text, path, &e), error)),
    };
    if let Some(why) = kind_mismatch(json.kind.as_deref(), json.orientation.is_some()) {
        return Err(error(why));
    }
    match json.orientation.as_deref() {
        Some("orthogonal") => {}
        Some(other) => {
            return Err(error(format!(
                "`orientation` {other:?} is not supported: tileslide loads orthogonal maps only"
            )));
        }
        None => return Err(error("the map has no `orientation`".into())),
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
        tile_sets.push(tile_set(set, path, &format!("tilesets[{i}]"))?);
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
        properties: properties(&json.properties).map_err(error)?,
    })
}

/// Why valid JSON `text` is not a Tiled map, or `None` if it may be one (or is not valid
/// JSON, which the map parser names at its line and column).
fn not_a_map(text: &str) -> Option<String> {
    match serde_json::from_str::<JsonKind>(text) {
        Ok(probe) => kind_mismatch(probe.kind.as_deref(), probe.orientation.is_some()),
        Err(_) => serde_json::from_str::<de::IgnoredAny>(text)
            .ok()
            .map(|_| "not a Tiled JSON map: the file is JSON but not an object".to_string()),
    }
}

/// Why a JSON object whose `type` is `kind` is not a Tiled map: Tiled writes `"type": "map"`
/// (since 1.2; older maps have no `type` but have an `orientation`).
fn kind_mismatch(kind: Option<&str>, has_orientation: bool) -> Option<String> {
    match kind {
        Some("map") => None,
        Some("tileset") => Some("a Tiled tile set (\"type\": \"tileset\"), not a map".into()),
        Some(other) => Some(format!(
            "not a Tiled JSON map: its `type` is {other:?}, not \"map\""
        )),
        None if has_orientation => None,
        None => Some(
            "not a Tiled JSON map: it has neither `\"type\": \"map\"` nor an `orientation`".into(),
        ),
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
    let (Some(width), Some(height)) = (width, height) else {
        return Err(invalid(
            path,
            Location::File,
            format!("{what}: `width` and `height` are required"),
        ));
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
fn tile_set(set: &JsonTileSet, map_path: &Path, field: &str) -> Result<TileSetDoc, LoadError> {
    let first_gid = set
        .firstgid
        .filter(|g| (1..=Flip::GID_MASK).contains(g))
        .ok_or_else(|| {
            invalid(
                map_path,
                Location::File,
                format!(
                    "{field}.firstgid is missing or not from 1 to {}",
                    Flip::GID_MASK
                ),
            )
        })?;
    let Some(source) = &set.source else {
        return tile_set_doc(set, first_gid, map_path, field);
    };
    let file = map_path.parent().unwrap_or(Path::new("")).join(source);
    let extension = file
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    if extension.as_deref() == Some("tsx") {
        return tmx::load_tile_set(&file, map_path, Location::File, first_gid);
    }
    let bytes = std::fs::read(&file).map_err(|e| {
        invalid(
            map_path,
            Location::File,
            format!(
                "{field}: cannot read the external tile set {}: {e}",
                file.display()
            ),
        )
    })?;
    let text = std::str::from_utf8(&bytes).map_err(|e| {
        LoadError::new(
            &file,
            Location::Byte(e.valid_up_to() as u64),
            LoadErrorKind::NotText,
        )
    })?;
    let external: JsonTileSet =
        serde_json::from_str(text).map_err(|e| json_error(text, &file, &e))?;
    tile_set_doc(&external, first_gid, &file, "tile set")
}

fn tile_set_doc(
    set: &JsonTileSet,
    first_gid: u32,
    file: &Path,
    field: &str,
) -> Result<TileSetDoc, LoadError> {
    let error = |m: String| invalid(file, Location::File, format!("{field}: {m}"));
    let (Some(width), Some(height), Some(count)) = (set.tilewidth, set.tileheight, set.tilecount)
    else {
        return Err(error(
            "`tilewidth`, `tileheight` and `tilecount` are required".into(),
        ));
    };
    if width == 0 || height == 0 {
        return Err(error(format!(
            "tile size {width}×{height} must be at least 1×1"
        )));
    }
    let mut tiles = BTreeMap::new();
    for (i, tile) in set.tiles.iter().enumerate() {
        let field = format!("tiles[{i}] (tile {})", tile.id);
        let collision = match &tile.objectgroup {
            Some(group) => group
                .objects
                .iter()
                .enumerate()
                .map(|(j, o)| {
                    object(o, Vec2::ZERO)
                        .map_err(|m| format!("{field}.objectgroup.objects[{j}]: {m}"))
                })
                .collect::<Result<Vec<_>, _>>()
                .map_err(error)?,
            None => Vec::new(),
        };
        let doc = TileDoc {
            class: tile
                .class
                .clone()
                .or_else(|| tile.kind.clone())
                .unwrap_or_default(),
            properties: properties(&tile.properties).map_err(|m| error(format!("{field}: {m}")))?,
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
            let error = |m: String| invalid(self.path, Location::File, format!("{label}: {m}"));
            let offset = offset + Vec2::new(layer.offsetx, layer.offsety);
            match layer.kind.as_str() {
                "tilelayer" => {
                    let cells = self.cells(layer, &label)?;
                    self.tile_layers.push(TileLayerDoc {
                        name: layer.name.clone(),
                        properties: properties(&layer.properties).map_err(error)?,
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
                        .enumerate()
                        .map(|(j, o)| object(o, offset).map_err(|m| format!("objects[{j}]: {m}")))
                        .collect::<Result<Vec<_>, _>>()
                        .map_err(error)?;
                    self.object_layers.push(ObjectLayer {
                        name: layer.name.clone(),
                        class: layer.class.clone(),
                        properties: properties(&layer.properties).map_err(error)?,
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
        let error = |m: String| invalid(self.path, Location::File, format!("{label}: {m}"));
        let compression = layer.compression.as_deref().filter(|c| !c.is_empty());
        if !self.infinite {
            let (width, height) =
                check_grid(self.path, label, layer.width, layer.height, self.max_cells)?;
            let data = layer
                .data
                .as_ref()
                .ok_or_else(|| error("a tile layer needs `data`".into()))?;
            let gids = gids(data, layer.encoding.as_deref(), compression, width, height)
                .map_err(|m| error(format!("data: {m}")))?;
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
                width,
                height,
            )
            .map_err(|m| invalid(self.path, Location::File, format!("{what}.data: {m}")))?;
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

/// The gids of `data` for a `width × height` grid (already within the limits).
fn gids(
    data: &JsonData,
    encoding: Option<&str>,
    compression: Option<&str>,
    width: u32,
    height: u32,
) -> Result<Vec<u32>, String> {
    let cells = width as usize * height as usize;
    match data {
        JsonData::Gids(gids) => {
            if !matches!(encoding, None | Some("csv")) || compression.is_some() {
                return Err(format!(
                    "an array of gids with encoding {:?} and compression {:?}: expected a base64 string",
                    encoding.unwrap_or("csv"),
                    compression.unwrap_or("none")
                ));
            }
            if gids.len() != cells {
                return Err(count_message(gids.len(), false, cells));
            }
            Ok(gids.clone())
        }
        JsonData::Text(text) => {
            let encoding = Encoding::from_attributes(Some(encoding.unwrap_or("csv")), compression)?;
            if encoding == Encoding::Csv {
                return Err("a string of data needs `encoding` = \"base64\"".into());
            }
            tile_data::decode(text, encoding, cells).map_err(|e| e.message)
        }
    }
}
