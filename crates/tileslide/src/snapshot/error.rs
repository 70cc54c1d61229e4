//! Why saved state was refused.

use thiserror::Error;

use crate::bodies::BodyError;
use crate::controller::ControllerError;
use crate::tiles::{Cell, MapError, TemporaryError, TileId};

/// Why saved state (a [`Bodies`](crate::Bodies) set, a [`HitWorld`](crate::HitWorld)'s
/// memory, [`MapEdits`](crate::MapEdits)) was refused: read from bad data, or restored
/// onto another map. A deserializer reports it as its own error, with this message.
///
/// ```
/// # use tileslide::{Cell, SnapshotError};
/// let e = SnapshotError::EditOutsideMap { index: 2, cell: Cell::new(9, 1), width: 8, height: 5 };
/// assert_eq!(e.to_string(), "tile edit 2 names cell (9, 1), outside the 8×5 map");
/// ```
#[derive(Clone, Debug, PartialEq, Error)]
#[non_exhaustive]
pub enum SnapshotError {
    /// The resolve settings are out of range.
    #[error("resolve settings: {0}")]
    Config(BodyError),
    /// A body's shape, position, proposed or resolved move is refused (NaN, infinite,
    /// beyond [`MAX_COORD`](crate::limits::MAX_COORD), a shape without circles).
    #[error("the body in slot {slot}: {error}")]
    Body {
        /// The body's slot (its handle's index).
        slot: u32,
        /// What is wrong with it.
        error: BodyError,
    },
    /// More slots than a set of bodies can index.
    #[error("{slots} body slots, more than a set can index (at most {max})")]
    TooManySlots {
        /// Slots in the data.
        slots: usize,
        /// The most there can be.
        max: u32,
    },
    /// An empty slot of generation 0: a slot is emptied by a removal, which moves its
    /// generation on, so its handles' generations are wrong.
    #[error("slot {slot} is empty at generation 0, which no removal leaves")]
    EmptyAtGenerationZero {
        /// The slot.
        slot: u32,
    },
    /// The free list names a slot that is not there, holds a body, is retired (its
    /// generation spent), or is named twice.
    #[error("the free list's entry {index} names slot {slot}, which is {why}")]
    BadFreeSlot {
        /// The entry's position in the free list.
        index: usize,
        /// The slot it names.
        slot: u32,
        /// `"past the last slot"`, `"holding a body"`, `"retired"` or `"listed before"`.
        why: &'static str,
    },
    /// An empty slot, neither retired nor in the free list, that no later body could take.
    #[error("slot {slot} is empty but not in the free list")]
    LostSlot {
        /// The slot.
        slot: u32,
    },
    /// The character's position, shape, up direction or settings, refused as
    /// [`Character::new`](crate::Character::new) refuses them.
    #[error("the character: {0}")]
    Character(ControllerError),
    /// A vector of the character's state (its up direction, its ground's normal, the
    /// platform it rides) that no move could leave it with.
    #[error("the character's {what} ({x}, {y}) must be {must}")]
    CharacterValue {
        /// Which vector.
        what: &'static str,
        /// Its x.
        x: f32,
        /// Its y.
        y: f32,
        /// What it must be.
        must: &'static str,
    },
    /// A list that is kept sorted is out of order or repeats an entry.
    #[error("the {what} are out of order or repeated at entry {index}")]
    Unsorted {
        /// Which list.
        what: &'static str,
        /// The first entry not after the one before it.
        index: usize,
    },
    /// A kept hit event whose time is outside `[0, 1]` (or NaN) or whose point is not
    /// finite: no `detect` reports one.
    #[error(
        "hit event {index} at t = {t}, point ({x}, {y}): t must be in [0, 1] and the point finite"
    )]
    BadEvent {
        /// The event's position in the list.
        index: usize,
        /// Its time.
        t: f32,
        /// Its point's x.
        x: f32,
        /// Its point's y.
        y: f32,
    },
    /// A map size refused as [`TileMap::new`](crate::TileMap::new) refuses it, or an
    /// edit the map refused.
    #[error(transparent)]
    Map(#[from] MapError),
    /// A tile edit outside the map the edits are of.
    #[error("tile edit {index} names cell {cell}, outside the {width}×{height} map")]
    EditOutsideMap {
        /// The edit's position in the list.
        index: usize,
        /// Its cell.
        cell: Cell,
        /// The map's width.
        width: u32,
        /// The map's height.
        height: u32,
    },
    /// A temporary segment refused as [`TileMap::add_temporary`](crate::TileMap::add_temporary)
    /// refuses it.
    #[error("temporary segment {index}: {error}")]
    Temporary {
        /// Its position in the list.
        index: usize,
        /// What is wrong with it.
        error: TemporaryError,
    },
    /// A temporary segment whose normal is not of unit length (the map keeps normals
    /// normalised).
    #[error("temporary segment {index} has normal ({x}, {y}), not of unit length")]
    NotUnitNormal {
        /// Its position in the list.
        index: usize,
        /// The normal's x.
        x: f32,
        /// The normal's y.
        y: f32,
    },
    /// Edits of a map of another size.
    #[error("the edits are of a {width}×{height} map, and this map is {map_width}×{map_height}")]
    OtherMapSize {
        /// The edits' map width.
        width: u32,
        /// Their map height.
        height: u32,
        /// This map's width.
        map_width: u32,
        /// This map's height.
        map_height: u32,
    },
    /// Edits of another map (another level, or the same level built another way): the
    /// maps as built differ.
    #[error(
        "the edits are of another map: its base has checksum {edits:#010x}, this map's \
         {map:#010x}"
    )]
    OtherBase {
        /// The CRC-32 of the base the edits were made on.
        edits: u32,
        /// This map's.
        map: u32,
    },
    /// A tile edit that puts the tile the cell held when the map was built: the edits list
    /// only cells that differ from it.
    #[error("the edit of cell {cell} puts the tile the map was built with there, which is no edit")]
    NoChange {
        /// The cell.
        cell: Cell,
    },
    /// A tile edit with a tile the map's tile set lacks.
    #[error("the edit of cell {cell} puts tile {id}, which is not in the map's tile set")]
    UnknownTile {
        /// The cell.
        cell: Cell,
        /// The tile.
        id: TileId,
    },
}
