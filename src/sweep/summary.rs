//! summary.json: the counts of a map and every point where the float finder, the certificates,
//! the exact criteria and the simulations disagree: the paper's Conjecture 1 ((i) CC or PCC in
//! drops, (ii) an effectively invariant cone, (iii) S_1's dominant eigenvalue real and positive)
//! and Conjecture 2 (PCC iff all eigenvalues of S_{n-1} S_1 are real) checked on the grid.

use super::grid::Grid;
use super::table::Row;
use serde::Serialize;
use std::collections::BTreeMap;

/// What was computed at every point.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, serde::Deserialize, schemars::JsonSchema)]
pub struct Computed {
    pub certify: bool,
    pub refute: bool,
    /// Random drops per point (0: none).
    pub simulate: u64,
    /// Impact budget of each drop's `f64` run (the paper's protocol: evidence).
    pub budget: usize,
    /// Impact budget of each drop's exact run that tries to prove its outcome (0: no proofs).
    #[serde(default)]
    pub proof_budget: usize,
}

/// A point where two verdicts disagree.
#[derive(Clone, Debug, Serialize, schemars::JsonSchema)]
pub struct Disagreement {
    pub index: usize,
    pub rho: String,
    pub kappa: String,
    pub gamma: String,
    /// One of [`KINDS`].
    pub kind: &'static str,
    pub detail: String,
}

/// The kinds of disagreement, with what each means.
pub const KINDS: [(&str, &str); 15] = [
    (
        "finder-found-criterion-fails",
        "the float finder found a cone where S_1's dominant eigenvalue is not real and positive (Conjecture 1 (ii) => (iii), numerically)",
    ),
    (
        "finder-no-cone-criterion-holds",
        "the float finder proved no cone contains the paper's seed where the CC criterion holds (Conjecture 1 (iii) => (ii), numerically)",
    ),
    (
        "certified-criterion-fails",
        "an exact certificate where the CC criterion fails: a counterexample to Conjecture 1 (ii) => (iii)",
    ),
    ("certified-finder-no-cone", "an exact certificate where the float finder reported no cone"),
    (
        "simulated-chatter-criterion-fails",
        "evidence (f64, the paper's 200-impact protocol): random drops end in CC or PCC where the CC criterion fails; not a proof (see proved-chatter-criterion-fails)",
    ),
    (
        "criterion-holds-all-icc",
        "evidence: the CC criterion holds but every random drop ends in ICC (the conjecture speaks of suitable initial conditions, so this contradicts the paper's figure, not the conjecture)",
    ),
    (
        "certified-simulated-icc",
        "evidence: a certificate covering every all-down drop, yet a simulated drop (all contacts moving down) ended in ICC in f64",
    ),
    (
        "simulated-pcc-criterion-fails",
        "evidence: a random drop ended in PCC in f64 where S_{n-1} S_1 has non-real eigenvalues (against the PCC Lemma)",
    ),
    (
        "refuted-criterion-holds",
        "an exact refutation where the CC criterion holds: a counterexample to Conjecture 1 (iii) => (ii)",
    ),
    (
        "refuted-finder-found",
        "an exact refutation where the float finder found a cone (the finder's tolerance let it stop early)",
    ),
    (
        "proved-chatter-criterion-fails",
        "a drop proved to end in CC (exact run entering the set X of a kernel-checked orbit certificate, impacts accumulating at a finite time) or PCC (exact pair proof) where the CC criterion fails: Conjecture 1 (i) => (iii) is false at this point (drops proved only no-ICC-no-PCC are the kind proved-no-icc-criterion-fails)",
    ),
    (
        "evidence-contradicted-by-proof",
        "a drop whose proved outcome contradicts its f64 evidence (e.g. CC by converging intervals, proved ICC by v > 0 in the exact run; no-ICC-no-PCC does not contradict CC)",
    ),
    (
        "evidence-cc-unproved",
        "fewer drops proved CC than drops with CC as f64 evidence: the exact run entered no orbit certificate's set within the proof budget (it entered a certified cone, which proves no-ICC-no-PCC but not the finite accumulation time, or no certified set)",
    ),
    (
        "certified-proved-icc",
        "a certificate covering every all-down drop, yet an all-down drop proved ICC: a contradiction between a kernel-checked certificate and an exact run (a bug to report)",
    ),
    (
        "proved-no-icc-criterion-fails",
        "a drop proved no-ICC-no-PCC (exact run entering the cone K of a kernel-checked cone certificate: it never separates and never ends in PCC; the finite accumulation time is not derived, so CC is not proved) where the CC criterion fails: K is effectively invariant there, a counterexample to Conjecture 1 (ii) => (iii)",
    ),
];

/// A kind of disagreement: what it means and at how many points it occurs.
#[derive(Clone, Debug, Serialize, schemars::JsonSchema)]
pub struct KindCount {
    pub meaning: &'static str,
    pub points: u64,
}

/// summary.json.
#[derive(Clone, Debug, Serialize, schemars::JsonSchema)]
pub struct Summary {
    /// `chatter.map/1` (docs/json.md).
    pub schema: &'static str,
    pub grid: Grid,
    pub computed: Computed,
    pub points: usize,
    /// Counts of each column's values ("true", "false", finder verdicts, claims), and of the
    /// drops' outcomes: `drops_evidence` (f64, the paper's protocol: `CC`, `PCC`, `ICC`,
    /// `undecided`, `simultaneous`) and `drops_proved` (exact runs; a drop without a proof counts
    /// as `undecided`; `CC` only with a finite accumulation time, a drop that entered a certified
    /// cone as `no-ICC-no-PCC`).
    pub counts: BTreeMap<&'static str, BTreeMap<String, u64>>,
    /// Kind -> meaning and number of points.
    pub disagreement_kinds: BTreeMap<&'static str, KindCount>,
    pub disagreements: Vec<Disagreement>,
}

fn bump(m: &mut BTreeMap<&'static str, BTreeMap<String, u64>>, column: &'static str, value: String) {
    *m.entry(column).or_default().entry(value).or_default() += 1;
}

/// The disagreements at one row.
fn disagreements(r: &Row) -> Vec<(&'static str, String)> {
    let mut out = Vec::new();
    let cc = r.cc_criterion;
    let claim = r.claim.clone().unwrap_or_default();
    if r.finder == "found" && !cc {
        out.push((KINDS[0].0, "finder found, CC criterion fails".to_string()));
    }
    if r.finder == "no-cone" && cc {
        out.push((KINDS[1].0, "finder no-cone, CC criterion holds".to_string()));
    }
    if r.certified == Some(true) && !cc {
        out.push((KINDS[2].0, format!("certificate {claim}, CC criterion fails")));
    }
    if r.certified == Some(true) && r.finder == "no-cone" {
        out.push((KINDS[3].0, format!("certificate {claim}, finder no-cone")));
    }
    if r.refuted == Some(true) && cc {
        out.push((KINDS[8].0, "refuted, CC criterion holds".to_string()));
    }
    if r.refuted == Some(true) && r.finder == "found" {
        out.push((KINDS[9].0, "refuted, finder found".to_string()));
    }
    if let Some(s) = &r.sim {
        let [c, p, i, _, _, _] = s.counts;
        if c + p > 0 && !cc {
            out.push((KINDS[4].0, format!("{c} CC and {p} PCC of {} drops, CC criterion fails", s.runs)));
        }
        if cc && i == s.runs {
            out.push((KINDS[5].0, format!("all {i} drops ICC, CC criterion holds")));
        }
        if i > 0 && r.certified == Some(true) && claim != "EffectivelyInvariant" {
            out.push((KINDS[6].0, format!("certificate {claim}, {i} of {} drops ICC", s.runs)));
        }
        if p > 0 && !r.pcc_criterion {
            out.push((KINDS[7].0, format!("{p} PCC drops, PCC criterion fails")));
        }
        if let Some(proved) = s.proved {
            out.extend(proof_disagreements(r, s, &proved));
        }
    }
    out
}

/// The disagreements of a row's proved drop outcomes with the criterion, the evidence and the
/// certificate.
fn proof_disagreements(
    r: &Row,
    s: &super::point::SimStats,
    proved: &[u64; crate::simulate::Outcome::COUNT],
) -> Vec<(&'static str, String)> {
    let mut out = Vec::new();
    let [c, p, i, _, _, none] = *proved;
    let claim = r.claim.clone().unwrap_or_default();
    if c + p > 0 && !r.cc_criterion {
        out.push((KINDS[10].0, format!("{c} CC and {p} PCC of {} drops proved, CC criterion fails", s.runs)));
    }
    if none > 0 && !r.cc_criterion {
        out.push((
            KINDS[14].0,
            format!("{none} of {} drops proved no-ICC-no-PCC (certified cone), CC criterion fails", s.runs),
        ));
    }
    if s.contradicted > 0 {
        out.push((
            KINDS[11].0,
            format!("{} of {} drops: proved outcome differs from the f64 evidence", s.contradicted, s.runs),
        ));
    }
    if s.counts[0] > c {
        let detail = format!(
            "{} drops CC as evidence, {c} proved CC, {none} proved only no-ICC-no-PCC (finite time not derived)",
            s.counts[0]
        );
        out.push((KINDS[12].0, detail));
    }
    if i > 0 && r.certified == Some(true) && claim != "EffectivelyInvariant" {
        out.push((KINDS[13].0, format!("certificate {claim}, {i} of {} drops proved ICC", s.runs)));
    }
    out
}

impl Summary {
    /// The summary of a complete map (rows in index order).
    pub fn new(grid: &Grid, computed: &Computed, rows: &[Row]) -> Summary {
        let mut counts = BTreeMap::new();
        let mut list = Vec::new();
        for r in rows {
            bump(&mut counts, "cc_criterion", r.cc_criterion.to_string());
            bump(&mut counts, "pcc_criterion", r.pcc_criterion.to_string());
            bump(&mut counts, "finder", r.finder.clone());
            if let Some(c) = r.certified {
                bump(&mut counts, "certified", c.to_string());
            }
            if let Some(c) = &r.claim {
                bump(&mut counts, "claim", c.clone());
            }
            if let Some(c) = r.refuted {
                bump(&mut counts, "refuted", c.to_string());
            }
            if let Some(s) = &r.sim {
                // The f64 evidence is never no-ICC-no-PCC: its outcomes only.
                for (name, k) in crate::simulate::Outcome::EVIDENCE.iter().zip(s.counts) {
                    *counts
                        .entry("drops_evidence")
                        .or_default()
                        .entry(name.name().to_string())
                        .or_default() += k;
                }
                for (name, k) in crate::simulate::Outcome::ALL.iter().zip(s.proved.unwrap_or_default()) {
                    if s.proved.is_some() {
                        *counts
                            .entry("drops_proved")
                            .or_default()
                            .entry(name.name().to_string())
                            .or_default() += k;
                    }
                }
            }
            for (kind, detail) in disagreements(r) {
                list.push(Disagreement {
                    index: r.index,
                    rho: r.rho.clone(),
                    kappa: r.kappa.to_string(),
                    gamma: r.gamma.to_string(),
                    kind,
                    detail,
                });
            }
        }
        let disagreement_kinds = KINDS
            .iter()
            .map(|(k, meaning)| {
                (*k, KindCount { meaning, points: list.iter().filter(|d| d.kind == *k).count() as u64 })
            })
            .collect();
        Summary {
            schema: <Summary as crate::json::Report>::SCHEMA,
            grid: grid.clone(),
            computed: computed.clone(),
            points: rows.len(),
            counts,
            disagreement_kinds,
            disagreements: list,
        }
    }

    /// The JSON text written to summary.json.
    pub fn json(&self) -> String {
        serde_json::to_string_pretty(self).expect("serialisable") + "\n"
    }
}

impl crate::json::Report for Summary {
    const SCHEMA: &'static str = "chatter.map/1";
}
