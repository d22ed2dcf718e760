//! `simulate`: the reports of `chatter simulate --json` (`chatter::report::simulate`), for one
//! drop or a batch of drops; the arguments are checked here as the command line checks them.

use crate::fail::Fail;
use crate::inputs;
use chatter::exact::Q;
use chatter::report::{self, simulate};
use chatter::simulate::{Arithmetic, Initial, Model, Options, Shape};
use chatter_kernel::model::BodyError;
use serde_json::Value;

/// Limits of the command line.
const MAX_IMPACTS: usize = 10_000_000;
const MAX_RUNS: u64 = 1_000_000;

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
    arithmetic: Arithmetic,
    initial: Initial,
    opts: Options,
}

fn bad(m: impl Into<String>) -> Fail {
    Fail::usage("invalid-input", m)
}

/// The rod or a regular n-gon, n <= 64 (exact arithmetic in Q or in Q(cos 2 pi/n)).
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
    Ok(Validated { model, arithmetic, initial, opts: Options::new(a.impacts) })
}

/// One drop (the paper's random drop from `seed`, or a given start) or a batch of `runs` drops:
/// the reports `chatter.simulate/1` and `chatter.simulate-batch/1`.
pub fn value(a: &Args) -> Result<Value, Fail> {
    let v = validate(a)?;
    // Exact runs of regular polygons and the rod are checked against certified sets made on the
    // fly (issue 22 §1), as `chatter simulate --exact` does.
    let polygon =
        matches!(v.model.shape(), chatter::simulate::Shape::Polygon(_) | chatter::simulate::Shape::Rod);
    let sets = (v.arithmetic == Arithmetic::Exact && polygon).then(|| chatter::prove::made(&v.model));
    let orbits = sets.is_some();
    Ok(match a.runs {
        Some(m) => report::to_value(&simulate::batch(
            &v.model,
            a.seed,
            m,
            v.arithmetic,
            &v.opts,
            sets,
            orbits,
            &|| {},
        )),
        None => {
            report::to_value(&simulate::single(&v.model, &v.initial, v.arithmetic, &v.opts, sets, orbits).0)
        }
    })
}
