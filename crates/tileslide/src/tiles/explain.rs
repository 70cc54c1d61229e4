//! Why a cell's segments are what they are: which parts of its tile's segments seam culling
//! hides and which neighbouring segment hides each, and how each active piece's ends join
//! the surface around them (and so whether a swept circle must round them).
//!
//! Nothing here decides anything: the answers come from the same rules the map applies
//! (`culling::covers_across`, `continuity::end_join`) and from the links it stored, so an
//! explanation cannot disagree with what queries, bodies and characters see.

use glam::Vec2;

use super::culling::{CellSide, boundary_side, covers_across, seam_tolerance};
use super::map::TileMap;
use super::store::{CAP_A, CAP_B};
use super::{Cell, MapError, SegmentFlags, SegmentRef, TileId};
use crate::geometry::Segment;

/// A segment of the tile placed in a cell: the cell, its tile, and the segment's index in
/// the tile's shape (as [`TileShape::segments`](crate::TileShape::segments) lists them).
/// Unlike a [`SegmentRef`], it names the same segment until the cell's tile changes,
/// whatever its neighbours do.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct PlacedSegment {
    /// The cell.
    pub cell: Cell,
    /// The tile in it.
    pub tile: TileId,
    /// The segment's index in the tile's shape.
    pub index: u32,
}

/// Where a wall a body or a character met comes from: a tile's segment (the tile segment
/// and the active piece of it met) or a temporary segment.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum WallSource {
    /// An active segment of a tile.
    Tile {
        /// The tile segment it is (a piece of).
        segment: PlacedSegment,
        /// The active segment (valid until the cell or a neighbour is edited).
        active: SegmentRef,
    },
    /// A temporary segment.
    Temporary {
        /// Who submitted it.
        owner: super::Owner,
        /// Its index in [`TileMap::temporaries`](crate::TileMap::temporaries).
        index: usize,
    },
}

impl WallSource {
    /// The source of active segment `active` of `map`, or `None` when it names none.
    pub(crate) fn tile(map: &TileMap, active: SegmentRef) -> Option<Self> {
        let a = map.active_segment(active)?;
        Some(WallSource::Tile {
            segment: PlacedSegment {
                cell: active.cell,
                tile: a.tile,
                index: a.source,
            },
            active,
        })
    }
}

/// Why each segment of a cell's tile is active or hidden, and how its active pieces end:
/// what [`TileMap::explain_cell`] returns.
#[derive(Clone, Debug, PartialEq)]
pub struct CellExplanation {
    /// The cell explained.
    pub cell: Cell,
    /// Its tile (`None`: an empty cell, with no segments).
    pub tile: Option<TileId>,
    /// Each segment of the tile's shape, in the shape's order.
    pub segments: Vec<SegmentExplanation>,
}

/// One segment of a cell's tile: the parts of it that are hidden and by what, and its active
/// pieces.
#[derive(Clone, Debug, PartialEq)]
pub struct SegmentExplanation {
    /// Index in the tile's shape.
    pub index: u32,
    /// The segment in world coordinates, in its shape's direction.
    pub segment: Segment,
    /// Its outward unit normal.
    pub normal: Vec2,
    /// Its flags.
    pub flags: SegmentFlags,
    /// The side of the cell it lies on and faces out of, if any. Only such a segment can be
    /// hidden: by a solid segment of the neighbour across that side that lies on the same
    /// line and faces back.
    pub side: Option<CellSide>,
    /// The parts a neighbour's segment hides, one per hiding segment (in that segment's
    /// shape order; two may overlap). Empty for a segment wholly active.
    pub hidden: Vec<HiddenPart>,
    /// The active pieces left (none when it is wholly hidden), in the order the map stores
    /// them.
    pub active: Vec<ActivePiece>,
}

impl SegmentExplanation {
    /// Whether no part of the segment is active.
    #[must_use]
    pub fn is_hidden(&self) -> bool {
        self.active.is_empty()
    }
}

/// A part of a tile segment hidden by a neighbour's segment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HiddenPart {
    /// The hidden part, in world coordinates (in the hidden segment's direction).
    pub part: Segment,
    /// The neighbour's segment that hides it: solid, on the same line, facing back.
    pub by: PlacedSegment,
}

/// An active piece of a tile segment: what queries test.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ActivePiece {
    /// The active segment's name in the map (valid until the cell or a neighbour is edited).
    pub active: SegmentRef,
    /// The piece in world coordinates, running with its normal on the right as every active
    /// segment does (see [`ActiveSegment`](crate::ActiveSegment)).
    pub segment: Segment,
    /// Its two ends, `segment.a` then `segment.b`.
    pub ends: [PieceEnd; 2],
}

/// An end of an active piece: the segment the surface continues into there and how it
/// joins it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PieceEnd {
    /// The end point.
    pub point: Vec2,
    /// The active segment the surface continues into (the one sharing the point whose
    /// normal is closest to this one's), if any.
    pub continues: Option<SegmentRef>,
    /// The tile segment that active segment comes from.
    pub into: Option<PlacedSegment>,
    /// How the surface goes on, and so whether a swept circle must round the end.
    pub join: super::EndJoin,
}

impl TileMap {
    /// Why each segment of `cell`'s tile is active or hidden, and how each active piece
    /// ends: the seam culling and end-point links the map keeps, explained.
    ///
    /// A segment on a side of its cell is hidden where a solid segment of the neighbour
    /// across that side lies on the same line and faces back (both are then unreachable, and
    /// a body sliding over the seam would catch on their ends). Each active piece's end
    /// either continues into a neighbouring segment, flat or concave, with the same flags
    /// (no cap: a circle sliding there sees one surface), or needs a rounded cap
    /// ([`EndJoin`](crate::EndJoin) says why). See `docs/seams.md`.
    ///
    /// ```
    /// use tileslide::{io::ascii, Cell, CellSide, EndJoin};
    /// // Two blocks side by side on row 1.
    /// let map = ascii::parse("...\n.##", "seam.txt", 1.0)?;
    /// let left = map.explain_cell(Cell::new(1, 1))?;
    /// // Its right edge (x = 2) is hidden by the left edge of the block in cell (2, 1).
    /// let seam = left.segments.iter().find(|s| s.side == Some(CellSide::MaxX)).unwrap();
    /// assert!(seam.is_hidden());
    /// assert_eq!(seam.hidden[0].by.cell, Cell::new(2, 1));
    /// // Its top edge continues flat into the neighbour's top edge at x = 2: no cap there,
    /// // and a convex corner (a cap) at x = 1.
    /// let top = left.segments.iter().find(|s| s.side == Some(CellSide::MinY)).unwrap();
    /// let ends = top.active[0].ends;
    /// let at_seam = ends.iter().find(|e| e.point.x == 2.0).unwrap();
    /// assert_eq!(at_seam.join, EndJoin::Flat);
    /// assert_eq!(at_seam.into.map(|s| s.cell), Some(Cell::new(2, 1)));
    /// let at_corner = ends.iter().find(|e| e.point.x == 1.0).unwrap();
    /// assert_eq!(at_corner.join, EndJoin::Convex);
    /// assert!(at_corner.join.needs_cap());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// [`MapError::CellOutOfBounds`] for a cell outside the map.
    pub fn explain_cell(&self, cell: Cell) -> Result<CellExplanation, MapError> {
        if cell.col >= self.width() || cell.row >= self.height() {
            return Err(MapError::CellOutOfBounds {
                cell,
                width: self.width(),
                height: self.height(),
            });
        }
        let tile = self.tile(cell);
        let Some(shape) = tile.and_then(|id| self.tile_set().shape(id)) else {
            return Ok(CellExplanation {
                cell,
                tile,
                segments: Vec::new(),
            });
        };
        let size = self.cell_size();
        let eps = seam_tolerance(size);
        let corner = self.cell_corner(cell);
        let index = (cell.row * self.width() + cell.col) as usize;
        let hot = self.store.cell(index);
        let mut segments = Vec::with_capacity(shape.segments().len());
        for (k, s) in shape.segments().iter().enumerate() {
            let side = boundary_side(s, size, eps);
            let mut hidden = Vec::new();
            if let Some(side) = side
                && let Some(next) = self.neighbour(cell, side)
                && let Some(next_tile) = self.tile(next)
                && let Some(next_shape) = self.tile_set().shape(next_tile)
            {
                let (ua, ub) = (side.along(s.a), side.along(s.b));
                for (j, (lo, hi)) in covers_across(side, next_shape, size, eps) {
                    // The covered interval, as fractions along a → b.
                    let f = |u: f32| ((u - ua) / (ub - ua)).clamp(0.0, 1.0);
                    let (f0, f1) = (f(lo), f(hi));
                    let (f0, f1) = (f0.min(f1), f0.max(f1));
                    if (f1 - f0) * (ub - ua).abs() <= eps {
                        continue;
                    }
                    let at = |f: f32| corner + s.a + (s.b - s.a) * f;
                    hidden.push(HiddenPart {
                        part: Segment::new(at(f0), at(f1)),
                        by: PlacedSegment {
                            cell: next,
                            tile: next_tile,
                            index: j as u32,
                        },
                    });
                }
            }
            let active = hot
                .iter()
                .enumerate()
                .filter(|(_, h)| usize::from(h.source) == k)
                .map(|(i, h)| self.explain_piece(cell, index, i, Segment::new(h.a, h.b())))
                .collect();
            segments.push(SegmentExplanation {
                index: k as u32,
                segment: Segment::new(corner + s.a, corner + s.b),
                normal: s.normal,
                flags: s.flags,
                side,
                hidden,
                active,
            });
        }
        Ok(CellExplanation {
            cell,
            tile,
            segments,
        })
    }

    /// Active segment `i` of the cell at row-major `index`, `segment`, with its ends.
    fn explain_piece(&self, cell: Cell, index: usize, i: usize, segment: Segment) -> ActivePiece {
        let seg = self.store.cell(index)[i];
        let links = self.store.links(index)[i];
        let caps = self.store.caps(index)[i];
        let ends = [0, 1].map(|k| {
            let continues = links[k].resolve(cell);
            let next = continues.and_then(|r| {
                let at = (r.cell.row * self.width() + r.cell.col) as usize;
                let h = *self.store.cell(at).get(r.index as usize)?;
                Some((r.cell, h))
            });
            let join = super::continuity::end_join(&seg, next.as_ref().map(|(_, h)| h), k);
            debug_assert_eq!(
                join.needs_cap(),
                caps & [CAP_A, CAP_B][k] != 0,
                "the stored cap and the join disagree"
            );
            PieceEnd {
                point: if k == 0 { segment.a } else { segment.b },
                continues,
                into: next.and_then(|(c, h)| {
                    Some(PlacedSegment {
                        cell: c,
                        tile: self.tile(c)?,
                        index: h.source.into(),
                    })
                }),
                join,
            }
        });
        ActivePiece {
            active: SegmentRef {
                cell,
                index: i as u32,
            },
            segment,
            ends,
        }
    }

    /// The cell across `side` of `cell`, if it is in the map.
    fn neighbour(&self, cell: Cell, side: CellSide) -> Option<Cell> {
        let (dc, dr) = side.neighbour_offset();
        let (c, r) = (i64::from(cell.col) + dc, i64::from(cell.row) + dr);
        (c >= 0 && r >= 0 && c < i64::from(self.width()) && r < i64::from(self.height()))
            .then(|| Cell::new(c as u32, r as u32))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::ascii;
    use crate::tiles::EndJoin;

    fn map(text: &str) -> TileMap {
        ascii::parse(text, "explain.txt", 1.0).unwrap_or_else(|e| panic!("{e}"))
    }

    fn v(x: f32, y: f32) -> Vec2 {
        Vec2::new(x, y)
    }

    fn on_side(e: &CellExplanation, side: CellSide) -> &SegmentExplanation {
        e.segments
            .iter()
            .find(|s| s.side == Some(side))
            .unwrap_or_else(|| panic!("no segment on {side:?} in {e:?}"))
    }

    fn end_at(piece: &ActivePiece, p: Vec2) -> PieceEnd {
        *piece
            .ends
            .iter()
            .find(|e| e.point == p)
            .unwrap_or_else(|| panic!("no end at {p} in {piece:?}"))
    }

    #[test]
    fn a_floor_of_three_blocks_hides_its_seams_and_joins_flat() {
        // Row 1: three blocks. The middle one keeps only its top and bottom.
        let m = map("...\n###\n...");
        let e = m.explain_cell(Cell::new(1, 1)).unwrap();
        assert_eq!(e.tile, m.tile(Cell::new(1, 1)));
        let left = on_side(&e, CellSide::MinX);
        assert!(left.is_hidden());
        assert_eq!(
            left.hidden,
            [HiddenPart {
                part: left.segment,
                by: PlacedSegment {
                    cell: Cell::new(0, 1),
                    tile: m.tile(Cell::new(0, 1)).unwrap(),
                    index: on_side(&m.explain_cell(Cell::new(0, 1)).unwrap(), CellSide::MaxX).index,
                },
            }]
        );
        assert!(on_side(&e, CellSide::MaxX).is_hidden());
        let top = on_side(&e, CellSide::MinY);
        assert!(top.hidden.is_empty());
        assert_eq!(top.active.len(), 1);
        let piece = top.active[0];
        // Both ends continue flat into the neighbours' top faces: no caps.
        for (x, col) in [(1.0, 0), (2.0, 2)] {
            let end = end_at(&piece, v(x, 1.0));
            assert_eq!(end.join, EndJoin::Flat, "{end:?}");
            let into = end.into.unwrap();
            assert_eq!(into.cell, Cell::new(col, 1));
            let neighbour = m.explain_cell(into.cell).unwrap();
            let theirs = on_side(&neighbour, CellSide::MinY);
            assert_eq!(into.index, theirs.index);
            assert_eq!(end.continues, Some(theirs.active[0].active));
        }
        // The end block's outer top corner is convex: a cap.
        let corner = on_side(&m.explain_cell(Cell::new(0, 1)).unwrap(), CellSide::MinY).active[0];
        assert_eq!(end_at(&corner, v(0.0, 1.0)).join, EndJoin::Convex);
    }

    #[test]
    fn a_block_on_a_floor_makes_concave_corners_and_hides_the_floor_under_it() {
        // A block at (1, 0) standing on the floor row 1.
        let m = map(".#.\n###");
        let floor = m.explain_cell(Cell::new(1, 1)).unwrap();
        let top = on_side(&floor, CellSide::MinY);
        assert!(top.is_hidden());
        assert_eq!(top.hidden[0].by.cell, Cell::new(1, 0));
        // The floor left of the block meets the block's left face at (1, 1): concave.
        let left = on_side(&m.explain_cell(Cell::new(0, 1)).unwrap(), CellSide::MinY).active[0];
        let end = end_at(&left, v(1.0, 1.0));
        assert_eq!(end.join, EndJoin::Concave);
        assert_eq!(end.into.map(|s| s.cell), Some(Cell::new(1, 0)));
        assert!(!end.join.needs_cap());
        // The far end of the map's floor has nothing beyond it... but turns down its side.
        assert_eq!(end_at(&left, v(0.0, 1.0)).join, EndJoin::Convex);
    }

    #[test]
    fn one_way_platforms_hide_nothing_and_keep_their_caps() {
        // A platform beside a block and a platform beside another: caps everywhere.
        let m = map("#==.");
        let platform = m.explain_cell(Cell::new(1, 0)).unwrap();
        assert_eq!(platform.segments.len(), 1);
        let s = &platform.segments[0];
        assert_eq!(s.flags, SegmentFlags::ONE_WAY);
        assert!(s.hidden.is_empty());
        let piece = s.active[0];
        // Into the next platform (same flags): capped because it is one-way.
        assert_eq!(end_at(&piece, v(2.0, 0.0)).join, EndJoin::OneWay);
        // Into the block's top face: the flags change.
        assert_eq!(end_at(&piece, v(1.0, 0.0)).join, EndJoin::FlagsChange);
        // The block's right face is not hidden by the platform (which is not solid).
        let block = m.explain_cell(Cell::new(0, 0)).unwrap();
        assert!(!on_side(&block, CellSide::MaxX).is_hidden());
        // The last platform's far end: nothing continues it.
        let last = m.explain_cell(Cell::new(2, 0)).unwrap().segments[0].active[0];
        assert_eq!(end_at(&last, v(3.0, 0.0)).join, EndJoin::Open);
        assert_eq!(end_at(&last, v(3.0, 0.0)).continues, None);
    }

    #[test]
    fn a_half_block_beside_a_block_hides_half_its_side() {
        use crate::{TileSet, TileShape};
        use std::sync::Arc;
        let mut set = TileSet::new(Vec2::ONE).unwrap();
        let square = TileShape::polygon(&[v(0.0, 0.0), v(1.0, 0.0), v(1.0, 1.0), v(0.0, 1.0)]);
        let half = TileShape::polygon(&[v(0.0, 0.5), v(1.0, 0.5), v(1.0, 1.0), v(0.0, 1.0)]);
        set.insert(TileId(1), square.unwrap()).unwrap();
        set.insert(TileId(2), half.unwrap()).unwrap();
        let mut m = TileMap::new(Arc::new(set), 2, 1, Vec2::ZERO).unwrap();
        m.set_tile(Cell::new(0, 0), Some(TileId(1))).unwrap();
        m.set_tile(Cell::new(1, 0), Some(TileId(2))).unwrap();
        let e = m.explain_cell(Cell::new(0, 0)).unwrap();
        let right = on_side(&e, CellSide::MaxX);
        assert_eq!(right.hidden.len(), 1);
        let part = right.hidden[0].part;
        assert_eq!(part.a.y.min(part.b.y), 0.5);
        assert_eq!(part.a.y.max(part.b.y), 1.0);
        assert_eq!(right.hidden[0].by.tile, TileId(2));
        assert_eq!(right.active.len(), 1);
        let piece = right.active[0].segment;
        assert_eq!(piece.a.y.min(piece.b.y), 0.0);
        assert_eq!(piece.a.y.max(piece.b.y), 0.5);
    }

    #[test]
    fn every_join_agrees_with_the_stored_caps_on_a_mixed_map() {
        let m = map("#####\n#./\\#\n#=.=#\n##/##\n#####");
        for row in 0..m.height() {
            for col in 0..m.width() {
                let cell = Cell::new(col, row);
                let e = m.explain_cell(cell).unwrap();
                let index = (row * m.width() + col) as usize;
                let caps = m.store.caps(index);
                let mut pieces = 0;
                for s in &e.segments {
                    for p in &s.active {
                        pieces += 1;
                        let stored = caps[p.active.index as usize];
                        assert_eq!(p.ends[0].join.needs_cap(), stored & CAP_A != 0);
                        assert_eq!(p.ends[1].join.needs_cap(), stored & CAP_B != 0);
                        let a = m.active_segment(p.active).unwrap();
                        assert_eq!(a.segment, p.segment);
                        assert_eq!(a.continues, [p.ends[0].continues, p.ends[1].continues]);
                        assert_eq!(a.source, s.index);
                    }
                }
                assert_eq!(pieces, m.active_segments(cell).len(), "{cell:?}");
            }
        }
        assert!(m.explain_cell(Cell::new(5, 0)).is_err());
        assert!(m.explain_cell(Cell::new(1, 1)).unwrap().segments.is_empty());
    }
}
