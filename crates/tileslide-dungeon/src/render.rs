//! Pictures of the game for `tileslide-render`: bodies coloured by team, the treasure,
//! fireballs, creatures' paths home.

use tileslide::{Circle, Vec2};
use tileslide_render::{Picture, Rgba, Style};

use crate::components::{Body, CreatureBrain, FIREBALL_RADIUS, Fireball, Kind};
use crate::game::Game;

const OUTLINE: Rgba = Rgba::opaque(25, 25, 30);
const GOLD: Rgba = Rgba::opaque(240, 190, 20);

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
    /// dug since are painted in the background colour first.
    #[must_use]
    pub fn picture(&self, dug_over_initial: bool) -> Picture {
        let mut picture = Picture::new();
        if dug_over_initial {
            let floor = Style::default().background;
            for &cell in self.dug() {
                let centre = self.map().cell_rect(cell).min;
                // Four discs, one per quarter, cover the square with little spill.
                for (dx, dy) in [(0.25, 0.25), (0.75, 0.25), (0.25, 0.75), (0.75, 0.75)] {
                    picture.body_with_color(Circle::new(centre + Vec2::new(dx, dy), 0.36), floor);
                }
            }
        }
        // The edge of the diggable earth: rock lies outside it.
        let centre = Vec2::splat(crate::layout::SIZE as f32 / 2.0);
        let edge: Vec<Vec2> = (0..=96)
            .map(|k| {
                centre
                    + Vec2::from_angle(k as f32 * std::f32::consts::TAU / 96.0)
                        * crate::layout::EARTH_RADIUS
            })
            .collect();
        picture.polyline(&edge);
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
