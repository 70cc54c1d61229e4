//! Navigation agents: bodies that steer along a path or down a flow field to a goal, on the
//! core's navigation grid (`NavGrid`), kept in step with the map.

use std::collections::BTreeMap;

use bevy::prelude::*;
use tileslide::{FlowField, NavConfig, NavError, NavGrid, NavPath, TileMap};

use crate::bodies::ProposedMove;
use crate::map::CollisionMap;
use crate::messages::{NavArrived, TileslideError};
use crate::units::MapUnits;

/// How an agent finds its way.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NavGoal {
    /// Along the shortest path to the point (found once, and again when a map edit
    /// changes the ground it crosses).
    Path(Vec2),
    /// Down the flow field of the point, shared by every agent of the same radius heading
    /// there (a crowd flowing to one spot).
    Flow(Vec2),
}

impl NavGoal {
    /// The point it leads to.
    #[must_use]
    pub fn point(&self) -> Vec2 {
        match *self {
            NavGoal::Path(p) | NavGoal::Flow(p) => p,
        }
    }
}

/// Where an agent is with its goal.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum NavStatus {
    /// No goal.
    #[default]
    Idle,
    /// On its way.
    Moving,
    /// At its goal (the goal is then cleared).
    Arrived,
    /// The goal cannot be reached by a circle of its radius.
    Unreachable,
}

/// A body that finds its way: each step, before the bodies are resolved, it sets its
/// [`ProposedMove`] towards its goal at its speed. Give the entity a [`Body`](crate::Body)
/// too; the resolver slides agents round each other and along walls.
///
/// ```
/// # use bevy::prelude::*;
/// # use tileslide_bevy::{Body, NavAgent, NavGoal};
/// fn spawn(mut commands: Commands) {
///     commands.spawn((
///         Body::circle(0.3),
///         NavAgent::new(0.3, 4.0).with_goal(NavGoal::Path(Vec2::new(12.5, -3.5))),
///         Transform::from_xyz(1.5, -1.5, 0.0),
///     ));
/// }
/// # let _ = spawn;
/// ```
#[derive(Component, Clone, Debug, PartialEq)]
#[require(ProposedMove)]
pub struct NavAgent {
    /// The radius its ways are planned for (world units): its body's.
    pub radius: f32,
    /// How fast it moves (world units per second).
    pub speed: f32,
    /// How near the goal counts as there (world units).
    pub arrive_distance: f32,
    goal: Option<NavGoal>,
    status: NavStatus,
    /// The path it follows (map units) and the index of its next point.
    path: Option<(NavPath, usize)>,
}

impl NavAgent {
    /// An agent of `radius` moving at `speed`, arriving within a tenth of its radius,
    /// without a goal.
    #[must_use]
    pub fn new(radius: f32, speed: f32) -> Self {
        Self {
            radius,
            speed,
            arrive_distance: radius * 0.1,
            goal: None,
            status: NavStatus::Idle,
            path: None,
        }
    }

    /// The same, heading for `goal`.
    #[must_use]
    pub fn with_goal(mut self, goal: NavGoal) -> Self {
        self.set_goal(Some(goal));
        self
    }

    /// Heads for `goal` (`None`: stops).
    pub fn set_goal(&mut self, goal: Option<NavGoal>) {
        if self.goal != goal {
            self.goal = goal;
            self.path = None;
            self.status = if goal.is_some() {
                NavStatus::Moving
            } else {
                NavStatus::Idle
            };
        }
    }

    /// Its goal.
    #[must_use]
    pub fn goal(&self) -> Option<NavGoal> {
        self.goal
    }

    /// Where it is with its goal.
    #[must_use]
    pub fn status(&self) -> NavStatus {
        self.status
    }

    /// The path it follows (map units), for a [`NavGoal::Path`] goal.
    #[must_use]
    pub fn path(&self) -> Option<&NavPath> {
        self.path.as_ref().map(|(path, _)| path)
    }
}

/// A flow field's key: its goal and radius, bit for bit.
type FieldKey = (u32, u32, u32);

/// The navigation grid of the map and the flow fields agents follow.
#[derive(Resource, Debug, Default)]
pub struct Navigation {
    /// `None`: the core's default, for circles up to one cell of the map wide.
    config: Option<NavConfig>,
    grid: Option<NavGrid>,
    /// The map generation the grid was built for.
    built_for: u64,
    fields: BTreeMap<FieldKey, FlowField>,
    used: Vec<FieldKey>,
}

impl Navigation {
    /// A grid built with `config` (map units) once there is a map.
    #[must_use]
    pub fn new(config: NavConfig) -> Self {
        Self {
            config: Some(config),
            ..Self::default()
        }
    }

    /// The config the grid of `map` is built with: the one given, or else the core's
    /// default with `max_radius` one cell of the map (the core's default is one map unit,
    /// a cell of a unit-cell map, but a Tiled or LDtk map is in pixels).
    fn config_for(&self, map: &TileMap) -> NavConfig {
        self.config.unwrap_or_else(|| NavConfig {
            max_radius: map.cell_size().min_element(),
            ..NavConfig::default()
        })
    }

    /// The grid, once built.
    #[must_use]
    pub fn grid(&self) -> Option<&NavGrid> {
        self.grid.as_ref()
    }

    /// Builds the grid for `map`, or catches it up with the map's edits. `None` when the
    /// map was edited in a way no path survives (the agents then plan again).
    fn catch_up(&mut self, map: &TileMap, generation: u64) -> Result<bool, NavError> {
        let config = self.config_for(map);
        let rebuild = |config| NavGrid::new(map, config);
        match &mut self.grid {
            Some(grid) if self.built_for == generation => match grid.sync(map) {
                Ok(change) => {
                    if !change.is_empty() {
                        for field in self.fields.values_mut() {
                            field.sync(grid, map)?;
                        }
                    }
                    Ok(!change.is_empty())
                }
                Err(NavError::OtherMap) => {
                    self.grid = Some(rebuild(config)?);
                    self.fields.clear();
                    Ok(true)
                }
                Err(e) => Err(e),
            },
            _ => {
                self.grid = Some(rebuild(config)?);
                self.built_for = generation;
                self.fields.clear();
                Ok(true)
            }
        }
    }
}

/// Steers every agent towards its goal by setting its proposed move.
pub(crate) fn steer_agents(
    units: Res<MapUnits>,
    time: Res<Time>,
    map: Res<CollisionMap>,
    mut nav: ResMut<Navigation>,
    mut agents: Query<(Entity, &mut NavAgent, &Transform, &mut ProposedMove)>,
    mut arrived: MessageWriter<NavArrived>,
    mut errors: MessageWriter<TileslideError>,
    mut commands: Commands,
) {
    let Some(tile_map) = map.map() else {
        return;
    };
    if agents.is_empty() {
        return;
    }
    let changed = match nav.catch_up(tile_map, map.generation()) {
        Ok(changed) => changed,
        Err(e) => {
            for (entity, ..) in &agents {
                errors.write(TileslideError {
                    entity,
                    message: e.to_string(),
                });
            }
            return;
        }
    };
    let nav = &mut *nav;
    let Some(grid) = nav.grid.as_ref() else {
        return;
    };
    nav.used.clear();
    let step = time.delta_secs();
    for (entity, mut agent, transform, mut proposed) in &mut agents {
        let Some(goal) = agent.goal else {
            continue;
        };
        let at = units.to_map(transform.translation.truncate());
        let to = units.to_map(goal.point());
        let reach = units.length_to_map(agent.speed) * step;
        let arrive = units.length_to_map(agent.arrive_distance);
        if at.distance(to) <= arrive {
            agent.goal = None;
            agent.path = None;
            agent.status = NavStatus::Arrived;
            let event = NavArrived {
                entity,
                goal: goal.point(),
            };
            arrived.write(event);
            commands.trigger(event);
            continue;
        }
        let radius = units.length_to_map(agent.radius);
        let direction = match goal {
            NavGoal::Path(_) => {
                if changed {
                    agent.path = None;
                }
                path_direction(grid, tile_map, &mut agent, at, to, radius)
            }
            NavGoal::Flow(_) => {
                let key = (to.x.to_bits(), to.y.to_bits(), radius.to_bits());
                if !nav.used.contains(&key) {
                    nav.used.push(key);
                }
                let field = match nav.fields.entry(key) {
                    std::collections::btree_map::Entry::Occupied(e) => e.into_mut(),
                    std::collections::btree_map::Entry::Vacant(e) => {
                        match FlowField::new(grid, tile_map, to, radius) {
                            Ok(field) => e.insert(field),
                            Err(e) => {
                                errors.write(TileslideError {
                                    entity,
                                    message: e.to_string(),
                                });
                                continue;
                            }
                        }
                    }
                };
                field
                    .direction(grid, tile_map, at)
                    .map(|d| d.map(|d| (d, at.distance(to))))
            }
        };
        match direction {
            Ok(Some((d, left))) => {
                agent.status = NavStatus::Moving;
                proposed.0 = units.to_world(d * reach.min(left));
            }
            Ok(None) => agent.status = NavStatus::Unreachable,
            Err(e) => {
                errors.write(TileslideError {
                    entity,
                    message: e.to_string(),
                });
            }
        }
    }
    // Fields no agent follows any more are dropped.
    if nav.fields.len() > nav.used.len() {
        let used = &nav.used;
        nav.fields.retain(|key, _| used.contains(key));
    }
}

/// The unit direction along the agent's path and the length left to its next point,
/// finding the path first if it has none.
fn path_direction(
    grid: &NavGrid,
    map: &TileMap,
    agent: &mut NavAgent,
    at: tileslide::Vec2,
    to: tileslide::Vec2,
    radius: f32,
) -> Result<Option<(tileslide::Vec2, f32)>, NavError> {
    if agent.path.is_none() {
        match grid.find_path(map, at, to, radius)? {
            Some(path) => agent.path = Some((path, 1)),
            None => return Ok(None),
        }
    }
    let Some((path, next)) = agent.path.as_mut() else {
        return Ok(None);
    };
    let points = path.points();
    // A point within a tenth of the radius is passed: the resolver keeps a gap from walls,
    // so a body does not always stop exactly on a corner's point.
    while *next + 1 < points.len() && at.distance(points[*next]) <= radius * 0.1 {
        *next += 1;
    }
    let target = points.get(*next).copied().unwrap_or(to);
    let left = at.distance(target);
    Ok((target - at).try_normalize().map(|d| (d, left)))
}
