//! `tileslide bench`.

use anyhow::{Result, anyhow};
use clap::Subcommand;
use indicatif::{ProgressBar, ProgressStyle};
use serde_json::json;
use tileslide_bench::rays::{RaysConfig, RaysReport, run_rays};
use tileslide_scenes::Scene;

#[derive(Subcommand, Debug)]
pub enum BenchCommand {
    /// The "rays" scene: 1,000,000 rays on dungeon256 or open256, tileslide vs parry2d.
    Rays {
        /// The map: dungeon256 or open256.
        #[arg(long, default_value = "dungeon256", value_parser = parse_scene)]
        scene: Scene,
        /// How many rays (the first N of the scene).
        #[arg(long, default_value_t = 1_000_000, value_parser = clap::value_parser!(u64).range(1..=100_000_000))]
        n: u64,
        /// Timed passes per engine; the median is reported.
        #[arg(long, default_value_t = 7, value_parser = clap::value_parser!(u64).range(1..=1000))]
        passes: u64,
        /// Print one JSON object.
        #[arg(long)]
        json: bool,
    },
}

fn parse_scene(name: &str) -> Result<Scene, String> {
    Scene::from_name(name)
        .ok_or_else(|| format!("unknown scene {name:?}: expected dungeon256 or open256"))
}

pub fn run(which: BenchCommand) -> Result<()> {
    match which {
        BenchCommand::Rays {
            scene,
            n,
            passes,
            json,
        } => {
            if cfg!(debug_assertions) {
                eprintln!(
                    "warning: this is a debug build; benchmark figures are only meaningful with --release"
                );
            }
            let config = RaysConfig {
                scene,
                rays: n as usize,
                passes: passes as usize,
            };
            // Hidden automatically when stderr is not a terminal.
            let bar = ProgressBar::new(0);
            if let Ok(style) = ProgressStyle::with_template("{msg} [{bar:30}] {pos}/{len} passes") {
                bar.set_style(style.progress_chars("=> "));
            }
            bar.set_message(format!("bench rays {}", scene.name()));
            let report = run_rays(config, |done, total| {
                bar.set_length(total as u64);
                bar.set_position(done as u64);
            })
            .map_err(|e| anyhow!("{e}"))?;
            bar.finish_and_clear();
            if json {
                println!("{}", rays_json(&report));
            } else {
                print_rays_table(&report);
            }
            Ok(())
        }
    }
}

fn rays_json(report: &RaysReport) -> serde_json::Value {
    let results: Vec<_> = report
        .results
        .iter()
        .map(|r| {
            json!({
                "name": r.name,
                "mrays_per_s": r.mrays_per_s,
                "min_mrays_per_s": r.spread.0,
                "max_mrays_per_s": r.spread.1,
                "hits": r.hits,
                "mean_t": r.mean_t,
                "mean_distance": r.mean_distance,
                "disagreements": r.disagreements,
            })
        })
        .collect();
    json!({
        "scene": report.scene,
        "fingerprint": report.fingerprint,
        "rays": report.rays,
        "passes": report.passes,
        "results": results,
    })
}

fn print_rays_table(report: &RaysReport) {
    println!(
        "scene {} (fingerprint {}), {} rays, median of {} passes, single thread",
        report.scene, report.fingerprint, report.rays, report.passes
    );
    println!(
        "{:<18} {:>9} {:>17} {:>9} {:>8} {:>10} {:>13}",
        "engine", "Mrays/s", "(slowest–fastest)", "hits", "mean t", "mean dist", "disagreements"
    );
    for r in &report.results {
        println!(
            "{:<18} {:>9.2} {:>17} {:>9} {:>8.4} {:>10.4} {:>13}",
            r.name,
            r.mrays_per_s,
            format!("({:.2}–{:.2})", r.spread.0, r.spread.1),
            r.hits,
            r.mean_t,
            r.mean_distance,
            r.disagreements
        );
    }
    if let Some((ours, peers)) = report.results.split_first()
        && let Some(best) = peers
            .iter()
            .max_by(|a, b| a.mrays_per_s.total_cmp(&b.mrays_per_s))
    {
        println!(
            "tileslide: {:.1}× the best peer ({}) in this run",
            ours.mrays_per_s / best.mrays_per_s,
            best.name
        );
    }
}
