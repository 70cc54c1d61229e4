//! Ray-cast scenarios drawn as ASCII maps (row 0 is the top line, y grows downward, unit
//! cells unless stated): ramps, concave corners, seams, rays through cell corners, one-cell
//! rays, rays ending on or running along a surface, one-way platforms, the filters, and every
//! defined case in the rustdoc of `TileMap::cast_ray`.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use crate::drawn;

use std::f32::consts::FRAC_1_SQRT_2;
use std::sync::Arc;

use tileslide::io::ascii;
use tileslide::{Cell, Faces, QueryFilter, Ray, RayHit, SegmentFlags, TileMap, Vec2};

/// A map drawn as text (see `drawn`).
fn map(drawing: &str) -> TileMap {
    drawn::map(drawing, "scenario.txt")
}

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

fn ray(x0: f32, y0: f32, x1: f32, y1: f32) -> Ray {
    Ray::between(v(x0, y0), v(x1, y1))
}

fn front() -> QueryFilter {
    QueryFilter::default()
}

#[track_caller]
fn assert_near(got: Vec2, want: Vec2) {
    assert!(got.distance(want) <= 1e-5, "got {got:?}, expected {want:?}");
}

#[track_caller]
fn hit(map: &TileMap, r: Ray, filter: &QueryFilter) -> RayHit {
    map.cast_ray(r, filter)
        .unwrap_or_else(|| panic!("expected a hit for {r:?} with {filter:?}"))
}

/// `/` faces up-left and `\` up-right, with y down.
const UP_LEFT: Vec2 = Vec2::new(-FRAC_1_SQRT_2, -FRAC_1_SQRT_2);
const UP_RIGHT: Vec2 = Vec2::new(FRAC_1_SQRT_2, -FRAC_1_SQRT_2);
const UP: Vec2 = Vec2::new(0.0, -1.0);
const DOWN: Vec2 = Vec2::new(0.0, 1.0);
const LEFT: Vec2 = Vec2::new(-1.0, 0.0);
const RIGHT: Vec2 = Vec2::new(1.0, 0.0);

fn ramps() -> TileMap {
    map(r"
        ......
        ./..\.
        ######
    ")
}

// ---------------------------------------------------------------------------------------
// Ramps
// ---------------------------------------------------------------------------------------

#[test]
fn slash_ramp_is_hit_on_its_slope_facing_up_left() {
    let m = ramps();
    // The slope of `/` in cell (1, 1) runs from (2, 1) to (1, 2): x + y = 3.
    let h = hit(&m, ray(1.25, 0.5, 1.25, 2.5), &front());
    assert_near(h.point, v(1.25, 1.75));
    assert_near(h.normal, UP_LEFT);
    assert_eq!(h.cell(), Some(Cell::new(1, 1)));
    assert_eq!(h.tile(), Some(ascii::RAMP_UP_RIGHT));
}

#[test]
fn backslash_ramp_is_hit_on_its_slope_facing_up_right() {
    let m = ramps();
    // The slope of `\` in cell (4, 1) runs from (5, 2) to (4, 1): y = x − 3.
    let h = hit(&m, ray(4.25, 0.5, 4.25, 2.5), &front());
    assert_near(h.point, v(4.25, 1.25));
    assert_near(h.normal, UP_RIGHT);
    assert_eq!(h.cell(), Some(Cell::new(4, 1)));
    assert_eq!(h.tile(), Some(ascii::RAMP_DOWN_RIGHT));
}

#[test]
fn ramps_are_hit_on_their_slopes_by_horizontal_rays_from_the_open_side() {
    let m = ramps();
    let from_left = hit(&m, ray(0.25, 1.5, 3.0, 1.5), &front());
    assert_near(from_left.point, v(1.5, 1.5));
    assert_near(from_left.normal, UP_LEFT);
    let from_right = hit(&m, ray(5.75, 1.5, 3.0, 1.5), &front());
    assert_near(from_right.point, v(4.5, 1.5));
    assert_near(from_right.normal, UP_RIGHT);
}

#[test]
fn ramp_cliff_faces_are_hit_with_axis_normals() {
    let m = ramps();
    // Behind each ramp its vertical side is a cliff: `/`'s right side, `\`'s left side.
    let h = hit(&m, ray(3.0, 1.5, 0.5, 1.5), &front());
    assert_near(h.point, v(2.0, 1.5));
    assert_near(h.normal, RIGHT);
    let h = hit(&m, ray(3.0, 1.5, 5.5, 1.5), &front());
    assert_near(h.point, v(4.0, 1.5));
    assert_near(h.normal, LEFT);
}

#[test]
fn ramp_hits_agree_with_the_slope_at_many_points() {
    let m = ramps();
    for i in 1..20 {
        let f = i as f32 / 20.0;
        let slash = hit(&m, ray(1.0 + f, 0.5, 1.0 + f, 2.5), &front());
        assert_near(slash.point, v(1.0 + f, 2.0 - f));
        assert_near(slash.normal, UP_LEFT);
        let back = hit(&m, ray(4.0 + f, 0.5, 4.0 + f, 2.5), &front());
        assert_near(back.point, v(4.0 + f, 1.0 + f));
        assert_near(back.normal, UP_RIGHT);
    }
}

#[test]
fn ramp_scenario_scales_with_cell_size_and_origin() {
    let set = Arc::new(ascii::tile_set(32.0).unwrap());
    let origin = v(-100.0, 48.0);
    let tiles: Vec<_> = [r"......", r"./..\.", r"######"]
        .concat()
        .chars()
        .map(|c| ascii::tile_for_char(c).unwrap())
        .collect();
    let m = TileMap::from_tiles(set, 6, 3, origin, &tiles).unwrap();
    // The same ray as `slash_ramp_is_hit_on_its_slope_facing_up_left`, scaled by 32 and moved.
    let to_world = |x: f32, y: f32| origin + v(x, y) * 32.0;
    let h = hit(
        &m,
        Ray::between(to_world(1.25, 0.5), to_world(1.25, 2.5)),
        &front(),
    );
    assert_near(h.point, to_world(1.25, 1.75));
    assert_near(h.normal, UP_LEFT);
    assert!((h.t - 0.625).abs() < 1e-6);
}

// ---------------------------------------------------------------------------------------
// Concave corners
// ---------------------------------------------------------------------------------------

#[test]
fn ray_into_a_concave_corner_stops_at_the_corner_point() {
    let m = map(r"
        #####
        #...#
        #...#
        #####
    ");
    // Into each of the four inner corners, diagonally.
    let cases = [
        (ray(2.5, 2.5, 0.5, 0.5), v(1.0, 1.0), [RIGHT, DOWN]),
        (ray(2.5, 2.5, 4.5, 0.5), v(4.0, 1.0), [LEFT, DOWN]),
        (ray(2.5, 1.5, 0.5, 3.5), v(1.0, 3.0), [RIGHT, UP]),
        (ray(2.5, 1.5, 4.5, 3.5), v(4.0, 3.0), [LEFT, UP]),
    ];
    for (r, corner, normals) in cases {
        let h = hit(&m, r, &front());
        assert_near(h.point, corner);
        assert!(
            normals.contains(&h.normal),
            "{r:?}: normal {:?} is not one of the corner's faces",
            h.normal
        );
        // Both faces meet there: cast_ray_all sees exactly the two, at the same t.
        let all = m.cast_ray_all(r, &front());
        assert_eq!(all.len(), 2, "{r:?}: {all:?}");
        assert_eq!(all[0].t, h.t);
        assert_eq!(all[1].t, h.t);
        let mut got: Vec<_> = all.iter().map(|a| (a.normal.x, a.normal.y)).collect();
        got.sort_by(|a, b| a.partial_cmp(b).unwrap());
        let mut want: Vec<_> = normals.iter().map(|n| (n.x, n.y)).collect();
        want.sort_by(|a, b| a.partial_cmp(b).unwrap());
        assert_eq!(got, want, "{r:?}");
    }
}

#[test]
fn ray_into_the_foot_of_a_ramp_stops_where_slope_meets_floor() {
    let m = map(r"
        ....
        .../
        ####
    ");
    // The slope x + y = 5 meets the floor y = 2 at (3, 2).
    let h = hit(&m, ray(1.5, 0.5, 3.5, 2.5), &front());
    assert_near(h.point, v(3.0, 2.0));
    assert_eq!(h.t, 0.75);
    assert!(h.normal == UP || h.normal.distance(UP_LEFT) < 1e-6, "{h:?}");
}

// ---------------------------------------------------------------------------------------
// Seams
// ---------------------------------------------------------------------------------------

#[test]
fn ray_down_onto_a_floor_seam_hits_the_top_face_never_an_interior_edge() {
    let m = map(r"
        ........
        ########
    ");
    for x in 1..8 {
        let r = ray(x as f32, 0.25, x as f32, 1.75);
        for filter in [front(), QueryFilter::both_sides()] {
            let h = hit(&m, r, &filter);
            assert_eq!(h.normal, UP, "seam at x = {x}, {filter:?}");
            assert_near(h.point, v(x as f32, 1.0));
            // Every surface the ray touches on its way into the floor is a top face.
            for a in m.cast_ray_all(r, &filter) {
                assert_eq!(a.normal, UP, "seam at x = {x}: {a:?}");
            }
        }
    }
}

#[test]
fn floor_of_full_squares_exposes_only_its_outer_boundary() {
    let m = map(r"
        ..........
        ##########
    ");
    assert_eq!(m.placed_segment_count(), 40);
    // 10 top faces, 10 bottom faces, one left and one right end.
    assert_eq!(m.active_segment_count(), 22);
    let block = map(r"
        ....
        .###
        .###
        .###
    ");
    assert_eq!(block.placed_segment_count(), 36);
    assert_eq!(block.active_segment_count(), 12);
    // Every active segment lies on the block's outline x ∈ {1, 4} or y ∈ {1, 4}, facing out.
    for row in 0..4 {
        for col in 0..4 {
            for s in block.active_segments(Cell::new(col, row)) {
                let mid = (s.segment.a + s.segment.b) * 0.5;
                let on_outline = (s.normal == LEFT && mid.x == 1.0)
                    || (s.normal == RIGHT && mid.x == 4.0)
                    || (s.normal == UP && mid.y == 1.0)
                    || (s.normal == DOWN && mid.y == 4.0);
                assert!(on_outline, "interior segment {s:?}");
            }
        }
    }
}

#[test]
fn ray_inside_a_floor_meets_no_interior_seam() {
    let m = map("######");
    let r = ray(0.5, 0.5, 7.0, 0.5);
    assert!(m.cast_ray(r, &front()).is_none());
    // Seen from inside, only the far end of the floor is there.
    let all = m.cast_ray_all(r, &QueryFilter::both_sides());
    assert_eq!(all.len(), 1, "{all:?}");
    assert_near(all[0].point, v(6.0, 0.5));
    assert_eq!(all[0].normal, RIGHT);
}

// ---------------------------------------------------------------------------------------
// Rays through cell corners
// ---------------------------------------------------------------------------------------

#[test]
fn diagonal_ray_through_the_lattice_point_between_two_diagonal_blocks_hits() {
    // Two blocks meeting only at their corners; a ray squeezing through that point touches
    // both (the walk visits the two side cells of the corner).
    let falling = map(r"
        ....
        .#..
        ..#.
        ....
    ");
    let rising = map(r"
        ....
        ..#.
        .#..
        ....
    ");
    let cases = [
        (&falling, ray(1.5, 2.5, 2.5, 1.5), [DOWN, LEFT]),
        (&falling, ray(2.5, 1.5, 1.5, 2.5), [RIGHT, UP]),
        (&rising, ray(1.5, 1.5, 2.5, 2.5), [LEFT, UP]),
        (&rising, ray(2.5, 2.5, 1.5, 1.5), [DOWN, RIGHT]),
    ];
    for (m, r, normals) in cases {
        let h = hit(m, r, &front());
        assert_eq!(h.t, 0.5, "{r:?}");
        assert_eq!(h.point, v(2.0, 2.0), "{r:?}");
        assert!(normals.contains(&h.normal), "{r:?}: {h:?}");
        // Both blocks are touched: one front face each.
        let mut cells: Vec<_> = m
            .cast_ray_all(r, &front())
            .iter()
            .map(|a| a.cell().unwrap())
            .collect();
        cells.sort();
        cells.dedup();
        assert_eq!(cells.len(), 2, "{r:?}: {cells:?}");
    }
}

#[test]
fn ray_grazing_the_corner_of_a_single_block_hits_it() {
    let m = map(r"
        ....
        ....
        ..#.
        ....
    ");
    // Through (2, 2), the block's top-left corner, from each diagonal side it has a front
    // face towards.
    for (r, want) in [
        (ray(1.5, 2.5, 2.5, 1.5), LEFT),
        (ray(2.5, 1.5, 1.5, 2.5), UP),
    ] {
        let h = hit(&m, r, &front());
        assert_near(h.point, v(2.0, 2.0));
        assert_eq!(h.normal, want);
    }
}

#[test]
fn long_diagonal_ray_through_many_lattice_points_touches_a_block_at_its_corner() {
    let m = map(r"
        ........
        ........
        ........
        .....#..
        ........
        ........
        ........
        ........
    ");
    // From (0.5, 7.5) up-right along x + y = 8, through the lattice points (1, 7), (2, 6),
    // …, (7, 1). It touches the block in cell (5, 3) only at that block's corner (5, 3).
    let h = hit(&m, ray(0.5, 7.5, 7.5, 0.5), &front());
    assert_near(h.point, v(5.0, 3.0));
    assert_eq!(h.normal, LEFT);
    assert_eq!(h.cell(), Some(Cell::new(5, 3)));
}

// ---------------------------------------------------------------------------------------
// One-cell rays
// ---------------------------------------------------------------------------------------

#[test]
fn ray_starting_and_ending_in_one_cell_hits_the_ramp_inside_it() {
    let slash = map(r"
        ...
        ./.
        ...
    ");
    let h = hit(&slash, ray(1.2, 1.2, 1.8, 1.8), &front());
    assert_near(h.point, v(1.5, 1.5));
    assert!((h.t - 0.5).abs() < 1e-6);
    assert_near(h.normal, UP_LEFT);
    assert_eq!(h.cell(), Some(Cell::new(1, 1)));

    let back = map(r"
        ...
        .\.
        ...
    ");
    let h = hit(&back, ray(1.8, 1.2, 1.2, 1.8), &front());
    assert_near(h.point, v(1.5, 1.5));
    assert_near(h.normal, UP_RIGHT);
}

#[test]
fn ray_inside_one_cell_that_stops_short_of_the_ramp_misses() {
    let slash = map(r"
        ...
        ./.
        ...
    ");
    assert!(slash.cast_ray(ray(1.1, 1.1, 1.4, 1.4), &front()).is_none());
}

// ---------------------------------------------------------------------------------------
// Ending on, and running along, a surface
// ---------------------------------------------------------------------------------------

#[test]
fn ray_ending_exactly_on_a_surface_hits_it_at_t_one() {
    let m = map(r"
        ......
        ...#..
        ./....
        ######
    ");
    let cases = [
        (ray(0.5, 0.5, 0.5, 3.0), v(0.5, 3.0), UP),
        (ray(0.5, 1.5, 3.0, 1.5), v(3.0, 1.5), LEFT),
        (ray(5.5, 1.25, 4.0, 1.25), v(4.0, 1.25), RIGHT),
        (ray(3.5, 0.25, 3.5, 1.0), v(3.5, 1.0), UP),
        // On the slope of `/` in cell (1, 2): x + y = 4.
        (ray(1.25, 0.5, 1.25, 2.75), v(1.25, 2.75), UP_LEFT),
    ];
    for (r, point, normal) in cases {
        let h = hit(&m, r, &front());
        assert_eq!(h.t, 1.0, "{r:?}");
        assert_eq!(h.point, point, "{r:?}");
        assert_near(h.normal, normal);
    }
}

#[test]
fn ray_stopping_just_short_of_a_surface_misses() {
    let m = map(r"
        ....
        ####
    ");
    assert!(m.cast_ray(ray(0.5, 0.5, 0.5, 0.999), &front()).is_none());
}

#[test]
fn ray_running_along_the_top_of_a_floor_is_not_stopped_by_it() {
    let m = map(r"
        ......
        ######
        ......
    ");
    for filter in [front(), QueryFilter::both_sides()] {
        assert!(m.cast_ray(ray(0.5, 1.0, 5.5, 1.0), &filter).is_none());
        assert!(m.cast_ray(ray(5.5, 1.0, 0.5, 1.0), &filter).is_none());
        // Along the bottom too.
        assert!(m.cast_ray(ray(0.5, 2.0, 5.5, 2.0), &filter).is_none());
    }
}

#[test]
fn ray_running_along_a_floor_hits_the_wall_it_runs_into() {
    let m = map(r"
        ......
        .....#
        ######
    ");
    let h = hit(&m, ray(0.5, 2.0, 5.5, 2.0), &front());
    assert_near(h.point, v(5.0, 2.0));
    assert_eq!(h.normal, LEFT);
    assert_eq!(h.cell(), Some(Cell::new(5, 1)));
}

#[test]
fn ray_running_down_a_wall_face_hits_the_floor_it_runs_into() {
    let m = map(r"
        #...
        #...
        ####
    ");
    // Down along x = 1, the right face of the wall, onto the floor's top face at (1, 2).
    let h = hit(&m, ray(1.0, 0.5, 1.0, 2.5), &front());
    assert_near(h.point, v(1.0, 2.0));
    assert_eq!(h.normal, UP);
}

// ---------------------------------------------------------------------------------------
// One-way platforms
// ---------------------------------------------------------------------------------------

fn platform() -> TileMap {
    map(r"
        .....
        .===.
        .....
    ")
}

#[test]
fn one_way_platform_blocks_a_ray_from_above() {
    let h = hit(&platform(), ray(2.5, 0.5, 2.5, 2.5), &front());
    assert_near(h.point, v(2.5, 1.0));
    assert_eq!(h.normal, UP);
    assert_eq!(h.flags, SegmentFlags::ONE_WAY);
}

#[test]
fn one_way_platform_lets_a_ray_from_below_through() {
    assert!(
        platform()
            .cast_ray(ray(2.5, 2.5, 2.5, 0.5), &front())
            .is_none()
    );
}

#[test]
fn one_way_platform_blocks_from_below_with_both_sides() {
    let h = hit(
        &platform(),
        ray(2.5, 2.5, 2.5, 0.5),
        &QueryFilter::both_sides(),
    );
    assert_near(h.point, v(2.5, 1.0));
    // The normal is the segment's own, not flipped towards the ray.
    assert_eq!(h.normal, UP);
}

#[test]
fn one_way_platform_seam_between_two_platform_tiles_is_hit_from_above() {
    let h = hit(&platform(), ray(2.0, 0.5, 2.0, 2.5), &front());
    assert_near(h.point, v(2.0, 1.0));
    assert_eq!(h.normal, UP);
}

// ---------------------------------------------------------------------------------------
// Filters
// ---------------------------------------------------------------------------------------

#[test]
fn direction_filter_counts_only_faces_opposing_its_direction() {
    let m = map(r"
        ..#....
        ..#....
        #######
    ");
    let r = ray(0.5, 0.5, 5.5, 2.5);
    // Front faces: the wall's left face at x = 2.
    let wall = hit(&m, r, &front());
    assert_eq!(wall.normal, LEFT);
    assert_near(wall.point, v(2.0, 1.1));
    // Against "down": only faces whose normal opposes (0, 1) count, so the wall is ignored
    // and the ray reaches the floor's top face.
    let floor = hit(&m, r, &QueryFilter::against(DOWN));
    assert_eq!(floor.normal, UP);
    assert_near(floor.point, v(4.25, 2.0));
    assert_eq!(m.cast_ray(r, &QueryFilter::against(DOWN)).unwrap().t, 0.75);
    // Against the zero direction no face counts.
    assert!(m.cast_ray(r, &QueryFilter::against(Vec2::ZERO)).is_none());
}

#[test]
fn direction_filter_uses_its_own_direction_not_the_rays() {
    // Moving up through a platform: the default filter lets it through, but a filter against
    // "down" counts the platform's upward face whichever way the ray moves.
    let r = ray(2.5, 2.5, 2.5, 0.5);
    assert!(platform().cast_ray(r, &front()).is_none());
    let h = hit(&platform(), r, &QueryFilter::against(DOWN));
    assert_near(h.point, v(2.5, 1.0));
    assert_eq!(h.normal, UP);
    let f = QueryFilter {
        faces: Faces::Against(DOWN),
        ..QueryFilter::default()
    };
    assert_eq!(platform().cast_ray(r, &f), Some(h));
}

#[test]
fn solid_mask_ignores_one_way_platforms() {
    let m = map(r"
        ...
        .=.
        ...
        ###
    ");
    let r = ray(1.5, 0.5, 1.5, 3.5);
    assert_eq!(hit(&m, r, &front()).flags, SegmentFlags::ONE_WAY);
    let h = hit(&m, r, &front().with_mask(SegmentFlags::SOLID));
    assert_near(h.point, v(1.5, 3.0));
    assert_eq!(h.flags, SegmentFlags::SOLID);
}

#[test]
fn one_way_mask_ignores_solid_tiles() {
    let m = map(r"
        ...
        ###
        ...
        .=.
    ");
    let r = ray(1.5, 0.5, 1.5, 3.5);
    assert_near(hit(&m, r, &front()).point, v(1.5, 1.0));
    let h = hit(
        &m,
        r,
        &QueryFilter::both_sides().with_mask(SegmentFlags::ONE_WAY),
    );
    assert_near(h.point, v(1.5, 3.0));
    assert_eq!(h.flags, SegmentFlags::ONE_WAY);
}

#[test]
fn mask_of_a_flag_no_tile_has_hits_nothing() {
    let m = map(r"
        ...
        .=.
        ###
    ");
    let mask = SegmentFlags::user(0).unwrap();
    assert!(
        m.cast_ray(
            ray(1.5, 0.5, 1.5, 2.5),
            &QueryFilter::both_sides().with_mask(mask)
        )
        .is_none()
    );
    assert!(
        m.cast_ray(
            ray(1.5, 0.5, 1.5, 2.5),
            &front().with_mask(SegmentFlags::NONE)
        )
        .is_none()
    );
}

// ---------------------------------------------------------------------------------------
// All hits
// ---------------------------------------------------------------------------------------

#[track_caller]
fn assert_ys(got: &[f32], want: &[f32]) {
    assert_eq!(got.len(), want.len(), "{got:?} vs {want:?}");
    for (g, w) in got.iter().zip(want) {
        assert!((g - w).abs() < 1e-5, "{got:?} vs {want:?}");
    }
}

#[test]
fn cast_ray_all_returns_every_hit_sorted_by_t() {
    let m = map(r"
        ...
        .=.
        ...
        .=.
        ...
        ###
    ");
    let r = ray(1.5, 0.5, 1.5, 6.5);
    let all = m.cast_ray_all(r, &front());
    let ys: Vec<f32> = all.iter().map(|h| h.point.y).collect();
    assert_ys(&ys, &[1.0, 3.0, 5.0]);
    assert!(all.windows(2).all(|w| w[0].t <= w[1].t));
    assert_eq!(all[0], m.cast_ray(r, &front()).unwrap());
    // Both sides adds the floor's bottom face, seen from behind.
    let all = m.cast_ray_all(r, &QueryFilter::both_sides());
    let ys: Vec<f32> = all.iter().map(|h| h.point.y).collect();
    assert_ys(&ys, &[1.0, 3.0, 5.0, 6.0]);
    // Reversed, from below: only the floor's bottom face is a front face.
    let back = Ray::between(r.end(), r.origin);
    let all = m.cast_ray_all(back, &front());
    assert_eq!(all.len(), 1);
    assert_eq!(all[0].normal, DOWN);
}

#[test]
fn cast_ray_all_into_reuses_and_clears_the_buffer() {
    let m = platform();
    let mut out = m.cast_ray_all(ray(1.5, 0.5, 1.5, 2.5), &front());
    assert_eq!(out.len(), 1);
    m.cast_ray_all_into(ray(0.5, 0.5, 0.5, 2.5), &front(), &mut out);
    assert!(out.is_empty());
}

// ---------------------------------------------------------------------------------------
// Defined cases
// ---------------------------------------------------------------------------------------

#[test]
fn zero_length_ray_hits_nothing_even_on_a_surface() {
    let m = map(r"
        ...
        ###
    ");
    for p in [v(1.5, 0.5), v(1.5, 1.0), v(1.0, 1.0), v(1.5, 1.5)] {
        let r = Ray {
            origin: p,
            delta: Vec2::ZERO,
        };
        for filter in [
            front(),
            QueryFilter::both_sides(),
            QueryFilter::against(DOWN),
        ] {
            assert!(m.cast_ray(r, &filter).is_none(), "{p:?} {filter:?}");
            assert!(m.cast_ray_all(r, &filter).is_empty(), "{p:?} {filter:?}");
        }
    }
}

#[test]
fn nan_or_infinite_ray_hits_nothing() {
    let m = map(r"
        ...
        ###
    ");
    let bad = [
        Ray {
            origin: v(f32::NAN, 0.5),
            delta: v(0.0, 2.0),
        },
        Ray {
            origin: v(1.5, 0.5),
            delta: v(0.0, f32::NAN),
        },
        Ray {
            origin: v(1.5, f32::NEG_INFINITY),
            delta: v(0.0, 2.0),
        },
        Ray {
            origin: v(1.5, 0.5),
            delta: v(0.0, f32::INFINITY),
        },
    ];
    for r in bad {
        for filter in [front(), QueryFilter::both_sides()] {
            assert!(m.cast_ray(r, &filter).is_none(), "{r:?}");
            assert!(m.cast_ray_all(r, &filter).is_empty(), "{r:?}");
        }
    }
}

#[test]
fn ray_starting_on_a_front_face_moving_away_is_not_stopped() {
    let m = map(r"
        ...
        ###
    ");
    // From the floor's top face, upward (and up at an angle): the face does not hold it.
    assert!(m.cast_ray(ray(1.5, 1.0, 1.5, 0.0), &front()).is_none());
    assert!(m.cast_ray(ray(1.5, 1.0, 2.5, 0.0), &front()).is_none());
    // From a seam's end point too.
    assert!(m.cast_ray(ray(1.0, 1.0, 1.0, 0.0), &front()).is_none());
}

#[test]
fn ray_starting_on_a_face_is_stopped_at_t_zero_with_both_sides() {
    let m = map(r"
        ...
        ###
    ");
    let h = hit(&m, ray(1.5, 1.0, 1.5, 0.0), &QueryFilter::both_sides());
    assert_eq!(h.t, 0.0);
    assert_near(h.point, v(1.5, 1.0));
    assert_eq!(h.normal, UP);
}

#[test]
fn ray_starting_on_a_front_face_moving_into_it_hits_at_t_zero() {
    let m = map(r"
        ...
        ###
    ");
    let h = hit(&m, ray(1.5, 1.0, 1.5, 1.5), &front());
    assert_eq!(h.t, 0.0);
    assert_eq!(h.normal, UP);
}

#[test]
fn ray_starting_outside_the_map_hits_its_border() {
    let m = map(r"
        #..
        ...
        ..#
    ");
    // From the left, outside, into the left face of (0, 0).
    let h = hit(&m, ray(-5.0, 0.5, 1.5, 0.5), &front());
    assert_near(h.point, v(0.0, 0.5));
    assert_eq!(h.normal, LEFT);
    // From below-right, outside, into the bottom face of (2, 2).
    let h = hit(&m, ray(2.5, 7.0, 2.5, -1.0), &front());
    assert_near(h.point, v(2.5, 3.0));
    assert_eq!(h.normal, DOWN);
    // Passing beside the map entirely.
    assert!(
        m.cast_ray(ray(-1.0, -1.0, 5.0, -1.0), &QueryFilter::both_sides())
            .is_none()
    );
}

#[test]
fn nearest_hit_is_global_across_the_cells_walked() {
    // A long ray over a ramp field: whatever the walk visits first, the answer is the hit
    // with the smallest t among all of cast_ray_all's.
    let m = map(r"
        ..........
        ..../\....
        ...//\\...
        ..///\\\..
        ##########
    ");
    for i in 0..40 {
        let x0 = 0.1 + i as f32 * 0.25;
        let r = ray(x0, 0.3, 9.7 - x0, 4.6);
        let all = m.cast_ray_all(r, &front());
        let h = m.cast_ray(r, &front());
        assert_eq!(h.map(|h| h.t), all.first().map(|a| a.t), "{r:?}");
    }
}

// ---------------------------------------------------------------------------------------
// Regressions: bugs found by `ray_vs_brute_force.rs`, each pinned by its smallest case.
// ---------------------------------------------------------------------------------------

/// The walk used to walk the strip of cells on one side of a grid line to its end before
/// the other, and `cast_ray` stopped in the first strip at a farther hit (here t = 0.643 at
/// (5, 3) instead of t = 0.5 at (4, 3)).
#[test]
fn ray_along_a_horizontal_grid_line_returns_the_nearest_hit_from_either_side() {
    let m = map(r"
        ........
        ........
        ....#...
        .....#..
        ........
    ");
    // Along y = 3: the left face of (4, 2) at its lower end (4, 3), t = 0.5, above the line;
    // the left face of (5, 3) at its upper end (5, 3), t = 0.643, below it.
    let r = ray(0.5, 3.0, 7.5, 3.0);
    let h = hit(&m, r, &front());
    assert_eq!(h.t, 0.5, "{h:?}");
    assert_eq!(h.cell(), Some(Cell::new(4, 2)));
    assert_eq!(m.cast_ray_all(r, &front())[0].cell(), Some(Cell::new(4, 2)));
}

/// The same along a vertical grid line (was t = 0.7 at (3, 2) instead of t = 0.3).
#[test]
fn ray_along_a_vertical_grid_line_returns_the_nearest_hit_from_either_side() {
    let m = map(r"
        ......
        ...#..
        ......
        ..#...
        ......
        ......
    ");
    // Up along x = 3: the bottom face of (2, 3) at its end (3, 4), t = 0.3, left of the
    // line; the bottom face of (3, 1) at its end (3, 2), t = 0.7, right of it.
    let h = hit(&m, ray(3.0, 5.5, 3.0, 0.5), &front());
    assert!((h.t - 0.3).abs() < 1e-6, "{h:?}");
    assert_eq!(h.cell(), Some(Cell::new(2, 3)));
}

/// The walk clipped the ray to the map with `t_lo = (n − o) · (1 / d)`; `1 / d` is rounded,
/// so the clipped start landed at (0.9999998, 2.9999998) instead of (1, 3), inside cell
/// (0, 2), and cell (1, 2), touched only at that corner, was never visited. All inputs are
/// exact in binary; 22 of 199 such rays missed.
#[test]
fn ray_entering_the_map_through_a_border_lattice_point_hits_the_block_touched_there() {
    let m = map(r"
        ....
        ....
        .#..
    ");
    // From outside, below-right, up-left through (1, 3), the block's bottom-left corner: its
    // bottom face is met at its end point.
    let r = ray(4.0, 6.0, 0.5, 2.5);
    let h = hit(&m, r, &front());
    assert!((h.t - 3.0 / 3.5).abs() < 1e-6, "{h:?}");
    assert_eq!(h.normal, DOWN);
    assert_eq!(h.cell(), Some(Cell::new(1, 2)));
    assert_eq!(m.cast_ray_all(r, &front()).len(), 1);
}

/// The fast walk, while being written, ended on leaving the map before checking for a
/// corner crossing, so a ray leaving through a corner of the border skipped the side cell.
#[test]
fn ray_leaving_the_map_through_a_border_lattice_point_hits_the_block_touched_there() {
    let m = map(r"
        ....
        ...#
    ");
    // From inside (3, 0), down-right out through (4, 1), the block's top-right corner.
    let h = hit(&m, ray(3.5, 0.5, 4.5, 1.5), &front());
    assert_eq!(h.t, 0.5);
    assert_eq!(h.normal, UP);
    assert_eq!(h.cell(), Some(Cell::new(3, 1)));
}

/// With an origin that is not a dyadic number, the walk (in grid units, `(p − origin) /
/// cell`) saw the end point of a ray ending exactly on a floor at grid y = 0.99999994 and
/// never entered the floor's row, against "a ray ending exactly on a surface hits it".
#[test]
fn ray_ending_exactly_on_a_floor_hits_it_with_a_non_dyadic_origin() {
    let set = Arc::new(ascii::tile_set(1.0).unwrap());
    let m = TileMap::from_tiles(set, 1, 2, v(0.0, 1.58), &[None, Some(ascii::SOLID)]).unwrap();
    let top = m
        .active_segments(Cell::new(0, 1))
        .find(|s| s.normal == UP)
        .unwrap()
        .segment;
    // The floor's top is y = 2.58 (as the map stores it); the ray ends exactly there.
    let r = ray(0.5, top.a.y - 0.5, 0.5, top.a.y);
    assert_eq!(r.end().y, top.a.y);
    assert_eq!(
        tileslide::geometry::cast_ray_segment(&r, &top).unwrap().t,
        1.0
    );
    assert_eq!(hit(&m, r, &front()).t, 1.0);
}
