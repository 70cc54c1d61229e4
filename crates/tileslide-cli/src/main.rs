//! The `tileslide` command-line tool: inspect maps, cast rays, find paths, simulate crowds,
//! draw and bake maps, run the demo games; with the `peers` feature, run the standard
//! benchmarks against tileslide's peers.
#![forbid(unsafe_code)]

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{CommandFactory, FromArgMatches, Parser, Subcommand};

#[cfg(feature = "peers")]
mod bench;
mod demo;
mod explain;
mod info;
mod json;
mod map_file;
mod output;
mod path;
mod point_arg;
mod raycast;
mod render;
mod scene;
mod simulate;
mod soak;

/// Collision detection for tile-based 2D games: inspect, cast rays, find paths, simulate,
/// draw and bake maps, run the demo games, benchmark.
#[derive(Parser, Debug)]
#[command(name = "tileslide", version)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Size, cell size, tiles used and segments before and after seam culling.
    Info {
        #[command(flatten)]
        map: map_file::MapArgs,
        /// Print one JSON object.
        #[arg(long)]
        json: bool,
    },
    /// Cast rays against a map: the nearest surface each ray hits.
    Raycast {
        #[command(flatten)]
        map: map_file::MapArgs,
        /// Start point `X,Y` in map coordinates.
        #[arg(
            long,
            value_name = "X,Y",
            requires = "to",
            conflicts_with = "rays",
            allow_hyphen_values = true
        )]
        from: Option<String>,
        /// End point `X,Y` in map coordinates.
        #[arg(
            long,
            value_name = "X,Y",
            requires = "from",
            allow_hyphen_values = true
        )]
        to: Option<String>,
        /// A CSV file with one ray per line, `x0,y0,x1,y1` (`#` starts a comment line).
        #[arg(long, value_name = "FILE", required_unless_present = "from")]
        rays: Option<PathBuf>,
        /// Hit back faces too (by default a ray hits only faces it meets head-on).
        #[arg(long)]
        both_sides: bool,
        /// Print one JSON object per ray, one per line, in input order.
        #[arg(long)]
        json: bool,
    },
    /// Find the way for a circle of radius R from one point to another: the shortest path
    /// on the navigation grid, smoothed into straight runs that keep clear of every wall.
    Path {
        #[command(flatten)]
        map: map_file::MapArgs,
        /// Start point `X,Y` in map coordinates.
        #[arg(long, value_name = "X,Y", allow_hyphen_values = true)]
        from: String,
        /// Goal point `X,Y` in map coordinates.
        #[arg(long, value_name = "X,Y", allow_hyphen_values = true)]
        to: String,
        /// The circle's radius, in map units (positive).
        #[arg(long, value_name = "R", allow_hyphen_values = true)]
        radius: String,
        /// Print one JSON object: `{"found":true,"length":L,"points":[[X,Y],...]}` or
        /// `{"found":false}`.
        #[arg(long)]
        json: bool,
    },
    /// Step circles with constant proposed moves through a map; print where they end and
    /// an audit of overlaps and wall penetrations.
    Simulate {
        /// The scene: `{"map": "file.txt"}` or `{"ascii": "..."}`, optional `"cell"` and
        /// `"steps"`, and `"bodies": [{"x": X, "y": Y, "r": R, "vx": VX, "vy": VY}]`.
        scene: PathBuf,
        /// Steps to run (overrides the scene's `"steps"`; default 100).
        #[arg(long)]
        steps: Option<u64>,
        /// Print one JSON object.
        #[arg(long)]
        json: bool,
        /// Also write an animated GIF of the bodies over the map: a frame at the start,
        /// every `--every` steps, and at the end.
        #[arg(long, value_name = "OUT.gif")]
        gif: Option<PathBuf>,
        /// Steps between GIF frames (default 1).
        #[arg(long, value_name = "N", requires = "gif")]
        every: Option<u64>,
        /// Pixels per cell in the GIF (default 16).
        #[arg(long, value_name = "PX", requires = "gif", allow_hyphen_values = true)]
        scale: Option<f32>,
    },
    /// Draw a map to a PNG: solid cells filled, active segments (one-way platforms in
    /// orange) with their normals. Replica Island levels are drawn y up, others y down.
    Render {
        #[command(flatten)]
        map: map_file::MapArgs,
        /// Pixels per cell.
        #[arg(long, value_name = "PX", default_value_t = tileslide_render::DEFAULT_PIXELS_PER_CELL, allow_hyphen_values = true)]
        scale: f32,
        /// Draw y up (row 0 at the bottom), for a baked Replica Island level.
        #[arg(long)]
        y_up: bool,
        /// Where to write the PNG (default: the map's name with `.png`, in the current
        /// directory).
        #[arg(short, long, value_name = "OUT.png")]
        output: Option<PathBuf>,
    },
    /// Bake a map into tileslide's binary format (`.tsm`), which loads without parsing
    /// text: its tile set, size, origin and tiles, checksummed.
    Bake {
        #[command(flatten)]
        map: map_file::MapArgs,
        /// Where to write the baked map (a `.tsm` name: the other commands tell a baked
        /// map by it).
        #[arg(short, long, value_name = "OUT.tsm")]
        output: PathBuf,
    },
    /// Run a standard benchmark scene of BENCHMARKS.md against the peers in the same run.
    #[cfg(feature = "peers")]
    Bench {
        #[command(subcommand)]
        which: bench::BenchCommand,
    },
    /// Benchmarks against parry2d, rapier2d and the pathfinding crate: not in this build
    /// (build with `--features peers`).
    #[cfg(not(feature = "peers"))]
    Bench {
        /// The benchmark and its arguments (`rays`, `crowd`, `broad`, `paths`).
        #[arg(trailing_var_arg = true, allow_hyphen_values = true)]
        args: Vec<String>,
    },
    /// Tell why: the story of a body (`--body K`) or of the character (`--character`) of a
    /// scene, every contact with the tile, segment or body it came from and what was done
    /// with it; or why each segment of a map's cell (`--cell C,R`) is active or hidden and
    /// how its ends join. `-o OUT.png` draws it.
    Explain(explain::ExplainArgs),
    /// Run a long randomized session (a cave dug and built, bodies, characters, moving
    /// platforms, hit volumes, rays, paths, snapshots) with every promise audited every
    /// step; report steps per second and the audit, and fail on any violation.
    Soak(soak::SoakArgs),
    /// Run a demo game headless and write a GIF, a final PNG and a summary.
    Demo {
        #[command(subcommand)]
        which: demo::DemoCommand,
    },
}

/// `tileslide bake`: loads the map, writes it baked, and says what it wrote.
fn bake(map: &map_file::MapArgs, output: &std::path::Path) -> anyhow::Result<()> {
    output::check(output, "-o", output::BAKED)?;
    let (loaded, _) = map_file::load(map)?;
    let bytes = tileslide::io::baked::to_bytes(&loaded);
    std::fs::write(output, &bytes)
        .map_err(|e| anyhow::anyhow!("{}: cannot write: {e}", output.display()))?;
    println!(
        "{}: {} × {} cells, {} tile shapes, {} bytes",
        output.display(),
        loaded.width(),
        loaded.height(),
        loaded.tile_set().len(),
        bytes.len()
    );
    Ok(())
}

/// `tileslide bench ...` in a build without the peers: says how to get them.
#[cfg(not(feature = "peers"))]
fn bench_without_peers(args: &[String]) -> anyhow::Result<()> {
    let shown = if args.is_empty() {
        "rays".to_owned()
    } else {
        args.join(" ")
    };
    anyhow::bail!(
        "`tileslide bench` measures tileslide against parry2d, rapier2d, Box2D and the pathfinding crate in the same run, and this build leaves them out; build it with the `peers` feature:\n  cargo run --release -p tileslide-cli --features peers -- bench {shown}"
    )
}

/// The command line, where every option takes a negative number as its value (`--cell -1`
/// reaches the check that refuses it, `--from -1.5,2` is a point), not as a flag.
fn command() -> clap::Command {
    fn negatives_are_values(command: clap::Command) -> clap::Command {
        command
            .allow_negative_numbers(true)
            .mut_subcommands(negatives_are_values)
    }
    negatives_are_values(Cli::command())
}

fn main() -> ExitCode {
    // Usage errors (an unknown option, a missing argument, a value of the wrong kind) are
    // clap's, with exit status 2; errors found while running exit with 1.
    let cli = match Cli::from_arg_matches(&command().get_matches()) {
        Ok(cli) => cli,
        Err(e) => e.format(&mut command()).exit(),
    };
    let result = match cli.command {
        Command::Info { map, json } => info::run(&map, json),
        Command::Raycast {
            map,
            from,
            to,
            rays,
            both_sides,
            json,
        } => raycast::run(&map, from.zip(to), rays, both_sides, json),
        Command::Path {
            map,
            from,
            to,
            radius,
            json,
        } => path::run(&map, &from, &to, &radius, json),
        Command::Simulate {
            scene,
            steps,
            json,
            gif,
            every,
            scale,
        } => {
            let gif = gif.map(|path| simulate::GifArgs {
                path,
                every: every.unwrap_or(1),
                scale: scale.unwrap_or(tileslide_render::DEFAULT_PIXELS_PER_CELL),
            });
            simulate::run(&scene, steps, json, gif.as_ref())
        }
        Command::Render {
            map,
            scale,
            y_up,
            output,
        } => render::run(&map, scale, output, y_up),
        Command::Bake { map, output } => bake(&map, &output),
        #[cfg(feature = "peers")]
        Command::Bench { which } => bench::run(which),
        #[cfg(not(feature = "peers"))]
        Command::Bench { args } => bench_without_peers(&args),
        Command::Explain(args) => explain::run(&args),
        Command::Soak(args) => soak::run(&args),
        Command::Demo { which } => demo::run(which),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {}", output::message(&e));
            ExitCode::FAILURE
        }
    }
}
