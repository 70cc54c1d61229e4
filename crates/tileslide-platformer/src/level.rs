//! A level: the tile map, which way is up, and where the player, the goal, the coins, the
//! enemies and the moving platform start.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use thiserror::Error;
use tileslide::io::{LoadError, ascii, read_limited, replica};
use tileslide::{Aabb, TileMap, Vec2};

use crate::replica_objects::{self, EnemyStart, IgnoredObjects};

/// The bundled level's text (`examples/maps/platformer.txt`).
pub const BUNDLED_LEVEL: &str = include_str!("../../../examples/maps/platformer.txt");

/// Why a level could not be made.
#[derive(Debug, Error)]
pub enum LevelError {
    /// The map itself did not load.
    #[error(transparent)]
    Load(#[from] LoadError),
    /// The level has no `P` (or a Replica Island level no player spawn).
    #[error("{0}: the level has no player start (`P`, or a Replica Island player spawn)")]
    NoStart(PathBuf),
    /// More than one `P` or `G`.
    #[error("{path}: line {line}: a second `{marker}` (a level has one)")]
    Duplicate {
        /// The level file.
        path: PathBuf,
        /// The line (1-based) of the second marker.
        line: usize,
        /// The marker.
        marker: char,
    },
    /// The `M` cells are not one horizontal run.
    #[error("{path}: line {line}: the moving platform's `M` cells must be one run on one row")]
    SplitPlatform {
        /// The level file.
        path: PathBuf,
        /// The line (1-based) of the stray `M`.
        line: usize,
    },
    /// The moving platform meets no solid ground to its right on its row.
    #[error("{0}: the moving platform has no solid ground to its right to travel to")]
    EndlessPlatform(PathBuf),
}

/// The characters an ASCII level uses on top of the ASCII map format: `P` start, `G` goal,
/// `o` coin, `E` enemy, `M` moving platform. Each stands for an empty cell.
pub const MARKERS: &str = "PGoEM";

/// What ends a run.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Goal {
    /// The level's goal: its `G` cell.
    #[default]
    Marked,
    /// The level has no goal (an ASCII level without `G`, every Replica Island level): the
    /// run ends when the player reaches its last three columns.
    RightEnd,
}

/// A moving platform's track: its top segment's left end at rest, its width, and how far
/// right it travels before it turns back.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlatformTrack {
    /// The top's left end at the start of the run.
    pub start: Vec2,
    /// The top's width.
    pub width: f32,
    /// How far right it goes before turning back.
    pub travel: f32,
}

/// A level to run: the map and what starts where. Lengths are in the map's units; `scale`
/// is one cell's width, so the game's speeds (in cells) fit any map.
#[derive(Clone, Debug)]
pub struct Level {
    /// The name shown in the summary (the file name).
    pub name: String,
    /// The collision world.
    pub map: TileMap,
    /// The unit up direction (−y for ASCII maps, +y for Replica Island levels).
    pub up: Vec2,
    /// One cell's width.
    pub scale: f32,
    /// The player's start: the bottom middle of its start cell (where its feet go).
    pub start: Vec2,
    /// The goal: reaching it ends the run.
    pub goal: Aabb,
    /// Whether `goal` is the level's own or its right end.
    pub goal_kind: Goal,
    /// Coin centres.
    pub coins: Vec<Vec2>,
    /// The enemies' starts.
    pub enemies: Vec<EnemyStart>,
    /// The moving platform, if any.
    pub platform: Option<PlatformTrack>,
    /// The objects of a Replica Island level the demo leaves out, by type number (empty
    /// for an ASCII level).
    pub ignored_objects: Vec<IgnoredObjects>,
}

impl Level {
    /// The bundled level (`examples/maps/platformer.txt`).
    pub fn bundled() -> Result<Self, LevelError> {
        Self::parse_ascii(BUNDLED_LEVEL, "platformer.txt")
    }

    /// Reads an ASCII level with the demo's markers (see the bundled level's header).
    pub fn load_ascii(path: impl AsRef<Path>) -> Result<Self, LevelError> {
        let path = path.as_ref();
        let text = read_limited(path)
            .and_then(|b| String::from_utf8(b).map_err(std::io::Error::other))
            .map_err(|e| unreadable(path, e))?;
        Self::parse_ascii(&text, path)
    }

    /// Parses an ASCII level with the demo's markers: `P` start, `G` goal, `o` coin, `E`
    /// enemy, `M` moving platform; everything else is the ASCII map format.
    pub fn parse_ascii(text: &str, path: impl AsRef<Path>) -> Result<Self, LevelError> {
        let path = path.as_ref();
        let mut start = None;
        let mut goal = None;
        let mut coins = Vec::new();
        let mut enemies = Vec::new();
        let mut platform: Option<(usize, usize, usize)> = None; // row, first col, end col
        let mut clean = String::with_capacity(text.len());
        let mut row = 0usize;
        for (index, line) in text.lines().enumerate() {
            let number = index + 1;
            if line.starts_with(';') {
                clean.push_str(line);
                clean.push('\n');
                continue;
            }
            for (col, c) in line.chars().enumerate() {
                let corner = Vec2::new(col as f32, row as f32);
                match c {
                    'P' => set_once(&mut start, corner, path, number, c)?,
                    'G' => set_once(&mut goal, corner, path, number, c)?,
                    'o' => coins.push(corner + Vec2::splat(0.5)),
                    'E' => enemies.push(EnemyStart {
                        feet: corner + Vec2::new(0.5, 1.0),
                        flies: false,
                    }),
                    'M' => match &mut platform {
                        None => platform = Some((row, col, col + 1)),
                        Some((r, _, end)) if *r == row && *end == col => *end += 1,
                        Some(_) => {
                            return Err(LevelError::SplitPlatform {
                                path: path.to_owned(),
                                line: number,
                            });
                        }
                    },
                    _ => {}
                }
                clean.push(if MARKERS.contains(c) { '.' } else { c });
            }
            clean.push('\n');
            row += 1;
        }
        let map = ascii::parse(&clean, path, 1.0)?;
        let start = start.ok_or_else(|| LevelError::NoStart(path.to_owned()))?;
        let platform = match platform {
            None => None,
            Some((row, first, end)) => Some(track(&map, row, first, end, path)?),
        };
        // Without a `G`, the goal is the last three columns (reach the right end).
        let goal_kind = if goal.is_some() {
            Goal::Marked
        } else {
            Goal::RightEnd
        };
        let goal = goal.map_or_else(
            || right_end(&map),
            |corner| Aabb::from_corners(corner, corner + Vec2::ONE),
        );
        Ok(Self {
            name: file_name(path),
            map,
            up: Vec2::NEG_Y,
            scale: 1.0,
            start: start + Vec2::new(0.5, 1.0),
            goal,
            goal_kind,
            coins,
            enemies,
            platform,
            ignored_objects: Vec::new(),
        })
    }

    /// A Replica Island level (`level_*.bin`) with its tile set (`collision.bin`): y up,
    /// 32-pixel cells, the goal the last three columns, and from the level's object layer
    /// the player's start, coins and enemies ([`ReplicaRole`] says which objects become
    /// what; the rest are listed in [`Level::ignored_objects`]); no moving platform.
    ///
    /// [`ReplicaRole`]: crate::ReplicaRole
    pub fn load_replica(
        level: impl AsRef<Path>,
        tile_set: impl AsRef<Path>,
    ) -> Result<Self, LevelError> {
        let (level, tile_set) = (level.as_ref(), tile_set.as_ref());
        let set_bytes = read_limited(tile_set).map_err(|e| unreadable(tile_set, e))?;
        let bytes = read_limited(level).map_err(|e| unreadable(level, e))?;
        Self::parse_replica(&bytes, level, &set_bytes, tile_set)
    }

    /// [`Level::load_replica`] from the files' bytes (a game with no disk): `level` and
    /// `tile_set` are the bytes of `level_*.bin` and `collision.bin`, named in errors by
    /// `level_path` and `tile_set_path`.
    pub fn parse_replica(
        level: &[u8],
        level_path: impl AsRef<Path>,
        tile_set: &[u8],
        tile_set_path: impl AsRef<Path>,
    ) -> Result<Self, LevelError> {
        let path = level_path.as_ref();
        let set = replica::parse_tile_set(tile_set, tile_set_path)?;
        let map = replica::parse_level(level, path, Arc::new(set))?;
        let scale = map.cell_size().x;
        let placed = replica_objects::place(&replica::parse_objects(level, path)?, scale)
            .ok_or_else(|| LevelError::NoStart(path.to_owned()))?;
        let goal = right_end(&map);
        Ok(Self {
            name: file_name(path),
            up: Vec2::Y,
            scale,
            start: placed.start,
            goal,
            goal_kind: Goal::RightEnd,
            coins: placed.coins,
            enemies: placed.enemies,
            platform: None,
            ignored_objects: placed.ignored,
            map,
        })
    }
}

fn unreadable(path: &Path, e: std::io::Error) -> LevelError {
    LevelError::Load(LoadError::unreadable(path, e))
}

fn file_name(path: &Path) -> String {
    path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into(),
    )
}

fn set_once(
    slot: &mut Option<Vec2>,
    corner: Vec2,
    path: &Path,
    line: usize,
    marker: char,
) -> Result<(), LevelError> {
    if slot.replace(corner).is_some() {
        return Err(LevelError::Duplicate {
            path: path.to_owned(),
            line,
            marker,
        });
    }
    Ok(())
}

/// The last three columns of the map, top to bottom.
fn right_end(map: &TileMap) -> Aabb {
    let b = map.bounds();
    let width = (3.0 * map.cell_size().x).min(b.max.x - b.min.x);
    Aabb::from_corners(Vec2::new(b.max.x - width, b.min.y), b.max)
}

/// The platform of cells `first..end` on `row` travels right until the cell after its end
/// is solid.
fn track(
    map: &TileMap,
    row: usize,
    first: usize,
    end: usize,
    path: &Path,
) -> Result<PlatformTrack, LevelError> {
    let y = row as f32;
    let wall = (end..map.width() as usize)
        .find(|&col| map.is_point_solid(Vec2::new(col as f32 + 0.5, y + 0.5)))
        .ok_or_else(|| LevelError::EndlessPlatform(path.to_owned()))?;
    Ok(PlatformTrack {
        start: Vec2::new(first as f32, y),
        width: (end - first) as f32,
        travel: (wall - end) as f32,
    })
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    #[test]
    fn bundled_level_has_its_markers() {
        let level = Level::bundled().unwrap();
        assert_eq!((level.map.width(), level.map.height()), (64, 16));
        assert_eq!(level.coins.len(), 10);
        assert_eq!(level.enemies.len(), 2);
        assert_eq!(level.start, Vec2::new(2.5, 10.0));
        let track = level.platform.unwrap();
        assert_eq!(
            (track.start, track.width, track.travel),
            (Vec2::new(44.0, 10.0), 3.0, 5.0)
        );
        // Markers are empty cells in the map.
        assert!(!level.map.is_point_solid(Vec2::new(44.5, 10.5)));
    }

    #[test]
    fn a_level_without_a_start_is_refused() {
        let err = Level::parse_ascii("#...\n####", "nostart.txt").unwrap_err();
        assert_eq!(
            err.to_string(),
            "nostart.txt: the level has no player start (`P`, or a Replica Island player spawn)"
        );
    }

    #[test]
    fn a_second_start_names_its_line() {
        let err = Level::parse_ascii("; c\n#P..\n#P..\n####", "two.txt").unwrap_err();
        assert_eq!(
            err.to_string(),
            "two.txt: line 3: a second `P` (a level has one)"
        );
    }

    #[test]
    fn a_split_platform_names_its_line() {
        let err = Level::parse_ascii("#PM.M#\n######", "split.txt").unwrap_err();
        assert!(
            matches!(err, LevelError::SplitPlatform { line: 1, .. }),
            "{err}"
        );
    }

    #[test]
    fn a_platform_with_nowhere_to_go_is_refused() {
        let err = Level::parse_ascii("#P....\n##MM..", "endless.txt").unwrap_err();
        assert!(matches!(err, LevelError::EndlessPlatform(_)), "{err}");
    }

    #[test]
    fn without_a_goal_the_goal_is_the_right_end() {
        let level = Level::parse_ascii("#P.....\n#######", "nogoal.txt").unwrap();
        assert_eq!(level.goal_kind, Goal::RightEnd);
        assert_eq!(Level::bundled().unwrap().goal_kind, Goal::Marked);
        assert_eq!(level.goal.min.x, 4.0);
        assert_eq!(level.goal.max.x, 7.0);
    }
}
