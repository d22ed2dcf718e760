//! The schema of orbit certificates (docs/orbit-certificates.md, docs/certificate-format.md §14):
//! a regular polygon, an impact pattern P, a compact set X of the section Σ (a parallelepiped
//! x* + A [-δ, δ]³ or a box) and bounds ρ, λ, T̄. Format `"chatter-orbit-certificate"`, version
//! 1; the legacy header `("chatter-certificate", 5)` is read as an alias. The numbers stay text.

use crate::syntax::cone::Claim;
use crate::syntax::{Kind, Schema};
use serde::Deserialize;

/// Value of the `format` field.
pub const FORMAT: &str = "chatter-orbit-certificate";
/// The version.
pub const VERSION: u64 = 1;

/// An orbit certificate.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename = "Certificate", deny_unknown_fields)]
pub struct OrbitCertificate {
    /// [`FORMAT`] (or the legacy `"chatter-certificate"`).
    pub format: String,
    /// [`VERSION`] (5 with the legacy format).
    pub version: u64,
    /// The falling body.
    pub body: OrbitBody,
    /// What the certificate proves: always [`Claim::CompleteChatterFromSet`].
    pub claim: Claim,
    /// The steps j_1, ..., j_m of the pattern, each in 1..n-1 (docs/orbit-certificates.md §2).
    pub pattern: Vec<u64>,
    /// The set X of the section Σ = {q = (0, a, 1), p = (b, c, -1)}, in coordinates x = (a, b, c).
    pub set: OrbitSet,
    /// The deepest bisection of X the kernel may use (sub-boxes of edge 2δ/2^depth).
    pub subdivision: u64,
    /// ρ: a bound on α/β per period (the flight-time ratio), 0 < ρ < 1.
    pub rho: String,
    /// λ: a bound on α and on β per period (position and velocity scales), 0 < λ < 1.
    pub lambda: String,
    /// T̄: a bound on the period's flight time T in the units of x, T̄ > 0.
    pub period: String,
    /// Informational only, never trusted.
    #[serde(default)]
    pub producer: String,
}

/// The body of an orbit certificate: a regular polygon at one parameter point.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum OrbitBody {
    /// Regular n-gon of contacts (circumradius 1), kappa = rho^2/R^2, restitution gamma.
    RegularPolygon {
        /// Number of contacts (3, 4 or 6: rational cos 2 pi/n).
        n: u64,
        /// kappa, canonical text.
        kappa: String,
        /// gamma, canonical text.
        gamma: String,
    },
}

/// A 3-vector as canonical text.
pub type Triple = (String, String, String);

/// The set X of an orbit certificate.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum OrbitSet {
    /// x* + A [-δ, δ]³: `centre` = x*, `axes` the three columns of A (non-singular), δ > 0.
    Parallelepiped {
        /// x* = (a, b, c).
        centre: Triple,
        /// The columns of A.
        axes: (Triple, Triple, Triple),
        /// δ > 0.
        delta: String,
    },
    /// The box [lo, hi] (lo < hi in every coordinate).
    Box {
        /// Lower corner (a, b, c).
        lo: Triple,
        /// Upper corner (a, b, c).
        hi: Triple,
    },
}

impl Schema for OrbitCertificate {
    const KIND: Kind = Kind::Orbit;
}

impl OrbitCertificate {
    /// Every number of the file as text with its path, in order (for the size limit and parsing).
    pub fn numbers(&self) -> Vec<(String, &str)> {
        let OrbitBody::RegularPolygon { kappa, gamma, .. } = &self.body;
        let mut v = vec![("body.kappa".to_string(), kappa.as_str()), ("body.gamma".into(), gamma.as_str())];
        fn triple<'a>(path: &str, t: &'a Triple, v: &mut Vec<(String, &'a str)>) {
            for (i, s) in [&t.0, &t.1, &t.2].into_iter().enumerate() {
                v.push((format!("{path}[{i}]"), s.as_str()));
            }
        }
        match &self.set {
            OrbitSet::Parallelepiped { centre, axes, delta } => {
                triple("set.centre", centre, &mut v);
                triple("set.axes[0]", &axes.0, &mut v);
                triple("set.axes[1]", &axes.1, &mut v);
                triple("set.axes[2]", &axes.2, &mut v);
                v.push(("set.delta".into(), delta.as_str()));
            }
            OrbitSet::Box { lo, hi } => {
                triple("set.lo", lo, &mut v);
                triple("set.hi", hi, &mut v);
            }
        }
        v.push(("rho".into(), self.rho.as_str()));
        v.push(("lambda".into(), self.lambda.as_str()));
        v.push(("period".into(), self.period.as_str()));
        v
    }
}
