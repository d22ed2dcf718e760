//! `classify`: the report `chatter.classify/1` of `chatter classify --json`
//! (`chatter::report::classify`).

use crate::fail::Fail;
use crate::inputs;
use chatter::report::{self, classify::ClassifyRequest};
use serde_json::Value;

/// The arguments as the package passes them.
pub struct Args {
    pub n: u64,
    pub kappa: String,
    pub gamma: String,
    pub velocity: Option<Vec<String>>,
    pub digits: usize,
}

/// The request, checked as the command line checks it; a bad value raises `UsageError` with
/// the code of its argument.
fn request(a: &Args) -> Result<ClassifyRequest, Fail> {
    let (kappa, gamma) = (inputs::number("kappa", &a.kappa)?, inputs::number("gamma", &a.gamma)?);
    let mut r = ClassifyRequest::new(a.n, kappa, gamma);
    r.digits = a.digits;
    if let Some(v) = &a.velocity {
        r.velocity = match inputs::numbers("velocity", v)?.as_slice() {
            [u0, u1] => Some([u0.clone(), u1.clone()]),
            _ => {
                let msg = format!("velocity: expected (u0, u1), got {} numbers", v.len());
                return Err(Fail::usage("invalid-input", msg));
            }
        };
    }
    r.validate().map_err(|e| {
        let code = match e.split_once(':').map(|(flag, _)| flag) {
            Some("--kappa") => "kappa-not-positive",
            Some("--gamma") => "gamma-out-of-range",
            _ => "invalid-input",
        };
        Fail::usage(code, e.replace("--", ""))
    })?;
    Ok(r)
}

/// Every exact criterion at one body, with its evidence, thresholds, the finder, simulated
/// drops and whether a certificate can be made.
pub fn value(a: &Args) -> Result<Value, Fail> {
    let r = request(a)?;
    let rep = report::classify::classify(&r).map_err(|e| Fail::usage("invalid-input", e))?;
    Ok(report::to_value(&rep))
}
