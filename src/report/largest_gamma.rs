//! `chatter.largest-gamma/1`: the largest gamma that certifies for one body, by exact bisection
//! (`chatter certify ... --largest-gamma`, issue 13 §4), and the simulated drops just above it.

use super::classify::Drops;
use super::convex::GeneralBodyReport;
use super::{Interval, Number, Report, ms};
use crate::certify::bisect::Bisection;
use crate::exact::{Q, QExt};
use chatter_kernel::exact::OrderedField;
use crate::simulate::{Arithmetic, Model, Options, Outcome, counts, simulate_many};
use schemars::JsonSchema;
use serde::Serialize;

/// Random drops simulated just above the largest certified gamma, and their impact budget.
pub const DROPS_ABOVE: u64 = 100;
/// The impact budget of each drop.
pub const DROP_BUDGET: usize = 20_000;

/// A gamma the pipeline certified, with its claim.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct CertifiedAt {
    pub gamma: Number,
    pub claim: &'static str,
}

/// A gamma the pipeline did not certify, with the reason.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct NotCertifiedAt {
    pub gamma: Number,
    pub reason: String,
}

/// `chatter certify --largest-gamma --json`.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct LargestGammaReport {
    /// `chatter.largest-gamma/1`.
    pub schema: &'static str,
    /// The body, in words (e.g. `n=4 kappa=1/6`, `rectangle 2 x 1 (uniform plate)`).
    pub body: String,
    /// Number of contacts.
    pub n: u64,
    /// kappa of a regular body; 0 for a general body (`general_body`).
    pub kappa: Number,
    /// A general convex body (docs/model.md §11), else `null`.
    pub general_body: Option<GeneralBodyReport>,
    /// The interval bisected.
    pub interval: Interval,
    /// Bisection steps after the two ends.
    pub steps: usize,
    /// Pipeline runs (search, exactifier, kernel on both backends).
    pub runs: usize,
    /// The largest gamma tried that certified (`null`: not even the lower end).
    pub certified: Option<CertifiedAt>,
    /// The smallest gamma above it tried that did not certify (`null`: the upper end certified).
    pub not_certified: Option<NotCertifiedAt>,
    /// f64 drops at `not_certified.gamma` (`null` when the upper end certified).
    pub drops_above: Option<Drops>,
    /// What stopped the bisection: the failure against the regular body's S_1 CC threshold.
    pub limit: Limit,
    /// The median time of one pipeline run, in ms: only with `--timings`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub median_ms: Option<f64>,
}

/// Where the bisection's failure lies relative to the S_1 CC threshold gamma* of the regular
/// body (the body itself, or the regular polygon it is an affine image of, docs/model.md §11.7).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, JsonSchema)]
#[serde(rename_all = "kebab-case")]
pub enum LimitKind {
    /// Above gamma*: the paper conjectures that no effectively invariant cone exists there (§6).
    AboveThreshold,
    /// Below gamma*: the pipeline's limit (the conjecture says a cone exists there).
    BelowThreshold,
    /// Inside the enclosure of gamma*: undecided.
    InEnclosure,
    /// A general body that is not an affine image of a regular polygon: no threshold is known.
    NoThreshold,
    /// The upper end certified, or not even the lower end: nothing to compare.
    NoBracket,
}

/// What stopped the bisection (issue 25 §3).
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct Limit {
    pub kind: LimitKind,
    /// The regular body whose threshold applies (`n=3 kappa=1/8`), `null` if none.
    pub regular: Option<String>,
    /// An exact enclosure of gamma* (width 2^-40; `classify --n`'s S_1 threshold), `null` if none.
    pub threshold: Option<Interval>,
    /// (gamma* - certified) / gamma* as f64 (lower end of the enclosure), `null` if either is missing.
    pub relative_gap: Option<f64>,
    /// The same in words.
    pub text: String,
}

/// Bits of the threshold's enclosure.
pub const THRESHOLD_BITS: u32 = 40;

impl Limit {
    /// The limit of bisection `b` for a body whose regular polygon is `regular` (n, kappa).
    pub fn of(regular: Option<&(u64, Q)>, b: &Bisection) -> Limit {
        let thr = regular.and_then(|(n, k)| crate::orbit::band::cc_threshold(*n, k, THRESHOLD_BITS));
        let name = regular.map(|(n, k)| format!("n={n} kappa={k}"));
        let gap = match (&thr, &b.certified) {
            (Some((lo, _)), Some((g, _))) => (lo - g).over(lo).map(|x| x.to_f64()),
            _ => None,
        };
        let kind = match (&thr, &b.failed, &b.certified) {
            (_, None, _) | (_, _, None) => LimitKind::NoBracket,
            (None, ..) => LimitKind::NoThreshold,
            (Some((lo, _)), Some((g, _)), _) if g < lo => LimitKind::BelowThreshold,
            (Some((_, hi)), Some((g, _)), _) if g > hi => LimitKind::AboveThreshold,
            _ => LimitKind::InEnclosure,
        };
        let text = limit_text(kind, name.as_deref(), thr.as_ref(), gap);
        Limit { kind, regular: name, threshold: thr.map(|(lo, hi)| Interval::of(&lo, &hi)), relative_gap: gap, text }
    }
}

/// The words of a [`Limit`].
fn limit_text(kind: LimitKind, regular: Option<&str>, thr: Option<&(Q, Q)>, gap: Option<f64>) -> String {
    let at = match (regular, thr) {
        (Some(r), Some((lo, _))) => format!("the S_1 CC threshold of {r} is gamma* = {:.11}", lo.to_f64()),
        (Some(r), None) => format!("{r} has no S_1 CC threshold in (0, 1)"),
        _ => "no threshold is known for this body (not an affine image of a regular polygon)".into(),
    };
    let gap = gap.map_or(String::new(), |g| format!("; the certified gamma is {g:.2e} (relative) below it"));
    let what = match kind {
        LimitKind::AboveThreshold => "the failure is above it, where the paper conjectures (docs/model.md §6) that no effectively invariant cone exists",
        LimitKind::BelowThreshold => "the failure is below it: the pipeline's limit, not the theory's",
        LimitKind::InEnclosure => "the failure lies inside its enclosure: undecided",
        LimitKind::NoThreshold => "the failure above is the pipeline's verdict only",
        LimitKind::NoBracket => "no bracket to compare",
    };
    format!("{at}{gap}; {what}")
}

impl Report for LargestGammaReport {
    const SCHEMA: &'static str = "chatter.largest-gamma/1";
}

/// `DROPS_ABOVE` random drops of `model` (seeds 0, 1, ...).
pub fn drops(model: &Model) -> Drops {
    let briefs = simulate_many(model, 0, DROPS_ABOVE, Arithmetic::Float, &Options::new(DROP_BUDGET), &|| {});
    let counts =
        Outcome::EVIDENCE.iter().zip(counts(&briefs)).map(|(o, k)| (o.name().to_string(), k)).collect();
    Drops { basis: "evidence", runs: DROPS_ABOVE, budget: DROP_BUDGET, counts }
}

/// What a body is, for the report.
pub struct BodyInfo {
    pub description: String,
    pub n: u64,
    pub kappa: Q,
    pub general: Option<GeneralBodyReport>,
    /// The regular polygon (n, kappa) whose S_1 threshold applies: the body itself, or the one it
    /// is an affine image of (docs/model.md §11.7); `None` if none is known.
    pub regular: Option<(u64, Q)>,
}

impl LargestGammaReport {
    /// The report of a bisection over `interval` with `steps` steps; `drops_above` simulated by
    /// the caller at the failing gamma.
    pub fn of(
        body: BodyInfo,
        interval: &(Q, Q),
        steps: usize,
        b: &Bisection,
        drops_above: Option<Drops>,
        timings: bool,
    ) -> LargestGammaReport {
        LargestGammaReport {
            schema: Self::SCHEMA,
            body: body.description,
            n: body.n,
            kappa: Number::of(&body.kappa),
            general_body: body.general,
            interval: Interval::of(&interval.0, &interval.1),
            steps,
            runs: b.times.len(),
            certified: b
                .certified
                .as_ref()
                .map(|(g, c)| CertifiedAt { gamma: Number::of(g), claim: c.name() }),
            not_certified: b
                .failed
                .as_ref()
                .map(|(g, why)| NotCertifiedAt { gamma: Number::of(g), reason: why.clone() }),
            drops_above,
            limit: Limit::of(body.regular.as_ref(), b),
            median_ms: timings.then(|| ms(b.median_time())),
        }
    }

    /// The text output.
    pub fn lines(&self) -> Vec<String> {
        let mut out = vec![format!(
            "largest gamma that certifies for {}, by {} bisection steps on [{}, {}] ({} pipeline runs):",
            self.body, self.steps, self.interval.lo.exact, self.interval.hi.exact, self.runs
        )];
        match &self.certified {
            Some(c) => out
                .push(format!("  certified at gamma = {} ({:.9}): {}", c.gamma.exact, c.gamma.f64, c.claim)),
            None => out.push("  not certified even at the lower end".into()),
        }
        match &self.not_certified {
            Some(f) => out.push(format!(
                "  not certified at gamma = {} ({:.9}): {}",
                f.gamma.exact, f.gamma.f64, f.reason
            )),
            None => out.push("  certified at the upper end: no failure found".into()),
        }
        if let Some(d) = &self.drops_above {
            let c: Vec<String> =
                d.counts.iter().filter(|(_, k)| **k > 0).map(|(o, k)| format!("{o} {k}")).collect();
            out.push(format!(
                "  {} random drops just above (evidence: f64, budget {} impacts): {}",
                d.runs,
                d.budget,
                c.join(", ")
            ));
        }
        out.push(format!("  limit: {}", self.limit.text));
        if let Some(t) = self.median_ms {
            out.push(format!("  median time of one pipeline run: {t:.2} ms"));
        }
        out
    }
}
