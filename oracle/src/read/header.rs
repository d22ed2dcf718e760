//! The header of a file (docs/certificate-format.md §2: `format` and `version` are read first,
//! other fields tolerated), and which reader the file goes to.

use super::Value;
use super::schema::{integer, record, string};
use crate::verdict::{Checked, Fail};

/// `format` of cone certificates (and the legacy headers of versions 4 and 5).
pub const CERTIFICATE: &str = "chatter-certificate";
/// `format` of family certificates of general convex bodies (§13).
pub const FAMILY: &str = "chatter-family-certificate";
/// `format` of orbit certificates (§14).
pub const ORBIT: &str = "chatter-orbit-certificate";
/// `format` of refutations (§10).
pub const REFUTATION: &str = "chatter-refutation";

/// Which reader a file goes to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reader {
    /// Cone certificates of regular polygons, versions 1 to 3 (§2-§9, §12).
    Cone(u64),
    /// General convex bodies, version 4 (§13).
    Family,
    /// Orbit certificates, version 5 (§14).
    Orbit,
    /// Refutations, version 1 (§10).
    Refutation,
}

/// Reads `format` and `version` and picks the reader. The top-level struct's name, when written,
/// must be `Certificate` for certificates and `Refutation` for refutations.
pub fn header(v: &Value) -> Checked<Reader> {
    let (mut format, mut version) = (None, None);
    for (name, value) in record(v)? {
        let slot_is_set = match name.as_str() {
            "format" => format.replace(string(value)?).is_some(),
            "version" => version.replace(integer(value)?).is_some(),
            _ => false,
        };
        if slot_is_set {
            return Err(Fail::new("duplicate-field", format!("duplicate field `{name}`")));
        }
    }
    let refutation = format == Some(REFUTATION);
    let expected_name = if refutation { "Refutation" } else { "Certificate" };
    if let Value::Named { name, .. } = v
        && !name.is_empty()
        && name != expected_name
    {
        return Err(Fail::new("syntax", format!("expected struct `{expected_name}`, found `{name}`")));
    }
    let format = format.ok_or_else(|| Fail::new("missing-field", "missing field `format`"))?;
    if ![CERTIFICATE, FAMILY, ORBIT, REFUTATION].contains(&format) {
        return Err(Fail::new("wrong-format", format!("format {format:?}")));
    }
    let version = version.ok_or_else(|| Fail::new("missing-field", "missing field `version`"))?;
    // docs/certificate-format.md's header table, with the two legacy aliases of version 4 and 5.
    match (format, version) {
        (REFUTATION, 1) => Ok(Reader::Refutation),
        (CERTIFICATE, 1..=3) => Ok(Reader::Cone(version)),
        (CERTIFICATE, 4) | (FAMILY, 1) => Ok(Reader::Family),
        (CERTIFICATE, 5) | (ORBIT, 1) => Ok(Reader::Orbit),
        _ => Err(Fail::new("unsupported-version", format!("version {version}"))),
    }
}
