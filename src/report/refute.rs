//! `chatter.refute/1`: an exact refutation derived and kernel-checked at a point (or why none
//! was found). Built by [`RefuteReport::refuted`] and [`RefuteReport::not_refuted`].

use super::{Number, Report, Timings, Verdict};
use crate::exact::Q;
use chatter_kernel::refute::Refuted;
use schemars::JsonSchema;
use serde::Serialize;

/// `chatter refute --json`.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct RefuteReport {
    /// `chatter.refute/1`.
    pub schema: &'static str,
    /// `refuted` or `not-refuted`.
    pub verdict: Verdict,
    pub n: u64,
    pub kappa: Number,
    pub gamma: Number,
    /// The claim refuted (and every stronger one).
    pub claim: Option<&'static str>,
    /// Number of derived points.
    pub points: Option<usize>,
    /// The last derived point (u_1, ..., v), canonical `p/q` texts.
    pub last: Option<Vec<String>>,
    /// Whether the last point has v > 0 (else v = 0).
    pub v_positive: Option<bool>,
    /// The file written (`-o`).
    pub output: Option<String>,
    /// Why each claim tried could not be refuted (`not-refuted`).
    pub reasons: Vec<String>,
    /// Only with `--timings` (`search_ms` is the exact derivation; `exactify_ms` is 0).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub timings: Option<Timings>,
}

impl Report for RefuteReport {
    const SCHEMA: &'static str = "chatter.refute/1";
}

impl RefuteReport {
    fn base(verdict: Verdict, n: u64, kappa: &Q, gamma: &Q) -> RefuteReport {
        RefuteReport {
            schema: Self::SCHEMA,
            verdict,
            n,
            kappa: Number::of(kappa),
            gamma: Number::of(gamma),
            claim: None,
            points: None,
            last: None,
            v_positive: None,
            output: None,
            reasons: Vec::new(),
            timings: None,
        }
    }

    /// A refutation the kernel accepted, written to `output` (if any).
    pub fn refuted(kappa: &Q, gamma: &Q, done: &Refuted, output: Option<String>) -> RefuteReport {
        RefuteReport {
            claim: Some(done.claim.name()),
            points: Some(done.points),
            last: Some(done.last.iter().map(|x| chatter_kernel::explain::abbreviate(x)).collect()),
            v_positive: Some(done.v_positive),
            output,
            ..Self::base(Verdict::Refuted, done.n, kappa, gamma)
        }
    }

    /// No refutation: why, per claim tried.
    pub fn not_refuted(n: u64, kappa: &Q, gamma: &Q, reasons: Vec<String>) -> RefuteReport {
        RefuteReport { reasons, ..Self::base(Verdict::NotRefuted, n, kappa, gamma) }
    }
}
