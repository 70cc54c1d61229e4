//! `tileslide explain SCENE.json --character`: what each move of the scene's character did,
//! sweep by sweep, with the surfaces met and where they came from.

use std::path::Path;

use anyhow::{Context, Result, bail};
use serde_json::{Value, json};
use tileslide::{
    Aabb, CharacterShape, Circle, DebugKind, DebugLines, MoveEvent, MoveTrace, OneWayPass, Owner,
    Segment, TileMap, Vec2, WallSource,
};
use tileslide_render::{Rgba, Style, Swatch};

use super::body::check_step;
use super::picture::{Row, Sketch};
use tileslide_explain::character::{
    event_words, purpose_words, response_words, step_words, surface_words,
};

use super::words::{num, point, point_json, wall, wall_json};
use crate::scene::Scene;

/// Runs the scene's character and tells its story (every step, or step `only`).
pub fn run(path: &Path, only: Option<u64>, out: Option<&Path>, json: bool) -> Result<()> {
    let scene = Scene::load(path)?;
    let steps = scene.steps(None, path)?;
    check_step(only, steps)?;
    let Some(mut run) = scene.character(path)? else {
        bail!("{}: the scene has no \"character\"", path.display());
    };
    let mut trace = MoveTrace::default();
    let mut told = Vec::new();
    for step in 1..=only.unwrap_or(steps) {
        run.step(&scene.map, Some(&mut trace))
            .with_context(|| format!("{}: character at step {step}", path.display()))?;
        if only.is_none_or(|s| s == step) {
            told.push((step, trace.clone()));
        }
    }
    if json {
        let steps: Vec<Value> = told.iter().map(|(s, t)| step_json(*s, t)).collect();
        println!("{}", json!({"character": steps}));
    } else {
        for (step, t) in &told {
            print!("{}", step_words(&format!("character, step {step}"), t));
        }
    }
    if let Some(out) = out {
        // The step asked for, or the last one where a sweep met something.
        let met = |t: &MoveTrace| {
            t.events
                .iter()
                .any(|e| matches!(e, MoveEvent::Sweep(s) if s.hit.is_some()))
        };
        let shown = told.iter().rev().find(|(_, t)| met(t)).or(told.last());
        if let Some((step, t)) = shown {
            let sketch = sketch(&scene.map, *step, t, run.character.shape());
            sketch.save(&scene.map, scene.format, false, out, json)?;
        }
    }
    Ok(())
}

fn step_json(step: u64, t: &MoveTrace) -> Value {
    let events: Vec<Value> = t
        .events
        .iter()
        .map(|e| match *e {
            MoveEvent::Sweep(s) => json!({
                "sweep": {
                    "purpose": format!("{:?}", s.purpose),
                    "from": point_json(s.from),
                    "motion": point_json(s.motion),
                    "moved": point_json(s.moved),
                    "hit": s.hit.map(|h| json!({
                        "source": wall_json(&h.source),
                        "flags": h.flags.0,
                        "t": crate::json::number(h.t),
                        "point": point_json(h.point),
                        "normal": point_json(h.normal),
                        "rounded": h.rounded,
                    })),
                }
            }),
            MoveEvent::OneWay { source, pass } => {
                json!({"one_way": {"source": wall_json(&source), "pass": format!("{pass:?}")}})
            }
            MoveEvent::Grounded {
                source,
                normal,
                drop,
            } => json!({"grounded": {
                "source": wall_json(&source),
                "normal": point_json(normal),
                "drop": crate::json::number(drop),
            }}),
            MoveEvent::Pushed {
                source,
                direction,
                depth,
                crushed,
            } => json!({"pushed": {
                "source": wall_json(&source),
                "direction": point_json(direction),
                "depth": crate::json::number(depth),
                "crushed": crushed,
            }}),
            ref other => json!({"event": event_words(other, &mut 0)}),
        })
        .collect();
    json!({
        "step": step,
        "start": point_json(t.start),
        "move": point_json(t.displacement),
        "end": point_json(t.end),
        "events": events,
    })
}

/// The character's shape at `at`, into `lines`.
fn draw_shape(lines: &mut DebugLines, shape: CharacterShape, at: Vec2) {
    match shape {
        CharacterShape::Circle { radius } => {
            lines.push_circle(DebugKind::Character, Circle::new(at, radius), Owner(0));
        }
        other => lines.push_box(DebugKind::Character, other.bounds(at), Owner(0)),
    }
}

/// The picture of one move: the shape where it started (faint) and where it ended, each
/// sweep's path, the surfaces met numbered with their normals, one-way platforms passed.
fn sketch(map: &TileMap, step: u64, t: &MoveTrace, shape: CharacterShape) -> Sketch {
    let style = Style::default();
    let faint = Rgba::opaque(120, 120, 140);
    let mut sketch = Sketch::new();
    let mut lines = DebugLines::new();
    draw_shape(&mut lines, shape, t.end);
    let reach: Aabb = shape.bounds(Vec2::ZERO);
    let size = (reach.max - reach.min).max_element();
    sketch.show(t.start, size);
    sketch.show(t.end, size);
    let mut legend = vec![
        Row::Heading(format!("character, step {step}")),
        Row::Key(Swatch::Square(style.character), "where it ended".to_owned()),
        Row::Line(format!("move {}", point(t.displacement))),
    ];
    let mut path = vec![t.start];
    let mut passed = Vec::new();
    let mut n = 0;
    for e in &t.events {
        match *e {
            MoveEvent::Sweep(s) => {
                path.push(s.from);
                path.push(s.from + s.moved);
                if let Some(h) = s.hit {
                    n += 1;
                    let tip = h.point + h.normal * 0.3;
                    lines.push_segment(DebugKind::Contact, Segment::new(h.point, tip), Owner(0));
                    // Behind the surface, clear of the character.
                    sketch.label(h.point - h.normal * 0.2, n.to_string(), style.contact);
                    sketch.show(h.point, 0.0);
                    legend.push(Row::Line(format!(
                        "{n}: {} sweep, {}, t {}",
                        purpose_words(s.purpose),
                        wall(&h.source),
                        num(h.t)
                    )));
                }
            }
            MoveEvent::Slide {
                surface, response, ..
            } => legend.push(Row::Line(format!(
                "   {}: {}",
                surface_words(surface),
                response_words(response)
            ))),
            MoveEvent::OneWay { source, pass } => {
                // The platform's segment, marked where the character went through it.
                if let WallSource::Tile { active, .. } = source
                    && let Some(platform) = map.active_segment(active)
                {
                    let middle = (platform.segment.a + platform.segment.b) * 0.5;
                    let text = match pass {
                        OneWayPass::DroppedThrough => "dropped through",
                        _ => "passed",
                    };
                    if !passed.contains(&active) {
                        passed.push(active);
                        sketch.label(middle, text, style.one_way);
                        sketch.show(middle, 0.0);
                    }
                }
                legend.push(Row::Line(event_words(e, &mut 0)));
            }
            MoveEvent::Carried { .. }
            | MoveEvent::Pushed { .. }
            | MoveEvent::SteppedUp { .. }
            | MoveEvent::LeftGround { .. }
            | MoveEvent::PlatformGone { .. } => legend.push(Row::Line(event_words(e, &mut 0))),
            _ => {}
        }
    }
    path.push(t.end);
    path.dedup();
    // The start drawn first, faint, under the rest.
    match shape {
        CharacterShape::Circle { radius } => {
            sketch
                .picture
                .body_with_color(Circle::new(t.start, radius), faint);
        }
        other => {
            sketch.picture.area(other.bounds(t.start), faint);
        }
    }
    sketch.picture.polyline(&path);
    sketch.picture.debug_lines(&lines);
    legend.insert(
        1,
        Row::Key(Swatch::Square(faint), "where it started".to_owned()),
    );
    sketch.legend = legend;
    sketch
}
