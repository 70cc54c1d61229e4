//! Many rays cast at once: the fast walk of `fast_walk.rs`, run for eight rays side by side
//! in SIMD lanes, with each ray's answer exactly the one `cast_ray` gives it.
//!
//! One ray's walk is a chain of dependent steps, each deciding "x or y" by a comparison the
//! branch predictor cannot learn (a coin toss on random rays), so a single cast is bound by
//! mispredictions and by the latency of that chain, not by arithmetic. Walking many rays
//! together turns the decision into a select and the independent rays into parallel work:
//! rays are set up [`LANES`] at a time (`WalkStart::lane`, the scalar walk's own arithmetic
//! without its early returns), a few groups of lanes are stepped side by side with no branch
//! per step, and every few steps (two or three, by instruction set and processor) each
//! lane whose ray has finished is answered and given the next ray, so that lanes idle
//! little while rays remain. This is the persistent-threads organisation of GPU ray tracers
//! (Aila and Laine, "Understanding the Efficiency of Ray Traversal on GPUs", HPG 2009) at
//! the scale of one CPU core.
//!
//! Only the rays the fast walk decides alone are finished here: face hits (exact `t` from the
//! cell's geometry, as in `cast_ray`) and misses. A ray that starts on a grid line or outside
//! the map, is parallel to an axis, passes within the tolerance of a cell corner, or reaches
//! a cell whose segments must be tested one by one is handed to `cast_ray` whole, as are
//! all rays when temporary segments exist or the filter is not a plain front-face query. So
//! every answer is `cast_ray`'s, bit for bit; the batch only changes how fast it comes.

use glam::Vec2;

use super::fast_walk::WalkStart;
use super::segment_test::SegmentTest;
use super::traversal::GridRay;
use super::{QueryFilter, RayHit};
use crate::geometry::Ray;
use crate::tiles::face_kind::{KIND_GENERAL, face_index};
use crate::tiles::{Cell, TileMap};

#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
#[path = "ray_batch_simd128.rs"]
mod simd128;

/// Rays stepped side by side: eight `f32` or `i32` lanes, two SSE registers or one AVX2
/// register.
const LANES: usize = 8;
/// Groups walked side by side: their steps are independent, so the processor overlaps
/// them, hiding each step's latency (a conversion, a subtraction and a multiplication).
const WALKERS: usize = 4;
/// Steps each group takes between two refills, for each instruction set. A lane that
/// finishes early idles until the refill, but each refill finds more finished lanes, which
/// spreads its fixed cost and its mispredicted loop exits over more steps. Measured on a
/// Xeon with SSE2: 2 steps 8 % faster than 1, 3 steps 2 % slower than 2.
const STEPS_PER_TURN_SSE2: usize = 2;
/// [`STEPS_PER_TURN_SSE2`] with AVX2 on Intel's processors, where a step costs half as
/// much: on a Xeon, 3 steps 6 % faster than 2, 4 no faster than 3.
#[cfg(target_arch = "x86_64")]
const STEPS_PER_TURN_AVX2: usize = 3;
/// [`STEPS_PER_TURN_AVX2`] on AMD's processors: on an EPYC (Zen 4), 2 steps walk
/// dungeon256's rays 30 % faster than 3 and open256's 11 % faster, and 1 or 4 steps are as
/// slow as 3.
#[cfg(target_arch = "x86_64")]
const STEPS_PER_TURN_AVX2_AMD: usize = 2;
/// Groups set up at a time, waiting to refill lanes.
const WAITING: usize = 8;

/// Rays per block: a batch is walked a block at a time, each block's answers cleared and
/// written while they are in cache (a million answers are tens of megabytes: walked
/// whole, a batch of them took 28 % longer on an EPYC, 45 ms against 35). With the
/// `parallel` feature the blocks are the tasks split across threads: enough rays that a
/// task's set-up (a few hundred bytes of walk state) and rayon's hand-over are noise beside
/// its walks; batches under two blocks' worth stay on the calling thread.
const RAYS_PER_TASK: usize = 4096;

/// Where a lane's ray stands.
const WALKING: i32 = 0;
/// It enters a whole-edge face it hits (the walk state is frozen at that cell).
const FACE: i32 = 1;
/// It ends, or leaves the map, without a hit.
const MISS: i32 = 2;
/// `cast_ray` must decide it.
const SCALAR: i32 = 3;
/// The lane holds no ray (the input has run out).
const IDLE: i32 = 4;

/// The walk state of [`LANES`] rays, one array per field so that a step is a handful of
/// vector instructions. Field meanings are those of [`WalkStart`] (whose crossings `tx`
/// and `ty` each step recomputes from the grid lines).
#[derive(Clone, Copy)]
struct Group {
    o_x: [f32; LANES],
    o_y: [f32; LANES],
    inv_x: [f32; LANES],
    inv_y: [f32; LANES],
    tol_t: [f32; LANES],
    t_stop: [f32; LANES],
    line_x: [i32; LANES],
    line_y: [i32; LANES],
    index: [i32; LANES],
    index_step_x: [i32; LANES],
    index_step_y: [i32; LANES],
    step_x: [i32; LANES],
    step_y: [i32; LANES],
    enter_x: [i32; LANES],
    enter_y: [i32; LANES],
    /// The `FACE_*` bit the current cell was entered through (0 for the start cell).
    entered: [i32; LANES],
    status: [i32; LANES],
    /// The ray's place in the input.
    ray: [usize; LANES],
}

impl Default for Group {
    fn default() -> Self {
        Self {
            o_x: [0.0; LANES],
            o_y: [0.0; LANES],
            inv_x: [0.0; LANES],
            inv_y: [0.0; LANES],
            tol_t: [0.0; LANES],
            t_stop: [0.0; LANES],
            line_x: [0; LANES],
            line_y: [0; LANES],
            index: [0; LANES],
            index_step_x: [0; LANES],
            index_step_y: [0; LANES],
            step_x: [0; LANES],
            step_y: [0; LANES],
            enter_x: [0; LANES],
            enter_y: [0; LANES],
            entered: [0; LANES],
            status: [IDLE; LANES],
            ray: [0; LANES],
        }
    }
}

/// Rays set up and waiting for a lane, in input order.
#[derive(Default)]
struct Waiting {
    groups: [Group; WAITING],
    /// The next lane to hand out, and how many lanes hold rays.
    next: usize,
    len: usize,
}

impl TileMap {
    /// The nearest hit of each ray: `out[i]` is exactly
    /// [`cast_ray`](Self::cast_ray)`(rays[i], filter)`, bit for bit, but many rays cost less
    /// than as many calls (about half as much on the benchmark scenes), because the rays
    /// are walked side by side in SIMD lanes (see `docs/ray-casting.md`). On x86-64 the
    /// lanes run on AVX2 when the processor has it (checked at run time), on SSE2
    /// otherwise; the answers are the same. Use it wherever rays come in numbers: line of
    /// sight for a crowd, sensor fans, lidar.
    ///
    /// With the `parallel` feature, a batch of 8,192 rays or more is split into blocks of
    /// 4,096 answered on the threads of the rayon pool the call runs in (the global pool
    /// unless called inside `rayon::ThreadPool::install`); the answers are the same, bit
    /// for bit, on any number of threads.
    ///
    /// ```
    /// # use tileslide::{io::ascii, Ray, QueryFilter, Vec2};
    /// let map = ascii::parse("\
    /// #####
    /// #...#
    /// #####", "doc.txt", 1.0)?;
    /// let rays = [
    ///     Ray::between(Vec2::new(1.5, 1.5), Vec2::new(9.5, 1.5)),
    ///     Ray::between(Vec2::new(2.5, 1.5), Vec2::new(2.6, 1.5)),
    /// ];
    /// let hits = map.cast_rays(&rays, &QueryFilter::default());
    /// assert_eq!(hits[0].unwrap().point, Vec2::new(4.0, 1.5));
    /// assert!(hits[1].is_none());
    /// # Ok::<(), tileslide::io::LoadError>(())
    /// ```
    #[must_use]
    pub fn cast_rays(&self, rays: &[Ray], filter: &QueryFilter) -> Vec<Option<RayHit>> {
        let mut out = Vec::with_capacity(rays.len());
        self.cast_rays_into(rays, filter, &mut out);
        out
    }

    /// [`cast_rays`](Self::cast_rays) into a buffer the caller reuses (cleared first).
    pub fn cast_rays_into(
        &self,
        rays: &[Ray],
        filter: &QueryFilter,
        out: &mut Vec<Option<RayHit>>,
    ) {
        if !self.batch_walks(filter) {
            out.clear();
            #[cfg(feature = "parallel")]
            if rays.len() >= 2 * RAYS_PER_TASK && rayon::current_num_threads() > 1 {
                use rayon::prelude::*;
                rays.par_iter()
                    .with_min_len(RAYS_PER_TASK)
                    .map(|&ray| self.cast_ray(ray, filter))
                    .collect_into_vec(out);
                return;
            }
            out.extend(rays.iter().map(|&ray| self.cast_ray(ray, filter)));
            return;
        }
        // The answers' slots: a reused buffer is only cut or grown here, and each block
        // of answers is cleared by the walk that answers it (below), in its cache (and,
        // split across threads, on its thread), not all of it first.
        out.truncate(rays.len());
        out.resize(rays.len(), None);
        #[cfg(feature = "parallel")]
        if rays.len() >= 2 * RAYS_PER_TASK && rayon::current_num_threads() > 1 {
            use rayon::prelude::*;
            // Each ray's answer is its own, so blocks answered on any thread, in any order,
            // give the same answers bit for bit.
            rays.par_chunks(RAYS_PER_TASK)
                .zip(out.par_chunks_mut(RAYS_PER_TASK))
                .for_each(|(rays, out)| self.walk_fastest(rays, filter, out));
            return;
        }
        for (rays, out) in rays
            .chunks(RAYS_PER_TASK)
            .zip(out.chunks_mut(RAYS_PER_TASK))
        {
            self.walk_fastest(rays, filter, out);
        }
    }

    /// [`walk`](Self::walk) on the widest instruction set this processor has, `out` cleared
    /// first.
    fn walk_fastest(&self, rays: &[Ray], filter: &QueryFilter, out: &mut [Option<RayHit>]) {
        // A miss is answered by leaving its slot as it is.
        out.fill(None);
        #[cfg(target_arch = "x86_64")]
        if self.walk_avx2_if_present(is_amd(), rays, filter, out) {
            return;
        }
        self.walk::<STEPS_PER_TURN_SSE2>(rays, filter, out);
    }

    /// [`walk_avx2`](Self::walk_avx2) with AMD's steps between refills or Intel's, if this
    /// processor has AVX2; `false`, and `out` untouched, if not.
    #[cfg(target_arch = "x86_64")]
    fn walk_avx2_if_present(
        &self,
        amd: bool,
        rays: &[Ray],
        filter: &QueryFilter,
        out: &mut [Option<RayHit>],
    ) -> bool {
        if !has_avx2() {
            return false;
        }
        // SAFETY: `walk_avx2` is `walk` compiled for AVX2 (with BMI1, BMI2, LZCNT and
        // POPCNT), and `has_avx2` has just found every one of these on this processor.
        #[allow(unsafe_code)]
        unsafe {
            if amd {
                self.walk_avx2::<STEPS_PER_TURN_AVX2_AMD>(rays, filter, out);
            } else {
                self.walk_avx2::<STEPS_PER_TURN_AVX2>(rays, filter, out);
            }
        }
        true
    }

    /// Whether the batch walk may answer rays under `filter`: temporary segments shorten
    /// each walk, and other filters test face cells segment by segment, both `cast_ray`'s
    /// work.
    fn batch_walks(&self, filter: &QueryFilter) -> bool {
        self.temporaries.is_empty() && SegmentTest::decides_by_faces(filter)
    }

    /// [`walk`](Self::walk) compiled for processors with AVX2: eight lanes are one register
    /// rather than two, and the step's conversions, compares and selects each one
    /// instruction (measured: 24 → 30 M rays/s on dungeon256). Only the instruction set
    /// differs: every operation is the same IEEE operation in the same order (Rust never
    /// fuses a multiply and an add on its own), so the answers are bit for bit those of the
    /// portable walk.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,bmi1,bmi2,lzcnt,popcnt")]
    fn walk_avx2<const STEPS: usize>(
        &self,
        rays: &[Ray],
        filter: &QueryFilter,
        out: &mut [Option<RayHit>],
    ) {
        self.walk::<STEPS>(rays, filter, out);
    }

    /// The batch walk on the portable instruction set, whatever the processor has: for
    /// tests that check it answers as `cast_ray` does on machines where `cast_rays` takes
    /// the AVX2 path.
    #[doc(hidden)]
    pub fn cast_rays_portable(&self, rays: &[Ray], filter: &QueryFilter) -> Vec<Option<RayHit>> {
        let mut out = Vec::with_capacity(rays.len());
        self.cast_rays_portable_into(rays, filter, &mut out);
        out
    }

    /// The AVX2 batch walk with the other processor family's steps between refills (Intel's
    /// on AMD, AMD's elsewhere), or `None` on a processor without AVX2: for tests that check
    /// that both answer as `cast_ray` does, whichever processor runs them.
    #[doc(hidden)]
    pub fn cast_rays_avx2_other_family(
        &self,
        rays: &[Ray],
        filter: &QueryFilter,
    ) -> Option<Vec<Option<RayHit>>> {
        #[cfg(target_arch = "x86_64")]
        if has_avx2() {
            if !self.batch_walks(filter) {
                return Some(rays.iter().map(|&ray| self.cast_ray(ray, filter)).collect());
            }
            let mut out = vec![None; rays.len()];
            self.walk_avx2_if_present(!is_amd(), rays, filter, &mut out);
            return Some(out);
        }
        let _ = (rays, filter);
        None
    }

    /// [`cast_rays_portable`](Self::cast_rays_portable) into a buffer the caller reuses
    /// (cleared first), on one thread: for benchmarks that time both instruction sets on
    /// one processor.
    #[doc(hidden)]
    pub fn cast_rays_portable_into(
        &self,
        rays: &[Ray],
        filter: &QueryFilter,
        out: &mut Vec<Option<RayHit>>,
    ) {
        out.clear();
        if !self.batch_walks(filter) {
            out.extend(rays.iter().map(|&ray| self.cast_ray(ray, filter)));
            return;
        }
        out.resize(rays.len(), None);
        self.walk::<STEPS_PER_TURN_SSE2>(rays, filter, out);
    }

    /// Answers `rays` into `out` (as long as `rays`, all `None`) by the batch walk, `STEPS`
    /// steps between refills; the caller has checked [`batch_walks`](Self::batch_walks).
    /// Always inlined, so that each caller compiles it for its own instruction set.
    #[inline(always)]
    fn walk<const STEPS: usize>(
        &self,
        rays: &[Ray],
        filter: &QueryFilter,
        out: &mut [Option<RayHit>],
    ) {
        let mut walkers = [Group::default(); WALKERS];
        let mut waiting = Box::<Waiting>::default();
        let mut queued = 0;
        let kinds = self.store.kinds();
        // Every walk ends within `max_steps` steps (one column or row each), so this many
        // turns of the loop finish every ray; the bound only guards against a walk that
        // rounding kept going, which `cast_ray` then decides.
        let max_steps = self.width() as usize + self.height() as usize + 2;
        let max_turns = (rays.len() / (LANES * WALKERS) + 2).saturating_mul(max_steps);
        for turn in 0.. {
            let give_up = turn > max_turns;
            let mut busy = false;
            for group in &mut walkers {
                // The lanes to answer and refill, found without a branch per lane: which
                // lanes finish is a coin toss for the branch predictor.
                let mut stopped = ALL_LANES & !lanes_equal(&group.status, WALKING);
                if give_up {
                    stopped = ALL_LANES;
                }
                if queued == rays.len() && waiting.next == waiting.len {
                    stopped &= !lanes_equal(&group.status, IDLE);
                }
                while stopped != 0 {
                    let k = stopped.trailing_zeros() as usize;
                    stopped &= stopped - 1;
                    // A miss is answered already: `out` starts as `None` (`walk_fastest`).
                    let status = group.status[k];
                    let ray = group.ray[k];
                    if let (true, Some(&r), Some(slot)) = (
                        status != MISS && status != IDLE,
                        rays.get(ray),
                        out.get_mut(ray),
                    ) {
                        if status == FACE {
                            self.answer_face(r, filter, group, k, slot);
                        } else {
                            // Declined by the fast walk (or walking when `give_up`).
                            *slot = self.cast_ray(r, filter);
                        }
                    }
                    if waiting.next == waiting.len && queued < rays.len() {
                        queued += self.start_waiting(&rays[queued..], queued, &mut waiting);
                    }
                    if waiting.next < waiting.len {
                        let n = waiting.next;
                        copy_lane(&waiting.groups[n / LANES], n % LANES, group, k);
                        waiting.next += 1;
                    } else {
                        group.status[k] = IDLE;
                    }
                }
                busy |= lanes_equal(&group.status, IDLE) != ALL_LANES;
            }
            if !busy {
                break;
            }
            for _ in 0..STEPS {
                for group in &mut walkers {
                    #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
                    simd128::step(group, kinds);
                    #[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
                    step(group, kinds);
                }
            }
        }
    }

    /// Sets up the walks of the first rays of `rays` (as many as `waiting` holds; the first
    /// is ray `first` of the input) and returns how many.
    #[inline(always)]
    fn start_waiting(&self, rays: &[Ray], first: usize, waiting: &mut Waiting) -> usize {
        let n = rays.len().min(WAITING * LANES);
        for (g, group) in waiting.groups.iter_mut().enumerate() {
            let base = g * LANES;
            let lane_rays = match rays.get(base..base + LANES) {
                Some(whole) => <&[Ray; LANES]>::try_from(whole).ok().copied(),
                None => None,
            };
            let lane_rays = lane_rays.unwrap_or_else(|| {
                // Past the input's end, NaN rays fill the lanes: they never walk.
                let mut padded = [Ray {
                    origin: Vec2::NAN,
                    delta: Vec2::NAN,
                }; LANES];
                for (lane, ray) in padded.iter_mut().zip(rays.iter().skip(base)) {
                    *lane = *ray;
                }
                padded
            });
            self.start_group(group, &lane_rays, first + base);
        }
        waiting.next = 0;
        waiting.len = n;
        n
    }

    /// Sets up the walks of `rays` in `group`; `first` is the first one's place in the
    /// input. Written lane by lane over plain `f32`/`i32` arrays so that it compiles to
    /// vector instructions.
    // Lane loops index a dozen arrays by the same lane: clearer as `k`, and they vectorize.
    #[allow(clippy::needless_range_loop)]
    #[inline(always)]
    fn start_group(&self, group: &mut Group, rays: &[Ray; LANES], first: usize) {
        let (origin, inv_cell) = (self.origin(), self.inv_cell_size());
        let (width, height) = (self.width(), self.height());
        let mut p = [[0.0f32; LANES]; 4];
        for (k, ray) in rays.iter().enumerate() {
            p[0][k] = ray.origin.x;
            p[1][k] = ray.origin.y;
            p[2][k] = ray.delta.x;
            p[3][k] = ray.delta.y;
        }
        for k in 0..LANES {
            let (p0, delta) = (Vec2::new(p[0][k], p[1][k]), Vec2::new(p[2][k], p[3][k]));
            // As `grid_ray` computes it.
            let grid = GridRay {
                origin: (p0 - origin) * inv_cell,
                delta: delta * inv_cell,
                width,
                height,
            };
            let (fits, s) = WalkStart::lane(&grid, 1.0);
            // (Ordinary rays are finite; the others are `cast_ray`'s to answer.)
            let ordinary = grid.is_ordinary();
            group.o_x[k] = s.o.x;
            group.o_y[k] = s.o.y;
            group.inv_x[k] = s.inv.x;
            group.inv_y[k] = s.inv.y;
            group.tol_t[k] = s.tol_t;
            group.t_stop[k] = s.t_stop;
            group.line_x[k] = s.line_x;
            group.line_y[k] = s.line_y;
            group.index[k] = s.index;
            group.index_step_x[k] = s.index_step_x;
            group.index_step_y[k] = s.index_step_y;
            group.step_x[k] = s.step_x;
            group.step_y[k] = s.step_y;
            group.enter_x[k] = s.enter_x.into();
            group.enter_y[k] = s.enter_y.into();
            group.entered[k] = 0;
            group.status[k] = if fits & ordinary { WALKING } else { SCALAR };
        }
        for (k, ray) in group.ray.iter_mut().enumerate() {
            *ray = first + k;
        }
    }

    /// Writes the answer for `ray`, whose walk in lane `k` of `group` entered a whole-edge
    /// face, to `slot`: the face hit at its exact `t`, computed from the cell's geometry as
    /// `cast_ray` computes it (`face_t`). As there, a face whose exact test misses
    /// (rounding at its very end can disagree with the walk's step) is left to the general
    /// walk. The hit is written where it is made, not returned: a hit returned through
    /// memory and copied stalls on loads of its just-written fields (measured: 12 % of the
    /// batch's time).
    #[inline(always)]
    fn answer_face(
        &self,
        ray: Ray,
        filter: &QueryFilter,
        group: &Group,
        k: usize,
        slot: &mut Option<RayHit>,
    ) {
        let index = group.index[k] as usize;
        let face = group.entered[k] as u8;
        let col = group.line_x[k] - i32::from(group.step_x[k] > 0);
        let row = group.line_y[k] - i32::from(group.step_y[k] > 0);
        let cell = Cell::new(col as u32, row as u32);
        match self.face_t(ray.origin, ray.delta, cell, face) {
            Some(t) => {
                let kind = self.store.kinds().get(index).copied();
                let i = face_index(kind.unwrap_or(KIND_GENERAL), face);
                *slot = Some(self.face_hit(cell, index, i, face, t, ray.origin + ray.delta * t));
            }
            None => *slot = self.cast_ray(ray, filter),
        }
    }
}

/// One step of every lane of `group` still walking: the body of `fast_walk`'s loop, with
/// masks (0 or −1, as SIMD comparisons give them) for its branches, so that the loop over
/// the lanes compiles to vector instructions. A lane that stops keeps its state (the cell
/// it stopped in).
#[allow(clippy::needless_range_loop)] // as in `start_group`
// (Builds with SIMD128 for WebAssembly step by `simd128::step`.)
#[cfg_attr(
    all(target_arch = "wasm32", target_feature = "simd128"),
    allow(dead_code)
)]
#[inline(always)]
fn step(group: &mut Group, kinds: &[u8]) {
    // The one read that cannot be a vector load: the kind of each lane's cell. An index
    // outside the map (which no walk reaches) reads as general: `cast_ray` then decides.
    let mut kind = [0i32; LANES];
    for (kind, &index) in kind.iter_mut().zip(&group.index) {
        *kind = kinds
            .get(index as usize)
            .map_or(i32::from(KIND_GENERAL), |&b| i32::from(b));
    }
    let mask = |b: bool| -i32::from(b);
    for k in 0..LANES {
        // The next crossing on each axis, from the origin as `fast_walk` computes it (not
        // kept between steps: recomputing costs less than storing and moving it).
        let tx = (group.line_x[k] as f32 - group.o_x[k]) * group.inv_x[k];
        let ty = (group.line_y[k] as f32 - group.o_y[k]) * group.inv_y[k];
        let x_first = mask(tx < ty);
        let t_exit = if tx < ty { tx } else { ty };
        // `fast_walk`'s tests, in its order: a face entered, a general cell, a corner, the
        // end of the walk.
        let face = mask(kind[k] & group.entered[k] & 0x0f != 0);
        let general = mask(kind[k] & i32::from(KIND_GENERAL) != 0);
        let corner = mask((tx - ty).abs() <= group.tol_t[k]);
        let end = mask(t_exit > group.t_stop[k]);
        // The status these give, in that order of precedence (`SCALAR` is `MISS | 1`).
        let stopped = (face & FACE) | (!face & (((general | corner) & SCALAR) | (end & MISS)));
        // A walking lane's status is 0.
        let walking = mask(group.status[k] == WALKING);
        group.status[k] |= walking & stopped;
        let go = walking & mask(stopped == WALKING);
        let (go_x, go_y) = (go & x_first, go & !x_first);
        group.index[k] += (go_x & group.index_step_x[k]) | (go_y & group.index_step_y[k]);
        group.line_x[k] += go_x & group.step_x[k];
        group.line_y[k] += go_y & group.step_y[k];
        group.entered[k] =
            (go_x & group.enter_x[k]) | (go_y & group.enter_y[k]) | (!go & group.entered[k]);
    }
}

/// Bit `k` set for each lane `k` whose status is `value`, without a branch per lane:
/// eight 0/1 bytes (vector compares and packs) gathered into eight bits by one
/// multiplication (byte `k` times `2^(56 − 7k)` lands in bit `56 + k`, and no two other
/// products meet or carry into the top byte).
#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
#[inline(always)]
fn lanes_equal(status: &[i32; LANES], value: i32) -> u32 {
    let mut bytes = [0u8; LANES];
    for (byte, &s) in bytes.iter_mut().zip(status) {
        *byte = u8::from(s == value);
    }
    (u64::from_le_bytes(bytes).wrapping_mul(0x0102_0408_1020_4080) >> 56) as u32
}

#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
use simd128::lanes_equal;

/// Every lane's bit, as [`lanes_equal`] gives them.
const ALL_LANES: u32 = u32::MAX >> (32 - LANES);

/// Copies lane `k` of `from` to lane `to_k` of `to`.
#[inline(always)]
fn copy_lane(from: &Group, k: usize, to: &mut Group, to_k: usize) {
    macro_rules! copy {
        ($($field:ident),*) => { $( to.$field[to_k] = from.$field[k]; )* };
    }
    copy!(
        o_x,
        o_y,
        inv_x,
        inv_y,
        tol_t,
        t_stop,
        line_x,
        line_y,
        index,
        index_step_x,
        index_step_y,
        step_x,
        step_y,
        enter_x,
        enter_y,
        entered,
        status,
        ray
    );
}

/// Whether this is an AMD processor (or a Hygon, whose cores are AMD's Zen), which walks
/// fastest with [`STEPS_PER_TURN_AVX2_AMD`]. Told by SSE4a, an extension that only these
/// implement: the standard library detects it without `unsafe` and caches the answer.
#[cfg(target_arch = "x86_64")]
fn is_amd() -> bool {
    std::is_x86_feature_detected!("sse4a")
}

/// Whether this processor runs [`TileMap::walk_avx2`]: it has AVX2 and the bit
/// instructions the walk's lane masks use. The standard library caches the answer, so a
/// call costs a load and a test.
#[cfg(target_arch = "x86_64")]
fn has_avx2() -> bool {
    std::is_x86_feature_detected!("avx2")
        && std::is_x86_feature_detected!("bmi1")
        && std::is_x86_feature_detected!("bmi2")
        && std::is_x86_feature_detected!("lzcnt")
        && std::is_x86_feature_detected!("popcnt")
}
