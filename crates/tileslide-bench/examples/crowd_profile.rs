//! Runs the "crowd" scene with tileslide alone, for profilers (perf, callgrind):
//! `cargo run --release -p tileslide-bench --example crowd_profile -- [N] [steps] [edits] [k]`.
//! `edits` is `none` (the scene as BENCHMARKS.md has it), `dig` (`k` wall cells next to the
//! floor dug out every step, as a player digs a dungeon) or `platform` (`k` temporary
//! segments submitted anew every step, each one cell long and moving 0.05 cells a step):
//! what map edits cost the resolver's memories. `k` is 1 unless given.
//! Prints the step times and the resolve report (contacts, bodies cut short); figures that
//! compare with peers come from `tileslide bench crowd`. Also prints a checksum of the final
//! positions, bit for bit, so that two builds can be shown to move every body exactly the
//! same at any N (the golden-hash test covers 2,000 bodies).

use std::time::Instant;

use glam::Vec2;
use tileslide::{
    Bodies, BodyDesc, BodyShape, Cell, Owner, Segment, SegmentFlags, TemporarySegment,
};
use tileslide_scenes::{CROWD_RADIUS, audit_crowd, dungeon256, positions_hash, scene_crowd};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let n: usize = args.next().and_then(|s| s.parse().ok()).unwrap_or(10_000);
    let default_steps = if n >= 50_000 { 30 } else { 100 };
    let steps: usize = args
        .next()
        .and_then(|s| s.parse().ok())
        .unwrap_or(default_steps);
    let edits = args.next().unwrap_or_else(|| "none".to_owned());
    if !["none", "dig", "platform"].contains(&edits.as_str()) {
        return Err(format!("edits must be none, dig or platform, not {edits:?}").into());
    }
    let k: usize = match args.next() {
        Some(s) => s.parse().map_err(|e| format!("k: {s:?}: {e}"))?,
        None => 1,
    };
    let grid = dungeon256();
    let crowd = scene_crowd(&grid, n);
    let mut map = grid.to_tile_map()?;
    // Wall cells next to the floor, spread over the map: the cells `dig` digs out.
    let faces: Vec<Cell> = (0..256i64)
        .flat_map(|y| (0..256i64).map(move |x| (x, y)))
        .filter(|&(x, y)| {
            grid.is_solid(x, y)
                && (1..255).contains(&x)
                && (1..255).contains(&y)
                && [(1, 0), (-1, 0), (0, 1), (0, -1)]
                    .iter()
                    .any(|(dx, dy)| !grid.is_solid(x + dx, y + dy))
        })
        .map(|(x, y)| Cell::new(x as u32, y as u32))
        .collect();
    let mut bodies = Bodies::new();
    let shape = BodyShape::circle(CROWD_RADIUS)?;
    let mut handles = Vec::with_capacity(n);
    for b in &crowd {
        handles.push((
            bodies.add(BodyDesc::new(b.position, shape.clone()))?,
            b.velocity,
        ));
    }
    let mut times = Vec::with_capacity(steps);
    let (mut moving, mut contacts, mut cut) = (0, 0, 0);
    for step in 0..steps {
        match edits.as_str() {
            "dig" => {
                for e in 0..k {
                    map.set_tile(faces[(step * k + e) * 7919 % faces.len()], None)?;
                }
            }
            "platform" => {
                map.clear_temporaries();
                for p in 0..k {
                    // Eight a row, three cells apart; rows seven cells apart.
                    let a = Vec2::new(
                        100.0 + 0.05 * step as f32 + 3.0 * (p % 8) as f32,
                        100.5 + 7.0 * (p / 8) as f32,
                    );
                    map.add_temporary(TemporarySegment {
                        segment: Segment::new(a, a + Vec2::X),
                        normal: Vec2::NEG_Y,
                        flags: SegmentFlags::SOLID,
                        owner: Owner(p as u64),
                        velocity: Vec2::new(0.05, 0.0),
                    })?;
                }
            }
            _ => {}
        }
        let start = Instant::now();
        for &(h, v) in &handles {
            bodies.propose(h, v)?;
        }
        let report = bodies.step(&map);
        times.push(start.elapsed().as_secs_f64() * 1e3);
        moving += report.moving;
        contacts += report.contact_count;
        cut += report.cut_short;
    }
    println!(
        "per step: {} bodies resolved, {} contacts, {} cut short",
        moving / steps,
        contacts / steps,
        cut / steps
    );
    let positions: Vec<Vec2> = handles
        .iter()
        .map(|&(h, _)| bodies.get(h).map_or(Vec2::NAN, |b| b.position()))
        .collect();
    let per_ten: Vec<String> = times
        .chunks(10)
        .map(|c| format!("{:.2}", c.iter().sum::<f64>() / c.len() as f64))
        .collect();
    println!("ms/step, mean of each 10 steps: {}", per_ten.join(" "));
    let mut sorted = times.clone();
    sorted.sort_by(f64::total_cmp);
    let median = sorted.get(steps / 2).copied().unwrap_or(0.0);
    println!(
        "{n} circles, {steps} steps: median {median:.3} ms/step, {:.3} µs per circle",
        median * 1e3 / n as f64
    );
    if edits == "none" {
        let audit = audit_crowd(&grid, &positions, CROWD_RADIUS);
        println!("audit: {audit:?}");
    }
    println!(
        "checksum of the positions: {:016x}",
        positions_hash(&positions)
    );
    Ok(())
}
