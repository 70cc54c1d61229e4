//! Drawing a game: the platform, coins, enemies with their volumes, the player, its trail,
//! the goal and the last step's hits, over the map drawn by `tileslide-render`.

use tileslide::{Aabb, Circle, Vec2, VolumeShape};
use tileslide_render::{Panel, Picture, Rgba, Style, Swatch, VolumeKind};

use crate::game::Game;
use crate::hits::{self, Boxed};

/// Coins are gold.
pub const COIN_COLOR: Rgba = Rgba::opaque(240, 190, 20);
/// The player is green; blinking pale while it cannot be hit.
pub const PLAYER_COLOR: Rgba = Rgba::opaque(39, 174, 96);
const PLAYER_BLINK: Rgba = Rgba::new(39, 174, 96, 90);
/// Enemies are purple, inside their attack box.
pub const ENEMY_COLOR: Rgba = Rgba::opaque(102, 51, 153);

impl Game {
    /// Adds this moment of the game to `picture` (cleared first).
    pub fn draw(&self, picture: &mut Picture) {
        picture.clear();
        let s = self.level.scale;
        let up = self.level.up;
        picture.temporaries(&self.level.map);
        picture.polyline(self.trail());
        self.draw_goal(picture);
        for c in self.coins.iter().filter(|c| !c.taken) {
            picture.body_with_color(hits::coin_circle(c.center, s), COIN_COLOR);
        }
        for e in self.enemies.iter().filter(|e| e.alive) {
            let b = Boxed {
                center: e.body.position,
                half: e.half(),
                motion: Vec2::ZERO,
            };
            picture.volume(rect_shape(b.center, b.half), VolumeKind::Attack);
            if let Some(top) = b.world_strip(up, true, s) {
                picture.volume(top, VolumeKind::Vulnerability);
            }
            picture.body_with_color(
                Circle::new(b.center, b.half.min_element() * 0.8),
                ENEMY_COLOR,
            );
        }
        let p = &self.player;
        let color = if p.invulnerable > 0 && (p.invulnerable / 6).is_multiple_of(2) {
            PLAYER_BLINK
        } else {
            PLAYER_COLOR
        };
        picture.volume(
            rect_shape(p.body.position, p.half()),
            VolumeKind::Vulnerability,
        );
        picture.body_with_color(Circle::new(p.body.position, p.half().x), color);
        for e in self.events().iter().filter(|e| e.accepted) {
            picture.hit_event(self.hit_world(), e);
        }
    }

    /// A flag on a pole at the goal's bottom middle.
    fn draw_goal(&self, picture: &mut Picture) {
        let s = self.level.scale;
        let up = self.level.up;
        let g = self.level.goal;
        let middle = 0.5 * (g.min.x + g.max.x);
        // The goal's bottom: its lower side along up.
        let bottom_y = if up.y < 0.0 { g.max.y } else { g.min.y };
        let foot = Vec2::new(middle, bottom_y);
        let top = foot + up * 0.9 * s;
        let tip = top - up * 0.2 * s + Vec2::X * 0.5 * s;
        let low = top - up * 0.4 * s;
        picture.polyline(&[foot, top, tip, low]);
    }
}

/// The legend of the platformer's pictures drawn in `style`: what each colour is.
#[must_use]
pub fn legend(style: &Style) -> Panel {
    let mut panel = Panel::new(Rgba::opaque(51, 51, 51), Rgba::opaque(255, 255, 255));
    panel
        .key(Swatch::Disc(PLAYER_COLOR), "player")
        .key(Swatch::Disc(ENEMY_COLOR), "enemy")
        .key(Swatch::Square(style.attack), "hurts")
        .key(Swatch::Square(style.vulnerability), "stomp here")
        .key(Swatch::Disc(COIN_COLOR), "coin")
        .key(Swatch::Square(style.one_way), "one-way platform")
        .key(Swatch::Square(style.temporary), "moving platform")
        .key(Swatch::Square(style.path), "trail, goal");
    panel
}

fn rect_shape(center: Vec2, half: Vec2) -> VolumeShape {
    VolumeShape::Rect(Aabb::from_center(center, half))
}
