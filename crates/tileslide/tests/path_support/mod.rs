//! Shared by `tests/path.rs`: references for the navigation grid computed without
//! `tileslide::path`, from the map's own segments, in `f64`.
//!
//! - [`walls`]: every blocking segment of a map and exact distances to it;
//! - [`lattice_reference`]: the half-cell lattice graph by brute force;
//! - [`any_angle`]: a lower bound of the exact any-angle shortest path of a disc among
//!   rectangular obstacles (visibility graph of inscribed polygons);
//! - [`split_mix`]: a seeded random source for picking query points.

// Each test uses a different part of this module.
#![allow(dead_code)]

pub mod any_angle;
pub mod lattice_reference;
pub mod split_mix;
pub mod walls;
