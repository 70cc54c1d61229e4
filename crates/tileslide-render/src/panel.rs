//! A legend or HUD beside a picture: headings, lines of text, keys with their swatches.

use tileslide::Vec2;

use crate::pen::Pen;
use crate::{Anchor, FontSize, Image, Rgba};

/// What a legend key shows beside its label.
#[derive(Clone, Debug, PartialEq)]
pub enum Swatch {
    /// A disc (a body, a creature).
    Disc(Rgba),
    /// A small disc (a projectile, a coin).
    Dot(Rgba),
    /// A filled square (a kind of ground).
    Square(Rgba),
    /// A square with a short text on it (a mark drawn on map cells, such as a cost).
    Marked {
        /// The square's colour.
        fill: Rgba,
        /// The text on it.
        text: String,
        /// The text's colour.
        ink: Rgba,
    },
    /// A bar, `fraction` (0 to 1) of it in `fill`, the rest in `empty` (a health bar).
    Bar {
        /// The full part.
        fill: Rgba,
        /// The empty part.
        empty: Rgba,
        /// How much is full.
        fraction: f32,
    },
}

/// One row of a panel.
#[derive(Clone, Debug, PartialEq)]
enum Row {
    Heading(String),
    Line(String),
    Key(Swatch, String),
    Gap,
}

/// A column of text drawn over a rectangle of an image: a legend (keys: a swatch and its
/// label), a HUD (lines of figures), headings between them. Rows are laid out from the
/// top; what does not fit the rectangle is left out.
///
/// ```
/// use tileslide_render::{Image, Panel, Rgba, Swatch};
///
/// let (dark, light) = (Rgba::opaque(51, 51, 51), Rgba::opaque(255, 255, 255));
/// let mut panel = Panel::new(dark, light);
/// panel
///     .heading("Dungeon")
///     .line("wave 2   gold 120")
///     .gap()
///     .key(Swatch::Disc(Rgba::opaque(0, 204, 255)), "hero");
/// let mut image = Image::filled(300, 200, Rgba::opaque(0, 0, 0))?;
/// panel.draw(&mut image, (200, 0), (100, 200));
/// assert_eq!(image.pixel(299, 199), Some(dark)); // the panel's background
/// assert_eq!(image.pixel(10, 10), Some(Rgba::opaque(0, 0, 0))); // left alone
/// # Ok::<(), tileslide_render::RenderError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Panel {
    background: Rgba,
    ink: Rgba,
    rows: Vec<Row>,
}

/// Pixels between the panel's edge and its text.
const PADDING: i32 = 8;
/// Pixels between rows.
const LEADING: i32 = 4;
/// Width of a key's swatch, in pixels.
const SWATCH: i32 = 16;

impl Panel {
    /// An empty panel with text in `ink` over `background`.
    #[must_use]
    pub fn new(background: Rgba, ink: Rgba) -> Self {
        Self {
            background,
            ink,
            rows: Vec::new(),
        }
    }

    /// Removes every row, keeping the colours.
    pub fn clear(&mut self) {
        self.rows.clear();
    }

    /// A heading, in bold.
    pub fn heading(&mut self, text: impl Into<String>) -> &mut Self {
        self.rows.push(Row::Heading(text.into()));
        self
    }

    /// A line of text.
    pub fn line(&mut self, text: impl Into<String>) -> &mut Self {
        self.rows.push(Row::Line(text.into()));
        self
    }

    /// A legend key: `swatch`, then `label`.
    pub fn key(&mut self, swatch: Swatch, label: impl Into<String>) -> &mut Self {
        self.rows.push(Row::Key(swatch, label.into()));
        self
    }

    /// An empty row.
    pub fn gap(&mut self) -> &mut Self {
        self.rows.push(Row::Gap);
        self
    }

    /// Fills `size` pixels from `top_left` of `image` with the background and draws the
    /// rows over it, from the top.
    pub fn draw(&self, image: &mut Image, top_left: (i32, i32), size: (u32, u32)) {
        image.fill_rect(top_left, size, self.background);
        let bottom = top_left
            .1
            .saturating_add(i32::try_from(size.1).unwrap_or(i32::MAX));
        let x = top_left.0 + PADDING;
        let mut y = top_left.1 + PADDING;
        for row in &self.rows {
            let height = match row {
                Row::Heading(_) => FontSize::Large.height() as i32,
                Row::Key(..) => (FontSize::Medium.height() as i32).max(12),
                Row::Line(_) | Row::Gap => FontSize::Medium.height() as i32,
            };
            if y + height > bottom {
                break;
            }
            match row {
                Row::Heading(text) => {
                    image.text(text, (x, y), FontSize::Large, Anchor::TopLeft, self.ink);
                }
                Row::Line(text) => {
                    image.text(text, (x, y), FontSize::Medium, Anchor::TopLeft, self.ink);
                }
                Row::Key(swatch, label) => {
                    let middle = Vec2::new((x + SWATCH / 2) as f32, y as f32 + height as f32 / 2.0);
                    draw_swatch(image, swatch, middle);
                    let text_y = y + (height - FontSize::Medium.height() as i32) / 2;
                    let at = (x + SWATCH + 6, text_y);
                    image.text(label, at, FontSize::Medium, Anchor::TopLeft, self.ink);
                }
                Row::Gap => {}
            }
            y += height + LEADING;
        }
    }
}

impl Panel {
    /// Like [`draw`](Self::draw), but laid out across: the rows one after another from
    /// the left, in one line centred in the rectangle's height (a legend strip under a
    /// wide picture). Gaps are wider spaces; what does not fit the width is left out.
    pub fn draw_across(&self, image: &mut Image, top_left: (i32, i32), size: (u32, u32)) {
        image.fill_rect(top_left, size, self.background);
        let right = top_left
            .0
            .saturating_add(i32::try_from(size.0).unwrap_or(i32::MAX));
        let middle = top_left.1 + (size.1 / 2) as i32;
        let mut x = top_left.0 + PADDING;
        for row in &self.rows {
            let (font, text) = match row {
                Row::Heading(text) => (FontSize::Large, text.as_str()),
                Row::Line(text) | Row::Key(_, text) => (FontSize::Medium, text.as_str()),
                Row::Gap => (FontSize::Medium, ""),
            };
            let swatch = if matches!(row, Row::Key(..)) {
                SWATCH + 6
            } else {
                0
            };
            let width = swatch + font.width_of(text) as i32 + 2 * PADDING;
            if x + width - PADDING > right {
                break;
            }
            if let Row::Key(s, _) = row {
                draw_swatch(image, s, Vec2::new((x + SWATCH / 2) as f32, middle as f32));
            }
            let at = (x + swatch, middle - (font.height() / 2) as i32);
            image.text(text, at, font, Anchor::TopLeft, self.ink);
            x += width;
        }
    }
}

/// Draws `swatch` centred on `middle` (pixels), [`SWATCH`] pixels wide.
fn draw_swatch(image: &mut Image, swatch: &Swatch, middle: Vec2) {
    let half = SWATCH as f32 / 2.0;
    let corner = |h: f32| ((middle.x - h) as i32, (middle.y - h) as i32);
    let clear = Rgba::new(0, 0, 0, 0);
    match swatch {
        Swatch::Disc(c) => {
            let mut pen = Pen::new(image.pixmap_mut());
            pen.disc(middle, half - 2.0, *c, Rgba::opaque(0, 0, 0), 1.0);
        }
        Swatch::Dot(c) => {
            let mut pen = Pen::new(image.pixmap_mut());
            pen.disc(middle, 3.0, *c, clear, 0.0);
        }
        Swatch::Square(c) => {
            image.fill_rect(
                corner(half - 1.0),
                (SWATCH as u32 - 2, SWATCH as u32 - 2),
                *c,
            );
        }
        Swatch::Marked { fill, text, ink } => {
            image.fill_rect(
                corner(half - 1.0),
                (SWATCH as u32 - 2, SWATCH as u32 - 2),
                *fill,
            );
            let at = (middle.x as i32, middle.y as i32);
            image.text(text, at, FontSize::Small, Anchor::Center, *ink);
        }
        Swatch::Bar {
            fill,
            empty,
            fraction,
        } => {
            let f = if fraction.is_finite() {
                fraction.clamp(0.0, 1.0)
            } else {
                0.0
            };
            let (left, top) = ((middle.x - half) as i32, middle.y as i32 - 2);
            let full = (SWATCH as f32 * f).round() as u32;
            image.fill_rect((left, top), (SWATCH as u32, 4), *empty);
            image.fill_rect((left, top), (full, 4), *fill);
        }
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;

    const DARK: Rgba = Rgba::opaque(51, 51, 51);
    const INK: Rgba = Rgba::opaque(255, 255, 255);
    const CYAN: Rgba = Rgba::opaque(0, 204, 255);

    fn count(
        image: &Image,
        color: Rgba,
        x: std::ops::Range<u32>,
        y: std::ops::Range<u32>,
    ) -> usize {
        y.flat_map(|y| x.clone().map(move |x| (x, y)))
            .filter(|&(x, y)| image.pixel(x, y) == Some(color))
            .count()
    }

    #[test]
    fn rows_are_drawn_top_down_with_their_swatches() {
        let mut panel = Panel::new(DARK, INK);
        panel
            .heading("Legend")
            .key(Swatch::Disc(CYAN), "hero")
            .line("wave 3");
        let mut image = Image::filled(200, 120, Rgba::opaque(0, 0, 0)).unwrap();
        panel.draw(&mut image, (100, 0), (100, 120));
        // The heading's text is in the first rows of pixels, the cyan disc below it.
        assert!(count(&image, INK, 100..200, 0..24) > 20);
        assert!(count(&image, CYAN, 100..130, 24..44) > 30);
        // Nothing of the panel left its rectangle.
        assert_eq!(count(&image, INK, 0..100, 0..120), 0);
        assert_eq!(count(&image, DARK, 0..100, 0..120), 0);
    }

    #[test]
    fn across_the_rows_go_left_to_right_in_one_line() {
        let mut panel = Panel::new(DARK, INK);
        panel
            .key(Swatch::Disc(CYAN), "hero")
            .key(Swatch::Square(Rgba::opaque(255, 0, 0)), "fire");
        let mut image = Image::filled(300, 60, Rgba::opaque(0, 0, 0)).unwrap();
        panel.draw_across(&mut image, (0, 30), (300, 24));
        assert_eq!(count(&image, DARK, 0..300, 0..30), 0);
        // The disc comes first, the square after the first label, on one line.
        let red = Rgba::opaque(255, 0, 0);
        assert!(count(&image, CYAN, 0..30, 30..54) > 30);
        assert_eq!(count(&image, red, 0..40, 30..54), 0);
        assert!(count(&image, red, 40..120, 30..54) > 30);
        assert!(count(&image, INK, 0..300, 30..54) > 40);
    }

    #[test]
    fn rows_that_do_not_fit_are_left_out() {
        let mut panel = Panel::new(DARK, INK);
        for k in 0..40 {
            panel.line(format!("line {k}"));
        }
        let mut image = Image::filled(100, 60, Rgba::opaque(0, 0, 0)).unwrap();
        panel.draw(&mut image, (0, 0), (100, 40));
        assert_eq!(count(&image, INK, 0..100, 40..60), 0);
        assert!(count(&image, INK, 0..100, 0..40) > 0);
    }
}
