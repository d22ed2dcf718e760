//! `chatter.simulate/1` (one drop) and `chatter.simulate-batch/1` (`--runs M` random drops).
//! Build them with [`single`] and [`batch`] (each runs the simulation), or [`of_run`] from a
//! run already made.

use super::{Number, Report};
use crate::simulate::pattern::find;
use crate::simulate::{
    Arithmetic, Decision, Initial, Model, Options, Outcome, Run, counts, simulate, simulate_many,
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

/// `chatter simulate --json` (one drop).
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct SimulateReport {
    /// `chatter.simulate/1`.
    pub schema: &'static str,
    /// `CC`, `PCC`, `ICC`, `undecided` or `simultaneous`.
    pub outcome: &'static str,
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
    /// Outcome (`CC`, `PCC`, `ICC`, `undecided`, `simultaneous`) -> drops.
    pub counts: BTreeMap<String, usize>,
    /// Deciding test -> drops.
    pub decided_by: BTreeMap<String, usize>,
    pub mean_impacts: f64,
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
        log2_time_left_after_last_impact: run.tail_log2,
        contraction_bits_per_impact: run.contraction,
        simultaneous,
        pcc_criterion_overruled: run.pcc_overruled,
        trajectory: None,
        plot: None,
    }
}

/// Simulates one drop and reports it; the run itself (with its records if `opts.record`) is
/// returned too.
pub fn single(
    model: &Model,
    initial: &Initial,
    arithmetic: Arithmetic,
    opts: &Options,
) -> (SimulateReport, Run) {
    let run = simulate(model, initial, arithmetic, opts);
    (of_run(model, initial, arithmetic, &run), run)
}

/// Simulates `runs` random drops with seeds `seed..seed + runs` in parallel, calling `tick`
/// after each, and reports the counts.
pub fn batch(
    model: &Model,
    seed: u64,
    runs: u64,
    arithmetic: Arithmetic,
    opts: &Options,
    tick: &(dyn Fn() + Sync),
) -> SimulateBatchReport {
    let briefs = simulate_many(model, seed, runs, arithmetic, opts, tick);
    let c = counts(&briefs);
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
        counts: Outcome::ALL.iter().zip(c).map(|(o, k)| (o.name().to_string(), k)).collect(),
        decided_by,
        mean_impacts: briefs.iter().map(|b| b.impacts as f64).sum::<f64>() / briefs.len().max(1) as f64,
    }
}
