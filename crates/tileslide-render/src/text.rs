//! Text on an image: legends, HUDs and labels, in the monospaced bitmap fonts that
//! `embedded-graphics` ships (the X11 misc-fixed fonts, in the public domain).
//!
//! Bitmap glyphs are drawn pixel for pixel in one colour, with no anti-aliasing, so text
//! stays crisp at any size of GIF palette and tests can find its pixels exactly.

use embedded_graphics::Drawable;
use embedded_graphics::draw_target::DrawTarget;
use embedded_graphics::geometry::{OriginDimensions, Point, Size};
use embedded_graphics::mono_font::{MonoFont, MonoTextStyle, ascii};
use embedded_graphics::pixelcolor::{Rgb888, RgbColor};
use embedded_graphics::text::{Baseline, Text};
use tiny_skia::{Pixmap, PremultipliedColorU8};

use crate::{Image, Rgba};

/// The size of a font, from the fonts `embedded-graphics` ships.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum FontSize {
    /// 5 × 7 pixels a character: labels inside map cells.
    Small,
    /// 6 × 10 pixels a character: legends and HUD lines.
    #[default]
    Medium,
    /// 7 × 13 pixels a character, bold: headings.
    Large,
    /// 10 × 20 pixels a character: banners.
    Huge,
}

impl FontSize {
    fn font(self) -> &'static MonoFont<'static> {
        match self {
            FontSize::Small => &ascii::FONT_5X7,
            FontSize::Medium => &ascii::FONT_6X10,
            FontSize::Large => &ascii::FONT_7X13_BOLD,
            FontSize::Huge => &ascii::FONT_10X20,
        }
    }

    /// Width of `text` in pixels when drawn in this size (characters outside ASCII count
    /// as one, drawn as `?`).
    #[must_use]
    pub fn width_of(self, text: &str) -> u32 {
        let font = self.font();
        let n = text.chars().count() as u32;
        if n == 0 {
            return 0;
        }
        n * font.character_size.width + (n - 1) * font.character_spacing
    }

    /// Height of a line of text in pixels.
    #[must_use]
    pub fn height(self) -> u32 {
        self.font().character_size.height
    }
}

/// Where a text is placed relative to the point given.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Anchor {
    /// The point is the text's top-left corner.
    #[default]
    TopLeft,
    /// The point is the middle of the text's box.
    Center,
}

impl Image {
    /// Draws `text` in `color` (opaque; its alpha is ignored) at pixel `at` of the image,
    /// placed by `anchor`; what falls outside the image is cut. Characters outside ASCII
    /// are drawn as `?`.
    ///
    /// ```
    /// use tileslide_render::{Anchor, FontSize, Image, Rgba};
    ///
    /// let mut image = Image::filled(40, 12, Rgba::opaque(0, 0, 0))?;
    /// image.text("HP 30", (1, 1), FontSize::Medium, Anchor::TopLeft, Rgba::opaque(255, 255, 255));
    /// let lit = (0..40).flat_map(|x| (0..12).map(move |y| (x, y)))
    ///     .filter(|&(x, y)| image.pixel(x, y) == Some(Rgba::opaque(255, 255, 255)))
    ///     .count();
    /// assert!(lit > 20);
    /// # Ok::<(), tileslide_render::RenderError>(())
    /// ```
    pub fn text(
        &mut self,
        text: &str,
        at: (i32, i32),
        size: FontSize,
        anchor: Anchor,
        color: Rgba,
    ) {
        let top_left = match anchor {
            Anchor::TopLeft => Point::new(at.0, at.1),
            Anchor::Center => Point::new(
                at.0 - (size.width_of(text) / 2) as i32,
                at.1 - (size.height() / 2) as i32,
            ),
        };
        let style = MonoTextStyle::new(size.font(), Rgb888::new(color.r, color.g, color.b));
        let mut target = Glyphs {
            pixmap: self.pixmap_mut(),
        };
        // Drawing into a pixmap cannot fail (`Glyphs` has no error), and the position
        // where a next text would go is not needed.
        let _ = Text::with_baseline(text, top_left, style, Baseline::Top).draw(&mut target);
    }
}

/// A pixmap as an `embedded-graphics` target: each lit glyph pixel is written opaque.
struct Glyphs<'a> {
    pixmap: &'a mut Pixmap,
}

impl OriginDimensions for Glyphs<'_> {
    fn size(&self) -> Size {
        Size::new(self.pixmap.width(), self.pixmap.height())
    }
}

impl DrawTarget for Glyphs<'_> {
    type Color = Rgb888;
    type Error = std::convert::Infallible;

    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = embedded_graphics::Pixel<Self::Color>>,
    {
        let (width, height) = (self.pixmap.width(), self.pixmap.height());
        let data = self.pixmap.pixels_mut();
        for embedded_graphics::Pixel(p, c) in pixels {
            let (Ok(x), Ok(y)) = (u32::try_from(p.x), u32::try_from(p.y)) else {
                continue;
            };
            if x >= width || y >= height {
                continue;
            }
            if let Some(color) = PremultipliedColorU8::from_rgba(c.r(), c.g(), c.b(), 255) {
                data[y as usize * width as usize + x as usize] = color;
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;

    const WHITE: Rgba = Rgba::opaque(255, 255, 255);

    fn lit(image: &Image) -> Vec<(u32, u32)> {
        (0..image.height())
            .flat_map(|y| (0..image.width()).map(move |x| (x, y)))
            .filter(|&(x, y)| image.pixel(x, y) == Some(WHITE))
            .collect()
    }

    #[test]
    fn text_lights_pixels_inside_its_box_only() {
        let mut image = Image::filled(60, 30, Rgba::opaque(0, 0, 0)).unwrap();
        image.text("50", (10, 5), FontSize::Small, Anchor::TopLeft, WHITE);
        let pixels = lit(&image);
        assert!(pixels.len() > 10, "{}", pixels.len());
        let w = FontSize::Small.width_of("50");
        assert_eq!(w, 10);
        for &(x, y) in &pixels {
            assert!(
                (10..10 + w).contains(&x) && (5..5 + 7).contains(&y),
                "{x}, {y}"
            );
        }
    }

    #[test]
    fn centred_text_is_centred_and_cut_at_the_edges() {
        let mut image = Image::filled(60, 30, Rgba::opaque(0, 0, 0)).unwrap();
        image.text("HUD", (30, 15), FontSize::Medium, Anchor::Center, WHITE);
        let pixels = lit(&image);
        let mean_x = pixels.iter().map(|p| p.0 as f32).sum::<f32>() / pixels.len() as f32;
        assert!((mean_x - 30.0).abs() < 3.0, "{mean_x}");
        // Half outside the image: drawn in part, nothing panics.
        image.text("edge", (-8, -4), FontSize::Huge, Anchor::TopLeft, WHITE);
        image.text("edge", (58, 28), FontSize::Huge, Anchor::TopLeft, WHITE);
        assert!(lit(&image).len() > pixels.len());
    }

    #[test]
    fn different_text_draws_different_pixels() {
        let draw = |s: &str| {
            let mut image = Image::filled(40, 12, Rgba::opaque(0, 0, 0)).unwrap();
            image.text(s, (0, 0), FontSize::Medium, Anchor::TopLeft, WHITE);
            lit(&image)
        };
        assert_ne!(draw("wave 1"), draw("wave 2"));
        assert_eq!(draw("wave 1"), draw("wave 1"));
    }
}
