//! The coordinates of the `f64` engine (docs/model.md §10): the heights and normal velocities of
//! the last three distinct contacts to land. Small bodies (n ≤ [`TABLE_CONTACTS`]) keep every
//! frame in a table; larger ones (up to 64 contacts: 249,984 frames) compute the one they need
//! when the frame changes, in O(n).

use super::system::{FloatSystem, System};
use crate::exact::{Q, QExt, Ring};
use chatter_kernel::model::linalg::{Vec3, dot};
use nalgebra::Matrix3;

/// Bodies with at most this many contacts keep all their frames in a table.
pub const TABLE_CONTACTS: usize = 6;

/// The index of the frame with contacts (a, b, c) in [`FloatSystem::frames`].
#[inline]
pub fn frame_index(slots: [usize; 3]) -> usize {
    (slots[0] * TABLE_CONTACTS + slots[1]) * TABLE_CONTACTS + slots[2]
}

/// Coordinates of the `f64` engine: the heights (h_s0, h_s1, h_s2) and normal velocities of three
/// contacts (for the rod (h0, h1, 0)), with every quantity the engine needs expressed in them.
///
/// The engine keeps the last three distinct contacts to land as the frame. When a contact outside
/// it lands, it replaces the one that landed longest ago: the two kept coordinates are copied
/// unchanged and the new one is h = 0, u = -γ u⁻ exactly, so a change of frame costs nothing and
/// loses nothing. Heights and velocities of chattering contacts are then always coordinates, not
/// differences of O(1) numbers, and keep their relative precision however small they become
/// next to the rest of the state (docs/model.md §10).
#[derive(Clone, Debug, Default)]
pub struct Frame {
    /// The contacts whose heights are the coordinates (slot 2 unused for the rod).
    pub slots: [usize; 3],
    /// Contact covectors: u_k = `f[k]`·p, h_k = `f[k]`·q in this frame (n entries).
    pub f: Vec<[f64; 3]>,
    /// Impact kicks in this frame.
    pub kick: Vec<[f64; 3]>,
    /// Copies of `f` and `kick` stored inline for bodies with at most [`TABLE_CONTACTS`]
    /// contacts: the hot loop then reads them without following a pointer.
    pub inline_f: [[f64; 3]; TABLE_CONTACTS],
    pub inline_kick: [[f64; 3]; TABLE_CONTACTS],
    pub inline_slot: [u8; TABLE_CONTACTS],
    /// Centre covector (v, hc).
    pub centre: [f64; 3],
    /// Energy Gram matrix.
    pub gram: [[f64; 3]; 3],
    /// This frame to our coordinates.
    pub to_ours: [[f64; 3]; 3],
    /// Our coordinates to this frame.
    pub from_ours: [[f64; 3]; 3],
    /// `slot[k]`: the slot holding contact k, or 3.
    pub slot: Vec<u8>,
}

/// Copies the first entries of `v` into an inline array (zeros beyond them).
fn inline(v: &[[f64; 3]]) -> [[f64; 3]; TABLE_CONTACTS] {
    std::array::from_fn(|k| v.get(k).copied().unwrap_or_default())
}

impl Frame {
    /// The table of every frame of three distinct contacts of an n-gon (n ≤ [`TABLE_CONTACTS`]).
    pub fn table(n: usize, build: impl Fn([usize; 3]) -> Frame) -> Vec<Frame> {
        assert!(n <= TABLE_CONTACTS, "frame tables are for n <= {TABLE_CONTACTS}");
        let mut frames = vec![Frame::default(); TABLE_CONTACTS.pow(3)];
        for a in 0..n {
            for b in (0..n).filter(|&b| b != a) {
                for c in (0..n).filter(|&c| c != a && c != b) {
                    frames[frame_index([a, b, c])] = build([a, b, c]);
                }
            }
        }
        frames
    }

    /// The frame computed exactly from the rational model, then rounded.
    pub fn new(sys: &System, slots: [usize; 3]) -> Frame {
        let v3 = |v: &Vec3<Q>| v.clone().map(|x| x.to_f64());
        let m3 = |m: &[[Q; 3]; 3]| m.clone().map(|r| r.map(|x| x.to_f64()));
        let a = sys.frame_matrix(slots);
        let b = inverse3(&a).expect("three vertices of a convex polygon are not collinear");
        let mut fr = Frame {
            slots,
            centre: v3(&row_times(&sys.centre, &b)),
            gram: m3(&mat_mul3(&transpose3(&b), &mat_mul3(&sys.gram, &b))),
            to_ours: m3(&b),
            from_ours: m3(&a),
            slot: vec![3; sys.n()],
            f: sys.contacts.iter().map(|f| v3(&row_times(f, &b))).collect(),
            kick: sys.kicks.iter().map(|k| v3(&mat_times(&a, k))).collect(),
            ..Frame::default()
        };
        for (i, &k) in slots[..sys.shape.dim()].iter().enumerate() {
            fr.slot[k] = i as u8;
        }
        fr.fill_inline();
        fr
    }

    /// Copies the first [`TABLE_CONTACTS`] covectors, kicks and slots inline.
    fn fill_inline(&mut self) {
        (self.inline_f, self.inline_kick) = (inline(&self.f), inline(&self.kick));
        self.inline_slot = std::array::from_fn(|k| self.slot.get(k).copied().unwrap_or(3));
    }

    /// The frame of a polygon computed in `f64` from its float copy.
    pub fn from_float(fs: &FloatSystem, slots: [usize; 3]) -> Frame {
        let mut fr = Frame::default();
        fr.refill(fs, slots);
        fr
    }

    /// Recomputes this frame in place for other `slots` of a polygon (no allocation once sized):
    /// A = [f_s0; f_s1; f_s2], f'_k = f_k A⁻¹, kick'_k = A kick_k, G' = A⁻ᵀ G A⁻¹. The covectors
    /// of the frame's own contacts are set to unit vectors exactly, so that their heights and
    /// velocities are coordinates, as in the exact frames.
    pub fn refill(&mut self, fs: &FloatSystem, slots: [usize; 3]) {
        let m = |x: &[[f64; 3]; 3]| Matrix3::from_fn(|r, c| x[r][c]);
        let arr = |x: &Matrix3<f64>| -> [[f64; 3]; 3] {
            std::array::from_fn(|r| std::array::from_fn(|c| x[(r, c)]))
        };
        let a = m(&slots.map(|k| fs.f[k]));
        let b = a.try_inverse().expect("three vertices of a convex polygon are not collinear");
        let row = |v: &[f64; 3]| -> [f64; 3] {
            std::array::from_fn(|c| v[0] * b[(0, c)] + v[1] * b[(1, c)] + v[2] * b[(2, c)])
        };
        let col = |v: &[f64; 3]| -> [f64; 3] {
            std::array::from_fn(|r| a[(r, 0)] * v[0] + a[(r, 1)] * v[1] + a[(r, 2)] * v[2])
        };
        self.slots = slots;
        self.centre = row(&fs.centre);
        self.gram = arr(&(b.transpose() * m(&fs.gram) * b));
        self.to_ours = arr(&b);
        self.from_ours = arr(&a);
        self.f.clear();
        self.f.extend(fs.f.iter().map(row));
        self.kick.clear();
        self.kick.extend(fs.kick.iter().map(col));
        self.slot.clear();
        self.slot.resize(fs.n, 3);
        for (i, &k) in slots.iter().enumerate() {
            self.slot[k] = i as u8;
            self.f[k] = std::array::from_fn(|c| if c == i { 1.0 } else { 0.0 });
        }
        if fs.n <= TABLE_CONTACTS {
            self.fill_inline();
        }
    }
}

fn row_times(r: &Vec3<Q>, m: &[[Q; 3]; 3]) -> Vec3<Q> {
    std::array::from_fn(|c| &(&(&r[0] * &m[0][c]) + &(&r[1] * &m[1][c])) + &(&r[2] * &m[2][c]))
}

fn mat_times(m: &[[Q; 3]; 3], x: &Vec3<Q>) -> Vec3<Q> {
    std::array::from_fn(|r| dot(&m[r], x))
}

fn transpose3(m: &[[Q; 3]; 3]) -> [[Q; 3]; 3] {
    std::array::from_fn(|r| std::array::from_fn(|c| m[c][r].clone()))
}

fn mat_mul3(a: &[[Q; 3]; 3], b: &[[Q; 3]; 3]) -> [[Q; 3]; 3] {
    std::array::from_fn(|r| row_times(&a[r], b))
}

/// The exact inverse of a 3x3 matrix (adjugate over determinant), `None` if singular.
fn inverse3(m: &[[Q; 3]; 3]) -> Option<[[Q; 3]; 3]> {
    let det = chatter_kernel::model::linalg::det3(&m[0], &m[1], &m[2]);
    if det.is_zero() {
        return None;
    }
    let cof = |r: usize, c: usize| {
        let (r1, r2) = ((r + 1) % 3, (r + 2) % 3);
        let (c1, c2) = ((c + 1) % 3, (c + 2) % 3);
        &(&m[r1][c1] * &m[r2][c2]) - &(&m[r1][c2] * &m[r2][c1])
    };
    Some(std::array::from_fn(|r| std::array::from_fn(|c| &cof(c, r) / &det)))
}
