//! The game as a person sees it: the dug dungeon framed by a camera that follows it as it
//! grows, the dig cost on every square the keeper could dig, and a panel with the HUD
//! (time, wave, gold, who is alive, the treasure) and the legend.

use tileslide::{Aabb, Cell, MapRevision, Vec2};
use tileslide_render::{
    Anchor, Camera, Canvas, FontSize, Framing, Image, Panel, RenderError, RenderOptions, Rgba,
    Swatch,
};

use crate::components::Kind;
use crate::game::Game;
use crate::render::{
    self, EARTH, FIREBALL, GOLD, HEALTH, HEALTH_LOST, HERO, IMP, ROCK, ROOM, SKELETON, UNEXPLORED,
};
use crate::step::STEPS_PER_SECOND;

/// Width of the map's part of a frame, in pixels.
pub const VIEWPORT_WIDTH: u32 = 480;
/// Height of a frame, in pixels.
pub const HEIGHT: u32 = 720;
/// Width of the panel right of the map, in pixels.
pub const PANEL_WIDTH: u32 = 200;
/// Width of a frame, in pixels.
pub const WIDTH: u32 = VIEWPORT_WIDTH + PANEL_WIDTH;
/// Cells of earth kept in view around the open squares.
const MARGIN: f32 = 2.0;
/// Dig costs are marked only when a cell is at least this many pixels wide.
const COST_MIN_PIXELS: f32 = 12.0;

const PANEL: Rgba = Rgba::opaque(51, 51, 51);
const INK: Rgba = Rgba::opaque(255, 255, 255);
/// The dig cost's colour on earth.
pub const COST_INK: Rgba = Rgba::opaque(255, 204, 153);

/// Draws frames of a game, [`WIDTH`] × [`HEIGHT`] pixels: the map on the left, framed by a
/// [`Camera`] around the open squares (plus two cells), the panel on the right. The
/// canvas is drawn again only when the map or the window changed.
///
/// ```
/// use tileslide_dungeon::{Game, Screen};
///
/// let mut game = Game::new(1)?;
/// let mut screen = Screen::new();
/// for _ in 0..30 {
///     game.step()?;
/// }
/// let frame = screen.frame(&game, false)?;
/// assert_eq!((frame.width(), frame.height()), (680, 720));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub struct Screen {
    camera: Camera,
    options: RenderOptions,
    /// The canvas of the last frame, with the window and map revision it was drawn for.
    canvas: Option<(Aabb, MapRevision, Canvas)>,
    panel: Panel,
}

impl Default for Screen {
    fn default() -> Self {
        Self::new()
    }
}

impl Screen {
    /// A screen whose camera has seen nothing yet.
    #[must_use]
    pub fn new() -> Self {
        Self {
            camera: Camera::new(VIEWPORT_WIDTH as f32 / HEIGHT as f32, MARGIN),
            options: RenderOptions::default().with_style(render::style()),
            canvas: None,
            panel: Panel::new(PANEL, INK),
        }
    }

    /// The frame of `game` now; with `ending`, a banner over the map says how the game
    /// ended (for the last frame).
    ///
    /// # Errors
    /// A render error (a bug: the sizes are fixed and the window finite).
    pub fn frame(&mut self, game: &Game, ending: bool) -> Result<Image, RenderError> {
        let window = self.camera.follow(open_area(game));
        let revision = game.map().revision();
        let canvas = match &mut self.canvas {
            Some((w, r, canvas)) if *w == window && *r == revision => canvas,
            slot => {
                let framing = Framing {
                    window,
                    image: (WIDTH, HEIGHT),
                    viewport: (VIEWPORT_WIDTH, HEIGHT),
                };
                let canvas = Canvas::framed(game.map(), &self.options, &framing)?;
                &mut slot.insert((window, revision, canvas)).2
            }
        };
        let mut image = canvas.render(&game.picture());
        mark_dig_costs(&mut image, canvas, game, window);
        self.hud(game);
        self.panel.draw(
            &mut image,
            (VIEWPORT_WIDTH as i32, 0),
            (PANEL_WIDTH, HEIGHT),
        );
        if ending {
            banner(&mut image, game);
        }
        Ok(image)
    }

    /// The window the last frame showed (world coordinates), if a frame was drawn.
    #[must_use]
    pub fn window(&self) -> Option<Aabb> {
        self.canvas.as_ref().map(|(w, _, _)| *w)
    }

    /// Where world point `p` was in the last frame, in pixels, if a frame was drawn.
    #[must_use]
    pub fn to_pixel(&self, p: Vec2) -> Option<Vec2> {
        self.canvas.as_ref().and_then(|(_, _, c)| c.to_pixel(p))
    }

    /// The panel's rows for `game` now: the HUD, then the legend.
    fn hud(&mut self, game: &Game) {
        let s = game.summary();
        let step = s.steps;
        let clock = |steps: u64| {
            let seconds = steps / u64::from(STEPS_PER_SECOND);
            format!("{}:{:02}", seconds / 60, seconds % 60)
        };
        let (mut heroes, mut creatures) = (0, 0);
        for kind in game.world().query::<&Kind>().iter() {
            if *kind == Kind::Hero {
                heroes += 1;
            } else {
                creatures += 1;
            }
        }
        let next = crate::arrivals::steps_to_next_wave(step);
        let cost = game.dig_cost();
        let panel = &mut self.panel;
        panel.clear();
        panel
            .heading("Dungeon Builder")
            .line(format!("time      {}", clock(step)))
            .line(format!("wave      {}  (next {})", s.waves, clock(next)))
            .line(format!("gold      {}", game.gold()))
            .line(format!("heroes    {heroes} in the dungeon"))
            .line(format!(
                "          {} killed, {} out",
                s.heroes_lost, s.heroes_escaped
            ))
            .line(format!("creatures {creatures} alive"))
            .line(format!("          {} killed", s.creatures_lost))
            .line(format!("treasure  {} left", s.treasure_left))
            .line(format!("          {} stolen", s.treasure_stolen))
            .line(format!("dug       {} squares", s.squares_dug))
            .gap()
            .heading("Legend")
            .key(Swatch::Disc(HERO), "hero")
            .key(Swatch::Disc(IMP), "imp (shoots)")
            .key(Swatch::Disc(SKELETON), "skeleton")
            .key(Swatch::Dot(FIREBALL), "fireball")
            .key(Swatch::Disc(GOLD), "treasure")
            .key(
                Swatch::Bar {
                    fill: HEALTH,
                    empty: HEALTH_LOST,
                    fraction: 0.6,
                },
                "health",
            )
            .key(Swatch::Square(UNEXPLORED), "not yet explored")
            .key(Swatch::Square(ROOM), "explored room")
            .key(
                Swatch::Marked {
                    fill: EARTH,
                    text: cost.to_string(),
                    ink: COST_INK,
                },
                format!("earth: dig for {cost} gold"),
            )
            .key(Swatch::Square(ROCK), "rock: no digging");
    }
}

/// The open squares' bounding box: the dug dungeon (with the rooms it starts with).
fn open_area(game: &Game) -> Aabb {
    let map = game.map();
    let mut area: Option<Aabb> = None;
    for row in 0..map.height() {
        for col in 0..map.width() {
            let cell = Cell::new(col, row);
            if map.tile(cell).is_none() {
                let r = map.cell_rect(cell);
                area = Some(area.map_or(r, |a| a.union(&r)));
            }
        }
    }
    area.unwrap_or_else(|| map.cell_rect(Cell::new(map.width() / 2, map.height() / 2)))
}

/// The dig cost, on every square in `window` the keeper could dig, when cells are large
/// enough to hold it.
fn mark_dig_costs(image: &mut Image, canvas: &Canvas, game: &Game, window: Aabb) {
    if canvas.pixels_per_cell() < COST_MIN_PIXELS {
        return;
    }
    let map = game.map();
    let cost = game.dig_cost().to_string();
    for row in 0..map.height() {
        for col in 0..map.width() {
            let cell = Cell::new(col, row);
            let r = map.cell_rect(cell);
            if !window.overlaps(&r) || !game.is_diggable(cell) {
                continue;
            }
            if let Some(p) = canvas.to_pixel((r.min + r.max) * 0.5) {
                image.text(
                    &cost,
                    (p.x as i32, p.y as i32),
                    FontSize::Small,
                    Anchor::Center,
                    COST_INK,
                );
            }
        }
    }
}

/// How the game ended, over the top of the map (rock, above the entrance).
fn banner(image: &mut Image, game: &Game) {
    let s = game.summary();
    let seconds = s.steps / u64::from(STEPS_PER_SECOND);
    let title = if s.treasure_left == 0 {
        "The heroes took all the treasure".to_string()
    } else {
        format!("{} pieces of treasure kept", s.treasure_left)
    };
    let detail = format!(
        "{}:{:02}, {} waves: {} heroes killed, {} escaped",
        seconds / 60,
        seconds % 60,
        s.waves,
        s.heroes_lost,
        s.heroes_escaped
    );
    let (top, height) = (12, 56);
    image.fill_rect((0, top), (VIEWPORT_WIDTH, height), PANEL.with_alpha(220));
    let middle = VIEWPORT_WIDTH as i32 / 2;
    image.text(
        &title,
        (middle, top + 18),
        FontSize::Huge,
        Anchor::Center,
        INK,
    );
    image.text(
        &detail,
        (middle, top + 42),
        FontSize::Medium,
        Anchor::Center,
        INK,
    );
}

#[cfg(test)]
#[path = "screen_tests.rs"]
mod tests;
