//! The debug lines of paths and flow fields.

use super::flow::{TO_GOAL, UNREACHED};
use super::lattice::MOVES;
use super::{FlowField, NavGrid, NavPath};
use crate::debug::{DebugKind, DebugLines};
use crate::geometry::{Aabb, Segment};
use crate::owner::Owner;

impl NavPath {
    /// Adds the path's legs to `out`, from the start point to the goal, as
    /// [`Path`](DebugKind::Path) segments with `owner` (whose path it is).
    ///
    /// ```
    /// use tileslide::{io::ascii, DebugKind, DebugLines, NavConfig, NavGrid, Owner, Vec2};
    ///
    /// let map = ascii::parse("\
    /// #####
    /// #...#
    /// #.#.#
    /// #...#
    /// #####", "ring.txt", 1.0)?;
    /// let nav = NavGrid::new(&map, NavConfig::default())?;
    /// let path = nav.find_path(&map, Vec2::new(1.5, 1.5), Vec2::new(3.5, 3.5), 0.3)?.unwrap();
    /// let mut lines = DebugLines::new();
    /// path.debug_lines(Owner(4), &mut lines);
    /// assert_eq!(lines.count(DebugKind::Path), path.points().len() - 1);
    /// assert_eq!(lines.segments()[0].segment.a, Vec2::new(1.5, 1.5));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn debug_lines(&self, owner: Owner, out: &mut DebugLines) {
        for leg in self.points().windows(2) {
            out.push_segment(DebugKind::Path, Segment::new(leg[0], leg[1]), owner);
        }
    }
}

impl FlowField {
    /// Adds the field's next move out of every lattice node that reaches the goal to
    /// `out`, as [`FlowArrow`](DebugKind::FlowArrow) segments from the node, half of the
    /// way to the next node (or towards the goal, for the nodes that join it straight).
    /// `nav` is the grid the field was made on; for another grid nothing is added. With a
    /// [view](DebugLines::with_view), only nodes in it are looked at.
    ///
    /// ```
    /// use tileslide::{io::ascii, DebugKind, DebugLines, FlowField, NavConfig, NavGrid, Vec2};
    ///
    /// let map = ascii::parse("\
    /// #####
    /// #...#
    /// #####", "hall.txt", 1.0)?;
    /// let nav = NavGrid::new(&map, NavConfig::default())?;
    /// let field = FlowField::new(&nav, &map, Vec2::new(3.5, 1.5), 0.3)?;
    /// let mut lines = DebugLines::new();
    /// field.debug_lines(&nav, &mut lines);
    /// assert!(lines.count(DebugKind::FlowArrow) > 0);
    /// // In this hall every arrow points right, towards the goal, or at it.
    /// assert!(lines.segments().iter().all(|s| s.segment.b.x >= s.segment.a.x));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn debug_lines(&self, nav: &NavGrid, out: &mut DebugLines) {
        let lattice = &nav.table.lattice;
        if !out.wants(DebugKind::FlowArrow) || self.distance.len() != lattice.len() {
            return;
        }
        for (n, (&distance, &next)) in self.distance.iter().zip(&self.next).enumerate() {
            if distance == UNREACHED {
                continue;
            }
            let from = lattice.position_of(n);
            if !out.sees(&Aabb::from_corners(from, from)) {
                continue;
            }
            let to = if next == TO_GOAL {
                // At most half a move's length towards the goal.
                let half = lattice.step.min_element() * 0.5;
                let d = self.goal - from;
                from + d.clamp_length_max(half)
            } else {
                let (dx, dy) = MOVES[usize::from(next)];
                from + glam::Vec2::new(dx as f32, dy as f32) * lattice.step * 0.5
            };
            if to != from {
                out.push_segment(DebugKind::FlowArrow, Segment::new(from, to), Owner(0));
            }
        }
    }
}
