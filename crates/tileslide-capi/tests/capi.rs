//! The C API called as C calls it: every map format loads, rays agree with the Rust API bit
//! for bit (one at a time and the standard rays scene in a batch), and bad input (null
//! pointers, coordinates that are not finite, unknown flags, missing and broken files) gets
//! a status and a message naming what and where.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic, unsafe_code)]

mod support;

use std::ffi::CString;
use std::path::{Path, PathBuf};
use std::ptr;

use support::last_error;
use tileslide::{QueryFilter, Ray};
use tileslide_capi::*;
use tileslide_scenes::{dungeon256, scene_rays};

fn maps() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/maps")
}

fn c(s: &str) -> CString {
    CString::new(s).unwrap()
}

/// Loads `path` through the C API, or the status and message.
fn load(path: &Path, tileset: Option<&Path>) -> Result<*mut ts_map, (ts_status, String)> {
    let p = c(path.to_str().unwrap());
    let t = tileset.map(|t| c(t.to_str().unwrap()));
    let mut out = ptr::null_mut();
    // SAFETY: valid strings and a writable out pointer.
    let status = unsafe {
        ts_map_load_file(
            p.as_ptr(),
            t.as_ref().map_or(ptr::null(), |t| t.as_ptr()),
            &mut out,
        )
    };
    if status == ts_status::TS_OK {
        assert!(!out.is_null());
        Ok(out)
    } else {
        assert!(out.is_null(), "out was written on failure");
        Err((status, last_error()))
    }
}

fn size(map: *const ts_map) -> (u32, u32, f32, f32) {
    let (mut w, mut h, mut cw, mut ch) = (0, 0, 0.0, 0.0);
    // SAFETY: a live map and writable outputs.
    let status = unsafe { ts_map_size(map, &mut w, &mut h, &mut cw, &mut ch) };
    assert_eq!(status, ts_status::TS_OK);
    (w, h, cw, ch)
}

#[test]
fn every_map_format_loads_and_is_the_rust_loaders_map() {
    let dir = maps();
    let baked = std::env::temp_dir().join(format!("tileslide-capi-{}.tsm", std::process::id()));
    let cave = tileslide::io::load_file(dir.join("cave.txt"), None).unwrap();
    tileslide::io::baked::save(&cave, &baked).unwrap();
    for (file, tileset) in [
        (dir.join("cave.txt"), None),
        (dir.join("cave.tmx"), None),
        (dir.join("cave.tmj"), None),
        (dir.join("ldtk/dungeon.ldtk"), None),
        (baked.clone(), None),
    ] {
        let map = load(&file, tileset).unwrap_or_else(|e| panic!("{}: {e:?}", file.display()));
        let rust = tileslide::io::load_file(&file, tileset).unwrap();
        let cell = rust.cell_size();
        assert_eq!(
            size(map),
            (rust.width(), rust.height(), cell.x, cell.y),
            "{}",
            file.display()
        );
        // SAFETY: a live map, freed once.
        unsafe { ts_map_free(map) };
    }
    std::fs::remove_file(&baked).unwrap();
    // SAFETY: null is ignored.
    unsafe { ts_map_free(ptr::null_mut()) };
}

#[test]
fn a_replica_island_level_loads_with_its_tile_set_and_is_refused_without() {
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/data/replica-island");
    if !data.is_dir() {
        assert!(
            std::env::var_os("CI").is_none(),
            "the Replica Island data is missing beside the checkout"
        );
        return;
    }
    let level = data.join("level_0_1_sewer.bin");
    let tileset = data.join("collision.bin");
    let map = load(&level, Some(&tileset)).unwrap();
    // SAFETY: a live map, freed once.
    unsafe { ts_map_free(map) };
    let (status, message) = load(&level, None).unwrap_err();
    assert_eq!(status, ts_status::TS_ERROR_INVALID_ARGUMENT);
    assert!(message.contains("needs its tile set"), "{message}");
}

#[test]
fn a_missing_a_broken_and_an_unknown_file_say_which_and_why() {
    let dir = maps();
    let (status, message) = load(&dir.join("nowhere.tmx"), None).unwrap_err();
    assert_eq!(status, ts_status::TS_ERROR_NOT_FOUND);
    assert!(message.starts_with("ts_map_load_file: "), "{message}");
    assert!(message.contains("nowhere.tmx"), "{message}");

    let broken = std::env::temp_dir().join(format!("tileslide-capi-{}.txt", std::process::id()));
    std::fs::write(&broken, "###\n#?#\n###").unwrap();
    let (status, message) = load(&broken, None).unwrap_err();
    std::fs::remove_file(&broken).unwrap();
    assert_eq!(status, ts_status::TS_ERROR_LOAD);
    assert!(
        message.contains(":2:2"),
        "names the line and column: {message}"
    );

    let (status, message) = load(&dir.join("tiles.png"), None).unwrap_err();
    assert_eq!(status, ts_status::TS_ERROR_INVALID_ARGUMENT);
    assert!(message.contains("unknown map format"), "{message}");

    let (status, message) = load(&dir.join("cave.txt"), Some(&dir.join("cave.txt"))).unwrap_err();
    assert_eq!(status, ts_status::TS_ERROR_INVALID_ARGUMENT);
    assert!(message.contains("carries its own tile set"), "{message}");
}

#[test]
fn null_pointers_bad_numbers_and_bad_flags_are_refused_with_a_status() {
    let mut out = ptr::null_mut();
    // SAFETY: each call is given a null or bad argument on purpose; the others are valid.
    unsafe {
        assert_eq!(
            ts_map_load_file(ptr::null(), ptr::null(), &mut out),
            ts_status::TS_ERROR_NULL_POINTER
        );
        assert!(last_error().contains("path is a null pointer"));
        let path = c("x.txt");
        assert_eq!(
            ts_map_load_file(path.as_ptr(), ptr::null(), ptr::null_mut()),
            ts_status::TS_ERROR_NULL_POINTER
        );
        let not_utf8 = CString::new(vec![0xff, 0xfe]).unwrap();
        assert_eq!(
            ts_map_load_file(not_utf8.as_ptr(), ptr::null(), &mut out),
            ts_status::TS_ERROR_INVALID_ARGUMENT
        );
        assert!(last_error().contains("not UTF-8"));
        let text = c("####\n#..#\n####");
        for cell in [0.0, -1.0, f32::NAN, f32::INFINITY] {
            assert_eq!(
                ts_map_from_ascii(text.as_ptr(), cell, &mut out),
                ts_status::TS_ERROR_INVALID_ARGUMENT
            );
        }
        assert!(out.is_null());
        assert_eq!(
            ts_map_from_ascii(text.as_ptr(), 1.0, &mut out),
            ts_status::TS_OK
        );
        let map = out;
        let mut hit = std::mem::zeroed::<ts_ray_hit>();
        assert!(!ts_map_cast_ray(
            ptr::null(),
            0.0,
            0.0,
            1.0,
            1.0,
            0,
            &mut hit
        ));
        assert!(last_error().contains("map is a null pointer"));
        assert!(!ts_map_cast_ray(
            map,
            1.5,
            1.5,
            9.0,
            1.5,
            0,
            ptr::null_mut()
        ));
        assert!(last_error().contains("out is a null pointer"));
        assert!(!ts_map_cast_ray(map, f32::NAN, 1.5, 9.0, 1.5, 0, &mut hit));
        assert!(last_error().contains("is not finite"), "{}", last_error());
        assert!(!ts_map_cast_ray(map, 1.5, 1.5, 9.0, 1.5, 6, &mut hit));
        assert!(last_error().contains("flags 0x6"), "{}", last_error());
        // A good ray after the failures: the wall at x = 3.
        assert!(ts_map_cast_ray(map, 1.5, 1.5, 9.0, 1.5, 0, &mut hit));
        assert_eq!((hit.x, hit.y, hit.nx, hit.ny), (3.0, 1.5, -1.0, 0.0));
        assert_eq!((hit.col, hit.row, hit.tile), (3, 1, 1));

        let mut hits = [std::mem::zeroed::<ts_ray_hit>(); 2];
        let rays = [1.5, 1.5, 9.0, 1.5, 1.5, 1.5, f32::INFINITY, 1.5];
        let before = hits;
        assert_eq!(
            ts_map_cast_rays(map, rays.as_ptr(), 2, 0, hits.as_mut_ptr()),
            ts_status::TS_ERROR_INVALID_ARGUMENT
        );
        assert!(
            last_error().contains("ray 1, (1.5, 1.5) to (inf, 1.5)"),
            "{}",
            last_error()
        );
        assert_eq!(hits, before, "nothing written");
        // Finite ends whose difference overflows: refused, not cast as a silent miss.
        let too_long = [1.5, 1.5, 2.5, 1.5, -3e38, 0.0, 3e38, 0.0];
        assert_eq!(
            ts_map_cast_rays(map, too_long.as_ptr(), 2, 0, hits.as_mut_ptr()),
            ts_status::TS_ERROR_INVALID_ARGUMENT
        );
        assert!(
            last_error().starts_with("ts_map_cast_rays: ray 1, ")
                && last_error().ends_with("is too long to cast"),
            "{}",
            last_error()
        );
        assert_eq!(hits, before, "nothing written");
        // Counts no memory could hold: refused before a slice of them is made.
        for n in [usize::MAX / 4 + 1, (isize::MAX as usize) / 16 + 1] {
            assert_eq!(
                ts_map_cast_rays(map, too_long.as_ptr(), n, 0, hits.as_mut_ptr()),
                ts_status::TS_ERROR_INVALID_ARGUMENT
            );
            assert!(last_error().contains("too many"), "{}", last_error());
        }
        assert_eq!(
            ts_map_cast_rays(map, ptr::null(), 2, 0, hits.as_mut_ptr()),
            ts_status::TS_ERROR_NULL_POINTER
        );
        assert_eq!(
            ts_map_cast_rays(map, ptr::null(), 0, 0, ptr::null_mut()),
            ts_status::TS_OK
        );
        ts_map_free(map);
    }
}

/// The standard rays scene on dungeon256, through the C batch and through Rust.
#[test]
fn the_rays_scene_through_c_is_the_rust_batch_bit_for_bit() {
    let grid = dungeon256();
    let rust_map = grid.to_tile_map().unwrap();
    // The same map through C: dungeon256 as ASCII text, unit cells.
    let text = grid.to_ascii();
    let ascii = c(&text);
    let mut map = ptr::null_mut();
    // SAFETY: a valid string and out pointer.
    assert_eq!(
        unsafe { ts_map_from_ascii(ascii.as_ptr(), 1.0, &mut map) },
        ts_status::TS_OK
    );
    // More rays than one chunk, and not a multiple of it.
    let scene = scene_rays(&grid, 10_000);
    let rays: Vec<Ray> = scene
        .iter()
        .map(|r| Ray::between(r.origin, r.end()))
        .collect();
    let flat: Vec<f32> = rays
        .iter()
        .flat_map(|r| {
            let end = r.end();
            [r.origin.x, r.origin.y, end.x, end.y]
        })
        .collect();
    for (flags, filter) in [
        (0, QueryFilter::default()),
        (
            TS_RAY_BOTH_SIDES,
            QueryFilter {
                faces: tileslide::Faces::Both,
                ..QueryFilter::default()
            },
        ),
    ] {
        let mut out = vec![unsafe { std::mem::zeroed::<ts_ray_hit>() }; rays.len()];
        // SAFETY: 4 n floats in, n hits out.
        let status =
            unsafe { ts_map_cast_rays(map, flat.as_ptr(), rays.len(), flags, out.as_mut_ptr()) };
        assert_eq!(status, ts_status::TS_OK);
        let rust = rust_map.cast_rays(&rays, &filter);
        let mut hits = 0;
        for (k, (c_hit, r_hit)) in out.iter().zip(&rust).enumerate() {
            match r_hit {
                None => assert!(c_hit.t.is_nan() && c_hit.tile == TS_NONE, "ray {k}"),
                Some(h) => {
                    hits += 1;
                    let cell = h.cell().unwrap();
                    let bits = |v: f32| v.to_bits();
                    assert_eq!(
                        [c_hit.t, c_hit.x, c_hit.y, c_hit.nx, c_hit.ny].map(bits),
                        [h.t, h.point.x, h.point.y, h.normal.x, h.normal.y].map(bits),
                        "ray {k}"
                    );
                    assert_eq!((c_hit.col, c_hit.row), (cell.col, cell.row), "ray {k}");
                    assert_eq!(c_hit.tile, h.tile().unwrap().0, "ray {k}");
                }
            }
            // One at a time agrees with the batch.
            let r = rays[k];
            let end = r.end();
            let mut single = unsafe { std::mem::zeroed::<ts_ray_hit>() };
            // SAFETY: a live map and a writable hit.
            let found = unsafe {
                ts_map_cast_ray(
                    map,
                    r.origin.x,
                    r.origin.y,
                    end.x,
                    end.y,
                    flags,
                    &mut single,
                )
            };
            assert_eq!(found, r_hit.is_some(), "ray {k}");
            if found {
                assert_eq!(single.t.to_bits(), c_hit.t.to_bits(), "ray {k}");
            }
        }
        assert!(hits > rays.len() * 9 / 10, "{hits} hits");
    }
    // SAFETY: a live map, freed once.
    unsafe { ts_map_free(map) };
}
