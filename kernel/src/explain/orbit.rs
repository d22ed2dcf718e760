//! The words of the rejections of orbit certificates.

use super::abbreviate;
use crate::orbit::map::Quantity;
use crate::reject::{KindLocus, Locus};
use crate::rules::orbit::{Failure, MAX_PATTERN};

/// The words of a failure of an orbit certificate (at a locus).
pub(super) fn words(f: &Failure, locus: &Locus) -> String {
    match f {
        Failure::Unsupported(n) => format!("n = {n}: orbit certificates need {}", supported()),
        Failure::ConeClaim(c) => {
            format!("{} is a cone claim; an orbit certificate claims CompleteChatterFromSet", c.name())
        }
        Failure::PatternLength(l) => format!("{l} steps; a pattern has 1 to {MAX_PATTERN}"),
        Failure::Step { step, n } => format!("step {step} is not in 1..{}", n.saturating_sub(1)),
        Failure::Bound { text, below_one } => {
            format!("{} is not in {}", abbreviate(text), if *below_one { "0 < x < 1" } else { "x > 0" })
        }
        Failure::DeltaNotPositive => "delta must be > 0".into(),
        Failure::Flat(i) => format!("lo >= hi in coordinate {i}: the box is empty or flat"),
        Failure::Singular => "the axes are linearly dependent".into(),
        Failure::Condition { quantity, wrong } => condition(*quantity, *wrong, locus),
    }
}

/// The n the kernel models for orbit certificates.
#[cfg(feature = "field")]
fn supported() -> String {
    format!("3 <= n <= {}", crate::exact::MAX_N)
}

/// The n the kernel models for orbit certificates without number fields.
#[cfg(not(feature = "field"))]
fn supported() -> String {
    "n in {3, 4, 6} (rational cos(2 pi/n); feature `field` for the others)".into()
}

/// "condition 1: ... fails at the centre of the sub-box y in [..] x [..] x [..]".
fn condition(q: Quantity, wrong: bool, locus: &Locus) -> String {
    let Locus::Kind(KindLocus::OrbitBox { sub_box, depth, .. }) = locus else { return describe(q) };
    let range: Vec<String> =
        sub_box.iter().map(|[lo, hi]| format!("[{}, {}]", abbreviate(lo), abbreviate(hi))).collect();
    let how = if wrong {
        "fails at the centre of".to_string()
    } else {
        format!("is not shown (interval bounds, {depth} bisections) on")
    };
    format!("condition {}: {} {how} the sub-box y in {}", q.condition(), describe(q), range.join(" x "))
}

/// The quantity in words.
fn describe(q: Quantity) -> String {
    match q {
        Quantity::Approach { step, contact } => {
            format!("at step {step}, the target contact {contact} approaches the floor (-u_{contact} > 0)")
        }
        Quantity::Up { step, contact } => {
            format!("at step {step}, the target contact {contact} is up (h_{contact} > 0)")
        }
        Quantity::Clear { step, contact } => format!(
            "at step {step}, contact {contact} is strictly above the floor when the target lands (h_k (-u_j) + h_j u_k > 0 for k = {contact})"
        ),
        Quantity::PositionScale => "alpha = hc(q_m) > 0".into(),
        Quantity::VelocityScale => "beta = -v(p_m) > 0".into(),
        Quantity::Inside { coordinate, upper: true } => {
            format!("R_P(x) in X: y'_{coordinate} <= delta for y' = A^-1 (R_P(x) - x*)")
        }
        Quantity::Inside { coordinate, upper: false } => {
            format!("R_P(x) in X: y'_{coordinate} >= -delta for y' = A^-1 (R_P(x) - x*)")
        }
        Quantity::VelocityBound => "beta <= lambda".into(),
        Quantity::RatioBound => "alpha/beta <= rho".into(),
        Quantity::PositionBound => "alpha <= lambda".into(),
        Quantity::TimeBound => "T <= period".into(),
    }
}
