//! Debug lines drawn in their kinds' colours: the one way the canvas draws the map and a
//! picture draws what the core's `debug_lines` methods give.

use tileslide::{DebugBox, DebugCircle, DebugKind, DebugKinds, DebugPoint, DebugSegment, Vec2};

use crate::pen::Pen;
use crate::view::{NORMAL_WIDTH, View};
use crate::{Rgba, Style};

/// The segment kinds in drawing order, bottom first, with their width as a multiple of the
/// line width: faint and thin things under walls, walls under what moves.
const SEGMENT_LAYERS: [(DebugKind, f32); 9] = [
    (DebugKind::HiddenSegment, 1.0),
    (DebugKind::FlowArrow, 0.75),
    (DebugKind::Normal, NORMAL_WIDTH),
    (DebugKind::Path, 1.0),
    (DebugKind::ActiveSegment, 1.0),
    (DebugKind::OneWaySegment, 1.0),
    (DebugKind::TemporarySegment, 1.0),
    (DebugKind::Ray, 1.0),
    (DebugKind::Contact, 1.5),
];

/// Draws `segments` of the kinds in `layers`, one stroke per kind (a map's thousands of
/// walls are one path). A [`Normal`](DebugKind::Normal) is drawn as a tick from its start
/// along its direction, [`View::tick_length`] pixels long whatever the scale, so normals
/// stay visible on small pictures.
pub(crate) fn draw_segments(
    pen: &mut Pen<'_>,
    view: &View,
    style: &Style,
    layers: DebugKinds,
    segments: &[DebugSegment],
) {
    let line = view.line_width();
    for (kind, width) in SEGMENT_LAYERS {
        if !layers.contains(kind) {
            continue;
        }
        let Some(color) = style.color_of(kind) else {
            continue;
        };
        let ends = segments.iter().filter(|s| s.kind == kind).filter_map(|s| {
            let (a, b) = (view.pixel_of(s.segment.a)?, view.pixel_of(s.segment.b)?);
            if kind == DebugKind::Normal {
                let d = (b - a).try_normalize()?;
                Some((a, a + d * view.tick_length()))
            } else {
                Some((a, b))
            }
        });
        pen.lines(ends, color, line * width);
    }
}

/// Draws `circles` of the kinds in `layers`, in order: bodies filled with an outline,
/// volumes filled translucent and outlined, characters and others outlined.
pub(crate) fn draw_circles(
    pen: &mut Pen<'_>,
    view: &View,
    style: &Style,
    layers: DebugKinds,
    circles: &[DebugCircle],
) {
    for c in circles.iter().filter(|c| layers.contains(c.kind)) {
        if c.kind == DebugKind::Body {
            draw_body(
                pen,
                view,
                style,
                c.circle.center,
                c.circle.radius,
                style.body,
            );
            continue;
        }
        let (Some(color), Some(center)) = (style.color_of(c.kind), view.pixel_of(c.circle.center))
        else {
            continue;
        };
        let (fill, width) = area_look(c.kind, color, view);
        pen.disc(
            center,
            view.pixel_length(c.circle.radius),
            fill,
            color,
            width,
        );
    }
}

/// Draws `boxes` of the kinds in `layers`, in order, as [`draw_circles`] draws circles.
pub(crate) fn draw_boxes(
    pen: &mut Pen<'_>,
    view: &View,
    style: &Style,
    layers: DebugKinds,
    boxes: &[DebugBox],
) {
    for b in boxes.iter().filter(|b| layers.contains(b.kind)) {
        let (Some(color), Some(min), Some(max)) = (
            style.color_of(b.kind),
            view.pixel_of(b.aabb.min),
            view.pixel_of(b.aabb.max),
        ) else {
            continue;
        };
        let (fill, width) = area_look(b.kind, color, view);
        pen.rect(min, max, fill, color, width);
    }
}

/// Draws `points` of the kinds in `layers`: hits as crosses, everything else as a dot.
pub(crate) fn draw_points(
    pen: &mut Pen<'_>,
    view: &View,
    style: &Style,
    layers: DebugKinds,
    points: &[DebugPoint],
) {
    let line = view.line_width();
    for p in points.iter().filter(|p| layers.contains(p.kind)) {
        let (Some(color), Some(at)) = (style.color_of(p.kind), view.pixel_of(p.point)) else {
            continue;
        };
        match p.kind {
            DebugKind::Hit | DebugKind::RefusedHit => {
                pen.cross(at, view.tick_length(), color, line * 1.5);
            }
            _ => pen.disc(at, line * 1.5 + 1.0, color, color, 0.0),
        }
    }
}

/// A body: a disc in `fill` with the style's outline (`center` and `radius` in world
/// units).
pub(crate) fn draw_body(
    pen: &mut Pen<'_>,
    view: &View,
    style: &Style,
    center: Vec2,
    radius: f32,
    fill: Rgba,
) {
    if let Some(c) = view.pixel_of(center) {
        let r = view.pixel_length(radius);
        let line = view.line_width();
        pen.disc(c, r, fill, style.body_outline, (line * 0.5).min(r * 0.25));
    }
}

/// The fill and outline width of an area of `kind` drawn in `color`: volumes filled at a
/// quarter of its opacity, the rest outlined only (broadphase boxes thinner).
fn area_look(kind: DebugKind, color: Rgba, view: &View) -> (Rgba, f32) {
    let line = view.line_width();
    match kind {
        DebugKind::AttackVolume | DebugKind::VulnerabilityVolume => {
            (color.with_alpha(color.a / 4), line)
        }
        DebugKind::BroadphaseBox => (Rgba::new(0, 0, 0, 0), line * 0.5),
        _ => (Rgba::new(0, 0, 0, 0), line),
    }
}
