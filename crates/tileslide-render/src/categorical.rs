//! A stable palette for telling things apart by number: bodies by id, objects by kind.

use crate::Rgba;

/// Ten colours that are easy to tell apart on the default style's light background and
/// from each other (after Okabe & Ito's colour-blind-safe set), each a colour of the GIF
/// palette's cube so animations show them exactly.
pub const CATEGORICAL: [Rgba; 10] = [
    Rgba::opaque(0, 102, 204),
    Rgba::opaque(255, 153, 0),
    Rgba::opaque(0, 153, 102),
    Rgba::opaque(204, 51, 153),
    Rgba::opaque(102, 204, 255),
    Rgba::opaque(204, 0, 0),
    Rgba::opaque(153, 102, 204),
    Rgba::opaque(204, 204, 0),
    Rgba::opaque(102, 51, 0),
    Rgba::opaque(102, 102, 102),
];

/// The colour of thing number `index` (a body's id, a kind's number): always the same
/// for the same number, [`CATEGORICAL`] in turn.
///
/// ```
/// use tileslide_render::{CATEGORICAL, categorical};
///
/// assert_eq!(categorical(0), CATEGORICAL[0]);
/// assert_ne!(categorical(0), categorical(1));
/// assert_eq!(categorical(12), categorical(2)); // after ten, the colours come round again
/// ```
#[must_use]
pub fn categorical(index: u64) -> Rgba {
    CATEGORICAL[(index % CATEGORICAL.len() as u64) as usize]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_colours_are_distinct_and_far_from_the_background() {
        let background = crate::Style::default().background;
        let far = |a: Rgba, b: Rgba| {
            let d = |x: u8, y: u8| i32::from(x.abs_diff(y));
            d(a.r, b.r) + d(a.g, b.g) + d(a.b, b.b)
        };
        for (i, &a) in CATEGORICAL.iter().enumerate() {
            assert!(far(a, background) > 150, "{a:?}");
            for &b in &CATEGORICAL[i + 1..] {
                assert!(far(a, b) > 90, "{a:?} {b:?}");
            }
            // On the cube: every channel a multiple of 51.
            assert!([a.r, a.g, a.b].iter().all(|c| c % 51 == 0), "{a:?}");
        }
    }
}
