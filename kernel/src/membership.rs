//! Membership of exact states in the sets that accepted certificates certify (issue 22 §1;
//! the argument is docs/kernel-soundness.md §8).
//!
//! A set is built only from a certificate that the kernel has just accepted on both backends
//! ([`crate::verify::verify`], [`crate::verify::verify_orbit`]); membership is then decided
//! exactly (malachite), in F(cos 2π/n) where that cosine is irrational:
//! - [`CertifiedCone::contains`]: a velocity p = (u0, u1, v) right after an impact at contact 0
//!   (relabelled) lies in the cone K of a cone certificate (v < 0 and every facet of the
//!   projected polygon non-negative, docs/kernel-soundness.md §2, R1; for the rod, s = u0/(-2v)
//!   between the two rays, docs/model.md §7);
//! - [`CertifiedOrbit::contains`]: a post-impact state (q, p), contact 0 just landed, lies, after
//!   the two scalings, in the set X ⊂ Σ of an orbit certificate (docs/orbit-certificates.md §2-§4).
//!
//! What entering a set proves is the certificate's claim (docs/kernel-soundness.md §8): for
//! `CompleteChatterFromAllDown`, CC or PCC with PCC excluded; for `CompleteChatterFromSet`, CC.

use crate::certificate::{Body, Certificate, Claim, OrbitCertificate, Param};
use crate::check::Accepted;
use crate::exact::{Algebraic, CosField, Field, OrderedField, ParseLimits, Ring, parse_canonical};
use crate::geometry::{ConvexPolygon, hull};
use crate::model::linalg::Vec3;
use crate::orbit::read_orbit_values;
use crate::verify::{Verdict, verify, verify_orbit};

/// The exact scalars of membership tests: rationals, or elements of F(cos 2π/n), over the
/// rationals `F` of a backend.
pub type Exact<F> = Algebraic<F>;

/// Why no set was built.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum NotCertified {
    /// The kernel did not accept the certificate on both backends.
    Verdict(Box<Verdict>),
    /// A number the kernel accepted could not be read again (cannot happen with the same limits).
    Unreadable(String),
}

/// The cone K of an accepted cone certificate, with the parameters it holds for.
pub struct CertifiedCone<F: Field> {
    /// Number of contacts.
    pub n: u64,
    /// The claim the kernel accepted.
    pub claim: Claim,
    /// [lo, hi] of κ and of γ (lo = hi for a point certificate).
    bounds: [[Exact<F>; 2]; 2],
    /// K: a polygon on the plane v = -1, or the rod's interval.
    shape: Shape<F>,
}

/// The cone K of a polygon certificate projected to v = -1, or the rod's interval of
/// s = u0/(-2v) between its two rays (docs/model.md §7).
enum Shape<F: Field> {
    Polygon(ConvexPolygon<Exact<F>>),
    Rod([Exact<F>; 2]),
}

/// s = u0/(-2v) = -u0/(u0 + u1) of a rod velocity with v < 0 (docs/model.md §7).
fn rod_s<F: Field>(u0: &Exact<F>, u1: &Exact<F>) -> Option<Exact<F>> {
    u0.negated().over(&u0.plus(u1))
}

/// Reads one accepted number as an element of the certificate's field.
fn element<F: Field>(field: &std::sync::Arc<CosField<F>>, s: &str, limits: ParseLimits) -> Result<Exact<F>, NotCertified> {
    if field.degree() <= 1 {
        return parse_canonical::<F>(s, limits)
            .map(Exact::<F>::rational)
            .map_err(|e| NotCertified::Unreadable(e.to_string()));
    }
    field.parse(s, limits).map_err(|e| NotCertified::Unreadable(e.to_string()))
}

/// [lo, hi] of a parameter.
fn bounds<F: Field>(
    field: &std::sync::Arc<CosField<F>>,
    p: &Param,
    limits: ParseLimits,
) -> Result<[Exact<F>; 2], NotCertified> {
    match p {
        Param::Point(x) => {
            let x = element(field, x, limits)?;
            Ok([x.clone(), x])
        }
        Param::Interval(lo, hi) => Ok([element(field, lo, limits)?, element(field, hi, limits)?]),
    }
}

impl<F: Field> CertifiedCone<F> {
    /// Verifies `cert` on both backends and, if accepted, builds K (rule R1's polygon).
    pub fn new(cert: &Certificate, limits: ParseLimits) -> Result<(CertifiedCone<F>, Accepted), NotCertified> {
        let accepted = match verify(cert, limits) {
            Verdict::Accepted(a) => a,
            v => return Err(NotCertified::Verdict(Box::new(v))),
        };
        let Body::RegularPolygon { n, kappa, gamma } = &cert.body;
        let field =
            CosField::<F>::new((*n).max(3)).ok_or_else(|| NotCertified::Unreadable(format!("n = {n}")))?;
        let mut points: Vec<Vec<Exact<F>>> = Vec::with_capacity(cert.cone.len());
        for g in &cert.cone {
            points.push(g.0.iter().map(|s| element(&field, s, limits)).collect::<Result<_, _>>()?);
        }
        let shape = if *n == 2 { rod_interval(&points)? } else { polygon(&points) };
        let bounds = [bounds(&field, kappa, limits)?, bounds(&field, gamma, limits)?];
        Ok((CertifiedCone { n: *n, claim: cert.claim, bounds, shape }, accepted))
    }

    /// Whether the certificate holds for the body (n, κ, γ): n equal, κ and γ in its bounds.
    pub fn applies_to(&self, n: u64, kappa: &Exact<F>, gamma: &Exact<F>) -> bool {
        let within = |b: &[Exact<F>; 2], x: &Exact<F>| b[0] <= *x && *x <= b[1];
        self.n == n && within(&self.bounds[0], kappa) && within(&self.bounds[1], gamma)
    }

    /// p ∈ K, for p = (u0, u1, v) right after an impact at contact 0: v < 0 and p in the polygon;
    /// for the rod p = (u0, u1, 0): u0 + u1 < 0 and s(p) in K's interval.
    pub fn contains(&self, p: &Vec3<Exact<F>>) -> bool {
        match &self.shape {
            Shape::Polygon(polygon) => p[2].is_negative() && polygon.contains(p),
            Shape::Rod([lo, hi]) => {
                p[0].plus(&p[1]).is_negative() && rod_s(&p[0], &p[1]).is_some_and(|s| *lo <= s && s <= *hi)
            }
        }
    }
}

/// K of a polygon certificate (rule R1's hull; the kernel accepted it, so it is a 3-D cone).
fn polygon<F: Field>(points: &[Vec<Exact<F>>]) -> Shape<F> {
    let points: Vec<Vec3<Exact<F>>> =
        points.iter().map(|v| [v[0].clone(), v[1].clone(), v[2].clone()]).collect();
    Shape::Polygon(ConvexPolygon::new(hull(&points).into_iter().map(|i| points[i].clone()).collect()))
}

/// K of a rod certificate: the interval of s between the extreme generators (v < 0 on each, by
/// the kernel's rule R1 for the rod).
fn rod_interval<F: Field>(points: &[Vec<Exact<F>>]) -> Result<Shape<F>, NotCertified> {
    let s: Option<Vec<Exact<F>>> = points.iter().map(|g| rod_s(&g[0], &g[1])).collect();
    let s = s.ok_or_else(|| NotCertified::Unreadable("a rod generator with v = 0".into()))?;
    match (s.iter().min(), s.iter().max()) {
        (Some(lo), Some(hi)) => Ok(Shape::Rod([lo.clone(), hi.clone()])),
        _ => Err(NotCertified::Unreadable("no generators".into())),
    }
}

/// The set X ⊂ Σ of an accepted orbit certificate, with its body.
#[derive(Clone)]
pub struct CertifiedOrbit<F: Field> {
    /// Number of contacts.
    pub n: u64,
    /// κ and γ of the certificate.
    params: [Exact<F>; 2],
    /// The pattern's steps.
    pub pattern: Vec<usize>,
    /// x*.
    centre: [Exact<F>; 3],
    /// A⁻¹ (rows).
    a_inv: [[Exact<F>; 3]; 3],
    /// δ.
    delta: Exact<F>,
}

impl<F: Field> CertifiedOrbit<F> {
    /// Verifies `cert` on both backends and, if accepted, builds X = x* + A [-δ, δ]³.
    pub fn new(
        cert: &OrbitCertificate,
        limits: ParseLimits,
    ) -> Result<(CertifiedOrbit<F>, Accepted), NotCertified> {
        let accepted = match verify_orbit(cert, limits) {
            Verdict::Accepted(a) => a,
            v => return Err(NotCertified::Verdict(Box::new(v))),
        };
        let orbit = read_orbit_values::<F>(cert, limits).map_err(|r| {
            NotCertified::Unreadable(format!("{} at {:?}", r.code.as_str(), r.locus))
        })?;
        let e = |x: &F| Exact::<F>::rational(x.clone());
        let crate::certificate::OrbitBody::RegularPolygon { n, kappa, gamma } = &cert.body;
        let param = |s: &str| {
            parse_canonical::<F>(s, limits)
                .map(Exact::<F>::rational)
                .map_err(|e| NotCertified::Unreadable(e.to_string()))
        };
        let set = CertifiedOrbit {
            n: *n,
            params: [param(kappa)?, param(gamma)?],
            pattern: orbit.pattern.clone(),
            centre: orbit.centre.each_ref().map(e),
            a_inv: orbit.a_inv.each_ref().map(|r| r.each_ref().map(e)),
            delta: e(&orbit.delta),
        };
        Ok((set, accepted))
    }

    /// Whether the certificate is about the body (n, κ, γ).
    pub fn applies_to(&self, n: u64, kappa: &Exact<F>, gamma: &Exact<F>) -> bool {
        self.n == n && self.params[0] == *kappa && self.params[1] == *gamma
    }

    /// (q, p) ∈ X up to the scalings, for q = (h0, h1, hc), p = (u0, u1, v) right after an
    /// impact at contact 0: h0 = 0, hc > 0, v < 0 and y = A⁻¹(x - x*) ∈ [-δ, δ]³ for
    /// x = (h1/hc, u0/(-v), u1/(-v)) (docs/orbit-certificates.md §2).
    pub fn contains(&self, q: &Vec3<Exact<F>>, p: &Vec3<Exact<F>>) -> bool {
        if !q[0].is_zero() || !q[2].is_positive() || !p[2].is_negative() {
            return false;
        }
        let w = p[2].negated();
        let (Some(a), Some(b), Some(c)) = (q[1].over(&q[2]), p[0].over(&w), p[1].over(&w)) else {
            return false;
        };
        let d: [Exact<F>; 3] = [a.minus(&self.centre[0]), b.minus(&self.centre[1]), c.minus(&self.centre[2])];
        self.a_inv.iter().all(|row| {
            let y = row[0].times(&d[0]).plus(&row[1].times(&d[1])).plus(&row[2].times(&d[2]));
            y <= self.delta && y.negated() <= self.delta
        })
    }
}
