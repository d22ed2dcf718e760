//! `chatter prove square`: the square-case lemmas, proved symbolically and written to proofs/.

use super::{Outcome, emit};
use crate::symbolic::crosscheck::cross_check;
use crate::symbolic::report::{markdown, ron, summary};
use crate::symbolic::square::prove;
use clap::{Args, ValueEnum};
use serde_json::json;
use std::path::PathBuf;

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Theorem {
    /// The paper's section "A semi-analytic construction for squares".
    Square,
}

/// Raw arguments of `chatter prove`.
#[derive(Args, Debug)]
#[command(
    after_help = "Writes OUT/square.md (readable) and OUT/square.ron (every step, machine-readable); exits\n\
non-zero if a step fails or the cross-check disagrees. With --check nothing is written: the files\n\
are compared with the ones on disk."
)]
pub struct ProveArgs {
    /// What to prove.
    #[arg(value_enum)]
    pub theorem: Theorem,
    /// Directory for the proof files.
    #[arg(long, default_value = "proofs")]
    pub out: PathBuf,
    /// Compare with the existing files instead of writing them.
    #[arg(long)]
    pub check: bool,
    /// Random parameter points of the cross-check.
    #[arg(long, default_value_t = 100)]
    pub points: usize,
    /// Seed of the cross-check's points.
    #[arg(long, default_value_t = 2026)]
    pub seed: u64,
    /// Print a JSON summary.
    #[arg(long)]
    pub json: bool,
}

pub fn run(a: ProveArgs) -> Outcome {
    if a.points == 0 || a.points > 10_000 {
        return Outcome::Usage("--points must be in 1..=10000".to_string());
    }
    let Theorem::Square = a.theorem;
    let proof = prove();
    let cross = cross_check(a.points, a.seed);
    let (md, rn) = (markdown(&proof, &cross), ron(&proof, &cross));
    let (md_path, ron_path) = (a.out.join("square.md"), a.out.join("square.ron"));
    let mut stale = Vec::new();
    if a.check {
        for (path, text) in [(&md_path, &md), (&ron_path, &rn)] {
            if std::fs::read_to_string(path).ok().as_ref() != Some(text) {
                stale.push(path.display().to_string());
            }
        }
    } else {
        if let Err(e) = std::fs::create_dir_all(&a.out) {
            return Outcome::Usage(format!("cannot create {}: {e}", a.out.display()));
        }
        for (path, text) in [(&md_path, &md), (&ron_path, &rn)] {
            if let Err(e) = std::fs::write(path, text) {
                return Outcome::Usage(format!("cannot write {}: {e}", path.display()));
            }
        }
    }
    let s = summary(&proof);
    let cross_ok = cross.disagreements.is_empty();
    if a.json {
        emit(&json!({"steps": s.steps, "checked": s.checked, "failed": s.failed, "cross_check": cross, "stale": stale}).to_string());
    } else {
        for st in proof.steps.iter().filter(|st| !st.ok) {
            emit(&format!("FAILED {} ({}): {} [{}]", st.id, st.lemma, st.statement, st.detail));
        }
        let written = if a.check { "checked against" } else { "written to" };
        emit(&format!(
            "square: {} steps, {} checked, {} failed; cross-check at {} points: inequalities {}, invariance {}, pipeline {}; {written} {} and {}",
            s.steps,
            s.checked,
            s.failed,
            cross.points,
            cross.inequalities,
            cross.invariance,
            cross.pipeline,
            md_path.display(),
            ron_path.display()
        ));
        for f in &stale {
            emit(&format!("stale: {f} differs from the regenerated proof"));
        }
    }
    Outcome::from_answer(s.failed == 0 && cross_ok && stale.is_empty())
}
