//! `chatter bodies`: the catalogue of bodies with exact thresholds in gamma.

use super::{Outcome, emit};
use crate::bodies::{self, Entry, PaperValue, Threshold, compare, kappa_decimal, kappa_f64};
use crate::exact::{Q, Ring, parse_user_number};
use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use serde_json::{Value, json};

/// Raw arguments of `chatter bodies`.
#[derive(Args, Debug)]
#[command(
    after_help = "For each body: kappa derived from its geometry (exact), and the values of gamma below which\n\
the CC criterion (S_1 has a real positive dominant eigenvalue) and the PCC criterion (all\n\
eigenvalues of S_(n-1) S_1 real) hold, as guaranteed enclosures; for the rod, Goyal's threshold.\n\
The paper's stated values are printed beside ours and disagreements are flagged.\n\n\
Extra bodies: --n N --kappa K, --plate N, --prism N --height H (circumradius 1)."
)]
pub struct BodiesArgs {
    /// Print a JSON array.
    #[arg(long)]
    pub json: bool,
    /// Decimal digits of the enclosures.
    #[arg(long, default_value_t = 12)]
    pub digits: usize,
    /// Add a body with this many contacts (with --kappa).
    #[arg(long)]
    pub n: Option<u64>,
    /// kappa of the body given with --n.
    #[arg(long, allow_hyphen_values = true)]
    pub kappa: Option<String>,
    /// Add the flat plate of a regular polygon with this many vertices.
    #[arg(long)]
    pub plate: Option<usize>,
    /// Add the prism over a regular polygon with this many vertices (with --height).
    #[arg(long)]
    pub prism: Option<usize>,
    /// Height of the prism, in units of the polygon's circumradius.
    #[arg(long, allow_hyphen_values = true)]
    pub height: Option<String>,
    /// Only the bodies given on the command line, not the catalogue.
    #[arg(long)]
    pub only: bool,
}

fn validate(a: &BodiesArgs) -> Result<Vec<Entry>, String> {
    if a.digits == 0 || a.digits > 60 {
        return Err("--digits must be in 1..=60".into());
    }
    let mut extra = Vec::new();
    match (a.n, &a.kappa) {
        (Some(n), Some(k)) => {
            let k = parse_user_number(k).map_err(|e| format!("--kappa: {e}"))?;
            extra.push(bodies::user(n, &k).map_err(|e| format!("--n/--kappa: {e}"))?);
        }
        (None, None) => {}
        _ => return Err("--n and --kappa go together".into()),
    }
    if let Some(n) = a.plate {
        extra.push(bodies::prism(n, &Q::int(0)).map_err(|e| format!("--plate: {e}"))?);
    }
    match (a.prism, &a.height) {
        (Some(n), Some(h)) => {
            let h = parse_user_number(h).map_err(|e| format!("--height: {e}"))?;
            if h.is_negative() {
                return Err("--height must be >= 0".into());
            }
            extra.push(bodies::prism(n, &h).map_err(|e| format!("--prism: {e}"))?);
        }
        (None, None) => {}
        _ => return Err("--prism and --height go together".into()),
    }
    if a.only && extra.is_empty() {
        return Err("--only needs a body (--n/--kappa, --plate or --prism/--height)".into());
    }
    let mut all = if a.only { Vec::new() } else { bodies::catalogue()? };
    all.extend(extra);
    Ok(all)
}

fn paper_text(p: &Option<PaperValue>) -> String {
    match p {
        None => "-".into(),
        Some(PaperValue::Never) => "never".into(),
        Some(PaperValue::Below { value, decimals }) => format!("< {value:.*}", *decimals as usize),
    }
}

fn ours_text(t: &Threshold) -> String {
    match (t.kind, &t.decimal) {
        ("below", Some([lo, hi])) => format!("< [{lo}, {hi}]"),
        ("up-to-one", _) => "all gamma".into(),
        _ => "never".into(),
    }
}

fn row(e: &Entry, digits: usize) -> (Value, Vec<String>) {
    let (cc, pcc) = bodies::thresholds(e, digits);
    let exact = |t: &Threshold| t.interval.clone().map(|[a, b]| json!([a, b])).unwrap_or(Value::Null);
    let gmax = |t: &Threshold| match t.kind {
        "below" => json!(t.midpoint),
        "up-to-one" => json!(1.0),
        _ => Value::Null,
    };
    let cmp_cc = compare(e.paper_cc, &cc);
    let cmp_pcc = pcc.as_ref().and_then(|p| compare(e.paper_pcc, p));
    let mut obj = json!({
        "name": e.name,
        "n": e.n,
        "kappa": e.kappa_text(),
        "kappa_f64": kappa_f64(e),
        "cc_gamma_max": gmax(&cc),
        "pcc_gamma_max": pcc.as_ref().map_or(Value::Null, gmax),
        "cc_gamma_interval": exact(&cc),
        "pcc_gamma_interval": pcc.as_ref().map_or(Value::Null, exact),
        "cc": cc,
        "pcc": pcc,
        "kappa_derivation": e.derivation,
        "paper": {"cc": e.paper_cc, "pcc": e.paper_pcc},
    });
    obj["certificate_kappa"] = json!(e.certificate_kappa());
    obj["paper_agrees"] =
        json!({"cc": cmp_cc.as_ref().map(|c| c.agrees()), "pcc": cmp_pcc.as_ref().map(|c| c.agrees())});
    obj["paper_status"] =
        json!({"cc": cmp_cc.as_ref().map(|c| c.status), "pcc": cmp_pcc.as_ref().map(|c| c.status)});
    let flag = |c: &Option<bodies::Comparison>| match c.as_ref().map(|c| c.status) {
        Some("agrees") => " (agrees)",
        Some("close") => " (close: within 5%, outside the paper's rounding)",
        Some(_) => " (DISAGREES)",
        None => "",
    };
    let pcc_text = pcc.as_ref().map_or("n/a (two contacts)".to_string(), ours_text);
    let mut lines = vec![
        format!("{} (n = {}, kappa = {} = {})", e.name, e.n, e.kappa_text(), kappa_decimal(e, 6)),
        format!(
            "  CC  criterion: {:<36} paper: {}{}",
            ours_text(&cc),
            paper_text(&e.paper_cc),
            flag(&cmp_cc)
        ),
        format!("  PCC criterion: {:<36} paper: {}{}", pcc_text, paper_text(&e.paper_pcc), flag(&cmp_pcc)),
    ];
    if let Some(p) = &cc.polynomial {
        lines.push(format!("  CC threshold is a root of {p}"));
    }
    if let Some(p) = pcc.as_ref().and_then(|p| p.polynomial.clone()) {
        lines.push(format!("  PCC threshold is a root of {p}"));
    }
    lines.push(format!("  decided {}; kappa by {}", cc.method, e.derivation));
    lines.push(certificates_line(e));
    (obj, lines)
}

/// Whether certificates can be made for the body, and how.
fn certificates_line(e: &Entry) -> String {
    match (e.certificate_kappa(), e.why_not_certifiable()) {
        (Some(k), _) if e.kappa.as_rational().is_none() => format!(
            "  certificates: kappa = \"{k}\" in Q(c), c = cos(2 pi/{}): chatter certify --body '{}' --gamma G",
            e.n, e.name
        ),
        (Some(_), _) => format!("  certificates: chatter certify --body '{}' --gamma G", e.name),
        (None, why) => format!("  certificates: none ({})", why.unwrap_or_default()),
    }
}

pub fn run(a: BodiesArgs) -> Outcome {
    let entries = match validate(&a) {
        Ok(e) => e,
        Err(e) => return Outcome::Usage(e.to_string()),
    };
    let bar = ProgressBar::new(entries.len() as u64);
    bar.set_style(ProgressStyle::with_template("{bar:30} {pos}/{len} bodies").expect("valid template"));
    let rows: Vec<(Value, Vec<String>)> = entries
        .par_iter()
        .map(|e| {
            let r = row(e, a.digits);
            bar.inc(1);
            r
        })
        .collect();
    bar.finish_and_clear();
    if a.json {
        emit(&Value::Array(rows.into_iter().map(|(o, _)| o).collect()).to_string());
    } else {
        for (_, lines) in rows {
            for l in lines {
                emit(&l);
            }
        }
    }
    Outcome::Success
}
