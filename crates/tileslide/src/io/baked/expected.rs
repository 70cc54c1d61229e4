//! What a baked map's culled segments must be: each cell's active segments as its tile and
//! its four neighbours make them, and links and caps that join what they say they join.
//!
//! A checksum only catches accidents. A file rewritten with a right checksum (by a buggy
//! tool, or on purpose) could otherwise hold a segment with a non-unit normal, or one outside
//! its cell and the map, and the map would answer rays differently from its source. Seam
//! culling depends only on a cell's tile and its four neighbours' tiles, and maps repeat a
//! few such patterns over and over, so each pattern is culled once (on a 3 × 3 map of it,
//! its middle cell's corner at the origin) and every cell's stored segments are compared
//! with it placed at the cell: exactly, bit for bit, for whole tile segments and for the
//! canonical faces of cells with whole-edge faces; within a ten-thousandth of a cell for a
//! piece of a partly hidden tile segment (whose cut points are not kept exactly apart from
//! the cell). Recomputing culling for every cell instead costs several times the load;
//! only a map of more than [`MAX_PATTERNS`] patterns (noise) is culled whole and compared.

use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};
use std::sync::Arc;

use glam::Vec2;

use super::BakedFault;
use crate::tiles::face_kind::{canonical_faces, kind_of};
use crate::tiles::store::{CAP_A, CAP_B, HotSegment};
use crate::tiles::{MapError, SegmentFlags, TileId, TileMap, TileSet};

/// The raw tile value of an empty cell (and of the outside of the map).
const EMPTY: u32 = u32::MAX;

/// Most distinct patterns culled one by one. Each costs a 3 × 3 map (microseconds), so a
/// map of noise, with a pattern per cell, would take far longer than culling the whole map
/// at once; past this many the loader does that instead (see [`Expected::gave_up`]).
const MAX_PATTERNS: usize = 4096;

/// Two ends closer than this (in cells) are the same point: as `tiles/continuity.rs` joins
/// them.
const JOIN_TOLERANCE: f32 = 1e-4;

/// A neighbour turns away (a convex corner) when its normal leans along the segment's
/// outward direction at the shared end by more than this cosine: as `tiles/continuity.rs`
/// decides caps.
const CONVEX_COSINE: f32 = 1e-4;

/// A cell's tile and its neighbours' (`[cell, −x, +x, −y, +y]`, raw, [`EMPTY`] outside the
/// map): all that seam culling reads.
pub(super) type Pattern = [u32; 5];

/// The pattern of cell `index` (column `col`, row `row`) of a `width × height` map.
pub(super) fn pattern_of(tiles: &[u32], width: usize, height: usize, index: usize) -> Pattern {
    let (col, row) = (index % width, index / width);
    let at = |ok: bool, i: usize| if ok { tiles[i] } else { EMPTY };
    [
        tiles[index],
        at(col > 0, index.wrapping_sub(1)),
        at(col + 1 < width, index + 1),
        at(row > 0, index.wrapping_sub(width)),
        at(row + 1 < height, index + width),
    ]
}

/// A multiply-and-rotate hash for patterns (FxHash's): five tile ids need no protection
/// against chosen collisions (a file can only make the table slower, over its own few
/// distinct patterns), and SipHash would cost more than the check it serves.
#[derive(Default)]
struct PatternHasher(u64);

impl Hasher for PatternHasher {
    fn finish(&self) -> u64 {
        self.0
    }

    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u64(u64::from(b));
        }
    }

    fn write_u32(&mut self, v: u32) {
        self.write_u64(u64::from(v));
    }

    fn write_u64(&mut self, v: u64) {
        self.0 = (self.0.rotate_left(5) ^ v).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
    }

    fn write_usize(&mut self, v: usize) {
        self.write_u64(v as u64);
    }
}

/// Culled patterns: each pattern's index in a table of their segments.
type Patterns = HashMap<Pattern, usize, BuildHasherDefault<PatternHasher>>;

/// One active segment of a pattern's middle cell, its corner at the origin.
#[derive(Clone, Copy)]
struct Local {
    segment: HotSegment,
    /// The whole tile segment, oriented as active segments are (normal on the right of
    /// `a → b`): placed at a cell, exactly `(corner + a, (corner + b) − (corner + a))`.
    whole: Option<(Vec2, Vec2)>,
}

/// Why a cell's stored segments are not what its tiles make.
pub(super) struct Mismatch {
    /// The segment at fault, by its index in the cell; `None` when the cell holds too many
    /// or too few.
    pub index: Option<usize>,
    pub fault: BakedFault,
}

/// Culled patterns, each worked out once.
pub(super) struct Expected {
    set: Arc<TileSet>,
    patterns: Patterns,
    culled: Vec<Vec<Local>>,
    /// The last pattern looked up and its index, for cells with segments and for cells
    /// without: neighbouring cells along a floor or inside a wall share one.
    last: [Option<(Pattern, usize)>; 2],
    /// Whether more than [`MAX_PATTERNS`] patterns came up: checks by pattern stopped.
    gave_up: bool,
    scratch: Vec<HotSegment>,
}

impl Expected {
    pub fn new(set: Arc<TileSet>) -> Self {
        Self {
            set,
            patterns: Patterns::default(),
            culled: Vec::new(),
            last: [None; 2],
            gave_up: false,
            scratch: Vec::new(),
        }
    }

    /// The index in `culled` of `pattern`'s middle-cell segments, culled once on a 3 × 3
    /// map.
    /// `None` once there were too many to cull one by one.
    fn lookup(&mut self, pattern: Pattern, slot: usize) -> Result<Option<usize>, MapError> {
        if let Some((p, k)) = self.last[slot]
            && p == pattern
        {
            return Ok(Some(k));
        }
        let k = match self.patterns.get(&pattern) {
            Some(&k) => k,
            None if self.gave_up || self.culled.len() == MAX_PATTERNS => {
                self.gave_up = true;
                return Ok(None);
            }
            None => {
                let locals = cull(&self.set, pattern)?;
                self.culled.push(locals);
                self.patterns.insert(pattern, self.culled.len() - 1);
                self.culled.len() - 1
            }
        };
        self.last[slot] = Some((pattern, k));
        Ok(Some(k))
    }

    /// Whether the checks by pattern stopped, there being too many patterns: the caller
    /// must compare the whole map with its tiles culled at once.
    pub fn gave_up(&self) -> bool {
        self.gave_up
    }

    /// How many active segments `pattern` makes (0 once [`gave_up`](Self::gave_up)).
    pub fn count(&mut self, pattern: Pattern) -> Result<usize, MapError> {
        Ok(self.lookup(pattern, 0)?.map_or(0, |k| self.culled[k].len()))
    }

    /// Checks the `stored` active segments of a cell with corner `base` and `pattern`
    /// against what the pattern makes there; returns the cell's kind (once
    /// [`gave_up`](Self::gave_up), the kind the stored segments make, unchecked).
    pub fn check_cell(
        &mut self,
        pattern: Pattern,
        base: Vec2,
        stored: &[HotSegment],
    ) -> Result<Result<u8, Mismatch>, MapError> {
        let size = self.set.tile_size();
        let Some(k) = self.lookup(pattern, 1)? else {
            return Ok(Ok(kind_of(stored, base, size)));
        };
        let (locals, expected) = (&self.culled[k], &mut self.scratch);
        // Rounding allowed for the cut points of pieces: a ten-thousandth of a cell, and a
        // few roundings of the cell's corner far from the origin.
        let tolerance = size.max_element() * 1e-4 + 4.0 * f32::EPSILON * base.abs().max_element();
        expected.clear();
        let mismatch = |index, fault| Ok(Err(Mismatch { index, fault }));
        if locals.len() != stored.len() {
            return mismatch(
                None,
                BakedFault::WrongCount {
                    stored: stored.len() as u64,
                    made: locals.len() as u64,
                },
            );
        }
        for (k, (local, s)) in locals.iter().zip(stored).enumerate() {
            let l = local.segment;
            let (a, e) = match local.whole {
                Some((a, b)) => (base + a, (base + b) - (base + a)),
                // A piece: the stored cut points, if they are where the piece is.
                None => {
                    let near = |p: Vec2, q: Vec2| (p - q).abs().max_element() <= tolerance;
                    if !(near(s.a, base + l.a) && near(s.e, l.e)) {
                        return mismatch(Some(k), BakedFault::NotThePiece);
                    }
                    (s.a, s.e)
                }
            };
            expected.push(HotSegment { a, e, ..l });
        }
        let kind = kind_of(expected, base, size);
        canonical_faces(expected, kind, base, size);
        let found = expected.iter().zip(stored).position(|(x, s)| {
            (x.a, x.e, x.normal, x.flags, x.source) != (s.a, s.e, s.normal, s.flags, s.source)
        });
        Ok(match found {
            Some(k) => Err(Mismatch {
                index: Some(k),
                fault: BakedFault::NotWhatTheTilesMake,
            }),
            None => Ok(kind),
        })
    }
}

/// The middle cell's active segments for `pattern`, culled on a 3 × 3 map of it.
fn cull(set: &Arc<TileSet>, pattern: Pattern) -> Result<Vec<Local>, MapError> {
    let size = set.tile_size();
    let [cell, min_x, max_x, min_y, max_y] = pattern.map(|t| (t != EMPTY).then_some(TileId(t)));
    let tiles = [
        None, min_y, None, //
        min_x, cell, max_x, //
        None, max_y, None,
    ];
    // Cell (1, 1)'s corner is −size + size = 0, exactly.
    let map = TileMap::from_tiles(set.clone(), 3, 3, -size, &tiles)?;
    let shape = cell.and_then(|id| set.shape(id));
    let locals = map
        .store
        .cell(4)
        .iter()
        .map(|&segment| {
            let whole = shape
                .and_then(|s| s.segments().get(usize::from(segment.source)))
                .map(|t| {
                    if (t.b - t.a).perp_dot(t.normal) > 0.0 {
                        (t.b, t.a)
                    } else {
                        (t.a, t.b)
                    }
                })
                .filter(|&(a, b)| segment.a == a && segment.e == b - a);
            Local { segment, whole }
        })
        .collect();
    Ok(locals)
}

/// Checks that a link from end `end` (0: `a`, 1: `b`) of `segment` to `other` joins them
/// (the two touch there, not back to back), as `tiles/continuity.rs` links ends; `None`
/// when it does, else why not.
pub(super) fn check_link(
    segment: &HotSegment,
    end: usize,
    other: &HotSegment,
    cell_size: Vec2,
) -> Option<BakedFault> {
    let tol = cell_size.max_element() * JOIN_TOLERANCE;
    let point = if end == 0 { segment.a } else { segment.b() };
    let touches = other.a.distance_squared(point) <= tol * tol
        || other.b().distance_squared(point) <= tol * tol;
    if !touches {
        Some(BakedFault::LinkNotTouching)
    } else if segment.normal.dot(other.normal) < -0.999 {
        Some(BakedFault::LinkBackToBack)
    } else {
        None
    }
}

/// The caps byte `tiles/continuity.rs` gives `segment` whose ends link to `others`: an end
/// needs no cap where the surface continues flat or concave into a neighbour that stops what
/// it stops (same flags, not a one-way platform).
pub(super) fn expected_caps(segment: &HotSegment, others: [Option<&HotSegment>; 2]) -> u8 {
    let along = segment.e.normalize_or_zero();
    let mut caps = CAP_A | CAP_B;
    for (k, other) in others.into_iter().enumerate() {
        let outward = if k == 0 { -along } else { along };
        if let Some(other) = other
            && other.normal.dot(outward) <= CONVEX_COSINE
            && other.flags == segment.flags
            && !segment.flags.contains(SegmentFlags::ONE_WAY)
        {
            caps &= !(if k == 0 { CAP_A } else { CAP_B });
        }
    }
    caps
}
