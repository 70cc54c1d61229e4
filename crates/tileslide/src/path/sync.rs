//! Catching up with the map: [`NavGrid::sync`] reads the map's edit journal and recomputes
//! the moves near each cell edited since the grid last caught up, and [`NavChange`] says
//! what that changed, for the paths a game keeps.

use std::sync::PoisonError;

use glam::Vec2;

use super::clearance::{ChangedMove, Clearance};
use super::{NavError, NavGrid, lattice};
use crate::geometry::{Aabb, Segment};
use crate::tiles::{JournalError, MapRevision, TileMap};

/// What the map's edits changed in a [`NavGrid`] since it last caught up (from
/// [`NavGrid::sync`]).
#[derive(Clone, Debug, PartialEq)]
pub struct NavChange {
    /// The moves whose clearance changed, edit after edit.
    moves: Vec<ChangedMove>,
    /// Per edited cell, in the order of the edits: where its moves end in `moves`, and
    /// their extent (map units; `None` when it changed no move).
    edits: Vec<(usize, Option<Aabb>)>,
    /// The extent of every changed move, or the whole map after a rebuild.
    region: Option<Aabb>,
    /// The rectangle of each edited cell, in the order of the edits.
    cells: Vec<Aabb>,
    /// True when the grid was built anew: the map's journal no longer reached back to it.
    rebuilt: bool,
}

impl NavChange {
    /// No change.
    fn none() -> Self {
        Self {
            moves: Vec::new(),
            edits: Vec::new(),
            region: None,
            cells: Vec::new(),
            rebuilt: false,
        }
    }

    /// True when no move's clearance changed (never after a rebuild).
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.moves.is_empty() && !self.rebuilt
    }

    /// True when the grid was more edits behind the map than the map remembers
    /// ([`JOURNAL_EDITS`](crate::limits::JOURNAL_EDITS)) and was built anew: which moves changed is
    /// not known, and every path counts as affected.
    #[must_use]
    pub fn is_rebuild(&self) -> bool {
        self.rebuilt
    }

    /// The region whose moves changed, if any (the whole map after a rebuild).
    #[must_use]
    pub fn region(&self) -> Option<Aabb> {
        self.region
    }

    /// Number of moves whose clearance changed (0 after a rebuild).
    #[must_use]
    pub fn changed_moves(&self) -> usize {
        self.moves.len()
    }

    /// Records the moves edited cell `cell` (its rectangle) changed.
    fn push_edit(&mut self, lattice: &lattice::Lattice, cell: Aabb, moves: Vec<ChangedMove>) {
        self.cells.push(cell);
        let region = moves.iter().fold(None, |acc: Option<Aabb>, m| {
            let p = lattice.position_of(m.node as usize);
            let (di, dj) = lattice::MOVES[m.dir as usize];
            let q = p + lattice.step * Vec2::new(di as f32, dj as f32);
            let b = Aabb::from_corners(p, q);
            Some(acc.map_or(b, |a| a.union(&b)))
        });
        self.moves.extend(moves);
        self.edits.push((self.moves.len(), region));
        if let Some(r) = region {
            self.region = Some(self.region.map_or(r, |a| a.union(&r)));
        }
    }

    /// True when some edited cell comes within `radius` of a run between consecutive
    /// `points`: its new walls may meet a circle of that radius on the run, whichever
    /// lattice moves it changed (a run is not a lattice move: filling a slope beside a
    /// run can block it while every move near it stays open).
    pub(super) fn touches_runs(&self, points: &[Vec2], radius: f32) -> bool {
        // A little more than the radius, for rounding: a cell that close may block the run.
        let reach = radius * (1.0 + 1e-4) + 1e-4;
        self.cells.iter().any(|cell| {
            let grown = cell.expand(reach);
            points
                .windows(2)
                .any(|run| grown.overlaps_segment(&Segment::new(run[0], run[1])))
        })
    }

    /// True when some edit changed moves within `bounds` and opened or closed some move for
    /// a circle needing `need` clearance steps (what [`NavPath::is_affected_by`] asks, edit by
    /// edit, as if the grid had caught up after each).
    ///
    /// [`NavPath::is_affected_by`]: super::NavPath::is_affected_by
    pub(super) fn affects(&self, bounds: &Aabb, need: u16) -> bool {
        if self.rebuilt {
            return true;
        }
        let mut start = 0;
        self.edits.iter().any(|&(end, region)| {
            let moves = &self.moves[start..end];
            start = end;
            region.is_some_and(|r| r.overlaps(bounds))
                && moves
                    .iter()
                    .any(|m| (m.before >= need) != (m.after >= need))
        })
    }
}

impl NavGrid {
    /// Catches up with `map`'s tile edits since the grid was built or last synced, and
    /// says what changed. Call it once after editing the map, before querying: until then
    /// queries refuse with [`NavError::Stale`]. Temporary segments never block paths, so
    /// they need no sync.
    ///
    /// Each edited cell costs the same as on any map size: the grid recomputes the moves
    /// near it (see `docs/path.md`), and is then what [`NavGrid::new`] would build. A grid
    /// more edits behind than the map remembers ([`JOURNAL_EDITS`](crate::limits::JOURNAL_EDITS))
    /// is built anew, and the change says so ([`NavChange::is_rebuild`]).
    ///
    /// # Errors
    /// [`NavError::OtherMap`] when `map` is not the map the grid was built for (nor a clone
    /// of it at a state the grid has seen); the grid is left as it was.
    pub fn sync(&mut self, map: &TileMap) -> Result<NavChange, NavError> {
        let mut change = NavChange::none();
        match map.changes_since(&self.revision) {
            Err(JournalError::OtherMap) => return Err(NavError::OtherMap),
            Err(JournalError::Overrun { .. }) => {
                self.table = Clearance::build(map, self.max_radius, self.table.mask);
                self.memory_mut().classes.clear();
                change.rebuilt = true;
                change.region = Some(map.bounds());
            }
            Ok(cells) if cells.len() == 0 => return Ok(change),
            Ok(cells) => {
                for cell in cells {
                    let moves = self.table.update_cell(map, cell);
                    let memory = self
                        .memory
                        .get_mut()
                        .unwrap_or_else(PoisonError::into_inner);
                    for class in &mut memory.classes {
                        class.apply(&self.table, &moves);
                    }
                    change.push_edit(&self.table.lattice, map.cell_rect(cell), moves);
                }
            }
        }
        self.revision = map.revision();
        Ok(change)
    }
}

/// Why navigation data caught up with `map` at `revision` cannot answer on it when the
/// map's tiles have changed since: it is behind, or it is another map's.
pub(super) fn behind(map: &TileMap, revision: &MapRevision) -> NavError {
    match map.changes_since(revision) {
        Err(JournalError::OtherMap) => NavError::OtherMap,
        _ => NavError::Stale,
    }
}
