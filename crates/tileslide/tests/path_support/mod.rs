//! Shared by `tests/path.rs` and `tests/path_followed.rs`: references for the navigation
//! grid computed without `tileslide::path`, from the map's own segments, in `f64`, and the
//! points the queries start from.
//!
//! - [`walls`]: every blocking segment of a map and exact distances to it;
//! - [`lattice_reference`]: the half-cell lattice graph by brute force;
//! - [`any_angle`]: a lower bound of the exact any-angle shortest path of a disc among
//!   rectangular obstacles (visibility graph of inscribed polygons);
//! - [`query_points`]: random points where a circle fits, for queries.

// Each test uses a different part of this module.
#![allow(dead_code)]

pub mod any_angle;
pub mod lattice_reference;
pub mod query_points;
pub mod walls;
