//! A tile's collision objects (drawn in Tiled's collision editor) as tile segments.
//!
//! - Rectangles, ellipses, capsules and polygons are closed outlines: solid, normals out of
//!   the enclosed area whatever the winding.
//! - A polyline is an open chain. By default it is a thin two-sided wall: each edge is two
//!   solid segments, one facing each side. With `one_way = true` each edge is one one-way
//!   segment facing the `one_way_side` (up by default).
//! - `one_way = true` on a closed outline keeps only its edges that face the
//!   `one_way_side` (outward normal · side > 0: for "up", every edge with a rising part of its
//!   normal — the top of a box, the slope of a ramp), as one-way segments; the others are
//!   dropped so a body can jump through from below.
//! - `flag0` … `flag23` set user bits on every segment of the object.
//!
//! An object's own property wins over its tile's. Points, text and tile objects in a
//! collision group have no outline and are ignored.

use std::f64::consts::PI;

use glam::Vec2;

use super::document::TileDoc;
use super::objects::{MapObject, ObjectShape};
use super::placement::Placement;
use super::properties::{Lookup, PropertyFault};
use crate::tiles::{SegmentFlags, TileSegment, TileShape};

/// Segments of the polygon that stands for an ellipse: its corners lie on the ellipse at
/// equal angles from its centre (`2πk / 16`), starting at the rightmost point. A capsule's
/// round ends take half as many each.
pub const ELLIPSE_SEGMENTS: usize = 16;

/// Below this, a normal is taken as perpendicular to the one-way side.
const PARALLEL: f32 = 1e-6;

/// Why a tile's collision objects give no segments.
#[derive(Debug, PartialEq)]
pub(super) enum TileShapeError {
    /// The tile's own definition is wrong (a property, a degenerate outline): the same
    /// wherever the tile is placed.
    Definition(String),
    /// An object reaches further outside the cell the tile is placed in than a vertex is
    /// moved (see [`Placement::snap`]).
    Overhang(String),
}

/// The segments of a tile's collision objects, in its own pixels (y down), unflipped, with
/// vertices just outside the part of the tile that lands in its cell moved onto its edge
/// (`placement`). Errors name the object.
pub(super) fn tile_segments(
    tile: &TileDoc,
    placement: &Placement,
) -> Result<Vec<TileSegment>, TileShapeError> {
    // The tile's own properties are checked even when it has no collision objects.
    let own = Lookup::of(&tile.properties);
    let definition = TileShapeError::Definition;
    own.bool("one_way").map_err(|e| definition(e.to_string()))?;
    own.one_way_side().map_err(|e| definition(e.to_string()))?;
    own.user_flags().map_err(|e| definition(e.to_string()))?;
    let mut out = Vec::new();
    for object in &tile.collision {
        let lookup = Lookup {
            own: &object.properties,
            inherited: Some(&tile.properties),
        };
        object_segments(object, lookup, placement, &mut out).map_err(|e| {
            let name = if object.name.is_empty() {
                String::new()
            } else {
                format!(" ({:?})", object.name)
            };
            let named = |m: String| format!("collision object {}{name}: {m}", object.id);
            match e {
                TileShapeError::Definition(m) => TileShapeError::Definition(named(m)),
                TileShapeError::Overhang(m) => TileShapeError::Overhang(named(m)),
            }
        })?;
    }
    Ok(out)
}

/// The outline of an object in its own frame (before rotation): closed or open.
enum Outline {
    Closed(Vec<Vec2>),
    Open(Vec<Vec2>),
}

fn outline(object: &MapObject) -> Result<Option<Outline>, String> {
    let Vec2 { x: w, y: h } = object.size;
    let positive = || {
        if w > 0.0 && h > 0.0 {
            Ok(())
        } else {
            Err(format!("its size {w}×{h} is not positive"))
        }
    };
    if object.gid.is_some() {
        return Ok(None);
    }
    Ok(match &object.shape {
        ObjectShape::Rectangle => {
            positive()?;
            Some(Outline::Closed(vec![
                Vec2::ZERO,
                Vec2::new(w, 0.0),
                Vec2::new(w, h),
                Vec2::new(0.0, h),
            ]))
        }
        ObjectShape::Ellipse => {
            positive()?;
            Some(Outline::Closed(ellipse(w, h)))
        }
        ObjectShape::Capsule => {
            positive()?;
            Some(Outline::Closed(capsule(w, h)))
        }
        ObjectShape::Polygon(points) => Some(Outline::Closed(points.clone())),
        ObjectShape::Polyline(points) => Some(Outline::Open(points.clone())),
        ObjectShape::Point | ObjectShape::Text(_) => None,
    })
}

fn object_segments(
    object: &MapObject,
    lookup: Lookup<'_>,
    placement: &Placement,
    out: &mut Vec<TileSegment>,
) -> Result<(), TileShapeError> {
    let definition = TileShapeError::Definition;
    let Some(outline) = outline(object).map_err(definition)? else {
        return Ok(());
    };
    let property = |e: PropertyFault| definition(e.to_string());
    let one_way = lookup.bool("one_way").map_err(property)?.unwrap_or(false);
    let side = lookup.one_way_side().map_err(property)?;
    let user = lookup.user_flags().map_err(property)?;
    let (sin, cos) = sin_cos(object.rotation).map_err(definition)?;
    let place = |p: Vec2| object.position + Vec2::new(cos * p.x - sin * p.y, sin * p.x + cos * p.y);
    let (closed, points) = match outline {
        Outline::Closed(p) => (true, p),
        Outline::Open(p) => (false, p),
    };
    let mut points: Vec<Vec2> = points.into_iter().map(place).collect();
    if placement
        .snap(&mut points)
        .map_err(TileShapeError::Overhang)?
    {
        // Neighbours that landed on the same point of the edge are one vertex.
        points.dedup();
        if closed && points.len() > 1 && points.first() == points.last() {
            points.pop();
        }
    }
    outline_segments(closed, &points, one_way, side, user, out).map_err(definition)
}

/// The segments of an outline already in the tile: closed (solid, or its edges facing
/// `side` one-way) or open (a two-sided or one-way chain).
fn outline_segments(
    closed: bool,
    points: &[Vec2],
    one_way: bool,
    side: Vec2,
    user: SegmentFlags,
    out: &mut Vec<TileSegment>,
) -> Result<(), String> {
    if closed {
        let polygon = TileShape::polygon(points).map_err(|e| e.to_string())?;
        for s in polygon.segments() {
            if !one_way {
                out.push(TileSegment::new(
                    s.a,
                    s.b,
                    s.normal,
                    SegmentFlags::SOLID | user,
                ));
            } else if s.normal.dot(side) > PARALLEL {
                out.push(TileSegment::new(
                    s.a,
                    s.b,
                    s.normal,
                    SegmentFlags::ONE_WAY | user,
                ));
            }
        }
        return Ok(());
    }
    if points.len() < 2 {
        return Err(format!(
            "a polyline needs at least 2 points, got {}",
            points.len()
        ));
    }
    for (i, pair) in points.windows(2).enumerate() {
        let (a, b) = (pair[0], pair[1]);
        if a == b || !(a.is_finite() && b.is_finite()) {
            return Err(format!(
                "polyline edge {i} has zero length or a non-finite point"
            ));
        }
        let d = (b - a).normalize();
        let normal = Vec2::new(d.y, -d.x) + Vec2::ZERO;
        if one_way {
            let facing = normal.dot(side);
            if facing.abs() <= PARALLEL {
                return Err(format!(
                    "polyline edge {i} is parallel to its one-way side, so it faces neither way"
                ));
            }
            let normal = if facing > 0.0 {
                normal
            } else {
                -normal + Vec2::ZERO
            };
            out.push(TileSegment::new(a, b, normal, SegmentFlags::ONE_WAY | user));
        } else {
            out.push(TileSegment::new(a, b, normal, SegmentFlags::SOLID | user));
            out.push(TileSegment::new(
                b,
                a,
                -normal + Vec2::ZERO,
                SegmentFlags::SOLID | user,
            ));
        }
    }
    Ok(())
}

/// Sine and cosine of a clockwise rotation in degrees, exact for quarter turns (so a
/// rotated rectangle keeps integer corners).
fn sin_cos(degrees: f32) -> Result<(f32, f32), String> {
    if !degrees.is_finite() {
        return Err(format!("its rotation {degrees} is not finite"));
    }
    let d = degrees.rem_euclid(360.0);
    let quarter = [
        (0.0, (0.0, 1.0)),
        (90.0, (1.0, 0.0)),
        (180.0, (0.0, -1.0)),
        (270.0, (-1.0, 0.0)),
    ];
    Ok(match quarter.iter().find(|(q, _)| *q == d) {
        Some((_, exact)) => *exact,
        None => {
            let r = f64::from(d).to_radians();
            (r.sin() as f32, r.cos() as f32)
        }
    })
}

/// The ellipse inscribed in `w × h` as [`ELLIPSE_SEGMENTS`] corners.
fn ellipse(w: f32, h: f32) -> Vec<Vec2> {
    let (rx, ry) = (f64::from(w) / 2.0, f64::from(h) / 2.0);
    (0..ELLIPSE_SEGMENTS)
        .map(|k| {
            let t = 2.0 * PI * k as f64 / ELLIPSE_SEGMENTS as f64;
            Vec2::new((rx + rx * t.cos()) as f32, (ry + ry * t.sin()) as f32)
        })
        .collect()
}

/// A capsule in `w × h`: two half circles of [`ELLIPSE_SEGMENTS`]` / 2` segments each,
/// joined by straight sides along the longer axis.
fn capsule(w: f32, h: f32) -> Vec<Vec2> {
    let half = ELLIPSE_SEGMENTS / 2;
    let (w, h) = (f64::from(w), f64::from(h));
    let r = w.min(h) / 2.0;
    // The two cap centres and the angle where the first cap starts.
    let (c0, c1, start) = if w >= h {
        ((w - r, r), (r, r), -PI / 2.0)
    } else {
        ((r, h - r), (r, r), 0.0)
    };
    let mut points: Vec<Vec2> = Vec::with_capacity(2 * half + 2);
    for (centre, from) in [(c0, start), (c1, start + PI)] {
        for j in 0..=half {
            let t = from + PI * j as f64 / half as f64;
            let p = Vec2::new(
                (centre.0 + r * t.cos()) as f32,
                (centre.1 + r * t.sin()) as f32,
            );
            if points.last() != Some(&p) {
                points.push(p);
            }
        }
    }
    if points.len() > 1 && points.first() == points.last() {
        points.pop();
    }
    points
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::HitTypes;
    use crate::io::tiled::properties::{Properties, PropertyValue};

    /// A 16-pixel tile in a 16-pixel cell, unflipped.
    const SIZE: &Placement = &Placement {
        tile: Vec2::splat(16.0),
        cell: Vec2::splat(16.0),
        flip: crate::io::tiled::Flip::NONE,
    };

    fn object(shape: ObjectShape, position: Vec2, size: Vec2) -> MapObject {
        MapObject {
            id: 1,
            name: String::new(),
            class: String::new(),
            position,
            size,
            rotation: 0.0,
            visible: true,
            shape,
            gid: None,
            properties: Properties::new(),
            hit_types: HitTypes::NONE,
        }
    }

    fn tile(objects: Vec<MapObject>, props: &[(&str, PropertyValue)]) -> TileDoc {
        TileDoc {
            class: String::new(),
            properties: props
                .iter()
                .map(|(k, v)| ((*k).to_string(), v.clone()))
                .collect(),
            collision: objects,
        }
    }

    #[test]
    fn an_ellipse_has_its_documented_corners() {
        let e = ellipse(16.0, 8.0);
        assert_eq!(e.len(), ELLIPSE_SEGMENTS);
        assert_eq!(e[0], Vec2::new(16.0, 4.0));
        assert_eq!(e[ELLIPSE_SEGMENTS / 4], Vec2::new(8.0, 8.0));
        assert_eq!(e[ELLIPSE_SEGMENTS / 2], Vec2::new(0.0, 4.0));
        let segments = tile_segments(
            &tile(
                vec![object(
                    ObjectShape::Ellipse,
                    Vec2::ZERO,
                    Vec2::new(16.0, 8.0),
                )],
                &[],
            ),
            SIZE,
        )
        .unwrap();
        assert_eq!(segments.len(), ELLIPSE_SEGMENTS);
        for s in &segments {
            // Normals point away from the centre.
            assert!(s.normal.dot((s.a + s.b) / 2.0 - Vec2::new(8.0, 4.0)) > 0.0);
        }
    }

    #[test]
    fn capsules_are_closed_and_inside_their_box() {
        for (w, h) in [(16.0, 8.0), (8.0, 16.0), (10.0, 10.0)] {
            let c = capsule(w, h);
            assert!(TileShape::polygon(&c).is_ok(), "{w}×{h}");
            for p in &c {
                assert!(p.x >= -1e-4 && p.x <= w + 1e-4 && p.y >= -1e-4 && p.y <= h + 1e-4);
            }
        }
    }

    #[test]
    fn a_rotated_rectangle_keeps_exact_corners() {
        let mut o = object(
            ObjectShape::Rectangle,
            Vec2::new(16.0, 0.0),
            Vec2::new(4.0, 8.0),
        );
        o.rotation = 90.0;
        let segments = tile_segments(&tile(vec![o], &[]), SIZE).unwrap();
        let corners: Vec<Vec2> = segments.iter().map(|s| s.a).collect();
        assert_eq!(
            corners,
            [
                Vec2::new(16.0, 0.0),
                Vec2::new(16.0, 4.0),
                Vec2::new(8.0, 4.0),
                Vec2::new(8.0, 0.0)
            ]
        );
    }

    #[test]
    fn a_one_way_box_keeps_only_its_top() {
        let o = object(ObjectShape::Rectangle, Vec2::ZERO, Vec2::new(16.0, 4.0));
        let segments = tile_segments(
            &tile(vec![o], &[("one_way", PropertyValue::Bool(true))]),
            SIZE,
        )
        .unwrap();
        assert_eq!(segments.len(), 1);
        assert_eq!(
            (segments[0].a, segments[0].b),
            (Vec2::ZERO, Vec2::new(16.0, 0.0))
        );
        assert_eq!(segments[0].normal, Vec2::NEG_Y);
        assert_eq!(segments[0].flags, SegmentFlags::ONE_WAY);
    }

    #[test]
    fn polylines_are_two_sided_or_one_way() {
        let line = ObjectShape::Polyline(vec![Vec2::new(0.0, 8.0), Vec2::new(16.0, 8.0)]);
        let two = tile_segments(
            &tile(vec![object(line.clone(), Vec2::ZERO, Vec2::ZERO)], &[]),
            SIZE,
        )
        .unwrap();
        assert_eq!(two.len(), 2);
        assert_eq!(two[0].normal, -two[1].normal);
        assert!(two.iter().all(|s| s.flags == SegmentFlags::SOLID));
        let mut o = object(line, Vec2::ZERO, Vec2::ZERO);
        o.properties
            .insert("one_way".to_string(), PropertyValue::Bool(true));
        o.properties
            .insert("flag3".to_string(), PropertyValue::Bool(true));
        let one = tile_segments(&tile(vec![o], &[]), SIZE).unwrap();
        assert_eq!(one.len(), 1);
        assert_eq!(one[0].normal, Vec2::NEG_Y);
        assert_eq!(
            one[0].flags,
            SegmentFlags::ONE_WAY | SegmentFlags::user(3).unwrap()
        );
        // A vertical one-way edge facing up faces neither way.
        let wall = ObjectShape::Polyline(vec![Vec2::new(8.0, 0.0), Vec2::new(8.0, 16.0)]);
        let e = tile_segments(
            &tile(
                vec![object(wall, Vec2::ZERO, Vec2::ZERO)],
                &[("one_way", PropertyValue::Bool(true))],
            ),
            SIZE,
        )
        .unwrap_err();
        assert!(
            matches!(&e, TileShapeError::Definition(m) if m.contains("collision object 1") && m.contains("parallel")),
            "{e:?}"
        );
    }

    #[test]
    fn objects_outside_the_tile_are_named() {
        let o = object(
            ObjectShape::Rectangle,
            Vec2::new(8.0, 8.0),
            Vec2::new(16.0, 4.0),
        );
        let TileShapeError::Overhang(e) = tile_segments(&tile(vec![o], &[]), SIZE).unwrap_err()
        else {
            panic!("not an overhang");
        };
        assert!(
            e.starts_with("collision object 1: it reaches (24, 8), 8 px outside the tile's 16×16"),
            "{e}"
        );
    }

    #[test]
    fn a_polygon_snapped_onto_the_edge_loses_the_vertices_it_merges() {
        // Two vertices 0.3 and 0.6 px past the right edge at the same height become one.
        let o = object(
            ObjectShape::Polygon(vec![
                Vec2::new(0.0, 0.0),
                Vec2::new(16.3, 0.0),
                Vec2::new(16.6, 0.0),
                Vec2::new(16.0, 16.0),
                Vec2::new(0.0, 16.0),
            ]),
            Vec2::ZERO,
            Vec2::ZERO,
        );
        let segments = tile_segments(&tile(vec![o], &[]), SIZE).unwrap();
        let corners: Vec<Vec2> = segments.iter().map(|s| s.a).collect();
        assert_eq!(
            corners,
            [
                Vec2::new(0.0, 0.0),
                Vec2::new(16.0, 0.0),
                Vec2::new(16.0, 16.0),
                Vec2::new(0.0, 16.0)
            ]
        );
    }
}
