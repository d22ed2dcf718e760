//! The general-body form of `chatter.classify/1` (docs/model.md §11.11, docs/bodies.md): the
//! body, the two conjectural product criteria around the polygon with their eigenvalues and
//! thresholds in gamma, the proved PCC exclusion per adjacent pair, simulated drops and the
//! certificate. Build it with [`classify_general`].

use super::classify::{CertificateSummary, ClassifyReport, Criterion, Drops, criterion, drops};
use super::convex::GeneralBodyReport;
use super::finder::FinderReport;
use super::{Number, Report, Verdict};
use crate::bodies::Threshold;
use crate::certify::convex::{ConvexRequest, certify_convex};
use crate::exact::{OrderedField, Q};
use crate::finder::Search;
use crate::simulate::{Model, Outcome};
use crate::spectral::convex::{
    Direction, PairExclusion, pair_exclusions, product_criterion, product_profile,
};
use crate::spectral::criteria::{Profile, Sup};
use chatter_kernel::model::{ConvexBody, PccExclusion};
use schemars::JsonSchema;
use serde::Serialize;

/// One conjectural product criterion (docs/model.md §11.11).
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct ProductCriterionReport {
    /// `counter-clockwise` (P_ccw = I_0 I_{n-1} ... I_1) or `clockwise` (P_cw = I_0 I_1 ... I_{n-1}).
    pub direction: &'static str,
    /// Always `conjectural`: no theorem links this criterion to CC for general bodies.
    pub status: &'static str,
    /// The dominant eigenvalue of the product is real and positive (decided exactly).
    pub criterion: Criterion,
    /// Where the criterion holds for gamma in (0, 1), the contacts and J fixed.
    pub threshold: Threshold,
}

/// The PCC lemma at one adjacent pair (docs/model.md §11.6: proved, not conjectural).
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct PairPccReport {
    /// The contacts (k, k + 1 mod n).
    pub pair: [usize; 2],
    /// t^2 + p t + q, the factor of det(tI - I_k I_{k+1}) beside t - 1 (null if not formed).
    pub p: Option<Number>,
    pub q: Option<Number>,
    /// p^2 - 4q.
    pub discriminant: Option<Number>,
    /// `excluded`, `real-roots`, `modulus-not-below-one` or `error`.
    pub verdict: &'static str,
    /// Whether the lemma excludes PCC of this pair.
    pub excluded: bool,
}

/// The general-body section of `chatter.classify/1`.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct GeneralClassify {
    pub body: GeneralBodyReport,
    /// The counter-clockwise product criterion (conjectural; S_1^n for regular polygons).
    pub counter_clockwise: ProductCriterionReport,
    /// The clockwise product criterion (conjectural; S_{n-1}^n for regular polygons).
    pub clockwise: ProductCriterionReport,
    /// The PCC lemma per adjacent pair (proved).
    pub pairs: Vec<PairPccReport>,
    /// The family finder's verdict (docs/model.md §11.12) for the claim the pipeline tried last
    /// (`found`: total vertices of the polygons K_0..K_{n-1}; `no-cone`: `step` is the target
    /// contact j of the transition whose image left v < 0); null if the search did not run.
    pub finder: Option<FinderReport>,
}

fn n(x: &Q) -> Number {
    Number::of(x)
}

/// The threshold of a product criterion's profile (`kind` as in `chatter bodies`).
fn threshold(p: &Profile<Q>, digits: usize) -> Threshold {
    let method = "exact over Q (Sturm sequences); the criterion is conjectural".to_string();
    let base = Threshold {
        kind: "never",
        interval: None,
        decimal: None,
        midpoint: None,
        polynomial: None,
        initial_interval: p.is_initial_interval(),
        method,
    };
    match p.sup() {
        Sup::Never => base,
        Sup::UpToOne => Threshold { kind: "up-to-one", ..base },
        Sup::At(t) => {
            let mut r = t.gamma.clone();
            let (lo, hi) = r.decimal_enclosure(digits);
            Threshold {
                kind: "below",
                interval: Some([r.lo.to_string(), r.hi.to_string()]),
                decimal: Some([lo, hi]),
                midpoint: Some(r.approx()),
                polynomial: Some(format!("{} (from the {})", t.factor.show("g"), t.source)),
                ..base
            }
        }
    }
}

/// The criterion of one direction; `threshold` is shared: P_ccw and P_cw have the same
/// characteristic polynomial at every gamma (docs/model.md §11.11).
fn product(
    body: &ConvexBody<Q>,
    dir: Direction,
    threshold: Threshold,
    digits: usize,
) -> ProductCriterionReport {
    let mut c = product_criterion(body, dir);
    let matrix = dir.matrix_text(body.n());
    ProductCriterionReport {
        direction: dir.name(),
        status: "conjectural",
        criterion: criterion(c.holds, matrix, &mut c.spectrum, Some(c.dominant), digits),
        threshold,
    }
}

fn pair<F: OrderedField>(
    e: &PairExclusion<F>,
    n_contacts: usize,
    num: impl Fn(&F) -> Number,
) -> PairPccReport {
    let verdict = match e.exclusion() {
        Some(PccExclusion::Excluded) => "excluded",
        Some(PccExclusion::RealRoots) => "real-roots",
        Some(PccExclusion::ModulusNotBelowOne) => "modulus-not-below-one",
        None => "error",
    };
    let q = e.quadratic.as_ref().ok();
    PairPccReport {
        pair: [e.k, (e.k + 1) % n_contacts],
        p: q.map(|q| num(&q.p)),
        q: q.map(|q| num(&q.q)),
        discriminant: q.map(|q| num(&q.discriminant)),
        verdict,
        excluded: verdict == "excluded",
    }
}

/// The certificate of the general-body pipeline (docs/model.md §11.12) at the body, and its
/// family finder's verdict.
fn certificate(body: &ConvexBody<Q>) -> (CertificateSummary, Option<FinderReport>) {
    let r = certify_convex(&ConvexRequest::new(body.clone()));
    let finder = r.finder.as_ref().map(FinderReport::of);
    let summary = match r.result {
        Ok(c) => CertificateSummary {
            verdict: Verdict::Certified,
            claim: Some(c.claim.name()),
            generators: Some(c.cones.iter().map(Vec::len).sum()),
            reason: None,
        },
        Err(e) => CertificateSummary {
            verdict: Verdict::NotCertified,
            claim: None,
            generators: None,
            reason: Some(e.to_string()),
        },
    };
    (summary, finder)
}

/// Classifies a general body (docs/model.md §11.11): `cc` and `cc_threshold` of the report
/// repeat the counter-clockwise product criterion, `kappa` is 0 (as in `simulate`).
pub fn classify_general(
    description: &str,
    body: &ConvexBody<Q>,
    digits: usize,
) -> Result<ClassifyReport, String> {
    if digits == 0 || digits > 60 {
        return Err(format!("--digits: {digits} is not accepted: give 1 to 60"));
    }
    let t = threshold(&product_profile(body, Direction::CounterClockwise), digits);
    let [ccw, cw] = Direction::BOTH.map(|d| product(body, d, t.clone(), digits));
    let pairs = pair_exclusions(body).iter().map(|e| pair(e, body.n(), n)).collect();
    let (certificate, finder) = certificate(body);
    let general = GeneralClassify {
        body: GeneralBodyReport::of(description, body),
        counter_clockwise: ccw.clone(),
        clockwise: cw,
        pairs,
        finder,
    };
    Ok(ClassifyReport {
        schema: ClassifyReport::SCHEMA,
        n: body.n() as u64,
        kappa: n(&Q::int(0)),
        gamma: n(body.gamma()),
        field: None,
        goyal: None,
        cc: ccw.criterion,
        pcc: None,
        from_velocity: None,
        cc_threshold: ccw.threshold,
        pcc_threshold: None,
        finder: None,
        drops: Some(drops(&Model::convex(body))),
        certificate,
        orbit: None,
        general_body: Some(general),
    })
}

fn holds(b: bool) -> &'static str {
    if b { "HOLDS" } else { "fails" }
}

fn body_lines(b: &GeneralBodyReport, r: &ClassifyReport, l: &mut Vec<String>) {
    l.push(format!(
        "body: {}, {} contacts, gamma = {} (general body, docs/model.md §11; exact over Q)",
        b.description, r.n, r.gamma.exact
    ));
    let pts: Vec<String> = b.contacts.iter().map(|c| format!("({}, {})", c[0].exact, c[1].exact)).collect();
    l.push(format!("  contacts (about the centre of mass, counter-clockwise): {}", pts.join(" ")));
    let j = &b.inertia;
    l.push(format!(
        "  J = [[{}, {}], [{}, {}]] per unit mass",
        j[0].exact, j[1].exact, j[1].exact, j[2].exact
    ));
}

fn product_lines(c: &ProductCriterionReport, l: &mut Vec<String>) {
    let m = &c.criterion.matrix;
    l.push(format!(
        "conjectural CC criterion, {} ({m} has a real, positive dominant eigenvalue): {}",
        c.direction,
        holds(c.criterion.holds)
    ));
    l.push(format!("  det(tI - {m}) = {}", c.criterion.char_poly));
    let eig: Vec<String> = c.criterion.eigenvalues.iter().map(|e| e.text()).collect();
    l.push(format!("  eigenvalues: {}", eig.join("; ")));
    l.push(format!("  dominant: {}", c.criterion.dominant_text));
    l.push(format!(
        "  conjectural threshold for these contacts and J: {}",
        super::classify::threshold_text(&c.threshold)
    ));
}

fn pair_line(p: &PairPccReport) -> String {
    let [a, b] = p.pair;
    let num = |x: &Option<Number>| x.as_ref().map_or("?".to_string(), |x| x.exact.clone());
    let what = match p.verdict {
        "excluded" => "PCC excluded (complex roots of modulus < 1)",
        "real-roots" => "not excluded (real roots)",
        "modulus-not-below-one" => "not excluded (complex roots of modulus >= 1)",
        _ => "not excluded (1 is not an eigenvalue: model error)",
    };
    format!(
        "PCC lemma (proved, docs/model.md §11.6), pair ({a}, {b}): {what}; t^2 + p t + q with p = {}, q = {}, p^2 - 4q = {}",
        num(&p.p),
        num(&p.q),
        num(&p.discriminant)
    )
}

fn drops_lines(g: &GeneralClassify, d: &Drops, l: &mut Vec<String>) {
    let count = |o: Outcome| d.counts.get(o.name()).copied().unwrap_or(0);
    let text: Vec<String> = Outcome::EVIDENCE.iter().map(|o| format!("{} {}", o.name(), count(*o))).collect();
    l.push(format!(
        "simulation (evidence: {} random drops in f64, budget {} impacts; `chatter simulate --exact` proves): {}",
        d.runs,
        d.budget,
        text.join(", ")
    ));
    let chatter = count(Outcome::Cc) + count(Outcome::Pcc);
    if !g.counter_clockwise.criterion.holds && !g.clockwise.criterion.holds && chatter > 0 {
        l.push(format!(
            "note: {chatter} of {} drops chatter although neither conjectural product criterion holds",
            d.runs
        ));
    }
}

/// The family finder's verdict in words.
fn family_text(f: &FinderReport, n: u64) -> String {
    match f.search() {
        Search::Found { cone, iterations } => {
            format!("found a family K_0..K_{} ({cone} vertices in all, {iterations} iterations)", n - 1)
        }
        Search::NoCone { iteration, step } => format!(
            "no family (an image under I_{step} of a piece K_i ∩ C_(i,{step}) has v >= 0 at iteration {iteration})"
        ),
        Search::Inconclusive { reason, .. } => format!("inconclusive: {reason}"),
    }
}

/// The text output of a general body's report (docs/model.md §11.11).
pub fn general_lines(r: &ClassifyReport, g: &GeneralClassify) -> Vec<String> {
    let mut l = Vec::new();
    body_lines(&g.body, r, &mut l);
    product_lines(&g.counter_clockwise, &mut l);
    product_lines(&g.clockwise, &mut l);
    l.extend(g.pairs.iter().map(pair_line));
    l.push(match &g.finder {
        Some(f) => format!("family finder (docs/model.md §11.12): {}", family_text(f, r.n)),
        None => "family finder: did not run (the claims were decided before the search)".into(),
    });
    if let Some(d) = &r.drops {
        drops_lines(g, d, &mut l);
    }
    let c = &r.certificate;
    l.push(match (c.claim, &c.reason) {
        (Some(claim), _) => format!(
            "certificate: {claim} ({} generators in {} cones; `chatter certify` with the same body options writes it)",
            c.generators.unwrap_or(0),
            r.n
        ),
        (None, reason) => format!("certificate: none: {}", reason.clone().unwrap_or_default()),
    });
    l
}
