//! Settled bodies: a body that was blocked in place last step, and around which nothing
//! changed since, is blocked in place again, so it is not swept again.
//!
//! A body's resolved move is a function of what it sees: its position and proposed move,
//! the walls within its reach, the resolve settings, and the positions of the bodies
//! within its reach, as seen in slot order (a lower slot where it ended this step, a
//! higher one where it ended the last). So when all of that is unchanged, the move is
//! unchanged, bit for bit. The memory keeps each body's inputs and whether it stayed put,
//! and the other side of the argument is a *disturbed* flag: a body that moves flags every
//! body whose reach disc touches its own (its disc holds its whole path, start and end),
//! for this step when they are resolved after it and for the next one otherwise.
//!
//! In a jammed crowd (bodies pressed into corners and into each other, each re-trying a
//! blocked move every step with all its passes) this skips a third of the sweeps. The skip
//! changes nothing else: positions and the report are the same as without it, which a model
//! test checks against a resolver without memory.
//!
//! A map edit disturbs the bodies whose reach disc touches the region it changed (see
//! `map_watch`). Anything the memory cannot see invalidates it: adding or removing bodies
//! or changing a filter ([`Settled::forget`]), another map or a change the map's edit
//! journal cannot place, other settings, and any body not where the last resolve left it
//! (a teleport, a resolve not integrated).

use glam::Vec2;

use super::config::ResolveConfig;
use super::resolve::ResolveReport;

/// What one body's last resolve saw and gave.
#[derive(Clone, Copy, Debug)]
struct Memory {
    /// Where it started, and the move it proposed.
    start: Vec2,
    motion: Vec2,
    /// Where the resolve left it (`start` plus the resolved move).
    end: Vec2,
    /// Its contacts and whether it was cut short (for the report of a skipped body).
    contacts: u32,
    cut_short: bool,
    /// It was resolved (moving) and stayed where it was.
    stayed: bool,
}

const UNKNOWN: Memory = Memory {
    start: Vec2::NAN,
    motion: Vec2::NAN,
    end: Vec2::NAN,
    contacts: 0,
    cut_short: false,
    stayed: false,
};

/// The memory of the last resolve, per body in resolve order.
#[derive(Clone, Debug, Default)]
pub(crate) struct Settled {
    bodies: Vec<Memory>,
    /// Per body: something within its reach moved where it will see the change this step,
    /// and next step.
    disturbed: Vec<bool>,
    disturbed_next: Vec<bool>,
    config: Option<ResolveConfig>,
    /// Bodies skipped by the current (or last) resolve.
    skipped: usize,
}

impl Settled {
    /// Drops the memory (the bodies changed in a way positions do not show).
    pub fn forget(&mut self) {
        self.bodies.clear();
    }

    /// Starts a resolve of bodies at `positions`: keeps the memory if everything it cannot
    /// see per body is unchanged (the map is the same, or `map_kept`: changed only where
    /// the caller then [wakes](Self::wake) the bodies near), and every body is where the
    /// last resolve left it.
    pub fn begin(&mut self, positions: &[Vec2], map_kept: bool, config: &ResolveConfig) {
        let same = self.bodies.len() == positions.len()
            && map_kept
            && self.config.as_ref() == Some(config)
            // `==` on floats: a NaN never matches, so an unknown end never does either.
            && self.bodies.iter().zip(positions).all(|(m, &p)| m.end == p);
        if !same {
            self.bodies.clear();
            self.bodies.resize(positions.len(), UNKNOWN);
            self.disturbed_next.clear();
            self.disturbed_next.resize(positions.len(), false);
        }
        self.skipped = 0;
        self.config = Some(*config);
        std::mem::swap(&mut self.disturbed, &mut self.disturbed_next);
        self.disturbed_next.clear();
        self.disturbed_next.resize(positions.len(), false);
    }

    /// If body `b`, at `start` with move `motion`, is blocked in place again: adds what its
    /// last resolve counted to `report` and returns true.
    pub fn stays(
        &mut self,
        b: usize,
        start: Vec2,
        motion: Vec2,
        report: &mut ResolveReport,
    ) -> bool {
        let m = &self.bodies[b];
        let stays = m.stayed && !self.disturbed[b] && m.start == start && m.motion == motion;
        if stays {
            report.moving += 1;
            report.contacts += m.contacts as usize;
            report.cut_short += usize::from(m.cut_short);
            self.skipped += 1;
        }
        stays
    }

    /// Bodies the current (or last) resolve skipped.
    #[cfg(test)]
    pub fn skipped(&self) -> usize {
        self.skipped
    }

    /// Remembers body `b`'s resolve: from `start` by the proposed `motion` to `end`.
    pub fn remember(
        &mut self,
        b: usize,
        start: Vec2,
        motion: Vec2,
        end: Vec2,
        contacts: usize,
        cut_short: bool,
    ) {
        self.bodies[b] = Memory {
            start,
            motion,
            end,
            contacts: u32::try_from(contacts).unwrap_or(u32::MAX),
            cut_short,
            stayed: motion != Vec2::ZERO && end == start,
        };
    }

    /// Remembers that body `b` was not resolved (no proposed move): it stays at `at`.
    pub fn remember_still(&mut self, b: usize, at: Vec2) {
        self.bodies[b] = Memory { end: at, ..UNKNOWN };
    }

    /// Something within body `b`'s reach changed (the map, near it): it is resolved this
    /// step.
    pub fn wake(&mut self, b: usize) {
        self.disturbed[b] = true;
    }

    /// Body `mover` moved, and body `other`'s reach disc touches its own: `other` sees the change
    /// this step if it is resolved later, the next step otherwise.
    pub fn disturb(&mut self, mover: usize, other: usize) {
        // Both flags written, without a branch: which one is set is a coin toss (slot
        // order is random in space).
        self.disturbed[other] |= other > mover;
        self.disturbed_next[other] |= other <= mover;
    }
}

#[cfg(test)]
mod tests {
    use crate::io::ascii::{self, TEST_ROOM};
    use crate::{Bodies, BodyDesc, BodyShape, Cell, TileMap, Vec2};

    fn room() -> TileMap {
        ascii::parse(TEST_ROOM, "room.txt", 1.0).unwrap()
    }

    /// Steps with the same proposed moves; the number of bodies skipped by each.
    fn skips(bodies: &mut Bodies, map: &TileMap, moves: &[Vec2], steps: usize) -> Vec<usize> {
        let handles: Vec<_> = bodies.iter().map(|(h, _)| h).collect();
        (0..steps)
            .map(|_| {
                for (h, m) in handles.iter().zip(moves) {
                    bodies.propose(*h, *m).unwrap();
                }
                bodies.step(map);
                bodies.scratch.settled.skipped()
            })
            .collect()
    }

    #[test]
    fn a_body_pressed_into_a_corner_is_skipped_until_something_changes() {
        let mut map = room();
        let mut bodies = Bodies::new();
        let circle = BodyShape::circle(0.4).unwrap();
        let hero = bodies
            .add(BodyDesc::new(Vec2::new(6.2, 1.6), circle.clone()))
            .unwrap();
        let push = [Vec2::new(0.3, -0.3)];
        // Into the corner in a few steps, then blocked in place (resolved once more: it
        // stays, remembered), then skipped every step.
        let skipped = skips(&mut bodies, &map, &push, 6);
        assert_eq!(skipped[..2], [0, 0]);
        assert_eq!(skipped[3..], [1, 1, 1], "{skipped:?}");
        let corner = bodies.get(hero).unwrap().position();
        assert!(corner.x > 6.59 && corner.y < 1.41, "{corner}");
        // A map edit far away does not wake it (the region an edit changes is its cell
        // grown by two cells, here x < 5.25; the hero reaches x > 5.7) ...
        let wall = Some(ascii::tile_for_char('#').unwrap().unwrap());
        map.set_tile(Cell::new(2, 3), wall).unwrap();
        assert_eq!(skips(&mut bodies, &map, &push, 3), [1, 1, 1]);
        // ... one near it does.
        map.set_tile(Cell::new(5, 2), wall).unwrap();
        assert_eq!(skips(&mut bodies, &map, &push, 3), [0, 1, 1]);
        assert_eq!(bodies.get(hero).unwrap().position(), corner);
        // So does a body walking up to it (it is resolved first: a lower slot).
        bodies.remove(hero).unwrap();
        let walker = bodies
            .add(BodyDesc::new(Vec2::new(4.0, 1.6), circle.clone()))
            .unwrap();
        let hero = bodies.add(BodyDesc::new(corner, circle)).unwrap();
        let moves = [Vec2::new(0.5, 0.0), Vec2::new(0.3, -0.3)];
        let skipped = skips(&mut bodies, &map, &moves, 8);
        // Forgotten on add; the hero is skipped while the walker is far, woken while it
        // closes in, and both settle in the end.
        assert_eq!(skipped[..3], [0, 1, 0], "{skipped:?}");
        assert_eq!(*skipped.last().unwrap(), 2, "{skipped:?}");
        assert_eq!(bodies.get(hero).unwrap().position(), corner);
        assert!(bodies.get(walker).unwrap().position().distance(corner) >= 0.8);
    }
}
