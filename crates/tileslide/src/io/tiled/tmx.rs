//! `.tmx` maps and `.tsx` tile sets through the `tiled` crate, after the first pass of
//! [`super::tmx_scan`] has checked every file it reads.

use std::io::Cursor;
use std::path::{Path, PathBuf};

use glam::Vec2;

use super::Flip;
use super::document::{Document, TileDoc, TileLayerDoc, TileSetDoc};
use super::files::{TiledFiles, read_external};
use super::objects::{MapObject, ObjectLayer, ObjectShape};
use super::properties::{Properties, PropertyValue};
use super::tmx_scan::{self, ScannedLayer};
use crate::HitTypes;
use crate::io::error::as_text;
use crate::io::{LoadError, LoadErrorKind, Location};

/// Serves the map's text from memory and every other file from disk, each checked by the
/// first pass before the `tiled` crate sees it. The first problem is kept for the caller:
/// the `tiled` crate's own report of it would have no position.
pub(super) struct GuardedReader {
    /// The map being parsed (already checked) and its text.
    map: Option<(PathBuf, Vec<u8>)>,
    /// The file that refers to external files (the map), for errors.
    referrer: PathBuf,
    /// External tile set files and where the referrer names them.
    references: Vec<(PathBuf, Location)>,
    /// The first problem found.
    pub failure: Option<LoadError>,
    /// External files given in memory (empty: read from disk).
    files: TiledFiles,
}

impl GuardedReader {
    /// A reader for files that `referrer` refers to.
    pub fn new(referrer: &Path, files: &TiledFiles) -> Self {
        Self {
            map: None,
            referrer: referrer.to_path_buf(),
            references: Vec::new(),
            failure: None,
            files: files.clone(),
        }
    }

    /// Says that `referrer` names the tile set file `path` at `location`.
    pub fn add_reference(&mut self, path: PathBuf, location: Location) {
        self.references.push((path, location));
    }

    fn read_external(&self, path: &Path) -> Result<Vec<u8>, LoadError> {
        let bytes = read_external(path, &self.referrer, &self.files).map_err(|source| {
            let location = match self.references.iter().find(|(p, _)| p == path) {
                Some((_, location)) => *location,
                None => Location::File,
            };
            let kind = LoadErrorKind::Io {
                referenced: Some(path.to_path_buf()),
                source,
            };
            LoadError::new(&self.referrer, location, kind)
        })?;
        let text = as_text(&bytes, path)?;
        tmx_scan::scan_external(text, path)?;
        Ok(bytes)
    }
}

impl ::tiled::ResourceReader for GuardedReader {
    type Resource = Cursor<Vec<u8>>;
    type Error = std::io::Error;

    fn read_from(&mut self, path: &Path) -> Result<Self::Resource, Self::Error> {
        if let Some((_, text)) = self.map.as_ref().filter(|(map_path, _)| map_path == path) {
            return Ok(Cursor::new(text.clone()));
        }
        self.read_external(path).map(Cursor::new).map_err(|e| {
            let io = std::io::Error::other(e.to_string());
            self.failure.get_or_insert(e);
            io
        })
    }
}

/// An error the `tiled` crate reported and the first pass did not foresee (`e`), or a
/// disagreement between the two readings (`message`).
fn crate_error(path: &Path, message: String, e: Option<::tiled::Error>) -> LoadError {
    let kind = LoadErrorKind::Syntax {
        format: "Tiled",
        truncated: false,
        message,
        source: e.map(|e| Box::new(e) as _),
    };
    LoadError::new(path, Location::File, kind)
}

/// An error the `tiled` crate reported and the first pass did not foresee.
fn refused(path: &Path, e: ::tiled::Error) -> LoadError {
    crate_error(path, format!("invalid Tiled file: {e}"), Some(e))
}

/// Parses a `.tmx` map's text; `path` names it and locates its external files.
pub(super) fn parse(
    text: &str,
    path: &Path,
    max_cells: u64,
    files: &TiledFiles,
) -> Result<Document, LoadError> {
    let scan = tmx_scan::scan_map(text, path, max_cells)?;
    let dir = path.parent().unwrap_or(Path::new(""));
    let mut reader = GuardedReader::new(path, files);
    reader.map = Some((path.to_path_buf(), text.as_bytes().to_vec()));
    for r in &scan.tile_sets {
        if let Some(source) = &r.source {
            reader.add_reference(dir.join(source), r.location);
        }
    }
    let mut loader = ::tiled::Loader::with_reader(reader);
    let loaded = loader.load_tmx_map(path);
    let (_, mut reader) = loader.into_inner();
    let map = match loaded {
        Ok(map) => map,
        Err(e) => {
            return Err(reader.failure.take().unwrap_or_else(|| refused(path, e)));
        }
    };
    if map.tilesets().len() != scan.tile_sets.len() {
        return Err(crate_error(
            path,
            "the tiled crate and the first pass disagree on the tile sets".into(),
            None,
        ));
    }
    let first_gids: Vec<u32> = scan.tile_sets.iter().map(|t| t.first_gid).collect();
    let tile_sets = map
        .tilesets()
        .iter()
        .zip(&first_gids)
        .map(|(set, &first_gid)| tile_set_doc(set, first_gid))
        .collect();
    let mut walk = LayerWalk {
        path,
        map: &map,
        first_gids: &first_gids,
        scanned: scan.tile_layers.into_iter(),
        tile_layers: Vec::new(),
        object_layers: Vec::new(),
    };
    walk.layers(map.layers(), Vec2::ZERO)?;
    let (tile_layers, object_layers) = (walk.tile_layers, walk.object_layers);
    Ok(Document {
        tile_size: scan.tile_size,
        tile_sets,
        tile_layers,
        object_layers,
        properties: properties(&map.properties),
    })
}

/// Parses an external `.tsx` tile set for a `.tmj` map that names it at `location`.
pub(super) fn load_tile_set(
    path: &Path,
    referrer: &Path,
    location: Location,
    first_gid: u32,
    files: &TiledFiles,
) -> Result<TileSetDoc, LoadError> {
    let mut reader = GuardedReader::new(referrer, files);
    reader.add_reference(path.to_path_buf(), location);
    let mut loader = ::tiled::Loader::with_reader(reader);
    let loaded = loader.load_tsx_tileset(path);
    let (_, mut reader) = loader.into_inner();
    match loaded {
        Ok(set) => Ok(tile_set_doc(&set, first_gid)),
        Err(e) => Err(reader.failure.take().unwrap_or_else(|| refused(path, e))),
    }
}

fn tile_set_doc(set: &::tiled::Tileset, first_gid: u32) -> TileSetDoc {
    TileSetDoc {
        first_gid,
        name: set.name.clone(),
        file: set.source.clone(),
        tile_size: (set.tile_width, set.tile_height),
        tile_count: set.tilecount,
        tiles: set
            .tiles()
            .map(|(id, tile)| {
                let collision = tile
                    .collision
                    .as_ref()
                    .map(|group| {
                        group
                            .object_data()
                            .iter()
                            .map(|o| object(o, Vec2::ZERO, None))
                            .collect()
                    })
                    .unwrap_or_default();
                let doc = TileDoc {
                    class: tile.user_type.clone(),
                    properties: properties(&tile.properties),
                    collision,
                };
                (id, doc)
            })
            .collect(),
    }
}

/// Walks the layer tree depth first, pairing tile layers with the first pass's.
struct LayerWalk<'a> {
    path: &'a Path,
    map: &'a ::tiled::Map,
    first_gids: &'a [u32],
    scanned: std::vec::IntoIter<ScannedLayer>,
    tile_layers: Vec<TileLayerDoc>,
    object_layers: Vec<ObjectLayer>,
}

impl LayerWalk<'_> {
    fn layers<'m>(
        &mut self,
        layers: impl Iterator<Item = ::tiled::Layer<'m>>,
        offset: Vec2,
    ) -> Result<(), LoadError> {
        for layer in layers {
            let offset = offset + Vec2::new(layer.offset_x, layer.offset_y);
            match layer.layer_type() {
                ::tiled::LayerType::Tiles(_) => {
                    let scanned = self.scanned.next().filter(|s| s.name == layer.name);
                    let Some(scanned) = scanned else {
                        return Err(crate_error(
                            self.path,
                            format!(
                                "the tiled crate and the first pass disagree on layer {:?}",
                                layer.name
                            ),
                            None,
                        ));
                    };
                    self.tile_layers.push(TileLayerDoc {
                        label: format!("layer {:?}", layer.name),
                        name: layer.name.clone(),
                        properties: properties(&layer.properties),
                        offset,
                        cells: scanned.cells,
                        location: scanned.location,
                    });
                }
                ::tiled::LayerType::Objects(group) => {
                    let gids = ObjectGids {
                        map: self.map,
                        first_gids: self.first_gids,
                    };
                    self.object_layers.push(ObjectLayer {
                        name: layer.name.clone(),
                        class: layer.user_type.clone(),
                        properties: properties(&layer.properties),
                        objects: group
                            .object_data()
                            .iter()
                            .map(|o| object(o, offset, Some(&gids)))
                            .collect(),
                    });
                }
                ::tiled::LayerType::Group(group) => self.layers(group.layers(), offset)?,
                ::tiled::LayerType::Image(_) => {}
            }
        }
        Ok(())
    }
}

/// Rebuilds a tile object's gid, which the `tiled` crate splits into a tile set and an id.
struct ObjectGids<'a> {
    map: &'a ::tiled::Map,
    first_gids: &'a [u32],
}

impl ObjectGids<'_> {
    fn gid(&self, tile: &::tiled::ObjectTileData) -> Option<u32> {
        let index = match tile.tileset_location() {
            ::tiled::TilesetLocation::Map(index) => *index,
            // A template's tile set: the map's own set from the same file, if it has one.
            ::tiled::TilesetLocation::Template(set) => self
                .map
                .tilesets()
                .iter()
                .position(|s| s.source == set.source)?,
        };
        let flip = Flip {
            horizontal: tile.flip_h,
            vertical: tile.flip_v,
            diagonal: tile.flip_d,
        };
        let gid = self.first_gids.get(index)?.checked_add(tile.id())?;
        Some(gid | flip.bits())
    }
}

fn object(o: &::tiled::ObjectData, offset: Vec2, gids: Option<&ObjectGids<'_>>) -> MapObject {
    let points = |list: &[(f32, f32)]| list.iter().map(|&(x, y)| Vec2::new(x, y)).collect();
    let (shape, size) = match &o.shape {
        ::tiled::ObjectShape::Rect { width, height } => {
            (ObjectShape::Rectangle, Vec2::new(*width, *height))
        }
        ::tiled::ObjectShape::Ellipse { width, height } => {
            (ObjectShape::Ellipse, Vec2::new(*width, *height))
        }
        ::tiled::ObjectShape::Capsule { width, height } => {
            (ObjectShape::Capsule, Vec2::new(*width, *height))
        }
        ::tiled::ObjectShape::Polyline { points: p } => {
            (ObjectShape::Polyline(points(p)), Vec2::ZERO)
        }
        ::tiled::ObjectShape::Polygon { points: p } => {
            (ObjectShape::Polygon(points(p)), Vec2::ZERO)
        }
        ::tiled::ObjectShape::Point(..) => (ObjectShape::Point, Vec2::ZERO),
        ::tiled::ObjectShape::Text {
            text,
            width,
            height,
            ..
        } => (ObjectShape::Text(text.clone()), Vec2::new(*width, *height)),
    };
    MapObject {
        id: o.id(),
        name: o.name.clone(),
        class: o.user_type.clone(),
        position: Vec2::new(o.x, o.y) + offset,
        size,
        rotation: o.rotation,
        visible: o.visible,
        shape,
        gid: o
            .tile_data()
            .and_then(|tile| gids.and_then(|g| g.gid(&tile))),
        properties: properties(&o.properties),
        hit_types: HitTypes::NONE,
    }
}

fn properties(from: &::tiled::Properties) -> Properties {
    from.iter()
        .map(|(name, value)| (name.clone(), property(value)))
        .collect()
}

fn property(value: &::tiled::PropertyValue) -> PropertyValue {
    use ::tiled::PropertyValue as P;
    match value {
        P::BoolValue(b) => PropertyValue::Bool(*b),
        P::FloatValue(f) => PropertyValue::Float(*f),
        P::IntValue(i) => PropertyValue::Int(*i),
        P::ColorValue(c) => {
            PropertyValue::Color(u32::from_be_bytes([c.alpha, c.red, c.green, c.blue]))
        }
        P::StringValue(s) => PropertyValue::String(s.clone()),
        P::FileValue(s) => PropertyValue::File(s.clone()),
        P::ObjectValue(id) => PropertyValue::Object(*id),
        P::ListValue(items) => PropertyValue::List(items.iter().map(property).collect()),
        P::ClassValue {
            property_type,
            properties: members,
        } => PropertyValue::Class {
            class: property_type.clone(),
            properties: properties(members),
        },
    }
}
