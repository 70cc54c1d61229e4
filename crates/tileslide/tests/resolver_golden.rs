//! The resolver on the BENCHMARKS.md crowd: a clean audit after every run, and bit-identical
//! positions from run to run and between debug and release builds (a golden hash: `.ci/run`
//! runs this test in both profiles). A change to the resolver that moves any body by a
//! single bit changes the hash: update `GOLDEN` only for a deliberate change, and say so in
//! the commit.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use tileslide::{Bodies, BodyDesc, BodyHandle, BodyShape, TileMap, Vec2};
use tileslide_scenes::{CROWD_RADIUS, audit_crowd, dungeon256, positions_hash, scene_crowd};

/// [`positions_hash`] of the final positions: FNV-1a 64 of their bits, x then y, body by
/// body.
const GOLDEN: u64 = 0x527e_da96_98ab_4a5d;

/// Steps of the run.
const STEPS: usize = 40;

/// The crowd: every body proposes its constant velocity, then one `Bodies::step`.
struct Crowd {
    map: TileMap,
    bodies: Bodies,
    crowd: Vec<(BodyHandle, Vec2)>,
}

impl Crowd {
    fn new(n: usize) -> Self {
        let grid = dungeon256();
        let map = grid.to_tile_map().unwrap();
        let mut bodies = Bodies::new();
        let shape = BodyShape::circle(CROWD_RADIUS).unwrap();
        let crowd = scene_crowd(&grid, n)
            .iter()
            .map(|b| {
                let h = bodies
                    .add(BodyDesc::new(b.position, shape.clone()))
                    .unwrap();
                (h, b.velocity)
            })
            .collect();
        Self { map, bodies, crowd }
    }

    fn step(&mut self) {
        for &(h, v) in &self.crowd {
            self.bodies.propose(h, v).unwrap();
        }
        self.bodies.step(&self.map);
    }

    fn positions(&self) -> Vec<Vec2> {
        self.crowd
            .iter()
            .map(|&(h, _)| self.bodies.get(h).unwrap().position())
            .collect()
    }
}

#[test]
fn the_crowd_is_clean_and_bit_identical_to_the_golden_run() {
    let mut crowd = Crowd::new(2_000);
    let mut before = crowd.positions();
    let mut travel = 0.0_f64;
    for _ in 0..STEPS {
        crowd.step();
        let after = crowd.positions();
        travel += before
            .iter()
            .zip(&after)
            .map(|(a, b)| f64::from(a.distance(*b)))
            .sum::<f64>();
        before = after;
    }
    let audit = audit_crowd(&dungeon256(), &before, CROWD_RADIUS);
    assert_eq!(audit.overlapping_pairs, 0, "{audit:?}");
    assert_eq!(audit.wall_penetrations, 0, "{audit:?}");
    // Nothing closer than the radii by more than 1e-4 cell.
    assert!(audit.max_overlap <= 1e-4, "{audit:?}");
    assert!(audit.max_penetration <= 1e-4, "{audit:?}");
    let mean_travel = travel / before.len() as f64;
    assert!(mean_travel > 1.0, "the crowd hardly moved: {mean_travel}");
    let hash = positions_hash(&before);
    // A second run from scratch gives the same bits.
    let mut again = Crowd::new(2_000);
    for _ in 0..STEPS {
        again.step();
    }
    assert_eq!(positions_hash(&again.positions()), hash);
    assert_eq!(
        hash, GOLDEN,
        "positions changed: golden hash is now {hash:#018x}"
    );
}

/// The same run on 1, 2, 3 and 8 threads (the `parallel` feature: resolved in waves of
/// bodies that do not meet) gives the golden hash every time.
#[cfg(feature = "parallel")]
#[test]
fn the_crowd_is_bit_identical_on_any_number_of_threads() {
    for threads in [1, 2, 3, 8] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        let hash = pool.install(|| {
            let mut crowd = Crowd::new(2_000);
            for _ in 0..STEPS {
                crowd.step();
            }
            positions_hash(&crowd.positions())
        });
        assert_eq!(hash, GOLDEN, "{threads} threads: {hash:#018x}");
    }
}

/// A copy of the set taken midway, with its resolver's memories and the waves' schedule,
/// goes on as the original would: both end on the golden hash, on 2 threads.
#[cfg(feature = "parallel")]
#[test]
fn a_crowd_copied_midway_goes_on_bit_for_bit_on_two_threads() {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .unwrap();
    let hashes = pool.install(|| {
        let mut crowd = Crowd::new(2_000);
        for _ in 0..STEPS / 3 {
            crowd.step();
        }
        let mut copy = Crowd {
            map: crowd.map.clone(),
            bodies: crowd.bodies.clone(),
            crowd: crowd.crowd.clone(),
        };
        for _ in STEPS / 3..STEPS {
            crowd.step();
            copy.step();
        }
        [crowd, copy].map(|c| positions_hash(&c.positions()))
    });
    assert_eq!(hashes, [GOLDEN; 2], "{hashes:x?}");
}

/// A crowd past the sizes from which bodies are copied in, neighbour rows filled and moves
/// made on every thread (8,192): 10,000 circles, 8 steps, the same bits on 2 and 3 threads
/// as on 1.
#[cfg(feature = "parallel")]
#[test]
fn a_crowd_large_enough_to_split_every_phase_is_bit_identical_on_any_number_of_threads() {
    let run = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| {
            let mut crowd = Crowd::new(10_000);
            for _ in 0..8 {
                crowd.step();
            }
            positions_hash(&crowd.positions())
        })
    };
    let one = run(1);
    for threads in [2, 3] {
        assert_eq!(run(threads), one, "{threads} threads");
    }
}
