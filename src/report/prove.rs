//! `chatter.prove/1` (the square-case proof produced and re-checked) and `chatter.check-proof/1`
//! (proof files re-checked by the kernel).

use super::{Report, Verdict};
use crate::symbolic::crosscheck::CrossCheck;
use chatter_kernel::certificate::Rejection;
use chatter_kernel::proof::Checked;
use schemars::JsonSchema;
use serde::Serialize;

/// `chatter prove square --json`.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct ProveReport {
    /// `chatter.prove/1`.
    pub schema: &'static str,
    /// The kernel's verdict on the produced proof: `accepted` or `rejected` (`failure`).
    pub verdict: Verdict,
    pub steps: usize,
    pub failure: Option<String>,
    /// (step id, problem) pairs the producer met.
    pub producer_problems: Vec<(String, String)>,
    /// Number of conclusions proved.
    pub conclusions: usize,
    pub cross_check: CrossCheck,
    /// With `--check`: the files that differ from the regenerated ones.
    pub stale: Vec<String>,
}

impl Report for ProveReport {
    const SCHEMA: &'static str = "chatter.prove/1";
}

/// One proof file.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct ProofFileReport {
    pub path: String,
    /// `accepted` or `rejected`.
    pub verdict: Verdict,
    /// The theorem's name (accepted).
    pub name: Option<String>,
    pub steps: Option<usize>,
    pub hypotheses: Option<Vec<String>>,
    pub conclusions: Option<Vec<String>>,
    /// Whether a witness shows the hypotheses' region is not empty.
    pub region_nonempty: Option<bool>,
    /// The rejection's code (kebab-case): a header's (`wrong-format`, `unsupported-version`,
    /// `invalid-header`, ...) or the failing step's kind of failure (`bad-expression`,
    /// `not-an-identity`, `sign-not-proved`, ...: docs/proof-format.md §7).
    #[schemars(with = "Option<String>")]
    pub code: Option<chatter_kernel::certificate::Code>,
    /// Where the first failing step is (an object with a `kind`).
    #[schemars(with = "Option<serde_json::Map<String, serde_json::Value>>")]
    pub locus: Option<chatter_kernel::certificate::Locus>,
    pub reason: Option<String>,
}

impl ProofFileReport {
    /// An accepted proof.
    pub fn accepted(path: &str, c: &Checked) -> ProofFileReport {
        ProofFileReport {
            verdict: Verdict::Accepted,
            name: Some(c.name.clone()),
            steps: Some(c.steps),
            hypotheses: Some(c.hypotheses.clone()),
            conclusions: Some(c.conclusions.clone()),
            region_nonempty: Some(c.nonempty),
            ..Self::empty(path)
        }
    }

    /// A rejected proof.
    pub fn rejected(path: &str, r: &Rejection) -> ProofFileReport {
        ProofFileReport {
            verdict: Verdict::Rejected,
            code: Some(r.code),
            locus: Some(r.locus.clone()),
            reason: Some(r.message().clone()),
            ..Self::empty(path)
        }
    }

    fn empty(path: &str) -> ProofFileReport {
        ProofFileReport {
            path: path.to_string(),
            verdict: Verdict::Rejected,
            name: None,
            steps: None,
            hypotheses: None,
            conclusions: None,
            region_nonempty: None,
            code: None,
            locus: None,
            reason: None,
        }
    }
}

/// `chatter check-proof --json`.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct CheckProofReport {
    /// `chatter.check-proof/1`.
    pub schema: &'static str,
    /// `accepted` if every file is, else `rejected`.
    pub verdict: Verdict,
    pub files: Vec<ProofFileReport>,
}

impl Report for CheckProofReport {
    const SCHEMA: &'static str = "chatter.check-proof/1";
}

impl CheckProofReport {
    /// The report over files.
    pub fn of(files: Vec<ProofFileReport>) -> CheckProofReport {
        let all = files.iter().all(|f| f.verdict == Verdict::Accepted);
        let verdict = if all { Verdict::Accepted } else { Verdict::Rejected };
        CheckProofReport { schema: Self::SCHEMA, verdict, files }
    }
}
