//! Direct simulation of falling bodies (issue 4; the paper's section "Comparison with direct
//! simulation"): event-driven, in `f64` with renormalisation and in exact rationals, with the
//! CC / PCC / ICC classification of [`classify`].
//!
//! - [`system`]: the body as covectors and impact kicks (exact: over Q for the rod and n = 3, 4,
//!   6, over Q(cos 2π/n) for the other n-gons; `f64`: every regular n-gon up to n = 64),
//!   [`scalar`]: the two exact fields, [`frame`]: the coordinates of the `f64` engine,
//!   [`regular`]: the float model of n-gons with irrational cos 2π/n.
//! - [`drop`](mod@drop): initial states, the paper's random-drop protocol, the seeded generator.
//! - [`engine`], [`float`], [`exact`]: one interface, two arithmetics; [`snapshot`]: the
//!   read-outs of a state they share.
//! - [`convex`](mod@convex): general convex bodies (docs/model.md §11), in the paper's coordinates.
//! - [`classify`]: the driver loop and the outcome rules; [`pcc`]: the two PCC tests.
//! - [`pattern`]: the impact sequence in words; [`record`]: CSV; [`text`]: wording (the figure of
//!   a run is `crate::plot::trajectory`, feature `cli`).
//!
//! Module dependencies (acyclic): `snapshot` and `text` depend on no other module here, `scalar`
//! on `snapshot`; `system` and `frame` on each other and `scalar`; `drop` on `scalar`, `system`;
//! `regular` on `system`; `pcc` on `scalar`, `snapshot`, `system`; `engine` on `pcc`,
//! `snapshot`; `float` and `exact` on `drop`, `engine`, `snapshot`, `system` (`exact` also on
//! `pcc`, `scalar`); `convex` on `scalar`, `system` (and `system` on it for the square);
//! `classify` on
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

pub mod certified;
pub mod classify;
pub mod convex;
pub mod drop;
pub mod engine;
pub mod exact;
pub mod float;
pub mod frame;
pub mod pattern;
pub mod pcc;
pub mod record;
pub mod regular;
pub mod rest;
pub mod scalar;
pub mod snapshot;
pub mod system;
pub mod text;

pub use certified::{Certified, SetKind};
pub use classify::{Decision, Options, Outcome, Record, Run, drive, drive_with};
pub use drop::{SplitMix64, Start, StartError, exact_drop, given_start, random_drop};
pub use engine::{Engine, Step};
pub use exact::ExactEngine;
pub use float::FloatEngine;
pub use scalar::{Nf, SimField};
pub use snapshot::{Scaled, Snapshot};
pub use system::{FloatSystem, Shape, System};

use crate::exact::Q;
use chatter_kernel::model::BodyError;

/// Which arithmetic runs the simulation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Arithmetic {
    /// `f64` with renormalisation after every impact.
    Float,
    /// Exact: rationals, or Q(cos 2π/n) where the cosine is irrational.
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

/// The exact system of a [`Model`], in the smallest field that holds it.
#[derive(Clone, Copy, Debug)]
pub enum ExactSystem<'a> {
    /// Over Q: the rod and n = 3, 4, 6.
    Rational(&'a System),
    /// Over Q(cos 2π/n): the other regular n-gons.
    Field(&'a System<Nf>),
}

/// Where a simulation starts.
#[derive(Clone, Debug)]
pub enum Initial {
    /// The paper's random drop with this seed ([`random_drop`]).
    RandomDrop { seed: u64 },
    /// A given state in our coordinates (validated by [`given_start`]).
    Given(Box<Start<Q>>),
}

/// A body in both arithmetics, built once and shared by many runs. Where cos 2π/n is irrational
/// the `f64` engine runs on the float model and the exact engine in Q(cos 2π/n) (issue 10 §1),
/// whose system is built on first use ([`Model::field_system`]).
#[derive(Clone, Debug)]
pub struct Model {
    /// The exact model over Q (the rod, n = 3, 4, 6); `None` for other n-gons.
    pub exact: Option<System>,
    /// The exact model over Q(cos 2π/n) of an n-gon without `exact`, built on first use.
    field: std::sync::OnceLock<System<Nf>>,
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
                Ok(Model { exact: None, field: std::sync::OnceLock::new(), float, kappa, gamma })
            }
            r => r.map(Model::of_system),
        }
    }

    /// The model of a kernel body (`chatter_kernel::model::Shape::new(n, kappa, gamma)` decides
    /// between the rod and a polygon).
    pub fn from_body(body: &chatter_kernel::model::Shape<Q>) -> Model {
        Model::of_system(System::from_body(body))
    }

    /// The model of a general convex body (docs/model.md §11): exact over Q, states in the
    /// paper's coordinates (φx, φy, h) and (ωx, ωy, v); `kappa` is 0 (not a parameter of it).
    pub fn convex(body: &chatter_kernel::model::ConvexBody<Q>) -> Model {
        Model::of_system(System::convex(body))
    }

    /// The model of an exact system, with its `f64` copy.
    fn of_system(system: System) -> Model {
        let float = FloatSystem::new(&system);
        let (kappa, gamma) = (system.kappa.clone(), system.gamma.clone());
        Model { exact: Some(system), field: std::sync::OnceLock::new(), float, kappa, gamma }
    }

    /// The exact model in Q(cos 2π/n) of an n-gon whose cosine is irrational (`None` where the
    /// rational [`Model::exact`] exists).
    pub fn field_system(&self) -> Option<&System<Nf>> {
        match self.exact_system() {
            ExactSystem::Field(sys) => Some(sys),
            ExactSystem::Rational(_) => None,
        }
    }

    /// The exact system: over Q where it exists, else over Q(cos 2π/n) (built on first use).
    pub fn exact_system(&self) -> ExactSystem<'_> {
        if let Some(sys) = &self.exact {
            return ExactSystem::Rational(sys);
        }
        let n = self.n() as u64;
        ExactSystem::Field(self.field.get_or_init(|| {
            System::in_field(n, &self.kappa, &self.gamma).expect("validated by the float model")
        }))
    }

    /// The body's shape.
    pub fn shape(&self) -> Shape {
        self.float.shape
    }

    /// Number of contacts.
    pub fn n(&self) -> usize {
        self.float.n
    }

    /// The exact system over Q.
    ///
    /// # Panics
    /// For an n-gon with irrational cos 2π/n (`exact` is `None`; see [`Model::field_system`]).
    pub fn system(&self) -> &System {
        self.exact.as_ref().expect("a rational exact system needs a rational cos(2 pi/n): n = 2, 3, 4, 6")
    }

    /// A start from coordinates in our convention, checked exactly ([`given_start`], in
    /// Q(cos 2π/n) where the cosine is irrational).
    pub fn given_start(&self, position: &[Q], velocity: &[Q]) -> Result<Start<Q>, StartError> {
        match self.exact_system() {
            ExactSystem::Rational(sys) => given_start(sys, position, velocity),
            ExactSystem::Field(sys) => given_start(sys, position, velocity),
        }
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

/// Simulates one drop exactly: in Q, or in Q(cos 2π/n) where the cosine is irrational. Without
/// certified sets neither CC nor "no ICC, no PCC" is ever proved (such runs end `undecided`, with
/// the evidence).
pub fn simulate_exact(model: &Model, start: &Start<Q>, opts: &Options) -> Run {
    simulate_exact_with(model, start, opts, None)
}

/// [`simulate_exact`] with sets whose entry proves no ICC and no PCC (a cone) or CC (an orbit
/// certificate's set; rule 4a of [`classify`]).
pub fn simulate_exact_with(model: &Model, start: &Start<Q>, opts: &Options, sets: Option<&Certified>) -> Run {
    match model.exact_system() {
        ExactSystem::Rational(sys) => drive_with(&mut ExactEngine::new(sys, start), &model.float, opts, sets),
        ExactSystem::Field(sys) => drive_with(&mut ExactEngine::new(sys, start), &model.float, opts, sets),
    }
}

/// Simulates one drop in the chosen arithmetic.
pub fn simulate(model: &Model, initial: &Initial, arithmetic: Arithmetic, opts: &Options) -> Run {
    simulate_with(model, initial, arithmetic, opts, None)
}

/// [`simulate`] with certified sets for the exact engine (ignored in `f64`: evidence only).
pub fn simulate_with(
    model: &Model,
    initial: &Initial,
    arithmetic: Arithmetic,
    opts: &Options,
    sets: Option<&Certified>,
) -> Run {
    match arithmetic {
        Arithmetic::Float => simulate_float(&model.float, &model.float_start(initial), opts),
        Arithmetic::Exact => simulate_exact_with(model, &model.exact_start(initial), opts, sets),
    }
}

/// The outcome of one of many random drops.
#[derive(Clone, Debug, PartialEq)]
pub struct Brief {
    pub seed: u64,
    /// The verdict ([`Run::outcome`]: proved in exact runs, evidence in `f64`).
    pub outcome: Outcome,
    /// Whether `outcome` is proved.
    pub proved: bool,
    /// What the rules say as evidence ([`Run::evidence`]).
    pub evidence: Outcome,
    pub decided_by: &'static str,
    pub impacts: usize,
    /// The steps of the periodic tail of the impact sequence, if it has one ([`pattern::find`]).
    pub cycle: Option<Vec<usize>>,
    /// A rod drop's measured T|v|/h (evidence, [`rest::measure`]), set by [`simulate_many`].
    pub time_to_rest: Option<f64>,
    /// The proved upper bound of the time, from the start, at which the impacts accumulate
    /// (`rest_by` of a [`Decision::Certified`] that proved CC).
    pub rest_by: Option<Q>,
    /// The impact after which the drop entered a certified cone, when the run went on past it
    /// ([`Options::after_cone`], [`Run::cone_entry`]).
    pub cone_after: Option<usize>,
    /// Wall time of the run(s) that made this brief, seconds (set by [`simulate_many_with`] and
    /// by reruns that prove a drop; machine-dependent: printed, never written to a file).
    pub seconds: f64,
}

impl Brief {
    /// The brief of a run with this seed.
    pub fn of(seed: u64, run: &Run, n: usize) -> Brief {
        let cycle = pattern::find(&run.sequence).map(|p| pattern::steps(&p.cycle, n));
        Brief {
            seed,
            outcome: run.outcome,
            proved: run.proved,
            evidence: run.evidence,
            decided_by: run.decision.key(),
            impacts: run.impacts,
            cycle,
            time_to_rest: None,
            rest_by: match &run.decision {
                Decision::Certified { rest_by, .. } => rest_by.clone(),
                _ => None,
            },
            cone_after: match &run.cone_entry {
                Some(Decision::Certified { after, .. }) => Some(*after),
                _ => None,
            },
            seconds: 0.0,
        }
    }
}

/// Outcome counts of many runs, in the order of [`Outcome::ALL`] (a cone entry counts as
/// [`Outcome::NoIccNoPcc`], never as CC).
pub fn counts(briefs: &[Brief]) -> [usize; Outcome::COUNT] {
    count_by(briefs, |b| b.outcome)
}

/// Counts of the evidence ([`Brief::evidence`]) of many runs, in the order of [`Outcome::ALL`]
/// (the count of [`Outcome::NoIccNoPcc`], never evidence, is 0).
pub fn evidence_counts(briefs: &[Brief]) -> [usize; Outcome::COUNT] {
    count_by(briefs, |b| b.evidence)
}

/// Counts of the proved outcomes of many runs, in the order of [`Outcome::ALL`]: a run without a
/// proof counts as `undecided`.
pub fn proved_counts(briefs: &[Brief]) -> [usize; Outcome::COUNT] {
    count_by(briefs, |b| if b.proved { b.outcome } else { Outcome::Undecided })
}

fn count_by(briefs: &[Brief], of: impl Fn(&Brief) -> Outcome) -> [usize; Outcome::COUNT] {
    let mut c = [0; Outcome::COUNT];
    for b in briefs {
        c[Outcome::ALL.iter().position(|o| *o == of(b)).expect("known outcome")] += 1;
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
    simulate_many_with(model, seed, runs, arithmetic, opts, None, tick)
}

/// [`simulate_many`] with certified sets for the exact engine.
pub fn simulate_many_with(
    model: &Model,
    seed: u64,
    runs: u64,
    arithmetic: Arithmetic,
    opts: &Options,
    sets: Option<&Certified>,
    tick: &(dyn Fn() + Sync),
) -> Vec<Brief> {
    use rayon::prelude::*;
    let opts = Options { record: false, ..*opts };
    (0..runs)
        .into_par_iter()
        .map(|i| {
            let s = seed.wrapping_add(i);
            let initial = Initial::RandomDrop { seed: s };
            let start = std::time::Instant::now();
            let run = simulate_with(model, &initial, arithmetic, &opts, sets);
            let seconds = start.elapsed().as_secs_f64();
            tick();
            let mut brief = Brief { seconds, ..Brief::of(s, &run, model.n()) };
            brief.time_to_rest = rest::measure(model, &initial, &run).map(|m| m.ratio);
            brief
        })
        .collect()
}
