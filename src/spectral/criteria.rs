//! The paper's spectral criteria, decided exactly, and their thresholds in gamma.
//!
//! - CC criterion (Conjecture 1 (iii), docs/model.md §6): S_1 has a real, positive dominant eigenvalue
//!   (Elsner-Vandergraft, with multiplicities).
//! - PCC criterion (the PCC Lemma and Conjecture 2): all eigenvalues of S_{n-1} S_1 are real.
//! - The rod (n = 2, the paper's Theorem after Goyal et al.): CC from pure translation iff
//!   sqrt(kappa) <= 2/(sqrt(gamma) + 1) - 1.
//!
//! For fixed n and kappa the maps are affine in gamma, S(gamma) = A + gamma B, so the
//! coefficients of the characteristic polynomials are polynomials in gamma. A criterion can
//! only change where a candidate polynomial in gamma vanishes (a discriminant, a modulus tie, a
//! zero eigenvalue); those roots in (0, 1) are isolated exactly and the criterion is evaluated
//! exactly at a rational point between each pair of neighbours.

use super::eigen::{Dominant, Spectrum, char_poly2, char_poly3};
use super::poly::Poly;
use super::roots::{RealRoot, isolate};
use crate::exact::{OrderedField, Q};
use chatter_kernel::model::Polygon as Body;
use chatter_kernel::model::linalg::{Mat3, mat_mul};
use chatter_kernel::model::{Mat2, Rod};
use std::cmp::Ordering;

/// A regular n-gon body with gamma left free: n, c_1 = cos(2 pi/n) and kappa, exact in `F`.
#[derive(Clone, Debug)]
pub struct Family<F> {
    pub n: u64,
    pub c1: F,
    pub kappa: F,
}

impl<F: OrderedField> Family<F> {
    /// The body at one value of gamma (0 <= gamma <= 1).
    pub fn at(&self, gamma: &Q) -> Body<F> {
        Body::with_cosine(self.n, self.c1.clone(), self.kappa.clone(), F::from_q(gamma))
            .expect("valid family")
    }
}

/// The CC criterion at one body: the spectrum of S_1 and its dominant eigenvalue(s).
pub fn cc_criterion<F: OrderedField>(b: &Body<F>) -> (bool, Spectrum<F>, Dominant) {
    let mut s = Spectrum::of3(&b.step(1));
    let d = s.dominant();
    (d.real_positive(), s, d)
}

/// The PCC criterion at one body: whether every eigenvalue of S_{n-1} S_1 is real.
pub fn pcc_criterion<F: OrderedField>(b: &Body<F>) -> (bool, Spectrum<F>) {
    let s = Spectrum::of3(&mat_mul(&b.step(b.n() as i64 - 1), &b.step(1)));
    (s.all_real(), s)
}

/// The CC criterion of the rod: S_1 = U_0 P has a real positive dominant eigenvalue.
pub fn rod_cc_criterion<F: OrderedField>(r: &Rod<F>) -> (bool, Spectrum<F>, Dominant) {
    let mut s = Spectrum::of2(&r.step());
    let d = s.dominant();
    (d.real_positive(), s, d)
}

/// Goyal's condition, decided exactly: sqrt(k) <= 2/(sqrt(g) + 1) - 1 iff (sqrt k + 1)(sqrt g + 1)
/// <= 2 iff k <= 1 and (1 + g)^2 (1 - k)^2 >= 4 g (1 + k)^2 (squaring twice, both sides >= 0).
pub fn goyal_condition<F: OrderedField>(kappa: &F, gamma: &F) -> bool {
    let one = F::one();
    let (a, b) = (one.minus(kappa), one.plus(kappa));
    let g1 = one.plus(gamma);
    *kappa <= one && g1.times(&g1).times(&a).times(&a) >= F::from_i64(4).times(gamma).times(&b).times(&b)
}

/// The gamma where Goyal's condition changes for a given kappa < 1: the root in (0, 1) of
/// (1 - k)^2 g^2 + (2 (1 - k)^2 - 4 (1 + k)^2) g + (1 - k)^2 (for k = 1/3: 7 - 4 sqrt 3).
pub fn goyal_threshold<F: OrderedField>(kappa: &F) -> Option<RealRoot<F>> {
    let one = F::one();
    if *kappa >= one {
        return None;
    }
    let (a, b) = (one.minus(kappa), one.plus(kappa));
    let a2 = a.times(&a);
    let mid = a2.plus(&a2).minus(&F::from_i64(4).times(&b).times(&b));
    isolate(&Poly::new(vec![a2.clone(), mid, a2]))
        .into_iter()
        .find_map(|mut r| inside_unit(&mut r).then_some(r))
}

/// Refines a root until it is known to lie in (0, 1) or not.
fn inside_unit<F: OrderedField>(r: &mut RealRoot<F>) -> bool {
    let (zero, one) = (Q::int(0), Q::int(1));
    loop {
        if r.is_exact() {
            return r.lo > zero && r.lo < one;
        }
        if r.lo >= zero && r.hi <= one {
            return true;
        }
        if r.hi <= zero || r.lo >= one {
            return false;
        }
        r.bisect();
    }
}

/// Lagrange interpolation through (x_i, y_i) with distinct rational x_i.
pub fn interpolate<F: OrderedField>(xs: &[Q], ys: &[F]) -> Poly<F> {
    let mut out = Poly::zero();
    for (i, (xi, yi)) in xs.iter().zip(ys).enumerate() {
        let mut term = Poly::constant(yi.clone());
        for (j, xj) in xs.iter().enumerate() {
            if i != j {
                let lin = Poly::new(vec![F::from_q(&-xj), F::one()]);
                term = term.mul(&lin).scale(&F::from_q(&(Q::int(1) / (xi - xj))));
            }
        }
        out = out.add(&term);
    }
    out
}

/// The coefficients (c2, c1, c0) of det(tI - M(gamma)) = t^3 - c2 t^2 + c1 t - c0 as
/// polynomials in gamma of degree <= `deg`, from exact values at gamma = 0, 1, ..., deg.
fn char_coefficients<F: OrderedField>(m: impl Fn(&Q) -> Mat3<F>, deg: usize) -> [Poly<F>; 3] {
    char_coefficients_at(m, &(0..=deg as i64).map(Q::int).collect::<Vec<_>>())
}

/// The coefficients (c2, c1, c0) of det(tI - M(x)) as polynomials in x, from exact values at
/// the given points (one more than the degree).
pub fn char_coefficients_at<F: OrderedField>(m: impl Fn(&Q) -> Mat3<F>, xs: &[Q]) -> [Poly<F>; 3] {
    let ps: Vec<Poly<F>> = xs.iter().map(|x| char_poly3(&m(x))).collect();
    let coef = |k: usize, neg: bool| {
        let ys: Vec<F> = ps.iter().map(|p| if neg { p.coeff(k).negated() } else { p.coeff(k) }).collect();
        interpolate(xs, &ys)
    };
    [coef(2, true), coef(1, false), coef(0, true)]
}

/// S_j at any rational gamma (also outside [0, 1], for interpolation): A + gamma B.
fn step_at<F: OrderedField>(fam: &Family<F>, j: i64, gamma: &Q) -> Mat3<F> {
    let (a, b) = (fam.at(&Q::int(0)).step(j), fam.at(&Q::int(1)).step(j));
    let g = F::from_q(gamma);
    std::array::from_fn(|r| std::array::from_fn(|c| a[r][c].plus(&g.times(&b[r][c].minus(&a[r][c])))))
}

/// A change of a criterion at an algebraic gamma.
#[derive(Clone, Debug)]
pub struct Threshold<F> {
    /// The value of gamma, a root of `factor` with an isolating interval.
    pub gamma: RealRoot<F>,
    /// The criterion just below and just above.
    pub below: bool,
    pub above: bool,
    /// A square-free polynomial in gamma vanishing here (its defining polynomial).
    pub factor: Poly<F>,
    /// Which candidate polynomial it came from.
    pub source: &'static str,
}

/// How a criterion behaves for gamma in (0, 1).
#[derive(Clone, Debug)]
pub struct Profile<F> {
    /// The criterion for gamma just above 0.
    pub near_zero: bool,
    pub thresholds: Vec<Threshold<F>>,
    /// The rational sample points used, with the criterion there.
    pub samples: Vec<(Q, bool)>,
}

/// The supremum of the gammas in (0, 1) where a criterion holds.
#[derive(Clone, Copy, Debug)]
pub enum Sup<'a, F> {
    Never,
    /// It holds for gamma up to 1.
    UpToOne,
    /// It holds just below this threshold and nowhere above it.
    At(&'a Threshold<F>),
}

impl<F: OrderedField> Profile<F> {
    pub fn sup(&self) -> Sup<'_, F> {
        if !self.samples.iter().any(|(_, v)| *v) {
            return Sup::Never;
        }
        if self.samples.last().is_some_and(|(_, v)| *v) {
            return Sup::UpToOne;
        }
        Sup::At(
            self.thresholds
                .iter()
                .rev()
                .find(|t| t.below && !t.above)
                .expect("a true sample before a false last one"),
        )
    }

    /// A rational lower bound within 2^-bits of the supremum gamma* of the criterion (when it is
    /// a threshold in (0, 1)).
    pub fn sup_lower_bound(&self, bits: u32) -> Option<Q> {
        let Sup::At(t) = self.sup() else { return None };
        let mut r = t.gamma.clone();
        let eps = Q::from_rational(malachite::rational::Rational::from(1u32) >> i64::from(bits));
        while &r.hi - &r.lo > eps {
            r.bisect();
        }
        Some(r.lo)
    }

    /// Whether the criterion holds on an initial interval (0, g*) and nowhere else.
    pub fn is_initial_interval(&self) -> bool {
        let first_false = self.samples.iter().position(|(_, v)| !*v).unwrap_or(self.samples.len());
        self.samples[first_false..].iter().all(|(_, v)| !*v)
    }
}

/// The profile of a criterion from candidate polynomials in gamma and an exact evaluator.
pub fn profile<F: OrderedField>(
    candidates: &[(&'static str, Poly<F>)],
    eval: impl Fn(&Q) -> bool,
) -> Profile<F> {
    let mut roots: Vec<(RealRoot<F>, &'static str, Poly<F>)> = Vec::new();
    for (name, c) in candidates {
        if c.degree().unwrap_or(0) == 0 {
            continue;
        }
        let sf = c.square_free();
        for mut r in isolate(&sf) {
            if inside_unit(&mut r)
                && !roots.iter_mut().any(|(o, _, _)| o.clone().compare(&mut r.clone()) == Ordering::Equal)
            {
                roots.push((r, name, sf.clone()));
            }
        }
    }
    roots.sort_by(|a, b| a.0.clone().compare(&mut b.0.clone()));
    // Make neighbouring intervals disjoint, with a gap, so that every rational sample lies strictly
    // between two roots (a sample on a shared endpoint could be an exact root of the other).
    for i in 1..roots.len() {
        let (left, right) = roots.split_at_mut(i);
        let (a, b) = (&mut left[i - 1].0, &mut right[0].0);
        while a.hi >= b.lo {
            if a.width() >= b.width() { a.bisect() } else { b.bisect() }
        }
    }
    // Keep the samples inside (0, 1): a criterion can differ at gamma = 0 or 1 themselves (e.g.
    // a zero eigenvalue at gamma = 0, elastic impacts at gamma = 1).
    if let Some((r, _, _)) = roots.first_mut() {
        while !r.is_exact() && r.lo <= Q::int(0) {
            r.bisect();
        }
    }
    if let Some((r, _, _)) = roots.last_mut() {
        while !r.is_exact() && r.hi >= Q::int(1) {
            r.bisect();
        }
    }
    let mut cuts = vec![Q::int(0)];
    for (r, _, _) in &roots {
        cuts.push(r.lo.clone());
        cuts.push(r.hi.clone());
    }
    cuts.push(Q::int(1));
    let samples: Vec<(Q, bool)> = cuts
        .chunks(2)
        .map(|w| {
            let x = (&w[0] + &w[1]) / Q::int(2);
            let v = eval(&x);
            (x, v)
        })
        .collect();
    let thresholds = roots
        .into_iter()
        .enumerate()
        .filter(|(i, _)| samples[*i].1 != samples[i + 1].1)
        .map(|(i, (gamma, source, factor))| Threshold {
            gamma,
            below: samples[i].1,
            above: samples[i + 1].1,
            factor,
            source,
        })
        .collect();
    Profile { near_zero: samples[0].1, thresholds, samples }
}

/// The discriminant of t^3 - c2 t^2 + c1 t - c0 (coefficients polynomials in gamma): with
/// a = -c2, b = c1, c = -c0 it is 18abc - 4a^3 c + a^2 b^2 - 4b^3 - 27c^2.
fn cubic_discriminant<F: OrderedField>(c2: &Poly<F>, c1: &Poly<F>, c0: &Poly<F>) -> Poly<F> {
    let (a, b, c) = (c2.neg(), c1.clone(), c0.neg());
    let k = |x: i64| F::from_i64(x);
    a.mul(&b)
        .mul(&c)
        .scale(&k(18))
        .sub(&a.pow(3).mul(&c).scale(&k(4)))
        .add(&a.pow(2).mul(&b.pow(2)))
        .sub(&b.pow(3).scale(&k(4)))
        .sub(&c.pow(2).scale(&k(27)))
}

/// The polynomials in gamma where the kind of S_1's dominant eigenvalue can change: the
/// discriminant, the real-complex modulus tie, the +-rho tie and a zero eigenvalue.
pub fn dominant_candidates<F: OrderedField>(fam: &Family<F>) -> Vec<(&'static str, Poly<F>)> {
    candidates_of(char_coefficients(|g| step_at(fam, 1, g), 3))
}

/// The candidates of [`dominant_candidates`] for any 3x3 matrix family whose characteristic
/// coefficients (c2, c1, c0) of t^3 - c2 t^2 + c1 t - c0 are polynomials in one variable.
pub fn candidates_of<F: OrderedField>([c2, c1, c0]: [Poly<F>; 3]) -> Vec<(&'static str, Poly<F>)> {
    let disc = cubic_discriminant(&c2, &c1, &c0);
    let modulus_tie = c1.pow(3).sub(&c0.mul(&c2.pow(3)));
    let sign_tie = c1.mul(&c2).sub(&c0);
    vec![
        ("discriminant", disc),
        ("real-complex modulus tie", modulus_tie),
        ("+-rho tie", sign_tie),
        ("zero eigenvalue", c0),
    ]
}

/// The CC profile of a body family: where S_1 has a real positive dominant eigenvalue.
pub fn cc_profile<F: OrderedField>(fam: &Family<F>) -> Profile<F> {
    profile(&dominant_candidates(fam), |g| cc_criterion(&fam.at(g)).0)
}

/// The PCC profile: where all eigenvalues of S_{n-1} S_1 are real. The product's coefficients
/// have degree <= 6 in gamma; its cubic discriminant is the only candidate.
pub fn pcc_profile<F: OrderedField>(fam: &Family<F>) -> Profile<F> {
    let last = fam.n as i64 - 1;
    let [c2, c1, c0] = char_coefficients(|g| mat_mul(&step_at(fam, last, g), &step_at(fam, 1, g)), 6);
    let disc = cubic_discriminant(&c2, &c1, &c0);
    profile(&[("discriminant", disc)], |g| pcc_criterion(&fam.at(g)).0)
}

/// The discriminant of t^3 - c2 t^2 + c1 t - c0 with polynomial coefficients (the PCC
/// criterion's only candidate).
pub fn discriminant_of<F: OrderedField>([c2, c1, c0]: &[Poly<F>; 3]) -> Poly<F> {
    cubic_discriminant(c2, c1, c0)
}

/// The rod's CC profile from the 2x2 step map: candidates are its discriminant, trace and
/// determinant.
pub fn rod_cc_profile<F: OrderedField>(kappa: &F) -> Profile<F> {
    let at = |g: &Q| -> Mat2<F> {
        let (a, b) = (rod(kappa, &Q::int(0)).step(), rod(kappa, &Q::int(1)).step());
        let g = F::from_q(g);
        std::array::from_fn(|r| std::array::from_fn(|c| a[r][c].plus(&g.times(&b[r][c].minus(&a[r][c])))))
    };
    let xs: Vec<Q> = (0..=2).map(Q::int).collect();
    let ps: Vec<Poly<F>> = xs.iter().map(|x| char_poly2(&at(x))).collect();
    let coef = |k: usize| interpolate(&xs, &ps.iter().map(|p| p.coeff(k)).collect::<Vec<_>>());
    let (b, c) = (coef(1), coef(0)); // t^2 + b t + c
    let disc = b.pow(2).sub(&c.scale(&F::from_i64(4)));
    let cands = [("discriminant", disc), ("trace", b), ("determinant", c)];
    profile(&cands, |g| rod_cc_criterion(&rod(kappa, g)).0)
}

fn rod<F: OrderedField>(kappa: &F, gamma: &Q) -> Rod<F> {
    Rod::new(kappa.clone(), F::from_q(gamma)).expect("valid rod")
}

/// The paper's Theorem on rotating initial velocities for the rod: CC iff Goyal's condition holds
/// and the initial velocity p0 = (u0, u1) lies in the cone spanned by the eigenvector e_min of
/// the smaller eigenvalue of S_1 = U_0 P and its mirror image. Returns `None` when the condition
/// fails (the rod never chatters completely), else whether p0 is in the cone.
///
/// On the line v = -1 a velocity is s = u0 / (-(u0 + u1)); mirroring maps s to -1 - s, so the
/// cone is the interval between s(e_min) and -1 - s(e_min). With e = (S01, lambda - S00),
/// s(e) - x = (S01 + x (S01 - S00) + x lambda) / d(lambda), d(lambda) = S00 - S01 - lambda, and
/// the signs of these linear forms at the algebraic lambda_min are decided exactly.
pub fn rod_velocity_in_cone<F: OrderedField>(rod: &Rod<F>, p0: &[F; 2]) -> Option<bool> {
    if !goyal_condition(rod.kappa(), rod.gamma()) {
        return None;
    }
    let w = p0[0].plus(&p0[1]).negated();
    if !w.is_positive() {
        return Some(false); // the centre of mass is not moving down
    }
    let x = p0[0].over(&w).expect("w > 0");
    let s = rod.step();
    let mut lmin = Spectrum::of2(&s).real.first()?.0.clone();
    let (s00, s01) = (&s[0][0], &s[0][1]);
    // sign of s(e_min) - y for a rational-in-F point y.
    let mut side = |y: &F| -> Ordering {
        let num = Poly::new(vec![s01.plus(&y.times(&s01.minus(s00))), y.clone()]);
        let den = Poly::new(vec![s00.minus(s01), F::one().negated()]);
        let (a, b) = (lmin.sign_of(&num), lmin.sign_of(&den));
        if a == Ordering::Equal {
            a
        } else if a == b {
            Ordering::Greater
        } else {
            Ordering::Less
        }
    };
    // The ends are e = s(e_min) and -1 - e; x lies between them iff (e - x)(-1 - e - x) <= 0,
    // i.e. iff e - x and e - (-1 - x) have the same sign (or one vanishes).
    let (a, b) = (side(&x), side(&x.negated().minus(&F::one())));
    Some(a == b || a == Ordering::Equal || b == Ordering::Equal)
}
