//! Pictures of the game for `tileslide-render`: bodies coloured by team, the treasure,
//! fireballs, creatures' paths home.

use tileslide::{Cell, Circle, Vec2};
use tileslide_render::{Picture, Rgba, Style};

use crate::components::{Body, CreatureBrain, FIREBALL_RADIUS, Fireball, Kind};
use crate::game::Game;

const OUTLINE: Rgba = Rgba::opaque(25, 25, 30);
const GOLD: Rgba = Rgba::opaque(240, 190, 20);
/// Diggable earth, where the canvas draws every solid grey: a colour of the GIF palette's
/// cube, so animations show it exactly.
const EARTH: Rgba = Rgba::opaque(153, 102, 51);

/// The style to draw game pictures with: bodies draw their own outlines (so that dug
/// squares can be painted over an older canvas without rings).
#[must_use]
pub fn style() -> Style {
    Style {
        body_outline: Rgba::new(0, 0, 0, 0),
        ..Style::default()
    }
}

fn colour(kind: Kind) -> Rgba {
    match kind {
        Kind::Hero => Rgba::opaque(40, 110, 230),
        Kind::Skeleton => Rgba::opaque(235, 235, 225),
        Kind::Imp => Rgba::opaque(200, 40, 40),
    }
}

impl Game {
    /// The current state over a canvas of [`Game::map`]; with `dug_over_initial`, for a
    /// canvas of [`Game::initial_map`] instead (an animation keeps one canvas), squares
    /// dug since are painted as floor and the walls around them redrawn from the map as
    /// it is now. Earth still standing is drawn brown over the canvas's grey, so rock and
    /// earth look different.
    #[must_use]
    pub fn picture(&self, dug_over_initial: bool) -> Picture {
        let mut picture = Picture::new();
        let map = self.map();
        let ground = &self.level().ground;
        // Row by row, runs of earth still standing in one box each, and with
        // `dug_over_initial` runs of floor too.
        let background = Style::default().background;
        for row in 0..map.height() {
            let mut col = 0;
            while col < map.width() {
                let kind = |c: u32| {
                    let cell = Cell::new(c, row);
                    match map.tile(cell) {
                        Some(_) if !ground.is_rock(cell) => Some(EARTH),
                        None if dug_over_initial => Some(background),
                        _ => None,
                    }
                };
                let start = col;
                let here = kind(col);
                while col < map.width() && kind(col) == here {
                    col += 1;
                }
                if let Some(color) = here {
                    let (a, b) = (
                        map.cell_rect(Cell::new(start, row)),
                        map.cell_rect(Cell::new(col - 1, row)),
                    );
                    picture.area(a.union(&b), color);
                }
            }
        }
        // The fills cover half the width of the canvas's wall lines, and walls changed
        // with each dig: draw every wall of the map as it is now over them.
        let cells =
            (0..map.height()).flat_map(|row| (0..map.width()).map(move |col| Cell::new(col, row)));
        picture.cell_walls(map, cells);
        let treasure = self.summary().treasure_left;
        for k in 0..treasure {
            let at = self.level().treasure
                + Vec2::new(k as f32 * 0.3 - (treasure as f32 - 1.0) * 0.15, 0.0);
            disc(&mut picture, at, 0.22, GOLD);
        }
        for (body, kind, brain) in self
            .world()
            .query::<(&Body, &Kind, Option<&CreatureBrain>)>()
            .iter()
        {
            let Ok(b) = self.bodies().get(body.0) else {
                continue;
            };
            if let Some((path, _)) = brain.and_then(|b| b.way_home.as_ref()) {
                picture.path(path);
            }
            disc(&mut picture, b.position(), kind.radius(), colour(*kind));
        }
        for handle in self.carriers() {
            if let Ok(b) = self.bodies().get(handle) {
                disc(&mut picture, b.position(), 0.12, GOLD);
            }
        }
        for ball in self.world().query::<&Fireball>().iter() {
            disc(
                &mut picture,
                ball.position,
                FIREBALL_RADIUS,
                Rgba::opaque(255, 120, 0),
            );
        }
        picture
    }
}

/// A disc with a dark rim.
fn disc(picture: &mut Picture, at: Vec2, radius: f32, fill: Rgba) {
    picture.body_with_color(Circle::new(at, radius), OUTLINE);
    picture.body_with_color(Circle::new(at, radius * 0.75), fill);
}
