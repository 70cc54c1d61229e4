//! Debug drawing with gizmos (feature `debug`): the core's debug lines of the map, the
//! bodies, the characters, the hit volumes and the agents' paths, drawn every frame.

use bevy::prelude::*;
use tileslide::debug::DebugKinds;
use tileslide::{Aabb, DebugKind, DebugLines};

use crate::bodies::{TileslideBodies, owner_of};
use crate::character::{CharacterContacts, CharacterController};
use crate::hits::TileslideHits;
use crate::map::CollisionMap;
use crate::nav::NavAgent;
use crate::units::MapUnits;

/// Draws what the plugin sees with Bevy's gizmos: the map's active segments with their
/// normals, the seams it hides, temporary segments, bodies, characters and their contacts,
/// hit volumes and hits, and agents' paths, from the core's debug lines (the same lines the
/// renderer and the browser playground draw). Add it beside [`TileslidePlugin`](crate::TileslidePlugin);
/// [`DebugDraw`] chooses what is drawn.
#[derive(Clone, Copy, Debug, Default)]
pub struct TileslideDebugPlugin;

impl Plugin for TileslideDebugPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<DebugDraw>().add_systems(
            PostUpdate,
            draw.after(bevy::transform::TransformSystems::Propagate),
        );
    }
}

/// What the debug drawing draws.
#[derive(Resource, Debug)]
pub struct DebugDraw {
    /// Draw at all.
    pub enabled: bool,
    /// The kinds of lines drawn (all by default).
    pub kinds: DebugKinds,
    /// Only what lies in this world rectangle (a camera's view) is drawn; `None`: all. On a
    /// large map, the map's lines are many: give the view.
    pub view: Option<Rect>,
    lines: DebugLines,
}

impl Default for DebugDraw {
    fn default() -> Self {
        Self {
            enabled: true,
            kinds: DebugKinds::ALL,
            view: None,
            lines: DebugLines::new(),
        }
    }
}

impl DebugDraw {
    /// The lines drawn last frame (map units, y down).
    #[must_use]
    pub fn lines(&self) -> &DebugLines {
        &self.lines
    }
}

/// The colour of `kind`'s lines, for a dark background; `None` for a kind of a newer core.
#[must_use]
pub fn color_of(kind: DebugKind) -> Option<Color> {
    let rgb = |r, g, b| Some(Color::srgb_u8(r, g, b));
    match kind {
        DebugKind::ActiveSegment => rgb(236, 240, 241),
        DebugKind::OneWaySegment => rgb(243, 156, 18),
        DebugKind::Normal => rgb(26, 188, 156),
        DebugKind::HiddenSegment => Some(Color::srgba_u8(149, 165, 166, 90)),
        DebugKind::TemporarySegment => rgb(187, 107, 217),
        DebugKind::Body => rgb(46, 204, 113),
        DebugKind::Character => rgb(52, 152, 219),
        DebugKind::Contact => rgb(230, 126, 34),
        DebugKind::Ray => rgb(232, 67, 147),
        DebugKind::RayHit => rgb(253, 121, 168),
        DebugKind::AttackVolume => rgb(231, 76, 60),
        DebugKind::VulnerabilityVolume => rgb(84, 160, 255),
        DebugKind::Hit => rgb(255, 71, 87),
        DebugKind::RefusedHit => rgb(149, 165, 166),
        DebugKind::Path => rgb(241, 196, 15),
        DebugKind::FlowArrow => rgb(127, 140, 141),
        DebugKind::BroadphaseBox => Some(Color::srgba_u8(187, 107, 217, 110)),
        _ => None,
    }
}

/// Fills the debug lines from the plugin's state and draws them.
fn draw(
    units: Res<MapUnits>,
    map: Option<Res<CollisionMap>>,
    bodies: Res<TileslideBodies>,
    hits: Res<TileslideHits>,
    characters: Query<(Entity, &CharacterController, &CharacterContacts)>,
    agents: Query<(Entity, &NavAgent)>,
    mut debug: ResMut<DebugDraw>,
    mut gizmos: Gizmos,
) {
    let debug = &mut *debug;
    debug.lines.clear();
    if !debug.enabled {
        return;
    }
    debug.lines.set_kinds(debug.kinds);
    let view = debug.view.map(|r| {
        let (a, b) = (units.to_map(r.min), units.to_map(r.max));
        Aabb::from_corners(a.min(b), a.max(b))
    });
    debug.lines.set_view(view);
    let lines = &mut debug.lines;
    if let Some(map) = map.as_deref().and_then(CollisionMap::map) {
        map.debug_lines(lines);
    }
    bodies.bodies().debug_lines(lines);
    for (entity, controller, contacts) in &characters {
        if let Some(core) = controller.core() {
            core.debug_lines(Some(&contacts.core), owner_of(entity), lines);
        }
    }
    hits.world().debug_lines(lines);
    for (entity, agent) in &agents {
        if let Some(path) = agent.path() {
            path.debug_lines(owner_of(entity), lines);
        }
    }
    let point = |p: tileslide::Vec2| units.to_world(p);
    for s in lines.segments() {
        if let Some(color) = color_of(s.kind) {
            gizmos.line_2d(point(s.segment.a), point(s.segment.b), color);
        }
    }
    for c in lines.circles() {
        if let Some(color) = color_of(c.kind) {
            let radius = units.length_to_world(c.circle.radius);
            gizmos.circle_2d(point(c.circle.center), radius, color);
        }
    }
    for b in lines.boxes() {
        if let Some(color) = color_of(b.kind) {
            let (min, max) = (point(b.aabb.min), point(b.aabb.max));
            gizmos.rect_2d((min + max) * 0.5, (max - min).abs(), color);
        }
    }
    let mark = units.length_to_world(0.1 * map_cell(map.as_deref()));
    for p in lines.points() {
        if let Some(color) = color_of(p.kind) {
            gizmos.cross_2d(point(p.point), mark, color);
        }
    }
}

/// The map's shorter cell side (1 without a map): the size of point marks.
fn map_cell(map: Option<&CollisionMap>) -> f32 {
    map.and_then(CollisionMap::map)
        .map_or(1.0, |m| m.cell_size().min_element())
}
