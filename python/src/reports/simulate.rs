//! `simulate`: the fields of `chatter simulate --json`, for one drop or a batch of drops.

use crate::fail::Fail;
use crate::inputs;
use chatter::exact::Q;
use chatter::simulate::pattern::{find, summary_for};
use chatter::simulate::{
    Arithmetic, Decision, Initial, Model, Options, Outcome, Run, Shape, counts, simulate, simulate_many,
};
use chatter_kernel::model::BodyError;
use serde_json::{Value, json};

/// Limits of the command line.
const MAX_IMPACTS: usize = 10_000_000;
const MAX_RUNS: u64 = 1_000_000;
/// Contacts of the sequence listed in a single run's result.
const SEQUENCE: usize = 1000;

/// The arguments as the package passes them.
pub struct Args {
    pub n: u64,
    pub kappa: String,
    pub gamma: String,
    pub seed: u64,
    pub impacts: usize,
    pub exact: bool,
    pub runs: Option<u64>,
    pub position: Option<Vec<String>>,
    pub velocity: Option<Vec<String>>,
}

struct Validated {
    model: Model,
    n: u64,
    kappa: Q,
    gamma: Q,
    arithmetic: Arithmetic,
    initial: Initial,
    opts: Options,
}

fn bad(m: impl Into<String>) -> Fail {
    Fail::usage("invalid-input", m)
}

/// The rod or a regular n-gon, n <= 64; exact arithmetic only where the model is exact.
fn model(a: &Args, kappa: &Q, gamma: &Q) -> Result<Model, Fail> {
    let max = chatter::model::float::MAX_FLOAT_CONTACTS;
    if !(2..=max).contains(&a.n) {
        return Err(bad(format!("n: {} is outside 2..={max} (2 is the rod)", a.n)));
    }
    let shape = if a.n == 2 { Shape::Rod } else { Shape::Polygon(a.n) };
    let model = Model::new(shape, kappa.clone(), gamma.clone()).map_err(|e| {
        let code = match e {
            BodyError::KappaNotPositive => "kappa-not-positive",
            BodyError::GammaOutOfRange => "gamma-out-of-range",
            BodyError::UnsupportedN(_) => "unsupported-n",
        };
        Fail::usage(code, format!("invalid body: {e}"))
    })?;
    if a.exact && model.exact.is_none() {
        return Err(Fail::usage("unsupported-n", "exact simulation supports n = 2, 3, 4, 6 only"));
    }
    Ok(model)
}

/// A random drop from `seed`, or the given position and velocity.
fn initial(a: &Args, model: &Model) -> Result<Initial, Fail> {
    match (&a.position, &a.velocity) {
        (None, None) => Ok(Initial::RandomDrop { seed: a.seed }),
        (Some(_), Some(_)) if a.runs.is_some() => {
            Err(bad("runs repeats random drops: drop position/velocity"))
        }
        (Some(q), Some(p)) => {
            let (q, p) = (inputs::numbers("position", q)?, inputs::numbers("velocity", p)?);
            let start = model.given_start(&q, &p).map_err(|e| bad(format!("position/velocity: {e}")))?;
            Ok(Initial::Given(Box::new(start)))
        }
        _ => Err(bad("position and velocity go together: give both or neither")),
    }
}

fn validate(a: &Args) -> Result<Validated, Fail> {
    let (kappa, gamma) = (inputs::number("kappa", &a.kappa)?, inputs::number("gamma", &a.gamma)?);
    let model = model(a, &kappa, &gamma)?;
    if a.impacts == 0 || a.impacts > MAX_IMPACTS {
        return Err(bad(format!("impacts must be between 1 and {MAX_IMPACTS}")));
    }
    if a.runs.is_some_and(|m| !(1..=MAX_RUNS).contains(&m)) {
        return Err(bad(format!("runs must be between 1 and {MAX_RUNS}")));
    }
    let initial = initial(a, &model)?;
    let arithmetic = if a.exact { Arithmetic::Exact } else { Arithmetic::Float };
    Ok(Validated { model, n: a.n, kappa, gamma, arithmetic, initial, opts: Options::new(a.impacts) })
}

/// How a single run started.
fn start(v: &Validated) -> Value {
    let d = v.model.shape().dim();
    match &v.initial {
        Initial::RandomDrop { seed } => json!({"kind": "random-drop", "seed": seed}),
        Initial::Given(s) => json!({
            "kind": "given",
            "position": s.q[..d].iter().map(ToString::to_string).collect::<Vec<_>>(),
            "velocity": s.p[..d].iter().map(ToString::to_string).collect::<Vec<_>>(),
        }),
    }
}

/// One run, as `chatter simulate --json`.
fn single(v: &Validated, run: &Run) -> Value {
    let mut contact_counts = vec![0usize; v.model.n()];
    run.sequence.iter().for_each(|&k| contact_counts[k as usize] += 1);
    let pattern =
        find(&run.sequence).map(|p| json!({"transient": p.transient, "cycle": p.cycle, "tail": p.tail}));
    let tie = match &run.decision {
        Decision::Tie { contacts, exact, .. } => json!({"contacts": contacts, "exact": exact}),
        _ => Value::Null,
    };
    json!({
        "outcome": run.outcome.name(),
        "decided_by": run.decision.key(),
        "decided_by_text": run.decision.describe(),
        "impacts": run.impacts,
        "budget": run.budget,
        "n": v.n,
        "kappa": v.kappa.to_string(),
        "gamma": v.gamma.to_string(),
        "arithmetic": v.arithmetic.name(),
        "start": start(v),
        "sequence_summary": summary_for(&run.sequence, v.model.shape()),
        "pattern": pattern,
        "sequence": &run.sequence[..run.sequence.len().min(SEQUENCE)],
        "sequence_truncated": run.sequence.len() > SEQUENCE,
        "contact_counts": contact_counts,
        "total_time": run.time,
        "accumulation_time": run.accumulation,
        "log2_time_left_after_last_impact": run.tail_log2,
        "contraction_bits_per_impact": run.contraction,
        "simultaneous": tie,
        "pcc_criterion_overruled": run.pcc_overruled,
    })
}

/// A batch of random drops from consecutive seeds, as `chatter simulate --runs M --json`.
fn many(v: &Validated, seed: u64, runs: u64) -> Value {
    let briefs = simulate_many(&v.model, seed, runs, v.arithmetic, &v.opts, &|| {});
    let mut by = std::collections::BTreeMap::<&str, usize>::new();
    briefs.iter().for_each(|b| *by.entry(b.decided_by).or_default() += 1);
    let counts: serde_json::Map<String, Value> =
        Outcome::ALL.iter().zip(counts(&briefs)).map(|(o, k)| (o.name().to_string(), json!(k))).collect();
    json!({
        "runs": runs,
        "seeds": [seed, seed.wrapping_add(runs - 1)],
        "n": v.n,
        "kappa": v.kappa.to_string(),
        "gamma": v.gamma.to_string(),
        "arithmetic": v.arithmetic.name(),
        "budget": v.opts.budget,
        "counts": counts,
        "decided_by": by,
        "mean_impacts": briefs.iter().map(|b| b.impacts as f64).sum::<f64>() / briefs.len() as f64,
    })
}

/// One drop (the paper's random drop from `seed`, or a given start) or a batch of `runs` drops.
pub fn value(a: &Args) -> Result<Value, Fail> {
    let v = validate(a)?;
    Ok(match a.runs {
        Some(m) => many(&v, a.seed, m),
        None => single(&v, &simulate(&v.model, &v.initial, v.arithmetic, &v.opts)),
    })
}
