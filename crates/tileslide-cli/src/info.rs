//! `tileslide info`.

use anyhow::Result;
use serde_json::json;

use crate::json::number;
use crate::map_file::{self, MapArgs};

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
    let list: Vec<String> = counts.iter().map(|(id, n)| format!("{id}×{n}")).collect();
    println!(
        "tiles:     {} distinct in {} of {} cells: {}",
        counts.len(),
        occupied,
        map.width() as u64 * map.height() as u64,
        list.join(" ")
    );
    println!("segments:  {placed} placed, {active} active after seam culling");
    Ok(())
}
