//! `tileslide simulate SCENE.json`: circles with constant proposed moves, stepped with the
//! resolver, audited at the end (and a character run from its script); with `--gif`,
//! recorded as an animated GIF.

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{Context, Result, bail};
use serde_json::json;
use tileslide::{Bodies, BodyHandle, Circle, TileMap, Vec2};
use tileslide_render::{Animation, Canvas, Picture, categorical};

use crate::json::number;
use crate::map_file::MapFormat;
use crate::output;
use crate::render;
use crate::scene::{Scene, audit_skin, penetration};

/// Most frames a GIF may have (each a full picture of the map).
const MAX_GIF_FRAMES: u64 = 10_000;

/// `--gif OUT.gif [--every N] [--scale PX]`.
#[derive(Clone, Debug)]
pub struct GifArgs {
    /// Where to write the GIF.
    pub path: PathBuf,
    /// Steps between frames.
    pub every: u64,
    /// Pixels per cell.
    pub scale: f32,
}

/// What the end of a simulation looks like.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Audit {
    pub overlapping_pairs: usize,
    pub max_overlap: f32,
    pub wall_penetrations: usize,
    pub max_penetration: f32,
}

pub fn run(
    scene_path: &Path,
    steps: Option<u64>,
    json_out: bool,
    gif: Option<&GifArgs>,
) -> Result<()> {
    if let Some(gif) = gif {
        output::check(&gif.path, "--gif", output::GIF)?;
        render::check_scale(gif.scale)?;
        if gif.every == 0 {
            bail!("--every 0: steps between frames must be at least 1");
        }
    }
    let scene = Scene::load(scene_path)?;
    let steps = scene.steps(steps, scene_path)?;
    let (map, format) = (&scene.map, scene.format);
    let canvas = gif
        .map(|g| gif_canvas(g, steps, map, format, scene_path))
        .transpose()?;
    let mut recording = canvas
        .as_ref()
        .zip(gif)
        .map(|(c, g)| Recording::new(c, g.every))
        .transpose()?;
    let skin = audit_skin(map);
    let (mut bodies, crowd) = scene.bodies(scene_path)?;
    let mut character = scene.character(scene_path)?;
    let mut elapsed = 0.0f64;
    if let Some(r) = &mut recording {
        r.record(&bodies, &crowd)?;
    }
    for step in 1..=steps {
        for (i, &(h, v)) in crowd.iter().enumerate() {
            // A constant move carries a body out of the coordinate range in the end: the
            // library refuses the move, naming where it would end.
            bodies
                .propose(h, v)
                .with_context(|| format!("{}: bodies[{i}] at step {step}", scene_path.display()))?;
        }
        let start = Instant::now();
        bodies.step(map);
        elapsed += start.elapsed().as_secs_f64();
        if let Some(run) = &mut character {
            run.step(map, None)
                .with_context(|| format!("{}: character at step {step}", scene_path.display()))?;
        }
        if let Some(r) = &mut recording
            && (step.is_multiple_of(r.every) || step == steps)
        {
            r.record(&bodies, &crowd)?;
        }
    }
    let circles: Vec<Circle> = crowd
        .iter()
        .map(|&(h, _)| {
            let body = bodies.get(h)?;
            Ok(Circle::new(body.position(), body.shape().bounding_radius()))
        })
        .collect::<Result<_>>()?;
    let audit = audit(map, &circles, skin);
    let ms_per_step = if steps == 0 {
        0.0
    } else {
        elapsed * 1e3 / steps as f64
    };
    if json_out {
        let bodies: Vec<_> = circles
            .iter()
            .map(|c| json!({"x": number(c.center.x), "y": number(c.center.y)}))
            .collect();
        let mut out = json!({
            "steps": steps,
            "bodies": bodies,
            "audit": {
                "overlapping_pairs": audit.overlapping_pairs,
                "max_overlap": number(audit.max_overlap),
                "wall_penetrations": audit.wall_penetrations,
                "max_penetration": number(audit.max_penetration),
            },
            "ms_per_step": ms_per_step,
        });
        if let Some(run) = &character {
            let c = &run.character;
            out["character"] = json!({
                "x": number(c.position.x),
                "y": number(c.position.y),
                "grounded": c.ground().is_some(),
            });
        }
        println!("{out}");
    } else {
        println!(
            "{} bodies, {steps} steps, {ms_per_step:.3} ms/step",
            circles.len()
        );
        for (i, c) in circles.iter().enumerate() {
            println!("  body {i}: ({}, {})", c.center.x, c.center.y);
        }
        println!(
            "audit (skin {skin}): {} overlapping pairs (max overlap {}), {} wall penetrations (max {})",
            audit.overlapping_pairs,
            audit.max_overlap,
            audit.wall_penetrations,
            audit.max_penetration
        );
        if let Some(run) = &character {
            let c = &run.character;
            let state = if c.ground().is_some() {
                "on the ground"
            } else {
                "in the air"
            };
            println!("character: ({}, {}), {state}", c.position.x, c.position.y);
        }
    }
    if let (Some(r), Some(gif)) = (recording, gif) {
        r.save(&gif.path, json_out)?;
    }
    Ok(())
}

/// The canvas of `--gif`, once the frames it would take are known to be allowed.
fn gif_canvas(
    gif: &GifArgs,
    steps: u64,
    map: &TileMap,
    format: MapFormat,
    scene_path: &Path,
) -> Result<Canvas> {
    let frames = steps / gif.every + 1 + u64::from(!steps.is_multiple_of(gif.every));
    if frames > MAX_GIF_FRAMES {
        bail!(
            "--gif: {steps} steps with a frame every {} make {frames} frames, more than the {MAX_GIF_FRAMES} allowed; raise --every",
            gif.every
        );
    }
    render::canvas(map, format, scene_path, gif.scale, false)
}

/// The GIF being recorded: the bodies over the map, one frame at a time.
struct Recording<'c> {
    animation: Animation<'c>,
    picture: Picture,
    /// Steps between frames.
    every: u64,
}

impl<'c> Recording<'c> {
    fn new(canvas: &'c Canvas, every: u64) -> Result<Self> {
        Ok(Self {
            animation: Animation::new(canvas)?,
            picture: Picture::new(),
            every,
        })
    }

    /// Writes the GIF and says so (on stderr under `--json`, so stdout stays one object).
    fn save(self, path: &Path, json_out: bool) -> Result<()> {
        let (width, height) = (self.animation.width(), self.animation.height());
        let frames = self.animation.frame_count();
        self.animation.save_gif(path)?;
        let note = format!(
            "{}: {width} × {height} pixels, {frames} frames",
            path.display()
        );
        if json_out {
            eprintln!("{note}");
        } else {
            println!("{note}");
        }
        Ok(())
    }

    /// Appends a frame of every body where it is now.
    fn record(&mut self, bodies: &Bodies, crowd: &[(BodyHandle, Vec2)]) -> Result<()> {
        self.picture.clear();
        // Each body in a colour of its own, by its number in the scene, the same in
        // every frame.
        for (i, &(h, _)) in crowd.iter().enumerate() {
            let body = bodies.get(h)?;
            let color = categorical(i as u64);
            for c in body.shape().circles() {
                self.picture
                    .body_with_color(Circle::new(body.position() + c.center, c.radius), color);
            }
        }
        self.animation.push(&self.picture)?;
        Ok(())
    }
}

/// Pairs overlapping by more than `skin`, and circles whose centre is in front of a solid
/// (not one-way) segment and closer to it than the radius by more than `skin`.
pub fn audit(map: &TileMap, circles: &[Circle], skin: f32) -> Audit {
    let mut audit = Audit::default();
    // Pairs: sweep along x.
    let mut order: Vec<usize> = (0..circles.len()).collect();
    order.sort_by(|&a, &b| circles[a].center.x.total_cmp(&circles[b].center.x));
    let largest = circles.iter().map(|c| c.radius).fold(0.0, f32::max);
    for (k, &i) in order.iter().enumerate() {
        let a = circles[i];
        for &j in &order[k + 1..] {
            let b = circles[j];
            if b.center.x - a.center.x > a.radius + largest {
                break;
            }
            let overlap = a.radius + b.radius - a.center.distance(b.center);
            audit.max_overlap = audit.max_overlap.max(overlap);
            if overlap > skin {
                audit.overlapping_pairs += 1;
            }
        }
    }
    for c in circles {
        let worst = penetration(map, c);
        audit.max_penetration = audit.max_penetration.max(worst);
        if worst > skin {
            audit.wall_penetrations += 1;
        }
    }
    audit
}
