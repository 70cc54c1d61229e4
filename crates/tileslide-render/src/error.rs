//! Why a picture or an animation could not be made or written.

use std::path::PathBuf;

use thiserror::Error;

use crate::{MAX_GIF_BYTES, MAX_PIXELS};

/// Why a picture or an animation could not be made or written.
#[derive(Debug, Error)]
pub enum RenderError {
    /// The scale is zero, negative, NaN or infinite.
    #[error("pixels per cell: {0} is not a positive finite number")]
    BadScale(f32),
    /// The image would have more than [`MAX_PIXELS`] pixels.
    #[error(
        "a {width} × {height} pixel image is too large: at most {MAX_PIXELS} pixels (lower the pixels per cell)"
    )]
    TooLarge {
        /// Width the image would have, in pixels.
        width: u64,
        /// Height the image would have, in pixels.
        height: u64,
    },
    /// A side is longer than a GIF can hold (65,535 pixels).
    #[error(
        "a {width} × {height} pixel animation is too large for a GIF: at most 65535 pixels a side"
    )]
    TooLargeForGif {
        /// Width of the canvas, in pixels.
        width: u32,
        /// Height of the canvas, in pixels.
        height: u32,
    },
    /// A [`Framing`](crate::Framing) that cannot be drawn: its window is empty or not
    /// finite, or its viewport is empty or larger than its image.
    #[error("framing: {0}")]
    BadFraming(&'static str),
    /// An image pushed to an animation is not the animation's size.
    #[error(
        "a {got_width} × {got_height} pixel frame pushed to a {width} × {height} pixel animation"
    )]
    FrameSize {
        /// The animation's width, in pixels.
        width: u32,
        /// The animation's height, in pixels.
        height: u32,
        /// The frame's width, in pixels.
        got_width: u32,
        /// The frame's height, in pixels.
        got_height: u32,
    },
    /// The animation's GIF already holds [`MAX_GIF_BYTES`] bytes: no frame more is taken.
    #[error(
        "the animation's GIF holds {bytes} bytes after {frames} frames: at most {MAX_GIF_BYTES} \
         (MAX_GIF_BYTES); record fewer or smaller frames"
    )]
    GifTooLarge {
        /// Frames taken.
        frames: usize,
        /// Bytes of GIF they made.
        bytes: u64,
    },
    /// The PNG encoder failed.
    #[error("cannot encode the PNG: {0}")]
    Png(#[from] png::EncodingError),
    /// The GIF encoder failed.
    #[error("cannot encode the GIF: {0}")]
    Gif(#[from] gif::EncodingError),
    /// The file could not be written.
    #[error("{}: cannot write: {source}", path.display())]
    Write {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
}

impl RenderError {
    /// Writes `bytes` to `path`, naming the file on failure.
    pub(crate) fn write_file(path: &std::path::Path, bytes: &[u8]) -> Result<(), Self> {
        std::fs::write(path, bytes).map_err(|source| Self::Write {
            path: path.to_owned(),
            source,
        })
    }
}
