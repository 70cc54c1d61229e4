//! The scene file that `simulate` and `explain` read: a map, circles with constant moves,
//! and a character run from a small script.

use std::path::Path;

use anyhow::{Context, Result, bail};
use serde::Deserialize;
use tileslide::io::ascii;
use tileslide::{
    Bodies, BodyDesc, BodyHandle, BodyShape, Character, CharacterShape, Circle, Contacts,
    ControllerConfig, MoveOptions, MoveTrace, SegmentFlags, TileMap, Vec2,
};

// `super`: the fuzz target `scene` includes this file beside a `map_file` of its own.
use super::map_file::{self, MapFormat};

/// Most steps a scene may ask for (a typo of a few zeros should not run for days).
pub const MAX_STEPS: u64 = 10_000_000;

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
    /// The collision layer of a Tiled map or an LDtk project.
    layer: Option<String>,
    /// The level of an LDtk project.
    level: Option<String>,
    /// Steps to run, unless `--steps` says otherwise.
    steps: Option<u64>,
    #[serde(default)]
    bodies: Vec<BodyEntry>,
    /// A platformer character run from a script.
    character: Option<CharacterEntry>,
}

/// A circle and its constant move per step.
#[derive(Deserialize, Debug, Clone, Copy)]
#[serde(deny_unknown_fields)]
pub struct BodyEntry {
    pub x: f32,
    pub y: f32,
    pub r: f32,
    #[serde(default)]
    pub vx: f32,
    #[serde(default)]
    pub vy: f32,
}

/// A character: a box (`half_width`, `half_height`) or a circle (`r`) at (`x`, `y`), with
/// gravity and a script.
#[derive(Deserialize, Debug, Clone)]
#[serde(deny_unknown_fields)]
struct CharacterEntry {
    x: f32,
    y: f32,
    half_width: Option<f32>,
    half_height: Option<f32>,
    r: Option<f32>,
    /// Added to the fall speed every step, in map units per step per step (default 0.02
    /// cells).
    gravity: Option<f32>,
    /// The highest ledge it steps up onto (default 0).
    step_height: Option<f32>,
    #[serde(default)]
    script: Vec<ScriptEntry>,
}

/// What the character does for a number of steps.
#[derive(Deserialize, Debug, Clone, Copy)]
#[serde(deny_unknown_fields)]
struct ScriptEntry {
    /// How many steps (default 1).
    #[serde(default = "one")]
    steps: u64,
    /// Sideways move per step, towards higher x (negative: lower x).
    #[serde(default)]
    walk: f32,
    /// An upward speed (map units per step) set at the entry's first step.
    jump: Option<f32>,
    /// Drop through one-way platforms during these steps.
    #[serde(default)]
    drop: bool,
}

fn one() -> u64 {
    1
}

/// A scene read and checked: its map, its bodies, its character.
pub struct Scene {
    pub map: TileMap,
    pub format: MapFormat,
    /// The steps the scene asks for, if it does.
    pub steps: Option<u64>,
    pub bodies: Vec<BodyEntry>,
    character: Option<CharacterEntry>,
}

impl Scene {
    /// Reads and checks the scene at `path`.
    pub fn load(path: &Path) -> Result<Self> {
        let bytes = tileslide::io::read_limited(path)
            .with_context(|| format!("{}: cannot read the scene", path.display()))?;
        let text = String::from_utf8(bytes)
            .with_context(|| format!("{}: the scene is not UTF-8 text", path.display()))?;
        Self::parse(&text, path)
    }

    /// Reads and checks the scene `text`, from the file at `path` (which names it in
    /// errors, and which the map file it names is relative to).
    pub fn parse(text: &str, path: &Path) -> Result<Self> {
        let scene: SceneFile = serde_json::from_str(text)
            .with_context(|| format!("{}: not a valid scene", path.display()))?;
        let (map, format) = load_map(path, &scene)?;
        if let Some(steps) = scene.steps
            && steps > MAX_STEPS
        {
            bail!(
                "{}: steps: {steps} is more than the {MAX_STEPS} allowed",
                path.display()
            );
        }
        Ok(Self {
            map,
            format,
            steps: scene.steps,
            bodies: scene.bodies,
            character: scene.character,
        })
    }

    /// The steps to run: `asked` (`--steps`), or the scene's, or those of the character's
    /// script, or 100.
    pub fn steps(&self, asked: Option<u64>, path: &Path) -> Result<u64> {
        // The script's total, added without overflow: past u64 it is past `MAX_STEPS` too.
        let script = match &self.character {
            Some(c) => match c
                .script
                .iter()
                .try_fold(0u64, |n, e| n.checked_add(e.steps))
            {
                Some(total) => Some(total),
                None => bail!(
                    "{}: character.script: its steps add up to more than the {MAX_STEPS} allowed",
                    path.display()
                ),
            },
            None => None,
        }
        .filter(|&n| n > 0);
        let steps = asked.or(self.steps).or(script).unwrap_or(100);
        if steps > MAX_STEPS {
            bail!(
                "{}: steps: {steps} is more than the {MAX_STEPS} allowed",
                path.display()
            );
        }
        Ok(steps)
    }

    /// The resolver for this map's cells, with the scene's bodies added, each with its
    /// constant move; an error naming the body when one cannot be (a bad radius, a
    /// position out of range, a circle starting in a wall, a move that is not finite).
    pub fn bodies(&self, path: &Path) -> Result<(Bodies, Vec<(BodyHandle, Vec2)>)> {
        let map = &self.map;
        // The resolver's default gap suits cells of side 1: scaled to this map's cells.
        let gap = tileslide::ResolveConfig::default().gap * map.cell_size().min_element();
        let mut bodies = Bodies::with_config(tileslide::ResolveConfig {
            gap,
            ..tileslide::ResolveConfig::default()
        })?;
        let skin = audit_skin(map);
        let mut crowd = Vec::with_capacity(self.bodies.len());
        for (i, b) in self.bodies.iter().enumerate() {
            let at = |field: &str| format!("{}: bodies[{i}].{field}", path.display());
            let shape = BodyShape::circle(b.r).with_context(|| at("r"))?;
            let handle = bodies
                .add(BodyDesc::new(Vec2::new(b.x, b.y), shape))
                .with_context(|| at("x/y"))?;
            // The resolver keeps bodies out of walls; one that starts in a wall has no
            // answer.
            let depth = penetration(map, &Circle::new(Vec2::new(b.x, b.y), b.r));
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
        Ok((bodies, crowd))
    }

    /// The scene's character, ready to run its script, if it has one.
    pub fn character(&self, path: &Path) -> Result<Option<CharacterRun>> {
        let Some(entry) = &self.character else {
            return Ok(None);
        };
        let at = |field: &str| format!("{}: character.{field}", path.display());
        let shape = match (entry.half_width, entry.half_height, entry.r) {
            (Some(w), Some(h), None) => CharacterShape::rect(Vec2::new(w, h))
                .with_context(|| at("half_width/half_height"))?,
            (None, None, Some(r)) => CharacterShape::circle(r).with_context(|| at("r"))?,
            _ => bail!(
                "{}: give either \"half_width\" and \"half_height\" (a box) or \"r\" (a circle)",
                at("shape")
            ),
        };
        let cell = self.map.cell_size().min_element();
        let config = ControllerConfig {
            skin: ControllerConfig::default().skin * cell,
            snap_distance: ControllerConfig::default().snap_distance * cell,
            step_height: entry.step_height.unwrap_or(0.0),
            ..ControllerConfig::default()
        };
        // Up is −y on maps whose row 0 is the top, +y on Replica Island's.
        let up = if self.format == MapFormat::ReplicaIsland {
            Vec2::Y
        } else {
            Vec2::NEG_Y
        };
        let character = Character::new(shape, Vec2::new(entry.x, entry.y), up, config)
            .with_context(|| at("x/y/step_height"))?;
        let gravity = entry.gravity.unwrap_or(0.02 * cell);
        if !gravity.is_finite() {
            bail!("{}: {gravity} is not a number", at("gravity"));
        }
        for (i, e) in entry.script.iter().enumerate() {
            if !(e.walk.is_finite() && e.jump.is_none_or(f32::is_finite)) {
                bail!(
                    "{}: walk and jump must be numbers",
                    at(&format!("script[{i}]"))
                );
            }
        }
        Ok(Some(CharacterRun {
            character,
            script: entry.script.clone(),
            gravity,
            rise: 0.0,
            step: 0,
        }))
    }
}

/// A character running its script, one step at a time.
pub struct CharacterRun {
    pub character: Character,
    script: Vec<ScriptEntry>,
    gravity: f32,
    /// Its speed along up, in map units per step: the game's rule, not the library's.
    rise: f32,
    /// Steps taken.
    step: u64,
}

impl CharacterRun {
    /// What the script asks at step `step` (from 0): the entry, and whether it is the
    /// entry's first step. After the script, it stands still (and falls).
    fn entry(&self, step: u64) -> Option<(ScriptEntry, bool)> {
        let mut start = 0;
        for e in &self.script {
            if step < start + e.steps {
                return Some((*e, step == start));
            }
            start += e.steps;
        }
        None
    }

    /// The move and the options of the next step.
    pub fn next_move(&mut self) -> (Vec2, MoveOptions) {
        let entry = self.entry(self.step);
        let walk = entry.map_or(0.0, |(e, _)| e.walk);
        match entry {
            Some((
                ScriptEntry {
                    jump: Some(jump), ..
                },
                true,
            )) => self.rise = jump,
            _ => self.rise -= self.gravity,
        }
        // Sideways is the map's x made square to up, as the character takes it.
        let up = self.character.up();
        let side = (Vec2::X - up * up.x).try_normalize().unwrap_or(up.perp());
        let displacement = side * walk + up * self.rise;
        let options = MoveOptions {
            drop_through: entry.is_some_and(|(e, _)| e.drop),
        };
        (displacement, options)
    }

    /// Takes the next step of the script, recording it into `trace` when given.
    pub fn step(&mut self, map: &TileMap, trace: Option<&mut MoveTrace>) -> Result<Contacts> {
        let (displacement, options) = self.next_move();
        let contacts = match trace {
            Some(trace) => self
                .character
                .move_by_traced(map, displacement, options, trace)?,
            None => self.character.move_by(map, displacement, options)?,
        };
        // Ground stops the fall, a ceiling the rise.
        if (contacts.ground.is_some() && self.rise < 0.0)
            || (contacts.ceiling.is_some() && self.rise > 0.0)
        {
            self.rise = 0.0;
        }
        self.step += 1;
        Ok(contacts)
    }
}

fn load_map(scene_path: &Path, scene: &SceneFile) -> Result<(TileMap, MapFormat)> {
    let cell = scene.cell.unwrap_or(1.0);
    if scene.map.is_none()
        && (scene.tileset.is_some() || scene.layer.is_some() || scene.level.is_some())
    {
        bail!(
            "{}: \"tileset\", \"layer\" and \"level\" go with a \"map\" file",
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
                level: scene.level.clone(),
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

/// How far a circle may overlap a wall or another circle before the audit counts it.
pub fn audit_skin(map: &TileMap) -> f32 {
    1e-4 * map.cell_size().min_element()
}

/// How deep `c` is in a wall: how much closer its centre is than its radius to a solid
/// (not one-way) segment it is in front of, or its radius when its centre is in solid; 0
/// when it is clear.
pub fn penetration(map: &TileMap, c: &Circle) -> f32 {
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
