//! The cost of one far body: nine bodies walking in a room, then the same with a tenth a
//! million cells above, per broadphase. Prints the mean time of a step.
//!
//! `cargo run --release -p tileslide --example broadphase_outlier`

use std::time::Instant;

use tileslide::io::ascii;
use tileslide::{
    Bodies, BodyDesc, BodyShape, ResolveConfig, TileMap, Vec2, broadphase::PairMethod,
};

const STEPS: u32 = 2000;

/// Mean milliseconds per step of nine bodies (and the far one, if `far`).
fn step_ms(
    map: &TileMap,
    broadphase: PairMethod,
    far: bool,
) -> Result<f64, Box<dyn std::error::Error>> {
    let config = ResolveConfig {
        broadphase,
        ..ResolveConfig::default()
    };
    let mut bodies = Bodies::with_config(config)?;
    let mut handles = Vec::new();
    for i in 0..9 {
        let at = Vec2::new(2.5 + (i % 3) as f32 * 2.0, 2.5 + (i / 3) as f32 * 2.0);
        handles.push(bodies.add(BodyDesc::new(at, BodyShape::circle(0.3)?))?);
    }
    if far {
        handles.push(bodies.add(BodyDesc::new(
            Vec2::new(5.0, 1.0e6),
            BodyShape::circle(0.3)?,
        ))?);
    }
    let start = Instant::now();
    for step in 0..STEPS {
        for (k, &h) in handles.iter().enumerate() {
            let angle = (step as f32 * 0.01 + k as f32).sin() * 3.0;
            bodies.propose(h, Vec2::new(angle.cos(), angle.sin()) * 0.1)?;
        }
        bodies.step(map);
    }
    Ok(start.elapsed().as_secs_f64() * 1e3 / f64::from(STEPS))
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let room = [
        "##########",
        "#........#",
        "#........#",
        "#........#",
        "#........#",
        "#........#",
        "#........#",
        "#........#",
        "##########",
    ];
    let map = ascii::parse(&room.join("\n"), "room.txt", 1.0)?;
    for broadphase in [PairMethod::SweepAndPrune, PairMethod::UniformGrid] {
        let near = step_ms(&map, broadphase, false)?;
        let far = step_ms(&map, broadphase, true)?;
        println!("{broadphase:?}: 9 bodies {near:.4} ms a step, with one at y = 1e6 {far:.4} ms");
    }
    Ok(())
}
