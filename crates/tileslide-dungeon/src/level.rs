//! The shared ground every system works on: the map, the rock/earth split, the navigation
//! grid and the two flow fields heroes follow.

use tileslide::{Bodies, FlowField, NavChange, NavConfig, NavGrid, TileMap, Vec2};

use crate::error::GameError;
use crate::explore::Explored;
use crate::layout::{Ground, Layout};

/// The widest circle the navigation grid serves.
const NAV_MAX_RADIUS: f32 = 0.5;

/// The map and what is derived from it.
pub struct Level {
    /// The collision map (dug squares empty).
    pub map: TileMap,
    /// Rock or earth.
    pub ground: Ground,
    /// Paths and flow fields for circles.
    pub nav: NavGrid,
    /// Heroes' way to the treasure.
    pub to_treasure: FlowField,
    /// Heroes' way out.
    pub to_exit: FlowField,
    /// Where the treasure lies.
    pub treasure: Vec2,
    /// What the heroes have seen.
    pub explored: Explored,
    /// The way in and out.
    pub exit: Vec2,
}

impl Level {
    /// The level of `layout`.
    ///
    /// # Errors
    /// A navigation error (the layout's points must fit a hero).
    pub fn new(layout: Layout) -> Result<Self, GameError> {
        let map = layout.map;
        let nav = NavGrid::new(
            &map,
            NavConfig {
                max_radius: NAV_MAX_RADIUS,
                ..NavConfig::default()
            },
        )?;
        let hero = crate::components::Kind::Hero.radius();
        let to_treasure = FlowField::new(&nav, &map, layout.treasure, hero)?;
        let to_exit = FlowField::new(&nav, &map, layout.exit, hero)?;
        let explored = Explored::new(&map);
        Ok(Self {
            map,
            ground: layout.ground,
            nav,
            to_treasure,
            to_exit,
            treasure: layout.treasure,
            explored,
            exit: layout.exit,
        })
    }

    /// Brings the navigation grid and the heroes' flow fields up to date with the map's
    /// edits since the last call (each reads the map's edit journal; a field is
    /// recomputed only when an edit changed its way), and returns what changed in the
    /// grid, for the paths creatures keep.
    ///
    /// # Errors
    /// A navigation error (a bug: the grid and fields are this map's).
    pub fn catch_up(&mut self) -> Result<NavChange, GameError> {
        let change = self.nav.sync(&self.map)?;
        self.to_treasure.sync(&self.nav, &self.map)?;
        self.to_exit.sync(&self.nav, &self.map)?;
        Ok(change)
    }

    /// True when nothing blocks the straight line from `a` to `b` (ray cast).
    #[must_use]
    pub fn sees(&self, a: Vec2, b: Vec2) -> bool {
        self.map
            .cast_ray(
                tileslide::Ray::between(a, b),
                &tileslide::QueryFilter::default(),
            )
            .is_none()
    }

    /// True when a circle of `radius` at `p` touches neither a wall nor a body.
    #[must_use]
    pub fn is_free(&self, bodies: &Bodies, p: Vec2, radius: f32) -> bool {
        self.nav.fits(&self.map, p, radius).unwrap_or(false)
            && bodies.iter().all(|(_, b)| {
                let other = b.shape().bounding_radius();
                b.position().distance(p) > radius + other + 0.05
            })
    }
}
