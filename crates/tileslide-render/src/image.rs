//! A rendered picture: RGBA pixels, encodable as PNG.

use std::path::Path;

use tiny_skia::Pixmap;

use crate::{RenderError, Rgba};

/// A rendered picture: `width × height` RGBA pixels, row by row from the top-left.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    pixmap: Pixmap,
}

impl Image {
    pub(crate) fn from_pixmap(pixmap: Pixmap) -> Self {
        Self { pixmap }
    }

    pub(crate) fn pixmap(&self) -> &Pixmap {
        &self.pixmap
    }

    pub(crate) fn pixmap_mut(&mut self) -> &mut Pixmap {
        &mut self.pixmap
    }

    /// Width in pixels.
    #[must_use]
    pub fn width(&self) -> u32 {
        self.pixmap.width()
    }

    /// Height in pixels.
    #[must_use]
    pub fn height(&self) -> u32 {
        self.pixmap.height()
    }

    /// The colour of pixel `(x, y)` (`(0, 0)` is the top-left), or `None` outside the image.
    #[must_use]
    pub fn pixel(&self, x: u32, y: u32) -> Option<Rgba> {
        let c = self.pixmap.pixel(x, y)?.demultiply();
        Some(Rgba::new(c.red(), c.green(), c.blue(), c.alpha()))
    }

    /// The image as a PNG file's bytes (8-bit RGBA).
    pub fn to_png(&self) -> Result<Vec<u8>, RenderError> {
        Ok(self.pixmap.encode_png()?)
    }

    /// Writes the image as a PNG file.
    pub fn save_png(&self, path: impl AsRef<Path>) -> Result<(), RenderError> {
        RenderError::write_file(path.as_ref(), &self.to_png()?)
    }
}
