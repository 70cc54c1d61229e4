//! A [`HitWorld`]'s memory between frames saved and restored with serde: its broadphase,
//! the swings registered in the last frame and which victims each swing has hit, so "hit
//! once per swing" goes on as it would have, and the last `detect`'s events, which stay
//! readable until the next one.
//!
//! The objects registered for a frame are not saved: the game registers its objects again
//! every frame. Save the world between frames (after [`detect`](HitWorld::detect), or
//! after [`begin_frame`](HitWorld::begin_frame)); a restored world holds no objects until
//! the game registers them, and the events it was saved with. The memory is written
//! sorted, so equal worlds give equal bytes.

use serde::{Deserialize, Deserializer, Serialize, Serializer};

use super::{SnapshotError, read_checked};
use crate::broadphase::PairMethod;
use crate::owner::Owner;
use crate::volumes::{HitEvent, HitWorld};

/// A world's memory as it is written and read.
#[derive(Serialize, Deserialize)]
struct HitWorldData {
    broadphase: PairMethod,
    /// The swings registered in the frame, sorted.
    swings: Vec<u64>,
    /// The victims each swing has hit, by swing then victim, sorted.
    swung: Vec<(u64, Owner)>,
    /// The last `detect`'s events, in its order.
    events: Vec<HitEvent>,
}

/// Written with the `serde` feature: the memory that decides later frames' hits (the
/// broadphase and the swing memory, sorted) and the last `detect`'s events. This frame's
/// objects are not written.
impl Serialize for HitWorld {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut swings: Vec<u64> = self.swings_now.iter().copied().collect();
        swings.sort_unstable();
        let mut swung: Vec<(u64, Owner)> = self.swung.iter().copied().collect();
        swung.sort_unstable();
        HitWorldData {
            broadphase: self.broadphase,
            swings,
            swung,
            events: self.events.clone(),
        }
        .serialize(serializer)
    }
}

/// Read with the `serde` feature, and checked: the lists sorted and without repeats, each
/// event's `t` in `[0, 1]` and its point finite (a [`SnapshotError`] message otherwise).
impl<'de> Deserialize<'de> for HitWorld {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        read_checked::<D, HitWorldData, Self>(deserializer)
    }
}

impl TryFrom<HitWorldData> for HitWorld {
    type Error = SnapshotError;

    fn try_from(data: HitWorldData) -> Result<Self, SnapshotError> {
        strictly_increasing("swings", &data.swings)?;
        strictly_increasing("swing hits", &data.swung)?;
        for (index, event) in data.events.iter().enumerate() {
            if !(0.0..=1.0).contains(&event.t) || !event.point.is_finite() {
                return Err(SnapshotError::BadEvent {
                    index,
                    t: event.t,
                    x: event.point.x,
                    y: event.point.y,
                });
            }
        }
        // Everything else (this frame's objects, buffers) as in a new world.
        let mut world = HitWorld::with_broadphase(data.broadphase);
        world.swings_now = data.swings.into_iter().collect();
        world.swung = data.swung.into_iter().collect();
        world.events = data.events;
        Ok(world)
    }
}

/// `Ok` when every entry of `list` is after the one before it.
fn strictly_increasing<T: Ord>(what: &'static str, list: &[T]) -> Result<(), SnapshotError> {
    match list.windows(2).position(|w| w[0] >= w[1]) {
        Some(k) => Err(SnapshotError::Unsorted { what, index: k + 1 }),
        None => Ok(()),
    }
}
