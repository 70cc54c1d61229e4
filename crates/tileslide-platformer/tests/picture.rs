//! The platformer's pictures: the player and each enemy drawn in their own colours where
//! they stand (not all one green), and the legend names them.
#![allow(clippy::unwrap_used)]

use tileslide_platformer::{ENEMY_COLOR, Game, Level, PLAYER_COLOR, legend};
use tileslide_render::{Canvas, Image, Picture, RenderOptions, Rgba};

fn count(image: &Image, color: Rgba) -> usize {
    (0..image.height())
        .flat_map(|y| (0..image.width()).map(move |x| (x, y)))
        .filter(|&(x, y)| image.pixel(x, y) == Some(color))
        .count()
}

#[test]
fn the_player_and_the_enemies_have_their_own_colours_where_they_stand() {
    let mut game = Game::new(Level::bundled().unwrap()).unwrap();
    for _ in 0..30 {
        game.step().unwrap();
    }
    let options = RenderOptions::default();
    let canvas = Canvas::new(&game.level.map, &options).unwrap();
    let mut picture = Picture::new();
    game.draw(&mut picture);
    let image = canvas.render(&picture);
    let at = |p: tileslide::Vec2| {
        let q = canvas.to_pixel(p).unwrap();
        image.pixel(q.x as u32, q.y as u32).unwrap()
    };
    assert_eq!(at(game.player.body.position), PLAYER_COLOR);
    let alive: Vec<_> = game.enemies.iter().filter(|e| e.alive).collect();
    assert!(alive.len() >= 2);
    for e in alive {
        assert_eq!(at(e.body.position), ENEMY_COLOR, "{:?}", e.body.position);
    }
    assert_ne!(PLAYER_COLOR, ENEMY_COLOR);

    // The legend shows both colours beside text.
    let mut strip = Image::filled(1024, 24, Rgba::opaque(0, 0, 0)).unwrap();
    legend(&options.style).draw_across(&mut strip, (0, 0), (1024, 24));
    assert!(count(&strip, PLAYER_COLOR) > 30 && count(&strip, ENEMY_COLOR) > 30);
    assert!(count(&strip, Rgba::opaque(255, 255, 255)) > 200);
}
