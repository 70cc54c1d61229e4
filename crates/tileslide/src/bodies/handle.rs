//! A body's handle: a slot index and the slot's generation.

/// A body's handle. Handles are generational: once a body is removed its handle is stale
/// for good, even after its slot is reused, and every call with it returns
/// [`BodyError::StaleHandle`](crate::BodyError::StaleHandle).
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct BodyHandle {
    pub(super) index: u32,
    pub(super) generation: u32,
}

impl BodyHandle {
    /// The slot index (small, dense; reused after a removal). Bodies are resolved in slot
    /// order.
    #[must_use]
    pub fn index(self) -> u32 {
        self.index
    }
}
