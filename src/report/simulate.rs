//! `chatter.simulate/1` (one drop) and `chatter.simulate-batch/1` (`--runs M` random drops).
//! Build them with [`single`] and [`batch`] (each runs the simulation), or [`of_run`] from a
//! run already made.

use super::{Number, Report};
use crate::exact::{QExt, Rounding};
use crate::simulate::pattern::find;
use crate::simulate::{
    Arithmetic, Brief, Certified, Decision, Initial, Model, Options, Outcome, Run, SetKind, counts,
    evidence_counts, proved_counts, simulate_many,
};
use schemars::JsonSchema;
use serde::Serialize;
use std::collections::BTreeMap;

/// Impacts of the sequence included in the report (the rest is summarised by `pattern`).
pub const JSON_SEQUENCE: usize = 1000;

/// The initial state.
#[derive(Clone, Debug, Serialize, JsonSchema)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum StartReport {
    /// The paper's random drop with this seed.
    RandomDrop { seed: u64 },
    /// A given state: heights (h0, h1[, hc]) and velocities (u0, u1[, v]) in our coordinates.
    Given { position: Vec<Number>, velocity: Vec<Number> },
}

/// The periodic tail of the contact sequence.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct PatternReport {
    /// Impacts before the periodic tail.
    pub transient: usize,
    /// One period (contact indices).
    pub cycle: Vec<u8>,
    /// Length of the periodic tail.
    pub tail: usize,
}

/// A simultaneous impact that stopped the run.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct TieReport {
    pub contacts: Vec<usize>,
    /// Decided exactly (else a float near-tie).
    pub exact: bool,
}

/// What the evidence rules said (issue 22 §1): the paper's protocol, never a proof by itself.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct EvidenceReport {
    /// `CC`, `PCC`, `ICC`, `undecided` or `simultaneous`, by the rule `decided_by` (never
    /// `no-ICC-no-PCC`: a cone entry's evidence is `CC`, the paper's Lemma on v).
    pub outcome: &'static str,
    /// The rule (e.g. `converging-intervals`, `v-positive`).
    pub decided_by: &'static str,
    /// The rule's evidence in words.
    pub description: String,
    /// Impacts simulated.
    pub impacts: usize,
    /// The centre's velocity v after the last impact (`f64`; the initial v is -1 for random drops).
    pub last_v: f64,
}

/// A set whose entry proves a drop's outcome, with the certificate it comes from: a cone K proves
/// no ICC and no PCC (`no-ICC-no-PCC`), an orbit certificate's set X proves CC.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct SetReport {
    /// `cone` (velocities in K) or `orbit` (normalised states in X).
    pub kind: &'static str,
    /// The certificate's file, or how it was made.
    pub certificate: String,
    /// The claim the kernel accepted (both backends).
    pub claim: &'static str,
}

/// Where a drop entered a certified set.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct EnteredReport {
    /// The impact after which the state lay in the set (from 1).
    pub impact: usize,
    /// `cone` or `orbit`.
    pub kind: &'static str,
    /// The certificate's file, or how it was made.
    pub certificate: String,
    /// Whether the set's theorem proves that the impacts accumulate at a finite time: true for
    /// an orbit certificate, and for a rod cone certificate with rule T1 when the drop was
    /// all-down at its first impact; false for any other cone entry, which proves v <= 0 for ever
    /// (no separation, impacts never stop) and no PCC, but not the finite time (docs/time-to-rest.md).
    pub finite_time: bool,
    /// A proved upper bound of the time, from the start, at which the impacts accumulate (decimal,
    /// rounded up). For an orbit certificate: the exact time of the entering impact, rounded up,
    /// plus its `time_to_rest_bound` B times h/|v| at that impact. For a rod cone certificate
    /// with rule T1 and a drop all-down at its first impact: the same at the first impact
    /// (docs/time-to-rest.md §2). Null for every other cone entry.
    pub time_to_rest_bound: Option<String>,
}

/// The certified sets a run was checked against, and why any is missing.
pub fn set_reports(sets: &Certified) -> Vec<SetReport> {
    sets.sets()
        .iter()
        .map(|s| SetReport { kind: s.kind.name(), certificate: s.name.clone(), claim: s.claim.name() })
        .collect()
}

/// Where a decision entered a certified set, if it is such an entry.
fn entered_report(decision: &Decision) -> Option<EnteredReport> {
    let Decision::Certified { after, kind, name, rest_by } = decision else { return None };
    Some(EnteredReport {
        impact: *after,
        kind: kind.name(),
        certificate: name.clone(),
        finite_time: *kind == SetKind::Orbit || rest_by.is_some(),
        time_to_rest_bound: rest_by.as_ref().map(|t| t.decimal(9, Rounding::Up)),
    })
}

/// The velocity v of the centre of mass in a snapshot (v = (u0 + u1)/2 for the rod).
pub fn snapshot_v(model: &Model, s: &crate::simulate::Snapshot) -> f64 {
    let v = if model.shape().dim() == 2 { (s.p[0] + s.p[1]) / 2.0 } else { s.p[2] };
    v * (s.p_exp as f64).exp2()
}

/// The evidence of a run.
pub fn evidence_of(model: &Model, run: &Run) -> EvidenceReport {
    EvidenceReport {
        outcome: run.evidence.name(),
        decided_by: run.decision.key(),
        description: run.decision.describe(),
        impacts: run.impacts,
        last_v: snapshot_v(model, &run.last),
    }
}

/// `chatter simulate --json` (one drop).
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct SimulateReport {
    /// `chatter.simulate/1`.
    pub schema: &'static str,
    /// The verdict: `CC`, `PCC`, `ICC`, `no-ICC-no-PCC`, `undecided` or `simultaneous`. With exact
    /// arithmetic it is proved (`proved`) or `undecided`; in `f64` it is evidence (`proved`
    /// false). `no-ICC-no-PCC` (exact runs only): proved never to separate and never to end in PCC
    /// by entering a certified cone; CC unless the impacts take infinite time, the finite
    /// accumulation time not being derived (docs/time-to-rest.md); `CC` is proved only with a
    /// finite accumulation time (an orbit certificate's set, `entered.finite_time`, or the exact
    /// pair proof).
    pub outcome: &'static str,
    /// Whether `outcome` is proved (exact arithmetic; for CC and `no-ICC-no-PCC` a kernel-checked
    /// certificate).
    pub proved: bool,
    /// `proof` or `evidence`.
    pub basis: &'static str,
    /// What the rules of the simulator say, as evidence.
    pub evidence: EvidenceReport,
    /// Where the drop entered a certified set (the proof of CC for an orbit certificate's set, of
    /// `no-ICC-no-PCC` for a cone), if it did.
    pub entered: Option<EnteredReport>,
    /// The cone entry an exact run went on past (issue 24 §2; docs/time-to-rest.md §1): the first
    /// fact proved (no ICC, no PCC: `kind` `cone`, `finite_time` false). For a drop proved CC
    /// after it, `entered` is the later orbit entry (CC, with its bound); when no orbit set
    /// followed within the budget it is the same entry as `entered`. Null when the run did not go
    /// on past a cone (it stopped there, or entered no cone).
    pub cone_entry: Option<EnteredReport>,
    /// The certified sets the exact run was checked against (empty in `f64`).
    pub certified_sets: Vec<SetReport>,
    /// Why a certified set is missing (e.g. no cone certificate above the CC threshold).
    pub certificate_notes: Vec<String>,
    /// The test that decided it (e.g. `paper-pcc-criterion`, `exact-tie`, `converging`).
    pub decided_by: &'static str,
    pub impacts: usize,
    /// The impact budget.
    pub budget: usize,
    pub n: u64,
    /// A general convex body (docs/model.md §11), else `null`.
    pub general_body: Option<super::convex::GeneralBodyReport>,
    /// 0 for a general body (`general_body`).
    pub kappa: Number,
    pub gamma: Number,
    /// `f64` or `exact`.
    pub arithmetic: &'static str,
    pub start: StartReport,
    pub pattern: Option<PatternReport>,
    /// The first impacts' contacts (at most [`JSON_SEQUENCE`]).
    pub sequence: Vec<u8>,
    pub sequence_truncated: bool,
    /// Impacts per contact.
    pub contact_counts: Vec<usize>,
    /// Time of the last impact.
    pub total_time: f64,
    /// The estimated (or, for an exact pair proof, bounded) accumulation time.
    pub accumulation_time: Option<f64>,
    pub log2_time_left_after_last_impact: Option<f64>,
    pub contraction_bits_per_impact: Option<f64>,
    pub simultaneous: Option<TieReport>,
    /// Pair phases where the paper's PCC test fired but the PCC Lemma excludes PCC.
    pub pcc_criterion_overruled: usize,
    /// The trajectory CSV written (`--trajectory`).
    pub trajectory: Option<String>,
    /// The figure written (`--plot`).
    pub plot: Option<String>,
    /// Rod drops with both ends moving down (docs/time-to-rest.md §2): the measured time to rest
    /// against the theorem's bound (evidence: the time comes from this simulation); else null.
    pub time_to_rest: Option<TimeToRestReport>,
}

/// A drop's time to rest against the bound B of T <= B h/|v| (docs/time-to-rest.md §2).
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct TimeToRestReport {
    /// B, exact ("p/q"), as rule T1 of the kernel checks it.
    pub bound: String,
    /// T|v|/h measured (evidence): T from the first impact to the accumulation point, h and v the
    /// centre's height and velocity just before the first impact.
    pub measured: f64,
    /// Whether measured <= B (with a relative tolerance of 1e-9 for the f64 measurement).
    pub within: bool,
}

impl TimeToRestReport {
    /// The report of a measurement.
    pub fn of(m: &crate::simulate::rest::Measured) -> Self {
        let b = crate::exact::QExt::to_f64(&m.bound);
        TimeToRestReport {
            bound: m.bound.to_string(),
            measured: m.ratio,
            within: m.ratio <= b * (1.0 + 1e-9),
        }
    }
}

impl Report for SimulateReport {
    const SCHEMA: &'static str = "chatter.simulate/1";
}

/// `chatter simulate --runs M --json`.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct SimulateBatchReport {
    /// `chatter.simulate-batch/1`.
    pub schema: &'static str,
    pub runs: u64,
    /// First and last seed.
    pub seeds: [u64; 2],
    pub n: u64,
    /// A general convex body (docs/model.md §11), else `null`.
    pub general_body: Option<super::convex::GeneralBodyReport>,
    /// 0 for a general body (`general_body`).
    pub kappa: Number,
    pub gamma: Number,
    /// `f64` or `exact`.
    pub arithmetic: &'static str,
    pub budget: usize,
    /// `proof` (exact arithmetic: `counts` counts proved outcomes, the rest `undecided`) or
    /// `evidence` (`f64`: `counts` is evidence, nothing is proved).
    pub basis: &'static str,
    /// Outcome (`CC`, `PCC`, `ICC`, `undecided`, `simultaneous`, `no-ICC-no-PCC`) -> drops: the
    /// verdicts.
    pub counts: BTreeMap<String, usize>,
    /// Proved outcome (the six of `counts`) -> drops (a drop without a proof counts as
    /// `undecided`); all undecided in `f64`. `CC` counts only drops proved CC with a finite
    /// accumulation time; a drop that entered a certified cone counts as `no-ICC-no-PCC`.
    pub proved: BTreeMap<String, usize>,
    /// What the rules say as evidence (the paper's protocol) -> drops: `CC`, `PCC`, `ICC`,
    /// `undecided`, `simultaneous` (a cone entry's evidence is `CC`).
    pub evidence: BTreeMap<String, usize>,
    /// The certified sets the exact runs were checked against (empty in `f64`).
    pub certified_sets: Vec<SetReport>,
    /// Why a certified set is missing.
    pub certificate_notes: Vec<String>,
    /// Deciding test -> drops.
    pub decided_by: BTreeMap<String, usize>,
    /// Drops proved CC by entering an orbit certificate's set after a cone entry had proved them
    /// no-ICC-no-PCC, the exact run going on past it (issue 24 §2; counted in `proved.CC`).
    pub cc_after_cone: usize,
    pub mean_impacts: f64,
    /// Rod bodies (docs/time-to-rest.md §2): the drops' measured T|v|/h against the bound B
    /// (evidence); null for other bodies.
    pub time_to_rest: Option<BatchTimeToRestReport>,
}

/// The batch's measured times to rest against B.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct BatchTimeToRestReport {
    /// B, exact ("p/q"), as rule T1 checks it.
    pub bound: String,
    /// Drops measured (an accumulation time was estimated).
    pub measured: usize,
    /// The largest T|v|/h measured.
    pub largest: Option<f64>,
    /// Drops with T|v|/h > B (beyond a relative 1e-9): a violation would contradict the theorem.
    pub violations: usize,
}

impl Report for SimulateBatchReport {
    const SCHEMA: &'static str = "chatter.simulate-batch/1";
}

fn start(model: &Model, initial: &Initial) -> StartReport {
    let d = model.shape().dim();
    match initial {
        Initial::RandomDrop { seed } => StartReport::RandomDrop { seed: *seed },
        Initial::Given(s) => StartReport::Given {
            position: s.q[..d].iter().map(Number::of).collect(),
            velocity: s.p[..d].iter().map(Number::of).collect(),
        },
    }
}

/// Impacts per contact.
pub fn contact_counts(run: &Run, n: usize) -> Vec<usize> {
    let mut c = vec![0; n];
    for &k in &run.sequence {
        c[k as usize] += 1;
    }
    c
}

/// The report of a run made from `initial` (no files written).
pub fn of_run(model: &Model, initial: &Initial, arithmetic: Arithmetic, run: &Run) -> SimulateReport {
    let simultaneous = match &run.decision {
        Decision::Tie { contacts, exact, .. } => {
            Some(TieReport { contacts: contacts.clone(), exact: *exact })
        }
        _ => None,
    };
    let pattern =
        find(&run.sequence).map(|p| PatternReport { transient: p.transient, cycle: p.cycle, tail: p.tail });
    SimulateReport {
        schema: SimulateReport::SCHEMA,
        outcome: run.outcome.name(),
        proved: run.proved,
        basis: if run.proved { "proof" } else { "evidence" },
        evidence: evidence_of(model, run),
        entered: entered_report(&run.decision),
        cone_entry: run.cone_entry.as_ref().and_then(entered_report),
        certified_sets: Vec::new(),
        certificate_notes: Vec::new(),
        decided_by: run.decision.key(),
        impacts: run.impacts,
        budget: run.budget,
        n: model.n() as u64,
        general_body: None,
        kappa: Number::of(&model.kappa),
        gamma: Number::of(&model.gamma),
        arithmetic: arithmetic.name(),
        start: start(model, initial),
        pattern,
        sequence: run.sequence[..run.sequence.len().min(JSON_SEQUENCE)].to_vec(),
        sequence_truncated: run.sequence.len() > JSON_SEQUENCE,
        contact_counts: contact_counts(run, model.n()),
        total_time: run.time,
        accumulation_time: run.accumulation,
        time_to_rest: crate::simulate::rest::measure(model, initial, run).as_ref().map(TimeToRestReport::of),
        log2_time_left_after_last_impact: run.tail_log2,
        contraction_bits_per_impact: run.contraction,
        simultaneous,
        pcc_criterion_overruled: run.pcc_overruled,
        trajectory: None,
        plot: None,
    }
}

/// Simulates one drop and reports it; the run itself (with its records if `opts.record`) is
/// returned too. Exact runs are checked against `sets` (and orbit certificates made for their
/// pattern with `make_orbits`); `f64` runs are evidence.
pub fn single(
    model: &Model,
    initial: &Initial,
    arithmetic: Arithmetic,
    opts: &Options,
    sets: Option<Certified>,
    make_orbits: bool,
) -> (SimulateReport, Run) {
    let (run, sets) = match (arithmetic, sets) {
        (Arithmetic::Exact, Some(sets)) => {
            let (run, sets) = crate::prove::prove_one(
                model,
                initial,
                opts,
                sets,
                make_orbits.then_some(crate::prove::Effort::Full),
            );
            (run, Some(sets))
        }
        _ => (crate::simulate::simulate(model, initial, arithmetic, opts), None),
    };
    let mut report = of_run(model, initial, arithmetic, &run);
    if let Some(sets) = &sets {
        report.certified_sets = set_reports(sets);
        report.certificate_notes = sets.notes.clone();
    }
    (report, run)
}

/// The briefs' measured times to rest against the rod's bound (docs/time-to-rest.md §2).
fn batch_time_to_rest(model: &Model, briefs: &[Brief]) -> Option<BatchTimeToRestReport> {
    if !matches!(model.shape(), crate::simulate::Shape::Rod) {
        return None;
    }
    let bound = crate::certify::rest::rod_bound(&model.kappa, &model.gamma)?;
    let b = crate::exact::QExt::to_f64(&bound);
    let ratios: Vec<f64> = briefs.iter().filter_map(|x| x.time_to_rest).collect();
    Some(BatchTimeToRestReport {
        bound: bound.to_string(),
        measured: ratios.len(),
        largest: ratios.iter().copied().reduce(f64::max),
        violations: ratios.iter().filter(|&&r| r > b * (1.0 + 1e-9)).count(),
    })
}

/// Simulates `runs` random drops with seeds `seed..seed + runs` in parallel, calling `tick`
/// after each, and reports the counts.
#[allow(clippy::too_many_arguments)]
pub fn batch(
    model: &Model,
    seed: u64,
    runs: u64,
    arithmetic: Arithmetic,
    opts: &Options,
    sets: Option<Certified>,
    make_orbits: bool,
    tick: &(dyn Fn() + Sync),
) -> SimulateBatchReport {
    let (briefs, sets): (Vec<Brief>, Option<Certified>) = match (arithmetic, sets) {
        (Arithmetic::Exact, Some(sets)) => {
            let p = crate::prove::prove_many(
                model,
                seed,
                runs,
                opts,
                sets,
                make_orbits.then_some(crate::prove::Effort::Full),
                tick,
            );
            (p.briefs, Some(p.sets))
        }
        _ => (simulate_many(model, seed, runs, arithmetic, opts, tick), None),
    };
    let c = counts(&briefs);
    let map = |outcomes: &[Outcome], c: [usize; Outcome::COUNT]| -> BTreeMap<String, usize> {
        outcomes.iter().zip(c).map(|(o, k)| (o.name().to_string(), k)).collect()
    };
    let mut decided_by = BTreeMap::new();
    for b in &briefs {
        *decided_by.entry(b.decided_by.to_string()).or_default() += 1;
    }
    SimulateBatchReport {
        schema: SimulateBatchReport::SCHEMA,
        runs,
        seeds: [seed, seed.wrapping_add(runs.saturating_sub(1))],
        n: model.n() as u64,
        general_body: None,
        kappa: Number::of(&model.kappa),
        gamma: Number::of(&model.gamma),
        arithmetic: arithmetic.name(),
        budget: opts.budget,
        basis: if arithmetic == Arithmetic::Exact { "proof" } else { "evidence" },
        counts: map(&Outcome::ALL, c),
        proved: map(&Outcome::ALL, proved_counts(&briefs)),
        evidence: map(&Outcome::EVIDENCE, evidence_counts(&briefs)),
        certified_sets: sets.as_ref().map(set_reports).unwrap_or_default(),
        certificate_notes: sets.map(|s| s.notes).unwrap_or_default(),
        decided_by,
        cc_after_cone: briefs
            .iter()
            .filter(|b| b.proved && b.outcome == Outcome::Cc && b.cone_after.is_some())
            .count(),
        mean_impacts: briefs.iter().map(|b| b.impacts as f64).sum::<f64>() / briefs.len().max(1) as f64,
        time_to_rest: batch_time_to_rest(model, &briefs),
    }
}
