//! A monotone priority queue of `u32` keys: a radix heap (Ahuja, Mehlhorn, Orlin & Tarjan,
//! "Faster algorithms for the shortest path problem", 1990, in the one-level form of
//! Cherkassky, Goldberg & Silverstein 1999).
//!
//! A* with a consistent heuristic and Dijkstra pop keys in non-decreasing order and never
//! push a key below the last one popped. A radix heap uses that: bucket `b` holds the
//! keys whose highest bit differing from the last popped key is bit `b − 1` (bucket 0 the
//! keys equal to it). Popping takes from bucket 0; when it is empty, the lowest non-empty
//! bucket is emptied into lower ones around its least key. Each item moves down at most
//! 32 times, and in practice once or twice, so a push and a pop cost a few instructions
//! where a binary heap pays `log n` comparisons of unpredictable outcome.
//!
//! Items with equal keys come out last in, first out: after A* expands a node, its
//! children with the same `f` (those heading straight for the goal) are taken next, the
//! tie-break that keeps open ground from being expanded row after row.

/// Buckets: bucket 0 for keys equal to the last popped, then one per bit position.
const BUCKETS: usize = 33;

/// A radix heap of `(key, item)` pairs.
#[derive(Clone, Debug)]
pub(crate) struct RadixHeap {
    buckets: [Vec<(u32, u32)>; BUCKETS],
    /// The last key popped: no key below it may be pushed.
    last: u32,
    len: usize,
}

impl Default for RadixHeap {
    fn default() -> Self {
        Self {
            buckets: std::array::from_fn(|_| Vec::new()),
            last: 0,
            len: 0,
        }
    }
}

impl RadixHeap {
    /// Empties the heap and lets keys from 0 be pushed again; keeps the buckets' memory.
    pub fn clear(&mut self) {
        for bucket in &mut self.buckets {
            bucket.clear();
        }
        self.last = 0;
        self.len = 0;
    }

    /// The bucket of `key` relative to the last popped key.
    #[inline]
    fn bucket(&self, key: u32) -> usize {
        (u32::BITS - (key ^ self.last).leading_zeros()) as usize
    }

    /// Adds `item` with `key`, which must not be below the last key popped (the
    /// monotone property); a key below it is queued as the last key, which keeps the heap
    /// sound but out of order, so callers must not rely on that.
    #[inline]
    pub fn push(&mut self, key: u32, item: u32) {
        debug_assert!(key >= self.last, "radix heap: key {key} < {}", self.last);
        let key = key.max(self.last);
        let b = self.bucket(key);
        self.buckets[b].push((key, item));
        self.len += 1;
    }

    /// Removes an item with the least key, the most recently pushed among equals.
    #[inline]
    pub fn pop(&mut self) -> Option<(u32, u32)> {
        if self.buckets[0].is_empty() {
            if self.len == 0 {
                return None;
            }
            self.refill();
        }
        self.len -= 1;
        self.buckets[0].pop()
    }

    /// Moves the lowest non-empty bucket's items down around its least key.
    #[cold]
    fn refill(&mut self) {
        let Some(b) = (1..BUCKETS).find(|&b| !self.buckets[b].is_empty()) else {
            return;
        };
        let items = std::mem::take(&mut self.buckets[b]);
        self.last = items.iter().map(|&(k, _)| k).min().unwrap_or(self.last);
        for &(key, item) in &items {
            // Every item lands in a lower bucket: they share bits above b − 1 with the new
            // last key, which is one of them.
            let to = self.bucket(key);
            self.buckets[to].push((key, item));
        }
        // Hand the emptied vector's memory back to its bucket.
        let mut items = items;
        items.clear();
        self.buckets[b] = items;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// Against a sorted list: Dijkstra-like use, where each push is at least the last
        /// key popped.
        #[test]
        fn pops_in_key_order_like_a_sorted_list(
            steps in proptest::collection::vec((any::<bool>(), 0u32..5000), 1..400),
        ) {
            let mut heap = RadixHeap::default();
            let mut reference: Vec<u32> = Vec::new();
            let mut last = 0u32;
            for (k, &(pop, delta)) in steps.iter().enumerate() {
                if pop {
                    reference.sort_unstable();
                    let expected = (!reference.is_empty()).then(|| reference.remove(0));
                    let got = heap.pop().map(|(key, _)| key);
                    prop_assert_eq!(got, expected);
                    if let Some(key) = got {
                        last = key;
                    }
                } else {
                    let key = last.saturating_add(delta);
                    heap.push(key, k as u32);
                    reference.push(key);
                }
            }
        }
    }

    #[test]
    fn equal_keys_come_out_last_in_first_out() {
        let mut heap = RadixHeap::default();
        heap.push(7, 1);
        heap.push(7, 2);
        heap.push(9, 3);
        assert_eq!(heap.pop(), Some((7, 2)));
        heap.push(7, 4);
        assert_eq!(heap.pop(), Some((7, 4)));
        assert_eq!(heap.pop(), Some((7, 1)));
        assert_eq!(heap.pop(), Some((9, 3)));
        assert_eq!(heap.pop(), None);
    }

    #[test]
    fn clear_allows_small_keys_again() {
        let mut heap = RadixHeap::default();
        heap.push(1000, 0);
        assert_eq!(heap.pop(), Some((1000, 0)));
        heap.clear();
        heap.push(3, 1);
        assert_eq!(heap.pop(), Some((3, 1)));
    }
}
