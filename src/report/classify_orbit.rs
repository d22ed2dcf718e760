//! The `orbit` field of `chatter.classify/1`: where the CC criterion fails but simulated drops
//! end in complete chatter, `classify` tries an orbit certificate (docs/orbit-certificates.md,
//! certificate-format.md §14) with the producer of [`crate::orbit`], bounded by the producer's
//! own limits, and reports whether the kernel accepted it on both backends, what it proves (CC
//! from an explicit set X of post-impact states, not from every drop) and what that says about
//! the paper's Conjecture 1; or why no certificate was made.

use super::classify::{Criterion, Drops};
use super::orbit::Diagnostics;
use super::{Number, Verdict};
use crate::orbit::{Failure, Found, Request, certify_orbit, find_cc_pattern, find_pattern};
use crate::simulate::Outcome;
use chatter_kernel::certificate::Triple;
use chatter_kernel::certificate::{OrbitCertificate, OrbitSet};
use chatter_kernel::verify::{MALACHITE, NUM};
use schemars::JsonSchema;
use serde::Serialize;

/// Random drops the producer simulates to find the impact pattern (seeds 1..=ORBIT_DROPS, 600
/// impacts each): enough to meet a cycle whose basin holds a few percent of the drops (the
/// pentagon's, docs/orbit-certificates.md §7.3).
pub const ORBIT_DROPS: u64 = 200;
/// The deepest subdivision of X the producer may ask the kernel for. With it the producer makes
/// at most 48 kernel calls per phase of the pattern (δ = 2^-4 down to 2^-27, subdivision 0
/// and 1), each on at most 9 sub-boxes: a failed attempt ends in seconds, never hangs.
pub const ORBIT_DEPTH: u64 = 1;

/// The set X of an orbit certificate, in the section's coordinates x = (a, b, c)
/// (docs/orbit-certificates.md §2).
#[derive(Clone, Debug, Serialize, JsonSchema)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum OrbitSetReport {
    /// x* + A [-δ, δ]³.
    Parallelepiped {
        /// x*.
        centre: [Number; 3],
        /// The columns of A.
        axes: Box<[[Number; 3]; 3]>,
        /// δ.
        delta: Number,
    },
    /// The box [lo, hi].
    Box { lo: [Number; 3], hi: [Number; 3] },
}

/// An orbit certificate attempted by `classify` (docs/orbit-certificates.md).
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct OrbitSummary {
    /// `certified` (the kernel accepted the certificate on both backends) or `not-certified`.
    pub verdict: Verdict,
    /// `CompleteChatterFromSet` when certified.
    pub claim: Option<&'static str>,
    /// The impact pattern's steps j (the next impact is j contacts on): found from simulated
    /// drops; the certified phase when certified; null when no drop settled into a pattern.
    pub pattern: Option<Vec<usize>>,
    /// The set X when certified.
    pub set: Option<OrbitSetReport>,
    /// The deepest subdivision of X the kernel used.
    pub subdivision: Option<u64>,
    /// Sub-boxes of X on which the kernel showed every sign.
    pub sub_boxes: Option<usize>,
    /// The certificate's bounds ρ (α/β), λ (α and β) and T̄ (flight time per period).
    pub rho: Option<Number>,
    pub lambda: Option<Number>,
    pub period: Option<Number>,
    /// The attracting cycle in `f64` (untrusted).
    pub cycle: Option<Diagnostics>,
    /// The kernel's backends that accepted the certificate (empty when not certified).
    pub backends: Vec<&'static str>,
    /// What the certificate proves, in words (null when not certified).
    pub proves: Option<String>,
    /// Why not certified: `unsupported-body`, `no-pattern`, `no-attracting-cycle`,
    /// `pattern-not-stable`, `no-contraction` or `internal`.
    pub failure: Option<&'static str>,
    /// Why not certified, in words.
    pub reason: Option<String>,
    /// What this says about the paper's Conjecture 1 ((i) CC or PCC possible ⇒ (iii) S_1 has a
    /// real positive dominant eigenvalue).
    pub conjecture_1: String,
    /// Whether an accepted certificate refutes Conjecture 1 (i) ⇒ (iii) at this point.
    pub conjecture_1_refuted: bool,
    /// The file the certificate was written to (`classify --orbit-out FILE`), else null.
    pub file: Option<String>,
    /// The certificate itself (for `--orbit-out`).
    #[serde(skip)]
    pub certificate: Option<OrbitCertificate>,
}

/// The failure's key in `failure`.
pub fn failure_kind(f: &Failure) -> &'static str {
    match f {
        Failure::Body(_) => "unsupported-body",
        Failure::NoPattern(_) => "no-pattern",
        Failure::NoAttractingCycle(_) => "no-attracting-cycle",
        Failure::PatternNotStable(_) => "pattern-not-stable",
        Failure::NoContraction(_) => "no-contraction",
        Failure::Internal(_) => "internal",
    }
}

fn numbers(t: &Triple) -> [Number; 3] {
    let n = |s: &String| Number::parse(s).unwrap_or(Number { exact: s.clone(), f64: f64::NAN });
    [n(&t.0), n(&t.1), n(&t.2)]
}

fn number(s: &str) -> Option<Number> {
    Number::parse(s)
}

fn set_report(s: &OrbitSet) -> OrbitSetReport {
    match s {
        OrbitSet::Parallelepiped { centre, axes, delta } => OrbitSetReport::Parallelepiped {
            centre: numbers(centre),
            axes: Box::new([numbers(&axes.0), numbers(&axes.1), numbers(&axes.2)]),
            delta: Number::parse(delta).unwrap_or(Number { exact: delta.clone(), f64: f64::NAN }),
        },
        OrbitSet::Box { lo, hi } => OrbitSetReport::Box { lo: numbers(lo), hi: numbers(hi) },
    }
}

/// The pattern as text: `2,2,1,1`.
pub fn pattern_text(p: &[usize]) -> String {
    p.iter().map(usize::to_string).collect::<Vec<_>>().join(",")
}

/// What a certificate for the pattern proves, in words (docs/orbit-certificates.md §4).
pub fn proves_text(pattern: &[usize]) -> String {
    format!(
        "every motion whose state right after an impact lies in X (up to relabelling the contacts and the two scalings) follows the pattern {} for ever and ends in complete chatter; not proved: CC from every drop",
        pattern_text(pattern)
    )
}

/// The failing CC criterion in words: "S_1's dominant eigenvalue is negative", ...
pub fn criterion_fails_text(cc: &Criterion) -> String {
    match cc.dominant {
        Some("negative") => "S_1's dominant eigenvalue is negative".into(),
        _ => format!("S_1 has no real positive dominant eigenvalue (dominant: {})", cc.dominant_text),
    }
}

/// The statement about Conjecture 1 when a certificate was accepted where the criterion fails.
pub fn refuted_text(cc: &Criterion) -> String {
    format!(
        "the paper's Conjecture 1 ((i) CC possible ⇒ (iii) S_1 criterion) is false here: CC is possible (proved from X) but {}",
        criterion_fails_text(cc)
    )
}

fn not_certified(
    pattern: Option<Vec<usize>>,
    failure: &'static str,
    reason: String,
    chatter: usize,
    runs: u64,
) -> OrbitSummary {
    OrbitSummary {
        verdict: Verdict::NotCertified,
        claim: None,
        pattern,
        set: None,
        subdivision: None,
        sub_boxes: None,
        rho: None,
        lambda: None,
        period: None,
        cycle: None,
        backends: Vec::new(),
        proves: None,
        failure: Some(failure),
        reason: Some(reason),
        conjecture_1: format!(
            "not decided by a certificate here: {chatter} of {runs} drops end in CC although the CC criterion fails, evidence against Conjecture 1 (i) ⇒ (iii) but not a proof"
        ),
        conjecture_1_refuted: false,
        file: None,
        certificate: None,
    }
}

fn certified(found: Found, cc: &Criterion) -> OrbitSummary {
    let c = &found.certificate;
    OrbitSummary {
        verdict: Verdict::Certified,
        claim: Some(c.claim.name()),
        pattern: Some(found.pattern.clone()),
        set: Some(set_report(&c.set)),
        subdivision: Some(c.subdivision),
        sub_boxes: Some(found.boxes),
        rho: number(&c.rho),
        lambda: number(&c.lambda),
        period: number(&c.period),
        cycle: Some(Diagnostics::of(&found)),
        backends: vec![MALACHITE.name, NUM.name],
        proves: Some(proves_text(&found.pattern)),
        failure: None,
        reason: None,
        conjecture_1: refuted_text(cc),
        conjecture_1_refuted: true,
        file: None,
        certificate: Some(found.certificate),
    }
}

/// The orbit certificate at a regular polygon (n, kappa, gamma) where the CC criterion `cc`
/// fails and some of the `drops` end in CC, or the producer's own [`ORBIT_DROPS`] drops find a
/// periodic pattern; `None` elsewhere (criterion holds, the rod, neither). Every regular n-gon
/// (3 <= n <= 64; Q(cos 2π/n) enclosed by rationals in the kernel).
pub fn orbit_attempt(
    n: u64,
    kappa: &crate::exact::Q,
    gamma: &crate::exact::Q,
    cc: &Criterion,
    drops: Option<&Drops>,
) -> Option<OrbitSummary> {
    if n < 3 || cc.holds {
        return None;
    }
    let drops = drops?;
    let chatter = drops.counts.get(Outcome::Cc.name()).copied().unwrap_or(0);
    let mut req = Request {
        n,
        kappa: kappa.clone(),
        gamma: gamma.clone(),
        pattern: None,
        drops: ORBIT_DROPS,
        max_depth: ORBIT_DEPTH,
    };
    if chatter == 0 {
        // A small basin: the evidence drops may all miss it; the pattern search is longer.
        req.pattern = Some(find_cc_pattern(&req)?);
    }
    Some(attempt(req, cc, drops))
}

/// The orbit certificate of a request (`req.pattern` `None`: the pattern of the producer's
/// simulated drops, [`find_pattern`]), reported against the failing criterion `cc` and the
/// `drops` that chatter. Bounded by the producer's limits: at most 24·(max_depth + 1) kernel
/// calls per phase of the pattern, each on at most 1 + 8 + ... + 8^max_depth sub-boxes (9 for
/// [`ORBIT_DEPTH`]).
pub fn attempt(mut req: Request, cc: &Criterion, drops: &Drops) -> OrbitSummary {
    let chatter = drops.counts.get(Outcome::Cc.name()).copied().unwrap_or(0);
    let pattern = match req.pattern.clone() {
        Some(p) => p,
        None => match find_pattern(&req) {
            Ok(p) => p,
            Err(e) => return not_certified(None, failure_kind(&e), e.to_string(), chatter, drops.runs),
        },
    };
    req.pattern = Some(pattern.clone());
    match certify_orbit(&req, &[MALACHITE, NUM]) {
        Ok(found) => certified(found, cc),
        Err(e) => not_certified(Some(pattern), failure_kind(&e), e.to_string(), chatter, drops.runs),
    }
}

/// The text output's lines of the orbit field.
pub fn orbit_lines(o: &OrbitSummary, l: &mut Vec<String>) {
    let head = "orbit certificate (docs/orbit-certificates.md)";
    match (&o.verdict, &o.set, &o.cycle) {
        (Verdict::Certified, Some(set), Some(cyc)) => {
            let pattern = o.pattern.as_deref().map(pattern_text).unwrap_or_default();
            let x = match set {
                OrbitSetReport::Parallelepiped { delta, .. } => format!(
                    "X = x* + A [-delta, delta]^3 with delta = {} around the attracting cycle x* ~ ({:.6}, {:.6}, {:.6}) of the return map R_P (A: its eigenvectors)",
                    delta.exact, cyc.fixed_point[0], cyc.fixed_point[1], cyc.fixed_point[2]
                ),
                OrbitSetReport::Box { lo, hi } => format!(
                    "X = the box [{}, {}] x [{}, {}] x [{}, {}]",
                    lo[0].exact, hi[0].exact, lo[1].exact, hi[1].exact, lo[2].exact, hi[2].exact
                ),
            };
            let exact = |n: &Option<Number>| n.as_ref().map_or("?".to_string(), |n| n.exact.clone());
            l.push(format!(
                "{head}: CC proved from an explicit set X of post-impact states (not from every drop); accepted by the kernel on both backends ({})",
                o.backends.join(" + "),
            ));
            l.push(format!(
                "  pattern {pattern}; {x}; {} sub-boxes (subdivision {}); bounds rho = {}, lambda = {}, T = {}; at x*: eigenvalues of R_P ~ {:.5}, {:.5}, {:.5}, alpha/beta ~ {:.5}",
                o.sub_boxes.unwrap_or(0),
                o.subdivision.unwrap_or(0),
                exact(&o.rho),
                exact(&o.lambda),
                exact(&o.period),
                cyc.eigenvalues[0],
                cyc.eigenvalues[1],
                cyc.eigenvalues[2],
                cyc.ratio,
            ));
            l.push(format!("  proves: {}", o.proves.clone().unwrap_or_default()));
            l.push(format!("  {}.", o.conjecture_1));
            l.push(match &o.file {
                Some(f) => format!("  written to {f} (`chatter verify {f}` re-checks it)"),
                None => "  `--orbit-out FILE` writes it (`chatter verify FILE` re-checks it)".into(),
            });
        }
        _ => {
            let from = match &o.pattern {
                Some(p) => format!(" (pattern {} from the simulated drops)", pattern_text(p)),
                None => String::new(),
            };
            l.push(format!(
                "{head}: none{from}: {}",
                o.reason.clone().unwrap_or_else(|| "not certified".into())
            ));
            l.push(format!("  Conjecture 1: {}", o.conjecture_1));
        }
    }
}
