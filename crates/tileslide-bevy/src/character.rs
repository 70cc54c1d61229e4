//! Characters: the core's platformer controller (`tileslide::Character`) on an entity, moved
//! by its input's velocity each step, with the surfaces it touched.

use bevy::prelude::*;
use tileslide::{
    Character, CharacterShape, Contact, ControllerConfig, MoveOptions, SegmentSource, TileMap,
};

use crate::bodies::entity_of;
use crate::map::CollisionMap;
use crate::messages::{Crushed, Side, SurfaceContact, SurfaceTouch, TileRef, TileslideError};
use crate::position::StepPosition;
use crate::units::MapUnits;

/// A platformer character: a box or a circle that walks up ramps, lands, slides along walls,
/// rides moving platforms ([`Platform`](crate::Platform)) and jumps up through one-way
/// platforms. Each step moves it by its [`CharacterInput`]'s velocity; what it touched is in
/// its [`CharacterContacts`].
///
/// Distances (the shape, and the configuration's skin, snap distance and step height) are
/// in world units.
///
/// ```
/// # use bevy::prelude::*;
/// # use tileslide_bevy::{CharacterController, CharacterInput};
/// fn spawn(mut commands: Commands) {
///     commands.spawn((
///         CharacterController::rect(Vec2::new(0.3, 0.45)),
///         CharacterInput { velocity: Vec2::new(6.0, 0.0), ..default() },
///         Transform::from_xyz(2.0, -7.5, 0.0),
///     ));
/// }
/// # let _ = spawn;
/// ```
#[derive(Component, Clone, Debug)]
#[require(Transform, CharacterInput, CharacterContacts, StepPosition)]
pub struct CharacterController {
    shape: Shape,
    up: Vec2,
    config: ControllerConfig,
    core: Option<Character>,
}

/// A character's shape in world units.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Shape {
    Rect(Vec2),
    Circle(f32),
}

impl CharacterController {
    /// A box of half extents `half` (world units), up along +y.
    #[must_use]
    pub fn rect(half: Vec2) -> Self {
        Self::of(Shape::Rect(half))
    }

    /// A circle of `radius` (world units), up along +y.
    #[must_use]
    pub fn circle(radius: f32) -> Self {
        Self::of(Shape::Circle(radius))
    }

    fn of(shape: Shape) -> Self {
        Self {
            shape,
            up: Vec2::Y,
            config: ControllerConfig::default(),
            core: None,
        }
    }

    /// The same, with `up` (world axes; any length but zero).
    #[must_use]
    pub fn with_up(self, up: Vec2) -> Self {
        Self {
            up,
            core: None,
            ..self
        }
    }

    /// The same, moving by `config` (its distances in world units).
    #[must_use]
    pub fn with_config(self, config: ControllerConfig) -> Self {
        Self {
            config,
            core: None,
            ..self
        }
    }

    /// The core's character, once the first step has made it (map units, y down).
    #[must_use]
    pub fn core(&self) -> Option<&Character> {
        self.core.as_ref()
    }

    /// The core character this describes, at world point `at`.
    fn build(&self, units: &MapUnits, at: Vec2) -> Result<Character, tileslide::ControllerError> {
        let shape = match self.shape {
            Shape::Rect(half) => CharacterShape::rect(units.to_map(half).abs())?,
            Shape::Circle(radius) => CharacterShape::circle(units.length_to_map(radius))?,
        };
        let config = ControllerConfig {
            snap_distance: units.length_to_map(self.config.snap_distance),
            skin: units.length_to_map(self.config.skin),
            step_height: units.length_to_map(self.config.step_height),
            ..self.config
        };
        Character::new(
            shape,
            units.to_map(at),
            units.direction_to_map(self.up),
            config,
        )
    }
}

/// What the game asks of a character this step.
#[derive(Component, Clone, Copy, Debug, Default, PartialEq)]
pub struct CharacterInput {
    /// The game's velocity for the character (world units per second, gravity and jumps
    /// included). The step moves the character by `velocity × dt` and leaves here what the
    /// surfaces it touched did not stop: landing zeroes the fall, a ceiling the rise, a wall
    /// the speed into it (the core's `move_and_slide`).
    pub velocity: Vec2,
    /// Fall through one-way platforms (hold it until the character is clear of one).
    pub drop_through: bool,
}

/// The surfaces a character touched in its last step, by side.
#[derive(Component, Clone, Copy, Debug, Default, PartialEq)]
pub struct CharacterContacts {
    /// Walkable ground under it after the step.
    pub ground: Option<SurfaceTouch>,
    /// A ceiling that stopped it.
    pub ceiling: Option<SurfaceTouch>,
    /// A wall on its left.
    pub left: Option<SurfaceTouch>,
    /// A wall on its right.
    pub right: Option<SurfaceTouch>,
    /// A platform that crushed it.
    pub crush: Option<SurfaceTouch>,
    /// The same, as the core reported them (map units).
    pub core: tileslide::Contacts,
}

impl CharacterContacts {
    /// True when it stands on walkable ground.
    #[must_use]
    pub fn is_grounded(&self) -> bool {
        self.ground.is_some()
    }

    /// True when it stands on a moving platform.
    #[must_use]
    pub fn is_riding(&self) -> bool {
        self.ground.is_some_and(|g| g.platform.is_some())
    }

    /// Each side touched, with its surface.
    pub fn touched(&self) -> impl Iterator<Item = (Side, SurfaceTouch)> {
        [
            (Side::Ground, self.ground),
            (Side::Ceiling, self.ceiling),
            (Side::Left, self.left),
            (Side::Right, self.right),
        ]
        .into_iter()
        .filter_map(|(side, touch)| Some((side, touch?)))
    }
}

/// A contact of the core in world terms.
fn touch_of(
    contact: &Contact,
    map: &TileMap,
    units: &MapUnits,
    centre: tileslide::Vec2,
) -> SurfaceTouch {
    let (tile, platform, segment) = match contact.source {
        SegmentSource::Tile { segment, tile } => (
            Some(TileRef {
                cell: segment.cell,
                tile,
            }),
            None,
            map.active_segment(segment).map(|s| s.segment),
        ),
        SegmentSource::Temporary { owner, index, .. } => (
            None,
            entity_of(owner),
            map.temporaries().get(index).map(|t| t.segment),
        ),
        // A source a later core may add: no tile, no platform, the point at the centre.
        _ => (None, None, None),
    };
    let point = segment.map_or(centre, |s| s.closest_point(centre));
    SurfaceTouch {
        normal: units.direction_to_world(contact.normal),
        point: units.to_world(point),
        flags: contact.flags,
        tile,
        platform,
        velocity: units.to_world(contact.platform_velocity()),
    }
}

/// Moves every character by its input, writes its contacts, and reports them.
pub(crate) fn move_characters(
    units: Res<MapUnits>,
    time: Res<Time>,
    map: Res<CollisionMap>,
    mut characters: Query<(
        Entity,
        &mut CharacterController,
        &Transform,
        &mut CharacterInput,
        &mut CharacterContacts,
        &mut StepPosition,
    )>,
    mut contacts_out: MessageWriter<SurfaceContact>,
    mut crushes: MessageWriter<Crushed>,
    mut errors: MessageWriter<TileslideError>,
    mut commands: Commands,
) {
    let Some(map) = map.map() else {
        return;
    };
    let dt = time.delta_secs();
    for (entity, mut controller, transform, mut input, mut contacts, mut position) in
        &mut characters
    {
        let moved = position.moved_by_game(transform);
        let controller = &mut *controller;
        let result = match (&mut controller.core, moved) {
            (Some(core), Some(at)) => core.teleport(units.to_map(at)),
            (None, _) => {
                let at = transform.translation.truncate();
                controller.build(&units, at).map(|core| {
                    controller.core = Some(core);
                })
            }
            (Some(_), None) => Ok(()),
        };
        let Some(core) = controller.core.as_mut().filter(|_| result.is_ok()) else {
            if let Err(e) = result {
                errors.write(TileslideError {
                    entity,
                    message: e.to_string(),
                });
            }
            continue;
        };
        if let Some(at) = moved {
            position.teleported(at);
        }
        let mut velocity = units.to_map(input.velocity);
        let options = MoveOptions {
            drop_through: input.drop_through,
        };
        let touched = match core.move_and_slide(map, &mut velocity, dt, options) {
            Ok(touched) => touched,
            Err(e) => {
                errors.write(TileslideError {
                    entity,
                    message: e.to_string(),
                });
                continue;
            }
        };
        input.velocity = units.to_world(velocity);
        let centre = core.position;
        let touch = |c: &Option<Contact>| c.as_ref().map(|c| touch_of(c, map, &units, centre));
        *contacts = CharacterContacts {
            ground: touch(&touched.ground),
            ceiling: touch(&touched.ceiling),
            left: touch(&touched.left),
            right: touch(&touched.right),
            crush: touch(&touched.crush),
            core: touched,
        };
        for (side, touch) in contacts.touched() {
            let event = SurfaceContact {
                entity,
                side,
                touch,
            };
            contacts_out.write(event);
            commands.trigger(event);
        }
        if let Some(touch) = contacts.crush {
            let event = Crushed { entity, touch };
            crushes.write(event);
            commands.trigger(event);
        }
    }
}

/// Writes each character's position into its `Transform`.
pub(crate) fn write_back_characters(
    units: Res<MapUnits>,
    mut characters: Query<(&CharacterController, &mut Transform, &mut StepPosition)>,
) {
    for (controller, mut transform, mut position) in &mut characters {
        if let Some(core) = &controller.core {
            position.step_to(units.to_world(core.position), &mut transform);
        }
    }
}
