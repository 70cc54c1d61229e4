//! Pictures of the game for `tileslide-render`, in the Dungeon Builder write-up's look:
//! heroes cyan, imps pink, skeletons blue, fireballs red, squares the heroes have not
//! explored yellow, the treasure gold, undiggable rock dark brown, rooms light brown, and
//! health bars over every fighter. [`Screen`](crate::Screen) frames it and adds the
//! legend, the HUD and the dig costs.

use tileslide::{Aabb, Cell, Circle, TileMap, Vec2};
use tileslide_render::{Picture, Rgba, Style};

use crate::components::{Body, CreatureBrain, FIREBALL_RADIUS, Fireball, Health, Kind};
use crate::game::Game;

// Every colour is one of the GIF palette's cube (steps of 51), so animations show them
// exactly.
/// Heroes.
pub const HERO: Rgba = Rgba::opaque(0, 204, 255);
/// Imps.
pub const IMP: Rgba = Rgba::opaque(255, 102, 204);
/// Skeletons.
pub const SKELETON: Rgba = Rgba::opaque(51, 102, 255);
/// Fireballs.
pub const FIREBALL: Rgba = Rgba::opaque(255, 0, 0);
/// The treasure, on its pile or carried.
pub const GOLD: Rgba = Rgba::opaque(255, 204, 0);
/// Open squares no hero has seen yet.
pub const UNEXPLORED: Rgba = Rgba::opaque(255, 255, 102);
/// Open squares (rooms and corridors) the heroes have seen.
pub const ROOM: Rgba = Rgba::opaque(204, 153, 102);
/// Earth the keeper can dig.
pub const EARTH: Rgba = Rgba::opaque(153, 102, 51);
/// Rock nobody can dig.
pub const ROCK: Rgba = Rgba::opaque(102, 51, 0);
/// Walls (the map's active segments).
pub const WALL: Rgba = Rgba::opaque(51, 0, 0);
/// The full part of a health bar.
pub const HEALTH: Rgba = Rgba::opaque(0, 204, 0);
/// The lost part of a health bar.
pub const HEALTH_LOST: Rgba = Rgba::opaque(153, 0, 0);
/// Outlines of fighters, the treasure and fireballs.
const OUTLINE: Rgba = Rgba::opaque(0, 0, 0);
/// Creatures' paths home.
const PATH: Rgba = Rgba::new(255, 255, 255, 150);

/// How far in from its cell's sides an unexplored square's yellow is painted (cells), so
/// the walls beside it keep their whole width.
const YELLOW_INSET: f32 = 0.08;

/// The style to draw game pictures with: the canvas's empty space is a room's floor, its
/// solid material earth, its walls dark; no normal ticks.
#[must_use]
pub fn style() -> Style {
    Style {
        background: ROOM,
        solid_fill: EARTH,
        solid: WALL,
        normal: Rgba::new(0, 0, 0, 0),
        body_outline: OUTLINE,
        path: PATH,
        ..Style::default()
    }
}

/// A fighter's colour.
#[must_use]
pub fn colour(kind: Kind) -> Rgba {
    match kind {
        Kind::Hero => HERO,
        Kind::Skeleton => SKELETON,
        Kind::Imp => IMP,
    }
}

impl Game {
    /// The current state, to draw over a canvas of [`Game::map`] drawn in [`style`]
    /// (earth is the canvas's solid fill, rooms its background): rock, unexplored
    /// squares, the treasure, creatures' paths home, fighters with their health bars,
    /// carried treasure and fireballs.
    #[must_use]
    pub fn picture(&self) -> Picture {
        let mut picture = Picture::new();
        self.draw_ground(&mut picture);
        let treasure = self.summary().treasure_left;
        for k in 0..treasure {
            // A small pile: two rows of coins.
            let (col, row) = ((k % 3) as f32, (k / 3) as f32);
            let at = self.level().treasure + Vec2::new((col - 1.0) * 0.32, (row - 0.5) * 0.3);
            picture.body_with_color(Circle::new(at, 0.17), GOLD);
        }
        let mut fighters: Vec<_> = self
            .world()
            .query::<(&Body, &Kind, &Health, Option<&CreatureBrain>)>()
            .iter()
            .filter_map(|(body, kind, health, brain)| {
                let at = self.bodies().get(body.0).ok()?.position();
                let home = brain
                    .and_then(|b| b.way_home.as_ref())
                    .map(|(p, _)| p.clone());
                Some((at, *kind, *health, home))
            })
            .collect();
        // Drawn in a fixed order, whatever order the ECS keeps.
        fighters.sort_by(|a, b| a.0.y.total_cmp(&b.0.y).then(a.0.x.total_cmp(&b.0.x)));
        for (_, _, _, home) in &fighters {
            if let Some(path) = home {
                picture.path(path);
            }
        }
        for &(at, kind, _, _) in &fighters {
            picture.body_with_color(Circle::new(at, kind.radius()), colour(kind));
        }
        for handle in self.carriers() {
            if let Ok(b) = self.bodies().get(handle) {
                picture.body_with_color(Circle::new(b.position(), 0.13), GOLD);
            }
        }
        for &(at, kind, health, _) in &fighters {
            health_bar(&mut picture, at, kind.radius(), health);
        }
        for ball in self.world().query::<&Fireball>().iter() {
            // A fading tail a step long behind it, then the ball, drawn larger than its
            // hit circle so that it shows.
            let tail = ball.position - ball.velocity * crate::DT * 1.5;
            picture.body_with_color(Circle::new(tail, FIREBALL_RADIUS), FIREBALL.with_alpha(110));
            picture.body_with_color(Circle::new(ball.position, FIREBALL_RADIUS * 1.5), FIREBALL);
        }
        picture
    }

    /// Rock over the canvas's earth (with the walls it covered drawn again), and the
    /// open squares no hero has seen in yellow.
    fn draw_ground(&self, picture: &mut Picture) {
        let map = self.map();
        let level = self.level();
        let ground = &level.ground;
        // Beyond the map is rock too (a window wider than the map shows it).
        if map.width() > 0 && map.height() > 0 {
            let inside = map
                .cell_rect(Cell::new(0, 0))
                .union(&map.cell_rect(Cell::new(map.width() - 1, map.height() - 1)));
            let far = inside.expand(inside.size().max_element());
            let (lo, hi) = (inside.min, inside.max);
            for (a, b) in [
                (far.min, Vec2::new(far.max.x, lo.y)),
                (Vec2::new(far.min.x, hi.y), far.max),
                (Vec2::new(far.min.x, lo.y), Vec2::new(lo.x, hi.y)),
                (Vec2::new(hi.x, lo.y), Vec2::new(far.max.x, hi.y)),
            ] {
                picture.area(Aabb::from_corners(a, b), ROCK);
            }
        }
        let mut walls = Vec::new();
        for row in 0..map.height() {
            let mut col = 0;
            while col < map.width() {
                let start = col;
                while col < map.width() && ground.is_rock(Cell::new(col, row)) {
                    if map.tile(Cell::new(col, row)).is_some()
                        && borders_open(map, Cell::new(col, row))
                    {
                        walls.push(Cell::new(col, row));
                    }
                    col += 1;
                }
                if col > start {
                    let a = map.cell_rect(Cell::new(start, row));
                    let b = map.cell_rect(Cell::new(col - 1, row));
                    picture.area(a.union(&b), ROCK);
                } else {
                    col += 1;
                }
            }
        }
        picture.cell_walls(map, walls);
        for row in 0..map.height() {
            for col in 0..map.width() {
                let cell = Cell::new(col, row);
                if map.tile(cell).is_none() && !level.explored.is_seen(cell) {
                    let r = map.cell_rect(cell);
                    let inset = map.cell_size() * YELLOW_INSET;
                    picture.area(Aabb::from_corners(r.min + inset, r.max - inset), UNEXPLORED);
                }
            }
        }
    }
}

/// A health bar above a fighter at `at` of `radius` (y down: above is −y).
fn health_bar(picture: &mut Picture, at: Vec2, radius: f32, health: Health) {
    let width = 0.8_f32;
    let height = 0.12_f32;
    let fraction = if health.max > 0 {
        (health.hp as f32 / health.max as f32).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let left = at.x - width / 2.0;
    let top = at.y - radius - 0.1 - height;
    let bar = |w: f32| Aabb::from_corners(Vec2::new(left, top), Vec2::new(left + w, top + height));
    picture.area(bar(width), HEALTH_LOST);
    if fraction > 0.0 {
        picture.area(bar(width * fraction), HEALTH);
    }
}

/// Whether one of `cell`'s four neighbours is an open square of `map`.
fn borders_open(map: &TileMap, cell: Cell) -> bool {
    [(-1i64, 0i64), (1, 0), (0, -1), (0, 1)]
        .into_iter()
        .any(|(dc, dr)| {
            let col = u32::try_from(i64::from(cell.col) + dc).ok();
            let row = u32::try_from(i64::from(cell.row) + dr).ok();
            match (col, row) {
                (Some(c), Some(r)) if c < map.width() && r < map.height() => {
                    map.tile(Cell::new(c, r)).is_none()
                }
                _ => false,
            }
        })
}
