//! tileslide's contenders: its [`PairFinder`] with each [`PairMethod`], fed the circles'
//! boxes every update.

use tileslide::{Aabb, broadphase::PairFinder, broadphase::PairMethod};
use tileslide_scenes::{BroadCircle, broad_boxes};

use super::{BroadContender, normalized_pairs};

/// tileslide's [`PairFinder`] with one [`PairMethod`]: every update converts the circles to
/// boxes ([`broad_boxes`], the same f32 boxes every contender uses) and asks the finder for
/// every overlapping pair. The finder keeps what it can between updates (its buffers, and the
/// sweep order of [`PairMethod::SweepAndPrune`]); nothing else is carried over.
#[derive(Clone, Debug)]
pub struct TileslideBroad {
    kind: PairMethod,
    finder: PairFinder,
    /// Scratch: the circles' boxes, refilled every update.
    boxes: Vec<Aabb>,
    /// The pairs of the last update, in the finder's order.
    pairs: Vec<(u32, u32)>,
}

impl TileslideBroad {
    /// An empty contender using `kind`, to be [built](BroadContender::build).
    #[must_use]
    pub fn new(kind: PairMethod) -> Self {
        Self {
            kind,
            finder: PairFinder::default(),
            boxes: Vec::new(),
            pairs: Vec::new(),
        }
    }

    /// The name a contender using `kind` is reported under.
    #[must_use]
    pub fn name_of(kind: PairMethod) -> &'static str {
        match kind {
            PairMethod::UniformGrid => "tileslide-grid",
            PairMethod::SweepAndPrune => "tileslide-sap",
            // A method added to tileslide after this benchmark was written.
            _ => "tileslide",
        }
    }
}

impl BroadContender for TileslideBroad {
    fn name(&self) -> &str {
        Self::name_of(self.kind)
    }

    fn build(&mut self, circles: &[BroadCircle]) {
        self.finder = PairFinder::default();
        self.update(circles);
    }

    fn update(&mut self, circles: &[BroadCircle]) {
        broad_boxes(circles, &mut self.boxes);
        self.pairs.clear();
        self.finder.find(self.kind, &self.boxes, &mut self.pairs);
    }

    fn pairs(&self) -> Vec<(u32, u32)> {
        normalized_pairs(self.pairs.iter().copied())
    }

    fn pair_count(&self) -> usize {
        self.pairs.len()
    }
}
