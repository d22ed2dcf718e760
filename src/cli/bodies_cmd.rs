//! `chatter bodies`: the catalogue of bodies with exact thresholds in gamma.

use super::{Outcome, emit, emit_report};
use crate::bodies::{self, Entry};
use crate::exact::{Q, Ring, parse_user_number};
use crate::report::bodies::{BodyRow, GeneralBodyRow, bodies, general_rows};
use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};

/// Raw arguments of `chatter bodies`.
#[derive(Args, Debug)]
#[command(
    after_help = "For each body: kappa derived from its geometry (exact), and the values of gamma below which\n\
the CC criterion (S_1 has a real positive dominant eigenvalue) and the PCC criterion (all\n\
eigenvalues of S_(n-1) S_1 real) hold, as guaranteed enclosures; for the rod, Goyal's threshold.\n\
The paper's stated values are printed beside ours and disagreements are flagged.\n\n\
Extra bodies: --n N --kappa K, --plate N, --prism N --height H (circumradius 1).\n\n\
After them, the general convex bodies (phone, brick, table, lander; docs/bodies.md): contacts,\n\
J and derivation, without gamma (classify them with --body NAME --gamma G)."
)]
pub struct BodiesArgs {
    /// Print one JSON object (schema chatter.bodies/1, docs/json.md).
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
        return Err(format!("--digits: {} is not accepted: give 1 to 60", a.digits));
    }
    let mut extra = Vec::new();
    match (a.n, &a.kappa) {
        (Some(n), Some(k)) => {
            let k = parse_user_number(k).map_err(|e| format!("--kappa: {e}"))?;
            extra.push(bodies::user(n, &k).map_err(|e| format!("--n/--kappa: {e}"))?);
        }
        (None, None) => {}
        _ => return Err("--n and --kappa go together: give both (e.g. --n 5 --kappa 1/8) or neither".into()),
    }
    if let Some(n) = a.plate {
        extra.push(bodies::prism(n, &Q::int(0)).map_err(|e| format!("--plate: {e}"))?);
    }
    match (a.prism, &a.height) {
        (Some(n), Some(h)) => {
            let h = parse_user_number(h).map_err(|e| format!("--height: {e}"))?;
            if h.is_negative() {
                return Err(format!("--height: {h} is not accepted: the height must be >= 0"));
            }
            extra.push(bodies::prism(n, &h).map_err(|e| format!("--prism: {e}"))?);
        }
        (None, None) => {}
        _ => {
            return Err(
                "--prism and --height go together: give both (e.g. --prism 4 --height 1/2) or neither".into(),
            );
        }
    }
    if a.only && extra.is_empty() {
        return Err("--only needs a body (--n/--kappa, --plate or --prism/--height)".into());
    }
    let mut all = if a.only { Vec::new() } else { bodies::catalogue()? };
    all.extend(extra);
    Ok(all)
}

pub fn run(a: BodiesArgs) -> Outcome {
    let entries = match validate(&a) {
        Ok(e) => e,
        Err(e) => return Outcome::Usage(e.to_string()),
    };
    let general = if a.only { Ok(Vec::new()) } else { general_rows() };
    let general = match general {
        Ok(g) => g,
        Err(e) => return Outcome::Internal(e),
    };
    let bar = ProgressBar::new(entries.len() as u64);
    bar.set_style(ProgressStyle::with_template("{bar:30} {pos}/{len} bodies").expect("valid template"));
    let mut report = bodies(&entries, a.digits, &|| bar.inc(1));
    bar.finish_and_clear();
    report.general = general;
    if a.json {
        emit_report(&report);
    } else {
        report.bodies.iter().flat_map(BodyRow::lines).for_each(|l| emit(&l));
        report.general.iter().flat_map(GeneralBodyRow::lines).for_each(|l| emit(&l));
    }
    Outcome::Success
}
