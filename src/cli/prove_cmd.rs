//! `chatter prove square`: the square-case lemmas written as a proof object, re-checked by the
//! kernel before the files are written to proofs/.

use super::{Outcome, emit, emit_report};
use crate::report::prove::ProveReport;
use crate::report::{self, Report};
use crate::symbolic::crosscheck::cross_check;
use crate::symbolic::report::{markdown, ron};
use crate::symbolic::square::prove;
use chatter_kernel::exact::ParseLimits;
use chatter_kernel::verify::{Verdict, verify_proof};
use clap::{Args, ValueEnum};
use std::path::PathBuf;

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Theorem {
    /// The paper's section "A semi-analytic construction for squares".
    Square,
}

/// Raw arguments of `chatter prove`.
#[derive(Args, Debug)]
#[command(
    after_help = "Writes OUT/square.ron (the proof object; `chatter check-proof` re-checks it) and OUT/square.md\n\
(a readable account). The kernel checks the proof on both backends before anything is written; exit 1\n\
if a step fails. With --check nothing is written: the files are compared with the ones on disk."
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
    /// Random parameter points of the numerical cross-check (evidence, not proof).
    #[arg(long, default_value_t = 100)]
    pub points: usize,
    /// Seed of the cross-check's points.
    #[arg(long, default_value_t = 2026)]
    pub seed: u64,
    /// Print a JSON summary.
    #[arg(long)]
    pub json: bool,
}

/// Writes the files, or lists those that differ from the regenerated ones (`check`).
fn write_or_compare(a: &ProveArgs, files: [(PathBuf, &str); 2]) -> Result<Vec<String>, String> {
    let mut stale = Vec::new();
    if !a.check {
        std::fs::create_dir_all(&a.out).map_err(|e| format!("cannot create {}: {e}", a.out.display()))?;
    }
    for (path, text) in files {
        if a.check {
            if std::fs::read_to_string(&path).ok().as_deref() != Some(text) {
                stale.push(path.display().to_string());
            }
        } else {
            std::fs::write(&path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        }
    }
    Ok(stale)
}

pub fn run(a: ProveArgs) -> Outcome {
    if a.points == 0 || a.points > 10_000 {
        return Outcome::Usage("--points must be in 1..=10000".into());
    }
    let Theorem::Square = a.theorem;
    let builder = prove();
    let file = builder.finish();
    let verdict = verify_proof(&file, ParseLimits::default());
    let checked = match &verdict {
        Verdict::Accepted(c) => Ok(c.clone()),
        Verdict::Rejected(r) => Err(r.message().clone()),
        Verdict::Disagree(s) => return Outcome::Internal(format!("the backends disagree on the proof: {s}")),
    };
    let cross = cross_check(a.points, a.seed);
    let (md, rn) = (markdown(&builder, &checked, &cross), ron(&file));
    let (md_path, ron_path) = (a.out.join("square.md"), a.out.join("square.ron"));
    let stale = match write_or_compare(&a, [(ron_path.clone(), &rn), (md_path.clone(), &md)]) {
        Ok(s) => s,
        Err(e) => return Outcome::Usage(e),
    };
    let conclusions = checked.as_ref().map(|c| c.conclusions.len()).unwrap_or(0);
    if a.json {
        emit_report(&ProveReport {
            schema: ProveReport::SCHEMA,
            verdict: if checked.is_ok() { report::Verdict::Accepted } else { report::Verdict::Rejected },
            steps: file.steps.len(),
            failure: checked.as_ref().err().cloned(),
            producer_problems: builder.problems.clone(),
            conclusions,
            cross_check: cross.clone(),
            stale: stale.clone(),
        });
    } else {
        for (id, why) in &builder.problems {
            emit(&format!("producer problem at `{id}`: {why}"));
        }
        if let Err(e) = &checked {
            emit(&format!("FAILED: {e}"));
        }
        let verb = if a.check { "checked against" } else { "written to" };
        emit(&format!(
            "square: {} steps, kernel check {} (malachite + num-rational), {conclusions} conclusions; cross-check at {} points: inequalities {}, invariance {}, pipeline {}; {verb} {} and {}",
            file.steps.len(),
            if checked.is_ok() { "OK" } else { "FAILED" },
            cross.points,
            cross.inequalities,
            cross.invariance,
            cross.pipeline,
            ron_path.display(),
            md_path.display()
        ));
        for f in &stale {
            emit(&format!("stale: {f} differs from the regenerated proof"));
        }
    }
    Outcome::from_answer(
        checked.is_ok() && builder.problems.is_empty() && cross.disagreements.is_empty() && stale.is_empty(),
    )
}
