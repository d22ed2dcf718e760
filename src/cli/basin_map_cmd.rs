//! `chatter basin-map`: basin certificates over a grid of (kappa, gamma), their kernel-checked
//! shares per point (docs/basin-certificates.md §6). A command of its own rather than
//! `map --basin`: its work per point (a certificate over a box of drops, seconds to minutes) and
//! its options (--box, --depth, --pattern) are not those of `map`, whose files (points.csv
//! columns, summary schema chatter.map/1, shards and merge) stay as documented in docs/map.md.

use super::basin_cmd::parse_box;
use super::map_cmd::{progress, with_jobs};
use super::{Env, Outcome, emit};
use crate::basin::BasinRequest;
use crate::basin::map::{MapRequest, SHARE_OF, run as run_map, write};
use crate::exact::{Q, QExt};
use crate::orbit::Request;
use crate::sweep::grid::{Axis, Grid, Variable};
use clap::Args;
use std::path::PathBuf;

/// The default box: the paper's box's centre, +-1/1000 in every coordinate.
pub const TINY_BOX: &str =
    "49/1000,49/1000,49/1000,49/1000,1049/1000:51/1000,51/1000,51/1000,51/1000,1051/1000";

/// Raw arguments of `chatter basin-map`.
#[derive(Args, Debug)]
#[command(
    after_help = "At every point of the grid: a basin certificate (as `chatter basin`) over the box of \
drops, checked by the kernel on both backends, and its exact shares cc_share (drops proved to end in \
complete chatter: they enter an orbit certificate's set X, or a node's cone of a time-to-rest \
certificate, where those that reach a simultaneous impact later, at which the model stops, have \
volume zero: docs/basin-certificates.md Lemma 4.1), icc_share (proved to reach v > 0) and \
undecided_share (no verdict). Each share is a share of the volume of the box of drops (velocity \
(omega_x, omega_y, -1), position (phi_x, phi_y, h) before the first impact), not of the grid cell; \
with the paper's box it is the probability that the paper's random drop lies in the set. The \
default box is tiny: the paper's box's centre +-1/1000.\n\n\
An axis a:b:STEPS is the centres of STEPS equal cells of [a, b], as in `chatter map`.\n\n\
Writes DIR/points.csv, DIR/summary.json (schema chatter.basin-map/1, exact \"p/q\" shares) and \
every certificate under DIR/certificates (check them with `chatter verify`); the files are \
identical for identical inputs. Draw with `chatter plot basin-map DIR -o FILE`.\n\n\
Example:\n  chatter basin-map --n 3 --kappa 0.05:0.25:4 --gamma 0.05:0.3:4 --depth 4 --out bmap\n  \
chatter plot basin-map bmap -o bmap.png"
)]
pub struct BasinMapArgs {
    /// Number of contacts of the regular polygon: 3, 4, 5 or 6.
    #[arg(long, default_value_t = 3)]
    pub n: u64,
    /// Horizontal axis in kappa: a:b:STEPS.
    #[arg(long, value_name = "A:B:STEPS", conflicts_with = "rho", allow_hyphen_values = true)]
    pub kappa: Option<String>,
    /// Horizontal axis in rho = sqrt(kappa) instead: a:b:STEPS.
    #[arg(long, value_name = "A:B:STEPS", allow_hyphen_values = true)]
    pub rho: Option<String>,
    /// Vertical axis, the coefficient of restitution: c:d:STEPS within [0, 1].
    #[arg(long, value_name = "C:D:STEPS", allow_hyphen_values = true)]
    pub gamma: String,
    /// The orbit certificates' pattern (e.g. 2,2,1,1); found by simulating drops at each point
    /// when omitted.
    #[arg(long, allow_hyphen_values = true)]
    pub pattern: Option<String>,
    /// The box of drops: "lo1,..,lo5:hi1,..,hi5" for (omega_x, omega_y, phi_x, phi_y, h)
    /// [default: the paper's box's centre +-1/1000].
    #[arg(long = "box", allow_hyphen_values = true)]
    pub drop_box: Option<String>,
    /// The deepest bisection of the box at each point.
    #[arg(long, default_value_t = 4)]
    pub depth: usize,
    /// The longest impact prefix tried per sub-box.
    #[arg(long, default_value_t = 400)]
    pub max_prefix: usize,
    /// The orbit certificates' deepest subdivision of X.
    #[arg(long, default_value_t = 2)]
    pub orbit_depth: u64,
    /// Do not try a time-to-rest certificate at each point (survey effort: at most 40 nodes).
    #[arg(long, conflicts_with = "full_rest")]
    pub no_rest: bool,
    /// Try each point's time-to-rest certificate with the full search of `chatter certify
    /// --time-to-rest` (up to 200 nodes, three pads, merged graphs) instead of the survey's:
    /// more points proved CC below the threshold, up to tens of seconds more per point.
    #[arg(long)]
    pub full_rest: bool,
    /// Output folder.
    #[arg(long, short = 'o', value_name = "DIR", default_value = "basin-map")]
    pub out: PathBuf,
    /// Worker threads (default: all cores).
    #[arg(long, value_name = "J")]
    pub jobs: Option<usize>,
}

fn validate(a: &BasinMapArgs) -> Result<MapRequest, String> {
    let (variable, x) = match (&a.rho, &a.kappa) {
        (Some(r), None) => (Variable::Rho, Axis::parse(r).map_err(|e| format!("--rho: {e}"))?),
        (None, Some(k)) => (Variable::Kappa, Axis::parse(k).map_err(|e| format!("--kappa: {e}"))?),
        _ => return Err("give the horizontal axis with --kappa a:b:STEPS or --rho a:b:STEPS".into()),
    };
    let gamma = Axis::parse(&a.gamma).map_err(|e| format!("--gamma: {e}"))?;
    let grid = Grid { n: a.n, variable, x, gamma, family: None };
    grid.validate()?;
    let pattern = a.pattern.as_deref().map(|p| super::orbit_cmd::parse_pattern(p, a.n)).transpose()?;
    let (lo, hi) = parse_box(a.drop_box.as_deref().unwrap_or(TINY_BOX))?;
    super::basin_cmd::check_box_and_limits(&lo, &hi, a.depth, a.max_prefix)?;
    if a.jobs.is_some_and(|j| !(1..=1024).contains(&j)) {
        return Err("--jobs: give a number of threads in 1..=1024".into());
    }
    let orbit = Request {
        n: a.n,
        kappa: Q::int(1),
        gamma: Q::int(0),
        pattern,
        drops: 200,
        max_depth: a.orbit_depth.min(4),
    };
    let rest = match (a.no_rest, a.full_rest) {
        (true, _) => None,
        (false, true) => Some(crate::certify::virtual_time::Config::default()),
        (false, false) => Some(crate::prove::survey_rest_config()),
    };
    let basin = BasinRequest { orbit, lo, hi, depth: a.depth, max_prefix: a.max_prefix, entry: 0.25, rest };
    Ok(MapRequest { grid, basin })
}

pub fn run(a: BasinMapArgs, env: &Env) -> Outcome {
    let req = match validate(&a) {
        Ok(r) => r,
        Err(e) => return Outcome::Usage(e),
    };
    let bar = progress(req.grid.len() as u64, "points");
    let start = std::time::Instant::now();
    let points = match with_jobs(a.jobs, || run_map(&req, &env.backends, &|| bar.inc(1))) {
        Ok(Ok(p)) => p,
        Ok(Err(e)) => return Outcome::Internal(e),
        Err(e) => return Outcome::Usage(e),
    };
    bar.finish_and_clear();
    let secs = start.elapsed().as_secs_f64();
    if let Err(e) = write(&a.out, &req, &points) {
        return Outcome::Usage(e);
    }
    let mean = |f: fn(&crate::basin::map::PointShares) -> &String| {
        let sum = points.iter().filter_map(|p| f(p).parse::<Q>().ok()).fold(Q::int(0), |s, x| &s + &x);
        (sum * Q::new(1, points.len().max(1) as i64)).to_f64()
    };
    emit(&format!(
        "basin-map n={} {}={} gamma={}: {} points in {secs:.1} s ({:.1} s/point) -> {}",
        req.grid.n,
        if req.grid.variable == Variable::Rho { "rho" } else { "kappa" },
        req.grid.x.text(),
        req.grid.gamma.text(),
        points.len(),
        secs / points.len().max(1) as f64,
        a.out.display()
    ));
    emit(&format!(
        "  mean kernel-checked shares over the points: CC {:.4}, ICC {:.4}, undecided {:.4} (of {SHARE_OF})",
        mean(|p| &p.cc_share),
        mean(|p| &p.icc_share),
        mean(|p| &p.undecided_share)
    ));
    Outcome::Success
}
