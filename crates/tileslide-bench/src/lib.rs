//! Whole-scene benchmarks of tileslide against its peers, measured in the same run.

pub mod broad;
pub mod crowd;
pub mod paths;
pub mod peers;
pub mod rays;
