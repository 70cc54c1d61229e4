//! tileslide's contender: [`NavGrid::find_path`] on the scene's grid.

#[cfg(doc)]
use tileslide::NavGrid;

use super::{PathContender, PathQuery, PathScene, PathsError};

/// tileslide's paths: every query is one [`NavGrid::find_path`] between the two points, the
/// A* search on the lattice and the smoothing of its result into straight runs (each run
/// checked with the map's circle cast), as a game calls it.
#[derive(Clone, Debug)]
pub struct TileslidePaths {
    radius: f32,
}

impl TileslidePaths {
    /// The name it is reported under.
    pub const NAME: &'static str = "tileslide";

    /// The contender for `scene`, searching its navigation grid.
    #[must_use]
    pub fn new(scene: &PathScene) -> Self {
        Self {
            radius: scene.nav().max_radius(),
        }
    }
}

impl PathContender for TileslidePaths {
    fn name(&self) -> &'static str {
        Self::NAME
    }

    fn prepare(&mut self, _: &PathScene, radius: f32) -> Result<(), PathsError> {
        self.radius = radius;
        Ok(())
    }

    fn find(&mut self, scene: &PathScene, query: &PathQuery) -> Result<Option<f32>, PathsError> {
        Ok(scene
            .nav()
            .find_path(scene.map(), query.from, query.to, self.radius)?
            .map(|path| path.length()))
    }
}
