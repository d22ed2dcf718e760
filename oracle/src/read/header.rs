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
/// `format` of basin certificates (§15).
pub const BASIN: &str = "chatter-basin-certificate";
/// `format` of time-to-rest certificates (§16).
pub const REST: &str = "chatter-time-to-rest";
/// `format` of time-to-rest certificates of a general convex body (§17).
pub const REST_FAMILY: &str = "chatter-family-time-to-rest";
/// `format` of refutations (§10).
pub const REFUTATION: &str = "chatter-refutation";

/// Which reader a file goes to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reader {
    /// Cone certificates of regular polygons, versions 1 to 3 (§2-§9, §12).
    Cone(u64),
    /// General convex bodies, family versions 1 and 2 (version 2 allows an interval of γ; the
    /// legacy header version 4 is version 1) (§13).
    Family,
    /// Orbit certificates, version 5 (§14).
    Orbit,
    /// Refutations, version 1 (§10).
    Refutation,
    /// Basin certificates, versions 1 and 2 (§15; version 2 adds tree leaves).
    Basin,
    /// Time-to-rest certificates, versions 1 to 3 (§16).
    Rest,
    /// Time-to-rest certificates of a general convex body, versions 1 and 2 (version 2 allows an
    /// interval of γ) (§17).
    RestFamily,
}

/// Reads `format` and `version` and picks the reader. The top-level struct's name, when written,
/// must be `Certificate` for certificates, `TimeToRest` for time-to-rest certificates (§16's
/// example), `FamilyTimeToRest` for those of a general body (§17) and `Refutation` for refutations (checked after the
/// header: the kernel reads the header under any struct name, then the kind's schema).
pub fn header(v: &Value) -> Checked<Reader> {
    let named = match v {
        Value::Named { name, .. } if !name.is_empty() => Some(name.as_str()),
        _ => None,
    };
    let (mut format, mut version) = (None, None);
    for (name, value) in record(v)? {
        // The kernel reads the RON header leniently, as optional fields with `Some` implicit:
        // `Some(x)` is x there and `None` an absent field; the kind's schema refuses both later.
        let value = match value {
            Value::Wrapped { name, items } if name == "Some" && items.len() == 1 => Some(&items[0]),
            Value::Named { name, fields: None } if name == "None" => None,
            other => Some(other),
        };
        let slot_is_set = match name.as_str() {
            "format" => format.replace(value.map(string).transpose()?).is_some(),
            "version" => version.replace(value.map(integer).transpose()?).is_some(),
            _ => false,
        };
        if slot_is_set {
            return Err(Fail::new("duplicate-field", format!("duplicate field `{name}`")));
        }
    }
    let format = format.flatten().ok_or_else(|| Fail::new("missing-field", "missing field `format`"))?;
    if ![CERTIFICATE, FAMILY, ORBIT, REFUTATION, BASIN, REST, REST_FAMILY].contains(&format) {
        return Err(Fail::new("wrong-format", format!("format {format:?}")));
    }
    let version = version.flatten().ok_or_else(|| Fail::new("missing-field", "missing field `version`"))?;
    // docs/certificate-format.md's header table, with the two legacy aliases of version 4 and 5.
    let reader = match (format, version) {
        (REFUTATION, 1) => Reader::Refutation,
        (CERTIFICATE, 1..=3) => Reader::Cone(version),
        (CERTIFICATE, 4) | (FAMILY, 1..=2) => Reader::Family,
        (CERTIFICATE, 5) | (ORBIT, 1) => Reader::Orbit,
        (BASIN, 1..=2) => Reader::Basin,
        (REST, 1..=3) => Reader::Rest,
        (REST_FAMILY, 1..=2) => Reader::RestFamily,
        _ => return Err(Fail::new("unsupported-version", format!("version {version}"))),
    };
    let expected_name = match reader {
        Reader::Refutation => "Refutation",
        Reader::Rest => "TimeToRest",
        Reader::RestFamily => "FamilyTimeToRest",
        _ => "Certificate",
    };
    if let Some(name) = named
        && name != expected_name
    {
        return Err(Fail::new("syntax", format!("expected struct `{expected_name}`, found `{name}`")));
    }
    Ok(reader)
}
