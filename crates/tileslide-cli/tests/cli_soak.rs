//! `tileslide soak` as CI runs it: a short session with every kind of check run and none
//! failing, the same seed giving the same final state and another seed another, and sizes
//! past the limits refused with errors that name them.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use serde_json::Value;
use support::{stderr, stdout, tileslide};

mod support;

/// A short soak's JSON report.
fn soak(seed: &str) -> Value {
    let o = tileslide(&[
        "soak",
        "--steps",
        "400",
        "--bodies",
        "300",
        "--characters",
        "12",
        "--snapshot-every",
        "100",
        "--seed",
        seed,
        "--json",
    ]);
    let report: Value = serde_json::from_str(&stdout(&o))
        .unwrap_or_else(|e| panic!("{e}: {}\n{}", stdout(&o), stderr(&o)));
    assert!(o.status.success(), "{report:#}\n{}", stderr(&o));
    report
}

#[test]
fn a_short_soak_runs_every_check_and_finds_nothing() {
    let report = soak("7");
    assert_eq!(report["violations"], 0, "{report:#}");
    assert_eq!(report["steps"], 400);
    assert_eq!(report["bodies"], 300);
    assert_eq!(report["characters"], 12);
    let checks = &report["checks"];
    // Per step: every body placed and every character moved; the rest at least this often.
    let least = [
        ("body_place", 400 * 300),
        ("body_pair", 1_000),
        ("character_place", 400 * 12),
        ("ray", 400 * 16),
        ("volumes", 400),
        ("circle_cast", 400),
        ("flow_direction", 400),
        ("path", 10),
        ("map_edit", 50),
        ("bad_value", 20),
        // Snapshots at steps 100, 200, 300 and 400... each checked over 30 steps: the one
        // at 400 has not finished.
        ("snapshot", 3),
    ];
    for (kind, n) in least {
        let runs = checks[kind]["checks"].as_u64().unwrap_or(0);
        assert!(
            runs >= n,
            "{kind}: {runs} checks, expected at least {n}: {report:#}"
        );
        assert_eq!(checks[kind]["violations"], 0, "{kind}: {report:#}");
    }
    assert!(report["steps_per_second"].as_f64().unwrap() > 0.0);
}

#[test]
fn the_same_seed_gives_the_same_run_and_another_seed_another() {
    let (a, b, c) = (soak("11"), soak("11"), soak("12"));
    assert_eq!(a["hash"], b["hash"]);
    assert_eq!(a["checks"], b["checks"]);
    assert_ne!(a["hash"], c["hash"]);
}

#[test]
fn sizes_past_the_limits_are_refused_by_name() {
    for (flag, value, max) in [
        ("--bodies", "200001", "200000"),
        ("--characters", "10001", "10000"),
        ("--rays", "10001", "10000"),
        ("--platforms", "1001", "1000"),
    ] {
        let o = tileslide(&["soak", "--steps", "1", flag, value]);
        assert!(!o.status.success());
        let err = stderr(&o);
        assert!(
            err.contains(flag) && err.contains(value) && err.contains(max),
            "{flag} {value}: {err}"
        );
    }
    let o = tileslide(&["soak", "--steps", "-5"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
}
