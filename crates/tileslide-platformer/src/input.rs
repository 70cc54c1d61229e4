//! What the player is told to do each step.

/// What the player does this step.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Input {
    /// Sideways run, −1 (left) to 1 (right).
    pub run: f32,
    /// Start a jump (only on the ground).
    pub jump: bool,
    /// Drop through the one-way platform stood on.
    pub drop: bool,
}
