//! Tile layer data as Tiled writes it: CSV text, or base64 of little-endian u32 gids,
//! optionally compressed with zlib, gzip or zstd. Shared by both formats: `.tmj` layers are
//! decoded here, and `.tmx` layers are decoded here too, before the `tiled` crate sees them,
//! so that their size is checked, their hexagonal bits are kept and their errors have a
//! line and column.

use std::io::Read;

use base64::Engine;

use crate::io::{LoadErrorKind, Unsupported};

/// How the gids are compressed inside base64.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Compression {
    None,
    Zlib,
    Gzip,
    Zstd,
}

/// How a layer's gids are written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Encoding {
    /// Comma-separated numbers.
    Csv,
    /// Base64 of little-endian u32s, maybe compressed.
    Base64(Compression),
}

impl Encoding {
    /// The encoding named by the `encoding` and `compression` attributes of `layer`'s data,
    /// or why it is not supported.
    pub fn from_attributes(
        encoding: Option<&str>,
        compression: Option<&str>,
        layer: &str,
    ) -> Result<Self, Unsupported> {
        let unknown = || Unsupported::Encoding {
            layer: layer.to_owned(),
            encoding: encoding.map(str::to_owned),
            compression: compression.map(str::to_owned),
        };
        match (encoding, compression) {
            (Some("csv"), None) => Ok(Self::Csv),
            (Some("base64"), None) => Ok(Self::Base64(Compression::None)),
            (Some("base64"), Some("zlib")) => Ok(Self::Base64(Compression::Zlib)),
            (Some("base64"), Some("gzip")) => Ok(Self::Base64(Compression::Gzip)),
            (Some("base64"), Some("zstd")) => {
                if cfg!(feature = "tiled-zstd") {
                    Ok(Self::Base64(Compression::Zstd))
                } else {
                    Err(ZSTD_FEATURE)
                }
            }
            _ => Err(unknown()),
        }
    }
}

/// What zstd-compressed data needs.
const ZSTD_FEATURE: Unsupported = Unsupported::Feature {
    what: "zstd-compressed tile data",
    feature: "tiled-zstd",
};

/// Why a layer's data could not be decoded, and where in its text (a byte offset from the
/// start of the data text) when that is known.
#[derive(Debug)]
pub(super) struct DataError {
    pub kind: LoadErrorKind,
    pub offset: Option<usize>,
}

impl DataError {
    fn new(kind: impl Into<LoadErrorKind>) -> Self {
        Self {
            kind: kind.into(),
            offset: None,
        }
    }

    /// A decoder's error: the data is not what its encoding says.
    fn damaged(format: &'static str, e: impl std::error::Error + Send + Sync + 'static) -> Self {
        Self::new(LoadErrorKind::Syntax {
            format,
            truncated: false,
            message: if format == "base64" {
                format!("bad base64 tile data: {e}")
            } else {
                format!("bad {format}-compressed tile data: {e}")
            },
            source: Some(Box::new(e)),
        })
    }
}

/// The error for `owner`'s data holding `found` gids (`or_more`: at least) for `cells`.
pub(super) fn count_error(owner: &str, found: usize, or_more: bool, cells: usize) -> LoadErrorKind {
    LoadErrorKind::GidCount {
        owner: owner.to_owned(),
        found: found as u64,
        or_more,
        expected: cells as u64,
    }
}

/// Decodes exactly `cells` gids (a count the caller has checked against the map limits) of
/// `owner`'s data (`layer "walls"`, named in errors).
pub(super) fn decode(
    text: &str,
    encoding: Encoding,
    cells: usize,
    owner: &str,
) -> Result<Vec<u32>, DataError> {
    match encoding {
        Encoding::Csv => decode_csv(text, cells, owner),
        Encoding::Base64(compression) => {
            let packed = base64::engine::general_purpose::STANDARD
                .decode(text.trim())
                .map_err(|e| DataError::damaged("base64", e))?;
            // At most one byte more than needed is inflated: enough to tell that the data is
            // too long, without letting a small compressed block expand without bound.
            let limit = cells as u64 * 4 + 1;
            let bytes = match compression {
                Compression::None => packed,
                Compression::Zlib => {
                    inflate(flate2::read::ZlibDecoder::new(&packed[..]), limit, "zlib")?
                }
                Compression::Gzip => {
                    inflate(flate2::read::GzDecoder::new(&packed[..]), limit, "gzip")?
                }
                Compression::Zstd => inflate_zstd(&packed, limit)?,
            };
            if bytes.len() as u64 >= limit {
                return Err(DataError::new(count_error(owner, cells + 1, true, cells)));
            }
            if bytes.len() % 4 != 0 {
                return Err(DataError::new(LoadErrorKind::BadSize {
                    field: "tile data",
                    value: bytes.len() as i64,
                    reason: format!(
                        "{owner}: the tile data is {} bytes, not a whole number of 4-byte gids",
                        bytes.len()
                    ),
                }));
            }
            if bytes.len() != cells * 4 {
                return Err(DataError::new(count_error(
                    owner,
                    bytes.len() / 4,
                    false,
                    cells,
                )));
            }
            Ok(bytes
                .chunks_exact(4)
                .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
                .collect())
        }
    }
}

fn decode_csv(text: &str, cells: usize, owner: &str) -> Result<Vec<u32>, DataError> {
    let mut gids = Vec::with_capacity(cells);
    let mut offset = 0;
    for field in text.split(',') {
        let trimmed = field.trim();
        // Tiled ends each row but the last with a comma; a lone comma at the very end is
        // tolerated too.
        if !(trimmed.is_empty() && offset + field.len() == text.len() && !gids.is_empty()) {
            if gids.len() == cells {
                return Err(DataError {
                    kind: count_error(owner, cells + 1, true, cells),
                    offset: Some(offset),
                });
            }
            let start = offset + (field.len() - field.trim_start().len());
            let gid = trimmed.parse::<u32>().map_err(|_| DataError {
                kind: LoadErrorKind::BadValue {
                    owner: owner.to_owned(),
                    field: "data",
                    found: format!("{trimmed:?}"),
                    expected: "a tile gid (a whole number from 0 to 2³²−1)",
                },
                offset: Some(start),
            })?;
            gids.push(gid);
        }
        offset += field.len() + 1;
    }
    if gids.len() != cells {
        return Err(DataError::new(count_error(owner, gids.len(), false, cells)));
    }
    Ok(gids)
}

fn inflate(decoder: impl Read, limit: u64, name: &'static str) -> Result<Vec<u8>, DataError> {
    let mut out = Vec::new();
    decoder
        .take(limit)
        .read_to_end(&mut out)
        .map_err(|e| DataError::damaged(name, e))?;
    Ok(out)
}

#[cfg(feature = "tiled-zstd")]
fn inflate_zstd(packed: &[u8], limit: u64) -> Result<Vec<u8>, DataError> {
    let decoder =
        zstd::stream::read::Decoder::new(packed).map_err(|e| DataError::damaged("zstd", e))?;
    inflate(decoder, limit, "zstd")
}

#[cfg(not(feature = "tiled-zstd"))]
fn inflate_zstd(_: &[u8], _: u64) -> Result<Vec<u8>, DataError> {
    // `Encoding::from_attributes` refuses zstd without the feature, so this is not reached.
    Err(DataError::new(ZSTD_FEATURE))
}

#[cfg(test)]
mod tests {
    use std::io::Write;

    use super::*;

    fn base64(bytes: &[u8]) -> String {
        base64::engine::general_purpose::STANDARD.encode(bytes)
    }

    fn le(gids: &[u32]) -> Vec<u8> {
        gids.iter().flat_map(|g| g.to_le_bytes()).collect()
    }

    #[test]
    fn csv_with_row_commas_and_newlines() {
        let gids = decode("\n1,2,\n0,2147483649\n", Encoding::Csv, 4, "l").unwrap();
        assert_eq!(gids, [1, 2, 0, 0x8000_0001]);
        let e = decode("1,x,3", Encoding::Csv, 3, "l").unwrap_err();
        assert_eq!(e.offset, Some(2));
        let e = decode("1,2", Encoding::Csv, 3, "l").unwrap_err();
        assert!(
            matches!(
                e.kind,
                LoadErrorKind::GidCount {
                    found: 2,
                    or_more: false,
                    expected: 3,
                    ..
                }
            ),
            "{}",
            e.kind
        );
        let e = decode("1,2,3,4", Encoding::Csv, 3, "l").unwrap_err();
        assert!(e.kind.to_string().contains("or more"), "{}", e.kind);
    }

    #[test]
    fn base64_plain_zlib_and_gzip() {
        let gids = [5, 0, 0x4000_0002, 1];
        let raw = le(&gids);
        let plain = decode(&base64(&raw), Encoding::Base64(Compression::None), 4, "l").unwrap();
        assert_eq!(plain, gids);
        let mut z = flate2::write::ZlibEncoder::new(Vec::new(), flate2::Compression::default());
        z.write_all(&raw).unwrap();
        let zlib = base64(&z.finish().unwrap());
        assert_eq!(
            decode(&zlib, Encoding::Base64(Compression::Zlib), 4, "l").unwrap(),
            gids
        );
        let mut g = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
        g.write_all(&raw).unwrap();
        let gzip = base64(&g.finish().unwrap());
        assert_eq!(
            decode(&gzip, Encoding::Base64(Compression::Gzip), 4, "l").unwrap(),
            gids
        );
    }

    #[cfg(feature = "tiled-zstd")]
    #[test]
    fn base64_zstd() {
        let gids = [3, 0x2000_0001];
        let packed = zstd::encode_all(&le(&gids)[..], 3).unwrap();
        let text = base64(&packed);
        assert_eq!(
            decode(&text, Encoding::Base64(Compression::Zstd), 2, "l").unwrap(),
            gids
        );
        let e = decode(&text, Encoding::Base64(Compression::Zstd), 1, "l").unwrap_err();
        assert!(e.kind.to_string().contains("or more"), "{}", e.kind);
    }

    #[test]
    fn a_compressed_block_cannot_expand_past_the_layer() {
        // 4 MB of zeros compress to a few kilobytes; the layer has 4 cells.
        let mut z = flate2::write::ZlibEncoder::new(Vec::new(), flate2::Compression::best());
        z.write_all(&vec![0u8; 4 << 20]).unwrap();
        let bomb = base64(&z.finish().unwrap());
        let e = decode(&bomb, Encoding::Base64(Compression::Zlib), 4, "l").unwrap_err();
        assert!(
            matches!(
                e.kind,
                LoadErrorKind::GidCount {
                    found: 5,
                    or_more: true,
                    ..
                }
            ),
            "{}",
            e.kind
        );
    }

    #[test]
    fn unknown_encodings_are_named() {
        let e = Encoding::from_attributes(Some("base32"), None, "l")
            .unwrap_err()
            .to_string();
        assert!(e.contains("\"base32\""), "{e}");
        let e = Encoding::from_attributes(Some("base64"), Some("lzma"), "l")
            .unwrap_err()
            .to_string();
        assert!(e.contains("\"lzma\""), "{e}");
        let e = Encoding::from_attributes(None, None, "l")
            .unwrap_err()
            .to_string();
        assert!(e.contains("XML <tile> elements"), "{e}");
    }
}
