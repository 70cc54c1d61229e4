//! The soak's world: a cave dug and built as the run goes on, bodies wandering, dashing and
//! following a flow field, platformer characters running and jumping over moving platforms,
//! every body's and character's hit volumes, and the queries a game asks each frame. Every
//! random choice comes from one seeded generator, so a run is a function of its settings.

use glam::Vec2;
use tileslide::io::ascii;
use tileslide::{
    Bodies, BodyDesc, BodyHandle, BodyShape, Cell, Character, CharacterShape, Circle,
    ControllerConfig, FlowField, HitWorld, MoveOptions, NavConfig, NavGrid, Owner, SegmentFlags,
    TemporarySegment, TileId, TileMap, broadphase::PairMethod,
};
use tileslide_scenes::SplitMix64;

use super::audit::{Audit, Kind};
use super::checks;

/// The frame time of the characters' moves (the bodies move by their proposals per step).
pub const DT: f32 = 1.0 / 60.0;

/// What a soak runs: its size and how often each event happens.
#[derive(Clone, Copy, Debug)]
pub struct Settings {
    /// The seed of every random choice.
    pub seed: u64,
    /// Bodies alive at any time (some are removed and added as the run goes on).
    pub bodies: u32,
    /// Platformer characters.
    pub characters: u32,
    /// Moving one-way platforms.
    pub platforms: u32,
    /// Rays cast a step (each also as part of one batch).
    pub rays: u32,
    /// Steps between map edits (a cell dug out or built).
    pub dig_every: u64,
    /// Steps between path searches.
    pub path_every: u64,
    /// Steps between snapshots restored into a second world.
    pub snapshot_every: u64,
    /// Steps the restored world runs beside the original.
    pub twin_steps: u64,
}

impl Settings {
    /// The map's size in cells: about 4,000 open cells plus six a body, three wide for two
    /// high.
    pub fn map_size(&self) -> (u32, u32) {
        let cells = 6_000.0 + 6.0 * f64::from(self.bodies) + 40.0 * f64::from(self.characters);
        let height = (cells / 1.5).sqrt().ceil() as u32;
        (height * 3 / 2, height)
    }
}

/// The largest radius of a body's circle, and the flow field's radius.
pub const MAX_BODY_RADIUS: f32 = 0.45;
/// The navigation grid's settings: circles up to half a cell wide.
pub fn nav_config() -> NavConfig {
    NavConfig {
        max_radius: 0.5,
        ..NavConfig::default()
    }
}
/// Bodies that follow the flow field refresh their direction this many at a time, round robin
/// (a direction costs tens of microseconds).
const FLOW_REFRESH: usize = 16;
/// Steps between moves of the flow field's goal.
const GOAL_EVERY: u64 = 600;
/// A moving platform's length, in cells.
const PLATFORM_LENGTH: f32 = 2.0;

/// A body as the game knows it.
#[derive(Clone, Debug)]
pub struct Placed {
    pub handle: BodyHandle,
    pub circles: Vec<Circle>,
    /// Its move per step.
    pub velocity: Vec2,
    /// Whether it follows the flow field.
    pub follows: bool,
    /// Where it was after the last step (or where it was put), for the room check.
    pub last: Vec2,
    pub owner: Owner,
}

/// A platformer character and what drives it.
#[derive(Clone, Debug)]
pub struct Runner {
    pub character: Character,
    pub velocity: Vec2,
    /// -1, 0 or 1: which way it runs.
    run: f32,
    /// Steps left holding "drop through".
    drop: u32,
    pub last: Vec2,
    pub owner: Owner,
}

/// A one-way platform moving back and forth along a track.
#[derive(Clone, Debug)]
pub struct Platform {
    /// The track's two ends (the platform's left end).
    from: Vec2,
    to: Vec2,
    /// Where along the track, 0 to 1, and which way it goes.
    at: f32,
    speed: f32,
    owner: Owner,
    /// The cells kept free for it and its riders.
    pub reserved: (Vec2, Vec2),
}

impl Platform {
    fn left(&self) -> Vec2 {
        self.from.lerp(self.to, self.at)
    }
}

/// The game's own state: everything besides the library's objects, cloned as a game saves
/// it beside a snapshot.
#[derive(Clone, Debug)]
pub struct Game {
    pub rng: SplitMix64,
    pub step: u64,
    pub placed: Vec<Placed>,
    pub removed: Vec<BodyHandle>,
    pub runners: Vec<Runner>,
    pub platforms: Vec<Platform>,
    /// The 4-connected room of every cell not solid (`None` for a solid square).
    pub rooms: Vec<Option<u32>>,
    pub goal: Vec2,
    /// The next follower whose direction is refreshed.
    next_follower: usize,
    next_owner: u64,
    pub settings: Settings,
}

/// The library's objects.
pub struct Sim {
    /// The map as built, for restoring snapshots.
    pub base: TileMap,
    pub map: TileMap,
    pub nav: NavGrid,
    pub flow: FlowField,
    pub bodies: Bodies,
    /// The same hit objects in a world of each broadphase.
    pub hits: [HitWorld; 2],
    pub game: Game,
}

/// A cave of `w` × `h` cells walled in: blocks, ledges with ramps at both ends, and one-way
/// platforms, at random.
fn cave(rng: &mut SplitMix64, w: usize, h: usize) -> Vec<Vec<char>> {
    let mut rows = vec![vec!['.'; w]; h];
    for (r, row) in rows.iter_mut().enumerate() {
        for (c, cell) in row.iter_mut().enumerate() {
            if r == 0 || c == 0 || r == h - 1 || c == w - 1 {
                *cell = '#';
            }
        }
    }
    let area = w * h;
    let put = |rows: &mut Vec<Vec<char>>, r: usize, c: usize, ch: char| {
        if r > 0 && c > 0 && r < h - 1 && c < w - 1 {
            rows[r][c] = ch;
        }
    };
    // Blocks.
    for _ in 0..area / 90 {
        let (bw, bh) = (1 + rng.below(4) as usize, 1 + rng.below(5) as usize);
        let (c, r) = (rng.below(w as u64) as usize, rng.below(h as u64) as usize);
        for dr in 0..bh {
            for dc in 0..bw {
                put(&mut rows, r + dr, c + dc, '#');
            }
        }
    }
    // Ledges with a ramp up at each end.
    for _ in 0..area / 150 {
        let len = 3 + rng.below(10) as usize;
        let (c, r) = (
            1 + rng.below(w as u64) as usize,
            rng.below(h as u64) as usize,
        );
        put(&mut rows, r, c - 1, '/');
        for k in 0..len {
            put(&mut rows, r, c + k, '#');
        }
        put(&mut rows, r, c + len, '\\');
    }
    // One-way platforms.
    for _ in 0..area / 200 {
        let len = 2 + rng.below(6) as usize;
        let (c, r) = (rng.below(w as u64) as usize, rng.below(h as u64) as usize);
        for k in 0..len {
            if rows.get(r).and_then(|row| row.get(c + k)) == Some(&'.') {
                put(&mut rows, r, c + k, '=');
            }
        }
    }
    rows
}

/// The 4-connected rooms of `map`'s cells that are not solid squares.
pub fn rooms(map: &TileMap) -> Vec<Option<u32>> {
    let (w, h) = (map.width() as usize, map.height() as usize);
    let open = |c: usize, r: usize| map.tile(Cell::new(c as u32, r as u32)) != Some(ascii::SOLID);
    let mut room = vec![None; w * h];
    let mut next = 0;
    let mut stack = Vec::new();
    for start in 0..w * h {
        if room[start].is_some() || !open(start % w, start / w) {
            continue;
        }
        room[start] = Some(next);
        stack.push(start);
        while let Some(i) = stack.pop() {
            let (c, r) = (i % w, i / w);
            let mut visit = |j: usize| {
                if room[j].is_none() && open(j % w, j / w) {
                    room[j] = Some(next);
                    stack.push(j);
                }
            };
            if c > 0 {
                visit(i - 1);
            }
            if c + 1 < w {
                visit(i + 1);
            }
            if r > 0 {
                visit(i - w);
            }
            if r + 1 < h {
                visit(i + w);
            }
        }
        next += 1;
    }
    room
}

/// The room of the cell `p` is in (unit cells from the origin); `None` in a solid square or
/// off the map.
pub fn room_of(map: &TileMap, rooms: &[Option<u32>], p: Vec2) -> Option<u32> {
    if !(p.x >= 0.0 && p.y >= 0.0 && p.x < map.width() as f32 && p.y < map.height() as f32) {
        return None;
    }
    rooms[p.y as usize * map.width() as usize + p.x as usize]
}

impl Sim {
    /// A new world for `settings`.
    pub fn new(settings: Settings) -> anyhow::Result<Self> {
        let mut rng = SplitMix64::new(settings.seed);
        let (w, h) = settings.map_size();
        let rows = cave(&mut rng, w as usize, h as usize);
        let text: String = rows
            .iter()
            .map(|row| row.iter().collect::<String>() + "\n")
            .collect();
        let map = ascii::parse(&text, "soak.txt", 1.0)?;
        let nav = NavGrid::new(&map, nav_config())?;
        let rooms = rooms(&map);
        let goal = Vec2::new(w as f32 / 2.0, h as f32 / 2.0);
        let flow = FlowField::new(&nav, &map, goal, MAX_BODY_RADIUS)?;
        let game = Game {
            rng,
            step: 0,
            placed: Vec::new(),
            removed: Vec::new(),
            runners: Vec::new(),
            platforms: Vec::new(),
            rooms,
            goal,
            next_follower: 0,
            next_owner: 1,
            settings,
        };
        let mut sim = Self {
            base: map.clone(),
            map,
            nav,
            flow,
            bodies: Bodies::new(),
            hits: [
                HitWorld::with_broadphase(PairMethod::SweepAndPrune),
                HitWorld::with_broadphase(PairMethod::UniformGrid),
            ],
            game,
        };
        for _ in 0..settings.platforms {
            sim.add_platform();
        }
        sim.submit_platforms()?;
        for _ in 0..settings.characters {
            sim.add_runner()?;
        }
        for _ in 0..settings.bodies {
            sim.add_body()?;
        }
        Ok(sim)
    }

    fn owner(&mut self) -> Owner {
        self.game.next_owner += 1;
        Owner(self.game.next_owner)
    }

    fn random_point(&mut self) -> Vec2 {
        let (w, h) = (self.map.width() as f32, self.map.height() as f32);
        Vec2::new(
            self.game.rng.range(1.0, w - 1.0),
            self.game.rng.range(1.0, h - 1.0),
        )
    }

    /// Whether circles at `at` are clear of walls, platforms' reserved space and the bodies
    /// the game knows, by `margin`.
    pub fn clear_for(&self, at: Vec2, circles: &[Circle], margin: f32) -> bool {
        circles.iter().all(|c| {
            let p = at + c.center;
            let grown = Circle::new(p, c.radius + margin);
            checks::penetration(&self.map, &grown) == 0.0
                && !self
                    .map
                    .segments_overlapping_circle(&grown)
                    .iter()
                    .any(|s| s.flags.contains(SegmentFlags::ONE_WAY))
                && self.game.placed.iter().all(|other| {
                    let q = self.position(other.handle);
                    other
                        .circles
                        .iter()
                        .all(|d| (q + d.center).distance(p) > c.radius + d.radius + margin)
                })
        })
    }

    /// A body's position (every handle the game holds is live).
    pub fn position(&self, handle: BodyHandle) -> Vec2 {
        self.bodies
            .get(handle)
            .map(|b| b.position())
            .unwrap_or(Vec2::NAN)
    }

    /// Adds a body of random shape at a random clear place (none after 200 tries).
    fn add_body(&mut self) -> anyhow::Result<()> {
        let rng = &mut self.game.rng;
        let circles = if rng.below(7) == 0 {
            let r = rng.range(0.18, 0.3);
            let d = rng.range(0.15, 0.3);
            vec![
                Circle::new(Vec2::new(-d, 0.0), r),
                Circle::new(Vec2::new(d, 0.0), r),
            ]
        } else {
            vec![Circle::new(Vec2::ZERO, rng.range(0.12, MAX_BODY_RADIUS))]
        };
        let follows = rng.below(3) == 0;
        for _ in 0..200 {
            let at = self.random_point();
            if !self.clear_for(at, &circles, 0.02) {
                continue;
            }
            let owner = self.owner();
            let shape = BodyShape::compound(circles.iter().copied())?;
            let handle = self
                .bodies
                .add(BodyDesc::new(at, shape).with_owner(owner))?;
            self.game.placed.push(Placed {
                handle,
                circles,
                velocity: Vec2::ZERO,
                follows,
                last: at,
                owner,
            });
            return Ok(());
        }
        Ok(())
    }

    fn add_runner(&mut self) -> anyhow::Result<()> {
        let rng = &mut self.game.rng;
        let shape = if rng.below(2) == 0 {
            CharacterShape::circle(rng.range(0.25, 0.45))?
        } else {
            CharacterShape::rect(Vec2::new(rng.range(0.2, 0.4), rng.range(0.3, 0.7)))?
        };
        let reach = shape.bounds(Vec2::ZERO).max.length();
        for _ in 0..200 {
            let at = self.random_point();
            if !self.clear_for(at, &[Circle::new(Vec2::ZERO, reach)], 0.05) {
                continue;
            }
            let character = Character::new(shape, at, Vec2::NEG_Y, ControllerConfig::default())?;
            let owner = self.owner();
            let run = self.game.rng.below(3) as f32 - 1.0;
            self.game.runners.push(Runner {
                character,
                velocity: Vec2::ZERO,
                run,
                drop: 0,
                last: at,
                owner,
            });
            return Ok(());
        }
        Ok(())
    }

    /// A platform on a horizontal or vertical track through open cells with room above it.
    fn add_platform(&mut self) {
        for _ in 0..200 {
            let start = self.random_point().floor();
            let vertical = self.game.rng.below(3) == 0;
            let run = 2.0 + self.game.rng.below(6) as f32;
            let (from, to) = if vertical {
                (start, start + Vec2::new(0.0, run))
            } else {
                (start, start + Vec2::new(run, 0.0))
            };
            // The cells the platform and a rider standing on it sweep, and one more all round.
            let lo = from - Vec2::new(1.0, 3.0);
            let hi = to + Vec2::new(PLATFORM_LENGTH + 1.0, 1.0);
            if !self.cells_open(lo, hi) {
                continue;
            }
            let owner = self.owner();
            let speed = self.game.rng.range(0.5, 4.0) * DT / run;
            self.game.platforms.push(Platform {
                from,
                to,
                at: 0.0,
                speed,
                owner,
                reserved: (lo, hi),
            });
            return;
        }
    }

    /// Whether every cell that meets the box `lo`..`hi` is on the map and empty.
    fn cells_open(&self, lo: Vec2, hi: Vec2) -> bool {
        let (w, h) = (self.map.width() as f32, self.map.height() as f32);
        if !(lo.x >= 0.0 && lo.y >= 0.0 && hi.x < w && hi.y < h) {
            return false;
        }
        (lo.y as u32..=hi.y as u32)
            .all(|r| (lo.x as u32..=hi.x as u32).all(|c| self.map.tile(Cell::new(c, r)).is_none()))
    }

    /// The platforms' segments, submitted anew.
    fn submit_platforms(&mut self) -> anyhow::Result<()> {
        self.map.clear_temporaries();
        for p in &self.game.platforms {
            let a = p.left();
            self.map.add_temporary(TemporarySegment {
                segment: tileslide::Segment::new(a, a + Vec2::new(PLATFORM_LENGTH, 0.0)),
                normal: Vec2::NEG_Y,
                flags: SegmentFlags::ONE_WAY,
                owner: p.owner,
                velocity: (p.to - p.from) * p.speed,
            })?;
        }
        Ok(())
    }

    /// One step of the whole world, checked: map edits, platforms, bodies, characters, hit
    /// volumes, queries and paths, then the audit of where everything ended.
    pub fn step(&mut self, audit: &mut Audit) -> anyhow::Result<()> {
        self.game.step += 1;
        let step = self.game.step;
        let settings = self.game.settings;
        if step.is_multiple_of(settings.dig_every) {
            self.edit_map(audit)?;
        }
        if step.is_multiple_of(GOAL_EVERY) {
            self.game.goal = self.random_point();
            self.flow = FlowField::new(&self.nav, &self.map, self.game.goal, MAX_BODY_RADIUS)?;
        }
        for p in &mut self.game.platforms {
            p.at += p.speed;
            if !(0.0..=1.0).contains(&p.at) {
                p.speed = -p.speed;
                p.at = p.at.clamp(0.0, 1.0);
            }
        }
        self.submit_platforms()?;
        self.churn_bodies(audit)?;
        checks::bad_values(self, audit);
        self.move_bodies(audit);
        self.move_runners(audit);
        checks::volumes(self, audit);
        checks::casts(self, audit);
        if step.is_multiple_of(settings.path_every) {
            checks::path(self, audit);
        }
        checks::bodies(self, audit);
        checks::runners(self, audit);
        Ok(())
    }

    /// Digs out a cell that is not the border, or builds a tile in an empty one that no
    /// body, character or platform's space is near; then brings the navigation grid, the
    /// flow field and the rooms up to date.
    fn edit_map(&mut self, audit: &mut Audit) -> anyhow::Result<()> {
        let (w, h) = (self.map.width(), self.map.height());
        let cell = Cell::new(
            1 + self.game.rng.below(u64::from(w - 2)) as u32,
            1 + self.game.rng.below(u64::from(h - 2)) as u32,
        );
        let tile: Option<TileId> = if self.map.tile(cell).is_some() {
            None
        } else {
            let pick = [
                ascii::SOLID,
                ascii::SOLID,
                ascii::RAMP_UP_RIGHT,
                ascii::RAMP_DOWN_RIGHT,
                ascii::ONE_WAY,
            ];
            let tile = pick[self.game.rng.below(pick.len() as u64) as usize];
            let lo = Vec2::new(cell.col as f32, cell.row as f32);
            let hi = lo + Vec2::ONE;
            let near = |p: Vec2, reach: f32| {
                p.x > lo.x - reach && p.x < hi.x + reach && p.y > lo.y - reach && p.y < hi.y + reach
            };
            let taken = self.game.placed.iter().any(|b| {
                let at = self.position(b.handle);
                b.circles
                    .iter()
                    .any(|c| near(at + c.center, c.radius + 0.1))
            }) || self.game.runners.iter().any(|r| {
                near(
                    r.character.position,
                    r.character.shape().bounds(Vec2::ZERO).max.length() + 0.1,
                )
            }) || self.game.platforms.iter().any(|p| {
                let (a, b) = p.reserved;
                hi.x > a.x && lo.x < b.x + 1.0 && hi.y > a.y && lo.y < b.y + 1.0
            });
            if taken {
                return Ok(());
            }
            Some(tile)
        };
        self.map.set_tile(cell, tile)?;
        audit.count(Kind::MapEdit);
        self.nav.sync(&self.map)?;
        self.flow.sync(&self.nav, &self.map)?;
        self.game.rooms = rooms(&self.map);
        Ok(())
    }

    /// Now and then a body is removed (its handle kept, to check it stays stale), another
    /// added, or one teleported to a clear place.
    fn churn_bodies(&mut self, audit: &mut Audit) -> anyhow::Result<()> {
        let n = self.game.placed.len() as u64;
        if n == 0 {
            return self.add_body();
        }
        match self.game.rng.below(40) {
            0 => {
                let k = self.game.rng.below(n) as usize;
                let gone = self.game.placed.swap_remove(k);
                if self.bodies.remove(gone.handle).is_err() {
                    audit.violation(
                        Kind::StaleHandle,
                        self.game.step,
                        "a live body's removal was refused".into(),
                    );
                }
                self.game.removed.push(gone.handle);
                if self.game.removed.len() > 64 {
                    self.game.removed.remove(0);
                }
                self.add_body()?;
            }
            1 => {
                let k = self.game.rng.below(n) as usize;
                let to = self.random_point();
                let circles = self.game.placed[k].circles.clone();
                let me = self.game.placed.swap_remove(k);
                if self.clear_for(to, &circles, 0.02) {
                    self.bodies.set_position(me.handle, to)?;
                    self.game.placed.push(Placed { last: to, ..me });
                } else {
                    self.game.placed.push(me);
                }
            }
            _ => {}
        }
        Ok(())
    }

    /// Every body proposes its move (a wander, a rare dash of up to 60 cells, or the flow
    /// field's direction), then one resolve and move.
    fn move_bodies(&mut self, audit: &mut Audit) {
        let followers: Vec<usize> = (0..self.game.placed.len())
            .filter(|&i| self.game.placed[i].follows)
            .collect();
        if !followers.is_empty() {
            for k in 0..FLOW_REFRESH.min(followers.len()) {
                let i = followers[(self.game.next_follower + k) % followers.len()];
                let p = self.position(self.game.placed[i].handle);
                let d = self.flow.direction(&self.nav, &self.map, p);
                audit.count(Kind::FlowDirection);
                let velocity = match d {
                    Ok(Some(d)) if d.is_finite() && (d.length() - 1.0).abs() < 1e-3 => d * 0.12,
                    Ok(None) => Vec2::ZERO,
                    Ok(Some(d)) => {
                        audit.violation(
                            Kind::FlowDirection,
                            self.game.step,
                            format!("direction {d} at {p}"),
                        );
                        Vec2::ZERO
                    }
                    Err(e) => {
                        audit.violation(
                            Kind::FlowDirection,
                            self.game.step,
                            format!("at {p}: {e}"),
                        );
                        Vec2::ZERO
                    }
                };
                self.game.placed[i].velocity = velocity;
            }
            self.game.next_follower = (self.game.next_follower + FLOW_REFRESH) % followers.len();
        }
        for b in &mut self.game.placed {
            let rng = &mut self.game.rng;
            let mut motion = b.velocity;
            if !b.follows && rng.below(50) == 0 {
                let angle = rng.range(0.0, std::f32::consts::TAU);
                b.velocity = Vec2::from_angle(angle) * rng.range(0.0, 0.25);
                motion = b.velocity;
            }
            if rng.below(2_000) == 0 {
                let angle = rng.range(0.0, std::f32::consts::TAU);
                motion = Vec2::from_angle(angle) * rng.range(5.0, 60.0);
            }
            if let Err(e) = self.bodies.propose(b.handle, motion) {
                audit.violation(
                    Kind::BodyRefused,
                    self.game.step,
                    format!("{motion} refused: {e}"),
                );
            }
        }
        self.bodies.step(&self.map);
    }

    /// Every character runs, jumps, drops through platforms and falls, one frame.
    fn move_runners(&mut self, audit: &mut Audit) {
        let step = self.game.step;
        for r in &mut self.game.runners {
            let rng = &mut self.game.rng;
            if rng.below(90) == 0 {
                r.run = rng.below(3) as f32 - 1.0;
            }
            let grounded = r.character.ground().is_some();
            r.velocity.x = r.run * 6.0;
            r.velocity.y = (r.velocity.y + 40.0 * DT).min(20.0);
            if grounded && rng.below(60) == 0 {
                r.velocity.y = -14.0;
            }
            if grounded && rng.below(150) == 0 {
                r.drop = 12;
            }
            let options = MoveOptions {
                drop_through: r.drop > 0,
            };
            r.drop = r.drop.saturating_sub(1);
            if let Err(e) = r
                .character
                .move_and_slide(&self.map, &mut r.velocity, DT, options)
            {
                audit.violation(
                    Kind::CharacterRefused,
                    step,
                    format!("velocity {}: {e}", r.velocity),
                );
            }
            audit.count(Kind::CharacterMove);
        }
    }
}
