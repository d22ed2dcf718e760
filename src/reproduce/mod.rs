//! `chatter reproduce`: the paper's results regenerated into one folder, each beside the
//! paper's claim with "agrees" or "differs" and its evidence ([`items`]), written as report.md
//! and report.html ([`report`]) with the figures (SVG and PNG).

pub mod band_grid;
pub mod items;
pub mod report;
pub mod time_to_rest;

use std::path::{Path, PathBuf};

/// How a result compares with the paper.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    Agrees,
    Differs,
    /// Not decidable with this version (e.g. pentagon certificates).
    NotChecked,
}

impl Verdict {
    pub fn word(self) -> &'static str {
        match self {
            Verdict::Agrees => "agrees",
            Verdict::Differs => "differs",
            Verdict::NotChecked => "not checked yet",
        }
    }

    /// Agrees exactly when `ok`.
    pub fn of(ok: bool) -> Verdict {
        if ok { Verdict::Agrees } else { Verdict::Differs }
    }
}

/// A figure of the report: its name (files NAME.svg and NAME.png under figures/) and caption.
#[derive(Clone, Debug)]
pub struct FigureRef {
    pub name: String,
    pub caption: String,
}

/// One result beside the paper's claim.
#[derive(Clone, Debug)]
pub struct Item {
    pub title: String,
    /// What the paper says (with its section or figure).
    pub paper: String,
    /// What we find.
    pub ours: String,
    pub verdict: Verdict,
    /// Evidence lines (numbers, files).
    pub evidence: Vec<String>,
    /// Commands that show the evidence.
    pub commands: Vec<String>,
    pub figures: Vec<FigureRef>,
}

/// A table of the report (header and rows).
#[derive(Clone, Debug, Default)]
pub struct Table {
    pub title: String,
    pub header: Vec<String>,
    pub rows: Vec<Vec<String>>,
}

/// Everything `chatter reproduce` produced.
#[derive(Clone, Debug, Default)]
pub struct Report {
    pub quick: bool,
    /// The folder the report is written to, as given (`--out`): its commands run from there.
    pub folder: String,
    pub tables: Vec<Table>,
    pub items: Vec<Item>,
    /// (step, seconds) for the record.
    pub timings: Vec<(String, f64)>,
}

/// The sizes of a run.
#[derive(Clone, Copy, Debug)]
pub struct Plan {
    pub quick: bool,
    /// Grid steps per axis of the maps of n = 3, 4 (with certificates) and n = 5.
    pub grid: u32,
    pub grid5: u32,
    /// Random drops per grid point.
    pub drops: u64,
    /// Columns and rows of the exact curves.
    pub curve_lines: u32,
    /// Random drops at the single parameter points.
    pub point_drops: u64,
    /// Random points of the square proof's numerical cross-check.
    pub cross_check: usize,
}

impl Plan {
    pub fn new(quick: bool) -> Plan {
        if quick {
            Plan { quick, grid: 16, grid5: 12, drops: 6, curve_lines: 48, point_drops: 40, cross_check: 10 }
        } else {
            Plan {
                quick,
                grid: 100,
                grid5: 80,
                drops: 20,
                curve_lines: 200,
                point_drops: 100,
                cross_check: 100,
            }
        }
    }
}

/// How a `chatter map` command line is read, as the command line reads it
/// (`cli::map_cmd::request_of`): each map of the report is made from the command it cites.
pub type MapReader = fn(&str) -> Result<crate::sweep::Request, String>;

/// Runs every step into `out`, the maps as `read_map` reads their commands; `step` is told the
/// name of each step as it starts.
pub fn run(out: &Path, plan: Plan, read_map: MapReader, step: &dyn Fn(&str)) -> Result<Report, String> {
    for d in ["figures", "certificates", "maps", "proofs"] {
        let p = out.join(d);
        std::fs::create_dir_all(&p).map_err(|e| format!("cannot create {}: {e}", p.display()))?;
    }
    let folder = out.display().to_string();
    let mut report = Report { quick: plan.quick, folder, ..Default::default() };
    let mut timed =
        |name: &str, f: &mut dyn FnMut(&mut Report) -> Result<(), String>| -> Result<(), String> {
            step(name);
            let start = std::time::Instant::now();
            let mut r = std::mem::take(&mut report);
            let result = f(&mut r);
            r.timings.push((name.to_string(), start.elapsed().as_secs_f64()));
            report = r;
            result
        };
    let ctx = items::Context { out: out.to_path_buf(), plan, read_map };
    timed("bodies", &mut |r| items::bodies(&ctx, r))?;
    timed("rod", &mut |r| items::rod(&ctx, r))?;
    timed("triangle plate", &mut |r| items::triangle(&ctx, r))?;
    timed("PCC for n >= 4", &mut |r| items::pcc_n4(&ctx, r))?;
    timed("n = 3 band", &mut |r| items::band(&ctx, r))?;
    timed("n = 3 band across kappa", &mut |r| band_grid::band_grid(&ctx, r))?;
    for n in [3, 4, 5] {
        timed(&format!("map n = {n}"), &mut |r| items::map(&ctx, n, r))?;
    }
    timed("certificates", &mut |r| items::certificates(&ctx, r))?;
    timed("square proof", &mut |r| items::square(&ctx, r))?;
    timed("time to rest", &mut |r| time_to_rest::time_to_rest(&ctx, r))?;
    report::write(out, &report)?;
    Ok(report)
}

/// The path of a figure file.
pub fn figure_path(out: &Path, name: &str, ext: &str) -> PathBuf {
    out.join("figures").join(format!("{name}.{ext}"))
}
