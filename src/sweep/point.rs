//! One point of a map: the exact CC and PCC criteria, the float finder's verdict from the paper's
//! seed, optionally an exact certificate, and optionally the paper's random drops.

use super::grid::Point;
use crate::bodies::cosine;
use crate::certify::{Failure, Request, certify};
use crate::exact::{OrderedField, Q, QExt, QField};
use crate::finder::{FinderConfig, Seed, find_cone};
use crate::model::FloatBody;
use crate::prove::Effort;
use crate::simulate::certified::Source;
use crate::simulate::{
    Arithmetic, Brief, Certified, Model, Options, Outcome, counts, proved_counts, simulate_many,
};
use crate::spectral::criteria::{Family, cc_criterion, pcc_criterion};
use crate::write::write;
use chatter_kernel::model::{Polygon, Shape};

/// The paper's impact budget per simulated drop (section "Comparison with direct simulation").
pub const PAPER_BUDGET: usize = 200;

/// What to compute at every point besides the criteria and the finder.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Tasks {
    /// Try for an exact certificate (n = 3, 4, 6).
    pub certify: bool,
    /// Try for an exact refutation where no certificate was made (n = 3, 4, 6).
    pub refute: bool,
    /// Random drops per point (the paper's protocol, 200 impacts each, `f64`: evidence).
    pub simulate: Option<u64>,
    /// With `simulate`: the impact budget of the exact run of each drop that tries to prove its
    /// outcome (issue 22 §1; 0: no proofs).
    pub proof_budget: usize,
}

/// The default impact budget of the exact runs that prove drops' outcomes in a map.
pub const PROOF_BUDGET: usize = 300;

/// Outcome counts and mean impact count of the random drops at one point.
#[derive(Clone, Debug, PartialEq)]
pub struct SimStats {
    pub runs: u64,
    /// Evidence (the paper's 200-impact protocol in `f64`), in the order of [`Outcome::ALL`]:
    /// CC, PCC, ICC, undecided, simultaneous, and no-ICC-no-PCC (always 0: never evidence).
    pub counts: [u64; Outcome::COUNT],
    /// Proved outcomes of the same drops (exact runs, issue 22 §1), in the same order; a drop
    /// without a proof counts as undecided, a drop that entered a certified cone as
    /// no-ICC-no-PCC (CC only with a finite accumulation time). `None` when no proofs were tried.
    pub proved: Option<[u64; Outcome::COUNT]>,
    /// Drops whose proved outcome contradicts their decided evidence ([`Outcome::contradicts`]:
    /// no-ICC-no-PCC does not contradict CC).
    pub contradicted: u64,
    /// Sum over the drops of the impacts before the drop ended, capped at the budget; a drop
    /// classified PCC counts as the full budget (the paper's runs would have continued it).
    pub impacts: u64,
}

impl SimStats {
    /// Mean impact count per drop.
    pub fn mean_impacts(&self) -> f64 {
        self.impacts as f64 / self.runs as f64
    }
}

/// Everything computed at one point.
#[derive(Clone, Debug, PartialEq)]
pub struct Evaluation {
    pub cc_criterion: bool,
    pub pcc_criterion: bool,
    /// "found", "no-cone" or "inconclusive" (the float finder from -U_0 u_3, as in the paper).
    pub finder: &'static str,
    /// With certify: `Some(claim name)` when a certificate was made, `Some(None)` when not; `None`
    /// when not attempted (not asked, or n = 5 whose certificates need a number-field kernel).
    pub certified: Option<Option<&'static str>>,
    /// The certificate's text (RON), to be written under the output folder.
    pub certificate: Option<String>,
    /// With refute: `Some(true)` when an exact refutation was made and checked by the kernel,
    /// `Some(false)` when not; `None` when not attempted (not asked, certified, or n = 5).
    pub refuted: Option<bool>,
    /// The refutation's text (RON), to be written under the output folder.
    pub refutation: Option<String>,
    pub sim: Option<SimStats>,
    /// An orbit certificate made to prove drops CC (RON), to be written under the output folder.
    pub orbit: Option<String>,
    /// A backend disagreement inside the kernel (an internal error to report).
    pub internal: Option<String>,
    /// Per drop with proofs: the proved outcome (undecided when none) and the wall time of its
    /// exact run(s) in seconds (machine-dependent: printed by `map`, never written to a file).
    pub proof_times: Vec<(Outcome, f64)>,
}

impl Evaluation {
    /// The criteria and the finder's verdict at a point; nothing else computed yet.
    pub fn new(cc_criterion: bool, pcc_criterion: bool, finder: &'static str) -> Evaluation {
        Evaluation {
            cc_criterion,
            pcc_criterion,
            finder,
            certified: None,
            certificate: None,
            refuted: None,
            refutation: None,
            sim: None,
            orbit: None,
            internal: None,
            proof_times: Vec::new(),
        }
    }
}

/// What [`prove_point`] returns: proved counts, contradicted drops, an orbit certificate (RON),
/// and per drop its proved outcome and exact wall time.
type ProofsAt = ([u64; Outcome::COUNT], u64, Option<String>, Vec<(Outcome, f64)>);

/// cos(2 pi/n) as an exact rational when it is one (n = 3, 4, 6), else its nearest `f64` taken as
/// an exact dyadic: the float finder and the f64 simulator then work to f64 accuracy, as always.
fn model_cosine(n: u64) -> (Q, bool) {
    match cosine(n as usize).as_rational() {
        Some(c) => (c, true),
        None => {
            let c = (2.0 * std::f64::consts::PI / n as f64).cos();
            (Q::from_f64_exact(c).expect("finite cosine"), false)
        }
    }
}

/// The exact CC and PCC criteria (docs/model.md §6), over Q or in Q(cos 2 pi/n).
pub fn criteria(n: u64, kappa: &Q, gamma: &Q) -> (bool, bool) {
    let c1 = cosine(n as usize);
    match c1.as_rational() {
        Some(c) => at(&Family { n, c1: c, kappa: kappa.clone() }, gamma),
        None => at(&Family { n, c1, kappa: crate::spectral::number_field::Nf::from_q(kappa) }, gamma),
    }
}

fn at<F: OrderedField>(fam: &Family<F>, gamma: &Q) -> (bool, bool) {
    let body = fam.at(gamma);
    (cc_criterion(&body).0, pcc_criterion(&body).0)
}

/// The polygon the float finder and the simulator run on (exact cosine where rational).
pub fn float_model(n: u64, kappa: &Q, gamma: &Q) -> Polygon<Q> {
    Polygon::with_cosine(n, model_cosine(n).0, kappa.clone(), gamma.clone()).expect("a validated grid point")
}

/// The paper's random drops at one point (evidence); seeds depend on the point alone
/// ([`point_seed`]).
pub fn simulate_point(n: u64, p: &Point, runs: u64) -> SimStats {
    stats(runs, &evidence_briefs(n, p, runs))
}

/// The `f64` runs of the paper's drops at one point.
fn evidence_briefs(n: u64, p: &Point, runs: u64) -> Vec<Brief> {
    let model = Model::from_body(&Shape::Polygon(float_model(n, &p.kappa, &p.gamma)));
    let seed = point_seed(n, &p.kappa, &p.gamma);
    simulate_many(&model, seed, runs, Arithmetic::Float, &Options::new(PAPER_BUDGET), &|| {})
}

/// The evidence counts of the drops at one point.
fn stats(runs: u64, briefs: &[Brief]) -> SimStats {
    let impacts = briefs
        .iter()
        .map(|b| if b.outcome == Outcome::Pcc { PAPER_BUDGET } else { b.impacts.min(PAPER_BUDGET) } as u64)
        .sum();
    SimStats { runs, counts: counts(briefs).map(|c| c as u64), proved: None, contradicted: 0, impacts }
}

/// The same drops run exactly to prove their outcomes (issue 22 §1): against the point's cone
/// certificate (`certificate`, RON, when the map made one; else one is made here), and orbit
/// certificates made for the patterns of drops whose evidence is CC. Returns the proved counts,
/// the drops whose proof contradicts `evidence`, and an orbit certificate made (RON).
fn prove_point(n: u64, p: &Point, evidence: &[Brief], budget: usize, certificate: Option<&str>) -> ProofsAt {
    let runs = evidence.len() as u64;
    let Ok(model) = Model::new(crate::simulate::Shape::Polygon(n), p.kappa.clone(), p.gamma.clone()) else {
        return (Outcome::ALL.map(|o| if o == Outcome::Undecided { runs } else { 0 }), 0, None, Vec::new());
    };
    let sets = match certificate.map(chatter_kernel::certificate::read) {
        Some(Ok(cert)) => {
            let mut sets = Certified::empty();
            if let Err(e) = sets.add_cone(&model, &cert, "the point's certificate") {
                sets.notes.push(e);
            }
            crate::prove::add_rest_for(&mut sets, &model, n, Effort::Survey);
            sets
        }
        _ => crate::prove::cone(&model, Effort::Survey),
    };
    let seed = point_seed(n, &p.kappa, &p.gamma);
    let proved = crate::prove::prove_many(
        &model,
        seed,
        runs,
        &Options::new(budget),
        sets,
        Some(Effort::Survey),
        &|| {},
    );
    let contradicted = contradicted(&proved.briefs, evidence);
    let orbit = proved.sets.sets().iter().find_map(|s| match &s.source {
        Source::Orbit(c) => Some(crate::write::write_orbit(c)),
        Source::Cone(_) | Source::Rest(_) | Source::RestFamily(_) => None,
    });
    let times = proved
        .briefs
        .iter()
        .map(|b| (if b.proved { b.outcome } else { Outcome::Undecided }, b.seconds))
        .collect();
    (proved_counts(&proved.briefs).map(|c| c as u64), contradicted, orbit, times)
}

/// The drops whose proved outcome contradicts their decided evidence ([`Outcome::contradicts`]).
pub(super) fn contradicted(proved: &[Brief], evidence: &[Brief]) -> u64 {
    let decided = |o: Outcome| matches!(o, Outcome::Cc | Outcome::Pcc | Outcome::Icc);
    (proved.iter().zip(evidence))
        .filter(|(b, e)| b.proved && decided(e.outcome) && b.outcome.contradicts(e.outcome))
        .count() as u64
}

/// The first seed of a point's drops: FNV-1a of "n/kappa/gamma", so that a point gets the same
/// drops in every grid, shard and thread count.
pub fn point_seed(n: u64, kappa: &Q, gamma: &Q) -> u64 {
    format!("{n}/{kappa}/{gamma}")
        .bytes()
        .fold(0xcbf2_9ce4_8422_2325, |h, b| (h ^ b as u64).wrapping_mul(0x0100_0000_01b3))
}

/// Evaluates one point.
pub fn evaluate(n: u64, p: &Point, tasks: Tasks) -> Evaluation {
    let (cc_criterion, pcc_criterion) = criteria(n, &p.kappa, &p.gamma);
    let body = float_model(n, &p.kappa, &p.gamma);
    let finder = find_cone(&FloatBody::new(&body), Seed::Translation, &FinderConfig::default()).label();
    let mut e = Evaluation::new(cc_criterion, pcc_criterion, finder);
    if tasks.certify && model_cosine(n).1 {
        let report = certify(&Request::new(n, p.kappa.clone(), p.gamma.clone()).survey());
        match report.result {
            Ok(cert) => {
                e.certified = Some(Some(cert.claim.name()));
                e.certificate = Some(write(&cert));
            }
            Err(Failure::Internal(s)) => e.internal = Some(s),
            Err(_) => e.certified = Some(None),
        }
    }
    if tasks.refute && model_cosine(n).1 {
        refute_point(n, p, &mut e);
    }
    if let Some(runs) = tasks.simulate {
        let briefs = evidence_briefs(n, p, runs);
        let mut sim = stats(runs, &briefs);
        if tasks.proof_budget > 0 {
            let (proved, contradicted, orbit, times) =
                prove_point(n, p, &briefs, tasks.proof_budget, e.certificate.as_deref());
            sim.proved = Some(proved);
            sim.contradicted = contradicted;
            e.orbit = orbit;
            e.proof_times = times;
        }
        e.sim = Some(sim);
    }
    e
}

/// An exact refutation (the translation seed first, then the all-down seeds), kept only if the
/// kernel accepts it on both backends.
fn refute_point(n: u64, p: &Point, e: &mut Evaluation) {
    use chatter_kernel::certificate::Claim;
    use chatter_kernel::verify::{MALACHITE, NUM, Verdict, verify_refutation};
    if matches!(e.certified, Some(Some(_))) {
        return;
    }
    let cfg = crate::refute::RefuteConfig::default();
    let made = [Claim::EffectivelyInvariant, Claim::CcOrPccFromAllDown]
        .iter()
        .find_map(|c| crate::refute::refute(n, &p.kappa, &p.gamma, *c, &cfg).ok());
    e.refuted = Some(false);
    if let Some(r) = made {
        match verify_refutation(&r, Default::default(), &[MALACHITE, NUM]) {
            Verdict::Accepted(_) => {
                e.refuted = Some(true);
                e.refutation = Some(crate::write::write_refutation(&r));
            }
            Verdict::Rejected(x) => {
                e.internal = Some(format!("the kernel rejects a refutation chatter made: {x}"))
            }
            Verdict::Disagree(s) => e.internal = Some(s),
        }
    }
}
