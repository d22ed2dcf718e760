//! Drops decided with proofs (issue 22 §1): exact runs against certified sets
//! ([`crate::simulate::certified`]), made on the fly here ([`made`]: a cone certificate by the
//! certify pipeline, cached per body and parameters) or given, with orbit certificates made for
//! the periodic patterns that the drops left undecided settle into ([`add_orbit_for`]), after
//! which those drops are run again.

mod make;

pub use make::{Effort, ORBIT_DEPTH, add_orbit_for, cone, made, remember};

use crate::simulate::certified::{Certified, canonical_cycle, pattern_text};
use crate::simulate::{
    Arithmetic, Brief, Initial, Model, Options, Outcome, Run, Shape, simulate_many_with, simulate_with,
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

/// The canonical cycles of the drops that are undecided although the evidence says CC.
fn open_cycles(briefs: &[Brief]) -> BTreeSet<Vec<usize>> {
    briefs
        .iter()
        .filter(|b| !b.proved && b.evidence == Outcome::Cc)
        .filter_map(|b| b.cycle.as_deref().map(canonical_cycle))
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

/// Runs `runs` random drops (seeds `seed..`) exactly with the sets `sets`; with `orbits`,
/// tries orbit certificates (with that effort) for the cycles of undecided drops whose evidence is CC and reruns
/// those drops. `tick` is called after each first run.
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
    let mut briefs = simulate_many_with(model, seed, runs, Arithmetic::Exact, opts, Some(&sets), tick);
    let cycles = open_cycles(&briefs);
    let try_orbits = |sets: &mut Certified| match orbits {
        Some(effort) if orbits_possible(model) && !cycles.is_empty() => {
            add_orbits(model, sets, &cycles, effort)
        }
        _ => false,
    };
    if try_orbits(&mut sets) {
        let opts = Options { record: false, ..*opts };
        let again: Vec<(usize, Brief)> = briefs
            .par_iter()
            .enumerate()
            .filter(|(_, b)| !b.proved)
            .map(|(i, b)| {
                let run = simulate_with(
                    model,
                    &Initial::RandomDrop { seed: b.seed },
                    Arithmetic::Exact,
                    &opts,
                    Some(&sets),
                );
                (i, Brief::of(b.seed, &run, model.n()))
            })
            .collect();
        for (i, b) in again {
            briefs[i] = b;
        }
    }
    Proved { briefs, sets }
}

/// One exact run with the sets `sets`; with `orbits`, when it ends undecided with CC as
/// evidence on a periodic pattern, tries an orbit certificate for that pattern and runs again.
pub fn prove_one(
    model: &Model,
    initial: &Initial,
    opts: &Options,
    mut sets: Certified,
    orbits: Option<Effort>,
) -> (Run, Certified) {
    let run = simulate_with(model, initial, Arithmetic::Exact, opts, Some(&sets));
    let brief = Brief::of(0, &run, model.n());
    let cycles = open_cycles(std::slice::from_ref(&brief));
    let effort = orbits.filter(|_| orbits_possible(model) && !cycles.is_empty());
    if effort.is_some_and(|e| add_orbits(model, &mut sets, &cycles, e)) {
        let again = simulate_with(model, initial, Arithmetic::Exact, opts, Some(&sets));
        return (again, sets);
    }
    (run, sets)
}
