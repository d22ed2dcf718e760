//! `chatter plot`: the paper's figures from a map's folder or a certificate (SVG or PNG by the
//! file extension).

use super::{self as cli, emit};
use crate::exact::{Q, parse_user_number};
use crate::plot::basin::{BasinFigure, axis_index};
use crate::plot::cone::ConeFigure;
use crate::plot::cover::{CoverFigure, read_boxes, title as cover_title};
use crate::plot::map::{MapFigure, Panel, body_name};
use crate::plot::{CURVE_LINES, Format, save};
use crate::sweep::grid::Variable;
use crate::sweep::{self, curves};
use clap::{Args, Subcommand};
use std::path::{Path, PathBuf};

/// Raw arguments of `chatter plot`.
#[derive(Args, Debug)]
#[command(after_help = "Figures are SVG or PNG, chosen by the extension of -o. Text is set in DejaVu Sans \
(Debian: fonts-dejavu-core; or set CHATTER_FONT to a .ttf file).\n\n\
Examples:\n  chatter map --n 3 --rho 0:1:100 --gamma 0:1:100 --certify --out map3\n  \
chatter plot map map3 -o map3.png\n  \
chatter map --n 3 --rho 0:1:60 --gamma 0:0.3:60 --simulate 20 --out sim3\n  \
chatter plot simulations sim3 -o sim3.svg\n  \
chatter certify --n 4 --kappa 1/6 --gamma 1/100 -o square.ron && chatter plot cone square.ron -o cone.png\n  \
chatter cover --n 6 --kappa 1/100:8/100 --gamma 0:1 --out cover6 && chatter plot cover cover6 -o cover6.png")]
pub struct PlotArgs {
    #[command(subcommand)]
    pub what: PlotWhat,
}

#[derive(Subcommand, Debug)]
pub enum PlotWhat {
    /// A map panel (figure "sajatertekek", left): finder verdicts, exact eigenvalue curves, certified points.
    Map(MapPlotArgs),
    /// A simulation map (figure "simulations"): level curves of the mean impact count (needs map --simulate).
    Simulations(MapPlotArgs),
    /// A certificate on the plane v = -1: its cone(s), or an orbit certificate's set X (figure "sajatertekek", right).
    Cone(ConePlotArgs),
    /// A certified cover (`chatter cover`): the boxes by status, with the exact CC boundary.
    Cover(CoverPlotArgs),
    /// A slice of a basin certificate (`chatter basin`): its leaves by verdict (proved CC, proved
    /// ICC, undecided) over two drop coordinates; the file is re-checked by the kernel first.
    Basin(BasinPlotArgs),
    /// A basin map (`chatter basin-map`): per point, the certified shares of its box of drops.
    BasinMap(MapPlotArgs),
}

#[derive(Args, Debug)]
#[command(
    after_help = "Drop coordinates (the paper's, before the first impact): velocity (omega_x, omega_y, -1), \
position (phi_x, phi_y, h). The kernel re-checks the file on both backends before drawing (a file \
it rejects is refused, exit status 1); the title gives its exact shares of the whole box.\n\n\
Example:\n  chatter plot basin certificates/valid/basin-n3-kappa1_8-gamma3_20.ron --axes phi_x,h \
--at omega_x=0.0495 -o slice.png"
)]
pub struct BasinPlotArgs {
    /// A basin certificate (RON).
    #[arg(value_name = "FILE")]
    pub cert: PathBuf,
    /// The two coordinates drawn, horizontal then vertical: two of omega_x, omega_y, phi_x, phi_y, h.
    #[arg(long, default_value = "omega_x,omega_y")]
    pub axes: String,
    /// Where a coordinate not drawn is fixed, NAME=VALUE (exact: 1/20, 0.05), repeatable;
    /// the others at the box's centre.
    #[arg(long, value_name = "NAME=VALUE")]
    pub at: Vec<String>,
    /// Output file: .svg or .png.
    #[arg(short = 'o', long = "out", value_name = "FILE")]
    pub out: PathBuf,
}

/// Why `plot basin` drew nothing: bad input (exit 2), a file the kernel rejects (exit 1), or
/// the backends disagree (exit 3).
enum BasinPlotError {
    Usage(String),
    Rejected(String),
    Disagree(String),
}

/// The slice figure of a basin certificate, after the kernel accepted it on both backends.
fn basin_figure(a: &BasinPlotArgs) -> Result<BasinFigure, BasinPlotError> {
    use BasinPlotError::{Disagree, Rejected, Usage};
    use chatter_kernel::verify::{Verdict, verify_basin};
    let axes: Vec<usize> = a
        .axes
        .split(',')
        .map(axis_index)
        .collect::<Result<_, _>>()
        .map_err(|e| Usage(format!("--axes: {e}")))?;
    let axes: [usize; 2] =
        axes.try_into().map_err(|_| Usage("--axes: give two coordinates, e.g. omega_x,h".into()))?;
    let mut at: [Option<Q>; 5] = Default::default();
    for s in &a.at {
        let (name, value) =
            s.split_once('=').ok_or_else(|| Usage(format!("--at {s:?}: write NAME=VALUE")))?;
        let k = axis_index(name).map_err(|e| Usage(format!("--at: {e}")))?;
        if axes.contains(&k) {
            return Err(Usage(format!("--at {name}: it is drawn (--axes {})", a.axes)));
        }
        at[k] = Some(parse_user_number(value.trim()).map_err(|e| Usage(format!("--at {name}: {e}")))?);
    }
    let text = std::fs::read_to_string(&a.cert).map_err(|e| Usage(format!("{}: {e}", a.cert.display())))?;
    let cert = chatter_kernel::syntax::read(&text, chatter_kernel::syntax::Encoding::Ron)
        .map_err(|r| Rejected(format!("{}: REJECTED by the kernel: {r}", a.cert.display())))?;
    let report = match verify_basin(&cert, Default::default(), &cli::Env::default().backends) {
        Verdict::Accepted(r) => r,
        Verdict::Rejected(r) => {
            return Err(Rejected(format!("{}: REJECTED by the kernel: {r}", a.cert.display())));
        }
        Verdict::Disagree(s) => {
            return Err(Disagree(format!("{}: the kernel's backends disagree: {s}", a.cert.display())));
        }
    };
    BasinFigure::new(&cert, &report, axes, &at).map_err(Usage)
}

#[derive(Args, Debug)]
pub struct CoverPlotArgs {
    /// A folder written by `chatter cover`.
    #[arg(value_name = "DIR")]
    pub dir: PathBuf,
    /// Output file: .svg or .png.
    #[arg(short = 'o', long = "out", value_name = "FILE")]
    pub out: PathBuf,
}

/// The cover figure of a folder: boxes.csv, and the request and ratio from summary.json.
pub fn cover_figure(dir: &Path) -> Result<CoverFigure, String> {
    let path = dir.join("summary.json");
    let text = std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    let s: serde_json::Value = serde_json::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))?;
    if s["schema"] != "chatter.cover/1" {
        return Err(format!("{}: not the summary of chatter cover (schema chatter.cover/1)", path.display()));
    }
    let pair = |key: &str| -> Result<[Q; 2], String> {
        let bad = || format!("{}: {key} must be two exact numbers", path.display());
        let a = s[key].as_array().filter(|a| a.len() == 2).ok_or_else(bad)?;
        let q = |v: &serde_json::Value| v.as_str().and_then(|t| t.parse::<Q>().ok()).ok_or_else(bad);
        Ok([q(&a[0])?, q(&a[1])?])
    };
    let (kappa, gamma) = (pair("kappa")?, pair("gamma")?);
    let n =
        s["n"].as_u64().filter(|n| [2, 3, 4, 6].contains(n)).ok_or(format!("{}: bad n", path.display()))?;
    let boxes = read_boxes(dir)?;
    let curves =
        curves::curves(n, Variable::Kappa, (&kappa[0], &kappa[1]), (&gamma[0], &gamma[1]), CURVE_LINES);
    Ok(CoverFigure { n, kappa, gamma, boxes, curves, title: cover_title(n, s["ratio"].as_f64()) })
}

#[derive(Args, Debug)]
pub struct MapPlotArgs {
    /// A folder written by `chatter map` (or `chatter map merge`).
    #[arg(value_name = "DIR")]
    pub dir: PathBuf,
    /// Output file: .svg or .png.
    #[arg(short = 'o', long = "out", value_name = "FILE")]
    pub out: PathBuf,
    /// Columns and rows of the map along which the exact curves are computed (each crossing
    /// exact; the drawn curve joins them): fewer draw faster and coarser (`chatter reproduce
    /// --quick` draws with 48).
    #[arg(long = "curve-lines", value_name = "N", default_value_t = CURVE_LINES,
        value_parser = clap::value_parser!(u32).range(2..=2000))]
    pub curve_lines: u32,
}

#[derive(Args, Debug)]
pub struct ConePlotArgs {
    /// A certificate (RON or JSON) of any version: a regular polygon (n = 3 to 64), a general body
    /// (one panel per contact) or an orbit certificate (its set X projected).
    #[arg(value_name = "CERT")]
    pub cert: PathBuf,
    /// Output file: .svg or .png.
    #[arg(short = 'o', long = "out", value_name = "FILE")]
    pub out: PathBuf,
}

/// The map figure of a folder.
pub fn map_figure(dir: &Path, panel: Panel, lines: u32) -> Result<MapFigure, String> {
    let (grid, computed, rows) = sweep::load(dir)?;
    if panel == Panel::Simulations && computed.simulate == 0 {
        return Err(format!(
            "{}: the map has no simulations (run chatter map with --simulate RUNS)",
            dir.display()
        ));
    }
    let curves = match &grid.family {
        Some(f) => crate::sweep::family::curves(f, &grid.x, &grid.gamma, lines),
        None => curves::curves(
            grid.n,
            grid.variable,
            (&grid.x.lo, &grid.x.hi),
            (&grid.gamma.lo, &grid.gamma.hi),
            lines,
        ),
    };
    let what = match (panel, &grid.family) {
        (Panel::Cones, None) => "cone finder and exact eigenvalue curves".to_string(),
        (Panel::Cones, Some(_)) => "family finder and certificates".to_string(),
        (Panel::Simulations, _) => {
            crate::plot::simulations::title_of(computed.simulate, computed.proof_budget)
        }
    };
    let title = match &grid.family {
        Some(f) => format!("{}: {what}", f.title()),
        None => format!("n = {} ({}): {what}", grid.n, body_name(grid.n)),
    };
    Ok(MapFigure { grid, rows, curves, panel, title, points: Vec::new() })
}

fn run_inner(a: PlotArgs) -> Result<String, String> {
    match a.what {
        PlotWhat::Map(m) | PlotWhat::Simulations(m) if Format::of(&m.out).is_err() => {
            Format::of(&m.out).map(|_| String::new())
        }
        PlotWhat::Map(m) => {
            save(&map_figure(&m.dir, Panel::Cones, m.curve_lines)?, &m.out)?;
            Ok(format!("wrote {}", m.out.display()))
        }
        PlotWhat::Simulations(m) => {
            save(&map_figure(&m.dir, Panel::Simulations, m.curve_lines)?, &m.out)?;
            Ok(format!("wrote {}", m.out.display()))
        }
        PlotWhat::Cover(c) => {
            Format::of(&c.out)?;
            save(&cover_figure(&c.dir)?, &c.out)?;
            Ok(format!("wrote {}", c.out.display()))
        }
        PlotWhat::Basin(_) => Err("plot basin is run by run()".into()),
        PlotWhat::BasinMap(m) => {
            Format::of(&m.out)?;
            save(&crate::plot::basin_map::read(&m.dir, m.curve_lines)?, &m.out)?;
            Ok(format!("wrote {}", m.out.display()))
        }
        PlotWhat::Cone(c) => {
            Format::of(&c.out)?;
            let text = std::fs::read_to_string(&c.cert).map_err(|e| format!("{}: {e}", c.cert.display()))?;
            let fig =
                ConeFigure::from_certificate(&text).map_err(|e| format!("{}: {e}", c.cert.display()))?;
            save(&fig, &c.out)?;
            Ok(format!("wrote {}", c.out.display()))
        }
    }
}

pub fn run(a: PlotArgs) -> cli::Outcome {
    if let PlotWhat::Basin(b) = &a.what {
        return run_basin(b);
    }
    match run_inner(a) {
        Ok(line) => {
            emit(&line);
            cli::Outcome::Success
        }
        Err(e) => cli::Outcome::Usage(e),
    }
}

/// `chatter plot basin`: refuses a file the kernel rejects (exit status 1).
fn run_basin(b: &BasinPlotArgs) -> cli::Outcome {
    if let Err(e) = Format::of(&b.out) {
        return cli::Outcome::Usage(e);
    }
    match basin_figure(b) {
        Ok(fig) => match save(&fig, &b.out) {
            Ok(()) => {
                emit(&format!(
                    "wrote {} ({} leaves in the slice; {})",
                    b.out.display(),
                    fig.rects.len(),
                    fig.title
                ));
                cli::Outcome::Success
            }
            Err(e) => cli::Outcome::Usage(e),
        },
        Err(BasinPlotError::Usage(e)) => cli::Outcome::Usage(e),
        Err(BasinPlotError::Disagree(e)) => cli::Outcome::Internal(e),
        Err(BasinPlotError::Rejected(e)) => {
            emit(&e);
            cli::Outcome::Negative
        }
    }
}
