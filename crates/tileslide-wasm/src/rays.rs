//! Ray casts as JavaScript asks for them, in plain Rust: flat `f32` arrays in and out, and
//! the options object's meaning. Tested natively; [`crate::map`] only converts values.

use tileslide::{Faces, QueryFilter, Ray, RayHit, TileMap, Vec2};

/// Floats a ray takes in a `castRays` input: `x0, y0, x1, y1`.
pub const RAY_IN: usize = 4;

/// Floats a ray takes in a `castRays` answer: `t, x, y, nx, ny` (all NaN for a miss).
pub const RAY_OUT: usize = 5;

/// The options of `castRay` and `castRays`: `{ bothSides, against: [dx, dy] }`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RayOptions {
    /// Faces hit from behind count too.
    pub both_sides: bool,
    /// Only faces that oppose this direction count (for example "only floors": `[0, 1]`
    /// on a y-down map).
    pub against: Option<Vec2>,
}

impl RayOptions {
    /// The query filter these options ask for.
    ///
    /// # Errors
    /// Both options at once (they choose faces two ways), or an `against` direction that is
    /// not finite or is zero.
    pub fn filter(&self) -> Result<QueryFilter, String> {
        let faces = match (self.both_sides, self.against) {
            (true, Some(_)) => {
                return Err("ray options: give `bothSides` or `against`, not both".into());
            }
            (true, None) => Faces::Both,
            (false, Some(dir)) => {
                if !dir.is_finite() || dir == Vec2::ZERO {
                    return Err(format!(
                        "ray options: `against` must be a finite, non-zero direction, not [{}, {}]",
                        dir.x, dir.y
                    ));
                }
                Faces::Against(dir)
            }
            (false, None) => Faces::Front,
        };
        Ok(QueryFilter {
            faces,
            ..QueryFilter::default()
        })
    }
}

/// The ray from (`x0`, `y0`) to (`x1`, `y1`); an error naming the ray (`which`) and the
/// coordinate when one is NaN or infinite, or when the two ends are too far apart for an
/// `f32`.
pub fn ray(which: &str, x0: f32, y0: f32, x1: f32, y1: f32) -> Result<Ray, String> {
    ray_named(|| which.to_owned(), x0, y0, x1, y1)
}

/// [`ray`], with the ray's name made only when there is an error to name it in: a batch of a
/// million rays formats no names.
#[inline(always)]
fn ray_named(
    which: impl FnOnce() -> String,
    x0: f32,
    y0: f32,
    x1: f32,
    y1: f32,
) -> Result<Ray, String> {
    for (name, v) in [("x0", x0), ("y0", y0), ("x1", x1), ("y1", y1)] {
        if !v.is_finite() {
            return Err(format!("{}: {name} is {v}, not a finite number", which()));
        }
    }
    let ray = Ray::between(Vec2::new(x0, y0), Vec2::new(x1, y1));
    if !ray.delta.is_finite() {
        return Err(format!(
            "{}: its end points ({x0}, {y0}) and ({x1}, {y1}) are too far apart for a 32-bit float",
            which()
        ));
    }
    Ok(ray)
}

/// Casts the rays of `rays` (`RAY_IN` floats each) with `filter`, all at once
/// ([`TileMap::cast_rays`], so each answer is `cast_ray`'s): `RAY_OUT` floats a ray.
///
/// # Errors
/// A length that is not a multiple of `RAY_IN`, or a ray [`ray`] refuses (named by its
/// index).
pub fn cast_flat(map: &TileMap, rays: &[f32], filter: &QueryFilter) -> Result<Vec<f32>, String> {
    cast_flat_with(rays, |chunk, hits| map.cast_rays_into(chunk, filter, hits))
}

/// [`cast_flat`] with the casting of each chunk of checked rays left to `cast`, which
/// answers them into the buffer it is given (as [`TileMap::cast_rays_into`] does); the
/// native benchmark times other walks through it.
///
/// # Errors
/// As [`cast_flat`].
pub fn cast_flat_with(
    rays: &[f32],
    mut cast: impl FnMut(&[Ray], &mut Vec<Option<RayHit>>),
) -> Result<Vec<f32>, String> {
    if !rays.len().is_multiple_of(RAY_IN) {
        return Err(format!(
            "castRays: {} floats is not a whole number of rays (4 floats a ray: x0, y0, x1, y1)",
            rays.len()
        ));
    }
    // In chunks, so that the rays and answers in flight stay small and in cache while the
    // answers are written straight into the one output buffer.
    let mut out = vec![0.0; rays.len() / RAY_IN * RAY_OUT];
    let mut chunk = Vec::with_capacity(CHUNK);
    let mut hits = Vec::with_capacity(CHUNK);
    let answers = out.chunks_mut(CHUNK * RAY_OUT);
    for (c, (floats, answers)) in rays.chunks(CHUNK * RAY_IN).zip(answers).enumerate() {
        chunk.clear();
        for (i, r) in floats.chunks_exact(RAY_IN).enumerate() {
            let index = c * CHUNK + i;
            chunk.push(ray_named(
                || format!("castRays: ray {index}"),
                r[0],
                r[1],
                r[2],
                r[3],
            )?);
        }
        cast(&chunk, &mut hits);
        for (answer, hit) in answers.chunks_exact_mut(RAY_OUT).zip(&hits) {
            let [t, x, y, nx, ny] = flat_hit(hit.as_ref());
            answer[0] = t;
            answer[1] = x;
            answer[2] = y;
            answer[3] = nx;
            answer[4] = ny;
        }
    }
    Ok(out)
}

/// Rays [`cast_flat`] checks and casts at a time.
const CHUNK: usize = 4096;

/// One answer of [`cast_flat`]: `t, x, y, nx, ny`, or five NaNs for a miss.
#[must_use]
#[inline(always)]
pub fn flat_hit(hit: Option<&RayHit>) -> [f32; RAY_OUT] {
    match hit {
        Some(h) => [h.t, h.point.x, h.point.y, h.normal.x, h.normal.y],
        None => [f32::NAN; RAY_OUT],
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;
    use tileslide::io::ascii;

    /// The bundled cave, which the Node tests load too.
    fn cave() -> TileMap {
        ascii::parse(
            include_str!("../../../examples/maps/cave.txt"),
            "cave.txt",
            1.0,
        )
        .unwrap()
    }

    /// The checksum rays: from a grid of starts inside the cave, in directions of every
    /// slope, all coordinates small dyadic fractions that JavaScript and Rust compute
    /// exactly alike. `web/test/package.test.mjs` builds the same list.
    fn checksum_rays() -> Vec<f32> {
        let mut out = Vec::new();
        for i in 0..2000u32 {
            let x0 = 1.5 + (i % 37) as f32 * 0.25;
            let y0 = 1.5 + (i % 11) as f32 * 0.5;
            let dx = ((i * 7919) % 41) as f32 * 0.5 - 10.0;
            let dy = ((i * 104_729) % 37) as f32 * 0.5 - 9.0;
            out.extend_from_slice(&[x0, y0, x0 + dx, y0 + dy]);
        }
        out
    }

    /// FNV-1a over the answers' bits, little-endian, as the Node test computes it.
    fn fnv1a(values: &[f32]) -> u64 {
        let mut h = 0xcbf2_9ce4_8422_2325_u64;
        for v in values {
            for b in v.to_bits().to_le_bytes() {
                h ^= u64::from(b);
                h = h.wrapping_mul(0x0100_0000_01b3);
            }
        }
        h
    }

    /// The checksum `web/test/package.test.mjs` expects from the wasm build: the same rays
    /// on the same map give the same bits there.
    const CAVE_CHECKSUM: u64 = 0xab27_5c4c_9461_0d89;

    #[test]
    fn the_checksum_rays_give_the_checksum_the_package_test_expects() {
        let out = cast_flat(&cave(), &checksum_rays(), &QueryFilter::default()).unwrap();
        let hits = out.chunks(RAY_OUT).filter(|h| !h[0].is_nan()).count();
        assert!(hits > 1000, "{hits} of 2000 hit");
        assert_eq!(fnv1a(&out), CAVE_CHECKSUM, "{:#018x}", fnv1a(&out));
    }

    #[test]
    fn each_flat_answer_is_cast_rays_answer() {
        let map = cave();
        let rays = checksum_rays();
        let out = cast_flat(&map, &rays, &QueryFilter::both_sides()).unwrap();
        assert_each_is_cast_ray(&map, &rays, &out, &QueryFilter::both_sides());
    }

    /// Every answer of `out` is, bit for bit, `cast_ray`'s for its ray of `rays`.
    fn assert_each_is_cast_ray(map: &TileMap, rays: &[f32], out: &[f32], filter: &QueryFilter) {
        assert_eq!(rays.len() / RAY_IN, out.len() / RAY_OUT);
        for (r, o) in rays.chunks(RAY_IN).zip(out.chunks(RAY_OUT)) {
            let ray = ray("test", r[0], r[1], r[2], r[3]).unwrap();
            let want = flat_hit(map.cast_ray(ray, filter).as_ref());
            assert_eq!(
                o.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
                want.iter().map(|v| v.to_bits()).collect::<Vec<_>>()
            );
        }
    }

    #[test]
    fn answers_and_errors_carry_across_chunks() {
        let map = cave();
        let base = checksum_rays();
        // More rays than three chunks, so every chunk boundary is crossed.
        let mut rays = Vec::new();
        while rays.len() < (3 * CHUNK + 7) * RAY_IN {
            rays.extend_from_slice(&base);
        }
        rays.truncate((3 * CHUNK + 7) * RAY_IN);
        let out = cast_flat(&map, &rays, &QueryFilter::default()).unwrap();
        assert_eq!(out.len(), (3 * CHUNK + 7) * RAY_OUT);
        assert_each_is_cast_ray(&map, &rays, &out, &QueryFilter::default());
        let bad = CHUNK + 5;
        rays[bad * RAY_IN + 2] = f32::INFINITY;
        let e = cast_flat(&map, &rays, &QueryFilter::default()).unwrap_err();
        assert!(
            e.contains(&format!("ray {bad}:")) && e.contains("x1 is inf"),
            "{e}"
        );
    }

    #[test]
    fn bad_rays_and_options_are_errors_that_name_them() {
        let map = cave();
        let e = cast_flat(&map, &[1.0, 1.0, 2.0], &QueryFilter::default()).unwrap_err();
        assert!(e.contains("3 floats"), "{e}");
        let e = cast_flat(
            &map,
            &[1.5, 1.5, 3.0, 3.0, 1.5, f32::NAN, 3.0, 3.0],
            &QueryFilter::default(),
        )
        .unwrap_err();
        assert!(e.contains("ray 1") && e.contains("y0 is NaN"), "{e}");
        let e = ray("castRay", -3e38, 0.0, 3e38, 0.0).unwrap_err();
        assert!(e.contains("too far apart"), "{e}");
        let both = RayOptions {
            both_sides: true,
            against: Some(Vec2::Y),
        };
        assert!(both.filter().unwrap_err().contains("not both"));
        let zero = RayOptions {
            both_sides: false,
            against: Some(Vec2::ZERO),
        };
        assert!(zero.filter().unwrap_err().contains("non-zero"));
        let floors = RayOptions {
            both_sides: false,
            against: Some(Vec2::Y),
        };
        assert_eq!(floors.filter().unwrap().faces, Faces::Against(Vec2::Y));
    }
}
