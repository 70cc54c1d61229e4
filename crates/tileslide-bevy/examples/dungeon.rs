//! Digging a dungeon with the mouse: imps wander the open cells along paths that change as
//! the rock is dug out and built back.
//!
//! ```sh
//! cargo run -p tileslide-bevy --features examples --example dungeon
//! ```
//!
//! The left mouse button digs the rock under the cursor, the right one builds it back
//! (not on an imp); F1 shows or hides the debug lines (active segments, bodies, paths), F2
//! shows every kind (hidden seams too). The map is edited in place (`CollisionMap::map_mut`): bodies and paths
//! follow its change journal.

// Bevy systems take what they use as parameters, queries as tuples: that is how Bevy code
// reads.
#![allow(clippy::too_many_arguments, clippy::type_complexity)]

mod support;

use bevy::prelude::*;
use bevy::window::PrimaryWindow;
use tileslide::io::ascii;
use tileslide::{Cell, TileMap};
use tileslide_bevy::{
    Body, CollisionMap, Interpolated, MapUnits, NavAgent, NavGoal, NavStatus, StepCount,
    TileslidePlugin,
};

const WIDTH: u32 = 44;
const HEIGHT: u32 = 26;
const IMPS: usize = 14;
const RADIUS: f32 = 0.3;
const SPEED: f32 = 3.5;

fn main() -> AppExit {
    let rock = match rock() {
        Ok(map) => map,
        Err(e) => {
            eprintln!("error: {e}");
            return AppExit::error();
        }
    };
    let plugin = TileslidePlugin::default();
    let mut app = support::app("tileslide: digging a dungeon", plugin);
    app.insert_resource(CollisionMap::new(rock))
        .insert_resource(Dig {
            dug: 0,
            random: 0x2545_f491_4f6c_dd1d,
            script: 0,
        })
        .add_systems(Startup, setup)
        .add_systems(Update, (dig_and_build, wander, hud));
    app.run()
}

/// Solid rock with a hall in the middle and a treasure room, walled in, to its right.
fn rock() -> Result<TileMap, tileslide::io::LoadError> {
    let mut text = String::new();
    for row in 0..HEIGHT {
        for col in 0..WIDTH {
            let hall = (8..16).contains(&col) && (9..16).contains(&row);
            let treasure = (32..38).contains(&col) && (4..9).contains(&row);
            text.push(if hall || treasure { '.' } else { '#' });
        }
        text.push('\n');
    }
    ascii::parse(&text, "dungeon.txt", 1.0)
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
    mut map: ResMut<CollisionMap>,
    mut dig: ResMut<Dig>,
    imps: Query<&Transform, With<Imp>>,
) {
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
        map.map()
            .and_then(|tiles| tiles.cell_at(units.to_map(at)))
            .into_iter()
            .collect()
    };
    let digging = scripted.is_some() || buttons.pressed(MouseButton::Left);
    if cells.is_empty() || !digging && !buttons.pressed(MouseButton::Right) {
        return;
    }
    // Taken mutably only to edit: the map's change journal tells bodies and paths.
    let Some(tiles) = map.map_mut() else {
        return;
    };
    for cell in cells {
        dig_or_build(tiles, cell, digging, &mut dig, &imps, &units);
    }
}

/// Digs out `cell` (`digging`) or builds it back, unless it is the map's border or an imp
/// stands there.
fn dig_or_build(
    tiles: &mut TileMap,
    cell: Cell,
    digging: bool,
    dig: &mut Dig,
    imps: &Query<&Transform, With<Imp>>,
    units: &MapUnits,
) {
    let border = cell.col == 0 || cell.row == 0 || cell.col + 1 >= WIDTH || cell.row + 1 >= HEIGHT;
    if border {
        return;
    }
    if digging {
        if tiles.tile(cell).is_some() && tiles.clear_tile(cell).is_ok() {
            dig.dug += 1;
        }
    } else if tiles.tile(cell).is_none() {
        let rect = tiles.cell_rect(cell).expand(RADIUS);
        let occupied = imps
            .iter()
            .any(|t| rect.contains_point(units.to_map(t.translation.truncate())));
        if !occupied && tiles.set_tile(cell, Some(ascii::SOLID)).is_ok() {
            dig.dug = dig.dug.saturating_sub(1);
        }
    }
}

/// An imp with nowhere to go (arrived, or its goal walled off) heads for a random open cell.
fn wander(
    map: Res<CollisionMap>,
    units: Res<MapUnits>,
    mut dig: ResMut<Dig>,
    mut imps: Query<&mut NavAgent, With<Imp>>,
) {
    let Some(tiles) = map.map() else {
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
