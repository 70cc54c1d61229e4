//! [`Bodies`] saved and restored with serde: the settings, every slot (its generation and
//! its body with the moves proposed and resolved) and the free list, so handles, the slots
//! later bodies take and every later step are as they would have been.
//!
//! The resolver's memories (candidate pairs, walls near each circle, settled bodies, the
//! map revision they were kept for) are not saved: none of them changes a result, and the
//! first resolve after a restore gathers them again, as the first resolve of any set does.
//! Neither is anything a resolve only reports on (a trace).

use glam::Vec2;
use serde::ser::SerializeSeq;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

use super::{SnapshotError, read_checked};
use crate::bodies::set::Slot;
use crate::bodies::{Bodies, Body, BodyError, BodyFilter, BodyShape, ResolveConfig};
use crate::geometry::{Circle, in_range};
use crate::owner::Owner;

/// A set as it is written: borrowed.
#[derive(Serialize)]
struct BodiesOut<'a> {
    config: &'a ResolveConfig,
    slots: SlotsOut<'a>,
    free: &'a [u32],
}

/// The slots, written one by one.
struct SlotsOut<'a>(&'a [Slot]);

#[derive(Serialize)]
struct SlotOut<'a> {
    generation: u32,
    body: Option<BodyOut<'a>>,
}

#[derive(Serialize)]
struct BodyOut<'a> {
    position: Vec2,
    shape: &'a [Circle],
    filter: BodyFilter,
    owner: Owner,
    proposed: Vec2,
    resolved: Vec2,
}

/// A set as it is read, before it is checked: the same fields, owned.
#[derive(Deserialize)]
struct BodiesIn {
    config: ResolveConfig,
    slots: Vec<SlotIn>,
    free: Vec<u32>,
}

#[derive(Deserialize)]
struct SlotIn {
    generation: u32,
    body: Option<BodyIn>,
}

#[derive(Deserialize)]
struct BodyIn {
    position: Vec2,
    /// Read as circles, so a bad shape is reported with its slot.
    shape: Vec<Circle>,
    filter: BodyFilter,
    owner: Owner,
    proposed: Vec2,
    resolved: Vec2,
}

impl Serialize for SlotsOut<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut seq = serializer.serialize_seq(Some(self.0.len()))?;
        for slot in self.0 {
            seq.serialize_element(&SlotOut {
                generation: slot.generation,
                body: slot.body.as_ref().map(|b| BodyOut {
                    position: b.position,
                    shape: b.shape.circles(),
                    filter: b.filter,
                    owner: b.owner,
                    proposed: b.proposed,
                    resolved: b.resolved,
                }),
            })?;
        }
        seq.end()
    }
}

/// Written with the `serde` feature: everything that decides the set's later steps, so a set
/// read back goes on bit for bit as this one (the settings, every slot with its generation
/// and body, the free list). The resolver's memories are not written; the first resolve
/// after reading the set gathers them again.
impl Serialize for Bodies {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        BodiesOut {
            config: &self.config,
            slots: SlotsOut(&self.slots),
            free: &self.free,
        }
        .serialize(serializer)
    }
}

/// Read with the `serde` feature, and checked: what is refused is named in the error (a
/// [`SnapshotError`] message), never a panic or a set in a state no calls could leave it.
impl<'de> Deserialize<'de> for Bodies {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        read_checked::<D, BodiesIn, Self>(deserializer)
    }
}

impl TryFrom<BodiesIn> for Bodies {
    type Error = SnapshotError;

    fn try_from(data: BodiesIn) -> Result<Self, SnapshotError> {
        data.config.validate().map_err(SnapshotError::Config)?;
        // A set hands out slot indices below u32::MAX (see `Bodies::add`).
        if data.slots.len() > u32::MAX as usize {
            return Err(SnapshotError::TooManySlots {
                slots: data.slots.len(),
                max: u32::MAX,
            });
        }
        let mut slots = Vec::with_capacity(data.slots.len());
        for (index, s) in data.slots.into_iter().enumerate() {
            // (Fewer than u32::MAX slots.)
            let slot = index as u32;
            let body = match s.body {
                Some(b) => Some(body(b).map_err(|error| SnapshotError::Body { slot, error })?),
                None if s.generation == 0 => {
                    return Err(SnapshotError::EmptyAtGenerationZero { slot });
                }
                None => None,
            };
            slots.push(Slot {
                generation: s.generation,
                body,
            });
        }
        // The free list: exactly the empty slots that are not retired, each once.
        let mut listed = vec![false; slots.len()];
        for (index, &slot) in data.free.iter().enumerate() {
            let bad = |why| SnapshotError::BadFreeSlot { index, slot, why };
            let s = slots.get(slot as usize).ok_or(bad("past the last slot"))?;
            if s.body.is_some() {
                return Err(bad("holding a body"));
            }
            if s.generation == u32::MAX {
                return Err(bad("retired"));
            }
            if std::mem::replace(&mut listed[slot as usize], true) {
                return Err(bad("listed before"));
            }
        }
        let lost = slots
            .iter()
            .zip(&listed)
            .position(|(s, &listed)| s.body.is_none() && s.generation < u32::MAX && !listed);
        if let Some(slot) = lost {
            return Err(SnapshotError::LostSlot { slot: slot as u32 });
        }
        // Everything else (the resolver and its memories) as in a new set.
        let mut bodies = Bodies::default();
        bodies.len = slots.iter().filter(|s| s.body.is_some()).count();
        bodies.slots = slots;
        bodies.free = data.free;
        bodies.config = data.config;
        Ok(bodies)
    }
}

/// A body read back, checked as [`Bodies::add`] and [`Bodies::propose`] check one: its
/// shape, its position, and its proposed and resolved moves, finite and ending within
/// [`MAX_COORD`](crate::limits::MAX_COORD).
fn body(b: BodyIn) -> Result<Body, BodyError> {
    let shape = BodyShape::compound(b.shape)?;
    for (what, value) in [
        ("position", b.position),
        ("proposed move", b.proposed),
        ("resolved move", b.resolved),
    ] {
        if !value.is_finite() {
            return Err(BodyError::NonFinite { what, value });
        }
    }
    for (what, value) in [
        ("position", b.position),
        ("proposed move's end point", b.position + b.proposed),
        ("resolved move's end point", b.position + b.resolved),
    ] {
        if !in_range(value) {
            return Err(BodyError::OutOfRange { what, value });
        }
    }
    Ok(Body {
        position: b.position,
        shape,
        filter: b.filter,
        owner: b.owner,
        proposed: b.proposed,
        resolved: b.resolved,
    })
}
