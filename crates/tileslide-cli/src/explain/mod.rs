//! `tileslide explain`: the story of a body or of the character of a scene, step by step,
//! in words and in a picture; or why each segment of a map's cell is active or hidden and
//! how its ends join.

mod body;
mod cell;
mod character;
mod picture;
mod words;

use std::path::PathBuf;

use anyhow::{Result, bail};
use clap::{ArgGroup, Args};

use crate::map_file::{MapArgs, TiledLimits};
use crate::output;

/// The arguments of `tileslide explain`.
#[derive(Args, Debug)]
#[command(group(ArgGroup::new("subject").required(true).args(["body", "character", "cell"])))]
pub struct ExplainArgs {
    /// A scene file (`simulate`'s format) with `--body` or `--character`, or a map with
    /// `--cell`.
    pub input: PathBuf,
    /// The body to follow: its index in the scene's `bodies`, from 0.
    #[arg(long, value_name = "K")]
    pub body: Option<usize>,
    /// Follow the scene's character.
    #[arg(long)]
    pub character: bool,
    /// The map cell to explain, as `COL,ROW`.
    #[arg(long, value_name = "C,R")]
    pub cell: Option<String>,
    /// Only this step (from 1); the picture shows it. Default: every step, and the picture
    /// shows the last one where something was met.
    #[arg(long, value_name = "S", conflicts_with = "cell")]
    pub step: Option<u64>,
    /// Write a picture of the story (PNG).
    #[arg(short, long, value_name = "OUT.png")]
    pub output: Option<PathBuf>,
    /// The tile set of a map that needs one (with `--cell`).
    #[arg(long, value_name = "FILE", requires = "cell")]
    pub tileset: Option<PathBuf>,
    /// The cell size of an ASCII map (with `--cell`; default 1).
    #[arg(long, value_name = "SIZE", requires = "cell")]
    pub cell_size: Option<f32>,
    /// The colliding tile layer of a Tiled map or LDtk project (with `--cell`).
    #[arg(long, value_name = "NAME", requires = "cell")]
    pub layer: Option<String>,
    /// The level of an LDtk project (with `--cell`).
    #[arg(long, value_name = "NAME", requires = "cell")]
    pub level: Option<String>,
    /// Print JSON instead of words.
    #[arg(long)]
    pub json: bool,
}

/// Runs `tileslide explain`.
pub fn run(args: &ExplainArgs) -> Result<()> {
    if let Some(out) = &args.output {
        output::check(out, "-o", output::PNG)?;
    }
    let out = args.output.as_deref();
    if let Some(text) = &args.cell {
        let map = MapArgs {
            map: args.input.clone(),
            tileset: args.tileset.clone(),
            cell: args.cell_size,
            layer: args.layer.clone(),
            level: args.level.clone(),
            limits: TiledLimits::default(),
        };
        return cell::run(&map, text, out, args.json);
    }
    if let Some(k) = args.body {
        return body::run(&args.input, k, args.step, out, args.json);
    }
    if args.character {
        return character::run(&args.input, args.step, out, args.json);
    }
    bail!("say what to explain: --body K, --character or --cell C,R")
}
