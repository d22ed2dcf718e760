//! The words of the rejections of time-to-rest certificates.

use super::abbreviate;
use crate::reject::{KindLocus, Locus};
use crate::rules::rest::Failure;

/// The words of a failure of a time-to-rest certificate (at a locus).
pub(super) fn words(f: &Failure, locus: &Locus) -> String {
    let at = match locus {
        Locus::Kind(KindLocus::RestNode { node, step, vertex, corner, gamma, .. }) => {
            let step = step.map_or(String::new(), |j| format!(", step j = {j}"));
            let vertex = vertex.map_or(String::new(), |i| format!(", vertex {i}"));
            let corner = corner.map_or(String::new(), |c| format!(", at corner {c} of the box"));
            let end = gamma
                .as_ref()
                .map_or(String::new(), |g| format!(", at the end gamma = {} of the interval", abbreviate(g)));
            format!("node {node}{step}{vertex}{corner}{end}: ")
        }
        _ => String::new(),
    };
    let what = match f {
        Failure::Claim(c) => format!("the claim {c:?} is not about all-down drops"),
        Failure::NotAtPoint => "kappa and gamma must be numbers, not intervals".into(),
        Failure::BoxVersion(v) => {
            format!(
                "a time-to-rest certificate over a box of kappa and gamma needs version 3; this file says version {v}"
            )
        }
        Failure::Denominator(index, value) => {
            format!("-b·g = {value} at generator {index}, scaled to v = -1 (rule G1 needs > 0)")
        }
        Failure::Height(first, value) => {
            let m = if *first { "m_{i,i+1}" } else { "m_{i-1,i}" };
            format!(
                "a·{m} = {value}, i the node's last contact (0 in a regular polygon's frame; b·{m} in version 1; rule G2 needs >= 0)"
            )
        }
        Failure::Scale(c) => format!("the scale c = {c} (rule G2 needs >= 1)"),
        Failure::Flight(index, a, b) => format!(
            "a·g = {} > b·g = {} at generator {index}, scaled to v = -1: the virtual time falls slower than time in flight (rule F)",
            abbreviate(a),
            abbreviate(b)
        ),
        Failure::Version(field, true) => {
            format!("`{field}` is not a field of this version (docs/certificate-format.md §16)")
        }
        Failure::Version(field, false) => format!("`{field}` is missing (docs/certificate-format.md §16)"),
        Failure::Successor(step, Some(s)) => {
            format!(
                "step {step} names node {s}, which does not exist (or, for a general body, is not a node of contact {step})"
            )
        }
        Failure::Successor(0, None) => "the graph has no node".into(),
        Failure::Successor(step, None) => {
            format!("K ∩ C_{step} is not {{0}} but `next` names no node for step {step} (rule G3)")
        }
        Failure::Increases(left, lhs, rhs) => {
            let q = if *left { "m_{j-1,j}" } else { "m_{j,j+1}" };
            let (l, r) = (abbreviate(lhs), abbreviate(rhs));
            format!(
                "the virtual time grows at q = {q}: (a_s·R_j q)(-b_r·p) = {l} > (a_r·q)(-b_s·S_j p) = {r}, p scaled to v = -1 (rule G3; a = c b in version 1)"
            )
        }
        Failure::Entry(i, None) => format!("the entry of contact {i} names no node (rule G4)"),
        Failure::Entry(i, Some((e, c))) => {
            format!("the entry of contact {i} names node {e}, a node of contact {c} (rule G4)")
        }
        Failure::Entries(found, n) => {
            format!("expected one entry node per contact ({n}), found {found} (rule G4)")
        }
        Failure::Contact(c, n) => format!("the node's contact {c} is not one of the body's {n} contacts"),
        Failure::Bound(generator, lhs, rhs) => format!(
            "B is too small at generator {generator} of D: B (-b_0·I_0 g) = {} < a_0·m = {} (rule G5; a = c b in version 1)",
            abbreviate(lhs),
            abbreviate(rhs)
        ),
    };
    format!("{at}{what}")
}
