//! Direct simulation of falling bodies (issue 4; the paper's section "Comparison with direct
//! simulation"): event-driven, in `f64` with renormalisation and in exact rationals, with the
//! CC / PCC / ICC classification of [`classify`].
//!
//! - [`system`]: the body as covectors and impact kicks (exact: polygons n = 3, 4, 6 and the
//!   rod; `f64`: every regular n-gon up to n = 64), [`frame`]: the coordinates of the `f64` engine,
//!   [`regular`]: n-gons with irrational cos 2π/n (the float model, exact start checks).
//! - [`drop`](mod@drop): initial states, the paper's random-drop protocol, the seeded generator.
//! - [`engine`], [`float`], [`exact`]: one interface, two arithmetics; [`snapshot`]: the
//!   read-outs of a state they share.
//! - [`classify`]: the driver loop and the outcome rules; [`pcc`]: the two PCC tests.
//! - [`pattern`]: the impact sequence in words; [`record`]: CSV; [`text`]: wording (the figure of
//!   a run is `crate::plot::trajectory`, feature `cli`).
//!
//! Module dependencies (acyclic): `snapshot` and `text` depend on no other module here; `system`
//! and `frame` on each other; `drop` on `system`; `regular` on `drop`, `system`; `pcc` on `snapshot`, `system`; `engine` on `pcc`, `snapshot`; `float` and
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
pub mod frame;
pub mod pattern;
pub mod pcc;
pub mod record;
pub mod regular;
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

/// A body in both arithmetics, built once and shared by many runs; `f64` only where
/// cos 2π/n is irrational (issue 10 §1: exact simulation there needs number fields, §2).
#[derive(Clone, Debug)]
pub struct Model {
    /// The exact model (the rod, n = 3, 4, 6); `None` for the float model of other n-gons.
    pub exact: Option<System>,
    pub float: FloatSystem,
    /// κ and γ as given (exact).
    pub kappa: Q,
    pub gamma: Q,
}

impl Model {
    /// The model of `shape` with the given kappa and gamma (validated as by the kernel): exact
    /// for the rod and n = 3, 4, 6, the float model of [`regular`] for other n up to 64.
    pub fn new(shape: Shape, kappa: Q, gamma: Q) -> Result<Model, BodyError> {
        match System::new(shape, kappa.clone(), gamma.clone()) {
            Err(BodyError::UnsupportedN(n)) if n >= 3 => {
                let float = regular::float_system(n, &kappa, &gamma)?;
                Ok(Model { exact: None, float, kappa, gamma })
            }
            r => r.map(Model::of_system),
        }
    }

    /// The model of a kernel body (`chatter_kernel::model::Shape::new(n, kappa, gamma)` decides
    /// between the rod and a polygon).
    pub fn from_body(body: &chatter_kernel::model::Shape<Q>) -> Model {
        Model::of_system(System::from_body(body))
    }

    /// The model of an exact system, with its `f64` copy.
    fn of_system(system: System) -> Model {
        let float = FloatSystem::new(&system);
        let (kappa, gamma) = (system.kappa.clone(), system.gamma.clone());
        Model { exact: Some(system), float, kappa, gamma }
    }

    /// The body's shape.
    pub fn shape(&self) -> Shape {
        self.float.shape
    }

    /// Number of contacts.
    pub fn n(&self) -> usize {
        self.float.n
    }

    /// The exact system.
    ///
    /// # Panics
    /// For the float model of an n-gon with irrational cos 2π/n (`exact` is `None`).
    pub fn system(&self) -> &System {
        self.exact.as_ref().expect("exact simulation needs a rational cos(2 pi/n): n = 2, 3, 4, 6")
    }

    /// A start from coordinates in our convention, checked exactly ([`given_start`]; in
    /// Q(cos 2π/n) for the float model, [`regular::check_start`]).
    pub fn given_start(&self, position: &[Q], velocity: &[Q]) -> Result<Start<Q>, StartError> {
        if let Some(sys) = &self.exact {
            return given_start(sys, position, velocity);
        }
        let n = self.n() as u64;
        for v in [position, velocity] {
            if v.len() != 3 {
                return Err(StartError::WrongLength { expected: 3, found: v.len() });
            }
        }
        let three = |v: &[Q]| -> [Q; 3] { std::array::from_fn(|i| v[i].clone()) };
        let start = Start { q: three(position), p: three(velocity) };
        regular::check_start(n, &self.kappa, &self.gamma, &start)?;
        Ok(start)
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
///
/// # Panics
/// For a model without an exact system ([`Model::system`]).
pub fn simulate_exact(model: &Model, start: &Start<Q>, opts: &Options) -> Run {
    drive(&mut ExactEngine::new(model.system(), start), &model.float, opts)
}

/// Simulates one drop in the chosen arithmetic.
///
/// # Panics
/// [`Arithmetic::Exact`] on a model without an exact system ([`Model::system`]).
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
