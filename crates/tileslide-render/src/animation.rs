//! Pictures over one canvas, frame after frame, as an animated GIF.

use std::path::Path;

use crate::{Canvas, Image, ImageAnimation, Picture, RenderError};

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
    frames: ImageAnimation,
    /// The frame being made, reused.
    image: Image,
}

impl<'c> Animation<'c> {
    /// An animation over `canvas`, or [`RenderError::TooLargeForGif`] if a side is longer
    /// than a GIF can hold.
    pub fn new(canvas: &'c Canvas) -> Result<Self, RenderError> {
        Ok(Self {
            canvas,
            frames: ImageAnimation::new(canvas.width(), canvas.height(), canvas.style())?,
            image: canvas.render(&Picture::new()),
        })
    }

    /// This animation with frames pushed from now on shown for `centiseconds` hundredths of
    /// a second each.
    #[must_use]
    pub fn with_frame_delay(mut self, centiseconds: u16) -> Self {
        self.frames.set_frame_delay(centiseconds);
        self
    }

    /// Renders `picture` over the canvas and appends it as the next frame.
    pub fn push(&mut self, picture: &Picture) -> Result<(), RenderError> {
        self.canvas.render_into(picture, &mut self.image);
        self.frames.push(&self.image)
    }

    /// Frames pushed so far.
    #[must_use]
    pub fn frame_count(&self) -> usize {
        self.frames.frame_count()
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
        if self.frames.frame_count() == 0 {
            self.push(&Picture::new())?;
        }
        self.frames.finish()
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
            .field("frames", &self.frames.frame_count())
            .field("delay", &self.frames.delay())
            .finish_non_exhaustive()
    }
}
