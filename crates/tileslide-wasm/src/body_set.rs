//! The bodies as JavaScript holds them, in plain Rust: the core's [`Bodies`] behind handle
//! numbers, batch proposals, and positions packed two floats a body. Tested natively;
//! [`crate::bodies`] only converts values.

use tileslide::{Bodies, BodyDesc, BodyHandle, ResolveConfig, ResolveReport, TileMap, Vec2};

use crate::handles::Handles;

/// [`Bodies`] with JavaScript handle numbers and a buffer of packed positions.
#[derive(Debug, Default)]
pub struct BodySet {
    /// The core's bodies.
    pub bodies: Bodies,
    handles: Handles<BodyHandle>,
    /// The handle number of the body in each core slot (by [`BodyHandle::index`]).
    numbers: Vec<f64>,
    /// `x, y` of every body, in slot order: refilled by [`positions`](Self::positions).
    packed: Vec<f32>,
    /// The last step's trace while steps are traced (`explain` feature).
    #[cfg(feature = "explain")]
    pub(crate) trace: Option<tileslide::ResolveTrace>,
}

impl BodySet {
    /// No bodies, with `config`.
    ///
    /// # Errors
    /// The core's error for a field out of its range.
    pub fn new(config: ResolveConfig) -> Result<Self, String> {
        Ok(Self {
            bodies: Bodies::with_config(config).map_err(|e| e.to_string())?,
            ..Self::default()
        })
    }

    /// Adds a body and returns its handle number.
    ///
    /// # Errors
    /// The core's error for a position it refuses.
    pub fn add(&mut self, desc: BodyDesc) -> Result<f64, String> {
        let core = self.bodies.add(desc).map_err(|e| e.to_string())?;
        let number = match self.handles.insert(core) {
            Ok(number) => number,
            Err(e) => {
                // Keep the two tables in step: the body the table could not name goes.
                let _ = self.bodies.remove(core);
                return Err(e);
            }
        };
        let slot = core.index() as usize;
        if self.numbers.len() <= slot {
            self.numbers.resize(slot + 1, f64::NAN);
        }
        self.numbers[slot] = number;
        Ok(number)
    }

    /// Resolves the proposed moves (traced while the `explain` feature's tracing is on).
    pub fn resolve(&mut self, map: &TileMap) -> ResolveReport {
        #[cfg(feature = "explain")]
        if let Some(trace) = &mut self.trace {
            return self.bodies.resolve_traced(map, trace);
        }
        self.bodies.resolve(map)
    }

    /// [`resolve`](Self::resolve) then the core's `integrate`: one whole step.
    pub fn step(&mut self, map: &TileMap) -> ResolveReport {
        let report = self.resolve(map);
        self.bodies.integrate();
        report
    }

    /// The handle number of the core's `handle`, if it names a body of the set.
    #[must_use]
    pub fn number_of(&self, handle: BodyHandle) -> Option<f64> {
        let number = *self.numbers.get(handle.index() as usize)?;
        (self.core(number).ok() == Some(handle)).then_some(number)
    }

    /// The core's handle for `handle`.
    ///
    /// # Errors
    /// A stale or unknown handle, named.
    pub fn core(&self, handle: f64) -> Result<BodyHandle, String> {
        self.handles.get("body", handle)
    }

    /// Removes `handle`'s body; the handle is stale from now on.
    ///
    /// # Errors
    /// A stale or unknown handle, named.
    pub fn remove(&mut self, handle: f64) -> Result<(), String> {
        let core = self.handles.remove("body", handle)?;
        self.bodies.remove(core).map_err(|e| e.to_string())?;
        Ok(())
    }

    /// Proposes `motion` for `handle`'s body ([`Bodies::propose`]).
    ///
    /// # Errors
    /// A stale handle, a non-finite move or one that ends beyond the coordinate range.
    pub fn propose(&mut self, handle: f64, motion: Vec2) -> Result<(), String> {
        let core = self.core(handle)?;
        self.bodies
            .propose(core, motion)
            .map_err(|e| format!("propose: {e}"))
    }

    /// Proposes `moves[2i], moves[2i + 1]` for `handles[i]`, in order.
    ///
    /// # Errors
    /// Mismatched lengths (nothing is proposed), or the first entry [`propose`](Self::propose)
    /// refuses, named by its index; the entries before it are proposed.
    pub fn propose_many(&mut self, handles: &[f64], moves: &[f32]) -> Result<(), String> {
        if moves.len() != 2 * handles.len() {
            return Err(format!(
                "proposeMany: {} handles need {} move floats (dx, dy each), not {}",
                handles.len(),
                2 * handles.len(),
                moves.len()
            ));
        }
        for (i, (&h, m)) in handles.iter().zip(moves.chunks_exact(2)).enumerate() {
            let core = self
                .core(h)
                .map_err(|e| format!("proposeMany: entry {i}: {e}"))?;
            self.bodies
                .propose(core, Vec2::new(m[0], m[1]))
                .map_err(|e| format!("proposeMany: entry {i}: {e}"))?;
        }
        Ok(())
    }

    /// `x, y` of every body, in slot order (the order of [`handles`](Self::handles) and of
    /// the resolve), in a buffer kept between calls.
    pub fn positions(&mut self) -> &[f32] {
        self.packed.clear();
        for (_, body) in self.bodies.iter() {
            let p = body.position();
            self.packed.extend_from_slice(&[p.x, p.y]);
        }
        &self.packed
    }

    /// The handle number of every body, in slot order.
    #[must_use]
    pub fn handles(&self) -> Vec<f64> {
        self.bodies
            .iter()
            .map(|(h, _)| {
                self.numbers
                    .get(h.index() as usize)
                    .copied()
                    .unwrap_or(f64::NAN)
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;
    use tileslide::BodyShape;

    fn desc(x: f32) -> BodyDesc {
        BodyDesc::new(Vec2::new(x, 1.5), BodyShape::circle(0.25).unwrap())
    }

    #[test]
    fn handles_and_positions_follow_slot_order_through_removals() {
        let mut set = BodySet::default();
        let a = set.add(desc(1.5)).unwrap();
        let b = set.add(desc(2.5)).unwrap();
        let c = set.add(desc(3.5)).unwrap();
        set.remove(b).unwrap();
        assert_eq!(set.handles(), vec![a, c]);
        assert_eq!(set.positions(), &[1.5, 1.5, 3.5, 1.5]);
        let d = set.add(desc(4.5)).unwrap();
        assert_ne!(d, b, "a reused slot gets a new handle number");
        assert_eq!(set.handles(), vec![a, d, c]);
        assert_eq!(set.positions(), &[1.5, 1.5, 4.5, 1.5, 3.5, 1.5]);
        assert!(
            set.propose(b, Vec2::X)
                .unwrap_err()
                .contains("stale body handle")
        );
        assert!(set.remove(b).is_err());
    }

    #[test]
    fn propose_many_names_the_bad_entry() {
        let mut set = BodySet::default();
        let a = set.add(desc(1.5)).unwrap();
        let e = set.propose_many(&[a], &[1.0]).unwrap_err();
        assert!(e.contains("2 move floats"), "{e}");
        let e = set
            .propose_many(&[a, a], &[0.5, 0.0, f32::NAN, 0.0])
            .unwrap_err();
        assert!(e.contains("entry 1") && e.contains("not finite"), "{e}");
        let core = set.core(a).unwrap();
        assert_eq!(
            set.bodies.get(core).unwrap().proposed_move(),
            Vec2::new(0.5, 0.0)
        );
        let e = set.propose_many(&[7.0], &[0.0, 0.0]).unwrap_err();
        assert!(e.contains("entry 0") && e.contains("stale"), "{e}");
    }
}
