//! `tileslide bench ...` as a user runs it, in a build with the peers (`--features peers`):
//! every contender in the JSON and the tables, the same answers as tileslide, and arguments
//! refused.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use serde_json::Value;
use support::{stderr, stdout, tileslide};

mod support;

#[test]
fn bench_rays_json_has_every_engine_and_the_fingerprint() {
    let o = tileslide(&["bench", "rays", "--n", "2000", "--passes", "1", "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(v["scene"], "dungeon256");
    assert_eq!(v["fingerprint"], "a36c9fd56f2ba422");
    assert_eq!(v["rays"], 2000);
    let names: Vec<&str> = v["results"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["name"].as_str().unwrap())
        .collect();
    assert_eq!(
        names,
        [
            "tileslide",
            "parry2d-voxels",
            "parry2d-polyline",
            "box2d-chains",
            "box2d-boxes",
            "tileslide-single",
            "tileslide-portable"
        ]
    );
    for r in v["results"].as_array().unwrap() {
        assert!(r["mrays_per_s"].as_f64().unwrap() > 0.0);
        assert!(r["hits"].as_u64().unwrap() > 1500);
    }
    for engine in [0, 1, 3, 4, 5, 6] {
        assert_eq!(
            v["results"][engine]["disagreements"], 0,
            "{}",
            names[engine]
        );
    }
}

#[test]
fn bench_crowd_json_lists_every_contender_with_its_audit() {
    let o = tileslide(&["bench", "crowd", "--n", "100", "--steps", "3", "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["n"], 100);
    assert_eq!(v["steps"], 3);
    let names: Vec<_> = v["results"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["name"].as_str().unwrap().to_string())
        .collect();
    assert_eq!(
        names,
        [
            "tileslide",
            "parry2d-voxels",
            "parry2d-segments",
            "rapier2d-kcc",
            "box2d-mover"
        ]
    );
    let ours = &v["results"][0];
    assert_eq!(ours["audit"]["overlapping_pairs"], 0);
    assert_eq!(ours["audit"]["wall_penetrations"], 0);
    assert!(ours["mean_travel"].as_f64().unwrap() > 0.0);
    assert!(ours["ms_per_step"].as_f64().unwrap() > 0.0);
}

#[test]
fn bench_broad_json_lists_every_contender_with_the_exact_pair_count() {
    let o = tileslide(&["bench", "broad", "--n", "3000", "--updates", "3", "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["scene"], "broad");
    assert_eq!(v["n"], 3000);
    assert_eq!(v["updates"], 3);
    let results = v["results"].as_array().unwrap();
    let names: Vec<&str> = results
        .iter()
        .map(|r| r["name"].as_str().unwrap())
        .collect();
    assert_eq!(
        names,
        [
            "tileslide-grid",
            "tileslide-sap",
            "parry2d-bvh",
            "rapier2d-broad",
            "box2d-tree"
        ]
    );
    // Every contender finds the same pairs, the brute-force ones.
    let pairs = results[0]["pairs"].as_u64().unwrap();
    assert!(pairs > 50, "{pairs}");
    for r in results {
        assert_eq!(r["pairs"].as_u64(), Some(pairs), "{r}");
        assert_eq!(r["exact"], true, "{r}");
        assert!(r["ms_per_update"].as_f64().unwrap() > 0.0, "{r}");
    }
}

#[test]
fn bench_broad_table_names_the_fastest_tileslide_entry_and_peer() {
    let o = tileslide(&["bench", "broad", "--n", "2000", "--updates", "2"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(out.contains("broad: 2000 circles"), "{out}");
    for name in [
        "tileslide-grid",
        "tileslide-sap",
        "parry2d-bvh",
        "rapier2d-broad",
        "box2d-tree",
    ] {
        assert!(out.contains(name), "{out}");
    }
    let ratio = out
        .lines()
        .find(|l| l.contains("× the fastest peer"))
        .unwrap_or_else(|| panic!("no ratio line in {out}"));
    assert!(ratio.starts_with("tileslide-"), "{ratio}");
    assert!(
        !ratio.contains("(tileslide"),
        "a tileslide entry taken for a peer: {ratio}"
    );
}

#[test]
fn bench_broad_rejects_zero_circles_and_updates() {
    for args in [["--n", "0"], ["--updates", "0"]] {
        let o = tileslide(&["bench", "broad", args[0], args[1]]);
        assert!(!o.status.success());
        assert!(stderr(&o).contains(args[0]), "{}", stderr(&o));
    }
}

#[test]
fn bench_paths_json_has_both_contenders_finding_the_same_queries() {
    let o = tileslide(&["bench", "paths", "--queries", "20", "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(v["scene"], "paths");
    assert_eq!(v["queries"], 20);
    let results = v["results"].as_array().unwrap();
    assert_eq!(results.len(), 4, "{v}");
    for radius in [0.3, 0.8] {
        let of = |name: &str| {
            results
                .iter()
                .find(|r| r["radius"].as_f64() == Some(radius) && r["name"] == name)
                .unwrap_or_else(|| panic!("no {name} at radius {radius}: {v}"))
        };
        let (ours, peer) = (of("tileslide"), of("pathfinding-astar"));
        for r in [ours, peer] {
            let keys: Vec<&str> = r.as_object().unwrap().keys().map(String::as_str).collect();
            assert_eq!(
                keys,
                [
                    "radius",
                    "name",
                    "ms_total",
                    "us_per_query",
                    "found",
                    "mean_length",
                    "mismatches"
                ]
            );
            assert_eq!(r["mismatches"], 0, "{r}");
            assert!(r["ms_total"].as_f64().unwrap() > 0.0, "{r}");
        }
        assert_eq!(ours["found"], peer["found"], "radius {radius}");
        assert!(ours["found"].as_u64().unwrap() > 0, "{ours}");
        // Smoothing makes tileslide's paths no longer than the lattice paths.
        assert!(
            ours["mean_length"].as_f64().unwrap() <= peer["mean_length"].as_f64().unwrap() + 1e-3,
            "{ours} {peer}"
        );
    }
}

#[test]
fn bench_threads_json_compares_every_pool_and_finds_the_same_answers() {
    let o = tileslide(&[
        "bench",
        "threads",
        "--threads",
        "1,3",
        "--rays",
        "20000",
        "--crowd",
        "2000",
        "--steps",
        "3",
        "--broad",
        "9000",
        "--passes",
        "1",
        "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["identical"], true);
    assert_eq!(v["crowd_clean"], true);
    // The host's share of the CPU time, read from /proc/stat on Linux.
    let steal = &v["host_steal_percent"];
    if cfg!(target_os = "linux") {
        let steal = steal.as_f64().unwrap_or_else(|| panic!("{steal}"));
        assert!((0.0..=100.0).contains(&steal), "{steal}");
    } else {
        assert!(steal.is_null(), "{steal}");
    }
    let rows: Vec<(String, u64)> = v["results"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| {
            (
                r["work"].as_str().unwrap().to_string(),
                r["threads"].as_u64().unwrap(),
            )
        })
        .collect();
    let expected: Vec<(String, u64)> = ["rays", "crowd", "broad"]
        .iter()
        .flat_map(|w| [1, 3].map(|t| (w.to_string(), t)))
        .collect();
    assert_eq!(rows, expected);
    for pair in v["results"].as_array().unwrap().chunks(2) {
        assert_eq!(pair[0]["checksum"], pair[1]["checksum"], "{pair:?}");
        assert_eq!(pair[0]["speedup"], 1.0);
    }
}

#[test]
fn bench_growth_table_lists_each_layout_on_each_pool() {
    let o = tileslide(&[
        "bench",
        "growth",
        "--n",
        "300",
        "--k",
        "1,2",
        "--threads",
        "1,2",
        "--steps",
        "2",
        "--passes",
        "2",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(
        out.contains("positions identical on every pool: yes"),
        "{out}"
    );
    assert!(out.contains("2 steps × 2 passes interleaved"), "{out}");
    for row in ["  1       300        1", "  2      1200        2"] {
        assert!(out.contains(row), "{row:?} in\n{out}");
    }
}

#[test]
fn bench_growth_json_gives_each_run_its_passes_range_and_the_steal_time() {
    let o = tileslide(&[
        "bench",
        "growth",
        "--n",
        "200",
        "--k",
        "1,2",
        "--threads",
        "1",
        "--steps",
        "2",
        "--passes",
        "3",
        "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(v["passes"], 3);
    assert_eq!(v["identical"], true);
    assert!(v["host_steal_percent"].is_number() || v["host_steal_percent"].is_null());
    let results = v["results"].as_array().unwrap();
    assert_eq!(results.len(), 2);
    for r in results {
        let (fast, median, slow) = (
            r["ms_fastest_pass"].as_f64().unwrap(),
            r["ms_per_step"].as_f64().unwrap(),
            r["ms_slowest_pass"].as_f64().unwrap(),
        );
        assert!(fast <= slow && fast > 0.0, "{r}");
        assert!(median > 0.0, "{r}");
    }
    assert_eq!(results[0]["growth"], 1.0);
    assert_eq!(results[1]["bodies"], 800);
}

#[test]
fn bench_threads_and_growth_refuse_zero_threads_and_large_layouts() {
    for args in [
        &["bench", "threads", "--threads", "0"][..],
        &["bench", "growth", "--k", "9"],
        &["bench", "growth", "--threads", "2,0"],
        &["bench", "growth", "--passes", "0"],
    ] {
        let o = tileslide(args);
        assert!(!o.status.success(), "{args:?}");
        assert!(
            stderr(&o).contains("invalid value"),
            "{args:?}: {}",
            stderr(&o)
        );
    }
}
