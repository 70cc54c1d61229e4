//! The fixed step: every system counts time in steps of [`DT`] seconds, never by a clock.

/// Steps per second of game time.
pub const STEPS_PER_SECOND: u32 = 30;
/// The fixed step (seconds).
pub const DT: f32 = 1.0 / STEPS_PER_SECOND as f32;
