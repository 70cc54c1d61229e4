//! The fixed 256-colour palette of animations: the style's colours exactly, then an even
//! colour cube for anti-aliased edges and translucent volumes.
//!
//! A fixed palette instead of per-frame quantisation (NeuQuant, as `gif`'s
//! `Frame::from_rgba_speed` does) keeps every frame's colours the same, so bodies do not
//! flicker between frames, and costs one table look-up per pixel.

use tiny_skia::Pixmap;

use crate::{Rgba, Style};

/// Steps of the colour cube on each channel (6 × 6 × 6 = 216 colours).
const CUBE_LEVELS: [u8; 6] = [0, 51, 102, 153, 204, 255];
/// Marks a look-up table entry not yet computed.
const UNKNOWN: u16 = u16::MAX;

/// A palette of at most 256 colours and a cache from 15-bit colour to palette index.
pub(crate) struct Palette {
    /// `[r, g, b, r, g, b, …]`, at most 256 colours.
    rgb: Vec<u8>,
    /// Palette index of each colour with 5 bits a channel, or [`UNKNOWN`].
    lookup: Vec<u16>,
}

impl Palette {
    /// The palette for pictures drawn in `style`.
    pub fn new(style: &Style) -> Self {
        let mut colors: Vec<[u8; 3]> = Vec::with_capacity(256);
        let mut add = |c: [u8; 3]| {
            if colors.len() < 256 && !colors.contains(&c) {
                colors.push(c);
            }
        };
        for c in style.colors() {
            add([c.r, c.g, c.b]);
        }
        for r in CUBE_LEVELS {
            for g in CUBE_LEVELS {
                for b in CUBE_LEVELS {
                    add([r, g, b]);
                }
            }
        }
        // Greys between the cube's, for the rest.
        for v in (0..=255u8).step_by(6) {
            add([v, v, v]);
        }
        let mut palette = Self {
            rgb: colors.concat(),
            lookup: vec![UNKNOWN; 1 << 15],
        };
        // The style's colours land on themselves, whatever is nearer the middle of their bin.
        for c in style.colors() {
            if let Some(index) = palette.exact(c) {
                palette.lookup[bin(c.r, c.g, c.b)] = index;
            }
        }
        palette
    }

    /// `[r, g, b, …]` for the GIF's global colour table.
    pub fn rgb(&self) -> &[u8] {
        &self.rgb
    }

    /// Replaces `indices` with the palette index of each pixel (alpha is ignored: pictures
    /// are drawn on an opaque background).
    pub fn index_pixels(&mut self, pixmap: &Pixmap, indices: &mut Vec<u8>) {
        indices.clear();
        indices.reserve(pixmap.pixels().len());
        for p in pixmap.pixels() {
            let c = p.demultiply();
            indices.push(self.index(c.red(), c.green(), c.blue()));
        }
    }

    fn index(&mut self, r: u8, g: u8, b: u8) -> u8 {
        let key = bin(r, g, b);
        if self.lookup[key] == UNKNOWN {
            // The middle of the bin, so the answer does not depend on which pixel came first.
            let mid = |v: u8| i32::from(v | 4);
            self.lookup[key] = self.nearest(mid(r), mid(g), mid(b));
        }
        // Every entry is a palette index (< 256) once computed.
        self.lookup[key] as u8
    }

    fn nearest(&self, r: i32, g: i32, b: i32) -> u16 {
        let mut best = (i32::MAX, 0u16);
        for (i, c) in self.rgb.chunks_exact(3).enumerate() {
            let d = |v: u8, w: i32| (i32::from(v) - w).pow(2);
            let distance = d(c[0], r) + d(c[1], g) + d(c[2], b);
            if distance < best.0 {
                best = (distance, i as u16);
            }
        }
        best.1
    }

    fn exact(&self, c: Rgba) -> Option<u16> {
        self.rgb
            .chunks_exact(3)
            .position(|p| p == [c.r, c.g, c.b])
            .map(|i| i as u16)
    }
}

/// The look-up table slot of a colour: 5 bits a channel.
fn bin(r: u8, g: u8, b: u8) -> usize {
    (usize::from(r >> 3) << 10) | (usize::from(g >> 3) << 5) | usize::from(b >> 3)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn style_colors_map_to_themselves() {
        let style = Style::default();
        let mut palette = Palette::new(&style);
        assert!(palette.rgb().len() <= 256 * 3);
        for c in style.colors() {
            let i = usize::from(palette.index(c.r, c.g, c.b));
            assert_eq!(&palette.rgb()[3 * i..3 * i + 3], &[c.r, c.g, c.b]);
        }
    }

    #[test]
    fn other_colors_map_to_a_near_one() {
        let mut palette = Palette::new(&Style::default());
        let i = usize::from(palette.index(100, 200, 50));
        let c = &palette.rgb()[3 * i..3 * i + 3];
        let far = c
            .iter()
            .zip([100u8, 200, 50])
            .map(|(&a, b)| a.abs_diff(b))
            .max();
        assert!(far.is_some_and(|d| d <= 32), "{c:?}");
    }
}
