//! Images of one size, frame after frame, as an animated GIF.

use std::borrow::Cow;
use std::path::Path;

use gif::{Encoder, Repeat};

use crate::palette::Palette;
use crate::{DEFAULT_FRAME_DELAY, Image, MAX_GIF_BYTES, RenderError, Style};

/// An animated GIF of images the caller renders, all of one size, looping forever: for
/// frames that are not one canvas's pictures (a [`Camera`](crate::Camera) that zooms
/// renders each frame on a canvas of its own, and a HUD is drawn on the image after).
///
/// Each frame is reduced to the fixed palette of [`Animation`](crate::Animation) (the
/// style's colours exactly, the 6 × 6 × 6 colour cube, greys) and compressed as soon as it
/// is pushed.
///
/// ```
/// use tileslide_render::{ImageAnimation, Image, Rgba, Style};
///
/// let mut gif = ImageAnimation::new(32, 16, &Style::default())?;
/// for shade in [0, 51, 102] {
///     gif.push(&Image::filled(32, 16, Rgba::opaque(shade, shade, shade))?)?;
/// }
/// gif.set_frame_delay(100); // the last frame shows for a second
/// gif.push(&Image::filled(32, 16, Rgba::opaque(255, 255, 255))?)?;
/// assert_eq!(gif.frame_count(), 4);
/// assert!(gif.push(&Image::filled(8, 8, Rgba::opaque(0, 0, 0))?).is_err()); // wrong size
/// assert!(gif.finish()?.starts_with(b"GIF89a"));
/// # Ok::<(), tileslide_render::RenderError>(())
/// ```
pub struct ImageAnimation {
    encoder: Encoder<Vec<u8>>,
    palette: Palette,
    /// The frame's palette indices, reused.
    indices: Vec<u8>,
    /// Frame width and height (checked to fit a GIF).
    size: (u16, u16),
    frames: usize,
    delay: u16,
    /// The most bytes the GIF may hold before a push: [`MAX_GIF_BYTES`].
    max_bytes: u64,
}

impl ImageAnimation {
    /// An animation of `width × height` images drawn in `style`'s colours, or
    /// [`RenderError::TooLargeForGif`] if a side is longer than a GIF can hold.
    pub fn new(width: u32, height: u32, style: &Style) -> Result<Self, RenderError> {
        let too_large = || RenderError::TooLargeForGif { width, height };
        let w = u16::try_from(width).map_err(|_| too_large())?;
        let h = u16::try_from(height).map_err(|_| too_large())?;
        let palette = Palette::new(style);
        let mut encoder = Encoder::new(Vec::new(), w, h, palette.rgb())?;
        encoder.set_repeat(Repeat::Infinite)?;
        Ok(Self {
            encoder,
            palette,
            indices: Vec::new(),
            size: (w, h),
            frames: 0,
            delay: DEFAULT_FRAME_DELAY,
            max_bytes: MAX_GIF_BYTES,
        })
    }

    /// Frames pushed from now on show for `centiseconds` hundredths of a second each.
    pub fn set_frame_delay(&mut self, centiseconds: u16) {
        self.delay = centiseconds;
    }

    /// Appends `image` as the next frame, or [`RenderError::FrameSize`] if it is not the
    /// animation's size, or [`RenderError::GifTooLarge`] once the GIF holds
    /// [`MAX_GIF_BYTES`].
    pub fn push(&mut self, image: &Image) -> Result<(), RenderError> {
        let bytes = self.encoder.get_ref().len() as u64;
        if bytes >= self.max_bytes {
            return Err(RenderError::GifTooLarge {
                frames: self.frames,
                bytes,
            });
        }
        if (image.width(), image.height()) != (self.width(), self.height()) {
            return Err(RenderError::FrameSize {
                width: self.width(),
                height: self.height(),
                got_width: image.width(),
                got_height: image.height(),
            });
        }
        self.palette.index_pixels(image.pixmap(), &mut self.indices);
        let frame = gif::Frame {
            delay: self.delay,
            width: self.size.0,
            height: self.size.1,
            buffer: Cow::Borrowed(&self.indices),
            ..gif::Frame::default()
        };
        self.encoder.write_frame(&frame)?;
        self.frames += 1;
        Ok(())
    }

    /// Frames pushed so far.
    #[must_use]
    pub fn frame_count(&self) -> usize {
        self.frames
    }

    /// Frame width in pixels.
    #[must_use]
    pub fn width(&self) -> u32 {
        self.size.0.into()
    }

    /// Frame height in pixels.
    #[must_use]
    pub fn height(&self) -> u32 {
        self.size.1.into()
    }

    /// The frame delay now, in hundredths of a second.
    pub(crate) fn delay(&self) -> u16 {
        self.delay
    }

    /// The GIF file's bytes (a GIF with no frame is still a valid file).
    pub fn finish(self) -> Result<Vec<u8>, RenderError> {
        Ok(self.encoder.into_inner()?)
    }

    /// Writes the GIF file (see [`finish`](Self::finish)).
    pub fn save_gif(self, path: impl AsRef<Path>) -> Result<(), RenderError> {
        RenderError::write_file(path.as_ref(), &self.finish()?)
    }
}

impl std::fmt::Debug for ImageAnimation {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ImageAnimation")
            .field("width", &self.width())
            .field("height", &self.height())
            .field("frames", &self.frames)
            .field("delay", &self.delay)
            .finish_non_exhaustive()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Rgba;

    #[test]
    fn frames_past_the_byte_limit_are_refused_and_the_gif_stays_whole() {
        let mut gif = ImageAnimation::new(64, 64, &Style::default()).unwrap();
        gif.max_bytes = 2_000;
        let mut pushed = 0;
        let error = loop {
            // Noise, which compresses badly: a few frames pass the limit.
            let mut image = Image::filled(64, 64, Rgba::opaque(0, 0, 0)).unwrap();
            for (i, p) in image.pixmap_mut().pixels_mut().iter_mut().enumerate() {
                let v = ((i * 7919 + pushed * 104_729) % 251) as u8;
                *p = tiny_skia::PremultipliedColorU8::from_rgba(v, v / 2, 255 - v, 255).unwrap();
            }
            match gif.push(&image) {
                Ok(()) => pushed += 1,
                Err(e) => break e,
            }
            assert!(pushed < 100, "the limit was never reached");
        };
        assert!(pushed >= 1);
        assert!(error.to_string().contains("MAX_GIF_BYTES"), "{error}");
        match error {
            RenderError::GifTooLarge { frames, bytes } => {
                assert_eq!(frames, pushed);
                assert!(bytes >= 2_000);
            }
            other => panic!("{other}"),
        }
        assert_eq!(gif.frame_count(), pushed, "a refused frame is not taken");
        let bytes = gif.finish().unwrap();
        assert!(bytes.starts_with(b"GIF89a") && bytes.ends_with(&[0x3b]));
    }
}
