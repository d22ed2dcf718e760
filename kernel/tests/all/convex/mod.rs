//! Tests of `chatter_kernel::model::ConvexBody` (docs/model.md §11), one file per source file of
//! `kernel/src/model/convex/` (the affine images, the pair PCC quadratic in floats and the
//! reduction to the regular polygons are tested with the tool, in tests/all/kernel/convex).
//! Shared here: exact random bodies and an independent statement of the kinematics (heights and
//! speeds of the contacts straight from their coordinates, never through the kernel).
#![cfg(feature = "family")]

mod cones;
mod impact;
mod interval;
mod shape;

use chatter_kernel::model::linalg::Vec3;
use chatter_kernel::model::{ConvexBody, Mat2, Vec2};
use malachite::base::num::arithmetic::traits::Abs;
use malachite::rational::Rational as Q;
use proptest::prelude::*;

/// A small deterministic generator for many samples inside one proptest case.
pub struct Rng(u64);

impl Rng {
    /// The generator seeded with `seed`.
    pub fn new(seed: u64) -> Self {
        Rng(seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407) | 1)
    }

    /// The next 64 random bits.
    pub fn bits(&mut self) -> u64 {
        // xorshift64*
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545F4914F6CDD1D)
    }

    /// An integer in [lo, hi].
    pub fn int(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.bits() % (hi - lo + 1) as u64) as i64
    }

    /// A rational a/b with a in [lo, hi], b in [1, den].
    pub fn ratio(&mut self, lo: i64, hi: i64, den: i64) -> Q {
        let a = self.int(lo, hi);
        let b = self.int(1, den);
        Q::from_signeds(a, b)
    }
}

/// (b - a) x (c - a): positive when a, b, c turn counter-clockwise.
fn orient(a: &Vec2<Q>, b: &Vec2<Q>, c: &Vec2<Q>) -> Q {
    (&b[0] - &a[0]) * (&c[1] - &a[1]) - (&b[1] - &a[1]) * (&c[0] - &a[0])
}

/// Strict convex hull (no collinear points), counter-clockwise (Andrew's monotone chain).
pub fn hull(mut pts: Vec<Vec2<Q>>) -> Vec<Vec2<Q>> {
    pts.sort();
    pts.dedup();
    if pts.len() < 3 {
        return pts;
    }
    let mut h: Vec<Vec2<Q>> = Vec::new();
    for pass in [pts.clone(), pts.iter().rev().cloned().collect()] {
        let start = h.len();
        for p in pass {
            while h.len() >= start + 2 && orient(&h[h.len() - 2], &h[h.len() - 1], &p) <= 0 {
                h.pop();
            }
            h.push(p);
        }
        h.pop();
    }
    h
}

/// The vertex mean, strictly inside a convex polygon with at least three vertices.
pub fn centre(pts: &[Vec2<Q>]) -> Vec2<Q> {
    let n = Q::from(pts.len() as i64);
    let sx = pts.iter().fold(Q::from(0), |a, p| a + &p[0]);
    let sy = pts.iter().fold(Q::from(0), |a, p| a + &p[1]);
    [sx / &n, sy / &n]
}

/// The data of an exact random body: the strict hull of `raw` (integers over `den`), shifted so
/// that the vertex mean is the origin, rotated so that contact `start` comes first; inertia
/// [[a, b], [b, c]] / 4 (made positive definite); gamma.
pub fn random_body(
    raw: &[(i64, i64)],
    den: i64,
    start: usize,
    j: (i64, i64, i64),
    gamma: Q,
) -> Option<ConvexBody<Q>> {
    let pts = hull(raw.iter().map(|&(x, y)| [Q::from_signeds(x, den), Q::from_signeds(y, den)]).collect());
    if pts.len() < 3 {
        return None;
    }
    let c = centre(&pts);
    let n = pts.len();
    let shifted: Vec<Vec2<Q>> =
        (0..n).map(|k| &pts[(k + start) % n]).map(|p| [&p[0] - &c[0], &p[1] - &c[1]]).collect();
    let (a, b, d) = (Q::from_signeds(j.0, 4), Q::from_signeds(j.1, 4), Q::from_signeds(j.2, 4));
    // Make it positive definite: raise the diagonal above |b|.
    let a = (&a).abs() + (&b).abs() + Q::from_signeds(1, 10);
    let d = (&d).abs() + (&b).abs() + Q::from_signeds(1, 10);
    let inertia: Mat2<Q> = [[a, b.clone()], [b, d]];
    Some(
        ConvexBody::new(shifted, inertia, gamma)
            .expect("a strict hull around its vertex mean is a valid body"),
    )
}

/// Strategy for random bodies with 3 to 8 contacts, every inertia and gamma in [0, 1].
pub fn bodies() -> impl Strategy<Value = ConvexBody<Q>> {
    let pts = prop::collection::vec((-12i64..=12, -12i64..=12), 3..9);
    (pts, 1i64..=5, 0usize..8, (-20i64..=20, -20i64..=20, -20i64..=20), 0i64..=20)
        .prop_filter_map("at least three hull vertices", |(raw, den, start, j, g)| {
            random_body(&raw, den, start, j, Q::from_signeds(g, 20))
        })
}

/// The height of contact point r for the configuration q = (phi_x, phi_y, h) (or its speed for
/// a velocity p = (omega_x, omega_y, v)): h + phi_x y - phi_y x, the vertical component of
/// h e_z + phi x r for a small rotation phi (the paper's linearised kinematics).
pub fn height(r: &Vec2<Q>, q: &Vec3<Q>) -> Q {
    &q[2] + &q[0] * &r[1] - &q[1] * &r[0]
}

/// Whether l . p >= 0 for every covector.
pub fn inside(cov: &[Vec3<Q>], p: &Vec3<Q>) -> bool {
    cov.iter().all(|l| chatter_kernel::model::linalg::dot(l, p) >= 0)
}

/// A few fixed irregular bodies (triangle, quadrilateral, pentagon), for deterministic tests.
pub fn fixed_bodies() -> Vec<ConvexBody<Q>> {
    let r =
        |pts: &[(i64, i64)], den, j, g| random_body(pts, den, 0, j, Q::from_signeds(g, 10)).expect("valid");
    vec![
        r(&[(5, -1), (1, 7), (-6, -2)], 3, (3, 1, 7), 3),
        r(&[(4, -3), (6, 2), (-1, 5), (-7, -1)], 2, (2, -3, 5), 1),
        r(&[(9, 0), (3, 6), (-4, 5), (-6, -3), (2, -7)], 5, (8, 2, 1), 7),
    ]
}
