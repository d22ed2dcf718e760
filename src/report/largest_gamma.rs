//! `chatter.largest-gamma/1`: the largest gamma that certifies for one body, by exact bisection
//! (`chatter certify ... --largest-gamma`, issue 13 §4), and the simulated drops just above it.

use super::classify::Drops;
use super::convex::GeneralBodyReport;
use super::{Interval, Number, Report, ms};
use crate::certify::bisect::Bisection;
use crate::exact::{Q, QExt};
use crate::simulate::{Arithmetic, Model, Options, Outcome, counts, simulate_many};
use chatter_kernel::exact::OrderedField;
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

/// Where the bisection's failure lies relative to a threshold gamma* of a CC criterion.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, JsonSchema)]
#[serde(rename_all = "kebab-case")]
pub enum LimitKind {
    /// Above gamma*: where the criterion conjectures that no effectively invariant cone exists.
    AboveThreshold,
    /// Below gamma*: the pipeline's limit (the criterion conjectures a cone there).
    BelowThreshold,
    /// Inside the enclosure of gamma*: undecided.
    InEnclosure,
    /// No threshold in (0, 1) is known: nothing to compare.
    NoThreshold,
    /// The upper end certified, or not even the lower end: nothing to compare.
    NoBracket,
}

/// A threshold to compare the bisection with: the S_1 criterion of a regular body (the body
/// itself, or the regular polygon a general body is an affine image of, docs/model.md §6, §11.7),
/// else the product criterion of a general body (§11.11); both conjectural as criteria for cones.
#[derive(Clone, Debug)]
pub struct ThresholdOf {
    /// `S_1 of n=3 kappa=1/8`, or `the product around the polygon (conjectural, §11.11)`.
    pub criterion: String,
    /// An exact enclosure of gamma* of width 2^-[`THRESHOLD_BITS`]; `None`: none in (0, 1).
    pub enclosure: Option<(Q, Q)>,
}

/// Bits of the threshold's enclosure.
pub const THRESHOLD_BITS: u32 = 40;

impl ThresholdOf {
    /// The S_1 CC threshold of the regular n-gon with this kappa (`classify --n`'s).
    pub fn regular(n: u64, kappa: &Q) -> ThresholdOf {
        let enclosure = crate::orbit::band::cc_threshold(n, kappa, THRESHOLD_BITS);
        ThresholdOf { criterion: format!("S_1 of n={n} kappa={kappa} (docs/model.md §6)"), enclosure }
    }

    /// The product criterion's threshold of a general body (`classify --rectangle ...`'s).
    pub fn product(body: &chatter_kernel::model::ConvexBody<Q>) -> ThresholdOf {
        use crate::spectral::convex::{Direction, product_profile};
        let lo = product_profile(body, Direction::CounterClockwise).sup_lower_bound(THRESHOLD_BITS);
        let eps = Q::from_rational(malachite::rational::Rational::from(1u32) >> i64::from(THRESHOLD_BITS));
        let enclosure = lo.map(|lo| (lo.clone(), &lo + &eps));
        let criterion =
            "the product around the polygon of this body (conjectural, docs/model.md §11.11)".into();
        ThresholdOf { criterion, enclosure }
    }
}

/// What stopped the bisection (issue 25 §3).
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct Limit {
    pub kind: LimitKind,
    /// The CC criterion whose threshold is compared, `null` if none.
    pub criterion: Option<String>,
    /// An exact enclosure of its threshold gamma* (width 2^-40), `null` if none in (0, 1).
    pub threshold: Option<Interval>,
    /// (gamma* - certified) / gamma* (gamma* the enclosure's lower end), `null` if either is missing.
    pub relative_gap: Option<f64>,
    /// The same in words.
    pub text: String,
}

impl Limit {
    /// The limit of bisection `b` against `thr`.
    pub fn of(thr: Option<&ThresholdOf>, b: &Bisection) -> Limit {
        let enc = thr.and_then(|t| t.enclosure.clone());
        let gap = match (&enc, &b.certified) {
            (Some((lo, _)), Some((g, _))) => (lo - g).over(lo).map(|x| x.to_f64()),
            _ => None,
        };
        let kind = match (&enc, &b.failed, &b.certified) {
            (_, None, _) | (_, _, None) => LimitKind::NoBracket,
            (None, ..) => LimitKind::NoThreshold,
            (Some((lo, _)), Some((g, _)), _) if g < lo => LimitKind::BelowThreshold,
            (Some((_, hi)), Some((g, _)), _) if g > hi => LimitKind::AboveThreshold,
            _ => LimitKind::InEnclosure,
        };
        let criterion = thr.map(|t| t.criterion.clone());
        let text = limit_text(kind, criterion.as_deref(), enc.as_ref(), gap);
        Limit {
            kind,
            criterion,
            threshold: enc.map(|(lo, hi)| Interval::of(&lo, &hi)),
            relative_gap: gap,
            text,
        }
    }
}

/// The words of a [`Limit`].
fn limit_text(kind: LimitKind, criterion: Option<&str>, enc: Option<&(Q, Q)>, gap: Option<f64>) -> String {
    let at = match (criterion, enc) {
        (Some(c), Some((lo, _))) => format!("the CC threshold of {c} is gamma* = {:.11}", lo.to_f64()),
        (Some(c), None) => format!("{c} has no CC threshold in (0, 1)"),
        _ => "no CC threshold is known for this body".into(),
    };
    let gap = gap.map_or(String::new(), |g| format!("; the certified gamma is {g:.2e} (relative) below it"));
    let what = match kind {
        LimitKind::AboveThreshold => {
            "the failure is above it, where the criterion conjectures that no effectively invariant cone exists"
        }
        LimitKind::BelowThreshold => "the failure is below it: the pipeline's limit",
        LimitKind::InEnclosure => "the failure lies inside its enclosure: undecided",
        LimitKind::NoThreshold => "the failure is the pipeline's verdict only",
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
    /// The threshold the bisection is compared with ([`ThresholdOf`]).
    pub threshold: Option<ThresholdOf>,
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
            limit: Limit::of(body.threshold.as_ref(), b),
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
