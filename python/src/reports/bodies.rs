//! `bodies`: the report `chatter.bodies/1` of `chatter bodies --json`
//! (`chatter::report::bodies::catalogue`).

use crate::fail::Fail;
use chatter::report;
use serde_json::Value;

/// Every body of the catalogue, with enclosures to `digits` decimal digits.
pub fn value(digits: usize) -> Result<Value, Fail> {
    if digits == 0 || digits > 60 {
        return Err(Fail::usage("invalid-input", "digits must be in 1..=60"));
    }
    let rep = report::bodies::catalogue(digits).map_err(|e| Fail::internal("internal", e))?;
    Ok(report::to_value(&rep))
}
