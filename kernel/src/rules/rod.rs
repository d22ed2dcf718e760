//! Cone certificates of the rod, n = 2 (docs/certificate-format.md §8). A generator (u0, u1)
//! with w = -(u0 + u1) = -2v > 0 projects to s = u0 / w; K is the interval between the extreme
//! generators. Rules, in the order they are checked:
//!
//! - range of γ: the claims about drops need 0 < γ < 1 (`parameter-out-of-range`);
//! - R1: two coordinates per generator (`wrong-arity`), every generator has v < 0
//!   (`generator-not-below`), and K has two distinct rays (`degenerate-cone`);
//! - R2: S_1(K ∩ C_1) ⊆ K on the ends of the piece K ∩ C_1 (`image-not-below`, `image-outside`);
//! - R3 (`CcOrPccFromAllDown` and stronger): I_0(D) ⊆ K on the generators of D
//!   (`initial-outside`);
//! - R4 holds trivially: with two contacts PCC is CC;
//! - T1 (optional field `time_to_rest_bound` B, claims about drops): 0 < κ < 1, Δ = σ² − 4γ ≥ 0
//!   with σ = (1 + γ)(1 − κ)/(1 + κ), and 1/B ≤ λ_1, the larger root of λ² − σλ + γ
//!   (`time-to-rest-not-shown`); then every all-down drop comes to rest by T ≤ B h/|v|
//!   (docs/time-to-rest.md §2).

use super::body::{body_error, gamma_range};
use super::generators::{self, Generators};
use super::outcome::Accepted;
use crate::exact::{Field, ParseLimits, Ring, scale_to_ints};
use crate::model::rod::{Mat2, Rod, Vec2, mat2_vec};
use crate::reject::{Boundary, Code, Detail, ImageFailure, Locus, Rejection, TimeToRestFailure};
use crate::syntax::cone::{Certificate, Claim};
use crate::syntax::numbers::{in_time, number};
use std::cmp::Ordering;

/// Rules R1 to R3 for a rod at one point (`kappa`, `gamma`: the body's parameters as written).
pub fn check_point<F: Field>(
    cert: &Certificate,
    [k, g]: [&str; 2],
    limits: ParseLimits,
) -> Result<Accepted, Rejection> {
    let kappa: F = number("body.kappa", k, limits)?;
    let gamma: F = number("body.gamma", g, limits)?;
    let rod = Rod::new(kappa, gamma).map_err(|e| body_error(e, "body.kappa", "body.gamma"))?;
    gamma_range(rod.gamma(), "body.gamma", cert.claim)?;
    let gens = generators::read::<F>(&cert.cone, &["u0", "u1"], |i| format!("cone[{i}]"), limits)?;
    let k = interval::<F>(&gens)?;
    in_time(limits, "building K")?;
    let piece = piece(&rod, &k);
    invariance(&rod, &k, &piece)?;
    if cert.claim >= Claim::CcOrPccFromAllDown {
        all_down(&rod, &k)?;
    }
    let mut a = accepted(&[&rod], &k, &gens, cert.claim, &piece);
    if let Some(b) = &cert.time_to_rest_bound {
        a.time_to_rest_bound = Some(time_to_rest::<F>(b, rod.kappa(), rod.gamma(), cert.claim, limits)?);
    }
    Ok(a)
}

/// Rule T1 (docs/time-to-rest.md §2, Theorem): B is shown when 0 < κ < 1, σ² − 4γ ≥ 0 and
/// 1/B ≤ λ_1, i.e. 1/B ≤ σ/2 or q(1/B) ≤ 0 with q(x) = x² − σx + γ (q increases beyond σ/2 and
/// vanishes at λ_1). Returns B as canonical text.
pub fn time_to_rest<F: Field>(
    b: &str,
    kappa: &F,
    gamma: &F,
    claim: Claim,
    limits: ParseLimits,
) -> Result<String, Rejection> {
    let fail = |why| {
        Err(Rejection::at(Code::TimeToRestNotShown, "time_to_rest_bound", Detail::TimeToRest(why, b.into())))
    };
    let bound: F = number("time_to_rest_bound", b, limits)?;
    if claim < Claim::CcOrPccFromAllDown {
        return fail(TimeToRestFailure::Claim);
    }
    if !bound.is_positive() {
        return fail(TimeToRestFailure::NotPositive);
    }
    // σ = s/d with s = (1 + γ)(1 − κ) and d = 1 + κ > 0; every test is multiplied by a power of
    // d > 0 and of B > 0, so no division is needed.
    let one = F::from_ratio(1, 1);
    let d = one.plus(kappa);
    let s = one.plus(gamma).times(&one.minus(kappa));
    if !s.is_positive() {
        return fail(TimeToRestFailure::SigmaNotPositive);
    }
    // σ² − 4γ ≥ 0  ⇔  s² − 4γd² ≥ 0.
    if s.times(&s).minus(&F::from_ratio(4, 1).times(gamma).times(&d).times(&d)).is_negative() {
        return fail(TimeToRestFailure::ComplexRoots);
    }
    // 1/B ≤ σ/2 ⇔ 2d ≤ sB;  q(1/B) ≤ 0 ⇔ d − sB + γdB² ≤ 0.
    let sb = s.times(&bound);
    let below_half = !d.times(&F::from_ratio(2, 1)).minus(&sb).is_positive();
    let q = d.minus(&sb).plus(&gamma.times(&d).times(&bound).times(&bound));
    if !below_half && q.is_positive() {
        return fail(TimeToRestFailure::TooSmall);
    }
    Ok(crate::exact::to_canonical(&bound))
}

/// K = [a, b] in s, with the indices of its end generators.
pub struct Interval<Z> {
    ends: [Vec2<Z>; 2],
    index: [usize; 2],
}

/// w = -(u0 + u1) = -2v, positive below the floor's plane.
fn w<Z: Ring>(g: &Vec2<Z>) -> Z {
    g[0].plus(&g[1]).negated()
}

/// Compares s = u0 / w of two points with w > 0: a0 w(b) against b0 w(a).
fn cmp<Z: Ring>(a: &Vec2<Z>, b: &Vec2<Z>) -> Ordering {
    a[0].times(&w(b)).cmp(&b[0].times(&w(a)))
}

impl<Z: Ring> Interval<Z> {
    fn contains(&self, q: &Vec2<Z>) -> bool {
        cmp(&self.ends[0], q) != Ordering::Greater && cmp(q, &self.ends[1]) != Ordering::Greater
    }
}

/// R1: every generator below, and two distinct rays.
pub fn interval<F: Field>(gens: &Generators<'_, F::Int>) -> Result<Interval<F::Int>, Rejection> {
    let v: Vec<Vec2<F::Int>> = gens.vectors.iter().map(|g| [g[0].clone(), g[1].clone()]).collect();
    if let Some(i) = v.iter().position(|g| !w(g).is_positive()) {
        let detail = Detail::NotBelow(gens.written[i].0.clone());
        return Err(Rejection::new(Code::GeneratorNotBelow, Locus::Generator { index: i }, detail));
    }
    let lo = (0..v.len()).min_by(|&i, &j| cmp(&v[i], &v[j]).then(i.cmp(&j)));
    let hi = (0..v.len()).max_by(|&i, &j| cmp(&v[i], &v[j]).then(j.cmp(&i)));
    match (lo, hi) {
        (Some(lo), Some(hi)) if cmp(&v[lo], &v[hi]) != Ordering::Equal => {
            Ok(Interval { ends: [v[lo].clone(), v[hi].clone()], index: [lo, hi] })
        }
        _ => {
            let detail = Detail::Degenerate(v.len(), usize::from(!v.is_empty()), 2);
            Err(Rejection::new(Code::DegenerateCone, Locus::Cone, detail))
        }
    }
}

/// The piece K ∩ C_1: K clipped by the rod's two covectors of C_1 (C_1 does not depend on kappa
/// or gamma). On a segment [a, b] crossing l = 0 the crossing is (l.a) b - (l.b) a (times the
/// sign of l.a), a positive combination of a and b.
pub fn piece<F: Field>(rod: &Rod<F>, k: &Interval<F::Int>) -> Vec<Vec2<F::Int>> {
    let clip = |seg: Vec<Vec2<F::Int>>, l: &Vec2<F::Int>| {
        let d: Vec<F::Int> = seg.iter().map(|p| l[0].times(&p[0]).plus(&l[1].times(&p[1]))).collect();
        let mut out = Vec::new();
        for (i, p) in seg.iter().enumerate() {
            if !d[i].is_negative() {
                out.push(p.clone());
            }
            if i + 1 < seg.len() && d[i].sign() != Ordering::Equal && d[i + 1].sign() == d[i].sign().reverse()
            {
                let x: Vec2<F::Int> =
                    std::array::from_fn(|c| d[i].times(&seg[i + 1][c]).minus(&d[i + 1].times(&p[c])));
                out.push(if d[i].is_negative() { x.map(|c| c.negated()) } else { x });
            }
        }
        out
    };
    rod.next_contact_cone().iter().fold(k.ends.to_vec(), |seg, l| clip(seg, &int_vec(l)))
}

/// R2 at one body: S_1 maps the ends of the piece into K.
pub fn invariance<F: Field>(
    rod: &Rod<F>,
    k: &Interval<F::Int>,
    piece: &[Vec2<F::Int>],
) -> Result<(), Rejection> {
    let step = int_mat(&rod.step());
    for (i, p) in piece.iter().enumerate() {
        let locus = |outside| Locus::Piece { piece: 1, vertex: i, outside, corner: None };
        check_image::<F>(k, p, &mat2_vec(&step, p), &locus, [Code::ImageOutside, Code::ImageNotBelow])?;
    }
    Ok(())
}

/// R3 at one body: I_0 maps the generators of D into K.
pub fn all_down<F: Field>(rod: &Rod<F>, k: &Interval<F::Int>) -> Result<(), Rejection> {
    let i0 = int_mat(&rod.impact(0));
    for (m, g) in rod.all_down_generators().iter().enumerate() {
        let g = int_vec(g);
        let locus = |outside| Locus::AllDown { generator: m, outside, corner: None };
        check_image::<F>(k, &g, &mat2_vec(&i0, &g), &locus, [Code::InitialOutside; 2])?;
    }
    Ok(())
}

/// Checks that the image `img` of `point` is 0, or has v < 0 and lies in K; `codes` are those
/// of an image outside K and of one with v >= 0.
fn check_image<F: Field>(
    k: &Interval<F::Int>,
    point: &Vec2<F::Int>,
    img: &Vec2<F::Int>,
    locus: &dyn Fn(Option<Boundary>) -> Locus,
    codes: [Code; 2],
) -> Result<(), Rejection> {
    if img.iter().all(Ring::is_zero) || (w(img).is_positive() && k.contains(img)) {
        return Ok(());
    }
    let mut failure =
        ImageFailure { n: 2, point: shown::<F>(point), image: None, v_zero: false, by: None, corner: None };
    if !w(img).is_positive() {
        return Err(Rejection::new(codes[1], locus(None), Detail::Image(Box::new(failure))));
    }
    let end = usize::from(cmp(img, &k.ends[0]) != Ordering::Less);
    let s = |g: &Vec2<F::Int>| F::from_int(&g[0]).over(&F::from_int(&w(g)));
    failure.by = s(img).zip(s(&k.ends[end])).map(|(a, b)| crate::exact::to_canonical(&a.minus(&b)));
    failure.image = Some(shown::<F>(img));
    let boundary = Boundary::End { generator: k.index[end] };
    Err(Rejection::new(codes[0], locus(Some(boundary)), Detail::Image(Box::new(failure))))
}

/// The point (u0, u1)/(-v) of a vector with v < 0, as text.
fn shown<F: Field>(g: &Vec2<F::Int>) -> Vec<String> {
    let half_w = F::from_int(&w(g)).times(&F::from_ratio(1, 2));
    g.iter()
        .map(|x| F::from_int(x).over(&half_w).map_or_else(String::new, |c| crate::exact::to_canonical(&c)))
        .collect()
}

/// What the accepted certificate reports (for a box, at every body).
pub fn accepted<F: Field>(
    rods: &[&Rod<F>],
    k: &Interval<F::Int>,
    gens: &Generators<'_, F::Int>,
    claim: Claim,
    piece: &[Vec2<F::Int>],
) -> Accepted {
    let contains = |rod: &&Rod<F>| {
        let t = mat2_vec(&int_mat(&rod.impact(0)), &[F::Int::from_i64(-1), F::Int::from_i64(-1)]);
        w(&t).is_positive() && k.contains(&t)
    };
    let mut a = Accepted::cone(claim, 2, gens.vectors.len(), vec![piece.len()]);
    a.redundant = (0..gens.vectors.len()).filter(|i| !k.index.contains(i)).collect();
    a.max_denominator_bits = gens.max_denominator_bits;
    a.contains_translation = rods.iter().all(contains);
    a
}

/// A positive integer multiple of a rational 2-vector.
fn int_vec<F: Field>(v: &Vec2<F>) -> Vec2<F::Int> {
    let z = scale_to_ints(v);
    [z[0].clone(), z[1].clone()]
}

/// A positive integer multiple of a rational 2x2 matrix.
fn int_mat<F: Field>(m: &Mat2<F>) -> Mat2<F::Int> {
    let z = scale_to_ints(&[m[0][0].clone(), m[0][1].clone(), m[1][0].clone(), m[1][1].clone()]);
    [[z[0].clone(), z[1].clone()], [z[2].clone(), z[3].clone()]]
}
