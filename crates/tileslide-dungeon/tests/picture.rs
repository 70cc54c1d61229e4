//! The game's pictures show the map: rock grey, earth brown, dug squares floor, at the
//! size the CLI draws them.
#![allow(clippy::unwrap_used)]

use tileslide::{Cell, Vec2};
use tileslide_dungeon::Game;
use tileslide_render::{Canvas, RenderOptions, Style};

#[test]
fn rock_earth_and_dug_squares_have_their_colours() {
    let mut game = Game::new(1).unwrap();
    for _ in 0..900 {
        game.step().unwrap();
    }
    let options = RenderOptions::default()
        .with_pixels_per_cell(8.0)
        .with_style(tileslide_dungeon::style());
    let style = Style::default();
    // An animation's frame: over the first canvas, squares dug since painted as floor.
    let canvas = Canvas::new(game.initial_map(), &options).unwrap();
    let image = canvas.render(&game.picture(true));
    assert_eq!((image.width(), image.height()), (512, 512));
    let at = |cell: Cell| {
        let p = canvas
            .to_pixel(game.map().cell_rect(cell).min + Vec2::splat(0.5))
            .unwrap();
        image.pixel(p.x as u32, p.y as u32).unwrap()
    };
    // A corner of the map is rock.
    assert_eq!(at(Cell::new(1, 1)), style.solid_fill);
    // The bottom of the disc is earth nobody dug.
    let earth = at(Cell::new(32, 55));
    assert_ne!(earth, style.solid_fill);
    assert_ne!(earth, style.background);
    // Dug squares are floor (or a body, the treasure or a creature's way home drawn over
    // it), never rock or earth; at least half of them are bare floor.
    let dug = game.dug().to_vec();
    assert!(!dug.is_empty());
    let mut floor = 0;
    for &cell in &dug {
        let c = at(cell);
        assert!(c != style.solid_fill && c != earth, "{cell:?}: {c:?}");
        floor += usize::from(c == style.background);
    }
    assert!(floor * 2 >= dug.len(), "{floor} of {}", dug.len());
}
