//! `tileslide info`.

use anyhow::Result;
use serde_json::json;
use tileslide::io::ldtk::{FLIP_X_BIT, FLIP_Y_BIT};
use tileslide::io::tiled::Flip;

use crate::json::number;
use crate::map_file::{self, MapArgs, MapFormat};

pub fn run(args: &MapArgs, as_json: bool) -> Result<()> {
    let (map, format) = map_file::load(args)?;
    let counts = map.tile_counts();
    let occupied: usize = counts.values().sum();
    let placed = map.placed_segment_count();
    let active = map.active_segment_count();
    let size = map.cell_size();
    let origin = map.origin();
    if as_json {
        let tile_counts: serde_json::Map<String, serde_json::Value> = counts
            .iter()
            .map(|(id, n)| (id.0.to_string(), json!(n)))
            .collect();
        let out = json!({
            "map": args.map.display().to_string(),
            "format": format.name(),
            "width": map.width(),
            "height": map.height(),
            "cell_size": [number(size.x), number(size.y)],
            "origin": [number(origin.x), number(origin.y)],
            "tiles_used": counts.len(),
            "occupied_cells": occupied,
            "tile_counts": tile_counts,
            "segments_placed": placed,
            "segments_active": active,
        });
        println!("{out}");
        return Ok(());
    }
    println!("map:       {} ({})", args.map.display(), format.name());
    println!(
        "size:      {} × {} cells of {} × {}, origin ({}, {})",
        map.width(),
        map.height(),
        size.x,
        size.y,
        origin.x,
        origin.y
    );
    let tiled = matches!(format, MapFormat::TiledXml | MapFormat::TiledJson);
    let ldtk = format == MapFormat::Ldtk;
    let mut entries: Vec<_> = counts.iter().collect();
    if tiled {
        // By gid, each followed by its flipped placements.
        entries.sort_by_key(|(id, _)| (id.0 & Flip::GID_MASK, id.0));
    } else if ldtk {
        entries.sort_by_key(|(id, _)| (id.0 & !(FLIP_X_BIT | FLIP_Y_BIT), id.0));
    }
    let list: Vec<String> = entries
        .into_iter()
        .map(|(id, n)| {
            if tiled {
                format!("{}×{n}", tiled_id(id.0))
            } else if ldtk {
                format!("{}×{n}", ldtk_id(id.0))
            } else {
                format!("{id}×{n}")
            }
        })
        .collect();
    println!(
        "tiles:     {} distinct in {} of {} cells: {}",
        counts.len(),
        occupied,
        map.width() as u64 * map.height() as u64,
        list.join(" ")
    );
    if tiled && counts.keys().any(|id| !Flip::from_gid(id.0).is_none()) {
        println!("           (Tiled gids; flipped h horizontally, v vertically, d diagonally)");
    }
    if ldtk
        && counts
            .keys()
            .any(|id| id.0 & (FLIP_X_BIT | FLIP_Y_BIT) != 0)
    {
        println!("           (mirrored x horizontally, y vertically)");
    }
    println!("segments:  {placed} placed, {active} active after seam culling");
    Ok(())
}

/// A Tiled tile id as its gid and the letters of its flips (`2hv` for gid 2 turned 180°),
/// not as the number with Tiled's flip bits set.
fn tiled_id(id: u32) -> String {
    let flip = Flip::from_gid(id);
    let mut text = (id & Flip::GID_MASK).to_string();
    for (on, letter) in [
        (flip.horizontal, 'h'),
        (flip.vertical, 'v'),
        (flip.diagonal, 'd'),
    ] {
        if on {
            text.push(letter);
        }
    }
    text
}

/// An LDtk tile id as its collision's id and the letters of its flips (`2x` for a ramp
/// mirrored horizontally), not as the number with the flip bits set.
fn ldtk_id(id: u32) -> String {
    let mut text = (id & !(FLIP_X_BIT | FLIP_Y_BIT)).to_string();
    for (bit, letter) in [(FLIP_X_BIT, 'x'), (FLIP_Y_BIT, 'y')] {
        if id & bit != 0 {
            text.push(letter);
        }
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ldtk_ids_show_the_collision_and_its_flips() {
        assert_eq!(ldtk_id(2), "2");
        assert_eq!(ldtk_id(2 | FLIP_X_BIT), "2x");
        assert_eq!(ldtk_id(40 | FLIP_X_BIT | FLIP_Y_BIT), "40xy");
    }

    #[test]
    fn tiled_ids_show_the_gid_and_its_flips() {
        assert_eq!(tiled_id(2), "2");
        assert_eq!(tiled_id(2 | Flip::VERTICAL_BIT), "2v");
        assert_eq!(
            tiled_id(7 | Flip::HORIZONTAL_BIT | Flip::DIAGONAL_BIT),
            "7hd"
        );
    }
}
