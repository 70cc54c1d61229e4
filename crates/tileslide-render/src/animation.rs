//! Pictures over one canvas, frame after frame, as an animated GIF.

use std::borrow::Cow;
use std::path::Path;

use gif::{Encoder, Repeat};

use crate::palette::Palette;
use crate::{Canvas, Image, Picture, RenderError};

/// Time each frame shows unless told otherwise: 5 hundredths of a second (20 frames a
/// second).
pub const DEFAULT_FRAME_DELAY: u16 = 5;

/// An animated GIF of pictures over one [`Canvas`], looping forever.
///
/// Each frame is rendered, reduced to a fixed palette (the style's colours exactly, plus a
/// colour cube for edges and translucent volumes) and compressed as soon as it is pushed,
/// so memory holds the compressed GIF and one frame, not every frame's pixels.
///
/// ```
/// use tileslide::io::ascii;
/// use tileslide::{Circle, Vec2};
/// use tileslide_render::{Animation, Canvas, Picture, RenderOptions};
///
/// let map = ascii::parse("#####\n#...#\n#####", "hall.txt", 1.0)?;
/// let canvas = Canvas::new(&map, &RenderOptions::default())?;
/// let mut animation = Animation::new(&canvas)?;
/// let mut picture = Picture::new();
/// for step in 0..4 {
///     picture.clear();
///     picture.body(Circle::new(Vec2::new(1.5 + 0.5 * step as f32, 1.5), 0.4));
///     animation.push(&picture)?;
/// }
/// assert_eq!(animation.frame_count(), 4);
/// let gif = animation.finish()?; // or animation.save_gif("hall.gif")?
/// assert!(gif.starts_with(b"GIF89a"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub struct Animation<'c> {
    canvas: &'c Canvas,
    encoder: Encoder<Vec<u8>>,
    palette: Palette,
    /// The frame being made, reused.
    image: Image,
    /// Its palette indices, reused.
    indices: Vec<u8>,
    /// Frame width and height (checked to fit a GIF).
    size: (u16, u16),
    frames: usize,
    delay: u16,
}

impl<'c> Animation<'c> {
    /// An animation over `canvas`, or [`RenderError::TooLargeForGif`] if a side is longer
    /// than a GIF can hold.
    pub fn new(canvas: &'c Canvas) -> Result<Self, RenderError> {
        let too_large = || RenderError::TooLargeForGif {
            width: canvas.width(),
            height: canvas.height(),
        };
        let width = u16::try_from(canvas.width()).map_err(|_| too_large())?;
        let height = u16::try_from(canvas.height()).map_err(|_| too_large())?;
        let palette = Palette::new(canvas.style());
        let mut encoder = Encoder::new(Vec::new(), width, height, palette.rgb())?;
        encoder.set_repeat(Repeat::Infinite)?;
        Ok(Self {
            canvas,
            encoder,
            palette,
            image: canvas.render(&Picture::new()),
            indices: Vec::new(),
            size: (width, height),
            frames: 0,
            delay: DEFAULT_FRAME_DELAY,
        })
    }

    /// This animation with frames pushed from now on shown for `centiseconds` hundredths of
    /// a second each.
    #[must_use]
    pub fn with_frame_delay(mut self, centiseconds: u16) -> Self {
        self.delay = centiseconds;
        self
    }

    /// Renders `picture` over the canvas and appends it as the next frame.
    pub fn push(&mut self, picture: &Picture) -> Result<(), RenderError> {
        self.canvas.render_into(picture, &mut self.image);
        self.palette
            .index_pixels(self.image.pixmap(), &mut self.indices);
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

    /// Frame width in pixels (the canvas's).
    #[must_use]
    pub fn width(&self) -> u32 {
        self.canvas.width()
    }

    /// Frame height in pixels (the canvas's).
    #[must_use]
    pub fn height(&self) -> u32 {
        self.canvas.height()
    }

    /// The GIF file's bytes. With no frame pushed, the map alone is the one frame, so the
    /// file always holds an image.
    pub fn finish(mut self) -> Result<Vec<u8>, RenderError> {
        if self.frames == 0 {
            self.push(&Picture::new())?;
        }
        Ok(self.encoder.into_inner()?)
    }

    /// Writes the GIF file (see [`finish`](Self::finish)).
    pub fn save_gif(self, path: impl AsRef<Path>) -> Result<(), RenderError> {
        RenderError::write_file(path.as_ref(), &self.finish()?)
    }
}

impl std::fmt::Debug for Animation<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Animation")
            .field("width", &self.width())
            .field("height", &self.height())
            .field("frames", &self.frames)
            .field("delay", &self.delay)
            .finish_non_exhaustive()
    }
}
