//! Asking the processor to bring memory into its caches before it is read.
//!
//! A resolve reads, for each body, its neighbours' circles and positions, and slot order is
//! no spatial order (a game adds bodies as they come), so those are anywhere in the
//! per-body arrays: once the arrays outgrow the caches, every neighbour is a wait for
//! memory, and the resolve asks for the neighbours of the bodies a few slots on while the
//! present one resolves (`Resolver::prefetch_neighbours`: the crowd of 50,000 a fifth
//! faster on one thread). Filling the neighbours' rows does the same for the candidates'
//! discs. The `parallel` feature's waves need it more: a wave's bodies are every fifteenth
//! or so in slot order, so even a body's own entries are a cache line each, and the rows
//! and walls lists, laid out in slot order, are jumps too (docs/parallel.md).

/// Asks the processor to bring `items[index]` into its caches; nothing when `index` is
/// past the end, or on processors other than x86-64.
#[inline(always)]
pub(crate) fn prefetch<T>(items: &[T], index: usize) {
    #[cfg(target_arch = "x86_64")]
    if let Some(item) = items.get(index) {
        // SAFETY: a prefetch is a hint: it reads nothing the program sees and never faults,
        // whatever the address (here a valid one), and SSE is part of every x86-64.
        #[allow(unsafe_code)]
        unsafe {
            std::arch::x86_64::_mm_prefetch::<{ std::arch::x86_64::_MM_HINT_T0 }>(
                std::ptr::from_ref(item).cast(),
            );
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = (items, index);
}
