//! `tileslide explain SCENE.json --body K`: what the resolver did with body K, pass by pass,
//! with every contact it considered and where it came from.

use std::path::Path;

use anyhow::{Context, Result, bail};
use serde_json::{Value, json};
use tileslide::{
    Bodies, BodyFate, BodyHandle, BodyTrace, Circle, ContactPart, ContactSource, ContactTrace,
    DebugKind, DebugLines, Owner, PassTrace, Ray, ResolveTrace, Response, Segment,
};
use tileslide_render::{Rgba, Style, Swatch};

use super::picture::{Row, Sketch};
use super::words::{num, point, point_json, wall, wall_json};
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
    let name = |h: BodyHandle| handles.iter().position(|&x| x == h);
    if json {
        let steps: Vec<Value> = told
            .iter()
            .map(|(step, story)| step_json(*step, story, &name))
            .collect();
        println!("{}", json!({"body": k, "steps": steps}));
    } else {
        for (step, story) in &told {
            print!("{}", step_words(k, *step, story, &name));
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

/// What a contact came from, in words.
fn source_words(c: &ContactTrace, name: &impl Fn(BodyHandle) -> Option<usize>) -> String {
    let part = match c.part {
        ContactPart::Face => " (face)",
        ContactPart::RoundedEnd => " (rounded end)",
        _ => "",
    };
    match c.source {
        ContactSource::Wall(w) => format!("{}{part}", wall(&w)),
        ContactSource::Body { handle, circle } => match name(handle) {
            Some(k) => format!("body {k} circle {circle}"),
            None => format!("a body not in the scene, circle {circle}"),
        },
        _ => "something new".to_owned(),
    }
}

/// What the resolver did, in words.
fn response_words(pass: &PassTrace) -> String {
    let said = match pass.response {
        Response::Free => "free: the rest of the move made".to_owned(),
        Response::Slid { slide } => format!("slid along it: next {}", point(slide)),
        Response::RoundedCorner { slide } => {
            format!("rounded the convex corner: next {}", point(slide))
        }
        Response::TieBreak { slide } => format!(
            "met head-on: the tie-break turns it (the lower slot one way, the higher the other): next {}",
            point(slide)
        ),
        Response::StoppedHeadOn => "stopped: met straight on, no side to slide to".to_owned(),
        Response::StoppedInCorner => {
            "stopped in a concave corner: the slide along the last wall ran straight into this one"
                .to_owned()
        }
        Response::NoSlide => "stopped at the contact (slide mode Stop)".to_owned(),
        Response::CutShort => "cut short at the contact: the passes are used up".to_owned(),
        Response::OutOfRange => "stopped: the slide would leave the coordinate range".to_owned(),
        _ => format!("{:?}", pass.response),
    };
    // (Noted only where it matters: a contact at t = 0 has no safe part.)
    let dropped = !pass.step_taken && pass.chosen().is_some_and(|c| c.t > 0.0);
    if dropped {
        format!("{said} (the safe part, under an eighth of the gap, not taken)")
    } else {
        said
    }
}

/// One step of the story, in words.
fn step_words(
    k: usize,
    step: u64,
    story: &BodyTrace,
    name: &impl Fn(BodyHandle) -> Option<usize>,
) -> String {
    let mut s = format!(
        "body {k}, step {step}: at {}, proposed {}\n",
        point(story.start),
        point(story.proposed)
    );
    match story.fate {
        BodyFate::Still => s.push_str("  still: no move proposed\n"),
        BodyFate::Settled => s.push_str(
            "  skipped as settled: blocked in place last step, and nothing it sees changed\n",
        ),
        _ => {}
    }
    let mut n = 0;
    for pass in &story.passes {
        s += &format!("  pass {}: sweeps {}\n", pass.pass, point(pass.motion));
        for (i, c) in pass.contacts.iter().enumerate() {
            n += 1;
            let mark = if c.grazed {
                "  ignored: a graze (moving along it)"
            } else if pass.first == Some(i) {
                "  <- first"
            } else {
                ""
            };
            s += &format!(
                "    [{n}] {}: t {}, at {}, normal {}{mark}\n",
                source_words(c, name),
                num(c.t),
                point(c.point),
                point(c.normal)
            );
        }
        s += &format!(
            "    moved {}; {}\n",
            point(pass.moved),
            response_words(pass)
        );
    }
    s += &format!(
        "  resolved {}: ends at {}\n",
        point(story.resolved),
        point(story.start + story.resolved)
    );
    s
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

/// The response in a few words.
fn response_short(r: &Response) -> &'static str {
    match r {
        Response::Free => "free",
        Response::Slid { .. } => "slid",
        Response::RoundedCorner { .. } => "rounded the corner",
        Response::TieBreak { .. } => "tie-break",
        Response::StoppedHeadOn => "stopped head-on",
        Response::StoppedInCorner => "stopped in a concave corner",
        Response::NoSlide => "stopped (no slide)",
        Response::CutShort => "cut short (passes used up)",
        Response::OutOfRange => "stopped (range)",
        _ => "?",
    }
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
    name: &impl Fn(BodyHandle) -> Option<usize>,
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
