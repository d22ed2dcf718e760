//! Drops decided with proofs (issue 22 §1): exact runs against certified sets
//! ([`crate::simulate::certified`]), made on the fly here ([`made`]: a cone certificate by the
//! certify pipeline, cached per body and parameters) or given, with orbit certificates made for
//! the periodic patterns that the drops left open settle into ([`add_orbit_for`]), after which
//! those drops are run again. Open: undecided with CC as evidence, or proved only no-ICC-no-PCC
//! by a cone (issue 24: a cone gives no finite accumulation time, an orbit set does); such a
//! rerun goes on past the cone entry ([`Options::after_cone`]), keeping the cone's proof should
//! it enter no orbit set within the budget.

mod make;

pub use make::{
    Effort, ORBIT_DEPTH, add_orbit_for, add_rest_for, cone, made, made_general, remember, survey_rest_config,
};

use crate::simulate::certified::{Certified, pattern_text, primitive_cycle};
use crate::simulate::{
    Arithmetic, Brief, Initial, Model, Options, Outcome, Run, Shape, simulate, simulate_many_with,
    simulate_with,
};
use std::collections::BTreeSet;

/// The drops and the sets they were decided with.
pub struct Proved {
    /// One brief per drop, in seed order.
    pub briefs: Vec<Brief>,
    /// The sets (those given, or made on the fly, with any orbit certificate added).
    pub sets: Certified,
}

/// Whether the orbit producer can certify this body (a regular n-gon, 3 <= n <= 64).
fn orbits_possible(model: &Model) -> bool {
    matches!(model.shape(), Shape::Polygon(n) if (3..=crate::exact::MAX_N).contains(&n))
}

/// Whether an orbit certificate could still prove the drop CC: undecided with CC as evidence,
/// or proved only no-ICC-no-PCC by a cone (finite accumulation time not derived; issue 24).
fn open(b: &Brief) -> bool {
    b.evidence == Outcome::Cc && (!b.proved || b.outcome == Outcome::NoIccNoPcc)
}

/// The primitive cycle of steps of an open drop: from its exact run, unless that run stopped at
/// a cone entry (too early to show one), then from an `f64` run of the same drop with the same
/// budget (the cycle only suggests a pattern to the orbit producer; the kernel proves).
fn cycle_of(model: &Model, initial: &Initial, b: &Brief, budget: usize) -> Option<Vec<usize>> {
    let stopped_at_cone = b.outcome == Outcome::NoIccNoPcc && b.cone_after.is_none();
    let cycle = if stopped_at_cone {
        let run = simulate(model, initial, Arithmetic::Float, &Options::new(budget));
        Brief::of(b.seed, &run, model.n()).cycle
    } else {
        b.cycle.clone()
    };
    cycle.as_deref().map(primitive_cycle)
}

/// The cycles of the open drops ([`open`], [`cycle_of`]) among random drops.
fn open_cycles(model: &Model, briefs: &[Brief], budget: usize) -> BTreeSet<Vec<usize>> {
    use rayon::prelude::*;
    briefs
        .par_iter()
        .filter(|b| open(b))
        .filter_map(|b| cycle_of(model, &Initial::RandomDrop { seed: b.seed }, b, budget))
        .collect::<Vec<_>>()
        .into_iter()
        .collect()
}

/// Adds an orbit certificate for each open cycle; whether any was added.
fn add_orbits(model: &Model, sets: &mut Certified, cycles: &BTreeSet<Vec<usize>>, effort: Effort) -> bool {
    let mut added = false;
    for cycle in cycles {
        match add_orbit_for(&mut *sets, model, cycle, effort) {
            Ok(new) => added |= new,
            Err(e) => {
                sets.notes.push(format!("no orbit certificate for the pattern {}: {e}", pattern_text(cycle)))
            }
        }
    }
    added
}

/// The options of a run against `sets`: go on past a cone entry when an orbit set may follow.
fn against(opts: &Options, sets: &Certified) -> Options {
    Options { after_cone: sets.has_orbits(), ..*opts }
}

/// Runs `runs` random drops (seeds `seed..`) exactly with the sets `sets`; with `orbits`, tries
/// orbit certificates (with that effort) for the cycles of the drops still open (`open`:
/// undecided with CC as evidence, or proved no-ICC-no-PCC by a cone) and reruns those drops,
/// going on past a cone entry so that they can enter an orbit set. `tick` is called after each
/// first run.
pub fn prove_many(
    model: &Model,
    seed: u64,
    runs: u64,
    opts: &Options,
    mut sets: Certified,
    orbits: Option<Effort>,
    tick: &(dyn Fn() + Sync),
) -> Proved {
    use rayon::prelude::*;
    let first = against(opts, &sets);
    let mut briefs = simulate_many_with(model, seed, runs, Arithmetic::Exact, &first, Some(&sets), tick);
    let Some(effort) = orbits.filter(|_| orbits_possible(model)) else { return Proved { briefs, sets } };
    let cycles = open_cycles(model, &briefs, opts.budget);
    if cycles.is_empty() || !add_orbits(model, &mut sets, &cycles, effort) {
        return Proved { briefs, sets };
    }
    let opts = Options { record: false, ..against(opts, &sets) };
    let again: Vec<(usize, Brief)> = briefs
        .par_iter()
        .enumerate()
        .filter(|(_, b)| open(b))
        .map(|(i, b)| {
            let initial = Initial::RandomDrop { seed: b.seed };
            let start = std::time::Instant::now();
            let run = simulate_with(model, &initial, Arithmetic::Exact, &opts, Some(&sets));
            let seconds = b.seconds + start.elapsed().as_secs_f64();
            (i, Brief { seconds, ..Brief::of(b.seed, &run, model.n()) })
        })
        .collect();
    for (i, b) in again {
        briefs[i] = b;
    }
    Proved { briefs, sets }
}

/// One exact run with the sets `sets`; with `orbits`, when it is still open (`open`: undecided
/// with CC as evidence, or proved no-ICC-no-PCC by a cone), tries an orbit certificate for its
/// cycle (`cycle_of`) and runs again, going on past a cone entry.
pub fn prove_one(
    model: &Model,
    initial: &Initial,
    opts: &Options,
    mut sets: Certified,
    orbits: Option<Effort>,
) -> (Run, Certified) {
    let run = simulate_with(model, initial, Arithmetic::Exact, &against(opts, &sets), Some(&sets));
    let brief = Brief::of(0, &run, model.n());
    let Some(effort) = orbits.filter(|_| orbits_possible(model) && open(&brief)) else { return (run, sets) };
    let cycles: BTreeSet<Vec<usize>> = cycle_of(model, initial, &brief, opts.budget).into_iter().collect();
    if add_orbits(model, &mut sets, &cycles, effort) {
        let again = simulate_with(model, initial, Arithmetic::Exact, &against(opts, &sets), Some(&sets));
        return (again, sets);
    }
    (run, sets)
}
