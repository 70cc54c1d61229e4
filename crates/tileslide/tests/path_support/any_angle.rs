//! A lower bound of the exact any-angle shortest path of a disc of radius r in a room with
//! rectangular obstacles (a map of whole solid cells inside a solid border ring).
//!
//! The disc's centre must stay out of every obstacle inflated by r (a rounded rectangle,
//! the Minkowski sum of the rectangle and the disc) and inside the room shrunk by r. Each
//! rounded rectangle is replaced by the convex polygon *inscribed* in it (its corner arcs
//! sampled at points exactly on the arcs), which is smaller, so the shortest path among the
//! polygons is at most the true one. Among polygonal obstacles in a convex room, a shortest
//! path is straight between obstacle vertices (Lozano-Pérez & Wesley 1979): Dijkstra on the
//! visibility graph of the start, the goal and every polygon vertex inside the room gives
//! it. Polygons are shrunk by [`EPS`] for the visibility test, so paths grazing an edge
//! count as clear, which only lowers the bound further.

use glam::DVec2;
use tileslide::{Cell, TileMap, io::ascii};

/// How far inside a polygon a point must be to count as inside (map units).
const EPS: f64 = 1e-7;

/// An axis-aligned rectangle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rect {
    pub min: DVec2,
    pub max: DVec2,
}

/// The room inside `map`'s border ring and its solid interior cells as rectangles (rows
/// of solid cells merged downwards while they have the same extent). Panics unless the
/// border ring is solid and every tile is `#` or empty.
pub fn room_and_blocks(map: &TileMap) -> (Rect, Vec<Rect>) {
    let (w, h) = (map.width(), map.height());
    let solid = |col: u32, row: u32| match map.tile(Cell::new(col, row)) {
        None => false,
        Some(t) if t == ascii::SOLID => true,
        Some(t) => panic!("tile {t} at ({col}, {row}) is not a solid square"),
    };
    for col in 0..w {
        for row in 0..h {
            if col == 0 || row == 0 || col == w - 1 || row == h - 1 {
                assert!(solid(col, row), "border cell ({col}, {row}) is not solid");
            }
        }
    }
    let cell = map.cell_size().as_dvec2();
    let origin = map.origin().as_dvec2();
    let corner = |col: u32, row: u32| origin + DVec2::new(f64::from(col), f64::from(row)) * cell;
    // (first col, last col, first row) of the blocks still growing, with the block index.
    let mut growing: Vec<(u32, u32, usize)> = Vec::new();
    let mut blocks: Vec<Rect> = Vec::new();
    for row in 1..h - 1 {
        let mut runs = Vec::new();
        let mut col = 1;
        while col < w - 1 {
            if solid(col, row) {
                let start = col;
                while col < w - 1 && solid(col, row) {
                    col += 1;
                }
                runs.push((start, col - 1));
            } else {
                col += 1;
            }
        }
        let mut next = Vec::new();
        for (c0, c1) in runs {
            if let Some(&(_, _, k)) = growing.iter().find(|g| (g.0, g.1) == (c0, c1)) {
                blocks[k].max = corner(c1 + 1, row + 1);
                next.push((c0, c1, k));
            } else {
                blocks.push(Rect {
                    min: corner(c0, row),
                    max: corner(c1 + 1, row + 1),
                });
                next.push((c0, c1, blocks.len() - 1));
            }
        }
        growing = next;
    }
    let room = Rect {
        min: corner(1, 1),
        max: corner(w - 1, h - 1),
    };
    (room, blocks)
}

/// A convex polygon, counter-clockwise (inside on the left of each edge).
#[derive(Clone, Debug)]
struct Polygon {
    vertices: Vec<DVec2>,
    lo: DVec2,
    hi: DVec2,
}

impl Polygon {
    /// The polygon inscribed in `rect` inflated by `r`, with `arc_segments` edges per
    /// rounded corner.
    fn inscribed(rect: Rect, r: f64, arc_segments: usize) -> Self {
        let corners = [
            (DVec2::new(rect.max.x, rect.min.y), -90.0f64),
            (rect.max, 0.0),
            (DVec2::new(rect.min.x, rect.max.y), 90.0),
            (rect.min, 180.0),
        ];
        let mut vertices = Vec::new();
        for (c, start) in corners {
            for m in 0..=arc_segments {
                let angle = (start + 90.0 * m as f64 / arc_segments as f64).to_radians();
                vertices.push(c + r * DVec2::new(angle.cos(), angle.sin()));
            }
        }
        Self {
            vertices,
            lo: rect.min - DVec2::splat(r),
            hi: rect.max + DVec2::splat(r),
        }
    }

    fn edges(&self) -> impl Iterator<Item = (DVec2, DVec2)> + '_ {
        let n = self.vertices.len();
        (0..n).map(move |k| (self.vertices[k], self.vertices[(k + 1) % n]))
    }

    /// True when `p` is inside by more than `EPS`.
    fn contains(&self, p: DVec2) -> bool {
        self.edges()
            .all(|(v, w)| (w - v).perp_dot(p - v) / (w - v).length() > EPS)
    }

    /// True when some piece of `a → b` of positive length is inside by more than `EPS`
    /// (Cyrus & Beck 1978 clipping against the edges' half-planes).
    fn blocks(&self, a: DVec2, b: DVec2) -> bool {
        if a.max(b).cmplt(self.lo).any() || a.min(b).cmpgt(self.hi).any() {
            return false;
        }
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        for (v, w) in self.edges() {
            let e = w - v;
            let len = e.length();
            let f0 = e.perp_dot(a - v) / len - EPS;
            let df = e.perp_dot(b - a) / len;
            if df == 0.0 {
                if f0 <= 0.0 {
                    return false;
                }
            } else if df > 0.0 {
                t0 = t0.max(-f0 / df);
            } else {
                t1 = t1.min(-f0 / df);
            }
            if t0 >= t1 {
                return false;
            }
        }
        true
    }
}

/// The relaxed obstacles of one map for one radius, with their visibility graph.
#[derive(Clone, Debug)]
pub struct InflatedScene {
    /// The room shrunk by r: where the disc's centre may be.
    lo: DVec2,
    hi: DVec2,
    polygons: Vec<Polygon>,
    vertices: Vec<DVec2>,
    /// Per vertex, the vertices it sees and the distance.
    sees: Vec<Vec<(usize, f64)>>,
}

impl InflatedScene {
    /// The scene of `blocks` in `room` for a disc of radius `r`, corner arcs sampled with
    /// `arc_segments` edges each.
    pub fn new(room: Rect, blocks: &[Rect], r: f64, arc_segments: usize) -> Self {
        let polygons: Vec<Polygon> = blocks
            .iter()
            .map(|&b| Polygon::inscribed(b, r, arc_segments))
            .collect();
        let mut scene = Self {
            lo: room.min + DVec2::splat(r),
            hi: room.max - DVec2::splat(r),
            polygons,
            vertices: Vec::new(),
            sees: Vec::new(),
        };
        let candidates: Vec<DVec2> = scene
            .polygons
            .iter()
            .flat_map(|p| p.vertices.iter().copied())
            .collect();
        scene.vertices = candidates
            .into_iter()
            .filter(|&v| scene.is_free(v))
            .collect();
        let n = scene.vertices.len();
        let mut sees = vec![Vec::new(); n];
        for a in 0..n {
            for b in a + 1..n {
                let (p, q) = (scene.vertices[a], scene.vertices[b]);
                if scene.is_visible(p, q) {
                    let d = p.distance(q);
                    sees[a].push((b, d));
                    sees[b].push((a, d));
                }
            }
        }
        scene.sees = sees;
        scene
    }

    /// True when the disc's centre may be at `p` in the relaxed problem.
    pub fn is_free(&self, p: DVec2) -> bool {
        p.cmpge(self.lo - DVec2::splat(EPS)).all()
            && p.cmple(self.hi + DVec2::splat(EPS)).all()
            && !self.polygons.iter().any(|poly| poly.contains(p))
    }

    fn is_visible(&self, a: DVec2, b: DVec2) -> bool {
        !self.polygons.iter().any(|poly| poly.blocks(a, b))
    }

    /// The length of the shortest path from `from` to `to` among the polygons (a lower
    /// bound of the disc's true shortest path), or `None` if they are not connected. Both
    /// ends must be free.
    pub fn lower_bound(&self, from: DVec2, to: DVec2) -> Option<f64> {
        assert!(
            self.is_free(from) && self.is_free(to),
            "{from} or {to} not free"
        );
        if self.is_visible(from, to) {
            return Some(from.distance(to));
        }
        // Dijkstra over the vertices, seeded with the ones the start sees; the goal is
        // reached from the ones it sees.
        let n = self.vertices.len();
        let mut dist = vec![f64::INFINITY; n];
        let mut done = vec![false; n];
        for (k, &v) in self.vertices.iter().enumerate() {
            if self.is_visible(from, v) {
                dist[k] = from.distance(v);
            }
        }
        let to_goal: Vec<f64> = self
            .vertices
            .iter()
            .map(|&v| {
                if self.is_visible(v, to) {
                    v.distance(to)
                } else {
                    f64::INFINITY
                }
            })
            .collect();
        let mut best = f64::INFINITY;
        loop {
            let next = (0..n)
                .filter(|&k| !done[k] && dist[k].is_finite())
                .min_by(|&a, &b| dist[a].total_cmp(&dist[b]));
            let Some(k) = next else { break };
            if dist[k] >= best {
                break;
            }
            done[k] = true;
            best = best.min(dist[k] + to_goal[k]);
            for &(m, d) in &self.sees[k] {
                if dist[k] + d < dist[m] {
                    dist[m] = dist[k] + d;
                }
            }
        }
        best.is_finite().then_some(best)
    }
}
