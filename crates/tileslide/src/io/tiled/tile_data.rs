//! Tile layer data as Tiled writes it: CSV text, or base64 of little-endian u32 gids,
//! optionally compressed with zlib, gzip or zstd. Shared by both formats: `.tmj` layers are
//! decoded here, and `.tmx` layers are decoded here too, before the `tiled` crate sees them,
//! so that their size is checked, their hexagonal bits are kept and their errors have a
//! line and column.

use std::io::Read;

use base64::Engine;

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
    /// The encoding named by a layer's `encoding` and `compression` attributes, or a message
    /// saying why it is not supported.
    pub fn from_attributes(
        encoding: Option<&str>,
        compression: Option<&str>,
    ) -> Result<Self, String> {
        let unknown = || {
            format!(
                "unknown tile data encoding: encoding {:?}, compression {:?} (supported: csv; \
                 base64 without compression or with zlib, gzip or zstd)",
                encoding.unwrap_or("none (XML <tile> elements)"),
                compression.unwrap_or("none")
            )
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
                    Err(
                        "zstd-compressed tile data needs tileslide's `tiled-zstd` cargo feature"
                            .to_string(),
                    )
                }
            }
            _ => Err(unknown()),
        }
    }
}

/// Why a layer's data could not be decoded, and where in its text (a byte offset from the
/// start of the data text) when that is known.
#[derive(Debug, PartialEq)]
pub(super) struct DataError {
    pub message: String,
    pub offset: Option<usize>,
}

impl DataError {
    fn new(message: String) -> Self {
        Self {
            message,
            offset: None,
        }
    }
}

/// Decodes exactly `cells` gids (a count the caller has checked against the map limits).
pub(super) fn decode(text: &str, encoding: Encoding, cells: usize) -> Result<Vec<u32>, DataError> {
    match encoding {
        Encoding::Csv => decode_csv(text, cells),
        Encoding::Base64(compression) => {
            let packed = base64::engine::general_purpose::STANDARD
                .decode(text.trim())
                .map_err(|e| DataError::new(format!("bad base64 tile data: {e}")))?;
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
                return Err(DataError::new(count_message(cells + 1, true, cells)));
            }
            if bytes.len() % 4 != 0 {
                return Err(DataError::new(format!(
                    "the tile data is {} bytes, not a whole number of 4-byte gids",
                    bytes.len()
                )));
            }
            if bytes.len() != cells * 4 {
                return Err(DataError::new(count_message(bytes.len() / 4, false, cells)));
            }
            Ok(bytes
                .chunks_exact(4)
                .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
                .collect())
        }
    }
}

/// The message for data holding the wrong number of gids.
pub(super) fn count_message(found: usize, more: bool, cells: usize) -> String {
    let more = if more { " or more" } else { "" };
    format!("the tile data holds {found}{more} gids, expected {cells} (one per cell)")
}

fn decode_csv(text: &str, cells: usize) -> Result<Vec<u32>, DataError> {
    let mut gids = Vec::with_capacity(cells);
    let mut offset = 0;
    for field in text.split(',') {
        let trimmed = field.trim();
        // Tiled ends each row but the last with a comma; a lone comma at the very end is
        // tolerated too.
        if !(trimmed.is_empty() && offset + field.len() == text.len() && !gids.is_empty()) {
            if gids.len() == cells {
                return Err(DataError {
                    message: count_message(cells + 1, true, cells),
                    offset: Some(offset),
                });
            }
            let start = offset + (field.len() - field.trim_start().len());
            let gid = trimmed.parse::<u32>().map_err(|_| DataError {
                message: format!("{trimmed:?} is not a tile gid (a whole number from 0 to 2³²−1)"),
                offset: Some(start),
            })?;
            gids.push(gid);
        }
        offset += field.len() + 1;
    }
    if gids.len() != cells {
        return Err(DataError::new(count_message(gids.len(), false, cells)));
    }
    Ok(gids)
}

fn inflate(decoder: impl Read, limit: u64, name: &str) -> Result<Vec<u8>, DataError> {
    let mut out = Vec::new();
    decoder
        .take(limit)
        .read_to_end(&mut out)
        .map_err(|e| DataError::new(format!("bad {name}-compressed tile data: {e}")))?;
    Ok(out)
}

#[cfg(feature = "tiled-zstd")]
fn inflate_zstd(packed: &[u8], limit: u64) -> Result<Vec<u8>, DataError> {
    let decoder = zstd::stream::read::Decoder::new(packed)
        .map_err(|e| DataError::new(format!("bad zstd-compressed tile data: {e}")))?;
    inflate(decoder, limit, "zstd")
}

#[cfg(not(feature = "tiled-zstd"))]
fn inflate_zstd(_: &[u8], _: u64) -> Result<Vec<u8>, DataError> {
    // `Encoding::from_attributes` refuses zstd without the feature, so this is not reached.
    Err(DataError::new(
        "zstd-compressed tile data needs tileslide's `tiled-zstd` cargo feature".to_string(),
    ))
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
        let gids = decode("\n1,2,\n0,2147483649\n", Encoding::Csv, 4).unwrap();
        assert_eq!(gids, [1, 2, 0, 0x8000_0001]);
        let e = decode("1,x,3", Encoding::Csv, 3).unwrap_err();
        assert_eq!(e.offset, Some(2));
        let e = decode("1,2", Encoding::Csv, 3).unwrap_err();
        assert!(
            e.message.contains("holds 2 gids, expected 3"),
            "{}",
            e.message
        );
        let e = decode("1,2,3,4", Encoding::Csv, 3).unwrap_err();
        assert!(e.message.contains("or more"), "{}", e.message);
    }

    #[test]
    fn base64_plain_zlib_and_gzip() {
        let gids = [5, 0, 0x4000_0002, 1];
        let raw = le(&gids);
        let plain = decode(&base64(&raw), Encoding::Base64(Compression::None), 4).unwrap();
        assert_eq!(plain, gids);
        let mut z = flate2::write::ZlibEncoder::new(Vec::new(), flate2::Compression::default());
        z.write_all(&raw).unwrap();
        let zlib = base64(&z.finish().unwrap());
        assert_eq!(
            decode(&zlib, Encoding::Base64(Compression::Zlib), 4).unwrap(),
            gids
        );
        let mut g = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
        g.write_all(&raw).unwrap();
        let gzip = base64(&g.finish().unwrap());
        assert_eq!(
            decode(&gzip, Encoding::Base64(Compression::Gzip), 4).unwrap(),
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
            decode(&text, Encoding::Base64(Compression::Zstd), 2).unwrap(),
            gids
        );
        let e = decode(&text, Encoding::Base64(Compression::Zstd), 1).unwrap_err();
        assert!(e.message.contains("or more"), "{}", e.message);
    }

    #[test]
    fn a_compressed_block_cannot_expand_past_the_layer() {
        // 4 MB of zeros compress to a few kilobytes; the layer has 4 cells.
        let mut z = flate2::write::ZlibEncoder::new(Vec::new(), flate2::Compression::best());
        z.write_all(&vec![0u8; 4 << 20]).unwrap();
        let bomb = base64(&z.finish().unwrap());
        let e = decode(&bomb, Encoding::Base64(Compression::Zlib), 4).unwrap_err();
        assert!(e.message.contains("holds 5 or more gids"), "{}", e.message);
    }

    #[test]
    fn unknown_encodings_are_named() {
        let e = Encoding::from_attributes(Some("base32"), None).unwrap_err();
        assert!(e.contains("\"base32\""), "{e}");
        let e = Encoding::from_attributes(Some("base64"), Some("lzma")).unwrap_err();
        assert!(e.contains("\"lzma\""), "{e}");
        let e = Encoding::from_attributes(None, None).unwrap_err();
        assert!(e.contains("XML <tile> elements"), "{e}");
    }
}
