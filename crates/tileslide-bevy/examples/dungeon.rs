//! Digging a dungeon with the mouse: imps wander the open cells along paths that change as
//! the rock is dug out and built back.
//!
//! ```sh
//! cargo run -p tileslide-bevy --features examples --example dungeon
//! ```
//!
//! The left mouse button digs the rock under the cursor, the right one builds it back
//! (not on an imp); F1 shows or hides the debug lines (active segments, bodies, paths), F2
//! shows every kind (hidden seams too). The dungeon is a bevy_ecs_tilemap layer, drawn by
//! bevy_ecs_tilemap: digging and building retexture its tiles (floor and rock), and the
//! layer's `TilemapCollision` keeps the collision map in step, edited in place, so bodies
//! and paths follow the map's change journal.

// Bevy systems take what they use as parameters, queries as tuples: that is how Bevy code
// reads.
#![allow(clippy::too_many_arguments, clippy::type_complexity)]

mod support;

use bevy::asset::RenderAssetUsages;
use bevy::prelude::*;
use bevy::render::render_resource::{Extent3d, TextureDimension, TextureFormat};
use bevy::window::PrimaryWindow;
use bevy_ecs_tilemap::prelude::*;
use tileslide::io::ldtk::Collision;
use tileslide::{Cell, TileMap};
use tileslide_bevy::{
    Body, CollisionMap, Interpolated, MapUnits, NavAgent, NavGoal, NavStatus, StepCount,
    TilemapCollision, TileslidePlugin,
};

const WIDTH: u32 = 44;
const HEIGHT: u32 = 26;
const IMPS: usize = 14;
const RADIUS: f32 = 0.3;
const SPEED: f32 = 3.5;
/// The tiles' size in the texture, in pixels; the layer is scaled to one world unit a tile.
const TILE_PX: u32 = 16;
/// The layer's textures: floor (no collision) and rock (solid, as every other texture).
const FLOOR: u32 = 0;
const ROCK: u32 = 1;

fn main() -> AppExit {
    let plugin = TileslidePlugin::default();
    let mut app = support::app("tileslide: digging a dungeon", plugin);
    app.add_plugins(TilemapPlugin)
        .insert_resource(support::TilesDrawnElsewhere)
        .insert_resource(Dig {
            dug: 0,
            random: 0x2545_f491_4f6c_dd1d,
            script: 0,
        })
        .add_systems(Startup, (setup, spawn_rock))
        .add_systems(Update, (dig_and_build, wander, hud));
    app.run()
}

/// Whether the cell at (`col`, `row`), y down, starts open: a hall in the middle and a
/// treasure room, walled in, to its right.
fn starts_open(col: u32, row: u32) -> bool {
    let hall = (8..16).contains(&col) && (9..16).contains(&row);
    let treasure = (32..38).contains(&col) && (4..9).contains(&row);
    hall || treasure
}

/// The dungeon's layer.
#[derive(Component)]
struct Rock;

/// The rock as a bevy_ecs_tilemap layer of floor and rock tiles, one world unit a tile, its
/// top-left corner at the world's origin (where the plugin puts the map's).
fn spawn_rock(mut commands: Commands, mut images: ResMut<Assets<Image>>) {
    let size = TilemapSize {
        x: WIDTH,
        y: HEIGHT,
    };
    let layer = commands.spawn_empty().id();
    let mut storage = TileStorage::empty(size);
    for row in 0..HEIGHT {
        for col in 0..WIDTH {
            // The layer counts rows up from the bottom.
            let position = TilePos {
                x: col,
                y: HEIGHT - 1 - row,
            };
            let texture = if starts_open(col, row) { FLOOR } else { ROCK };
            let tile = commands
                .spawn(TileBundle {
                    position,
                    tilemap_id: TilemapId(layer),
                    texture_index: TileTextureIndex(texture),
                    ..default()
                })
                .id();
            storage.set(&position, tile);
        }
    }
    let px = TILE_PX as f32;
    commands.entity(layer).insert((
        TilemapBundle {
            grid_size: TilemapGridSize { x: px, y: px },
            map_type: TilemapType::Square,
            size,
            storage,
            texture: TilemapTexture::Single(images.add(tile_texture())),
            tile_size: TilemapTileSize { x: px, y: px },
            // Tile (0, 0), the bottom-left one, centred half a unit in from the corner.
            transform: Transform::from_xyz(0.5, 0.5 - HEIGHT as f32, -2.0)
                .with_scale(Vec3::splat(1.0 / px)),
            ..default()
        },
        TilemapCollision::default().with_texture(FLOOR, Collision::Empty),
        Rock,
    ));
}

/// The two tiles side by side: a dark floor with a faint grid, and rock lit from the top
/// left.
fn tile_texture() -> Image {
    let (w, h) = (2 * TILE_PX, TILE_PX);
    let mut pixels = Vec::with_capacity((w * h * 4) as usize);
    for y in 0..h {
        for x in 0..w {
            let (tile, tx) = (x / TILE_PX, x % TILE_PX);
            let edge = |v: u32| v == 0 || v == TILE_PX - 1;
            let rgb: [u8; 3] = if tile == 0 {
                if edge(tx) || edge(y) {
                    [30, 28, 34]
                } else {
                    [22, 21, 26]
                }
            } else if tx == 0 || y == 0 {
                [112, 124, 148]
            } else if tx == TILE_PX - 1 || y == TILE_PX - 1 {
                [50, 56, 70]
            } else if (tx * 7 + y * 13) % 11 == 0 {
                [88, 98, 118]
            } else {
                [76, 86, 106]
            };
            pixels.extend_from_slice(&[rgb[0], rgb[1], rgb[2], 255]);
        }
    }
    Image::new(
        Extent3d {
            width: w,
            height: h,
            depth_or_array_layers: 1,
        },
        TextureDimension::D2,
        pixels,
        TextureFormat::Rgba8UnormSrgb,
        RenderAssetUsages::default(),
    )
}

/// How much has been dug, the imps' random numbers, and the script's last cell.
#[derive(Resource)]
struct Dig {
    dug: u32,
    random: u64,
    script: u32,
}

impl Dig {
    /// A number below `n` (xorshift: the same imps wander the same way every run).
    fn below(&mut self, n: usize) -> usize {
        self.random ^= self.random << 13;
        self.random ^= self.random >> 7;
        self.random ^= self.random << 17;
        (self.random % n.max(1) as u64) as usize
    }
}

#[derive(Component)]
struct Imp;

fn setup(
    mut commands: Commands,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<ColorMaterial>>,
) {
    let centre = Vec2::new(WIDTH as f32 * 0.5, -(HEIGHT as f32) * 0.5);
    commands.spawn(support::camera(
        centre,
        WIDTH as f32 + 2.0,
        HEIGHT as f32 + 2.0,
    ));
    commands.spawn(support::hud(""));
    let mesh = meshes.add(Circle::new(RADIUS));
    let material = materials.add(Color::srgb(0.6, 0.9, 0.4));
    for k in 0..IMPS {
        let (col, row) = (9 + (k % 6) as u32, 10 + (k / 6) as u32);
        commands.spawn((
            Imp,
            Body::circle(RADIUS),
            NavAgent::new(RADIUS, SPEED),
            Interpolated,
            Transform::from_xyz(col as f32 + 0.5, -(row as f32 + 0.5), 1.0),
            Mesh2d(mesh.clone()),
            MeshMaterial2d(material.clone()),
        ));
    }
}

/// The left button digs the cell under the cursor, the right one builds it (not where an imp
/// stands, and not the map's border). Taking a screenshot, a script digs a corridor from
/// the hall to the treasure room and a side room.
fn dig_and_build(
    buttons: Res<ButtonInput<MouseButton>>,
    window: Single<&Window, With<PrimaryWindow>>,
    camera: Single<(&Camera, &GlobalTransform)>,
    scripted: Option<Res<support::Screenshotting>>,
    steps: Res<StepCount>,
    units: Res<MapUnits>,
    map: Option<Res<CollisionMap>>,
    rock: Single<&TileStorage, With<Rock>>,
    mut textures: Query<&mut TileTextureIndex>,
    mut dig: ResMut<Dig>,
    imps: Query<&Transform, With<Imp>>,
) {
    let Some(tiles) = map.as_ref().and_then(|m| m.map()) else {
        return;
    };
    let cells: Vec<Cell> = if scripted.is_some() {
        // A cell every fourth step (however many steps a frame ran): east along row 12,
        // then north along column 30, then east into the treasure room.
        let now = u32::try_from(steps.0 / 4).unwrap_or(u32::MAX).min(22);
        let from = std::mem::replace(&mut dig.script, now);
        (from..now)
            .map(|k| match k {
                0..15 => Cell::new(16 + k, 12),
                15..20 => Cell::new(30, 12 - (k - 14)),
                _ => Cell::new(31 + (k - 20), 7),
            })
            .collect()
    } else {
        let Some(at) = support::cursor_world(&window, &camera) else {
            return;
        };
        tiles.cell_at(units.to_map(at)).into_iter().collect()
    };
    let digging = scripted.is_some() || buttons.pressed(MouseButton::Left);
    if cells.is_empty() || !digging && !buttons.pressed(MouseButton::Right) {
        return;
    }
    for cell in cells {
        let border =
            cell.col == 0 || cell.row == 0 || cell.col + 1 >= WIDTH || cell.row + 1 >= HEIGHT;
        let position = TilePos {
            x: cell.col,
            y: HEIGHT - 1 - cell.row,
        };
        let Some(mut texture) = rock
            .get(&position)
            .and_then(|tile| textures.get_mut(tile).ok())
        else {
            continue;
        };
        if border {
            continue;
        }
        // Only a tile that changes is written: the plugin edits the map for each one.
        if digging {
            if texture.0 == ROCK {
                texture.0 = FLOOR;
                dig.dug += 1;
            }
        } else if texture.0 == FLOOR {
            let rect = tiles.cell_rect(cell).expand(RADIUS);
            let occupied = imps
                .iter()
                .any(|t| rect.contains_point(units.to_map(t.translation.truncate())));
            if !occupied {
                texture.0 = ROCK;
                dig.dug = dig.dug.saturating_sub(1);
            }
        }
    }
}

/// An imp with nowhere to go (arrived, or its goal walled off) heads for a random open cell.
fn wander(
    map: Option<Res<CollisionMap>>,
    units: Res<MapUnits>,
    mut dig: ResMut<Dig>,
    mut imps: Query<&mut NavAgent, With<Imp>>,
) {
    let Some(tiles) = map.as_ref().and_then(|m| m.map()) else {
        return;
    };
    let mut open: Option<Vec<Cell>> = None;
    for mut imp in &mut imps {
        if imp.status() == NavStatus::Moving {
            continue;
        }
        let open = open.get_or_insert_with(|| open_cells(tiles));
        if open.is_empty() {
            return;
        }
        let cell = open[dig.below(open.len())];
        let goal = units.to_world(tiles.cell_corner(cell) + tiles.cell_size() * 0.5);
        imp.set_goal(Some(NavGoal::Path(goal)));
    }
}

fn open_cells(map: &TileMap) -> Vec<Cell> {
    (0..map.height())
        .flat_map(|row| (0..map.width()).map(move |col| Cell::new(col, row)))
        .filter(|&cell| map.tile(cell).is_none())
        .collect()
}

fn hud(
    dig: Res<Dig>,
    imps: Query<&NavAgent, With<Imp>>,
    mut text: Single<&mut Text, With<support::Hud>>,
) {
    let walking = imps
        .iter()
        .filter(|a| a.status() == NavStatus::Moving)
        .count();
    text.0 = format!(
        "{} cells dug  |  {walking} of {IMPS} imps walking  |  left button digs, right builds, F1/F2 debug lines",
        dig.dug
    );
}
