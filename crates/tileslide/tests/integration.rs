//! The core crate's integration tests, as one test binary: each file of this folder is a
//! module (`cargo test -p tileslide --test integration path::` runs one), so the suite is
//! built and linked once rather than once a file. Two stay binaries of their own:
//! `resolver_golden` (CI runs it again in an optimised build) and `ray_batch_miri` (run
//! under Miri, see docs/fuzzing.md).

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

// Shared by the modules below.
mod drawn;
mod generators;
mod path_support;
mod replica_support;

mod bodies_behaviour;
mod bodies_invariants;
mod bodies_slide;
mod bodies_trace;
mod controller;
mod controller_corners;
mod controller_ledges;
mod controller_limits;
mod controller_replica;
mod controller_seams;
mod controller_trace;
mod controller_velocity;
mod debug_lines;
mod edits_vs_rebuild;
mod float_entry_points;
mod fuzz_regressions;
mod geometry_absurd;
mod loader_ascii;
mod loader_baked;
mod loader_fuzz;
mod loader_ldtk;
mod loader_replica_errors;
mod loader_tiled;
mod map_limits;
mod overlap_queries;
mod path;
mod path_absurd;
mod path_followed;
mod query_absurd_circles;
mod query_absurd_rays;
mod ray_batch;
mod ray_scenarios;
mod ray_vs_brute_force;
mod replica_data;
mod replica_objects;
mod replica_rays;
mod seam_culling;
mod serde_values;
mod snapshots;
mod sweep_box_corners;
mod temporary_segments;
mod toi_exact_vs_bisection;
mod volumes;
