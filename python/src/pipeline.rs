//! `certify`: the pipeline of `chatter certify` (chatter::certify), its result as JSON with the
//! certificate's RON text (the kernel's writer) and its JSON twin.

use crate::fail::Fail;
use crate::inputs;
use chatter::certify::{Failure, Report, Request};
use chatter::finder::Search;
use chatter_kernel::model::{BodyError, Shape};
use serde_json::{Value, json};

/// The request: validated as `chatter certify` does (every corner of a box is a valid body).
fn request(n: u64, kappa: &str, gamma: &str, claim: Option<&str>) -> Result<Request, Fail> {
    let kappa = inputs::range("kappa", kappa)?;
    let gamma = inputs::range("gamma", gamma)?;
    for (k, g) in [(&kappa[0], &gamma[0]), (&kappa[1], &gamma[1])] {
        if let Err(e) = Shape::new(n, k.clone(), g.clone()) {
            let code = match e {
                BodyError::UnsupportedN(_) => "unsupported-n",
                BodyError::KappaNotPositive => "kappa-not-positive",
                BodyError::GammaOutOfRange => "gamma-out-of-range",
            };
            return Err(Fail::usage(code, format!("invalid body: {e}")));
        }
    }
    let mut req = Request::boxed(n, kappa, gamma);
    req.claim = inputs::claim(claim)?;
    Ok(req)
}

/// The rejection code of a failure to certify (the kernel's code when the kernel rejected).
fn code(f: &Failure) -> String {
    match f {
        Failure::Body(_) => "invalid-body".into(),
        Failure::PccNotExcluded(_) => "pcc-not-excluded".into(),
        Failure::GammaOutOfRange(_) => "gamma-out-of-range".into(),
        Failure::SeedNotBelow { .. } => "seed-not-below".into(),
        Failure::Finder(Search::NoCone { .. }) => "no-cone".into(),
        Failure::Finder(_) => "inconclusive".into(),
        Failure::Exactify(_) => "exactify-failed".into(),
        Failure::Kernel(r) => r.code.as_str().into(),
        Failure::Internal(_) => "internal".into(),
    }
}

fn ms(d: std::time::Duration) -> f64 {
    d.as_secs_f64() * 1e3
}

/// The certificate and how it was made, or the failure as an exception.
fn result(report: Report) -> Result<Value, Fail> {
    let cert = match &report.result {
        Ok(c) => c,
        Err(f @ Failure::Internal(_)) => return Err(Fail::internal("internal", f.to_string())),
        Err(f) => {
            let notes: String = report.notes.iter().map(|n| format!("; note: {n}")).collect();
            return Err(Fail::negative(&code(f), format!("not certified: {f}{notes}")));
        }
    };
    let t = &report.timings;
    Ok(json!({
        "ron": chatter_kernel::certificate::write(cert),
        "json": chatter::convert::certificate_to_json(cert),
        "method": report.method,
        "max_denominator_bits": report.max_denominator_bits,
        "notes": report.notes,
        "timings_ms": {"finder": ms(t.finder), "exactify": ms(t.exactify), "kernel": ms(t.kernel)},
    }))
}

/// Certifies (n, kappa, gamma) for `claim` (strongest by default).
pub fn certify(n: u64, kappa: &str, gamma: &str, claim: Option<&str>) -> Result<Value, Fail> {
    let req = request(n, kappa, gamma, claim)?;
    result(chatter::certify::certify(&req))
}
