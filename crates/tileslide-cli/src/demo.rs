//! `tileslide demo dungeon`: runs the Dungeon Builder game headless with a progress bar,
//! writes an animated GIF and a final PNG, and prints the summary.

use std::path::{Path, PathBuf};

use anyhow::{Result, bail};
use clap::Subcommand;
use indicatif::{ProgressBar, ProgressStyle};
use tileslide::io::replica::ObjectKind;
use tileslide::{Aabb, Vec2};
use tileslide_dungeon::{Game, STEPS_PER_SECOND, Screen, Summary};
use tileslide_platformer::{Goal, IgnoredObjects, Level, MAX_STEPS};
use tileslide_render::{Canvas, Framing, ImageAnimation, Picture, RenderOptions, YAxis};

use crate::output;

/// GIF frames at most (a frame every N steps is chosen to stay under it): with frames of
/// 680 × 720 pixels, encoding them is most of the demo's time.
const MAX_FRAMES: u64 = 140;
/// Time each dungeon frame shows, in hundredths of a second: 140 frames play in about
/// 19 s.
const DUNGEON_FRAME_DELAY: u16 = 14;
/// How long the dungeon GIF's last frame (the end state) shows, in hundredths of a second.
const LAST_FRAME_DELAY: u16 = 400;

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
    /// Platformer: a scripted character runs a level of ramps, one-way platforms, a moving
    /// platform, coins and enemies (the bundled level, or a Replica Island level).
    ///
    /// A Replica Island level is played with the objects of its object layer: the player
    /// starts at its PLAYER spawn; COIN, RUBY and DIARY are coins; BROBOT, SNAILBOMB,
    /// SHADOWSLIME, MUDMAN, SKELETON and ONION walk back and forth; BAT, STING and KARAGUIN
    /// fly back and forth. Every other object (story characters, bosses, turrets, doors,
    /// buttons, cannons, spawners, breakable blocks, signs, effects) is ignored and counted
    /// in the summary by type number; the hot-spot layer is not used.
    Platformer {
        /// A level: an ASCII map with the demo's markers (`.txt`, see
        /// examples/maps/platformer.txt) or a Replica Island level (`.bin`, needs
        /// `--tileset`). Default: the bundled level.
        map: Option<PathBuf>,
        /// The tile set of a Replica Island level (`collision.bin`).
        #[arg(long, value_name = "FILE")]
        tileset: Option<PathBuf>,
        /// The animated GIF to write (the final PNG goes beside it).
        #[arg(short = 'o', long = "output", default_value = "platformer.gif")]
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
        DemoCommand::Platformer {
            map,
            tileset,
            output,
            json,
        } => platformer(map.as_deref(), tileset.as_deref(), &output, json),
    }
}

/// Refuses an output name the demo cannot write, before a game runs, not after: the GIF
/// `output` and the final frame's PNG beside it.
fn check_outputs(output: &Path) -> Result<PathBuf> {
    output::check(output, "-o", output::GIF)?;
    let png = output.with_extension("png");
    output::check(&png, "-o (the final frame beside the GIF)", output::PNG)?;
    Ok(png)
}

fn dungeon(seed: u64, minutes: f64, output: &Path, json: bool) -> Result<()> {
    if !(minutes.is_finite() && (0.0..=600.0).contains(&minutes)) {
        bail!("--minutes {minutes}: must be between 0 and 600");
    }
    let png = check_outputs(output)?;
    let steps = (minutes * 60.0 * f64::from(STEPS_PER_SECOND)).round() as u64;
    let every = steps.div_ceil(MAX_FRAMES).max(1);
    let mut game = Game::new(seed)?;
    let mut screen = Screen::new();
    let mut animation = ImageAnimation::new(
        tileslide_dungeon::WIDTH,
        tileslide_dungeon::HEIGHT,
        &tileslide_dungeon::style(),
    )?;
    animation.set_frame_delay(DUNGEON_FRAME_DELAY);
    let bar = ProgressBar::new(steps);
    bar.set_style(ProgressStyle::with_template(
        "{bar:40} {pos}/{len} steps {elapsed}",
    )?);
    if json {
        bar.set_draw_target(indicatif::ProgressDrawTarget::hidden());
    }
    for step in 0..steps {
        if step % every == 0 {
            animation.push(&screen.frame(&game, false)?)?;
        }
        game.step()?;
        bar.inc(1);
    }
    bar.finish_and_clear();
    // The end state, with how the game ended, held for a few seconds before the loop.
    let last = screen.frame(&game, true)?;
    animation.set_frame_delay(LAST_FRAME_DELAY);
    animation.push(&last)?;
    animation.save_gif(output)?;
    last.save_png(&png)?;
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

/// The platformer's GIF has a frame every this many steps (20 a second at 60 steps a
/// second, as its frame delay of 5 hundredths says: it plays in real time); a Replica
/// Island run (up to a minute over a large level) every 12, at four times the speed.
const PLATFORMER_FRAME_EVERY: u64 = 3;
const REPLICA_FRAME_EVERY: u64 = 12;

/// The platformer's pictures: at most this many pixels across (a long Replica Island level
/// gets fewer pixels per cell), and at most 16 pixels per cell.
const PLATFORMER_WIDTH: f32 = 1024.0;
/// Height of the legend strip under the platformer's pictures, in pixels.
const LEGEND_HEIGHT: u32 = 24;

fn platformer(map: Option<&Path>, tileset: Option<&Path>, output: &Path, json: bool) -> Result<()> {
    let png = check_outputs(output)?;
    let level = match (map, tileset) {
        (None, None) => Level::bundled()?,
        (None, Some(_)) => bail!("--tileset needs a Replica Island level (MAP.bin)"),
        (Some(map), Some(tileset)) => Level::load_replica(map, tileset)?,
        (Some(map), None) if map.extension().is_some_and(|e| e == "bin") => bail!(
            "{}: a Replica Island level needs its tile set: add --tileset collision.bin",
            map.display()
        ),
        (Some(map), None) => Level::load_ascii(map)?,
    };
    let y_axis = if level.up.y > 0.0 {
        YAxis::Up
    } else {
        YAxis::Down
    };
    let scale = (PLATFORMER_WIDTH / level.map.width().max(1) as f32).min(16.0);
    let options = RenderOptions::default()
        .with_pixels_per_cell(scale)
        .with_y_axis(y_axis);
    // The whole level, with a legend strip under it.
    let cell = level.map.cell_size();
    let width = (level.map.width() as f32 * scale).round().max(1.0) as u32;
    let height = (level.map.height() as f32 * scale * cell.y / cell.x)
        .round()
        .max(1.0) as u32;
    let corner = level.map.origin();
    let framing = Framing {
        window: Aabb::from_corners(
            corner,
            corner + Vec2::new(level.map.width() as f32, level.map.height() as f32) * cell,
        ),
        image: (width, height + LEGEND_HEIGHT),
        viewport: (width, height),
    };
    let canvas = Canvas::framed(&level.map, &options, &framing)?;
    let legend = tileslide_platformer::legend(&options.style);
    let every = if tileset.is_some() {
        REPLICA_FRAME_EVERY
    } else {
        PLATFORMER_FRAME_EVERY
    };
    let ignored = level.ignored_objects.clone();
    let mut game = tileslide_platformer::Game::new(level)?;
    let mut animation = ImageAnimation::new(canvas.width(), canvas.height(), &options.style)?;
    animation.set_frame_delay(5);
    let mut picture = Picture::new();
    let frame = |picture: &Picture| {
        let mut image = canvas.render(picture);
        legend.draw_across(&mut image, (0, height as i32), (width, LEGEND_HEIGHT));
        image
    };
    while !game.is_over() && game.summary().steps < MAX_STEPS {
        if game.summary().steps % every == 0 {
            game.draw(&mut picture);
            animation.push(&frame(&picture))?;
        }
        game.step()?;
    }
    game.draw(&mut picture);
    let last = frame(&picture);
    animation.push(&last)?;
    animation.save_gif(output)?;
    last.save_png(&png)?;
    let s = game.summary();
    let audit = &s.audit;
    if json {
        let value = serde_json::json!({
            "level": s.level,
            "steps": s.steps,
            "coins_collected": s.coins_collected,
            "coins_total": s.coins_total,
            "enemies_defeated": s.enemies_defeated,
            "enemies_total": s.enemies_total,
            "hits_taken": s.hits_taken,
            "jumps": s.jumps,
            "steps_riding": s.steps_riding,
            "goal": match s.goal {
                Goal::Marked => "marked",
                Goal::RightEnd => "right_end",
            },
            "reached": s.reached_goal,
            "ignored_objects": ignored.iter().map(|i| serde_json::json!({
                "type": i.type_number,
                "kind": i.kind.map(ObjectKind::name),
                "count": i.count,
            })).collect::<Vec<_>>(),
            "gif": output.display().to_string(),
            "png": png.display().to_string(),
            "audit": {
                "inside_solid": audit.inside_solid,
                "tunnels": audit.tunnels,
                "max_penetration": audit.max_penetration,
            },
        });
        println!("{value}");
        return Ok(());
    }
    let seconds = s.steps as f64 / f64::from(tileslide_platformer::STEPS_PER_SECOND);
    println!(
        "platformer ({}): {} steps ({seconds:.1} game s)",
        s.level, s.steps
    );
    println!(
        "  coins {}/{}, enemies defeated {}/{}, hits taken {}, jumps {}, steps riding the platform {}",
        s.coins_collected,
        s.coins_total,
        s.enemies_defeated,
        s.enemies_total,
        s.hits_taken,
        s.jumps,
        s.steps_riding
    );
    let reached = if s.reached_goal {
        "reached"
    } else {
        "not reached"
    };
    match s.goal {
        Goal::Marked => println!("  goal {reached}"),
        Goal::RightEnd => println!("  right end {reached} (the level has no goal)"),
    }
    if !ignored.is_empty() {
        let count: usize = ignored.iter().map(|i| i.count).sum();
        let each: Vec<String> = ignored
            .iter()
            .map(|i| format!("{} ×{}", object_name(i), i.count))
            .collect();
        println!("  objects ignored {count}: {}", each.join(", "));
    }
    println!(
        "  audit: steps inside solid {}, tunnels {}, max penetration {} cells",
        audit.inside_solid, audit.tunnels, audit.max_penetration
    );
    println!("  wrote {} and {}", output.display(), png.display());
    Ok(())
}

/// An ignored object's name in the summary: the game's name and type number, `DOOR_RED
/// (32)`, or `type 4` for a number the game does not define.
fn object_name(i: &IgnoredObjects) -> String {
    match i.kind {
        Some(kind) => format!("{kind} ({})", i.type_number),
        None => format!("type {}", i.type_number),
    }
}
