//! The batch walk's step written in WebAssembly SIMD128 for builds with that feature.
//!
//! The package is built for size (`opt-level = "s"`), and at that level rustc runs neither
//! of LLVM's vectorizers, so the portable step's lane loops stay scalar there: eight lanes
//! one after another. Here each group of eight lanes is two `v128` halves, every operation
//! written as the intrinsic the portable step's loop vectorizes to elsewhere. The
//! operations are the same IEEE operations in the same order (a select, not `min`, for the
//! exit), so every lane's walk is bit for bit the portable one's, and so is every answer.

use core::arch::wasm32::{
    f32x4, f32x4_abs, f32x4_convert_i32x4, f32x4_gt, f32x4_le, f32x4_lt, f32x4_mul, f32x4_sub,
    i32x4, i32x4_add, i32x4_bitmask, i32x4_eq, i32x4_extract_lane, i32x4_splat, v128, v128_and,
    v128_andnot, v128_bitselect, v128_not, v128_or,
};

use super::{FACE, Group, LANES, MISS, SCALAR, WALKING};
use crate::tiles::face_kind::KIND_GENERAL;

/// Lanes `half * 4 ..` of a field, as one vector load.
#[inline(always)]
fn f32s(a: &[f32; LANES], half: usize) -> v128 {
    let o = 4 * half;
    f32x4(a[o], a[o + 1], a[o + 2], a[o + 3])
}

/// Lanes `half * 4 ..` of a field, as one vector load.
#[inline(always)]
fn i32s(a: &[i32; LANES], half: usize) -> v128 {
    let o = 4 * half;
    i32x4(a[o], a[o + 1], a[o + 2], a[o + 3])
}

/// Stores `v` to lanes `half * 4 ..` of a field, as one vector store.
#[inline(always)]
fn put(a: &mut [i32; LANES], half: usize, v: v128) {
    let o = 4 * half;
    a[o] = i32x4_extract_lane::<0>(v);
    a[o + 1] = i32x4_extract_lane::<1>(v);
    a[o + 2] = i32x4_extract_lane::<2>(v);
    a[o + 3] = i32x4_extract_lane::<3>(v);
}

/// The kind of the cell at `index` (general outside the map, as in the portable step).
#[inline(always)]
fn kind_at(kinds: &[u8], index: i32) -> i32 {
    kinds
        .get(index as usize)
        .map_or(i32::from(KIND_GENERAL), |&b| i32::from(b))
}

/// One step of every lane of `group` still walking: the portable `step`, line for line, on
/// two four-lane halves.
#[inline(always)]
pub(super) fn step(group: &mut Group, kinds: &[u8]) {
    half(group, kinds, 0);
    half(group, kinds, 1);
}

/// [`step`] for lanes `half * 4 ..`; `half` is a constant after inlining, so each field's
/// four lanes are one load and one store.
#[inline(always)]
fn half(group: &mut Group, kinds: &[u8], half: usize) {
    let o = 4 * half;
    let index = i32s(&group.index, half);
    let kind = i32x4(
        kind_at(kinds, group.index[o]),
        kind_at(kinds, group.index[o + 1]),
        kind_at(kinds, group.index[o + 2]),
        kind_at(kinds, group.index[o + 3]),
    );
    let line_x = i32s(&group.line_x, half);
    let line_y = i32s(&group.line_y, half);
    let tx = f32x4_mul(
        f32x4_sub(f32x4_convert_i32x4(line_x), f32s(&group.o_x, half)),
        f32s(&group.inv_x, half),
    );
    let ty = f32x4_mul(
        f32x4_sub(f32x4_convert_i32x4(line_y), f32s(&group.o_y, half)),
        f32s(&group.inv_y, half),
    );
    let x_first = f32x4_lt(tx, ty);
    let t_exit = v128_bitselect(tx, ty, x_first);
    let zero = i32x4_splat(0);
    let entered = i32s(&group.entered, half);
    let face = v128_not(i32x4_eq(
        v128_and(v128_and(kind, entered), i32x4_splat(0x0f)),
        zero,
    ));
    let general = v128_not(i32x4_eq(
        v128_and(kind, i32x4_splat(i32::from(KIND_GENERAL))),
        zero,
    ));
    let corner = f32x4_le(f32x4_abs(f32x4_sub(tx, ty)), f32s(&group.tol_t, half));
    let end = f32x4_gt(t_exit, f32s(&group.t_stop, half));
    let stopped = v128_or(
        v128_and(face, i32x4_splat(FACE)),
        v128_andnot(
            v128_or(
                v128_and(v128_or(general, corner), i32x4_splat(SCALAR)),
                v128_and(end, i32x4_splat(MISS)),
            ),
            face,
        ),
    );
    let status = i32s(&group.status, half);
    let walking = i32x4_eq(status, i32x4_splat(WALKING));
    put(
        &mut group.status,
        half,
        v128_or(status, v128_and(walking, stopped)),
    );
    let go = v128_and(walking, i32x4_eq(stopped, i32x4_splat(WALKING)));
    let go_x = v128_and(go, x_first);
    let go_y = v128_andnot(go, x_first);
    let index_step = v128_or(
        v128_and(go_x, i32s(&group.index_step_x, half)),
        v128_and(go_y, i32s(&group.index_step_y, half)),
    );
    put(&mut group.index, half, i32x4_add(index, index_step));
    put(
        &mut group.line_x,
        half,
        i32x4_add(line_x, v128_and(go_x, i32s(&group.step_x, half))),
    );
    put(
        &mut group.line_y,
        half,
        i32x4_add(line_y, v128_and(go_y, i32s(&group.step_y, half))),
    );
    put(
        &mut group.entered,
        half,
        v128_or(
            v128_or(
                v128_and(go_x, i32s(&group.enter_x, half)),
                v128_and(go_y, i32s(&group.enter_y, half)),
            ),
            v128_andnot(entered, go),
        ),
    );
}

/// Bit `k` set for each lane `k` whose status is `value`: a compare and a `bitmask` per
/// half (the portable version's byte packing and multiplication, unvectorized at
/// `opt-level = "s"`, cost more than the compare).
#[inline(always)]
pub(super) fn lanes_equal(status: &[i32; LANES], value: i32) -> u32 {
    let value = i32x4_splat(value);
    let low = i32x4_bitmask(i32x4_eq(i32s(status, 0), value));
    let high = i32x4_bitmask(i32x4_eq(i32s(status, 1), value));
    u32::from(low) | (u32::from(high) << 4)
}
