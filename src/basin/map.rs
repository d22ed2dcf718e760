//! Maps of basin certificates (`chatter basin-map`, docs/basin-certificates.md §6): at every
//! point (κ, γ) of a grid, a basin certificate over one box of drops, checked by the kernel on
//! both backends, whose exact shares (CC, ICC, undecided, of the box's volume) are the map's
//! values. Deterministic: the files depend only on the request, not on threads or shards (a
//! shard evaluates the points whose index is K modulo N; the shards' rows and certificates, read
//! back, are written as one run's).

use super::{BasinRequest, produce, write_basin};
use crate::exact::Q;
use crate::orbit::Request;
use crate::sweep::grid::{Grid, Point, Shard, Variable};
use chatter_kernel::basin::drop::DIMS;
use chatter_kernel::exact::ParseLimits;
use chatter_kernel::verify::{Backend, Verdict, verify_basin};
use schemars::JsonSchema;
use serde::Serialize;
use std::path::Path;

/// What the share is a share of (printed by `--help`, kept in summary.json).
pub const SHARE_OF: &str = "the volume of the box of drops (velocity (omega_x, omega_y, -1), position (phi_x, phi_y, h) before the first impact): with the paper's box, the probability that the paper's random drop is in the set";

/// A basin map: the grid and the request made at each of its points.
#[derive(Clone, Debug)]
pub struct MapRequest {
    pub grid: Grid,
    /// The box, depth, prefix and orbit settings of every point (its body is replaced).
    pub basin: BasinRequest,
}

/// One point's kernel-checked shares (canonical "p/q" strings) and its certificate.
#[derive(Clone, Debug)]
pub struct PointShares {
    pub point: Point,
    pub cc_share: String,
    pub icc_share: String,
    pub undecided_share: String,
    /// Leaves: CC, ICC, undecided.
    pub leaves: [usize; 3],
    /// The orbit certificate's pattern, or empty when none was found (then no CC leaf).
    pub pattern: Vec<usize>,
    /// The certificate's RON text.
    pub certificate: String,
}

impl MapRequest {
    /// The basin request at one point of the grid.
    pub fn at(&self, p: &Point) -> BasinRequest {
        let mut b = self.basin.clone();
        b.orbit = Request { kappa: p.kappa.clone(), gamma: p.gamma.clone(), ..b.orbit };
        b
    }
}

/// The certificate at one point, checked by the kernel on `backends`; an error is internal (the
/// producer's file rejected, or the backends disagree).
pub fn point(req: &MapRequest, index: usize, backends: &[Backend]) -> Result<PointShares, String> {
    let p = req.grid.point(index);
    let produced = produce(&req.at(&p), backends, &|_| {})?;
    let pattern = produced.orbit.as_ref().map(|f| f.pattern.clone()).unwrap_or_default();
    let r = match verify_basin(&produced.certificate, ParseLimits::default(), backends) {
        Verdict::Accepted(r) => r,
        Verdict::Rejected(r) => return Err(format!("the producer's certificate is rejected: {r}")),
        Verdict::Disagree(s) => return Err(s),
    };
    Ok(PointShares {
        point: p,
        cc_share: r.cc_share,
        icc_share: r.icc_share,
        undecided_share: r.undecided_share,
        leaves: r.leaves,
        pattern,
        certificate: write_basin(&produced.certificate),
    })
}

/// The points of `shard` ([`Shard::ALL`]: every point), in parallel (rayon), in the grid's order;
/// `tick` after each.
pub fn run(
    req: &MapRequest,
    shard: Shard,
    backends: &[Backend],
    tick: &(dyn Fn() + Sync),
) -> Result<Vec<PointShares>, String> {
    use rayon::prelude::*;
    let indices: Vec<usize> = shard.indices(req.grid.len()).collect();
    indices
        .into_par_iter()
        .map(|i| {
            let r = point(req, i, backends);
            tick();
            r.map_err(|e| format!("point {i}: {e}"))
        })
        .collect()
}

/// The header of points.csv.
pub const CSV_HEADER: &str = "index,rho,kappa,gamma,cc_share,icc_share,undecided_share,cc_leaves,icc_leaves,undecided_leaves,orbit_pattern";

/// One row of points.csv.
fn csv_row(s: &PointShares) -> String {
    let p = &s.point;
    let pattern: Vec<String> = s.pattern.iter().map(usize::to_string).collect();
    format!(
        "{},{},{},{},{},{},{},{},{},{},{}",
        p.index,
        p.rho.as_ref().map_or(String::new(), Q::to_string),
        p.kappa,
        p.gamma,
        s.cc_share,
        s.icc_share,
        s.undecided_share,
        s.leaves[0],
        s.leaves[1],
        s.leaves[2],
        pattern.join(" ")
    )
}

/// The shares and leaf counts (CC, ICC, undecided) and the orbit pattern that a basin
/// certificate's text declares: 2^-depth per leaf by its verdict, as the kernel sums them. Read,
/// not checked (that is `chatter verify`'s work): what a row of points.csv must agree with.
fn declared(certificate: &str) -> Result<Declared, String> {
    use chatter_kernel::syntax::basin::BasinCertificate;
    let cert: BasinCertificate =
        chatter_kernel::syntax::read(certificate, chatter_kernel::syntax::Encoding::Ron)
            .map_err(|r| format!("not a basin certificate ({r})"))?;
    let (mut shares, mut counts) = ([Q::int(0), Q::int(0), Q::int(0)], [0usize; 3]);
    for leaf in &cert.leaves {
        let kind = chatter_kernel::rules::basin::kind(&leaf.verdict);
        let volume = (0..leaf.path.len()).fold(Q::int(1), |v, _| v * Q::new(1, 2));
        shares[kind] = &shares[kind] + &volume;
        counts[kind] += 1;
    }
    let pattern = cert.orbit.map(|o| o.pattern.iter().map(|&j| j as usize).collect()).unwrap_or_default();
    Ok(Declared { shares: shares.map(|s| s.to_string()), leaves: counts, pattern })
}

/// What a basin certificate declares of its point: shares (canonical text), leaf counts (CC,
/// ICC, undecided) and the orbit pattern.
#[derive(PartialEq, Eq)]
struct Declared {
    shares: [String; 3],
    leaves: [usize; 3],
    pattern: Vec<usize>,
}

/// A point read back from its row of points.csv and its certificate's text (`chatter basin-map
/// merge`): the row must be exactly the one `chatter basin-map` writes for that point of `req`'s
/// grid, and its shares, leaf counts and pattern those its certificate declares.
pub fn read_row(req: &MapRequest, line: &str, certificate: String) -> Result<PointShares, String> {
    let bad = || format!("not a row of a basin map of this grid ({CSV_HEADER}): {line:?}");
    let cols: Vec<&str> = line.split(',').collect();
    let [index, _, _, _, cc, icc, undecided, l0, l1, l2, pattern] = cols[..] else { return Err(bad()) };
    let index = index.parse::<usize>().ok().filter(|&i| i < req.grid.len()).ok_or_else(bad)?;
    let count = |s: &str| s.parse::<usize>().map_err(|_| bad());
    let pattern = pattern.split_whitespace().map(count).collect::<Result<_, _>>()?;
    let p = PointShares {
        point: req.grid.point(index),
        cc_share: cc.into(),
        icc_share: icc.into(),
        undecided_share: undecided.into(),
        leaves: [count(l0)?, count(l1)?, count(l2)?],
        pattern,
        certificate,
    };
    if csv_row(&p) != line {
        return Err(bad());
    }
    let row = Declared {
        shares: [p.cc_share.clone(), p.icc_share.clone(), p.undecided_share.clone()],
        leaves: p.leaves,
        pattern: p.pattern.clone(),
    };
    if declared(&p.certificate).map_err(|e| format!("point {index}: {e}"))? != row {
        return Err(format!(
            "point {index}: the row's shares, leaves or pattern are not its certificate's: {line:?}"
        ));
    }
    Ok(p)
}

/// The box of drops of every point, canonical "p/q" per coordinate (ω_x, ω_y, φ_x, φ_y, h).
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct BoxOfDrops {
    pub lo: Vec<String>,
    pub hi: Vec<String>,
}

/// One point's exact shares, as the kernel reported them on both backends.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct PointSummary {
    /// The point's index in the grid (and in certificates/point-INDEX.ron).
    pub index: usize,
    /// Canonical "p/q".
    pub kappa: String,
    /// Canonical "p/q".
    pub gamma: String,
    /// Proved CC, canonical "p/q" (of the box's volume; the three shares sum to 1): the drops
    /// enter an orbit certificate's X, or a node's cone of a time-to-rest certificate (those that
    /// reach a simultaneous impact later, where the model stops, have volume zero).
    pub cc_share: String,
    /// Proved ICC (v > 0), canonical "p/q".
    pub icc_share: String,
    /// No verdict claimed, canonical "p/q".
    pub undecided_share: String,
}

/// summary.json of `chatter basin-map` (schema `chatter.basin-map/1`, docs/basin-certificates.md
/// §6): the request, what the shares are shares of, and every point's exact shares.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct BasinMapSummary {
    /// `chatter.basin-map/1`.
    pub schema: &'static str,
    pub n: u64,
    /// The grid's first coordinate: `rho` or `kappa`.
    pub variable: &'static str,
    /// The first coordinate's range `a:b:STEPS`, as given.
    pub x: String,
    /// γ's range `c:d:STEPS`, as given.
    pub gamma: String,
    #[serde(rename = "box")]
    pub drops: BoxOfDrops,
    /// Halvings of the box at most.
    pub depth: usize,
    /// Impacts of a leaf's prefix at most.
    pub max_prefix: usize,
    /// What the shares are shares of.
    pub share_of: &'static str,
    pub points: Vec<PointSummary>,
}

impl crate::json::Report for BasinMapSummary {
    const SCHEMA: &'static str = "chatter.basin-map/1";
}

/// The summary of a map's points.
pub fn summary(req: &MapRequest, points: &[PointShares]) -> BasinMapSummary {
    let b = &req.basin;
    let text = |v: &[Q; DIMS]| v.iter().map(Q::to_string).collect::<Vec<_>>();
    let row = |s: &PointShares| PointSummary {
        index: s.point.index,
        kappa: s.point.kappa.to_string(),
        gamma: s.point.gamma.to_string(),
        cc_share: s.cc_share.clone(),
        icc_share: s.icc_share.clone(),
        undecided_share: s.undecided_share.clone(),
    };
    BasinMapSummary {
        schema: <BasinMapSummary as crate::json::Report>::SCHEMA,
        n: req.grid.n,
        variable: if req.grid.variable == Variable::Rho { "rho" } else { "kappa" },
        x: req.grid.x.text(),
        gamma: req.grid.gamma.text(),
        drops: BoxOfDrops { lo: text(&b.lo), hi: text(&b.hi) },
        depth: b.depth,
        max_prefix: b.max_prefix,
        share_of: SHARE_OF,
        points: points.iter().map(row).collect(),
    }
}

fn io(p: &Path, e: std::io::Error) -> String {
    format!("cannot write {}: {e}", p.display())
}

/// Writes DIR/points.csv and DIR/certificates/point-INDEX.ron of the points (a whole map's or a
/// shard's), in a folder prepared as `chatter map` prepares its own (an earlier map's files
/// removed; a non-empty folder without points.csv refused).
pub fn write_rows(dir: &Path, points: &[PointShares]) -> Result<(), String> {
    crate::sweep::prepare_dir(dir)?;
    let certs = dir.join("certificates");
    std::fs::create_dir_all(&certs).map_err(|e| io(&certs, e))?;
    let mut csv = format!("{CSV_HEADER}\n");
    for s in points {
        csv.push_str(&csv_row(s));
        csv.push('\n');
        let path = certs.join(format!("point-{}.ron", s.point.index));
        std::fs::write(&path, &s.certificate).map_err(|e| io(&path, e))?;
    }
    let path = dir.join("points.csv");
    std::fs::write(&path, csv).map_err(|e| io(&path, e))
}

/// Writes a whole map: DIR/points.csv, DIR/summary.json and DIR/certificates/point-INDEX.ron.
pub fn write(dir: &Path, req: &MapRequest, points: &[PointShares]) -> Result<(), String> {
    write_rows(dir, points)?;
    let path = dir.join("summary.json");
    let json = serde_json::to_string_pretty(&summary(req, points)).map_err(|e| e.to_string())?;
    std::fs::write(&path, json + "\n").map_err(|e| io(&path, e))
}
