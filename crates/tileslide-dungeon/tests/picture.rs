//! The game's pictures through the public API: a frame of `Screen` is `WIDTH × HEIGHT`,
//! and over a canvas of the map in the game's style rock, earth and dug squares differ.
#![allow(clippy::unwrap_used)]

use tileslide::{Cell, Vec2};
use tileslide_dungeon::{Game, HEIGHT, Screen, WIDTH};
use tileslide_render::{Canvas, RenderOptions};

#[test]
fn rock_earth_and_dug_squares_have_their_colours() {
    let mut game = Game::new(1).unwrap();
    for _ in 0..900 {
        game.step().unwrap();
    }
    let style = tileslide_dungeon::style();
    let options = RenderOptions::default()
        .with_pixels_per_cell(8.0)
        .with_style(style);
    let canvas = Canvas::new(game.map(), &options).unwrap();
    let image = canvas.render(&game.picture());
    let at = |cell: Cell| {
        let p = canvas
            .to_pixel(game.map().cell_rect(cell).min + Vec2::splat(0.5))
            .unwrap();
        image.pixel(p.x as u32, p.y as u32).unwrap()
    };
    // The bottom of the disc is earth nobody dug: the canvas's solid fill.
    assert_eq!(at(Cell::new(32, 55)), style.solid_fill);
    // A corner of the map is rock, drawn over it in another colour.
    let rock = at(Cell::new(1, 1));
    assert_ne!(rock, style.solid_fill);
    // Dug squares are open: never rock or earth.
    for &cell in game.dug() {
        let c = at(cell);
        assert!(c != rock && c != style.solid_fill, "{cell:?}: {c:?}");
    }
    let frame = Screen::new().frame(&game, false).unwrap();
    assert_eq!((frame.width(), frame.height()), (WIDTH, HEIGHT));
}
