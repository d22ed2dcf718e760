//! `chatter.largest-gamma/1`: the largest gamma that certifies for one body, by exact bisection
//! (`chatter certify ... --largest-gamma`, issue 13 §4), and the simulated drops just above it.

use super::classify::Drops;
use super::convex::GeneralBodyReport;
use super::{Interval, Number, Report, ms};
use crate::certify::bisect::Bisection;
use crate::exact::Q;
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
    /// The median time of one pipeline run, in ms: only with `--timings`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub median_ms: Option<f64>,
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
        if let Some(t) = self.median_ms {
            out.push(format!("  median time of one pipeline run: {t:.2} ms"));
        }
        out
    }
}
