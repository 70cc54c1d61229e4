//! Circle casts: the first segment a circle moving along a straight line touches.
//!
//! Every segment is tested as a capsule ([`sweep_circle_segment`]): its flat front side plus
//! rounded caps only at the ends where the surface does not continue flat or concave into a
//! neighbour (recorded with the end links, see `tiles::continuity`). So a circle sliding
//! along a floor of many tiles sees one flat surface, and rounds convex corners.

use glam::Vec2;

use super::{CastError, Faces, QueryFilter, SegmentSource};
use crate::geometry::{
    Aabb, EndCaps, MAX_COORD, Segment, SweepHit, circle_segment, in_range, sweep_circle_segment,
};
use crate::tiles::store::{CAP_A, CAP_B, HotSegment};
use crate::tiles::{Owner, SegmentFlags, SegmentRef, TileId, TileMap};

/// The longest motion along an axis that a circle cast sweeps as given: 2²⁷. From a
/// centre within `MAX_COORD` it reaches past `2·MAX_COORD`, beyond which no circle of
/// radius up to `MAX_COORD` touches a segment; up to it the sweep's squared lengths and
/// products stay far from `f32::MAX`.
const MAX_CAST_MOTION: f32 = 134_217_728.0;

/// A circle cast's first contact.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CircleHit {
    /// Fraction of the motion, in `[0, 1]`, at which the circle touches the segment.
    pub t: f32,
    /// The circle's centre at that moment.
    pub center: Vec2,
    /// Unit contact normal, from the segment towards the centre (the segment's normal on
    /// its flat side, radial at a rounded end).
    pub normal: Vec2,
    /// The point of contact, on the segment; for a circle that already overlaps the
    /// segment at `t = 0`, the point of its edge opposite the normal
    /// (`center − normal·radius`).
    pub point: Vec2,
    /// The segment's flags.
    pub flags: SegmentFlags,
    /// Where the segment comes from.
    pub source: SegmentSource,
}

/// A segment as a moving circle sees it: its capsule, front side only.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Capsule {
    pub segment: Segment,
    pub normal: Vec2,
    /// Rounded cap at `[a, b]`: the public sweeps' [`EndCaps`] as an array, which the
    /// resolver's hot loop has always been compiled with (as `EndCaps` the loop took 0.25 %
    /// more instructions).
    pub caps: [bool; 2],
}

impl Capsule {
    /// The capsule of `segment` whose front is the side `normal` points to.
    ///
    /// Sweeps measure heights along the normal, so it must be perpendicular to the segment:
    /// an authored normal a little off (Replica Island's are up to half a degree off, about
    /// 0.3 pixel over a tile) would let a box's corner sink into the surface by that much.
    /// Such a normal is replaced by the segment's perpendicular on the same side; a normal
    /// perpendicular to rounding (every computed one) is kept bit for bit.
    #[inline]
    pub fn new(segment: Segment, normal: Vec2, caps: [bool; 2]) -> Self {
        let e = segment.delta();
        let normal = if normal.dot(e).abs() <= 1e-6 * e.length() {
            normal
        } else {
            let perp = e.perp().normalize_or(normal);
            if perp.dot(normal) >= 0.0 { perp } else { -perp }
        };
        Self {
            segment,
            normal,
            caps,
        }
    }

    /// The time of impact of a circle of `radius` at `center` moving by `motion`.
    #[inline]
    pub fn sweep(&self, center: Vec2, radius: f32, motion: Vec2) -> Option<SweepHit> {
        sweep_circle_segment(
            center,
            radius,
            motion,
            &self.segment,
            self.normal,
            EndCaps::from_array(self.caps),
        )
    }

    /// [`sweep`](Self::sweep) without the size check, for the resolver, whose bodies and
    /// walls lie within `MAX_COORD` (see [`circle_segment`]).
    #[inline]
    pub fn sweep_ordinary(&self, center: Vec2, radius: f32, motion: Vec2) -> Option<SweepHit> {
        circle_segment(
            center,
            radius,
            motion,
            &self.segment,
            self.normal,
            self.caps,
        )
    }

    /// The same segment seen from behind: reversed, so its normal flips and the caps swap.
    fn back(&self) -> Self {
        Self {
            segment: Segment::new(self.segment.b, self.segment.a),
            normal: -self.normal,
            caps: [self.caps[1], self.caps[0]],
        }
    }
}

/// A capsule with what a query reports about its segment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Wall {
    pub capsule: Capsule,
    pub flags: SegmentFlags,
    pub source: SegmentSource,
}

impl TileMap {
    /// The first segment a circle of `radius` at `center` touches when it moves by
    /// `motion`, or `None`.
    ///
    /// The whole motion is checked exactly (swept capsules), so a fast circle cannot pass
    /// through a thin wall. With the default filter a segment blocks only a circle whose
    /// centre is in front of it and that moves towards it: a circle inside a solid or below
    /// a one-way platform moves out freely, and one sliding along a surface is not stopped by
    /// it. [`Faces::Both`] makes segments block from both sides;
    /// [`Faces::Against`]`(dir)` keeps only segments whose normal opposes `dir`. On equal
    /// `t`, temporary segments win, then cells row by row.
    ///
    /// Range: every finite input is answered. A motion of any finite length is checked
    /// whole: a motion longer than 2²⁷ along an axis is first scaled down by a power of two
    /// (exactly) to at most 2²⁷, which still carries the circle across and out of the box
    /// of every segment it can reach, and the hit's `t` is scaled back. A centre farther
    /// from the map's rectangle than the radius plus the map's larger side plus 8 cells
    /// (the rule of rays), or a radius beyond [`MAX_COORD`], is not rounded near the map,
    /// which would move the line it travels: the motion is clipped in `f64` to the box of
    /// every segment grown by the radius and a cell, from a point of the exact line, each
    /// segment is swept from there with its offset taken in `f64`, and `t` (along the
    /// motion as given), the centre and the point are computed in `f64` and rounded once
    /// (see `docs/ray-casting.md`).
    ///
    /// A circle that already overlaps a segment at its start and moves towards its front
    /// gets `t = 0` there, whatever its radius: one of radius 10³⁰ holding the whole map
    /// stops at once against the first segment (in the order above) that faces its centre
    /// and that it moves towards, and moves freely when there is none. Its `point` is then
    /// `center − normal·radius`, on the circle's edge, not on the segment.
    ///
    /// A NaN or infinite centre or motion hits nothing (`None`), as a ray does.
    ///
    /// # Errors
    /// [`CastError::InvalidRadius`] for a radius that is zero, negative, NaN or infinite.
    ///
    /// ```
    /// # use tileslide::{io::ascii, QueryFilter, Vec2};
    /// let map = ascii::parse("\
    /// #####
    /// #...#
    /// #...#
    /// #####", "doc.txt", 1.0)?;
    /// // A circle of radius 0.25 moving right from (1.5, 1.5) touches the wall at x = 4.
    /// let hit = map.cast_circle(Vec2::new(1.5, 1.5), 0.25, Vec2::new(10.0, 0.0), &QueryFilter::default())?.unwrap();
    /// assert_eq!(hit.center, Vec2::new(3.75, 1.5));
    /// assert_eq!(hit.normal, Vec2::new(-1.0, 0.0));
    /// assert_eq!(hit.point, Vec2::new(4.0, 1.5));
    /// // A negative radius is a mistake, not a miss.
    /// assert!(map.cast_circle(Vec2::new(1.5, 1.5), -0.25, Vec2::X, &QueryFilter::default()).is_err());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn cast_circle(
        &self,
        center: Vec2,
        radius: f32,
        motion: Vec2,
        filter: &QueryFilter,
    ) -> Result<Option<CircleHit>, CastError> {
        if !(radius > 0.0 && radius.is_finite()) {
            return Err(CastError::InvalidRadius(radius));
        }
        Ok(self.cast_valid_circle(center, radius, motion, filter))
    }

    /// [`cast_circle`](Self::cast_circle) of a circle whose radius is positive and finite.
    #[inline]
    pub(crate) fn cast_valid_circle(
        &self,
        center: Vec2,
        radius: f32,
        motion: Vec2,
        filter: &QueryFilter,
    ) -> Option<CircleHit> {
        let ordinary = radius <= MAX_COORD
            && in_range(center)
            && motion.is_finite()
            && self.is_near(center, radius);
        if !ordinary {
            return if center.is_finite() && motion.is_finite() {
                self.cast_circle_wide(center, radius, motion, filter)
            } else {
                None
            };
        }
        // The part of the motion where a contact can be, as `motion · 2^-k` (exact but for
        // components that underflow, which move nothing that matters); `t` along it is
        // `t · 2^k` along the motion.
        let longest = motion.x.abs().max(motion.y.abs());
        let k = if longest > MAX_CAST_MOTION {
            (longest / MAX_CAST_MOTION).log2().ceil() as i32
        } else {
            0
        };
        let t_scale = 2f32.powi(-k);
        let motion = motion * t_scale;
        let swept = Aabb::from_corners(center, center + motion).expand(radius);
        let best = self.first_wall_in(&swept, filter, |capsule| {
            capsule.sweep(center, radius, motion)
        });
        best.map(|(hit, wall)| {
            let at = center + motion * hit.t;
            CircleHit {
                t: hit.t * t_scale,
                center: at,
                normal: hit.normal,
                point: at - hit.normal * radius,
                flags: wall.flags,
                source: wall.source,
            }
        })
    }

    /// Whether `cast_circle` sweeps a circle of `radius` (at most `MAX_COORD`) at `center`
    /// in `f32` as given: its centre lies within the radius plus the map's larger side
    /// plus 8 cells of the map's rectangle, where rounding its offset from a segment moves
    /// it no more than rounding the segment's own coordinates does.
    #[inline]
    fn is_near(&self, center: Vec2, radius: f32) -> bool {
        let cell = self.cell_size();
        let size = Vec2::new(self.width() as f32, self.height() as f32) * cell;
        let margin = radius + size.max_element() + 8.0 * cell.max_element();
        let lo = self.origin() - margin;
        let hi = self.origin() + size + margin;
        center.cmpge(lo).all() && center.cmple(hi).all()
    }

    /// The wall near `region` that `filter` keeps which `sweep` meets first, with its hit:
    /// each wall's front, and its back too for [`Faces::Both`]; the smallest `t`, the first
    /// found of equals (in the order of [`walls_in`](Self::walls_in)).
    pub(super) fn first_wall_in(
        &self,
        region: &Aabb,
        filter: &QueryFilter,
        sweep: impl Fn(&Capsule) -> Option<SweepHit>,
    ) -> Option<(SweepHit, Wall)> {
        // Visited in place, not collected: a cast allocates nothing.
        let mut best: Option<(SweepHit, Wall)> = None;
        self.for_each_wall_in(region, filter, |wall| {
            let facing = match filter.faces {
                Faces::Both => [Some(wall.capsule), Some(wall.capsule.back())],
                _ => [Some(wall.capsule), None],
            };
            for capsule in facing.into_iter().flatten() {
                if let Some(hit) = sweep(&capsule)
                    && best.is_none_or(|(b, _)| hit.t < b.t)
                {
                    best = Some((hit, wall));
                }
            }
        });
        best
    }

    /// Appends the temporary segments, then the active segments of the cells (row by row)
    /// that share a point with `region`, that `filter` lets block a moving circle (flag mask,
    /// excluded owner, and for [`Faces::Against`] the direction).
    pub(crate) fn walls_in(&self, region: &Aabb, filter: &QueryFilter, out: &mut Vec<Wall>) {
        self.for_each_wall_in(region, filter, |wall| out.push(wall));
    }

    /// Calls `f` with each wall [`walls_in`](Self::walls_in) appends, in the same order.
    #[inline]
    fn for_each_wall_in(&self, region: &Aabb, filter: &QueryFilter, mut f: impl FnMut(Wall)) {
        // The sweep itself tells a segment's front from its back (`first_wall_in` sweeps
        // the back too for `Faces::Both`), so here `Faces::Front` keeps every face and the
        // filter's one rule decides the rest.
        let walls = QueryFilter {
            faces: match filter.faces {
                Faces::Front => Faces::Both,
                faces => faces,
            },
            ..*filter
        };
        let keeps = |normal: Vec2, flags: SegmentFlags, owner: Option<Owner>| {
            walls.accepts(Vec2::ZERO, normal, flags, owner)
        };
        for (index, tmp) in self.temporaries().iter().enumerate() {
            if !keeps(tmp.normal, tmp.flags, Some(tmp.owner))
                || !region.overlaps_segment(&tmp.segment)
            {
                continue;
            }
            f(Wall {
                capsule: Capsule::new(tmp.segment, tmp.normal, [true; 2]),
                flags: tmp.flags,
                source: SegmentSource::Temporary {
                    owner: tmp.owner,
                    index,
                    velocity: tmp.velocity,
                },
            });
        }
        self.for_each_segment_in(region, |index, i, s, capsule| {
            if keeps(s.normal, s.flags, None) {
                f(Wall {
                    capsule,
                    flags: s.flags,
                    source: SegmentSource::Tile {
                        segment: SegmentRef {
                            cell: self.cell_of(index),
                            index: i,
                        },
                        tile: self.tile_at_index(index).unwrap_or(TileId(u32::MAX)),
                    },
                });
            }
        });
    }

    /// Appends the capsules of the temporary and active segments near `region` with one of
    /// `mask`'s flags, front faces only: what the resolver sweeps bodies against.
    pub(crate) fn capsules_in(&self, region: &Aabb, mask: SegmentFlags, out: &mut Vec<Capsule>) {
        for tmp in self.temporaries() {
            if tmp.flags.intersects(mask) && region.overlaps_segment(&tmp.segment) {
                out.push(Capsule::new(tmp.segment, tmp.normal, [true; 2]));
            }
        }
        self.for_each_segment_in(region, |_, _, s, capsule| {
            if s.flags.intersects(mask) {
                out.push(capsule);
            }
        });
    }

    /// Calls `f(cell index, segment index, segment, capsule)` for the active segments of
    /// the cells (row by row) that share a point with `region`.
    #[inline]
    fn for_each_segment_in(
        &self,
        region: &Aabb,
        mut f: impl FnMut(usize, u32, &HotSegment, Capsule),
    ) {
        let Some((c0, r0, c1, r1)) = self.cell_range(region) else {
            return;
        };
        let width = self.width() as usize;
        let kinds = self.store.kinds();
        for row in r0 as usize..=r1 as usize {
            for col in c0 as usize..=c1 as usize {
                let index = row * width + col;
                // Most cells near a body are empty: their kind byte says so, from an array
                // a quarter the size of the segment indices.
                if kinds[index] == 0 {
                    continue;
                }
                let caps = self.store.caps(index);
                for (i, (s, &cap)) in self.store.cell(index).iter().zip(caps).enumerate() {
                    let capsule = Capsule::new(
                        Segment::new(s.a, s.b()),
                        s.normal,
                        [cap & CAP_A != 0, cap & CAP_B != 0],
                    );
                    f(index, i as u32, s, capsule);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::ascii::{self, TEST_ROOM};

    fn map(text: &str) -> TileMap {
        ascii::parse(text, "test.txt", 1.0).unwrap()
    }

    fn v(x: f32, y: f32) -> Vec2 {
        Vec2::new(x, y)
    }

    /// The cast of a valid radius.
    fn cast(m: &TileMap, c: Vec2, r: f32, motion: Vec2, filter: &QueryFilter) -> Option<CircleHit> {
        m.cast_circle(c, r, motion, filter).unwrap()
    }

    #[test]
    fn a_circle_sliding_along_a_floor_of_many_tiles_is_never_stopped() {
        let m = map(TEST_ROOM);
        // Resting on the floor (y = 4, y down) at exactly its radius, moving along it over
        // five seams.
        let hit = cast(&m, v(1.5, 3.75), 0.25, v(6.0, 0.0), &QueryFilter::default());
        // Only the far wall stops it, not a seam.
        let hit = hit.unwrap();
        assert_eq!(hit.point.x, 7.0);
        assert_eq!(hit.normal, v(-1.0, 0.0));
    }

    #[test]
    fn convex_corners_are_rounded_and_concave_ones_are_not() {
        let m = map("\
......
......
..##..
......");
        // Moving diagonally past the block's top-left corner (2, 2): touches the rounded end.
        let hit = cast(&m, v(0.5, 0.5), 0.25, v(3.0, 3.0), &QueryFilter::default()).unwrap();
        assert!((hit.point - v(2.0, 2.0)).length() < 1e-5, "{hit:?}");
        assert!(hit.normal.x < 0.0 && hit.normal.y < 0.0);
        // The seam between the block's two tiles on its top face has no cap: a circle
        // moving along the top at its radius is not stopped there.
        assert!(
            cast(
                &m,
                v(2.25, 1.75),
                0.25,
                v(1.5, 0.0),
                &QueryFilter::default()
            )
            .is_none()
        );
    }

    #[test]
    fn fast_circles_do_not_tunnel_and_back_faces_let_circles_out() {
        let m = map("\
..........
.....#....
..........");
        // 1000 cells in one move, straight through the one-cell wall.
        let hit = cast(
            &m,
            v(0.5, 1.5),
            0.4,
            v(1000.0, 0.0),
            &QueryFilter::default(),
        )
        .unwrap();
        assert!((hit.center.x - 4.6).abs() < 1e-3, "{hit:?}");
        // A circle whose centre is inside the solid cell moves out freely.
        assert!(cast(&m, v(5.5, 1.5), 0.4, v(3.0, 0.0), &QueryFilter::default()).is_none());
        // Unless both faces count.
        assert!(
            cast(
                &m,
                v(5.5, 1.5),
                0.4,
                v(3.0, 0.0),
                &QueryFilter::both_sides()
            )
            .is_some()
        );
    }

    #[test]
    fn one_way_platforms_hold_from_above_only() {
        let m = map("\
....
.==.
....");
        let down = cast(&m, v(1.5, 0.2), 0.1, v(0.0, 2.0), &QueryFilter::default());
        assert!((down.unwrap().center.y - 0.9).abs() < 1e-5);
        assert!(cast(&m, v(1.5, 2.5), 0.1, v(0.0, -2.0), &QueryFilter::default()).is_none());
    }

    #[test]
    fn flag_masks_and_bad_input() {
        let m = map(TEST_ROOM);
        let none = QueryFilter::default().with_mask(SegmentFlags::ONE_WAY);
        assert!(cast(&m, v(2.0, 2.0), 0.25, v(9.0, 0.0), &none).is_none());
        // Positions and motions are answered as given: a NaN or infinite one hits nothing.
        for (c, mv) in [
            (v(f32::NAN, 2.0), v(9.0, 0.0)),
            (v(2.0, 2.0), v(f32::INFINITY, 0.0)),
            (v(2.0, f32::NEG_INFINITY), v(9.0, 0.0)),
        ] {
            assert_eq!(cast(&m, c, 0.25, mv, &QueryFilter::default()), None);
        }
        // A radius is a size: one that describes no circle is refused, naming it.
        for r in [0.0, -0.0, -1.0, f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
            let err = m.cast_circle(v(2.0, 2.0), r, v(9.0, 0.0), &QueryFilter::default());
            assert!(
                matches!(err, Err(CastError::InvalidRadius(got)) if got.to_bits() == r.to_bits()),
                "{r}: {err:?}"
            );
        }
        let message = CastError::InvalidRadius(-1.0).to_string();
        assert!(
            message.contains("-1") && message.contains("radius"),
            "{message}"
        );
    }
}
