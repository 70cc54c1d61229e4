//! Proves how temporary segments (moving platforms, doors) take part in queries: one in front
//! of a wall is hit first and reported with its owner and velocity; the owner's own casts can
//! exclude it; clearing removes it (all, or one owner's); it is hit outside the map too; it
//! follows the same face and mask rules as tile segments; and invalid ones are refused with
//! an error naming the owner.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use tileslide::io::ascii;
use tileslide::limits::MAX_TEMPORARIES;
use tileslide::{
    MapError, Owner, QueryFilter, Ray, RayHit, Segment, SegmentFlags, SegmentSource,
    TemporaryError, TemporarySegment, TileMap, Vec2,
};

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

/// A corridor with a wall at x = 6.
fn corridor() -> TileMap {
    ascii::parse("#######\n......#\n#######", "corridor.txt", 1.0).unwrap()
}

/// A door: a vertical segment at `x`, across the corridor, facing −x.
fn door(x: f32, owner: u64) -> TemporarySegment {
    TemporarySegment {
        segment: Segment::new(v(x, 1.0), v(x, 2.0)),
        normal: v(-1.0, 0.0),
        flags: SegmentFlags::SOLID,
        owner: Owner(owner),
        velocity: v(0.0, -2.0),
    }
}

#[track_caller]
fn assert_near(got: Vec2, want: Vec2) {
    assert!(got.distance(want) < 1e-5, "got {got:?}, expected {want:?}");
}

fn along() -> Ray {
    Ray::between(v(0.5, 1.5), v(9.0, 1.5))
}

fn owner_of(hit: &RayHit) -> Option<Owner> {
    match hit.source {
        SegmentSource::Temporary { owner, .. } => Some(owner),
        // Tile segments, and any other source, have no owner.
        _ => None,
    }
}

#[test]
fn temporary_segment_in_front_of_a_wall_is_hit_first() {
    let mut m = corridor();
    assert_near(
        m.cast_ray(along(), &QueryFilter::default()).unwrap().point,
        v(6.0, 1.5),
    );
    m.add_temporary(door(3.0, 7)).unwrap();
    let hit = m.cast_ray(along(), &QueryFilter::default()).unwrap();
    assert_near(hit.point, v(3.0, 1.5));
    assert_eq!(hit.normal, v(-1.0, 0.0));
    assert_eq!(hit.flags, SegmentFlags::SOLID);
    assert_eq!(hit.cell(), None);
    assert_eq!(hit.tile(), None);
    assert_eq!(
        hit.source,
        SegmentSource::Temporary {
            owner: Owner(7),
            index: 0,
            velocity: v(0.0, -2.0),
        }
    );
}

#[test]
fn temporary_segment_behind_a_wall_is_not_the_nearest_hit() {
    let mut m = corridor();
    m.add_temporary(door(6.5, 7)).unwrap();
    let hit = m.cast_ray(along(), &QueryFilter::default()).unwrap();
    assert_near(hit.point, v(6.0, 1.5));
    assert_eq!(owner_of(&hit), None);
    // cast_ray_all sees both, wall first.
    let all = m.cast_ray_all(along(), &QueryFilter::default());
    assert_eq!(all.len(), 2);
    assert_eq!(owner_of(&all[0]), None);
    assert_eq!(owner_of(&all[1]), Some(Owner(7)));
}

#[test]
fn temporary_segment_is_excluded_for_its_owner() {
    let mut m = corridor();
    m.add_temporary(door(3.0, 7)).unwrap();
    m.add_temporary(door(4.0, 8)).unwrap();
    let hit = m
        .cast_ray(along(), &QueryFilter::default().excluding(Owner(7)))
        .unwrap();
    assert_eq!(owner_of(&hit), Some(Owner(8)));
    let hit = m
        .cast_ray(along(), &QueryFilter::default().excluding(Owner(8)))
        .unwrap();
    assert_eq!(owner_of(&hit), Some(Owner(7)));
    // Excluding someone else changes nothing.
    let hit = m
        .cast_ray(along(), &QueryFilter::default().excluding(Owner(99)))
        .unwrap();
    assert_eq!(owner_of(&hit), Some(Owner(7)));
    let all = m.cast_ray_all(along(), &QueryFilter::default().excluding(Owner(7)));
    assert!(all.iter().all(|h| owner_of(h) != Some(Owner(7))));
    assert_eq!(all.len(), 2);
}

#[test]
fn cleared_temporary_segments_are_gone() {
    let mut m = corridor();
    m.add_temporary(door(3.0, 7)).unwrap();
    m.add_temporary(door(4.0, 8)).unwrap();
    m.clear_temporaries_of(Owner(7));
    assert_eq!(m.temporaries().len(), 1);
    assert_eq!(
        owner_of(&m.cast_ray(along(), &QueryFilter::default()).unwrap()),
        Some(Owner(8))
    );
    m.clear_temporaries();
    assert!(m.temporaries().is_empty());
    let hit = m.cast_ray(along(), &QueryFilter::default()).unwrap();
    assert_eq!(owner_of(&hit), None);
    assert_near(hit.point, v(6.0, 1.5));
}

#[test]
fn temporary_segment_outside_the_map_is_still_hit() {
    let mut m = corridor();
    let platform = TemporarySegment {
        segment: Segment::new(v(-20.0, -5.0), v(-10.0, -5.0)),
        normal: v(0.0, -1.0),
        flags: SegmentFlags::ONE_WAY,
        owner: Owner(1),
        velocity: v(3.0, 0.0),
    };
    m.add_temporary(platform).unwrap();
    let down = Ray::between(v(-15.0, -8.0), v(-15.0, -2.0));
    let hit = m.cast_ray(down, &QueryFilter::default()).unwrap();
    assert_eq!(hit.t, 0.5);
    assert_eq!(owner_of(&hit), Some(Owner(1)));
    assert_eq!(m.cast_ray_all(down, &QueryFilter::default()).len(), 1);
    // From below, a one-way temporary lets the ray through, like a `=` tile.
    assert!(
        m.cast_ray(
            Ray::between(down.end(), down.origin),
            &QueryFilter::default()
        )
        .is_none()
    );
}

#[test]
fn temporary_segments_follow_the_face_and_mask_rules() {
    let mut m = corridor();
    m.add_temporary(door(3.0, 7)).unwrap();
    // From the far side, the door's back face: ignored by default, hit with both sides.
    let back = Ray::between(v(5.5, 1.5), v(0.5, 1.5));
    assert!(m.cast_ray(back, &QueryFilter::default()).is_none());
    let hit = m.cast_ray(back, &QueryFilter::both_sides()).unwrap();
    assert_eq!(owner_of(&hit), Some(Owner(7)));
    // A mask without SOLID skips it (and the wall).
    let one_way = QueryFilter::default().with_mask(SegmentFlags::ONE_WAY);
    assert!(m.cast_ray(along(), &one_way).is_none());
    // The direction filter applies to it too.
    assert!(
        m.cast_ray(along(), &QueryFilter::against(v(0.0, 1.0)))
            .is_none()
    );
    assert_eq!(
        owner_of(
            &m.cast_ray(along(), &QueryFilter::against(v(1.0, 0.0)))
                .unwrap()
        ),
        Some(Owner(7))
    );
}

#[test]
fn temporary_segment_on_a_tile_face_wins_the_tie() {
    // Documented: on equal t, temporary segments come first.
    let mut m = corridor();
    m.add_temporary(door(6.0, 3)).unwrap();
    let hit = m.cast_ray(along(), &QueryFilter::default()).unwrap();
    assert_near(hit.point, v(6.0, 1.5));
    assert_eq!(owner_of(&hit), Some(Owner(3)));
}

#[test]
fn temporary_normal_is_normalised_when_added() {
    let mut m = corridor();
    let mut d = door(3.0, 1);
    d.normal = v(-4.0, 0.0);
    m.add_temporary(d).unwrap();
    assert_eq!(m.temporaries()[0].normal, v(-1.0, 0.0));
    assert_eq!(
        m.cast_ray(along(), &QueryFilter::default()).unwrap().normal,
        v(-1.0, 0.0)
    );
}

#[test]
fn nan_temporary_segment_is_refused_with_an_error() {
    let mut m = corridor();
    let mut bad = door(3.0, 42);
    bad.segment.a.x = f32::NAN;
    let e = m.add_temporary(bad).unwrap_err().to_string();
    assert!(e.contains("end point a (NaN, 1)"), "{e}");
    let mut bad = door(3.0, 42);
    bad.normal = v(f32::NAN, 0.0);
    let e = m.add_temporary(bad).unwrap_err().to_string();
    assert!(
        e.contains("owner 42") && e.contains("normal (NaN, 0)"),
        "{e}"
    );
    let mut bad = door(3.0, 42);
    bad.velocity = v(0.0, f32::INFINITY);
    assert_eq!(
        m.add_temporary(bad),
        Err(MapError::Temporary(TemporaryError::NonFinite {
            owner: Owner(42),
            what: "velocity",
            x: 0.0,
            y: f32::INFINITY
        }))
    );
    assert!(m.temporaries().is_empty(), "nothing refused is kept");
    // The error names the owner.
    let e = m.add_temporary(bad).unwrap_err().to_string();
    assert!(e.contains("42"), "{e}");
}

#[test]
fn degenerate_temporary_segments_are_refused() {
    let mut m = corridor();
    let mut point = door(3.0, 5);
    point.segment = Segment::new(v(3.0, 1.0), v(3.0, 1.0));
    assert_eq!(
        m.add_temporary(point),
        Err(MapError::Temporary(TemporaryError::ZeroLength(Owner(5))))
    );
    let mut no_normal = door(3.0, 5);
    no_normal.normal = Vec2::ZERO;
    assert_eq!(
        m.add_temporary(no_normal),
        Err(MapError::Temporary(TemporaryError::ZeroNormal(Owner(5))))
    );
    assert!(m.temporaries().is_empty());
}

#[test]
fn huge_but_finite_normal_is_normalised_not_zeroed() {
    let mut map = tileslide::io::ascii::parse("...", "huge.txt", 1.0).unwrap();
    map.add_temporary(TemporarySegment {
        segment: Segment::new(Vec2::new(1.5, 0.0), Vec2::new(1.5, 1.0)),
        normal: Vec2::new(-3e38, 3e38),
        flags: SegmentFlags::SOLID,
        owner: Owner(9),
        velocity: Vec2::ZERO,
    })
    .unwrap();
    let n = map.temporaries()[0].normal;
    assert!(
        (n - Vec2::new(-1.0, 1.0).normalize()).length() < 1e-6,
        "{n:?}"
    );
}

#[test]
fn temporary_segment_beyond_max_coord_is_refused_naming_the_point() {
    let mut m = corridor();
    let far = tileslide::limits::MAX_COORD * 2.0;
    for (a, b) in [
        (v(3.0, 1.0), v(far, 1.0)),
        (v(-far, 1.0), v(3.0, 1.0)),
        (v(3.0, -3e38), v(3.0, 2.0)),
    ] {
        let mut bad = door(3.0, 8);
        bad.segment = Segment::new(a, b);
        let p = if a.x.abs().max(a.y.abs()) > tileslide::limits::MAX_COORD {
            a
        } else {
            b
        };
        let err = m.add_temporary(bad).unwrap_err();
        assert_eq!(
            err,
            MapError::Temporary(TemporaryError::OutOfRange {
                owner: Owner(8),
                x: p.x,
                y: p.y,
            })
        );
        let text = err.to_string();
        assert!(text.contains('8') && text.contains("MAX_COORD"), "{text}");
    }
    assert!(m.temporaries().is_empty(), "nothing refused is kept");
    // At MAX_COORD exactly it is accepted, and a ray from afar along it hits it.
    let mut edge = door(3.0, 8);
    edge.segment = Segment::new(
        v(tileslide::limits::MAX_COORD, -1.0),
        v(tileslide::limits::MAX_COORD, 4.0),
    );
    m.add_temporary(edge).unwrap();
    let ray = Ray::between(v(0.5, 1.5), v(3e38, 1.5));
    let hits = m.cast_ray_all(ray, &QueryFilter::default());
    assert!(
        hits.iter().any(|h| owner_of(h) == Some(Owner(8))),
        "{hits:?}"
    );
}

#[test]
fn a_map_holds_at_most_max_temporaries() {
    let mut m = corridor();
    for i in 0..MAX_TEMPORARIES {
        m.add_temporary(door(0.5 + (i % 5) as f32, i as u64))
            .unwrap();
    }
    let revision = m.revision();
    assert_eq!(
        m.add_temporary(door(3.0, 7)),
        Err(MapError::Temporary(TemporaryError::TooMany(Owner(7))))
    );
    assert_eq!(
        m.temporaries().len(),
        MAX_TEMPORARIES,
        "nothing refused is kept"
    );
    assert_eq!(m.revision(), revision, "a refusal is no change");
    let e = m.add_temporary(door(3.0, 7)).unwrap_err().to_string();
    assert!(e.contains("owner 7") && e.contains("65536"), "{e}");
    // A bad segment is named for what is wrong with it, even at the limit.
    let mut bad = door(3.0, 8);
    bad.segment.a.x = f32::NAN;
    assert!(matches!(
        m.add_temporary(bad),
        Err(MapError::Temporary(TemporaryError::NonFinite {
            owner: Owner(8),
            what: "end point a",
            ..
        }))
    ));
    // Room again once one owner's are cleared.
    m.clear_temporaries_of(Owner(0));
    m.add_temporary(door(3.0, 7)).unwrap();
}
