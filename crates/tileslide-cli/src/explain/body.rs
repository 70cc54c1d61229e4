//! `tileslide explain SCENE.json --body K`: what the resolver did with body K, pass by pass,
//! with every contact it considered and where it came from.

use std::path::Path;

use anyhow::{Context, Result, bail};
use serde_json::{Value, json};
use tileslide::{
    Bodies, BodyHandle, BodyTrace, Circle, ContactSource, DebugKind, DebugLines, Owner, Ray,
    ResolveTrace, Response, Segment,
};
use tileslide_render::{Rgba, Style, Swatch};

use super::picture::{Row, Sketch};
use tileslide_explain::body::{response_short, source_words, step_words};

use super::words::{num, point, point_json, wall_json};
use crate::json::number;
use crate::scene::Scene;

/// Runs the scene, tracing body `k`, and tells its story (every step, or step `only`).
pub fn run(path: &Path, k: usize, only: Option<u64>, out: Option<&Path>, json: bool) -> Result<()> {
    let scene = Scene::load(path)?;
    let steps = scene.steps(None, path)?;
    if scene.bodies.is_empty() {
        bail!("{}: the scene has no bodies", path.display());
    }
    if k >= scene.bodies.len() {
        bail!(
            "--body {k}: the scene's bodies are numbered 0 to {} (--body counts from 0)",
            scene.bodies.len().saturating_sub(1)
        );
    }
    check_step(only, steps)?;
    let (mut bodies, crowd) = scene.bodies(path)?;
    let handles: Vec<BodyHandle> = crowd.iter().map(|&(h, _)| h).collect();
    let mut trace = ResolveTrace::of(handles[k]);
    let mut told = Vec::new();
    for step in 1..=only.unwrap_or(steps) {
        for (i, &(h, v)) in crowd.iter().enumerate() {
            bodies
                .propose(h, v)
                .with_context(|| format!("{}: bodies[{i}] at step {step}", path.display()))?;
        }
        bodies.step_traced(&scene.map, &mut trace);
        if only.is_none_or(|s| s == step)
            && let Some(story) = trace.body(handles[k])
        {
            told.push((step, story.clone()));
        }
    }
    let index = |h: BodyHandle| handles.iter().position(|&x| x == h);
    let name = |h: BodyHandle| index(h).map(|k| format!("body {k}"));
    if json {
        let steps: Vec<Value> = told
            .iter()
            .map(|(step, story)| step_json(*step, story, &index))
            .collect();
        println!("{}", json!({"body": k, "steps": steps}));
    } else {
        for (step, story) in &told {
            print!(
                "{}",
                step_words(&format!("body {k}, step {step}"), story, &name)
            );
        }
    }
    if let Some(out) = out {
        // The step asked for, or the last one where something was met.
        let shown = told
            .iter()
            .rev()
            .find(|(_, s)| s.passes.iter().any(|p| !p.contacts.is_empty()))
            .or(told.last());
        if let Some((step, story)) = shown {
            let sketch = sketch(k, *step, story, &bodies, &name);
            sketch.save(&scene.map, scene.format, false, out, json)?;
        }
    }
    Ok(())
}

/// Refuses a step outside the run.
pub fn check_step(only: Option<u64>, steps: u64) -> Result<()> {
    if let Some(s) = only
        && !(1..=steps).contains(&s)
    {
        bail!("--step {s}: the scene runs steps 1 to {steps}");
    }
    Ok(())
}

fn step_json(step: u64, story: &BodyTrace, name: &impl Fn(BodyHandle) -> Option<usize>) -> Value {
    let passes: Vec<Value> = story
        .passes
        .iter()
        .map(|pass| {
            let contacts: Vec<Value> = pass
                .contacts
                .iter()
                .map(|c| {
                    let source = match c.source {
                        ContactSource::Wall(w) => wall_json(&w),
                        ContactSource::Body { handle, circle } => {
                            json!({"body": name(handle), "circle": circle})
                        }
                        _ => Value::Null,
                    };
                    json!({
                        "source": source,
                        "part": format!("{:?}", c.part),
                        "t": number(c.t),
                        "point": point_json(c.point),
                        "normal": point_json(c.normal),
                        "grazed": c.grazed,
                    })
                })
                .collect();
            let slide = pass.response.slide().map(point_json);
            json!({
                "pass": pass.pass,
                "from": point_json(pass.from),
                "motion": point_json(pass.motion),
                "contacts": contacts,
                "first": pass.first,
                "moved": point_json(pass.moved),
                "step_taken": pass.step_taken,
                "response": response_name(&pass.response),
                "slide": slide,
            })
        })
        .collect();
    json!({
        "step": step,
        "start": point_json(story.start),
        "proposed": point_json(story.proposed),
        "resolved": point_json(story.resolved),
        "fate": format!("{:?}", story.fate),
        "passes": passes,
    })
}

/// The response's name, without its slide.
fn response_name(r: &Response) -> String {
    let debug = format!("{r:?}");
    debug
        .split([' ', '{'])
        .next()
        .unwrap_or_default()
        .to_owned()
}

/// The picture of one step: the body where it started (faint) and where it ended, its
/// path pass by pass, each contact numbered with its normal, and the slides.
fn sketch(
    k: usize,
    step: u64,
    story: &BodyTrace,
    bodies: &Bodies,
    name: &impl Fn(BodyHandle) -> Option<String>,
) -> Sketch {
    let style = Style::default();
    let mut sketch = Sketch::new();
    let circles: Vec<Circle> = bodies
        .get(story.handle)
        .map(|b| b.shape().circles().to_vec())
        .unwrap_or_default();
    let radius = circles.iter().map(|c| c.radius).fold(0.0, f32::max);
    let end = story.start + story.resolved;
    let faint = Rgba::opaque(120, 120, 140);
    for c in &circles {
        sketch
            .picture
            .body_with_color(Circle::new(story.start + c.center, c.radius), faint);
        sketch.picture.body(Circle::new(end + c.center, c.radius));
    }
    sketch.show(story.start, radius);
    sketch.show(end, radius);
    let mut path = vec![story.start];
    path.extend(story.passes.iter().map(|p| p.from + p.moved));
    sketch.picture.polyline(&path);
    let mut lines = DebugLines::new();
    let mut legend = vec![
        Row::Heading(format!("body {k}, step {step}")),
        Row::Key(Swatch::Disc(faint), "where it started".to_owned()),
        Row::Key(Swatch::Disc(style.body), "where it ended".to_owned()),
    ];
    let normal_length = 0.3;
    let mut n = 0;
    for pass in &story.passes {
        for (i, c) in pass.contacts.iter().enumerate() {
            n += 1;
            let tip = c.point + c.normal * normal_length;
            lines.push_segment(DebugKind::Contact, Segment::new(c.point, tip), Owner(0));
            let color = if c.grazed { faint } else { style.contact };
            // Behind the contact, in what was met: clear of the body.
            sketch.label(c.point - c.normal * 0.2, n.to_string(), color);
            sketch.show(c.point, 0.0);
            let chosen = if pass.first == Some(i) { ", first" } else { "" };
            let graze = if c.grazed { ", graze" } else { "" };
            legend.push(Row::Line(format!(
                "{n}: pass {}, {}, t {}{chosen}{graze}",
                pass.pass,
                source_words(c, name),
                num(c.t)
            )));
        }
        if let Some(slide) = pass.response.slide() {
            let from = pass.from + pass.moved;
            sketch.picture.ray(Ray::between(from, from + slide), None);
            sketch.label(
                from + slide * 0.5,
                format!("slide {}", pass.pass),
                style.ray,
            );
            sketch.show(from + slide, 0.0);
            legend.push(Row::Line(format!("slide {}: {}", pass.pass, point(slide))));
        } else if !matches!(pass.response, Response::Free) {
            legend.push(Row::Line(format!(
                "pass {}: {}",
                pass.pass,
                response_short(&pass.response)
            )));
        }
    }
    sketch.picture.debug_lines(&lines);
    sketch.legend = legend;
    sketch
}
