//! Handles as JavaScript numbers: a generational table from exact JavaScript integers to
//! the core's handles, so that a removed or made-up handle is an error and never another
//! object's.
//!
//! A JavaScript number holds integers exactly up to 2⁵³, too few bits for the core's
//! 32-bit slot and 32-bit generation together. The table keeps its own slots: a handle is
//! `generation · 2³² + slot`, with generations below 2²¹. A slot whose generation would
//! reach that is retired, never reused, so no number ever names two objects.

/// Generations a slot lives through before it is retired.
const GENERATIONS: u32 = 1 << 21;

/// The span of one generation in a handle number.
const SLOT_SPAN: f64 = 4_294_967_296.0;

#[derive(Clone, Debug)]
struct Slot<T> {
    generation: u32,
    value: Option<T>,
}

/// Values of type `T` (the core's handles) behind JavaScript numbers.
#[derive(Clone, Debug)]
pub struct Handles<T> {
    slots: Vec<Slot<T>>,
    free: Vec<u32>,
}

impl<T> Default for Handles<T> {
    fn default() -> Self {
        Self {
            slots: Vec::new(),
            free: Vec::new(),
        }
    }
}

impl<T: Copy> Handles<T> {
    /// Stores `value` and returns its handle number.
    ///
    /// # Errors
    /// Every one of the 2³² slots is in use or retired.
    pub fn insert(&mut self, value: T) -> Result<f64, String> {
        let index = match self.free.pop() {
            Some(index) => index,
            None => {
                let index = u32::try_from(self.slots.len())
                    .map_err(|_| "too many handles (at most 2^32)".to_string())?;
                self.slots.push(Slot {
                    generation: 0,
                    value: None,
                });
                index
            }
        };
        let Some(slot) = self.slots.get_mut(index as usize) else {
            return Err(format!("handle slot {index} is missing"));
        };
        slot.value = Some(value);
        Ok(f64::from(slot.generation) * SLOT_SPAN + f64::from(index))
    }

    /// The value of `handle`.
    ///
    /// # Errors
    /// A number that is not a handle this table gave, or whose value was removed: the
    /// message names it (`what` is the kind of handle, "body").
    pub fn get(&self, what: &str, handle: f64) -> Result<T, String> {
        let (index, generation) = decode(what, handle)?;
        self.slots
            .get(index as usize)
            .filter(|s| s.generation == generation)
            .and_then(|s| s.value)
            .ok_or_else(|| stale(what, handle))
    }

    /// Removes `handle`'s value and returns it; the handle is stale from now on.
    ///
    /// # Errors
    /// As [`get`](Self::get).
    pub fn remove(&mut self, what: &str, handle: f64) -> Result<T, String> {
        let (index, generation) = decode(what, handle)?;
        let slot = self
            .slots
            .get_mut(index as usize)
            .filter(|s| s.generation == generation && s.value.is_some())
            .ok_or_else(|| stale(what, handle))?;
        let value = slot.value.take().ok_or_else(|| stale(what, handle))?;
        slot.generation += 1;
        if slot.generation < GENERATIONS {
            self.free.push(index);
        }
        Ok(value)
    }

    /// Forgets every value; every handle given so far is stale from now on.
    pub fn clear(&mut self) {
        for (index, slot) in self.slots.iter_mut().enumerate() {
            if slot.value.take().is_some() {
                slot.generation += 1;
                if slot.generation < GENERATIONS {
                    self.free.push(index as u32);
                }
            }
        }
    }
}

/// The slot and generation `handle` names, or an error when it is not a handle number.
fn decode(what: &str, handle: f64) -> Result<(u32, u32), String> {
    let limit = f64::from(GENERATIONS) * SLOT_SPAN;
    if !(handle.fract() == 0.0 && (0.0..limit).contains(&handle)) {
        return Err(format!(
            "{handle} is not a {what} handle (a whole number given by the add call)"
        ));
    }
    let generation = (handle / SLOT_SPAN).floor();
    let index = handle - generation * SLOT_SPAN;
    Ok((index as u32, generation as u32))
}

fn stale(what: &str, handle: f64) -> String {
    format!(
        "stale {what} handle {handle}: the {what} was removed, or the handle is not one of this set's"
    )
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;

    #[test]
    fn a_removed_handle_stays_stale_after_its_slot_is_reused() {
        let mut table = Handles::default();
        let a = table.insert('a').unwrap();
        let b = table.insert('b').unwrap();
        assert_eq!(table.get("body", a), Ok('a'));
        assert_eq!(table.remove("body", a), Ok('a'));
        assert!(
            table
                .get("body", a)
                .unwrap_err()
                .contains("stale body handle")
        );
        assert!(table.remove("body", a).is_err());
        let c = table.insert('c').unwrap();
        assert_ne!(c, a);
        assert_eq!(c % SLOT_SPAN, a % SLOT_SPAN, "the slot is reused");
        assert!(table.get("body", a).is_err());
        assert_eq!(table.get("body", c), Ok('c'));
        assert_eq!(table.get("body", b), Ok('b'));
        for bad in [f64::NAN, -1.0, 0.5, f64::INFINITY, 1e300] {
            assert!(
                table
                    .get("body", bad)
                    .unwrap_err()
                    .contains("not a body handle")
            );
        }
        table.clear();
        assert!(table.get("body", b).is_err() && table.get("body", c).is_err());
    }

    #[test]
    fn a_slot_is_retired_before_its_generation_leaves_the_exact_integers() {
        let mut table = Handles::default();
        let mut last = 0.0;
        for _ in 0..GENERATIONS {
            last = table.insert(1u8).unwrap();
            table.remove("body", last).unwrap();
        }
        assert!(last <= crate::args::MAX_SAFE_INTEGER);
        // The slot is retired: the next value gets a new one.
        let next = table.insert(2u8).unwrap();
        assert_eq!(next, 1.0);
    }
}
