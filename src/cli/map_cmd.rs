//! `chatter map`: the paper's maps over (rho, gamma) as data (issue 12), and `chatter map merge`.

use super::{self as cli, emit};
use crate::exact::Q;
use crate::sweep::family::BodyFamily;
use crate::sweep::grid::{Axis, Grid, Shard, Variable};
use crate::sweep::point::Tasks;
use crate::sweep::summary::Summary;
use crate::sweep::{self, Request};
use clap::{Args, Subcommand};
use std::io::IsTerminal;
use std::path::PathBuf;

/// Largest number of random drops per point.
pub const MAX_RUNS: u64 = 100_000;

/// Raw arguments of `chatter map`.
#[derive(Args, Debug)]
#[command(
    args_conflicts_with_subcommands = true,
    after_help = "Evaluates every point of a grid over (rho, gamma) or (kappa, gamma) in parallel: the exact CC \
criterion (S_1 has a real, positive dominant eigenvalue) and PCC criterion (all eigenvalues of \
S_{n-1} S_1 real), exact over Q for n = 3, 4, 6 and in Q(cos 2pi/n) for n = 5; the float cone \
finder's verdict from the paper's seed -U_0 u_3 (found / no-cone / inconclusive); with --certify an \
exact certificate where one can be made (n = 3, 4, 6), kept under DIR/certificates; with --simulate \
the paper's random drops (200 impacts each, seeded per point).\n\n\
An axis a:b:STEPS is the centres of STEPS equal cells of [a, b]: a + (i + 1/2)(b - a)/STEPS, so \
0:1:100 gives 0.005, 0.015, ..., 0.995 and never touches 0 or 1. Numbers are exact (0.1 is 1/10).\n\n\
Writes DIR/points.csv (one row per point, columns in docs/map.md) and DIR/summary.json (counts, \
and every point where the finder, the certificates, the criteria and the simulations disagree). \
The files are byte-identical for identical inputs whatever --jobs and --shard; `chatter map merge` \
joins the folders of all shards into exactly the files of one run. Draw them with `chatter plot map`.\n\n\
Exit status 0 when the map was written, 2 on bad input, 3 if the kernel's backends disagreed.\n\n\
Examples:\n  chatter map --n 3 --rho 0:1:100 --gamma 0:1:100 --certify --out map3\n  \
chatter map --n 4 --rho 0:1:40 --gamma 0:0.2:40 --simulate 20 --out map4\n  \
chatter map --n 3 --rho 0:1:100 --gamma 0:1:100 --shard 0/4 --out part0   (and 1/4, 2/4, 3/4)\n  \
chatter map merge part0 part1 part2 part3 --out map3\n  \
chatter map --family rectangle:aspect=1:4:50 --gamma 0:0.1:50 --certify --out rect\n\n\
With --family the horizontal axis is one parameter of a general body (docs/map.md \"Body families\"): \
the cc_criterion column is the conjectural product criterion (docs/model.md §11.11), pcc_criterion \
says whether the PCC Lemma leaves PCC possible at some adjacent pair, finder is the family finder's \
verdict from I_i(0, 0, -1), --certify makes family certificates checked by the kernel on both \
backends, --simulate runs f64 drops (evidence) and, within --proof-budget, the same drops exactly \
against a time-to-rest certificate of the body made with the survey's budget (a drop all-down at \
its first impact is then proved CC, with a bound on its time to rest); --refute is for regular polygons."
)]
pub struct MapArgs {
    #[command(subcommand)]
    pub merge: Option<MapSub>,
    /// Number of contacts of the regular polygon: 3, 4, 5 or 6.
    #[arg(long, allow_hyphen_values = true, conflicts_with = "family")]
    pub n: Option<String>,
    /// A body family instead of --n and --rho/--kappa: one parameter of a general body on the
    /// horizontal axis, KIND:PARAM=A:B:STEPS with rectangle:aspect (plate aspect x 1),
    /// box:height (box 2 x 1 x height; box=PxQ:height for the base P x Q) or lander:spread (the
    /// lander's feet at spread x their catalogue positions); docs/map.md "Body families".
    #[arg(long, value_name = "KIND:PARAM=A:B:STEPS", conflicts_with_all = ["rho", "kappa", "refute"])]
    pub family: Option<String>,
    /// Horizontal axis in rho = sqrt(kappa): a:b:STEPS (the paper's axis).
    #[arg(long, value_name = "A:B:STEPS", conflicts_with = "kappa", allow_hyphen_values = true)]
    pub rho: Option<String>,
    /// Horizontal axis in kappa instead: a:b:STEPS.
    #[arg(long, value_name = "A:B:STEPS", allow_hyphen_values = true)]
    pub kappa: Option<String>,
    /// Vertical axis, the coefficient of restitution: c:d:STEPS within [0, 1].
    #[arg(long, value_name = "C:D:STEPS", allow_hyphen_values = true)]
    pub gamma: Option<String>,
    /// Also make an exact certificate at every point where the pipeline can (n = 3, 4, 6).
    #[arg(long)]
    pub certify: bool,
    /// Also make an exact refutation (checked by the kernel) wherever no certificate was made
    /// (n = 3, 4, 6), kept under DIR/refutations.
    #[arg(long)]
    pub refute: bool,
    /// Also simulate RUNS of the paper's random drops per point: the paper's protocol in f64
    /// (200 impacts each; evidence) and, for each drop, an exact run that proves its outcome where
    /// it can (CC by entering a kernel-checked orbit certificate's set; no-ICC-no-PCC, not CC, by
    /// entering a kernel-checked cone, whose finite accumulation time is not derived; ICC by v > 0;
    /// PCC by the exact pair proof; docs/map.md).
    #[arg(long, value_name = "RUNS", allow_hyphen_values = true)]
    pub simulate: Option<String>,
    /// With --simulate: the impact budget of each exact run that proves a drop's outcome (0: no
    /// proofs, evidence only).
    #[arg(long, value_name = "IMPACTS", default_value_t = crate::sweep::point::PROOF_BUDGET)]
    pub proof_budget: usize,
    /// Output folder.
    #[arg(long, short = 'o', value_name = "DIR", default_value = "map")]
    pub out: PathBuf,
    /// Worker threads (default: all cores).
    #[arg(long, value_name = "J", allow_hyphen_values = true)]
    pub jobs: Option<String>,
    /// Evaluate only part K of N (K = 0..N-1), or `auto` to read K and N from a SLURM job array.
    #[arg(long, value_name = "K/N|auto")]
    pub shard: Option<String>,
}

/// `chatter map merge`.
#[derive(Subcommand, Debug)]
pub enum MapSub {
    /// Join the output folders of all shards of a sweep into the files of one run.
    Merge(MergeArgs),
}

#[derive(Args, Debug)]
pub struct MergeArgs {
    /// The shards' output folders.
    #[arg(required = true, value_name = "DIR")]
    pub dirs: Vec<PathBuf>,
    /// Output folder.
    #[arg(long, short = 'o', value_name = "DIR")]
    pub out: PathBuf,
}

/// A validated `chatter map`.
struct Validated {
    request: Request,
    out: PathBuf,
    jobs: Option<usize>,
}

/// The grid of a body family (`--family`): n from its body, the parameter on the x axis.
fn family_grid(text: &str, gamma: Axis) -> Result<Grid, String> {
    let (family, x) = BodyFamily::parse(text).map_err(|e| format!("--family: {e}"))?;
    let (body, _) = family.body(&x.value(0), &Q::new(1, 2)).map_err(|e| format!("--family: {e}"))?;
    Ok(Grid { n: body.n() as u64, variable: Variable::Parameter, x, gamma, family: Some(family) })
}

/// The grid of a regular n-gon's map (`--n` with `--rho` or `--kappa`).
fn regular_grid(a: &MapArgs, gamma: Axis) -> Result<Grid, String> {
    let n_text = a.n.as_deref().ok_or("--n is required (3, 4, 5 or 6), or --family")?;
    let n: u64 = n_text.trim().parse().map_err(|_| format!("--n: {n_text:?} is not a positive integer"))?;
    let (variable, x) = match (&a.rho, &a.kappa) {
        (Some(r), None) => (Variable::Rho, Axis::parse(r).map_err(|e| format!("--rho: {e}"))?),
        (None, Some(k)) => (Variable::Kappa, Axis::parse(k).map_err(|e| format!("--kappa: {e}"))?),
        _ => return Err("give the horizontal axis with --rho a:b:STEPS or --kappa a:b:STEPS".into()),
    };
    Ok(Grid { n, variable, x, gamma, family: None })
}

fn validate(a: MapArgs, env_var: impl Fn(&str) -> Option<String>) -> Result<Validated, String> {
    let gamma_text = a.gamma.as_deref().ok_or("--gamma c:d:STEPS is required")?;
    let gamma = Axis::parse(gamma_text).map_err(|e| format!("--gamma: {e}"))?;
    let grid = match &a.family {
        Some(f) => family_grid(f, gamma)?,
        None => regular_grid(&a, gamma)?,
    };
    grid.validate()?;
    let n = grid.n;
    let simulate = match a.simulate {
        None => None,
        Some(s) => {
            let runs: u64 =
                s.trim().parse().map_err(|_| format!("--simulate: {s:?} is not a positive integer"))?;
            if runs == 0 || runs > MAX_RUNS {
                return Err(format!("--simulate: RUNS must be between 1 and {MAX_RUNS}"));
            }
            Some(runs)
        }
    };
    let shard = match a.shard.as_deref() {
        None => Shard::ALL,
        Some("auto") => Shard::from_slurm(env_var).map_err(|e| format!("--shard auto: {e}"))?,
        Some(s) => Shard::parse(s).map_err(|e| format!("--shard: {e}"))?,
    };
    let jobs = match a.jobs {
        None => None,
        Some(j) => match j.trim().parse::<usize>() {
            Ok(j) if (1..=1024).contains(&j) => Some(j),
            _ => return Err(format!("--jobs: {j:?} is not a number of threads in 1..=1024")),
        },
    };
    if a.certify && n == 5 && grid.family.is_none() {
        eprintln!(
            "note: certificates for n = 5 need the number-field kernel (not available yet); the certified and claim columns stay empty"
        );
    }
    if a.refute && n == 5 {
        eprintln!(
            "note: refutations for n = 5 need the number-field kernel (not available yet); the refuted column stays empty"
        );
    }
    if a.proof_budget > crate::cli::simulate_cmd::MAX_IMPACTS {
        return Err(format!(
            "--proof-budget: {} is more than {} impacts",
            a.proof_budget,
            crate::cli::simulate_cmd::MAX_IMPACTS
        ));
    }
    let tasks = Tasks { certify: a.certify, refute: a.refute, simulate, proof_budget: a.proof_budget };
    Ok(Validated { request: Request { grid, tasks, shard }, out: a.out, jobs })
}

/// The request of a `chatter map` command as written (`chatter map --n 3 ...`), read and
/// validated as `chatter map` reads it: `reproduce` makes its maps from the commands it cites, so
/// that each is the map its command makes.
pub fn request_of(command: &str) -> Result<Request, String> {
    let words = command.split_whitespace();
    match <super::Cli as clap::Parser>::try_parse_from(words)
        .map_err(|e| format!("`{command}`: {e}"))?
        .command
    {
        super::Command::Map(a) if a.merge.is_none() => validate(a, |_| None).map(|v| v.request),
        _ => Err(format!("`{command}` is not a `chatter map` command")),
    }
}

/// Runs `f` on a pool of `jobs` threads (or the global pool).
pub fn with_jobs<T: Send>(jobs: Option<usize>, f: impl FnOnce() -> T + Send) -> Result<T, String> {
    match jobs {
        None => Ok(f()),
        Some(j) => rayon::ThreadPoolBuilder::new()
            .num_threads(j)
            .build()
            .map(|pool| pool.install(f))
            .map_err(|e| format!("cannot start {j} threads: {e}")),
    }
}

/// A progress bar on stderr when it is a terminal, hidden otherwise.
pub fn progress(len: u64, what: &str) -> indicatif::ProgressBar {
    let bar = indicatif::ProgressBar::new(len);
    if std::io::stderr().is_terminal() {
        let template = format!("{{bar:40}} {{pos}}/{{len}} {what} {{elapsed}} (eta {{eta}})");
        if let Ok(style) = indicatif::ProgressStyle::with_template(&template) {
            bar.set_style(style);
        }
    } else {
        bar.set_draw_target(indicatif::ProgressDrawTarget::hidden());
    }
    bar
}

/// One line per count of the summary.
pub fn summary_lines(s: &Summary) -> Vec<String> {
    let mut lines = Vec::new();
    for (column, values) in &s.counts {
        let v: Vec<String> = values.iter().map(|(k, n)| format!("{k} {n}")).collect();
        lines.push(format!("  {column}: {}", v.join(", ")));
    }
    for (kind, k) in &s.disagreement_kinds {
        if k.points > 0 {
            lines.push(format!("  disagreement {kind}: {} points", k.points));
        }
    }
    lines
}

/// Runs a validated sweep and writes its folder.
fn sweep(v: Validated) -> cli::Outcome {
    let req = &v.request;
    let count = req.shard.indices(req.grid.len()).count() as u64;
    let bar = progress(count, "points");
    let start = std::time::Instant::now();
    let done = match with_jobs(v.jobs, || sweep::run(req, &|| bar.inc(1))) {
        Ok(d) => d,
        Err(e) => return cli::Outcome::Usage(e),
    };
    bar.finish_and_clear();
    let secs = start.elapsed().as_secs_f64();
    if let Some(d) = done.iter().find(|d| d.internal.is_some()) {
        return cli::Outcome::Internal(format!(
            "point {} (kappa = {}, gamma = {}): {}",
            d.row.index,
            d.row.kappa,
            d.row.gamma,
            d.internal.as_deref().unwrap_or_default()
        ));
    }
    let summary = match sweep::write_output(&v.out, req, &done) {
        Ok(s) => s,
        Err(e) => return cli::Outcome::Usage(e),
    };
    let g = &req.grid;
    let part = if req.shard.count > 1 {
        format!(" (shard {}/{})", req.shard.index, req.shard.count)
    } else {
        String::new()
    };
    let body = match (&g.family, g.variable) {
        (Some(f), _) => format!("family {}={}", f.text(), g.x.text()),
        (None, Variable::Rho) => format!("n={} rho={}", g.n, g.x.text()),
        (None, _) => format!("n={} kappa={}", g.n, g.x.text()),
    };
    emit(&format!(
        "map {body} gamma={}: {count} points{part} in {secs:.1} s ({:.0} points/s) -> {}",
        g.gamma.text(),
        count as f64 / secs.max(1e-9),
        v.out.display()
    ));
    for l in summary.as_ref().map(summary_lines).unwrap_or_default() {
        emit(&l);
    }
    for l in sweep::proofs::lines(g.n, &done) {
        emit(&l);
    }
    cli::Outcome::Success
}

pub fn run(a: MapArgs) -> cli::Outcome {
    if let Some(MapSub::Merge(m)) = a.merge {
        return match sweep::merge(&m.dirs, &m.out) {
            Ok(s) => {
                emit(&format!("merged {} shards: {} points -> {}", m.dirs.len(), s.points, m.out.display()));
                for l in summary_lines(&s) {
                    emit(&l);
                }
                cli::Outcome::Success
            }
            Err(e) => cli::Outcome::Usage(e),
        };
    }
    match validate(a, |k| std::env::var(k).ok()) {
        Ok(v) => sweep(v),
        Err(e) => cli::Outcome::Usage(e),
    }
}
