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

    /// An image `width × height` pixels filled with `color`, or
    /// [`RenderError::TooLarge`] for an empty or too large one.
    pub fn filled(width: u32, height: u32, color: Rgba) -> Result<Self, RenderError> {
        let too_large = || RenderError::TooLarge {
            width: width.into(),
            height: height.into(),
        };
        if u64::from(width) * u64::from(height) > crate::MAX_PIXELS {
            return Err(too_large());
        }
        let mut pixmap = Pixmap::new(width, height).ok_or_else(too_large)?;
        pixmap.fill(color.to_skia());
        Ok(Self { pixmap })
    }

    /// Fills the `width × height` pixels from `(left, top)` with `color` (blended when
    /// translucent); what falls outside the image is cut.
    pub fn fill_rect(&mut self, (left, top): (i32, i32), (width, height): (u32, u32), color: Rgba) {
        let rect = tiny_skia::Rect::from_xywh(left as f32, top as f32, width as f32, height as f32);
        if let Some(rect) = rect {
            let mut paint = tiny_skia::Paint::default();
            paint.set_color(color.to_skia());
            self.pixmap
                .fill_rect(rect, &paint, tiny_skia::Transform::identity(), None);
        }
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
