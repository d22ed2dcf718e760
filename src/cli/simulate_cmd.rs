//! `chatter simulate` (issue 4).

use super::{self as cli, emit, emit_report};
use crate::exact::{Q, parse_user_number};
use crate::plot::save;
use crate::plot::trajectory::TrajectoryFigure;
use crate::report::simulate as report;
use crate::simulate::classify::DEFAULT_PCC_EPSILON;
use crate::simulate::pattern;
use crate::simulate::{
    Arithmetic, Certified, Decision, Initial, Model, Options, Outcome, Run, Shape, record,
};
use clap::Args;
use std::io::IsTerminal;
use std::path::PathBuf;

/// Largest impact budget accepted.
pub const MAX_IMPACTS: usize = 10_000_000;
/// Largest number of contacts simulated (the float model's limit).
pub const MAX_N: u64 = crate::model::float::MAX_FLOAT_CONTACTS;
/// Largest number of runs accepted.
pub const MAX_RUNS: u64 = 1_000_000;

/// Raw arguments of `chatter simulate`.
#[derive(Args, Debug)]
#[command(after_help = "Outcomes: CC (complete chatter: impacts accumulate, the body comes to rest), \
PCC (two adjacent contacts chatter to rest, then all contacts land at once), ICC (the body leaves: \
v > 0 or no contact approaches), simultaneous (two contacts land at the same instant: undecidable \
in this model, never resolved), undecided (the budget cannot tell). With --exact an outcome is \
proved or undecided; no-ICC-no-PCC (\"no ICC, no PCC\") is proved when the state enters the cone \
of a kernel-checked cone certificate: the body never separates and never ends in PCC, so it is CC \
unless the impacts take infinite time, which is not excluded (docs/time-to-rest.md); CC is proved \
only with a finite accumulation time (an orbit certificate's set, or the exact pair proof). When \
orbit certificates may follow (made on the fly, or given), a run that entered a cone goes on within \
the budget and is CC if it then enters an orbit certificate's set. The line `decided by` names the test.\n\n\
Without --position/--velocity the body is dropped as in the paper: velocity (R1, R2, -1) and \
position (R3, R4, 1 + R5) in the paper's coordinates (omega_x, omega_y, v), (phi_x, phi_y, h), \
R_i uniform on (0, 0.1) from --seed (SplitMix64: the same on every machine); the rod uses \
(omega, v) = (R1, -1) and (phi, h) = (R3, 1 + R5). --position and \
--velocity take our coordinates instead: (h0, h1, hc) and (u0, u1, v), heights and normal \
velocities of contacts 0 and 1 and of the centre of mass; for the rod (--n 2) two numbers \
(h0, h1) and (u0, u1). General bodies (--rectangle, --box, --polygon, --body; docs/model.md §11) are dropped the same way, and --position/--velocity take the paper's coordinates for them: (phi_x, phi_y, h) and (omega_x, omega_y, v).\n\n\
Numbers are read exactly: 1/6, 0.01 (= 1/100), 1e-2. Exit status 0 when the simulation ran, \
2 on bad input.\n\n\
Examples:\n  chatter simulate --n 3 --kappa 3/20 --gamma 1/20 --seed 7\n  \
chatter simulate --n 4 --runs 1000 --json\n  \
chatter simulate --n 3 --kappa 1/8 --gamma 1/200 --exact --plot pcc.png\n  \
chatter simulate --n 5 --kappa 1/20 --gamma 1/10 --exact\n  \
chatter simulate --n 4 --position 1/2,1/2,1 --velocity -1,-1,-1 --exact\n  \
chatter simulate --rectangle 2,1 --gamma 1/20 --exact\n  \
chatter simulate --box 150,75,8 --runs 100\n  \
chatter simulate --polygon \"0,0 4,0 0,3\" --plate --seed 3")]
pub struct SimulateArgs {
    #[command(flatten)]
    pub body: super::BodyArgs,
    #[command(flatten)]
    pub general: super::convex_args::ConvexArgs,
    /// Seed of the random drop (default 0); with --runs, run i uses seed + i.
    #[arg(long, allow_hyphen_values = true)]
    pub seed: Option<String>,
    /// Impact budget.
    #[arg(long, default_value = "200", allow_hyphen_values = true)]
    pub impacts: String,
    /// Exact arithmetic instead of f64 (slower; decides ties and symmetric cases exactly): rationals
    /// for n = 2, 3, 4, 6, the number field Q(cos 2pi/n) for every other n.
    #[arg(long)]
    pub exact: bool,
    /// Write one CSV row per impact to this file.
    #[arg(long, value_name = "CSV")]
    pub trajectory: Option<PathBuf>,
    /// Write a figure (SVG or PNG, by the extension): (a) the rescaled contact heights h_k/h_c
    /// over the last 24 impacts, (b) log10 of the centre's height and of the time between impacts
    /// against the impact number.
    #[arg(long, value_name = "FILE")]
    pub plot: Option<PathBuf>,
    /// Repeat with this many random drops (parallel) and print the outcome counts.
    #[arg(long, value_name = "M", allow_hyphen_values = true)]
    pub runs: Option<String>,
    /// Print one JSON object instead of text.
    #[arg(long)]
    pub json: bool,
    /// Initial velocity in our coordinates: u0,u1,v (rod: u0,u1). Needs --position.
    #[arg(long, value_name = "U0,U1,V", allow_hyphen_values = true)]
    pub velocity: Option<String>,
    /// Initial position in our coordinates: h0,h1,hc (rod: h0,h1). Needs --velocity.
    #[arg(long, value_name = "H0,H1,HC", allow_hyphen_values = true)]
    pub position: Option<String>,
    /// Epsilon of the paper's PCC criterion (state within eps of a multiple of m_(i,i+1)).
    #[arg(long, default_value_t = DEFAULT_PCC_EPSILON)]
    pub pcc_epsilon: f64,
    /// With --exact: prove outcomes from these certificates only (cone certificates with claim
    /// CompleteChatterFromAllDown: no ICC and no PCC; orbit certificates: CC; time-to-rest
    /// certificates, also of a general body: CC of every all-down drop with a time bound; RON or
    /// .json; each re-checked by the kernel on both backends and required to be about this body).
    /// Without it, certificates are made on the fly (for a general body, a time-to-rest one).
    #[arg(long, value_name = "FILE", num_args = 1..)]
    pub certificate: Vec<PathBuf>,
}

/// Validated arguments.
struct Validated {
    model: Model,
    /// A general body (docs/model.md §11) and its description.
    general: Option<super::convex_args::GeneralBody>,
    n: u64,
    kappa: Q,
    gamma: Q,
    arithmetic: Arithmetic,
    initial: Initial,
    seed: u64,
    runs: Option<u64>,
    opts: Options,
    trajectory: Option<PathBuf>,
    plot: Option<PathBuf>,
    json: bool,
    /// Exact runs on regular polygons: the certified sets, and whether orbit certificates may be
    /// made on the fly (not when the sets were given as files).
    sets: Option<Certified>,
    make_orbits: bool,
}

fn numbers(flag: &str, s: &str) -> Result<Vec<Q>, String> {
    s.split(',').map(|x| parse_user_number(x).map_err(|e| format!("{flag}: {e}"))).collect()
}

/// The model of the body: the rod (n = 2) or a regular n-gon, n ≤ 64 (exact over Q for n = 3, 4,
/// 6, over Q(cos 2π/n) and the float model otherwise; issue 10 §1).
fn model(n: u64, kappa: &Q, gamma: &Q) -> Result<Model, String> {
    if !(2..=MAX_N).contains(&n) {
        return Err(format!("--n: {n} is outside 2..={MAX_N} (2 is the rod, 3..={MAX_N} regular n-gons)"));
    }
    let shape = if n == 2 { Shape::Rod } else { Shape::Polygon(n) };
    let model = Model::new(shape, kappa.clone(), gamma.clone())
        .map_err(|e| super::body_error(&e, n, kappa, gamma, "n = 2 (the rod) or 3 to 64"))?;
    Ok(model)
}

fn validate(a: SimulateArgs) -> Result<Validated, String> {
    let (n, kappa, gamma) = a.body.parse()?;
    let general = a.general.parse(&gamma, a.body.gamma.is_some())?;
    let (model, n) = match &general {
        Some(g) => (Model::convex(&g.body), g.body.n() as u64),
        None => (model(n, &kappa, &gamma)?, n),
    };
    let gamma = model.gamma.clone();
    let impacts: usize = a
        .impacts
        .trim()
        .parse()
        .map_err(|_| format!("--impacts: {:?} is not a non-negative integer", a.impacts))?;
    if impacts == 0 || impacts > MAX_IMPACTS {
        return Err(format!("--impacts must be between 1 and {MAX_IMPACTS}"));
    }
    let seed = match &a.seed {
        None => 0,
        Some(s) => s.trim().parse().map_err(|_| format!("--seed: {s:?} is not an integer in 0..2^64"))?,
    };
    let runs = match &a.runs {
        None => None,
        Some(s) => match s.trim().parse::<u64>() {
            Ok(m) if (1..=MAX_RUNS).contains(&m) => Some(m),
            _ => return Err(format!("--runs: {s:?} is not an integer between 1 and {MAX_RUNS}")),
        },
    };
    if !(a.pcc_epsilon.is_finite() && a.pcc_epsilon > 0.0 && a.pcc_epsilon < 1.0) {
        return Err(format!("--pcc-epsilon: {} is not in (0, 1)", a.pcc_epsilon));
    }
    let initial = match (&a.position, &a.velocity) {
        (None, None) => Initial::RandomDrop { seed },
        (Some(pos), Some(vel)) => {
            if a.seed.is_some() {
                return Err(
                    "--seed chooses a random drop: it cannot be combined with --position/--velocity".into()
                );
            }
            if runs.is_some() {
                return Err(
                    "--runs repeats random drops: it cannot be combined with --position/--velocity".into()
                );
            }
            let q = numbers("--position", pos)?;
            let p = numbers("--velocity", vel)?;
            let names = match model.shape() {
                Shape::Rod => "h0,h1 and u0,u1",
                Shape::Polygon(_) => "h0,h1,hc and u0,u1,v",
                Shape::Convex(_) => "phix,phiy,h and wx,wy,v (the paper's coordinates)",
            };
            let start = model.given_start(&q, &p).map_err(|e| match e {
                crate::simulate::StartError::WrongLength { .. } => {
                    format!("--position/--velocity: {e} ({names} for n = {n})")
                }
                _ => format!("--position/--velocity: {e}"),
            })?;
            Initial::Given(Box::new(start))
        }
        _ => return Err("--position and --velocity go together: give both or neither".into()),
    };
    if let Some(p) = &a.plot {
        crate::plot::Format::of(p).map_err(|e| format!("--plot: {e}"))?;
    }
    if runs.is_some() && (a.trajectory.is_some() || a.plot.is_some()) {
        return Err("--trajectory and --plot describe a single run: drop --runs".into());
    }
    let arithmetic = if a.exact { Arithmetic::Exact } else { Arithmetic::Float };
    let (sets, make_orbits) = certified_sets(&model, general.as_ref(), arithmetic, &a.certificate)?;
    let mut opts = Options::new(impacts);
    opts.pcc_epsilon = a.pcc_epsilon;
    opts.record = a.trajectory.is_some() || a.plot.is_some();
    Ok(Validated {
        model,
        general,
        n,
        kappa,
        gamma,
        arithmetic,
        initial,
        seed,
        runs,
        opts,
        trajectory: a.trajectory,
        plot: a.plot,
        json: a.json,
        sets,
        make_orbits,
    })
}

/// The certified sets of an exact run: the given files (each must be accepted by the kernel,
/// exclude PCC and be about this body), or those made on the fly (for a general body, a
/// time-to-rest certificate of it, docs/time-to-rest.md Theorem 5.2).
fn certified_sets(
    model: &Model,
    general: Option<&super::convex_args::GeneralBody>,
    arithmetic: Arithmetic,
    files: &[PathBuf],
) -> Result<(Option<Certified>, bool), String> {
    if arithmetic == Arithmetic::Float {
        if !files.is_empty() {
            return Err("--certificate needs --exact (f64 runs prove nothing)".into());
        }
        return Ok((None, false));
    }
    if files.is_empty() {
        return Ok(match general {
            Some(g) => (Some(crate::prove::made_general(model, &g.body, crate::prove::Effort::Full)), false),
            None => (Some(crate::prove::made(model)), true),
        });
    }
    let mut sets = Certified::empty();
    for f in files {
        sets.add_file(model, f).map_err(|e| format!("--certificate {}: {e}", f.display()))?;
    }
    Ok((Some(sets), false))
}

fn arithmetic_text(a: Arithmetic, model: &Model) -> String {
    match (a, &model.exact) {
        (Arithmetic::Float, _) => "f64 (renormalised)".into(),
        (Arithmetic::Exact, Some(_)) => "exact rationals".into(),
        (Arithmetic::Exact, None) => format!("exact, in Q(cos 2pi/{})", model.n()),
    }
}

/// The body in a figure's title, in the figures' notation (κ =, γ =).
fn figure_head(v: &Validated) -> String {
    match &v.general {
        Some(g) => format!("{}, γ = {}", g.description, v.gamma),
        None => format!("n = {}, κ = {}, γ = {}", v.n, v.kappa, v.gamma),
    }
}

fn head(v: &Validated) -> String {
    if let Some(g) = &v.general {
        return format!("{}, n={} gamma={}", g.description, v.n, v.gamma);
    }
    format!("n={} kappa={} gamma={}", v.n, v.kappa, v.gamma)
}

fn start_text(v: &Validated) -> String {
    match &v.initial {
        Initial::RandomDrop { seed } => format!("random drop, seed {seed}"),
        Initial::Given(s) => {
            let d = v.model.shape().dim();
            let list = |x: &[Q]| x[..d].iter().map(ToString::to_string).collect::<Vec<_>>().join(",");
            format!("position ({}), velocity ({})", list(&s.q), list(&s.p))
        }
    }
}

fn single_text(v: &Validated, run: &Run) -> Vec<String> {
    let n = v.model.n();
    let counts = report::contact_counts(run, n);
    let counts = counts.iter().enumerate().map(|(k, c)| format!("{k}: {c}")).collect::<Vec<_>>().join(", ");
    let mut lines = vec![
        format!(
            "{}, {}, {}, budget {} impacts",
            head(v),
            start_text(v),
            arithmetic_text(v.arithmetic, &v.model),
            run.budget
        ),
        verdict_line(v, run),
        format!("decided by: {}", run.decision.describe()),
    ];
    lines.extend(cone_line(run));
    lines.extend([
        format!("impacts: {} (per contact {counts})", run.impacts),
        format!("sequence: {}", pattern::summary_for(&run.sequence, v.model.shape())),
    ]);
    let mut time = if run.impacts == 0 {
        "total time: 0 (no impacts)".to_string()
    } else {
        format!("total time: {:.12} (at the last impact)", run.time)
    };
    if let (Some(t), Some(l)) = (run.accumulation, run.tail_log2) {
        let how = if matches!(run.decision, Decision::ExactPair { .. }) { "at most" } else { "about" };
        time += &format!("; accumulation point {how} {t:.12}, {how} 2^{l:.1} after the last impact");
    }
    if let Decision::Tie { .. } = run.decision {
        time = format!("total time: {:.12} (at the last impact before the tie)", run.time);
    }
    lines.push(time);
    if let Some(m) = crate::simulate::rest::measure(&v.model, &v.initial, run) {
        let r = crate::report::simulate::TimeToRestReport::of(&m);
        let verdict = if r.within { "within" } else { "VIOLATES" };
        lines.push(format!(
            "time to rest: T|v|/h = {:.6} (evidence, measured from the first impact) {verdict} the proved bound B = {} (docs/time-to-rest.md §2)",
            r.measured, r.bound
        ));
    }
    if run.pcc_overruled > 0 {
        lines.push(format!(
            "note: in {} pair phase(s) the state came within eps of a multiple of m_(i,i+1) (the paper's \
             PCC criterion), but the PCC Lemma excludes PCC for this body (the pair's step map has \
             complex or negative eigenvalues), so those phases end and the run went on",
            run.pcc_overruled
        ));
    }
    lines
}

/// The cone entry a run went on past (issue 24): the first fact proved, and what followed.
fn cone_line(run: &Run) -> Option<String> {
    let cone = run.cone_entry.as_ref()?;
    let Decision::Certified { after, .. } = cone else { return None };
    Some(if *cone == run.decision {
        format!(
            "went on past the cone entry at impact {after}, exactly, to the budget: no orbit certificate's \
             set entered, so the cone's proof (no ICC, no PCC) stands"
        )
    } else {
        format!("first proved: {}; the exact run went on past it, to the entry above", cone.describe())
    })
}

/// "outcome: CC (proved)", "outcome: no ICC, no PCC (proved; CC not proved: ...; evidence: CC
/// ...)", "outcome: undecided (no proof; evidence: CC, last v = ...)" or, in `f64`, "outcome: CC
/// (evidence: f64 simulation proves nothing; rerun with --exact)".
fn verdict_line(v: &Validated, run: &Run) -> String {
    let last_v = report::snapshot_v(&v.model, &run.last);
    if run.proved && run.outcome == Outcome::NoIccNoPcc {
        let evidence = crate::simulate::text::singular(format!(
            "{} after {} impacts, last v = {last_v:.3e}",
            run.evidence, run.impacts
        ));
        return format!(
            "outcome: {} (proved; CC not proved: finite accumulation time not derived, docs/time-to-rest.md; \
             evidence: {evidence})",
            run.outcome.words()
        );
    }
    if run.proved {
        return format!("outcome: {} (proved)", run.outcome.words());
    }
    match v.arithmetic {
        Arithmetic::Float => format!(
            "outcome: {} (evidence: an f64 simulation proves nothing; last v = {last_v:.3e}; --exact proves)",
            run.evidence
        ),
        Arithmetic::Exact => format!(
            "outcome: undecided (no proof within {} impacts; evidence: {} after {} impacts, last v = {last_v:.3e})",
            run.budget, run.evidence, run.impacts
        ),
    }
}

/// The certified sets an exact run was checked against, and why any is missing.
fn sets_lines(sets: &[report::SetReport], notes: &[String]) -> Vec<String> {
    let mut lines: Vec<String> = sets
        .iter()
        .map(|s| {
            let proves = match s.kind {
                "cone" => "entering K proves no ICC and no PCC, not the finite accumulation time",
                "time-to-rest" => {
                    "a drop all-down at its first impact is proved CC, T <= B h/|v| from there (rules G1-G5, F)"
                }
                _ => "entering X proves CC, the impacts accumulating at a finite time",
            };
            format!(
                "certified set: {} ({}, claim {}, kernel-checked on both backends): {proves}",
                s.kind, s.certificate, s.claim
            )
        })
        .collect();
    lines.extend(notes.iter().map(|n| format!("note: {n}")));
    if sets.is_empty() {
        lines.push(
            "no certified set: neither CC nor no-ICC-no-PCC can be proved here (ICC and PCC still can)"
                .into(),
        );
    }
    lines
}

fn general_report(v: &Validated) -> Option<crate::report::convex::GeneralBodyReport> {
    v.general.as_ref().map(|g| crate::report::convex::GeneralBodyReport::of(&g.description, &g.body))
}

fn write_file(path: &PathBuf, text: &str) -> Result<(), String> {
    std::fs::write(path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))
}

fn run_single(v: &Validated) -> cli::Outcome {
    let (mut report, run) =
        report::single(&v.model, &v.initial, v.arithmetic, &v.opts, v.sets.clone(), v.make_orbits);
    if let Some(path) = &v.trajectory
        && let Err(e) = write_file(path, &record::csv(&run, v.model.shape()))
    {
        return cli::Outcome::Usage(e.to_string());
    }
    if let Some(path) = &v.plot {
        let title = format!(
            "{}: {} after {} impacts ({}, {})",
            figure_head(v),
            run.outcome,
            run.impacts,
            start_text(v),
            v.arithmetic.name()
        );
        let fig = TrajectoryFigure::new(&run, &v.model.float, title);
        if let Err(e) = save(&fig, path) {
            return cli::Outcome::Usage(e);
        }
    }
    if v.json {
        report.general_body = general_report(v);
        report.trajectory = v.trajectory.as_ref().map(|p| p.display().to_string());
        report.plot = v.plot.as_ref().map(|p| p.display().to_string());
        emit_report(&report);
    } else {
        for line in single_text(v, &run) {
            emit(&line);
        }
        if v.sets.is_some() {
            for line in sets_lines(&report.certified_sets, &report.certificate_notes) {
                emit(&line);
            }
        }
        if let Some(p) = &v.trajectory {
            emit(&format!("trajectory: {} ({} rows)", p.display(), run.records.len()));
        }
        if let Some(p) = &v.plot {
            emit(&format!("plot: {}", p.display()));
        }
    }
    cli::Outcome::Success
}

fn run_many(v: &Validated, runs: u64) -> cli::Outcome {
    let bar = indicatif::ProgressBar::new(runs);
    if std::io::stderr().is_terminal() && runs > 1 {
        if let Ok(style) = indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} drops {eta}") {
            bar.set_style(style);
        }
    } else {
        bar.set_draw_target(indicatif::ProgressDrawTarget::hidden());
    }
    let tick = || bar.inc(1);
    let mut r =
        report::batch(&v.model, v.seed, runs, v.arithmetic, &v.opts, v.sets.clone(), v.make_orbits, &tick);
    r.general_body = general_report(v);
    bar.finish_and_clear();
    if v.json {
        emit_report(&r);
    } else {
        emit(&format!(
            "{}, {runs} random drops (seeds {}..={}), {}, budget {} impacts",
            head(v),
            r.seeds[0],
            r.seeds[1],
            arithmetic_text(v.arithmetic, &v.model),
            r.budget
        ));
        let list = |outcomes: &[Outcome], m: &std::collections::BTreeMap<String, usize>| {
            let count = |o: &Outcome| m.get(o.name()).copied().unwrap_or(0);
            outcomes.iter().map(|o| format!("{o} {}", count(o))).collect::<Vec<_>>().join(", ")
        };
        match v.arithmetic {
            Arithmetic::Exact => {
                emit(&format!("proved: {}", list(&Outcome::ALL, &r.proved)));
                if r.cc_after_cone > 0 {
                    emit(&format!(
                        "CC after a cone: {} of the CC drops were first proved no ICC, no PCC by a certified \
                         cone, then CC with a time-to-rest bound by an orbit certificate's set (the exact run \
                         went on past the cone entry)",
                        r.cc_after_cone
                    ));
                }
                if r.proved.get(Outcome::NoIccNoPcc.name()).is_some_and(|&k| k > 0) {
                    emit(
                        "no-ICC-no-PCC: entered a certified cone, so never separates and never ends in PCC; \
                         CC not proved (finite accumulation time not derived, docs/time-to-rest.md)",
                    );
                }
                emit(&format!(
                    "evidence (the simulator's rules, not proofs): {}",
                    list(&Outcome::EVIDENCE, &r.evidence)
                ));
            }
            Arithmetic::Float => emit(&format!(
                "outcomes (evidence: f64 simulation proves nothing; --exact proves): {}",
                list(&Outcome::EVIDENCE, &r.counts)
            )),
        }
        let by = r.decided_by.iter().map(|(k, c)| format!("{k} {c}")).collect::<Vec<_>>().join(", ");
        emit(&format!("decided by: {by}"));
        emit(&format!("mean impacts: {:.1}", r.mean_impacts));
        if let Some(t) = &r.time_to_rest {
            emit(&format!(
                "time to rest: largest T|v|/h = {} over {} drops (evidence) against the proved bound B = {} (docs/time-to-rest.md §2): {} violations",
                t.largest.map_or("-".to_string(), |x| format!("{x:.6}")),
                t.measured,
                t.bound,
                t.violations
            ));
        }
        if v.sets.is_some() {
            for line in sets_lines(&r.certified_sets, &r.certificate_notes) {
                emit(&line);
            }
        }
    }
    cli::Outcome::Success
}

pub fn run(a: SimulateArgs) -> cli::Outcome {
    let v = match validate(a) {
        Ok(v) => v,
        Err(e) => return cli::Outcome::Usage(e.to_string()),
    };
    match v.runs {
        Some(m) => run_many(&v, m),
        None => run_single(&v),
    }
}
