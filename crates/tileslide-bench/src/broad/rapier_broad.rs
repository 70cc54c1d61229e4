//! The rapier2d peer: rapier's broad phase (`BroadPhaseBvh`, the default one in 0.36) fed the
//! moved colliders every update, its pair events kept as a pair set.

use rapier2d::prelude::{
    ActiveCollisionTypes, BroadPhaseBvh, BroadPhasePairEvent, ColliderBuilder, ColliderHandle,
    ColliderPair, ColliderSet, CollisionPipeline, IntegrationParameters, IslandManager,
    NarrowPhase, RigidBodySet,
};
use tileslide::Aabb;
use tileslide_scenes::{BROAD_RADIUS, BroadCircle, boxes_overlap, broad_boxes};

use super::{BroadContender, normalized_pairs};
use crate::parry_vectors::to_parry;

/// The circles as standalone ball colliders (radius [`BROAD_RADIUS`], every
/// [`ActiveCollisionTypes`] enabled: rapier treats a collider without a body as fixed, and by
/// default its broad phase drops pairs of two fixed colliders) in a rapier2d [`ColliderSet`],
/// and rapier's [`BroadPhaseBvh`] with default [`IntegrationParameters`], driven directly (no
/// physics pipeline: no narrow phase, no solver). Every update:
///
/// 1. each collider is moved to its circle's new centre (`ColliderSet::get_mut` then
///    `Collider::set_translation`, as a user moves standalone colliders);
/// 2. [`BroadPhaseBvh::update`] with every collider as modified: rapier updates its tree
///    (leaves are the colliders' boxes loosened by half the prediction distance, 0.001, then
///    fattened by a change-detection margin of 0.04 and only updated when a box leaves its fat
///    box), refits it, optimizes it incrementally, finds the new pairs by a self traversal of
///    the changed leaves and drops the pairs whose fat boxes no longer overlap; it reports
///    both as `AddPair`/`DeletePair` events;
/// 3. the events are applied to this peer's own pair set (rapier keeps its pair map private):
///    per circle, the list of higher-index circles it forms a pair with;
/// 4. that pair set is filtered down to the pairs whose exact boxes
///    ([`broad_boxes`], touching included) overlap.
///
/// Rapier's pairs are a superset of the exact ones (fat boxes, kept until they separate),
/// hence the filter of step 4, which makes the reported set exact. All four steps are timed:
/// the moves are how rapier learns the new positions, and the filter is the work a user of
/// rapier's broad phase needs to get the pairs this benchmark asks for.
///
/// Driving the broad phase without a pipeline needs one detour: rapier marks a new collider
/// as changed in every way (parent and collision groups included) and only a pipeline step
/// clears those flags; left set, they make every [`BroadPhaseBvh::update`] remove and
/// re-insert every leaf. So [`build`](BroadContender::build) runs one
/// [`CollisionPipeline`] step on the new colliders with a throw-away broad and narrow phase
/// (not timed), then gives the colliders to this peer's broad phase. For the same reason the
/// updates pass the list of all handles as the modified colliders rather than
/// `ColliderSet::take_modified` (whose flags would never be cleared either); every circle
/// moves every update, so that list is exact.
pub struct RapierBroad {
    params: IntegrationParameters,
    bodies: RigidBodySet,
    colliders: ColliderSet,
    broad_phase: BroadPhaseBvh,
    /// Circle `i`'s collider.
    handles: Vec<ColliderHandle>,
    /// The circle of each collider, by collider index (the handle's arena index).
    circle_of: Vec<u32>,
    /// Scratch: the events of the last broad-phase update.
    events: Vec<BroadPhasePairEvent>,
    /// Rapier's current pairs: for each circle, the higher-index circles it pairs with.
    kept: Vec<Vec<u32>>,
    /// Scratch: the exact boxes of the circles.
    boxes: Vec<Aabb>,
    /// The exact pairs of the last update, `(i, j)` with `i < j`, `i` ascending.
    pairs: Vec<(u32, u32)>,
}

impl RapierBroad {
    /// The name this peer is reported under.
    pub const NAME: &'static str = "rapier2d-broad";

    /// An empty peer, to be [built](BroadContender::build).
    #[must_use]
    pub fn new() -> Self {
        Self {
            params: IntegrationParameters::default(),
            bodies: RigidBodySet::new(),
            colliders: ColliderSet::new(),
            broad_phase: BroadPhaseBvh::new(),
            handles: Vec::new(),
            circle_of: Vec::new(),
            events: Vec::new(),
            kept: Vec::new(),
            boxes: Vec::new(),
            pairs: Vec::new(),
        }
    }

    /// The number of pairs rapier's broad phase currently keeps (fat boxes overlapping), of
    /// which [`pair_count`](BroadContender::pair_count) are exact.
    #[must_use]
    pub fn kept_pairs(&self) -> usize {
        self.kept.iter().map(Vec::len).sum()
    }

    /// The circles of a pair reported by rapier, lower index first.
    fn circles_of(&self, pair: &ColliderPair) -> (u32, u32) {
        let circle = |h: ColliderHandle| {
            self.circle_of
                .get(h.into_raw_parts().0 as usize)
                .copied()
                .unwrap_or(u32::MAX)
        };
        let (a, b) = (circle(pair.collider1), circle(pair.collider2));
        (a.min(b), a.max(b))
    }
}

impl Default for RapierBroad {
    fn default() -> Self {
        Self::new()
    }
}

impl BroadContender for RapierBroad {
    fn name(&self) -> &str {
        Self::NAME
    }

    fn build(&mut self, circles: &[BroadCircle]) {
        let mut colliders = ColliderSet::with_capacity(circles.len());
        let handles: Vec<ColliderHandle> = circles
            .iter()
            .map(|c| {
                colliders.insert(
                    ColliderBuilder::ball(BROAD_RADIUS)
                        .translation(to_parry(c.position))
                        // Standalone colliders count as fixed, and by default rapier drops
                        // fixed–fixed pairs in the broad phase itself.
                        .active_collision_types(ActiveCollisionTypes::all()),
                )
            })
            .collect();
        // Clears the "changed in every way" flags of the new colliders (see the type's doc).
        CollisionPipeline::new().step(
            self.params.prediction_distance(),
            &mut IslandManager::new(),
            &mut BroadPhaseBvh::new(),
            &mut NarrowPhase::new(),
            &mut self.bodies,
            &mut colliders,
            &(),
            &(),
        );
        let slots = handles
            .iter()
            .map(|h| h.into_raw_parts().0 as usize + 1)
            .max()
            .unwrap_or(0);
        self.circle_of = vec![u32::MAX; slots];
        for (i, h) in handles.iter().enumerate() {
            self.circle_of[h.into_raw_parts().0 as usize] = i as u32;
        }
        self.colliders = colliders;
        self.handles = handles;
        self.broad_phase = BroadPhaseBvh::new();
        self.kept = vec![Vec::new(); circles.len()];
        // The first update inserts every collider into the tree (the moves to the same
        // positions mark them as moved) and reports every start pair.
        self.update(circles);
    }

    fn update(&mut self, circles: &[BroadCircle]) {
        for (&handle, circle) in self.handles.iter().zip(circles) {
            if let Some(collider) = self.colliders.get_mut(handle) {
                collider.set_translation(to_parry(circle.position));
            }
        }
        self.events.clear();
        self.broad_phase.update(
            &self.params,
            &self.colliders,
            &self.bodies,
            &self.handles,
            &[],
            &mut self.events,
        );
        for event in &self.events {
            match event {
                BroadPhasePairEvent::AddPair(pair) => {
                    let (a, b) = self.circles_of(pair);
                    if let Some(list) = self.kept.get_mut(a as usize) {
                        list.push(b);
                    }
                }
                BroadPhasePairEvent::DeletePair(pair) => {
                    let (a, b) = self.circles_of(pair);
                    if let Some(list) = self.kept.get_mut(a as usize)
                        && let Some(at) = list.iter().position(|&j| j == b)
                    {
                        list.swap_remove(at);
                    }
                }
            }
        }
        broad_boxes(circles, &mut self.boxes);
        self.pairs.clear();
        for (i, list) in self.kept.iter().enumerate() {
            let a = &self.boxes[i];
            for &j in list {
                if boxes_overlap(a, &self.boxes[j as usize]) {
                    self.pairs.push((i as u32, j));
                }
            }
        }
    }

    fn pairs(&self) -> Vec<(u32, u32)> {
        normalized_pairs(self.pairs.iter().copied())
    }

    fn pair_count(&self) -> usize {
        self.pairs.len()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::broad::tests::touching_trio;
    use glam::Vec2;
    use tileslide_scenes::{scene_broad, update_broad};

    #[test]
    fn rapier_keeps_pairs_on_fat_boxes_and_the_filter_drops_them() {
        let mut peer = RapierBroad::new();
        let mut circles = touching_trio();
        peer.build(&circles);
        assert_eq!(peer.kept_pairs(), 1);
        // Two ulps apart: still well within rapier's fat boxes, so kept, but filtered out.
        circles[1].position.x = circles[1].position.x.next_up().next_up();
        peer.update(&circles);
        assert!(peer.pairs().is_empty());
        assert_eq!(peer.kept_pairs(), 1);
        // Far apart: rapier drops the pair itself.
        circles[1].position = Vec2::new(100.0, 100.0);
        peer.update(&circles);
        assert_eq!(peer.kept_pairs(), 0);

        let mut circles = scene_broad(3_000);
        peer.build(&circles);
        for _ in 0..5 {
            update_broad(&mut circles);
            peer.update(&circles);
            assert!(peer.kept_pairs() >= peer.pair_count());
        }
    }
}
