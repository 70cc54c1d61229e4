//! `tileslide simulate SCENE.json`: circles with constant proposed moves, stepped with the
//! resolver, audited at the end; with `--gif`, recorded as an animated GIF.

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{Context, Result, bail};
use serde::Deserialize;
use serde_json::json;
use tileslide::io::ascii;
use tileslide::{Bodies, BodyDesc, BodyHandle, BodyShape, Circle, SegmentFlags, TileMap, Vec2};
use tileslide_render::{Animation, Canvas, Picture, categorical};

use crate::json::number;
use crate::map_file::{self, MapFormat};
use crate::output;
use crate::render;

/// Most steps a scene may ask for (a typo of a few zeros should not run for days).
const MAX_STEPS: u64 = 10_000_000;

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

/// The scene file.
#[derive(Deserialize, Debug)]
#[serde(deny_unknown_fields)]
struct SceneFile {
    /// A map file, relative to the scene file: any format the other commands read.
    map: Option<String>,
    /// Or an ASCII map itself.
    ascii: Option<String>,
    /// Cell size of an ASCII map (default 1).
    cell: Option<f32>,
    /// The tile set of a Replica Island level, relative to the scene file.
    tileset: Option<String>,
    /// The collision layer of a Tiled map.
    layer: Option<String>,
    /// Steps to run, unless `--steps` says otherwise.
    steps: Option<u64>,
    bodies: Vec<BodyEntry>,
}

#[derive(Deserialize, Debug)]
#[serde(deny_unknown_fields)]
struct BodyEntry {
    x: f32,
    y: f32,
    r: f32,
    #[serde(default)]
    vx: f32,
    #[serde(default)]
    vy: f32,
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
    let text = std::fs::read_to_string(scene_path)
        .with_context(|| format!("{}: cannot read the scene", scene_path.display()))?;
    let scene: SceneFile = serde_json::from_str(&text)
        .with_context(|| format!("{}: not a valid scene", scene_path.display()))?;
    let (map, format) = load_map(scene_path, &scene)?;
    let steps = steps.or(scene.steps).unwrap_or(100);
    if steps > MAX_STEPS {
        bail!(
            "{}: steps: {steps} is more than the {MAX_STEPS} allowed",
            scene_path.display()
        );
    }
    let canvas = gif
        .map(|g| gif_canvas(g, steps, &map, format, scene_path))
        .transpose()?;
    let mut recording = canvas
        .as_ref()
        .zip(gif)
        .map(|(c, g)| Recording::new(c, g.every))
        .transpose()?;
    // The resolver's default gap suits cells of side 1: scaled to this map's cells.
    let gap = tileslide::ResolveConfig::default().gap * map.cell_size().min_element();
    let mut bodies = Bodies::with_config(tileslide::ResolveConfig {
        gap,
        ..tileslide::ResolveConfig::default()
    })?;
    let skin = 1e-4 * map.cell_size().min_element();
    let mut crowd: Vec<(BodyHandle, Vec2)> = Vec::with_capacity(scene.bodies.len());
    for (i, b) in scene.bodies.iter().enumerate() {
        let at = |field: &str| format!("{}: bodies[{i}].{field}", scene_path.display());
        let shape = BodyShape::circle(b.r).with_context(|| at("r"))?;
        let handle = bodies
            .add(BodyDesc::new(Vec2::new(b.x, b.y), shape))
            .with_context(|| at("x/y"))?;
        // The resolver keeps bodies out of walls; one that starts in a wall has no answer.
        let depth = penetration(&map, &Circle::new(Vec2::new(b.x, b.y), b.r));
        if depth > skin {
            bail!(
                "{}: the circle at ({}, {}) of radius {} starts inside a wall (by {depth})",
                at("x/y"),
                b.x,
                b.y,
                b.r
            );
        }
        let velocity = Vec2::new(b.vx, b.vy);
        if !velocity.is_finite() {
            bail!(
                "{}: the move ({}, {}) is not finite",
                at("vx/vy"),
                b.vx,
                b.vy
            );
        }
        crowd.push((handle, velocity));
    }
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
        bodies.step(&map);
        elapsed += start.elapsed().as_secs_f64();
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
    let audit = audit(&map, &circles, skin);
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
        let out = json!({
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

fn load_map(scene_path: &Path, scene: &SceneFile) -> Result<(TileMap, MapFormat)> {
    let cell = scene.cell.unwrap_or(1.0);
    if scene.map.is_none() && (scene.tileset.is_some() || scene.layer.is_some()) {
        bail!(
            "{}: \"tileset\" and \"layer\" go with a \"map\" file",
            scene_path.display()
        );
    }
    if !(cell > 0.0 && cell.is_finite()) {
        bail!(
            "{}: cell: {cell} must be a positive number",
            scene_path.display()
        );
    }
    match (&scene.map, &scene.ascii) {
        (Some(_), Some(_)) => bail!(
            "{}: give either \"map\" (a file) or \"ascii\" (the map itself), not both",
            scene_path.display()
        ),
        (None, None) => bail!(
            "{}: missing the map: add \"map\": \"file.txt\" or \"ascii\": \"...\"",
            scene_path.display()
        ),
        (Some(file), None) => {
            let dir = scene_path.parent().unwrap_or(Path::new("."));
            let args = map_file::MapArgs {
                map: dir.join(file),
                tileset: scene.tileset.as_ref().map(|t| dir.join(t)),
                cell: scene.cell,
                layer: scene.layer.clone(),
                limits: map_file::TiledLimits::default(),
            };
            map_file::load(&args)
        }
        (None, Some(text)) => {
            let name = format!("{} (field \"ascii\")", scene_path.display());
            Ok((ascii::parse(text, &name, cell)?, MapFormat::Ascii))
        }
    }
}

/// How deep `c` is in a wall: how much closer its centre is than its radius to a solid
/// (not one-way) segment it is in front of, or its radius when its centre is in solid; 0
/// when it is clear.
fn penetration(map: &TileMap, c: &Circle) -> f32 {
    let mut worst = 0.0f32;
    for s in map.segments_overlapping_circle(c) {
        if s.flags.contains(SegmentFlags::ONE_WAY) || (c.center - s.segment.a).dot(s.normal) < 0.0 {
            continue;
        }
        let depth = c.radius - s.segment.distance_squared_to(c.center).sqrt();
        worst = worst.max(depth);
    }
    if map.is_point_solid(c.center) {
        worst = worst.max(c.radius);
    }
    worst
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
