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

    /// The slot's generation: how many times the slot was given out before this body.
    #[must_use]
    pub fn generation(self) -> u32 {
        self.generation
    }

    /// The handle of slot `index` at `generation`, as [`index`](Self::index) and
    /// [`generation`](Self::generation) gave them: what a binding to another language
    /// passes by value. A made-up handle is harmless: [`Bodies`](crate::Bodies) answers it
    /// with [`BodyError::StaleHandle`](crate::BodyError::StaleHandle) unless it names a
    /// live body.
    ///
    /// ```
    /// use tileslide::{Bodies, BodyDesc, BodyHandle, BodyShape, Vec2};
    /// let mut bodies = Bodies::new();
    /// let h = bodies.add(BodyDesc::new(Vec2::ZERO, BodyShape::circle(0.5)?))?;
    /// assert_eq!(BodyHandle::from_parts(h.index(), h.generation()), h);
    /// assert!(bodies.get(BodyHandle::from_parts(7, 0)).is_err());
    /// # Ok::<(), tileslide::BodyError>(())
    /// ```
    #[must_use]
    pub fn from_parts(index: u32, generation: u32) -> Self {
        Self { index, generation }
    }
}
