//! The map's debug lines: active segments and their normals, the pieces seam culling
//! hides, and temporary segments.

use glam::Vec2;

use super::culling::seam_tolerance;
use super::store::HotSegment;
use super::{Cell, SegmentFlags, TileMap};
use crate::debug::{DebugKind, DebugLines};
use crate::geometry::Segment;
use crate::owner::Owner;

/// Length of a normal tick, as a fraction of the cell's smaller side.
const NORMAL_TICK: f32 = 0.25;

impl TileMap {
    /// Adds what the map holds to `out`, cell by cell in row-major order, then its
    /// temporary segments:
    ///
    /// - each active segment, as [`ActiveSegment`](DebugKind::ActiveSegment) or
    ///   [`OneWaySegment`](DebugKind::OneWaySegment), followed by its
    ///   [`Normal`](DebugKind::Normal) (a quarter of the cell's smaller side long);
    /// - each piece of a tile segment that seam culling hides, as
    ///   [`HiddenSegment`](DebugKind::HiddenSegment): a cell's active and hidden pieces
    ///   together cover its tile's segments exactly;
    /// - each temporary segment, as [`TemporarySegment`](DebugKind::TemporarySegment) with
    ///   its owner, followed by its normal.
    ///
    /// With a [view](DebugLines::with_view), only the cells it overlaps are visited (and
    /// only the temporary segments touching it are taken): the cost follows the view, not
    /// the map. Hidden pieces are worked out only when `out` takes them.
    ///
    /// ```
    /// use tileslide::{io::ascii, DebugKind, DebugLines, Segment, Vec2};
    ///
    /// // A one-way platform under a solid block: the block hides it.
    /// let map = ascii::parse("#\n=", "stack.txt", 1.0)?;
    /// let mut lines = DebugLines::new();
    /// map.debug_lines(&mut lines);
    /// assert_eq!(lines.count(DebugKind::OneWaySegment), 0);
    /// let hidden: Vec<Segment> = lines
    ///     .segments()
    ///     .iter()
    ///     .filter(|s| s.kind == DebugKind::HiddenSegment)
    ///     .map(|s| s.segment)
    ///     .collect();
    /// assert_eq!(hidden, [Segment::new(Vec2::new(0.0, 1.0), Vec2::new(1.0, 1.0))]);
    /// # Ok::<(), tileslide::io::LoadError>(())
    /// ```
    pub fn debug_lines(&self, out: &mut DebugLines) {
        let tick = self.cell_size().min_element() * NORMAL_TICK;
        let walls = out.wants(DebugKind::ActiveSegment) || out.wants(DebugKind::OneWaySegment);
        let hidden = out.wants(DebugKind::HiddenSegment);
        if (walls || hidden)
            && let Some((cols, rows)) = self.cells_in_view(out)
        {
            for row in rows {
                for col in cols.clone() {
                    let index = (row * self.width() + col) as usize;
                    let hot = self.store.cell(index);
                    if walls {
                        for h in hot {
                            let kind = if h.flags.contains(SegmentFlags::ONE_WAY) {
                                DebugKind::OneWaySegment
                            } else {
                                DebugKind::ActiveSegment
                            };
                            let segment = Segment::new(h.a, h.b());
                            out.push_with_normal(kind, segment, h.normal, tick, Owner(0));
                        }
                    }
                    if hidden {
                        self.hidden_pieces(Cell::new(col, row), hot, out);
                    }
                }
            }
        }
        if out.wants(DebugKind::TemporarySegment) {
            for t in self.temporaries() {
                let kind = DebugKind::TemporarySegment;
                out.push_with_normal(kind, t.segment, t.normal, tick, t.owner);
            }
        }
    }

    /// The columns and rows of the cells `out`'s view overlaps (every cell without a
    /// view), or `None` when it overlaps none.
    fn cells_in_view(
        &self,
        out: &DebugLines,
    ) -> Option<(std::ops::Range<u32>, std::ops::Range<u32>)> {
        let Some(view) = out.view() else {
            return Some((0..self.width(), 0..self.height()));
        };
        // Float-to-integer casts saturate, so a view far outside clamps to the border and
        // gives no cells. One cell of slack on each side: a segment on a cell's edge
        // belongs to the cell on either side, and a normal sticks out of its cell by a
        // quarter of one; `push_segment` makes the exact test.
        let lo = ((view.min - self.origin()) * self.inv_cell_size()).floor() - 1.0;
        let hi = ((view.max - self.origin()) * self.inv_cell_size()).floor() + 2.0;
        let clamp = |v: f32, n: u32| (v.max(0.0) as u64).min(u64::from(n)) as u32;
        Some((
            clamp(lo.x, self.width())..clamp(hi.x, self.width()),
            clamp(lo.y, self.height())..clamp(hi.y, self.height()),
        ))
    }

    /// Adds the pieces of `cell`'s tile segments that no active segment (`hot`, the cell's)
    /// covers: what seam culling hid, each running with its tile segment's normal on the
    /// right as active segments do. Each tile segment's active pieces lie on it in order
    /// and apart; the gaps between them are walked from the segment's start, taking each
    /// time the piece that starts first past the covered part, without allocating (a
    /// segment has few pieces).
    fn hidden_pieces(&self, cell: Cell, hot: &[HotSegment], out: &mut DebugLines) {
        let Some(shape) = self.tile(cell).and_then(|id| self.tile_set().shape(id)) else {
            return;
        };
        let corner = self.cell_corner(cell);
        let eps_length = seam_tolerance(self.cell_size());
        for (index, s) in shape.segments().iter().enumerate() {
            let (a, b) = (corner + s.a, corner + s.b);
            let d = b - a;
            let length = d.length();
            if !length.is_normal() {
                continue;
            }
            let eps = eps_length / length;
            // Where an active piece starts and ends along a → b, as fractions, and the end
            // point at its far end.
            let along = |p: Vec2| (p - a).dot(d) / (length * length);
            let pieces = hot
                .iter()
                .filter(|h| usize::from(h.source) == index)
                .map(|h| {
                    let (ta, tb) = (along(h.a), along(h.b()));
                    if ta <= tb {
                        (ta, tb, h.b())
                    } else {
                        (tb, ta, h.a)
                    }
                });
            let mut push = |p: Vec2, q: Vec2| {
                let (p, q) = if (q - p).perp_dot(s.normal) > 0.0 {
                    (q, p)
                } else {
                    (p, q)
                };
                out.push_segment(DebugKind::HiddenSegment, Segment::new(p, q), Owner(0));
            };
            let (mut covered, mut from) = (0.0f32, a);
            loop {
                let next = pieces
                    .clone()
                    .filter(|&(_, t1, _)| t1 > covered + eps)
                    .min_by(|x, y| x.0.total_cmp(&y.0));
                match next {
                    Some((t0, t1, end)) => {
                        if t0 > covered + eps {
                            let to = a + d * t0;
                            push(from, to);
                        }
                        covered = t1;
                        from = end;
                    }
                    None => {
                        if covered < 1.0 - eps {
                            push(from, b);
                        }
                        break;
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;
    use crate::geometry::Aabb;
    use crate::io::ascii;

    fn lines_of(map: &TileMap) -> DebugLines {
        let mut lines = DebugLines::new();
        map.debug_lines(&mut lines);
        lines
    }

    fn of_kind(lines: &DebugLines, kind: DebugKind) -> Vec<Segment> {
        lines
            .segments()
            .iter()
            .filter(|s| s.kind == kind)
            .map(|s| s.segment)
            .collect()
    }

    #[test]
    fn a_seam_between_two_squares_is_hidden_not_active() {
        let map = ascii::parse("##", "two.txt", 1.0).unwrap();
        let lines = lines_of(&map);
        let hidden = of_kind(&lines, DebugKind::HiddenSegment);
        assert_eq!(hidden.len(), 2);
        for s in &hidden {
            assert_eq!((s.a.x, s.b.x), (1.0, 1.0), "{s:?}");
            assert_eq!((s.a.y.min(s.b.y), s.a.y.max(s.b.y)), (0.0, 1.0));
        }
        let active = of_kind(&lines, DebugKind::ActiveSegment);
        assert_eq!(active.len(), 6);
        assert!(active.iter().all(|s| !(s.a.x == 1.0 && s.b.x == 1.0)));
        assert_eq!(lines.count(DebugKind::Normal), 6);
    }

    #[test]
    fn normals_start_at_the_middle_and_point_out() {
        let map = ascii::parse("#", "one.txt", 2.0).unwrap();
        let lines = lines_of(&map);
        let segments = lines.segments();
        assert_eq!(segments.len(), 8);
        for pair in segments.chunks(2) {
            let (wall, normal) = (pair[0].segment, pair[1].segment);
            assert_eq!(pair[1].kind, DebugKind::Normal);
            assert_eq!(normal.a, (wall.a + wall.b) * 0.5);
            assert!((normal.length() - 0.5).abs() < 1e-6);
            // Outward: the tip is outside the square [0, 2]².
            let tip = normal.b;
            assert!(
                tip.x < 0.0 || tip.x > 2.0 || tip.y < 0.0 || tip.y > 2.0,
                "{tip}"
            );
        }
    }

    #[test]
    fn a_partly_covered_edge_leaves_a_hidden_piece_of_the_covered_length() {
        // A square beside a ramp '/' (solid lower-right triangle): the ramp's right edge is
        // whole; the square's left edge meets it fully, so it is hidden; nothing partial.
        // Then a square beside a half-covered neighbour: a custom tile set.
        use crate::tiles::{TileId, TileSet, TileShape};
        use std::sync::Arc;
        let v = Vec2::new;
        let mut set = TileSet::new(Vec2::ONE).unwrap();
        set.insert(
            TileId(1),
            TileShape::polygon(&[v(0.0, 0.0), v(1.0, 0.0), v(1.0, 1.0), v(0.0, 1.0)]).unwrap(),
        )
        .unwrap();
        set.insert(
            TileId(2),
            TileShape::polygon(&[v(0.0, 0.5), v(1.0, 0.5), v(1.0, 1.0), v(0.0, 1.0)]).unwrap(),
        )
        .unwrap();
        let tiles = [Some(TileId(1)), Some(TileId(2))];
        let map = TileMap::from_tiles(Arc::new(set), 2, 1, Vec2::ZERO, &tiles).unwrap();
        let lines = lines_of(&map);
        let hidden = of_kind(&lines, DebugKind::HiddenSegment);
        // The square's right edge: its lower half is hidden; the half block's left edge
        // (y in [0.5, 1]) is hidden whole.
        let length: f32 = hidden.iter().map(Segment::length).sum();
        assert_eq!(hidden.len(), 2);
        assert!((length - 1.0).abs() < 1e-6, "{hidden:?}");
        assert!(
            hidden
                .iter()
                .all(|s| s.a.x == 1.0 && s.b.x == 1.0 && s.a.y.min(s.b.y) >= 0.5)
        );
    }

    #[test]
    fn the_view_limits_the_cells_visited() {
        let map = ascii::parse(&"#.".repeat(50), "row.txt", 1.0).unwrap();
        let mut lines = DebugLines::new().with_view(Aabb::from_corners(
            Vec2::new(10.2, 0.2),
            Vec2::new(10.8, 0.8),
        ));
        map.debug_lines(&mut lines);
        // Cell 10 is a square; the view is inside it and touches none of its edges.
        assert_eq!(lines.count(DebugKind::ActiveSegment), 0);
        lines.clear();
        lines.set_view(Some(Aabb::from_corners(
            Vec2::new(9.5, 0.2),
            Vec2::new(11.5, 0.8),
        )));
        map.debug_lines(&mut lines);
        // The square's left and right edges cross the view.
        assert_eq!(lines.count(DebugKind::ActiveSegment), 2);
        lines.clear();
        lines.set_view(Some(Aabb::from_corners(
            Vec2::splat(-50.0),
            Vec2::splat(-40.0),
        )));
        map.debug_lines(&mut lines);
        assert!(lines.is_empty());
    }

    #[test]
    fn temporary_segments_keep_their_owner() {
        use crate::tiles::TemporarySegment;
        let mut map = ascii::parse("...", "air.txt", 1.0).unwrap();
        map.add_temporary(TemporarySegment {
            segment: Segment::new(Vec2::ZERO, Vec2::X),
            normal: Vec2::NEG_Y,
            flags: SegmentFlags::SOLID,
            owner: Owner(42),
            velocity: Vec2::ZERO,
        })
        .unwrap();
        let lines = lines_of(&map);
        assert_eq!(lines.segments().len(), 2);
        assert_eq!(lines.segments()[0].kind, DebugKind::TemporarySegment);
        assert!(lines.segments().iter().all(|s| s.owner == Owner(42)));
    }
}
