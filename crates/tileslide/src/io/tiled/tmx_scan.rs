//! A first pass over every XML file of a `.tmx` map (the map, its `.tsx` tile sets, its
//! `.tx` templates) with quick-xml, before the `tiled` crate reads them.
//!
//! The `tiled` crate's errors carry no position, it allocates from a tile set's `tilecount`
//! without a bound, it reads a tile layer's `<data>` without checking it against the layer's
//! size (and then indexes out of bounds), and it drops the hexagonal rotation bit of gids.
//! This pass finds malformed and truncated XML with its line and column, refuses absurd
//! sizes before anything is allocated from them, refuses unknown encodings and
//! non-orthogonal maps at their element, and decodes each tile layer's gids (with the
//! decoder `.tmj` maps use) so the layer's size is checked and no bit is lost.

use std::path::Path;

use super::document::{Chunk, LayerCells};
use super::tile_data::{self, DataError, Encoding};
use super::xml_walker::{Element, Item, Walker};
use super::{MAX_TILE_COUNT, line_column};
use crate::io::{LoadError, Location, NotTiled, Unsupported};

/// What the first pass learned about a map.
#[derive(Debug)]
pub(super) struct ScannedMap {
    /// The grid cell size in pixels.
    pub tile_size: (u32, u32),
    /// The map's `<tileset>` elements, in order.
    pub tile_sets: Vec<TileSetRef>,
    /// The tile layers, in document order (group members included).
    pub tile_layers: Vec<ScannedLayer>,
}

/// A `<tileset>` element of the map.
#[derive(Debug)]
pub(super) struct TileSetRef {
    pub first_gid: u32,
    /// The external file, as written.
    pub source: Option<String>,
    pub location: Location,
}

/// A `<layer>` element and its decoded gids.
#[derive(Debug)]
pub(super) struct ScannedLayer {
    pub name: String,
    pub location: Location,
    pub cells: LayerCells,
}

impl Walker<'_> {
    /// `width` and `height` of at least 1 whose product is at most the walk's `max_cells`.
    fn grid_size(&self, element: &Element) -> Result<(u32, u32), LoadError> {
        let width: u32 = self.required(element, "width", "a whole number")?;
        let height: u32 = self.required(element, "height", "a whole number")?;
        for (field, value) in [("width", width), ("height", height)] {
            if value == 0 {
                return Err(self.size_error(element.offset, field, 0, "must be at least 1".into()));
            }
        }
        check_cells(self, element, width, height)?;
        Ok((width, height))
    }

    /// `tilewidth`, `tileheight` (at least 1) and `tilecount` (at most [`MAX_TILE_COUNT`])
    /// of a tile set element.
    fn check_tile_set(&self, element: &Element) -> Result<(), LoadError> {
        for field in ["tilewidth", "tileheight"] {
            let value: u32 = self.required(element, field, "a whole number")?;
            if value == 0 {
                return Err(self.size_error(element.offset, field, 0, "must be at least 1".into()));
            }
        }
        let count = self.number::<u32>(element, "tilecount", "a whole number")?;
        if let Some(count) = count.filter(|&c| c > MAX_TILE_COUNT) {
            return Err(self.size_error(
                element.offset,
                "tilecount",
                count.into(),
                format!("more than {MAX_TILE_COUNT} tiles"),
            ));
        }
        Ok(())
    }
}

fn check_cells(
    w: &Walker<'_>,
    element: &Element,
    width: u32,
    height: u32,
) -> Result<(), LoadError> {
    let cells = u64::from(width) * u64::from(height);
    if cells > w.max_cells {
        return Err(w.size_error(
            element.offset,
            "width × height",
            cells as i64,
            format!(
                "{width}×{height} is more than {}",
                super::cell_limit(w.max_cells)
            ),
        ));
    }
    Ok(())
}

/// Checks a `.tsx` tile set or `.tx` template: well-formed XML and sane tile set sizes.
pub(super) fn scan_external(text: &str, path: &Path) -> Result<(), LoadError> {
    let mut w = Walker::new(text, path);
    loop {
        match w.next()? {
            Item::End => return Ok(()),
            // A template's `<tileset>` is only a reference to a file.
            Item::Open(element)
                if element.name == "tileset" && w.attribute(&element, "source").is_none() =>
            {
                w.check_tile_set(&element)?;
            }
            _ => {}
        }
    }
}

/// A `<data>` or `<chunk>` whose text is being gathered.
struct PendingData {
    encoding: Encoding,
    element_offset: usize,
    /// For a chunk: x, y, width, height.
    chunk: Option<(i32, i32, u32, u32)>,
    text: String,
    text_offset: Option<usize>,
    verbatim: bool,
}

/// A `<layer>` being read.
struct PendingLayer {
    name: String,
    offset: usize,
    /// Finite layers: width and height.
    size: Option<(u32, u32)>,
    encoding: Option<Encoding>,
    gids: Option<Vec<u32>>,
    chunks: Vec<Chunk>,
    chunk_cells: u64,
    chunk_blocks: u64,
}

/// Checks a `.tmx` map and decodes its tile layers, each of at most `max_cells` cells.
pub(super) fn scan_map(text: &str, path: &Path, max_cells: u64) -> Result<ScannedMap, LoadError> {
    let mut w = Walker::new(text, path);
    w.max_cells = max_cells;
    let mut header: Option<((u32, u32), bool)> = None;
    let mut tile_sets = Vec::new();
    let mut tile_layers = Vec::new();
    let mut layer: Option<PendingLayer> = None;
    let mut data: Option<PendingData> = None;
    loop {
        match w.next()? {
            Item::End => break,
            Item::Open(element) => {
                let parent = w.parent().map(str::to_owned);
                match (parent.as_deref(), element.name.as_str()) {
                    (None, "map") => header = Some(map_header(&w, &element)?),
                    (None, other) => {
                        return Err(w.fail(element.offset, NotTiled::RootElement(other.into())));
                    }
                    (Some("map"), "tileset") => tile_sets.push(tile_set_ref(&w, &element)?),
                    (Some("map" | "group"), "layer") => {
                        let infinite = header.is_some_and(|h| h.1);
                        let size = if infinite {
                            None
                        } else {
                            Some(w.grid_size(&element)?)
                        };
                        layer = Some(PendingLayer {
                            name: w.attribute(&element, "name").unwrap_or("").to_owned(),
                            offset: element.offset,
                            size,
                            encoding: None,
                            gids: None,
                            chunks: Vec::new(),
                            chunk_cells: 0,
                            chunk_blocks: 0,
                        });
                    }
                    (Some("layer"), "data") => {
                        let name = layer.as_ref().map_or("", |l| &l.name);
                        let encoding = Encoding::from_attributes(
                            w.attribute(&element, "encoding"),
                            w.attribute(&element, "compression"),
                            &format!("layer {name:?}"),
                        )
                        .map_err(|u| w.fail(element.offset, u))?;
                        if let Some(layer) = layer.as_mut() {
                            layer.encoding = Some(encoding);
                            if layer.size.is_some() {
                                data = Some(PendingData::new(encoding, element.offset, None));
                            }
                        }
                    }
                    (Some("data"), "chunk") => {
                        let chunk = chunk_header(&w, &element, layer.as_mut())?;
                        if let Some(encoding) = layer.as_ref().and_then(|l| l.encoding) {
                            data = Some(PendingData::new(encoding, element.offset, Some(chunk)));
                        }
                    }
                    _ => {}
                }
            }
            Item::Text {
                text: t,
                offset,
                verbatim,
            } => {
                if let Some(d) = data.as_mut() {
                    if d.text_offset.is_none() {
                        d.text_offset = Some(offset);
                        d.verbatim = verbatim;
                    } else {
                        d.verbatim = false;
                    }
                    d.text.push_str(&t);
                }
            }
            Item::Close(name) => match name.as_str() {
                "data" | "chunk" => {
                    if let (Some(d), Some(l)) = (data.take(), layer.as_mut()) {
                        d.finish(&w, l)?;
                    }
                }
                "layer" => {
                    if let Some(l) = layer.take() {
                        tile_layers.push(l.finish(&w)?);
                    }
                }
                _ => {}
            },
        }
    }
    let Some((tile_size, _)) = header else {
        return Err(w.fail(0, NotTiled::NoMapElement));
    };
    Ok(ScannedMap {
        tile_size,
        tile_sets,
        tile_layers,
    })
}

/// The `<map>` element: orthogonal, tile size at least 1, finite maps within the limits.
fn map_header(w: &Walker<'_>, element: &Element) -> Result<((u32, u32), bool), LoadError> {
    match w.attribute(element, "orientation") {
        Some("orthogonal") => {}
        Some(other) => {
            return Err(w.fail(element.offset, Unsupported::Orientation(other.into())));
        }
        None => return Err(w.missing(element, "orientation")),
    }
    // The tiled crate needs `version`; without it, it fails with no position.
    if w.attribute(element, "version").is_none() {
        return Err(w.missing(element, "version"));
    }
    let infinite = w.attribute(element, "infinite") == Some("1");
    if !infinite {
        w.grid_size(element)?;
    }
    let tile_width: u32 = w.required(element, "tilewidth", "a whole number")?;
    let tile_height: u32 = w.required(element, "tileheight", "a whole number")?;
    for (field, value) in [("tilewidth", tile_width), ("tileheight", tile_height)] {
        if value == 0 {
            return Err(w.size_error(element.offset, field, 0, "must be at least 1".into()));
        }
    }
    Ok(((tile_width, tile_height), infinite))
}

fn tile_set_ref(w: &Walker<'_>, element: &Element) -> Result<TileSetRef, LoadError> {
    let first_gid: u32 = w.required(element, "firstgid", "a whole number")?;
    if first_gid == 0 || first_gid > super::Flip::GID_MASK {
        return Err(w.size_error(
            element.offset,
            "firstgid",
            first_gid.into(),
            format!("must be from 1 to {}", super::Flip::GID_MASK),
        ));
    }
    let source = w.attribute(element, "source").map(str::to_owned);
    match &source {
        Some(file) => {
            let extension = Path::new(file)
                .extension()
                .and_then(|e| e.to_str())
                .map(str::to_ascii_lowercase);
            if matches!(extension.as_deref(), Some("tsj" | "json")) {
                return Err(w.fail(element.offset, Unsupported::JsonTileSetInTmx(file.clone())));
            }
        }
        None => w.check_tile_set(element)?,
    }
    Ok(TileSetRef {
        first_gid,
        source,
        location: line_column(w.text, element.offset),
    })
}

/// A `<chunk>`'s x, y, width and height, within bounds that keep every sum in range.
fn chunk_header(
    w: &Walker<'_>,
    element: &Element,
    layer: Option<&mut PendingLayer>,
) -> Result<(i32, i32, u32, u32), LoadError> {
    const FAR: i32 = 1 << 30;
    let x: i32 = w.required(element, "x", "a whole number")?;
    let y: i32 = w.required(element, "y", "a whole number")?;
    for (field, value) in [("x", x), ("y", y)] {
        if !(-FAR..=FAR).contains(&value) {
            return Err(w.size_error(
                element.offset,
                field,
                value.into(),
                format!("chunks must lie within ±{FAR} cells"),
            ));
        }
    }
    let (width, height) = w.grid_size(element)?;
    if let Some(layer) = layer {
        // The tiled crate stores an infinite layer in blocks of 16 × 16 cells, so small
        // chunks far apart cost it a block each: bound the blocks as well as the cells.
        let blocks = |at: i32, len: u32| {
            let first = i64::from(at).div_euclid(16);
            let last = (i64::from(at) + i64::from(len) - 1).div_euclid(16);
            (last - first + 1) as u64
        };
        layer.chunk_cells += u64::from(width) * u64::from(height);
        layer.chunk_blocks += blocks(x, width) * blocks(y, height);
        let max_blocks = w.max_cells.div_ceil(256);
        if layer.chunk_cells > w.max_cells || layer.chunk_blocks > max_blocks {
            return Err(w.size_error(
                element.offset,
                "width × height",
                layer.chunk_cells as i64,
                format!(
                    "the layer's chunks hold more than {}, or spread over more than \
                     {max_blocks} blocks of 16×16 cells",
                    super::cell_limit(w.max_cells)
                ),
            ));
        }
    }
    Ok((x, y, width, height))
}

impl PendingData {
    fn new(encoding: Encoding, element_offset: usize, chunk: Option<(i32, i32, u32, u32)>) -> Self {
        Self {
            encoding,
            element_offset,
            chunk,
            text: String::new(),
            text_offset: None,
            verbatim: true,
        }
    }

    fn finish(self, w: &Walker<'_>, layer: &mut PendingLayer) -> Result<(), LoadError> {
        let (width, height) = match (self.chunk, layer.size) {
            (Some((_, _, cw, ch)), _) => (cw, ch),
            (None, Some(size)) => size,
            (None, None) => return Ok(()),
        };
        let cells = width as usize * height as usize;
        let owner = format!("layer {:?}", layer.name);
        let gids = tile_data::decode(&self.text, self.encoding, cells, &owner)
            .map_err(|e| self.error(w, e))?;
        match self.chunk {
            Some((x, y, width, height)) => layer.chunks.push(Chunk {
                x,
                y,
                width,
                height,
                gids,
            }),
            None => layer.gids = Some(gids),
        }
        Ok(())
    }

    fn error(&self, w: &Walker<'_>, e: DataError) -> LoadError {
        let offset = match (e.offset, self.text_offset) {
            (Some(at), Some(start)) if self.verbatim => start + at,
            _ => self.element_offset,
        };
        w.fail(offset, e.kind)
    }
}

impl PendingLayer {
    fn finish(self, w: &Walker<'_>) -> Result<ScannedLayer, LoadError> {
        let cells = match (self.size, self.gids) {
            (Some((width, height)), Some(gids)) => LayerCells::Finite {
                width,
                height,
                gids,
            },
            (Some(_), None) => {
                return Err(w.fail(
                    self.offset,
                    crate::io::LoadErrorKind::Missing {
                        owner: format!("layer {:?}", self.name),
                        field: "<data>".into(),
                    },
                ));
            }
            (None, _) => LayerCells::Chunks(self.chunks),
        };
        Ok(ScannedLayer {
            name: self.name,
            location: line_column(w.text, self.offset),
            cells,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tiles::MAX_CELLS;

    #[test]
    fn line_column_counts_characters_from_one() {
        let text = "ab\ncé\nx";
        assert_eq!(
            line_column(text, 0),
            Location::LineColumn { line: 1, column: 1 }
        );
        assert_eq!(
            line_column(text, 3),
            Location::LineColumn { line: 2, column: 1 }
        );
        // "é" is two bytes: the offset after it is column 3.
        assert_eq!(
            line_column(text, 6),
            Location::LineColumn { line: 2, column: 3 }
        );
        assert_eq!(
            line_column(text, 99),
            Location::LineColumn { line: 3, column: 2 }
        );
    }

    #[test]
    fn a_finite_map_is_scanned_and_decoded() {
        let tmx = r#"<?xml version="1.0"?>
<map version="1.10" orientation="orthogonal" width="2" height="1" tilewidth="8" tileheight="8">
 <tileset firstgid="1" source="t.tsx"/>
 <group name="g"><layer name="a" width="2" height="1"><data encoding="csv">1,2</data></layer></group>
</map>"#;
        let scan = scan_map(tmx, Path::new("m.tmx"), MAX_CELLS).unwrap();
        assert_eq!(scan.tile_size, (8, 8));
        assert_eq!(scan.tile_sets[0].first_gid, 1);
        assert_eq!(scan.tile_layers.len(), 1);
        assert!(matches!(
            &scan.tile_layers[0].cells,
            LayerCells::Finite { gids, .. } if gids == &[1, 2]
        ));
    }

    #[test]
    fn a_bad_csv_entry_is_named_at_its_own_line_and_column() {
        let tmx = "<map version=\"1.10\" orientation=\"orthogonal\" width=\"2\" height=\"2\" tilewidth=\"8\" \
                   tileheight=\"8\">\n<layer name=\"a\" width=\"2\" height=\"2\"><data encoding=\"csv\">\n1,2,\n3,x\n</data></layer></map>";
        let e = scan_map(tmx, Path::new("m.tmx"), MAX_CELLS).unwrap_err();
        assert_eq!(e.location, Location::LineColumn { line: 4, column: 3 });
        assert!(e.to_string().contains("\"x\""), "{e}");
    }
}
