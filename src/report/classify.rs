//! `chatter.classify/1`: every exact criterion at one body with its evidence, the thresholds in
//! gamma for its kappa, the float finder, a batch of simulated drops and whether a certificate
//! can be made. Build it with [`classify`]; [`ClassifyReport::lines`] is the text output.

use super::finder::FinderReport;
use super::{Interval, Number, Report, Verdict};
use crate::bodies::{self, Threshold};
use crate::certify::{Request, certify};
use crate::exact::{OrderedField, Q, QExt, QField, Ring, Rounding};
use crate::finder::{FinderConfig, Seed, find_cone};
use crate::model::FloatBody;
use crate::model::float::FloatPolygon;
use crate::simulate::{Arithmetic, Model, Options, Outcome, Shape, counts, simulate_many};
use crate::spectral::criteria::{
    Family, cc_criterion, goyal_condition, pcc_criterion, rod_cc_criterion, rod_velocity_in_cone,
};
use crate::spectral::eigen::{Dominant, Spectrum};
use crate::spectral::number_field::Nf;
use chatter_kernel::model::{Polygon, Rod, Shape as ExactShape};
use schemars::JsonSchema;
use serde::Serialize;
use std::collections::BTreeMap;

/// Random drops simulated by `classify`, and their impact budget.
pub const SIM_RUNS: u64 = 20;
/// The impact budget of each drop.
pub const SIM_BUDGET: usize = 2000;

/// What to classify: a body (n contacts, kappa, gamma), and for the rod an initial velocity.
#[derive(Clone, Debug)]
pub struct ClassifyRequest {
    /// 2 (the rod) to 64.
    pub n: u64,
    /// kappa > 0.
    pub kappa: Q,
    /// gamma in [0, 1].
    pub gamma: Q,
    /// Rod only: the initial velocity (u0, u1) to decide CC from.
    pub velocity: Option<[Q; 2]>,
    /// Decimal digits of the enclosures' decimal texts (1..=60; 12 by default).
    pub digits: usize,
}

impl ClassifyRequest {
    /// The body (n, kappa, gamma) with no velocity and 12 digits.
    pub fn new(n: u64, kappa: Q, gamma: Q) -> ClassifyRequest {
        ClassifyRequest { n, kappa, gamma, velocity: None, digits: 12 }
    }

    /// Checks the ranges; the message names the flag (`--n: ...`).
    pub fn validate(&self) -> Result<(), String> {
        if !(2..=64).contains(&self.n) {
            return Err(format!("--n: {} is not supported here: give n = 2 (the rod) or 3 to 64", self.n));
        }
        if !self.kappa.is_positive() {
            return Err(format!("--kappa: {} is not accepted: kappa must be > 0", self.kappa));
        }
        if self.gamma.is_negative() || self.gamma > Q::int(1) {
            return Err(format!("--gamma: {} is not accepted: gamma must lie in [0, 1]", self.gamma));
        }
        if self.velocity.is_some() && self.n != 2 {
            return Err("--velocity is for the rod (--n 2)".into());
        }
        if self.digits == 0 || self.digits > 60 {
            return Err(format!("--digits: {} is not accepted: give 1 to 60", self.digits));
        }
        Ok(())
    }
}

/// One eigenvalue (or a complex-conjugate pair), enclosed exactly.
#[derive(Clone, Debug, Serialize, JsonSchema)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum Eigenvalue {
    /// A real eigenvalue: the only root of the characteristic polynomial in the enclosure (or
    /// exactly `enclosure.lo` when `exact`).
    Real {
        enclosure: Interval,
        /// The enclosure in decimals, rounded outwards.
        decimal: [String; 2],
        exact: bool,
        multiplicity: usize,
    },
    /// A complex-conjugate pair a ± bi: enclosures of a and of a² + b².
    ComplexPair { real_part: Interval, modulus_squared: Interval, decimal: ComplexDecimal },
}

/// The enclosures of a complex pair in decimals, rounded outwards.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct ComplexDecimal {
    pub real_part: [String; 2],
    pub modulus_squared: [String; 2],
}

impl Eigenvalue {
    /// The eigenvalues of a spectrum, real ones in increasing order, then the complex pair.
    pub fn of<F: OrderedField>(s: &mut Spectrum<F>, digits: usize) -> Vec<Eigenvalue> {
        let mut out = Vec::new();
        for (r, m) in &mut s.real {
            let (a, b) = r.decimal_enclosure(digits);
            out.push(Eigenvalue::Real {
                enclosure: Interval::of(&r.lo, &r.hi),
                decimal: [a, b],
                exact: r.is_exact(),
                multiplicity: *m,
            });
        }
        if s.non_real == 2 {
            let (re, md) = s.non_real_enclosure(digits);
            let d = |x: &(Q, Q)| [x.0.decimal(digits, Rounding::Down), x.1.decimal(digits, Rounding::Up)];
            let decimal = ComplexDecimal { real_part: d(&re), modulus_squared: d(&md) };
            out.push(Eigenvalue::ComplexPair {
                real_part: Interval::of(&re.0, &re.1),
                modulus_squared: Interval::of(&md.0, &md.1),
                decimal,
            });
        }
        out
    }

    /// The text output's form (as `Spectrum::describe`).
    pub fn text(&self) -> String {
        match self {
            Eigenvalue::Real { enclosure, decimal, exact, multiplicity } => {
                let mult =
                    if *multiplicity > 1 { format!(" (multiplicity {multiplicity})") } else { String::new() };
                let value = if *exact {
                    enclosure.lo.exact.clone()
                } else {
                    format!("[{}, {}]", decimal[0], decimal[1])
                };
                value + &mult
            }
            Eigenvalue::ComplexPair { decimal: d, .. } => format!(
                "a complex pair with real part in [{}, {}] and squared modulus in [{}, {}]",
                d.real_part[0], d.real_part[1], d.modulus_squared[0], d.modulus_squared[1]
            ),
        }
    }
}

/// An exact spectral criterion with its evidence.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct Criterion {
    /// Whether the criterion holds (decided exactly).
    pub holds: bool,
    /// The matrix whose spectrum decides it: `S_1`, `U_0 P` (the rod) or `S_{n-1} S_1`.
    pub matrix: String,
    /// det(tI - M), exact coefficients.
    pub char_poly: String,
    pub eigenvalues: Vec<Eigenvalue>,
    pub all_real: bool,
    /// CC criteria: which eigenvalues dominate (`positive`, `negative`, `plus-minus`,
    /// `non-real`, `positive-and-non-real`, `negative-and-non-real`, `zero`).
    pub dominant: Option<&'static str>,
    /// The same in words (text output only).
    #[serde(skip)]
    pub dominant_text: &'static str,
}

/// A criterion's report from its exact spectrum (docs/model.md §6).
pub(crate) fn criterion<F: OrderedField + std::fmt::Display>(
    holds: bool,
    matrix: String,
    s: &mut Spectrum<F>,
    dominant: Option<Dominant>,
    digits: usize,
) -> Criterion {
    Criterion {
        holds,
        matrix,
        char_poly: s.char_poly.to_string(),
        eigenvalues: Eigenvalue::of(s, digits),
        all_real: s.all_real(),
        dominant: dominant.map(Dominant::key),
        dominant_text: dominant.map_or("", Dominant::describe),
    }
}

/// The rod from a given initial velocity.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct FromVelocity {
    /// (u0, u1).
    pub velocity: [Number; 2],
    /// Whether the drop ends in CC (the velocity lies in the invariant cone).
    pub cc: bool,
    /// Whether the invariant cone exists at all (Goyal's condition holds).
    pub cone_exists: bool,
}

/// The float finder from the paper's two seeds.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct Finders {
    pub translation: FinderReport,
    pub all_down: FinderReport,
}

/// A batch of random drops (f64): evidence, never a proof (issue 22 §1).
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct Drops {
    /// Always `evidence`: f64 simulations prove nothing (`chatter simulate --exact` proves).
    pub basis: &'static str,
    pub runs: u64,
    /// Impact budget of each drop.
    pub budget: usize,
    /// Outcome (`CC`, `PCC`, `ICC`, `undecided`, `simultaneous`) -> number of drops.
    pub counts: BTreeMap<String, usize>,
}

/// Whether the pipeline certifies here.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct CertificateSummary {
    /// `certified` or `not-certified`.
    pub verdict: Verdict,
    /// The strongest claim certified.
    pub claim: Option<&'static str>,
    pub generators: Option<usize>,
    /// Why not.
    pub reason: Option<String>,
}

/// `chatter classify --json`.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct ClassifyReport {
    /// `chatter.classify/1`.
    pub schema: &'static str,
    pub n: u64,
    pub kappa: Number,
    pub gamma: Number,
    /// The number field the criteria are decided in (`null`: over Q), e.g. `Q(c) with c = cos(2*pi/5) ...`.
    pub field: Option<String>,
    /// Rod only: Goyal's condition sqrt(kappa) <= 2/(sqrt(gamma) + 1) - 1, decided exactly.
    pub goyal: Option<bool>,
    /// The CC criterion: S_1 (the rod: U_0 P) has a real, positive dominant eigenvalue.
    pub cc: Criterion,
    /// n >= 3: the PCC criterion, all eigenvalues of S_{n-1} S_1 real (false: the paper's
    /// Lemma excludes PCC).
    pub pcc: Option<Criterion>,
    /// Rod with `--velocity`: CC from that velocity.
    pub from_velocity: Option<FromVelocity>,
    /// The CC criterion's threshold in gamma for this kappa.
    pub cc_threshold: Threshold,
    /// n >= 3: the PCC criterion's threshold.
    pub pcc_threshold: Option<Threshold>,
    /// n >= 3: the float finder's verdicts.
    pub finder: Option<Finders>,
    /// A batch of random drops.
    pub drops: Option<Drops>,
    pub certificate: CertificateSummary,
    /// Only where the CC criterion fails and some simulated drop ends in CC (regular polygons,
    /// not the rod): the orbit certificate attempted there (docs/orbit-certificates.md), whether
    /// the kernel accepted it, what it proves, and what that says about the paper's Conjecture 1.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub orbit: Option<super::classify_orbit::OrbitSummary>,
    /// General convex bodies only (absent otherwise): the body, the conjectural product
    /// criteria and the PCC lemma per adjacent pair (docs/model.md §11.11). For them `n` is the
    /// number of contacts, `kappa` is 0, and `cc`, `cc_threshold` repeat the counter-clockwise
    /// product criterion.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub general_body: Option<super::classify_general::GeneralClassify>,
}

impl Report for ClassifyReport {
    const SCHEMA: &'static str = "chatter.classify/1";
}

/// Criteria of an n-gon body over the field `F` (Q, or a number field).
fn polygon<F: OrderedField + std::fmt::Display>(
    r: &ClassifyRequest,
    fam: &Family<F>,
) -> (Criterion, Criterion) {
    let body = fam.at(&r.gamma);
    let (cc, mut s1, dom) = cc_criterion(&body);
    let cc = criterion(cc, "S_1".into(), &mut s1, Some(dom), r.digits);
    let (pcc, mut s2) = pcc_criterion(&body);
    (cc, criterion(pcc, format!("S_{} S_1", r.n - 1), &mut s2, None, r.digits))
}

/// The rod: Goyal's condition, the CC criterion, CC from the velocity.
fn rod(r: &ClassifyRequest, rod: &Rod<Q>) -> (bool, Criterion, Option<FromVelocity>) {
    let goyal = goyal_condition(&r.kappa, &r.gamma);
    let (cc, mut s, dom) = rod_cc_criterion(rod);
    let cc = criterion(cc, "U_0 P".into(), &mut s, Some(dom), r.digits);
    let from = r.velocity.as_ref().map(|p0| {
        let inside = rod_velocity_in_cone(rod, p0);
        FromVelocity {
            velocity: [Number::of(&p0[0]), Number::of(&p0[1])],
            cc: inside == Some(true),
            cone_exists: inside.is_some(),
        }
    });
    (goyal, cc, from)
}

/// The float finder's maps: rounded from the exact model, else the float model of the n-gon.
fn float_body(r: &ClassifyRequest, exact: Option<&Polygon<Q>>) -> Option<FloatBody> {
    match exact {
        Some(b) => Some(FloatBody::new(b)),
        None => {
            FloatPolygon::new(r.n, r.kappa.to_f64(), r.gamma.to_f64()).ok().map(|b| FloatBody::from_float(&b))
        }
    }
}

fn finders(fb: &FloatBody) -> Finders {
    let run = |seed| FinderReport::of(&find_cone(fb, seed, &FinderConfig::default()).map(Vec::len));
    Finders { translation: run(Seed::Translation), all_down: run(Seed::AllDown) }
}

/// SIM_RUNS random drops of the model in f64 (seeds 0.., budget SIM_BUDGET).
pub(crate) fn drops(model: &Model) -> Drops {
    let briefs = simulate_many(model, 0, SIM_RUNS, Arithmetic::Float, &Options::new(SIM_BUDGET), &|| {});
    let c = counts(&briefs);
    let counts = Outcome::EVIDENCE.iter().zip(c).map(|(o, k)| (o.name().to_string(), k)).collect();
    Drops { basis: "evidence", runs: SIM_RUNS, budget: SIM_BUDGET, counts }
}

/// The certificate at the body (every n from 2 to 64: in Q(cos 2 pi/n) where that is irrational).
fn certificate(r: &ClassifyRequest) -> CertificateSummary {
    let none = |reason: String| CertificateSummary {
        verdict: Verdict::NotCertified,
        claim: None,
        generators: None,
        reason: Some(reason),
    };
    match certify(&Request::new(r.n, r.kappa.clone(), r.gamma.clone())).result {
        Ok(c) => CertificateSummary {
            verdict: Verdict::Certified,
            claim: Some(c.claim.name()),
            generators: Some(c.cone.len()),
            reason: None,
        },
        Err(e) => none(e.to_string()),
    }
}

/// Classifies one body: every criterion with its evidence, the thresholds, the finder, a batch
/// of drops and the certificate (the request is validated first).
pub fn classify(r: &ClassifyRequest) -> Result<ClassifyReport, String> {
    r.validate()?;
    let entry = bodies::user(r.n, &r.kappa)?;
    let exact = ExactShape::new(r.n, r.kappa.clone(), r.gamma.clone()).ok();
    let (goyal, cc, pcc, from_velocity) = match &exact {
        Some(ExactShape::Rod(b)) => {
            let (g, cc, from) = rod(r, b);
            (Some(g), cc, None, from)
        }
        Some(ExactShape::Polygon(_)) => {
            let c1 = entry.c1.as_rational().ok_or("an exact polygon has a rational cosine")?;
            let (cc, pcc) = polygon(r, &Family { n: r.n, c1, kappa: r.kappa.clone() });
            (None, cc, Some(pcc), None)
        }
        None => {
            let (cc, pcc) = polygon(r, &Family { n: r.n, c1: entry.c1.clone(), kappa: Nf::from_q(&r.kappa) });
            (None, cc, Some(pcc), None)
        }
    };
    let (cc_threshold, pcc_threshold) = bodies::thresholds(&entry, r.digits);
    let polygon = match &exact {
        Some(ExactShape::Polygon(b)) => Some(b),
        _ => None,
    };
    let finder = if r.n >= 3 { float_body(r, polygon).map(|fb| finders(&fb)) } else { None };
    let shape = if r.n == 2 { Shape::Rod } else { Shape::Polygon(r.n) };
    let drops = Model::new(shape, r.kappa.clone(), r.gamma.clone()).ok().map(|m| drops(&m));
    let orbit = super::classify_orbit::orbit_attempt(r.n, &r.kappa, &r.gamma, &cc, drops.as_ref());
    Ok(ClassifyReport {
        schema: ClassifyReport::SCHEMA,
        n: r.n,
        kappa: Number::of(&r.kappa),
        gamma: Number::of(&r.gamma),
        field: entry.c1.as_rational().is_none().then(|| entry.c1.field_meaning().unwrap_or_default()),
        goyal,
        cc,
        pcc,
        from_velocity,
        cc_threshold,
        pcc_threshold,
        finder,
        drops,
        certificate: certificate(r),
        orbit,
        general_body: None,
    })
}

fn holds(b: bool) -> &'static str {
    if b { "HOLDS" } else { "fails" }
}

/// A threshold in words.
pub fn threshold_text(t: &Threshold) -> String {
    match (t.kind, &t.decimal) {
        ("below", Some([lo, hi])) => format!("holds for gamma below a threshold in [{lo}, {hi}]"),
        ("up-to-one", _) => "holds for every gamma in (0, 1)".into(),
        _ => "never holds for gamma in (0, 1)".into(),
    }
}

fn eigen_text(c: &Criterion) -> String {
    c.eigenvalues.iter().map(Eigenvalue::text).collect::<Vec<_>>().join("; ")
}

impl ClassifyReport {
    /// The text output, one line per item.
    pub fn lines(&self) -> Vec<String> {
        if let Some(g) = &self.general_body {
            return super::classify_general::general_lines(self, g);
        }
        let method = match &self.field {
            None => "exact over Q".to_string(),
            Some(f) => format!("exact in Q({f})"),
        };
        let mut l = vec![format!(
            "body: n = {}, kappa = {}, gamma = {} ({method})",
            self.n, self.kappa.exact, self.gamma.exact
        )];
        self.criteria_lines(&mut l);
        l.push(format!("CC threshold for this kappa: {}", threshold_text(&self.cc_threshold)));
        if let Some(p) = &self.pcc_threshold {
            l.push(format!("PCC threshold for this kappa: {}", threshold_text(p)));
        }
        if let Some(f) = &self.finder {
            l.push(format!("float finder, translation seed: {}", f.translation.search()));
            l.push(format!("float finder, all-down seed: {}", f.all_down.search()));
        }
        if let Some(d) = &self.drops {
            self.drops_lines(d, &mut l);
        }
        let c = &self.certificate;
        l.push(match (c.claim, &c.reason) {
            (Some(claim), _) => format!(
                "certificate: {claim} ({} generators; `chatter certify` writes it)",
                c.generators.unwrap_or(0)
            ),
            (None, Some(r)) if self.field.is_some() => format!("certificate: none ({r})"),
            (None, r) => format!("certificate: none: {}", r.clone().unwrap_or_default()),
        });
        if let Some(o) = &self.orbit {
            super::classify_orbit::orbit_lines(o, &mut l);
        }
        l
    }

    fn criteria_lines(&self, l: &mut Vec<String>) {
        let cc = &self.cc;
        if let Some(g) = self.goyal {
            l.push(format!(
                "Goyal's condition sqrt(kappa) <= 2/(sqrt(gamma) + 1) - 1 (decided exactly): {}",
                holds(g)
            ));
            l.push(format!(
                "CC criterion (U_0 P has a real, positive dominant eigenvalue): {}",
                holds(cc.holds)
            ));
            l.push(format!("  det(tI - U_0 P) = {}", cc.char_poly));
            l.push(format!("  eigenvalues: {}; dominant: {}", eigen_text(cc), cc.dominant_text));
        } else {
            l.push(format!(
                "CC criterion (S_1 has a real, positive dominant eigenvalue): {}",
                holds(cc.holds)
            ));
            l.push(format!("  det(tI - S_1) = {}", cc.char_poly));
            l.push(format!("  eigenvalues: {}", eigen_text(cc)));
            l.push(format!("  dominant: {}", cc.dominant_text));
        }
        if let Some(p) = &self.pcc {
            l.push(format!("PCC criterion (all eigenvalues of {} real): {}", p.matrix, holds(p.holds)));
            l.push(format!("  det(tI - {}) = {}", p.matrix, p.char_poly));
            l.push(format!("  eigenvalues: {}", eigen_text(p)));
            l.push(if p.holds {
                "  PCC is not excluded by the paper's Lemma".into()
            } else {
                "  PCC is excluded by the paper's Lemma (complex eigenvalues)".into()
            });
        }
        if let Some(f) = &self.from_velocity {
            let (u0, u1) = (&f.velocity[0].exact, &f.velocity[1].exact);
            let text = match (f.cone_exists, f.cc) {
                (false, _) => "ICC from every initial velocity (the condition fails)".to_string(),
                (true, true) => format!("CC: the initial velocity ({u0}, {u1}) lies in the invariant cone"),
                (true, false) => {
                    format!("ICC: the initial velocity ({u0}, {u1}) lies outside the invariant cone")
                }
            };
            l.push(format!("from the given velocity: {text}"));
        }
    }

    fn drops_lines(&self, d: &Drops, l: &mut Vec<String>) {
        let count = |o: Outcome| d.counts.get(o.name()).copied().unwrap_or(0);
        let text: Vec<String> =
            Outcome::EVIDENCE.iter().map(|o| format!("{} {}", o.name(), count(*o))).collect();
        l.push(format!(
            "simulation (evidence: {} random drops in f64, budget {} impacts; `chatter simulate --exact` proves): {}",
            d.runs,
            d.budget,
            text.join(", ")
        ));
        let runs = d.runs;
        let chatter = count(Outcome::Cc) + count(Outcome::Pcc);
        if !self.cc.holds && chatter > 0 {
            l.push(format!("note: {chatter} of {runs} drops chatter although the CC criterion fails: evidence against the paper's Conjecture 1 ((i) <=> (iii))"));
        }
        let icc = count(Outcome::Icc);
        if self.cc.holds && icc > 0 {
            l.push(format!("note: {icc} of {runs} drops end in ICC although the CC criterion holds (the criterion concerns suitable initial conditions)"));
        }
    }
}
