//! A map's revisions and its journal of tile edits: how everything that remembers map data
//! (the resolver's kept walls and settled bodies, navigation grids, flow fields) catches up
//! with the map by itself, without being told which cells changed.
//!
//! A system remembers the [`MapRevision`] it last saw and asks the map for the cells edited
//! since ([`TileMap::changes_since`]). The map keeps its latest [`JOURNAL_EDITS`] edits; a
//! system further behind is told so ([`JournalError::Overrun`]) and rebuilds.
//!
//! **Identity.** Revisions are numbered per map, not by a process-wide counter: a map and
//! its clones draw them from one counter they share (their *lineage*), which nothing else
//! can reach. A system holds a weak reference to that counter and compares addresses, so a
//! revision of one map is never taken for a revision of another, even after the first map
//! is dropped (the weak reference keeps the address from being reused).
//!
//! **Clones.** A clone is the same map as its original at the moment it is made: a system
//! caught up with the original then catches up with the clone too (clone a map and its
//! navigation grid together, edit either copy, and sync each). After that, each copy's
//! edits take numbers the other never had, so a system that saw an edit of one copy is
//! refused by the other ([`JournalError::OtherMap`]), as long as the other's journal still
//! reaches back to that edit; a system older than anything the journal holds rebuilds.

use std::collections::VecDeque;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Weak};

use thiserror::Error;

use super::{Cell, TileMap};

/// How many of its latest tile edits a map remembers: a system further behind than this
/// rebuilds what it keeps of the map ([`JournalError::Overrun`]).
pub const JOURNAL_EDITS: usize = 4096;

/// The counter a map and its clones draw revisions from. Its address is the lineage's
/// identity.
#[derive(Debug, Default)]
struct Lineage(AtomicU64);

impl Lineage {
    fn next(&self) -> u64 {
        self.0.fetch_add(1, Ordering::Relaxed)
    }
}

/// A state of a map, as a system that remembers map data keeps it: which map (or clone of
/// it) and which revision of its tiles and temporary segments.
///
/// Two revisions are equal only if they are of the same lineage (a map and its clones) and
/// name the same tiles and the same temporaries. It keeps no map alive.
///
/// ```
/// # use tileslide::{io::ascii, Cell};
/// let mut map = ascii::parse("###\n#.#\n###", "doc.txt", 1.0)?;
/// let seen = map.revision();
/// map.clear_tile(Cell::new(1, 0))?;
/// let edited: Vec<Cell> = map.changes_since(&seen)?.collect();
/// assert_eq!(edited, [Cell::new(1, 0)]);
/// assert_eq!(map.changes_since(&map.revision())?.len(), 0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug)]
pub struct MapRevision {
    lineage: Weak<Lineage>,
    tiles: u64,
    temporaries: u64,
}

impl PartialEq for MapRevision {
    fn eq(&self, other: &Self) -> bool {
        Weak::ptr_eq(&self.lineage, &other.lineage)
            && self.tiles == other.tiles
            && self.temporaries == other.temporaries
    }
}

impl Eq for MapRevision {}

/// Why a map cannot list the edits since a revision.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum JournalError {
    /// The revision is this map's (or its lineage's), but older than the
    /// [`JOURNAL_EDITS`] edits the map remembers: rebuild from the map as it is.
    #[error(
        "the map remembers its latest {kept} edits and the revision asked about is older: \
         rebuild from the map as it is"
    )]
    Overrun {
        /// Edits the map remembers ([`JOURNAL_EDITS`]).
        kept: usize,
    },
    /// The revision is not one this map had: another map's, or a clone's edited apart from
    /// this one after the clone was made.
    #[error("the revision is not one this map had: another map's, or a clone's edited since")]
    OtherMap,
}

/// A map's revisions and latest tile edits (see the module docs).
#[derive(Clone, Debug)]
pub(crate) struct Journal {
    lineage: Arc<Lineage>,
    tiles: u64,
    temporaries: u64,
    /// The latest tile edits, oldest first: each the tiles revision before it and the cell.
    /// The revisions increase along the deque.
    edits: VecDeque<(u64, Cell)>,
    /// True once an edit has been dropped from the front: the journal no longer reaches
    /// back to the lineage's first state.
    overrun: bool,
}

impl Default for Journal {
    fn default() -> Self {
        let lineage = Arc::new(Lineage::default());
        let (tiles, temporaries) = (lineage.next(), lineage.next());
        Self {
            lineage,
            tiles,
            temporaries,
            edits: VecDeque::new(),
            overrun: false,
        }
    }
}

impl Journal {
    /// The state the map is in.
    pub fn revision(&self) -> MapRevision {
        MapRevision {
            lineage: Arc::downgrade(&self.lineage),
            tiles: self.tiles,
            temporaries: self.temporaries,
        }
    }

    /// Records an edit of `cell`'s tile.
    pub fn record_edit(&mut self, cell: Cell) {
        if self.edits.len() == JOURNAL_EDITS {
            self.edits.pop_front();
            self.overrun = true;
        }
        self.edits.push_back((self.tiles, cell));
        self.tiles = self.lineage.next();
    }

    /// Records a change of the temporary segments.
    pub fn record_temporaries(&mut self) {
        self.temporaries = self.lineage.next();
    }

    fn is_own(&self, revision: &MapRevision) -> bool {
        std::ptr::eq(revision.lineage.as_ptr(), Arc::as_ptr(&self.lineage))
    }

    /// True when the map's tiles are as they were at `revision` (the temporaries may
    /// differ). O(1): what every navigation query checks.
    #[inline]
    pub fn tiles_at(&self, revision: &MapRevision) -> bool {
        revision.tiles == self.tiles && self.is_own(revision)
    }

    /// True when the map's temporary segments are as they were at `revision`. (False
    /// tells nothing: they may have been changed and changed back.)
    pub fn temporaries_at(&self, revision: &MapRevision) -> bool {
        revision.temporaries == self.temporaries && self.is_own(revision)
    }

    /// The cells edited since `revision`, oldest first (a cell edited twice is listed
    /// twice).
    pub fn changes_since(
        &self,
        revision: &MapRevision,
    ) -> Result<impl ExactSizeIterator<Item = Cell> + Clone + '_, JournalError> {
        if !self.is_own(revision) {
            return Err(JournalError::OtherMap);
        }
        let from = if revision.tiles == self.tiles {
            self.edits.len()
        } else {
            let at = self
                .edits
                .partition_point(|&(before, _)| before < revision.tiles);
            match self.edits.get(at) {
                Some(&(before, _)) if before == revision.tiles => at,
                // Older than the oldest edit kept, and edits were dropped: the map may
                // have been there.
                _ if at == 0 && self.overrun => {
                    return Err(JournalError::Overrun {
                        kept: JOURNAL_EDITS,
                    });
                }
                // A state the journal would list if the map had had it.
                _ => return Err(JournalError::OtherMap),
            }
        };
        Ok(self.edits.range(from..).map(|&(_, cell)| cell))
    }
}

impl TileMap {
    /// The state the map is in now: what a system that remembers map data keeps, to ask
    /// [`changes_since`](Self::changes_since) later.
    #[must_use]
    pub fn revision(&self) -> MapRevision {
        self.journal.revision()
    }

    /// The cells whose tiles were edited since the map was at `revision`, oldest first (a
    /// cell edited twice is listed twice; nothing when the tiles are as they were). Edits
    /// change the active segments of the cell and its four neighbours, and the end-point
    /// links within two cells of it (see [`set_tile`](Self::set_tile)). Temporary
    /// segments are not edits.
    ///
    /// # Errors
    /// [`JournalError::Overrun`] when `revision` is older than the map's latest
    /// [`JOURNAL_EDITS`] edits (rebuild from the map as it is);
    /// [`JournalError::OtherMap`] when the map never had `revision`: another map's, or a
    /// clone's after the two were edited apart.
    pub fn changes_since(
        &self,
        revision: &MapRevision,
    ) -> Result<impl ExactSizeIterator<Item = Cell> + Clone + '_, JournalError> {
        self.journal.changes_since(revision)
    }

    /// True when the map's tiles are as they were at `revision`, in O(1).
    #[inline]
    pub(crate) fn tiles_at(&self, revision: &MapRevision) -> bool {
        self.journal.tiles_at(revision)
    }

    /// True when the map's temporary segments are as they were at `revision` (false tells
    /// nothing: they may have been changed back).
    pub(crate) fn temporaries_at(&self, revision: &MapRevision) -> bool {
        self.journal.temporaries_at(revision)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cells(journal: &Journal, since: &MapRevision) -> Result<Vec<Cell>, JournalError> {
        journal.changes_since(since).map(Iterator::collect)
    }

    #[test]
    fn the_edits_since_a_revision_are_listed_oldest_first() {
        let mut journal = Journal::default();
        let start = journal.revision();
        journal.record_edit(Cell::new(1, 2));
        let middle = journal.revision();
        journal.record_edit(Cell::new(3, 4));
        journal.record_temporaries();
        assert_eq!(
            cells(&journal, &start),
            Ok(vec![Cell::new(1, 2), Cell::new(3, 4)])
        );
        assert_eq!(cells(&journal, &middle), Ok(vec![Cell::new(3, 4)]));
        assert_eq!(cells(&journal, &journal.revision()), Ok(vec![]));
        assert!(journal.tiles_at(&journal.revision()) && !journal.tiles_at(&middle));
        assert!(!journal.temporaries_at(&middle));
    }

    #[test]
    fn a_revision_older_than_the_journal_is_an_overrun() {
        let mut journal = Journal::default();
        let start = journal.revision();
        for k in 0..JOURNAL_EDITS as u32 {
            journal.record_edit(Cell::new(k, 0));
        }
        assert_eq!(cells(&journal, &start).map(|c| c.len()), Ok(JOURNAL_EDITS));
        journal.record_edit(Cell::new(0, 1));
        assert_eq!(
            cells(&journal, &start),
            Err(JournalError::Overrun {
                kept: JOURNAL_EDITS
            })
        );
    }

    #[test]
    fn another_lineage_or_a_clone_edited_apart_is_another_map() {
        let mut journal = Journal::default();
        assert_eq!(
            cells(&Journal::default(), &journal.revision()),
            Err(JournalError::OtherMap)
        );
        let before = journal.revision();
        let mut clone = journal.clone();
        assert_eq!(
            clone.revision(),
            journal.revision(),
            "a clone is the same map"
        );
        journal.record_edit(Cell::new(1, 1));
        clone.record_edit(Cell::new(2, 2));
        assert_ne!(clone.revision().tiles, journal.revision().tiles);
        assert_eq!(cells(&clone, &before), Ok(vec![Cell::new(2, 2)]));
        assert_eq!(
            cells(&clone, &journal.revision()),
            Err(JournalError::OtherMap)
        );
        assert_eq!(
            cells(&journal, &clone.revision()),
            Err(JournalError::OtherMap)
        );
    }
}
