//! What a soak checked and what it found: a count of checks and of violations per kind, with
//! the first few violations of each in words.

use std::collections::BTreeMap;

/// Violations of a kind kept in words (the rest are counted).
const KEEP: usize = 5;

/// A kind of check.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Kind {
    /// A body's position after a step: finite, in no wall by more than the skin, in the room
    /// it was in (nothing crossed a wall).
    BodyPlace,
    /// A pair of bodies within reach of each other: apart, but for the skin.
    BodyPair,
    /// A proposal of a finite, in-range move accepted.
    BodyRefused,
    /// A removed body's handle refused by every call.
    StaleHandle,
    /// A NaN, infinite or out-of-range value refused with an error, changing nothing.
    BadValue,
    /// A character's move accepted.
    CharacterRefused,
    /// A character moved (counted, never a violation: see `CharacterPlace`).
    CharacterMove,
    /// A character's place after its move: finite, in no wall by more than the skin, in its
    /// room.
    CharacterPlace,
    /// A ray cast: `t` in [0, 1], a finite point on the ray and a unit normal;
    /// `cast_ray_all`'s first hit equal to it; the batch equal to the single casts.
    Ray,
    /// A circle cast from a body: the circle stops where it is in no wall.
    CircleCast,
    /// A frame of hit volumes: both broadphases give the same ids and events, each event's
    /// `t` in [0, 1], its point finite, its objects registered this frame.
    Volumes,
    /// A path: from the start to the goal, its ends where the circle fits, every run
    /// clear by the circle cast.
    Path,
    /// A flow field direction: a unit vector or none.
    FlowDirection,
    /// A cell dug out or built (counted, never a violation).
    MapEdit,
    /// A snapshot restored into a second world that then ran beside the first: the same
    /// positions and events, bit for bit, at every step.
    Snapshot,
}

impl Kind {
    /// The name in reports.
    pub fn name(self) -> &'static str {
        match self {
            Kind::BodyPlace => "body_place",
            Kind::BodyPair => "body_pair",
            Kind::BodyRefused => "body_move_refused",
            Kind::StaleHandle => "stale_handle",
            Kind::BadValue => "bad_value",
            Kind::CharacterRefused => "character_move_refused",
            Kind::CharacterMove => "character_move",
            Kind::CharacterPlace => "character_place",
            Kind::Ray => "ray",
            Kind::CircleCast => "circle_cast",
            Kind::Volumes => "volumes",
            Kind::Path => "path",
            Kind::FlowDirection => "flow_direction",
            Kind::MapEdit => "map_edit",
            Kind::Snapshot => "snapshot",
        }
    }
}

/// Checks and violations of one kind.
#[derive(Clone, Debug, Default)]
pub struct Tally {
    pub checks: u64,
    pub violations: u64,
    /// The first few violations: (step, what).
    pub first: Vec<(u64, String)>,
}

/// Every kind's tally.
#[derive(Clone, Debug, Default)]
pub struct Audit {
    pub kinds: BTreeMap<Kind, Tally>,
    /// Print each violation kept, as it is found, on standard error (a long run's first
    /// findings are not left waiting for its end).
    pub live: bool,
}

impl Audit {
    /// One check of `kind` passed (or is about to be judged).
    pub fn count(&mut self, kind: Kind) {
        self.kinds.entry(kind).or_default().checks += 1;
    }

    /// A check of `kind` failed at `step`, for `why`.
    pub fn violation(&mut self, kind: Kind, step: u64, why: String) {
        let tally = self.kinds.entry(kind).or_default();
        tally.violations += 1;
        if tally.first.len() < KEEP {
            if self.live {
                eprintln!("soak: step {step}: {}: {why}", kind.name());
            }
            tally.first.push((step, why));
        }
    }

    /// Violations of every kind.
    pub fn violations(&self) -> u64 {
        self.kinds.values().map(|t| t.violations).sum()
    }
}
