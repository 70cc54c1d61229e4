//! The API-surface targets: a map built from the input's first bytes, then a sequence of
//! calls decoded from the rest, with the library's promises checked after every call.
//!
//! - `bodies`: circles and compound bodies added, removed (stale handles too), proposed,
//!   teleported and stepped, with any float (NaN, infinities, 3e38 and ordinary values):
//!   bad values are refused with an error and change nothing; after every step every
//!   position is finite, no two bodies overlap and no body is in a wall by more than
//!   [`SKIN`], every centre is still in the room it started in (nothing passed through a
//!   wall), and the same calls on a second world give bit-identical positions.
//! - `character`: a circle or a box moved by any displacement, teleported, dropping
//!   through one-way platforms, under a moving platform: bad values are refused; the
//!   character is never inside a solid segment by more than [`SKIN`], never leaves its
//!   room, and two runs agree bit for bit.
//! - `casts`: rays and circle casts with any floats: `cast_ray` answers `None` or a finite
//!   hit with `t` in [0, 1] and a unit normal, `cast_ray_all`'s first hit is `cast_ray`'s,
//!   `cast_rays` equals the single casts bit for bit, and `cast_circle` refuses a bad
//!   radius and otherwise stops a circle short of the walls it was clear of.
//! - `volumes`: hit objects with circle and rectangle volumes of any floats registered
//!   frame after frame: bad values are refused and leave the world unchanged; the two
//!   broadphases give the same events, every event's `t` in [0, 1] and point finite, and
//!   each names objects registered this frame.
//! - `paths`: `find_path` between any points for any radius on maps with ramps (a path
//!   may cross a one-way platform from behind, where the circle does not fit): errors for
//!   bad values; a path found runs from one end to the other, both where the circle fits,
//!   and every straight run of it is clear by the circle cast.

use tileslide::broadphase::PairMethod;
use tileslide::io::ascii;
use tileslide::{
    Bodies, BodyDesc, BodyHandle, BodyShape, Cell, Character, CharacterShape, Circle,
    ControllerConfig, HitEvent, HitObject, HitTypes, HitWorld, MoveOptions, NavConfig, NavGrid,
    ObjectId, Owner, QueryFilter, Ray, Segment, SegmentFlags, TeamRule, TemporarySegment, TileMap,
    Vec2, Volume,
};

/// The most two bodies may overlap, or a body a wall, after a step (the resolver's promise,
/// in cells).
pub const SKIN: f32 = 1e-4;

/// Reads what a target needs from its input; past the end every read is 0.
pub struct Input<'a> {
    data: &'a [u8],
}

impl<'a> Input<'a> {
    pub fn new(data: &'a [u8]) -> Self {
        Self { data }
    }

    pub fn is_empty(&self) -> bool {
        self.data.is_empty()
    }

    pub fn byte(&mut self) -> u8 {
        match self.data.split_first() {
            Some((&b, rest)) => {
                self.data = rest;
                b
            }
            None => 0,
        }
    }

    /// True for one byte value in `n`.
    pub fn one_in(&mut self, n: u8) -> bool {
        self.byte().is_multiple_of(n)
    }

    /// A fraction in [0, 1].
    pub fn unit(&mut self) -> f32 {
        f32::from(self.byte()) / 255.0
    }

    /// Any f32 bit pattern.
    pub fn bits(&mut self) -> f32 {
        f32::from_le_bytes([self.byte(), self.byte(), self.byte(), self.byte()])
    }

    /// Mostly an ordinary value in [-span, span]; sometimes NaN, an infinity, a huge or
    /// tiny value, or any bit pattern.
    pub fn float(&mut self, span: f32) -> f32 {
        match self.byte() % 16 {
            0 => f32::NAN,
            1 => f32::INFINITY,
            2 => f32::NEG_INFINITY,
            3 => 3e38,
            4 => -1e20,
            5 => 1e-30,
            6 => self.bits(),
            _ => (self.unit() * 2.0 - 1.0) * span,
        }
    }
}

/// What a fuzzed map is made of besides empty and solid cells.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Tiles {
    /// Whole cells only.
    Whole,
    /// Ramps too.
    Ramps,
    /// Ramps and one-way platforms.
    Platforms,
}

/// A map of `tiles` walled in, from the input: its width and height (4 to 15 cells), then
/// one byte a cell. Returns the map and its rows.
pub fn grid(input: &mut Input<'_>, tiles: Tiles) -> (TileMap, Vec<Vec<char>>) {
    let w = 4 + usize::from(input.byte() % 12);
    let h = 4 + usize::from(input.byte() % 12);
    let mix: &[char] = match tiles {
        Tiles::Whole => &['.', '.', '.', '#'],
        Tiles::Ramps => &['.', '.', '.', '.', '#', '/', '\\'],
        Tiles::Platforms => &['.', '.', '.', '.', '#', '/', '\\', '='],
    };
    let rows: Vec<Vec<char>> = (0..h)
        .map(|r| {
            (0..w)
                .map(|c| {
                    let pick = mix[usize::from(input.byte()) % mix.len()];
                    if r == 0 || c == 0 || r == h - 1 || c == w - 1 {
                        '#'
                    } else {
                        pick
                    }
                })
                .collect()
        })
        .collect();
    let text: String = rows
        .iter()
        .map(|row| row.iter().collect::<String>() + "\n")
        .collect();
    let map = ascii::parse(&text, "fuzz.txt", 1.0).unwrap_or_else(|e| panic!("{e}"));
    (map, rows)
}

/// The 4-connected room of each cell that is not solid (`#`), `None` for a solid cell.
fn rooms(rows: &[Vec<char>]) -> Vec<Vec<Option<usize>>> {
    let (h, w) = (rows.len(), rows[0].len());
    let mut room = vec![vec![None; w]; h];
    let mut next = 0;
    for r in 0..h {
        for c in 0..w {
            if rows[r][c] == '#' || room[r][c].is_some() {
                continue;
            }
            let mut stack = vec![(r, c)];
            room[r][c] = Some(next);
            while let Some((r, c)) = stack.pop() {
                for (dr, dc) in [(0isize, 1isize), (0, -1), (1, 0), (-1, 0)] {
                    let (nr, nc) = (r as isize + dr, c as isize + dc);
                    if nr < 0 || nc < 0 || nr >= h as isize || nc >= w as isize {
                        continue;
                    }
                    let (nr, nc) = (nr as usize, nc as usize);
                    if rows[nr][nc] != '#' && room[nr][nc].is_none() {
                        room[nr][nc] = Some(next);
                        stack.push((nr, nc));
                    }
                }
            }
            next += 1;
        }
    }
    room
}

/// The room of the cell `p` is in (maps of unit cells from the origin).
fn room_of(rooms: &[Vec<Option<usize>>], p: Vec2) -> Option<usize> {
    let (c, r) = (p.x.floor(), p.y.floor());
    if c < 0.0 || r < 0.0 {
        return None;
    }
    *rooms.get(r as usize)?.get(c as usize)?
}

/// Every active segment of `map` facing `p` that blocks from the front (one-way platforms
/// left out): (segment, normal).
fn walls_facing(map: &TileMap, p: Vec2) -> Vec<(Segment, Vec2)> {
    let mut out = Vec::new();
    for r in 0..map.height() {
        for c in 0..map.width() {
            for s in map.active_segments(Cell::new(c, r)) {
                if !s.flags.contains(SegmentFlags::ONE_WAY)
                    && (p - s.segment.a).dot(s.normal) >= 0.0
                {
                    out.push((s.segment, s.normal));
                }
            }
        }
    }
    out
}

/// One body's circles, for the checks.
struct Placed {
    handle: BodyHandle,
    circles: Vec<Circle>,
    room: Option<usize>,
}

/// The `bodies` target: one run of the calls, returning every step's positions' bits.
fn bodies_run(data: &[u8]) -> Vec<u32> {
    let mut input = Input::new(data);
    let (map, rows) = grid(&mut input, tiles_or_whole(data, Tiles::Platforms));
    let rooms = rooms(&rows);
    let size = Vec2::new(map.width() as f32, map.height() as f32);
    let mut bodies = Bodies::new();
    let mut placed: Vec<Placed> = Vec::new();
    let mut removed: Vec<BodyHandle> = Vec::new();
    let mut trail = Vec::new();
    for step in 0..64 {
        if input.is_empty() {
            break;
        }
        match input.byte() % 8 {
            // Add a circle, or a pair, anywhere (a place in a wall is the game's business:
            // only its checks are asked of the library); bodies that start overlapping
            // anything are left out of the checks.
            0 | 1 => {
                let at = Vec2::new(input.float(size.x), input.float(size.y)).abs();
                let radius = input.float(0.6).abs();
                let circles = if input.one_in(2) {
                    vec![Circle::new(Vec2::ZERO, radius)]
                } else {
                    vec![
                        Circle::new(Vec2::ZERO, radius),
                        Circle::new(Vec2::new(input.float(0.5), input.float(0.5)), radius),
                    ]
                };
                let shape = BodyShape::compound(circles.iter().copied());
                let good = at.is_finite()
                    && circles
                        .iter()
                        .all(|c| c.center.is_finite() && c.radius.is_finite());
                match shape {
                    Ok(shape) => {
                        let added = bodies.add(BodyDesc::new(at, shape));
                        match added {
                            Ok(handle) => {
                                assert!(good, "a body at {at} of {circles:?} was accepted");
                                if clear(&map, &bodies, &placed, at, &circles) {
                                    let room = room_of(&rooms, at);
                                    placed.push(Placed {
                                        handle,
                                        circles,
                                        room,
                                    });
                                } else {
                                    bodies.remove(handle).unwrap_or_else(|e| panic!("{e}"));
                                    removed.push(handle);
                                }
                            }
                            Err(e) => assert!(!e.to_string().is_empty()),
                        }
                    }
                    Err(e) => assert!(!e.to_string().is_empty()),
                }
            }
            2 if !placed.is_empty() => {
                let k = usize::from(input.byte()) % placed.len();
                let gone = placed.remove(k);
                assert!(bodies.remove(gone.handle).is_ok());
                removed.push(gone.handle);
            }
            // A stale handle is refused and changes nothing.
            3 if !removed.is_empty() => {
                let handle = removed[usize::from(input.byte()) % removed.len()];
                assert!(bodies.remove(handle).is_err(), "a stale handle was removed");
                assert!(bodies.propose(handle, Vec2::X).is_err());
                assert!(bodies.set_position(handle, Vec2::ONE).is_err());
            }
            4 if !placed.is_empty() => {
                let k = usize::from(input.byte()) % placed.len();
                let to = Vec2::new(input.float(size.x), input.float(size.y));
                let handle = placed[k].handle;
                let before = position(&bodies, handle);
                if bodies.set_position(handle, to).is_ok() {
                    assert!(to.is_finite(), "teleport to {to} accepted");
                    // A teleport's place is the game's: the body leaves the checks unless it
                    // lands clear.
                    let body = placed.remove(k);
                    if clear(&map, &bodies, &placed, to, &body.circles) {
                        placed.push(Placed {
                            room: room_of(&rooms, to),
                            ..body
                        });
                    } else {
                        bodies.remove(handle).unwrap_or_else(|e| panic!("{e}"));
                        removed.push(handle);
                    }
                } else {
                    assert_eq!(
                        position(&bodies, handle),
                        before,
                        "a refused teleport moved"
                    );
                }
            }
            _ => {
                for body in &placed {
                    let motion = Vec2::new(input.float(3.0), input.float(3.0));
                    let proposed = bodies.propose(body.handle, motion);
                    if motion.is_finite() && motion.abs().max_element() <= 3.0 {
                        assert!(proposed.is_ok(), "{motion} refused: {proposed:?}");
                    } else if proposed.is_err() {
                        // Refused: a zero move stands in, so the step still runs.
                        let _ = bodies.propose(body.handle, Vec2::ZERO);
                    }
                }
                bodies.step(&map);
                check_bodies(&map, &bodies, &placed, &rooms, step);
                for body in &placed {
                    let p = position(&bodies, body.handle);
                    trail.extend([p.x.to_bits(), p.y.to_bits()]);
                }
            }
        }
    }
    trail
}

/// `tiles` when the input's first byte has its top bit set, whole cells otherwise.
fn tiles_or_whole(data: &[u8], tiles: Tiles) -> Tiles {
    if data.first().is_some_and(|b| b & 0x80 != 0) {
        tiles
    } else {
        Tiles::Whole
    }
}

fn position(bodies: &Bodies, handle: BodyHandle) -> Vec2 {
    bodies
        .get(handle)
        .unwrap_or_else(|e| panic!("{e}"))
        .position()
}

/// Whether circles at `at` are clear of the walls and of the checked bodies, by a margin.
fn clear(map: &TileMap, bodies: &Bodies, placed: &[Placed], at: Vec2, circles: &[Circle]) -> bool {
    circles.iter().all(|c| {
        let p = at + c.center;
        p.is_finite()
            && c.radius > 0.0
            && !map.is_point_solid(p)
            && walls_facing(map, p)
                .iter()
                .all(|(s, _)| s.distance_squared_to(p).sqrt() > c.radius + 0.01)
            && placed.iter().all(|other| {
                let q = position(bodies, other.handle);
                other
                    .circles
                    .iter()
                    .all(|d| (q + d.center).distance(p) > c.radius + d.radius + 0.01)
            })
    })
}

fn check_bodies(
    map: &TileMap,
    bodies: &Bodies,
    placed: &[Placed],
    rooms: &[Vec<Option<usize>>],
    step: usize,
) {
    let circles: Vec<(usize, Vec2, f32)> = placed
        .iter()
        .enumerate()
        .flat_map(|(i, b)| {
            let at = position(bodies, b.handle);
            b.circles.iter().map(move |c| (i, at + c.center, c.radius))
        })
        .collect();
    for (i, body) in placed.iter().enumerate() {
        let at = position(bodies, body.handle);
        assert!(at.is_finite(), "step {step}: body {i} at {at}");
        if body.room.is_some() {
            assert_eq!(
                room_of(rooms, at),
                body.room,
                "step {step}: body {i} left its room for {at}"
            );
        }
    }
    for (k, &(i, c, r)) in circles.iter().enumerate() {
        assert!(
            !map.is_point_solid(c),
            "step {step}: body {i}'s centre {c} is in a solid"
        );
        for (s, _) in walls_facing(map, c) {
            let d = s.distance_squared_to(c).sqrt();
            assert!(
                d >= r - SKIN,
                "step {step}: body {i} at {c} is {} into {s:?}",
                r - d
            );
        }
        for &(j, c2, r2) in &circles[k + 1..] {
            if i != j {
                let d = c.distance(c2);
                assert!(
                    d >= r + r2 - SKIN,
                    "step {step}: bodies {i} and {j} overlap by {}",
                    r + r2 - d
                );
            }
        }
    }
}

/// The `bodies` target: the calls' checks, and a second run giving the same positions.
pub fn bodies(data: &[u8]) {
    let first = bodies_run(data);
    assert!(
        first == bodies_run(data),
        "two runs of the same calls differ"
    );
}

/// The `character` target: one run, returning every move's end position's bits.
fn character_run(data: &[u8]) -> Vec<u32> {
    let mut input = Input::new(data);
    let (mut map, rows) = grid(&mut input, Tiles::Platforms);
    let rooms = rooms(&rows);
    let size = Vec2::new(map.width() as f32, map.height() as f32);
    let shape = if input.one_in(2) {
        CharacterShape::circle(0.1 + 0.35 * input.unit())
    } else {
        CharacterShape::rect(Vec2::new(
            0.1 + 0.3 * input.unit(),
            0.1 + 0.4 * input.unit(),
        ))
    };
    let Ok(shape) = shape else {
        panic!("a sound shape was refused")
    };
    let start = Vec2::new(input.unit(), input.unit()) * size;
    let Ok(mut ch) = Character::new(shape, start, Vec2::NEG_Y, ControllerConfig::default()) else {
        return Vec::new();
    };
    let reach = shape.bounds(Vec2::ZERO).max;
    // Checked only from where it stands clear of every wall, in a room.
    let mut room = placed_clear(&map, start, reach)
        .then(|| room_of(&rooms, start))
        .flatten();
    let mut trail = Vec::new();
    let mut platform = Vec2::new(input.unit(), input.unit()) * size;
    for step in 0..96 {
        if input.is_empty() {
            break;
        }
        match input.byte() % 8 {
            0 => {
                let to = Vec2::new(input.float(size.x), input.float(size.y));
                let before = ch.position;
                match ch.teleport(to) {
                    Ok(()) => {
                        assert!(to.is_finite());
                        room = placed_clear(&map, to, reach)
                            .then(|| room_of(&rooms, to))
                            .flatten();
                    }
                    Err(_) => assert_eq!(ch.position, before, "a refused teleport moved"),
                }
            }
            // A platform moving under or into the character: re-submitted each time.
            1 => {
                let motion = Vec2::new(input.float(0.5), input.float(0.5));
                if motion.is_finite() {
                    platform = (platform + motion).clamp(Vec2::ZERO, size);
                }
                map.clear_temporaries();
                let added = map.add_temporary(TemporarySegment {
                    segment: Segment::new(platform, platform + Vec2::new(1.5, 0.0)),
                    normal: Vec2::NEG_Y,
                    flags: if input.one_in(2) {
                        SegmentFlags::ONE_WAY
                    } else {
                        SegmentFlags::SOLID
                    },
                    owner: Owner(1),
                    velocity: if motion.is_finite() {
                        motion
                    } else {
                        Vec2::ZERO
                    },
                });
                added.unwrap_or_else(|e| panic!("{e}"));
                // A solid platform may push the character anywhere (crushing is allowed):
                // the room check stops here.
                room = None;
            }
            _ => {
                let d = Vec2::new(input.float(2.0), input.float(2.0));
                let options = MoveOptions {
                    drop_through: input.one_in(4),
                };
                let before = ch.position;
                match ch.move_by(&map, d, options) {
                    Ok(_) => {
                        assert!(d.is_finite(), "a move of {d} was accepted");
                        assert!(ch.position.is_finite(), "step {step}: at {}", ch.position);
                        if map.temporaries().is_empty() && room.is_some() {
                            check_character(&map, &ch, reach, step);
                            assert_eq!(
                                room_of(&rooms, ch.position),
                                room,
                                "step {step}: left its room for {}",
                                ch.position
                            );
                        }
                    }
                    Err(_) => assert_eq!(ch.position, before, "a refused move moved"),
                }
                trail.extend([ch.position.x.to_bits(), ch.position.y.to_bits()]);
            }
        }
    }
    trail
}

/// Whether a shape reaching `reach` from its centre at `p` is clear of every wall.
fn placed_clear(map: &TileMap, p: Vec2, reach: Vec2) -> bool {
    p.is_finite()
        && !map.is_point_solid(p)
        && walls_facing(map, p)
            .iter()
            .all(|(s, _)| s.distance_squared_to(p).sqrt() > reach.length() + 0.01)
}

/// The character is not in a solid segment by more than [`SKIN`]: for a circle, no facing
/// segment is nearer its centre than its radius; for a box, none crosses the box shrunk by
/// the skin.
fn check_character(map: &TileMap, ch: &Character, reach: Vec2, step: usize) {
    let p = ch.position;
    assert!(!map.is_point_solid(p), "step {step}: centre {p} in a solid");
    for (s, _) in walls_facing(map, p) {
        match ch.shape() {
            CharacterShape::Circle { radius } => {
                let d = s.distance_squared_to(p).sqrt();
                assert!(
                    d >= radius - SKIN,
                    "step {step}: {} into {s:?} at {p}",
                    radius - d
                );
            }
            _ => {
                let inner = tileslide::Aabb::from_center(p, reach - Vec2::splat(SKIN));
                assert!(
                    !inner.overlaps_segment(&s),
                    "step {step}: the box at {p} crosses {s:?}"
                );
            }
        }
    }
}

/// The `character` target: the calls' checks, and a second run giving the same positions.
pub fn character(data: &[u8]) {
    let first = character_run(data);
    assert!(
        first == character_run(data),
        "two runs of the same calls differ"
    );
}

/// The `casts` target.
pub fn casts(data: &[u8]) {
    let mut input = Input::new(data);
    let (map, _) = grid(&mut input, tiles_or_whole(data, Tiles::Platforms));
    let size = Vec2::new(map.width() as f32, map.height() as f32);
    let mut rays = Vec::new();
    while !input.is_empty() && rays.len() < 64 {
        let a = Vec2::new(input.float(size.x * 1.5), input.float(size.y * 1.5));
        let b = Vec2::new(input.float(size.x * 1.5), input.float(size.y * 1.5));
        let ray = Ray::between(a, b);
        let filter = if input.one_in(2) {
            QueryFilter::default()
        } else {
            QueryFilter::both_sides()
        };
        let first = map.cast_ray(ray, &filter);
        if let Some(hit) = &first {
            assert!((0.0..=1.0).contains(&hit.t), "t = {} for {ray:?}", hit.t);
            assert!(hit.point.is_finite() && hit.normal.is_finite(), "{hit:?}");
            assert!((hit.normal.length() - 1.0).abs() < 1e-3, "{hit:?}");
        }
        assert_eq!(
            map.cast_ray_all(ray, &filter).first(),
            first.as_ref(),
            "{ray:?}"
        );
        // The circle cast: refused for a bad radius; a circle clear of every wall at its
        // start stops where it touches one, not past it.
        let radius = input.float(0.5);
        match map.cast_circle(a, radius, b - a, &filter) {
            Err(_) => assert!(
                !(radius > 0.0 && radius.is_finite()),
                "a circle of radius {radius} refused"
            ),
            Ok(_) if !(radius > 0.0 && radius.is_finite()) => {
                panic!("a circle of radius {radius} cast")
            }
            Ok(Some(hit)) => {
                assert!((0.0..=1.0).contains(&hit.t), "circle t = {}", hit.t);
                assert!(hit.normal.is_finite(), "{hit:?}");
            }
            Ok(None) => {}
        }
        if input.one_in(2) {
            rays.push(ray);
        }
    }
    let filter = QueryFilter::default();
    let batch = map.cast_rays(&rays, &filter);
    for (ray, hit) in rays.iter().zip(&batch) {
        assert_eq!(
            *hit,
            map.cast_ray(*ray, &filter),
            "the batch differs for {ray:?}"
        );
    }
}

/// The `paths` target.
pub fn paths(data: &[u8]) {
    let mut input = Input::new(data);
    let (map, _) = grid(&mut input, tiles_or_whole(data, Tiles::Ramps));
    let size = Vec2::new(map.width() as f32, map.height() as f32);
    let config = NavConfig {
        max_radius: [0.5, 1.0, 0.0, -1.0, f32::NAN, 40.0][usize::from(input.byte() % 6)],
        ..NavConfig::default()
    };
    let Ok(grid) = NavGrid::new(&map, config) else {
        assert!(
            !(config.max_radius > 0.0 && config.max_radius <= 31.0),
            "{config:?} refused"
        );
        return;
    };
    for _ in 0..16 {
        if input.is_empty() {
            break;
        }
        let from = Vec2::new(input.float(size.x), input.float(size.y)).abs();
        let to = Vec2::new(input.float(size.x), input.float(size.y)).abs();
        let radius = input.float(1.0);
        match grid.find_path(&map, from, to, radius) {
            Err(_) => {}
            Ok(None) => {}
            // What `find_path` promises: from `from` to `to`, both where the circle fits,
            // every straight run clear by the circle cast (a corner the smoothing cut may be
            // nearer a wall than the grid's margin, which `fits` asks of a place).
            Ok(Some(path)) => {
                assert!(from.is_finite() && to.is_finite() && radius.is_finite());
                let points = path.points();
                assert_eq!(
                    (points.first(), points.last()),
                    (Some(&from), Some(&to)),
                    "{points:?}"
                );
                for p in [from, to] {
                    assert_eq!(
                        grid.fits(&map, p, radius).ok(),
                        Some(true),
                        "an end {p} where a circle of {radius} does not fit"
                    );
                }
                let filter = QueryFilter::both_sides().with_mask(SegmentFlags(
                    NavConfig::default().mask.0 & !SegmentFlags::ONE_WAY.0,
                ));
                for run in points.windows(2) {
                    let (a, b) = (run[0], run[1]);
                    assert!(a.is_finite() && b.is_finite(), "{points:?}");
                    if a != b {
                        let cast = map.cast_circle(a, radius, b - a, &filter);
                        assert!(
                            matches!(cast, Ok(None)),
                            "the run {a} to {b} of a circle of {radius} is not clear: {cast:?}"
                        );
                    }
                }
            }
        }
    }
}

/// The `volumes` target.
pub fn volumes(data: &[u8]) {
    let mut input = Input::new(data);
    let mut worlds = [
        HitWorld::with_broadphase(PairMethod::SweepAndPrune),
        HitWorld::with_broadphase(PairMethod::UniformGrid),
    ];
    for frame in 0..16 {
        if input.is_empty() {
            break;
        }
        for world in &mut worlds {
            world.begin_frame();
        }
        let mut ids: Vec<ObjectId> = Vec::new();
        for k in 0..usize::from(input.byte() % 24) {
            let mut object = HitObject::new(
                Owner(k as u64 + 1),
                Vec2::new(input.float(20.0), input.float(20.0)),
                Vec2::new(input.float(2.0), input.float(2.0)).abs(),
            );
            object.motion = Vec2::new(input.float(4.0), input.float(4.0));
            object.team = u32::from(input.byte() % 3);
            object.invulnerable = input.one_in(8);
            object.swing = (input.one_in(4)).then_some(u64::from(input.byte() % 4));
            let mut volumes = [Vec::new(), Vec::new()];
            for list in &mut volumes {
                for _ in 0..input.byte() % 3 {
                    let center = Vec2::new(input.float(1.0), input.float(1.0));
                    let hit = HitTypes::from_bits(u32::from(input.byte() % 8));
                    let volume = if input.one_in(2) {
                        Volume::circle(center, input.float(1.0), hit)
                    } else {
                        Volume::rect(center, Vec2::new(input.float(1.0), input.float(1.0)), hit)
                    };
                    if let Ok(volume) = volume {
                        list.push(volume);
                    }
                }
            }
            let [attack, vulnerable] = &volumes;
            let results = worlds
                .each_mut()
                .map(|world| world.register(object, attack, vulnerable));
            match results {
                [Ok(a), Ok(b)] => {
                    assert_eq!(a, b, "the two worlds gave different ids");
                    ids.push(a);
                }
                [Err(_), Err(_)] => {}
                other => panic!("frame {frame}: the worlds disagree on registering: {other:?}"),
            }
        }
        let [sap, grid] = &mut worlds;
        let events: Vec<HitEvent> = sap.detect(&mut TeamRule).to_vec();
        assert_eq!(
            events.as_slice(),
            grid.detect(&mut TeamRule),
            "frame {frame}: the broadphases' events differ"
        );
        for e in &events {
            assert!((0.0..=1.0).contains(&e.t), "frame {frame}: {e:?}");
            assert!(e.point.is_finite(), "frame {frame}: {e:?}");
            assert!(
                ids.contains(&e.attacker) && ids.contains(&e.victim),
                "frame {frame}: an event names an object not registered: {e:?}"
            );
        }
    }
}
