//! Whole-edge faces: the one-byte summary of a cell that lets the ray walk decide a hit on
//! a solid square's exposed faces without reading its segments, and the canonical form in
//! which the store keeps such cells' segments.

use glam::Vec2;

use super::SegmentFlags;
use super::store::HotSegment;

/// A cell's shape summary (`kinds`), read by the ray walk at every step: 0 for no active
/// segments, [`KIND_GENERAL`] for segments that must be tested one by one, or otherwise a
/// set of `FACE_*` bits: the cell's active segments are exactly those whole cell edges, each
/// facing straight out of the cell and flagged exactly [`SegmentFlags::SOLID`] (the
/// boundary of solid squares, by far the most common tile). A front-face ray entering such
/// a cell hits it exactly when it enters through one of those faces, so the walk decides
/// from this byte alone, without reading the segments.
pub(crate) const KIND_GENERAL: u8 = 0x80;
/// The edge `x = x0` (normal −x).
pub(crate) const FACE_MIN_X: u8 = 1;
/// The edge `x = x0 + w` (normal +x).
pub(crate) const FACE_MAX_X: u8 = 2;
/// The edge `y = y0` (normal −y).
pub(crate) const FACE_MIN_Y: u8 = 4;
/// The edge `y = y0 + h` (normal +y).
pub(crate) const FACE_MAX_Y: u8 = 8;

/// Slot of a `FACE_*` bit in the per-face tables below (bit order).
#[inline(always)]
fn face_slot(face: u8) -> usize {
    face.trailing_zeros() as usize & 3
}

/// Per face, in `FACE_*` bit order: its start and end point as fractions of the cell's size
/// (0 or 1, so scaling by the size is exact), running with the normal on the right.
const FACE_ENDS: [([f32; 2], [f32; 2]); 4] = [
    ([0.0, 1.0], [0.0, 0.0]),
    ([1.0, 0.0], [1.0, 1.0]),
    ([0.0, 0.0], [1.0, 0.0]),
    ([1.0, 1.0], [0.0, 1.0]),
];

/// Per face, in `FACE_*` bit order: its outward normal.
const FACE_NORMALS: [Vec2; 4] = [Vec2::NEG_X, Vec2::X, Vec2::NEG_Y, Vec2::Y];

/// The outward normal of a whole-edge face (a `FACE_*` bit). A table rather than a
/// `match`: which face a ray hits is a coin toss for the branch predictor.
#[inline(always)]
pub(crate) fn face_normal(face: u8) -> Vec2 {
    FACE_NORMALS[face_slot(face)]
}

/// The stored form of a whole-edge face of the cell with corner `base` and size `size`:
/// start point and `e = b − a`, running with the normal on the right like every active
/// segment. The store keeps face cells' segments exactly so (see `canonical_faces`) and the
/// ray walk recomputes them from the cell alone, with the same operations, so both agree
/// bit for bit.
#[inline(always)]
pub(crate) fn face_segment(base: Vec2, size: Vec2, face: u8) -> (Vec2, Vec2) {
    // A table rather than a `match` (see `face_normal`).
    let (fa, fb) = FACE_ENDS[face_slot(face)];
    let la = Vec2::new(fa[0] * size.x, fa[1] * size.y);
    let lb = Vec2::new(fb[0] * size.x, fb[1] * size.y);
    let (a, b) = (base + la, base + lb);
    (a, b - a)
}

/// Index of `face` among a face cell's segments, which are stored in `FACE_*` bit order.
#[inline(always)]
pub(crate) fn face_index(kind: u8, face: u8) -> u32 {
    // A table: x86-64's baseline has no popcount instruction.
    const BITS: [u8; 16] = [0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4];
    BITS[usize::from(kind & (face - 1) & 0x0f)].into()
}

/// Puts a face cell's segments (`kind` from [`kind_of`]) in the stored form: `FACE_*` bit
/// order, each as [`face_segment`] gives it.
pub(crate) fn canonical_faces(segments: &mut [HotSegment], kind: u8, base: Vec2, size: Vec2) {
    if kind == 0 || kind == KIND_GENERAL {
        return;
    }
    segments.sort_by_key(|s| face_bit(s.normal));
    for s in segments.iter_mut() {
        let (a, e) = face_segment(base, size, face_bit(s.normal));
        s.a = a;
        s.e = e;
    }
}

fn face_bit(normal: Vec2) -> u8 {
    if normal == Vec2::NEG_X {
        FACE_MIN_X
    } else if normal == Vec2::X {
        FACE_MAX_X
    } else if normal == Vec2::NEG_Y {
        FACE_MIN_Y
    } else {
        FACE_MAX_Y
    }
}

/// The `kinds` byte for a cell with corner `base` and size `size` holding `segments`.
pub(crate) fn kind_of(segments: &[HotSegment], base: Vec2, size: Vec2) -> u8 {
    if segments.is_empty() {
        return 0;
    }
    let (x0, y0) = (base.x, base.y);
    let (x1, y1) = (base.x + size.x, base.y + size.y);
    let faces = [
        (
            FACE_MIN_X,
            Vec2::new(x0, y0),
            Vec2::new(x0, y1),
            Vec2::NEG_X,
        ),
        (FACE_MAX_X, Vec2::new(x1, y0), Vec2::new(x1, y1), Vec2::X),
        (
            FACE_MIN_Y,
            Vec2::new(x0, y0),
            Vec2::new(x1, y0),
            Vec2::NEG_Y,
        ),
        (FACE_MAX_Y, Vec2::new(x0, y1), Vec2::new(x1, y1), Vec2::Y),
    ];
    let mut kind = 0;
    for s in segments {
        let (a, b) = (s.a, s.b());
        let face = faces.iter().find(|(_, p, q, n)| {
            s.normal == *n
                && s.flags == SegmentFlags::SOLID
                && ((a == *p && b == *q) || (a == *q && b == *p))
        });
        match face {
            Some((bit, ..)) if kind & bit == 0 => kind |= bit,
            _ => return KIND_GENERAL,
        }
    }
    kind
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn face_tables_give_the_bits_of_the_explicit_edges() {
        // The tables replaced a `match` on the face; stored maps (baked files included) hold
        // faces built by that form, so the two must agree bit for bit, also on corners that
        // are not exact in binary.
        let explicit = |base: Vec2, size: Vec2, face: u8| {
            let (la, lb) = match face {
                FACE_MIN_X => (Vec2::new(0.0, size.y), Vec2::ZERO),
                FACE_MAX_X => (Vec2::new(size.x, 0.0), size),
                FACE_MIN_Y => (Vec2::ZERO, Vec2::new(size.x, 0.0)),
                _ => (size, Vec2::new(0.0, size.y)),
            };
            let (a, b) = (base + la, base + lb);
            (a, b - a)
        };
        let normals = [Vec2::NEG_X, Vec2::X, Vec2::NEG_Y, Vec2::Y];
        for base in [Vec2::ZERO, Vec2::new(-7.3, 2.9), Vec2::new(1000.1, -0.1)] {
            for size in [Vec2::ONE, Vec2::new(0.3, 32.0)] {
                for (i, face) in [FACE_MIN_X, FACE_MAX_X, FACE_MIN_Y, FACE_MAX_Y]
                    .into_iter()
                    .enumerate()
                {
                    let (a, e) = face_segment(base, size, face);
                    let (xa, xe) = explicit(base, size, face);
                    let bits = |v: Vec2| (v.x.to_bits(), v.y.to_bits());
                    assert_eq!((bits(a), bits(e)), (bits(xa), bits(xe)), "face {face}");
                    assert_eq!(face_normal(face), normals[i]);
                }
            }
        }
    }

    #[test]
    fn whole_solid_cell_edges_are_summarised_as_faces() {
        let base = Vec2::new(3.0, 5.0);
        let edge = |a: Vec2, b: Vec2, normal: Vec2| HotSegment {
            a: base + a,
            e: b - a,
            normal,
            flags: SegmentFlags::SOLID,
            source: 0,
            count: 0,
        };
        let left = edge(Vec2::new(0.0, 1.0), Vec2::new(0.0, 0.0), Vec2::NEG_X);
        let top = edge(Vec2::new(1.0, 1.0), Vec2::new(0.0, 1.0), Vec2::Y);
        assert_eq!(
            kind_of(&[left, top], base, Vec2::ONE),
            FACE_MIN_X | FACE_MAX_Y
        );
        assert_eq!(kind_of(&[], base, Vec2::ONE), 0);
        // A one-way edge, a half edge or a slanted normal needs the general test.
        let one_way = HotSegment {
            flags: SegmentFlags::ONE_WAY,
            ..top
        };
        assert_eq!(kind_of(&[left, one_way], base, Vec2::ONE), KIND_GENERAL);
        let half = HotSegment {
            e: Vec2::new(0.0, -0.5),
            ..left
        };
        assert_eq!(kind_of(&[half], base, Vec2::ONE), KIND_GENERAL);
        let slanted = HotSegment {
            normal: Vec2::new(-0.6, 0.8),
            ..left
        };
        assert_eq!(kind_of(&[slanted], base, Vec2::ONE), KIND_GENERAL);
        assert_eq!(kind_of(&[left, left], base, Vec2::ONE), KIND_GENERAL);
    }
}
