//! Sweeps over the parameter plane: the paper's maps (figures "sajatertekek" and "simulations")
//! as data. Every grid point is evaluated independently ([`point`]) and in parallel (rayon); the
//! output folder holds points.csv ([`table`]), summary.json ([`summary`]) and the certificates.
//! A sweep can be split into shards (separate processes, e.g. a SLURM job array) and the shards
//! merged into exactly the files of one run: results never depend on threads or shards.

pub mod curves;
pub mod family;
pub mod general;
pub mod grid;
pub mod point;
pub mod proofs;
pub mod summary;
pub mod table;

use grid::{Grid, Shard};
use point::{Evaluation, PAPER_BUDGET, Tasks, evaluate};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};
use summary::{Computed, Summary};
use table::{Row, csv, parse_csv};

/// A sweep request (validated).
#[derive(Clone, Debug)]
pub struct Request {
    pub grid: Grid,
    pub tasks: Tasks,
    pub shard: Shard,
}

impl Request {
    /// What every point records as computed (summary.json, shard.json).
    pub fn computed(&self) -> Computed {
        Computed {
            certify: self.tasks.certify,
            refute: self.tasks.refute,
            simulate: self.tasks.simulate.unwrap_or(0),
            budget: PAPER_BUDGET,
            proof_budget: if self.tasks.simulate.is_some() { self.tasks.proof_budget } else { 0 },
        }
    }
}

/// One evaluated point: its row and its certificate, refutation and orbit certificate texts.
#[derive(Clone, Debug)]
pub struct Done {
    pub row: Row,
    pub certificate: Option<String>,
    pub refutation: Option<String>,
    pub orbit: Option<String>,
    pub internal: Option<String>,
    /// Per drop with proofs: proved outcome (undecided when none) and exact wall time, seconds
    /// ([`point::Evaluation::proof_times`]; printed, never written).
    pub proof_times: Vec<(crate::simulate::Outcome, f64)>,
}

/// Evaluates the shard's points in parallel on the current rayon pool, in index order; `tick`
/// is called after each point.
pub fn run(req: &Request, tick: &(dyn Fn() + Sync)) -> Vec<Done> {
    use rayon::prelude::*;
    let indices: Vec<usize> = req.shard.indices(req.grid.len()).collect();
    // One point per task: the work per point varies by orders of magnitude (certification near
    // the threshold), and rayon's adaptive splitting would otherwise leave one thread a long
    // run of expensive points while the other idles (jobs 1 / jobs 2 was 1.19).
    indices
        .into_par_iter()
        .with_max_len(1)
        .map(|i| {
            let p = req.grid.point(i);
            let e: Evaluation = match &req.grid.family {
                Some(f) => family::evaluate(f, &p, req.tasks),
                None => evaluate(req.grid.n, &p, req.tasks),
            };
            tick();
            let row = Row::new(&req.grid, &p, &e);
            Done {
                row,
                certificate: e.certificate,
                refutation: e.refutation,
                orbit: e.orbit,
                internal: e.internal,
                proof_times: e.proof_times,
            }
        })
        .collect()
}

/// shard.json: what a shard's folder holds, so that [`merge`] can check the pieces fit.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct ShardFile {
    pub grid: Grid,
    pub computed: Computed,
    pub shard: Shard,
}

/// The files of a map's output folder.
pub const POINTS: &str = "points.csv";
pub const SUMMARY: &str = "summary.json";
pub const SHARD: &str = "shard.json";
pub const CERTIFICATES: &str = "certificates";
pub const REFUTATIONS: &str = "refutations";
pub const ORBITS: &str = "orbits";

fn io(path: &Path, e: std::io::Error) -> String {
    format!("{}: {e}", path.display())
}

/// Refuses, before any work, a folder for a map's files that is not empty and not a map's.
pub fn check_dir(dir: &Path) -> Result<(), String> {
    if dir.exists() {
        let mut entries = std::fs::read_dir(dir).map_err(|e| io(dir, e))?.peekable();
        if entries.peek().is_some() && !dir.join(POINTS).exists() {
            return Err(format!(
                "{} is not empty and holds no {POINTS}: not overwriting it (choose another --out)",
                dir.display()
            ));
        }
    }
    Ok(())
}

/// Prepares `dir` for a map's files: creates it, or clears the files of an earlier map in it;
/// refuses a non-empty folder that is not a map's ([`check_dir`]).
pub fn prepare_dir(dir: &Path) -> Result<(), String> {
    check_dir(dir)?;
    if dir.exists() {
        for f in [POINTS, SUMMARY, SHARD] {
            let p = dir.join(f);
            if p.exists() {
                std::fs::remove_file(&p).map_err(|e| io(&p, e))?;
            }
        }
        for sub in [CERTIFICATES, REFUTATIONS, ORBITS] {
            let c = dir.join(sub);
            if c.exists() {
                std::fs::remove_dir_all(&c).map_err(|e| io(&c, e))?;
            }
        }
    }
    std::fs::create_dir_all(dir).map_err(|e| io(dir, e))
}

fn write(path: PathBuf, text: &str) -> Result<(), String> {
    if let Some(parent) = path.parent() {
        std::fs::create_dir_all(parent).map_err(|e| io(parent, e))?;
    }
    std::fs::write(&path, text).map_err(|e| io(&path, e))
}

/// Writes a sweep's results: the whole grid gets points.csv, summary.json and certificates/, a
/// shard its rows, shard.json and its certificates. Returns the summary of a whole grid.
pub fn write_output(dir: &Path, req: &Request, done: &[Done]) -> Result<Option<Summary>, String> {
    prepare_dir(dir)?;
    for d in done {
        if let (Some(text), Some(rel)) = (&d.certificate, &d.row.certificate) {
            write(dir.join(rel), text)?;
        }
        if let (Some(text), Some(rel)) = (&d.refutation, &d.row.refutation) {
            write(dir.join(rel), text)?;
        }
        if let (Some(text), Some(rel)) = (&d.orbit, &d.row.orbit) {
            write(dir.join(rel), text)?;
        }
    }
    let rows: Vec<Row> = done.iter().map(|d| d.row.clone()).collect();
    write(dir.join(POINTS), &csv(&req.grid, &rows))?;
    if req.shard.count == 1 {
        let summary = Summary::new(&req.grid, &req.computed(), &rows);
        write(dir.join(SUMMARY), &summary.json())?;
        Ok(Some(summary))
    } else {
        let shard = ShardFile { grid: req.grid.clone(), computed: req.computed(), shard: req.shard };
        write(dir.join(SHARD), &(serde_json::to_string_pretty(&shard).expect("serialisable") + "\n"))?;
        Ok(None)
    }
}

fn read(path: &Path) -> Result<String, String> {
    std::fs::read_to_string(path).map_err(|e| io(path, e))
}

/// Joins shard folders into the files of one run of the whole grid, written to `out`.
pub fn merge(dirs: &[PathBuf], out: &Path) -> Result<Summary, String> {
    let mut shards: Vec<(ShardFile, Vec<Row>, &PathBuf)> = Vec::new();
    for d in dirs {
        let file: ShardFile = serde_json::from_str(&read(&d.join(SHARD))?)
            .map_err(|e| format!("{}: {e}", d.join(SHARD).display()))?;
        let rows =
            parse_csv(&read(&d.join(POINTS))?).map_err(|e| format!("{}: {e}", d.join(POINTS).display()))?;
        shards.push((file, rows, d));
    }
    let Some((first, _, _)) = shards.first() else { return Err("no shard folders given".into()) };
    let (grid, computed, count) = (first.grid.clone(), first.computed.clone(), first.shard.count);
    grid.validate().map_err(|e| format!("{}: {e}", shards[0].2.join(SHARD).display()))?;
    for (f, _, d) in &shards {
        if f.grid != grid || f.computed != computed || f.shard.count != count {
            return Err(format!(
                "{} belongs to a different sweep (grid, tasks or shard count differ)",
                d.display()
            ));
        }
    }
    Shard::check_cover(count, shards.iter().map(|(f, _, d)| (f.shard, d.as_path())))?;
    for (f, rows, d) in &shards {
        let expected: Vec<usize> = f.shard.indices(grid.len()).collect();
        if rows.iter().map(|r| r.index).ne(expected.iter().copied()) {
            return Err(format!(
                "{}: the rows are not those of shard {}/{count}",
                d.display(),
                f.shard.index
            ));
        }
    }
    let mut rows: Vec<(Row, &PathBuf)> =
        shards.iter().flat_map(|(_, rows, d)| rows.iter().map(move |r| (r.clone(), *d))).collect();
    rows.sort_by_key(|(r, _)| r.index);
    prepare_dir(out)?;
    for (r, d) in &rows {
        for rel in r.certificate.iter().chain(&r.refutation).chain(&r.orbit) {
            write(out.join(rel), &read(&d.join(rel))?)?;
        }
    }
    let rows: Vec<Row> = rows.into_iter().map(|(r, _)| r).collect();
    write(out.join(POINTS), &csv(&grid, &rows))?;
    let summary = Summary::new(&grid, &computed, &rows);
    write(out.join(SUMMARY), &summary.json())?;
    Ok(summary)
}

/// Reads a whole map's folder (points.csv and summary.json's grid), e.g. for plotting.
pub fn load(dir: &Path) -> Result<(Grid, Computed, Vec<Row>), String> {
    #[derive(Deserialize)]
    struct Head {
        grid: Grid,
        computed: Computed,
    }
    let path = dir.join(SUMMARY);
    let head: Head = serde_json::from_str(&read(&path)?).map_err(|e| format!("{}: {e}", path.display()))?;
    let rows =
        parse_csv(&read(&dir.join(POINTS))?).map_err(|e| format!("{}: {e}", dir.join(POINTS).display()))?;
    if rows.len() != head.grid.len() {
        return Err(format!(
            "{}: {} rows for a grid of {} points",
            dir.display(),
            rows.len(),
            head.grid.len()
        ));
    }
    Ok((head.grid, head.computed, rows))
}
