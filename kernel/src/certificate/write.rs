//! The deterministic RON writer: one generator per line, in the strict syntax.

use super::{Body, Certificate, Param};

/// A string in the strict syntax: quoted, without escapes. Characters the syntax does not allow
/// in strings (`"`, `\`, control characters) become spaces; they can only come from the free-text
/// `producer` field (numbers and names never contain them).
pub fn quoted(s: &str) -> String {
    let clean: String =
        s.chars().map(|c| if c == '"' || c == '\\' || c.is_control() { ' ' } else { c }).collect();
    format!("\"{clean}\"")
}

/// A parameter: `"x"` or `["lo", "hi"]`.
fn param(p: &Param) -> String {
    match p {
        Param::Point(x) => quoted(x),
        Param::Interval(a, b) => format!("[{}, {}]", quoted(a), quoted(b)),
    }
}

/// Writes a certificate as RON, one generator per line (deterministic).
pub fn write(c: &Certificate) -> String {
    let q = |s: &str| quoted(s);
    let Body::RegularPolygon { n, kappa, gamma } = &c.body;
    let mut out = String::new();
    out.push_str("Certificate(\n");
    out.push_str(&format!("    format: {},\n", q(&c.format)));
    out.push_str(&format!("    version: {},\n", c.version));
    out.push_str(&format!(
        "    body: RegularPolygon(n: {n}, kappa: {}, gamma: {}),\n",
        param(kappa),
        param(gamma)
    ));
    out.push_str("    coordinates: ContactVelocities,\n");
    out.push_str(&format!("    claim: {},\n", c.claim.name()));
    out.push_str("    cone: [\n");
    for g in &c.cone {
        let coords: Vec<String> = g.0.iter().map(|s| q(s)).collect();
        out.push_str(&format!("        ({}),\n", coords.join(", ")));
    }
    out.push_str("    ],\n");
    out.push_str(&format!("    producer: {},\n", q(&c.producer)));
    out.push_str(")\n");
    out
}
