//! tileslide's own contender: the crowd as [`Bodies`] on the scene's map, each step one
//! [`Bodies::step`] with every body proposing its velocity.

use glam::Vec2;
use tileslide::{Bodies, BodyDesc, BodyError, BodyHandle, BodyShape, TileMap};
use tileslide_scenes::{CrowdBody, SolidGrid, TileMapError};

use super::CrowdContender;

/// Why the tileslide crowd could not be built.
#[derive(Debug, thiserror::Error)]
pub enum TileslideCrowdError {
    /// The grid could not become a map.
    #[error(transparent)]
    Map(#[from] TileMapError),
    /// A body was refused.
    #[error(transparent)]
    Body(#[from] BodyError),
}

/// The crowd moved by tileslide's resolver.
#[derive(Debug)]
pub struct TileslideCrowd {
    map: TileMap,
    bodies: Bodies,
    crowd: Vec<(BodyHandle, Vec2)>,
}

impl TileslideCrowd {
    /// The name it is reported under.
    pub const NAME: &'static str = "tileslide";

    /// The crowd on `grid`'s map (solid squares), one circle of `radius` per body.
    ///
    /// # Errors
    /// When the map or a body cannot be built.
    pub fn new(
        grid: &SolidGrid,
        crowd: &[CrowdBody],
        radius: f32,
    ) -> Result<Self, TileslideCrowdError> {
        let map = grid.to_tile_map()?;
        let mut bodies = Bodies::new();
        let shape = BodyShape::circle(radius)?;
        let crowd = crowd
            .iter()
            .map(|b| {
                let h = bodies.add(BodyDesc::new(b.position, shape.clone()))?;
                Ok((h, b.velocity))
            })
            .collect::<Result<_, BodyError>>()?;
        Ok(Self { map, bodies, crowd })
    }
}

impl CrowdContender for TileslideCrowd {
    fn name(&self) -> &'static str {
        Self::NAME
    }

    fn step(&mut self) {
        for &(h, v) in &self.crowd {
            // Handles were just made by this contender and never removed; velocities are
            // finite by construction of the scene.
            let _ = self.bodies.propose(h, v);
        }
        self.bodies.step(&self.map);
    }

    fn positions(&self) -> Vec<Vec2> {
        self.crowd
            .iter()
            .map(|&(h, _)| self.bodies.get(h).map_or(Vec2::NAN, |b| b.position()))
            .collect()
    }
}
