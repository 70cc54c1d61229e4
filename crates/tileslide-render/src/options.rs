//! How a map is turned into pixels: scale, which way is up, colours.

use tileslide::DebugKind;
use tileslide::debug::DebugKinds;

use crate::Style;

/// The kinds drawn unless told otherwise: every kind but hidden seam segments, which
/// would draw a grid inside every solid area.
pub const DEFAULT_LAYERS: DebugKinds = DebugKinds::ALL.without(DebugKind::HiddenSegment);

/// The most pixels an image may have: 32 Mi (128 MiB of RGBA), so a huge map or a typo in
/// the scale is refused instead of allocating gigabytes.
pub const MAX_PIXELS: u64 = 1 << 25;

/// The most bytes an animation's GIF may grow to (1 GiB): frames are compressed as they are
/// pushed, and a push past this is refused ([`RenderError::GifTooLarge`](crate::RenderError::GifTooLarge)), so a
/// loop that never stops recording does not take all the memory.
pub const MAX_GIF_BYTES: u64 = 1 << 30;

/// The scale used unless told otherwise: 16 pixels per cell.
pub const DEFAULT_PIXELS_PER_CELL: f32 = 16.0;

/// Which way the map's y axis points in the picture.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum YAxis {
    /// y grows down the image: row 0 at the top. For maps whose "up" is −y (ASCII maps,
    /// Tiled maps).
    #[default]
    Down,
    /// y grows up the image: row 0 at the bottom. For maps whose "up" is +y (Replica Island
    /// levels).
    Up,
}

/// The scale, orientation and colours of a picture.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderOptions {
    /// Pixels per cell along x (positive, finite; need not be whole). A map with
    /// non-square cells keeps its proportions: a cell is `pixels_per_cell × h / w` pixels
    /// tall.
    pub pixels_per_cell: f32,
    /// Which way y points in the picture.
    pub y_axis: YAxis,
    /// The colours.
    pub style: Style,
    /// Which kinds of [debug lines](tileslide::DebugLines) are drawn, on the canvas and
    /// in pictures ([`DEFAULT_LAYERS`] unless told otherwise).
    pub layers: DebugKinds,
}

impl Default for RenderOptions {
    fn default() -> Self {
        Self {
            pixels_per_cell: DEFAULT_PIXELS_PER_CELL,
            y_axis: YAxis::Down,
            style: Style::default(),
            layers: DEFAULT_LAYERS,
        }
    }
}

impl RenderOptions {
    /// These options with another scale.
    #[must_use]
    pub fn with_pixels_per_cell(self, pixels_per_cell: f32) -> Self {
        Self {
            pixels_per_cell,
            ..self
        }
    }

    /// These options with another orientation.
    #[must_use]
    pub fn with_y_axis(self, y_axis: YAxis) -> Self {
        Self { y_axis, ..self }
    }

    /// These options drawing only the kinds of debug lines in `layers`.
    ///
    /// ```
    /// use tileslide::DebugKind;
    /// use tileslide_render::{RenderOptions, DEFAULT_LAYERS};
    ///
    /// // The seams the map hides, faint, as well as everything else.
    /// let options = RenderOptions::default().with_layers(DEFAULT_LAYERS.with(DebugKind::HiddenSegment));
    /// assert!(options.layers.contains(DebugKind::HiddenSegment));
    /// ```
    #[must_use]
    pub fn with_layers(self, layers: DebugKinds) -> Self {
        Self { layers, ..self }
    }

    /// These options with other colours.
    #[must_use]
    pub fn with_style(self, style: Style) -> Self {
        Self { style, ..self }
    }
}
