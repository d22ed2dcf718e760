//! `map`: the grid of `chatter map` evaluated in memory: the summary `chatter.map/1` (as
//! `summary.json`, `chatter::report::map::MapSummary`) with the points as columns named as in
//! points.csv (docs/map.md) under `"columns"`, the certificate and refutation texts in place of
//! their paths.

use crate::fail::Fail;
use chatter::report::{self, map::MapSummary};
use chatter::simulate::Outcome;
use chatter::sweep::grid::{Axis, Grid, Shard, Variable};
use chatter::sweep::point::Tasks;
use chatter::sweep::table::Row;
use chatter::sweep::{self, Done, Request};
use serde_json::{Map, Value, json};

/// Largest number of simulated drops per point (as the command line).
const MAX_RUNS: u64 = 100_000;

/// The arguments as the package passes them: the axes as `a:b:STEPS`.
pub struct Args {
    pub n: u64,
    pub variable: String,
    pub x: String,
    pub gamma: String,
    pub certify: bool,
    pub refute: bool,
    pub simulate: Option<u64>,
}

fn request(a: &Args) -> Result<Request, Fail> {
    let bad = |m: String| Fail::usage("invalid-input", m);
    let variable = match a.variable.as_str() {
        "rho" => Variable::Rho,
        "kappa" => Variable::Kappa,
        v => return Err(bad(format!("the horizontal variable {v:?} is not rho or kappa"))),
    };
    let x = Axis::parse(&a.x).map_err(|e| bad(format!("{}: {e}", a.variable)))?;
    let gamma = Axis::parse(&a.gamma).map_err(|e| bad(format!("gamma: {e}")))?;
    let grid = Grid { n: a.n, variable, x, gamma, family: None };
    grid.validate().map_err(bad)?;
    if a.simulate.is_some_and(|r| !(1..=MAX_RUNS).contains(&r)) {
        return Err(bad(format!("simulate: runs must be between 1 and {MAX_RUNS}")));
    }
    let tasks = Tasks {
        certify: a.certify,
        refute: a.refute,
        simulate: a.simulate,
        proof_budget: chatter::sweep::point::PROOF_BUDGET,
    };
    Ok(Request { grid, tasks, shard: Shard::ALL })
}

/// One point as a JSON object with the columns of points.csv.
fn point(row: &Row, done: &Done, variable: Variable) -> Map<String, Value> {
    let sim = row.sim.as_ref();
    let count = |o: Outcome| sim.map(|s| s.counts[o.index()]);
    let proved = |o: Outcome| sim.and_then(|s| s.proved).map(|p| p[o.index()]);
    let rho = match variable {
        Variable::Rho => json!(row.rho),
        Variable::Kappa | Variable::Parameter => json!(row.rho.parse::<f64>().ok()),
    };
    let obj = json!({
        "index": row.index, "n": row.n, "rho": rho,
        "kappa": row.kappa.to_string(), "gamma": row.gamma.to_string(),
        "cc_criterion": row.cc_criterion, "pcc_criterion": row.pcc_criterion,
        "finder": row.finder, "certified": row.certified, "claim": row.claim, "refuted": row.refuted,
        "sim_runs": sim.map(|s| s.runs), "sim_cc_evidence": count(Outcome::Cc),
        "sim_pcc_evidence": count(Outcome::Pcc), "sim_icc_evidence": count(Outcome::Icc),
        "sim_undecided_evidence": count(Outcome::Undecided),
        "sim_simultaneous_evidence": count(Outcome::Simultaneous),
        "mean_impacts": sim.map(|s| s.mean_impacts()),
        "sim_cc_proved": proved(Outcome::Cc), "sim_no_icc_no_pcc_proved": proved(Outcome::NoIccNoPcc),
        "sim_pcc_proved": proved(Outcome::Pcc), "sim_icc_proved": proved(Outcome::Icc),
        "sim_simultaneous_proved": proved(Outcome::Simultaneous), "sim_undecided": proved(Outcome::Undecided),
        "sim_contradicted": sim.filter(|s| s.proved.is_some()).map(|s| s.contradicted),
        "certificate": done.certificate, "refutation": done.refutation, "orbit": done.orbit,
    });
    match obj {
        Value::Object(m) => m,
        _ => Map::new(),
    }
}

/// Rows to columns, one per column of points.csv (keys in JSON order, i.e. sorted).
fn columns(rows: Vec<Map<String, Value>>) -> Value {
    let header = chatter::sweep::table::HEADER.split(',');
    let cols = header.map(|k| {
        let col: Vec<Value> = rows.iter().map(|r| r.get(k).cloned().unwrap_or(Value::Null)).collect();
        (k.to_string(), Value::Array(col))
    });
    Value::Object(cols.collect())
}

/// Evaluates every point of the grid (in parallel, on rayon's pool) and returns the summary
/// with the columns. This is `report::map::map` keeping each point's certificate and refutation
/// texts (that function returns the rows only, whose `certificate` is a path in a folder).
pub fn value(a: &Args) -> Result<Value, Fail> {
    let req = request(a)?;
    let done = sweep::run(&req, &|| {});
    if let Some(d) = done.iter().find(|d| d.internal.is_some()) {
        let why = d.internal.clone().unwrap_or_default();
        return Err(Fail::internal("internal", format!("point {}: {why}", d.row.index)));
    }
    let rows: Vec<Row> = done.iter().map(|d| d.row.clone()).collect();
    let summary = MapSummary::new(&req.grid, &req.computed(), &rows);
    let mut out = report::to_value(&summary);
    out["columns"] = columns(done.iter().map(|d| point(&d.row, d, req.grid.variable)).collect());
    Ok(out)
}
