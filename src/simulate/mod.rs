//! Direct simulation of falling bodies (issue 4; the paper's section "Comparison with direct
//! simulation"): event-driven, in `f64` with renormalisation and in exact rationals, with the
//! CC / PCC / ICC classification of [`classify`].
//!
//! - [`system`]: the body as covectors and impact kicks (polygons n = 3, 4, 6 and the rod).
//! - [`drop`](mod@drop): initial states, the paper's random-drop protocol, the seeded generator.
//! - [`engine`], [`float`], [`exact`]: one interface, two arithmetics; [`snapshot`]: the
//!   read-outs of a state they share.
//! - [`classify`]: the driver loop and the outcome rules; [`pcc`]: the two PCC tests.
//! - [`pattern`]: the impact sequence in words; [`record`]: CSV; [`text`]: wording (the figure of
//!   a run is `crate::plot::trajectory`, feature `cli`).
//!
//! Module dependencies (acyclic): `system`, `snapshot` and `text` depend on no other module here;
//! `drop` on `system`; `pcc` on `snapshot`, `system`; `engine` on `pcc`, `snapshot`; `float` and
//! `exact` on `drop`, `engine`, `snapshot`, `system` (`exact` also on `pcc`); `classify` on
//! `engine`, `pcc`, `snapshot`, `system`, `text`; `pattern` on `system`, `text`; `record` on
//! `classify`, `snapshot`, `system`.
//!
//! ```
//! use chatter::exact::Q;
//! use chatter::simulate::{Arithmetic, Initial, Model, Options, Outcome, Shape, simulate};
//! let model = Model::new(Shape::Polygon(4), Q::new(1, 6), Q::new(1, 100)).unwrap();
//! let run = simulate(&model, &Initial::RandomDrop { seed: 1 }, Arithmetic::Float, &Options::new(200));
//! assert_eq!(run.outcome, Outcome::Cc);
//! ```

pub mod classify;
pub mod drop;
pub mod engine;
pub mod exact;
pub mod float;
pub mod pattern;
pub mod pcc;
pub mod record;
pub mod snapshot;
pub mod system;
pub mod text;

pub use classify::{Decision, Options, Outcome, Record, Run, drive};
pub use drop::{SplitMix64, Start, StartError, exact_drop, given_start, random_drop};
pub use engine::{Engine, Step};
pub use exact::ExactEngine;
pub use float::FloatEngine;
pub use snapshot::{Scaled, Snapshot};
pub use system::{FloatSystem, Shape, System};

use crate::exact::Q;
use chatter_kernel::model::BodyError;

/// Which arithmetic runs the simulation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Arithmetic {
    /// `f64` with renormalisation after every impact.
    Float,
    /// Exact rationals.
    Exact,
}

impl Arithmetic {
    pub fn name(self) -> &'static str {
        match self {
            Arithmetic::Float => "f64",
            Arithmetic::Exact => "exact",
        }
    }
}

/// Where a simulation starts.
#[derive(Clone, Debug)]
pub enum Initial {
    /// The paper's random drop with this seed ([`random_drop`]).
    RandomDrop { seed: u64 },
    /// A given state in our coordinates (validated by [`given_start`]).
    Given(Box<Start<Q>>),
}

/// A body in both arithmetics, built once and shared by many runs.
#[derive(Clone, Debug)]
pub struct Model {
    pub system: System,
    pub float: FloatSystem,
}

impl Model {
    /// The model of `shape` with the given kappa and gamma (validated by the kernel).
    pub fn new(shape: Shape, kappa: Q, gamma: Q) -> Result<Model, BodyError> {
        Ok(Model::of_system(System::new(shape, kappa, gamma)?))
    }

    /// The model of a kernel body (`chatter_kernel::model::Shape::new(n, kappa, gamma)` decides
    /// between the rod and a polygon).
    pub fn from_body(body: &chatter_kernel::model::Shape<Q>) -> Model {
        Model::of_system(System::from_body(body))
    }

    /// The model of an exact system, with its `f64` copy.
    fn of_system(system: System) -> Model {
        let float = FloatSystem::new(&system);
        Model { system, float }
    }

    /// The exact start of `initial`.
    pub fn exact_start(&self, initial: &Initial) -> Start<Q> {
        match initial {
            Initial::RandomDrop { seed } => exact_drop(&self.float, *seed),
            Initial::Given(s) => (**s).clone(),
        }
    }

    /// The `f64` start of `initial` (the nearest floats of a given state).
    pub fn float_start(&self, initial: &Initial) -> Start<f64> {
        match initial {
            Initial::RandomDrop { seed } => random_drop(&self.float, *seed),
            Initial::Given(s) => s.to_f64(),
        }
    }
}

/// Simulates one drop in `f64`.
pub fn simulate_float(fs: &FloatSystem, start: &Start<f64>, opts: &Options) -> Run {
    drive(&mut FloatEngine::new(fs, start), fs, opts)
}

/// Simulates one drop exactly.
pub fn simulate_exact(model: &Model, start: &Start<Q>, opts: &Options) -> Run {
    drive(&mut ExactEngine::new(&model.system, start), &model.float, opts)
}

/// Simulates one drop in the chosen arithmetic.
pub fn simulate(model: &Model, initial: &Initial, arithmetic: Arithmetic, opts: &Options) -> Run {
    match arithmetic {
        Arithmetic::Float => simulate_float(&model.float, &model.float_start(initial), opts),
        Arithmetic::Exact => simulate_exact(model, &model.exact_start(initial), opts),
    }
}

/// The outcome of one of many random drops.
#[derive(Clone, Debug, PartialEq)]
pub struct Brief {
    pub seed: u64,
    pub outcome: Outcome,
    pub decided_by: &'static str,
    pub impacts: usize,
}

/// Outcome counts of many runs, in the order of [`Outcome::ALL`].
pub fn counts(briefs: &[Brief]) -> [usize; 5] {
    let mut c = [0; 5];
    for b in briefs {
        c[Outcome::ALL.iter().position(|o| *o == b.outcome).expect("known outcome")] += 1;
    }
    c
}

/// Runs `runs` random drops with seeds seed, seed + 1, ... in parallel (rayon). Results are in
/// seed order and do not depend on the number of threads; `tick` is called after each run.
pub fn simulate_many(
    model: &Model,
    seed: u64,
    runs: u64,
    arithmetic: Arithmetic,
    opts: &Options,
    tick: &(dyn Fn() + Sync),
) -> Vec<Brief> {
    use rayon::prelude::*;
    let opts = Options { record: false, ..*opts };
    (0..runs)
        .into_par_iter()
        .map(|i| {
            let s = seed.wrapping_add(i);
            let run = simulate(model, &Initial::RandomDrop { seed: s }, arithmetic, &opts);
            tick();
            Brief { seed: s, outcome: run.outcome, decided_by: run.decision.key(), impacts: run.impacts }
        })
        .collect()
}
