//! The soak's checks: the library's promises, asked of every body, character, query and
//! frame of hit volumes, every step.

use glam::Vec2;
use tileslide::{
    BodyDesc, BodyShape, CharacterShape, Circle, HitEvent, HitObject, HitTypes, MoveOptions,
    NavConfig, ObjectId, QueryFilter, Ray, SegmentFlags, TeamRule, TileMap, Volume,
};

use super::audit::{Audit, Kind};
use super::world::{DT, Sim, room_of};

/// The most a body may overlap another or a wall, or a character a wall, after a step: the
/// resolver's and the controller's promise (on the soak's unit cells).
pub const SKIN: f32 = 1e-4;

/// Values no entry point that takes a place, a move or a size may take: NaN, infinities
/// and finite values far beyond `MAX_COORD` (queries answer them: see docs/limits.md).
const BAD: [f32; 5] = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY, 3e38, -1e20];

pub use crate::scene::penetration;

/// Every body: finite, in no wall, in the room it was in, and apart from every other body.
pub fn bodies(sim: &mut Sim, audit: &mut Audit) {
    let step = sim.game.step;
    let map = &sim.map;
    let (w, h) = (map.width() as usize, map.height() as usize);
    // Every circle, and a grid of unit cells listing the circles whose centre is in each.
    let mut circles: Vec<(usize, Circle)> = Vec::new();
    let mut grid: Vec<Vec<u32>> = vec![Vec::new(); w * h];
    for (i, b) in sim.game.placed.iter().enumerate() {
        let at = sim.position(b.handle);
        audit.count(Kind::BodyPlace);
        if !at.is_finite() {
            audit.violation(Kind::BodyPlace, step, format!("body {} at {at}", b.owner.0));
            continue;
        }
        for c in &b.circles {
            let circle = Circle::new(at + c.center, c.radius);
            let depth = penetration(map, &circle);
            if depth > SKIN {
                audit.violation(
                    Kind::BodyPlace,
                    step,
                    format!(
                        "body {} circle at {} is {depth} into a wall",
                        b.owner.0, circle.center
                    ),
                );
            }
            let cell = cell_index(map, circle.center);
            if let Some(k) = cell {
                grid[k].push(circles.len() as u32);
            }
            circles.push((i, circle));
        }
        if let Some(why) = left_room(map, &sim.game.rooms, b.last, at) {
            audit.violation(Kind::BodyPlace, step, format!("body {} {why}", b.owner.0));
        }
    }
    for (k, &(i, a)) in circles.iter().enumerate() {
        let Some(cell) = cell_index(map, a.center) else {
            continue;
        };
        let (c, r) = (cell % w, cell / w);
        for nr in r.saturating_sub(1)..(r + 2).min(h) {
            for nc in c.saturating_sub(1)..(c + 2).min(w) {
                for &m in &grid[nr * w + nc] {
                    let (j, b) = circles[m as usize];
                    if m as usize <= k || j == i {
                        continue;
                    }
                    audit.count(Kind::BodyPair);
                    let overlap = a.radius + b.radius - a.center.distance(b.center);
                    if overlap > SKIN {
                        audit.violation(
                            Kind::BodyPair,
                            step,
                            format!(
                                "bodies {} and {} overlap by {overlap} at {} and {}",
                                sim.game.placed[i].owner.0,
                                sim.game.placed[j].owner.0,
                                a.center,
                                b.center
                            ),
                        );
                    }
                }
            }
        }
    }
    for b in &mut sim.game.placed {
        if let Ok(body) = sim.bodies.get(b.handle) {
            b.last = body.position();
        }
    }
}

/// How something that was at `was` and is at `now` left its room (4-connected open cells),
/// if it did: through a wall.
fn left_room(map: &TileMap, rooms: &[Option<u32>], was: Vec2, now: Vec2) -> Option<String> {
    let (from, to) = (room_of(map, rooms, was), room_of(map, rooms, now));
    (from != to).then(|| format!("went from {was} (room {from:?}) to {now} (room {to:?})"))
}

/// The index of the unit cell `p` is in, if on the map.
fn cell_index(map: &TileMap, p: Vec2) -> Option<usize> {
    (p.x >= 0.0 && p.y >= 0.0 && p.x < map.width() as f32 && p.y < map.height() as f32)
        .then(|| p.y as usize * map.width() as usize + p.x as usize)
}

/// Every character: finite, in no wall, in the room it was in.
pub fn runners(sim: &mut Sim, audit: &mut Audit) {
    let step = sim.game.step;
    let map = &sim.map;
    for r in &mut sim.game.runners {
        audit.count(Kind::CharacterPlace);
        let p = r.character.position;
        if !p.is_finite() {
            audit.violation(
                Kind::CharacterPlace,
                step,
                format!("character {} at {p}", r.owner.0),
            );
            continue;
        }
        if let Some(why) = character_in_wall(map, r.character.shape(), p) {
            audit.violation(
                Kind::CharacterPlace,
                step,
                format!(
                    "character {} ({:?}) at {p}: {why}",
                    r.owner.0,
                    r.character.shape()
                ),
            );
        }
        if let Some(why) = left_room(map, &sim.game.rooms, r.last, p) {
            audit.violation(
                Kind::CharacterPlace,
                step,
                format!("character {} {why}", r.owner.0),
            );
        }
        r.last = p;
    }
}

/// Why a character of `shape` at `p` is in a wall by more than [`SKIN`], if it is: a
/// circle nearer than its radius to a solid segment it is in front of; a box, shrunk by the
/// skin, crossing one; either with its centre in solid.
pub fn character_in_wall(map: &TileMap, shape: CharacterShape, p: Vec2) -> Option<String> {
    if map.is_point_solid(p) {
        return Some("its centre is in a solid".into());
    }
    let half = shape.bounds(Vec2::ZERO).max;
    let reach = Circle::new(p, half.length());
    for s in map.segments_overlapping_circle(&reach) {
        if s.flags.contains(SegmentFlags::ONE_WAY) || (p - s.segment.a).dot(s.normal) < 0.0 {
            continue;
        }
        match shape {
            CharacterShape::Circle { radius } => {
                let depth = radius - s.segment.distance_squared_to(p).sqrt();
                if depth > SKIN {
                    return Some(format!("{depth} into {:?}", s.segment));
                }
            }
            _ => {
                let inner = tileslide::Aabb::from_center(p, half - Vec2::splat(SKIN));
                if inner.overlaps_segment(&s.segment) {
                    return Some(format!("the box crosses {:?}", s.segment));
                }
            }
        }
    }
    None
}

/// Now and then, a bad value or a stale handle handed to an entry point: refused with an
/// error, changing nothing.
pub fn bad_values(sim: &mut Sim, audit: &mut Audit) {
    let step = sim.game.step;
    let rng = &mut sim.game.rng;
    if rng.below(8) != 0 {
        return;
    }
    let bad = BAD[rng.below(BAD.len() as u64) as usize];
    let good = rng.range(1.0, 4.0);
    let v = if rng.below(2) == 0 {
        Vec2::new(bad, good)
    } else {
        Vec2::new(good, bad)
    };
    let which = rng.below(8);
    audit.count(Kind::BadValue);
    let mut fail = |what: String| audit.violation(Kind::BadValue, step, what);
    match which {
        0 | 1 if !sim.game.placed.is_empty() => {
            let k = sim.game.rng.below(sim.game.placed.len() as u64) as usize;
            let h = sim.game.placed[k].handle;
            let Ok(before) = sim.bodies.get(h).map(|b| (b.position(), b.proposed_move())) else {
                return;
            };
            let refused = if which == 0 {
                sim.bodies.propose(h, v).is_err()
            } else {
                sim.bodies.set_position(h, v).is_err()
            };
            let after = sim.bodies.get(h).map(|b| (b.position(), b.proposed_move()));
            if !refused || after != Ok(before) {
                fail(format!(
                    "{} of {v}: refused {refused}",
                    ["propose", "set_position"][which as usize]
                ));
            }
        }
        2 => {
            let n = sim.bodies.len();
            let added = BodyShape::circle(0.3)
                .map_err(|e| e.to_string())
                .and_then(|s| {
                    sim.bodies
                        .add(BodyDesc::new(v, s))
                        .map_err(|e| e.to_string())
                });
            if added.is_ok() || sim.bodies.len() != n {
                fail(format!("a body added at {v}"));
            }
            let shape = BodyShape::circle(bad);
            if shape.is_ok() {
                fail(format!("a circle of radius {bad} made"));
            }
        }
        3 if !sim.game.removed.is_empty() => {
            let k = sim.game.rng.below(sim.game.removed.len() as u64) as usize;
            let h = sim.game.removed[k];
            audit.count(Kind::StaleHandle);
            if sim.bodies.get(h).is_ok()
                || sim.bodies.propose(h, Vec2::X).is_ok()
                || sim.bodies.set_position(h, Vec2::ONE).is_ok()
                || sim.bodies.remove(h).is_ok()
            {
                audit.violation(Kind::StaleHandle, step, format!("{h:?} accepted"));
            }
        }
        4 if !sim.game.runners.is_empty() => {
            let k = sim.game.rng.below(sim.game.runners.len() as u64) as usize;
            let r = &mut sim.game.runners[k];
            let before = r.character.clone();
            let moved = r.character.move_by(&sim.map, v, MoveOptions::default());
            let mut velocity = v;
            let slid =
                r.character
                    .move_and_slide(&sim.map, &mut velocity, DT, MoveOptions::default());
            let teleported = r.character.teleport(v);
            if moved.is_ok()
                || slid.is_ok()
                || teleported.is_ok()
                || r.character.position.to_array() != before.position.to_array()
            {
                fail(format!("a character's move or teleport of {v} accepted"));
            }
        }
        5 => {
            let from = Vec2::new(good, good);
            // docs/limits.md: a bad radius is refused; a NaN or infinite start or move hits
            // nothing; any finite one is answered (exactly: here, finitely).
            let filter = QueryFilter::default();
            let radius = sim.map.cast_circle(from, bad, Vec2::X, &filter);
            if radius.is_ok() != (bad.is_finite() && bad > 0.0) {
                fail(format!("a circle cast of radius {bad} answered {radius:?}"));
            }
            for (what, cast) in [
                ("start", sim.map.cast_circle(v, 0.3, Vec2::X, &filter)),
                ("move", sim.map.cast_circle(from, 0.3, v, &filter)),
            ] {
                let sound = match &cast {
                    Ok(None) => true,
                    Ok(Some(hit)) => {
                        v.is_finite()
                            && (0.0..=1.0).contains(&hit.t)
                            && hit.center.is_finite()
                            && hit.point.is_finite()
                    }
                    Err(_) => false,
                };
                if !sound {
                    fail(format!("a circle cast with {what} {v} answered {cast:?}"));
                }
            }
        }
        6 => {
            let p = Vec2::new(good, good);
            if sim.nav.find_path(&sim.map, v, p, 0.3).is_ok()
                || sim.nav.find_path(&sim.map, p, v, 0.3).is_ok()
                || sim.nav.find_path(&sim.map, p, p, bad).is_ok()
            {
                fail(format!("a path from or to {v}, or of radius {bad}"));
            }
        }
        _ => {
            let object = HitObject::new(tileslide::Owner(0), v, Vec2::ONE);
            let vulnerable = Volume::circle(Vec2::ZERO, 0.5, HitTypes::from_bits(1));
            if let Ok(vulnerable) = vulnerable {
                for world in &mut sim.hits {
                    if world.register(object, &[], &[vulnerable]).is_ok() {
                        fail(format!("a hit object at {v} registered"));
                    }
                }
            }
            if Volume::circle(Vec2::ZERO, bad, HitTypes::from_bits(1)).is_ok() {
                fail(format!("a volume of radius {bad} made"));
            }
        }
    }
}

/// Registers every body and character in both hit worlds for this frame (each vulnerable;
/// one in ten attacking with a circle ahead of it, once per swing), detects, and compares.
pub fn volumes(sim: &mut Sim, audit: &mut Audit) {
    let step = sim.game.step;
    audit.count(Kind::Volumes);
    for world in &mut sim.hits {
        world.begin_frame();
    }
    let mut objects = Vec::with_capacity(sim.game.placed.len() + sim.game.runners.len());
    for b in &sim.game.placed {
        if let Ok(body) = sim.bodies.get(b.handle) {
            let r = body.shape().bounding_radius();
            objects.push((b.owner, body.position(), body.resolved_move(), r));
        }
    }
    for r in &sim.game.runners {
        let half = r.character.shape().bounds(Vec2::ZERO).max;
        objects.push((
            r.owner,
            r.character.position,
            r.velocity * DT,
            half.max_element(),
        ));
    }
    let mut ids: Vec<ObjectId> = Vec::with_capacity(objects.len());
    for (owner, position, motion, reach) in objects {
        let mut object = HitObject::new(owner, position, Vec2::splat(reach + 0.6));
        object.motion = motion;
        object.team = (owner.0 % 4) as u32;
        let attacks = owner.0 % 10 == 0;
        if attacks {
            object.swing = Some(step / 30);
        }
        let (Ok(vulnerable), Ok(attack)) = (
            Volume::circle(Vec2::ZERO, reach, HitTypes::from_bits(1)),
            Volume::circle(Vec2::new(reach, 0.0), 0.5, HitTypes::from_bits(1)),
        ) else {
            audit.violation(
                Kind::Volumes,
                step,
                format!("a volume of radius {reach} refused"),
            );
            continue;
        };
        let attack: &[Volume] = if attacks { &[attack] } else { &[] };
        let [a, b] = &mut sim.hits;
        match (
            a.register(object, attack, &[vulnerable]),
            b.register(object, attack, &[vulnerable]),
        ) {
            (Ok(x), Ok(y)) if x == y => ids.push(x),
            other => {
                audit.violation(
                    Kind::Volumes,
                    step,
                    format!("registering {object:?}: {other:?}"),
                );
                return;
            }
        }
    }
    let [sap, grid] = &mut sim.hits;
    let events: Vec<HitEvent> = sap.detect(&mut TeamRule).to_vec();
    if events.as_slice() != grid.detect(&mut TeamRule) {
        audit.violation(Kind::Volumes, step, "the broadphases' events differ".into());
    }
    ids.sort_unstable();
    for e in &events {
        if !(0.0..=1.0).contains(&e.t)
            || !e.point.is_finite()
            || ids.binary_search(&e.attacker).is_err()
            || ids.binary_search(&e.victim).is_err()
        {
            audit.violation(Kind::Volumes, step, format!("{e:?}"));
        }
    }
}

/// Rays between random points (single, all hits, and as a batch) and circle casts from
/// bodies' places.
pub fn casts(sim: &mut Sim, audit: &mut Audit) {
    let step = sim.game.step;
    let (w, h) = (sim.map.width() as f32, sim.map.height() as f32);
    let mut batch = Vec::new();
    for k in 0..sim.game.settings.rays {
        let rng = &mut sim.game.rng;
        let a = Vec2::new(rng.range(0.0, w), rng.range(0.0, h));
        let b = a + Vec2::from_angle(rng.range(0.0, std::f32::consts::TAU)) * rng.range(0.1, 40.0);
        let ray = Ray::between(a, b);
        let filter = if k % 2 == 0 {
            QueryFilter::default()
        } else {
            QueryFilter::both_sides()
        };
        audit.count(Kind::Ray);
        let first = sim.map.cast_ray(ray, &filter);
        if let Some(hit) = &first {
            let on_ray = a.lerp(b, hit.t);
            if !(0.0..=1.0).contains(&hit.t)
                || !hit.point.is_finite()
                || (hit.normal.length() - 1.0).abs() > 1e-3
                || hit.point.distance(on_ray) > 1e-3
            {
                audit.violation(Kind::Ray, step, format!("{ray:?}: {hit:?}"));
            }
        }
        if sim.map.cast_ray_all(ray, &filter).first() != first.as_ref() {
            audit.violation(
                Kind::Ray,
                step,
                format!("{ray:?}: cast_ray_all's first hit differs"),
            );
        }
        if k % 2 == 0 {
            batch.push((ray, first));
        }
    }
    let rays: Vec<Ray> = batch.iter().map(|(r, _)| *r).collect();
    let hits = sim.map.cast_rays(&rays, &QueryFilter::default());
    for ((ray, single), hit) in batch.iter().zip(&hits) {
        if hit != single {
            audit.violation(Kind::Ray, step, format!("{ray:?}: the batch's hit differs"));
        }
    }
    // Circle casts from two bodies of one circle.
    for _ in 0..2 {
        let n = sim.game.placed.len() as u64;
        if n == 0 {
            break;
        }
        let b = &sim.game.placed[sim.game.rng.below(n) as usize];
        let [c] = b.circles.as_slice() else {
            continue;
        };
        let start = sim.position(b.handle) + c.center;
        let rng = &mut sim.game.rng;
        let delta = Vec2::from_angle(rng.range(0.0, std::f32::consts::TAU)) * rng.range(0.5, 20.0);
        audit.count(Kind::CircleCast);
        match sim
            .map
            .cast_circle(start, c.radius, delta, &QueryFilter::default())
        {
            Err(e) => audit.violation(Kind::CircleCast, step, format!("from {start}: {e}")),
            Ok(Some(hit)) => {
                let depth = penetration(&sim.map, &Circle::new(hit.center, c.radius));
                let before = penetration(&sim.map, &Circle::new(start, c.radius));
                if depth > SKIN.max(before) || !(0.0..=1.0).contains(&hit.t) {
                    audit.violation(
                        Kind::CircleCast,
                        step,
                        format!(
                            "from {start} by {delta} radius {}: stops {depth} into a wall: {hit:?}; {:?}",
                            c.radius,
                            sim.map.segments_overlapping_circle(&Circle::new(hit.center, c.radius))
                        ),
                    );
                }
            }
            Ok(None) => {}
        }
    }
}

/// A path for a random radius from a body to a random point, checked against what
/// `find_path` promises.
pub fn path(sim: &mut Sim, audit: &mut Audit) {
    let step = sim.game.step;
    let n = sim.game.placed.len() as u64;
    if n == 0 {
        return;
    }
    let k = sim.game.rng.below(n) as usize;
    let from = sim.position(sim.game.placed[k].handle);
    let (w, h) = (sim.map.width() as f32, sim.map.height() as f32);
    let rng = &mut sim.game.rng;
    let to = Vec2::new(rng.range(1.0, w - 1.0), rng.range(1.0, h - 1.0));
    let radius = rng.range(0.1, 0.45);
    audit.count(Kind::Path);
    let path = match sim.nav.find_path(&sim.map, from, to, radius) {
        Err(e) => {
            audit.violation(
                Kind::Path,
                step,
                format!("{from} to {to}, radius {radius}: {e}"),
            );
            return;
        }
        Ok(None) => return,
        Ok(Some(path)) => path,
    };
    let mask = SegmentFlags(NavConfig::default().mask.0 & !SegmentFlags::ONE_WAY.0);
    let filter = QueryFilter::both_sides().with_mask(mask);
    // `find_path`'s promise: the path runs from `from` to `to`, where the circle fits, and
    // every straight run is clear by the circle cast. (A corner the smoothing cut may lie
    // closer to a wall than the grid's margin, which `fits` asks of a place: clear, not
    // where a body is left.)
    let points = path.points();
    let ends = (points.first(), points.last());
    if ends != (Some(&from), Some(&to)) || points.iter().any(|p| !p.is_finite()) {
        audit.violation(
            Kind::Path,
            step,
            format!("{from} to {to}: the path {points:?}"),
        );
        return;
    }
    for p in [from, to] {
        if sim.nav.fits(&sim.map, p, radius).ok() != Some(true) {
            audit.violation(
                Kind::Path,
                step,
                format!("radius {radius}: an end {p} where it does not fit"),
            );
        }
    }
    for run in points.windows(2) {
        let (a, b) = (run[0], run[1]);
        if a != b && !matches!(sim.map.cast_circle(a, radius, b - a, &filter), Ok(None)) {
            audit.violation(
                Kind::Path,
                step,
                format!("radius {radius}: the run {a} to {b} is not clear"),
            );
        }
    }
}
