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

use super::config::{ResolveConfig, ResolveReport};

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

impl Memory {
    /// A resolve from `start` by `motion` to `end`, with its contacts.
    fn of(start: Vec2, motion: Vec2, end: Vec2, contacts: usize, cut_short: bool) -> Self {
        Self {
            start,
            motion,
            end,
            contacts: u32::try_from(contacts).unwrap_or(u32::MAX),
            cut_short,
            stayed: motion != Vec2::ZERO && end == start,
        }
    }
}

const UNKNOWN: Memory = Memory {
    start: Vec2::NAN,
    motion: Vec2::NAN,
    end: Vec2::NAN,
    contacts: 0,
    cut_short: false,
    stayed: false,
};

/// A body's flag: disturbed, it is resolved this step.
const NOW: u8 = 1;
/// A body's flag: disturbed, it is resolved next step.
const NEXT: u8 = 2;

/// The memory of the last resolve, per body in resolve order.
#[derive(Clone, Debug, Default)]
pub(super) struct Settled {
    bodies: Vec<Memory>,
    /// Per body: something within its reach moved where it will see the change this step
    /// ([`NOW`]), or next step ([`NEXT`]). Both in one byte: a body that moves sets one of
    /// its neighbours' flags, and they lie anywhere in memory.
    disturbed: Vec<u8>,
    config: Option<ResolveConfig>,
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
        self.config = Some(*config);
        if !same {
            self.bodies.clear();
            self.bodies.resize(positions.len(), UNKNOWN);
            self.disturbed.clear();
            self.disturbed.resize(positions.len(), 0);
            return;
        }
        // Last step's flags for the next step are this step's.
        for flags in &mut self.disturbed {
            *flags >>= 1;
        }
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
        let kept = self.kept(b, start, motion);
        if let Some((contacts, cut_short)) = kept {
            report.moving += 1;
            report.contact_count += contacts;
            report.cut_short += usize::from(cut_short);
        }
        kept.is_some()
    }

    /// Asks the processor to bring body `b`'s memory into its caches (see
    /// [`prefetch`](crate::prefetch)).
    #[cfg(feature = "parallel")]
    pub fn prefetch(&self, b: usize) {
        crate::prefetch::prefetch(&self.bodies, b);
        crate::prefetch::prefetch(&self.disturbed, b);
    }

    /// Asks the processor to bring body `b`'s disturbed flags into its caches: a body that
    /// moves sets its neighbours' flags.
    pub fn prefetch_flags(&self, b: usize) {
        crate::prefetch::prefetch(&self.disturbed, b);
    }

    /// Whether body `b` stays as [`stays`](Self::stays) tells, without counting it: if so,
    /// its last resolve's contacts and whether it was cut short.
    pub fn kept(&self, b: usize, start: Vec2, motion: Vec2) -> Option<(usize, bool)> {
        let m = &self.bodies[b];
        let stays =
            m.stayed && self.disturbed[b] & NOW == 0 && m.start == start && m.motion == motion;
        stays.then_some((m.contacts as usize, m.cut_short))
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
        self.bodies[b] = Memory::of(start, motion, end, contacts, cut_short);
    }

    /// [`remember`](Self::remember) for every body `b` for which `each(b, &mut items[b])`
    /// gives what its resolve saw and gave (`(start, motion, end, contacts, cut_short)`),
    /// and flags for the next step each body that stayed for which `disturbed_next(b)` holds
    /// (the others are resolved next step whatever their flag); on the threads of the
    /// current rayon pool, each body's entries (and item, which `each` may write) taken by
    /// one task.
    #[cfg(feature = "parallel")]
    pub fn remember_each<T: Send>(
        &mut self,
        items: &mut [T],
        each: impl Fn(usize, &mut T) -> Option<(Vec2, Vec2, Vec2, usize, bool)> + Sync,
        disturbed_next: impl Fn(usize) -> bool + Sync,
    ) {
        use rayon::prelude::*;
        self.bodies
            .par_iter_mut()
            .zip(self.disturbed.par_iter_mut())
            .zip(items.par_iter_mut())
            .enumerate()
            .with_min_len(1024)
            .for_each(|(b, ((memory, flags), item))| {
                if let Some((start, motion, end, contacts, cut_short)) = each(b, item) {
                    *memory = Memory::of(start, motion, end, contacts, cut_short);
                }
                if memory.stayed && *flags & NEXT == 0 && disturbed_next(b) {
                    *flags |= NEXT;
                }
            });
    }

    /// Remembers that body `b` was not resolved (no proposed move): it stays at `at`.
    pub fn remember_still(&mut self, b: usize, at: Vec2) {
        self.bodies[b] = Memory { end: at, ..UNKNOWN };
    }

    /// Something within body `b`'s reach changed (the map, near it): it is resolved this
    /// step.
    pub fn wake(&mut self, b: usize) {
        self.disturbed[b] |= NOW;
    }

    /// Body `mover` moved, and body `other`'s reach disc touches its own: `other` sees the change
    /// this step if it is resolved later, the next step otherwise.
    pub fn disturb(&mut self, mover: usize, other: usize) {
        // A select rather than a branch: which flag is set is a coin toss (slot order is
        // random in space).
        self.disturbed[other] |= if other > mover { NOW } else { NEXT };
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two bodies blocked in place by the last resolve, which saw `config`, an unchanged
    /// map and `positions`; begins the next resolve.
    fn blocked(config: &ResolveConfig, positions: &[Vec2], motion: Vec2) -> Settled {
        let mut settled = Settled::default();
        settled.begin(positions, true, config);
        for (b, &p) in positions.iter().enumerate() {
            settled.remember(b, p, motion, p, 2, b == 1);
        }
        settled.begin(positions, true, config);
        settled
    }

    #[test]
    fn a_body_blocked_in_place_is_skipped_only_while_nothing_it_saw_changed() {
        let config = ResolveConfig::default();
        let positions = [Vec2::new(1.5, 1.5), Vec2::new(3.5, 1.5)];
        let push = Vec2::new(0.5, 0.0);
        let mut report = ResolveReport::default();
        // The same inputs: both skipped, counted as the last resolve counted them.
        let mut settled = blocked(&config, &positions, push);
        assert!(settled.stays(0, positions[0], push, &mut report));
        assert!(settled.stays(1, positions[1], push, &mut report));
        let counted = ResolveReport {
            moving: 2,
            contact_count: 4,
            cut_short: 1,
        };
        assert_eq!(report, counted);
        // Another move or another start: resolved.
        assert!(!settled.stays(0, positions[0], -push, &mut report));
        assert!(!settled.stays(0, positions[1], push, &mut report));
        assert_eq!(report, counted);
        // A body that moved is never skipped, nor one that had no move.
        let mut settled = blocked(&config, &positions, push);
        settled.remember(0, positions[0], push, positions[0] + push, 0, false);
        settled.remember_still(1, positions[1]);
        settled.begin(&[positions[0] + push, positions[1]], true, &config);
        assert!(!settled.stays(0, positions[0] + push, push, &mut report));
        assert!(!settled.stays(1, positions[1], push, &mut report));
        // What the memory cannot see per body forgets it all: the map changed in a way the
        // caller cannot wake bodies for, other settings, a body not where it was left.
        let moved = [positions[0], positions[1] + push];
        let other = ResolveConfig {
            passes: 3,
            ..config
        };
        for (map_kept, now, at) in [
            (false, &config, &positions),
            (true, &other, &positions),
            (true, &config, &moved),
        ] {
            let mut settled = blocked(&config, &positions, push);
            settled.begin(at, map_kept, now);
            assert!(!settled.stays(0, positions[0], push, &mut report));
        }
    }

    #[test]
    fn a_woken_or_disturbed_body_is_resolved_when_it_can_see_the_change() {
        let config = ResolveConfig::default();
        let positions = [Vec2::new(1.5, 1.5), Vec2::new(3.5, 1.5)];
        let push = Vec2::new(0.5, 0.0);
        let mut report = ResolveReport::default();
        let stays = |settled: &mut Settled, b: usize, report: &mut ResolveReport| {
            settled.stays(b, positions[b], push, report)
        };
        // Woken by a map edit near it: resolved this step, skipped the next.
        let mut settled = blocked(&config, &positions, push);
        settled.wake(0);
        assert!(!stays(&mut settled, 0, &mut report));
        assert!(stays(&mut settled, 1, &mut report));
        settled.begin(&positions, true, &config);
        assert!(stays(&mut settled, 0, &mut report));
        // Body 0 moves next to body 1, which is resolved later: body 1 sees it this step.
        let mut settled = blocked(&config, &positions, push);
        settled.disturb(0, 1);
        assert!(!stays(&mut settled, 1, &mut report));
        settled.begin(&positions, true, &config);
        assert!(stays(&mut settled, 1, &mut report));
        // Body 1 moves next to body 0, already resolved: body 0 sees it next step.
        let mut settled = blocked(&config, &positions, push);
        settled.disturb(1, 0);
        assert!(stays(&mut settled, 0, &mut report));
        settled.begin(&positions, true, &config);
        assert!(!stays(&mut settled, 0, &mut report));
    }
}
