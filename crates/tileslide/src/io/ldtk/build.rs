//! From the project's JSON to levels placed in the world, and from a chosen level to an
//! [`LdtkMap`]: reading its level file, choosing its layer, gathering its entities.

use std::borrow::Cow;
use std::path::{Path, PathBuf};

use glam::Vec2;

use super::entities::{self, EntityLayer, Fault, PointGrid};
use super::schema::{LayerInstanceJson, LevelJson, ProjectJson};
use super::{
    LINEAR_LEVEL_SPACING, LdtkLevel, LdtkMap, LdtkOptions, LdtkProject, WorldLayout, disk_error,
    files, from_json, layers, ldtk_error,
};
use crate::io::error::as_text;
use crate::io::{LdtkFault, LoadError, LoadErrorKind, Location};

/// Most levels a project may hold whose positions the linear layouts add up (and most
/// pixels a level may span), so that sums stay exact in `i64` and in `f32` world space.
const MAX_LEVEL_PIXELS: i64 = 1 << 24;

/// Where a level is in the project's JSON.
#[derive(Clone, Debug)]
pub(super) struct LevelSource {
    /// Its JSON path (`levels[2]`, `worlds[0].levels[1]`).
    pub at: String,
    /// Its world's index, in a multi-world project.
    pub world: Option<usize>,
    /// Its index in its `levels` array.
    pub index: usize,
}

/// The project's levels with their world positions, and where each one is.
pub(super) fn levels(json: &ProjectJson) -> Result<(Vec<LdtkLevel>, Vec<LevelSource>), Fault> {
    let default_grid = json
        .default_grid_size
        .unwrap_or(16)
        .clamp(1, super::MAX_GRID_SIZE);
    let mut out = Vec::new();
    let mut paths = Vec::new();
    // A multi-world project keeps its levels in its worlds, each with its own layout; any
    // other keeps them at the root (as LDtk reads them: by the `MultiWorlds` flag).
    let multi = json.flags.iter().any(|f| f == "MultiWorlds")
        || (json.levels.is_empty() && !json.worlds.is_empty());
    type World<'a> = (
        Option<usize>,
        String,
        Option<&'a str>,
        &'a [LevelJson],
        String,
    );
    let worlds: Vec<World<'_>> = if multi {
        json.worlds
            .iter()
            .enumerate()
            .map(|(w, world)| {
                (
                    Some(w),
                    world.identifier.clone(),
                    world.world_layout.as_deref(),
                    world.levels.as_slice(),
                    format!("worlds[{w}]."),
                )
            })
            .collect()
    } else {
        vec![(
            None,
            String::new(),
            json.world_layout.as_deref(),
            json.levels.as_slice(),
            String::new(),
        )]
    };
    for (world_index, world, layout, levels, prefix) in worlds {
        let layout_path = if prefix.is_empty() {
            "worldLayout".to_owned()
        } else {
            format!("{prefix}worldLayout")
        };
        let layout = match layout {
            None | Some("Free") => WorldLayout::Free,
            Some("GridVania") => WorldLayout::GridVania,
            Some("LinearHorizontal") => WorldLayout::LinearHorizontal,
            Some("LinearVertical") => WorldLayout::LinearVertical,
            Some(other) => {
                return Err((
                    layout_path,
                    LdtkFault::Schema(format!(
                        "unknown world layout {other:?} (expected Free, GridVania, LinearHorizontal or LinearVertical)"
                    )),
                ));
            }
        };
        // LDtk places the levels of a linear layout itself, whatever the file says (it
        // writes -1): one after the other from 0, 48 pixels apart.
        let mut along = 0i64;
        for (i, level) in levels.iter().enumerate() {
            let at = format!("{prefix}levels[{i}]");
            for (field, value) in [("pxWid", level.px_wid), ("pxHei", level.px_hei)] {
                if !(1..=MAX_LEVEL_PIXELS).contains(&value) {
                    return Err((
                        format!("{at}.{field}"),
                        size_fault(
                            field,
                            value,
                            format!("a level is 1 to {MAX_LEVEL_PIXELS} pixels"),
                        ),
                    ));
                }
            }
            let (x, y) = match layout {
                WorldLayout::Free | WorldLayout::GridVania => {
                    for (field, value) in [("worldX", level.world_x), ("worldY", level.world_y)] {
                        if value.abs() > MAX_LEVEL_PIXELS {
                            return Err((
                                format!("{at}.{field}"),
                                size_fault(
                                    field,
                                    value,
                                    format!("levels lie within ±{MAX_LEVEL_PIXELS} pixels"),
                                ),
                            ));
                        }
                    }
                    (level.world_x, level.world_y)
                }
                WorldLayout::LinearHorizontal => {
                    let x = along;
                    along += level.px_wid + LINEAR_LEVEL_SPACING;
                    (x, 0)
                }
                WorldLayout::LinearVertical => {
                    let y = along;
                    along += level.px_hei + LINEAR_LEVEL_SPACING;
                    (0, y)
                }
            };
            if along > MAX_LEVEL_PIXELS {
                return Err((
                    format!("{at}.pxWid"),
                    size_fault(
                        "pxWid",
                        along,
                        format!(
                            "the levels of a linear layout span at most {MAX_LEVEL_PIXELS} pixels"
                        ),
                    ),
                ));
            }
            let origin = Vec2::new(x as f32, y as f32);
            let grid = PointGrid {
                size: default_grid as f64,
                origin,
            };
            out.push(LdtkLevel {
                identifier: level.identifier.clone(),
                iid: level.iid.clone(),
                world: world.clone(),
                layout,
                world_position: origin,
                size: Vec2::new(level.px_wid as f32, level.px_hei as f32),
                world_depth: level.world_depth,
                external_file: level.external_rel_path.clone().filter(|p| !p.is_empty()),
                fields: entities::fields(
                    &level.field_instances,
                    grid,
                    &format!("{at}.fieldInstances"),
                )?,
            });
            paths.push(LevelSource {
                at,
                world: world_index,
                index: i,
            });
        }
    }
    Ok((out, paths))
}

/// A [`LdtkFault::Size`].
pub(super) fn size_fault(field: &'static str, value: i64, reason: String) -> LdtkFault {
    LdtkFault::Size {
        field,
        value,
        reason,
    }
}

/// The level, read from its file if it has one: the file's path (for errors), the JSON
/// path of its layers there, and its layers.
struct LevelLayers<'a> {
    file: PathBuf,
    at: String,
    /// Borrowed from the project, or owned when read from the level's file.
    layers: Cow<'a, [LayerInstanceJson]>,
}

/// Builds the level and layer `options` choose.
pub(super) fn build(project: &LdtkProject, options: &LdtkOptions) -> Result<LdtkMap, LoadError> {
    let path = project.path.as_path();
    if project.levels.is_empty() {
        return Err(ldtk_error(path, "levels".into(), LdtkFault::NoLevels));
    }
    let index = match &options.level {
        None => 0,
        Some(name) => project
            .levels
            .iter()
            .position(|l| &l.identifier == name)
            .ok_or_else(|| {
                ldtk_error(
                    path,
                    "levels".into(),
                    LdtkFault::UnknownLevel {
                        requested: name.clone(),
                        levels: project
                            .levels
                            .iter()
                            .map(|l| l.identifier.clone())
                            .collect(),
                    },
                )
            })?,
    };
    let info = &project.levels[index];
    let source = &project.level_paths[index];
    let json = match source.world {
        None => project.json.levels.get(source.index),
        Some(w) => project
            .json
            .worlds
            .get(w)
            .and_then(|w| w.levels.get(source.index)),
    };
    let Some(json) = json else {
        return Err(ldtk_error(path, source.at.clone(), LdtkFault::NoLevels));
    };
    let level = level_layers(project, json, &source.at, options)?;
    let fail = |at: String, fault| ldtk_error(&level.file, at, fault);
    let collision_index =
        layers::choose(&level.layers, &project.json.defs, options, &info.identifier).map_err(
            |(i, fault)| {
                fail(
                    i.map_or_else(|| level.at.clone(), |i| format!("{}[{i}]", level.at)),
                    fault,
                )
            },
        )?;
    let layer = &level.layers[collision_index];
    let layer_at = format!("{}[{collision_index}]", level.at);
    let built = layers::build(
        layer,
        &project.json.defs,
        options,
        info.world_position,
        &layer_at,
    )
    .map_err(|e| match e {
        layers::BuildError::Fault(at, fault) => fail(at, fault),
        layers::BuildError::ProjectFault(at, fault) => ldtk_error(path, at, fault),
        layers::BuildError::Kind(kind) => LoadError::new(&level.file, Location::File, kind),
    })?;
    let mut entity_layers = Vec::new();
    for (i, layer) in level.layers.iter().enumerate() {
        if layer.kind != "Entities" {
            continue;
        }
        let at = format!("{}[{i}]", level.at);
        entity_layers.push(
            entity_layer(layer, info.world_position, &at).map_err(|(at, fault)| fail(at, fault))?,
        );
    }
    Ok(LdtkMap {
        map: built.map,
        level: info.identifier.clone(),
        level_index: index,
        collision_layer: layer.identifier.clone(),
        layers: level.layers.iter().map(|l| l.identifier.clone()).collect(),
        entity_layers,
        levels: project.levels.clone(),
        int_grid: built.int_grid,
    })
}

/// The layers of `level`: in the project, or read from its level file.
fn level_layers<'a>(
    project: &LdtkProject,
    level: &'a LevelJson,
    level_at: &str,
    options: &LdtkOptions,
) -> Result<LevelLayers<'a>, LoadError> {
    let path = project.path.as_path();
    if let Some(layers) = &level.layer_instances {
        return Ok(LevelLayers {
            file: path.to_path_buf(),
            at: format!("{level_at}.layerInstances"),
            layers: Cow::Borrowed(layers),
        });
    }
    let rel_at = format!("{level_at}.externalRelPath");
    let Some(rel) = level.external_rel_path.as_deref().filter(|p| !p.is_empty()) else {
        return Err(ldtk_error(
            path,
            format!("{level_at}.layerInstances"),
            LdtkFault::NoLayerInstances,
        ));
    };
    let inside = files::inside(rel).map_err(|fault| ldtk_error(path, rel_at.clone(), fault))?;
    // The level file's error is the project's: it is the project that names the file.
    let unreadable = |file: &Path, source| {
        let referenced = Some(file.to_path_buf());
        LoadError::new(
            path,
            Location::File,
            LoadErrorKind::Io { referenced, source },
        )
    };
    let (file, bytes) = if options.files.is_empty() {
        let file = files::disk_path(path, &inside).map_err(|e| match disk_error(path, e) {
            LoadError {
                kind: LoadErrorKind::Ldtk { fault, .. },
                ..
            } => ldtk_error(path, rel_at.clone(), *fault),
            other => other,
        })?;
        let bytes = crate::io::read_limited(&file).map_err(|source| unreadable(&file, source))?;
        (file, bytes)
    } else {
        let file = folder_of(path).join(&inside);
        let bytes = files::from_memory(&inside, &options.files)
            .map_err(|source| unreadable(&file, source))?;
        (file, bytes)
    };
    let text = as_text(&bytes, &file)?;
    let json: LevelJson = from_json(text, &file)?;
    if json.identifier != level.identifier {
        return Err(ldtk_error(
            &file,
            "identifier".into(),
            LdtkFault::WrongLevelFile {
                expected: level.identifier.clone(),
                found: json.identifier,
            },
        ));
    }
    let Some(layers) = json.layer_instances else {
        return Err(ldtk_error(
            &file,
            "layerInstances".into(),
            LdtkFault::NoLayerInstances,
        ));
    };
    Ok(LevelLayers {
        file,
        at: "layerInstances".into(),
        layers: Cow::Owned(layers),
    })
}

/// The folder of the project at `path`.
fn folder_of(path: &Path) -> &Path {
    path.parent().unwrap_or(Path::new(""))
}

/// The entity layer `json` of a level at `level_origin`; `at` is its JSON path.
fn entity_layer(
    json: &LayerInstanceJson,
    level_origin: Vec2,
    at: &str,
) -> Result<EntityLayer, Fault> {
    let grid_size = layers::grid_size(json, at)?;
    let origin = level_origin + Vec2::new(json.offset_x as f32, json.offset_y as f32);
    let grid = PointGrid {
        size: f64::from(grid_size),
        origin,
    };
    let entities = json
        .entity_instances
        .iter()
        .enumerate()
        .map(|(i, e)| entities::entity(e, grid, &format!("{at}.entityInstances[{i}]")))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(EntityLayer {
        identifier: json.identifier.clone(),
        iid: json.iid.clone(),
        grid_size,
        entities,
    })
}
