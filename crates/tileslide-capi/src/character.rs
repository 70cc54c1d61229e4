//! The platformer character from C: a box or circle moved through a map by the game's
//! velocity × dt, walking slopes, landing, sliding along walls, standing on one-way
//! platforms and dropping through them on request (the core's `Character::move_and_slide`).

use tileslide::{
    Character, CharacterShape, Contact, Contacts, ControllerConfig, ControllerError, MoveOptions,
    SegmentFlags, SegmentSource, Vec2,
};

use crate::{
    Failure, TS_NONE, TS_SHAPE_CIRCLE, TS_SHAPE_RECT, coordinate, fill, free_boxed, give_boxed,
    guarded, map_ref, ts_map, ts_status,
};

/// A platformer character (opaque): made by `ts_character_create`, freed by
/// `ts_character_free`.
pub struct ts_character {
    pub(crate) character: Character,
    /// The game's velocity: set by `ts_character_set_input`, clipped by each step.
    velocity: Vec2,
    /// Fall through one-way platforms in the coming steps.
    drop_through: bool,
    /// What the last move touched.
    pub(crate) contacts: Contacts,
}

/// What a character is and how it moves: start from `ts_default_character_def()` and set
/// what differs. Distances are in map units (the defaults suit cells of size 1).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct ts_character_def {
    /// The shape's centre, x.
    pub x: f32,
    /// The shape's centre, y.
    pub y: f32,
    /// `TS_SHAPE_RECT` (by `half_width`, `half_height`) or `TS_SHAPE_CIRCLE` (by `radius`).
    pub shape: u32,
    /// A rectangle's half width.
    pub half_width: f32,
    /// A rectangle's half height.
    pub half_height: f32,
    /// A circle's radius.
    pub radius: f32,
    /// The up direction, x (any length but zero).
    pub up_x: f32,
    /// The up direction, y: -1 by default, for maps whose row 0 is the top (ASCII, Tiled).
    pub up_y: f32,
    /// The steepest walkable slope, in degrees from level, in [0, 90).
    pub max_slope_degrees: f32,
    /// How far below its feet a grounded character looks for ground to stay on.
    pub snap_distance: f32,
    /// The gap kept between the character and every surface it stops against.
    pub skin: f32,
    /// How many times one move may hit a surface and slide on (at least 1).
    pub max_slides: u32,
    /// The highest ledge a walk steps up onto (0: none).
    pub step_height: f32,
    /// The segment flags that block it (`TS_SEGMENT_SOLID | TS_SEGMENT_ONE_WAY`).
    pub mask: u32,
}

/// Segment flag: a solid segment.
pub const TS_SEGMENT_SOLID: u32 = 1;

/// Segment flag: a one-way platform (blocks only from its front).
pub const TS_SEGMENT_ONE_WAY: u32 = 2;

// Literals, for cbindgen to write into the header; the core's numbers.
const _: () = assert!(TS_SEGMENT_SOLID == SegmentFlags::SOLID.0);
const _: () = assert!(TS_SEGMENT_ONE_WAY == SegmentFlags::ONE_WAY.0);

/// Where a character is after its last step, how fast the game's velocity is once the
/// surfaces touched have taken out what they stopped, and whether it stands on ground.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ts_character_state {
    /// The shape's centre, x.
    pub x: f32,
    /// The shape's centre, y.
    pub y: f32,
    /// The velocity, x.
    pub vx: f32,
    /// The velocity, y.
    pub vy: f32,
    /// Stands on walkable ground.
    pub grounded: bool,
}

/// Which surface of a character a contact is.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ts_contact_side {
    /// Walkable ground under it after the move.
    TS_CONTACT_GROUND = 0,
    /// A ceiling that stopped it.
    TS_CONTACT_CEILING = 1,
    /// A wall on its left (lower x): the normal points right.
    TS_CONTACT_LEFT = 2,
    /// A wall on its right: the normal points left.
    TS_CONTACT_RIGHT = 3,
    /// A moving platform that pressed it into the world.
    TS_CONTACT_CRUSH = 4,
}

/// One surface a character touched in its last move.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ts_character_contact {
    /// Which surface.
    pub side: ts_contact_side,
    /// The surface's unit normal, pointing towards the character, x.
    pub nx: f32,
    /// The normal, y.
    pub ny: f32,
    /// The segment's flags (`TS_SEGMENT_ONE_WAY` for a platform).
    pub flags: u32,
    /// The tile's column (`TS_NONE` for a surface that is not a tile's).
    pub col: u32,
    /// The tile's row (`TS_NONE` likewise).
    pub row: u32,
    /// The tile's id (`TS_NONE` likewise).
    pub tile: u32,
}

/// The most contacts a character reports after a move: one of each side.
pub const TS_CHARACTER_MAX_CONTACTS: usize = 5;

fn controller_failure(e: &ControllerError) -> Failure {
    Failure::invalid(e.to_string())
}

/// # Safety
/// `character` is null or a live character.
unsafe fn character_mut<'a>(character: *mut ts_character) -> Result<&'a mut ts_character, Failure> {
    // SAFETY: null or a live character, as the caller promises.
    unsafe { character.as_mut() }.ok_or_else(|| Failure::null("character"))
}

/// # Safety
/// `character` is null or a live character.
unsafe fn character_ref<'a>(character: *const ts_character) -> Result<&'a ts_character, Failure> {
    // SAFETY: null or a live character, as the caller promises.
    unsafe { character.as_ref() }.ok_or_else(|| Failure::null("character"))
}

/// A character definition's defaults: at (0, 0), a box 0.5 wide and 0.8 tall, up -y, and
/// the core's `ControllerConfig` defaults (slopes to 50°, snap 0.3, skin 0.001, 4 slides,
/// no stepping up, blocked by solid and one-way segments).
#[unsafe(no_mangle)]
pub extern "C" fn ts_default_character_def() -> ts_character_def {
    let config = ControllerConfig::default();
    ts_character_def {
        x: 0.0,
        y: 0.0,
        shape: TS_SHAPE_RECT,
        half_width: 0.25,
        half_height: 0.4,
        radius: 0.4,
        up_x: 0.0,
        up_y: -1.0,
        max_slope_degrees: config.max_slope_degrees,
        snap_distance: config.snap_distance,
        skin: config.skin,
        max_slides: config.max_slides,
        step_height: config.step_height,
        mask: config.mask.0,
    }
}

/// The core character `def` describes.
fn character_of(def: &ts_character_def) -> Result<Character, Failure> {
    let shape = match def.shape {
        TS_SHAPE_RECT => CharacterShape::rect(Vec2::new(def.half_width, def.half_height)),
        TS_SHAPE_CIRCLE => CharacterShape::circle(def.radius),
        other => {
            return Err(Failure::invalid(format!(
                "def.shape is {other}: it must be TS_SHAPE_RECT ({TS_SHAPE_RECT}) or TS_SHAPE_CIRCLE ({TS_SHAPE_CIRCLE})"
            )));
        }
    }
    .map_err(|e| controller_failure(&e))?;
    let config = ControllerConfig {
        max_slope_degrees: def.max_slope_degrees,
        snap_distance: def.snap_distance,
        skin: def.skin,
        max_slides: def.max_slides,
        step_height: def.step_height,
        mask: SegmentFlags(def.mask),
    };
    let position = Vec2::new(def.x, def.y);
    let up = Vec2::new(def.up_x, def.up_y);
    Character::new(shape, position, up, config).map_err(|e| controller_failure(&e))
}

/// Makes a character as `def` says, standing still. On `TS_OK`, `*out` is the character,
/// for `ts_character_free`. A position or up that is not finite (or up zero), a size that is
/// not positive, an unknown shape and settings out of range are refused, named.
///
/// # Safety
/// `def` points to a definition; `out` points to a writable `ts_character*`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_character_create(
    def: *const ts_character_def,
    out: *mut *mut ts_character,
) -> ts_status {
    guarded("ts_character_create", || {
        // SAFETY: null or a definition, as the caller promises.
        let Some(def) = (unsafe { def.as_ref() }) else {
            return Err(Failure::null("def"));
        };
        if out.is_null() {
            return Err(Failure::null("out"));
        }
        let character = ts_character {
            character: character_of(def)?,
            velocity: Vec2::ZERO,
            drop_through: false,
            contacts: Contacts::default(),
        };
        // SAFETY: not null, writable as the caller promises.
        unsafe { give_boxed(out, character) };
        Ok(())
    })
}

/// Frees a character (null is ignored).
///
/// # Safety
/// `character` is null or a character from this library not yet freed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_character_free(character: *mut ts_character) {
    // SAFETY: null or from `ts_character_create`, freed once, as the caller promises.
    unsafe { free_boxed(character) };
}

/// Sets what the game asks of the character for the coming steps: its velocity (`vx`,
/// `vy`, map units per second, gravity and jumps included: those are the game's rules) and
/// whether it drops through one-way platforms (hold it until it is clear of one). Each
/// `ts_character_step` moves it by velocity × dt and keeps in the velocity what the
/// surfaces touched leave of it, so a game adds gravity to `ts_character_get_state`'s
/// velocity and sets it back.
///
/// # Safety
/// `character` is a live character.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_character_set_input(
    character: *mut ts_character,
    vx: f32,
    vy: f32,
    drop_through: bool,
) -> ts_status {
    guarded("ts_character_set_input", || {
        // SAFETY: as the caller promises.
        let c = unsafe { character_mut(character) }?;
        let velocity = Vec2::new(coordinate("vx", vx)?, coordinate("vy", vy)?);
        c.velocity = velocity;
        c.drop_through = drop_through;
        Ok(())
    })
}

/// One step of `dt` seconds (finite, not negative) through `map` and its temporary
/// segments: moves the character by its velocity × dt as far as the world lets it
/// (`Character::move_and_slide`), takes out of the velocity what the surfaces touched
/// stopped (landing zeroes the fall, a ceiling the rise, a wall the speed into it), and
/// keeps what it touched for `ts_character_contacts`. On a failure nothing changes.
///
/// # Safety
/// `character` is a live character, `map` a live map.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_character_step(
    character: *mut ts_character,
    map: *const ts_map,
    dt: f32,
) -> ts_status {
    guarded("ts_character_step", || {
        // SAFETY: as the caller promises.
        let c = unsafe { character_mut(character) }?;
        // SAFETY: as the caller promises.
        let map = unsafe { map_ref(map) }?;
        let options = MoveOptions {
            drop_through: c.drop_through,
        };
        let mut velocity = c.velocity;
        c.contacts = c
            .character
            .move_and_slide(map, &mut velocity, dt, options)
            .map_err(|e| controller_failure(&e))?;
        c.velocity = velocity;
        Ok(())
    })
}

/// Moves the character by (`dx`, `dy`) through `map` as far as the world lets it
/// (`Character::move_by`), for a game that makes its own displacements; its velocity is
/// left as it was. `drop_through` falls through one-way platforms during this move.
///
/// # Safety
/// `character` is a live character, `map` a live map.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_character_move_by(
    character: *mut ts_character,
    map: *const ts_map,
    dx: f32,
    dy: f32,
    drop_through: bool,
) -> ts_status {
    guarded("ts_character_move_by", || {
        // SAFETY: as the caller promises.
        let c = unsafe { character_mut(character) }?;
        // SAFETY: as the caller promises.
        let map = unsafe { map_ref(map) }?;
        let displacement = Vec2::new(coordinate("dx", dx)?, coordinate("dy", dy)?);
        c.contacts = c
            .character
            .move_by(map, displacement, MoveOptions { drop_through })
            .map_err(|e| controller_failure(&e))?;
        Ok(())
    })
}

/// Moves the character to (`x`, `y`) at once (a teleport: no sweep), forgetting its ground
/// and contacts; its velocity is left as it was.
///
/// # Safety
/// `character` is a live character.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_character_teleport(
    character: *mut ts_character,
    x: f32,
    y: f32,
) -> ts_status {
    guarded("ts_character_teleport", || {
        // SAFETY: as the caller promises.
        let c = unsafe { character_mut(character) }?;
        c.character
            .teleport(Vec2::new(x, y))
            .map_err(|e| controller_failure(&e))?;
        c.contacts = Contacts::default();
        Ok(())
    })
}

/// The character's position, velocity and whether it stands on ground, into `*out`.
///
/// # Safety
/// `character` is a live character; `out` points to a writable `ts_character_state`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_character_get_state(
    character: *const ts_character,
    out: *mut ts_character_state,
) -> ts_status {
    guarded("ts_character_get_state", || {
        // SAFETY: as the caller promises.
        let c = unsafe { character_ref(character) }?;
        if out.is_null() {
            return Err(Failure::null("out"));
        }
        let p = c.character.position;
        let state = ts_character_state {
            x: p.x,
            y: p.y,
            vx: c.velocity.x,
            vy: c.velocity.y,
            grounded: c.character.ground().is_some(),
        };
        // SAFETY: not null, writable as the caller promises.
        unsafe { out.write(state) };
        Ok(())
    })
}

fn contact_of(side: ts_contact_side, contact: &Contact) -> ts_character_contact {
    let (col, row, tile) = match contact.source {
        SegmentSource::Tile { segment, tile } => (segment.cell.col, segment.cell.row, tile.0),
        _ => (TS_NONE, TS_NONE, TS_NONE),
    };
    ts_character_contact {
        side,
        nx: contact.normal.x,
        ny: contact.normal.y,
        flags: contact.flags.0,
        col,
        row,
        tile,
    }
}

/// The surfaces the character touched in its last step or move, into `out` (room for
/// `capacity`; `TS_CHARACTER_MAX_CONTACTS` always suffices), ground first, then ceiling,
/// left, right and crush, each at most once; `*count` is how many. When they do not fit,
/// `TS_ERROR_BUFFER_TOO_SMALL` with only `*count` written.
///
/// # Safety
/// `character` is a live character; `out` has room for `capacity` contacts (or is null
/// when `capacity` is 0); `count` is writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ts_character_contacts(
    character: *const ts_character,
    out: *mut ts_character_contact,
    capacity: usize,
    count: *mut usize,
) -> ts_status {
    guarded("ts_character_contacts", || {
        // SAFETY: as the caller promises.
        let c = unsafe { character_ref(character) }?;
        let k = &c.contacts;
        let sides = [
            (ts_contact_side::TS_CONTACT_GROUND, k.ground),
            (ts_contact_side::TS_CONTACT_CEILING, k.ceiling),
            (ts_contact_side::TS_CONTACT_LEFT, k.left),
            (ts_contact_side::TS_CONTACT_RIGHT, k.right),
            (ts_contact_side::TS_CONTACT_CRUSH, k.crush),
        ];
        // The touched sides, first `n` of `touched`, without allocating.
        let mut touched = [None; TS_CHARACTER_MAX_CONTACTS];
        let mut n = 0;
        for (side, contact) in &sides {
            if let Some(contact) = contact {
                touched[n] = Some(contact_of(*side, contact));
                n += 1;
            }
        }
        let items = touched.into_iter().take(n).flatten();
        // SAFETY: as the caller promises.
        unsafe { fill(items, n, out, capacity, count, "contacts") }
    })
}
