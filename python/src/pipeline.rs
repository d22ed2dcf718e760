//! `certify`: the pipeline of `chatter certify` (chatter::certify), its result as JSON with the
//! certificate's RON text (the kernel's writer) and its JSON twin.

use crate::fail::Fail;
use crate::inputs;
use chatter::certify::{Failure, Report, Request, check_body};
use chatter::exact::Q;
use chatter::finder::Search;
use chatter_kernel::model::BodyError;
use serde_json::{Value, json};

/// kappa as an element of Q(cos 2 pi/n) in canonical text, as `chatter certify --kappa`.
fn field_kappa(n: u64, text: &str) -> Result<Option<(Q, String)>, Fail> {
    chatter::certify::field_kappa(n, text).map_err(|m| Fail::usage("invalid-number", format!("kappa: {m}")))
}

/// The request: validated as `chatter certify` does (every corner of a box is a valid body;
/// n = 5, 7, 8, ... in Q(cos 2 pi/n), where kappa may be an element of that field).
fn request(n: u64, kappa: &str, gamma: &str, claim: Option<&str>) -> Result<Request, Fail> {
    let field = field_kappa(n, kappa)?;
    let kappa = match &field {
        Some((k, _)) => [k.clone(), k.clone()],
        None => inputs::range("kappa", kappa)?,
    };
    let gamma = inputs::range("gamma", gamma)?;
    for (k, g) in [(&kappa[0], &gamma[0]), (&kappa[1], &gamma[1])] {
        if let Err(e) = check_body(n, k, g) {
            let code = match e {
                BodyError::UnsupportedN(_) => "unsupported-n",
                BodyError::KappaNotPositive => "kappa-not-positive",
                BodyError::GammaOutOfRange => "gamma-out-of-range",
            };
            return Err(Fail::usage(code, format!("invalid body: {e}")));
        }
    }
    let mut req = Request::boxed(n, kappa, gamma);
    req.kappa_field = field.map(|(_, text)| text);
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
        Failure::NoFamily { .. } => "no-family".into(),
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
        "ron": chatter::write::write(cert),
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
