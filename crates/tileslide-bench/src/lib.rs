//! Whole-scene benchmarks of tileslide against its peers, measured in the same run.
#![forbid(unsafe_code)]

pub mod box2d_map;
pub mod broad;
pub mod crowd;
pub mod parry_vectors;
pub mod paths;
pub mod rays;
pub mod threads;
pub mod wall_loops;
