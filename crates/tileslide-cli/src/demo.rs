//! `tileslide demo dungeon`: runs the Dungeon Builder game headless with a progress bar,
//! writes an animated GIF and a final PNG, and prints the summary.

use std::path::{Path, PathBuf};

use anyhow::{Result, bail};
use clap::Subcommand;
use indicatif::{ProgressBar, ProgressStyle};
use tileslide_dungeon::{Game, STEPS_PER_SECOND, Summary};
use tileslide_render::{Animation, Canvas, RenderOptions};

/// GIF frames at most (a frame every N steps is chosen to stay under it).
const MAX_FRAMES: u64 = 240;
/// Pixels per cell of the pictures (the map is 64 cells wide).
const SCALE: f32 = 8.0;

#[derive(Subcommand, Debug)]
pub enum DemoCommand {
    /// Dungeon Builder: a keeper digs and defends, hero parties raid the treasure.
    Dungeon {
        /// The game's seed.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Game minutes to run.
        #[arg(long, default_value_t = 2.0)]
        minutes: f64,
        /// The animated GIF to write (the final PNG goes beside it).
        #[arg(short = 'o', long = "output", default_value = "dungeon.gif")]
        output: PathBuf,
        /// Print the summary as one JSON object.
        #[arg(long)]
        json: bool,
    },
}

/// Runs a demo.
pub fn run(which: DemoCommand) -> Result<()> {
    match which {
        DemoCommand::Dungeon {
            seed,
            minutes,
            output,
            json,
        } => dungeon(seed, minutes, &output, json),
    }
}

fn dungeon(seed: u64, minutes: f64, output: &Path, json: bool) -> Result<()> {
    if !(minutes.is_finite() && (0.0..=600.0).contains(&minutes)) {
        bail!("--minutes {minutes}: must be between 0 and 600");
    }
    // Refuse a path that cannot be written before running the game, not after.
    let folder = output
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    if !folder.is_dir() {
        bail!(
            "{}: cannot write there: the folder {} does not exist",
            output.display(),
            folder.display()
        );
    }
    let steps = (minutes * 60.0 * f64::from(STEPS_PER_SECOND)).round() as u64;
    let every = steps.div_ceil(MAX_FRAMES).max(1);
    let mut game = Game::new(seed)?;
    let options = RenderOptions::default()
        .with_pixels_per_cell(SCALE)
        .with_style(tileslide_dungeon::style());
    let canvas = Canvas::new(game.initial_map(), &options)?;
    let mut animation = Animation::new(&canvas)?.with_frame_delay(8);
    let bar = ProgressBar::new(steps);
    bar.set_style(ProgressStyle::with_template(
        "{bar:40} {pos}/{len} steps {elapsed}",
    )?);
    if json {
        bar.set_draw_target(indicatif::ProgressDrawTarget::hidden());
    }
    for step in 0..steps {
        if step % every == 0 {
            animation.push(&game.picture(true))?;
        }
        game.step()?;
        bar.inc(1);
    }
    bar.finish_and_clear();
    animation.push(&game.picture(true))?;
    animation.save_gif(output)?;
    let png = output.with_extension("png");
    Canvas::new(game.map(), &options)?
        .render(&game.picture(false))
        .save_png(&png)?;
    let summary = game.summary();
    if json {
        println!(
            "{}",
            summary_json(&summary, seed, game.state_hash(), output, &png)
        );
    } else {
        print_summary(&summary, seed, game.state_hash(), output, &png);
    }
    Ok(())
}

fn summary_json(s: &Summary, seed: u64, hash: u64, gif: &Path, png: &Path) -> serde_json::Value {
    serde_json::json!({
        "seed": seed,
        "steps": s.steps,
        "waves": s.waves,
        "heroes_lost": s.heroes_lost,
        "heroes_escaped": s.heroes_escaped,
        "creatures_summoned": s.creatures_summoned,
        "creatures_lost": s.creatures_lost,
        "treasure_taken": s.treasure_taken,
        "treasure_left": s.treasure_left,
        "treasure_stolen": s.treasure_stolen,
        "squares_dug": s.squares_dug,
        "state_hash": format!("{hash:016x}"),
        "gif": gif.display().to_string(),
        "png": png.display().to_string(),
        "audit": {
            "overlapping_pairs": s.audit.overlapping_pairs,
            "wall_penetrations": s.audit.wall_penetrations,
        },
    })
}

fn print_summary(s: &Summary, seed: u64, hash: u64, gif: &Path, png: &Path) {
    println!(
        "dungeon (seed {seed}): {} steps ({:.1} game s)",
        s.steps,
        s.steps as f64 / f64::from(STEPS_PER_SECOND)
    );
    println!(
        "  waves {}, heroes lost {}, heroes escaped {}",
        s.waves, s.heroes_lost, s.heroes_escaped
    );
    println!(
        "  creatures summoned {}, creatures lost {}",
        s.creatures_summoned, s.creatures_lost
    );
    println!(
        "  treasure left {} (taken {}, stolen {}), squares dug {}",
        s.treasure_left, s.treasure_taken, s.treasure_stolen, s.squares_dug
    );
    println!(
        "  audit: overlapping pairs {}, wall penetrations {}",
        s.audit.overlapping_pairs, s.audit.wall_penetrations
    );
    println!(
        "  state hash {hash:016x}; wrote {} and {}",
        gif.display(),
        png.display()
    );
}
