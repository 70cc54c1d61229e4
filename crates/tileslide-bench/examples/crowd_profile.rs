//! Runs the "crowd" scene with tileslide alone, for profilers (perf, callgrind):
//! `cargo run --release -p tileslide-bench --example crowd_profile -- [N] [steps]`.
//! Prints the step times and the resolve report (contacts, bodies cut short); figures that
//! compare with peers come from `tileslide bench crowd`. Also prints a checksum of the final
//! positions, bit for bit, so that two builds can be shown to move every body exactly the
//! same at any N (the golden-hash test covers 2,000 bodies).

use std::time::Instant;

use glam::Vec2;
use tileslide::{Bodies, BodyDesc, BodyShape};
use tileslide_scenes::{CROWD_RADIUS, audit_crowd, dungeon256, scene_crowd};

/// FNV-1a (64-bit) over the bits of every final position, x then y, body by body (the
/// golden-hash test's checksum).
fn checksum(positions: &[Vec2]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for bits in positions
        .iter()
        .flat_map(|p| [p.x.to_bits(), p.y.to_bits()])
    {
        for byte in bits.to_le_bytes() {
            h = (h ^ u64::from(byte)).wrapping_mul(0x0000_0100_0000_01b3);
        }
    }
    h
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let n: usize = args.next().and_then(|s| s.parse().ok()).unwrap_or(10_000);
    let default_steps = if n >= 50_000 { 30 } else { 100 };
    let steps: usize = args
        .next()
        .and_then(|s| s.parse().ok())
        .unwrap_or(default_steps);
    let grid = dungeon256();
    let crowd = scene_crowd(&grid, n);
    let map = grid.to_tile_map()?;
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
    for _ in 0..steps {
        let start = Instant::now();
        for &(h, v) in &handles {
            bodies.propose(h, v)?;
        }
        let report = bodies.step(&map);
        times.push(start.elapsed().as_secs_f64() * 1e3);
        moving += report.moving;
        contacts += report.contacts;
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
    let audit = audit_crowd(&grid, &positions, CROWD_RADIUS);
    println!("audit: {audit:?}");
    println!("checksum of the positions: {:016x}", checksum(&positions));
    Ok(())
}
