//! Certificate format version 5: orbit certificates (docs/orbit-certificates.md,
//! docs/certificate-format.md §14). A regular polygon, an impact pattern P, a compact set X of
//! the section Σ (a parallelepiped x* + A [-δ, δ]³ or a box) and bounds ρ, λ, T̄; the kernel
//! checks the three conditions of docs/orbit-certificates.md §3 over all of X
//! (`crate::orbit::check_orbit`). The numbers stay text here, as in the other versions.

use super::write::quoted;
use super::{Claim, Encoding, FORMAT, Rejection};
use serde::{Deserialize, Serialize};

/// The version that introduced (and alone carries) orbit certificates.
pub const ORBIT_VERSION: u64 = 5;

/// An orbit certificate (format version 5).
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename = "Certificate", deny_unknown_fields)]
pub struct OrbitCertificate {
    /// Always [`FORMAT`].
    pub format: String,
    /// Always [`ORBIT_VERSION`].
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
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
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
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
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

/// Reads version-5 certificate text (RON in the strict syntax, or its JSON twin): the header
/// first (`format`, `version` = 5), then the full schema with unknown fields denied.
pub fn read_orbit(text: &str, encoding: Encoding) -> Result<OrbitCertificate, Rejection> {
    let v = ORBIT_VERSION..=ORBIT_VERSION;
    match encoding {
        Encoding::Ron => {
            super::strict::check(text)?;
            #[derive(Deserialize)]
            #[serde(rename = "Certificate")]
            struct Header {
                format: Option<String>,
                version: Option<u64>,
            }
            let lenient =
                ron::Options::default().with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME);
            let header: Header = lenient.from_str(text).map_err(super::ron_error)?;
            super::check_header(header.format.as_deref(), header.version, FORMAT, v)?;
            ron::Options::default().from_str(text).map_err(super::ron_error)
        }
        Encoding::Json => super::read_json(text, FORMAT, v),
    }
}

fn triple(t: &Triple) -> String {
    format!("({}, {}, {})", quoted(&t.0), quoted(&t.1), quoted(&t.2))
}

/// Writes a version-5 certificate as RON (deterministic, one vector per line).
pub fn write_orbit(c: &OrbitCertificate) -> String {
    let q = |s: &str| quoted(s);
    let OrbitBody::RegularPolygon { n, kappa, gamma } = &c.body;
    let mut out = String::new();
    out.push_str("Certificate(\n");
    out.push_str(&format!("    format: {},\n", q(&c.format)));
    out.push_str(&format!("    version: {},\n", c.version));
    out.push_str(&format!("    body: RegularPolygon(n: {n}, kappa: {}, gamma: {}),\n", q(kappa), q(gamma)));
    out.push_str(&format!("    claim: {},\n", c.claim.name()));
    let steps: Vec<String> = c.pattern.iter().map(u64::to_string).collect();
    out.push_str(&format!("    pattern: [{}],\n", steps.join(", ")));
    match &c.set {
        OrbitSet::Parallelepiped { centre, axes, delta } => {
            out.push_str("    set: Parallelepiped(\n");
            out.push_str(&format!("        centre: {},\n", triple(centre)));
            out.push_str("        axes: (\n");
            for a in [&axes.0, &axes.1, &axes.2] {
                out.push_str(&format!("            {},\n", triple(a)));
            }
            out.push_str("        ),\n");
            out.push_str(&format!("        delta: {},\n", q(delta)));
            out.push_str("    ),\n");
        }
        OrbitSet::Box { lo, hi } => {
            out.push_str("    set: Box(\n");
            out.push_str(&format!("        lo: {},\n", triple(lo)));
            out.push_str(&format!("        hi: {},\n", triple(hi)));
            out.push_str("    ),\n");
        }
    }
    out.push_str(&format!("    subdivision: {},\n", c.subdivision));
    out.push_str(&format!("    rho: {},\n", q(&c.rho)));
    out.push_str(&format!("    lambda: {},\n", q(&c.lambda)));
    out.push_str(&format!("    period: {},\n", q(&c.period)));
    out.push_str(&format!("    producer: {},\n", q(&c.producer)));
    out.push_str(")\n");
    out
}
