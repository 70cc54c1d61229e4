//! What a frame promises a person looking at it: fighters in their colours where they
//! stand, with health bars; unexplored squares yellow; dig costs on diggable squares; every
//! open square in view; the HUD and the legend as text; the end state with its banner.
#![allow(clippy::unwrap_used)]

use tileslide::{Cell, Vec2};
use tileslide_render::{Image, Rgba};

use super::*;
use crate::components::{Body, Health, Kind};
use crate::render::{HEALTH, HERO, IMP, SKELETON, UNEXPLORED};

/// The game after `steps` steps.
fn game_at(steps: u64) -> Game {
    let mut game = Game::new(1).unwrap();
    while game.summary().steps < steps {
        game.step().unwrap();
    }
    game
}

/// Fighters of `kind`: where they stand and their hit points.
fn fighters(game: &Game, kind: Kind) -> Vec<(Vec2, Health)> {
    game.world()
        .query::<(&Body, &Kind, &Health)>()
        .iter()
        .filter(|(_, k, _)| **k == kind)
        .map(|(b, _, h)| (game.bodies().get(b.0).unwrap().position(), *h))
        .collect()
}

fn pixel_at(image: &Image, screen: &Screen, p: Vec2) -> Rgba {
    let q = screen.to_pixel(p).unwrap();
    image.pixel(q.x as u32, q.y as u32).unwrap()
}

/// Pixels of `color` in the box `x × y`.
fn count(image: &Image, color: Rgba, x: std::ops::Range<u32>, y: std::ops::Range<u32>) -> usize {
    y.flat_map(|y| x.clone().map(move |x| (x, y)))
        .filter(|&(x, y)| image.pixel(x, y) == Some(color))
        .count()
}

/// Open squares with no fighter or treasure near their middle.
fn bare_open_squares(game: &Game) -> Vec<Cell> {
    let map = game.map();
    let near_something = |p: Vec2| {
        p.distance(game.level().treasure) < 1.5
            || game
                .bodies()
                .iter()
                .any(|(_, b)| b.position().distance(p) < 1.5)
    };
    (0..map.height())
        .flat_map(|row| (0..map.width()).map(move |col| Cell::new(col, row)))
        .filter(|&c| map.tile(c).is_none() && !near_something(crate::explore::centre_of(map, c)))
        .collect()
}

#[test]
fn fighters_are_drawn_in_their_colours_where_they_stand_with_health_bars() {
    // 20 s: the first party is in, the lair's skeletons are summoned. 50 s: imps too.
    for steps in [600, 1500] {
        let game = game_at(steps);
        let mut screen = Screen::new();
        let image = screen.frame(&game, false).unwrap();
        let mut seen = 0;
        for (kind, colour) in [
            (Kind::Hero, HERO),
            (Kind::Imp, IMP),
            (Kind::Skeleton, SKELETON),
        ] {
            for (at, health) in fighters(&game, kind) {
                // Another fighter may stand over this one's middle: look for the colour
                // anywhere inside a third of its radius.
                let q = screen.to_pixel(at).unwrap();
                let r = (kind.radius() * screen_scale(&screen) / 3.0) as u32;
                let (x, y) = (q.x as u32, q.y as u32);
                let here = count(&image, colour, x - r..x + r + 1, y - r..y + r + 1);
                assert!(
                    here > 0,
                    "{kind:?} at {at} (steps {steps}): no {colour:?} pixel"
                );
                // The health bar above it: green in proportion to what is left.
                let top = screen
                    .to_pixel(at - Vec2::new(0.0, kind.radius() + 0.16))
                    .unwrap();
                let bar = count(
                    &image,
                    HEALTH,
                    x - 8..x + 9,
                    top.y as u32 - 2..top.y as u32 + 3,
                );
                assert_eq!(bar > 0, health.hp > 0, "{kind:?} at {at}: {health:?}");
                seen += 1;
            }
        }
        assert!(seen >= 4, "{seen} fighters at step {steps}");
        assert!(!fighters(&game, Kind::Hero).is_empty() || steps > 600);
    }
}

/// Pixels per cell of the screen's last frame.
fn screen_scale(screen: &Screen) -> f32 {
    let a = screen.to_pixel(Vec2::ZERO).unwrap();
    let b = screen.to_pixel(Vec2::X).unwrap();
    b.x - a.x
}

#[test]
fn unexplored_squares_are_yellow_and_explored_ones_are_not() {
    // Before the first party (12 s) no hero has seen anything.
    let game = game_at(300);
    let mut screen = Screen::new();
    let image = screen.frame(&game, false).unwrap();
    let squares = bare_open_squares(&game);
    assert!(squares.len() > 30);
    for &cell in &squares {
        let c = pixel_at(&image, &screen, crate::explore::centre_of(game.map(), cell));
        assert_eq!(c, UNEXPLORED, "{cell:?}");
    }
    // A minute in, the heroes have seen most of the dungeon: those squares are rooms.
    let game = game_at(1800);
    let image = screen.frame(&game, false).unwrap();
    let (mut yellow, mut room) = (0, 0);
    for cell in bare_open_squares(&game) {
        let c = pixel_at(&image, &screen, crate::explore::centre_of(game.map(), cell));
        let seen = game.level().explored.is_seen(cell);
        assert_eq!(c == UNEXPLORED, !seen, "{cell:?}: {c:?}");
        yellow += usize::from(!seen);
        room += usize::from(seen);
    }
    assert!(room > yellow, "{room} seen, {yellow} not");
}

#[test]
fn every_open_square_is_in_view_and_dig_costs_mark_the_diggable_ones() {
    let mut game = Game::new(1).unwrap();
    let mut screen = Screen::new();
    let mut previous: Option<tileslide::Aabb> = None;
    for until in [0, 300, 900, 1500] {
        while game.summary().steps < until {
            game.step().unwrap();
        }
        let image = screen.frame(&game, false).unwrap();
        let window = screen.window().unwrap();
        // The window never shrinks (no swaying back and forth).
        if let Some(p) = previous {
            assert!(window.contains(&p), "{p:?} then {window:?}");
        }
        previous = Some(window);
        let map = game.map();
        let (mut marked, mut checked) = (0, 0);
        for row in 0..map.height() {
            for col in 0..map.width() {
                let cell = Cell::new(col, row);
                let r = map.cell_rect(cell);
                let (a, b) = (
                    screen.to_pixel(r.min).unwrap(),
                    screen.to_pixel(r.max).unwrap(),
                );
                let in_view = a.x >= 0.0
                    && a.y >= 0.0
                    && b.x <= VIEWPORT_WIDTH as f32
                    && b.y <= HEIGHT as f32;
                if map.tile(cell).is_none() {
                    assert!(
                        in_view,
                        "step {until}: open {cell:?} out of view ({a}, {b})"
                    );
                    continue;
                }
                if !in_view {
                    continue;
                }
                let (x, y) = (a.x as u32 + 1..b.x as u32, a.y as u32 + 1..b.y as u32);
                let ink = count(&image, COST_INK, x, y);
                let diggable = game.is_diggable(cell);
                assert_eq!(ink > 0, diggable, "step {until}: {cell:?}");
                marked += usize::from(diggable);
                checked += 1;
            }
        }
        assert!(marked > 20 && checked > marked, "{marked} of {checked}");
    }
}

#[test]
fn the_panel_holds_the_hud_and_the_legend_as_text() {
    let game = game_at(450);
    let mut screen = Screen::new();
    let image = screen.frame(&game, false).unwrap();
    let panel = VIEWPORT_WIDTH..WIDTH;
    // The HUD's lines (the top third) and the legend's labels are text.
    assert!(count(&image, INK, panel.clone(), 0..HEIGHT / 3) > 500);
    assert!(count(&image, INK, panel.clone(), HEIGHT / 3..HEIGHT) > 300);
    // The legend's swatches show the game's colours.
    for colour in [HERO, IMP, SKELETON, UNEXPLORED, crate::render::ROCK] {
        assert!(
            count(&image, colour, panel.clone(), 0..HEIGHT) > 20,
            "{colour:?}"
        );
    }
    // The HUD changes with the game: another moment draws other text.
    let later = screen.frame(&game_at(480), false).unwrap();
    let differ = (0..HEIGHT / 3)
        .flat_map(|y| panel.clone().map(move |x| (x, y)))
        .filter(|&(x, y)| image.pixel(x, y) != later.pixel(x, y))
        .count();
    assert!(differ > 10, "{differ}");
}

#[test]
fn the_last_frame_shows_the_dungeon_filling_the_view_and_how_the_game_ended() {
    let game = game_at(1200);
    let mut screen = Screen::new();
    let plain = screen.frame(&game, false).unwrap();
    let last = screen.frame(&game, true).unwrap();
    // The banner is text over the top of the map, only on the last frame.
    let banner = 0..80;
    assert_eq!(count(&plain, INK, 0..VIEWPORT_WIDTH, banner.clone()), 0);
    assert!(count(&last, INK, 0..VIEWPORT_WIDTH, banner) > 300);
    // The dungeon is not a speck: the open squares span most of the view both ways.
    let map = game.map();
    let (mut lo, mut hi) = (Vec2::splat(f32::MAX), Vec2::splat(f32::MIN));
    for row in 0..map.height() {
        for col in 0..map.width() {
            let cell = Cell::new(col, row);
            if map.tile(cell).is_none() {
                let r = map.cell_rect(cell);
                lo = lo.min(screen.to_pixel(r.min).unwrap());
                hi = hi.max(screen.to_pixel(r.max).unwrap());
            }
        }
    }
    let span = (hi - lo) / Vec2::new(VIEWPORT_WIDTH as f32, HEIGHT as f32);
    assert!(span.x > 0.6 && span.y > 0.8, "{span}");
}
