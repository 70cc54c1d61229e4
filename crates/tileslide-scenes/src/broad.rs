//! The "broad" scene: circles bouncing around a 256-cell square, and every pair of them whose
//! boxes overlap.

use glam::Vec2;
use tileslide::Aabb;

use crate::SplitMix64;

/// Seed of the broad scene.
const BROAD_SEED: u64 = 0xB0A0_0000_0000_0004;
/// Length of every velocity, in cells per update.
const SPEED: f32 = 0.05;
/// Smallest coordinate a centre stays at (it bounces back below it).
const LOW: f32 = 1.0;
/// Largest coordinate a centre stays at (it bounces back above it).
const HIGH: f32 = 255.0;

/// Radius of every circle of the broad scene, in cells. A circle's box is its centre ∓ this
/// on both axes (see [`broad_boxes`]).
pub const BROAD_RADIUS: f32 = 0.3;

/// One circle of the broad scene: where it is and how far it moves per update.
///
/// ```
/// use glam::Vec2;
/// use tileslide_scenes::{BroadCircle, update_broad};
/// let mut circles = [BroadCircle { position: Vec2::new(2.0, 3.0), velocity: Vec2::new(0.05, 0.0) }];
/// update_broad(&mut circles);
/// assert_eq!(circles[0].position, Vec2::new(2.05, 3.0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BroadCircle {
    /// Centre, in `[1, 255]²` at the start and after every [`update_broad`].
    pub position: Vec2,
    /// Move per update, `0.05 · (cos θ, sin θ)` cells at the start; [`update_broad`] flips the
    /// sign of a component when the circle bounces.
    pub velocity: Vec2,
}

/// The first `n` circles of the "broad" scene of BENCHMARKS.md (seed `0xB0A0000000000004`).
///
/// Per circle, in draw order: position `(1 + 254 · f32(), 1 + 254 · f32())` (x then y), then
/// angle `f32() · 2π` in f32 arithmetic, velocity `0.05 · (cos, sin)` with Rust's f32
/// `cos`/`sin` (the convention of [`scene_crowd`](crate::scene_crowd)). Every circle has radius
/// [`BROAD_RADIUS`]; the circles are drawn one after the other, so a smaller scene is a prefix
/// of a larger one.
///
/// ```
/// let circles = tileslide_scenes::scene_broad(1_000);
/// assert_eq!(circles.len(), 1_000);
/// assert!(circles.iter().all(|c| (c.velocity.length() - 0.05).abs() < 1e-6));
/// assert_eq!(circles[..10], tileslide_scenes::scene_broad(10)[..]);
/// ```
#[must_use]
pub fn scene_broad(n: usize) -> Vec<BroadCircle> {
    let mut rng = SplitMix64::new(BROAD_SEED);
    (0..n)
        .map(|_| {
            // Separate statements: the draw order (x, y, angle) is part of the scene.
            let x = LOW + 254.0 * rng.f32();
            let y = LOW + 254.0 * rng.f32();
            let angle = rng.f32() * std::f32::consts::TAU;
            BroadCircle {
                position: Vec2::new(x, y),
                velocity: Vec2::new(angle.cos(), angle.sin()) * SPEED,
            }
        })
        .collect()
}

/// Moves every circle by one update of the broad scene: per axis, `p += v`, and if that leaves
/// `[1, 255]` (`p < 1` or `p > 255`), the circle bounces: `v = -v; p += 2v` (f32 arithmetic,
/// in that order).
///
/// ```
/// use glam::Vec2;
/// use tileslide_scenes::{BroadCircle, update_broad};
/// let mut circles = [BroadCircle { position: Vec2::new(1.02, 9.0), velocity: Vec2::new(-0.05, 0.0) }];
/// update_broad(&mut circles);
/// // 1.02 − 0.05 = 0.97 < 1: back by 0.1, and now heading +x.
/// assert!((circles[0].position.x - 1.07).abs() < 1e-6);
/// assert_eq!(circles[0].velocity, Vec2::new(0.05, 0.0));
/// ```
pub fn update_broad(circles: &mut [BroadCircle]) {
    for circle in circles {
        bounce(&mut circle.position.x, &mut circle.velocity.x);
        bounce(&mut circle.position.y, &mut circle.velocity.y);
    }
}

/// One axis of [`update_broad`].
#[inline]
fn bounce(p: &mut f32, v: &mut f32) {
    *p += *v;
    if *p < LOW || *p > HIGH {
        *v = -*v;
        *p += 2.0 * *v;
    }
}

/// The box of one circle: `min = position − r`, `max = position + r` on both axes, with
/// `r = ` [`BROAD_RADIUS`], in f32.
///
/// Every contender must use exactly these boxes (these f32 values), so that "touching" means
/// the same thing for all of them and for [`broad_pairs_reference`].
///
/// ```
/// use glam::Vec2;
/// use tileslide_scenes::{BROAD_RADIUS, BroadCircle, broad_box};
/// let c = BroadCircle { position: Vec2::new(2.0, 3.0), velocity: Vec2::ZERO };
/// let b = broad_box(&c);
/// assert_eq!(b.min, c.position - Vec2::splat(BROAD_RADIUS));
/// assert_eq!(b.max, c.position + Vec2::splat(BROAD_RADIUS));
/// ```
#[inline]
#[must_use]
pub fn broad_box(circle: &BroadCircle) -> Aabb {
    // Not `Aabb::from_center`: its NaN check and min/max are not needed for circles of the
    // scene, and the box must be exactly these two sums.
    let r = Vec2::splat(BROAD_RADIUS);
    Aabb {
        min: circle.position - r,
        max: circle.position + r,
    }
}

/// The boxes of `circles` ([`broad_box`]), in order, written into `out` (cleared first; reuse
/// it between updates to avoid reallocating).
///
/// ```
/// let circles = tileslide_scenes::scene_broad(100);
/// let mut boxes = Vec::new();
/// tileslide_scenes::broad_boxes(&circles, &mut boxes);
/// assert_eq!(boxes.len(), 100);
/// assert_eq!(boxes[7], tileslide_scenes::broad_box(&circles[7]));
/// ```
pub fn broad_boxes(circles: &[BroadCircle], out: &mut Vec<Aabb>) {
    out.clear();
    out.extend(circles.iter().map(broad_box));
}

/// Whether two closed boxes overlap, touching included: `a.min <= b.max` and `b.min <= a.max`
/// on both axes, exactly (no tolerance). The overlap test of the broad scene.
///
/// ```
/// use glam::Vec2;
/// use tileslide::Aabb;
/// let a = Aabb { min: Vec2::ZERO, max: Vec2::ONE };
/// let b = Aabb { min: Vec2::new(1.0, 0.5), max: Vec2::new(2.0, 2.0) };
/// assert!(tileslide_scenes::boxes_overlap(&a, &b)); // touching at x = 1
/// ```
#[inline]
#[must_use]
pub fn boxes_overlap(a: &Aabb, b: &Aabb) -> bool {
    a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y
}

/// Every pair `(i, j)`, `i < j`, of `circles` whose [boxes](broad_box) overlap, touching
/// included ([`boxes_overlap`]), sorted: the answer every broad-phase contender must give.
///
/// A plain sweep, exact by construction: the boxes sorted by `min.x`, each compared with the
/// following ones until their `min.x` passes its `max.x`. Circle indices are `u32`: scenes of
/// more than 2³² circles are not supported.
///
/// "Overlap" is decided on the f32 boxes of [`broad_box`], as every contender sees them, not
/// in exact arithmetic: two boxes whose sides round to the same f32 touch even if the exact
/// sides are a hair apart. On the 100,000-circle scene after 10 updates this gives 111,125
/// pairs, one more than BENCHMARKS.md's 111,124 (the exact-arithmetic count): circles 855 and
/// 92485, 0.600006 apart in x, whose box sides meet at the same f32 near x = 130.187.
///
/// ```
/// use tileslide_scenes::{broad_pairs_reference, scene_broad, update_broad};
/// let mut circles = scene_broad(10_000);
/// for _ in 0..10 {
///     update_broad(&mut circles);
/// }
/// let pairs = broad_pairs_reference(&circles);
/// assert!(pairs.windows(2).all(|w| w[0] < w[1]));
/// assert!(pairs.iter().all(|&(i, j)| i < j));
/// ```
#[must_use]
pub fn broad_pairs_reference(circles: &[BroadCircle]) -> Vec<(u32, u32)> {
    let mut boxes = Vec::with_capacity(circles.len());
    broad_boxes(circles, &mut boxes);
    let mut order: Vec<u32> = (0..circles.len()).map(|i| i as u32).collect();
    // Ties broken by index only to make the order (not the result) deterministic.
    order.sort_unstable_by(|&a, &b| {
        boxes[a as usize]
            .min
            .x
            .total_cmp(&boxes[b as usize].min.x)
            .then(a.cmp(&b))
    });
    let mut pairs = Vec::new();
    for (k, &i) in order.iter().enumerate() {
        let a = &boxes[i as usize];
        for &j in &order[k + 1..] {
            let b = &boxes[j as usize];
            // `b.min.x >= a.min.x` by the sort, so the x extents overlap exactly while
            // `b.min.x <= a.max.x`; every later box starts further right.
            if b.min.x > a.max.x {
                break;
            }
            if a.min.y <= b.max.y && b.min.y <= a.max.y {
                pairs.push((i.min(j), i.max(j)));
            }
        }
    }
    pairs.sort_unstable();
    pairs
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every overlapping pair by testing all of them.
    fn brute_force(circles: &[BroadCircle]) -> Vec<(u32, u32)> {
        let boxes: Vec<Aabb> = circles.iter().map(broad_box).collect();
        let mut pairs = Vec::new();
        for i in 0..boxes.len() {
            for j in i + 1..boxes.len() {
                if boxes_overlap(&boxes[i], &boxes[j]) {
                    pairs.push((i as u32, j as u32));
                }
            }
        }
        pairs
    }

    fn still(x: f32, y: f32) -> BroadCircle {
        BroadCircle {
            position: Vec2::new(x, y),
            velocity: Vec2::ZERO,
        }
    }

    /// The centre right of `x` whose box's left side is exactly the right side of the box
    /// around `x` (found by stepping one ulp at a time from `x + 2r`).
    fn touching_partner(x: f32) -> f32 {
        let right = x + BROAD_RADIUS;
        let mut b = x + 2.0 * BROAD_RADIUS;
        for _ in 0..64 {
            let left = b - BROAD_RADIUS;
            if left == right {
                return b;
            }
            b = if left < right {
                b.next_up()
            } else {
                b.next_down()
            };
        }
        panic!("no exact touching partner for {x}");
    }

    /// The pairs whose boxes overlap in exact arithmetic: `|Δx| <= 2r` and `|Δy| <= 2r` on
    /// the f32 centres, computed in f64 (exact: the difference of two f32 values in
    /// `[1, 255]` fits the f64 mantissa), instead of comparing the f32-rounded box sides.
    fn exact_arithmetic_pairs(circles: &[BroadCircle]) -> Vec<(u32, u32)> {
        let reach = 2.0 * f64::from(BROAD_RADIUS);
        let mut order: Vec<u32> = (0..circles.len() as u32).collect();
        order.sort_unstable_by(|&a, &b| {
            let (pa, pb) = (circles[a as usize].position, circles[b as usize].position);
            pa.x.total_cmp(&pb.x)
        });
        let mut pairs = Vec::new();
        for (k, &i) in order.iter().enumerate() {
            let a = circles[i as usize].position;
            for &j in &order[k + 1..] {
                let b = circles[j as usize].position;
                let dx = f64::from(b.x) - f64::from(a.x);
                if dx > reach {
                    break;
                }
                if (f64::from(b.y) - f64::from(a.y)).abs() <= reach {
                    pairs.push((i.min(j), i.max(j)));
                }
            }
        }
        pairs.sort_unstable();
        pairs
    }

    #[test]
    fn after_ten_updates_the_100k_scene_has_111125_pairs_one_more_than_published() {
        // BENCHMARKS.md publishes 111,124. The f32 boxes give one pair more: circles 855 and
        // 92485, whose centres are 0.600006 apart in x (6e-6 more than 2r), but whose box
        // sides both round to the same f32 near x = 130.187 (the f32 spacing there is 1.5e-5),
        // so the boxes touch. The published figure is the exact-arithmetic count (or the
        // strict `<` count, the same at this update): every other pair agrees.
        let mut circles = scene_broad(100_000);
        for _ in 0..10 {
            update_broad(&mut circles);
        }
        let pairs = broad_pairs_reference(&circles);
        assert_eq!(pairs.len(), 111_125);
        let exact = exact_arithmetic_pairs(&circles);
        assert_eq!(exact.len(), 111_124);
        let extra: Vec<(u32, u32)> = pairs
            .iter()
            .filter(|p| exact.binary_search(p).is_err())
            .copied()
            .collect();
        assert_eq!(extra, vec![(855, 92_485)]);
        let (a, b) = (broad_box(&circles[855]), broad_box(&circles[92_485]));
        assert_eq!(a.max.x, b.min.x);
    }

    #[test]
    fn the_scene_follows_the_published_draw_order() {
        let mut rng = SplitMix64::new(0xB0A0_0000_0000_0004);
        for c in scene_broad(50) {
            let x = 1.0 + 254.0 * rng.f32();
            let y = 1.0 + 254.0 * rng.f32();
            let angle = rng.f32() * std::f32::consts::TAU;
            assert_eq!(c.position, Vec2::new(x, y));
            assert_eq!(c.velocity, Vec2::new(angle.cos(), angle.sin()) * 0.05);
        }
    }

    #[test]
    fn circles_start_and_stay_in_the_square() {
        let mut circles = scene_broad(5_000);
        for _ in 0..200 {
            for c in &circles {
                assert!((LOW..=HIGH).contains(&c.position.x), "{c:?}");
                assert!((LOW..=HIGH).contains(&c.position.y), "{c:?}");
            }
            update_broad(&mut circles);
        }
    }

    #[test]
    fn a_circle_bounces_off_both_ends() {
        let mut circles = [
            BroadCircle {
                position: Vec2::new(254.98, 1.03),
                velocity: Vec2::new(0.05, -0.05),
            },
            still(128.0, 128.0),
        ];
        update_broad(&mut circles);
        assert!((circles[0].position - Vec2::new(254.93, 1.08)).length() < 1e-4);
        assert_eq!(circles[0].velocity, Vec2::new(-0.05, 0.05));
        assert_eq!(circles[1], still(128.0, 128.0));
    }

    #[test]
    fn the_sweep_equals_brute_force_on_the_scene() {
        // The first 3,000 circles after a few updates: sparse, about 100 pairs.
        let mut circles = scene_broad(3_000);
        for _ in 0..5 {
            update_broad(&mut circles);
        }
        let pairs = broad_pairs_reference(&circles);
        assert!(pairs.len() > 50, "{}", pairs.len());
        assert_eq!(pairs, brute_force(&circles));
    }

    #[test]
    fn the_sweep_equals_brute_force_on_a_crowded_patch() {
        // 400 circles in a 10 × 10 patch: about a thousand pairs, many boxes overlapping
        // several others, and many equal `min.x` (a coarse lattice of x values).
        let mut rng = SplitMix64::new(99);
        let circles: Vec<BroadCircle> = (0..400)
            .map(|_| still(1.0 + (rng.below(40) as f32) * 0.25, 1.0 + 10.0 * rng.f32()))
            .collect();
        let pairs = broad_pairs_reference(&circles);
        assert!(pairs.len() > 500, "{}", pairs.len());
        assert_eq!(pairs, brute_force(&circles));
    }

    #[test]
    fn touching_boxes_overlap_and_a_gap_of_one_ulp_does_not() {
        let x = 17.3;
        let b = touching_partner(x);
        let circles = [still(x, 5.0), still(b, 5.0), still(b.next_up(), 40.0)];
        assert_eq!(broad_box(&circles[0]).max.x, broad_box(&circles[1]).min.x);
        assert_eq!(broad_pairs_reference(&circles), vec![(0, 1)]);
        // One ulp further right and the boxes are apart (unless the subtraction rounds back).
        let apart = [still(x, 5.0), still(b.next_up(), 5.0)];
        let gap = broad_box(&apart[1]).min.x > broad_box(&apart[0]).max.x;
        assert_eq!(broad_pairs_reference(&apart).is_empty(), gap);
        assert_eq!(broad_pairs_reference(&apart), brute_force(&apart));
    }

    #[test]
    fn empty_and_single_scenes_have_no_pairs() {
        assert!(broad_pairs_reference(&[]).is_empty());
        assert!(broad_pairs_reference(&scene_broad(1)).is_empty());
    }
}
