//! summary.json of `chatter cover` (schema `chatter.cover/1`, docs/json.md and docs/cover.md).

use super::{CoverRequest, Leaf, f, tally};
use schemars::JsonSchema;
use serde::Serialize;

/// The finest subdivision, as numbers of halvings.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct Depths {
    pub kappa: u32,
    pub gamma: u32,
}

/// Boxes by status.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct BoxCounts {
    pub certified: usize,
    pub refuted: usize,
    pub undecided: usize,
}

/// Contradictions of the exact CC criterion (box indices in boxes.csv).
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct Findings {
    pub certified_where_criterion_fails: Vec<usize>,
    pub refuted_where_criterion_holds: Vec<usize>,
}

/// summary.json.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct CoverSummary {
    /// `chatter.cover/1`.
    pub schema: &'static str,
    pub n: u64,
    /// [lo, hi], canonical `p/q`.
    pub kappa: [String; 2],
    /// [lo, hi], canonical `p/q`.
    pub gamma: [String; 2],
    pub max_depth: Depths,
    pub boxes: BoxCounts,
    pub certified_area: f64,
    /// The certified area exactly, canonical `p/q`.
    pub certified_area_exact: String,
    /// The area of the exact CC region in the box (numerical).
    pub cc_area: f64,
    pub cc_area_error_estimate: f64,
    /// certified_area / cc_area (null if cc_area is 0).
    pub ratio: Option<f64>,
    pub refuted_area: f64,
    pub undecided_area: f64,
    pub undecided_band_height: f64,
    pub findings: Findings,
}

impl crate::json::Report for CoverSummary {
    const SCHEMA: &'static str = "chatter.cover/1";
}

impl CoverSummary {
    /// The summary of a cover's leaves, with the CC region's area and its error estimate.
    pub fn new(req: &CoverRequest, leaves: &[Leaf], cc_area: f64, error: f64) -> CoverSummary {
        let t = tally(leaves);
        let count = |s: &str| leaves.iter().filter(|l| l.status.name() == s).count();
        let certified_area = f(&t.certified_area);
        CoverSummary {
            schema: <Self as crate::json::Report>::SCHEMA,
            n: req.n,
            kappa: [req.kappa[0].to_string(), req.kappa[1].to_string()],
            gamma: [req.gamma[0].to_string(), req.gamma[1].to_string()],
            max_depth: Depths { kappa: req.max_depth[0], gamma: req.max_depth[1] },
            boxes: BoxCounts {
                certified: count("certified"),
                refuted: count("refuted"),
                undecided: count("undecided"),
            },
            certified_area,
            certified_area_exact: t.certified_area.to_string(),
            cc_area,
            cc_area_error_estimate: error,
            ratio: (cc_area > 0.0).then(|| certified_area / cc_area),
            refuted_area: f(&t.refuted_area),
            undecided_area: f(&t.undecided_area),
            undecided_band_height: f(&t.undecided_height),
            findings: Findings {
                certified_where_criterion_fails: t.certified_criterion_fails,
                refuted_where_criterion_holds: t.refuted_criterion_holds,
            },
        }
    }
}
