//! The parry2d peer: one `Bvh` over the circles' boxes, refitted every update and traversed
//! against itself.

use parry2d::bounding_volume::Aabb;
use parry2d::partitioning::{Bvh, BvhBuildStrategy, BvhWorkspace};
use tileslide_scenes::{BroadCircle, broad_box};

use super::{BroadContender, normalized_pairs};
use crate::parry_vectors::to_parry;

/// The circles' boxes in a parry2d [`Bvh`] (parry's default binned SAH build, once, from the
/// start positions). Every update:
///
/// 1. each leaf's box is set to the circle's new box with
///    [`Bvh::insert_or_update_partially`] and a change-detection margin of 0, so the leaves
///    are the exact boxes (no fattening);
/// 2. [`Bvh::refit`] recomputes the inner boxes bottom-up (and lays the nodes out again in
///    depth-first order, as parry recommends for the queries that follow);
/// 3. [`Bvh::traverse_bvtt_single_tree`] (without change detection: every circle moved)
///    walks the tree against itself and reports every pair of leaves whose boxes intersect,
///    each pair once.
///
/// parry's box test is closed (`mins <= other.maxs && maxs >= other.mins`), so touching boxes
/// are reported, and as the leaves are the exact boxes, the pair set is exact as reported: no
/// filtering.
///
/// The tree's topology is the one built at the start; only its boxes follow the circles, so
/// the tree degrades as they drift apart from the neighbours they were grouped with. Over the
/// benchmark's 10 updates (0.5 cell of travel) that is mild: at 100,000 circles an update
/// creeps from about 7.8 to 10 ms. Longer runs need more: the median update of updates 31–40
/// is about 3× that of the first 10. Calling parry's `optimize_incremental` before every
/// refit slows the creep (about 1.8× by updates 31–40) but costs more over the first 10
/// updates, and rebuilding the tree every update costs about 44 ms; neither is this peer.
///
/// The timed update is all three steps, plus converting the circles' boxes to parry's type;
/// the pairs are kept in the order and orientation parry reports them, and sorted only by
/// [`pairs`](BroadContender::pairs).
#[derive(Clone, Default)]
pub struct ParryBvhBroad {
    bvh: Bvh,
    workspace: BvhWorkspace,
    /// The pairs of the last update, as reported by the traversal.
    pairs: Vec<(u32, u32)>,
}

impl ParryBvhBroad {
    /// The name this peer is reported under.
    pub const NAME: &'static str = "parry2d-bvh";

    /// An empty peer, to be [built](BroadContender::build).
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }
}

/// parry's box of a circle: [`broad_box`], the same f32 values.
#[inline]
fn parry_box(circle: &BroadCircle) -> Aabb {
    let b = broad_box(circle);
    Aabb::new(to_parry(b.min), to_parry(b.max))
}

impl BroadContender for ParryBvhBroad {
    fn name(&self) -> &str {
        Self::NAME
    }

    fn build(&mut self, circles: &[BroadCircle]) {
        let boxes: Vec<Aabb> = circles.iter().map(parry_box).collect();
        self.bvh = Bvh::from_leaves(BvhBuildStrategy::Binned, &boxes);
        self.workspace = BvhWorkspace::default();
        self.update(circles);
    }

    fn update(&mut self, circles: &[BroadCircle]) {
        for (i, circle) in circles.iter().enumerate() {
            // Leaf `i` is circle `i` (`from_leaves` numbers the leaves in order).
            self.bvh
                .insert_or_update_partially(parry_box(circle), i as u32, 0.0);
        }
        self.bvh.refit(&mut self.workspace);
        self.pairs.clear();
        let pairs = &mut self.pairs;
        self.bvh
            .traverse_bvtt_single_tree::<false>(&mut self.workspace, &mut |a, b| {
                pairs.push((a, b));
            });
    }

    fn pairs(&self) -> Vec<(u32, u32)> {
        normalized_pairs(self.pairs.iter().copied())
    }

    fn pair_count(&self) -> usize {
        self.pairs.len()
    }
}
