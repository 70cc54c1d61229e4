//! What the steps report: contacts, crushes, hits and arrivals, each sent both as a Bevy
//! message (read with `MessageReader`) and as an entity event (watched with observers).

use bevy::prelude::*;
use tileslide::{Cell, HitTypes, SegmentFlags, TileId};

/// A tile: its cell and its id.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct TileRef {
    /// The tile's cell.
    pub cell: Cell,
    /// The tile's id (for a Tiled map, its gid with its flip bits).
    pub tile: TileId,
}

/// Which side of a character a surface touched it on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Side {
    /// Walkable ground under it.
    Ground,
    /// A ceiling that stopped it.
    Ceiling,
    /// A wall on its left (lower x).
    Left,
    /// A wall on its right (higher x).
    Right,
}

/// One surface a character touched, in world terms.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceTouch {
    /// The surface's unit normal, towards the character (world axes, y up).
    pub normal: Vec2,
    /// The point of the surface nearest the character's centre after its move.
    pub point: Vec2,
    /// The segment's flags (`ONE_WAY` for a platform).
    pub flags: SegmentFlags,
    /// The tile touched; `None` for a moving platform.
    pub tile: Option<TileRef>,
    /// The moving platform touched; `None` for a tile.
    pub platform: Option<Entity>,
    /// How fast the surface moves (world units per second): a platform's velocity, zero for
    /// a tile.
    pub velocity: Vec2,
}

/// A character touched a surface during a step: sent for each side touched, every step.
#[derive(Message, EntityEvent, Clone, Copy, Debug, PartialEq)]
pub struct SurfaceContact {
    /// The character.
    pub entity: Entity,
    /// Where the surface was.
    pub side: Side,
    /// The surface.
    pub touch: SurfaceTouch,
}

/// A body with [`ReportContacts`](crate::ReportContacts) met something during a step: a
/// tile, a moving platform or another body. Sent for each contact the resolver acted on
/// (the first of each pass of collide and slide: what stopped the body or turned it), in
/// the order of the passes; a body that moved freely sends none.
#[derive(Message, EntityEvent, Clone, Copy, Debug, PartialEq)]
pub struct BodyContact {
    /// The body.
    pub entity: Entity,
    /// The tile met; `None` for a platform or a body.
    pub tile: Option<TileRef>,
    /// The moving platform met; `None` otherwise.
    pub platform: Option<Entity>,
    /// The other body met; `None` otherwise.
    pub other: Option<Entity>,
    /// The point met (world units): on a wall, the point nearest the circle's centre; on
    /// another body, the point of its circle facing this one's centre.
    pub point: Vec2,
    /// The unit contact normal, from what was met towards the body (world axes).
    pub normal: Vec2,
}

/// A moving platform pushed a character into the world with no room left: the character is
/// crushed (it stays on the world's side, overlapping the platform).
#[derive(Message, EntityEvent, Clone, Copy, Debug, PartialEq)]
pub struct Crushed {
    /// The character.
    pub entity: Entity,
    /// The platform's surface that pushed.
    pub touch: SurfaceTouch,
}

/// An attack hit a vulnerable entity: another entity's attack volume, or a tile whose hit
/// types the entity's vulnerability accepts. Sent to the victim.
#[derive(Message, EntityEvent, Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// The victim.
    #[event_target]
    pub victim: Entity,
    /// The attacking entity; `None` when a tile hit.
    pub attacker: Option<Entity>,
    /// The tile that hit; `None` when an entity hit.
    pub tile: Option<TileRef>,
    /// The types dealt.
    pub hit_type: HitTypes,
    /// Whether the victim took the hit (the team rule: another team, not invulnerable).
    pub accepted: bool,
    /// When in the step the volumes first touched, a fraction in [0, 1] (0 for a tile).
    pub t: f32,
    /// Where they touched (world units).
    pub point: Vec2,
}

/// A navigation agent reached its goal.
#[derive(Message, EntityEvent, Clone, Copy, Debug, PartialEq)]
pub struct NavArrived {
    /// The agent.
    pub entity: Entity,
    /// The goal it reached (world units).
    pub goal: Vec2,
}

/// A component the plugin could not take (a radius that is not positive, a position out of
/// the map's range), and why; the entity is left out of the step until it is fixed.
#[derive(Message, Clone, Debug, PartialEq)]
pub struct TileslideError {
    /// The entity.
    pub entity: Entity,
    /// What was wrong, in the core's words.
    pub message: String,
}
