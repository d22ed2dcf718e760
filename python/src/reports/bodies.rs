//! `bodies`: the catalogue, the rows of `chatter bodies --json`.

use crate::fail::Fail;
use chatter::bodies::{self, Entry, Threshold, compare, kappa_f64};
use serde_json::{Value, json};

/// One body: kappa, exact thresholds in gamma, the paper's values and whether they agree.
fn row(e: &Entry, digits: usize) -> Value {
    let (cc, pcc) = bodies::thresholds(e, digits);
    let exact = |t: &Threshold| t.interval.clone().map_or(Value::Null, |[a, b]| json!([a, b]));
    let gmax = |t: &Threshold| match t.kind {
        "below" => json!(t.midpoint),
        "up-to-one" => json!(1.0),
        _ => Value::Null,
    };
    let cmp_cc = compare(e.paper_cc, &cc);
    let cmp_pcc = pcc.as_ref().and_then(|p| compare(e.paper_pcc, p));
    json!({
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
        "paper_agrees": {"cc": cmp_cc.as_ref().map(|c| c.agrees()), "pcc": cmp_pcc.as_ref().map(|c| c.agrees())},
        "paper_status": {"cc": cmp_cc.as_ref().map(|c| c.status), "pcc": cmp_pcc.as_ref().map(|c| c.status)},
    })
}

/// Every body of the catalogue, with enclosures to `digits` decimal digits.
pub fn value(digits: usize) -> Result<Value, Fail> {
    if digits == 0 || digits > 60 {
        return Err(Fail::usage("invalid-input", "digits must be in 1..=60"));
    }
    let entries = bodies::catalogue().map_err(|e| Fail::internal("internal", e))?;
    Ok(Value::Array(entries.iter().map(|e| row(e, digits)).collect()))
}
