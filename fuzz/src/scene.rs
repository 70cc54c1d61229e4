//! The `scene` target: the CLI's scene files (`crates/tileslide-cli/src/scene.rs`, included
//! as it is, beside a `map_file` that reads no files), read and run as `tileslide simulate`
//! runs them, for at most [`MAX_STEPS`] steps.
//!
//! Checks: reading returns `Ok` or `Err` and never panics; a scene read runs with every
//! body's position finite and no body deeper in a wall than the audit's skin or than it
//! started; a circle character that started clear stays out of every wall by the skin; a
//! refused move ends the run as it ends `simulate`'s; and a second run of the same scene
//! ends bit for bit where the first did.

use std::path::Path;

use tileslide::{Bodies, BodyHandle, CharacterShape, Circle, Vec2};

/// The CLI's map files, for the scene files: the target reads none.
mod map_file {
    use std::path::PathBuf;

    use tileslide::TileMap;

    /// The fields of the CLI's map arguments that a scene file sets.
    #[allow(dead_code)]
    pub struct MapArgs {
        pub map: PathBuf,
        pub tileset: Option<PathBuf>,
        pub cell: Option<f32>,
        pub layer: Option<String>,
        pub level: Option<String>,
        pub limits: TiledLimits,
    }

    /// The CLI's bounds on loading a Tiled map: the defaults.
    #[derive(Default)]
    #[allow(dead_code)]
    pub struct TiledLimits {
        /// As the CLI's.
        pub max_cells: Option<u64>,
    }

    /// The CLI's map formats that the scene code names.
    #[derive(Clone, Copy, Debug, PartialEq, Eq)]
    pub enum MapFormat {
        Ascii,
        ReplicaIsland,
    }

    /// A scene naming a map file: refused, so the target reads nothing from disk.
    pub fn load(args: &MapArgs) -> anyhow::Result<(TileMap, MapFormat)> {
        anyhow::bail!("{}: the fuzz target reads no map files", args.map.display())
    }
}

#[path = "../../crates/tileslide-cli/src/scene.rs"]
#[allow(dead_code)]
mod scene;

/// Most steps a scene runs here.
pub const MAX_STEPS: u64 = 48;

/// The `scene` target.
pub fn check(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let first = run_bits(text);
    assert!(first == run_bits(text), "two runs of the same scene differ");
}

/// Reads and runs `text` with the checks; the bits of every position at the end (none for a
/// scene refused).
pub fn run_bits(text: &str) -> Vec<u32> {
    let path = Path::new("fuzz.json");
    let Ok(scene) = scene::Scene::parse(text, path) else {
        return Vec::new();
    };
    let Ok(steps) = scene.steps(None, path) else {
        return Vec::new();
    };
    let map = &scene.map;
    let skin = scene::audit_skin(map);
    let Ok((mut bodies, crowd)) = scene.bodies(path) else {
        return Vec::new();
    };
    let depth = |bodies: &Bodies, h| {
        let body = bodies.get(h).expect("a live body");
        let circle = Circle::new(body.position(), body.shape().bounding_radius());
        scene::penetration(map, &circle)
    };
    let allowed: Vec<f32> = crowd
        .iter()
        .map(|&(h, _)| depth(&bodies, h).max(skin))
        .collect();
    let mut character = scene.character(path).ok().flatten();
    // A circle character is checked when it starts clear of every wall.
    let circle = character
        .as_ref()
        .and_then(|run| match run.character.shape() {
            CharacterShape::Circle { radius } => {
                let c = Circle::new(run.character.position, radius);
                (scene::penetration(map, &c) == 0.0).then_some(radius)
            }
            _ => None,
        });
    'steps: for step in 1..=steps.min(MAX_STEPS) {
        for &(h, v) in &crowd {
            if bodies.propose(h, v).is_err() {
                break 'steps;
            }
        }
        bodies.step(map);
        for (i, &(h, _)) in crowd.iter().enumerate() {
            let p = bodies_position(&bodies, h);
            assert!(p.is_finite(), "step {step}: body {i} at {p}");
            let d = depth(&bodies, h);
            assert!(
                d <= allowed[i] * 1.01,
                "step {step}: body {i} at {p} is {d} into a wall (allowed {})",
                allowed[i]
            );
        }
        if let Some(run) = &mut character {
            if run.step(map, None).is_err() {
                break;
            }
            let p = run.character.position;
            assert!(p.is_finite(), "step {step}: the character at {p}");
            if let Some(radius) = circle {
                let d = scene::penetration(map, &Circle::new(p, radius));
                assert!(
                    d <= skin,
                    "step {step}: the character at {p} is {d} into a wall"
                );
            }
        }
    }
    let mut bits: Vec<u32> = crowd
        .iter()
        .flat_map(|&(h, _)| {
            let p = bodies_position(&bodies, h);
            [p.x.to_bits(), p.y.to_bits()]
        })
        .collect();
    if let Some(run) = &character {
        let p: Vec2 = run.character.position;
        bits.extend([p.x.to_bits(), p.y.to_bits()]);
    }
    bits
}

fn bodies_position(bodies: &Bodies, h: BodyHandle) -> Vec2 {
    bodies.get(h).expect("a live body").position()
}
