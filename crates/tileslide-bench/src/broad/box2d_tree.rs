//! The Box2D peer: Box2D v3's dynamic tree (`b2DynamicTree`) over the circles' boxes, kept up
//! to date the way Box2D's broad phase keeps it, and queried once per circle.

use boxdd::{Aabb as Box2dAabb, DynamicTree, TreeProxyId};
use tileslide::Aabb;
use tileslide_scenes::{BROAD_RADIUS, BroadCircle, boxes_overlap, broad_boxes};

use super::{BroadContender, normalized_pairs};
use crate::box2d_map::{box2d_foundation, to_box2d};

/// How far a proxy's box is fattened beyond the circle's box, in cells: Box2D's margin for a
/// circle shape, `B2_AABB_MARGIN_FRACTION` (0.125) times the radius, at most
/// `B2_MAX_AABB_MARGIN` (0.05 m, at one unit per meter), so 0.0375 for the scene's radius.
const MARGIN: f32 = (0.125 * BROAD_RADIUS).min(0.05);

/// The circles' boxes in a Box2D v3 [`DynamicTree`] (through `boxdd`), one proxy per circle,
/// its user data the circle's index, handled as Box2D's broad phase handles the proxies of
/// moving shapes:
///
/// - a proxy holds a fat box, the circle's box grown on every side by Box2D's margin for a
///   circle (0.0375 here); an update leaves it alone while the fat box still contains the
///   circle's box, and otherwise gives it a new fat box around the new one with
///   `b2DynamicTree_EnlargeProxy` (which grows the ancestors and marks them enlarged), as
///   Box2D's solver does for bodies that moved;
/// - after the moves, `b2DynamicTree_Rebuild` with `fullBuild = false` rebuilds the enlarged
///   part of the tree, as Box2D's broad phase does every step;
/// - then one `b2DynamicTree_QueryAll` per circle with its exact box collects the circles whose
///   fat boxes it overlaps; of those, the pairs `(i, j)` with `j > i` whose exact boxes
///   ([`broad_boxes`], touching included) overlap are kept, so each pair once.
///
/// Box2D's broad phase itself queries only the proxies that moved, with their fat boxes, and
/// keeps pairs from one step to the next until their fat boxes part, leaving the exact test to
/// its narrow phase. Here every circle moves every update (and, moving 0.05 a step, leaves its
/// fat box almost every time), so querying each circle is the same work, and the exact test
/// makes the reported set exact. The tree is built by inserting the proxies one by one, as
/// Box2D does when shapes are created; [`build`](BroadContender::build) then finds the start
/// pairs.
///
/// All of an update is timed: the boxes, the enlargements, the rebuild and the queries.
/// `boxdd` checks every call (proxy ids through a map, boxes for finite, ordered bounds) and
/// calls the query's visitor through a panic guard: that is part of what is measured.
pub struct Box2dTreeBroad {
    tree: Option<DynamicTree>,
    /// Circle `i`'s proxy.
    proxies: Vec<TreeProxyId>,
    /// Circle `i`'s fat box, as given to the tree (Box2D keeps it in the shape).
    fat: Vec<Aabb>,
    /// Scratch: the exact boxes of the circles.
    boxes: Vec<Aabb>,
    /// The exact pairs of the last update, `(i, j)` with `i < j`, `i` ascending.
    pairs: Vec<(u32, u32)>,
    /// The first error boxdd reported, if any (see [`error`](Self::error)).
    error: Option<boxdd::Error>,
}

impl Box2dTreeBroad {
    /// The name this peer is reported under.
    pub const NAME: &'static str = "box2d-tree";

    /// An empty peer, to be [built](BroadContender::build).
    #[must_use]
    pub fn new() -> Self {
        Self {
            tree: None,
            proxies: Vec::new(),
            fat: Vec::new(),
            boxes: Vec::new(),
            pairs: Vec::new(),
            error: None,
        }
    }

    /// The first error boxdd reported while building or updating, if any. The
    /// [`BroadContender`] contract has no error path: an error leaves the pairs empty (so the
    /// benchmark reports them as not exact) and is kept here. None is expected: boxdd reports
    /// errors for non-finite boxes and exhausted memory.
    pub fn error(&self) -> Option<boxdd::Error> {
        self.error
    }

    fn try_build(&mut self, circles: &[BroadCircle]) -> Result<(), boxdd::Error> {
        broad_boxes(circles, &mut self.boxes);
        box2d_foundation()?;
        let mut tree = DynamicTree::with_capacity(circles.len())?;
        self.fat = self.boxes.iter().map(fattened).collect();
        self.proxies = self
            .fat
            .iter()
            .enumerate()
            .map(|(i, fat)| tree.create_proxy(box2d_box(fat)?, 1, i as u64))
            .collect::<Result<_, _>>()?;
        self.tree = Some(tree);
        self.find_pairs()
    }

    fn try_update(&mut self, circles: &[BroadCircle]) -> Result<(), boxdd::Error> {
        broad_boxes(circles, &mut self.boxes);
        let Some(tree) = self.tree.as_mut() else {
            return Ok(());
        };
        for ((&proxy, fat), exact) in self.proxies.iter().zip(&mut self.fat).zip(&self.boxes) {
            if !contains(fat, exact) {
                *fat = fattened(exact);
                tree.enlarge_proxy(proxy, box2d_box(fat)?)?;
            }
        }
        tree.rebuild(false)?;
        self.find_pairs()
    }

    /// One query per circle: the pairs of the current boxes.
    fn find_pairs(&mut self) -> Result<(), boxdd::Error> {
        self.pairs.clear();
        let Some(tree) = self.tree.as_ref() else {
            return Ok(());
        };
        let (boxes, pairs) = (&self.boxes, &mut self.pairs);
        for (i, exact) in boxes.iter().enumerate() {
            let i = i as u32;
            tree.query_all(box2d_box(exact)?, &mut |_, user_data| {
                let j = user_data as u32;
                if j > i && boxes_overlap(exact, &boxes[j as usize]) {
                    pairs.push((i, j));
                }
                true
            })?;
        }
        Ok(())
    }

    /// Records `result`'s error, if any, and then reports no pairs.
    fn keep_error(&mut self, result: Result<(), boxdd::Error>) {
        if let Err(e) = result {
            self.error.get_or_insert(e);
            self.pairs.clear();
        }
    }
}

impl Default for Box2dTreeBroad {
    fn default() -> Self {
        Self::new()
    }
}

/// `b` grown by [`MARGIN`] on every side.
fn fattened(b: &Aabb) -> Aabb {
    Aabb {
        min: b.min - MARGIN,
        max: b.max + MARGIN,
    }
}

/// Whether `outer` contains `inner`, bounds included (Box2D's `b2AABB_Contains`).
fn contains(outer: &Aabb, inner: &Aabb) -> bool {
    outer.min.cmple(inner.min).all() && inner.max.cmple(outer.max).all()
}

/// Box2D's box of `b`: the same f32 bounds.
fn box2d_box(b: &Aabb) -> Result<Box2dAabb, boxdd::Error> {
    Box2dAabb::new(to_box2d(b.min), to_box2d(b.max))
}

impl BroadContender for Box2dTreeBroad {
    fn name(&self) -> &str {
        Self::NAME
    }

    fn build(&mut self, circles: &[BroadCircle]) {
        self.error = None;
        let result = self.try_build(circles);
        self.keep_error(result);
    }

    fn update(&mut self, circles: &[BroadCircle]) {
        let result = self.try_update(circles);
        self.keep_error(result);
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

    #[test]
    fn the_margin_is_box2d_s_for_the_scene_s_circles() {
        assert_eq!(MARGIN, 0.0375);
    }

    #[test]
    fn a_proxy_is_enlarged_only_when_its_circle_leaves_its_fat_box() {
        let mut peer = Box2dTreeBroad::new();
        let mut circles = touching_trio();
        peer.build(&circles);
        assert_eq!(peer.error(), None);
        let fat = peer.fat[1];
        // Within the margin: the fat box stays.
        circles[1].position.x += 0.03;
        peer.update(&circles);
        assert_eq!(peer.fat[1], fat);
        // Beyond it: a new fat box around the new box.
        circles[1].position += Vec2::new(0.03, -0.02);
        peer.update(&circles);
        assert_ne!(peer.fat[1], fat);
        assert!(contains(&peer.fat[1], &peer.boxes[1]));
        assert_eq!(peer.error(), None);
        // The pair broke when the boxes parted, fat boxes or not.
        assert!(peer.pairs().is_empty());
    }
}
