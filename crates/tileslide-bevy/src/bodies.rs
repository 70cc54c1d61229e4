//! Bodies: circles and compounds of circles moved by the core's resolver (`Bodies`), one
//! component per body and one core set for them all.

use bevy::ecs::entity::EntityHashMap;
use bevy::prelude::*;
use tileslide::{
    BodyDesc, BodyFilter, BodyHandle, BodyShape, Circle, ContactSource, Owner, ResolveConfig,
    ResolveTrace, WallSource,
};

use crate::map::CollisionMap;
use crate::messages::{BodyContact, TileRef, TileslideError};
use crate::position::StepPosition;
use crate::units::MapUnits;

/// A body: a circle, or a compound of circles, that the resolver moves without overlap
/// and without crossing walls. Its place is its `Transform`'s x and y (world units); it
/// moves by its [`ProposedMove`] and its [`Velocity`] each step.
///
/// ```
/// # use bevy::prelude::*;
/// # use tileslide_bevy::{Body, ProposedMove};
/// fn spawn(mut commands: Commands) {
///     commands.spawn((Body::circle(0.3), Transform::from_xyz(1.5, -1.5, 0.0)));
/// }
/// # let _ = spawn;
/// ```
#[derive(Component, Clone, Debug, PartialEq)]
#[require(Transform, ProposedMove, StepPosition, BodyLink)]
pub struct Body {
    /// Its circles: centre offsets from the body's position (world units, y up) and radii.
    circles: Vec<(Vec2, f32)>,
    /// What it collides with.
    pub filter: BodyFilter,
}

impl Body {
    /// A circle of `radius` (world units) centred on the entity.
    #[must_use]
    pub fn circle(radius: f32) -> Self {
        Self::compound([(Vec2::ZERO, radius)])
    }

    /// Circles `(offset from the entity, radius)`, moved together (world units).
    #[must_use]
    pub fn compound(circles: impl IntoIterator<Item = (Vec2, f32)>) -> Self {
        Self {
            circles: circles.into_iter().collect(),
            filter: BodyFilter::default(),
        }
    }

    /// The same body, with `filter`.
    #[must_use]
    pub fn with_filter(self, filter: BodyFilter) -> Self {
        Self { filter, ..self }
    }

    /// Its circles: `(offset, radius)`, world units.
    #[must_use]
    pub fn circles(&self) -> &[(Vec2, f32)] {
        &self.circles
    }

    /// The core's shape, in map units.
    fn shape(&self, units: &MapUnits) -> Result<BodyShape, tileslide::BodyError> {
        if let [(offset, radius)] = self.circles[..]
            && offset == Vec2::ZERO
        {
            return BodyShape::circle(units.length_to_map(radius));
        }
        BodyShape::compound(self.circles.iter().map(|&(offset, radius)| {
            Circle::new(units.to_map(offset), units.length_to_map(radius))
        }))
    }
}

/// The move a body wants to make in the next step (world units), on top of its
/// [`Velocity`]; the step takes it and sets it back to zero. Set it in the fixed schedule
/// before [`TileslideSet::SyncIn`](crate::TileslideSet::SyncIn).
#[derive(Component, Clone, Copy, Debug, Default, PartialEq)]
pub struct ProposedMove(pub Vec2);

/// A body's velocity (world units per second): each step proposes `velocity × dt`. It is
/// the game's to keep: the resolver slides the move, it does not change the velocity.
#[derive(Component, Clone, Copy, Debug, Default, PartialEq)]
pub struct Velocity(pub Vec2);

/// Asks for a body's contacts: each step, a [`BodyContact`] message and entity event for
/// each tile, platform or body the resolver stopped or turned it at (a bullet's wall, a
/// ball's bounce). The resolve of these bodies is traced, which costs a little for each of
/// them and nothing for the others; their moves are the same either way.
///
/// ```
/// # use bevy::prelude::*;
/// # use tileslide_bevy::{Body, BodyContact, ReportContacts};
/// fn spawn(mut commands: Commands) {
///     commands
///         .spawn((Body::circle(0.1), ReportContacts, Transform::from_xyz(1.5, -1.5, 0.0)))
///         .observe(|contact: On<BodyContact>| {
///             if let Some(tile) = contact.tile {
///                 println!("hit tile {} in cell {:?}", tile.tile, tile.cell);
///             }
///         });
/// }
/// # let _ = spawn;
/// ```
#[derive(Component, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ReportContacts;

/// Which core body an entity's [`Body`] is (none until the first step takes it).
#[derive(Component, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BodyLink {
    handle: Option<BodyHandle>,
}

impl BodyLink {
    /// The body's handle in [`TileslideBodies`], once the plugin has added it.
    #[must_use]
    pub fn handle(&self) -> Option<BodyHandle> {
        self.handle
    }
}

/// Every body of the world, in the core's [`Bodies`](tileslide::Bodies) (map units, y
/// down), and which entity each one is.
#[derive(Resource, Debug, Default)]
pub struct TileslideBodies {
    bodies: tileslide::Bodies,
    entities: EntityHashMap<BodyHandle>,
    report: tileslide::ResolveReport,
    /// Scratch: entities to add or remove, sorted so that slots are taken in a fixed order.
    scratch: Vec<Entity>,
}

impl TileslideBodies {
    /// The core's bodies (map units).
    #[must_use]
    pub fn bodies(&self) -> &tileslide::Bodies {
        &self.bodies
    }

    /// What the last step's resolve did.
    #[must_use]
    pub fn last_report(&self) -> tileslide::ResolveReport {
        self.report
    }

    /// Sets how the resolver works.
    ///
    /// # Errors
    /// The core's error for a setting out of range; the settings are then unchanged.
    pub fn set_config(&mut self, config: ResolveConfig) -> Result<(), tileslide::BodyError> {
        self.bodies.set_config(config)
    }

    fn remove(&mut self, entity: Entity) {
        if let Some(handle) = self.entities.remove(&entity) {
            // The handle came from this set and is removed once: it cannot be stale.
            let _ = self.bodies.remove(handle);
        }
    }
}

/// The owner a body, a character or a platform of `entity` is given in the core.
pub(crate) fn owner_of(entity: Entity) -> Owner {
    Owner(entity.to_bits())
}

/// The entity of a core owner, if it is one.
pub(crate) fn entity_of(owner: Owner) -> Option<Entity> {
    Entity::try_from_bits(owner.0)
}

/// A key that sorts entities in the order a fresh world spawns them: by index, then
/// generation. (`Entity`'s own order compares bit patterns, which in Bevy 0.19 run
/// against the index.)
pub(crate) fn spawn_order(entity: Entity) -> (u32, u32) {
    (entity.index_u32(), entity.generation().to_bits())
}

/// Takes new, changed and removed bodies into the core, in entity order (so the same spawns
/// give the same slots, and the same results).
pub(crate) fn add_and_remove_bodies(
    units: Res<MapUnits>,
    mut set: ResMut<TileslideBodies>,
    mut removed: RemovedComponents<Body>,
    mut changed: Query<
        (Entity, &Body, &Transform, &mut BodyLink, &mut StepPosition),
        Changed<Body>,
    >,
    mut errors: MessageWriter<TileslideError>,
) {
    let set = &mut *set;
    set.scratch.clear();
    set.scratch.extend(removed.read());
    set.scratch.sort_unstable_by_key(|&e| spawn_order(e));
    for i in 0..set.scratch.len() {
        let entity = set.scratch[i];
        set.remove(entity);
    }
    set.scratch.clear();
    set.scratch
        .extend(changed.iter().map(|(entity, ..)| entity));
    if set.scratch.is_empty() {
        return;
    }
    set.scratch.sort_unstable_by_key(|&e| spawn_order(e));
    for i in 0..set.scratch.len() {
        let entity = set.scratch[i];
        let Ok((_, body, transform, mut link, mut position)) = changed.get_mut(entity) else {
            continue;
        };
        set.remove(entity);
        link.handle = None;
        let at = transform.translation.truncate();
        let added = body.shape(&units).and_then(|shape| {
            let desc = BodyDesc::new(units.to_map(at), shape)
                .with_filter(body.filter)
                .with_owner(owner_of(entity));
            set.bodies.add(desc)
        });
        match added {
            Ok(handle) => {
                set.entities.insert(entity, handle);
                link.handle = Some(handle);
                position.teleported(at);
            }
            Err(e) => {
                errors.write(TileslideError {
                    entity,
                    message: e.to_string(),
                });
            }
        }
    }
}

/// Proposes each body's move: its velocity × dt plus its proposed move (taken), after a
/// teleport if the game moved its `Transform`.
pub(crate) fn propose_moves(
    units: Res<MapUnits>,
    time: Res<Time>,
    mut set: ResMut<TileslideBodies>,
    mut bodies: Query<(
        Entity,
        &BodyLink,
        &Transform,
        &mut ProposedMove,
        Option<&Velocity>,
        &mut StepPosition,
    )>,
    mut errors: MessageWriter<TileslideError>,
) {
    let dt = time.delta_secs();
    for (entity, link, transform, mut proposed, velocity, mut position) in &mut bodies {
        let Some(handle) = link.handle else {
            continue;
        };
        let mut result = Ok(());
        if let Some(at) = position.moved_by_game(transform) {
            result = set.bodies.set_position(handle, units.to_map(at));
            if result.is_ok() {
                position.teleported(at);
            }
        }
        let world_move = match velocity {
            Some(v) if v.0 != Vec2::ZERO && proposed.0 != Vec2::ZERO => v.0 * dt + proposed.0,
            Some(v) if v.0 != Vec2::ZERO => v.0 * dt,
            _ => proposed.0,
        };
        if proposed.0 != Vec2::ZERO {
            proposed.0 = Vec2::ZERO;
        }
        if world_move != Vec2::ZERO {
            result = result.and(set.bodies.propose(handle, units.to_map(world_move)));
        }
        if let Err(e) = result {
            errors.write(TileslideError {
                entity,
                message: e.to_string(),
            });
        }
    }
}

/// The step of the bodies: resolve every proposed move together, then make them; the
/// resolve traced for the bodies with [`ReportContacts`], whose contacts are then sent.
pub(crate) fn step_bodies(
    mut commands: Commands,
    units: Res<MapUnits>,
    map: Res<CollisionMap>,
    mut set: ResMut<TileslideBodies>,
    reporting: Query<&BodyLink, With<ReportContacts>>,
    mut out: MessageWriter<BodyContact>,
) {
    let Some(map) = map.map() else {
        return;
    };
    if set.bodies.is_empty() {
        return;
    }
    if reporting.is_empty() {
        set.report = set.bodies.step(map);
        return;
    }
    let mut trace = ResolveTrace::of_bodies(reporting.iter().filter_map(BodyLink::handle));
    set.report = set.bodies.step_traced(map, &mut trace);
    let entity_of_body = |handle| {
        set.bodies
            .get(handle)
            .ok()
            .and_then(|b| entity_of(b.owner()))
    };
    for story in &trace.bodies {
        let Some(entity) = entity_of_body(story.handle) else {
            continue;
        };
        for contact in story.passes.iter().filter_map(|p| p.chosen()) {
            let (tile, platform, other) = match contact.source {
                ContactSource::Wall(WallSource::Tile { segment, .. }) => (
                    Some(TileRef {
                        cell: segment.cell,
                        tile: segment.tile,
                    }),
                    None,
                    None,
                ),
                ContactSource::Wall(WallSource::Temporary { owner, .. }) => {
                    (None, entity_of(owner), None)
                }
                ContactSource::Body { handle, .. } => (None, None, entity_of_body(handle)),
                // A source a later core may add: reported with what is known.
                _ => (None, None, None),
            };
            let event = BodyContact {
                entity,
                tile,
                platform,
                other,
                point: units.to_world(contact.point),
                normal: units.direction_to_world(contact.normal),
            };
            out.write(event);
            commands.trigger(event);
        }
    }
}

/// Writes each body's position into its `Transform`.
pub(crate) fn write_back_bodies(
    units: Res<MapUnits>,
    set: Res<TileslideBodies>,
    mut bodies: Query<(&BodyLink, &mut Transform, &mut StepPosition)>,
) {
    for (link, mut transform, mut position) in &mut bodies {
        let Some(body) = link.handle.and_then(|h| set.bodies.get(h).ok()) else {
            continue;
        };
        position.step_to(units.to_world(body.position()), &mut transform);
    }
}
