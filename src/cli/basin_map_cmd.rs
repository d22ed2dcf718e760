//! `chatter basin-map`: basin certificates over a grid of (kappa, gamma), their kernel-checked
//! shares per point (docs/basin-certificates.md §6). A command of its own rather than
//! `map --basin`: its work per point (a certificate over a box of drops, seconds to minutes) and
//! its options (--box, --depth, --pattern) are not those of `map`, whose files (points.csv
//! columns, summary schema chatter.map/1, shards and merge) stay as documented in docs/map.md.

use super::basin_cmd::parse_box;
use super::map_cmd::{MergeArgs, progress, with_jobs};
use super::{Env, Outcome, emit};
use crate::basin::BasinRequest;
use crate::basin::map::{
    CSV_HEADER, MapRequest, PointShares, SHARE_OF, read_row, run as run_map, write, write_rows,
};
use crate::exact::{Q, QExt};
use crate::orbit::Request;
use crate::sweep::grid::{Axis, Grid, Shard, Variable};
use clap::{Args, Subcommand};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

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
On a cluster, --shard K/N (or --shard auto in a SLURM job array) evaluates the points whose index \
is K modulo N and writes their rows, certificates and DIR/shard.json; `chatter basin-map merge \
DIR... -o OUT` joins the folders of all N shards into exactly the files of one run (docs/cluster.md).\n\n\
Example:\n  chatter basin-map --n 3 --kappa 0.05:0.25:4 --gamma 0.05:0.3:4 --depth 4 --out bmap\n  \
chatter plot basin-map bmap -o bmap.png",
    args_conflicts_with_subcommands = true
)]
pub struct BasinMapArgs {
    #[command(subcommand)]
    pub merge: Option<BasinMapSub>,
    /// Number of contacts of the regular polygon: 3, 4, 5 or 6.
    #[arg(long, default_value_t = 3)]
    pub n: u64,
    /// Horizontal axis in kappa: a:b:STEPS.
    #[arg(long, value_name = "A:B:STEPS", conflicts_with = "rho", allow_hyphen_values = true)]
    pub kappa: Option<String>,
    /// Horizontal axis in rho = sqrt(kappa) instead: a:b:STEPS.
    #[arg(long, value_name = "A:B:STEPS", allow_hyphen_values = true)]
    pub rho: Option<String>,
    /// Vertical axis, the coefficient of restitution: c:d:STEPS within [0, 1] (required).
    #[arg(long, value_name = "C:D:STEPS", allow_hyphen_values = true)]
    pub gamma: Option<String>,
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
    /// Evaluate only part K of N of the points (K = 0..N-1: those whose index is K modulo N), or
    /// `auto` to read K and N from a SLURM job array; join the shards with `basin-map merge`.
    #[arg(long, value_name = "K/N|auto")]
    pub shard: Option<String>,
}

/// `chatter basin-map merge`.
#[derive(Subcommand, Debug)]
pub enum BasinMapSub {
    /// Join the output folders of all shards of one basin map into the files of one run.
    Merge(MergeArgs),
}

/// The schema of a shard's shard.json.
const SHARD_SCHEMA: &str = "chatter.basin-map-shard/1";

/// DIR/shard.json of a shard: what decides every point's certificate (canonical text, as the
/// options of `chatter basin-map` would give it) and the shard, so that `basin-map merge` joins
/// the shards of one map only.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
struct ShardFile {
    schema: String,
    settings: Settings,
    shard: Shard,
}

/// The options of `chatter basin-map` that decide its files, in canonical text.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
struct Settings {
    n: u64,
    /// `kappa` or `rho`, and its axis A:B:STEPS.
    variable: String,
    x: String,
    gamma: String,
    pattern: Option<String>,
    #[serde(rename = "box")]
    drop_box: String,
    depth: usize,
    max_prefix: usize,
    orbit_depth: u64,
    /// The time-to-rest search at each point: `survey`, `full` or `none`.
    rest: String,
}

impl Settings {
    /// The settings of a validated map.
    fn of(a: &BasinMapArgs, req: &MapRequest) -> Settings {
        let join = |v: &[Q]| v.iter().map(Q::to_string).collect::<Vec<_>>().join(",");
        let (b, g) = (&req.basin, &req.grid);
        Settings {
            n: g.n,
            variable: if g.variable == Variable::Rho { "rho" } else { "kappa" }.into(),
            x: g.x.text(),
            gamma: g.gamma.text(),
            pattern: b
                .orbit
                .pattern
                .as_ref()
                .map(|p| p.iter().map(usize::to_string).collect::<Vec<_>>().join(",")),
            drop_box: format!("{}:{}", join(&b.lo), join(&b.hi)),
            depth: b.depth,
            max_prefix: b.max_prefix,
            orbit_depth: b.orbit.max_depth,
            rest: if a.no_rest {
                "none"
            } else if a.full_rest {
                "full"
            } else {
                "survey"
            }
            .into(),
        }
    }

    /// The map these settings describe, validated as `chatter basin-map` validates its options.
    fn request(&self) -> Result<MapRequest, String> {
        let axis = Some(self.x.clone());
        let (kappa, rho) = if self.variable == "rho" { (None, axis) } else { (axis, None) };
        if !matches!(self.rest.as_str(), "survey" | "full" | "none") {
            return Err(format!("rest {:?} is not survey, full or none", self.rest));
        }
        if !matches!(self.variable.as_str(), "rho" | "kappa") {
            return Err(format!("variable {:?} is not rho or kappa", self.variable));
        }
        let args = BasinMapArgs {
            merge: None,
            n: self.n,
            kappa,
            rho,
            gamma: Some(self.gamma.clone()),
            pattern: self.pattern.clone(),
            drop_box: Some(self.drop_box.clone()),
            depth: self.depth,
            max_prefix: self.max_prefix,
            orbit_depth: self.orbit_depth,
            no_rest: self.rest == "none",
            full_rest: self.rest == "full",
            out: PathBuf::new(),
            jobs: None,
            shard: None,
        };
        validate(&args)
    }
}

fn validate(a: &BasinMapArgs) -> Result<MapRequest, String> {
    let (variable, x) = match (&a.rho, &a.kappa) {
        (Some(r), None) => (Variable::Rho, Axis::parse(r).map_err(|e| format!("--rho: {e}"))?),
        (None, Some(k)) => (Variable::Kappa, Axis::parse(k).map_err(|e| format!("--kappa: {e}"))?),
        _ => return Err("give the horizontal axis with --kappa a:b:STEPS or --rho a:b:STEPS".into()),
    };
    let gamma_text = a.gamma.as_deref().ok_or("--gamma c:d:STEPS is required")?;
    let gamma = Axis::parse(gamma_text).map_err(|e| format!("--gamma: {e}"))?;
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

/// The request and the shard, and the checks that need no work: the output folder is one that
/// may be written (`sweep::check_dir`), and a shard's options read back from its shard.json as
/// they were given (else `merge` could not join the shards).
fn prepare(a: &BasinMapArgs) -> Result<(MapRequest, Shard), String> {
    let req = validate(a)?;
    let shard = shard_of(a.shard.as_deref())?;
    crate::sweep::check_dir(&a.out)?;
    if shard != Shard::ALL {
        Settings::of(a, &req)
            .request()
            .map_err(|e| format!("--shard: these options cannot be read back from shard.json ({e})"))?;
    }
    Ok((req, shard))
}

/// The shard of `--shard` (the whole grid without it).
fn shard_of(text: Option<&str>) -> Result<Shard, String> {
    match text {
        None => Ok(Shard::ALL),
        Some("auto") => {
            Shard::from_slurm(|k| std::env::var(k).ok()).map_err(|e| format!("--shard auto: {e}"))
        }
        Some(s) => Shard::parse(s).map_err(|e| format!("--shard: {e}")),
    }
}

pub fn run(a: BasinMapArgs, env: &Env) -> Outcome {
    if let Some(BasinMapSub::Merge(m)) = &a.merge {
        return match merge(m) {
            Ok((req, points)) => match write(&m.out, &req, &points) {
                Ok(()) => {
                    emit(&format!(
                        "merged {} shards: {} points -> {} (the shares as the shards' kernel runs reported them, not checked again: `chatter verify {}/certificates` re-checks)",
                        m.dirs.len(),
                        points.len(),
                        m.out.display(),
                        m.out.display()
                    ));
                    emit(&mean_shares(&points));
                    Outcome::Success
                }
                Err(e) => Outcome::Usage(e),
            },
            Err(e) => Outcome::Usage(e),
        };
    }
    let (req, shard) = match prepare(&a) {
        Ok(r) => r,
        Err(e) => return Outcome::Usage(e),
    };
    let count = shard.indices(req.grid.len()).count();
    let bar = progress(count as u64, "points");
    let start = std::time::Instant::now();
    let points = match with_jobs(a.jobs, || run_map(&req, shard, &env.backends, &|| bar.inc(1))) {
        Ok(Ok(p)) => p,
        Ok(Err(e)) => return Outcome::Internal(e),
        Err(e) => return Outcome::Usage(e),
    };
    bar.finish_and_clear();
    let secs = start.elapsed().as_secs_f64();
    let written = if shard == Shard::ALL {
        write(&a.out, &req, &points)
    } else {
        let file = ShardFile { schema: SHARD_SCHEMA.into(), settings: Settings::of(&a, &req), shard };
        write_rows(&a.out, &points).and_then(|()| write_json(&a.out.join("shard.json"), &file))
    };
    if let Err(e) = written {
        return Outcome::Usage(e);
    }
    let part =
        if shard == Shard::ALL { String::new() } else { format!(" (shard {}/{})", shard.index, shard.count) };
    emit(&format!(
        "basin-map n={} {}={} gamma={}: {} points{part} in {secs:.1} s ({:.1} s/point) -> {}",
        req.grid.n,
        if req.grid.variable == Variable::Rho { "rho" } else { "kappa" },
        req.grid.x.text(),
        req.grid.gamma.text(),
        points.len(),
        secs / points.len().max(1) as f64,
        a.out.display()
    ));
    emit(&mean_shares(&points));
    Outcome::Success
}

/// The line of the mean kernel-checked shares over the points.
fn mean_shares(points: &[PointShares]) -> String {
    let mean = |f: fn(&PointShares) -> &String| {
        let sum = points.iter().filter_map(|p| f(p).parse::<Q>().ok()).fold(Q::int(0), |s, x| &s + &x);
        (sum * Q::new(1, points.len().max(1) as i64)).to_f64()
    };
    format!(
        "  mean kernel-checked shares over the points: CC {:.4}, ICC {:.4}, undecided {:.4} (of {SHARE_OF})",
        mean(|p| &p.cc_share),
        mean(|p| &p.icc_share),
        mean(|p| &p.undecided_share)
    )
}

fn write_json(path: &Path, value: &impl Serialize) -> Result<(), String> {
    let text = serde_json::to_string_pretty(value).map_err(|e| e.to_string())? + "\n";
    std::fs::write(path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))
}

fn read_text(path: &Path) -> Result<String, String> {
    std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))
}

/// The shards' folders read back: every shard of one map exactly once, each with exactly its
/// points' rows and certificates; the points in the grid's order.
fn merge(m: &MergeArgs) -> Result<(MapRequest, Vec<PointShares>), String> {
    let mut shards = Vec::new();
    for d in &m.dirs {
        let path = d.join("shard.json");
        let file: ShardFile =
            serde_json::from_str(&read_text(&path)?).map_err(|e| format!("{}: {e}", path.display()))?;
        if file.schema != SHARD_SCHEMA {
            return Err(format!("{}: not the shard.json of a shard of `chatter basin-map`", path.display()));
        }
        shards.push((file, d));
    }
    let Some((first, _)) = shards.first() else { return Err("no shard folders given".into()) };
    let (settings, count) = (first.settings.clone(), first.shard.count);
    for (f, d) in &shards {
        if f.settings != settings || f.shard.count != count {
            return Err(format!(
                "{} belongs to a different basin map (options or shard count differ)",
                d.display()
            ));
        }
    }
    Shard::check_cover(count, shards.iter().map(|(f, d)| (f.shard, d.as_path())))?;
    let req = settings.request()?;
    let mut points = Vec::new();
    for (f, d) in &shards {
        let csv = read_text(&d.join("points.csv"))?;
        let expected: Vec<usize> = f.shard.indices(req.grid.len()).collect();
        let rows: Vec<&str> = csv.lines().skip(1).collect();
        if csv.lines().next() != Some(CSV_HEADER) || rows.len() != expected.len() {
            return Err(format!(
                "{}: the rows are not those of shard {}/{count}",
                d.display(),
                f.shard.index
            ));
        }
        for (line, &i) in rows.iter().zip(&expected) {
            let cert = read_text(&d.join(format!("certificates/point-{i}.ron")))?;
            let p = read_row(&req, line, cert).map_err(|e| format!("{}: {e}", d.display()))?;
            if p.point.index != i {
                return Err(format!(
                    "{}: the rows are not those of shard {}/{count}",
                    d.display(),
                    f.shard.index
                ));
            }
            points.push(p);
        }
    }
    points.sort_by_key(|p| p.point.index);
    Ok((req, points))
}
