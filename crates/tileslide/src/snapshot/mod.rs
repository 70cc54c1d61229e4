//! Snapshots: the state of a game's collision world saved at a step and restored later, so
//! that the restored run goes on bit for bit as the run that was never interrupted. What
//! rollback netcode (restore the last confirmed step, replay the inputs since) and replays
//! need.
//!
//! Three parts make up the state, each saved on its own:
//!
//! - the map: [`MapEdits`] ([`TileMap::edits`](crate::TileMap::edits),
//!   [`TileMap::restore_edits`](crate::TileMap::restore_edits)), the cells that differ
//!   from the level as loaded and the temporary segments. The level itself is the game's
//!   file; the edits are small, and restoring them is a few ordinary tile edits.
//! - [`Bodies`](crate::Bodies), with the `serde` feature: the settings, every slot with
//!   its generation and its body (position, shape, filter, owner, the moves proposed and
//!   resolved) and the free list, so later handles and steps are as they would have been.
//! - [`HitWorld`](crate::HitWorld), with the `serde` feature: its broadphase and "hit once
//!   per swing" memory.
//! - [`Character`](crate::Character), with the `serde` feature: its position, shape, up
//!   direction and settings, its ground and the platform it rides.
//!
//! What only makes a step cheaper (the resolver's candidate pairs, kept walls and settled
//! bodies, the map revision they were kept for) changes no result and is not saved: the
//! first step after a restore gathers it again. What is read is checked as the calls that
//! build the same state check it, and bad data is refused with a [`SnapshotError`] naming
//! what is wrong (a deserializer reports its message), never a panic or a half-restored
//! state.

mod error;
mod map_edits;

#[cfg(feature = "serde")]
mod bodies;
#[cfg(feature = "serde")]
mod character;
#[cfg(feature = "serde")]
mod hit_world;

pub use error::SnapshotError;
pub use map_edits::MapEdits;

/// Reads a `T` as the data `S` it is written as, then checks it (`T::try_from`): what
/// every snapshot's `Deserialize` does, the refusal reported as the deserializer's error.
#[cfg(feature = "serde")]
fn read_checked<'de, D, S, T>(deserializer: D) -> Result<T, D::Error>
where
    D: serde::Deserializer<'de>,
    S: serde::Deserialize<'de>,
    T: TryFrom<S, Error = SnapshotError>,
{
    use serde::de::Error as _;
    let data = S::deserialize(deserializer)?;
    T::try_from(data).map_err(D::Error::custom)
}
