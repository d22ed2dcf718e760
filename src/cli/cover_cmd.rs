//! `chatter cover`: a certified cover of the CC region of a box of parameters (issue 11 §3).

use super::map_cmd::{progress, with_jobs};
use super::{Outcome, emit, range};
use crate::cover::area::cc_area;
use crate::cover::{CoverRequest, CoverSummary, Leaf, Status, cover};
use crate::exact::Q;
use clap::Args;
use std::path::{Path, PathBuf};

/// Raw arguments of `chatter cover`.
#[derive(Args, Debug)]
#[command(
    after_help = "Subdivides the box [kappa] x [gamma] adaptively (halving in kappa, gamma or both, where the\n\
exact CC criterion changes) into boxes that are each certified (one box certificate, an all-down\n\
claim for every (kappa, gamma) of the box), refuted at their corners (exact refutations at\n\
points, where the CC criterion fails at every corner), or undecided: outside the CC region at\n\
every corner with a corner not refuted (such boxes are not split), or at the finest size along\n\
the axis it would be split (the strip at gamma = 0 is split in gamma only).\n\n\
Writes DIR/boxes.csv (every box), DIR/certificates/ and DIR/refutations/ (all re-checkable with\n\
`chatter verify DIR`), and DIR/summary.json: the certified area, the area of the exact CC region\n\
in the same box (from the spectral module's exact thresholds, integrated over kappa), their ratio,\n\
the undecided band, and every box that contradicts the exact CC criterion (findings about the\n\
paper's Conjecture 1). The files do not depend on --jobs.\n\n\
Example:\n  chatter cover --n 4 --kappa 1/100:1/4 --gamma 0:1/10 --out cover4"
)]
pub struct CoverArgs {
    /// Number of contacts: 3, 4 or 6 (or 2, the rod).
    #[arg(long, default_value = "4")]
    pub n: String,
    /// kappa's interval a:b (a > 0).
    #[arg(long, allow_hyphen_values = true)]
    pub kappa: String,
    /// gamma's interval c:d within [0, 1].
    #[arg(long, allow_hyphen_values = true)]
    pub gamma: String,
    /// Output folder (must be empty or absent).
    #[arg(long, short = 'o', default_value = "cover")]
    pub out: PathBuf,
    /// Worker threads (default: all cores).
    #[arg(long)]
    pub jobs: Option<usize>,
    /// Finest subdivision: halvings of kappa's interval.
    #[arg(long, default_value_t = 10)]
    pub kappa_depth: u32,
    /// Finest subdivision: halvings of gamma's interval.
    #[arg(long, default_value_t = 13)]
    pub gamma_depth: u32,
    /// Simpson intervals in kappa for the area of the exact CC region.
    #[arg(long, default_value_t = 256)]
    pub area_intervals: usize,
}

fn validate(a: &CoverArgs) -> Result<CoverRequest, String> {
    let n: u64 = a.n.trim().parse().map_err(|_| format!("--n: {:?} is not a number of contacts", a.n))?;
    if ![2, 3, 4, 6].contains(&n) {
        return Err(format!(
            "--n: {n} is not supported here: give n = 2, 3, 4 or 6 (box certificates need a rational cos 2π/n)"
        ));
    }
    let kappa = range("--kappa", &a.kappa)?;
    let gamma = range("--gamma", &a.gamma)?;
    if kappa[0] <= Q::int(0) || kappa[0] == kappa[1] {
        return Err("--kappa: a proper interval a:b with 0 < a < b".into());
    }
    if gamma[0] < Q::int(0) || gamma[1] > Q::int(1) || gamma[0] == gamma[1] {
        return Err("--gamma: a proper interval c:d within [0, 1]".into());
    }
    if a.kappa_depth > 24 || a.gamma_depth > 30 {
        return Err("--kappa-depth at most 24, --gamma-depth at most 30".into());
    }
    if a.jobs == Some(0) {
        return Err("--jobs: at least 1".into());
    }
    Ok(CoverRequest { n, kappa, gamma, max_depth: [a.kappa_depth, a.gamma_depth] })
}

/// The folder must be new or empty.
fn prepare(dir: &Path) -> Result<(), String> {
    if dir.exists() && std::fs::read_dir(dir).map_err(|e| e.to_string())?.next().is_some() {
        return Err(format!("{} is not empty: not overwriting it (choose another --out)", dir.display()));
    }
    std::fs::create_dir_all(dir.join("certificates")).map_err(|e| format!("{}: {e}", dir.display()))?;
    std::fs::create_dir_all(dir.join("refutations")).map_err(|e| format!("{}: {e}", dir.display()))
}

/// Writes boxes.csv, the certificates and the refutations (one file per refuted point).
fn write_leaves(dir: &Path, leaves: &[Leaf]) -> Result<(), String> {
    let w = |p: PathBuf, text: &str| std::fs::write(&p, text).map_err(|e| format!("{}: {e}", p.display()));
    let mut csv =
        String::from("index,kappa_lo,kappa_hi,gamma_lo,gamma_hi,status,claim,criterion_at_corners,file\n");
    let mut points = std::collections::BTreeMap::new();
    for (i, l) in leaves.iter().enumerate() {
        let (claim, file) = match &l.status {
            Status::Certified { claim, certificate } => {
                let file = format!("certificates/box-{i:05}.ron");
                w(dir.join(&file), &crate::write::write(certificate))?;
                (claim.name(), file)
            }
            Status::Refuted { refutations } => {
                for r in refutations {
                    let chatter_kernel::certificate::Body::RegularPolygon { kappa, gamma, .. } = &r.body;
                    points.insert(
                        (kappa.texts()[0].to_string(), gamma.texts()[0].to_string()),
                        crate::write::write_refutation(r),
                    );
                }
                ("", String::new())
            }
            Status::Undecided => ("", String::new()),
        };
        let crit: String = l.criterion.iter().map(|c| if *c { '1' } else { '0' }).collect();
        let c = &l.cell;
        csv.push_str(&format!(
            "{i},{},{},{},{},{},{claim},{crit},{file}\n",
            c.kappa[0],
            c.kappa[1],
            c.gamma[0],
            c.gamma[1],
            l.status.name()
        ));
    }
    for (k, ((kappa, gamma), text)) in points.iter().enumerate() {
        let _ = (kappa, gamma);
        w(dir.join(format!("refutations/point-{k:05}.ron")), text)?;
    }
    w(dir.join("boxes.csv"), &csv)
}

pub fn run(a: CoverArgs) -> Outcome {
    let req = match validate(&a) {
        Ok(r) => r,
        Err(e) => return Outcome::Usage(e),
    };
    if let Err(e) = prepare(&a.out) {
        return Outcome::Usage(e);
    }
    let start = std::time::Instant::now();
    let bar = progress(0, "boxes");
    let timings = crate::cover::Timings::default();
    let leaves = match with_jobs(a.jobs, || {
        cover(&req, &timings, &|k| {
            bar.set_length(k as u64);
            bar.set_position(k as u64);
        })
    }) {
        Ok(l) => l,
        Err(e) => return Outcome::Usage(e),
    };
    bar.finish_and_clear();
    let (area, error) = match with_jobs(a.jobs, || cc_area(req.n, &req.kappa, &req.gamma, a.area_intervals)) {
        Ok(x) => x,
        Err(e) => return Outcome::Usage(e),
    };
    let secs = start.elapsed().as_secs_f64();
    let summary = CoverSummary::new(&req, &leaves, area, error);
    let text = serde_json::to_string_pretty(&summary).expect("serialisable") + "\n";
    if let Err(e) = write_leaves(&a.out, &leaves)
        .and_then(|()| std::fs::write(a.out.join("summary.json"), &text).map_err(|e| e.to_string()))
    {
        return Outcome::Usage(e);
    }
    emit(&format!(
        "cover n={} kappa=[{}, {}] gamma=[{}, {}]: {} boxes ({} certified, {} refuted, {} undecided) in {secs:.1} s -> {}",
        req.n,
        req.kappa[0],
        req.kappa[1],
        req.gamma[0],
        req.gamma[1],
        leaves.len(),
        summary.boxes.certified,
        summary.boxes.refuted,
        summary.boxes.undecided,
        a.out.display()
    ));
    emit(&format!(
        "  certified area {:.6e}, CC region area {area:.6e} (± {error:.1e}), ratio {:.4}; undecided area {:.3e}, band height {:.3e}",
        summary.certified_area,
        summary.ratio.unwrap_or(f64::NAN),
        summary.undecided_area,
        summary.undecided_band_height
    ));
    let [tc, tb, tr] = timings.seconds();
    emit(&format!("  thread time: criterion {tc:.1} s, box certification {tb:.1} s, refutation {tr:.1} s"));
    let fails = &summary.findings.certified_where_criterion_fails;
    if !fails.is_empty() {
        emit(&format!(
            "  finding: {} certified boxes have a corner where the CC criterion fails (against Conjecture 1 (ii) => (iii)); see summary.json",
            fails.len()
        ));
    }
    Outcome::Success
}
