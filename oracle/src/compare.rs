//! Comparing the kernel's verdict with the oracle's. The kernel's verdict arrives as plain data
//! ([`KernelView`], filled in by the differential tests and the fuzz target, which may depend on
//! the kernel; this library does not). A [`Finding`] is a disagreement to report.

use crate::verdict::{Judgement, Kind, Outcome, Report, Sided};

/// The kernel's verdict as plain data.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct KernelView {
    /// Whether every backend accepted.
    pub accepted: bool,
    /// The backends disagreed (an internal error of the kernel).
    pub disagree: Option<String>,
    /// The rejection code (kebab-case).
    pub code: Option<String>,
    /// The rejection's locus as JSON.
    pub locus: Option<serde_json::Value>,
    /// The rejection's message.
    pub message: String,
    /// The report of an accepted file (fields the kernel did not report are `None`).
    pub report: Report,
    /// For an accepted box claiming CC: the number of Bernstein boxes.
    pub pcc_boxes: Option<usize>,
    /// For an accepted orbit certificate: the number of sub-boxes shown.
    pub orbit_boxes: Option<usize>,
    /// For an accepted file: the bound B on the time to rest as the kernel reports it (rule T1
    /// of a rod, T̄/(1 - ρ) of an orbit certificate; `Some(None)`: no bound); `None` where the
    /// caller did not read it (then it is not compared).
    pub time_to_rest_bound: Option<Option<String>>,
    /// For an accepted family certificate: [γ_lo, γ_hi] when its γ is an interval, as the tool's
    /// report of the kernel's verdict gives it (`chatter verify --json`, `gamma_interval`;
    /// `Some(None)`: a single γ); `None` where the caller did not read it.
    pub gamma_interval: Option<Option<[String; 2]>>,
}

/// A disagreement between the kernel and the oracle.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Finding {
    /// `backends-disagree`, `kernel-accepts-false` (the kernel accepts, the oracle finds a rule
    /// false), `oracle-accepts` (the kernel rejects what the oracle accepts, two-sided),
    /// `wrong-code` (both reject, the kernel's code is not one the oracle's first failing rule
    /// can give), `wrong-end` (both reject a family certificate over an interval of γ with the
    /// same code, at different ends; also time-to-rest certificates of general bodies) or
    /// `wrong-report` (both accept, with different reports).
    pub kind: &'static str,
    /// What differs.
    pub detail: String,
}

impl std::fmt::Display for Finding {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.kind, self.detail)
    }
}

/// What a comparison found when there was no disagreement.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Agreement {
    /// Both accept (for a one-sided kind: the oracle found no counterexample).
    BothAccept,
    /// Both reject with a compatible code.
    BothReject,
    /// The kernel rejects as "not shown" (a box's PCC region, an orbit sub-box) what the oracle
    /// accepts or cannot decide: the kernel is conservative there by design.
    KernelConservative,
    /// A limit (`too-large`, `time-limit`): no verdict on the content to compare.
    Limit,
}

fn finding(kind: &'static str, detail: String) -> Finding {
    Finding { kind, detail }
}

/// The kernel's abbreviation of long numbers in reports and messages
/// (docs/certificate-format.md §5): first 16 and last 8 characters and the length.
pub fn abbreviated(s: &str) -> String {
    if s.len() <= 40 {
        return s.to_string();
    }
    format!("{}...{} ({} characters)", &s[..16], &s[s.len() - 8..], s.len())
}

/// Whether a kernel rejection says that something was not shown rather than false: a box's R4
/// on a region wider than a point, or an orbit condition "is not shown".
fn not_shown(k: &KernelView) -> bool {
    let code = k.code.as_deref().unwrap_or("");
    let region_wide = k.locus.as_ref().is_some_and(|l| {
        l["kind"] == "pcc-region" && (l["kappa"][0] != l["kappa"][1] || l["gamma"][0] != l["gamma"][1])
    });
    (code == "pcc-not-excluded" && region_wide) || k.message.contains("is not shown")
}

/// Compares the two reports of an accepted file, field by field where both have the field.
/// Whether two optional report fields agree where both are present.
fn both<T: PartialEq>(a: &Option<T>, b: &Option<T>) -> bool {
    a.is_none() || b.is_none() || a == b
}

fn same_report(k: &Report, o: &Report) -> Result<(), String> {
    let mut diffs = vec![];
    let mut check = |name: &str, same: bool| {
        if !same {
            diffs.push(name.to_string());
        }
    };
    check("claim", k.claim == o.claim);
    check("n", k.n == o.n);
    check("generators", both(&k.generators, &o.generators));
    check("redundant", both(&k.redundant, &o.redundant));
    check("max_denominator_bits", both(&k.max_denominator_bits, &o.max_denominator_bits));
    check("pcc", both(&k.pcc, &o.pcc));
    check("contains_translation", both(&k.contains_translation, &o.contains_translation));
    check("region", both(&k.region, &o.region));
    check("basin", both(&k.basin, &o.basin));
    check("rest_nodes", both(&k.rest_nodes, &o.rest_nodes));
    if let (Some(kp), Some(op)) = (&k.pieces, &o.pieces) {
        // The kernel's clipped list may repeat a point of a degenerate piece.
        let ok =
            kp.len() == op.len() && kp.iter().zip(op).all(|(a, b)| if *b >= 3 { a == b } else { a >= b });
        check("pieces", ok);
    }
    if let (Some(kr), Some(or)) = (&k.refutation, &o.refutation) {
        // The kernel reports the last point exactly (typed rejections and reports, issue 23 §1);
        // a report rendered for display may abbreviate long numbers.
        let last: Vec<String> = or.1.iter().map(|s| abbreviated(s)).collect();
        check("refutation", kr.0 == or.0 && (kr.1 == or.1 || kr.1 == last) && kr.2 == or.2);
    }
    if diffs.is_empty() {
        Ok(())
    } else {
        Err(format!("{} differ: kernel {k:?}, oracle {o:?}", diffs.join(", ")))
    }
}

/// Compares the bound B on the time to rest of an accepted file, where the kernel's was read: the
/// oracle has one for a rod whose `time_to_rest_bound` rule T1 shows, and for an orbit
/// certificate (T̄/(1 - ρ)).
fn same_bound(k: &KernelView, o: &Judgement) -> Result<(), String> {
    if o.kind == Kind::Basin {
        return basin_bound(k, o);
    }
    match &k.time_to_rest_bound {
        Some(kb) if *kb != o.time_to_rest_bound => {
            Err(format!("time_to_rest_bound differs: kernel {kb:?}, oracle {:?}", o.time_to_rest_bound))
        }
        _ => Ok(()),
    }
}

/// A basin certificate's bound: the kernel's bounds the time to rest of every drop of every CC
/// leaf, so it must be at least the exact time of each drop the oracle followed into X.
fn basin_bound(k: &KernelView, o: &Judgement) -> Result<(), String> {
    use crate::arith::rational::parse_rational;
    let (Some(kb), Some(ob)) = (&k.time_to_rest_bound, &o.time_to_rest_bound) else { return Ok(()) };
    let below = |s: &str| parse_rational(s, usize::MAX).ok();
    match (kb.as_deref().and_then(below), below(ob)) {
        (Some(kb), Some(ob)) if kb >= ob => Ok(()),
        _ => Err(format!("time_to_rest_bound {kb:?} is below the exact time {ob} of a drop followed into X")),
    }
}

/// The end of an interval of γ at which the kernel rejects a family certificate (rules K2-K4:
/// the loci `transition`, `convex-all-down` and `pcc-pair` carry it) or a general body's
/// time-to-rest certificate (G3-G5 and K4: `rest-node`, `convex-all-down`, `pcc-pair`).
fn kernel_end(k: &KernelView) -> Option<&str> {
    let locus = k.locus.as_ref()?;
    let kinds = ["transition", "convex-all-down", "pcc-pair", "rest-node"];
    kinds.iter().any(|kind| locus["kind"] == *kind).then(|| locus["gamma"].as_str()).flatten()
}

/// Both reject a family certificate (or a general body's time-to-rest certificate) with the
/// same code: they must name the same end of an interval of γ (or none).
fn same_end(k: &KernelView, why: &str) -> Result<(), Finding> {
    let (kernel, oracle) = (kernel_end(k), crate::convex::rules::end_named(why));
    if kernel == oracle {
        return Ok(());
    }
    let detail =
        format!("the kernel fails at the end {kernel:?} ({}), the oracle at {oracle:?}: {why}", k.message);
    Err(finding("wrong-end", detail))
}

/// Compares a kernel verdict with the oracle's judgement of the same file.
pub fn compare(k: &KernelView, o: &Judgement) -> Result<Agreement, Finding> {
    if let Some(d) = &k.disagree {
        return Err(finding("backends-disagree", d.clone()));
    }
    let code = k.code.as_deref().unwrap_or("");
    if !k.accepted && (code == "too-large" || code == "time-limit") {
        return Ok(Agreement::Limit);
    }
    match (&o.outcome, k.accepted) {
        (Outcome::Accept(report), true) => {
            same_report(&k.report, report).map_err(|d| finding("wrong-report", d))?;
            same_bound(k, o).map_err(|d| finding("wrong-report", d))?;
            if let Some(kg) = &k.gamma_interval
                && *kg != o.gamma_interval
            {
                let detail = format!("gamma_interval differs: kernel {kg:?}, oracle {:?}", o.gamma_interval);
                return Err(finding("wrong-report", detail));
            }
            Ok(Agreement::BothAccept)
        }
        (Outcome::Reject { codes, why }, true) => {
            let detail = format!("the kernel accepts; the oracle finds {codes:?}: {why}");
            Err(finding("kernel-accepts-false", detail))
        }
        (Outcome::Accept(_), false) if not_shown(k) || o.sided == Sided::One => {
            Ok(Agreement::KernelConservative)
        }
        (Outcome::Accept(_), false) => Err(finding(
            "oracle-accepts",
            format!("the kernel rejects ({code}: {}), the oracle accepts", k.message),
        )),
        (Outcome::Reject { codes, why }, false) => {
            let content = ["pattern-not-forced", "set-not-invariant", "no-contraction"];
            let both_content = content.contains(&code) && codes.iter().all(|c| content.contains(c));
            // A basin certificate's orbit conditions (O2) come before B3 and B4 (and the
            // embedded time-to-rest certificate's rules): where the kernel finds O2 false or not
            // shown and the oracle's sample points pass it, the oracle goes on to the later rules
            // and may meet one of them first.
            let later = [
                "not-a-partition",
                "leaf-not-shown",
                "generator-not-below",
                "degenerate-cone",
                "virtual-time-not-positive",
                "virtual-time-increases",
                "missing-successor",
                "image-not-below",
                "image-outside",
                "initial-outside",
                "bound-too-small",
                "pcc-not-excluded",
            ];
            let basin_later = o.kind == Kind::Basin
                && content.contains(&code)
                && codes.iter().all(|c| content.contains(c) || later.contains(c));
            if codes.contains(&code) && matches!(o.kind, Kind::Family | Kind::RestFamily) {
                same_end(k, why).map(|()| Agreement::BothReject)
            } else if codes.contains(&code) || (o.sided == Sided::One && (both_content || basin_later)) {
                Ok(Agreement::BothReject)
            } else {
                let detail = format!("kernel {code} ({}); oracle {codes:?}: {why}", k.message);
                Err(finding("wrong-code", detail))
            }
        }
    }
}

/// The kernel's claim that an orbit condition "fails at the centre" of a sub-box, checked
/// exactly: `Some(true)` when the oracle's return map fails that condition at that point,
/// `Some(false)` when it does not, `None` when the rejection makes no such claim.
pub fn orbit_centre_confirmed(text: &str, encoding: crate::read::Encoding, k: &KernelView) -> Option<bool> {
    use crate::arith::Num;
    use crate::arith::rational::parse_rational;
    use crate::kinds::{limits::Limits, orbit};
    if k.accepted || !k.message.contains("fails at the centre") {
        return None;
    }
    let locus = k.locus.as_ref()?;
    let value = crate::read::parse::parse(text, encoding).ok()?;
    let o = orbit::rules(&orbit::read(&value).ok()?, &Limits::default()).ok()?;
    // The centre is rational; the return map runs in the body's field Q(cos 2π/n).
    let field = o.delta.field.clone();
    let mut y = vec![];
    for i in 0..3 {
        let end = |j: usize| locus["sub_box"][i][j].as_str().and_then(|s| parse_rational(s, usize::MAX).ok());
        let mid = (end(0)? + end(1)?) / parse_rational("2", 9).ok()?;
        y.push(Num::rational(&field, mid));
    }
    let y = [y[0].clone(), y[1].clone(), y[2].clone()];
    let code = k.code.as_deref()?;
    Some(o.conditions(&y).is_err_and(|f| f.codes.contains(&code)))
}

/// Judges a text with the oracle and compares it with the kernel's verdict, checking an orbit
/// rejection "at the centre" of a sub-box exactly.
pub fn differential(
    text: &str,
    encoding: crate::read::Encoding,
    k: &KernelView,
) -> (Judgement, Result<Agreement, Finding>) {
    let o = crate::judge(text, encoding);
    let mut cmp = compare(k, &o);
    if cmp.is_ok() && orbit_centre_confirmed(text, encoding, k) == Some(false) {
        let detail = format!(
            "the kernel says {} fails at the centre of its sub-box; exactly, it holds there",
            k.code.as_deref().unwrap_or("")
        );
        cmp = Err(finding("kernel-centre-false", detail));
    }
    (o, cmp)
}
