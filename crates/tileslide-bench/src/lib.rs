//! Whole-scene benchmarks of tileslide against its peers, measured in the same run.

pub mod broad;
pub mod crowd;
pub mod parry_vectors;
pub mod paths;
pub mod rays;
