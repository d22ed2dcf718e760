//! The exact search for the rod (n = 2; untrusted, but exact: no float search is needed in one
//! dimension). On the line v = -1/2 a velocity (u0, u1) with w = -(u0 + u1) > 0 is the number
//! s = u0 / w; a cone is an interval [lo, hi] of s, C_1 is s >= 0 and the relabelling R maps s to
//! -1 - s.
//!
//! Two methods, the first that gives an invariant interval containing the seeds wins:
//! 1. the paper's cone (proof of its Theorem after Goyal et al.): K = cone(p_min, P p_min), with
//!    p_min the eigenvector of S_1 for its smaller eigenvalue and P p_min = R p_min, whenever the
//!    eigenvalues are rational (always so on Goyal's boundary, where they coincide);
//! 2. exact interval iteration: grow [lo, hi] by the images of the ends of K ∩ C_1, with a small
//!    outward slack so that it stops when the orbit converges to the attracting eigenvector.

use super::{FinderConfig, Search};
use crate::exact::{Field, Q, QExt, Ring};
use chatter_kernel::model::{Mat2, Rod, Vec2, mat2_vec};
use malachite::Natural;
use malachite::base::num::arithmetic::traits::{CheckedSqrt, UnsignedAbs};

/// An invariant interval [lo, hi] of s = u0 / (-(u0 + u1)), and how it was found.
#[derive(Clone, Debug, PartialEq)]
pub struct RodCone {
    pub lo: Q,
    pub hi: Q,
    pub method: &'static str,
}

impl RodCone {
    /// The two generators (u0, u1) of the cone, on the line v = -1 (u0 + u1 = -2).
    pub fn generators(&self) -> [Vec2<Q>; 2] {
        [&self.lo, &self.hi].map(|s| [s * &Q::int(2), (s + &Q::int(1)) * &Q::int(-2)])
    }
}

/// s = u0 / w of a velocity, if w = -(u0 + u1) > 0.
pub fn s_of(p: &Vec2<Q>) -> Option<Q> {
    let w = -(&p[0] + &p[1]);
    w.is_positive().then(|| &p[0] / &w)
}

/// The velocity (s, -1 - s) with w = 1.
fn ray(s: &Q) -> Vec2<Q> {
    [s.clone(), -(s + &Q::int(1))]
}

/// The images under S_1 of the ends of K ∩ C_1 for K = [lo, hi] (`None` for an image with
/// v >= 0 that is not zero; a zero image is at rest and fits every cone).
fn piece_images(step: &Mat2<Q>, lo: &Q, hi: &Q) -> Option<Vec<Q>> {
    if hi.is_negative() {
        return Some(Vec::new());
    }
    let ends = [if lo.is_negative() { Q::int(0) } else { lo.clone() }, hi.clone()];
    let mut out = Vec::new();
    for e in ends {
        let img = mat2_vec(step, &ray(&e));
        if img.iter().all(Ring::is_zero) {
            continue;
        }
        out.push(s_of(&img)?);
    }
    Some(out)
}

/// Whether [lo, hi] (lo < hi) contains the seeds and is invariant under every step, exactly.
fn invariant(steps: &[Mat2<Q>], lo: &Q, hi: &Q, seeds: &[Q]) -> bool {
    let inside = |s: &Q| lo <= s && s <= hi;
    let images_inside = |step| piece_images(step, lo, hi).is_some_and(|v| v.iter().all(inside));
    lo < hi && seeds.iter().all(inside) && steps.iter().all(images_inside)
}

/// The square root of a non-negative rational, if it is rational.
fn rational_sqrt(x: &Q) -> Option<Q> {
    let root = |z: &malachite::Integer| -> Option<Natural> { z.unsigned_abs().checked_sqrt() };
    let (n, d) = (root(&x.numer())?, root(&x.denom())?);
    Some(Q::from_rational(malachite::rational::Rational::from_naturals(n, d)))
}

/// Method 1: the paper's cone cone(p_min, R p_min) of `step` when S_1 has rational eigenvalues,
/// if it is invariant under every one of `steps` (the corners of a box; `step` is one of them).
fn paper_cone(step: &Mat2<Q>, steps: &[Mat2<Q>], seeds: &[Q]) -> Option<RodCone> {
    let [[a, b], [c, d]] = step;
    let disc = &(&(a - d) * &(a - d)) + &(&Q::int(4) * &(b * c));
    if disc.is_negative() {
        return None;
    }
    let lambda = (&(a + d) - &rational_sqrt(&disc)?) / Q::int(2);
    // An eigenvector: (b, lambda - a), or (lambda - d, c) when that one is zero.
    let p = if b.is_zero() && (&lambda - a).is_zero() {
        [&lambda - d, c.clone()]
    } else {
        [b.clone(), &lambda - a]
    };
    let s = s_of(&p).or_else(|| s_of(&[-&p[0], -&p[1]]))?;
    let (x, y) = (s.clone(), -(&s + &Q::int(1)));
    let (lo, hi) = if x < y { (x, y) } else { (y, x) };
    invariant(steps, &lo, &hi, seeds).then_some(RodCone {
        lo,
        hi,
        method: "exact eigenvectors: the paper's two-ray cone {p_min, R p_min}",
    })
}

/// Method 2: exact interval iteration with outward slack (dyadic ends), under every step.
fn iterate(steps: &[Mat2<Q>], seeds: &[Q], cfg: &FinderConfig) -> Search<RodCone> {
    let (mut lo, mut hi) =
        (seeds.iter().min().expect("a seed").clone(), seeds.iter().max().expect("a seed").clone());
    for it in 0..cfg.max_iterations {
        let Some(images) = steps.iter().map(|s| piece_images(s, &lo, &hi)).collect::<Option<Vec<_>>>() else {
            return Search::NoCone { iteration: it, step: 1 };
        };
        let images: Vec<Q> = images.into_iter().flatten().collect();
        let mut grew = false;
        for s in images {
            // A grown end goes a little beyond the image (the orbit approaches the attracting
            // eigenvector from inside and would never stop), rounded outwards to a dyadic.
            let slack = (&hi - &lo + s.abs()) * Q::new(1, 1 << 20);
            if s < lo {
                lo = (&s - &slack).floor_dyadic(40);
                grew = true;
            } else if s > hi {
                hi = (&s + &slack).ceil_dyadic(40);
                grew = true;
            }
        }
        if !grew && lo < hi {
            return Search::Found {
                cone: RodCone { lo, hi, method: "exact interval iteration" },
                iterations: it,
            };
        }
        if !grew {
            // A single ray (a fixed point): widen to a proper interval and continue.
            hi = &hi + &Q::new(1, 1 << 20);
        }
    }
    let reason =
        format!("the exact interval iteration did not settle within {} iterations", cfg.max_iterations);
    Search::Inconclusive { iterations: cfg.max_iterations, reason }
}

/// Searches an invariant interval containing the seeds (given as values of s; at least one).
pub fn find_rod_cone(rod: &Rod<Q>, seeds: &[Q], cfg: &FinderConfig) -> Search<RodCone> {
    find_rod_cone_box(std::slice::from_ref(rod), seeds, cfg)
}

/// Searches an interval invariant under the rod's maps at every one of `rods` (the corners of a
/// box of parameters, docs/kernel-soundness.md §2 "Boxes") and containing the seeds.
pub fn find_rod_cone_box(rods: &[Rod<Q>], seeds: &[Q], cfg: &FinderConfig) -> Search<RodCone> {
    let steps: Vec<Mat2<Q>> = rods.iter().map(Rod::step).collect();
    match steps.iter().find_map(|step| paper_cone(step, &steps, seeds)) {
        Some(cone) => Search::Found { cone, iterations: 0 },
        None => iterate(&steps, seeds, cfg),
    }
}
