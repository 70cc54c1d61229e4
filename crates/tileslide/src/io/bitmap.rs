//! Tile sets traced from images: a PNG tile sheet whose opaque (or dark) pixels are solid
//! becomes a [`TileSet`], each tile's outline traced with [`TileShape::trace`]. An
//! image-authored tile set gets collision without drawing any polygon.
//!
//! The sheet is cut into tiles of the given size, row by row; tile `k` (0-based, left to
//! right, then top to bottom) gets id `k`. A pixel is solid when its alpha is at least the
//! threshold (images with an alpha channel or a transparent colour), or, for an image
//! without transparency, when its luminance is below the threshold (dark on light).
//! Coordinates are the tile's pixels, y down.

use std::io::Cursor;
use std::path::Path;

use glam::Vec2;

use super::error::read_file;
use super::{LoadError, LoadErrorKind, Location};
use crate::tiles::{TileId, TileSet, TileSetError, TileShape};

/// How to cut and trace a tile sheet.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BitmapOptions {
    /// Width and height of one tile, in pixels.
    pub tile_width: u32,
    /// Height of one tile, in pixels.
    pub tile_height: u32,
    /// Alpha (or, without transparency, luminance) threshold, 0–255. Default 128.
    pub threshold: u8,
    /// Outline simplification, in pixels (see [`TileShape::trace`]). Default 1.
    pub tolerance: f32,
    /// Most tiles the sheet may be cut into, checked before the image is decoded: each
    /// traced tile costs about 300 bytes, so a 3 KB image cut into 1 × 1 tiles would cost
    /// 300 MB. Default [`DEFAULT_MAX_TILES`].
    pub max_tiles: u32,
}

/// The default [`BitmapOptions::max_tiles`]: 2¹⁸ tiles (about 80 MB of shapes), a 512 × 512
/// sheet of single-pixel tiles or a 8192 × 8192 sheet of 16-pixel ones.
pub const DEFAULT_MAX_TILES: u32 = 1 << 18;

impl BitmapOptions {
    /// Tiles of `tile_width × tile_height` pixels, default threshold and tolerance.
    #[must_use]
    pub fn new(tile_width: u32, tile_height: u32) -> Self {
        Self {
            tile_width,
            tile_height,
            threshold: 128,
            tolerance: 1.0,
            max_tiles: DEFAULT_MAX_TILES,
        }
    }
}

/// The decoded image is refused past this many bytes (8-bit RGBA: 64 megapixels).
const MAX_DECODED_BYTES: usize = 256 << 20;

/// Loads a PNG tile sheet as a traced tile set.
pub fn load_tile_set(
    path: impl AsRef<Path>,
    options: &BitmapOptions,
) -> Result<TileSet, LoadError> {
    let path = path.as_ref();
    parse_tile_set(&read_file(path)?, path, options)
}

/// Parses PNG bytes as a traced tile set; `path` names it in errors.
///
/// ```
/// use tileslide::io::bitmap::{BitmapOptions, parse_tile_set};
/// let png = std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/maps/tiles.png"))?;
/// let set = parse_tile_set(&png, "tiles.png", &BitmapOptions::new(16, 16))?;
/// assert_eq!(set.len(), 8); // a 64 × 32 sheet of 16-pixel tiles
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn parse_tile_set(
    data: &[u8],
    path: impl AsRef<Path>,
    options: &BitmapOptions,
) -> Result<TileSet, LoadError> {
    let path = path.as_ref();
    let error = |kind| LoadError::new(path, Location::File, kind);
    let damaged = |message: &str, e: png::DecodingError| {
        error(LoadErrorKind::Syntax {
            format: "PNG",
            truncated: matches!(&e, png::DecodingError::IoError(io)
                if io.kind() == std::io::ErrorKind::UnexpectedEof),
            message: format!("{message}: {e}"),
            source: Some(Box::new(e)),
        })
    };
    let (tw, th) = (options.tile_width, options.tile_height);
    if tw == 0 || th == 0 {
        return Err(error(LoadErrorKind::Parameter(format!(
            "tile size {tw} × {th} must be at least one pixel each way"
        ))));
    }
    let limits = png::Limits {
        bytes: MAX_DECODED_BYTES,
    };
    let mut decoder = png::Decoder::new_with_limits(Cursor::new(data), limits);
    decoder.set_transformations(png::Transformations::normalize_to_color8());
    let mut reader = decoder
        .read_info()
        .map_err(|e| damaged("not a readable PNG image", e))?;
    let (width, height) = (reader.info().width, reader.info().height);
    let tiles = u64::from(width / tw) * u64::from(height / th);
    if tiles > u64::from(options.max_tiles) {
        return Err(error(LoadErrorKind::BadSize {
            field: "tiles",
            value: tiles as i64,
            reason: format!(
                "a {width} × {height} image cut into {tw} × {th} tiles gives {tiles} tiles, \
                 more than `BitmapOptions::max_tiles` ({}); raise it to load this sheet",
                options.max_tiles
            ),
        }));
    }
    let size = reader
        .output_buffer_size()
        .filter(|&n| n <= MAX_DECODED_BYTES)
        .ok_or_else(|| {
            let bytes = reader.output_buffer_size().unwrap_or(usize::MAX);
            error(LoadErrorKind::BadSize {
                field: "decoded bytes",
                value: i64::try_from(bytes).unwrap_or(i64::MAX),
                reason: format!(
                    "a {width} × {height} image is larger than {MAX_DECODED_BYTES} bytes decoded"
                ),
            })
        })?;
    let mut pixels = vec![0u8; size];
    let frame = reader
        .next_frame(&mut pixels)
        .map_err(|e| damaged("the PNG image data is damaged", e))?;
    let (width, height) = (frame.width, frame.height);
    if width % tw != 0 || height % th != 0 {
        return Err(error(LoadErrorKind::SheetSize {
            width,
            height,
            tile_width: tw,
            tile_height: th,
        }));
    }
    let solid = solidity(
        &pixels,
        frame.color_type,
        frame.line_size,
        width,
        height,
        options.threshold,
    );
    let mut set = TileSet::new(Vec2::new(tw as f32, th as f32)).map_err(|e| error(e.into()))?;
    let columns = width / tw;
    for ty in 0..height / th {
        for tx in 0..columns {
            let mask: Vec<bool> = (0..th)
                .flat_map(|y| (0..tw).map(move |x| (x, y)))
                .map(|(x, y)| solid[((ty * th + y) * width + tx * tw + x) as usize])
                .collect();
            let id = TileId(ty * columns + tx);
            let shape = TileShape::trace(&mask, tw, th, options.tolerance)
                .map_err(|source| error(TileSetError::InvalidTile { id, source }.into()))?;
            set.insert(id, shape).map_err(|e| error(e.into()))?;
        }
    }
    Ok(set)
}

/// Per pixel, whether it is solid (see the module's documentation).
fn solidity(
    pixels: &[u8],
    color: png::ColorType,
    line: usize,
    width: u32,
    height: u32,
    threshold: u8,
) -> Vec<bool> {
    let channels = color.samples();
    let pixel = |x: u32, y: u32| {
        let at = y as usize * line + x as usize * channels;
        pixels.get(at..at + channels).unwrap_or(&[])
    };
    let luminance = |p: &[u8]| -> u8 {
        let (r, g, b) = (f32::from(p[0]), f32::from(p[1]), f32::from(p[2]));
        (0.299 * r + 0.587 * g + 0.114 * b) as u8
    };
    (0..height)
        .flat_map(|y| (0..width).map(move |x| (x, y)))
        .map(|(x, y)| {
            let p = pixel(x, y);
            match (color, p.len()) {
                (png::ColorType::GrayscaleAlpha, 2) => p[1] >= threshold,
                (png::ColorType::Rgba, 4) => p[3] >= threshold,
                (png::ColorType::Grayscale, 1) => p[0] < threshold,
                (png::ColorType::Rgb, 3) => luminance(p) < threshold,
                _ => false,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A PNG of `width × height` pixels of `color` with `pixel(x, y)`'s samples.
    fn png_bytes(
        width: u32,
        height: u32,
        color: png::ColorType,
        pixel: impl Fn(u32, u32) -> Vec<u8>,
    ) -> Vec<u8> {
        let mut out = Vec::new();
        let mut encoder = png::Encoder::new(&mut out, width, height);
        encoder.set_color(color);
        encoder.set_depth(png::BitDepth::Eight);
        let mut writer = encoder.write_header().unwrap();
        let data: Vec<u8> = (0..height)
            .flat_map(|y| (0..width).map(move |x| (x, y)))
            .flat_map(|(x, y)| pixel(x, y))
            .collect();
        writer.write_image_data(&data).unwrap();
        writer.finish().unwrap();
        out
    }

    /// Two 8 × 8 tiles: a full block, and a ramp drawn in steps rising to the right.
    fn sheet(color: png::ColorType, on: &[u8], off: &[u8]) -> Vec<u8> {
        png_bytes(16, 8, color, |x, y| {
            let solid = x < 8 || (x - 8) + y >= 7;
            if solid { on.to_vec() } else { off.to_vec() }
        })
    }

    fn check_block_and_ramp(set: &TileSet) {
        assert_eq!(set.len(), 2);
        assert_eq!(set.tile_size(), Vec2::splat(8.0));
        let block = set.shape(TileId(0)).unwrap();
        assert_eq!(block.segments().len(), 4);
        assert!(block.contains_point(Vec2::new(4.0, 4.0)));
        let ramp = set.shape(TileId(1)).unwrap();
        let slopes = ramp
            .segments()
            .iter()
            .filter(|s| s.normal.x < -0.5 && s.normal.y < -0.5)
            .count();
        assert_eq!(slopes, 1, "{:?}", ramp.segments());
        assert!(ramp.contains_point(Vec2::new(7.5, 7.5)));
        assert!(!ramp.contains_point(Vec2::new(0.5, 0.5)));
    }

    #[test]
    fn opaque_pixels_of_an_rgba_sheet_are_solid() {
        let png = sheet(png::ColorType::Rgba, &[9, 9, 9, 255], &[9, 9, 9, 0]);
        let set = parse_tile_set(&png, "sheet.png", &BitmapOptions::new(8, 8)).unwrap();
        check_block_and_ramp(&set);
    }

    #[test]
    fn dark_pixels_of_an_opaque_grayscale_sheet_are_solid() {
        let png = sheet(png::ColorType::Grayscale, &[10], &[240]);
        let set = parse_tile_set(&png, "sheet.png", &BitmapOptions::new(8, 8)).unwrap();
        check_block_and_ramp(&set);
    }

    #[test]
    fn bad_images_and_sizes_are_errors_naming_the_file() {
        let png = sheet(png::ColorType::Rgba, &[0, 0, 0, 255], &[0, 0, 0, 0]);
        let err = |data: &[u8], w: u32, h: u32| {
            parse_tile_set(data, "sheet.png", &BitmapOptions::new(w, h))
                .unwrap_err()
                .to_string()
        };
        assert!(err(&png, 5, 8).contains("does not divide into 5 × 8"));
        assert!(err(&png, 0, 8).contains("at least one pixel"));
        assert!(err(b"GIF89a", 8, 8).contains("not a readable PNG"));
        // The causes as a program reads them: the sizes, and the png crate's own error.
        let e = parse_tile_set(&png, "sheet.png", &BitmapOptions::new(5, 8)).unwrap_err();
        assert!(
            matches!(
                e.kind,
                LoadErrorKind::SheetSize {
                    width: 16,
                    height: 8,
                    tile_width: 5,
                    tile_height: 8
                }
            ),
            "{e}"
        );
        let e = parse_tile_set(b"GIF89a", "sheet.png", &BitmapOptions::new(8, 8)).unwrap_err();
        assert!(
            matches!(e.kind, LoadErrorKind::Syntax { format: "PNG", .. }),
            "{e}"
        );
        let source = std::error::Error::source(&e).unwrap();
        assert!(source.is::<png::DecodingError>(), "{source}");
        // Every truncation: an error naming the file, never a panic; or, cut only after
        // the last pixel (the PNG reader does not insist on the end marker), the same set.
        let full = parse_tile_set(&png, "sheet.png", &BitmapOptions::new(8, 8)).unwrap();
        for len in 0..png.len() {
            match parse_tile_set(&png[..len], "sheet.png", &BitmapOptions::new(8, 8)) {
                Ok(set) => assert_eq!(set, full, "cut at {len}"),
                Err(e) => assert!(e.to_string().starts_with("sheet.png"), "{e}"),
            }
        }
    }

    #[test]
    fn a_small_image_cut_into_too_many_tiles_is_refused_before_decoding() {
        // 600 × 600 pixels of one grey (a few hundred bytes of PNG) in 1 × 1 tiles: 360 000
        // tiles, more than the default 2^18.
        let png = png_bytes(600, 600, png::ColorType::Grayscale, |_, _| vec![10]);
        assert!(png.len() < 2000, "{}", png.len());
        let e = parse_tile_set(&png, "dots.png", &BitmapOptions::new(1, 1)).unwrap_err();
        assert_eq!(
            e.to_string(),
            "dots.png: `tiles` = 360000 is out of range: a 600 × 600 image cut into 1 × 1 tiles \
             gives 360000 tiles, more than `BitmapOptions::max_tiles` (262144); raise it to load \
             this sheet"
        );
        // The bound is the caller's: 400 tiles load under a bound of 400, not of 399.
        let small = png_bytes(20, 20, png::ColorType::Grayscale, |_, _| vec![10]);
        let with = |max_tiles| BitmapOptions {
            max_tiles,
            ..BitmapOptions::new(1, 1)
        };
        assert_eq!(
            parse_tile_set(&small, "s.png", &with(400)).unwrap().len(),
            400
        );
        assert!(parse_tile_set(&small, "s.png", &with(399)).is_err());
    }

    #[test]
    fn the_example_tile_sheet_traces_into_closed_or_empty_shapes() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/maps/tiles.png");
        let set = load_tile_set(path, &BitmapOptions::new(16, 16)).unwrap();
        assert_eq!(set.len(), 8);
        for (id, shape) in set.iter() {
            assert!(
                shape.segments().is_empty() || shape.has_inside(),
                "tile {id:?}: {:?}",
                shape.segments()
            );
        }
    }
}
