//! `tileslide simulate` on scenes whose numbers leave the coordinate range: refused with an
//! error naming the body, the field or the step, never a run through every wall.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use support::{scratch_in, stderr, tileslide};

mod support;

#[test]
fn simulate_refuses_positions_radii_and_moves_beyond_the_range() {
    let room = r######""ascii": "#####\n#...#\n#####""######;
    let cases = [
        // Finite, but past MAX_COORD.
        (
            r#"{"x": 1.5, "y": 1e20, "r": 0.3}"#,
            vec!["bodies[0].x/y", "out of range"],
        ),
        (
            r#"{"x": 1.5, "y": 1.5, "r": 3e38}"#,
            vec!["bodies[0].r", "16777216"],
        ),
        // A move of 1e20 cells once went through every wall with a clean audit.
        (
            r#"{"x": 1.5, "y": 1.5, "r": 0.3, "vx": 0.0, "vy": 1e20}"#,
            vec!["bodies[0] at step 1", "out of range"],
        ),
        // A constant move, in the open beside the map, leaves the range after a few steps.
        (
            r#"{"x": 10.5, "y": 1.5, "r": 0.3, "vx": 0.0, "vy": -6000000}"#,
            vec!["bodies[0] at step 3", "out of range"],
        ),
    ];
    for (i, (body, expected)) in cases.iter().enumerate() {
        let text = format!(r#"{{{room}, "steps": 5, "bodies": [{body}]}}"#);
        let scene = scratch_in("bodies_simulate", &format!("far_{i}.json"), &text);
        let o = tileslide(&["simulate", scene.to_str().unwrap(), "--json"]);
        assert!(!o.status.success(), "case {i} should fail");
        let err = stderr(&o);
        for part in expected {
            assert!(err.contains(part), "case {i}: {err}");
        }
        assert!(err.contains(&format!("far_{i}.json")), "case {i}: {err}");
    }
}
