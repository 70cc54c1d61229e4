//! What the windowed examples share: the app with a window, the map drawn as meshes, a
//! text line, the camera, the debug lines' keys, and `SCREENSHOT=out.png` (save the window
//! once the plugin has run `SCREENSHOT_STEPS` fixed steps, default 180, then exit), with
//! which the examples play themselves (a scripted player, a fixed goal), so the picture
//! shows them at work and the same moment of the game whatever the frame rate.

#![allow(dead_code)]

use bevy::asset::RenderAssetUsages;
use bevy::camera::ScalingMode;
use bevy::mesh::{Indices, PrimitiveTopology};
use bevy::prelude::*;
use bevy::render::view::screenshot::{Screenshot, ScreenshotCaptured, save_to_disk};
use bevy::window::{PrimaryWindow, WindowResolution};
use tileslide::DebugKind;
use tileslide::debug::DebugKinds;
use tileslide::{MapRevision, SegmentFlags, TileMap};
use tileslide_bevy::{
    CollisionMap, DebugDraw, MapUnits, StepCount, TileslideDebugPlugin, TileslideError,
    TileslidePlugin,
};

/// The repository's bundled maps, the examples' asset folder.
pub const MAPS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/maps");

/// The window's size in pixels.
pub const WINDOW: (u32, u32) = (1280, 720);

/// A windowed app with the plugin at `scale` world units per map unit, the debug drawing,
/// the examples' asset folder, and the screenshot of `SCREENSHOT` if it is set.
pub fn app(title: &str, plugin: TileslidePlugin) -> App {
    let mut app = App::new();
    app.add_plugins(
        DefaultPlugins
            .set(WindowPlugin {
                primary_window: Some(Window {
                    title: title.into(),
                    resolution: WindowResolution::new(WINDOW.0, WINDOW.1),
                    ..default()
                }),
                ..default()
            })
            .set(AssetPlugin {
                file_path: MAPS.into(),
                ..default()
            }),
    )
    .add_plugins((plugin, TileslideDebugPlugin))
    .insert_resource(ClearColor(Color::srgb(0.07, 0.08, 0.11)))
    .init_resource::<MapMeshes>()
    .add_systems(Startup, quiet_debug_lines)
    .add_systems(Update, (draw_map, report_errors, toggle_debug));
    if let Some(shot) = Screenshotting::from_env() {
        app.insert_resource(shot)
            .add_systems(Update, screenshot_then_exit);
    }
    app
}

/// The debug lines the examples start with: all but the seams seam culling hides and the
/// broadphase's boxes (F2 shows those too).
const QUIET: DebugKinds = DebugKinds::ALL
    .without(DebugKind::HiddenSegment)
    .without(DebugKind::BroadphaseBox);

fn quiet_debug_lines(mut debug: ResMut<DebugDraw>) {
    debug.kinds = QUIET;
}

/// F1 shows or hides the debug lines; F2 shows every kind, or the quieter set.
fn toggle_debug(keys: Res<ButtonInput<KeyCode>>, mut debug: ResMut<DebugDraw>) {
    if keys.just_pressed(KeyCode::F1) {
        debug.enabled = !debug.enabled;
    }
    if keys.just_pressed(KeyCode::F2) {
        debug.kinds = if debug.kinds == QUIET {
            DebugKinds::ALL
        } else {
            QUIET
        };
    }
}

/// Logs what the plugin refused (each error once a frame at most, however many entities
/// it names).
fn report_errors(mut errors: MessageReader<TileslideError>) {
    let mut last = None;
    for error in errors.read() {
        if last != Some(&error.message) {
            warn!("{:?}: {}", error.entity, error.message);
            last = Some(&error.message);
        }
    }
}

/// Set when the example runs to take a screenshot (`SCREENSHOT=path`): the examples then
/// play themselves.
#[derive(Resource, Clone, Debug)]
pub struct Screenshotting {
    path: String,
    steps: u64,
    /// The frames since the screenshot was asked for (`None`: not yet asked).
    waiting: Option<u32>,
}

impl Screenshotting {
    fn from_env() -> Option<Self> {
        let path = std::env::var("SCREENSHOT").ok()?;
        let steps = std::env::var("SCREENSHOT_STEPS")
            .ok()
            .and_then(|f| f.parse().ok())
            .unwrap_or(180);
        Some(Self {
            path,
            steps,
            waiting: None,
        })
    }
}

fn screenshot_then_exit(
    mut commands: Commands,
    steps: Res<StepCount>,
    mut shot: ResMut<Screenshotting>,
    mut exit: MessageWriter<AppExit>,
) {
    match shot.waiting {
        None if steps.0 >= shot.steps => {
            info!("saving the window to {} after {} steps", shot.path, steps.0);
            shot.waiting = Some(0);
            commands
                .spawn(Screenshot::primary_window())
                .observe(save_to_disk(shot.path.clone()))
                .observe(
                    |_: On<ScreenshotCaptured>, mut exit: MessageWriter<AppExit>| {
                        exit.write(AppExit::Success);
                    },
                );
        }
        Some(frames) if frames > 600 => {
            error!("no screenshot 600 frames after asking for it");
            exit.write(AppExit::error());
        }
        Some(frames) => shot.waiting = Some(frames + 1),
        None => {}
    }
}

/// A 2D camera showing at least `width × height` world units around `center`.
pub fn camera(center: Vec2, width: f32, height: f32) -> impl Bundle {
    (
        Camera2d,
        Projection::Orthographic(OrthographicProjection {
            scaling_mode: ScalingMode::AutoMin {
                min_width: width,
                min_height: height,
            },
            ..OrthographicProjection::default_2d()
        }),
        Transform::from_translation(center.extend(0.0)),
    )
}

/// A line of text at the window's top left, updated through [`Hud`].
pub fn hud(text: &str) -> impl Bundle {
    (
        Hud,
        Text::new(text),
        TextFont::from_font_size(18.0),
        TextColor(Color::srgb(0.9, 0.92, 0.95)),
        Node {
            position_type: PositionType::Absolute,
            top: Val::Px(10.0),
            left: Val::Px(12.0),
            ..default()
        },
    )
}

/// The HUD's text.
#[derive(Component)]
pub struct Hud;

/// The world point under the cursor, if the cursor is over the window.
pub fn cursor_world(
    window: &Single<&Window, With<PrimaryWindow>>,
    camera: &Single<(&Camera, &GlobalTransform)>,
) -> Option<Vec2> {
    let (camera, transform) = **camera;
    let at = window.cursor_position()?;
    camera.viewport_to_world_2d(transform, at).ok()
}

/// Put in an app whose tiles are drawn by something else (a bevy_ecs_tilemap layer): the
/// map is then not drawn as meshes.
#[derive(Resource)]
pub struct TilesDrawnElsewhere;

/// The meshes drawing the map's tiles, and the map generation and revision they show.
#[derive(Resource, Default)]
struct MapMeshes {
    meshes: Vec<Handle<Mesh>>,
    shown: Option<(u64, MapRevision)>,
}

/// Draws the collision map's tiles as filled shapes (solid tiles) and bars (one-way
/// platforms), again each time the map is replaced or its tiles are edited (the meshes are
/// rewritten in place).
fn draw_map(
    mut commands: Commands,
    map: Option<Res<CollisionMap>>,
    units: Res<MapUnits>,
    mut shown: ResMut<MapMeshes>,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<ColorMaterial>>,
    elsewhere: Option<Res<TilesDrawnElsewhere>>,
) {
    let Some(map) = map.filter(|_| elsewhere.is_none()) else {
        return;
    };
    let Some(tiles) = map.map() else {
        return;
    };
    // Drawn again when the map is replaced or its tiles edited (not when only its
    // temporary segments, the platforms, move).
    let same = shown.shown.as_ref().is_some_and(|(generation, revision)| {
        *generation == map.generation()
            && tiles
                .changes_since(revision)
                .is_ok_and(|edits| edits.len() == 0)
    });
    if same {
        return;
    }
    shown.shown = Some((map.generation(), tiles.revision()));
    let (solid, one_way) = tile_meshes(tiles, &units);
    if shown.meshes.is_empty() {
        for (mesh, color, z) in [
            (solid, Color::srgb(0.30, 0.34, 0.42), -2.0),
            (one_way, Color::srgb(0.55, 0.45, 0.25), -1.9),
        ] {
            let handle = meshes.add(mesh);
            commands.spawn((
                Mesh2d(handle.clone()),
                MeshMaterial2d(materials.add(color)),
                Transform::from_xyz(0.0, 0.0, z),
            ));
            shown.meshes.push(handle);
        }
    } else {
        for (handle, mesh) in shown.meshes.iter().zip([solid, one_way]) {
            if let Some(mut slot) = meshes.get_mut(handle) {
                *slot = mesh;
            }
        }
    }
}

/// Triangle meshes (world units) of the map's solid tiles and of its one-way platforms.
fn tile_meshes(map: &TileMap, units: &MapUnits) -> (Mesh, Mesh) {
    let mut solid = Triangles::default();
    let mut one_way = Triangles::default();
    let bar = 0.12 * map.cell_size().y;
    for row in 0..map.height() {
        for col in 0..map.width() {
            let cell = tileslide::Cell::new(col, row);
            let Some(id) = map.tile(cell) else {
                continue;
            };
            let Some(shape) = map.tile_set().shape(id) else {
                continue;
            };
            let corner = map.cell_corner(cell);
            let segments = shape.segments();
            if shape.has_inside() {
                // A convex outline: a fan from its first corner.
                let points: Vec<Vec2> = segments
                    .iter()
                    .map(|s| units.to_world(corner + s.a))
                    .collect();
                solid.fan(&points);
            } else {
                for s in segments
                    .iter()
                    .filter(|s| s.flags.contains(SegmentFlags::ONE_WAY))
                {
                    let (a, b) = (corner + s.a, corner + s.b);
                    let below = tileslide::Vec2::new(0.0, bar);
                    let quad = [a, b, b + below, a + below].map(|p| units.to_world(p));
                    one_way.fan(&quad);
                }
            }
        }
    }
    (solid.mesh(), one_way.mesh())
}

/// Triangles being gathered into a mesh.
#[derive(Default)]
struct Triangles {
    positions: Vec<[f32; 3]>,
    indices: Vec<u32>,
}

impl Triangles {
    /// A convex polygon, as a fan.
    fn fan(&mut self, points: &[Vec2]) {
        let first = self.positions.len() as u32;
        self.positions
            .extend(points.iter().map(|p| [p.x, p.y, 0.0]));
        for k in 1..points.len().saturating_sub(1) as u32 {
            self.indices.extend([first, first + k, first + k + 1]);
        }
    }

    fn mesh(mut self) -> Mesh {
        // Bevy's mesh allocator refuses a mesh without vertices: nothing to draw is one
        // triangle of no area.
        if self.positions.is_empty() {
            self.fan(&[Vec2::ZERO; 3]);
        }
        Mesh::new(
            PrimitiveTopology::TriangleList,
            RenderAssetUsages::default(),
        )
        .with_inserted_attribute(Mesh::ATTRIBUTE_POSITION, self.positions)
        .with_inserted_indices(Indices::U32(self.indices))
    }
}
